"""The rigid flat wall: the model's partner (the paper's wall).

Units: the grain's reduced units (``E = rho = R = 1``, speeds in ``c``).

The wall does not move and takes no energy: ``v = w / c`` with ``w`` the speed towards it. Its
contact is the body's own Hertz law on a rigid plane; it has no options and no record in a law
file (a law without one is a law on the rigid wall).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.laws.partners.base import NoWall, register_partner

__all__ = ["KIND", "RigidWall", "rigid_contact"]

_WALL_OPTIONS = ("wall_E", "wall_nu", "wall_rho", "wall_thickness")
"""The request fields of an elastic wall: none given asks for the rigid one."""


def rigid_contact(si):
    """``(Hertz's law, mass)`` of a sphere of ``si`` on a rigid wall, reduced units."""
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law

    return sphere_contact_law(float(si.law.nu)), SPHERE_MASS


@dataclass(frozen=True)
class RigidWall(NoWall):
    """The rigid flat wall (module docs)."""

    name: str = "wall"
    against: str = "wall"
    order: float = 10
    options: tuple[str, ...] = ()
    speed_factor: float = 1.0
    speed_meaning: str = "a rigid flat wall hit at speed w (v = w / c)"
    is_grain: bool = False
    body: type | None = None
    loss: str | None = None
    quasistatic_note: str | None = None
    route_words: str = "rigid wall"
    model_words: str = "wall"
    served_further: str = ""
    split_head: str = "        loss in ball / wall"
    dem_mass: str = "a grain on a wall: 2 m"
    dem_mass_line: str = "2.0 * m;  // kg, effective mass of a grain on a wall (m2 infinite)"
    variance_factor: float = 1.0

    def matches(self, request) -> bool:
        return request.against == self.against and all(
            getattr(request, o) is None for o in _WALL_OPTIONS
        )

    def meaning(self, si) -> str:
        """What the SI speed of the answer ``si`` means."""
        return self.speed_meaning

    def contact(self, si):
        return rigid_contact(si)


KIND = register_partner(RigidWall())
"""The rigid wall, registered."""
