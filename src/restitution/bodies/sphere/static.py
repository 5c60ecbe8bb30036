"""The sphere's static flexibility at its surface, and the part its truncated modes leave out.

Units: ``E = rho = R = 1`` (three-dimensional constants), ``m = 4 pi / 3``; displacements per
unit force per unit area of the surface.

**Per order, in closed form.** An axisymmetric traction ``sigma_rr = A P_l(cos theta)``,
``sigma_rtheta = B dP_l/dtheta`` on the free surface deforms the sphere, for ``l >= 2``, into
``u_r = U P_l``, ``u_theta = W dP_l/dtheta`` with ``[U, W] = K_l [A, B]``::

    D     = (l - 1) [(2l + 1) nu + l^2 + l + 1]
    U_A   = (1 + nu) [(2l^2 - 1) - (2l^2 - l - 2) nu] / D
    W_B   = (1 + nu) [(2l^2 - l + 1) - (2l^2 - 3l - 1) nu] / D
    W_A   = (1 + nu) [(2l - 1) nu - (l - 2)] / D,      U_B = l (l + 1) W_A

(Navier's equations in spherical coordinates with the ansatz
``u_r = (p r^(l-1) + q r^(l+1)) P_l``, ``u_theta = (s r^(l-1) + t r^(l+1)) dP_l/dtheta``, the
regular solution; solved symbolically for ``l = 2 ... 6`` and the polynomials read off, every
one of them reproduced. Large ``l``: ``U_A -> 2 (1 - nu^2) / l``, the half-space's normal
compliance ``2 (1 - nu^2) / (E k)``.) For ``l = 0`` (a uniform pressure) ``U = (1 - 2 nu) A``.
For ``l = 1`` the load has the net force ``(4 pi / 3)(A + 2B)``; the free modes answer it with
the inertial body force that balances it and the rigid translation taken out::

    K_1 = [[3 (1 - 2 nu) / 5, -4 (1 - 2 nu) / 5], [-2 (1 - 2 nu) / 5, 2 (3 - nu) / 5]]

The modal sums obey ``K_l = 2 pi sum [C, S] [C N_0, S N_1] / (m omega^2)`` over the modes of
order ``l``, with ``N_0 = 2 / (2l + 1)`` and ``N_1 = l (l + 1) N_0`` the norms of ``P_l`` and
``dP_l/dtheta`` on ``[-1, 1]``: the tests check both routes against each other. The same
``K_l`` holds for the spheroidal fields of every azimuthal order ``m`` (the radial equations
depend on ``l`` alone; ``Y_lm`` and its surface gradient in place of ``P_l`` and
``dP_l/dtheta``).

**Toroidal, per order** (:func:`toroidal_static_compliance`). A shear traction ``t = c r_hat x
grad_1 Y`` moves the surface by ``w r_hat x grad_1 Y`` with ``w = T_l c``. The regular static
field is ``W = A r^l``, whose shear ``mu (W' - W / r)`` is ``mu (l - 1) A`` at ``r = 1``::

    T_l = 1 / (mu (l - 1)) = 2 (1 + nu) / (l - 1)        (l >= 2)

``l = 1`` is a torque about a diameter: the free modes answer it with the inertial body force
``-rho alpha x r`` of the angular acceleration ``alpha = M / I`` (``W = c r^3``,
``10 mu c = -alpha``) and the rigid rotation taken out (``W`` orthogonal to ``r``:
``int W r^3 dr = 0``), which leaves ``T_1 = 2 (1 + nu) / 7``. The modal sums obey
``T_l = (4 pi l (l + 1) / (2 l + 1)) sum T_n^2 / (m omega_n^2)`` over the toroidal modes of
order ``l`` (surface amplitude ``T_n = W(1)``): a test.

**The residual on the surface nodes** (:func:`residual_flexibility`). Along the impact axis a
mode of order ``l`` moves the surface by ``b_l(theta) = [mu P_l(mu), l (P_(l-1)(mu) - mu
P_l(mu))]`` per unit ``(C, S)`` (``mu = cos theta``; the second entry is
``-dP_l/dtheta sin(theta)`` written without a division), so a force per unit area ``p`` moves
it by ``-int G(theta, theta') p dA'`` with ``G = sum_l b_l^T M_l b_l``,
``M_l = K_l diag(1 / N_0, 1 / N_1) / (2 pi)``. ``G`` has the ``1 / distance`` singularity of a
point load, integrable on rings; on the quadrature's nodes it is taken between hat functions in
``theta`` (Galerkin; the first hat is flat from the axis to the first node), each normalised to
unit force, so that node ``j``'s force is spread over its hat and node ``i``'s displacement is
its hat's average. The projections of ``b_l`` on the hats are integrated by Gauss-Legendre
(:data:`POINTS_PER_INTERVAL` per interval between nodes) with ``P_l`` by its recurrence; the
series is summed to ``l = ORDERS_PER_SPACING / h`` (``h``: the nodes' spacing at the tip).
The residual is this full kernel less the kept modes' own part between the same hats.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numpy.polynomial.legendre import leggauss

from restitution.bodies.blocks import LeadingBlocks
from restitution.errors import InputError

if TYPE_CHECKING:
    from restitution.bodies.sphere.modes import SphereModes

__all__ = [
    "ORDERS_PER_SPACING",
    "POINTS_PER_INTERVAL",
    "hat_projections",
    "residual_flexibility",
    "static_compliance",
    "toroidal_static_compliance",
]

ORDERS_PER_SPACING = 48.0
"""The series is summed to ``l = ORDERS_PER_SPACING / h``; the terms beyond fall like
``(l h)^-4 / l`` (doubling it moves the kernel by less than 1e-6 of its diagonal, a test)."""

POINTS_PER_INTERVAL = 32
"""Gauss-Legendre points per interval between nodes for the hats' projections: an interval
holds about ``ORDERS_PER_SPACING / (2 pi)`` periods of the highest ``P_l``."""


def static_compliance(orders, nu: float) -> np.ndarray:
    """``K_l`` of the module docstring for every order, shape (len(orders), 2, 2).

    Rows: ``(U, W)``; columns: ``(A, B)``; ``E = R = 1``.
    """
    l = np.asarray(orders, dtype=float)
    if l.ndim != 1 or np.any(l < 0) or np.any(l != np.round(l)):
        raise InputError("orders must be a one-dimensional array of integers >= 0")
    out = np.zeros((l.size, 2, 2))
    hi = l >= 2
    L = l[hi]
    D = (L - 1.0) * ((2.0 * L + 1.0) * nu + L * L + L + 1.0)
    out[hi, 0, 0] = (1.0 + nu) * ((2 * L * L - 1) - (2 * L * L - L - 2) * nu) / D
    out[hi, 1, 1] = (1.0 + nu) * ((2 * L * L - L + 1) - (2 * L * L - 3 * L - 1) * nu) / D
    out[hi, 1, 0] = (1.0 + nu) * ((2 * L - 1) * nu - (L - 2)) / D
    out[hi, 0, 1] = L * (L + 1) * out[hi, 1, 0]
    out[l == 0, 0, 0] = 1.0 - 2.0 * nu
    one = l == 1
    out[one, 0, 0] = 0.6 * (1.0 - 2.0 * nu)
    out[one, 0, 1] = -0.8 * (1.0 - 2.0 * nu)
    out[one, 1, 0] = -0.4 * (1.0 - 2.0 * nu)
    out[one, 1, 1] = 0.4 * (3.0 - nu)
    return out


def toroidal_static_compliance(orders, nu: float) -> np.ndarray:
    """``T_l`` of the module docstring for every order ``l >= 1``, shape (len(orders),);
    ``E = R = 1``.

    >>> [round(float(t), 12) for t in toroidal_static_compliance([1, 2, 5], 0.3)]
    [0.371428571429, 2.6, 0.65]
    """
    l = np.asarray(orders, dtype=float)
    if l.ndim != 1 or np.any(l < 1) or np.any(l != np.round(l)):
        raise InputError("toroidal orders must be a one-dimensional array of integers >= 1")
    shear = 1.0 / (2.0 * (1.0 + nu))
    return np.where(l == 1, 1.0 / (7.0 * shear), 1.0 / (shear * np.maximum(l - 1.0, 1.0)))


def _modal_weights(l_top: int, nu: float) -> np.ndarray:
    """``M_l = K_l diag(1/N_0, 1/N_1) / (2 pi)`` for ``l = 0 .. l_top``, shape (l_top+1, 2, 2)."""
    l = np.arange(l_top + 1, dtype=float)
    K = static_compliance(l, nu)
    n0 = 2.0 / (2.0 * l + 1.0)
    n1 = l * (l + 1.0) * n0
    inv1 = np.divide(1.0, n1, out=np.zeros_like(n1), where=n1 > 0)
    return K * np.stack([1.0 / n0, inv1])[None, :, :].transpose(2, 0, 1) / (2.0 * math.pi)


def hat_projections(theta: np.ndarray, count: int, l_top: int) -> np.ndarray:
    """``int h_j(theta) b_l(theta) dA`` for the normalised hats of the first ``count`` nodes of
    ``theta`` (increasing from the tip) and every ``l <= l_top``; shape (2, l_top+1, count)."""
    theta = np.asarray(theta, dtype=float)
    if count < 2 or theta.size < count + 1:
        raise InputError("the residual needs at least two nodes and one beyond them")
    edges = np.r_[0.0, theta[: count + 1]]  # intervals [edges[k], edges[k+1]], k = 0..count
    t, w = leggauss(POINTS_PER_INTERVAL)
    lo, hi = edges[:-1, None], edges[1:, None]
    x = 0.5 * (lo + hi) + 0.5 * (hi - lo) * t[None, :]  # (count+1, q)
    dA = 2.0 * math.pi * np.sin(x) * (0.5 * (hi - lo)) * w[None, :]
    frac = (x - lo) / (hi - lo)  # 0 at the interval's start, 1 at its end
    # Interval k = 0 is [0, theta_0]: hat 0 is flat there. Interval k >= 1 is
    # [theta_(k-1), theta_k]: hat k-1 falls, hat k rises.
    rise, fall = frac * dA, (1.0 - frac) * dA
    rise[0], fall[0] = dA[0], 0.0
    mu = np.cos(x)
    out = np.zeros((2, l_top + 1, count))
    p_prev, p = np.zeros_like(mu), np.ones_like(mu)
    norm = rise[:count].sum(axis=1) + np.r_[fall[1 : count + 1].sum(axis=1)]
    for l in range(l_top + 1):
        normal = mu * p
        tangential = l * (p_prev - mu * p)
        for c, values in enumerate((normal, tangential)):
            up = (values * rise).sum(axis=1)
            down = (values * fall).sum(axis=1)
            out[c, l] = (up[:count] + down[1 : count + 1]) / norm
        p_prev, p = p, ((2 * l + 1) * mu * p - l * p_prev) / (l + 1)
    return out


def _build_kernel(nu: float, theta: tuple, count: int) -> tuple[np.ndarray, np.ndarray]:
    """The hat-averaged static kernel of all orders, and the projections."""
    theta = np.asarray(theta)
    h = float(theta[1] - theta[0])
    l_top = int(math.ceil(ORDERS_PER_SPACING / h))
    a = hat_projections(theta, count, l_top)
    M = _modal_weights(l_top, nu)
    G = np.zeros((count, count))
    for r in range(2):
        for c in range(2):
            G += (a[r].T * M[:, r, c]) @ a[c]
    return G, a


_full_kernel = LeadingBlocks(
    lambda key, count: _build_kernel(key[0], key[1], count),
    lambda value, count: (value[0][:count, :count], value[1][:, :, :count]),
    lambda value: value[0].shape[0],
)
"""The kernel and projections per ``(nu, nodes, ORDERS_PER_SPACING)``, built once at the
largest node count asked (:class:`~restitution.bodies.blocks.LeadingBlocks`: one quadrature
serves every kept set and wall; each hat's projections depend on its own nodes alone)."""


def residual_flexibility(modes: SphereModes, theta: np.ndarray, count: int) -> np.ndarray:
    """The static flexibility the modes of ``modes`` leave out, between the hats of the first
    ``count`` surface nodes ``theta``; shape (count, count), symmetric (module docstring)."""
    key = (float(modes.nu), tuple(np.asarray(theta, dtype=float)), ORDERS_PER_SPACING)
    G, a = _full_kernel(key, int(count))
    l_top = a.shape[1] - 1
    if int(modes.l.max(initial=0)) > l_top:
        raise InputError(
            f"the surface nodes (tip spacing {theta[1] - theta[0]:.3g}) do not resolve the "
            f"kept modes' highest order {int(modes.l.max())}: use more nodes"
        )
    kept = (modes.C[:, None] * a[0, modes.l] + modes.S[:, None] * a[1, modes.l]) / (
        math.sqrt(modes.mass) * modes.omega[:, None]
    )
    return G - kept.T @ kept
