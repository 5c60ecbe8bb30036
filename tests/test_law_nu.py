"""Serving a law at any Poisson number: interpolation in nu and its leave-one-out error, tested
on synthetic laws whose exact epsilon(nu, v) is known."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.interpolate import PchipInterpolator

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_nu import NuInterpolatedLaw, law_for, shipped_nus

V = np.linspace(0.01, 0.3, 30)
GRID = [0.1, 0.3, 0.5, 0.7, 0.9]


def exact(nu, v):
    """A smooth synthetic epsilon(nu, v): monotone in v, curved in nu."""
    return 1.0 - (0.3 + 0.4 * nu**2) * v**0.8


def synthetic(nu, err=1e-4):
    return EpsilonLaw.from_points(nu, V, exact(nu, V), np.full(V.size, err))


def test_a_grid_value_is_served_as_it_is():
    laws = [synthetic(nu) for nu in GRID]
    assert law_for(0.5, laws=laws) is laws[2]
    assert law_for(0.5 + 5e-5, laws=laws) is laws[2]  # within NU_MATCH


def test_interpolation_error_covers_the_true_error_between_grid_values():
    laws = [synthetic(nu) for nu in GRID]
    v = np.array([0.05, 0.15, 0.25])
    for nu in (0.2, 0.42, 0.6, 0.85):
        served = law_for(nu, laws=laws)
        assert isinstance(served, NuInterpolatedLaw)
        true_err = np.abs(served.epsilon(v) - exact(nu, v))
        assert np.all(true_err <= served.interpolation_err(v))
        assert np.all(true_err <= served.epsilon_err(v))
        # Not a vacuous bound: the interpolation error is a real term, not a blanket number.
        assert np.all(served.interpolation_err(v) < 0.02)


def test_leave_one_out_is_the_prediction_without_the_node():
    laws = [synthetic(nu) for nu in GRID]
    served = law_for(0.42, laws=laws)
    v = 0.2
    loo = served.leave_one_out(v)[:, 0]
    # Node 0.5 predicted from 0.1, 0.3, 0.7, 0.9 by an independent PCHIP call.
    others = [0.1, 0.3, 0.7, 0.9]
    predicted = PchipInterpolator(others, [exact(x, v) for x in others])(0.5)
    assert_allclose(loo[2], abs(predicted - exact(0.5, v)), rtol=1e-12)
    assert np.isnan(loo[0]) and np.isnan(loo[-1])
    # Between 0.3 and 0.5 (t = 0.6): 4 t (1 - t) times the larger of the two nodes' errors at
    # v and at the multiples SPEED_WINDOW of it inside the laws' range (here 0.1 and 0.3).
    window = served.leave_one_out(np.array([v, 0.1, 0.3]))[1:3]
    assert_allclose(served.interpolation_err(v), 4 * 0.6 * 0.4 * window.max(), rtol=1e-12)
    assert window.max() > max(loo[1], loo[2])  # the envelope is wider than the value at v


def test_interpolation_error_is_continuous_and_vanishes_at_the_grid():
    """One rule whatever the distance to a grid law (issue 30: nu_2d = 0.3301 was served the
    0.33 law with its error while 0.3305 got a 6 times larger one): the error tends to the
    grid law's as nu tends to it, from either side."""
    laws = [synthetic(nu, err=1e-5) for nu in GRID]
    v = np.array([0.05, 0.2])
    node = law_for(0.5, laws=laws)
    for nu in (0.5 - 1.5e-4, 0.5 + 1.5e-4):  # just beyond NU_MATCH
        served = law_for(nu, laws=laws)
        assert isinstance(served, NuInterpolatedLaw)
        gap = abs(nu - 0.5) / 0.2  # t or 1 - t of the interval
        mid = law_for(0.4, laws=laws).interpolation_err(v)  # t = 0.5
        assert np.all(served.interpolation_err(v) <= 1.1 * 4 * gap * np.maximum(mid, 1e-300))
        # The rest of the error is the node's point error, interpolated in nu.
        point = np.sqrt(served.epsilon_err(v) ** 2 - served.interpolation_err(v) ** 2)
        assert_allclose(point, node.epsilon_err(v), rtol=1e-9)
        assert np.all(np.abs(served.epsilon(v) - exact(nu, v)) <= served.epsilon_err(v))
    # Growing from the node's error with the distance to it.
    errs = [law_for(nu, laws=laws).epsilon_err(v) for nu in (0.5 + 1.5e-4, 0.5 + 1e-3, 0.55)]
    assert np.all(node.epsilon_err(v) <= errs[0]) and np.all(errs[0] < errs[1])
    assert np.all(errs[1] < errs[2])


def test_error_adds_point_errors_in_quadrature():
    laws = [synthetic(nu, err=3e-3) for nu in GRID]
    served = law_for(0.6, laws=laws)
    v = np.array([0.1, 0.2])
    assert_allclose(served.epsilon_err(v), np.hypot(3e-3, served.interpolation_err(v)))


def test_interpolated_law_exposes_its_points():
    laws = [synthetic(nu) for nu in GRID]
    served = law_for(0.6, laws=laws)
    assert_allclose(served.v, V)
    assert_allclose(served.epsilon_points, served.epsilon(V))
    assert served.asymptotic_ok.all()
    assert served.valid_range == (pytest.approx(0.01), pytest.approx(0.3))


@pytest.mark.parametrize(
    "nu, grid, match",
    [
        (0.6, [0.1, 0.9], "fewer than three"),
        (0.95, GRID, "outside the given grid"),
        (0.05, GRID, "outside the given grid"),
    ],
)
def test_refusals_name_the_grid_and_the_command(nu, grid, match):
    laws = [synthetic(x) for x in grid]
    with pytest.raises(InputError, match=match) as info:
        law_for(nu, laws=laws)
    msg = str(info.value)
    assert f"restitution curve --nu {nu:g} --production --out DIR" in msg
    assert all(f"{x:g}" in msg for x in grid)


def test_shipped_laws_today():
    nus = shipped_nus()
    assert 0.33 in nus and 0.9 in nus
    assert law_for(0.33).nu == 0.33
    if len(nus) < 3:
        with pytest.raises(
            InputError, match=r"shipped laws.*grid: 0\.33, 0\.9.*restitution curve --nu 0\.5"
        ):
            law_for(0.5)


def test_law_file_must_match_nu(tmp_path):
    path = synthetic(0.3).to_json(tmp_path / "law_nu0.3.json")
    assert law_for(0.3, path=path).nu == 0.3
    with pytest.raises(InputError, match="is for nu_2d = 0.3, not 0.4"):
        law_for(0.4, path=path)


FIRST_GRID = (0.2, 0.33, 0.5, 0.7, 0.9)
"""The shipped grid before 0.25, 3/7, 0.6 and 0.8 joined it (production.SHIPPED_NUS)."""


@pytest.mark.parametrize("nu", [0.25, 0.4285714285714286, 0.6, 0.8])
def test_interpolation_covers_direct_laws_between_the_first_grid(nu):
    """Issue 28: the interpolated law's stated error against a direct computation. The laws at
    0.25, 3/7, 0.6 and 0.8 were computed with the production settings (they now ship); served
    from the first grid alone, the interpolation must lie within one combined error (its own
    and the direct law's) at least at the 68 % of the speeds a Gaussian error would, and within
    two at 95 % (measured with the shipped laws, their slowest points rerouted: 101 of the 102
    speeds within one, all within two)."""
    from restitution.laws.law_load import law

    direct = law(nu)
    served = law_for(nu, laws=[law(x) for x in FIRST_GRID])
    assert isinstance(served, NuInterpolatedLaw)
    v = direct.v[(direct.v <= served.valid_range[1]) & ~direct.quasistatic]  # the collisions
    diff = np.abs(served.epsilon(v) - direct.epsilon(v))
    sigma = diff / np.hypot(served.epsilon_err(v), direct.epsilon_err(v))
    assert np.mean(sigma <= 1.0) >= 0.68, sigma
    assert np.mean(sigma <= 2.0) >= 0.95, sigma
    # Conservative, not vacuous: the stated error is a few times the true one. Measured median
    # ratios 3.0, 8.8, 5.8 and 27.3 at nu = 0.6, 3/7, 0.8, 0.25 since the leave-one-out term is
    # the envelope over SPEED_WINDOW (3-19 with the value at v alone, which vanished where the
    # leave-one-out miss changes sign; 4-38 with the grid's largest leave-one-out error). The
    # limit was 25 before the envelope; the served standard deviation is 1.9-9.9 times the
    # miss (docs/errors.md).
    assert np.median(served.epsilon_err(v) / np.maximum(diff, 1e-12)) < 30


def test_first_grid_interpolation_coverage_over_all_direct_laws():
    """Pooled over the four direct laws: the measured coverage quoted in docs/materials.md."""
    from restitution.laws.law_load import law

    sigmas = []
    for nu in (0.25, 0.4285714285714286, 0.6, 0.8):
        direct = law(nu)
        served = law_for(nu, laws=[law(x) for x in FIRST_GRID])
        v = direct.v[(direct.v <= served.valid_range[1]) & ~direct.quasistatic]
        diff = np.abs(served.epsilon(v) - direct.epsilon(v))
        sigmas += list(diff / np.hypot(served.epsilon_err(v), direct.epsilon_err(v)))
    sigmas = np.array(sigmas)
    # 22 production speeds of each direct law and its refined points (3, 3, 5, 3; issue 45).
    assert sigmas.size == 88 + 14
    assert np.mean(sigmas <= 1.0) >= 0.9 and np.all(sigmas <= 2.0)


def test_first_grid_interpolation_coverage_of_the_low_speed_points():
    """The same check at the 400 low-speed points of the four direct laws (the slow-impact
    model, v = 1e-7 - 0.93e-4), pooled: within one combined error at least at 68 %, within two
    at 95 % (measured: 85 % and 96.8 %). Not at every nu: at 0.8 only 90 % lie within two and
    the worst is 6.5 combined errors (v = 2.75e-6; docs/materials.md)."""
    from restitution.laws.law_load import law

    sigmas = []
    for nu in (0.25, 0.4285714285714286, 0.6, 0.8):
        direct = law(nu)
        served = law_for(nu, laws=[law(x) for x in FIRST_GRID])
        v = direct.v[direct.quasistatic]
        diff = np.abs(served.epsilon(v) - direct.epsilon(v))
        sigmas += list(diff / np.hypot(served.epsilon_err(v), direct.epsilon_err(v)))
    sigmas = np.array(sigmas)
    assert sigmas.size == 400
    assert np.mean(sigmas <= 1.0) >= 0.68 and np.mean(sigmas <= 2.0) >= 0.95


def test_outside_nan_gives_nan_outside_and_the_value_inside():
    """Issue 62: a sphere between the shipped laws (glass, nu = 0.2481) asked at speeds partly
    outside its range with outside="nan" raised scipy's "`y` must contain only finite values";
    now the speeds outside are nan and those inside are what each gives alone (one code path:
    the same numbers)."""
    import restitution

    law = restitution.si_law(63e9, 0.2481, 2500, "sphere", "wall").law
    v = np.array([1e-9, 1e-4, 1e-2, 10.0])  # below, inside, inside, above (units of c)
    eps, err = law.epsilon(v, outside="nan"), law.epsilon_err(v, outside="nan")
    assert np.isnan(eps[[0, 3]]).all() and np.isnan(err[[0, 3]]).all()
    for i in (1, 2):
        assert eps[i] == law.epsilon(v[i]) and err[i] == law.epsilon_err(v[i])
    with pytest.raises(InputError):
        law.epsilon(v)  # the default still refuses a speed outside
