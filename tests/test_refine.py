"""Speeds added where epsilon(v) turns between a law's computed points (issue 45, item 1).

The scan (:func:`restitution.laws.making.refine.turning_speeds`) compares PCHIP with a cubic
spline in ``ln v`` inside every interval; :func:`refine` computes a point where they differ by
more than
the points' errors, with the neighbouring point's settings. Checked: the scan on laws whose
shape is known (a line: nothing; a vertex between two points: that interval, near the vertex),
the refinement of a small real disk law (the new points are the production route's values at
their speeds, with their neighbours' settings), and the shipped laws after refinement.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.making.refine import neighbour_settings, refine, turning_speeds
from restitution.limits.curves import compute_curves, epsilon_at
from restitution.limits.sweep import defaults_for

V = np.geomspace(0.01, 0.1, 8)


def _law(eps, err=1e-7) -> EpsilonLaw:
    return EpsilonLaw.from_points(0.33, V, eps, np.full(V.size, err))


def test_a_smooth_monotone_law_is_left_alone():
    # epsilon falls by 0.023 over a decade, straight in ln v: PCHIP (in v) and the spline (in
    # ln v) differ by at most 3.7e-5, in the end intervals; points errors of 1e-4 flag nothing.
    assert turning_speeds(_law(0.99 - 0.01 * np.log(V), err=1e-4)) == []
    assert max(r for _, r in turning_speeds(_law(0.99 - 0.01 * np.log(V), err=1e-6))) < 40


def test_a_vertex_between_two_points_is_found_near_it():
    # A parabola in ln v with its maximum between the 4th and 5th speeds.
    top = float(np.sqrt(V[3] * V[4]) * 1.05)
    eps = 0.99 - 0.002 * (np.log(V) - np.log(top)) ** 2
    flagged = turning_speeds(_law(eps))
    inside = [v for v, _ in flagged if V[3] < v < V[4]]
    assert len(inside) == 1
    assert abs(np.log(inside[0] / top)) < 0.25 * np.log(V[4] / V[3])
    # A point error larger than the difference flags nothing there.
    assert not [v for v, _ in turning_speeds(_law(eps, err=1e-2)) if V[3] < v < V[4]]


def test_scan_refusals():
    served = _law(0.99 - 0.01 * V)
    with pytest.raises(InputError, match="per_interval"):
        turning_speeds(served, per_interval=0)
    with pytest.raises(InputError, match="factor"):
        turning_speeds(served, factor=-1.0)
    with pytest.raises(InputError, match="rounds"):
        refine(served, rounds=-1)


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    """A real disk law of few modes (five speeds, 0.05-0.3) and its store."""
    root = tmp_path_factory.mktemp("refine")
    settings = replace(
        defaults_for("disk"), velocities=(0.05, 0.08, 0.13, 0.2, 0.3), n_modes=(40, 60, 80)
    )
    store = root / "store.sqlite"
    curve = compute_curves([0.33], settings, store=store, progress=False)[0.33]
    return EpsilonLaw.from_curve(curve), store


def test_refined_points_are_the_production_route_at_their_speeds(tiny):
    base, store = tiny
    flagged = turning_speeds(base, factor=1e-9)
    assert flagged  # a law of few modes wiggles: the scan finds something to add
    refined = refine(base, factor=1e-9, store=store)
    new = sorted(set(refined.v.tolist()) - set(base.v.tolist()))
    assert new == sorted(v for v, _ in flagged)
    assert refined.metadata["refined"]["rounds"][0]["speeds"] == [v for v, _ in flagged]
    records = {r["v"]: r for r in refined.metadata["points"]}
    for v in new:
        settings = neighbour_settings(base, v)
        stored = dict(records[v]["settings"])
        assert v in stored.pop("velocities")  # the group's speeds, as in from_curves
        assert stored == {k: x for k, x in settings.to_dict().items() if k != "velocities"}
        direct = epsilon_at(0.33, v, settings=settings, store=store)
        assert records[v]["epsilon"] == direct.epsilon
        assert records[v]["epsilon_err"] == direct.epsilon_err
    # The computed points stay as they were: stored exactly, served by PCHIP at its nodes to
    # within its rounding (one ulp off with scipy 1.17.1).
    refined_points = dict(zip(refined.v.tolist(), refined.epsilon_points.tolist(), strict=True))
    for v, e in zip(base.v, base.epsilon_points, strict=True):
        assert refined_points[float(v)] == e
        assert float(refined.epsilon(v)) == pytest.approx(e, rel=4 * np.finfo(float).eps)


def test_neighbour_settings_refuse_speeds_outside_the_points(tiny):
    base, _ = tiny
    with pytest.raises(InputError, match="not strictly between"):
        neighbour_settings(base, 0.01)
    with pytest.raises(InputError, match="not strictly between"):
        neighbour_settings(base, 0.08)


@pytest.mark.parametrize(
    ("geometry", "nu"), [("sphere", 0.3), ("disk", 0.33)], ids=["sphere", "disk"]
)
def test_shipped_laws_record_their_refinement(geometry, nu):
    """The shipped laws carry the points of one round of refinement, each at a speed its scan
    flagged, with the settings of a neighbour."""
    served = law(nu, geometry=geometry)
    refined = served.metadata.get("refined")
    assert refined and refined["rounds"]
    speeds = refined["rounds"][0]["speeds"]
    assert set(speeds) <= set(served.v.tolist())
    records = {r["v"]: r for r in served.metadata["points"]}
    modal = served.v[~served.quasistatic]
    # A refined point computed again by another route later (issue 65) is listed there.
    rerouted = {c["v"] for c in (served.metadata.get("rerouted") or {}).get("points", [])}
    assert all(records[v].get("route") in (None, "modal") for v in set(speeds) - rerouted)
    for v in sorted(set(speeds) - rerouted):
        j = int(np.searchsorted(modal, v))
        neighbours = [records[float(modal[j - 1])], records[float(modal[j + 1])]]
        settings = {k: x for k, x in records[v]["settings"].items() if k != "velocities"}
        assert any(
            settings == {k: x for k, x in n.get("settings", {}).items() if k != "velocities"}
            for n in neighbours
        ), v
