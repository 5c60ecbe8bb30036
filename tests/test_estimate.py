"""One result type for an epsilon with its error (issue 40): every route answers an Estimate.

Each route's own numbers are read back through its ``estimate`` (nothing is recomputed: these
check the mapping of each route's fields and verdict onto one status vocabulary, and that every
status that asks something of the user says what).
"""

from __future__ import annotations

import math

import pytest

from restitution.estimate import Estimate, estimate_of
from restitution.fem.reference import load_reference
from restitution.laws.law_load import law
from restitution.laws.si_law import si_law
from restitution.status import ASYMPTOTIC, Status


def test_every_status_that_asks_something_says_what():
    for status in Status:
        if status in ASYMPTOTIC:
            assert status.advice is None and status.asymptotic
        else:
            assert status.advice and "\n" not in status.advice and not status.asymptotic


def test_an_estimate_without_a_finite_value_has_none():
    e = Estimate(math.nan, math.inf, "outside", "above the range")
    assert e.epsilon is None and e.epsilon_err is None and e.status is Status.OUTSIDE
    assert e.to_dict()["advice"] == Status.OUTSIDE.advice and not e.covers(0.9)
    assert estimate_of(0.9, 0.01, False, "curved").status == Status.NOT_ASYMPTOTIC
    assert estimate_of(0.9, 0.01, True, "ignored").message == ""
    assert Estimate(0.9, 0.01, "ok").covers(0.905) and not Estimate(0.9, 0.01, "ok").covers(0.92)


def test_law_points_and_si_points_answer_their_own_status():
    served = law(0.33)
    for p in served.points:
        e = p.estimate
        assert (e.epsilon, e.epsilon_err, e.status) == (p.epsilon, p.epsilon_err, p.status)
    s = si_law(210e9, 0.3, 7850, "sphere", "wall")
    for p in s.points([0.01, 1.0, 1e5]):
        e = p.estimate
        assert e.status == p.status and e.epsilon == p.epsilon
    assert [p.estimate.status for p in s.points([0.01, 1e5])] == ["quasistatic", "outside"]


@pytest.mark.parametrize("geometry", ["disk", "sphere"])
def test_fem_reference_points_map_their_flag(geometry):
    points = load_reference(geometry=geometry)
    assert points
    for p in points:
        assert p.estimate.asymptotic == bool(p.asymptotic_ok)
        assert p.estimate.epsilon == pytest.approx(p.epsilon, rel=0, abs=0)


def test_low_speed_routes_answer_quasistatic():
    from restitution import get_modes
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES, low_speed_loss
    from restitution.quasistatic.slow_disk import slow_loss, slow_modes

    r = low_speed_loss(get_modes(0.3, LOW_SPEED_MODES, geometry="sphere"), 1e-4)
    d = slow_loss(slow_modes(0.33), 1e-5)
    for route in (r, d):
        e = route.estimate
        assert e.status == Status.QUASISTATIC and not e.asymptotic
        assert (e.epsilon, e.epsilon_err) == (route.epsilon, route.epsilon_err)
