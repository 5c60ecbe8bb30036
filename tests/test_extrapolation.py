"""Extrapolations alpha -> infinity (1/alpha) and N -> infinity (1/sqrt(N)) on synthetic data.

The synthetic data have a known limit; the statistics tests use fixed seeds.
"""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from restitution.errors import InputError
from restitution.limits.extrapolation import (
    combined_limit,
    epsilon_from_loss,
    extrapolate_alpha,
    extrapolate_modes,
    linear_limit,
)

PAPER_N = np.array([300, 400, 600, 940])  # the paper's mode counts (Fig. 8 caption)
ALPHAS = np.array([125.0, 250.0, 500.0, 1000.0])


def test_exact_line_recovered_with_zero_error():
    x = 1.0 / np.sqrt(PAPER_N)
    fit = extrapolate_modes(PAPER_N, 0.12 - 0.8 * x)
    assert_allclose(fit.limit, 0.12, rtol=1e-13)
    assert_allclose(fit.slope, -0.8, rtol=1e-12)
    assert fit.limit_err < 1e-14
    assert fit.asymptotic_ok, fit.message
    assert_allclose(fit.line(x), 0.12 - 0.8 * x, atol=1e-15)


@pytest.mark.parametrize(
    ("fit", "parameter", "slope", "noise"),
    [
        (extrapolate_modes, PAPER_N, 2.0, 1e-3),
        (extrapolate_alpha, ALPHAS, 5.0, 1e-3),
        (extrapolate_alpha, ALPHAS[:3], 5.0, 1e-3),
    ],
)
def test_error_bar_coverage_on_noisy_lines(fit, parameter, slope, noise):
    # Linear data + Gaussian noise: the quoted 1-sigma error (standard error combined in
    # quadrature with the drop-one spread) should cover the truth about 68% of the time. With
    # 2-3 points per fit the standard error is itself uncertain (t distribution, 1-2 degrees
    # of freedom), so the 2-sigma coverage falls short of 95%. 200 repetitions give a binomial
    # scatter of about 0.03; the bounds are wide enough to be robust, tight enough to catch an
    # error bar that is off by a factor 2.
    rng = np.random.default_rng(20240601)
    truth = 0.1
    x = 1.0 / np.sqrt(parameter) if fit is extrapolate_modes else 1.0 / parameter
    z = []
    for _ in range(200):
        y = truth + slope * x + rng.normal(0.0, noise, x.size)
        result = fit(parameter, y)
        z.append(abs(result.limit - truth) / result.limit_err)
    z = np.array(z)
    assert 0.55 < np.mean(z < 1.0) < 0.85
    assert np.mean(z < 2.0) > 0.75
    assert np.mean(z < 4.0) > 0.9


def test_flag_fires_on_non_asymptotic_data():
    # Energy loss that only becomes linear in 1/alpha at hard walls: at soft walls the loss
    # saturates (quasi-elastic), as the paper describes for small speeds (Fig. 7 discussion).
    alpha = np.array([20.0, 40.0, 80.0])
    loss = 0.05 * (1.0 - np.exp(-alpha / 60.0))
    fit = extrapolate_alpha(alpha, loss)
    assert not fit.asymptotic_ok
    assert "curved" in fit.message or "dropping" in fit.message


def test_flag_fires_on_strong_curvature_in_modes():
    x = 1.0 / np.sqrt(PAPER_N)
    fit = extrapolate_modes(PAPER_N, 0.1 + 2.0 * x + 60.0 * x**2)
    assert not fit.asymptotic_ok
    assert "curved in 1/sqrt(N)" in fit.message


def test_mild_curvature_is_accepted():
    # y = 0.1 + 2 x + c x^2 with 2 c x_max = 0.2: the slope grows by 10% of 2 between x = 0 and
    # the least asymptotic point; the reported curvature is relative to the fitted slope.
    x = 1.0 / np.sqrt(PAPER_N)
    c = 0.1 * 2.0 / (2.0 * x.max())
    fit = extrapolate_modes(PAPER_N, 0.1 + 2.0 * x + c * x**2)
    assert fit.asymptotic_ok, fit.message
    assert_allclose(fit.curvature, 2.0 * c * x.max() / fit.slope, rtol=1e-8)


def test_too_few_points_are_flagged():
    fit = extrapolate_alpha([250.0, 500.0], [0.2, 0.15])
    assert not fit.asymptotic_ok
    assert "need >= 3" in fit.message
    assert_allclose(fit.limit, 0.1, rtol=1e-12)  # the line through two points
    single = linear_limit([0.1], [0.3])
    assert not single.asymptotic_ok and math.isnan(single.limit_err)


def test_non_finite_points_are_ignored():
    x = np.array([0.1, 0.2, 0.3, 0.4])
    fit = linear_limit(x, [1.1, np.nan, 1.3, 1.4])
    assert_allclose(fit.limit, 1.0, rtol=1e-12)
    assert fit.x.size == 3


def test_bad_input():
    with pytest.raises(InputError):
        linear_limit([0.1, 0.2], [1.0])
    with pytest.raises(InputError):
        extrapolate_alpha([-1.0, 2.0, 3.0], [0.1, 0.2, 0.3])
    with pytest.raises(InputError):
        combined_limit([1.0, 2.0], [10, 20], np.zeros((3, 2)))
    with pytest.raises(InputError):
        combined_limit([1.0, 2.0], [10, 20], np.zeros((2, 2)), order="random")


def _bilinear(alpha, n, limit=0.2):
    # Energy loss with independent corrections in 1/alpha and 1/sqrt(N) and a cross term.
    a, s = 1.0 / alpha[:, None], 1.0 / np.sqrt(n)[None, :]
    return limit + 5.0 * a - 1.0 * s + 3.0 * a * s


def test_combined_limit_exact_on_bilinear_grid():
    alpha = np.array([125.0, 250.0, 500.0])
    loss = _bilinear(alpha, PAPER_N)
    c = combined_limit(alpha, PAPER_N, loss)
    assert_allclose(c.limit, 0.2, rtol=1e-12)
    assert_allclose(c.epsilon, math.sqrt(0.8), rtol=1e-12)
    assert c.asymptotic_ok, c.message
    # Unweighted fits on a complete grid: both orders give the same limit to round-off.
    assert abs(c.order_difference) < 1e-14
    assert len(c.first) == alpha.size and len(c.check_first) == PAPER_N.size
    other = combined_limit(alpha, PAPER_N, loss, order="alpha_first")
    assert_allclose(other.limit, c.limit, rtol=1e-12)


def test_combined_limit_with_noise_and_a_missing_point():
    rng = np.random.default_rng(7)
    alpha = np.array([125.0, 250.0, 500.0, 1000.0])
    loss = _bilinear(alpha, PAPER_N) + rng.normal(0.0, 2e-4, (alpha.size, PAPER_N.size))
    loss[0, 1] = np.nan  # a failed collision
    c = combined_limit(alpha, PAPER_N, loss)
    assert np.isfinite(c.limit) and c.limit_err > 0
    assert abs(c.limit - 0.2) < 3.0 * c.limit_err
    assert c.first[0].x.size == 3  # the missing point was left out of its fit
    d = c.to_dict()
    assert d["energy_loss_grid"][0][1] is None and d["epsilon"] == pytest.approx(c.epsilon)


def test_epsilon_error_propagation():
    # d sqrt(1 - L) / dL = -1 / (2 sqrt(1 - L)), compared with a central difference.
    loss, err = 0.3, 1e-3
    eps, eps_err = epsilon_from_loss(loss, err)
    h = 1e-6
    slope = (math.sqrt(1 - loss - h) - math.sqrt(1 - loss + h)) / (2 * h)
    assert_allclose(eps, math.sqrt(0.7), rtol=1e-15)
    assert_allclose(eps_err, abs(slope) * err, rtol=1e-8)
    assert all(math.isnan(x) for x in epsilon_from_loss(-0.01, 0.001))
    assert all(math.isnan(x) for x in epsilon_from_loss(1.0, 0.001))


def test_unphysical_limit_is_flagged():
    alpha = np.array([125.0, 250.0, 500.0])
    c = combined_limit(alpha, PAPER_N, _bilinear(alpha, PAPER_N, limit=-0.05))
    assert not c.asymptotic_ok and "outside [0, 1)" in c.message
    assert math.isnan(c.epsilon)


def _flat_in_modes_grid(wiggle: float) -> np.ndarray:
    """Loss linear-plus-mild-curvature in 1/alpha (an alpha stage with an error of its own) and
    a curved, non-monotone dependence on N of amplitude ``wiggle`` at every alpha."""
    alpha = np.array([1000.0, 2000.0, 4000.0])
    base = 0.03 - 3.0 / alpha + 200.0 / alpha**2
    return alpha, base[:, None] + wiggle * np.array([0.0, 1.0, 0.3, 0.0])[None, :]


def test_negligible_flat_mode_stage_is_waived_with_a_note():
    """Flat in N (1e-6) against an alpha stage uncertain by 4.5e-5: the N fits fail their
    relative tests, which mean nothing there, and the limit passes with the waiver noted."""
    alpha, loss = _flat_in_modes_grid(1e-6)
    n_modes = [1000, 2000, 4000, 8000]
    for row in loss:
        assert not extrapolate_modes(n_modes, row).asymptotic_ok
    fit = combined_limit(alpha, n_modes, loss)
    assert fit.asymptotic_ok
    assert fit.notes.count("relative tests waived") == 3
    # The exact alpha -> infinity limit of the base curve is 0.03 (+ at most 1e-6 from N).
    assert abs(fit.limit - 0.03) < 3 * fit.limit_err


def test_mode_stage_that_matters_is_not_waived():
    """The same grid with a 1e-4 dependence on N: more than 0.3 of the alpha stage's own error,
    so the negligible-stage waiver does not apply. The N fits' slopes are zero within their
    errors, so they are judged by window stability instead, and their stated error must cover
    every value the wiggle allows (0.03 to 0.03 + 1e-4)."""
    alpha, loss = _flat_in_modes_grid(1e-4)
    fit = combined_limit(alpha, [1000, 2000, 4000, 8000], loss)
    assert "relative tests waived" not in fit.notes
    assert fit.notes.count("relative tests ill-posed, window stable") == 3
    assert fit.asymptotic_ok
    assert abs(fit.limit - 0.03) <= fit.limit_err
    assert abs(fit.limit - 0.0301) <= fit.limit_err
    # Without the stability judgement the same fits flag the point.
    plain = combined_limit(alpha, [1000, 2000, 4000, 8000], loss, stability=False)
    assert not plain.asymptotic_ok
    assert "N -> inf at alpha = 1000" in plain.message


def _wiggly(pattern: np.ndarray, slope: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The alpha dependence of :func:`_flat_in_modes_grid` (limit 0.03) plus a wiggle
    ``pattern`` (shape (3, 4), in units of 1e-4) over N = 1000-8000 and a slope in 1/sqrt(N)."""
    alpha = np.array([1000.0, 2000.0, 4000.0])
    n_modes = np.array([1000, 2000, 4000, 8000])
    base = 0.03 - 3.0 / alpha + 200.0 / alpha**2
    return alpha, n_modes, base[:, None] + 1e-4 * pattern + slope / np.sqrt(n_modes)[None, :]


def test_flat_mode_stage_whose_window_is_not_stable_is_flagged():
    """Flat but wiggling N fits whose combined limit moves by more than its error when the
    window loses its most asymptotic member: flagged, with both shifts in the message."""
    pattern = np.array([[1, -1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 0]], dtype=float)
    alpha, n_modes, loss = _wiggly(pattern)
    fit = combined_limit(alpha, n_modes, loss)
    assert not fit.asymptotic_ok
    assert "window not stable" in fit.message
    assert "more than the error" in fit.message


def test_resolved_slope_is_not_rescued_by_a_stable_window():
    """N fits with a clearly resolved slope and strong curvature keep their relative tests:
    the stability judgement is only for slopes that are zero within their errors."""
    alpha, n_modes, loss = _wiggly(np.zeros((3, 4)))
    x = 1.0 / np.sqrt(n_modes)
    loss = loss + 0.02 * x + 30.0 * x**2  # curved: the slope doubles across the window
    fit = combined_limit(alpha, n_modes, loss)
    assert not fit.asymptotic_ok
    assert "curved in 1/sqrt(N)" in fit.message
    assert "ill-posed" not in fit.notes + fit.message


@pytest.mark.parametrize("slope", [0.0, pytest.param(0.006, marks=pytest.mark.slow)])
def test_window_stability_errors_cover_the_truth(slope):
    """Coverage of the rule on synthetic non-convergent data: random wiggles (uniform, +-1e-4,
    independent at every grid point) on a loss whose limit is exactly 0.03, with and without a
    real slope in 1/sqrt(N) of the wiggles' size that they mask. Of the points passed by window
    stability, at least 68% must have the truth within 1 error and 95% within 2 (measured at
    300 draws with this seed: 95% and 100% without the slope, 98% and 100% with it)."""
    rng = np.random.default_rng(7)
    z = []
    for _ in range(300):
        alpha, n_modes, loss = _wiggly(rng.uniform(-1.0, 1.0, size=(3, 4)), slope)
        fit = combined_limit(alpha, n_modes, loss)
        if fit.asymptotic_ok and "window stable" in fit.notes:
            z.append(abs(fit.limit - 0.03) / fit.limit_err)
    z = np.array(z)
    assert z.size >= 50  # the rule is exercised
    assert np.mean(z <= 1.0) >= 0.68
    assert np.mean(z <= 2.0) >= 0.95


# -- the wall's curvature in 1/alpha (issue 45, item 3) ---------------------------------------


def test_a_bent_wall_dependence_is_covered_by_the_curvature_term():
    """A loss quadratic in 1/alpha on the production design (walls 1, 2, 4 times the softest's
    hardness): the straight line's intercept is off by 5 c h^2 (h = 1/alpha of the hardest
    wall), which its fit error and drop-one spread (3.6 c h^2 together) do not cover; the
    quadratic's shift is that bias exactly, so the stated error now does."""
    alpha = np.array([400.0, 800.0, 1600.0])
    c = 2000.0
    loss = (0.02 + 1.0 / alpha + c / alpha**2)[:, None] + np.zeros((1, PAPER_N.size))
    fit = combined_limit(alpha, PAPER_N, loss)
    bias = fit.limit - 0.02
    assert bias == pytest.approx(-5.0 * c / alpha[-1] ** 2, rel=1e-6)
    assert fit.alpha_curvature == pytest.approx(abs(bias), rel=1e-6)
    before = math.hypot(fit.second.stat_err, fit.second.drop_spread)
    assert before < 0.75 * abs(bias) <= 0.75 * fit.limit_err
    assert abs(bias) <= fit.limit_err
    assert fit.to_dict()["alpha_curvature"] == pytest.approx(fit.alpha_curvature)


def test_harder_walls_stay_within_the_sphere_points_error():
    """The shipped sphere point at v = 0.0993 (nu = 0.3, walls alpha delta_max = 80-320) and the
    same point computed on harder walls (160-640 and 320-1280; tests/data, regression values of
    this package): epsilon moved by 5.8e-5 and 7.0e-5, more than the 5.0e-5 stated before the
    curvature term, within the error stated now."""
    from importlib import resources

    stored = json.loads(resources.files("restitution.laws").joinpath("data").joinpath(
        "law_sphere_nu0.3.json").read_text())["metadata"]["points"]  # fmt: skip
    hard = json.loads(
        (Path(__file__).parent / "data" / "sphere_hard_walls_v0.0993.json").read_text()
    )
    (p,) = [p for p in stored if p.get("route") != "quasistatic" and p["v"] == hard["v"]]
    ex = p["extrapolation"]
    assert ex["n_modes"] == hard["n_modes"]
    alpha = np.array(ex["alpha"] + hard["alpha"])
    grid = np.vstack([np.array(ex["energy_loss_grid"]), np.array(hard["energy_loss_grid"])])
    shipped = combined_limit(alpha[:3], ex["n_modes"], grid[:3])
    assert shipped.epsilon == pytest.approx(p["epsilon"], abs=1e-12)
    without = math.sqrt(shipped.limit_err**2 - shipped.alpha_curvature**2) / (2 * shipped.epsilon)
    for walls in ([1, 2, 3], [2, 3, 4]):
        harder = combined_limit(alpha[walls], ex["n_modes"], grid[walls])
        moved = abs(harder.epsilon - shipped.epsilon)
        assert without < moved <= shipped.epsilon_err, (walls, moved, shipped.epsilon_err)
