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

**Annuli.** :func:`annulus_flexibility` takes the same sums between the piecewise-constant
tractions of annuli of the projected plane, normal or tangential (in line): the flexibility
of a contact problem solved on the sphere itself rather than with the half-space's traction
shapes (tools/sphere_partial_slip.py). :func:`half_space_annulus_flexibility` is its
closed form on the half-space.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import hyp2f1, roots_legendre

from restitution.bodies.sphere.static import static_compliance, toroidal_static_compliance
from restitution.errors import InputError

__all__ = [
    "DIRECTIONS",
    "LOADS",
    "annulus_flexibility",
    "annulus_tilt_flexibility",
    "continuum_compliance",
    "half_space_annulus_flexibility",
    "half_space_compliance",
    "modal_annulus_flexibility",
    "modal_annulus_tilt_flexibility",
    "modal_compliance",
]

LOADS = ("pressure", "stick", "slip", "punch")
"""The loads of the module docstring."""

_TANGENTIAL = frozenset(LOADS[1:3])
_SINGULAR = frozenset(LOADS[1::2])  # the flat punch's shape, 1 / sqrt(a^2 - r^2)

ORDERS_PER_RADIUS = 800.0
""":func:`continuum_compliance` sums the orders to ``ORDERS_PER_RADIUS / a``. The smooth loads'
terms fall fast (doubling the cut moves them by 1.5e-9); the stick traction's and the punch's
fall like ``l^-2`` (their edge singularity), so their tails beyond the cut are about 3.6e-4 and
4.6e-4 of the sums, which they underestimate by that much (doubling the cut moves the stick's
by 1.8e-4 at ``a = 0.15`` and 1.9e-4 at ``a = 0.3``, the punch's by 2.3e-4: half the tail).
The annuli of :func:`annulus_flexibility` jump at their edges and converge the same way."""


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


_BLOCK = 256  # orders per block of _coefficients' matrix products


def _coefficients(
    theta: np.ndarray, w: np.ndarray, l_top: int, kind: str
) -> tuple[np.ndarray, ...]:
    """The loads' coefficients of every order (module docstring): ``(A, B)`` of the normal
    loads (``kind`` ``"normal"``) or ``(a, b, c)`` of the tangential ones (``"tangential"``)
    and of the tilting ones along ``-e1`` times ``cos(phi)`` (``"tilt"``), each of shape
    ``(l_top + 1, loads)``, for loads given by their weights ``w`` (shape ``(loads,
    len(theta))``) at the polar angles ``theta``."""
    x, s = np.cos(theta), np.sin(theta)
    proj = np.zeros((l_top + 1, 3, w.shape[0]))
    # normal:     int t (-x P_l),  int t (-s^2 P_l')
    # tangential: int t s P_l^1,   int t (x dP_l^1 + P_l^1/s),   -int t (dP_l^1 + x P_l^1/s)
    # tilt:       -int t x P_l^1,  int t s dP_l^1,               -int t P_l^1
    # with P_l^1 = s P_l', P_l^1 / s = P_l', dP_l^1/dtheta = l (l + 1) P_l - x P_l' (the
    # Legendre equation), so the tangential third is -l (l + 1) int t P_l
    if kind not in ("normal", "tangential", "tilt"):
        raise InputError(f"kind must be normal, tangential or tilt, got {kind!r}")
    tangential = kind != "normal"
    wx, ws2, wxx = w * x, w * s * s, w * x * x
    ws, wxs = w * s, w * x * s
    # P_l and P_l' of a block of orders by the recurrence, then the products as matrix products
    # (one pass over the block for all the loads)
    block = min(l_top + 1, _BLOCK)
    P, D = np.empty((block, x.size)), np.empty((block, x.size))
    p_prev, p = np.zeros_like(x), np.ones_like(x)  # P_(l-1), P_l
    d_prev, d = np.zeros_like(x), np.zeros_like(x)  # their x-derivatives
    for first in range(0, l_top + 1, block):
        rows = min(block, l_top + 1 - first)
        for i in range(rows):
            l = first + i
            P[i], D[i] = p, d
            p_prev, p = p, ((2 * l + 1) * x * p - l * p_prev) / (l + 1)
            d_prev, d = d, (d_prev + (2 * l + 1) * p_prev if l else np.ones_like(x))
        Pb, Db, out = P[:rows], D[:rows], proj[first : first + rows]
        ll = (np.arange(first, first + rows) * (np.arange(first, first + rows) + 1.0))[:, None]
        if kind == "tilt":
            Dxs = Db @ wxs.T
            out[:, 0], out[:, 2] = -Dxs, -(Db @ ws.T)
            out[:, 1] = ll * (Pb @ ws.T) - Dxs
        elif tangential:
            out[:, 0], out[:, 2] = Db @ ws2.T, -ll * (Pb @ w.T)
            out[:, 1] = ll * (Pb @ wx.T) - Db @ wxx.T + Db @ w.T
        else:
            out[:, 0], out[:, 1] = -(Pb @ wx.T), -(Db @ ws2.T)
    return _normalised(proj, tangential)


def _normalised(proj: np.ndarray, tangential: bool) -> tuple[np.ndarray, ...]:
    """:func:`_coefficients` from the loads' projections ``proj`` (shape ``(l_top + 1, 3,
    loads)``) on ``P_l`` and its derivatives, with the harmonics' norms."""
    orders = np.arange(proj.shape[0], dtype=float)
    ll = (orders * (orders + 1.0))[:, None]
    norm = (4.0 * math.pi / (2.0 * orders + 1.0))[:, None]
    safe = np.where(ll > 0, ll, 1.0)
    if not tangential:
        return 2.0 * math.pi * proj[:, 0] / norm, 2.0 * math.pi * proj[:, 1] / (safe * norm)
    n1 = np.sqrt(2.0 / safe) * (ll > 0)
    tang = math.pi * n1 / (safe * norm)
    return math.pi * n1 * proj[:, 0] / norm, tang * proj[:, 1], tang * proj[:, 2]


def _bilinear(
    coefficients: tuple[np.ndarray, ...], nu: float, loads: tuple[np.ndarray, ...] | None = None
) -> np.ndarray:
    """``int t_i . u(t_j) dA`` for every pair of the loads ``t_i`` of ``coefficients`` and
    ``t_j`` of ``loads`` (default the same; :func:`_coefficients`, of one azimuthal order):
    ``sum_l |Y|^2 (a_i U_j + l (l + 1) (b_i W_j + c_i w_j))``."""
    first = coefficients
    coefficients = first if loads is None else loads
    l_top = coefficients[0].shape[0] - 1
    orders = np.arange(l_top + 1, dtype=float)
    ll = orders * (orders + 1.0)
    norm = 4.0 * math.pi / (2.0 * orders + 1.0)
    K = static_compliance(orders, nu)
    a, b = coefficients[:2]
    U = K[:, 0, 0, None] * a + K[:, 0, 1, None] * b
    W = K[:, 1, 0, None] * a + K[:, 1, 1, None] * b
    out = (first[0] * norm[:, None]).T @ U + (first[1] * (norm * ll)[:, None]).T @ W
    if len(coefficients) == 3:
        T = np.r_[0.0, toroidal_static_compliance(orders[1:], nu)]
        out += (first[2] * (norm * ll * T)[:, None]).T @ coefficients[2]
    return out


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
    kind = "tangential" if load in _TANGENTIAL else "normal"
    coefficients = _coefficients(theta, w[None, :], int(l_top), kind)
    return float(_bilinear(coefficients, nu)[0, 0])


DIRECTIONS = ("normal", "tangential")
"""The annuli's loads in :func:`annulus_flexibility`: along ``-e1`` (a pressure) or ``e2``."""


def _annuli(edges, direction: str) -> np.ndarray:
    if direction not in DIRECTIONS:
        raise InputError(f"direction must be one of {', '.join(DIRECTIONS)}, got {direction!r}")
    edges = np.asarray(edges, dtype=float)
    if edges.ndim != 1 or edges.size < 2 or edges[0] < 0.0 or edges[-1] >= 1.0:
        raise InputError("edges must be at least two radii in [0, 1) (R)")
    if np.any(np.diff(edges) <= 0.0):
        raise InputError("edges must increase")
    return edges


def annulus_flexibility(
    edges, nu: float, direction: str, *, l_top: int | None = None, points: int | None = None
) -> np.ndarray:
    """The Galerkin flexibility of the annuli ``edges[i] <= r < edges[i + 1]`` of the
    projected contact plane on the elastic sphere: ``G[i, j] = int_i u . e dA``, the
    displacement along ``e`` (``-e1`` or ``e2`` by ``direction``) summed over annulus ``i``
    (per projected area) under the unit traction per projected area along ``e`` on annulus
    ``j``. Symmetric; ``q @ G @ q`` is ``C`` of the module docstring for the piecewise-constant
    traction ``q`` (so twice its strain energy).

    Summed to order ``l_top`` (default ``ORDERS_PER_RADIUS / edges[-1]``), with ``points``
    Gauss nodes in ``r`` on each annulus (default 12 plus one per radian of the highest
    order's phase across it). A piecewise-constant traction jumps at every edge, so the terms
    fall like the stick traction's.
    """
    edges = _annuli(edges, direction)
    theta, loads, l_top = _annulus_loads(edges, l_top, points)
    G = _bilinear(_coefficients(theta, loads, l_top, direction), nu)
    return 0.5 * (G + G.T)


def _annulus_loads(edges: np.ndarray, l_top: int | None, points: int | None):
    """The polar angles, the annuli's unit loads per projected area (weights ``r dr``, shape
    ``(annuli, nodes)``) and the highest order, at :func:`annulus_flexibility`'s defaults."""
    if l_top is None:
        l_top = int(math.ceil(ORDERS_PER_RADIUS / edges[-1]))
    width = np.diff(edges)
    if points is None:
        points = 12 + int(math.ceil(l_top * width.max()))
    t, w = roots_legendre(int(points))
    r = edges[:-1, None] + 0.5 * width[:, None] * (t + 1.0)  # (annuli, points)
    weight = 0.5 * width[:, None] * w * r  # unit load per projected area, r dr
    n = width.size
    loads = np.zeros((n, r.size))
    for i in range(n):
        loads[i, i * r.shape[1] : (i + 1) * r.shape[1]] = weight[i]
    return np.arcsin(r.ravel()), loads, int(l_top)


def annulus_tilt_flexibility(
    edges, nu: float, *, l_top: int | None = None, points: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The annuli's order-1 normal flexibility and its coupling to the in-line traction on the
    elastic sphere (Dundurs' coupling; docs/oblique.md, "Dundurs' coupling"), as
    :func:`annulus_flexibility`:

    * ``tilt[i, j] = int_i (u . (-e1)) cos(phi) dA`` under the traction ``cos(phi)`` per
      projected area along ``-e1`` on annulus ``j`` (a pressure tilting the contact);
    * ``cross[i, j]``, the same measure under the unit in-line traction (``e2``) on annulus
      ``j``; by Betti's theorem also ``int_j u . e2 dA`` under annulus ``i``'s tilting
      pressure.

    ``phi`` is measured about the pole ``e1`` from ``e2``. ``tilt`` is symmetric; ``cross``
    vanishes with the half-space's ``1 - 2 nu``.
    """
    edges = _annuli(edges, DIRECTIONS[0])
    theta, loads, l_top = _annulus_loads(edges, l_top, points)
    tilt = _coefficients(theta, loads, l_top, "tilt")
    G = _bilinear(tilt, nu)
    return 0.5 * (G + G.T), _bilinear(tilt, nu, _coefficients(theta, loads, l_top, "tangential"))


def half_space_annulus_flexibility(edges, nu: float, direction: str) -> np.ndarray:
    """:func:`annulus_flexibility` on the half-space, in closed form.

    The normal displacement's transform is ``2 p(k) / (E* k)``, and for the in-line
    traction the displacement along it, averaged over the ring, is ``(2 - nu) / (2 (1 -
    nu))`` times that (Cerruti's). An annulus's transform is ``[r J1(k r) / k]`` between its
    edges, and ``int J1(k r) J1(k s) dk / k^2 = (s / 2) 2F1(1/2, -1/2; 2; s^2 / r^2)`` for
    ``s <= r`` (Weber and Schafheitlin), so ``G = (4 pi / E*) sum +- r s I(r, s)`` over the
    pairs of edges.
    """
    edges = _annuli(edges, direction)
    hi = np.maximum.outer(edges, edges)
    lo = np.minimum.outer(edges, edges)
    ratio = np.divide(lo, hi, out=np.zeros_like(hi), where=hi > 0)
    pair = np.outer(edges, edges) * 0.5 * lo * hyp2f1(0.5, -0.5, 2.0, ratio * ratio)
    diff = np.zeros((edges.size - 1, edges.size))
    idx = np.arange(edges.size - 1)
    diff[idx, idx], diff[idx, idx + 1] = -1.0, 1.0
    G = 4.0 * math.pi * (1.0 - nu * nu) * (diff @ pair @ diff.T)
    if direction == DIRECTIONS[1]:
        G *= (2.0 - nu) / (2.0 * (1.0 - nu))
    return G


def modal_annulus_flexibility(cap, edges, direction: str, *, points: int = 16,
                              azimuths: int = 8) -> np.ndarray:  # fmt: skip
    """:func:`annulus_flexibility` in the modes of ``cap`` (a
    :class:`~restitution.bodies.sphere.cap.SphereCap`): ``G[i, j] = sum_k f_ki f_kj / (m
    omega_k^2)``, ``f_ki`` the mode's displacement along the load summed over annulus ``i``
    (per projected area; ``points`` Gauss nodes in ``r`` and ``azimuths`` in ``phi``, exact
    for the products of the first orders). Only the modes of azimuthal order 0 (``normal``)
    or 1 (``tangential``) carry a force of these loads; the others are left out exactly."""
    edges = _annuli(edges, direction)
    tangential = direction == DIRECTIONS[1]
    part = cap.take(cap.m == int(tangential))
    t, w = roots_legendre(int(points))
    width = np.diff(edges)
    r = edges[:-1, None] + 0.5 * width[:, None] * (t + 1.0)  # (annuli, points)
    weight = 0.5 * width[:, None] * w * r * (2.0 * math.pi / azimuths)  # r dr dphi
    phi = 2.0 * math.pi * np.arange(azimuths) / azimuths
    theta = np.repeat(np.arcsin(r.ravel()), azimuths)
    d1, d2, _ = part.displacement(theta, np.tile(phi, r.size))
    shape = (d2 if tangential else -d1).reshape(r.shape[0], r.shape[1] * azimuths, len(part))
    f = np.einsum("ip,ipk->ik", np.repeat(weight, azimuths, axis=1), shape)
    return (f / (part.mass * part.omega**2)) @ f.T


def modal_annulus_tilt_flexibility(cap, edges, *, points: int = 16,
                                   azimuths: int = 8) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """:func:`annulus_tilt_flexibility` in the modes of ``cap`` (their azimuthal order 1, the
    only ones these loads move), as :func:`modal_annulus_flexibility`."""
    edges = _annuli(edges, DIRECTIONS[0])
    part = cap.take(cap.m == 1)
    t, w = roots_legendre(int(points))
    width = np.diff(edges)
    r = edges[:-1, None] + 0.5 * width[:, None] * (t + 1.0)  # (annuli, points)
    weight = 0.5 * width[:, None] * w * r * (2.0 * math.pi / azimuths)  # r dr dphi
    phi = np.tile(2.0 * math.pi * np.arange(azimuths) / azimuths, r.size)
    d1, d2, _ = part.displacement(np.repeat(np.arcsin(r.ravel()), azimuths), phi)
    weights = np.repeat(weight, azimuths, axis=1)
    shape = (r.shape[0], r.shape[1] * azimuths, len(part))
    f_tilt = np.einsum("ip,ipk->ik", weights * np.cos(phi).reshape(shape[:2]), -d1.reshape(shape))
    f_line = np.einsum("ip,ipk->ik", weights, d2.reshape(shape))
    scaled = f_tilt / (part.mass * part.omega**2)
    return scaled @ f_tilt.T, scaled @ f_line.T


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
