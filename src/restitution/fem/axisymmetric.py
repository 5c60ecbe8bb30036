"""Axisymmetric elasticity of the sphere's meridian section: weak forms and the lumped mass.

Units: ``E = rho = R = 1`` of the three-dimensional material unless it says otherwise;
displacements in ``R``.

The half disk ``{x^2 + r^2 <= 1, r >= 0}`` of :mod:`restitution.fem.mesh` (its ``y`` is the
distance ``r`` from the impact axis) is the meridian section of the sphere. A torsion-free
axisymmetric displacement ``(u_x, u_r)`` has the strains ``e_xx = d_x u_x``, ``e_rr = d_r u_r``,
``e_xr = (d_r u_x + d_x u_r) / 2`` and the hoop strain ``e_theta = u_r / r``; the elastic and
kinetic energies of the whole sphere are

    (1/2) int [lambda (tr e)^2 + 2 mu (e_xx^2 + e_rr^2 + 2 e_xr^2 + e_theta^2)] 2 pi r dA,
    (1/2) int rho |udot|^2 2 pi r dA,

with ``tr e = e_xx + e_rr + e_theta`` and the three-dimensional Lame constants
(:meth:`restitution.fem.section.Section.lame`). The axis carries ``u_r = 0`` (the roller of the
disk's diameter); the hoop term ``u_r v_r / r`` is integrated at interior quadrature points only.

Lumped mass (for the explicit impact solver). The disk's element (P2 + bubble in the nodal basis
of vertices, edge midpoints and centroid, mass lumped by the quadrature rule on those seven
points; Cohen, Joly, Roberts and Tordjman, SIAM J. Numer. Anal. 38 (2001) 2047) with the weight
``2 pi r`` evaluated at the seven points keeps its accuracy (the rule integrates ``r p`` exactly
for quadratic ``p``) but gives **zero mass** to every node on the axis, so ``M`` cannot be
inverted. No rule on the seven nodes that is exact for ``r p`` (``p`` quadratic) is positive on
an element with an edge on the axis: the only such rules are the weighted rule plus multiples of
the null pattern ``(1, 1, 1, -4, -4, -4, 9)`` (vertices, midpoints, centroid), which gives the
axis midpoint and the axis vertices masses of opposite signs (summing the rows of the consistent
matrix is one of them; it comes out negative there). So on the elements **with an edge on the
axis** (all others keep the weighted seven-point rule):

1. HRZ (Hinton, Rock and Zienkiewicz, Earthquake Eng. Struct. Dyn. 4 (1976) 245): the diagonal
   of the element's consistent ``2 pi r``-weighted mass matrix in the same nodal basis, scaled
   to the element's mass; positive by construction (``int 2 pi r phi_i^2 dA > 0``);
2. multiplied node by node by the affine function ``l(x, r)`` for which the masses integrate
   ``2 pi r``, ``2 pi r x`` and ``2 pi r r`` over the element exactly (``l`` lies in 0.57-1.49
   on these meshes; an element where it is not positive keeps plain HRZ). Exactness for affine
   integrands on the axis strip (total weight ``O(h^2)``) keeps the ``O(h^4)`` consistency of
   the interior; HRZ alone is exact for the element mass only and leaves an ``O(h^3)`` term.

Verified against Lamb's frequencies (``tests/test_fem_sphere.py``) on uniform meshes of levels
3-6: the largest relative error of the lowest 10 frequencies at nu = 0.3 is 2.6e-4, 3.1e-5,
2.5e-6, 1.7e-7 (error ratios 8.7, 12.1, 14.6, rising to 16; fitted rate 3.7 on levels 4-6, 3.4
on 3-5; nu = 0.25: 3.7 and 3.2), and of the lowest 40 at level 6 7.6e-6 (rate 3.55), below the
consistent P2 mass (2.6e-5). Measured alternatives at nu = 0.3: plain HRZ has errors 7.0e-6 and
6.1e-7 at levels 5 and 6 with error ratios 15.6, 16.4, then 11.6 (falling towards ``h^3``); HRZ
on every element converges like ``h^2``; the centroid radius on the axis elements (DYNA2D's
area weighting) has 10 times larger errors; leaving the axis masses zero (not invertible, but
a shift-invert eigen-solve condenses them) gives 7.3e-7 at level 5. The largest frequency of the
level-5 mesh is 382 ``c / R`` (plain HRZ: 359), which sets the explicit step.
"""

from __future__ import annotations

import math

import numpy as np
from skfem import Basis, BilinearForm, ElementTriP2B, MeshTri2
from skfem.helpers import ddot, dot, sym_grad

__all__ = ["axisymmetric_elasticity", "axisymmetric_mass", "lumped_weights"]

_TWO_PI = 2.0 * math.pi
# Lumping points closer than this to the axis (R) lie on it.
_ON_AXIS = 1e-12
# Values of the P2 vertex and edge shape functions at the centroid (the nodal P2 + bubble basis
# is phi_i = psi_i - psi_i(centroid) * bubble, psi the P2 Lagrange functions).
_P2_AT_CENTROID = np.array([-1.0, -1.0, -1.0, 4.0, 4.0, 4.0]) / 9.0


def axisymmetric_elasticity(lam: float, mu: float) -> BilinearForm:
    """Stiffness form of the sphere's meridian section (module docstring), weight ``2 pi r``.

    Parameters
    ----------
    lam, mu : float
        Three-dimensional Lame constants, ``E``.
    """

    @BilinearForm
    def stiffness(u, v, w):
        r = w.x[1]
        eu, ev = sym_grad(u), sym_grad(v)
        tr_u = eu[0, 0] + eu[1, 1] + u[1] / r
        tr_v = ev[0, 0] + ev[1, 1] + v[1] / r
        return _TWO_PI * (lam * tr_u * tr_v * r + 2.0 * mu * (ddot(eu, ev) * r + u[1] * v[1] / r))

    return stiffness


def axisymmetric_mass(rho: float) -> BilinearForm:
    """Consistent mass form ``int rho u . v 2 pi r dA`` of the meridian section."""

    @BilinearForm
    def mass(u, v, w):
        return _TWO_PI * rho * w.x[1] * dot(u, v)

    return mass


def lumped_weights(
    mesh: MeshTri2, rule_points: np.ndarray, rule_weights: np.ndarray, intorder: int
) -> np.ndarray:
    """Lumped masses (``rho = 1``) of the seven nodes of every element, with the ``2 pi r`` weight.

    Parameters
    ----------
    mesh : skfem.MeshTri2
        A half-disk mesh whose diameter ``y = 0`` is the axis.
    rule_points : numpy.ndarray, shape (2, 7)
        The lumping points on the reference triangle (vertices, edge midpoints in skfem's facet
        order, centroid).
    rule_weights : numpy.ndarray, shape (7,)
        The rule's weights on the reference triangle.
    intorder : int
        Quadrature order of the consistent element masses on the axis elements.

    Returns
    -------
    numpy.ndarray, shape (n_elements, 7)
        ``w_k |det J| 2 pi r_k`` of the weighted rule; HRZ on the elements with an edge on the
        axis (module docstring). Every node's assembled mass is positive.
    """
    mapping = mesh._mapping()
    detJ = np.abs(mapping.detDF(rule_points))  # (n_el, 7)
    r = mapping.F(rule_points)[1]  # (n_el, 7)
    weights = rule_weights[None, :] * detJ * (_TWO_PI * r)
    # An edge on the axis: its midpoint (a lumping point) lies at r = 0 (mesh.py keeps the
    # diameter's coordinates y = 0).
    axis = np.nonzero((np.abs(r[:, 3:6]) <= _ON_AXIS).any(axis=1))[0]
    if axis.size:
        weights[axis] = _hrz(mesh, axis, rule_points, intorder)
    return weights


def _hrz(mesh: MeshTri2, elements: np.ndarray, points: np.ndarray, intorder: int) -> np.ndarray:
    """Lumped masses of the given elements, shape (n, 7): HRZ, then exact first moments.

    HRZ: ``m_i = M_ii m_e / sum_j M_jj`` with ``M`` the element's consistent ``2 pi r``-weighted
    mass in the nodal basis and ``m_e`` its mass. Then ``m_i -> m_i l(X_i)`` with the affine
    ``l`` for which the masses integrate ``2 pi r p`` exactly for affine ``p`` (three moments);
    where ``l`` is not positive at every node (never on the meshes of :mod:`restitution.fem.mesh`,
    whose ``l`` lies in 0.57-1.49) the element keeps HRZ.
    """
    basis = Basis(mesh, ElementTriP2B(), intorder=intorder, elements=elements)
    xq = np.asarray(basis.global_coordinates())  # (2, n, q)
    dm = basis.dx * (_TWO_PI * xq[1])  # 2 pi r dA at the points
    # skfem's local order: the three vertices, the three edges, the bubble (value 1 at the
    # centroid); the nodal basis subtracts each P2 function's centroid value times the bubble.
    psi = [np.asarray(basis.basis[i][0]) for i in range(7)]
    phi = [psi[i] - _P2_AT_CENTROID[i] * psi[6] for i in range(6)] + [psi[6]]
    diagonal = np.stack([(dm * p**2).sum(axis=1) for p in phi], axis=1)
    hrz = diagonal * (dm.sum(axis=1) / diagonal.sum(axis=1))[:, None]
    moments = np.stack([dm.sum(axis=1), (dm * xq[0]).sum(axis=1), (dm * xq[1]).sum(axis=1)], 1)
    nodes = mesh._mapping().F(points, tind=elements)  # (2, n, 7)
    affine = np.stack([np.ones_like(nodes[0]), nodes[0], nodes[1]], axis=2)  # (n, 7, 3)
    gram = np.einsum("ei,eia,eib->eab", hrz, affine, affine)
    factor = np.einsum("eia,ea->ei", affine, np.linalg.solve(gram, moments[..., None])[..., 0])
    return np.where((factor > 0.0).all(axis=1)[:, None], hrz * factor, hrz)
