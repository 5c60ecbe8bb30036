"""The body a half-disk mesh stands for: the disk's upper half or the sphere's meridian section.

Units: ``E = rho = R = 1`` of the body's own constants (the disk's two-dimensional plane-stress
constants, the sphere's three-dimensional ones); speeds in ``c``, lengths in ``R``, forces in
``E R`` (disk, per unit thickness) or ``E R^2`` (sphere), times in ``R / c``.

Both bodies are meshed on the same half disk ``{x^2 + y^2 <= 1, y >= 0}``
(:mod:`restitution.fem.mesh`) with the same elements; only the measure and the elastic
constants differ. The route meshes the kinds that are balls (:attr:`BodyKind.ball
<restitution.bodies.kinds.BodyKind.ball>`), each by its dimension: a planar kind on its upper
half, a three-dimensional kind on its meridian section:

* ``"disk"``: plane stress on the upper half of the disk (the symmetric family, roller
  ``u_y = 0`` on the diameter); measure ``dA``; Lame constants of eq. (6),
  ``lambda_2d = E nu / (1 - nu^2)``; the mesh holds half the disk, so the whole disk's force is
  twice the mesh's (:attr:`Section.copies` = 2).
* ``"sphere"``: axisymmetric elasticity on the meridian section, ``y = r`` the distance from the
  impact axis (the axis is the diameter, where ``u_r = 0``: the same roller); measure
  ``2 pi r dA`` (volume) and ``2 pi r ds`` (surface); three-dimensional Lame constants
  ``lambda = E nu / ((1 + nu)(1 - 2 nu))``; the section stands for the whole sphere
  (:attr:`Section.copies` = 1). The weak forms are in :mod:`restitution.fem.axisymmetric`.

The contact scales that size the meshes and the time step are the bodies' quasistatic Hertz
estimates: eq. (61) and two-dimensional Hertz for the disk, three-dimensional Hertz for the
sphere (:mod:`restitution.bodies.sphere.surface`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.bodies.disk.contact import peak_force_estimate
from restitution.bodies.kinds import DEFAULT_GEOMETRY, BodyKind, geometries, kinds
from restitution.bodies.material import Material
from restitution.errors import InputError

__all__ = [
    "FEM_GEOMETRIES",
    "Section",
    "contact_time",
    "fem_geometries",
    "fem_material",
    "hertz_scales",
    "peak_pressure",
    "section",
]


def fem_geometries() -> tuple[str, ...]:
    """The names of the kinds the FEM route meshes (:attr:`BodyKind.ball`), the default first."""
    return tuple(name for name in geometries() if kinds()[name].ball)


FEM_GEOMETRIES: tuple[str, ...] = fem_geometries()
"""The bodies the FEM route meshes: the package's balls, the disk and the sphere (a kind
registered later is in :func:`fem_geometries`)."""


@dataclass(frozen=True)
class Section:
    """How the half-disk mesh stands for a body.

    Attributes
    ----------
    geometry : str
        A body kind's name (:func:`fem_geometries`).
    axisymmetric : bool
        Whether every integral carries the weight ``2 pi y`` (the sphere's meridian section).
    copies : float
        The whole body's mass, energies and wall force over the mesh's: 2 for the half disk,
        1 for the sphere's section (its weight ``2 pi y`` already sweeps the whole sphere).
    """

    geometry: str
    axisymmetric: bool
    copies: float

    def lame(self, material: Material) -> tuple[float, float]:
        """Lame constants ``(lambda, mu)`` in ``E``: two-dimensional (eq. 6) for the disk,
        three-dimensional for the sphere."""
        E, nu = material.E, material.nu
        if self.axisymmetric:
            return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))
        return E * nu / (1.0 - nu**2), E / (2.0 * (1.0 + nu))


def _kind(geometry: str) -> BodyKind:
    """The kind named ``geometry`` if the FEM route meshes it; else :class:`InputError` naming
    those it meshes."""
    found = kinds().get(geometry) if isinstance(geometry, str) else None
    if found is None or not found.ball:
        raise InputError(
            f"the FEM route meshes {', '.join(fem_geometries())}; got geometry {geometry!r}"
        )
    return found


def section(geometry: str) -> Section:
    """The :class:`Section` of ``geometry``: a planar kind's upper half (two copies make the
    body) or a three-dimensional kind's meridian section (axisymmetric, the whole body);
    :class:`InputError` naming the choices if the FEM route does not mesh it."""
    kind = _kind(geometry)
    if kind.planar:
        return Section(kind.geometry, axisymmetric=False, copies=2.0)
    return Section(kind.geometry, axisymmetric=True, copies=1.0)


def fem_material(material_or_nu: Material | float, geometry: str = DEFAULT_GEOMETRY) -> Material:
    """The material of a FEM body, from itself or from its Poisson number (``E = rho = 1``).

    The constants are the body's own: two-dimensional (plane stress) for the disk,
    three-dimensional for the sphere, whose Poisson number must lie in ``(-1, 0.5)``
    (the kind's :meth:`~restitution.bodies.kinds.BodyKind.check_nu`; the disk's interval is the
    :class:`Material`'s own).
    """
    kind = _kind(geometry)
    material = (
        material_or_nu
        if isinstance(material_or_nu, Material)
        else Material(nu=float(material_or_nu))
    )
    kind.check_nu(material.nu)
    return material


def hertz_scales(
    v: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None
) -> tuple[float, float]:
    """Quasistatic largest wall force and contact half-width at speed ``v`` (``c``).

    * disk: ``F = 2 E0 / delta`` with ``E0 = pi v^2 / 2`` and ``delta = v sqrt(ln(4/v))``
      (eq. 61, :func:`restitution.bodies.disk.contact.peak_force_estimate`; ``E R`` per unit
      thickness) and the two-dimensional Hertz half-width ``a = sqrt(4 F R / (pi E))``;
    * sphere: Hertz, ``delta`` from
      :func:`restitution.bodies.sphere.surface.max_compression_estimate`,
      ``F = (4/3) E* sqrt(R) delta^(3/2)`` (``E R^2``, ``E* = E / (1 - nu^2)``) and the contact
      radius ``a = sqrt(R delta)``.

    Returns
    -------
    force, half_width : float
        ``E R`` (disk) or ``E R^2`` (sphere), and ``R``.
    """
    v = float(v)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    kind = _kind(geometry)
    if section(geometry).axisymmetric:
        nu = _scale_nu(kind, nu)
        delta = kind.max_compression(v, nu)
        force = 4.0 / 3.0 / (1.0 - nu**2) * delta**1.5
        return force, math.sqrt(delta)
    force = peak_force_estimate(v)
    return force, math.sqrt(4.0 * force / math.pi)


def peak_pressure(v: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None) -> float:
    """Quasistatic peak wall pressure at speed ``v``, ``E``: the disk's ``2 F / (pi a)``, the
    sphere's ``3 F / (2 pi a^2)`` (:func:`hertz_scales`)."""
    force, a = hertz_scales(v, geometry, nu)
    if section(geometry).axisymmetric:
        return 3.0 * force / (2.0 * math.pi * a**2)
    return 2.0 * force / (math.pi * a)


def contact_time(v: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None) -> float:
    """Quasistatic contact time against a rigid wall at speed ``v``, ``R / c`` (the kind's
    :attr:`~restitution.bodies.kinds.BodyKind.contact_time`: eq. 61 for the disk, Hertz's
    ``2.943 delta_max / v`` for the sphere)."""
    kind = _kind(geometry)
    if kind.scales_need_nu:
        return float(kind.contact_time(float(v), _scale_nu(kind, nu)))
    return kind.contact_time(float(v), nu)


def _scale_nu(kind: BodyKind, nu: float | None) -> float:
    """``nu`` checked by ``kind``; :class:`InputError` if it is missing."""
    if nu is None:
        raise InputError(
            f"the {kind.geometry}'s contact scales need its Poisson number nu; pass nu="
        )
    return kind.check_nu(nu)
