"""The exponential wall potential and its forces on a body (paper eqs. 41-42, 45).

Units: ``E = rho = R = 1``. The wall is the plane ``x = 0``; the body approaches from ``x < 0``.

A surface point at node ``j`` of the body's :class:`~restitution.bodies.base.SurfaceQuadrature`
sits at ``x_j = x0 + height_j + basis_j @ [a, b]`` (for the disk, eq. 40), and the wall potential
is ``V = (1/alpha) sum_j weight_j exp(alpha x_j)`` (eq. 41). Its derivatives are the total wall
force on the centre of mass ``F = dV/dx0`` (eq. 45) and the generalised forces on the modes
``f_k = dV/dQ_k`` (eq. 42). Nothing here depends on the body's shape.
"""

from __future__ import annotations

import numpy as np

from restitution.bodies.base import SurfaceQuadrature

__all__ = ["active_nodes", "wall_terms"]


# Nodes whose exponent alpha x is certainly below -_NEGLIGIBLE contribute less than
# exp(-40) = 4e-18 of the force at the wall and are skipped.
_NEGLIGIBLE = 40.0


def active_nodes(quad: SurfaceQuadrature, alpha: np.ndarray, x0: np.ndarray, ab: np.ndarray) -> int:
    """Number of leading nodes where ``exp(alpha x)`` can exceed ``exp(-40)``.

    With the per-order amplitudes ``ab = [a, b]`` (shape (B, 2K)) and basis values of magnitude
    at most 1 (the disk: ``|cos(n phi) cos(phi)|, |sin(n phi) sin(phi)| <= 1``),
    ``x_j <= x0 + height_j + sum |ab|``; this is never looser than
    ``sum_k |Q_k| (|C_k| + |S_k|)``. ``height`` does not increase from the tip, so the nodes
    that matter for the whole batch form a prefix.
    """
    reach = x0 + np.abs(ab).sum(axis=1)
    bound = np.min(-reach - _NEGLIGIBLE / alpha)
    return int(np.searchsorted(-quad.height, -bound, side="right"))


def wall_terms(
    quad: SurfaceQuadrature, alpha: np.ndarray, x0: np.ndarray, Q: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wall potential and forces for a batch of states.

    Parameters
    ----------
    quad : SurfaceQuadrature
    alpha : numpy.ndarray, shape (B,)
        Wall hardness per batch member, ``1 / R``.
    x0 : numpy.ndarray, shape (B,)
        Centre-of-mass positions, ``R``.
    Q : numpy.ndarray, shape (B, N)
        Modal coordinates.

    Returns
    -------
    V : numpy.ndarray, shape (B,)
        Wall potential energy.
    F : numpy.ndarray, shape (B,)
        ``dV/dx0``: total wall force pushing the body back, ``E``.
    f : numpy.ndarray, shape (B, N)
        ``dV/dQ_k``: generalised wall forces on the modes.
    """
    # Per-order amplitudes [a_n, b_n], shape (B, 2K).
    ab = (quad.edge_t @ Q.T).T
    J = active_nodes(quad, alpha, x0, ab)
    if J == 0:
        zeros = np.zeros(x0.shape)
        return zeros, zeros, np.zeros(Q.shape)
    trig = quad.basis[:J]
    x = x0[:, None] + quad.height[None, :J] + ab @ trig.T
    e = np.exp(alpha[:, None] * x) * quad.weight[None, :J]
    F = e.sum(axis=1)
    cs = e @ trig  # [c_n, -s_n], shape (B, 2K)
    f = (quad.edge @ cs.T).T
    return F / alpha, F, np.ascontiguousarray(f)
