"""The frequency equation of the free elastic disk (paper eqs. 18, 20, 22-25).

Units: ``E = rho = R = 1`` (two-dimensional constants), so ``omega`` is in ``c / R``.

A symmetric mode with ``n`` directional nodes has the radial shapes (eq. 19, ERRATA item 1)::

    U_r(r)   =   A dJ_n(kappa r)/dr + n B J_n(kappa' r) / r
    U_phi(r) = -[n A J_n(kappa r) / r + B dJ_n(kappa' r)/dr]

with ``kappa = omega sqrt(1 - nu^2)`` and ``kappa' = omega sqrt(2 (1 + nu))`` (eq. 18). The
stress-free edge, ``sigma_rr(1) = sigma_rphi(1) = 0``, is the linear system (22)-(23) for
``(A, B)``; its determinant vanishes at the eigenfrequencies. For ``n = 0`` the system
decouples into the breathing condition (20) and the torsional condition (21); only the
breathing family belongs to the symmetric set used here.
"""

from __future__ import annotations

import numpy as np
from scipy.special import jv

__all__ = [
    "wavenumbers",
    "boundary_matrix",
    "normalized_determinant",
    "breathing_condition",
    "eq25",
    "bessel_and_derivative",
]


def wavenumbers(omega: np.ndarray | float, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """Dilatational and shear wavenumbers ``(kappa, kappa')`` of eq. (18), in ``1/R``."""
    omega = np.asarray(omega, dtype=float)
    return omega * np.sqrt(1.0 - nu**2), omega * np.sqrt(2.0 * (1.0 + nu))


def bessel_and_derivative(n: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``J_n(x)`` and ``J_n'(x) = J_{n-1}(x) - (n/x) J_n(x)`` from two Bessel evaluations."""
    Jn = jv(n, x)
    with np.errstate(divide="ignore", invalid="ignore"):
        dJn = jv(n - 1, x) - n * Jn / x
    return Jn, dJn


def boundary_matrix(n: int | np.ndarray, omega: np.ndarray | float, nu: float) -> np.ndarray:
    """Matrix of the edge conditions (22)-(23) acting on ``(A, B)``.

    Parameters
    ----------
    n : int or array of int
        Number of directional nodes; broadcasts against ``omega``.
    omega : float or array
        Angular frequency in ``c / R``.
    nu : float
        Two-dimensional Poisson number.

    Returns
    -------
    numpy.ndarray, shape ``broadcast(n, omega).shape + (2, 2)``
        Row 0 is ``sigma_rr(1)``, row 1 is ``sigma_rphi(1)`` (each up to a positive factor);
        column 0 multiplies ``A``, column 1 multiplies ``B``.
    """
    n = np.asarray(n)
    k, kp = wavenumbers(omega, nu)
    n, k, kp = np.broadcast_arrays(n, k, kp)
    Jk, dJk = bessel_and_derivative(n, k)
    Jq, dJq = bessel_and_derivative(n, kp)
    m = np.empty(k.shape + (2, 2))
    m[..., 0, 0] = -((1.0 - nu) * k * dJk + (k**2 - (1.0 - nu) * n**2) * Jk)
    m[..., 0, 1] = n * (1.0 - nu) * (kp * dJq - Jq)
    m[..., 1, 0] = -2.0 * n * (k * dJk - Jk)
    m[..., 1, 1] = 2.0 * kp * dJq + (kp**2 - 2.0 * n**2) * Jq
    return m


def _column_norms(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return np.hypot(m[..., 0, 0], m[..., 1, 0]), np.hypot(m[..., 0, 1], m[..., 1, 1])


def normalized_determinant(n: int | np.ndarray, omega: np.ndarray | float, nu: float) -> np.ndarray:
    """Boundary determinant divided by the norms of its two columns, for ``n >= 1``.

    Dividing each column by its (positive) norm keeps the zeros and removes the enormous
    scale differences between ``J_n(kappa)`` and ``J_n(kappa')`` at large ``n``; the result is
    a smooth function with values in ``[-1, 1]`` (the sine of the angle between the columns).
    """
    m = boundary_matrix(n, omega, nu)
    c0, c1 = _column_norms(m)
    det = m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        return det / (c0 * c1)


def breathing_condition(omega: np.ndarray | float, nu: float) -> np.ndarray:
    """Eq. (20), ``kappa J_1'(kappa) + nu J_1(kappa)``, scaled to stay of order one.

    The scale ``hypot(kappa J_1'(kappa), J_1(kappa))`` is positive for ``kappa > 0``, so the
    zeros are those of eq. (20).
    """
    k, _ = wavenumbers(omega, nu)
    b, d = bessel_and_derivative(1, k)
    a = k * d
    return (a + nu * b) / np.hypot(a, b)


def eq25(n: int, omega: np.ndarray | float, nu: float) -> np.ndarray:
    """The paper's eliminated eigenvalue equation (25), as printed (``R = 1``).

    Used only as an independent check of :func:`boundary_matrix`: its zeros must coincide with
    those of the determinant. It is not scaled and not suited to root finding at large ``n``.
    """
    k, kp = wavenumbers(omega, nu)
    Jk, Jk1 = jv(n, k), jv(n - 1, k)
    Jq, Jq1 = jv(n, kp), jv(n - 1, kp)
    one = 1.0 - nu
    return (
        one**2 * (1 - n**2) * k * kp * Jk1 * Jq1
        + one * (k**2 - one * (1 - n**2) * n) * (k * Jk1 * Jq + kp * Jq1 * Jk)
        + (k**4 - 2 * (n**2 + n) * one * k**2) * Jk * Jq
    )
