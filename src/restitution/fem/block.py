"""An elastic wall meshed: a block (or plate) of finite radius and depth, graded towards the
contact, as the partner of a ball in the FEM route.

Units: the ball's, ``E = rho = R = 1`` of its own three-dimensional constants; lengths in
``R``, the wall's constants in the ball's units (:class:`restitution.bodies.wall.HalfSpace`).

The block is the cylinder ``{-depth <= x <= 0, r <= radius}`` about the impact axis, meshed on
its meridian section ``{-depth <= x <= 0, 0 <= y <= radius}`` (``y = r``) and computed by the
axisymmetric elasticity of the sphere's section (:mod:`restitution.fem.section`, the same
weak forms and mass-lumped elements, :mod:`restitution.fem.elasticity`). Its top ``x = 0`` faces
the ball (``+x``) and is named :data:`restitution.fem.mesh.ARC` (the boundary the contact
quadrature walks); the axis ``y = 0`` is :data:`restitution.fem.mesh.DIAMETER` (``u_r = 0``).
The bottom and the side are free: the block is a free body of large mass, so that the
composite of :mod:`restitution.fem.pair_model` (its rigid translation, the relative speed of
the centres of mass) applies as it is.

**The mesh** starts from squares of side ``h_far`` and bisects every element whose longest
edge exceeds ``2^-refine min(h_far, h_contact + grading d)``, ``d`` the distance from the
contact segment ``{x = 0, 0 <= y <= contact_width}`` (the sphere's grading of
:func:`restitution.fem.mesh.graded_half_disk`, on a rectangle). ``h_far`` resolves the waves
the pulse sends (module :mod:`restitution.fem.wall_impact`); the block must be large enough
that no reflection from its bottom or side returns to the contact before the ball leaves
(checked there by doubling it).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from skfem import MeshTri1, MeshTri2

from restitution.bodies.material import Material
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.fem.mesh import ARC, DIAMETER, graded_refinement
from restitution.fem.model import FemModel, model_of_mesh

__all__ = ["block_model", "graded_block"]

_ON_LINE = 1e-12
"""Facet midpoints within this of ``x = 0`` (``y = 0``) lie on the top (the axis)."""


def _distance_to_contact(x: np.ndarray, y: np.ndarray, contact_width: float) -> np.ndarray:
    """Distance from points to the segment ``{x = 0, 0 <= y <= contact_width}``."""
    dy = np.maximum(y - contact_width, 0.0)
    return np.hypot(x, dy)


def graded_block(
    radius: float,
    depth: float,
    contact_width: float,
    *,
    refine: int = 0,
    h_contact: float = 0.04,
    h_far: float = 1.0,
    grading: float = 0.3,
    max_passes: int = 80,
) -> MeshTri2:
    """The block's meridian section graded towards the contact (module docs).

    Parameters
    ----------
    radius, depth : float
        The cylinder's radius and depth, ``R``.
    contact_width : float
        Radius of the top kept at the finest size, ``R``.
    refine : int
        Refinement level; each level halves every target size.
    h_contact, h_far, grading : float
        The size function at ``refine = 0`` (``R``, ``R``, per unit distance).

    Returns
    -------
    skfem.MeshTri2
        With boundaries :data:`~restitution.fem.mesh.ARC` (the top) and
        :data:`~restitution.fem.mesh.DIAMETER` (the axis).
    """
    for name, value in (("radius", radius), ("depth", depth), ("h_contact", h_contact),
                        ("h_far", h_far), ("grading", grading)):  # fmt: skip
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"the block's {name} must be positive, got {value!r}")
    if not 0.0 <= contact_width <= radius:
        raise InputError(f"the contact width must lie in [0, radius], got {contact_width!r}")
    if int(refine) != refine or refine < 0:
        raise InputError(f"the mesh refinement must be a non-negative integer, got {refine}")
    # Squares of side h_far (the last row and column narrower): the cells near the contact,
    # and so their refinement, do not depend on the block's size.
    xs = -np.unique(np.append(np.arange(0.0, depth, h_far), depth))[::-1]
    ys = np.unique(np.append(np.arange(0.0, radius, h_far), radius))
    scale = 2.0**-refine
    m = graded_refinement(
        MeshTri1.init_tensor(np.sort(xs), ys),
        lambda x, y: _distance_to_contact(x, y, contact_width),
        scale * h_contact, scale * h_far, scale * grading, max_passes,
    )  # fmt: skip
    if m is None:
        raise InputError(
            f"the block's mesh did not reach its size function in {max_passes} passes; "
            "raise h_contact or h_far"
        )
    m2 = MeshTri2.from_mesh(m)
    facets = m2.boundary_facets()
    mid = m2.p[:, m2.facets[:, facets]].mean(axis=1)
    top = facets[np.abs(mid[0]) <= _ON_LINE]
    axis = facets[mid[1] <= _ON_LINE]
    return m2.with_boundaries({ARC: top, DIAMETER: axis})


@functools.lru_cache(maxsize=4)
def block_model(
    material: Material,
    radius: float,
    depth: float,
    contact_width: float,
    refine: int,
    h_contact: float,
    h_far: float,
    grading: float,
    n_gauss: int = 8,
) -> FemModel:
    """The block's :class:`~restitution.fem.model.FemModel` (cached): its mesh
    (:func:`graded_block`), the axisymmetric matrices of ``material`` (the wall's constants in
    the ball's units) and the compliances of its top within ``4 contact_width`` of the axis
    (at least ``R``, the part a ball can touch, and one far element beyond)."""
    mesh = graded_block(radius, depth, contact_width, refine=refine, h_contact=h_contact,
                        h_far=h_far, grading=grading)  # fmt: skip
    reach = min(radius, max(4.0 * contact_width, 1.0) + h_far)
    return model_of_mesh(mesh, material, n_gauss, SPHERE.geometry, surface_reach=reach)
