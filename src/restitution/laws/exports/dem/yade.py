"""The YADE snippet (Python): ``FrictMat`` and Hertz-Mindlin physics with ``en``.

Young's modulus (Pa), Poisson number and density (kg/m^3) per material, epsilon as ``en``
(a ``MatchMaker`` per pair of materials). Registers itself as the DEM target ``yade``
(``yade.py``).
"""

from __future__ import annotations

import math

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    RIGID,
    WALL_NOTE,
    _comment,
    _constants,
    _particles,
    friction_line,
    time_step_lines,
    viscoelastic_head,
    wall_material,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.plastic_native import is_plastic, luding_lines
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.exports.viscoelastic import Viscoelastic
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "yade_time_step", "yade_snippet", "yade_viscoelastic"]

_WALL_GEOMETRY = (
    "walls: Ig2_Wall_Sphere_ScGeom(hertzian=True) and Ig2_Facet_Sphere_ScGeom(hertzian=True), "
    "so that R* = R"
)


def yade_snippet(s: SILaw, c: Constant | TypePairs, friction: float | None = None) -> str:
    """Python lines for YADE (Hertz-Mindlin with ``en``). A :class:`TypePairs` gives two
    materials of the same constants (``mat1`` for the small grains, ``mat2`` for the large) and
    ``en`` as a ``MatchMaker`` over their ids."""
    consts = _constants(s, c)
    angle = 0.0 if friction is None else math.atan(friction)  # YADE takes atan(mu), rad

    def mat(g) -> str:
        return (
            f"O.materials.append(FrictMat(young={g.E:.8g}, poisson={g.nu:.8g}, "
            f"density={g.rho:.8g}, frictionAngle={angle!r}))"
        )

    if len(consts) == 1:
        body = [
            mat(s.grain),
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en={consts[1, 1].epsilon:.8f})",
        ]
        if not partner_of(s).is_grain:  # the wall's material: YADE's Hertz-Mindlin mixes both
            wall = wall_material(s)
            if wall.rigid:
                what = (
                    f"the rigid wall, nearly: {RIGID:g} times the grains' modulus, so that E* and "
                    "G* are the rigid wall's E/(1-nu^2) and G/(2-nu) within 1e-6 (a wall of the "
                    "grains' material would be a half-space of it, its contact about 1.3 times "
                    "longer)"
                )
            else:
                what = "the elastic wall (E_w, nu_w, rho_w)"
            body[1:1] = [
                f"wallMat = {mat(wall)}  # {what}: give your walls material=wallMat; "
                "Hertz-Mindlin takes 1/E* = (1-nu^2)/E + (1-nu_w^2)/E_w and 1/G* = (2-nu)/G + "
                "(2-nu_w)/G_w, the stiffness of ball and wall (Ip2_FrictMat_FrictMat_MindlinPhys "
                "as in YADE's HertzMindlin.cpp today; a version that averages G, (G + G_w)/2, "
                "would make a stiff wall's shear spring far too stiff: check yours)",
                f"# {_WALL_GEOMETRY}",
            ]
    else:
        matches = ", ".join(f"(mat{i}, mat{j}, {k.epsilon:.8f})" for (i, j), k in consts.items())
        two = c.two_materials
        body = [
            f"mat1 = {mat(c.grains[1])}  # type 1: "
            + ("this grain's material" if two else "the small grains"),
            f"mat2 = {mat(c.grains[2])}  # type 2: "
            + ("the partner's material" if two else "the large grains (same constants, own id)"),
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=({matches})))",
            "# give type 1 particles material=mat1, type 2 material=mat2"
            if two
            else "# give the small particles material=mat1, the large ones material=mat2",
        ]
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            *([f"# {WALL_NOTE}"] if not partner_of(s).is_grain else []),
            f"# {friction_line(friction, 'frictionAngle = atan(mu)')}",
            *body,
            "# use ip2 in the InteractionLoop with Law2_ScGeom_MindlinPhys_Mindlin()",
            "",
        ]
    )


def yade_viscoelastic(
    s: SILaw, model: Viscoelastic, friction: float | None = None, speed_m_s: float | None = None
) -> str:
    """Python lines for YADE that carry a damped sphere law in its own viscoelastic Hertz
    contact: ``Ip2_FrictMat_FrictMat_MindlinPhys(en=..., vn=...)``.

    With ``vn`` given, YADE (merge request 977: Brilliantov 1996, Muller and Poschel 2011)
    damps Hertz's contact with ``2 A E* sqrt(R* delta) delta'``, the Kelvin-Voigt force
    (:mod:`~restitution.laws.exports.viscoelastic`, eq. 1) with ``A = tau``; but ``A`` is not
    an input: YADE infers it from a restitution ``en`` at the speed ``vn`` through a Pade
    approximant, and for one ``en`` it scales with the size (``A ~ R``). So each pair of
    materials gets ``en`` = the Kelvin-Voigt epsilon of its own contact at ``vn`` (the
    package's viscous collision), one material per grain size, the wall its own (nearly
    rigid, :data:`RIGID`); ``A = tau`` up to the approximant's accuracy. Walls need
    ``hertzian=True`` (``R* = R``). Not run here (no YADE on this machine).
    """
    vn = speed_m_s if speed_m_s is not None else (
        model.dropped[len(model.dropped) // 2].speed_m_s if model.dropped else 1.0
    )  # fmt: skip
    angle = 0.0 if friction is None else math.atan(friction)
    g = s.grain
    types = sorted(model.radii_m)

    def mat(name: str, young: float) -> str:
        return (
            f"{name} = O.materials.append(FrictMat(young={young:.8g}, poisson={g.nu:.8g}, "
            f"density={g.rho:.8g}, frictionAngle={angle!r}))"
        )

    def en(pair) -> float:
        return float(model.contacts[pair].epsilon(model.relaxation_time_s, vn)[0])

    matches = [f"(mat{i}, mat{j}, {en((i, j)):.10f})" for i, j in model.grain_pairs]
    matches += [f"(mat{i}, wallMat, {en((i, 0)):.10f})" for i, _ in model.wall_pairs]
    return "\n".join(
        [
            *viscoelastic_head(s, model, friction, "frictionAngle = atan(mu)", "#"),
            "# not run here (no YADE on this machine); YADE infers its dissipation constant A "
            "from en at vn (a Pade approximant): A = tau to that approximant's accuracy",
            f"# en: the Kelvin-Voigt epsilon of each contact at vn = {vn:.6g} m/s, for grains of "
            "the radii above (one material per size: A ~ R for one en)",
            *(
                mat(f"mat{i}", g.E) + f"  # grains of radius {model.radii_m[i]:.6g} m"
                for i in types
            ),  # fmt: skip
            mat("wallMat", RIGID * g.E) + "  # the wall, nearly rigid",
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=({', '.join(matches)}"
            f")), vn={vn!r})",
            f"# {_WALL_GEOMETRY}; use ip2 with Law2_ScGeom_MindlinPhys_Mindlin()",
            "",
        ]
    )


def yade_time_step(steps, viscoelastic: bool = False) -> list[str]:
    """The snippet's time-step lines (:func:`~restitution.laws.exports.dem._common.
    time_step_lines`), the constant's and the viscoelastic contact's alike: both are Hertz's."""
    return time_step_lines(steps, "#", lambda dt: f"O.dt = {dt:.3g}  # s")


def yade_plastic(s) -> list[str]:
    """Comment lines on YADE's own elastic-plastic contact (Luding's) for a plastic law
    (:mod:`restitution.laws.exports.plastic_native`); ``[]`` without plastic flow."""
    if not is_plastic(s):
        return []
    return luding_lines(s, "Law2_ScGeom_LudingPhys_Basic", "#")


TARGET = register_dem_target(
    DemTarget(
        name="yade",
        file_name="yade.py",
        snippet=yade_snippet,
        viscoelastic=yade_viscoelastic,
        time_step=yade_time_step,
        plastic=yade_plastic,
    )
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
