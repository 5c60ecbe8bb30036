"""The MercuryDPM snippet (C++): a ``LinearViscoelasticSpecies`` per particle type.

Density in kg/m^3, epsilon with the user's collision time ``tc`` (s) and the effective mass
(kg) it needs. Registers itself as the DEM target ``mercurydpm`` (``mercurydpm.cpp``).
"""

from __future__ import annotations

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import _comment, _constants, _particles
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "mercurydpm_snippet"]


def _mass_ratio(s: SILaw, r: float) -> str:
    """``m2 = ... m1`` of two grains with radius ratio ``r`` (and, of two materials, density
    ratio ``rho2 / rho1``)."""
    if s.partner_grain is not None:
        q = s.partner_grain.rho / s.grain.rho
        return (
            f"m2 = r^2 (rho2/rho1) m1 = {r**2 * q:.6g} m1 for disks of one thickness (cylinders "
            "of one length)"
        )
    if s.grain.kind.dimension == 3:
        return f"m2 = r^3 m1 = {r**3:.6g} m1 for {s.grain.body}s"
    return f"m2 = r^2 m1 = {r**2:.6g} m1 for disks of one thickness (cylinders of one length)"


def _mercury_mass(s: SILaw, c: Constant | TypePairs) -> str:
    """What MercuryDPM's ``mass`` argument must be for this partner and body.

    ``setCollisionTimeAndRestitutionCoefficient(tc, eps, mass)`` takes the effective mass
    ``2 m1 m2 / (m1 + m2)`` (MercuryDPM's ``LinearViscoelasticNormalSpecies``): the particle
    mass ``m`` for two identical grains, ``2 m`` for a grain against a wall (``m2`` infinite),
    ``2 m1 m2 / (m1 + m2)`` for a small and a large grain.
    """
    head = "mass: the effective mass 2 m1 m2 / (m1 + m2) (kg)"
    pair = s.law.partner
    if pair is not None:
        ratio = _mass_ratio(s, pair.radius_ratio)
        which = "type 1 and type 2" if s.partner_grain is not None else "a small and a large"
        both = f"m1, m2 the masses of {which} particle ({ratio})"
        if isinstance(c, TypePairs):
            each = "m1 for 1-1, m2 for 2-2, 2 m1 m2 / (m1 + m2) for 1-2"
            return f"{head} of each type pair: {each}; {both}"
        return f"{head} of the small and the large grain; {both}"
    m = "m = 4/3 pi rho R^3" if s.grain.kind.dimension == 3 else "m the particle mass"
    which = "two identical grains: m" if s.against == "grain" else "a grain on a wall: 2 m"
    return f"{head}; for {which}, {m}"


def _mercury_species(name: str, rho: float, eps: float, mass: str) -> list[str]:
    return [
        f"auto {name} = speciesHandler.copyAndAddObject(LinearViscoelasticSpecies());",
        f"{name}->setDensity({rho:.8g});",
        f"{name}->setCollisionTimeAndRestitutionCoefficient(tc, {eps:.8f}, {mass});",
    ]


def mercurydpm_snippet(s: SILaw, c: Constant | TypePairs) -> str:
    """C++ lines for MercuryDPM (``LinearViscoelasticSpecies``; choose the collision time). A
    :class:`TypePairs` gives a species per type (``species1`` the small grains, ``species2`` the
    large) and their mixed species (``speciesHandler.getMixedObject``)."""
    g = s.grain
    consts = _constants(s, c)
    if len(consts) == 1:
        body = _mercury_species("species", g.rho, consts[1, 1].epsilon, "mass")
    else:
        two = c.two_materials
        body = [
            "// type 1: this grain's material" if two else "// type 1: the small grains",
            *_mercury_species("species1", c.grains[1].rho, consts[1, 1].epsilon, "m1"),
            "// type 2: the partner's material" if two else "// type 2: the large grains",
            *_mercury_species("species2", c.grains[2].rho, consts[2, 2].epsilon, "m2"),
            "// 1-2: type 1 with type 2" if two else "// 1-2: a small grain with a large one",
            "auto species12 = speciesHandler.getMixedObject(species1, species2);",
            "species12->setCollisionTimeAndRestitutionCoefficient(tc, "
            f"{consts[1, 2].epsilon:.8f}, 2 * m1 * m2 / (m1 + m2));",
        ]
    return "\n".join(
        [
            _comment(s, c, "//"),
            f"// {_particles(s)}",
            f"// tc: your collision time (s); {_mercury_mass(s, c)}",
            *body,
            "",
        ]
    )


TARGET = register_dem_target(
    DemTarget(name="mercurydpm", file_name="mercurydpm.cpp", snippet=mercurydpm_snippet)
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
