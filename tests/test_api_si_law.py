"""``restitution.si_law`` takes the mechanisms' options as keywords (issue 60, the start of issue
62): with a relaxation time it is the damped law at every speed, and agrees with the command
line's answer (``serve``) at the asked speeds within the stated error (the table interpolates
the damped law between the elastic law's computed speeds, where ``serve`` computes each speed
alone); a mechanism that makes no law at every speed is refused in one line."""

from __future__ import annotations

import pytest

import restitution
from restitution.errors import InputError
from restitution.laws.request import request
from restitution.laws.serve import serve

GLASS = dict(E=63e9, nu=0.24, rho=2500.0, shape="sphere", against="wall")
TAU_S, RADIUS = 1.2e-7, 1e-3


def test_without_options_it_is_the_elastic_law():
    from restitution.laws.si_law import si_law as elastic

    a, b = restitution.si_law(**GLASS), elastic(**GLASS)
    assert a.points([1.0]) == b.points([1.0])


def test_the_damped_law_at_every_speed_agrees_with_the_answer():
    law = restitution.si_law(**GLASS, relaxation_time=TAU_S, radius=RADIUS)
    speeds = (0.1, 1.0, 10.0)
    direct = serve(request(**GLASS, speeds=speeds, relaxation_time=TAU_S, radius=RADIUS)).points
    for p, q in zip(law.points(list(speeds)), direct, strict=True):
        assert abs(p.epsilon - q.epsilon) <= max(p.epsilon_err, q.epsilon_err), (p, q)
        assert q.epsilon < 0.99  # damped: the elastic law is above 0.9999 at these speeds
    assert "viscous" in " ".join(law.to_dict(list(speeds))["mechanisms"])


def test_a_mechanism_without_a_table_is_refused_in_one_line():
    with pytest.raises(InputError, match="no law at every speed is made yet"):
        restitution.si_law(**GLASS, yield_stress=1e9)
