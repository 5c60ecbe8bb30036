"""The viscous loss of a Kelvin-Voigt Hertz contact as a function of its one group: the damped part
of the LAMMPS plugin's law per contact (docs/lammps-plugin.md, "A law per contact").

Units: SI at the edge (s, Pa, m, kg, m/s); the group and epsilon are dimensionless.

The package's viscous part of a damped sphere (:mod:`restitution.laws.damped`, on the wall or in
a pair) is the quasistatic collision ``mu xi'' = -K xi^(3/2) - tau xi' (3/2) K xi^(1/2)``
(:func:`restitution.quasistatic.viscoelastic.viscous_collision`: Hertz's law of the contact,
``K = (4/3) E* sqrt(R*)``, its reduced mass ``mu``, the material's relaxation time ``tau``),
ended when the total force reaches zero. Scaled, it depends on one group only::

    q = (3/2) tau (K / mu)^(2/5) w^(1/5),                                                   (1)

``tau`` over the contact's time scale (Hertz's contact time is ``3.2181 (mu / K)^(2/5)
w^(-1/5)``, so ``q = 4.827 tau / t_c``); Ramirez, Poschel, Brilliantov and Schwager (PRE 60,
4465, 1999) write epsilon as a series in it. This module tabulates ``epsilon_v(q)`` once: knots
:data:`LOG_STEP` apart in ``ln q`` from :data:`Q_LOW` to :data:`Q_TOP`, each a DOP853
integration at ``rtol = 1e-12``, with slopes of the cubic spline through them (the cubic Hermite
between the knots strays from the integration by at most 7e-9 at every interval's midpoint);
below :data:`Q_LOW` the series ``1 - C1 q + C2 q^2 + (4/15) q^(5/2)``, whose ``O(q^3)`` rest is
5e-10 at ``Q_LOW``. Beyond the last knot (``q = 20.95``) epsilon_v is below 0.008, under the
plugin's least epsilon.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError

__all__ = [
    "LOG_STEP",
    "Q_LOW",
    "Q_TOP",
    "ViscousMap",
    "exact_viscous_epsilon",
    "viscous_group",
    "viscous_map",
]

Q_LOW = 1e-3
"""The first knot; the series below it (module docs)."""

Q_TOP = 20.0
"""The knots reach it (the last is at 20.95, epsilon_v = 0.0079); no value above the last."""

LOG_STEP = 0.05
"""Spacing of the knots in ``ln q``."""


def viscous_group(relaxation_time_s, estar, rstar, mstar, w):
    """``q`` of eq. (1): relaxation time (s), contact modulus ``E*`` (Pa), reduced radius (m)
    and mass (kg), impact speed (m/s).

    >>> round(float(viscous_group(1e-7, 115.38e9, 1e-3 / 3 * 2, 3.29e-5 * 8 / 9, 1.0)), 6)
    0.067497
    """
    k = 4.0 / 3.0 * np.asarray(estar, dtype=float) * np.sqrt(rstar)
    return 1.5 * relaxation_time_s * (k / mstar) ** 0.4 * np.asarray(w, dtype=float) ** 0.2


@dataclass(frozen=True)
class ViscousMap:
    """``epsilon_v(q)`` as the plugin evaluates it (module docs).

    Attributes
    ----------
    u, epsilon, slope : numpy.ndarray, shape (N,)
        Knots in ``u = ln q``, epsilon_v there and ``d epsilon_v / du``.
    series : tuple of float
        ``(C1, C2, h)`` of the series below the first knot.
    """

    u: np.ndarray
    epsilon: np.ndarray
    slope: np.ndarray
    series: tuple[float, float, float]

    def __call__(self, q):
        """epsilon_v at ``q >= 0``: the series below the first knot, the cubic Hermite in ``ln q``
        between the knots, NaN above the last."""
        q = np.atleast_1d(np.asarray(q, dtype=float))
        c1, c2, h = self.series
        low = q < math.exp(self.u[0])
        safe = np.where(low | (q <= 0.0), math.exp(self.u[0]), q)
        u = np.log(safe)
        k, y, d = self.u, self.epsilon, self.slope
        i = np.clip(np.searchsorted(k, u, side="right") - 1, 0, k.size - 2)
        step = k[i + 1] - k[i]
        t = (u - k[i]) / step
        val = (
            (1 + 2 * t) * (1 - t) ** 2 * y[i]
            + t * (1 - t) ** 2 * step * d[i]
            + t**2 * (3 - 2 * t) * y[i + 1]
            - t**2 * (1 - t) * step * d[i + 1]
        )
        series = 1.0 - c1 * q + c2 * q**2 + h * np.maximum(q, 0.0) ** 2.5
        out = np.where(low, series, np.where(u > k[-1], np.nan, val))
        return np.where(q >= 0.0, out, np.nan)


def _exact(q) -> np.ndarray:
    """epsilon_v at every ``q`` (shape (K,)): the package's viscous collision, DOP853 at
    ``rtol = 1e-12``, on the sphere's Hertz law at a speed and ``tau`` giving ``q``."""
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law
    from restitution.quasistatic.viscoelastic import viscous_collision

    law, v = sphere_contact_law(0.3), 1e-3  # any law and speed: only q matters
    per_tau = 1.5 * (law.K / SPHERE_MASS) ** 0.4 * v**0.2
    return np.array(
        [viscous_collision(law, [v], x / per_tau, rtol=1e-12).epsilon[0] for x in np.ravel(q)]
    )


def exact_viscous_epsilon(q) -> np.ndarray:
    """epsilon_v at every ``q`` by direct integration (what the knots are made of), shape (K,)."""
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if np.any(~(q > 0.0)):
        raise InputError("q must be > 0")
    return _exact(q)


@functools.cache
def viscous_map() -> ViscousMap:
    """The plugin's :class:`ViscousMap` (200 integrations, about 2 s, once a process)."""
    from scipy.interpolate import CubicSpline

    from restitution.quasistatic.viscoelastic import C1, C2, DELAYED_RECOVERY

    n = math.ceil(math.log(Q_TOP / Q_LOW) / LOG_STEP)
    u = math.log(Q_LOW) + LOG_STEP * np.arange(n + 1)
    eps = _exact(np.exp(u))
    return ViscousMap(u, eps, CubicSpline(u, eps)(u, 1), (C1, C2, DELAYED_RECOVERY))
