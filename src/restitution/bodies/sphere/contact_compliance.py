"""The static compliance of the sphere's contact, in the continuum and in its truncated modes.

Units: ``E = rho = R = 1`` (three-dimensional constants), ``m = 4 pi / 3``; compliances in
``1 / (E R)``.

**Why.** The oblique collision (:mod:`restitution.dynamics.oblique`) moves the sphere's surface
with its kept modes alone; a contact of radius ``a`` feels the normal and tangential
compliance those modes give it. A static load that balances itself by the body's inertia (the
free modes' answer to a slow load) stores ``sum_k f_k^2 / (2 m omega_k^2)`` in the modes of
frequency ``omega_k`` and generalised force ``f_k = int t . u_k dA``, so the truncated body's
compliance is a partial sum of the continuum's: below it, and rising with every mode kept.
:func:`modal_compliance` is that sum over a :class:`~restitution.bodies.sphere.cap.SphereCap`,
:func:`continuum_compliance` the same load on the elastic sphere, by the closed forms of every
order (:mod:`restitution.bodies.sphere.static`). docs/oblique.md uses them for the sphere's
microslip ``beta``, whose modal series in the mode count is not monotonic.

**Loads** (total force 1, on the cap about the pole ``e1`` whose projection on the wall is the
disk of radius ``a``; per unit projected area, ``r`` the distance from the axis):

* ``"pressure"``: Hertz's ``p = 3 / (2 pi a^2) sqrt(1 - r^2 / a^2)``, along ``-e1``;
* ``"stick"``: Mindlin's full-stick traction ``q = 1 / (2 pi a sqrt(a^2 - r^2))``, along ``e2``;
* ``"slip"``: the pressure's shape along ``e2`` (the gross-slip traction ``mu p``);
* ``"punch"``: the stick traction's shape along ``-e1``, the flat punch's pressure
  ``1 / (2 pi a sqrt(a^2 - r^2))``. It is the increment of Hertz's pressure when the
  compression grows at a fixed contact radius, so its compliance is the contact's incremental
  normal one, ``1 / k_n``, as the stick traction's is ``1 / k_t``: their ratio is the
  stiffness ratio ``chi = k_t / k_n`` of Maw, Barber and Fawcett's theory
  (:mod:`restitution.quasistatic.oblique`).

**Compliance** ``C = int t . u dA`` for unit force: twice the strain energy, the work-conjugate
mean displacement. On the half-space (``a -> 0``) ``C a`` tends to ``3 (1 - nu^2) / 5`` for the
pressure (its mean ``4/5`` of Hertz's approach ``3 / (4 E* a)``), to ``(2 - nu) (1 + nu) /
4`` for the stick traction (Mindlin's uniform displacement ``(2 - nu) / (8 G a)``) and to
``(1 - nu^2) / 2`` for the punch (its uniform displacement ``1 / (2 E* a)``).

**Continuum, per order.** With ``x = cos theta``, ``s = sin theta`` and ``t`` the load per
unit surface area (``x`` times the one per projected area), the pressure's traction ``(t_r,
t_theta) = t (-x, s)`` projects on ``P_l`` and ``dP_l/dtheta`` (coefficients ``A_l, B_l``); the
tangential traction ``t e2`` on the spheroidal ``Y = N P_l^1 cos(phi)``, its surface gradient
and the toroidal ``r_hat x grad_1 (N P_l^1 sin(phi))`` (``a_l, b_l, c_l``)::

    a_l |Y|^2            =  pi int t s P           dOmega_theta
    b_l l (l + 1) |Y|^2  =  pi int t (x P' + P/s)  dOmega_theta
    c_l l (l + 1) |Y|^2  = -pi int t (P' + x P/s)  dOmega_theta

(``P = N P_l^1``, ``P' = dP/dtheta``, ``dOmega_theta = s dtheta``, ``|Y|^2 = 4 pi / (2 l +
1)``), and ``C = sum_l |Y|^2 (a U + l (l + 1) (b W + c w))`` with ``[U, W] = K_l [a, b]`` and
``w = T_l c``. The quadrature runs in ``r = a sin(sigma)``, which makes both loads smooth.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import roots_legendre

from restitution.bodies.sphere.static import static_compliance, toroidal_static_compliance
from restitution.errors import InputError

__all__ = ["LOADS", "continuum_compliance", "half_space_compliance", "modal_compliance"]

LOADS = ("pressure", "stick", "slip", "punch")
"""The loads of the module docstring."""

_TANGENTIAL = frozenset(LOADS[1:3])
_SINGULAR = frozenset(LOADS[1::2])  # the flat punch's shape, 1 / sqrt(a^2 - r^2)

ORDERS_PER_RADIUS = 800.0
""":func:`continuum_compliance` sums the orders to ``ORDERS_PER_RADIUS / a``. The smooth loads'
terms fall fast (doubling the cut moves them by 1.5e-9); the stick traction's fall like
``l^-2`` (its edge singularity), so its tail beyond the cut is about 3.6e-4 of the sum, which
it underestimates by that much (doubling the cut moves it by 1.8e-4 at ``a = 0.15`` and 1.9e-4
at ``a = 0.3``: half the tail)."""


def _check(a: float, load: str) -> float:
    if load not in LOADS:
        raise InputError(f"load must be one of {', '.join(LOADS)}, got {load!r}")
    a = float(a)
    if not 0.0 < a < 1.0:
        raise InputError(f"the contact radius a must be in (0, 1) (R), got {a!r}")
    return a


def _quadrature(a: float, load: str, points: int) -> tuple[np.ndarray, np.ndarray]:
    """Polar angles of the loaded cap and the load's weights: ``int g t dOmega_theta`` over
    ``theta`` is ``sum g w`` (the load per surface area times ``sin(theta) dtheta``, ``phi``
    not yet integrated)."""
    t, w = roots_legendre(points)
    sigma = 0.25 * math.pi * (t + 1.0)
    w = 0.25 * math.pi * w
    r = a * np.sin(sigma)
    # (load per projected area) r dr / d sigma: smooth in sigma for both shapes
    if load in _SINGULAR:
        weight = np.sin(sigma) / (2.0 * math.pi)
    else:
        weight = 3.0 / (2.0 * math.pi) * np.sin(sigma) * np.cos(sigma) ** 2
    return np.arcsin(r), weight * w


def half_space_compliance(a: float, nu: float, load: str) -> float:
    """The half-space's compliance of the module docstring (``a -> 0``), all loads but
    ``slip``.

    >>> round(half_space_compliance(0.5, 0.3, "stick"), 12)
    1.105
    """
    a = _check(a, load)
    if load == LOADS[0]:
        return 0.6 * (1.0 - nu * nu) / a
    if load == LOADS[1]:
        return (2.0 - nu) * (1.0 + nu) / (4.0 * a)
    if load == LOADS[3]:
        return 0.5 * (1.0 - nu * nu) / a
    raise InputError("the half-space's slip compliance is not given; use continuum_compliance")


def continuum_compliance(
    a: float, nu: float, load: str, *, l_top: int | None = None, points: int | None = None
) -> float:
    """``C`` of ``load`` on the elastic sphere (module docstring), summed to order ``l_top``
    (default ``ORDERS_PER_RADIUS / a``) with ``points`` Gauss-Legendre nodes across the
    contact (default 16 per period of the highest order)."""
    a = _check(a, load)
    if l_top is None:
        l_top = int(math.ceil(ORDERS_PER_RADIUS / a))
    if points is None:
        points = max(64, int(16 * l_top * math.asin(a) / (2.0 * math.pi)) + 1)
    theta, w = _quadrature(a, load, int(points))
    x, s = np.cos(theta), np.sin(theta)
    tangential = load in _TANGENTIAL
    # per order, the projections' integrals (module docstring) before the norms
    proj = np.zeros((l_top + 1, 3))
    # normal:     int t (-x P_l),  int t (-s^2 P_l')
    # tangential: int t s P_l^1,   int t (x dP_l^1 + P_l^1/s),   -int t (dP_l^1 + x P_l^1/s)
    # with P_l^1 = s P_l', P_l^1 / s = P_l', dP_l^1/dtheta = l (l + 1) P_l - x P_l' (the
    # Legendre equation), so the last is -l (l + 1) int t P_l
    wx, ws2, wxx = w * x, w * s * s, w * x * x
    p_prev, p = np.zeros_like(x), np.ones_like(x)  # P_(l-1), P_l
    d_prev, d = np.zeros_like(x), np.zeros_like(x)  # their x-derivatives
    for l in range(l_top + 1):
        if tangential:
            ll = l * (l + 1.0)
            proj[l] = (ws2 @ d, ll * (wx @ p) - wxx @ d + w @ d, -ll * (w @ p))
        else:
            proj[l] = (-(wx @ p), -(ws2 @ d), 0.0)
        p_prev, p = p, ((2 * l + 1) * x * p - l * p_prev) / (l + 1)
        d_prev, d = d, (d_prev + (2 * l + 1) * p_prev if l else np.ones_like(x))
    orders = np.arange(l_top + 1, dtype=float)
    ll = orders * (orders + 1.0)
    norm = 4.0 * math.pi / (2.0 * orders + 1.0)
    K = static_compliance(orders, nu)
    if not tangential:
        A = 2.0 * math.pi * proj[:, 0] / norm
        B = 2.0 * math.pi * np.divide(proj[:, 1], ll * norm, out=np.zeros(l_top + 1), where=ll > 0)
        U = K[:, 0, 0] * A + K[:, 0, 1] * B
        W = K[:, 1, 0] * A + K[:, 1, 1] * B
        return float(np.sum(norm * (A * U + ll * B * W)))
    n1 = np.sqrt(np.divide(2.0, ll, out=np.zeros(l_top + 1), where=ll > 0))
    T = np.r_[0.0, toroidal_static_compliance(orders[1:], nu)]
    a_l = math.pi * n1 * proj[:, 0] / norm
    tang = np.divide(math.pi * n1, ll * norm, out=np.zeros(l_top + 1), where=ll > 0)
    b_l, c_l = tang * proj[:, 1], tang * proj[:, 2]
    U = K[:, 0, 0] * a_l + K[:, 0, 1] * b_l
    W = K[:, 1, 0] * a_l + K[:, 1, 1] * b_l
    return float(np.sum(norm * (a_l * U + ll * (b_l * W + c_l * T * c_l))))


def modal_compliance(cap, a: float, load: str, *, points: int = 200) -> float:
    """``C`` of ``load`` in the modes of ``cap`` (a
    :class:`~restitution.bodies.sphere.cap.SphereCap`): ``sum_k f_k^2 / (m omega_k^2)``.

    Only the modes of azimuthal order 0 (``pressure``) or 1 (``stick``, ``slip``) carry a
    generalised force; the others are orthogonal to the load and left out exactly.
    """
    a = _check(a, load)
    tangential = load in _TANGENTIAL
    part = cap.take(cap.m == int(tangential))
    theta, w = _quadrature(a, load, int(points))
    n_phi = 8  # exact for the products of cos(phi), cos(2 phi) and their sines
    phi = 2.0 * math.pi * np.arange(n_phi) / n_phi
    T, F = np.meshgrid(theta, phi, indexing="ij")
    d1, d2, _ = part.displacement(T.ravel(), F.ravel())
    weight = w[:, None] * np.full(n_phi, 2.0 * math.pi / n_phi)
    f = weight.ravel() @ (d2 if tangential else -d1)
    return float(np.sum(f * f / (part.mass * part.omega**2)))
