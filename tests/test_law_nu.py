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
    assert np.isnan(loo[0]) and np.isnan(loo[-1])
    # Node 0.5 predicted from 0.1, 0.3, 0.7, 0.9 by an independent PCHIP call.
    others = [0.1, 0.3, 0.7, 0.9]
    predicted = PchipInterpolator(others, [exact(x, v) for x in others])(0.5)
    assert_allclose(loo[2], abs(predicted - exact(0.5, v)), rtol=1e-12)
    # The largest leave-one-out error of the grid at that speed.
    assert_allclose(served.interpolation_err(v), max(loo[1], loo[2], loo[3]), rtol=1e-12)


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
    assert f"restitution curve --nu {nu:g} --out DIR" in msg
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
