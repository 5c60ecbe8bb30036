"""A second grain: identical, or of another size and material (a
:class:`~restitution.bodies.pair.partner.Partner` of the same body kind).

Units: the grain's reduced units (``E = rho = R = 1`` of this grain, speeds in ``c``).

Two identical grains at relative normal speed ``w`` each move at ``w / 2`` towards the contact
plane, which is the rigid wall's problem at ``v = w / (2 c)``: they are served by the law on
the wall (speed scale 2). Grains of another size or material are served by the pair's own law,
whose ``v`` is the relative speed (``law.partner``; the answer's ``k`` is then 1). Its options
are the partner's radius ratio and material; its law files carry the pair in the law's own
``partner`` field (:mod:`restitution.laws.law_file`), not here.
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.bodies.pair.partner import Partner
from restitution.laws.partners.base import NoWall, register_partner
from restitution.laws.partners.rigid_wall import rigid_contact

__all__ = ["KIND", "GrainPartner"]


@dataclass(frozen=True)
class GrainPartner(NoWall):
    """A second grain (module docs)."""

    name: str = "grain"
    against: str = "grain"
    order: float = 20
    options: tuple[str, ...] = ("partner_radius_ratio", "partner_E", "partner_nu", "partner_rho")
    speed_factor: float = 2.0
    speed_meaning: str = "an identical grain, relative normal speed w (v = w / (2 c))"
    is_grain: bool = True
    body: type | None = Partner
    loss: str | None = None
    quasistatic_note: str | None = None
    route_words: str = "pair"
    model_words: str = "pair"
    served_further: str = ""
    split_head: str = "        loss in grain 1 / 2"
    dem_mass: str = "two identical grains: m"
    dem_mass_line: str = "m;  // kg, effective mass of two identical grains"
    variance_factor: float = 2.0

    def matches(self, request) -> bool:
        return request.against == self.against

    def meaning(self, si) -> str:
        """What the SI speed of ``si`` means: an identical grain's, or the pair law's."""
        pair = si.law.partner
        if pair is None:
            return self.speed_meaning
        if si.partner_grain is not None:
            g = si.partner_grain
            return (
                f"a grain of another material (E = {g.E:.4g} Pa, nu = {g.nu:g}, rho = "
                f"{g.rho:.4g} kg/m^3) {pair.radius_ratio:g} times as large, relative normal "
                "speed w (v = w / c, c of this grain; the pair's law)"
            )
        return (
            f"a grain of the same material {pair.radius_ratio:g} times as large, relative "
            "normal speed w (v = w / c, the pair's law)"
        )

    def contact(self, si):
        """The pair's Hertz law and reduced mass; identical spheres are served as the wall at
        ``w / 2``, so theirs is the rigid wall's."""
        from restitution.bodies.sphere.kind import KIND as SPHERE
        from restitution.quasistatic.pulse import pair_contact_for

        pair = si.law.partner
        if pair is not None:
            return pair_contact_for(SPHERE.geometry, float(si.law.nu), pair)
        return rigid_contact(si)


KIND = register_partner(GrainPartner())
"""The second grain, registered."""
