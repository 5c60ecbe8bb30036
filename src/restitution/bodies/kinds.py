"""The kinds of body the package knows, by name: what the layers above need before a body exists.

Units: ``E = rho = R = 1`` of the body's own constants (the disk's two-dimensional plane-stress
constants, the sphere's three-dimensional ones); speeds in ``c = sqrt(E / rho)``; compressions in
``R``; times in ``R / c``; frequencies in ``c / R``.

A :class:`~restitution.bodies.base.ModalBody` answers for itself once its modes are computed.
Some questions come earlier -- which Poisson numbers are allowed, how many modes lie below a
frequency, how far a wall compresses the body at a speed (the sweeps size their walls from it) --
and a name such as ``"sphere"`` on the command line has to become a body. :func:`body_kind`
answers them; a new body registers one :class:`BodyKind` in :data:`KINDS`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from restitution.bodies.base import ModalBody
from restitution.bodies.disk import contact as disk_contact
from restitution.bodies.disk.modes import _ALGORITHM_VERSION as _DISK_ALGORITHM
from restitution.bodies.disk.modes import ModeSet, compute_modes
from restitution.bodies.disk.modes import weyl_count as disk_weyl_count
from restitution.bodies.sphere import surface as sphere_surface
from restitution.bodies.sphere.modes import _ALGORITHM_VERSION as _SPHERE_ALGORITHM
from restitution.bodies.sphere.modes import SphereModes, compute_sphere_modes
from restitution.bodies.sphere.modes import weyl_count as sphere_weyl_count
from restitution.errors import InputError, real

__all__ = ["GEOMETRIES", "KINDS", "BodyKind", "body_kind"]


@dataclass(frozen=True)
class BodyKind:
    """What is known about a kind of body before its modes are computed.

    Attributes
    ----------
    geometry : str
        The name (``"disk"``, ``"sphere"``), equal to the bodies' ``geometry``.
    description : str
        One line for users: the body and which constants its reduced units are made of.
    nu_low, nu_high : float
        The open interval of allowed Poisson numbers (of the body's own elasticity).
    mode_class : type
        The dataclass of its mode sets (the cache stores its array fields).
    algorithm : int
        Version of the mode algorithm (part of the mode cache key).
    compute : callable
        ``compute(nu, count=None, omega_max=None)`` -> mode set (no cache).
    weyl_count : callable
        ``weyl_count(omega, nu)``: leading estimate of the number of modes below ``omega``.
    max_compression : callable
        ``max_compression(v, nu)``: quasistatic largest compression against a rigid wall, ``R``.
    contact_time : callable
        ``contact_time(v, nu)``: quasistatic contact time against a rigid wall, ``R / c``.
    max_modes : int
        Most modes the mode cache computes (their cost is measured in the module of the modes).
    units : dict of str to str
        The units of every number reported for this body (every JSON output carries them).
    """

    geometry: str
    description: str
    nu_low: float
    nu_high: float
    mode_class: type
    algorithm: int
    compute: Callable[..., ModalBody]
    weyl_count: Callable[[float, float], float]
    max_compression: Callable[[float, float], float]
    contact_time: Callable[[float, float], float]
    max_modes: int
    units: dict[str, str]

    def check_nu(self, nu) -> float:
        """``nu`` as a float if it is a number in ``(nu_low, nu_high)``, else
        :class:`InputError` naming ``nu`` (a bool or a string is not a number)."""
        allowed = f"in ({self.nu_low:g}, {self.nu_high:g})"
        nu = real(nu, "nu", f"{allowed} (the Poisson number of the {self.geometry})")
        if not self.nu_low < nu < self.nu_high:
            raise InputError(
                f"the Poisson number nu of the {self.geometry} must lie {allowed}, got {nu!r}; "
                f"pass nu {allowed}"
            )
        return nu

    def omega_for(self, count: int, nu: float) -> float:
        """The frequency below which about ``count`` modes lie (inverse of ``weyl_count``)."""
        return math.sqrt(count / self.weyl_count(1.0, nu))


def _units(system: str, body: str, force: str, mass: str) -> dict[str, str]:
    return {
        "system": system,
        "length": "R",
        "time": "R/c",
        "speed": f"c = sqrt(E/rho) (v: the {body}'s speed towards the wall)",
        "frequency": "c/R",
        "alpha": "1/R",
        "force": force,
        "energy": f"fraction of the initial kinetic energy (m/2) v^2, {mass}",
        "wall_time": "s",
    }


KINDS: dict[str, BodyKind] = {
    "disk": BodyKind(
        geometry="disk",
        description=(
            "elastic disk in plane stress; E, nu, rho are its two-dimensional constants; "
            "mass pi rho R^2 per unit thickness"
        ),
        nu_low=-1.0,
        nu_high=1.0,
        mode_class=ModeSet,
        algorithm=_DISK_ALGORITHM,
        compute=compute_modes,
        weyl_count=disk_weyl_count,
        max_compression=lambda v, nu: disk_contact.max_compression_estimate(v),
        contact_time=lambda v, nu: disk_contact.contact_time_estimate(v),
        # The scale-free Bessel scan (docs/numerics.md): 1e4 modes in about 2 s, 1e5 in 23-44 s
        # with 300-380 MiB peak on the project's 2-core machine; 2e5 take minutes and ~1 GiB.
        max_modes=200_000,
        units=_units(
            "E = rho = R = 1: two-dimensional Young modulus, mass per area and disk radius",
            "disk",
            "E R",
            "m = pi",
        ),
    ),
    "sphere": BodyKind(
        geometry="sphere",
        description=(
            "elastic sphere; E, nu, rho are its three-dimensional constants; mass 4 pi rho R^3 / 3"
        ),
        nu_low=-1.0,
        nu_high=0.5,
        mode_class=SphereModes,
        algorithm=_SPHERE_ALGORITHM,
        compute=compute_sphere_modes,
        weyl_count=sphere_weyl_count,
        max_compression=sphere_surface.max_compression_estimate,
        contact_time=sphere_surface.contact_time_estimate,
        # The dense scan over (l, omega) grows like N^(3/2): 6400 modes in 18 s at nu = 0.3
        # (0.8 million grid points); 20000 modes scan about 2.6 million.
        max_modes=20_000,
        units=_units(
            "E = rho = R = 1: the sphere's Young modulus, density and radius",
            "sphere",
            "E R^2",
            "m = 4 pi / 3",
        ),
    ),
}
"""Every kind of body, by geometry name."""

GEOMETRIES: tuple[str, ...] = tuple(KINDS)
"""The geometry names, the disk first (the default everywhere)."""


def body_kind(geometry: str) -> BodyKind:
    """The :class:`BodyKind` named ``geometry``; :class:`InputError` naming the choices if none."""
    kind = KINDS.get(geometry) if isinstance(geometry, str) else None
    if kind is None:
        raise InputError(f"unknown geometry {geometry!r}; choose one of {', '.join(GEOMETRIES)}")
    return kind
