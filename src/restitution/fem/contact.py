"""The exponential wall acting on the arc of the finite-element half disk (paper eq. 41).

Units: ``E = rho = R = 1``. The material point with reference position ``X`` sits at
``x = x_c + X_x + u_x(X)``, where ``x_c`` is the reference position of the disk's centre and
``u`` the finite-element displacement (including the rigid motion). The wall potential of the
half disk is

    V_half = (1/alpha) int_{arc, 0 <= phi <= pi/2} exp(alpha x) ds,

half of eq. (41) (``ds = dphi`` for ``R = 1``); the whole disk's potential and wall force are
twice the half disk's. For the sphere (``geometry="sphere"``, :mod:`restitution.fem.section`)
the arc is the meridian of its surface and the same integral, weighted by ``2 pi r``
(``r = X_y``, the distance from the axis), is the wall potential of the whole sphere,

    V = (1/alpha) int_{near hemisphere} exp(alpha x) dA,    dA = 2 pi r ds,

the surface integral of :mod:`restitution.bodies.sphere.surface` (``0 <= theta <= pi/2``; the
far half never touches).

The integral is a Gauss-Legendre rule on every arc facet. On a facet the isoparametric P2 map
and the displacement trace are both quadratic in the facet parameter ``t`` in ``[0, 1]``, with
shape functions ``(1-t)(1-2t)``, ``t(2t-1)`` (end vertices) and ``4t(1-t)`` (midpoint); the
weights are the arc length of the discretised boundary, ``|dX/dt| dt``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from restitution.errors import InputError
from restitution.fem.elasticity import HalfDisk
from restitution.fem.mesh import ARC

__all__ = ["ArcQuadrature", "arc_quadrature", "wall_terms"]


@dataclass(frozen=True, eq=False)
class ArcQuadrature:
    """Quadrature of the wall integral over the arc ``0 <= phi <= phi_max``.

    Attributes
    ----------
    phi : numpy.ndarray, shape (P,)
        Reference polar angle of each point, radians.
    x_ref : numpy.ndarray, shape (P,)
        Reference ``x`` of each point relative to the centre, ``R`` (``~cos phi``).
    weight : numpy.ndarray, shape (P,)
        Arc-length weights of the half disk's arc, ``R`` (sphere: surface weights
        ``2 pi r ds``, ``R^2``).
    B : scipy.sparse.csr_matrix, shape (P, n)
        ``u_x`` at the points from the kept degrees of freedom of the :class:`HalfDisk`.
    BT : scipy.sparse.csr_matrix, shape (n, P)
        ``B.T``, stored so that forces are gathered without re-transposing every step.
    facet_nodes : numpy.ndarray of int, shape (P, 3)
        Kept-dof indices of the ``u_x`` values that ``B`` combines for each point (the two
        vertices and the midpoint of its facet).
    """

    phi: np.ndarray
    x_ref: np.ndarray
    weight: np.ndarray
    B: sp.csr_matrix
    BT: sp.csr_matrix
    facet_nodes: np.ndarray

    @property
    def size(self) -> int:
        """Number of quadrature points."""
        return int(self.phi.size)


def arc_quadrature(
    disk: HalfDisk, n_gauss: int = 8, phi_max: float = 0.5 * math.pi, y_max: float | None = None
) -> ArcQuadrature:
    """Build the arc quadrature of a discretised half disk.

    Parameters
    ----------
    disk : HalfDisk
    n_gauss : int
        Gauss-Legendre points per arc facet.
    phi_max : float
        Facets whose midpoint angle exceeds this (radians) are left out; ``pi/2`` gives the
        paper's range ``-pi/2 <= phi <= pi/2`` of the whole disk.
    y_max : float, optional
        Facets whose midpoint lies farther than this from the axis ``y = 0`` (``R``) are left
        out too (a flat boundary, :mod:`restitution.fem.block`, where every angle is ``pi/2``).
    """
    if n_gauss < 1:
        raise InputError(f"n_gauss must be at least 1, got {n_gauss}")
    mesh, basis = disk.mesh, disk.basis
    facets = mesh.boundaries[ARC]
    nverts = mesh.nvertices
    a, b = mesh.facets[0, facets], mesh.facets[1, facets]
    mid_loc = mesh.doflocs[:, nverts + facets]
    keep = np.arctan2(mid_loc[1], mid_loc[0]) <= phi_max + 1e-12
    if y_max is not None:
        keep &= mid_loc[1] <= y_max
    facets, a, b, mid_loc = facets[keep], a[keep], b[keep], mid_loc[:, keep]
    Xa, Xb, Xm = mesh.doflocs[:, a], mesh.doflocs[:, b], mid_loc

    t, gw = np.polynomial.legendre.leggauss(n_gauss)
    t, gw = 0.5 * (t + 1.0), 0.5 * gw
    N = np.stack([(1 - t) * (1 - 2 * t), t * (2 * t - 1), 4 * t * (1 - t)])  # (3, G)
    dN = np.stack([4 * t - 3, 4 * t - 1, 4 - 8 * t])
    X = Xa[:, :, None] * N[0] + Xb[:, :, None] * N[1] + Xm[:, :, None] * N[2]  # (2, F, G)
    dX = Xa[:, :, None] * dN[0] + Xb[:, :, None] * dN[1] + Xm[:, :, None] * dN[2]
    weight = np.sqrt((dX**2).sum(axis=0)) * gw  # (F, G)
    if disk.section.axisymmetric:
        weight = weight * (2.0 * math.pi * X[1])

    index = disk.reduced_index()
    nodes = np.stack(
        [
            index[basis.nodal_dofs[0, a]],
            index[basis.nodal_dofs[0, b]],
            index[basis.facet_dofs[0, facets]],
        ]
    )  # (3, F)
    if np.any(nodes < 0):
        raise InputError("an arc u_x degree of freedom was removed; the mesh boundaries are wrong")
    F, G = facets.size, t.size
    rows = np.broadcast_to(np.arange(F * G).reshape(F, G)[None], (3, F, G))
    cols = np.broadcast_to(nodes[:, :, None], (3, F, G))
    vals = np.broadcast_to(N[:, None, :], (3, F, G))
    B = sp.csr_matrix((vals.ravel(), (rows.ravel(), cols.ravel())), shape=(F * G, disk.n_dofs))
    phi = np.arctan2(X[1], X[0]).ravel()
    order = np.argsort(phi, kind="stable")
    B = B[order].tocsr()
    return ArcQuadrature(
        phi=phi[order],
        x_ref=X[0].ravel()[order],
        weight=weight.ravel()[order],
        B=B,
        BT=B.T.tocsr(),
        facet_nodes=np.repeat(nodes.T, G, axis=0)[order],
    )


def wall_terms(
    quad: ArcQuadrature, alpha: float, x_c: float, u: np.ndarray
) -> tuple[float, float, np.ndarray, np.ndarray]:
    """Wall potential, total force and its gradient for the half disk (the sphere's section:
    the whole sphere).

    Parameters
    ----------
    quad : ArcQuadrature
    alpha : float
        Wall hardness, ``1 / R``.
    x_c : float
        Reference position of the disk's centre, ``R``.
    u : numpy.ndarray, shape (n,)
        Displacement on the kept degrees of freedom, ``R``.

    Returns
    -------
    V : float
        Wall potential energy of the half disk, ``E R^2`` (sphere: ``E R^3``).
    F : float
        Total wall force on the half disk, pushing it away from the wall, ``E R`` (sphere:
        ``E R^2``).
    grad : numpy.ndarray, shape (n,)
        ``dV/du``; the wall force on the degrees of freedom is ``-grad``.
    density : numpy.ndarray, shape (P,)
        ``w exp(alpha x)`` at the quadrature points (force per point).
    """
    x = x_c + quad.x_ref + quad.B @ u
    density = quad.weight * np.exp(alpha * x)
    F = float(density.sum())
    return F / alpha, F, quad.BT @ density, density
