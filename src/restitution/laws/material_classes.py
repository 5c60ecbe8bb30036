"""Typical yield stresses of material classes: from which speed an elastic answer is an upper bound.

Units: SI (Pa, kg/m^3).

An elastic epsilon(w) is exact for the model (waves and vibrations) but, for metal grains, an
upper bound above the speed where plastic flow starts (issue 43). Without a yield stress from the
user that speed is not known; for the class of material the grain's constants suggest it lies in
a range, which every elastic answer states. The class is the nearest of :data:`CLASSES` in
``(ln E, ln rho, nu)`` (a heuristic: aluminium and glass differ mainly in ``nu``), and the answer
says which class it took, so that a user whose grain is of another class gives
``--yield-stress``.

Sources. Yield strengths: "Typical values of Yield Strength, Ultimate Strength" (NOT FOR DESIGN),
http://ah-engr.com/som/tools/tables/table_2_strengths.htm: aluminium alloys 2014-T6, 6061-T6,
7075-T6 270-480 MPa; brass 70-550, bronze 82-690, copper (cold-drawn) 55-760 MPa; steels
(structural A36 250 MPa to spring steel 1600 MPa); plate glass and plastics listed without a
yield strength (glass is brittle: it cracks, it does not flow). Elastic constants and the yield of
pure aluminium (21 MPa) and of titanium alloy Ti-6Al-4V (830 MPa):
http://ecoursesbook.com/cgi-bin/ebook.cgi?topic=me&chap_sec=&page=&appendix=mat_prop (in psi
and slug/ft^3, converted).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["CLASSES", "MaterialClass", "material_class"]


@dataclass(frozen=True)
class MaterialClass:
    """A class of materials: typical constants and the range of its yield stress.

    Attributes
    ----------
    name : str
    E, rho, nu : float
        Typical Young modulus (Pa), density (kg/m^3) and Poisson number.
    yield_stress : tuple of float or None
        ``(lowest, highest)`` typical uniaxial yield stress, Pa; ``None`` for a class that does
        not flow plastically (brittle, or without a discernible yield).
    remark : str
        What happens instead, for a class without a yield stress.
    """

    name: str
    E: float
    rho: float
    nu: float
    yield_stress: tuple[float, float] | None
    remark: str = ""


CLASSES: tuple[MaterialClass, ...] = (
    MaterialClass("steel", 200e9, 7730.0, 0.29, (250e6, 1600e6)),
    MaterialClass("aluminium alloy", 69e9, 2730.0, 0.33, (21e6, 480e6)),
    MaterialClass("copper alloy (copper, brass, bronze)", 110e9, 8500.0, 0.34, (55e6, 760e6)),
    MaterialClass("titanium alloy", 114e9, 4480.0, 0.33, (830e6, 830e6)),
    MaterialClass(
        "glass",
        69e9,
        2580.0,
        0.22,
        None,
        "glass is brittle: it cracks above some speed (not modelled) instead of flowing",
    ),  # fmt: skip
    MaterialClass(
        "polymer",
        2.8e9,
        1130.0,
        0.4,
        None,
        "polymers have no discernible yield stress; their loss is mostly viscous (give the "
        "damping)",
    ),  # fmt: skip
)
"""The classes (module docs for the sources)."""

_FAR = 0.5
"""A grain farther than this from every class in ``(ln E, ln rho, nu / 0.1)`` takes none."""


def material_class(E: float, rho: float, nu: float) -> MaterialClass | None:
    """The nearest class to a material of ``E`` (Pa), ``rho`` (kg/m^3), ``nu``, or ``None``
    when none is near (module docs)."""

    def distance(c: MaterialClass) -> float:
        return math.sqrt(
            math.log(E / c.E) ** 2 + math.log(rho / c.rho) ** 2 + ((nu - c.nu) / 0.1) ** 2
        )

    best = min(CLASSES, key=distance)
    return best if distance(best) <= _FAR else None
