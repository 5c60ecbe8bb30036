"""How much more (or less) a plastic contact's pulse drives a sphere's vibrations than Hertz's
pulse at the same speed, as a function of the contact's duration over the sphere's transit time
and of its impact speed over its yield speed: the wave part of the LAMMPS plugin's plastic law
per contact (docs/lammps-plugin.md, "A law per contact").

Units: SI at the edge (Pa, m, kg, m/s); inside, a sphere's reduced units (``E = rho = R = 1``,
frequencies in ``c / R``); the ratio, ``x`` and ``u`` are dimensionless.

The package's plastic law (:mod:`restitution.laws.plastic`) takes the elastic law's wave loss
at the impact speed and scales it by the ratio of Rayleigh's estimates of the actual pulse
(Thornton's force, :mod:`restitution.quasistatic.plastic_collision`) and of Hertz's pulse at
that speed, summed over the modes the pulse drives. Thornton's contact has one scale besides
Hertz's, the yield speed of the contact's own constants (:func:`yield_speed`)::

    v_y = sqrt((pi^5 / 30) p_y^5 R*^3 / (E*^4 m*)),                                         (1)

and in Hertz's scaled variables (compression over Hertz's ``delta_max``, time over Hertz's
``t_c``, both at the impact speed ``w``) the pulse depends on ``u = w / v_y`` alone: the yield
compression is ``(v_y / w)^(4/5)`` of ``delta_max``, the plastic branch and the unloading radius
follow from it. So the drive of a mode of frequency ``omega`` is ``I = m* w J_p(omega t_c; u)``
(``J_p = J`` of :mod:`~restitution.laws.exports.sphere_loss` for ``u <= 1``), and a sphere of
mass ``m``, radius ``R`` and bar speed ``c`` keeps::

    L = (m* / m) H(x; u),   H(x; u) = sum_k C_k^2 |J_p(Omega_k x; u)|^2,   x = t_c c / R,

with Hertz's ``G(x) = H(x; 1)``. The plugin reads the ratio ``r(x, u) = H(x; u) / G(x)`` (1 for
``u <= 1``): two spheres lose ``(m*/m1) G1(x1) r1(x1, u) + (m*/m2) G2(x2) r2(x2, u)`` (the ratio
of the pair's Rayleigh sums is that sum over ``(m*/m1) G1 + (m*/m2) G2``), a sphere on the wall
its elastic law's loss times ``r(x, u)``.

*Tabulated* (:func:`plastic_waves`): ``r`` and ``dr/dx`` (exact: the mode sums' derivatives) at
``x`` :data:`KNOT_SPACING` apart from the route's ``x_lo`` to :data:`X_TOP`, at :data:`U_KNOTS`
values of ``u`` :data:`ETA_STEP` apart in ``eta = arccosh(u)`` from 1 to :data:`U_TOP`. Between,
cubic Hermite in ``x`` at the four nearest ``u`` knots, then the cubic through those four in ``eta``
(:meth:`PlasticWaves.__call__`). ``J_p`` of each ``u`` is the spectrum of the pulse (DOP853 at
``rtol = 1e-10``, Gauss-Legendre panels, :meth:`~restitution.quasistatic.plastic_collision.
PulseCollision.spectrum`) on a grid :data:`DRIVE_STEP` apart in ``s = omega t_c``, interpolated by
a cubic spline. Outside (``x > X_TOP`` or ``u > U_TOP`` for a contact that yields) there is no
value: the plugin stops the run.
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
import os
import tempfile
import zipfile
from dataclasses import dataclass

import numpy as np

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT

__all__ = [
    "DRIVE_STEP",
    "ETA_STEP",
    "KNOT_SPACING",
    "U_KNOTS",
    "U_TOP",
    "X_TOP",
    "PlasticWaves",
    "exact_ratio",
    "plastic_waves",
    "yield_speed",
]

ETA_STEP = 0.1
"""Spacing of the ``u`` knots in ``eta = arccosh(u)``: ``sqrt(2 (u - 1))`` near the yield speed
(the plastic loading lasts ``~ sqrt(u - 1)`` of ``t_c``: the ratio is not smooth in ``u``
there), ``ln(2 u)`` far above it. ``r`` oscillates in ``u`` at fixed ``x`` (the pulse's length
moves the lowest modes' phases: from 2.9 to 0.70 and back to 1.1 over ``eta`` 4.0 ... 4.6 at
``x = 26``), so the step sets the error. Measured against :func:`exact_ratio` at random points
(``benchmarks/bench_plastic_contact.py``): 0.1 in ``eta`` missed ``r`` by up to 9.7e-3 (median
1.7e-4, 24 points where ``u x^5 <= 1e9``); a first table 0.25 apart in ``ln u`` (``x <= 40``)
had missed by up to 0.61 (40 random points anywhere in it)."""

U_KNOTS = 78
"""Knots in ``u``: ``u = cosh(j ETA_STEP)``, ``j = 0 ... 77``."""

U_TOP = math.cosh(ETA_STEP * (U_KNOTS - 1))
"""The fastest contact over its yield speed served: ``cosh(7.7) = 1105`` (steel of yield stress
1 GPa on the wall: ``v_y = 0.0345`` m/s, so 38 m/s, beyond the route's reach)."""

KNOT_SPACING = 0.05
"""Spacing in ``x`` of the knots (the sphere's ``G`` is tabulated on the same spacing)."""

X_TOP = 80.0
"""The slowest contact served once it yields (``x``; ``x`` grows like ``w^(-1/5)``): steel of yield
stress 1 GPa yields from ``x = 53`` on the wall (0.0345 m/s, any radius) and from 61 for the
smaller of radii 1 and 2 mm (0.0798 m/s), 0.1 m/s gives 43 and 59."""

DRIVE_STEP = 0.1
"""Spacing in ``s = omega t_c`` of the spectrum ``J_p`` is splined from."""

_SPEED = 1e-4
"""The reduced speed the pulses are computed at (any: only ``u`` matters)."""


def yield_speed(p_y, estar, rstar, mstar):
    """Thornton's yield speed (m/s), eq. (1), of a contact of limiting pressure ``p_y`` (Pa),
    modulus ``estar`` (Pa), reduced radius ``rstar`` (m) and mass ``mstar`` (kg).

    >>> round(yield_speed(1.6128e9, 210e9 / 0.91, 1e-3, 4 / 3 * math.pi * 1e-9 * 7850), 5)
    0.03455
    """
    return math.sqrt(math.pi**5 / 30.0 * p_y**5 * rstar**3 / (estar**4 * mstar))


def _modes(nu: float):
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    return get_modes(float(nu), LOW_SPEED_MODES, geometry=SPHERE.geometry)


def _pulse(u: float):
    """The plastic pulse at ``u = w / v_y`` in a sphere's reduced units, with Hertz's contact
    time ``t_c`` at that speed: ``(pulse, t_c)``."""
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law
    from restitution.quasistatic.plastic_collision import pulse_collision

    law, v = sphere_contact_law(0.3), _SPEED  # any nu: the pulse's shape is u's
    d = (1.25 * SPHERE_MASS * v * v / law.K) ** 0.4
    # p_y from eq. (1) for v_y = v / u (reduced: E* and R of the law, the sphere's mass)
    p_y = ((v / u) ** 2 * 30.0 / math.pi**5 * law.E_star**4 * SPHERE_MASS / law.R**3) ** 0.2
    p_y = None if u <= 1.0 else p_y
    return pulse_collision(law, v, p_y=p_y, mass=SPHERE_MASS), CONTACT_TIME_CONSTANT * d / v


def _uniform_spectrum(pulse, omega0: float, step: float, n: int) -> np.ndarray:
    """``F(omega0 + j step)``, ``j < n``, of ``pulse`` (shape (n,), complex): the quadrature of
    :meth:`~restitution.quasistatic.plastic_collision.PulseCollision.spectrum`, the phases
    ``e^{-i (a B + b) step t}`` split into two factors so that one matrix product sums them."""
    top = omega0 + step * (n - 1)
    t, w = pulse.quadrature(top)
    wp = w * pulse.force(t)
    block = 128
    rows = -(-n // block)
    inner = np.exp(-1j * step * np.outer(np.arange(block), t))
    outer = wp * np.exp(-1j * np.outer(omega0 + block * step * np.arange(rows), t))
    return (outer @ inner.T).ravel()[:n]


def _drive(u: float, s_top: float):
    """``J_p`` of ``u`` as a cubic spline of ``s = omega t_c`` on ``[8, s_top]``, values
    ``(Re, Im)``."""
    from scipy.interpolate import CubicSpline

    from restitution.quasistatic.hertz_sphere import SPHERE_MASS

    pulse, tc = _pulse(u)
    n = int(math.ceil((s_top - 8.0) / DRIVE_STEP)) + 3
    s = 8.0 + DRIVE_STEP * np.arange(n)
    j = _uniform_spectrum(pulse, 8.0 / tc, DRIVE_STEP / tc, n) / (SPHERE_MASS * _SPEED)
    return CubicSpline(s, np.stack([j.real, j.imag], axis=1))


def _ratio_at_knots(nu: float, u: float, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(r, dr/dx)`` of ``u`` at ``x`` from the splined drive, summed over the modes."""
    from restitution.laws.exports.sphere_loss import loss_curve

    modes = _modes(nu)
    c2, om = np.asarray(modes.C, dtype=float) ** 2, np.asarray(modes.omega, dtype=float)
    spline = _drive(u, float(x.max() * om.max()) + 1.0)
    h, dh = np.empty(x.shape), np.empty(x.shape)
    for i in range(0, x.size, 128):
        s = np.outer(x[i : i + 128], om)
        j, dj = spline(s), spline(s, 1)
        h[i : i + 128] = (j[..., 0] ** 2 + j[..., 1] ** 2) @ c2
        dh[i : i + 128] = 2.0 * ((j[..., 0] * dj[..., 0] + j[..., 1] * dj[..., 1]) @ (c2 * om))
    g, dg = loss_curve(nu, x)
    return h / g, (dh * g - h * dg) / (g * g)


def exact_ratio(nu: float, x: float, u: float) -> float:
    """``r(x, u)`` as the package's plastic law computes it (:func:`restitution.laws.plastic.
    _ratios`): the spectra of the plastic and of Hertz's pulse at the modes' frequencies, their
    Rayleigh sums divided; what the knots are checked against."""
    from restitution.quasistatic.plastic_collision import pulse_collision

    if u <= 1.0:
        return 1.0
    modes = _modes(nu)
    pulse, tc = _pulse(u)
    hertz = pulse_collision(pulse_law(), _SPEED, mass=pulse.mass)
    omega = np.asarray(modes.omega, dtype=float) * x / tc
    c2 = np.asarray(modes.C, dtype=float) ** 2
    on_hertz = c2 @ np.abs(hertz.spectrum(omega)) ** 2
    return float(c2 @ np.abs(pulse.spectrum(omega)) ** 2 / on_hertz)


def pulse_law():
    """The reduced Hertz law the pulses are computed on (any: only ``u`` matters)."""
    from restitution.quasistatic.hertz_sphere import sphere_contact_law

    return sphere_contact_law(0.3)


@dataclass(frozen=True)
class PlasticWaves:
    """``r(x, u)`` for one material on the plugin's knots (module docs).

    Attributes
    ----------
    nu : float
        The material's 3D Poisson number.
    x : numpy.ndarray, shape (N,)
        Knots in ``x`` (from the route's ``x_lo``, :data:`KNOT_SPACING` apart, to
        :data:`X_TOP`).
    eta : numpy.ndarray, shape (K,)
        Knots in ``eta = arccosh(u)`` (:data:`ETA_STEP` apart from 0).
    ratio, slope : numpy.ndarray, shape (K, N)
        ``r`` and ``dr/dx`` at the knots (``r = 1``, ``dr/dx = 0`` at ``u = 1``).
    """

    nu: float
    x: np.ndarray
    eta: np.ndarray
    ratio: np.ndarray
    slope: np.ndarray

    @property
    def u_top(self) -> float:
        return math.cosh(self.eta[-1])

    def __call__(self, x: float, u: float) -> float:
        """``r`` at one ``(x, u)`` as the plugin evaluates it (``contact_law.cpp``): 1 for
        ``u <= 1``; cubic Hermite in ``x`` at the four nearest ``u`` knots, then Lagrange's cubic
        through them in ``eta = arccosh(u)``; NaN outside the knots."""
        if u <= 1.0:
            return 1.0
        k = self.x
        if not (k[0] <= x <= k[-1]) or not (u <= self.u_top):
            return math.nan
        eta = math.acosh(u)
        h = self.eta[1] - self.eta[0]
        n = self.eta.size
        first = min(max(int(eta / h) - 1, 0), n - 4)
        lo = min(max(int(np.searchsorted(k, x, side="right")) - 1, 0), k.size - 2)
        x0, x1 = k[lo], k[lo + 1]
        t = (eta - self.eta[first]) / h
        out = 0.0
        for a in range(4):
            weight = 1.0
            for b in range(4):
                if b != a:
                    weight *= (t - b) / (a - b)
            row = first + a
            out += weight * _hermite(x, x0, x1, self.ratio[row, lo], self.ratio[row, lo + 1],
                                     self.slope[row, lo], self.slope[row, lo + 1])  # fmt: skip
        return out


def _hermite(x, x0, x1, y0, y1, d0, d1) -> float:
    """The cubic Hermite polynomial of ``table_reader.h`` (the same expression)."""
    h = x1 - x0
    t = (x - x0) / h
    s = 1.0 - t
    return (
        (1.0 + 2.0 * t) * s * s * y0
        + t * s * s * h * d0
        + t * t * (3.0 - 2.0 * t) * y1
        - (t * t * s * h * d1)
    )


def _key(nu: float) -> str:
    from restitution._version import __version__

    fields = {"kind": "plastic-waves", "nu": float(nu).hex(), "x_top": X_TOP,
              "spacing": KNOT_SPACING, "eta_step": ETA_STEP, "u_knots": U_KNOTS,
              "drive_step": DRIVE_STEP, "version": __version__}  # fmt: skip
    return json.dumps(fields, sort_keys=True)


def _load(path, key: str) -> PlasticWaves | None:
    try:
        with np.load(path, allow_pickle=False) as data:
            if str(data["key"]) != key:
                return None
            arrays = {f: np.array(data[f]) for f in ("x", "eta", "ratio", "slope")}
    except (OSError, KeyError, ValueError, zipfile.BadZipFile, EOFError):
        return None
    if not all(np.all(np.isfinite(a)) for a in arrays.values()):
        return None
    return PlasticWaves(float.fromhex(json.loads(key)["nu"]), **arrays)


def _save(path, key: str, waves: PlasticWaves) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp.npz")
    os.close(fd)
    try:
        np.savez(tmp, key=np.array(key), x=waves.x, eta=waves.eta, ratio=waves.ratio,
                 slope=waves.slope)  # fmt: skip
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def _compute(nu: float) -> PlasticWaves:
    from restitution.laws.exports.sphere_loss import sphere_loss

    x_lo = sphere_loss(nu).x_lo
    x = x_lo + KNOT_SPACING * np.arange(int((X_TOP - x_lo) / KNOT_SPACING) + 1)
    eta = ETA_STEP * np.arange(U_KNOTS)
    ratio, slope = np.ones((U_KNOTS, x.size)), np.zeros((U_KNOTS, x.size))
    for j in range(1, U_KNOTS):
        ratio[j], slope[j] = _ratio_at_knots(nu, math.cosh(eta[j]), x)
    return PlasticWaves(nu, x, eta, ratio, slope)


@functools.cache
def plastic_waves(nu: float) -> PlasticWaves:
    """:class:`PlasticWaves` of a material of 3D Poisson number ``nu``: 77 pulses' spectra and
    their mode sums (about three minutes), kept in the disk cache of the modes
    (:func:`restitution.bodies.cache.cache_dir`)."""
    from restitution.bodies.cache import CacheError, cache_dir

    nu = SPHERE.check_nu(nu)
    key = _key(nu)
    try:
        path = cache_dir() / f"plastic-waves-{hashlib.sha256(key.encode()).hexdigest()[:24]}.npz"
    except CacheError:
        return _compute(nu)
    if path.exists():
        cached = _load(path, key)
        if cached is not None:
            return cached
    waves = _compute(nu)
    try:
        _save(path, key, waves)
    except OSError:
        pass  # a read-only cache only costs recomputation
    return waves
