"""The sphere's wall quadrature for an oblique impact: rings of material nodes around the pole
that cover the contact wherever rolling takes it.

Units: ``E = rho = R = 1``; areas in ``R^2``.

**Nodes.** The head-on sphere's Gauss-Legendre rings in ``cos(theta)`` on the near hemisphere
(:func:`restitution.bodies.sphere.surface._nodes`: ``theta_i``, ring weights ``w_i``), each
with ``A`` (even) nodes at ``phi_k = 2 pi k / A``, weight ``w_i / A``. The grid is material: it
turns with the sphere. When the sphere has turned by ``Theta`` about ``e3`` the wall faces the
material point ``(theta, phi) = (|Theta|, pi or 0)``, and the wall's integrand on ring ``i`` is,
to leading order, ``exp(alpha theta_i |Theta| cos phi)`` times a function of ``theta_i``: its
Fourier coefficients are ``I_j(alpha theta_i |Theta|)``, so the trapezoidal rule in ``phi``
(exact for harmonics below ``A``) errs by about ``I_A(z) / I_0(z)``, ``z = alpha theta |Theta|``
over the rings in contact; docs/oblique.md measures it. Without rotation (and without friction)
every ring's sum is the head-on ring weight times the axisymmetric integrand, so the
frictionless run sums the wall as the head-on collision does.

**Placing them.** With the body's rotation ``Theta`` about ``e3`` and modal coordinates ``Q``,
node ``j`` (rest position ``(c_j, s_j)`` along ``(e1, e2)``, displacements ``D1, D2`` per unit
``Q``) sits at

    X = x0 + (c_j + D1 Q) cos Theta - (s_j + D2 Q) sin Theta,
    Y = y0 + (c_j + D1 Q) sin Theta + (s_j + D2 Q) cos Theta

(the disk's formulas with ``phi + Theta`` expanded). A ring can reach the wall only if
``x0 + cos(max(theta_i - |Theta|, 0)) + reach`` clears the cutoff (its nearest point); the rings
are in increasing ``theta``, so the active ones are a prefix and their nodes a slice.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.node_jacobian import NodeJacobian, row_products
from restitution.bodies.sphere import surface
from restitution.errors import InputError

__all__ = ["BLOCK_NODES", "CapNodes", "cap_nodes", "ring_count"]


@dataclass(frozen=True, eq=False)
class CapNodes:
    """The wall nodes of a :class:`~restitution.bodies.sphere.cap.SphereCap` (module docs).

    Attributes
    ----------
    theta : numpy.ndarray, shape (K,)
        Ring angles, increasing from the pole.
    azimuths : int
        Nodes per ring (``phi_k = 2 pi k / azimuths``).
    weight : numpy.ndarray, shape (K * azimuths,)
        Node weights, ``R^2``, ring by ring.
    c, s : numpy.ndarray, shape (K * azimuths,)
        Rest position along ``e1`` and ``e2``.
    D : numpy.ndarray, shape (K * azimuths, 2, N)
        Displacement along ``e1`` and ``e2`` per unit ``Q`` (:attr:`D1`, :attr:`D2`),
        interleaved node by node (:mod:`restitution.bodies.node_jacobian`).
    reach : numpy.ndarray, shape (N,)
        ``max_j |D1| + |D2|``: bounds the displacement along the wall's normal at any rotation.
    """

    theta: np.ndarray
    azimuths: int
    weight: np.ndarray
    c: np.ndarray
    s: np.ndarray
    D: np.ndarray
    reach: np.ndarray

    def __len__(self) -> int:
        return int(self.weight.size)

    @property
    def D1(self) -> np.ndarray:
        """Displacement along ``e1`` per unit ``Q``, shape (K * azimuths, N) (a view)."""
        return self.D[:, 0, :]

    @property
    def D2(self) -> np.ndarray:
        """Displacement along ``e2`` per unit ``Q``, shape (K * azimuths, N) (a view)."""
        return self.D[:, 1, :]

    @functools.cached_property
    def _rows(self) -> np.ndarray:
        return row_products(self.D)

    def start_integral(self, alpha: float) -> float:
        """``sum_j w_j exp(alpha (c_j - 1))``: the undeformed sphere's wall integral, ``R^2``."""
        return float(self.weight @ np.exp(alpha * (self.c - 1.0)))

    def _active(self, x0, rotation, reach: float, cutoff: float) -> int:
        """How many nodes (whole rings from the pole) may reach ``x = cutoff``; 0 if none."""
        if x0 + 1.0 + reach <= cutoff:  # no point of the sphere can reach the cutoff
            return 0
        near = np.cos(np.maximum(self.theta - abs(rotation), 0.0))
        return int(np.count_nonzero(x0 + near + reach > cutoff)) * self.azimuths

    def _check_edge(self, j: int, X, rotation, cutoff: float) -> None:
        """Refuse a contact that reaches the last ring of the wall nodes."""
        if j == self.theta.size * self.azimuths and X[-self.azimuths :].max() > cutoff:
            raise InputError(
                f"the contact reaches the edge of the sphere's wall nodes (the near hemisphere "
                f"about the modes' pole; the sphere has turned by {rotation:.3g} rad): the "
                "impact rolls the contact too far for this quadrature; lower the speed or the "
                "tangential speed, or start with a smaller rotation"
            )

    def place(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes that may touch, placed (module docs): ``None`` if no ring can reach
        ``x = cutoff``, else ``(weight, X, Y - y0, xi, eta, project)`` of the active nodes
        (:class:`restitution.dynamics.oblique.WallNodes`). The active rows ``D`` (both
        directions interleaved) are read three times: for the positions, the velocities and
        the projection of the forces."""
        j = self._active(x0, rotation, reach, cutoff)
        if j == 0:
            return None
        D = self.D[:j]
        flat = D.reshape(2 * j, -1)
        P, V = (flat @ Q).reshape(j, 2), (flat @ Qd).reshape(j, 2)  # two passes: see jacobian
        P1 = self.c[:j] + P[:, 0]
        P2 = self.s[:j] + P[:, 1]
        ct, st = math.cos(rotation), math.sin(rotation)
        X = x0 + P1 * ct - P2 * st
        Yr = P1 * st + P2 * ct
        self._check_edge(j, X, rotation, cutoff)
        xi = V[:, 0] * ct - V[:, 1] * st
        eta = V[:, 0] * st + V[:, 1] * ct

        def project(e, p):
            f1, f2 = (e @ D.reshape(j, -1)).reshape(2, -1)
            return f1 * ct - f2 * st, (f1 * st + f2 * ct) / float(e.sum())

        return self.weight[:j], X, Yr, xi, eta, project

    def jacobian(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes that may touch with their identity and their position's derivatives in
        the modal coordinates: ``None`` or ``(index, weight, X, Y - y0, eta, J)``, ``eta =
        dY/dQ @ Qd`` and ``J`` a :class:`~restitution.bodies.node_jacobian.NodeJacobian`
        (one turn for the whole cap; the active rings a view), as
        :meth:`restitution.bodies.disk.rim.RimNodes.jacobian` (friction point by point along
        the plane of incidence). Two matrix-vector passes over the active rings' displacements
        (one for ``Q``, one for ``Qd``: OpenBLAS took longer for one product with both as
        columns, docs/oblique.md)."""
        j = self._active(x0, rotation, reach, cutoff)
        if j == 0:
            return None
        ct, st = math.cos(rotation), math.sin(rotation)
        J = NodeJacobian(self.D[:j], ct, st, self._rows[:, :j])
        P = (J.flat() @ Q).reshape(j, 2)
        P1 = self.c[:j] + P[:, 0]
        P2 = self.s[:j] + P[:, 1]
        X = x0 + P1 * ct - P2 * st
        self._check_edge(j, X, rotation, cutoff)
        eta = J.dY(Qd)
        return np.arange(j), self.weight[:j], X, P1 * st + P2 * ct, eta, J

    def jacobians(self, x0, rotation, Q, reach: float, cutoff: float):
        """:meth:`jacobian` at rest (``Qd = 0``) with the Jacobians formed: ``None`` or
        ``(index, weight, X, Y - y0, dX/dQ, dY/dQ)`` (for checks)."""
        placed = self.jacobian(x0, rotation, Q, np.zeros_like(Q), reach, cutoff)
        return None if placed is None else (*placed[:4], *placed[5].formed())


BLOCK_NODES = 512
"""Nodes whose displacements :func:`cap_nodes` evaluates at once: the build holds the stored
rows (2 per node and mode) and the displacements' arrays and temporaries for this many nodes,
not for every node (tracemalloc at 13248 nodes: all at once peaked at 7.0 times one
node-by-mode array, in blocks at 2.40)."""


def ring_count(cap, alpha: float, n_nodes: int | None = None) -> int:
    """The rings of :func:`cap_nodes`: ``n_nodes``, or
    :func:`restitution.bodies.sphere.surface.default_n_nodes` with the cap's highest order
    among its axisymmetric modes (as the head-on sphere)."""
    if n_nodes is not None:
        return int(n_nodes)
    axial = cap.l[cap.m == 0]
    l_max = int(axial.max()) if axial.size else (int(cap.l.max()) if len(cap) else 0)
    return surface.default_n_nodes(alpha, l_max)


def cap_nodes(cap, alpha: float, n_nodes: int | None = None) -> CapNodes:
    """The nodes of ``cap`` for a wall of hardness ``alpha``: :func:`ring_count` rings of
    ``cap.azimuths`` nodes each, their displacements evaluated :data:`BLOCK_NODES` at a
    time."""
    theta, ring_weight = surface._nodes(ring_count(cap, alpha, n_nodes))
    A = int(cap.azimuths)
    phi = 2.0 * math.pi * np.arange(A) / A
    th = np.repeat(theta, A)
    ph = np.tile(phi, theta.size)
    D = np.empty((th.size, 2, len(cap)))
    reach = np.zeros(len(cap))
    for start in range(0, th.size, BLOCK_NODES):
        part = slice(start, start + BLOCK_NODES)
        d1, d2, _ = cap.displacement(th[part], ph[part])
        D[part, 0], D[part, 1] = d1, d2
        reach = np.maximum(reach, np.max(np.abs(d1) + np.abs(d2), axis=0, initial=0.0))
    return CapNodes(
        theta=theta,
        azimuths=A,
        weight=np.repeat(ring_weight / A, A),
        c=np.cos(th),
        s=np.sin(th) * np.cos(ph),
        D=D,
        reach=reach,
    )
