"""An elastic wall, by its constants: the partner of a ball that is not a rigid wall.

Units: the ball's reduced units, ``E = rho = R = 1`` of its own constants (a sphere's 3D ones);
speeds in ``c = sqrt(E / rho)``.

A :class:`HalfSpace` is a massive block of another material, so thick and wide that no wave
returns before the ball leaves: its modulus and density in units of the ball's and its own
Poisson number. It has no modes; what it takes is the energy radiated away as elastic waves
(:mod:`restitution.quasistatic.half_space`). Plates (Zener's thin-plate model) are a later
partner of this kind (issue 42).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.errors import InputError

__all__ = ["HalfSpace", "Plate", "wall_from_dict"]


@dataclass(frozen=True)
class HalfSpace:
    """An elastic half-space wall (module docs).

    Attributes
    ----------
    modulus_ratio, density_ratio : float
        ``E_w / E`` and ``rho_w / rho`` (3D constants).
    nu : float
        The wall's Poisson number, in ``(-1, 0.5)``.
    """

    modulus_ratio: float
    density_ratio: float
    nu: float

    def __post_init__(self) -> None:
        for name in ("modulus_ratio", "density_ratio", "nu"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise InputError(f"the wall's {name.replace('_', ' ')} must be a number")
            object.__setattr__(self, name, float(value))
        for name in ("modulus_ratio", "density_ratio"):
            value = getattr(self, name)
            if not (math.isfinite(value) and 1e-12 <= value <= 1e12):
                raise InputError(
                    f"the wall's {name.replace('_', ' ')} must lie in 1e-12 ... 1e12 (the "
                    f"ball's units), got {value!r}"
                )
        if not -1.0 < self.nu < 0.5:
            raise InputError(f"the wall's Poisson number must lie in (-1, 0.5), got {self.nu!r}")

    @property
    def shear_speed(self) -> float:
        """``c_T = sqrt(E_w / (2 (1 + nu_w) rho_w))``, ``c``."""
        return math.sqrt(self.modulus_ratio / (2.0 * (1.0 + self.nu) * self.density_ratio))

    @property
    def compressional_speed(self) -> float:
        """``c_L = c_T sqrt(2 (1 - nu_w) / (1 - 2 nu_w))``, ``c``."""
        return self.shear_speed * math.sqrt(2.0 * (1.0 - self.nu) / (1.0 - 2.0 * self.nu))

    def effective_modulus(self, nu_ball: float) -> float:
        """Hertz's ``E*``: ``1 / E* = (1 - nu^2) + (1 - nu_w^2) / E_w``, ``E``."""
        return 1.0 / ((1.0 - nu_ball**2) + (1.0 - self.nu**2) / self.modulus_ratio)

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "kind": "half-space",
            "modulus_ratio": self.modulus_ratio,
            "density_ratio": self.density_ratio,
            "nu": self.nu,
        }


@dataclass(frozen=True)
class Plate(HalfSpace):
    """An infinite elastic plate of ``thickness`` (``R``, the ball's radius): a wall that
    bends (Zener's thin-plate model, :mod:`restitution.quasistatic.plate`).

    Attributes
    ----------
    thickness : float
        ``h / R``.
    """

    thickness: float = 1.0

    def __post_init__(self) -> None:
        super().__post_init__()
        h = self.thickness
        if (
            isinstance(h, bool)
            or not isinstance(h, int | float)
            or not (math.isfinite(h) and 1e-6 <= h <= 1e6)
        ):
            raise InputError(f"the plate's thickness must lie in 1e-6 ... 1e6 R, got {h!r}")
        object.__setattr__(self, "thickness", float(h))

    @property
    def bending_stiffness(self) -> float:
        """``D = E_w h^3 / (12 (1 - nu_w^2))``, ``E R^3``."""
        return self.modulus_ratio * self.thickness**3 / (12.0 * (1.0 - self.nu**2))

    @property
    def impedance(self) -> float:
        """The infinite thin plate's point impedance ``Z = 8 sqrt(D rho_w h)`` (force over the
        velocity of the loaded point, real), ``E R^2 / c``."""
        return 8.0 * math.sqrt(self.bending_stiffness * self.density_ratio * self.thickness)

    def to_dict(self) -> dict:
        return {**super().to_dict(), "kind": "plate", "thickness": self.thickness}


def wall_from_dict(d: dict) -> HalfSpace:
    """The wall of a :meth:`HalfSpace.to_dict` (``"kind"`` ``"half-space"`` or ``"plate"``)."""
    constants = (float(d["modulus_ratio"]), float(d["density_ratio"]), float(d["nu"]))
    if d["kind"] == "plate":
        return Plate(*constants, thickness=float(d["thickness"]))
    if d["kind"] == "half-space":
        return HalfSpace(*constants)
    raise InputError(f"a wall's kind is 'half-space' or 'plate', got {d['kind']!r}")
