"""Meshes graded towards the contact point, sized by the expected contact half-width.

Units: ``E = rho = R = 1``; lengths in ``R``, speeds in ``c``, ``alpha`` in ``1/R``.

A slow collision touches the wall on a short arc: the two-dimensional Hertz half-width is
``a ~ 0.04 R`` at ``v = 1e-3`` and ``0.13 R`` at ``v = 1e-2`` (:func:`contact_half_width`). A
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

import math
from dataclasses import dataclass, replace

import numpy as np

from restitution.bodies.disk.contact import peak_force_estimate
from restitution.errors import InputError
from restitution.fem.impact import FemSettings, contact_angle_estimate
from restitution.fem.mesh import ARC

__all__ = [
    "ContactGrading",
    "MeshSummary",
    "contact_half_width",
    "graded_settings",
    "mesh_summary",
]


def contact_half_width(v: float) -> float:
    """Expected contact half-width ``a`` (``R``) at speed ``v`` (``c``), two-dimensional Hertz.

    ``a = sqrt(4 F R / (pi E))`` with the quasistatic peak force ``F = pi v / sqrt(ln(4/v))``
    (``E R``; energy ``pi v^2 / 2`` over the compression ``v sqrt(ln(4/v))`` of eq. 61, times 2).

    Examples
    --------
    >>> round(contact_half_width(1e-3), 4)
    0.0373
    """
    v = float(v)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    force = peak_force_estimate(v)
    return math.sqrt(4.0 * force / math.pi)


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


def graded_settings(
    v: float,
    alpha: float,
    level: int,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
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
    base : FemSettings, optional
        Integrator settings (``energy_tol``, ``step_safety``, ...) to keep.

    Returns
    -------
    FemSettings
    """
    grading = grading or ContactGrading()
    base = base or FemSettings()
    a = contact_half_width(v)
    h_contact = min(grading.contact_fraction * a, grading.h_far)
    # The mesh fields come from the grading; every other (integrator) field is kept from base.
    return replace(
        base,
        refine=int(level),
        contact_angle=contact_angle_estimate(v, alpha),
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
        Degrees of freedom of the half disk (kept ``u_x``, ``u_y``).
    n_elements : int
        Triangles.
    h_contact : float
        Longest arc facet (chord) within the Hertz half-width ``a`` of ``(R, 0)``, ``R``.
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
    inside = angle <= contact_half_width(v)
    chords = edges[arc][inside] if np.any(inside) else edges[arc]
    return MeshSummary(
        n_dofs=int(model.disk.n_dofs),
        n_elements=int(mesh.t.shape[1]),
        h_contact=float(chords.max()),
        h_min=float(edges.min()),
        h_max=float(edges.max()),
    )
