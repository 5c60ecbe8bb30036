"""The tangential models the package's oblique ``beta`` is compared with (issue 63, items 2 and
4): LAMMPS's ``mindlin`` and ``linear_history`` (restitution.laws.tangential_models) and
Walton's three-parameter law, and their fits (restitution.laws.oblique_fits).

Independent routes: the codes' step-by-step update of ``mindlin`` against the no-microslip law
of restitution.quasistatic.oblique (DOP853 in the variable ``s``, phase by phase); the
``linear_history`` rough limit in closed form (a constant stiffness: a harmonic oscillator of
``omega^2 = (15/8) K chi`` over Hertz's contact time ``2.9432``, so ``beta_0 = -cos(omega
tau)``); gross slip against the impulse ratio ``-1 + 2 K / X``; fits recovering the parameters
of synthetic data; Walton's fit to Maw, Barber and Fawcett's exact gross-slip line.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.oblique_fits import fit_history, fit_walton, lammps_mindlin_kt
from restitution.laws.tangential_models import history_beta, walton_beta
from restitution.quasistatic.oblique import beta_of_psi, gross_slip_psi

X = np.array([0.3, 0.6, 1.0, 2.0, 3.0, 5.0, 8.0])


@pytest.mark.parametrize("chi", [0.75, 0.85, 1.0])
def test_mindlin_as_the_codes_step_it_is_the_no_microslip_law(chi):
    nu = (2.0 - 2.0 * chi) / (2.0 - chi)  # chi = 2 (1 - nu) / (2 - nu)
    exact = beta_of_psi(chi * X, nu, inertia_factor=3.0, model="no-microslip")
    assert np.max(np.abs(history_beta(X, chi, "mindlin", steps=20000) - exact)) < 1e-6


def test_step_error_falls_with_the_steps():
    chi = 0.85
    ref = history_beta(X, chi, "linear_history", steps=40000)
    errs = [np.max(np.abs(history_beta(X, chi, "linear_history", steps=n) - ref))
            for n in (1000, 2000, 4000)]  # fmt: skip
    assert errs[0] > errs[1] > errs[2]
    assert math.log(errs[0] / errs[2], 4.0) > 0.9  # at least first order


@pytest.mark.parametrize("chi", [0.3, 0.85])
def test_linear_history_rough_limit_is_the_harmonic_turn(chi):
    tau = 0.8 * math.gamma(0.4) * math.sqrt(math.pi) / math.gamma(0.9)  # 2 (2/5) B(2/5, 1/2)
    omega = math.sqrt(1.875 * 3.0 * chi)
    # The contact slips where its cap (2/3) x^(3/2) / chi falls below the spring's stretch
    # (near both ends), which moves beta by ~ X^(2/3) (measured: 1.8e-3, 3.8e-4 at X = 1e-3,
    # 1e-4, chi = 0.3); at X = 1e-6 the step's error (1.5e-5 at 80000 steps) is left.
    beta = history_beta([1e-6], chi, "linear_history", steps=80000)[0]
    assert beta == pytest.approx(-math.cos(omega * tau), abs=3e-5)


def test_gross_slip_is_the_impulse_ratio():
    for model in ("mindlin", "linear_history"):
        big = np.array([10.0, 20.0, 50.0])
        np.testing.assert_allclose(history_beta(big, 0.85, model), -1.0 + 6.0 / big, atol=1e-9)


def test_refusals():
    with pytest.raises(InputError, match="model"):
        history_beta(X, 0.85, "hooke")
    with pytest.raises(InputError, match="chi"):
        history_beta(X, -1.0)
    with pytest.raises(InputError, match="1-D"):
        fit_walton([1.0], [0.1], [1.0], 0.3)


def test_walton_fit_recovers_its_parameters():
    beta = walton_beta(X, 0.97, 1.2, 0.31)
    f = fit_walton(X, beta, np.full(X.size, 0.97), 0.3)
    assert (f.mu_ratio, f.beta_0) == pytest.approx((1.2, 0.31), abs=1e-8)
    assert f.mu_w == pytest.approx(0.36, abs=1e-8) and f.rms < 1e-9


def test_walton_fit_to_the_gross_slip_of_maw_barber_fawcett_is_exact():
    """Beyond ``2 K chi - 1`` MBF's ``beta`` is the impulse ratio with ``e = 1``: Walton's
    ``mu_W = mu``."""
    nu, K = 0.3, 3.5
    chi = 2.0 * (1.0 - nu) / (2.0 - nu)
    psi = gross_slip_psi(nu, K) * np.array([1.05, 1.5, 2.0, 4.0])
    beta = beta_of_psi(psi, nu, inertia_factor=K, springs=400)
    f = fit_walton(psi / chi, beta, np.ones(psi.size), 1.0, K)
    assert f.mu_ratio == pytest.approx(1.0, abs=2e-6) and f.rms < 2e-6


def test_history_fit_recovers_chi():
    beta = history_beta(X, 0.62, "linear_history", steps=4000)
    f = fit_history(X, beta, "linear_history", steps=4000)
    assert f.chi == pytest.approx(0.62, rel=1e-4) and f.rms < 1e-6


def test_lammps_null_stiffness_is_mindlins_ratio():
    for nu in (0.0, 0.3, 0.45):
        chi = 2.0 * (1.0 - nu) / (2.0 - nu)
        assert lammps_mindlin_kt(chi, 210e9, nu)["ratio_to_null"] == pytest.approx(1.0, 1e-14)
