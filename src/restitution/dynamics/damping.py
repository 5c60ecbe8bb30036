"""Exact free flow of a damped mode: the propagator both integration paths use (numba).

Units: ``E = rho = R = 1``; times in ``R / c``, rates in ``c / R``; ``P`` is a momentum (``m c``).

A mode of a viscoelastic body (:class:`restitution.bodies.viscoelastic.Viscoelastic`) obeys,
away from the wall::

    dQ/dt = P / m,    dP/dt = -m omega^2 Q - gamma P,

with ``gamma = tau omega^2`` for a Kelvin-Voigt material of relaxation time ``tau``. Over a time
``h >= 0`` its exact flow is linear::

    Q(h) = a Q + b P,    P(h) = d P - c Q,

with, for ``e = exp(-gamma h / 2)`` and ``kappa^2 = gamma^2 / 4 - omega^2``::

    a = e [C + (gamma / 2) S],   b = e S / m,   c = m omega^2 e S,   d = e [C - (gamma / 2) S],

``C = cos(omega_d h)``, ``S = sin(omega_d h) / omega_d`` (``omega_d^2 = -kappa^2``, underdamped)
or ``C = cosh(kappa h)``, ``S = sinh(kappa h) / kappa`` (overdamped); ``S = h`` at critical
damping. Overdamped, ``e C`` and ``e S`` are formed from the two decay rates
``lambda_1 = -omega^2 / (gamma/2 + kappa)`` (slow, written without cancellation) and
``lambda_2 = -gamma/2 - kappa``: ``a = (lambda_1 e_2 - lambda_2 e_1) / (2 kappa)``,
``b m = (e_1 - e_2) / (2 kappa)``, ``d = (lambda_1 e_1 - lambda_2 e_2) / (2 kappa)`` with
``e_i = exp(lambda_i h)``, so no huge ``cosh`` meets a tiny ``e`` (near critical damping,
``2 kappa h < 1``, the first form with ``e S`` from ``expm1``).

A mode with ``gamma = 0`` gets the undamped rotation in exactly the arithmetic of the elastic
kernel (:mod:`restitution.dynamics.kernel`): ``a = d = cos``, ``b = sin / (m omega)``,
``c = m omega sin``, so a body with zero viscosity gives today's results bit for bit.

The flow is run forwards only: backwards (``h < 0``) a damped mode grows like
``exp(gamma |h| / 2)``, which is why damped bodies are integrated with Strang's splitting,
whose substeps are all positive, and never with Yoshida's composition.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["damped_flow", "fill_damped_flow"]


@njit(cache=True, nogil=True)
def _one_mode(omega, gamma, m, h):
    """``(a, b, c, d)`` of one mode over ``h`` (module docstring)."""
    if gamma == 0.0:
        arg = omega * h
        sn = math.sin(arg)
        mw = m * omega
        cs = math.cos(arg)
        return cs, sn / mw, mw * sn, cs
    half = 0.5 * gamma
    disc = half * half - omega * omega
    if disc < 0.0:
        wd = math.sqrt(-disc)
        e = math.exp(-half * h)
        eC = e * math.cos(wd * h)
        eS = e * math.sin(wd * h) / wd
    elif disc == 0.0:
        e = math.exp(-half * h)
        eC = e
        eS = e * h
    else:
        kappa = math.sqrt(disc)
        slow = (omega * omega) / (half + kappa)  # -lambda_1, the slow decay rate
        fast = half + kappa  # -lambda_2
        e1 = math.exp(-slow * h)
        e2 = math.exp(-fast * h)
        if 2.0 * kappa * h < 1.0:
            # Near critical damping: e cosh, and e sinh / kappa without cancellation.
            eC = 0.5 * (e1 + e2)
            eS = e2 * math.expm1(2.0 * kappa * h) / (2.0 * kappa)
        else:
            # Strongly overdamped: each coefficient from the two decays, no cosh against e.
            diff = (e1 - e2) / (2.0 * kappa)
            return (
                (fast * e1 - slow * e2) / (2.0 * kappa),
                diff / m,
                m * omega * omega * diff,
                (fast * e2 - slow * e1) / (2.0 * kappa),
            )
    return eC + half * eS, eS / m, m * omega * omega * eS, eC - half * eS


@njit(cache=True, nogil=True)
def fill_damped_flow(omega, gamma, m, h, out, k0, k1):
    """Write the propagator of modes ``k0 <= k < k1`` over ``h`` into ``out[0:4, k]``
    (``a, b, c, d``)."""
    for k in range(k0, k1):
        a, b, c, d = _one_mode(omega[k], gamma[k], m, h)
        out[0, k] = a
        out[1, k] = b
        out[2, k] = c
        out[3, k] = d


def damped_flow(omega, gamma, mass: float, h: float) -> tuple[np.ndarray, ...]:
    """``(a, b, c, d)``, each of shape (N,): the exact flow of every mode over ``h >= 0``.

    Parameters
    ----------
    omega, gamma : array_like, shape (N,)
        Angular frequencies and damping rates, ``c / R``.
    mass : float
        The body's mass (reduced units).
    h : float
        Time, ``R / c``; not negative.
    """
    omega = np.ascontiguousarray(omega, dtype=np.float64)
    gamma = np.ascontiguousarray(gamma, dtype=np.float64)
    out = np.empty((4, omega.size))
    fill_damped_flow(omega, gamma, float(mass), float(h), out, 0, omega.size)
    return out[0], out[1], out[2], out[3]
