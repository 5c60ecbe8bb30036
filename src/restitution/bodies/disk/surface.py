"""The disk's edge quadrature against the wall (paper eqs. 40-41): nodes, weights, basis.

Units: ``E = rho = R = 1``. The wall is the line ``x = 0``; the disk approaches from ``x < 0``.

The boundary point with reference angle ``phi`` sits at (eq. 40)::

    x(phi) = x0 + cos(phi) + sum_k Q_k g_k(phi),
    g_k(phi) = C_k cos(n_k phi) cos(phi) - S_k sin(n_k phi) sin(phi)

so the basis of order ``n`` is ``[cos(n phi) cos(phi), -sin(n phi) sin(phi)]``. The wall
potential is ``V = (1/alpha) int_{-pi/2}^{pi/2} exp(alpha x(phi)) dphi`` (eq. 41). ``x(phi)`` is
even in ``phi`` for the symmetric mode family, so the integral is taken over ``[0, pi/2]`` and
doubled. The quadrature is the trapezoidal rule on a uniform grid: the integrand is smooth and,
for any wall hard enough to matter (``alpha >> 1``), exponentially small at ``phi = pi/2``, so
the rule converges spectrally once the peak of width ``~1/sqrt(alpha)`` and the shapes
``cos(n phi)`` are resolved.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from restitution.bodies.base import SurfaceQuadrature, surface_quadrature
from restitution.errors import InputError

if TYPE_CHECKING:
    from restitution.bodies.disk.modes import ModeSet

__all__ = [
    "default_n_phi",
    "dense_edge_matrix",
    "depth_transform",
    "edge_basis",
    "edge_quadrature",
]


def default_n_phi(alpha: float, n_max: int) -> int:
    """Number of quadrature nodes on ``[0, pi/2]`` for a contact zone of depth ``1 / alpha``.

    At least 256 (the paper's choice), at least 8 nodes per period of the highest angular
    order ``n_max``, and a node spacing of at most ``0.12 / sqrt(alpha)`` so that the initial
    contact peak ``exp(-alpha phi^2 / 2)`` (the edge within ``1 / alpha`` of its tip) is
    resolved. The convergence in this parameter is checked by a test.
    """
    spacing = min(0.12 / math.sqrt(alpha), 2.0 * math.pi / (8.0 * max(n_max, 1)))
    return max(256, int(math.ceil(0.5 * math.pi / spacing)) + 1)


def depth_transform(s):
    """``int_0^{pi/2} exp(-s (1 - cos phi)) dphi``, ``R``, approximated by the Gaussian peak
    at ``phi = 0``: ``min(pi/2, sqrt(pi / (2 s)))`` (the quarter arc for small ``s``)."""
    return np.minimum(0.5 * math.pi, np.sqrt(0.5 * math.pi / s))


def edge_basis(orders: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """The basis of eq. (40) at angles ``phi``: ``[cos(n phi) cos(phi) | -sin(n phi) sin(phi)]``.

    Parameters
    ----------
    orders : numpy.ndarray of int, shape (K,)
        Orders ``n``.
    phi : numpy.ndarray, shape (M,)
        Reference angles of edge points, radians.

    Returns
    -------
    numpy.ndarray, shape (M, 2K)
        Displacement along the impact axis per unit normal amplitude (columns ``0..K-1``) and
        per unit tangential amplitude (``K..2K-1``).
    """
    arg = np.asarray(orders)[None, :] * phi[:, None]
    return np.hstack([np.cos(arg) * np.cos(phi)[:, None], -np.sin(arg) * np.sin(phi)[:, None]])


def edge_quadrature(modes: ModeSet, n_phi: int) -> SurfaceQuadrature:
    """The edge quadrature of ``modes`` with ``n_phi`` nodes on ``[0, pi/2]``."""
    if n_phi < 16:
        raise InputError(f"n_phi must be at least 16, got {n_phi}")
    phi = np.linspace(0.0, 0.5 * math.pi, n_phi)
    h = phi[1] - phi[0]
    weight = np.full(n_phi, 2.0 * h)
    weight[0] = weight[-1] = h
    orders, column = np.unique(modes.n, return_inverse=True)
    basis = edge_basis(orders, phi)
    return surface_quadrature(phi, weight, np.cos(phi), basis, column, modes.C, modes.S)


def dense_edge_matrix(modes: ModeSet, phi: np.ndarray) -> np.ndarray:
    """``g_k(phi_j)`` as a dense matrix, shape (M, N) (eq. 40); for checks and baselines."""
    n = modes.n[None, :]
    return (
        modes.C[None, :] * np.cos(n * phi[:, None]) * np.cos(phi)[:, None]
        - modes.S[None, :] * np.sin(n * phi[:, None]) * np.sin(phi)[:, None]
    )
