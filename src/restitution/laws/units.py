"""The edge between SI units and the package's reduced units.

Inside, everything is reduced: ``E_2d = rho = R = 1``, speeds in units of ``c = sqrt(E_2d/rho)``
with the **two-dimensional** constants of eq. (6). At the edge a user names

* a material by its three-dimensional constants: Young modulus ``E`` in Pa, Poisson number
  ``nu``, density ``rho`` in kg/m^3 (any consistent units work; speeds then come out in
  ``sqrt(unit of E / unit of rho)``);
* a geometry: ``"cylinder"`` (a long cylinder hit along a diameter: plane strain, eq. (2),
  ``E_2d = E / (1 - nu^2)``, ``nu_2d = nu / (1 - nu)``) or ``"thin-disk"`` (plane stress:
  ``E_2d = E``, ``nu_2d = nu``);
* a collision partner: ``"wall"`` (the model's rigid flat wall, hit at speed ``w``: ``v = w/c``)
  or ``"grain"`` (two identical grains at relative normal speed ``w``: by symmetry each moves at
  ``w/2`` towards the contact plane, so ``v = w / (2c)``).

The radius never enters ``epsilon`` (the model has no other length), so it is not asked for.
Every result of this module says which geometry and partner it belongs to.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np

from restitution.bodies.material import Material
from restitution.errors import InputError

__all__ = [
    "GEOMETRIES",
    "PARTNERS",
    "Grain",
    "partner_factor",
]

Geometry = Literal["cylinder", "thin-disk"]
Partner = Literal["wall", "grain"]

GEOMETRIES: dict[str, str] = {"cylinder": "strain", "thin-disk": "stress"}
"""Geometry name -> plane condition of eq. (2)."""

PARTNERS: dict[str, str] = {
    "wall": "a rigid flat wall hit at speed w (v = w / c)",
    "grain": "an identical grain, relative normal speed w (v = w / (2 c))",
}
"""Collision partner name -> what the speed ``w`` means."""


def partner_factor(against: str) -> float:
    """``k`` in ``v = w / (k c)``: 1 against a wall, 2 for two identical grains."""
    if against == "wall":
        return 1.0
    if against == "grain":
        return 2.0
    raise InputError(f"the collision partner must be 'wall' or 'grain', got {against!r}")


@dataclass(frozen=True)
class Grain:
    """A grain material in SI units, its geometry, and the conversion to reduced units.

    Parameters
    ----------
    E : float
        Three-dimensional Young modulus, Pa.
    nu : float
        Three-dimensional Poisson number, in (-1, 0.5] (``< 0.5`` for a cylinder).
    rho : float
        Three-dimensional density, kg/m^3.
    geometry : {"cylinder", "thin-disk"}
        Long cylinder (plane strain) or thin disk (plane stress).

    Examples
    --------
    >>> g = Grain(E=210e9, nu=0.3, rho=7850, geometry="thin-disk")
    >>> round(g.c_m_s)
    5172
    >>> round(float(g.v_over_c(1.0, "grain")), 7)
    9.67e-05
    """

    E: float
    nu: float
    rho: float
    geometry: Geometry

    def __post_init__(self) -> None:
        if self.geometry not in GEOMETRIES:
            raise InputError(
                f"the geometry must be 'cylinder' (plane strain) or 'thin-disk' (plane stress), "
                f"got {self.geometry!r}"
            )
        _ = self.material  # validates E, nu, rho with one-line messages

    @property
    def plane(self) -> str:
        """``"strain"`` for a cylinder, ``"stress"`` for a thin disk."""
        return GEOMETRIES[self.geometry]

    @property
    def material(self) -> Material:
        """The 2D constants per unit thickness (``E_2d`` in Pa, ``rho`` in kg/m^3)."""
        return Material.from_3d(E=self.E, nu=self.nu, plane=self.plane, rho=self.rho)

    @property
    def nu_2d(self) -> float:
        """Two-dimensional Poisson number of eq. (6), the law's parameter."""
        return self.material.nu

    @property
    def E_2d(self) -> float:
        """Two-dimensional Young modulus per unit thickness, Pa."""
        return self.material.E

    @property
    def c_m_s(self) -> float:
        """The velocity unit ``c = sqrt(E_2d / rho)``, m/s."""
        return self.material.c

    def speed_scale(self, against: str) -> float:
        """``k c`` in m/s: the SI speed ``w`` that corresponds to ``v = 1``."""
        return partner_factor(against) * self.c_m_s

    def v_over_c(self, speed_m_s, against: str):
        """Reduced speed ``v`` (towards the wall, units of ``c``) of SI speed(s) ``w``.

        Parameters
        ----------
        speed_m_s : float or array_like
            Impact speed ``w`` in m/s: towards the wall, or the relative normal speed of two
            grains; non-negative.
        against : {"wall", "grain"}
            Collision partner.

        Returns
        -------
        float or numpy.ndarray
            ``v = w / (k c)`` with ``k = 1`` (wall) or ``2`` (grain).
        """
        w = np.asarray(speed_m_s, dtype=float)
        if not np.all(np.isfinite(w)) or np.any(w < 0):
            raise InputError(f"speeds must be finite and non-negative (m/s), got {speed_m_s!r}")
        v = w / self.speed_scale(against)
        return float(v) if np.ndim(speed_m_s) == 0 else v

    def speed_m_s(self, v, against: str):
        """SI speed ``w`` (m/s) of reduced speed(s) ``v``: the inverse of :meth:`v_over_c`."""
        v_arr = np.asarray(v, dtype=float)
        w = v_arr * self.speed_scale(against)
        return float(w) if np.ndim(v) == 0 else w

    def to_dict(self) -> dict:
        """JSON-ready description with units in every key."""
        return {
            "E_Pa": self.E,
            "nu": self.nu,
            "rho_kg_m3": self.rho,
            "geometry": self.geometry,
            "plane": self.plane,
            "E_2d_Pa": self.E_2d,
            "nu_2d": self.nu_2d,
            "c_m_s": self.c_m_s,
        }

    def describe(self) -> str:
        """One line: material, geometry, 2D constants and ``c``."""
        plane = "plane strain" if self.plane == "strain" else "plane stress"
        return (
            f"E = {self.E:.4g} Pa, nu = {self.nu:g}, rho = {self.rho:.4g} kg/m^3, "
            f"{self.geometry} ({plane}): nu_2d = {self.nu_2d:.6g}, c = {self.c_m_s:.6g} m/s"
        )
