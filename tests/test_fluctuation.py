"""Detailed balance of collisions with thermal modes (issue 17, docs/vibrating.md).

The relation ``v e^{-(m/2)v^2/T} K(v'|v) = v' e^{-(m/2)v'^2/T} K(v|v')`` is tested on a thermal
ensemble (seeded) with Bowker's symmetry test and two antisymmetric means; the statistics are
first calibrated on synthetic pairs whose answer is known. The control (translation hotter
than the modes), which the relation predicts to fail, shows the test's power.
"""

import math

import numpy as np
import pytest
from scipy import stats

from restitution import get_modes
from restitution.vibrating.fluctuation import detailed_balance_test, flux_speeds, symmetry_test
from restitution.vibrating.vibration import kinetic_energy

N, ALPHA, V_TH, WINDOW = 4, 200.0, 0.1, (0.05, 0.2)


@pytest.fixture(scope="module")
def modes():
    return get_modes(0.33, count=N)


def test_symmetry_test_is_calibrated():
    rng = np.random.default_rng(0)
    x, y = rng.uniform(0, 1, (2, 4000))
    edges = np.linspace(0, 1, 6)
    null = symmetry_test(x, y, edges)
    assert null.dof == 10 and null.p_value > 0.01 and null.counts.sum() == 4000
    shifted = symmetry_test(x, np.clip(x + 0.1 * y, 0, 1), edges)
    assert shifted.p_value < 1e-10


def test_flux_speeds_follow_the_flux_density(modes):
    T = float(kinetic_energy(modes, V_TH))
    v = flux_speeds(modes, T, WINDOW, 5000, np.random.default_rng(1))
    s = 0.5 * modes.mass / T
    a, b = WINDOW

    def cdf(x):
        return (np.exp(-s * a * a) - np.exp(-s * x * x)) / (np.exp(-s * a * a) - np.exp(-s * b * b))

    assert v.min() >= a and v.max() <= b
    assert stats.kstest(v, cdf).pvalue > 0.01


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_detailed_balance_on_a_thermal_ensemble(modes):
    """400 collisions (N = 4 modes, about 15 s). Measured: Bowker p = 0.82, z = -0.77, -0.65."""
    T = float(kinetic_energy(modes, V_TH))
    bt = detailed_balance_test(modes, ALPHA, T, WINDOW, 400, seed=3, energy_tol=1e-5)
    # The step is judged by epsilon (vibration.STEP_JUDGE): its error is held to energy_tol / 2;
    # the drift is reported, not held (measured at most 6.3e-5).
    assert bt.failed == 0 and 0 < bt.max_step_error <= 0.5e-5 and bt.max_energy_drift < 1e-3
    assert bt.test.dof >= 10 and bt.test.p_value > 0.01
    z = bt.antisymmetric_z()
    assert abs(z["energy"]) < 3 and abs(z["log_speed"]) < 3
    # Many pairs change bins: the table is not trivially diagonal.
    assert np.trace(bt.test.counts) < 0.5 * bt.test.counts.sum()


@pytest.mark.slow
def test_the_test_rejects_a_translation_hotter_than_the_modes(modes):
    """Control: speeds from the flux density at 2T, modes at T: the pairs are not symmetric."""
    T = float(kinetic_energy(modes, V_TH))
    bt = detailed_balance_test(modes, ALPHA, T, WINDOW, 1600, seed=5,
                               translation_temperature=2 * T, energy_tol=1e-5)  # fmt: skip
    z = bt.antisymmetric_z()
    assert z["energy"] < -4
    assert math.isfinite(bt.test.chi2)
