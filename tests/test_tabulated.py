"""A mechanism's law at every speed, tabulated once (restitution.laws.tabulated, issue 62): the
table's speeds are the elastic law's own, its value there is the mechanism's, its stated error
covers what the interpolation misses at speeds between its own, and it stops where the
mechanism gives no rebound.

The default tests tabulate a synthetic mechanism (a closed form on the elastic law, so that the
truth is known at every speed and costs nothing); the slow one tabulates plastic flow itself and
checks it against the mechanism computed at speeds between the table's (the command line's
numbers, ``serve``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.law_point import LOG_V
from restitution.laws.si_law import si_law
from restitution.laws.tabulated import GAP_FACTOR, coverage, mechanism_table, table_speeds

STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall")
YIELD_M_S = 0.05
STOP_M_S = 80.0


@dataclass(frozen=True)
class _Point:
    epsilon: float | None
    epsilon_err: float | None
    status: str = "quasistatic"
    note: str = ""
    parts: tuple = ()


def _synthetic(si):
    """A plastic-like mechanism on the elastic law: epsilon times ``(1 + (w / w_y)^2)^(-1/8)``
    (a knee at ``w_y``, then ``w^(-1/4)`` as Thornton's law), no rebound from
    :data:`STOP_M_S` on; its error the elastic law's."""

    def f(w: float) -> float:
        return float(si.epsilon(w)) * (1.0 + (w / YIELD_M_S) ** 2) ** -0.125

    def points_at(ws):
        out = []
        for w in ws:
            if w >= STOP_M_S:
                out.append(_Point(None, None, "outside", "contact: crushed; the rest"))
            else:
                out.append(_Point(f(w), float(si.epsilon_err(w)), parts=(("loss_plastic", 0.1),)))
        return out

    return f, points_at


@pytest.fixture(scope="module")
def table():
    si = si_law(**STEEL)
    f, points_at = _synthetic(si)
    notes = []
    t = mechanism_table(si, points_at, words="a knee", mechanisms=["waves", "knee"],
                        parameters={"w_y": YIELD_M_S}, seconds_per_speed=0.0,
                        note=notes.append)  # fmt: skip
    return si, f, points_at, t, notes


def test_table_speeds_are_the_elastic_laws_own_four_a_decade():
    si = si_law(**STEEL)
    v = np.asarray(si.law.v, dtype=float)
    idx = table_speeds(v, 4)
    assert idx[0] == 0 and idx[-1] == v.size - 1
    assert np.all(np.diff(idx) > 0)
    ratios = np.diff(np.log10(v[idx]))
    # Nearest computed points to a grid of 0.25 decades: the law's points lie 1.2 apart or
    # closer (the sphere's grid), so no step strays by more than a spacing of the law.
    assert np.all(np.abs(ratios - 0.25) < 0.2), ratios


def test_the_tables_points_are_the_mechanisms_and_its_stops_where_it_gives_no_rebound(table):
    si, f, _, t, notes = table
    w = np.asarray(t.law.v, dtype=float) * t.speed_scale_m_s
    assert w[-1] < STOP_M_S
    got = t.epsilon(w)
    want = np.array([f(x) for x in w])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-13)  # one code path: round-off
    assert np.all(np.isin(t.law.v, si.law.v))  # the elastic law's own speeds
    assert t.law.metadata["interpolate_in"] == LOG_V
    assert t.law.metadata["mechanisms"] == ["waves", "knee"]
    assert "served up to" in t.law.metadata["source"] and "crushed" in t.law.metadata["source"]
    assert math.isnan(t.epsilon(STOP_M_S, outside="nan"))
    assert "tabulated now at" in notes[0]
    assert t.law._records()[3]["loss_plastic"] == 0.1  # the parts kept per point
    parts = t.losses([w[1], np.sqrt(w[1] * w[2]), 2.0 * STOP_M_S])
    np.testing.assert_allclose(parts["loss_plastic"][:2], 0.1, rtol=1e-15)
    assert np.isnan(parts["loss_plastic"][2]) and np.isnan(parts["loss_total"][2])


def test_statuses_at_the_table_points_are_the_elastic_laws(table):
    si, _, _, t, _ = table
    w = np.asarray(t.law.v, dtype=float) * t.speed_scale_m_s
    for p, q in zip(t.points(w), si.points(w), strict=True):
        assert p.status == q.status, (p.speed_m_s, p.status, q.status)


def test_the_stated_error_covers_the_interpolation_between_table_speeds(table):
    """At 3 speeds inside every interval (none of them the middles the table measured at), the
    table's miss of the closed form lies within its stated error; the measured part of that
    error is GAP_FACTOR times a measured miss, so the largest ratio is reported too."""
    _, f, points_at, t, _ = table
    v = np.asarray(t.law.v, dtype=float)
    frac = np.array([0.17, 0.38, 0.81])
    between = (v[:-1, None] * (v[1:, None] / v[:-1, None]) ** frac[None, :]).ravel()
    c = coverage(t, points_at, between * t.speed_scale_m_s)
    assert len(c.misses) == between.size
    assert c.covered == 1.0, (c.largest_ratio, c)
    # The error is not inflated without bound either: somewhere the miss is a visible part of it.
    assert c.largest_ratio > 0.05 / GAP_FACTOR


def test_fewer_than_two_rebounds_are_refused_in_one_line():
    si = si_law(**STEEL)

    def never(ws):
        return [_Point(None, None, "outside", "no rebound; losses exceed") for _ in ws]

    with pytest.raises(InputError, match="fewer than two speeds") as caught:
        mechanism_table(si, never, words="nothing", mechanisms=["waves"], parameters={},
                        seconds_per_speed=0.0)  # fmt: skip
    assert "\n" not in str(caught.value)


@pytest.mark.slow
def test_the_plastic_table_covers_the_command_lines_answers_between_its_speeds():
    """Plastic steel (yield stress 1 GPa, R 1 mm) tabulated by ``si_law`` against the
    mechanism computed at speeds between the table's (what ``restitution law`` answers there).
    Measured when written: 19 speeds from 6 mm/s to 170 m/s, all covered, the largest miss 0.19
    of the stated error, the median 0.045 (0.49 at most when the table held the computed
    speeds alone, before the closed form, restitution.laws.shaped_table)."""
    import restitution
    from restitution.laws.request import request
    from restitution.laws.serve import serve

    t = restitution.si_law(**STEEL, yield_stress=1e9, radius=1e-3)
    answer = serve(request(**STEEL, yield_stress=1e9, radius=1e-3, speeds=[1.0]))
    # Between the speeds where the pulse was computed (the table's other records are the
    # elastic law's speeds between them, the closed form there and the rest interpolated).
    v = np.array([r["v"] for r in t.law.metadata["points"] if r["computed"]])
    assert v.size < t.law.v.size
    between = np.exp(np.log(v[:-1]) + 0.27 * np.log(v[1:] / v[:-1])) * t.speed_scale_m_s
    c = coverage(t, answer.by.points, between)
    assert len(c.misses) >= 15
    assert c.covered == 1.0, c
    assert "plastic" in t.law.metadata["mechanisms"]
