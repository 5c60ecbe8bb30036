"""Triangle meshes of the upper half of the unit disk, with a curved (quadratic) arc.

Units: lengths in ``R = 1``. The half disk ``{|x| <= 1, y >= 0}`` carries the symmetric family
of the disk's motions (``u_x`` even and ``u_y`` odd in ``y``); its diameter ``y = 0`` is the
symmetry line and its arc the free (or wall-facing) edge.

Meshes are built from two right triangles by refinement; after every refinement the new
vertices on the arc are moved onto the circle. The returned :class:`skfem.MeshTri2` is
isoparametric: the midpoint of every arc facet lies on the circle too, so the boundary is
represented to ``O(h^3)`` and P2 eigenvalues converge like ``h^4`` (not ``h^2`` as with straight
facets).

Two families:

* :func:`uniform_half_disk` -- ``level`` uniform (red) refinements; element size ``~ 2^-level``.
* :func:`graded_half_disk` -- refined by marking until every element is smaller than a size
  function that is finest along the arc ``0 <= phi <= contact_angle`` (where the disk touches
  the wall) and grows linearly with the distance from it.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from skfem import MeshTri1, MeshTri2

from restitution.errors import InputError

__all__ = ["graded_half_disk", "graded_refinement", "uniform_half_disk", "ARC", "DIAMETER"]

ARC = "arc"
"""Name of the boundary part ``r = 1, y > 0``."""
DIAMETER = "diameter"
"""Name of the boundary part ``y = 0`` (the symmetry line)."""

# Facet midpoints with y below this lie on the diameter (their y is exactly 0 there).
_ON_DIAMETER = 1e-12


def _coarse() -> MeshTri1:
    """Two right triangles: the square with corners (+-1, 0), (0, 1), centre (0, 0)."""
    p = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]]).T
    t = np.array([[0, 1, 2], [0, 2, 3]]).T
    return MeshTri1(p, t)


def _project_arc(m: MeshTri1) -> MeshTri1:
    """Move the boundary vertices off the diameter onto the unit circle."""
    nodes = m.boundary_nodes()
    nodes = nodes[m.p[1, nodes] > _ON_DIAMETER]
    p = m.p.copy()
    p[:, nodes] /= np.linalg.norm(p[:, nodes], axis=0)
    return replace(m, doflocs=p)


def _quadratic(m: MeshTri1) -> MeshTri2:
    """Isoparametric P2 mesh with arc facet midpoints on the circle and named boundaries."""
    m2 = MeshTri2.from_mesh(m)
    facets = m2.boundary_facets()
    mid = m2.p[:, m2.facets[:, facets]].mean(axis=1)
    arc = facets[mid[1] > _ON_DIAMETER]
    diameter = facets[mid[1] <= _ON_DIAMETER]
    dofs = m2.dofs.get_facet_dofs(arc).flatten()
    doflocs = m2.doflocs.copy()
    doflocs[:, dofs] /= np.linalg.norm(doflocs[:, dofs], axis=0)
    m2 = replace(m2, doflocs=doflocs)
    return m2.with_boundaries({ARC: arc, DIAMETER: diameter})


def uniform_half_disk(level: int) -> MeshTri2:
    """Half disk after ``level`` uniform refinements of two right triangles.

    Parameters
    ----------
    level : int
        Number of refinements, >= 1. The diameter is cut into ``2^(level+1)`` facets of length
        ``h = 2^-level`` (in ``R``).

    Returns
    -------
    skfem.MeshTri2
        Isoparametric mesh with boundaries ``"arc"`` and ``"diameter"``;
        ``2 * 4^level`` triangles.

    Examples
    --------
    >>> uniform_half_disk(2).t.shape
    (3, 32)
    """
    if level < 1:
        raise InputError(f"the mesh level must be at least 1, got {level}")
    m = _coarse()
    for _ in range(level):
        m = _project_arc(m.refined())
    return _quadratic(m)


def _distance_to_contact_arc(x: np.ndarray, y: np.ndarray, contact_angle: float) -> np.ndarray:
    """Distance from points to the arc ``{(cos phi, sin phi): 0 <= phi <= contact_angle}``."""
    r = np.hypot(x, y)
    theta = np.arctan2(y, x)
    end = np.hypot(x - math.cos(contact_angle), y - math.sin(contact_angle))
    return np.where(theta <= contact_angle, np.abs(1.0 - r), end)


def graded_half_disk(
    refine: int,
    contact_angle: float,
    *,
    h_contact: float = 0.04,
    h_far: float = 0.25,
    grading: float = 0.3,
    max_passes: int = 60,
) -> MeshTri2:
    """Half disk graded towards the part of the arc that touches the wall.

    Elements are bisected until their longest edge is below the size function
    ``2^-refine * min(h_far, h_contact + grading * d)``, with ``d`` the distance (in ``R``) to
    the contact arc ``0 <= phi <= contact_angle``. Raising ``refine`` by one halves every
    element size, so ``refine`` is the parameter of a mesh-convergence study.

    Parameters
    ----------
    refine : int
        Refinement level, >= 0.
    contact_angle : float
        Angular half-width (radians) of the arc kept at the finest size; it should cover the
        largest contact patch of the collision.
    h_contact, h_far : float
        Element sizes (``R``) on the contact arc and far from it at ``refine = 0``.
    grading : float
        Growth of the element size per unit distance from the contact arc.
    max_passes : int
        Bound on the refinement passes.

    Returns
    -------
    skfem.MeshTri2
        Isoparametric mesh with boundaries ``"arc"`` and ``"diameter"``.
    """
    if refine < 0:
        raise InputError(f"the mesh refinement must be >= 0, got {refine}")
    if not 0.0 <= contact_angle <= math.pi:
        raise InputError(f"contact_angle must lie in [0, pi], got {contact_angle}")
    if not (0 < h_contact <= h_far):
        raise InputError(f"need 0 < h_contact <= h_far, got {h_contact}, {h_far}")
    m = graded_refinement(
        _project_arc(_coarse().refined()),
        lambda x, y: _distance_to_contact_arc(x, y, contact_angle),
        2.0**-refine * h_contact, 2.0**-refine * h_far, 2.0**-refine * grading, max_passes,
        _project_arc,
    )  # fmt: skip
    if m is None:
        raise InputError(
            f"the graded mesh did not reach its size function in {max_passes} passes; "
            "raise max_passes or h_contact"
        )
    return _quadratic(m)


def graded_refinement(
    m: MeshTri1,
    distance,
    h_contact: float,
    h_far: float,
    grading: float,
    max_passes: int,
    after=lambda m: m,
) -> MeshTri1 | None:
    """``m`` bisected until every element's longest edge is below
    ``min(h_far, h_contact + grading d)``, ``d = distance(x, y)`` of the element's nearest
    point (its centroid's less half its longest edge); ``after`` is applied to every refined
    mesh (the half disk projects its arc). ``None`` if ``max_passes`` passes do not reach it."""
    for _ in range(max_passes):
        p = m.p[:, m.t]
        edges = np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 1], p[:, 0] - p[:, 2]])
        longest = np.sqrt((edges**2).sum(axis=1)).max(axis=0)
        cx, cy = p.mean(axis=1)
        d = np.maximum(distance(cx, cy) - 0.5 * longest, 0.0)
        target = np.minimum(h_far, h_contact + grading * d)
        marked = np.nonzero(longest > target)[0]
        if marked.size == 0:
            return m
        m = after(m.refined(marked))
    return None
