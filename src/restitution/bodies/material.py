"""Elastic constants of the two-dimensional disk material.

The paper works with the *two-dimensional* (plane-stress) constants ``E`` and ``nu`` of its
eq. (6). Plane strain maps onto them through eq. (2)::

    E_2d = E_3d / (1 - nu_3d**2),    nu_2d = nu_3d / (1 - nu_3d)

Units. The modal path (eigenmodes, collisions, laws) works in reduced units
``E_2d = rho = R = 1``, so the velocity unit is ``c = sqrt(E_2d / rho)`` and the disk mass is
``m = rho * pi * R**2 = pi``; it accepts only a reduced :class:`Material`
(:func:`require_reduced`). A material in SI (or any consistent) units comes from
:meth:`Material.from_3d`: ``E`` in Pa and ``rho`` in kg/m^3 of the 3D body, so that ``E_2d``
is the 2D modulus per unit thickness (Pa) and ``c`` comes out in m/s; the finite-element path
uses these constants as they are. :mod:`restitution.laws.units` maps SI speeds onto reduced ones.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from restitution.errors import InputError, describe, is_real, real

__all__ = ["Material", "MaterialError", "require_reduced"]


class MaterialError(InputError):
    """Raised for elastic constants outside their physical range."""


def _check_finite(name: str, value: float, allowed: str) -> float:
    """``value`` as a float if it is a finite real number, else a one-line
    :class:`MaterialError` that names ``name`` and its ``allowed`` range."""
    return real(value, name, allowed, error=MaterialError)


@dataclass(frozen=True)
class Material:
    """Isotropic two-dimensional elastic material.

    Parameters
    ----------
    nu : float
        Two-dimensional Poisson number of eq. (6), in the open interval (-1, 1).
    E : float, optional
        Two-dimensional Young modulus per unit thickness (Pa in SI; force per length divided by
        the thickness). Default 1 (the paper's reduced unit).
    rho : float, optional
        Density, mass per area per unit thickness (kg/m^3 in SI). Default 1 (reduced unit).

    Notes
    -----
    Construct from three-dimensional constants with :meth:`from_3d` and from the shear and
    compression moduli with :meth:`from_moduli`. The thickness cancels in every speed
    (``c = sqrt(E / rho)``), so it is never needed. The modal path takes only reduced materials
    (``E = rho = 1``, :attr:`is_reduced`); :meth:`reduced` gives one with the same ``nu``.
    """

    nu: float
    E: float = 1.0
    rho: float = 1.0

    def __post_init__(self) -> None:
        nu = _check_finite("nu", self.nu, "in (-1, 1)")
        E = _check_finite("E", self.E, "> 0")
        rho = _check_finite("rho", self.rho, "> 0")
        if not -1.0 < nu < 1.0:
            raise MaterialError(
                f"the two-dimensional Poisson number must lie in (-1, 1), got nu = {nu}"
            )
        if E <= 0.0:
            raise MaterialError(f"Young's modulus must be positive, got E = {E}")
        if rho <= 0.0:
            raise MaterialError(f"the density must be positive, got rho = {rho}")
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "rho", rho)

    @classmethod
    def from_3d(
        cls,
        E: float,
        nu: float,
        plane: Literal["stress", "strain"] = "stress",
        rho: float = 1.0,
    ) -> Material:
        """Material from three-dimensional constants.

        Parameters
        ----------
        E : float
            Three-dimensional Young modulus (Pa, or any unit consistent with ``rho``).
        nu : float
            Three-dimensional Poisson number, in (-1, 0.5].
        plane : {"stress", "strain"}
            ``"stress"`` (thin disk) keeps the constants; ``"strain"`` (long cylinder) applies
            eq. (2): ``E_2d = E / (1 - nu^2)``, ``nu_2d = nu / (1 - nu)``.
        rho : float
            Three-dimensional density (kg/m^3 in SI); a disk of thickness ``h`` has mass
            ``rho h`` per area and 2D modulus ``E_2d h``, and ``h`` cancels in ``c``.

        Returns
        -------
        Material
            2D constants per unit thickness: ``c = sqrt(E_2d / rho)`` in m/s for SI input
            (steel, thin disk: 5.2 km/s, the bar speed; long cylinder: 5.4 km/s, the plate
            speed ``sqrt(E / (rho (1 - nu^2)))``).
        """
        E = _check_finite("E", E, "> 0")
        nu = _check_finite("nu", nu, "in (-1, 0.5]")
        if not -1.0 < nu <= 0.5:
            raise MaterialError(
                f"the three-dimensional Poisson number must lie in (-1, 0.5], got nu = {nu}"
            )
        if E <= 0.0:
            raise MaterialError(f"Young's modulus must be positive, got E = {E}")
        rho = _check_finite("rho", rho, "> 0")
        if rho <= 0.0:
            raise MaterialError(f"the density must be positive, got rho = {rho}")
        if not (isinstance(plane, str) and plane in ("stress", "strain")):
            raise MaterialError(
                f"plane must be 'stress' (thin disk) or 'strain' (long cylinder), got "
                f"{describe(plane)}"
            )
        if plane == "stress":
            return cls(nu=nu, E=E, rho=rho)
        if nu == 0.5:
            raise MaterialError(
                "plane strain with nu = 0.5 (incompressible) maps to nu_2d = 1, which is "
                "outside (-1, 1); use nu < 0.5"
            )
        return cls(nu=nu / (1.0 - nu), E=E / (1.0 - nu**2), rho=rho)

    @classmethod
    def from_moduli(cls, mu: float, K: float, rho: float = 1.0) -> Material:
        """Material from the 2D shear modulus ``mu`` and compression modulus ``K`` (eq. 4)."""
        mu = _check_finite("mu", mu, "> 0")
        K = _check_finite("K", K, "> 0")
        if mu <= 0.0 or K <= 0.0:
            raise MaterialError(f"mu and K must both be positive, got mu = {mu}, K = {K}")
        return cls(nu=(K - mu) / (K + mu), E=4.0 * mu * K / (K + mu), rho=rho)

    @property
    def is_reduced(self) -> bool:
        """Whether ``E = rho = 1`` (the reduced units of the modal path)."""
        return self.E == 1.0 and self.rho == 1.0

    def reduced(self) -> Material:
        """The same Poisson number in reduced units ``E = rho = 1`` (speeds in units of
        :attr:`c`, times in ``R / c``)."""
        return Material(nu=self.nu)

    @property
    def mu(self) -> float:
        """Shear modulus, ``E / (2 (1 + nu))``."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def K(self) -> float:
        """Two-dimensional compression modulus, ``E / (2 (1 - nu))``."""
        return self.E / (2.0 * (1.0 - self.nu))

    @property
    def c(self) -> float:
        """Velocity unit ``sqrt(E / rho)`` of the paper."""
        return math.sqrt(self.E / self.rho)

    @property
    def c_p(self) -> float:
        """Dilatational wave speed ``sqrt(E / (rho (1 - nu^2)))``."""
        return math.sqrt(self.E / (self.rho * (1.0 - self.nu**2)))

    @property
    def c_s(self) -> float:
        """Shear wave speed ``sqrt(mu / rho)``."""
        return math.sqrt(self.mu / self.rho)


def require_reduced(material: Material | float, where: str) -> float:
    """The Poisson number of ``material`` for a path that works in reduced units.

    Parameters
    ----------
    material : Material or float
        A reduced material (``E = rho = 1``) or a two-dimensional Poisson number.
    where : str
        Name of the calling path, for the message.

    Returns
    -------
    float
        The two-dimensional Poisson number.

    Raises
    ------
    MaterialError
        If ``material`` carries ``E != 1`` or ``rho != 1``: the modal path would silently use
        ``E = rho = 1`` instead (nothing is accepted and then ignored).
    """
    if not isinstance(material, Material):
        if not is_real(material):
            raise MaterialError(
                f"material must be a Material or a Poisson number (a float), got "
                f"{describe(material)}; pass e.g. 0.33 or Material(0.33)"
            )
        return Material(nu=material).nu
    if not material.is_reduced:
        raise MaterialError(
            f"{where} works in reduced units E = rho = R = 1, but got E = {material.E:g}, "
            f"rho = {material.rho:g}; pass material.reduced() and convert speeds with "
            f"restitution.laws.units (c = {material.c:g} in the units of E and rho)"
        )
    return material.nu
