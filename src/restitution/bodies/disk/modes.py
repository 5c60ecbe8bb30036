"""Symmetric in-plane eigenmodes of the free elastic disk (paper section 2).

Units: ``E = rho = R = 1`` (two-dimensional constants), ``omega`` in ``c / R``.

The symmetric family has ``u_r = U_r(r) cos(n phi)`` and ``u_phi = U_phi(r) sin(n phi)``:

* ``n = 0``: the breathing modes, roots of eq. (20). The torsional ``n = 0`` modes (eq. 21) have
  ``u_phi ~ sin(0) = 0`` in this family and are excluded (ERRATA, conventions).
* ``n >= 1``: roots of the determinant of the edge conditions (22)-(23). The root
  ``omega = 0`` of ``n = 1`` is the rigid translation, carried by the centre of mass; excluded.

Root finding (see :func:`_roots_for_orders`): each order ``n`` is scanned on a fine grid of a
column-normalised determinant; sign changes give brackets, and discrete local minima of ``|f|``
without a sign change are refined by a bounded minimisation, which splits near-degenerate
pairs that fall into one grid cell. Roots are polished with Chandrupatla's method
(:func:`scipy.optimize.elementwise.find_root`).

Normalisation (eq. 26, ERRATA): ``int_0^1 r (U_r^2 + U_phi^2) dr = 1`` for ``n >= 1`` and
``int_0^1 r U_r^2 dr = 1/2`` for ``n = 0``, so the kinetic energy is ``(m/2) sum Qdot^2``.

Sign convention: every mode is scaled so that its edge radial amplitude ``C = U_r(1)`` is
positive (``S = U_phi(1)`` positive where ``C`` vanishes to round-off).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.optimize import brentq
from scipy.special import jv

from restitution.bodies.base import SurfaceQuadrature, check_mode_selection
from restitution.bodies.disk import contact, static, surface
from restitution.bodies.disk.bessel_ratio import scaled_pairs
from restitution.bodies.disk.frequency_equation import (
    bessel_and_derivative,
    breathing_condition,
    edge_matrix_from_pairs,
    normalized_determinant,
    normalized_determinant_grid,
    wavenumbers,
)
from restitution.bodies.material import Material, require_reduced
from restitution.bodies.roots import bracket_and_polish, null_vector
from restitution.errors import (
    InputError,
    RestitutionError,
    is_real,
    non_negative,
    real,
)

__all__ = ["ModeSet", "compute_modes", "weyl_count", "ModeError"]

# Grid step of the scan in omega (units c/R). Roots of one order n are spaced by about
# pi * c_s (~1.9 at nu = 0.33); pairs closer than the step are split by the local-minimum
# refinement. Steps 0.04, 0.06 and 0.08 give identical roots (to 2e-11) below omega = 62 for
# nu = 0.33, 0.9 and -0.5.
_SCAN_STEP = 0.06
# Orders are processed in blocks (one Bessel recurrence per frequency serves a block); the
# scan stops after a block without any root.
_BLOCK = 128
_ALGORITHM_VERSION = 3


class ModeError(RestitutionError):
    """Raised when the mode computation cannot deliver what was asked."""


@dataclass(frozen=True, eq=False)
class ModeSet:
    """A set of normalised symmetric eigenmodes of the disk, sorted by frequency.

    The disk's implementation of the body protocol
    (:class:`restitution.bodies.base.ModalBody`): its order is ``n``, its surface quadrature
    the edge quadrature of :mod:`restitution.bodies.disk.surface`, its contact scales those of
    eq. (61) (:mod:`restitution.bodies.disk.contact`).

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number.
    n, l : numpy.ndarray of int, shape (N,)
        Number of directional nodes and root index within that ``n`` (from 0).
    omega : numpy.ndarray, shape (N,)
        Angular frequency in ``c / R``.
    kappa, kappa_p : numpy.ndarray, shape (N,)
        Wavenumbers ``kappa`` and ``kappa'`` of eq. (18), in ``1 / R``.
    A, B : numpy.ndarray, shape (N,)
        Amplitudes of eq. (19), normalised by eq. (26).
    C, S : numpy.ndarray, shape (N,)
        Edge amplitudes ``U_r(1)`` and ``U_phi(1)`` of eq. (28), in ``R`` per unit ``Q``.
    """

    nu: float
    n: np.ndarray
    l: np.ndarray
    omega: np.ndarray
    kappa: np.ndarray
    kappa_p: np.ndarray
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    S: np.ndarray

    geometry: ClassVar[str] = "disk"

    def __len__(self) -> int:
        return int(self.omega.size)

    @property
    def mass(self) -> float:
        """Disk mass ``m = pi`` in units ``rho R^2``."""
        return math.pi

    @property
    def order(self) -> np.ndarray:
        """Angular order of every mode: the number ``n`` of directional nodes."""
        return self.n

    def contact_nodes(self, s: float) -> int:
        """Edge nodes on ``[0, pi/2]`` for a contact zone of depth ``1 / s``
        (:func:`restitution.bodies.disk.surface.default_n_phi`)."""
        return surface.default_n_phi(float(s), int(self.n.max()))

    def surface_quadrature(self, n_nodes: int) -> SurfaceQuadrature:
        """The edge quadrature with ``n_nodes`` nodes on ``[0, pi/2]`` (eqs. 40-41)."""
        return surface.edge_quadrature(self, n_nodes)

    def surface_matrix(self, nodes: np.ndarray) -> np.ndarray:
        """``g_k(phi_j)`` of eq. (40), shape (M, N)."""
        return surface.dense_edge_matrix(self, nodes)

    def contact_time_estimate(self, v):
        """Quasistatic contact time ``pi sqrt(ln(4/v))`` of eq. (61), ``R / c``."""
        return contact.contact_time_estimate(v)

    def depth_transform(self, s):
        """``int exp(-s (1 - cos phi)) dphi`` over the edge, ``R``
        (:func:`restitution.bodies.disk.surface.depth_transform`)."""
        return surface.depth_transform(s)

    def residual_flexibility(self, quad: SurfaceQuadrature, count: int) -> np.ndarray:
        """The static flexibility of the modes above this set on the first ``count`` nodes of
        the edge quadrature ``quad``, shape (count, count)
        (:func:`restitution.bodies.disk.static.residual_flexibility`)."""
        return static.residual_flexibility(self, count, float(quad.nodes[1] - quad.nodes[0]))

    def take(self, index: np.ndarray) -> ModeSet:
        """Subset of modes at ``index`` (integer or boolean array), in the order given."""
        idx = np.arange(len(self))[index]
        return ModeSet(
            nu=self.nu,
            **{f: getattr(self, f)[idx] for f in _ARRAY_FIELDS},
        )

    def lowest(self, count: int) -> ModeSet:
        """The ``count`` lowest-frequency modes."""
        if count > len(self):
            raise ModeError(f"asked for {count} modes but the set holds only {len(self)}")
        return self.take(np.arange(count))

    def shapes(self, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Radial shape functions ``U_r(r)`` and ``U_phi(r)``.

        Uses ``J_n(x)/x = (J_{n-1} + J_{n+1})/(2n)`` and ``J_n' = (J_{n-1} - J_{n+1})/2`` so
        that the shapes are finite and exact at ``r = 0``.

        Parameters
        ----------
        r : array_like, shape (M,)
            Radii in units of ``R``, in ``[0, 1]``.

        Returns
        -------
        U_r, U_phi : numpy.ndarray, shape (N, M)
        """
        r = np.atleast_1d(np.asarray(r, dtype=float))
        n = self.n[:, None]
        x = self.kappa[:, None] * r[None, :]
        y = self.kappa_p[:, None] * r[None, :]
        jxm, jxp = jv(n - 1, x), jv(n + 1, x)
        jym, jyp = jv(n - 1, y), jv(n + 1, y)
        a = (self.A * self.kappa / 2.0)[:, None]
        b = (self.B * self.kappa_p / 2.0)[:, None]
        U_r = a * (jxm - jxp) + b * (jym + jyp)
        U_phi = -(a * (jxm + jxp) + b * (jym - jyp))
        return U_r, U_phi

    def as_records(self) -> list[dict]:
        """One dict per mode with keys ``order`` (the angular order ``n``: the one name every
        body gives it), ``n, l, omega, kappa, kappa_p, A, B, C, S``."""
        return [
            {
                "order": int(self.order[i]),
                "n": int(self.n[i]),
                "l": int(self.l[i]),
                "omega": float(self.omega[i]),
                "kappa": float(self.kappa[i]),
                "kappa_p": float(self.kappa_p[i]),
                "A": float(self.A[i]),
                "B": float(self.B[i]),
                "C": float(self.C[i]),
                "S": float(self.S[i]),
            }
            for i in range(len(self))
        ]


_ARRAY_FIELDS = ("n", "l", "omega", "kappa", "kappa_p", "A", "B", "C", "S")


def weyl_count(omega: float, nu: float) -> float:
    """Leading Weyl estimate of the number of symmetric modes below ``omega``.

    Half of the in-plane count ``(area / 4 pi) omega^2 (1/c_p^2 + 1/c_s^2)`` for the unit disk,
    since the symmetric and antisymmetric families share the spectrum (except ``n = 0``).

    Parameters
    ----------
    omega : float or array_like
        Frequency, ``c / R``, finite and ``>= 0``.
    nu : float
        Two-dimensional Poisson number, in (-1, 1).
    """
    omega = _check_weyl(omega, nu, (-1.0, 1.0))
    return omega**2 / 8.0 * ((1.0 - nu**2) + 2.0 * (1.0 + nu))


def _check_weyl(omega, nu, nu_range: tuple[float, float]):
    """``omega`` (a list as an array) if it holds finite numbers ``>= 0`` and ``nu`` is a number
    in the open interval ``nu_range``, else a one-line :class:`InputError`."""
    w = non_negative(omega, "omega", "c/R")
    lo, hi = nu_range
    allowed = f"in ({lo:g}, {hi:g})"
    if not lo < real(nu, "nu", allowed) < hi:
        raise InputError(f"nu must lie {allowed}, got {nu!r}; pass a Poisson number {allowed}")
    return omega if is_real(omega) or isinstance(omega, np.ndarray) else w


@functools.cache
def rayleigh_speed(nu: float) -> float:
    """Rayleigh wave speed ``c_R`` of the two-dimensional solid, units ``c``.

    Root ``xi = c_R / c_s`` in (0, 1) of ``(2 - xi^2)^2 = 4 sqrt(1 - xi^2) sqrt(1 - s^2 xi^2)``
    with ``s^2 = (c_s / c_p)^2 = (1 - nu) / 2`` for the plane-stress constants of eq. (6).
    ``c_R -> 0`` as ``nu -> -1``.
    """
    s2 = (1.0 - nu) / 2.0

    def f(xi):
        # Divided by xi^2: xi = 0 is a trivial root, f ~ -2 (1 - s^2) xi^2 near it.
        root = math.sqrt(1.0 - xi**2) * math.sqrt(1.0 - s2 * xi**2)
        return ((2.0 - xi**2) ** 2 - 4.0 * root) / xi**2

    c_s = 1.0 / math.sqrt(2.0 * (1.0 + nu))
    return brentq(f, 1e-4, 1.0, xtol=1e-15) * c_s


def _omega_floor(n: np.ndarray, nu: float) -> np.ndarray:
    """A frequency below the lowest root of order ``n``: ``0.4 n c_R``.

    The lowest root of order ``n`` approaches ``n c_R`` (Rayleigh waves around the rim). The
    factor 0.4 is a wide margin (the earlier bound ``0.4 n c_s`` lies above this one for every
    ``nu`` and was checked against finite-element counts); unlike a bound in ``c_s`` it stays
    below the roots when ``c_R << c_s`` (``nu -> -1``). The scan's Bessel pairs do not
    underflow, so a low floor costs only grid points.
    """
    return np.maximum(0.05, 0.4 * n * rayleigh_speed(nu))


def _scan_function(n: np.ndarray, omega: np.ndarray, nu: float) -> np.ndarray:
    n, omega = np.broadcast_arrays(n, omega)
    f = normalized_determinant(np.maximum(n, 1), omega, nu)
    zero = n == 0
    if np.any(zero):
        f[zero] = breathing_condition(omega[zero], nu)
    return f


def _roots_for_orders(orders: np.ndarray, nu: float, omega_max: float) -> tuple[np.ndarray, ...]:
    """All symmetric roots below ``omega_max`` for the consecutive orders ``orders``.

    Returns arrays ``(n, omega)`` of the roots found, unsorted.
    """
    floor = _omega_floor(orders, nu)
    n_pts = int(np.ceil((omega_max - floor.min()) / _SCAN_STEP)) + 2
    w = floor.min() + np.arange(n_pts) * _SCAN_STEP
    grid = np.broadcast_to(w[None, :], (orders.size, n_pts))
    nn = np.broadcast_to(orders[:, None], grid.shape)
    f = np.empty(grid.shape)
    positive = orders >= 1
    if np.any(positive):
        lo = int(orders[positive].min())
        f[positive] = normalized_determinant_grid(lo, int(orders.max()), w, nu)
    if not np.all(positive):
        f[~positive] = breathing_condition(w, nu)[None, :]
    inside = grid >= floor[:, None]
    if not np.all(np.isfinite(f[inside])):
        bad = np.unique(nn[~np.isfinite(f) & inside])
        raise ModeError(
            f"the frequency equation is not finite for n = {bad[:5].tolist()}; this is a bug, "
            "please report it with nu and the mode count"
        )
    return bracket_and_polish(
        lambda nloc, w: _scan_function(nloc, w, nu),
        orders,
        grid,
        f,
        inside,
        lambda: ModeError("root polishing failed for some modes; this is a bug, please report it"),
    )


def _all_roots(nu: float, omega_max: float) -> tuple[np.ndarray, np.ndarray]:
    ns, ws = [], []
    start = 0
    while True:
        orders = np.arange(start, start + _BLOCK)
        orders = orders[_omega_floor(orders, nu) < omega_max]
        if orders.size == 0:
            break
        rn, rw = _roots_for_orders(orders, nu, omega_max)
        ns.append(rn)
        ws.append(rw)
        if rn.size == 0:
            break
        start += _BLOCK
    if not ns:  # no order has a root below omega_max
        return np.zeros(0, int), np.zeros(0)
    n = np.concatenate(ns).astype(int)
    w = np.concatenate(ws)
    keep = w < omega_max
    return n[keep], w[keep]


def _lommel_square(v, x, J, dJ):
    """``int_0^1 r J_v(x r)^2 dr = [J_v'(x)^2 + (1 - v^2/x^2) J_v(x)^2] / 2``."""
    return 0.5 * (dJ**2 + (1.0 - v**2 / x**2) * J**2)


def _lommel_cross(a, b, Ja, dJa, Jb, dJb):
    """``int_0^1 r J_v(a r) J_v(b r) dr = [b J_v(a) J_v'(b) - a J_v(b) J_v'(a)] / (a^2 - b^2)``."""
    return (b * Ja * dJb - a * Jb * dJa) / (a**2 - b**2)


def _side_bessel(n, x, jm, jn):
    """``(J_{n-1}, J_{n-1}', J_{n+1}, J_{n+1}')`` at ``x`` in the scale of the unit pair."""
    j_lo2 = 2.0 * (n - 1) / x * jm - jn  # J_{n-2}
    j_hi = 2.0 * n / x * jn - jm  # J_{n+1}
    return jm, j_lo2 - (n - 1) / x * jm, j_hi, jn - (n + 1) / x * j_hi


def _flexural(n, kappa, kappa_p, nu):
    """Normalised ``(A, B, C, S)`` for ``n >= 1``, computed from unit Bessel pairs.

    With ``s = hypot(J_{n-1}, J_n)`` at each wavenumber, the shapes, the edge conditions and
    the normalisation integrals are bilinear in the scales, so ``(A s, B s')`` are solved and
    normalised scale-free; ``A`` and ``B`` themselves overflow to ``inf`` where ``s``
    underflows (orders far above ``kappa``), while ``C`` and ``S`` stay exact.

    With ``J_pm = J_{n+-1}(kappa r)``, ``Y_pm = J_{n+-1}(kappa' r)``, ``a = A kappa / 2`` and
    ``b = B kappa' / 2``::

        U_r^2 + U_phi^2 = 2 a^2 (J_-^2 + J_+^2) + 2 b^2 (Y_-^2 + Y_+^2) + 4 a b (J_- Y_- - J_+ Y_+)

    and each term is a Lommel integral. ``kappa' > kappa`` always, so no denominator vanishes.
    """
    jm_k, jn_k, ls_k = scaled_pairs(n, kappa)
    jm_q, jn_q, ls_q = scaled_pairs(n, kappa_p)
    m = edge_matrix_from_pairs(n, kappa, kappa_p, jm_k, jn_k, jm_q, jn_q, nu)
    A, B = null_vector(m)
    xd_k = kappa * jm_k - n * jn_k  # kappa J_n'(kappa)
    xd_q = kappa_p * jm_q - n * jn_q
    U1 = A * xd_k + n * B * jn_q
    V1 = -(n * A * jn_k + B * xd_q)
    Jm_k, dJm_k, Jp_k, dJp_k = _side_bessel(n, kappa, jm_k, jn_k)
    Jm_q, dJm_q, Jp_q, dJp_q = _side_bessel(n, kappa_p, jm_q, jn_q)
    a = A * kappa / 2.0
    b = B * kappa_p / 2.0
    norm = (
        2.0
        * a**2
        * (_lommel_square(n - 1, kappa, Jm_k, dJm_k) + _lommel_square(n + 1, kappa, Jp_k, dJp_k))
        + 2.0
        * b**2
        * (
            _lommel_square(n - 1, kappa_p, Jm_q, dJm_q)
            + _lommel_square(n + 1, kappa_p, Jp_q, dJp_q)
        )
        + 4.0
        * a
        * b
        * (
            _lommel_cross(kappa, kappa_p, Jm_k, dJm_k, Jm_q, dJm_q)
            - _lommel_cross(kappa, kappa_p, Jp_k, dJp_k, Jp_q, dJp_q)
        )
    )
    scale = 1.0 / np.sqrt(norm)
    tiny = np.abs(U1) <= 1e-12 * np.abs(V1)
    sign = np.where(tiny, np.sign(V1), np.sign(U1))
    scale = scale * np.where(sign == 0, 1.0, sign)
    with np.errstate(over="ignore"):
        A_abs = A * scale * np.exp(-ls_k)
        B_abs = B * scale * np.exp(-ls_q)
    return A_abs, B_abs, U1 * scale, V1 * scale


def _breathing(kappa):
    """Normalised ``(A, B, C, S)`` of the breathing modes (``n = 0``, eq. 20).

    ``U_r = A dJ_0(kappa r)/dr = -A kappa J_1(kappa r)``, ``U_phi = 0``, normalised to
    ``int_0^1 r U_r^2 dr = 1/2`` (ERRATA) and signed so that ``C = U_r(1) > 0``.
    """
    J1, dJ1 = bessel_and_derivative(np.ones_like(kappa), kappa)
    norm = kappa**2 * _lommel_square(1.0, kappa, J1, dJ1)
    U1 = -kappa * J1
    A = np.sign(U1) * np.sqrt(0.5 / norm)
    return A, np.zeros_like(kappa), U1 * A, np.zeros_like(kappa)


def _build(n: np.ndarray, omega: np.ndarray, nu: float) -> ModeSet:
    order = np.lexsort((omega, n))
    n, omega = n[order], omega[order]
    # l counts roots within each order n, from 0.
    first = np.r_[True, n[1:] != n[:-1]]
    group_start = np.maximum.accumulate(np.where(first, np.arange(n.size), 0))
    l = np.arange(n.size) - group_start
    kappa, kappa_p = wavenumbers(omega, nu)
    A, B, C, S = (np.empty_like(omega) for _ in range(4))
    b = n == 0
    if np.any(b):
        A[b], B[b], C[b], S[b] = _breathing(kappa[b])
    if not np.all(b):
        p = ~b
        A[p], B[p], C[p], S[p] = _flexural(n[p], kappa[p], kappa_p[p], nu)
    if not (np.all(np.isfinite(C)) and np.all(np.isfinite(S))):
        # Issue 47: at nu = -0.9999 the normalisation's norm came out negative (round-off in
        # the near-cancelling terms as nu -> -1) and amplitudes were NaN, served as "ok".
        raise ModeError(
            f"the disk's mode normalisation fails at nu = {nu:g} (non-finite amplitudes): the "
            "frequency equation loses its precision as nu approaches -1; use nu > -0.999"
        )
    full = ModeSet(nu=nu, n=n, l=l, omega=omega, kappa=kappa, kappa_p=kappa_p, A=A, B=B, C=C, S=S)
    return full.take(np.argsort(omega, kind="stable"))


def _as_nu(material: Material | float) -> float:
    return require_reduced(material, "the modal path")


def compute_modes(
    material: Material | float,
    count: int | None = None,
    omega_max: float | None = None,
) -> ModeSet:
    """Compute the symmetric eigenmodes of the free disk (no caching).

    Parameters
    ----------
    material : Material or float
        The material, or its two-dimensional Poisson number.
    count : int, optional
        Return the ``count`` lowest-frequency modes.
    omega_max : float, optional
        Return all modes with ``omega < omega_max`` (in ``c / R``).

    Exactly one of ``count`` and ``omega_max`` must be given.

    Returns
    -------
    ModeSet
        Sorted by frequency; the rigid translation and the torsional ``n = 0`` family excluded.
    """
    nu = _as_nu(material)
    check_mode_selection(count, omega_max)
    if omega_max is not None:
        n, w = _all_roots(nu, float(omega_max))
        return _build(n, w, nu)
    # Invert Weyl's law for a first frequency bound, then widen until enough roots exist.
    # (The perimeter correction to Weyl's law is positive, so this bound is usually enough.)
    w_max = math.sqrt(8.0 * count / ((1.0 - nu**2) + 2.0 * (1.0 + nu))) + 2.0
    for _ in range(20):
        n, w = _all_roots(nu, w_max)
        if w.size > count:
            # Cut strictly between the count-th and (count+1)-th frequency.
            order = np.argsort(w, kind="stable")[:count]
            return _build(n[order], w[order], nu)
        w_max *= 1.2
    raise ModeError(f"could not find {count} modes; this is a bug, please report it")
