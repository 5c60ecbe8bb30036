"""The wall nodes' position Jacobians in the modal coordinates, as a turned pair of matrices that
is never formed: what friction point by point needs of them, one pass over the modes each.

Units: ``E = rho = R = 1``; Jacobians in ``R`` per unit modal coordinate.

A node ``j`` of a disk's rim or a sphere's cap moves by ``U1_j . Q`` along the body's impact
axis and ``U2_j . Q`` along its tangent in the plane of incidence (``U1_j``, ``U2_j`` rows of
shape (N,), fixed to the material). Turned by an angle with cosine ``a_j`` and sine ``b_j``
(one angle for the sphere's whole cap, one per node for the disk's rim), its position's
derivatives along the wall's normal and tangent are

    dX_j/dQ = a_j U1_j - b_j U2_j,      dY_j/dQ = b_j U1_j + a_j U2_j.

:class:`NodeJacobian` keeps ``U1``, ``U2`` interleaved (shape (M, 2, N), the body's stored
layout, so the sphere's active rings are a view) with ``a``, ``b`` and gives the products
with one matrix-vector pass each, where forming ``dX/dQ`` and ``dY/dQ`` costs two passes to
write them and one to read each. The rows' squared norms come from the per-node constants
``|U1_j|^2``, ``|U2_j|^2``, ``U1_j . U2_j`` (computed once per body, :func:`row_products`):

    |dX_j/dQ|^2 = a^2 |U1|^2 + b^2 |U2|^2 - 2 a b U1.U2,
    |dY_j/dQ|^2 = b^2 |U1|^2 + a^2 |U2|^2 + 2 a b U1.U2.

The products equal those of the formed matrices up to rounding (the sums are taken in another
order); tests/test_oblique_microslip.py compares them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["NodeJacobian", "row_products"]


def row_products(U: np.ndarray) -> np.ndarray:
    """``(|U1_j|^2, |U2_j|^2, U1_j . U2_j)`` of every node of ``U`` (shape (M, 2, N)), shape
    (3, M)."""
    U1, U2 = U[:, 0, :], U[:, 1, :]
    return np.stack(
        [
            np.einsum("ij,ij->i", U1, U1),
            np.einsum("ij,ij->i", U2, U2),
            np.einsum("ij,ij->i", U1, U2),
        ]
    )


@dataclass(frozen=True, eq=False)
class NodeJacobian:
    """``dX/dQ`` and ``dY/dQ`` of ``M`` active nodes (module docs), never formed.

    Attributes
    ----------
    U : numpy.ndarray, shape (M, 2, N)
        ``U1_j`` and ``U2_j`` of each node, interleaved; C-contiguous (a view of the body's).
    a, b : float or numpy.ndarray of shape (M,)
        Cosine and sine of each node's turn.
    rows : numpy.ndarray, shape (3, M)
        :func:`row_products` of ``U``.
    """

    U: np.ndarray
    a: float | np.ndarray
    b: float | np.ndarray
    rows: np.ndarray

    def flat(self) -> np.ndarray:
        """``U`` as a matrix of shape (2 M, N), rows ``U1_0, U2_0, U1_1, ...`` (a view)."""
        M, _, N = self.U.shape
        return self.U.reshape(2 * M, N)

    def apply(self, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(dX/dQ @ v, dY/dQ @ v)`` for ``v`` of shape (N,) or (N, k): shape (M,) or (M, k)
        each."""
        P = (self.flat() @ v).reshape(self.U.shape[0], 2, *v.shape[1:])
        u1, u2 = P[:, 0], P[:, 1]
        a, b = self._turn(v.ndim)
        return a * u1 - b * u2, b * u1 + a * u2

    def dY(self, v: np.ndarray) -> np.ndarray:
        """``dY/dQ @ v``, shape (M,) or (M, k)."""
        return self.apply(v)[1]

    def _turn(self, ndim: int):
        a, b = self.a, self.b
        if ndim == 2 and np.ndim(a):
            return a[:, None], b[:, None]
        return a, b

    def pull(self, cx: np.ndarray, cy: np.ndarray) -> np.ndarray:
        """``cx @ dX/dQ + cy @ dY/dQ``, shape (N,), for nodal weights ``cx``, ``cy`` (M,)."""
        w = np.empty((cx.size, 2))
        w[:, 0] = self.a * cx + self.b * cy
        w[:, 1] = self.a * cy - self.b * cx
        return w.reshape(-1) @ self.flat()

    def norms(self) -> tuple[np.ndarray, np.ndarray]:
        """``(|dX_j/dQ|^2, |dY_j/dQ|^2)``, shape (M,) each."""
        n11, n22, n12 = self.rows
        a, b = self.a, self.b
        return (
            a * a * n11 + b * b * n22 - 2.0 * a * b * n12,
            b * b * n11 + a * a * n22 + 2.0 * a * b * n12,
        )

    def formed(self) -> tuple[np.ndarray, np.ndarray]:
        """``(dX/dQ, dY/dQ)`` as matrices, shape (M, N) each (for checks)."""
        U1, U2 = self.U[:, 0, :], self.U[:, 1, :]
        a = np.asarray(self.a, dtype=float).reshape(-1, 1)
        b = np.asarray(self.b, dtype=float).reshape(-1, 1)
        return a * U1 - b * U2, b * U1 + a * U2
