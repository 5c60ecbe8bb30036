"""An elastic half-space: a thick block of another material that takes the waves it radiates
(:class:`restitution.bodies.wall.HalfSpace`, :mod:`restitution.quasistatic.half_space`).

Units: the grain's reduced units (``E = rho = R = 1``, speeds in ``c``).

A request asks for it with ``--against wall`` and the wall's constants (``--wall-E``,
``--wall-nu``, ``--wall-rho``); its law file carries the wall's constants under
:data:`~restitution.laws.partners.base.WALL_KEY` of its metadata, with its name as their
``kind``. Hertz's contact takes ``E*`` of both; the energy radiated into the wall is the
mechanism :data:`RADIATION`; at slow impacts that loss dominates, ``~ v^(3/5)`` (Hunter).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from restitution.bodies.wall import HalfSpace
from restitution.errors import InputError
from restitution.laws.partners.base import WALL_KEY, register_partner, stored_wall
from restitution.laws.partners.rigid_wall import rigid_contact

__all__ = ["ELASTIC_WALL_QUASISTATIC_NOTE", "KIND", "RADIATION", "ElasticHalfSpace"]

RADIATION = "wall"
"""The name of the mechanism of the waves radiated into an elastic wall (a half-space's or a
plate's: :class:`restitution.laws.mechanisms.waves.WallWaves`), as answers and law files list
it."""

ELASTIC_WALL_QUASISTATIC_NOTE = (
    "from the low-speed theory, not from collisions: Rayleigh's estimate of the energy left in "
    "the ball's modes by Hertz's pulse on the elastic wall, plus the energy radiated into the "
    "wall as elastic waves (Lamb's point-force radiation of the same pulse), each with its "
    "error (docs/walls.md)"
)
"""What ``quasistatic`` means for a sphere on an elastic half-space."""

_NO_2D_FORM = (
    "no slow-impact form is derived for a 2D body on an elastic wall; its exports stop at the "
    "law's slowest point"
)


@dataclass(frozen=True)
class ElasticHalfSpace:
    """An elastic half-space (module docs)."""

    name: str = "half-space"
    against: str = "wall"
    order: float = 30
    options: tuple[str, ...] = ("wall_E", "wall_nu", "wall_rho")
    speed_factor: float = 1.0
    speed_meaning: str = "an elastic half-space hit at speed w (v = w / c)"
    is_grain: bool = False
    body: type | None = HalfSpace
    loss: str | None = RADIATION
    quasistatic_note: str | None = ELASTIC_WALL_QUASISTATIC_NOTE
    route_words: str = "elastic wall"
    model_words: str = "half-space"
    served_further: str = ""
    split_head: str = "        loss in ball / wall"
    dem_mass: str = "a grain on a wall: 2 m"
    dem_mass_line: str = "2.0 * m;  // kg, effective mass of a grain on a wall (m2 infinite)"
    variance_factor: float = 1.0
    slow: tuple[str, float, str] = (
        "power", 0.6, "waves radiated into the half-space, ~ v^(3/5) (Hunter)"
    )  # fmt: skip

    def matches(self, request) -> bool:
        given = any(getattr(request, o) is not None for o in self.options)
        return request.against == self.against and given and request.wall_thickness is None

    def _what(self, wall: dict) -> str:
        return "an elastic half-space"

    def meaning(self, si) -> str:
        """The wall's constants and what the speed means."""
        wall = self.read(si.law)
        return (
            f"{self._what(wall)} (E_w/E = {wall['modulus_ratio']:.4g}, rho_w/rho = "
            f"{wall['density_ratio']:.4g}, nu_w = {wall['nu']:g}) hit at speed w (v = w / c)"
        )

    def contact(self, si):
        """Hertz's law of the sphere with ``E*`` of both bodies, and the sphere's mass."""
        law, mass = rigid_contact(si)
        hs = self.half_space(si.law)
        return replace(law, effective_modulus=hs.effective_modulus(float(si.law.nu))), mass

    def half_space(self, law):
        wall = self.read(law)
        return None if wall is None else HalfSpace(
            wall["modulus_ratio"], wall["density_ratio"], wall["nu"]
        )  # fmt: skip

    def slow_form(self, planar: bool):
        if planar:
            raise InputError(_NO_2D_FORM)
        return self.slow

    def read(self, law) -> dict | None:
        wall = stored_wall(law)
        # A record without its kind is a half-space's (the first elastic wall had no other).
        return wall if wall is not None and wall.get("kind", "half-space") == self.name else None

    def write(self, law, wall) -> None:
        law.metadata[WALL_KEY] = wall.to_dict()


KIND = register_partner(ElasticHalfSpace())
"""The elastic half-space, registered."""
