"""Axisymmetric spheroidal eigenmodes of the free elastic sphere (Lamb 1882).

Units: ``E = rho = R = 1`` of the three-dimensional material, ``c = sqrt(E / rho) = 1``,
``omega`` in ``c / R``; Lame constants ``mu = 1 / (2 (1 + nu))``,
``lambda = nu / ((1 + nu) (1 - 2 nu))``, speeds ``c_T = sqrt(mu)``, ``c_L = sqrt(lambda + 2 mu)``.

Only the axisymmetric spheroidal modes couple to a head-on impact along ``z``::

    u_r = U(r) P_l(cos theta),    u_theta = V(r) dP_l(cos theta)/dtheta,
    U(r) = A h j_l'(h r) + B l(l+1) j_l(k r) / r,
    V(r) = A j_l(h r) / r + B [j_l(k r) / r + k j_l'(k r)],

with ``h = omega / c_L``, ``k = omega / c_T`` (the gradient of ``A j_l(h r) P_l`` plus the
divergence-free poloidal part). With ``L = l (l + 1)``, ``div u = -h^2 A j_l(h r) P_l`` and
``(lambda + 2 mu) h^2 = mu k^2 = omega^2``, the free-surface conditions at ``r = 1``,
``sigma_rr / mu = sigma_rtheta / mu = 0``, read (per unit ``P_l`` and ``dP_l/dtheta``)::

    [-k^2 j(h) - 4 h j'(h) + 2 L j(h)]  A + 2 L [k j'(k) - j(k)]                  B = 0
    2 [h j'(h) - j(h)]                  A + [(2 L - 2 - k^2) j(k) - 2 k j'(k)]   B = 0

``l = 0`` (breathing) keeps the first row with ``B = 0``: ``-k^2 j_0(h) - 4 h j_0'(h) = 0``,
which is Lamb's ``tan(x) / x = 1 / (1 - eta^2 x^2 / 4)`` with ``x = h``, ``eta = c_L / c_T``.
``l = 1`` has the root ``omega = 0`` (rigid translation, carried by the centre of mass); it is
excluded.

Root finding: every order is scanned on a grid in ``omega`` of the determinant with its columns
divided by their norms (a smooth function in ``[-1, 1]``, free of poles); sign changes give
brackets, and discrete local minima of ``|f|`` without sign change are refined by a bounded
minimisation that splits near-degenerate pairs. Roots are polished by
:func:`scipy.optimize.elementwise.find_root`.

Order limit: :func:`scipy.special.spherical_jn` underflows for ``l >> h r``. The scan of order
``l`` starts at ``0.8 l c_R`` (below its lowest root, ``~ (l + 1/2) c_R``, measured >= 1.02
``l c_R``); orders where the columns underflow there (``|j_l| < 1e-280``) are refused with
:class:`~restitution.errors.InputError`. 12800 modes at ``nu = 0.3`` reach ``l = 300``.

Normalisation: ``int rho |u|^2 dV = m = 4 pi / 3``, i.e.
``(2 pi) (2 / (2l + 1)) int_0^1 r^2 [U^2 + L V^2] dr = 4 pi / 3``, so that the kinetic energy is
``(m / 2) sum Qdot^2``; the radial integral is taken by Gauss-Legendre with
``int(k) + 60`` nodes (converged to round-off, see the tests). Sign: ``C = U(1) > 0``
(``S = V(1) > 0`` where ``C`` vanishes to round-off).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.optimize import brentq
from scipy.special import roots_legendre, spherical_jn

from restitution.bodies.base import SurfaceQuadrature, check_mode_selection
from restitution.bodies.roots import bracket_and_polish, null_vector
from restitution.bodies.sphere import static, surface
from restitution.errors import (
    InputError,
    RestitutionError,
    is_real,
    non_negative,
    real,
)

__all__ = [
    "SphereModes",
    "SphereModeError",
    "boundary_matrix",
    "compute_sphere_modes",
    "normalized_determinant",
    "speeds",
    "weyl_count",
]

_ALGORITHM_VERSION = 1
"""Version of the mode algorithm; part of the mode cache key."""

# Grid step of the scan in omega (c / R). Roots of one order are spaced by about pi c_T / 2 or
# more (c_T >= 0.577); closer pairs are split by the local-minimum refinement.
_SCAN_STEP = 0.04
# Smallest column norm accepted in the scan (spherical_jn underflow).
_TINY = 1e-280


class SphereModeError(RestitutionError):
    """Raised when the mode computation cannot deliver what was asked."""


def _check_nu(nu: float) -> float:
    nu = real(nu, "nu", "in (-1, 0.5)")
    if not (-1.0 < nu < 0.5):
        raise InputError(
            f"the Poisson number nu of the sphere must be in (-1, 0.5), got {nu!r}; pass nu in "
            "(-1, 0.5)"
        )
    return nu


def speeds(nu: float) -> tuple[float, float]:
    """``(c_L, c_T)`` in units ``c = sqrt(E / rho)``."""
    mu = 1.0 / (2.0 * (1.0 + nu))
    lam = nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return math.sqrt(lam + 2.0 * mu), math.sqrt(mu)


@functools.cache
def rayleigh_speed(nu: float) -> float:
    """Rayleigh speed of the three-dimensional half-space, units ``c``.

    Root ``xi = c_R / c_T`` in (0, 1) of ``(2 - xi^2)^2 = 4 sqrt(1 - xi^2) sqrt(1 - s^2 xi^2)``,
    ``s = c_T / c_L``.
    """
    c_L, c_T = speeds(nu)
    s2 = (c_T / c_L) ** 2

    def f(xi):
        root = math.sqrt(1.0 - xi**2) * math.sqrt(1.0 - s2 * xi**2)
        return ((2.0 - xi**2) ** 2 - 4.0 * root) / xi**2

    return brentq(f, 1e-4, 1.0, xtol=1e-15) * c_T


def weyl_count(omega: float, nu: float) -> float:
    """Leading estimate of the number of axisymmetric spheroidal modes below ``omega``.

    Per order ``l`` and speed ``c``, the semiclassical number of radial roots below ``omega``
    is ``(1/pi) [sqrt(K^2 - L^2) - L arccos(L / K)]`` with ``K = omega / c``, ``L = l + 1/2``;
    summed over ``l`` (integral over ``L`` from 0 to ``K``) this is ``K^2 / 8``. (Weighted by
    ``2l + 1`` it gives Weyl's ``V K^3 / (6 pi^2)`` of the ball.) The spheroidal family holds
    the P waves and one of the two S polarisations::

        N(omega) ~ (omega^2 / 8) (1 / c_L^2 + 1 / c_T^2),

    with corrections of order ``omega`` (surface terms, the Rayleigh branch).

    ``omega`` (``c / R``) must hold finite numbers ``>= 0``, ``nu`` lie in (-1, 0.5).
    """
    w = non_negative(omega, "omega", "c/R")
    _check_nu(nu)
    if not (is_real(omega) or isinstance(omega, np.ndarray)):
        omega = w  # a list
    c_L, c_T = speeds(nu)
    return omega**2 / 8.0 * (1.0 / c_L**2 + 1.0 / c_T**2)


def _bessel(l, x):
    return spherical_jn(l, x), spherical_jn(l, x, derivative=True)


def boundary_matrix(l, omega, nu: float) -> np.ndarray:
    """``[sigma_rr / mu, sigma_rtheta / mu]`` at ``r = 1`` per unit ``(A, B)`` (module docs).

    Shape ``broadcast(l, omega).shape + (2, 2)``; rows are the conditions, columns ``A, B``.
    """
    l, omega = np.broadcast_arrays(np.asarray(l), np.asarray(omega, dtype=float))
    c_L, c_T = speeds(nu)
    h, k = omega / c_L, omega / c_T
    jh, dh = _bessel(l, h)
    jk, dk = _bessel(l, k)
    L = l * (l + 1.0)
    m = np.empty(l.shape + (2, 2))
    m[..., 0, 0] = -(k**2) * jh - 4.0 * h * dh + 2.0 * L * jh
    m[..., 1, 0] = 2.0 * (h * dh - jh)
    m[..., 0, 1] = 2.0 * L * (k * dk - jk)
    m[..., 1, 1] = (2.0 * L - 2.0 - k**2) * jk - 2.0 * k * dk
    return m


def _column_norms(m):
    return np.hypot(m[..., 0, 0], m[..., 1, 0]), np.hypot(m[..., 0, 1], m[..., 1, 1])


def normalized_determinant(l, omega, nu: float) -> np.ndarray:
    """The determinant with its columns divided by their norms (``l >= 1``); for ``l = 0`` the
    breathing condition ``sigma_rr`` divided by the norm of its two terms. Values in [-1, 1].

    ``nan`` where a column underflows (orders far above ``h``).
    """
    l, omega = np.broadcast_arrays(np.asarray(l), np.asarray(omega, dtype=float))
    m = boundary_matrix(l, omega, nu)
    c0, c1 = _column_norms(m)
    with np.errstate(invalid="ignore", divide="ignore"):
        f = (m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]) / (c0 * c1)
        zero = l == 0
        if np.any(zero):
            c_L, c_T = speeds(nu)
            h, k = omega[zero] / c_L, omega[zero] / c_T
            j, d = _bessel(0, h)
            f[zero] = (-(k**2) * j - 4.0 * h * d) / np.hypot(k**2 * j, 4.0 * h * d)
        tiny = np.where(zero, np.abs(c0) < _TINY, (c0 < _TINY) | (c1 < _TINY))
    return np.where(tiny, np.nan, f)


# The lowest root of order l >= 2 is the sphere's Rayleigh (surface) wave, omega ~ (l + 1/2) c_R
# for large l, approached from above: min over l of omega / (l c_R) is 1.022-1.030 for all l up
# to omega = 50 at nu = -0.9, -0.5, 0, 0.25, 0.3, 0.45, 0.49 (measured, 120-1060 modes each).
# Scanning from 0.8 l c_R keeps a 20 % margin below it and spares the orders whose Bessel
# columns would underflow far below their first root (0.4 l c_R refused 3200 modes at nu = 0.3).
_FLOOR_FRACTION = 0.8


def _floor(l: np.ndarray, nu: float) -> np.ndarray:
    """A frequency below the lowest root of order ``l``: ``0.8 l c_R`` (at least 0.05)."""
    return np.maximum(0.05, _FLOOR_FRACTION * l * rayleigh_speed(nu))


def _roots(nu: float, omega_max: float) -> tuple[np.ndarray, np.ndarray]:
    """All roots ``(l, omega)`` with ``omega < omega_max``, unsorted."""
    orders = np.arange(0, int(omega_max / (_FLOOR_FRACTION * rayleigh_speed(nu))) + 2)
    floor = _floor(orders, nu)
    orders, floor = orders[floor < omega_max], floor[floor < omega_max]
    if orders.size == 0:  # omega_max below every order's floor: no root
        return np.zeros(0, int), np.zeros(0)
    n_pts = int(np.ceil((omega_max - floor.min()) / _SCAN_STEP)) + 2
    w = floor.min() + np.arange(n_pts) * _SCAN_STEP
    grid = np.broadcast_to(w[None, :], (orders.size, n_pts))
    ll = np.broadcast_to(orders[:, None], grid.shape)
    inside = grid >= floor[:, None]
    f = np.where(inside, normalized_determinant(ll, grid, nu), np.nan)
    bad = inside & ~np.isfinite(f)
    if np.any(bad):
        l_bad = int(ll[bad].min())
        raise InputError(
            f"order l = {l_bad} is beyond the sphere's order limit at nu = {nu} "
            "(scipy.special.spherical_jn underflows); ask for fewer modes or a lower omega_max"
        )
    rl, roots = bracket_and_polish(
        lambda lloc, x: normalized_determinant(lloc, x, nu),
        orders,
        grid,
        f,
        inside,
        lambda: SphereModeError("root polishing failed for some modes; this is a bug"),
    )
    if rl.size == 0:
        return rl.astype(int), roots
    keep = roots < omega_max
    return rl[keep].astype(int), roots[keep]


def radial_shapes(l, omega, A, B, r, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """``U(r)`` and ``V(r)`` of modes ``(l, omega, A, B)`` (shape (N,)) at radii ``r`` (shape
    (M,), in ``(0, 1]``); returns arrays of shape (N, M)."""
    c_L, c_T = speeds(nu)
    r = np.atleast_1d(np.asarray(r, dtype=float))[None, :]
    l = np.asarray(l)[:, None]
    h = (np.asarray(omega) / c_L)[:, None]
    k = (np.asarray(omega) / c_T)[:, None]
    A, B = np.asarray(A)[:, None], np.asarray(B)[:, None]
    jh, dh = _bessel(l, h * r)
    jk, dk = _bessel(l, k * r)
    U = A * h * dh + B * l * (l + 1.0) * jk / r
    V = A * jh / r + B * (jk / r + k * dk)
    return U, V


def _radial_nodes(k_max: float) -> tuple[np.ndarray, np.ndarray]:
    t, w = roots_legendre(int(k_max) + 60)
    return 0.5 * (t + 1.0), 0.5 * w


def _normalise(l, omega, A, B, nu):
    """Scale ``(A, B)`` so that ``int rho |u|^2 dV = 4 pi / 3``, sign ``C > 0``; with C, S."""
    _, c_T = speeds(nu)
    A, B = A.copy(), B.copy()
    C, S = np.empty_like(A), np.empty_like(A)
    for i in range(l.size):
        r, w = _radial_nodes(omega[i] / c_T)
        U, V = radial_shapes(l[i : i + 1], omega[i : i + 1], A[i : i + 1], B[i : i + 1], r, nu)
        L = l[i] * (l[i] + 1.0)
        integral = np.sum(w * r**2 * (U[0] ** 2 + L * V[0] ** 2))
        scale = math.sqrt((2 * l[i] + 1) / 3.0 / integral)
        U1, V1 = radial_shapes(l[i : i + 1], omega[i : i + 1], A[i : i + 1], B[i : i + 1], 1.0, nu)
        U1, V1 = float(U1[0, 0]), float(V1[0, 0]) if l[i] > 0 else 0.0
        sign = math.copysign(1.0, V1) if abs(U1) <= 1e-12 * abs(V1) else math.copysign(1.0, U1)
        A[i] *= scale * sign
        B[i] *= scale * sign
        C[i], S[i] = U1 * scale * sign, V1 * scale * sign + 0.0
    return A, B, C, S


@dataclass(frozen=True, eq=False)
class SphereModes:
    """A set of normalised axisymmetric spheroidal modes of the free sphere, sorted by frequency.

    The sphere's implementation of :class:`restitution.bodies.base.ModalBody`: its order is
    ``l``, its surface quadrature :func:`restitution.bodies.sphere.surface.sphere_quadrature`.

    Attributes
    ----------
    nu : float
        Three-dimensional Poisson number.
    l, n : numpy.ndarray of int, shape (N,)
        Angular order and root index within that order (from 0; the rigid translation of
        ``l = 1`` is not counted).
    omega : numpy.ndarray, shape (N,)
        Angular frequency, ``c / R``.
    A, B : numpy.ndarray, shape (N,)
        Amplitudes of the shapes (module docs), normalised to ``int rho |u|^2 dV = 4 pi / 3``.
    C, S : numpy.ndarray, shape (N,)
        Surface amplitudes ``U(1)`` (radial) and ``V(1)`` (the factor of ``dP_l/dtheta`` of
        ``u_theta``), ``R`` per unit ``Q``.
    """

    nu: float
    l: np.ndarray
    n: np.ndarray
    omega: np.ndarray
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    S: np.ndarray

    geometry: ClassVar[str] = "sphere"

    def __len__(self) -> int:
        return int(self.omega.size)

    @property
    def mass(self) -> float:
        """Sphere mass ``m = 4 pi / 3`` in units ``rho R^3``."""
        return 4.0 * math.pi / 3.0

    @property
    def order(self) -> np.ndarray:
        """Angular order ``l`` of every mode."""
        return self.l

    def take(self, index) -> SphereModes:
        """Subset of modes at ``index`` (integer or boolean array), in the order given."""
        idx = np.arange(len(self))[index]
        return SphereModes(nu=self.nu, **{f: getattr(self, f)[idx] for f in _ARRAY_FIELDS})

    def lowest(self, count: int) -> SphereModes:
        """The ``count`` lowest-frequency modes."""
        if count > len(self):
            raise SphereModeError(f"asked for {count} modes but the set holds only {len(self)}")
        return self.take(np.arange(count))

    def shapes(self, r) -> tuple[np.ndarray, np.ndarray]:
        """Radial shapes ``U(r)``, ``V(r)``, shape (N, M), at radii ``r`` in ``(0, 1]``."""
        return radial_shapes(self.l, self.omega, self.A, self.B, r, self.nu)

    def contact_nodes(self, s: float) -> int:
        """Surface nodes for a contact zone of depth ``1 / s``
        (:func:`restitution.bodies.sphere.surface.default_n_nodes`)."""
        return surface.default_n_nodes(float(s), int(self.l.max()))

    def surface_quadrature(self, n_nodes: int) -> SurfaceQuadrature:
        """Gauss-Legendre in ``cos(theta)`` on the near hemisphere, tangential columns scaled
        to ``|basis| <= 1`` with ``S`` compensating
        (:func:`restitution.bodies.sphere.surface.sphere_quadrature`)."""
        return surface.sphere_quadrature(self, n_nodes)

    def residual_flexibility(self, quad: SurfaceQuadrature, count: int) -> np.ndarray:
        """The static flexibility of the modes above this set between the first ``count``
        nodes of the surface quadrature ``quad``, shape (count, count)
        (:func:`restitution.bodies.sphere.static.residual_flexibility`)."""
        return static.residual_flexibility(self, quad.nodes, count)

    def surface_matrix(self, nodes: np.ndarray) -> np.ndarray:
        """``u_r cos(theta) - u_theta sin(theta)`` per unit ``Q_k`` at ``nodes``, shape (M, N)."""
        return surface.dense_surface_matrix(self, nodes)

    def contact_time_estimate(self, v):
        """Hertz contact time ``2.9433 delta_max / v`` against a rigid wall, ``R / c``."""
        return surface.contact_time_estimate(v, self.nu)

    def depth_transform(self, s):
        """``int exp(-s (1 - cos theta)) dA`` over the near hemisphere, ``R^2``
        (:func:`restitution.bodies.sphere.surface.depth_transform`)."""
        return surface.depth_transform(s)

    def as_records(self) -> list[dict]:
        """One dict per mode with keys ``order`` (the angular order ``l``: the one name every
        body gives it), ``l, n, omega, A, B, C, S``."""
        return [
            {
                "order": int(self.order[i]),
                "l": int(self.l[i]),
                "n": int(self.n[i]),
                "omega": float(self.omega[i]),
                "A": float(self.A[i]),
                "B": float(self.B[i]),
                "C": float(self.C[i]),
                "S": float(self.S[i]),
            }
            for i in range(len(self))
        ]


_ARRAY_FIELDS = ("l", "n", "omega", "A", "B", "C", "S")


def _build(l: np.ndarray, omega: np.ndarray, nu: float) -> SphereModes:
    order = np.lexsort((omega, l))
    l, omega = l[order], omega[order]
    first = np.r_[True, l[1:] != l[:-1]]
    start = np.maximum.accumulate(np.where(first, np.arange(l.size), 0))
    n = np.arange(l.size) - start
    A, B = np.ones_like(omega), np.zeros_like(omega)
    p = l > 0
    if np.any(p):
        A[p], B[p] = null_vector(boundary_matrix(l[p], omega[p], nu))
    A, B, C, S = _normalise(l, omega, A, B, nu)
    full = SphereModes(nu=nu, l=l, n=n, omega=omega, A=A, B=B, C=C, S=S)
    return full.take(np.argsort(omega, kind="stable"))


def compute_sphere_modes(
    nu: float, count: int | None = None, omega_max: float | None = None
) -> SphereModes:
    """Compute the axisymmetric spheroidal eigenmodes of the free sphere (no caching).

    Parameters
    ----------
    nu : float
        Three-dimensional Poisson number in (-1, 0.5).
    count : int, optional
        Return the ``count`` lowest-frequency modes.
    omega_max : float, optional
        Return all modes with ``omega < omega_max`` (``c / R``).

    Exactly one of ``count`` and ``omega_max`` must be given.
    """
    nu = _check_nu(nu)
    check_mode_selection(count, omega_max)
    if omega_max is not None:
        return _build(*_roots(nu, float(omega_max)), nu)
    c_L, c_T = speeds(nu)
    w_max = math.sqrt(8.0 * count / (1.0 / c_L**2 + 1.0 / c_T**2)) + 2.0
    for _ in range(30):
        l, w = _roots(nu, w_max)
        if w.size > count:
            keep = np.argsort(w, kind="stable")[:count]
            return _build(l[keep], w[keep], nu)
        w_max *= 1.2
    raise SphereModeError(f"could not find {count} modes; this is a bug")
