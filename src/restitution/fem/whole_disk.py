"""The whole disk for finite elements: mesh, matrices, rim quadrature and bounds (no symmetry).

Units: ``E = rho = R = 1`` (the disk's two-dimensional plane-stress constants, eq. 6); lengths
in ``R``, frequencies in ``c / R``, compliances in ``R / E``.

An oblique impact breaks the mirror symmetry that lets the head-on route mesh half the disk
(:mod:`restitution.fem.elasticity`), so this module builds the whole disk from the same pieces:

* the mesh is the graded half disk (:func:`restitution.fem.mesh.graded_half_disk`) mirrored
  about its diameter, the vertices on the diameter merged, and made isoparametric again (every
  rim facet midpoint on the circle); the finely meshed arc is ``|phi| <= contact_angle``;
* the matrices are those of :func:`restitution.fem.elasticity.assemble_half_disk` (mass-lumped
  P2 + bubble, plane stress) with no roller: all three rigid motions are free;
* the rim quadrature (Gauss-Legendre on every rim facet within ``|phi| <= phi_max``) gives both
  displacement components at its points, ``Bx`` and ``By``: the wall's normal force acts on
  ``u_x``, friction on ``u_y``;
* the bounds of the explicit step: ``omega_K`` (largest frequency), ``lambda_x`` and
  ``lambda_y`` (largest eigenvalues of ``M^-1 Bx^T W Bx`` and ``M^-1 By^T W By``);
* ``chi_j``: the static compliance of the nodes behind each rim point (``|d_j|^2 <= 2 E_vib
  chi_j`` for a free vibration of energy ``E_vib``), for the stop test.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla
from skfem import MeshTri1, MeshTri2

from restitution.bodies.material import Material
from restitution.errors import InputError
from restitution.fem.elasticity import HalfDisk, assemble_half_disk
from restitution.fem.mesh import ARC, DIAMETER, graded_half_disk
from restitution.fem.model import _largest_eigenvalue
from restitution.fem.section import fem_geometries, section

__all__ = [
    "PLANAR_GEOMETRY",
    "RimQuadrature",
    "WholeDisk",
    "mirrored_disk",
    "rim_quadrature",
    "whole_disk_model",
]

PLANAR_GEOMETRY: str = next(g for g in fem_geometries() if not section(g).axisymmetric)
"""The body kind the whole-disk mesh stands for: the FEM route's planar ball (the disk)."""

_ON_DIAMETER = 1e-12


def mirrored_disk(half: MeshTri2) -> MeshTri2:
    """The whole disk: ``half`` and its mirror image in ``y = 0``, with the vertices on the
    diameter merged; isoparametric, every boundary facet named ``"arc"`` (``"diameter"`` is
    empty).

    Examples
    --------
    >>> from restitution.fem.mesh import uniform_half_disk
    >>> m = mirrored_disk(uniform_half_disk(2))
    >>> m.t.shape[1], round(float(abs(m.p[1]).max()), 6)
    (64, 1.0)
    """
    p = half.p[:, : half.nvertices]
    t = half.t
    on = np.abs(p[1]) <= _ON_DIAMETER
    image = np.empty(p.shape[1], dtype=np.int64)
    off = np.nonzero(~on)[0]
    image[on] = np.nonzero(on)[0]
    image[off] = p.shape[1] + np.arange(off.size)
    p_all = np.hstack([p, p[:, off] * np.array([[1.0], [-1.0]])])
    t_image = image[t][[0, 2, 1]]  # mirrored triangles keep a positive orientation
    m1 = MeshTri1(p_all, np.hstack([t, t_image]))
    m2 = MeshTri2.from_mesh(m1)
    facets = m2.boundary_facets()
    dofs = m2.dofs.get_facet_dofs(facets).flatten()
    doflocs = m2.doflocs.copy()
    verts = np.unique(m2.facets[:, facets])
    doflocs[:, verts] /= np.linalg.norm(doflocs[:, verts], axis=0)
    doflocs[:, dofs] /= np.linalg.norm(doflocs[:, dofs], axis=0)
    m2 = replace(m2, doflocs=doflocs)
    return m2.with_boundaries({ARC: facets, DIAMETER: np.zeros(0, dtype=np.int64)})


@dataclass(frozen=True, eq=False)
class RimQuadrature:
    """Quadrature of the rim integrals ``int f ds`` over ``|phi| <= phi_max``.

    Attributes
    ----------
    phi, x_ref, y_ref, weight : numpy.ndarray, shape (P,)
        Reference angle (radians), position (``R``, relative to the reference centre) and arc
        length weight (``R``) of each point, sorted by ``phi``.
    Bx, By : scipy.sparse.csr_matrix, shape (P, n)
        ``u_x`` and ``u_y`` at the points from the degrees of freedom.
    BxT, ByT : scipy.sparse.csr_matrix, shape (n, P)
        Their transposes (forces gathered without re-transposing every step).
    nodes : numpy.ndarray of int, shape (P, 3)
        Scalar node (column of the basis' ``doflocs``) behind each point's two vertices and
        midpoint.
    """

    phi: np.ndarray
    x_ref: np.ndarray
    y_ref: np.ndarray
    weight: np.ndarray
    Bx: sp.csr_matrix
    By: sp.csr_matrix
    BxT: sp.csr_matrix
    ByT: sp.csr_matrix
    nodes: np.ndarray

    @property
    def size(self) -> int:
        """Number of quadrature points."""
        return int(self.phi.size)


def rim_quadrature(disk: HalfDisk, n_gauss: int = 8, phi_max: float = 0.5 * math.pi):
    """Gauss-Legendre points on the whole disk's rim facets whose midpoint has ``|phi| <=
    phi_max`` (the isoparametric facet map of :mod:`restitution.fem.contact`, both components).
    """
    if n_gauss < 1:
        raise InputError(f"n_gauss must be at least 1, got {n_gauss}")
    mesh, basis = disk.mesh, disk.basis
    if disk.free.size != basis.N:
        raise InputError("rim_quadrature needs the whole disk (no removed dofs); use WholeDisk")
    facets = mesh.boundaries[ARC]
    nverts = mesh.nvertices
    a, b = mesh.facets[0, facets], mesh.facets[1, facets]
    mid = mesh.doflocs[:, nverts + facets]
    keep = np.abs(np.arctan2(mid[1], mid[0])) <= phi_max + 1e-12
    facets, a, b, mid = facets[keep], a[keep], b[keep], mid[:, keep]
    Xa, Xb = mesh.doflocs[:, a], mesh.doflocs[:, b]
    t, gw = np.polynomial.legendre.leggauss(n_gauss)
    t, gw = 0.5 * (t + 1.0), 0.5 * gw
    N = np.stack([(1 - t) * (1 - 2 * t), t * (2 * t - 1), 4 * t * (1 - t)])
    dN = np.stack([4 * t - 3, 4 * t - 1, 4 - 8 * t])
    X = Xa[:, :, None] * N[0] + Xb[:, :, None] * N[1] + mid[:, :, None] * N[2]
    dX = Xa[:, :, None] * dN[0] + Xb[:, :, None] * dN[1] + mid[:, :, None] * dN[2]
    weight = np.sqrt((dX**2).sum(axis=0)) * gw
    F, G = facets.size, t.size
    rows = np.broadcast_to(np.arange(F * G).reshape(F, G)[None], (3, F, G))
    vals = np.broadcast_to(N[:, None, :], (3, F, G))
    mats = []
    for comp in range(2):
        dofs = np.stack(
            [
                basis.nodal_dofs[comp, a],
                basis.nodal_dofs[comp, b],
                basis.facet_dofs[comp, facets],
            ]
        )
        cols = np.broadcast_to(dofs[:, :, None], (3, F, G))
        mats.append(
            sp.csr_matrix((vals.ravel(), (rows.ravel(), cols.ravel())), shape=(F * G, basis.N))
        )
    scalar = np.stack([a, b, nverts + facets])  # scalar node numbers (doflocs columns of P2)
    phi = np.arctan2(X[1], X[0]).ravel()
    order = np.argsort(phi, kind="stable")
    Bx, By = (m[order].tocsr() for m in mats)
    return RimQuadrature(
        phi=phi[order],
        x_ref=X[0].ravel()[order],
        y_ref=X[1].ravel()[order],
        weight=weight.ravel()[order],
        Bx=Bx,
        By=By,
        BxT=Bx.T.tocsr(),
        ByT=By.T.tocsr(),
        nodes=np.repeat(scalar.T, G, axis=0)[order],
    )


@dataclass(frozen=True, eq=False)
class WholeDisk:
    """Everything about one whole-disk mesh that an oblique collision needs, computed once.

    Attributes
    ----------
    disk : HalfDisk
        The assembled whole disk (no dof removed; ``rigid`` the unit ``x`` translation).
    quad : RimQuadrature
    ix, iy : numpy.ndarray of int, shape (nodes,)
        The ``u_x`` and ``u_y`` dof of every node (vertices, edge midpoints, centroids).
    X : numpy.ndarray, shape (2, nodes)
        Reference node positions relative to the discrete centre of mass, ``R``.
    node_mass : numpy.ndarray, shape (nodes,)
        Lumped mass of each node (``rho R^2``); ``mass`` their sum, ``inertia`` the moment of
        inertia about the centre (``rho R^4``; ``pi/2`` for the exact disk).
    inverse_mass : numpy.ndarray, shape (n,)
    omega_K, lambda_x, lambda_y : float
        Bounds of the stable step (module docstring), ``c / R`` and ``1 / R``.
    chi : numpy.ndarray, shape (P,)
        Static compliance bound ``max`` over the three nodes behind each point of
        ``chi_x + chi_y`` (``R / E``).
    h_min : float
        Shortest element edge, ``R``.
    """

    disk: HalfDisk
    quad: RimQuadrature
    ix: np.ndarray
    iy: np.ndarray
    X: np.ndarray
    node_mass: np.ndarray
    mass: float
    inertia: float
    inverse_mass: np.ndarray
    omega_K: float
    lambda_x: float
    lambda_y: float
    chi: np.ndarray
    h_min: float


def _node_dofs(disk: HalfDisk) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``u_x`` and ``u_y`` dofs of every scalar node and its reference position."""
    basis = disk.basis
    ix, iy = (
        np.concatenate([basis.nodal_dofs[c], basis.facet_dofs[c], basis.interior_dofs[c]]).ravel()
        for c in range(2)
    )
    mesh = disk.mesh
    centroids = mesh._mapping().F(np.array([[1.0 / 3.0], [1.0 / 3.0]]))[:, :, 0]
    nv, nf = mesh.nvertices, mesh.facets.shape[1]
    X = np.hstack([mesh.doflocs[:, :nv], mesh.doflocs[:, nv : nv + nf], centroids])
    return ix, iy, X


def _rim_compliance(
    disk: HalfDisk, quad: RimQuadrature, ix, iy, X, node_mass: np.ndarray
) -> np.ndarray:
    """``chi_x + chi_y`` of the rim nodes behind every point: ``c^T K^+ c`` with ``c`` the unit
    load with the three rigid motions projected out, solved with three dofs pinned (the load is
    self-equilibrated, so the pins carry no reaction)."""
    n = disk.n_dofs
    rigid = np.zeros((n, 3))
    rigid[ix, 0] = 1.0
    rigid[iy, 1] = 1.0
    rigid[ix, 2] = -X[1]
    rigid[iy, 2] = X[0]
    m = disk.M.diagonal()
    gram = rigid.T @ (m[:, None] * rigid)
    a = int(np.argmin(np.hypot(X[0], X[1])))
    b = int(np.argmin(np.hypot(X[0] + 0.9, X[1])))
    pins = [ix[a], iy[a], iy[b]]
    keep = np.setdiff1d(np.arange(n), pins)
    lu = sla.splu(disk.K[keep][:, keep].tocsc(), permc_spec="MMD_AT_PLUS_A")
    nodes = np.unique(quad.nodes)
    chi_of = {}
    for comp_dofs in (ix, iy):
        dofs = comp_dofs[nodes]
        for start in range(0, dofs.size, 64):
            sel = dofs[start : start + 64]
            c = np.zeros((n, sel.size))
            c[sel, np.arange(sel.size)] = 1.0
            c -= (m[:, None] * rigid) @ np.linalg.solve(gram, rigid[sel].T)
            z = lu.solve(c[keep])
            chi = np.einsum("ij,ij->j", c[keep], z)
            for node, value in zip(nodes[start : start + 64], chi, strict=True):
                chi_of[int(node)] = chi_of.get(int(node), 0.0) + float(value)
    per_node = np.vectorize(chi_of.__getitem__)(quad.nodes)
    return per_node.max(axis=1)


@functools.lru_cache(maxsize=8)
def whole_disk_model(
    material: Material,
    refine: int,
    contact_angle: float,
    h_contact: float = 0.04,
    h_far: float = 0.25,
    grading: float = 0.3,
    n_gauss: int = 8,
    phi_max: float = 0.5 * math.pi,
) -> WholeDisk:
    """Mesh, matrices, rim quadrature and bounds of the whole disk (cached).

    Parameters are those of :class:`restitution.fem.impact.FemSettings` (the graded half disk
    of :func:`restitution.fem.mesh.graded_half_disk`, mirrored); ``phi_max`` (radians) bounds
    the rim the wall integral covers.
    """
    half = graded_half_disk(
        refine, contact_angle, h_contact=h_contact, h_far=h_far, grading=grading
    )
    mesh = mirrored_disk(half)
    disk = assemble_half_disk(mesh, material, "P2+lumped", PLANAR_GEOMETRY)
    if disk.free.size != disk.basis.N:
        raise InputError("the whole disk lost degrees of freedom to a roller; check the mesh")
    quad = rim_quadrature(disk, n_gauss, phi_max)
    ix, iy, X = _node_dofs(disk)
    m = disk.M.diagonal()
    node_mass = m[ix]
    mass = float(node_mass.sum())
    X = X - (node_mass @ X.T / mass)[:, None]
    inertia = float(node_mass @ (X**2).sum(axis=0))
    lam = [
        _largest_eigenvalue((B.T @ sp.diags(quad.weight) @ B).tocsr(), m)
        for B in (quad.Bx, quad.By)
    ]
    p = mesh.p[:, : mesh.nvertices]
    edges = p[:, mesh.facets[0]] - p[:, mesh.facets[1]]
    return WholeDisk(
        disk=disk,
        quad=quad,
        ix=ix,
        iy=iy,
        X=X,
        node_mass=node_mass,
        mass=mass,
        inertia=inertia,
        inverse_mass=1.0 / m,
        omega_K=math.sqrt(_largest_eigenvalue(disk.K, m)),
        lambda_x=lam[0],
        lambda_y=lam[1],
        chi=_rim_compliance(disk, quad, ix, iy, X, node_mass),
        h_min=float(np.sqrt((edges**2).sum(axis=0)).min()),
    )
