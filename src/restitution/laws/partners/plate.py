"""An elastic plate: a wall that bends (Zener's thin-plate model,
:class:`restitution.bodies.wall.Plate`, :mod:`restitution.quasistatic.plate`).

Units: the grain's reduced units (``E = rho = R = 1``, speeds in ``c``).

A request asks for it with the elastic wall's constants and ``--wall-thickness``; its law file
carries them as a half-space's do, with its name as their ``kind`` and the thickness. Zener's
model is elastic: no plastic contact is built on it. Its flexural waves dominate the slow
impacts' loss, ``~ v^(1/5)`` (the model's first order).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.bodies.wall import Plate
from restitution.errors import InputError
from restitution.laws.partners.base import register_partner
from restitution.laws.partners.half_space import ElasticHalfSpace

__all__ = ["KIND", "PLATE_QUASISTATIC_NOTE", "ElasticPlate"]

PLATE_QUASISTATIC_NOTE = (
    "from Zener's thin-plate model, not from collisions: Hertz's contact coupled to the plate's "
    "point impedance 8 sqrt(D rho h), solved as the coupled equation; the loss is the plate's "
    "flexural waves plus the ball's own vibrations driven by the same force history; its error "
    "an estimate of the model's neglected terms, judged by the finite elements (docs/walls.md)"
)
"""What ``quasistatic`` means for a sphere on a thin plate."""


@dataclass(frozen=True)
class ElasticPlate(ElasticHalfSpace):
    """An elastic plate (module docs)."""

    name: str = "plate"
    order: float = 25
    options: tuple[str, ...] = ("wall_thickness",)
    speed_meaning: str = "an elastic plate hit at speed w (v = w / c)"
    body: type | None = Plate
    quasistatic_note: str | None = PLATE_QUASISTATIC_NOTE
    model_words: str = "plate"
    served_further: str = "; a thicker plate loses less and is served further"
    slow: tuple[str, float, str] = (
        "power",
        0.2,
        "flexural waves of Zener's thin plate, ~ lambda ~ v^(1/5) (its first order)",
    )

    def matches(self, request) -> bool:
        return request.against == self.against and request.wall_thickness is not None

    def _what(self, wall: dict) -> str:
        return f"an elastic plate {wall['thickness']:.4g} ball radii thick"

    def contact(self, si):
        raise InputError(
            "plastic flow on a thin plate is not modelled (Zener's plate model is elastic); use "
            "a half-space or a rigid wall, or leave out the plastic options"
        )

    def half_space(self, law):
        return None


KIND = register_partner(ElasticPlate())
"""The elastic plate, registered."""
