"""The LIGGGHTS snippet: ``coefficientRestitution peratomtypepair`` and the Hertz model, or a
damped sphere law in ``hertz/stiffness``.

Young's modulus (Pa) and Poisson number per atom type, epsilon per pair of atom types; or the
stiffness and damping constants per type pair of the viscoelastic contact
(:func:`liggghts_viscoelastic`). Registers itself as the DEM target ``liggghts``
(``liggghts.in``).
"""

from __future__ import annotations

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    RIGID,
    WALL_NOTE,
    _comment,
    _constants,
    _grain_of,
    _particles,
    friction_line,
    time_step_lines,
    viscoelastic_head,
    wall_material,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.plastic_native import is_plastic
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.exports.viscoelastic import Viscoelastic
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "liggghts_time_step", "liggghts_snippet", "liggghts_viscoelastic"]


def liggghts_snippet(s: SILaw, c: Constant | TypePairs, friction: float | None = None) -> str:
    """Input lines for LIGGGHTS (``coefficientRestitution peratomtypepair``): one atom type for
    one constant, two for a :class:`TypePairs` (type 1 the small grains; the matrix row by
    row)."""
    consts = _constants(s, c)
    n = 2 if len(consts) > 1 else 1
    matrix = [
        consts[min(i, j), max(i, j)].epsilon for i in range(1, n + 1) for j in range(1, n + 1)
    ]
    grains = [_grain_of(s, c, i) for i in range(1, n + 1)]
    moduli = [g.E for g in grains]
    poisson = [g.nu for g in grains]
    on_wall = not partner_of(s).is_grain
    wall_lines = []
    if on_wall and n == 1:  # the wall its own atom type: LIGGGHTS mixes E* and G* of the two
        n = 2
        matrix = matrix * 4
        wall = wall_material(s)
        moduli.append(wall.E)
        poisson.append(wall.nu)
        if wall.rigid:
            what = (
                f"the rigid wall: atom type 2 with {RIGID:g} times the grains' modulus, so that "
                "the mixed E* and G* are the rigid wall's E/(1-nu^2) and G/(2-nu) within 1e-6 "
                "(LIGGGHTS's mixing has no rigid partner; a wall of type 1 would be a half-space "
                "of the grains' material, its contact about 1.3 times longer)"
            )
        else:
            what = (
                f"the elastic wall: atom type 2 (E_w = {moduli[1]:.6g} Pa, nu_w = {poisson[1]:g})"
            )
        wall_lines = [
            f"# {what}; LIGGGHTS's Hertz takes 1/E* = (1-nu^2)/E + (1-nu_w^2)/E_w and 1/G* = "
            "2(2-nu)(1+nu)/E + 2(2-nu_w)(1+nu_w)/E_w of the two types, the stiffness of ball "
            "and wall (the matrix's 1-1 entry is this wall law's constant too: grain-grain "
            "contacts take the law of two grains)",
            "fix restitution_wall all wall/gran model hertz tangential history primitive type 2 "
            "zplane 0.0",
        ]
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            *([f"# {WALL_NOTE}"] if on_wall else []),
            f"# {friction_line(friction, 'coefficientFriction')}",
            "fix m1 all property/global youngsModulus peratomtype "
            + " ".join(f"{E:.8g}" for E in moduli),
            "fix m2 all property/global poissonsRatio peratomtype "
            + " ".join(f"{x:.8g}" for x in poisson),
            f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
            + " ".join(f"{e:.8f}" for e in matrix),
            f"fix m4 all property/global coefficientFriction peratomtypepair {n} "
            + " ".join([repr(float(0.0 if friction is None else friction))] * (n * n)),
            "pair_style gran model hertz tangential history",
            "pair_coeff * *",
            *wall_lines,
            "",
        ]
    )


def liggghts_viscoelastic(s: SILaw, model: Viscoelastic, friction: float | None = None) -> str:
    """Input lines for LIGGGHTS that carry a damped sphere law natively: ``model
    hertz/stiffness`` with ``limitForce on``.

    LIGGGHTS's ``hertz/stiffness`` force is ``kn sqrt(R* delta) delta + gamman m*
    sqrt(R* delta) delta'`` (``normal_model_hertz_stiffness.h``), so the Kelvin-Voigt force
    (:mod:`~restitution.laws.exports.viscoelastic`, eq. 1) is ``kn = (4/3) E*`` and
    ``gamman = 2 tau E* / m*`` (1/(m s)), per type pair, exact for grains of the radii the
    model holds for; LIGGGHTS mixes nothing, so every pair is given, the wall as the last atom
    type. ``limitForce on`` clips the force at zero. Tangential: Mindlin's ``kt = 8 G*``,
    ``gammat = 0``, Coulomb's ``mu`` the given friction (0 otherwise). Not run here (no
    LIGGGHTS on this machine): written from its source and documentation.
    """
    types = sorted(model.radii_m)
    wall = len(types) + 1
    n = wall

    def entry(i: int, j: int):
        a, b = sorted((i, j))
        if a == wall:  # wall with wall: never in contact
            return None
        return model.contacts[(a, 0) if b == wall else (a, b)]

    def matrix(value) -> str:
        rows = []
        for i in range(1, n + 1):
            for j in range(1, n + 1):
                c = entry(i, j)
                rows.append("0.0" if c is None else f"{value(c, (i, j)):.10g}")
        return " ".join(rows)

    def gamman(c, ij) -> float:
        return 2.0 * model.relaxation_time_s * c.E_star_pa / c.m_eff_kg

    mu = repr(float(0.0 if friction is None else friction))
    return "\n".join(
        [
            *viscoelastic_head(s, model, friction, "coefficientFriction", "#"),
            "# not run here (no LIGGGHTS on this machine): written from hertz/stiffness's source",
            "# kn = (4/3) E* (Pa), gamman = 2 tau E* / m* (1/(m s)), kt = 8 G* (Pa), gammat = 0; "
            f"atom types: grains {', '.join(map(str, types))}, the wall {wall}",
            f"fix m1 all property/global kn peratomtypepair {n} "
            + matrix(lambda c, ij: 4.0 / 3.0 * c.E_star_pa),
            f"fix m2 all property/global kt peratomtypepair {n} "
            + matrix(lambda c, ij: 8.0 * c.G_star_pa),
            f"fix m3 all property/global gamman peratomtypepair {n} " + matrix(gamman),
            f"fix m4 all property/global gammat peratomtypepair {n} " + matrix(lambda c, ij: 0.0),
            f"fix m5 all property/global coefficientFriction peratomtypepair {n} "
            + " ".join([mu] * (n * n)),
            "pair_style gran model hertz/stiffness tangential history limitForce on",
            "pair_coeff * *",
            "# the wall: a plane at z = 0 below the grains, atom type "
            f"{wall} (change zplane 0.0 to your wall)",
            "fix restitution_wall all wall/gran model hertz/stiffness tangential history "
            f"limitForce on primitive type {wall} zplane 0.0",
            "",
        ]
    )


def liggghts_time_step(steps, viscoelastic: bool = False) -> list[str]:
    """The snippet's time-step lines (:func:`~restitution.laws.exports.dem._common.
    time_step_lines`), the constant's and the viscoelastic contact's alike: both are Hertz's."""
    return time_step_lines(steps, "#", lambda dt: f"timestep {dt:.3g}")


def liggghts_plastic(s) -> list[str]:
    """Comment lines for a plastic law: LIGGGHTS-PUBLIC has no elastic-plastic normal model (its
    doc/Section_gran_models: hertz, hertz/stiffness, hooke, hooke/stiffness); ``[]`` without
    plastic flow."""
    if not is_plastic(s):
        return []
    return [
        "# plastic flow: LIGGGHTS-PUBLIC has no elastic-plastic normal model (hertz,",
        "# hertz/stiffness, hooke, hooke/stiffness); the constant below is the package's law",
        "# at one speed",
    ]


TARGET = register_dem_target(
    DemTarget(
        name="liggghts",
        file_name="liggghts.in",
        snippet=liggghts_snippet,
        viscoelastic=liggghts_viscoelastic,
        time_step=liggghts_time_step,
        plastic=liggghts_plastic,
    )
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
