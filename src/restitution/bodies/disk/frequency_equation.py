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

from restitution.bodies.disk.bessel_ratio import scaled_pairs, scaled_pairs_grid

__all__ = [
    "wavenumbers",
    "boundary_matrix",
    "scaled_boundary_matrix",
    "edge_matrix_from_pairs",
    "normalized_determinant",
    "normalized_determinant_grid",
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


def edge_matrix_from_pairs(n, k, kp, jm_k, jn_k, jm_q, jn_q, nu) -> np.ndarray:
    """:func:`boundary_matrix` from unit Bessel pairs ``(J_{n-1}, J_n) / hypot(...)`` at
    ``kappa`` (``jm_k, jn_k``) and ``kappa'`` (``jm_q, jn_q``): the columns come out divided by
    those two (positive) scales."""
    xd_k = k * jm_k - n * jn_k  # kappa J_n'(kappa), scaled
    xd_q = kp * jm_q - n * jn_q
    m = np.empty(np.broadcast_shapes(np.shape(xd_k), np.shape(xd_q)) + (2, 2))
    m[..., 0, 0] = -((1.0 - nu) * xd_k + (k**2 - (1.0 - nu) * n**2) * jn_k)
    m[..., 0, 1] = n * (1.0 - nu) * (xd_q - jn_q)
    m[..., 1, 0] = -2.0 * n * (xd_k - jn_k)
    m[..., 1, 1] = 2.0 * xd_q + (kp**2 - 2.0 * n**2) * jn_q
    return m


def scaled_boundary_matrix(
    n: np.ndarray, omega: np.ndarray, nu: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`boundary_matrix` with column 0 divided by ``s = hypot(J_{n-1}, J_n)(kappa)`` and
    column 1 by the same at ``kappa'``, for ``n >= 1``; finite where ``J_n`` underflows.

    Returns
    -------
    m : numpy.ndarray, shape ``broadcast(n, omega).shape + (2, 2)``
    log_s, log_s_p : numpy.ndarray
        ``log`` of the two (positive) column scales, so ``boundary_matrix`` is
        ``m * exp([log_s, log_s_p])`` column by column.
    """
    n, omega = np.broadcast_arrays(np.asarray(n), np.asarray(omega, dtype=float))
    k, kp = wavenumbers(omega, nu)
    jm_k, jn_k, ls_k = (a.reshape(n.shape) for a in scaled_pairs(n, k))
    jm_q, jn_q, ls_q = (a.reshape(n.shape) for a in scaled_pairs(n, kp))
    return edge_matrix_from_pairs(n, k, kp, jm_k, jn_k, jm_q, jn_q, nu), ls_k, ls_q


def _normalized(m: np.ndarray) -> np.ndarray:
    c0, c1 = _column_norms(m)
    det = m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        return det / (c0 * c1)


def normalized_determinant(n: int | np.ndarray, omega: np.ndarray | float, nu: float) -> np.ndarray:
    """Boundary determinant divided by the norms of its two columns, for ``n >= 1``.

    Dividing each column by its (positive) norm keeps the zeros and removes the enormous
    scale differences between ``J_n(kappa)`` and ``J_n(kappa')`` at large ``n``; the result is
    a smooth function with values in ``[-1, 1]`` (the sine of the angle between the columns).
    It is computed from unit Bessel pairs (:mod:`restitution.bodies.disk.bessel_ratio`), so it stays
    exact where ``J_n`` itself underflows.
    """
    n, omega = np.broadcast_arrays(np.asarray(n), np.asarray(omega, dtype=float))
    k, kp = wavenumbers(omega, nu)
    jm_k, jn_k, _ = (a.reshape(n.shape) for a in scaled_pairs(n, k, with_log=False))
    jm_q, jn_q, _ = (a.reshape(n.shape) for a in scaled_pairs(n, kp, with_log=False))
    return _normalized(edge_matrix_from_pairs(n, k, kp, jm_k, jn_k, jm_q, jn_q, nu))


def normalized_determinant_grid(n_lo: int, n_hi: int, omega: np.ndarray, nu: float) -> np.ndarray:
    """:func:`normalized_determinant` for every order ``n_lo..n_hi`` (``>= 1``) at every
    frequency of ``omega``; shape ``(n_hi - n_lo + 1, len(omega))``. One Bessel recurrence per
    frequency serves all orders."""
    omega = np.asarray(omega, dtype=float)
    k, kp = wavenumbers(omega, nu)
    jm_k, jn_k = scaled_pairs_grid(n_lo, n_hi, k)
    jm_q, jn_q = scaled_pairs_grid(n_lo, n_hi, kp)
    n = np.arange(n_lo, n_hi + 1)[:, None].astype(float)
    m = edge_matrix_from_pairs(n, k[None, :], kp[None, :], jm_k, jn_k, jm_q, jn_q, nu)
    return _normalized(m)


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
