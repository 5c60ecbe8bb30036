"""The body protocol: what the collision, the limits and the laws need from an elastic body.

Units: reduced units of the body's own material, ``E = rho = R = 1``; ``omega`` in ``c / R``.

A body hits a flat wall head-on along its symmetry axis. It is expanded in its free eigenmodes,
and only the modes symmetric about the impact axis couple. Every such mode belongs to an
angular *order* (``n`` of ``cos(n phi)`` for the disk, ``l`` of ``P_l(cos theta)`` for a sphere)
and has two *surface amplitudes*: ``C``, the normal (radial) displacement of the surface per
unit modal coordinate, and ``S``, the tangential one. The displacement of the surface point at
the node ``j`` along the impact axis is then::

    u_x(j) = sum_k Q_k [C_k b_{n_k}(j) + S_k s_{n_k}(j)]

with two basis values per order and node, which the body supplies. Everything the dynamics
does (the wall integral, its forces, the stop test) follows from:

* the mode set: ``omega``, ``order``, ``C``, ``S`` (arrays of shape (N,)) and the ``mass``;
* the :class:`SurfaceQuadrature` of its surface against the wall (:meth:`ModalBody.
  surface_quadrature`, with :meth:`ModalBody.contact_nodes` nodes for a contact zone of a given
  depth) and the Laplace transform of its depth below the tip (:meth:`ModalBody.
  depth_transform`): geometry, which the contact law (:mod:`restitution.dynamics.contact`)
  reads;
* its quasistatic contact scales (:meth:`ModalBody.contact_time_estimate`), which size the time
  steps and the time bounds.

The undeformed body's tip (the surface point on the impact axis) is at ``height = 1`` (``R``)
from the centre. :mod:`restitution.bodies.disk` implements the protocol for the disk; a sphere
is one more module of this layer (docs/architecture.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
import scipy.sparse as sp

from restitution.errors import InputError, describe, is_integer, is_real

__all__ = ["ModalBody", "SurfaceQuadrature", "check_mode_selection", "surface_quadrature"]


@dataclass(frozen=True, eq=False)
class SurfaceQuadrature:
    """Quadrature of a body's surface integral against a flat wall, summed order by order.

    With the per-order amplitudes ``a_i = sum_{k: column_k = i} Q_k C_k`` and ``b_i`` likewise
    with ``S_k``, the surface's displacement along the impact axis at node ``j`` is
    ``basis[j] @ [a, b]``, and the generalised forces are ``f_k = C_k c_i + S_k s_i`` with the
    per-order integrals ``[c, s] = (weight * exp(alpha x)) @ basis``. The cost per evaluation is
    ``M x (number of orders)`` instead of ``M x N``.

    Attributes
    ----------
    nodes : numpy.ndarray, shape (M,)
        Surface coordinate of the nodes: the angle from the impact axis (``phi`` of the disk,
        ``theta`` of a sphere), radians, increasing from 0 (the tip).
    weight : numpy.ndarray, shape (M,)
        Quadrature weights of the surface integral (including symmetry factors).
    height : numpy.ndarray, shape (M,)
        Undeformed surface position along the impact axis relative to the centre, ``R``;
        non-increasing, ``height[0] = 1`` at the tip.
    basis : numpy.ndarray, shape (M, 2K)
        Displacement along the impact axis per unit amplitude: columns ``0..K-1`` for the
        normal amplitudes ``C`` of the ``K`` orders present, ``K..2K-1`` for the tangential
        amplitudes ``S``.
    C, S : numpy.ndarray, shape (N,)
        Surface amplitudes of the modes.
    column : numpy.ndarray of int, shape (N,)
        Column (order index ``0..K-1``) of every mode.
    edge : scipy.sparse.csr_matrix, shape (N, 2K)
        ``C_k`` at ``(k, column_k)`` and ``S_k`` at ``(k, K + column_k)``: maps mode
        coordinates to per-order amplitudes (``Q @ edge``) and per-order integrals back to
        generalised forces (``edge @ cs``).
    edge_t : scipy.sparse.csr_matrix, shape (2K, N)
        Its transpose, stored for fast products.
    g_max : numpy.ndarray, shape (N,)
        ``|C_k| + |S_k|``, a bound of every mode's displacement along the axis (the basis
        values are at most 1 in magnitude).
    """

    nodes: np.ndarray
    weight: np.ndarray
    height: np.ndarray
    basis: np.ndarray
    C: np.ndarray
    S: np.ndarray
    column: np.ndarray
    edge: sp.csr_matrix
    edge_t: sp.csr_matrix
    g_max: np.ndarray

    @property
    def n_orders(self) -> int:
        """Number ``K`` of distinct orders in the mode set."""
        return int(self.basis.shape[1] // 2)


def surface_quadrature(
    nodes: np.ndarray,
    weight: np.ndarray,
    height: np.ndarray,
    basis: np.ndarray,
    column: np.ndarray,
    C: np.ndarray,
    S: np.ndarray,
) -> SurfaceQuadrature:
    """Assemble a :class:`SurfaceQuadrature` from a body's nodes and basis values.

    Parameters
    ----------
    nodes, weight, height : numpy.ndarray, shape (M,)
    basis : numpy.ndarray, shape (M, 2K)
        Normal-amplitude columns of the ``K`` orders, then the tangential ones.
    column : numpy.ndarray of int, shape (N,)
        Order column of each mode.
    C, S : numpy.ndarray, shape (N,)
        Surface amplitudes.
    """
    N, K = C.size, basis.shape[1] // 2
    rows = np.r_[np.arange(N), np.arange(N)]
    edge = sp.csr_matrix((np.r_[C, S], (rows, np.r_[column, K + column])), shape=(N, 2 * K))
    return SurfaceQuadrature(
        nodes=nodes,
        weight=weight,
        height=height,
        basis=np.ascontiguousarray(basis),
        C=C.copy(),
        S=S.copy(),
        column=column,
        edge=edge,
        edge_t=edge.T.tocsr(),
        g_max=np.abs(C) + np.abs(S),
    )


@runtime_checkable
class ModalBody(Protocol):
    """An elastic body expanded in a truncated set of its free eigenmodes (see module docs).

    Implementations are immutable; ``take`` and ``lowest`` return new bodies with fewer modes.
    The attributes are arrays of shape (N,), sorted as the implementation chooses (the disk:
    by frequency); results come back in the same order.
    """

    geometry: str
    """``"disk"``, ``"sphere"``, ...: names the body in results, stores and file names."""
    nu: float
    """The Poisson number the modes were computed for (the disk: the two-dimensional one)."""
    omega: np.ndarray
    """Angular frequencies, ``c / R``."""
    C: np.ndarray
    """Normal surface amplitude per unit modal coordinate, ``R``."""
    S: np.ndarray
    """Tangential surface amplitude per unit modal coordinate, ``R``."""

    def __len__(self) -> int: ...

    @property
    def order(self) -> np.ndarray:
        """Angular order of every mode (int array, shape (N,))."""
        ...

    @property
    def mass(self) -> float:
        """Mass in reduced units (the disk: ``pi``, a sphere: ``4 pi / 3``)."""
        ...

    def take(self, index) -> ModalBody:
        """The modes at ``index`` (integer or boolean array), in the order given."""
        ...

    def lowest(self, count: int) -> ModalBody:
        """The ``count`` lowest-frequency modes."""
        ...

    def contact_nodes(self, s: float) -> int:
        """Quadrature nodes that resolve a contact zone of depth ``1 / s`` below the tip
        (``s`` in ``1/R``; the exponential wall asks for ``s = alpha``)."""
        ...

    def surface_quadrature(self, n_nodes: int) -> SurfaceQuadrature:
        """The surface quadrature with ``n_nodes`` nodes."""
        ...

    def surface_matrix(self, nodes: np.ndarray) -> np.ndarray:
        """Dense ``u_x`` per unit ``Q_k`` at ``nodes``, shape (M, N); for checks and baselines."""
        ...

    def contact_time_estimate(self, v):
        """Quasistatic contact time against a rigid wall at speed ``v`` (``c``), ``R / c``."""
        ...

    def depth_transform(self, s):
        """``int exp(-s (1 - h)) dA`` over the undeformed surface facing the wall (``h`` the
        height along the impact axis, ``1 - h`` the depth below the tip, ``s`` in ``1/R``):
        the Laplace transform of the surface's depth distribution, ``R`` for the disk's edge,
        ``R^2`` for a surface. (The exponential wall of hardness ``alpha`` touching the tip
        has the potential ``depth_transform(alpha) / alpha``.)"""
        ...


def check_mode_selection(count, omega_max) -> None:
    """One-line :class:`~restitution.errors.InputError` unless exactly one of ``count`` (an
    integer >= 1: the lowest modes) and ``omega_max`` (a finite number > 0, ``c / R``: every
    mode below it) is given, as every body's mode builder takes them."""
    if (count is None) == (omega_max is None):
        raise InputError(
            f"give exactly one of count and omega_max, got count={count!r} and "
            f"omega_max={omega_max!r}; pass e.g. count=100"
        )
    if omega_max is not None:
        if not (is_real(omega_max) and math.isfinite(omega_max) and omega_max > 0):
            raise InputError(
                f"omega_max must be a positive number (c/R), got {describe(omega_max)}; pass a "
                "finite float > 0, e.g. omega_max=40.0"
            )
    elif not (is_integer(count) and count >= 1):
        raise InputError(
            f"count must be a positive integer (the number of modes), got {describe(count)}; "
            "pass an int >= 1, e.g. count=100"
        )
