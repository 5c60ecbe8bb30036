"""The finite-element impact solver: conservation, mesh convergence, agreement with the modes.

Reference numbers come from runs of :func:`restitution.fem.fem_collide` and of the modal solver
:func:`restitution.dynamics.collision.collide` on the development machine (Nov 2026); each is quoted
where it is used. At nu = 0.33, v = 0.1, alpha = 500 the FEM gives (default mesh family)

    refine   dofs    epsilon     1 - eps^2   steps
    0        3563    0.9526132   0.092528    2736
    1       12301    0.9529402   0.091905    5072
    2       44763    0.9529514   0.091884    9760

and the modal solver (N lowest modes, default settings) 1 - eps^2 = 0.101703, 0.098765,
0.096990, 0.095433, 0.094372 at N = 200, 400, 800, 1600, 3200, extrapolated linearly in
1/sqrt(N) to 0.092083 +- 0.00019 (N = 200-1600; eps = 0.952847 +- 1.0e-4) or 0.091741 +-
0.000079 (N = 800-3200; eps = 0.953026 +- 4.1e-5). The modal contact time 5.4628, compression
0.16288 and peak force 0.1721 at N = 3200 approach the FEM's 5.48288, 0.16381 and 0.1715.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad

from restitution import InputError, Material
from restitution.fem import fem_collide
from restitution.fem.contact import wall_terms
from restitution.fem.impact import contact_angle_estimate
from restitution.fem.model import fem_model

NU, V, ALPHA = 0.33, 0.1, 500.0
# A coarse mesh family (4x the default element sizes near the contact, 2x in the bulk) for
# the convergence test of the default suite; refine = 0, 1, 2 take ~1 + 2 + 8 s.
COARSE = {"h_contact": 0.16, "h_far": 0.5, "grading": 0.6}


def test_wall_integral_matches_adaptive_quadrature():
    model = fem_model(Material(NU), 0, contact_angle_estimate(V, ALPHA))
    u = np.zeros(model.disk.n_dofs)
    for alpha in (50.0, 500.0):
        V_half, F, grad, _ = wall_terms(model.quad, alpha, -1.0, u)
        exact = quad(lambda p, a=alpha: math.exp(a * (math.cos(p) - 1.0)), 0, math.pi / 2)[0]
        # Measured relative errors 1.9e-8 (alpha = 50) and 1.9e-7 (alpha = 500): the
        # quadratic arc's O(h^3) deviation from the circle, amplified by alpha.
        assert_allclose(F, exact, rtol=1e-6)
        assert_allclose(V_half, F / alpha, rtol=1e-14)
        # The force on the dofs adds up to the total force (P2 partition of unity).
        assert_allclose(model.disk.rigid @ grad, F, rtol=1e-12)
    # A rigid shift by s multiplies the force by exp(alpha s).
    _, F1, _, _ = wall_terms(model.quad, ALPHA, -1.0, 0.01 * model.disk.rigid)
    _, F0, _, _ = wall_terms(model.quad, ALPHA, -1.0, u)
    assert_allclose(F1 / F0, math.exp(ALPHA * 0.01), rtol=1e-12)


def test_energy_is_conserved_to_second_order_in_the_step():
    coarse = fem_collide(NU, V, ALPHA, refine=0)
    fine = fem_collide(NU, V, ALPHA, refine=0, step_safety=0.45)
    assert coarse.method == "fem" and coarse.n_modes == 0 and coarse.integrator == "verlet"
    # Measured drift 1.7e-6 at step_safety 0.9 (the default), 4.2e-7 at 0.45.
    assert coarse.energy_drift < 3e-6
    assert_allclose(fine.dt, 0.5 * coarse.dt, rtol=1e-12)
    # Velocity Verlet: the energy error is O(dt^2).
    ratio = coarse.energy_drift / fine.energy_drift
    assert 3.0 < ratio < 5.5, ratio
    # epsilon's time-discretisation error is far below its mesh error (3e-4 at refine 0).
    assert abs(coarse.epsilon - fine.epsilon) < 1e-5


def test_epsilon_converges_under_mesh_refinement():
    eps = np.array([fem_collide(NU, V, ALPHA, refine=k, **COARSE).epsilon for k in range(3)])
    # Measured 0.9545431, 0.9526531, 0.9529374: Cauchy differences 1.9e-3 and 2.8e-4.
    d = np.abs(np.diff(eps))
    assert d[1] < d[0] / 4.0, eps
    # The finest of them lies within its Cauchy estimate of the default family's refine = 2
    # value 0.9529514 (module docstring), which is converged to ~1e-5.
    assert abs(eps[2] - 0.9529514) < d[1], eps


def test_collision_observables_are_consistent():
    r = fem_collide(NU, V, ALPHA, refine=0, record=True)
    h = r.history
    # The momentum change is the time integral of the wall force (whole disk, mass pi).
    impulse = np.trapezoid(h.force, h.t)
    assert_allclose(impulse, math.pi * V * (1.0 + r.epsilon), rtol=2e-3)
    # Measured 5.4827 and 0.16381 at refine 0; the modal solver gives 5.4544 and 0.16249 with
    # 1600 modes, rising with N (5.3935/0.15964 at N = 200).
    assert 5.3 < r.contact_time < 5.6
    assert 0.16 < r.max_compression < 0.167
    assert_allclose(h.x0.max() + 1.0, r.max_compression, atol=2e-4)


@pytest.mark.parametrize(
    "kwargs", [{"v": 0.0}, {"v": 1.0}, {"v": float("nan")}, {"alpha": 0.0}, {"alpha": -5.0}]
)
def test_bad_input_is_rejected(kwargs):
    args = {"v": V, "alpha": ALPHA, **kwargs}
    with pytest.raises(InputError):
        fem_collide(NU, args["v"], args["alpha"], refine=0)


def _modal_limit(nu: float, v: float, alpha: float, counts: list[int]):
    """Modal epsilon at the N lowest modes and its N -> infinity limit with error."""
    from restitution import get_modes
    from restitution.dynamics.collision import collide
    from restitution.limits.extrapolation import epsilon_from_loss, extrapolate_modes

    pool = get_modes(nu, count=max(counts))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        loss = [1.0 - collide(pool.lowest(n), v, alpha).epsilon ** 2 for n in counts]
    fit = extrapolate_modes(np.array(counts), np.array(loss))
    return fit, epsilon_from_loss(fit.limit, fit.limit_err)


def _fem_limit(nu: float, v: float, alpha: float, levels: list[int]):
    """Finest FEM epsilon and its error, the last Cauchy difference (an overestimate: the
    differences fall by 8-30x per level)."""
    eps = [fem_collide(nu, v, alpha, refine=k).epsilon for k in levels]
    return eps[-1], abs(eps[-1] - eps[-2]), eps


# The modal side uses the largest N: 800, 1600, 3200. Its 1/sqrt(N) extrapolation depends on
# the window of N more than its own error estimate says: at nu = 0.9, v = 0.3 the window
# 400-1600 gives eps = 0.751628 +- 1.1e-4, 8 of its errors below the FEM; 800-3200 gives
# 0.752206 +- 7.8e-4 (flagged non-asymptotic by the extrapolation).
MODAL_COUNTS = [800, 1600, 3200]


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_fem_agrees_with_modal_extrapolation_at_nu_033():
    # About 35 s (default run, issue 7). Measured: FEM 0.9529514 +- 1.1e-5 (refine 2, last
    # Cauchy difference), modal 0.9530261 +- 4.1e-5: 1.76 combined errors apart.
    fem_eps, fem_err, _ = _fem_limit(NU, V, ALPHA, [0, 1, 2])
    fit, (modal_eps, modal_err) = _modal_limit(NU, V, ALPHA, MODAL_COUNTS)
    assert fit.asymptotic_ok, fit.message
    combined = math.hypot(fem_err, modal_err)
    assert abs(fem_eps - modal_eps) < 2.0 * combined, (fem_eps, fem_err, modal_eps, modal_err)


# At nu = 0.9, v = 0.3 the window 800-3200 fails the extrapolation's own checks (dropping
# N = 800 moves the limit by 1.0e-3; the slope changes by 211%), so it cannot be the test's
# reference. The next window, 1600-6400, passes them (measured): losses 0.4382484,
# 0.4367624, 0.4357336 at N = 1600, 3200, 6400; eps = 0.7528530 +- 2.9e-5.
MODAL_COUNTS_NU09 = [1600, 3200, 6400]


@pytest.mark.slow
@pytest.mark.xfail(
    strict=True,
    reason="open: the modal fit over N = 1600-6400 passes its own checks, but "
    "eps = 0.7528530 +- 2.9e-5 lies 2.27 combined errors above the FEM's 0.7526889 +- 6.6e-5 "
    "(measured, 263 s); windows 400-1600, 800-3200, 1600-6400 give 0.75163, 0.75221, 0.75285: "
    "the 1/sqrt(N) limit still drifts with N at nu = 0.9, v = 0.3",
)
def test_fem_agrees_with_modal_extrapolation_at_nu_09_high_speed():
    # ~4.5 minutes. Like the nu = 0.33 test: the modal fit must pass its own checks, then
    # agree with the FEM within two combined errors. It does not yet (see the xfail reason);
    # strict, so the test reports when it starts to agree.
    nu, v = 0.9, 0.3
    fem_eps, fem_err, _ = _fem_limit(nu, v, ALPHA, [0, 1, 2])
    fit, (modal_eps, modal_err) = _modal_limit(nu, v, ALPHA, MODAL_COUNTS_NU09)
    assert fit.asymptotic_ok, fit.message
    combined = math.hypot(fem_err, modal_err)
    assert abs(fem_eps - modal_eps) < 2.0 * combined, (fem_eps, fem_err, modal_eps, modal_err)


def test_compare_fem_command_prints_both_methods():
    from click.testing import CliRunner

    from restitution.cli.fem_compare import compare_fem

    args = ["--refine", "0", "--modes", "50,100,200", "--json"]
    result = CliRunner().invoke(compare_fem, args)
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert [row["refine"] for row in data["fem"]] == [0]
    assert [row["n_modes"] for row in data["modal"]] == [50, 100, 200]
    assert data["fem"][0]["method"] == "fem" and data["modal"][0]["method"] == "modal"
    # With one FEM level there is no error estimate; the modal limit exists.
    assert data["fem_error"] is None and math.isfinite(data["modal_epsilon"])  # NaN -> null
    bad = CliRunner().invoke(compare_fem, ["--refine", "1", "--refine-min", "2"])
    assert isinstance(bad.exception, InputError)
