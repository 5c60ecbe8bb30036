"""Elastic constants of the two-dimensional disk material.

The paper works with the *two-dimensional* (plane-stress) constants ``E`` and ``nu`` of its
eq. (6). Plane strain maps onto them through eq. (2)::

    E_2d = E_3d / (1 - nu_3d**2),    nu_2d = nu_3d / (1 - nu_3d)

Units used throughout the package: ``E_2d = rho = R = 1``, so the velocity unit is
``c = sqrt(E_2d / rho)`` and the disk mass is ``m = rho * pi * R**2 = pi``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from restitution.errors import InputError

__all__ = ["Material", "MaterialError"]


class MaterialError(InputError):
    """Raised for elastic constants outside their physical range."""


def _check_finite(name: str, value: float) -> float:
    value = float(value)
    if not math.isfinite(value):
        raise MaterialError(f"{name} must be a finite number, got {value!r}")
    return value


@dataclass(frozen=True)
class Material:
    """Isotropic two-dimensional elastic material.

    Parameters
    ----------
    nu : float
        Two-dimensional Poisson number of eq. (6), in the open interval (-1, 1).
    E : float, optional
        Two-dimensional Young modulus (force per length). Default 1 (the paper's unit).
    rho : float, optional
        Mass per area. Default 1 (the paper's unit).

    Notes
    -----
    Construct from three-dimensional constants with :meth:`from_3d` and from the shear and
    compression moduli with :meth:`from_moduli`.
    """

    nu: float
    E: float = 1.0
    rho: float = 1.0

    def __post_init__(self) -> None:
        nu = _check_finite("nu", self.nu)
        E = _check_finite("E", self.E)
        rho = _check_finite("rho", self.rho)
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
        E, nu : float
            Three-dimensional Young modulus and Poisson number; ``nu`` in (-1, 0.5].
        plane : {"stress", "strain"}
            ``"stress"`` (thin plate) keeps the constants; ``"strain"`` applies eq. (2).
        rho : float
            Mass per area of the two-dimensional body.
        """
        E = _check_finite("E", E)
        nu = _check_finite("nu", nu)
        if not -1.0 < nu <= 0.5:
            raise MaterialError(
                f"the three-dimensional Poisson number must lie in (-1, 0.5], got nu = {nu}"
            )
        if E <= 0.0:
            raise MaterialError(f"Young's modulus must be positive, got E = {E}")
        if plane == "stress":
            return cls(nu=nu, E=E, rho=rho)
        if plane == "strain":
            if nu == 0.5:
                raise MaterialError(
                    "plane strain with nu = 0.5 (incompressible) maps to nu_2d = 1, which is "
                    "outside (-1, 1); use nu < 0.5"
                )
            return cls(nu=nu / (1.0 - nu), E=E / (1.0 - nu**2), rho=rho)
        raise MaterialError(f"plane must be 'stress' or 'strain', got {plane!r}")

    @classmethod
    def from_moduli(cls, mu: float, K: float, rho: float = 1.0) -> Material:
        """Material from the 2D shear modulus ``mu`` and compression modulus ``K`` (eq. 4)."""
        mu = _check_finite("mu", mu)
        K = _check_finite("K", K)
        if mu <= 0.0 or K <= 0.0:
            raise MaterialError(f"mu and K must both be positive, got mu = {mu}, K = {K}")
        return cls(nu=(K - mu) / (K + mu), E=4.0 * mu * K / (K + mu), rho=rho)

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
