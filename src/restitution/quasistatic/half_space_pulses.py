"""The half-space's radiated energy on other pulse shapes: Hertz's exact pulse beside Hunter's
half-sine and Reed's ``sin^(3/2)`` (issue 65, item 5).

Units: any consistent set, as :mod:`restitution.quasistatic.half_space`; the tests use the
ball's ``E = rho = R = 1``.

**Why the shape enters as one number.** A vertical point force on a half-space radiates the
power ``W = I omega^2 F^2 / (4 pi rho_w c_T^3)`` (``Im G ~ omega`` since ``G ~ k_T = omega /
c_T``, times the ``omega`` of the power): the radiation weights the pulse's spectrum with
``omega^k``, ``k = 2``, and by Parseval ``int_0^inf |F(omega)|^2 omega^2 d omega = pi int
(dF/dt)^2 dt``. A pulse of shape ``F(t) = (J / T) f(t / T)`` (impulse ``J``, duration ``T``,
``int_0^1 f = 1``) has ``int (dF/dt)^2 dt = r J^2 / T^3`` with the *rate factor*::

    r = int_0^1 f'(u)^2 du = (1/pi) int_0^inf S(y)^2 y^2 dy,    S(omega T) = |F(omega)| / J,

and on the half-space's conductance ``g = I / (2 pi rho_w c_T^3)``
(:func:`~restitution.quasistatic.half_space.radiation_conductance`) a ball of mass ``m``
rebounding from it (``J = 2 m v`` to leading order) loses the fraction::

    E_rad / ((m/2) v^2) = g r J^2 / T^3 / ((m/2) v^2) = 8 g r m / T^3.

With Hertz's duration ``T = kappa delta_max / v ~ v^(-1/5)`` that is ``~ v^(3/5)`` for every
shape; the shape sets the constant through ``r`` alone.

**The three shapes** (:data:`PULSE_SHAPES`):

* Hertz's exact pulse: ``r = (45/64) B(4/5, 3/2) kappa^3 = 15.8542``
  (:data:`~restitution.quasistatic.half_space.HERTZ_PULSE_FACTOR` with ``v tau = kappa
  delta_max`` and ``K delta_max^(5/2) = (5/4) m v^2``), ``J / (F_max T) = 8 / (5 kappa)``;
* ``F = F_max sin^p(pi t / T)`` (:func:`sine_power_shape`): ``r = p^2 pi^3 B(p - 1/2, 3/2) /
  B(1/2, (p + 1)/2)^2``, ``J / (F_max T) = B(1/2, (p + 1)/2) / pi``; Hunter's half-sine ``p =
  1`` gives ``r = pi^4 / 8 = 12.1761``, Reed's ``p = 3/2`` gives ``r = 3 pi^3 / (2 B(1/2,
  5/4)^2) = 15.2209``. Their spectra are closed forms (:func:`sine_power_spectrum`).

**Matching a pulse to Hertz's** (:class:`Match`). At Hertz's impulse and duration the ratio of
the losses is ``r / r_Hertz``; a shape matched on another pair of Hertz's numbers gains
``(q / q_Hertz)^n``, ``q = J / (F_max T)``: ``n = 2`` at the same peak force and duration,
``n = 3`` at the same impulse and peak force.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

import numpy as np
from scipy.special import beta, gammaln, rgamma

from restitution.errors import InputError
from restitution.quasistatic.half_space import (
    HERTZ_PULSE_FACTOR,
    radiation_conductance,
)
from restitution.quasistatic.hertz_sphere import CONTACT_TIME_CONSTANT

__all__ = [
    "HALF_SINE",
    "HERTZ_PULSE",
    "PULSE_SHAPES",
    "SINE_THREE_HALVES",
    "Match",
    "PulseShape",
    "shape_loss_ratio",
    "shape_radiated_fraction",
    "sine_power_shape",
    "sine_power_spectrum",
]


@dataclass(frozen=True)
class PulseShape:
    """A force pulse's shape, as far as the half-space's radiation sees it (module docs).

    Attributes
    ----------
    name : str
    rate_factor : float
        ``r = int (dF/dt)^2 dt * T^3 / J^2`` (impulse ``J``, duration ``T``), dimensionless.
    peak_factor : float
        ``q = J / (F_max T)``, dimensionless.
    exponent : float or None
        ``p`` of ``sin^p(pi t / T)``; ``None`` for Hertz's pulse.
    """

    name: str
    rate_factor: float
    peak_factor: float
    exponent: float | None = None


class Match(Enum):
    """Which two of Hertz's numbers a pulse shape keeps; the value is the power ``n`` of
    ``q / q_Hertz`` in the ratio of the losses (module docs)."""

    IMPULSE_DURATION = 0
    PEAK_DURATION = 2
    IMPULSE_PEAK = 3


HERTZ_PULSE = PulseShape(
    "hertz",
    rate_factor=HERTZ_PULSE_FACTOR * 25.0 / 64.0 * CONTACT_TIME_CONSTANT**3,
    peak_factor=8.0 / (5.0 * CONTACT_TIME_CONSTANT),
)
"""Hertz's exact pulse of a sphere (:mod:`restitution.quasistatic.hertz_sphere`):
``r = 15.8542``, ``q = 0.54361``."""


def sine_power_shape(p: float, name: str | None = None) -> PulseShape:
    """The shape ``sin^p(pi t / T)`` on ``0 < t < T`` for ``p > 1/2`` (``int (dF/dt)^2 dt``
    diverges at ``p <= 1/2``), named ``name`` (default ``"sin^p"``); closed forms in the
    module docs."""
    if not (isinstance(p, int | float) and math.isfinite(p) and p > 0.5):
        raise InputError(f"the exponent p of sin^p must be a number above 1/2, got {p!r}")
    area = beta(0.5, 0.5 * (p + 1.0))  # int_0^pi sin^p
    rate = p * p * math.pi**3 * beta(p - 0.5, 1.5) / area**2
    return PulseShape(name or f"sin^{p:g}", float(rate), float(area / math.pi), float(p))


HALF_SINE = sine_power_shape(1.0, "half-sine")
"""Hunter's (1957) half-sine: ``r = pi^4 / 8 = 12.1761``, ``q = 2 / pi``."""

SINE_THREE_HALVES = sine_power_shape(1.5, "sin^(3/2)")
"""Reed's (1985) ``sin^(3/2)``: ``r = 15.2209``, ``q = 0.55642``."""

PULSE_SHAPES: dict[str, PulseShape] = {
    s.name: s for s in (HERTZ_PULSE, HALF_SINE, SINE_THREE_HALVES)
}
"""The three shapes compared in docs/walls.md, by name."""


def sine_power_spectrum(p: float, omega_t) -> np.ndarray:
    """``|F(omega)| / J`` of the pulse ``sin^p(pi t / T)`` at ``omega_t = omega T``::

        S = Gamma(1 + p/2)^2 / (Gamma(1 + p/2 + x) Gamma(1 + p/2 - x)),   x = omega T / (2 pi)

    (Gradshteyn and Ryzhik 3.631.9 on ``int_0^(pi/2) cos^p(phi) cos(a phi) d phi``), signed:
    ``F(omega) = J S e^(-i omega T / 2)``. For ``p = 1`` it is ``cos(pi x) / (1 - 4 x^2)``.
    Beyond ``x = 1 + p/2`` the second Gamma function is reflected, so large ``omega T``
    neither overflows nor loses the sign.

    Parameters
    ----------
    p : float
        The exponent, ``p > -1``.
    omega_t : array_like
        ``omega T``, dimensionless, any shape.

    Returns
    -------
    numpy.ndarray
        The same shape as ``omega_t``.
    """
    c = 1.0 + 0.5 * p
    x = np.abs(0.5 * np.asarray(omega_t, dtype=float) / math.pi)
    near = rgamma(c + x) * rgamma(c - np.minimum(x, c))
    far_x = np.maximum(x, c)  # Gamma(c - x) = pi / (sin(pi (c - x)) Gamma(1 - c + x))
    far = (
        np.sin(math.pi * (c - far_x))
        / math.pi
        * np.exp(gammaln(1 - c + far_x) - gammaln(c + far_x))
    )
    return math.gamma(c) ** 2 * np.where(x < c, near, far)


def shape_loss_ratio(shape: PulseShape, match: Match = Match.IMPULSE_DURATION) -> float:
    """The energy ``shape`` radiates into a half-space over what Hertz's pulse radiates, the
    two matched on ``match`` (module docs): ``(r / r_H) (q / q_H)^n``."""
    n = match.value
    return (shape.rate_factor / HERTZ_PULSE.rate_factor) * (
        shape.peak_factor / HERTZ_PULSE.peak_factor
    ) ** n


def shape_radiated_fraction(
    shape: PulseShape,
    v: float,
    *,
    mass: float,
    radius: float,
    e_star: float,
    wall_density: float,
    wall_shear_speed: float,
    wall_nu: float,
    match: Match = Match.IMPULSE_DURATION,
) -> float:
    """``E_rad / E_kin`` of a ball hitting a half-space at ``v`` when its force pulse has
    ``shape``, matched to Hertz's pulse on ``match``: ``8 g r m / T^3`` with Hertz's ``T``
    (module docs) at the same impulse and duration. The arguments are
    :func:`~restitution.quasistatic.half_space.radiated_fraction`'s, which this gives for
    :data:`HERTZ_PULSE`."""
    given = {"v": v, "mass": mass, "radius": radius, "e_star": e_star,
             "wall_density": wall_density, "wall_shear_speed": wall_shear_speed}  # fmt: skip
    for name, x in given.items():
        if not (math.isfinite(x) and x > 0):
            raise InputError(f"{name} must be a positive number, got {x!r}")
    k = 4.0 / 3.0 * e_star * math.sqrt(radius)
    delta = (1.25 * mass * v * v / k) ** 0.4
    duration = CONTACT_TIME_CONSTANT * delta / v
    conductance = radiation_conductance(wall_density, wall_shear_speed, wall_nu)
    hertz = 8.0 * conductance * HERTZ_PULSE.rate_factor * mass / duration**3
    return hertz * shape_loss_ratio(shape, match)
