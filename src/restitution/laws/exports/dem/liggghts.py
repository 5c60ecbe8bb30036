"""The LIGGGHTS snippet: ``coefficientRestitution peratomtypepair`` and the Hertz model.

Young's modulus (Pa) and Poisson number per atom type, epsilon per pair of atom types.
Registers itself as the DEM target ``liggghts`` (``liggghts.in``).
"""

from __future__ import annotations

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    WALL_NOTE,
    _comment,
    _constants,
    _grain_of,
    _particles,
    friction_line,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.si_law import SILaw

__all__ = ["TARGET", "liggghts_snippet"]


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
    moduli = " ".join(f"{g.E:.8g}" for g in grains)
    poisson = " ".join(f"{g.nu:.8g}" for g in grains)
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            *([f"# {WALL_NOTE}"] if s.against == "wall" else []),
            f"# {friction_line(friction, 'coefficientFriction')}",
            f"fix m1 all property/global youngsModulus peratomtype {moduli}",
            f"fix m2 all property/global poissonsRatio peratomtype {poisson}",
            f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
            + " ".join(f"{e:.8f}" for e in matrix),
            f"fix m4 all property/global coefficientFriction peratomtypepair {n} "
            + " ".join([repr(float(0.0 if friction is None else friction))] * (n * n)),
            "pair_style gran model hertz tangential history",
            "pair_coeff * *",
            "",
        ]
    )


TARGET = register_dem_target(
    DemTarget(name="liggghts", file_name="liggghts.in", snippet=liggghts_snippet)
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
