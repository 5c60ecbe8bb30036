"""``restitution.si_law`` takes the mechanisms' options as keywords (issue 60, the start of issue
62): with a relaxation time it is the damped law at every speed, and agrees with the command
line's answer (``serve``) at the asked speeds within the stated error (the table interpolates
the damped law between the elastic law's computed speeds, where ``serve`` computes each speed
alone); a mechanism that makes no law at every speed is refused in one line."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

import restitution
from restitution.errors import InputError
from restitution.laws.mechanisms.base import (
    MechanismOption,
    register_mechanism,
    unregister_mechanism,
)
from restitution.laws.request import request
from restitution.laws.serve import serve

GLASS = dict(E=63e9, nu=0.24, rho=2500.0, shape="sphere", against="wall")
TAU_S, RADIUS = 1.2e-7, 1e-3


def test_without_options_it_is_the_elastic_law():
    from restitution.laws.si_law import si_law as elastic

    a, b = restitution.si_law(**GLASS), elastic(**GLASS)
    assert a.points([1.0]) == b.points([1.0])


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_the_damped_law_at_every_speed_agrees_with_the_answer():
    law = restitution.si_law(**GLASS, relaxation_time=TAU_S, radius=RADIUS)
    speeds = (0.1, 1.0, 10.0)
    direct = serve(request(**GLASS, speeds=speeds, relaxation_time=TAU_S, radius=RADIUS)).points
    for p, q in zip(law.points(list(speeds)), direct, strict=True):
        assert abs(p.epsilon - q.epsilon) <= max(p.epsilon_err, q.epsilon_err), (p, q)
        assert q.epsilon < 0.99  # damped: the elastic law is above 0.9999 at these speeds
    assert "viscous" in " ".join(law.to_dict(list(speeds))["mechanisms"])


@dataclass(frozen=True)
class _NoTable:
    """A mechanism that answers at asked speeds only (no ``table``)."""

    name: str = "no-table"
    words: str = "a mechanism without a law at every speed"
    rank: float = 6.0
    options: tuple = (MechanismOption("no_table", "--no-table", "A number.", "", True),)
    reads: tuple = ()
    slow_form: str = "none"

    def asked(self, r) -> bool:
        return r.option_value("no_table") is not None

    def check(self, r) -> None:
        return None

    def answer(self, r, si, note, progress):
        raise AssertionError("not asked at speeds here")


def test_a_mechanism_without_a_table_is_refused_in_one_line(cli, tmp_path):
    register_mechanism(_NoTable())
    try:
        with pytest.raises(InputError, match="no law at every speed is made yet") as caught:
            restitution.si_law(**GLASS, no_table=1.0)
        assert "\n" not in str(caught.value)
        assert "serve(" in str(caught.value)  # the call that answers at asked speeds
        # The command line's --plot refuses it before anything is computed.
        figure = tmp_path / "law.png"
        code, _, err = cli("law", "--E", "63e9", "--nu", "0.24", "--rho", "2500", "--shape",
                           "sphere", "--against", "wall", "--speed", "1", "--no-table", "1",
                           "--plot", str(figure))  # fmt: skip
        assert code == 2 and "--plot draws a law at every speed" in err, err
        assert not figure.exists()
    finally:
        unregister_mechanism("no-table")
