"""Served values between a law's computed points keep their stated error (issue 45, item 1).

PCHIP makes no extremum between two points; a law's served error therefore carries an
interpolation term (:meth:`EpsilonLaw.interpolation_err`). Checked here: the term's
arithmetic on laws whose interpolation error is known (a straight line: none; a parabola with
its vertex between two points: PCHIP misses it), and the coverage of the shipped laws' served
errors against epsilon computed directly between their points (the stored comparisons of
``python -m restitution.laws.making.between``; ``-m slow`` recomputes a sample of them).
"""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.law_point import leave_one_out

V = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07])


def _law(eps) -> EpsilonLaw:
    return EpsilonLaw.from_points(0.33, V, eps, np.full(V.size, 1e-9))


def test_a_straight_law_has_no_interpolation_error():
    served = _law(0.99 - 0.5 * V)
    between = np.linspace(V[0], V[-1], 61)
    assert np.max(served.interpolation_err(between)) < 1e-12
    assert np.max(np.abs(served.epsilon_err(between) - 1e-9)) < 1e-12


def test_the_term_is_zero_at_computed_points_and_covers_a_missed_vertex():
    # A parabola whose maximum (at v = 0.0355) lies between two points: PCHIP cannot reach it.
    truth = lambda v: 0.99 - 20.0 * (v - 0.0355) ** 2  # noqa: E731
    served = _law(truth(V))
    assert np.all(served.interpolation_err(V) == 0.0)
    fine = np.linspace(V[0], V[-1], 601)
    miss = np.abs(served.epsilon(fine) - truth(fine))
    assert miss.max() > 1e-6  # PCHIP does miss it ...
    assert np.all(miss <= served.epsilon_err(fine) + 1e-15)  # ... within the served error


def test_leave_one_out_is_the_prediction_without_the_point():
    eps = 0.99 - 20.0 * (V - 0.0355) ** 2
    loo = leave_one_out(V, eps)
    from scipy.interpolate import PchipInterpolator

    rest = np.delete(np.arange(V.size), 3)
    assert loo[3] == abs(float(PchipInterpolator(V[rest], eps[rest])(V[3])) - eps[3])
    assert loo[0] == loo[1] and loo[-1] == loo[-2]


def test_the_shipped_sphere_law_resolves_its_maximum():
    # An independent modal code put a maximum of the sphere's epsilon(v) at nu = 0.3 near
    # v = 0.0203, between the computed 0.0189 and 0.0228 (issue 45). The refinement scan
    # (restitution.laws.making.refine) added a point in that interval; the served value at the
    # direct maximum (0.999265 at v = 0.0206, tests/data/between_sphere_nu0.3.json) now
    # misses by less than a fifth of what PCHIP between 0.0189 and 0.0228 missed (1.6e-4).
    served = law(0.3, geometry="sphere")
    assert np.any((served.v > 0.0189) & (served.v < 0.0228))
    d = json.loads((Path(__file__).parent / "data" / "between_sphere_nu0.3.json").read_text())
    top = max(d["rows"], key=lambda r: r["direct"])
    assert abs(top["v"] - 0.0206) < 5e-4
    miss = abs(float(served.epsilon(top["v"])) - top["direct"])
    assert miss < 0.2 * 1.6e-4
    assert miss <= float(served.epsilon_err(top["v"]))


# -- coverage against direct computations ---------------------------------------------------

_DATA = Path(__file__).parent / "data"
COMPARISONS = sorted(_DATA.glob("between_*.json"))


def _rows(path: Path) -> tuple[EpsilonLaw, list[dict]]:
    d = json.loads(path.read_text())
    return law(d["nu"], geometry=d["geometry"]), d["rows"]


def test_there_are_comparisons_of_a_disk_and_a_sphere_law():
    names = {p.name for p in COMPARISONS}
    assert any(n.startswith("between_disk") for n in names), names
    assert any(n.startswith("between_sphere") for n in names), names


@pytest.mark.parametrize("path", COMPARISONS, ids=lambda p: p.stem)
def test_served_errors_cover_the_direct_values_between_points(path):
    """The served value is within one served error of the direct value at >= 68 % of the
    speeds, within two at >= 95 %; served values and errors are the current code's (the
    direct values are the file's, computed by the production route)."""
    served, rows = _rows(path)
    z = []
    for r in rows:
        diff = abs(float(served.epsilon(r["v"])) - r["direct"])
        z.append(diff / float(np.hypot(served.epsilon_err(r["v"]), r["direct_err"])))
    z = np.array(z)
    assert z.size >= 8
    assert np.mean(z <= 1.0) >= 0.68, sorted(z)
    assert np.mean(z <= 2.0) >= 0.95, sorted(z)


@pytest.mark.slow
@pytest.mark.parametrize("path", COMPARISONS, ids=lambda p: p.stem)
def test_a_stored_direct_value_is_what_the_production_route_gives(path, tmp_path):
    """The cheapest-looking stored direct value (the fastest speed), recomputed now, agrees
    with the file within its own error (a regression check of the stored values)."""
    from restitution.laws.making.between import direct_points

    d = json.loads(path.read_text())
    row = max(d["rows"], key=lambda r: r["v"])
    (p,) = direct_points(d["geometry"], d["nu"], [row["v"]], store=tmp_path / "store.sqlite")
    assert abs(p.epsilon - row["direct"]) <= 0.1 * row["direct_err"]


def test_the_shipped_data_folder_is_not_the_comparisons_folder():
    shipped = {p.name for p in resources.files("restitution.laws").joinpath("data").iterdir()}
    assert not any(n.startswith("between_") for n in shipped)
