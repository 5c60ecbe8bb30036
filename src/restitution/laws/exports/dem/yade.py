"""The YADE snippet (Python): ``FrictMat`` and Hertz-Mindlin physics with ``en``.

Young's modulus (Pa), Poisson number and density (kg/m^3) per material, epsilon as ``en``
(a ``MatchMaker`` per pair of materials). Registers itself as the DEM target ``yade``
(``yade.py``).
"""

from __future__ import annotations

import math

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    WALL_NOTE,
    _comment,
    _constants,
    _particles,
    friction_line,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "yade_snippet"]


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
            *([f"# {WALL_NOTE}"] if s.against == "wall" else []),
            f"# {friction_line(friction, 'frictionAngle = atan(mu)')}",
            *body,
            "# use ip2 in the InteractionLoop with Law2_ScGeom_MindlinPhys_Mindlin()",
            "",
        ]
    )


TARGET = register_dem_target(DemTarget(name="yade", file_name="yade.py", snippet=yade_snippet))
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
