"""Meshes graded towards the contact point, sized by the expected contact half-width.

Units: ``E = rho = R = 1``; lengths in ``R``, speeds in ``c``, ``alpha`` in ``1/R``.

A slow collision touches the wall on a short arc: the two-dimensional Hertz half-width is
``a ~ 0.04 R`` at ``v = 1e-3`` and ``0.13 R`` at ``v = 1e-2`` (:func:`contact_half_width`); the
sphere's Hertz contact radius ``a = sqrt(R delta_max)`` is wider, ``0.20 R`` and ``0.51 R`` at
``v = 1e-2`` and ``0.1`` (nu = 0.3). A
uniform mesh fine enough to resolve that arc is far too large; this module sizes the mesh of
:func:`restitution.fem.mesh.graded_half_disk` from ``a`` instead:

* on the contact arc (:func:`restitution.fem.impact.contact_angle_estimate`, the Hertz arc
  widened by the soft wall's tail) the longest element edge is at most
  ``h_contact = contact_fraction * a * 2^-level``;
* away from it the size grows like ``h_contact + grading * d`` (``d`` the distance to the arc),
  i.e. geometrically, by a factor ``1 + grading`` from one element to the next, up to
  ``h_far * 2^-level``;
* boundary vertices and the midpoints of the quadratic arc facets lie on the circle (the mesh
  is isoparametric), so the contact arc is curved as in the continuum problem.

Meshing choice: scikit-fem's own refinement of marked elements, with the new arc vertices
projected onto the circle after every pass (:mod:`restitution.fem.mesh`). It needs no new
dependency, is deterministic, and halving every target size (``level + 1``) halves every
element, which is what a three-level Richardson study needs. An unstructured generator
(PyPI's ``gmsh``) grades more smoothly but gives meshes of unrelated topology at each level.

``level`` 0, 1, 2 are the three meshes of a convergence study; with the default
``contact_fraction = 0.4`` the finest (``level = 2``) has target edges of ``a / 10`` on the
contact arc (bisection makes the actual longest arc chords between about half the target and
the target, measured 0.48-0.82 of ``a / 10`` at ``v`` = 1e-4 to 0.3; :func:`mesh_summary`
measures them).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.errors import InputError
from restitution.fem.impact import FemSettings, contact_angle_estimate
from restitution.fem.mesh import ARC
from restitution.fem.section import hertz_scales, section

__all__ = [
    "ContactGrading",
    "MeshSummary",
    "contact_half_width",
    "default_grading",
    "graded_settings",
    "mesh_summary",
]


def contact_half_width(
    v: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None
) -> float:
    """Expected contact half-width ``a`` (``R``) at speed ``v`` (``c``).

    Disk: two-dimensional Hertz, ``a = sqrt(4 F R / (pi E))`` with the quasistatic peak force
    ``F = pi v / sqrt(ln(4/v))`` (``E R``; energy ``pi v^2 / 2`` over the compression
    ``v sqrt(ln(4/v))`` of eq. 61, times 2). Sphere (needs its ``nu``): Hertz's contact radius
    ``a = sqrt(R delta_max)`` (:func:`restitution.fem.section.hertz_scales`).

    Examples
    --------
    >>> round(contact_half_width(1e-3), 4)
    0.0373
    >>> round(contact_half_width(0.1, "sphere", nu=0.3), 3)
    0.514
    """
    return hertz_scales(v, geometry, nu)[1]


@dataclass(frozen=True)
class ContactGrading:
    """How a mesh is graded towards the contact, relative to the contact half-width.

    Attributes
    ----------
    contact_fraction : float
        Target longest edge on the contact arc at ``level = 0``, in units of the contact
        half-width ``a`` (dimensionless).
    grading : float
        Growth of the element size per unit distance from the contact arc (dimensionless);
        neighbouring elements differ in size by about ``1 + grading``.
    h_far : float
        Largest element size at ``level = 0``, ``R``.
    """

    contact_fraction: float = 0.4
    grading: float = 0.5
    h_far: float = 0.4

    def __post_init__(self) -> None:
        if not self.contact_fraction > 0:
            raise InputError(f"contact_fraction must be positive, got {self.contact_fraction}")
        if not self.grading > 0:
            raise InputError(f"grading must be positive, got {self.grading}")
        if not self.h_far > 0:
            raise InputError(f"h_far must be positive (R), got {self.h_far}")

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "contact_fraction": self.contact_fraction,
            "grading": self.grading,
            "h_far": self.h_far,
        }


def default_grading(geometry: str = DEFAULT_GEOMETRY) -> ContactGrading:
    """The grading of a convergence study of ``geometry`` when none is given.

    The disk: :class:`ContactGrading` as it is. The sphere: bulk elements of at most
    ``h_far = 0.17 R`` at level 0 (``0.4 R`` for the disk). Its contact radius is wide (``0.51 R``
    at ``v = 0.1``, nu = 0.3) and its loss comes from the whole body, and the bisection meshes
    halve their sizes cleanly only below about ``0.2 R``. Measured ``1 - eps^2`` at nu = 0.3,
    ``v = 0.1``, ``alpha = 303`` on levels 0, 1, 2: ``h_far = 0.4``: 0.0137270, 0.0135632,
    0.0137332 (not contracting); ``0.2``: 0.0137254, 0.0137213, 0.0137269 (not contracting,
    the arc chords jump from 0.098 to 0.025); ``0.17``: 0.0137195, 0.0137266, 0.0137274
    (monotone, order 3.2; limit 0.0137275 +- 1e-7, level 3 of ``h_far = 0.2`` gives 0.0137276).
    Cost: 46 s at ``v = 0.1`` and 95 s at ``v = 0.01`` for both limits (``0.2``: 12 s, 28 s).
    """
    if section(geometry).axisymmetric:
        return ContactGrading(h_far=0.17)
    return ContactGrading()


def graded_settings(
    v: float,
    alpha: float,
    level: int,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    nu: float | None = None,
) -> FemSettings:
    """FEM settings of the contact-graded mesh ``level`` for speed ``v`` and hardness ``alpha``.

    Parameters
    ----------
    v : float
        Speed towards the wall, ``c``.
    alpha : float
        Wall hardness, ``1/R`` (widens the finely meshed arc by the wall's tail).
    level : int
        Refinement level, >= 0; every level halves all target sizes.
    grading : ContactGrading, optional
        Default :func:`default_grading` of the ``geometry``.
    base : FemSettings, optional
        Integrator settings (``energy_tol``, ``step_safety``, ...) to keep.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body whose contact sizes the mesh; the sphere's needs its Poisson number ``nu``.

    Returns
    -------
    FemSettings
    """
    grading = grading or default_grading(geometry)
    base = base or FemSettings()
    a = contact_half_width(v, geometry, nu)
    h_contact = min(grading.contact_fraction * a, grading.h_far)
    # The mesh fields come from the grading; every other (integrator) field is kept from base.
    return replace(
        base,
        refine=int(level),
        contact_angle=contact_angle_estimate(v, alpha, geometry, nu),
        h_contact=h_contact,
        h_far=grading.h_far,
        grading=grading.grading,
    )


@dataclass(frozen=True)
class MeshSummary:
    """Sizes of one graded mesh.

    Attributes
    ----------
    n_dofs : int
        Degrees of freedom of the half disk (kept ``u_x``, ``u_y``; the sphere's ``u_x``,
        ``u_r``).
    n_elements : int
        Triangles.
    h_contact : float
        Longest arc facet (chord) within the Hertz half-width (sphere: contact radius) ``a`` of
        ``(R, 0)``, ``R``.
    h_min, h_max : float
        Shortest and longest element edge, ``R``.
    """

    n_dofs: int
    n_elements: int
    h_contact: float
    h_min: float
    h_max: float

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "n_dofs": self.n_dofs,
            "n_elements": self.n_elements,
            "h_contact": self.h_contact,
            "h_min": self.h_min,
            "h_max": self.h_max,
        }


def mesh_summary(model, v: float) -> MeshSummary:
    """Measured sizes of the mesh of a :class:`restitution.fem.model.FemModel` at speed ``v``."""
    mesh = model.disk.mesh
    p = mesh.p[:, : mesh.nvertices]
    edges = np.sqrt(((p[:, mesh.facets[0]] - p[:, mesh.facets[1]]) ** 2).sum(axis=0))
    arc = mesh.boundaries[ARC]
    a, b = p[:, mesh.facets[0, arc]], p[:, mesh.facets[1, arc]]
    angle = np.minimum(np.abs(np.arctan2(a[1], a[0])), np.abs(np.arctan2(b[1], b[0])))
    disk = model.disk
    inside = angle <= contact_half_width(v, disk.geometry, disk.material.nu)
    chords = edges[arc][inside] if np.any(inside) else edges[arc]
    return MeshSummary(
        n_dofs=int(model.disk.n_dofs),
        n_elements=int(mesh.t.shape[1]),
        h_contact=float(chords.max()),
        h_min=float(edges.min()),
        h_max=float(edges.max()),
    )
