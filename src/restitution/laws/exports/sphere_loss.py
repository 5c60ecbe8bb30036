"""The loss a slow contact leaves in one sphere's vibrations, as a function of the contact's
duration over the sphere's transit time: the elastic part of the LAMMPS plugin's law per
contact (docs/lammps-plugin.md, "A law per contact").

Units: SI at the edge (m, s, kg, Pa); inside, a sphere's reduced units (``E = rho = R = 1``,
frequencies in ``c / R``).

Rayleigh's estimate (the package's low-speed route, :mod:`restitution.quasistatic.low_speed`):
the quasistatic Hertz pulse of a contact drives every mode of each sphere at its pole. The pulse
is one curve whatever the constants (Hertz's law has no scale): with ``mu`` the contact's reduced
mass, ``w`` its impact speed and ``t_c`` its contact time, the drive of a mode of frequency
``omega`` is ``I = mu w J(omega t_c)``, ``J`` universal. A sphere of mass ``m``, radius ``R`` and
bar speed ``c = sqrt(E / rho)`` then keeps the fraction::

    L = (mu / m) G(x),   x = t_c c / R,   G(x) = 4 sum_k C_k^2 J(Omega_k x)^2             (1)

of the contact's kinetic energy ``(mu / 2) w^2`` (``Omega_k``, ``C_k``: the sphere's modes and
their drive at the pole, :func:`restitution.bodies.cache.get_modes`, the
:data:`~restitution.quasistatic.low_speed.LOW_SPEED_MODES` lowest). On the rigid wall ``mu = m``
and ``L = G``: ``G`` is the wall law of the low-speed route read as a function of ``x``. Two
spheres lose ``(mu / m1) G1(x1) + (mu / m2) G2(x2)``, each in its own modes: what the pair's
route sums (both mode sets under one pulse), so that one curve ``G`` per material serves every
pair of radii. Two identical spheres at ``w`` are the wall at ``w / 2``.

``J`` is the Duhamel integral of Hertz's pulse (:func:`restitution.quasistatic.pulse.
pulse_drive`) up to ``s = omega t_c`` = :data:`DUHAMEL_UP_TO`, interpolated on a fine grid, and
its two-term asymptote (:func:`~restitution.quasistatic.hertz_sphere.drive_asymptote`) above,
where the two differ by ``2e-8`` of the drive's amplitude.

Reach: the route's (:func:`restitution.quasistatic.low_speed.reach`), per contact. Every
sphere's ``x`` is at least ``x_lo = SLOWEST_PHASE / Omega_1`` (its lowest mode rings at least
11.5 radians during the contact), and the contact radius ``a = sqrt(R* delta_max)`` over the
smaller radius is at most the sphere's on the rigid wall at the route's fastest wall speed
(``width_max``). Beyond either the package has no estimate to give.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.errors import InputError

__all__ = [
    "BEYOND_POWER",
    "DUHAMEL_UP_TO",
    "KNOT_SPACING",
    "X_TOP",
    "SphereLoss",
    "contact_time",
    "loss_curve",
    "sphere_loss",
]

DUHAMEL_UP_TO = 200.0
"""``s = omega t_c`` up to which ``J`` is the Duhamel integral; above, the asymptote (their
difference falls like ``s^-5``: 7e-6 of the amplitude at 60, 2e-8 at 200)."""

_DRIVE_STEP = 0.01
"""Spacing in ``s`` of the Duhamel grid ``J`` is interpolated on (cubic spline: 1e-12 of it)."""

KNOT_SPACING = 0.05
"""Spacing in ``x`` of the plugin's knots of ``G``: cubic Hermite with exact slopes strays from
(1) by at most 1.4e-4 of ``G`` at ``nu = 0.3`` (every interval's midpoint; 1.5e-3 at 0.1,
4.9e-6 at 0.02). ``G`` oscillates in ``x`` with each mode's ``Omega_k / 2``, evenly at every
``x``, so the knots are evenly spaced."""

X_TOP = 250.0
"""The slowest contact the knots reach (``x``; a steel sphere of 1 mm on the rigid wall at
1.5e-5 m/s). Above, ``G = G(X_TOP) (X_TOP / x)^5``: Rayleigh's loss in proportion to ``w``
(``x ~ w^(-1/5)``), the sphere's slow continuation (:mod:`~restitution.laws.exports.below`)."""

BEYOND_POWER = 5.0
"""``G ~ x^-5`` beyond :data:`X_TOP` (the loss ``~ w``)."""


def contact_time(estar, rstar, mstar, w):
    """Hertz's contact time (s) of a contact of modulus ``estar`` (Pa), reduced radius ``rstar``
    (m) and mass ``mstar`` (kg) at impact speed ``w`` (m/s): ``kappa delta_max / w``,
    ``delta_max = (5 mstar w^2 / (4 K))^(2/5)``, ``K = (4/3) estar sqrt(rstar)``
    (:data:`~restitution.bodies.sphere.surface.CONTACT_TIME_CONSTANT`).

    >>> round(float(contact_time(230.77e9, 0.01, 0.032882, 1.0)) * 1e6, 3)  # steel, R = 1 cm
    52.376
    """
    k = 4.0 / 3.0 * estar * np.sqrt(rstar)
    dmax = (1.25 * mstar * np.asarray(w, dtype=float) ** 2 / k) ** 0.4
    out = CONTACT_TIME_CONSTANT * dmax / w
    return float(out) if np.ndim(out) == 0 else out


def _modes(nu: float):
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    return get_modes(float(nu), LOW_SPEED_MODES, geometry=SPHERE.geometry)


_LEAD = 1.25 * CONTACT_TIME_CONSTANT**2.5 * math.gamma(2.5)
_NEXT = 45.0 / 7.0 * CONTACT_TIME_CONSTANT**5


def _drive_asymptote(s):
    """``(J, dJ/ds)`` of :func:`~restitution.quasistatic.hertz_sphere.drive_asymptote` per unit
    momentum: ``I = m v J(omega tau)``, written with ``K = (5/4) kappa^(5/2) m v^(-1/2)
    tau^(-5/2)``."""
    s = np.asarray(s, dtype=float)
    c, sn = np.cos(0.5 * s - 1.25 * np.pi), np.sin(0.5 * s - 1.25 * np.pi)
    h, hc = np.sin(0.5 * s), np.cos(0.5 * s)
    j = _LEAD * s**-2.5 * c - _NEXT * s**-5 * h
    dlead = -2.5 * s**-3.5 * c - 0.5 * s**-2.5 * sn
    dnext = 5.0 * s**-6 * h - 0.5 * s**-5 * hc
    dj = _LEAD * dlead + _NEXT * dnext
    return j, dj


@functools.cache
def _duhamel_drive():
    """The Duhamel ``J`` on ``[8, DUHAMEL_UP_TO]`` as a cubic spline (one pulse, every ``s``)."""
    from scipy.interpolate import CubicSpline

    from restitution.quasistatic.hertz_sphere import (
        SPHERE_MASS,
        sphere_contact_law,
        sphere_quasistatic_trajectory,
    )
    from restitution.quasistatic.pulse import pulse_drive

    v = 1e-4  # any speed and nu: the pulse's shape is Hertz's
    pulse = sphere_quasistatic_trajectory(sphere_contact_law(0.3), v)
    s = np.arange(8.0, DUHAMEL_UP_TO + 2 * _DRIVE_STEP, _DRIVE_STEP)
    return CubicSpline(s, pulse_drive(pulse, s / pulse.contact_time) / (SPHERE_MASS * v))


def _drive(s):
    """``(J, dJ/ds)`` at ``s = omega t_c`` (any shape)."""
    spline = _duhamel_drive()
    low = s < DUHAMEL_UP_TO
    inner = np.where(low, s, DUHAMEL_UP_TO)
    far = _drive_asymptote(np.where(low, DUHAMEL_UP_TO, s))
    return np.where(low, spline(inner), far[0]), np.where(low, spline(inner, 1), far[1])


def loss_curve(nu: float, x) -> tuple[np.ndarray, np.ndarray]:
    """``(G, dG/dx)`` of eq. (1) at ``x`` (shape (K,)), summed over the sphere's modes.

    ``x`` must be at least ``8 / Omega_1`` (the Duhamel grid's start); the plugin's curve starts
    at ``SLOWEST_PHASE / Omega_1``.
    """
    modes = _modes(nu)
    c2, om = np.asarray(modes.C, dtype=float) ** 2, np.asarray(modes.omega, dtype=float)
    x = np.atleast_1d(np.asarray(x, dtype=float))
    if np.any(x * om.min() < 8.0):
        raise InputError(f"x must be at least {8.0 / om.min():.4g} (8 / Omega_1), got {x.min()}")
    g, dg = np.empty(x.shape), np.empty(x.shape)
    for i in range(0, x.size, 256):  # blocks of 256 x 1600 drives
        j, dj = _drive(np.outer(x[i : i + 256], om))
        g[i : i + 256] = 4.0 * (j**2 @ c2)
        dg[i : i + 256] = 8.0 * ((j * dj) @ (c2 * om))
    return g, dg


@dataclass(frozen=True)
class SphereLoss:
    """``G(x)`` of eq. (1) for one material on the plugin's knots, and the route's reach.

    Attributes
    ----------
    nu : float
        The material's 3D Poisson number.
    x, g, slope : numpy.ndarray, shape (N,)
        Knots (:data:`KNOT_SPACING` apart from :attr:`x_lo` to :data:`X_TOP`), ``G`` there
        (dimensionless) and ``dG / dx``.
    x_lo : float
        The least ``x`` of the route: :data:`~restitution.quasistatic.low_speed.SLOWEST_PHASE`
        over the lowest mode's ``Omega_1``; the first knot.
    width_max : float
        The largest contact radius over the smaller sphere's radius the route serves: the
        sphere's on the rigid wall at :data:`~restitution.quasistatic.low_speed.
        REACH_WALL_SPEED`.
    n_modes : int
        Modes summed.
    """

    nu: float
    x: np.ndarray
    g: np.ndarray
    slope: np.ndarray
    x_lo: float
    width_max: float
    n_modes: int

    def __call__(self, x):
        """``G`` at ``x`` as the plugin evaluates it: cubic Hermite between the knots, ``G(x_N)
        (x_N / x)^5`` beyond the last, NaN below the first (outside the route)."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        k, g, d = self.x, self.g, self.slope
        i = np.clip(np.searchsorted(k, x, side="right") - 1, 0, k.size - 2)
        h = k[i + 1] - k[i]
        t = (x - k[i]) / h
        val = (
            (1 + 2 * t) * (1 - t) ** 2 * g[i]
            + t * (1 - t) ** 2 * h * d[i]
            + t**2 * (3 - 2 * t) * g[i + 1]
            - t**2 * (1 - t) * h * d[i + 1]
        )
        beyond = g[-1] * (k[-1] / np.maximum(x, k[-1])) ** BEYOND_POWER
        out = np.where(x > k[-1], beyond, val)
        return np.where(x >= k[0], out, np.nan)


@functools.cache
def sphere_loss(nu: float) -> SphereLoss:
    """:class:`SphereLoss` of a material of 3D Poisson number ``nu``: eq. (1) summed over its
    1600 lowest modes on about 4900 knots (a few seconds, once a process and ``nu``)."""
    from restitution.quasistatic.low_speed import REACH_WALL_SPEED, SLOWEST_PHASE

    nu = SPHERE.check_nu(nu)
    modes = _modes(nu)
    x_lo = SLOWEST_PHASE / float(np.min(modes.omega))
    x = x_lo + KNOT_SPACING * np.arange(int((X_TOP - x_lo) / KNOT_SPACING) + 1)
    g, slope = loss_curve(nu, x)
    width = math.sqrt(float(SPHERE.max_compression(REACH_WALL_SPEED, nu)))
    return SphereLoss(nu, x, g, slope, x_lo, width, len(modes))
