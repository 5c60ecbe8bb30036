"""The sphere's surface quadrature against the wall, and its Hertz contact scales.

Units: ``E = rho = R = 1`` (three-dimensional constants); ``v`` in ``c = sqrt(E / rho)``.

The surface point at polar angle ``theta`` from the impact axis sits, along the axis, at::

    x(theta) = x0 + cos(theta) + sum_k Q_k g_k(theta),
    g_k(theta) = C_k P_l(cos theta) cos(theta) - S_k dP_l/dtheta(theta) sin(theta)

(``u_r cos(theta) - u_theta sin(theta)``), so the basis of order ``l`` is
``[P_l(cos theta) cos(theta), -dP_l/dtheta sin(theta)]``. The wall integral over the near
hemisphere is ``int_0^{pi/2} f(theta) 2 pi sin(theta) dtheta = 2 pi int_0^1 f d(cos theta)``
(the far half never touches), taken by Gauss-Legendre in ``mu = cos(theta)`` on ``[0, 1]``;
its nodes crowd the tip, where they are spaced almost uniformly in ``theta`` (about
``2.2 / M``), which resolves the contact peak ``exp(-alpha theta^2 / 2)``.

The stop test and the active-node bound of the dynamics assume basis values of magnitude at
most 1 (``g_max = |C| + |S|``). ``|P_l| <= 1`` holds, but ``|dP_l/dtheta|`` grows like ``l``:
the tangential column of every order is therefore divided by its largest magnitude over the
nodes and the ``S`` of that order's modes multiplied by it, so ``S * basis`` is unchanged.
The quadrature's ``S`` is then *not* the modes' ``S``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from scipy.special import eval_legendre, lpmv, roots_legendre

from restitution.bodies.base import SurfaceQuadrature, surface_quadrature
from restitution.errors import InputError

if TYPE_CHECKING:
    from restitution.bodies.sphere.modes import SphereModes

__all__ = [
    "CONTACT_TIME_CONSTANT",
    "contact_time_estimate",
    "default_n_nodes",
    "dense_surface_matrix",
    "depth_transform",
    "legendre_and_theta_derivative",
    "max_compression_estimate",
    "pair_max_compression",
    "sphere_quadrature",
    "surface_basis",
]


def legendre_and_theta_derivative(l, theta):
    """``P_l(cos theta)`` and ``dP_l(cos theta)/dtheta`` (broadcast).

    ``dP_l/dtheta = -sin(theta) P_l'(cos theta) = P_l^1(cos theta)`` with the Condon-Shortley
    phase of :func:`scipy.special.lpmv`.
    """
    l, theta = np.broadcast_arrays(np.asarray(l), np.asarray(theta, dtype=float))
    mu = np.cos(theta)
    return eval_legendre(l, mu), lpmv(1, l, mu)


def default_n_nodes(alpha: float, l_max: int) -> int:
    """Gauss-Legendre nodes on the near hemisphere for a contact zone of depth ``1 / alpha``.

    At least 128, a tip spacing ``~2.2 / M`` of at most ``0.12 / sqrt(alpha)`` (the disk's
    criterion for the peak ``exp(-alpha theta^2 / 2)``), and at least ``4 l_max + 32`` so that
    ``P_l`` of the highest order is resolved.
    """
    return max(128, int(math.ceil(18.5 * math.sqrt(alpha))), 4 * int(l_max) + 32)


def _nodes(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """``theta`` increasing from the tip and the weights ``2 pi dmu`` of Gauss-Legendre."""
    t, w = roots_legendre(n_nodes)
    mu = 0.5 * (t + 1.0)
    order = np.argsort(-mu)
    return np.arccos(mu[order]), math.pi * w[order]


def surface_basis(orders: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """The basis of every order at polar angles ``theta``, unscaled (module docs):
    ``[P_l(cos theta) cos(theta) | -dP_l/dtheta sin(theta)]``, shape (M, 2K).

    What a pair of two radii needs of the sphere that does not carry the quadrature (the
    larger one): its surface at the angles that pair with the other's nodes
    (:class:`restitution.bodies.pair.BodyPair`). Its tangential columns grow like ``l``; the
    pair scales them as :func:`sphere_quadrature` does.
    """
    theta = np.asarray(theta, dtype=float)
    P, dP = legendre_and_theta_derivative(np.asarray(orders)[None, :], theta[:, None])
    return np.hstack([P * np.cos(theta)[:, None], -dP * np.sin(theta)[:, None]])


def sphere_quadrature(modes: SphereModes, n_nodes: int) -> SurfaceQuadrature:
    """The surface quadrature of ``modes`` with ``n_nodes`` nodes on ``theta in [0, pi/2]``.

    The tangential columns are scaled to ``max |.| = 1`` and ``S`` compensates (module docs).
    """
    if n_nodes < 16:
        raise InputError(f"n_nodes must be at least 16, got {n_nodes}")
    theta, weight = _nodes(int(n_nodes))
    orders, column = np.unique(modes.l, return_inverse=True)
    P, dP = legendre_and_theta_derivative(orders[None, :], theta[:, None])
    normal = P * np.cos(theta)[:, None]
    tangential = -dP * np.sin(theta)[:, None]
    scale = np.max(np.abs(tangential), axis=0)
    scale = np.where(scale > 0.0, scale, 1.0)
    basis = np.hstack([normal, tangential / scale])
    S = modes.S * scale[column]
    return surface_quadrature(theta, weight, np.cos(theta), basis, column, modes.C, S)


def dense_surface_matrix(modes: SphereModes, theta: np.ndarray) -> np.ndarray:
    """``g_k(theta_j)`` (module docs) as a dense matrix, shape (M, N); for checks."""
    theta = np.asarray(theta, dtype=float)
    P, dP = legendre_and_theta_derivative(modes.l[None, :], theta[:, None])
    return (
        modes.C[None, :] * P * np.cos(theta)[:, None]
        - modes.S[None, :] * dP * np.sin(theta)[:, None]
    )


def depth_transform(s):
    """``int_0^{pi/2} exp(-s (1 - cos theta)) 2 pi sin(theta) dtheta
    = 2 pi (1 - exp(-s)) / s``, ``R^2`` (exact)."""
    s = np.asarray(s, dtype=float)
    return 2.0 * math.pi * -np.expm1(-s) / s


def max_compression_estimate(v, nu: float):
    """Hertz largest compression against a rigid wall, ``R``.

    ``(1/2) m v^2 = (8/15) E* sqrt(R) delta^(5/2)`` with ``m = 4 pi / 3`` and
    ``E* = E / (1 - nu^2)``: ``delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5)``.
    """
    e_star = 1.0 / (1.0 - nu**2)
    m = 4.0 * math.pi / 3.0
    out = (15.0 * m * np.asarray(v, dtype=float) ** 2 / (16.0 * e_star)) ** 0.4
    return float(out) if np.ndim(out) == 0 else out


CONTACT_TIME_CONSTANT = 2.0 * math.sqrt(math.pi) * math.gamma(1.4) / math.gamma(0.9)
"""``kappa = v tau / delta_max = 2 int_0^1 dx / sqrt(1 - x^(5/2)) = 2 sqrt(pi) Gamma(7/5) /
Gamma(9/10) = 2.9432752...`` for the Hertz sphere on a rigid wall (the literature's 2.943,
:mod:`restitution.quasistatic.hertz_sphere` derives it)."""


def contact_time_estimate(v, nu: float):
    """Hertz contact time ``kappa delta_max / v`` (:data:`CONTACT_TIME_CONSTANT`, 2.9433)
    against a rigid wall, ``R / c``."""
    out = CONTACT_TIME_CONSTANT * max_compression_estimate(v, nu) / np.asarray(v, dtype=float)
    return float(out) if np.ndim(out) == 0 else out


def pair_max_compression(
    w,
    radius_ratio: float,
    modulus_ratio: float,
    density_ratio: float,
    nu1: float,
    nu2: float,
):
    """Two spheres' Hertz largest approach of the centres at relative speed ``w`` (``c1``),
    ``R1`` (the second sphere's constants in the first's units).

    ``(mu/2) w^2 = (8/15) E* sqrt(R_eff) delta^(5/2)`` with the reduced mass
    ``mu = m1 m2 / (m1 + m2)``, ``1/E* = (1 - nu1^2) + (1 - nu2^2) / E2`` and
    ``R_eff = R2 / (1 + R2)``. Two identical spheres give ``2 delta_wall(w / 2)``; a rigid,
    infinitely heavy and large partner gives the wall's ``delta_wall(w)``.
    """
    r2, e2 = float(radius_ratio), float(modulus_ratio)
    m1 = 4.0 * math.pi / 3.0
    m2 = m1 * float(density_ratio) * r2**3
    mu = m1 * m2 / (m1 + m2)
    e_star = 1.0 / ((1.0 - nu1**2) + (1.0 - nu2**2) / e2)
    r_eff = r2 / (1.0 + r2)
    out = (15.0 * mu * np.asarray(w, dtype=float) ** 2 / (16.0 * e_star * math.sqrt(r_eff))) ** 0.4
    return float(out) if np.ndim(out) == 0 else out
