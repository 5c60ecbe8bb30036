"""What a finite-element collision needs to know about one mesh, computed once and cached.

Units: ``E = rho = R = 1``; frequencies in ``c / R``, compliances in ``R / E``.

* The discretised half disk (mass-lumped P2 + bubble, :mod:`restitution.fem.elasticity`; for
  ``geometry="sphere"`` the sphere's axisymmetric meridian section) on the graded mesh
  (:func:`restitution.fem.mesh.graded_half_disk`) and its arc quadrature.
* ``omega_K``: the largest frequency of the mesh, and ``lambda_B``: the largest eigenvalue of
  ``M^-1 B^T W B``; the wall adds at most ``alpha p_max lambda_B`` to ``omega^2`` (``p_max`` the
  largest pressure), which bounds the stable step of the explicit integrator.
* ``chi_j = c_j^T K^+ c_j``: the static compliance of every arc node ``j`` in ``x`` with the
  translation projected out (``c_j = e_j - M rigid / mass``). A free vibration of energy ``E``
  moves node ``j`` relative to the centre of mass by at most ``sqrt(2 E chi_j)``.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla
from skfem import MeshTri2

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.fem.contact import ArcQuadrature, arc_quadrature
from restitution.fem.elasticity import HalfDisk, assemble_half_disk
from restitution.fem.mesh import graded_half_disk

__all__ = ["FemModel", "fem_model", "model_of_mesh", "start_vector"]


@dataclass(frozen=True, eq=False)
class FemModel:
    """Everything about one mesh that a collision needs, computed once.

    Attributes
    ----------
    disk : HalfDisk
    quad : ArcQuadrature
    inverse_mass : numpy.ndarray, shape (n,)
        Inverse of the diagonal (lumped) mass matrix, ``1 / (rho R^2)``.
    r : numpy.ndarray, shape (n,)
        ``M @ rigid``: ``r @ u / mass`` is the centre-of-mass displacement.
    omega_K : float
        Largest frequency of the mesh, ``c / R``.
    lambda_B : float
        Largest eigenvalue of ``M^-1 B^T W B`` (``1 / R``).
    chi : numpy.ndarray, shape (P,)
        Largest static compliance ``c^T K^+ c`` of the three nodes behind each quadrature
        point (``R / E``).
    h_min : float
        Shortest element edge, ``R``.
    """

    disk: HalfDisk
    quad: ArcQuadrature
    inverse_mass: np.ndarray
    r: np.ndarray
    omega_K: float
    lambda_B: float
    chi: np.ndarray
    h_min: float


def _largest_eigenvalue(A: sp.spmatrix, mass_diagonal: np.ndarray) -> float:
    """Largest eigenvalue of the pencil ``(A, diag(mass_diagonal))``, with 1 % headroom."""
    scale = sp.diags(1.0 / np.sqrt(mass_diagonal))
    # A fixed start vector: without one ARPACK draws it from a generator whose state is kept
    # across calls, so the step, and every number of a run, would depend on what the process
    # computed before (their last digits; stop 70).
    w = sla.eigsh(scale @ A @ scale, k=1, which="LA", return_eigenvectors=False, tol=1e-4,
                  v0=start_vector(A.shape[0]))  # fmt: skip
    # eigsh's tolerance is relative; the headroom covers it.
    return float(w[0]) * 1.01


def start_vector(n: int) -> np.ndarray:
    """ARPACK's start vector for a matrix of order ``n``: normal deviates of a fixed seed, so
    an eigenvalue does not depend on the calls made before it in the process."""
    return np.random.default_rng(20261202).standard_normal(n)


def _arc_compliance(disk: HalfDisk, quad: ArcQuadrature, r: np.ndarray) -> np.ndarray:
    """``chi_j = c_j^T K^+ c_j`` of the arc nodes, gathered to the quadrature points."""
    nodes = np.unique(quad.facet_nodes)
    pin = int(np.nonzero(disk.rigid)[0][0])
    if pin in nodes:
        pin = int(np.nonzero(disk.rigid)[0][-1])
    keep = np.setdiff1d(np.arange(disk.n_dofs), [pin])
    lu = sla.splu(disk.K[keep][:, keep].tocsc(), permc_spec="MMD_AT_PLUS_A")
    pos = np.searchsorted(keep, nodes)
    y = lu.solve(r[keep] / disk.mass)
    chi = np.empty(nodes.size)
    for start in range(0, nodes.size, 64):
        sel = slice(start, start + 64)
        rhs = np.zeros((keep.size, pos[sel].size))
        rhs[pos[sel], np.arange(pos[sel].size)] = 1.0
        z = lu.solve(rhs) - y[:, None]
        # c~ = e_j - r / mass, so c~^T z = z_j - (r / mass) . z
        chi[sel] = z[pos[sel], np.arange(pos[sel].size)] - (r[keep] / disk.mass) @ z
    chi_of = dict(zip(nodes.tolist(), chi, strict=True))
    per_node = np.vectorize(chi_of.__getitem__)(quad.facet_nodes)
    return per_node.max(axis=1)


@functools.lru_cache(maxsize=8)
def fem_model(
    material: Material,
    refine: int,
    contact_angle: float,
    h_contact: float = 0.04,
    h_far: float = 0.25,
    grading: float = 0.3,
    n_gauss: int = 8,
    geometry: str = DEFAULT_GEOMETRY,
) -> FemModel:
    """Mesh, matrices and bounds for one material and mesh (cached).

    Parameters are those of :class:`FemSettings` (``contact_angle`` in radians) and the
    ``geometry`` (a body kind the FEM route meshes, :func:`restitution.fem.section.fem_geometries`).
    """
    mesh = graded_half_disk(
        refine, contact_angle, h_contact=h_contact, h_far=h_far, grading=grading
    )
    return model_of_mesh(mesh, material, n_gauss, geometry)


def model_of_mesh(
    mesh: MeshTri2,
    material: Material,
    n_gauss: int,
    geometry: str,
    surface_reach: float | None = None,
) -> FemModel:
    """The :class:`FemModel` of any mesh with the boundaries of :mod:`restitution.fem.mesh`
    (``"arc"``, the contact side; ``"diameter"``, the symmetry line or axis): the matrices of
    ``geometry``, the contact quadrature on the arc facets (those within ``surface_reach`` of
    the axis when given, :func:`restitution.fem.contact.arc_quadrature`), the bounds and the
    compliances."""
    disk = assemble_half_disk(mesh, material, "P2+lumped", geometry)
    quad = arc_quadrature(disk, n_gauss, y_max=surface_reach)
    mass_diagonal = disk.M.diagonal()
    r = disk.M @ disk.rigid
    omega_K = math.sqrt(_largest_eigenvalue(disk.K, mass_diagonal))
    BtWB = (quad.B.T @ sp.diags(quad.weight) @ quad.B).tocsr()
    lambda_B = _largest_eigenvalue(BtWB, mass_diagonal)
    p = mesh.p[:, : mesh.nvertices]
    edges = p[:, mesh.facets[0]] - p[:, mesh.facets[1]]
    return FemModel(
        disk=disk,
        quad=quad,
        inverse_mass=1.0 / mass_diagonal,
        r=r,
        omega_K=omega_K,
        lambda_B=lambda_B,
        chi=_arc_compliance(disk, quad, r),
        h_min=float(np.sqrt((edges**2).sum(axis=0)).min()),
    )
