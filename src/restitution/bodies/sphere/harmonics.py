"""Associated Legendre functions of the sphere's modes, normalised as its axisymmetric ones.

A mode of order ``l`` and azimuthal order ``m`` has the angular function
``Y = N_lm P_l^m(cos theta) cos(m phi)`` (spheroidal) or ``... sin(m phi)`` (toroidal, module
:mod:`restitution.bodies.sphere.toroidal`), ``N_l0 = 1`` and ``N_lm^2 = 2 (l - m)! / (l + m)!``
for ``m >= 1``, so that every one has ``int Y^2 dOmega = 4 pi / (2 l + 1)``: that of ``P_l``.
The same radial shapes then carry the same normalisation ``int rho |u|^2 dV = 4 pi / 3`` for
every ``m`` (:mod:`restitution.bodies.sphere.modes`).

With ``x = cos(theta)``, ``s = sin(theta)`` and ``D_j = d^j P_l / dx^j`` (Legendre series
derivatives, :func:`numpy.polynomial.legendre.legder`), dropping the Condon-Shortley sign::

    P_l^m = s^m D_m,    P_l^m / s = s^(m-1) D_m,
    dP_l^m/dtheta = m s^(m-1) x D_m - s^(m+1) D_(m+1),

all finite at the pole (for ``m = 0`` the middle one is not needed). For ``m = 0``,
``dP_l/dtheta = -s P_l'``: the head-on modes' ``lpmv(1, l, x)``
(:func:`restitution.bodies.sphere.surface.legendre_and_theta_derivative`).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.polynomial import legendre

__all__ = ["angular_functions", "normalisation"]


def normalisation(l: int, m: int) -> float:
    """``N_lm`` of the module docs."""
    if m == 0:
        return 1.0
    return math.sqrt(2.0 * math.factorial(l - m) / math.factorial(l + m))


@functools.lru_cache(maxsize=4096)
def _derivative(l: int, j: int) -> np.ndarray:
    """The Legendre series of ``d^j P_l / dx^j`` (read-only: it is shared)."""
    coef = np.zeros(l + 1)
    coef[l] = 1.0
    series = legendre.legder(coef, j) if j else coef
    series.setflags(write=False)
    return series


def angular_functions(l: int, m: int, theta) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``N P_l^m``, ``N dP_l^m/dtheta`` and ``N P_l^m / sin(theta)`` at ``theta`` (radians).

    ``m <= l``; the last is ``0`` for ``m = 0`` (not used).

    >>> import numpy as np
    >>> Y, dY, Ys = angular_functions(2, 1, np.array([0.3]))
    >>> bool(np.allclose(Y, np.sqrt(1 / 3) * 3 * np.cos(0.3) * np.sin(0.3)))
    True
    """
    if not 0 <= m <= l:
        raise ValueError(f"need 0 <= m <= l, got l = {l}, m = {m}")
    theta = np.asarray(theta, dtype=float)
    x, s = np.cos(theta), np.sin(theta)
    Dm = legendre.legval(x, _derivative(l, m))
    Dm1 = legendre.legval(x, _derivative(l, m + 1)) if m + 1 <= l else np.zeros_like(x)
    N = normalisation(l, m)
    if m == 0:
        return N * Dm, -N * s * Dm1, np.zeros_like(x)
    sm1 = s ** (m - 1)
    Y = sm1 * s * Dm
    dY = m * sm1 * x * Dm - sm1 * s * s * Dm1
    return N * Y, N * dY, N * sm1 * Dm
