"""The mechanisms the elastic law holds: the elastic waves and vibrations of the bodies, and the
waves radiated into an elastic wall.

Units: none (declarations).

Both are of rank 0: every answer contains them, and no option asks for them (an elastic wall is
a partner, :mod:`restitution.laws.routes.wall`).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.laws.mechanisms.base import register_mechanism
from restitution.laws.partners.half_space import RADIATION

__all__ = ["ElasticWaves", "WallWaves"]


@dataclass(frozen=True)
class ElasticWaves:
    """The elastic waves and vibrations of the bodies: the elastic law itself."""

    name: str = "waves"
    words: str = "elastic waves and vibrations of the bodies (the elastic law)"
    rank: float = 0.0
    options: tuple = ()
    reads: tuple = ()
    slow_form: str = (
        "1 - epsilon ~ v for a 3D body (Rayleigh's estimate on Hertz's pulse), ~ 1/ln^2(1/v) "
        "for a 2D one (restitution.laws.exports.below)"
    )

    def asked(self, request) -> bool:
        return True

    def check(self, request) -> None:
        return None

    def answer(self, request, si, note, progress: bool):
        raise NotImplementedError("the elastic law holds the waves; serve answers without it")


@dataclass(frozen=True)
class WallWaves:
    """The elastic waves radiated into an elastic wall (a half-space or a plate)."""

    name: str = RADIATION  # the loss the elastic walls' partner kinds declare
    words: str = "elastic waves radiated into the wall"
    rank: float = 0.0
    options: tuple = ()
    reads: tuple = ()
    slow_form: str = (
        "1 - epsilon ~ v^(3/5) into a half-space (Hunter), ~ v^(1/5) into a thin plate (Zener)"
    )

    def asked(self, request) -> bool:
        return request.elastic_wall is not None

    def check(self, request) -> None:
        return None

    def answer(self, request, si, note, progress: bool):
        raise NotImplementedError("the elastic wall's law holds its waves")


register_mechanism(ElasticWaves())
register_mechanism(WallWaves())
