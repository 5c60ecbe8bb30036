"""A local contact law summed over a body's surface (paper eqs. 40-42, 45 for the disk).

Units: ``E = rho = R = 1``. The wall is the plane ``x = 0``; the body approaches from ``x < 0``.

A surface point at node ``j`` of the body's :class:`~restitution.bodies.base.SurfaceQuadrature`
sits at ``x_j = x0 + height_j + basis_j @ [a, b]`` (for the disk, eq. 40). The law gives each
node's potential and force (:meth:`~restitution.dynamics.contact.base.ContactLaw.node_terms`;
the exponential wall: ``V = (1/alpha) sum_j weight_j exp(alpha x_j)``, eq. 41); their sums are
the wall potential, the total force on the centre of mass ``F = dV/dx0`` (eq. 45) and the
generalised forces on the modes ``f_k = dV/dQ_k`` (eq. 42), formed order by order. Nothing here
depends on the body's shape or on which law it is.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from restitution.bodies.base import SurfaceQuadrature

if TYPE_CHECKING:
    from restitution.dynamics.contact.base import ContactLaw

__all__ = ["active_nodes", "surface_terms"]


def active_nodes(
    law: ContactLaw, quad: SurfaceQuadrature, alpha: np.ndarray, x0: np.ndarray, ab: np.ndarray
) -> int:
    """Number of leading nodes that can come within the law's :meth:`~restitution.dynamics.
    contact.base.ContactLaw.cutoff` of the wall (the exponential wall: where ``exp(alpha x)``
    can exceed ``exp(-40)``).

    With the per-order amplitudes ``ab = [a, b]`` (shape (B, 2K)) and basis values of magnitude
    at most 1 (the disk: ``|cos(n phi) cos(phi)|, |sin(n phi) sin(phi)| <= 1``),
    ``x_j <= x0 + height_j + sum |ab|``; this is never looser than
    ``sum_k |Q_k| (|C_k| + |S_k|)``. ``height`` does not increase from the tip, so the nodes
    that matter for the whole batch form a prefix.
    """
    reach = x0 + np.abs(ab).sum(axis=1)
    bound = np.min(-reach - law.cutoff(alpha))
    return int(np.searchsorted(-quad.height, -bound, side="right"))


def surface_terms(
    law: ContactLaw, quad: SurfaceQuadrature, alpha: np.ndarray, x0: np.ndarray, Q: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wall potential and forces of ``law`` for a batch of states.

    Parameters
    ----------
    law : ContactLaw
    quad : SurfaceQuadrature
    alpha : numpy.ndarray, shape (B,)
        Hardness of the law per batch member (the exponential wall: ``1 / R``).
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
    J = active_nodes(law, quad, alpha, x0, ab)
    if J == 0:
        zeros = np.zeros(x0.shape)
        return zeros, zeros, np.zeros(Q.shape)
    trig = quad.basis[:J]
    x = x0[:, None] + quad.height[None, :J] + ab @ trig.T
    V, F, e = law.node_terms(alpha, x, quad.weight[:J])
    cs = e @ trig  # [c_n, -s_n], shape (B, 2K)
    f = (quad.edge @ cs.T).T
    return V, F, np.ascontiguousarray(f)
