"""The MercuryDPM snippet (C++): a ``LinearViscoelasticSpecies`` per particle type, or a damped
sphere law as ``HertzianBSHPViscoelasticSpecies`` (:func:`mercurydpm_viscoelastic`).

Density in kg/m^3, epsilon with the user's collision time ``tc`` (s) and the effective mass
(kg) it needs. Registers itself as the DEM target ``mercurydpm`` (``mercurydpm.cpp``).
"""

from __future__ import annotations

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    WALL_NOTE,
    _comment,
    _constants,
    _particles,
    friction_line,
    time_step_lines,
    viscoelastic_head,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.plastic_native import is_plastic, luding_lines
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.exports.viscoelastic import Viscoelastic
from restitution.laws.mechanisms.bounds import wall_of
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "mercurydpm_time_step", "mercurydpm_snippet", "mercurydpm_viscoelastic"]


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
    which = partner_of(s).dem_mass
    return f"{head}; for {which}, {m}"


def _mass_expr(s: SILaw, radius: str, rho: float) -> str:
    """C++ for the mass of a particle of radius ``radius`` (a C++ name) and density ``rho``, as
    MercuryDPM computes it (``pi r^2 rho`` in a 2D simulation)."""
    if s.grain.kind.dimension == 3:
        return f"4.0 / 3.0 * constants::pi * {radius} * {radius} * {radius} * {rho:.8g}"
    return f"constants::pi * {radius} * {radius} * {rho:.8g}"


def _mercury_declarations(s: SILaw, c: Constant | TypePairs) -> list[str]:
    """Every name the species lines use, declared (issue 44: ``tc``, ``mass``, ``m1``, ``m2``
    were left undefined): ``tc`` and ``radius`` are the user's to set, the masses follow from
    them and the densities."""
    lines = [
        "// SET tc and radius to your simulation's: they are placeholders so that these lines "
        "compile; epsilon is exact for any tc (tc sets the species' stiffness)",
        "const Mdouble tc = 1e-5;  // s: your collision time",
    ]
    pair = s.law.partner
    if pair is None:
        lines += [
            "const Mdouble radius = 1e-3;  // m: your grains' radius",
            f"const Mdouble m = {_mass_expr(s, 'radius', s.grain.rho)};  // kg, one grain",
            "const Mdouble mass = "
            + partner_of(s).dem_mass_line,
        ]  # fmt: skip
        return lines
    rho2 = s.partner_grain.rho if s.partner_grain is not None else s.grain.rho
    small = "type 1" if s.partner_grain is not None else "the small grains'"
    lines += [
        f"const Mdouble radius = 1e-3;  // m: {small} radius",
        f"const Mdouble m1 = {_mass_expr(s, 'radius', s.grain.rho)};  // kg",
        f"const Mdouble m2 = {_mass_expr(s, f'({pair.radius_ratio:.8g} * radius)', rho2)};  // kg",
    ]
    if not isinstance(c, TypePairs):
        lines.append("const Mdouble mass = 2 * m1 * m2 / (m1 + m2);  // kg, effective mass")
    return lines


def _mercury_friction(name: str, friction: float | None) -> list[str]:
    """The sliding friction of a species, with MercuryDPM's usual sliding stiffness and
    dissipation (2/7 of the normal ones), when ``friction`` is given."""
    if friction is None:
        return []
    return [
        f"{name}->setSlidingFrictionCoefficient({friction:g});",
        f"{name}->setSlidingStiffness(2.0 / 7.0 * {name}->getStiffness());",
        f"{name}->setSlidingDissipation(2.0 / 7.0 * {name}->getDissipation());",
    ]


def _mercury_species(
    name: str, rho: float, eps: float, mass: str, friction: float | None = None
) -> list[str]:
    species = "LinearViscoelastic" + ("" if friction is None else "SlidingFriction") + "Species"
    return [
        f"auto {name} = speciesHandler.copyAndAddObject({species}());",
        f"{name}->setDensity({rho:.8g});",
        f"{name}->setCollisionTimeAndRestitutionCoefficient(tc, {eps:.8f}, {mass});",
        *_mercury_friction(name, friction),
    ]


def _mercury_wall(s: SILaw) -> list[str]:
    """The comment an elastic wall needs: the linear species has no modulus to give it."""
    elastic = wall_of(s.law) if not partner_of(s).is_grain else None
    if elastic is None:
        return []
    E_w = float(elastic["modulus_ratio"]) * s.grain.E
    return [
        f"// the elastic wall (E_w = {E_w:.6g} Pa, nu_w = {float(elastic['nu']):g}) is in "
        "epsilon; a linear species has no modulus, so tc alone sets the grain-wall stiffness: "
        "take your grains' collision time on this wall"
    ]


def mercurydpm_snippet(s: SILaw, c: Constant | TypePairs, friction: float | None = None) -> str:
    """C++ lines for MercuryDPM (``LinearViscoelasticSpecies``; choose the collision time). A
    :class:`TypePairs` gives a species per type (``species1`` the small grains, ``species2`` the
    large) and their mixed species (``speciesHandler.getMixedObject``)."""
    g = s.grain
    consts = _constants(s, c)
    if len(consts) == 1:
        body = _mercury_species("species", g.rho, consts[1, 1].epsilon, "mass", friction)
        if s.law.partner is not None:  # one constant for a pair: the 1-2 contact's
            body.insert(0, "// the pair's constant (small with large)")
    else:
        two = c.two_materials
        body = [
            "// type 1: this grain's material" if two else "// type 1: the small grains",
            *_mercury_species("species1", c.grains[1].rho, consts[1, 1].epsilon, "m1", friction),
            "// type 2: the partner's material" if two else "// type 2: the large grains",
            *_mercury_species("species2", c.grains[2].rho, consts[2, 2].epsilon, "m2", friction),
            "// 1-2: type 1 with type 2" if two else "// 1-2: a small grain with a large one",
            "auto species12 = speciesHandler.getMixedObject(species1, species2);",
            "species12->setCollisionTimeAndRestitutionCoefficient(tc, "
            f"{consts[1, 2].epsilon:.8f}, 2 * m1 * m2 / (m1 + m2));",
            *_mercury_friction("species12", friction),
        ]
    return "\n".join(
        [
            _comment(s, c, "//"),
            f"// {_particles(s)}",
            *([f"// {WALL_NOTE}"] if not partner_of(s).is_grain else []),
            *_mercury_wall(s),
            f"// {friction_line(friction, 'a sliding-friction species')}",
            f"// tc: your collision time (s); {_mercury_mass(s, c)}",
            *_mercury_declarations(s, c),
            *body,
            "",
        ]
    )


def mercurydpm_viscoelastic(s: SILaw, model: Viscoelastic, friction: float | None = None) -> str:
    """C++ lines for MercuryDPM that carry a damped sphere law natively:
    ``HertzianBSHPViscoelasticSpecies`` (Brilliantov-Spahn-Hertzsch-Poschel).

    Its force is ``max(0, (4/3) E* sqrt(R* delta) delta + (3/2) A (4/3) E* sqrt(R* delta)
    delta')`` (``HertzianBSHPViscoelasticInteraction.cc``): the Kelvin-Voigt force
    (:mod:`~restitution.laws.exports.viscoelastic`, eq. 1) with ``A = tau`` (s) and ``E*``
    (Pa), clipped at zero, with no mass or size in it: exact for every size. One species for
    the grains (its own contacts take ``E*`` of two grains); the walls' species and the mixed
    grain-wall species set explicitly (MercuryDPM's default mixing averages ``A`` and ``E*``
    harmonically): ``E*`` of the rigid wall. With friction, the Mindlin variant with ``G*``.
    Not run here (no MercuryDPM on this machine): written from its source.
    """
    grain = model.contacts[1, 1]
    on_wall = model.contacts[1, 0]
    kind = "HertzianBSHPViscoelastic" + ("" if friction is None else "Mindlin") + "Species"

    def setters(name: str, c) -> list[str]:
        lines = [
            f"{name}->setEffectiveElasticModulus({c.E_star_pa:.10g});  // E*, Pa",
            f"{name}->setDissipation({model.relaxation_time_s:.10g});  // A = tau, s",
        ]
        if friction is not None:
            lines += [
                f"{name}->setEffectiveShearModulus({c.G_star_pa:.10g});  // G*, Pa",
                f"{name}->setSlidingFrictionCoefficient({friction:g});",
            ]
        return lines

    return "\n".join(
        [
            *viscoelastic_head(s, model, friction, "a Mindlin species' sliding friction", "//"),
            "// not run here (no MercuryDPM on this machine): written from the BSHP species' "
            "source; A and E* hold for grains of every size",
            f"auto species = speciesHandler.copyAndAddObject({kind}());  // the grains",
            f"species->setDensity({model.density:.8g});",
            *setters("species", grain),
            f"auto wallSpecies = speciesHandler.copyAndAddObject({kind}());  // give your walls "
            "this species",
            f"wallSpecies->setDensity({model.density:.8g});",
            *setters("wallSpecies", on_wall),
            "auto grainWall = speciesHandler.getMixedObject(species, wallSpecies);  // the "
            "grains on the rigid wall",
            *setters("grainWall", on_wall),
            "",
        ]
    )


def mercurydpm_time_step(steps, viscoelastic: bool = False) -> list[str]:
    """The snippet's time-step lines. The viscoelastic snippet's species is Hertz's:
    :func:`~restitution.laws.exports.dem._common.time_step_lines` with ``setTimeStep``. The
    constant's linear species lasts the user's ``tc`` at every speed: ``setTimeStep(tc / 50)``,
    with Hertz's contact times of the material for the choice of ``tc``."""
    if viscoelastic:
        return time_step_lines(steps, "//", lambda dt: f"setTimeStep({dt:.3g});  // s")
    n = steps.steps_per_contact
    return [
        f"// time step: dt = tc/{n} (a linear species' contact lasts tc at every speed; {n} "
        "steps per contact keep epsilon within about 1 % of the loss 1 - epsilon, "
        "restitution.laws.exports.time_step); Hertz's contact of this material, for choosing "
        "tc, lasts t_c = 2.868 (m*^2/(E*^2 R* w))^(1/5) at the fastest impact w of each law:",
        *(f"// {line}" for line in steps.contact_lines()),
        f"setTimeStep(tc / {n}.0);",
    ]


def mercurydpm_plastic(s) -> list[str]:
    """Comment lines on MercuryDPM's own elastic-plastic contact (Luding's) for a plastic law
    (:mod:`restitution.laws.exports.plastic_native`); ``[]`` without plastic flow."""
    if not is_plastic(s):
        return []
    return luding_lines(s, "LinearPlasticViscoelasticNormalSpecies", "//")


TARGET = register_dem_target(
    DemTarget(
        name="mercurydpm",
        file_name="mercurydpm.cpp",
        snippet=mercurydpm_snippet,
        viscoelastic=mercurydpm_viscoelastic,
        time_step=mercurydpm_time_step,
        plastic=mercurydpm_plastic,
    )
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
