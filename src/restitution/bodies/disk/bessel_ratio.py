"""Scale-free Bessel pairs ``(J_{n-1}(x), J_n(x)) / hypot(J_{n-1}(x), J_n(x))`` for any order.

For orders far above the argument, ``J_n(x)`` underflows double precision (at ``n = 600`` and
``x = 0.23 n`` it is about ``1e-304``), although everything the disk's modes need -- the zeros
of the edge determinant, the edge amplitudes, the normalisation integrals -- depends only on
ratios of Bessel functions at one argument. This module computes the ratios
``h_k = J_k(x) / J_{k-1}(x)`` by the backward recurrence ``h_k = x / (2k - x h_{k+1})``
(Miller's algorithm in ratio form; it converges to the minimal solution, so it is stable), and
the signs of ``J_k`` from ``sign J_0(x)`` and the signs of the ratios. The result is the unit
vector ``(j_{n-1}, j_n)`` pointing along ``(J_{n-1}(x), J_n(x))``, plus ``log hypot(...)`` for
callers that need the absolute scale.

The start of the recurrence, ``N = max(n, x) + 20 + 10 x^{1/3}``, leaves an error of
order ``exp(-36)`` relative to the minimal solution; ``tests/test_bessel_ratio.py`` checks the
pairs against :func:`scipy.special.jv` where that does not underflow, to 1e-13.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange
from scipy.special import j0

__all__ = ["scaled_pairs", "scaled_pairs_grid"]


@njit(cache=True, nogil=True)
def _start(n_top: int, x: float) -> int:
    return int(max(float(n_top), x) + 20.0 + 10.0 * x ** (1.0 / 3.0))


@njit(cache=True, nogil=True)
def _ratios(x: float, n_top: int, h: np.ndarray) -> None:
    """``h[k] = J_k(x) / J_{k-1}(x)`` for ``k = 1..n_top`` (``h[0]`` unused)."""
    N = _start(n_top, x)
    hk = x / (2.0 * N + 2.0)
    for k in range(N, 0, -1):
        d = 2.0 * k - x * hk
        hk = x / d if d != 0.0 else math.inf
        if k <= n_top:
            h[k] = hk


@njit(cache=True, nogil=True)
def _pair(h_n: float, sign_prev: float, log_prev: float) -> tuple[float, float, float]:
    """Unit ``(j_{n-1}, j_n)`` from ``h_n`` and the sign and log-size of ``J_{n-1}``."""
    if abs(h_n) <= 1.0:
        r = math.sqrt(1.0 + h_n * h_n)
        return sign_prev / r, sign_prev * h_n / r, log_prev + math.log(r)
    g = 1.0 / h_n
    r = math.sqrt(1.0 + g * g)
    s_n = sign_prev * (1.0 if h_n > 0 else -1.0)
    return s_n * g / r, s_n / r, log_prev + math.log(abs(h_n)) + math.log(r)


@njit(cache=True, nogil=True)
def _descend(x: float, n: int, with_log: bool) -> tuple[float, float, float]:
    """One backward recurrence: ``h_n``, and the sign and log-size of ``J_{n-1} / J_0``."""
    N = _start(n, x)
    hk = x / (2.0 * N + 2.0)
    h_n = 0.0
    sign = 1.0
    lg = 0.0
    for k in range(N, 0, -1):
        d = 2.0 * k - x * hk
        hk = x / d if d != 0.0 else math.inf
        if k == n:
            h_n = hk
        elif k < n:
            if hk < 0:
                sign = -sign
            if with_log:
                lg += math.log(abs(hk))
    return h_n, sign, lg


@njit(cache=True, parallel=True)
def _points(n, x, sign0, log0, with_log, out):
    for i in prange(n.size):
        h_n, sign, lg = _descend(x[i], n[i], with_log)
        a, b, c = _pair(h_n, sign0[i] * sign, log0[i] + lg)
        out[i, 0] = a
        out[i, 1] = b
        out[i, 2] = c


@njit(cache=True, parallel=True)
def _grid(n_lo, n_hi, x, sign0, out):
    for j in prange(x.size):
        h = np.empty(n_hi + 1)
        _ratios(x[j], n_hi, h)
        s = sign0[j]
        for k in range(1, n_lo):
            s *= 1.0 if h[k] > 0 else -1.0
        for n in range(n_lo, n_hi + 1):
            a, b, _ = _pair(h[n], s, 0.0)
            out[n - n_lo, j, 0] = a
            out[n - n_lo, j, 1] = b
            s *= 1.0 if h[n] > 0 else -1.0


def _j0_sign_log(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    J = j0(x)
    with np.errstate(divide="ignore"):
        return np.where(J < 0, -1.0, 1.0), np.log(np.abs(J))


def scaled_pairs(n, x, with_log: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit pairs at scattered points.

    Parameters
    ----------
    n : array_like of int, shape (P,)
        Orders, ``n >= 1``.
    x : array_like, shape (P,)
        Arguments, ``x > 0``.
    with_log : bool
        Also accumulate ``log s`` (``n`` logarithms per point); without it ``log_s`` is
        meaningless.

    Returns
    -------
    jm, jn : numpy.ndarray, shape (P,)
        ``J_{n-1}(x) / s`` and ``J_n(x) / s`` with ``s = hypot(J_{n-1}(x), J_n(x)) > 0``.
    log_s : numpy.ndarray, shape (P,)
        ``log s`` (finite even where ``s`` underflows).
    """
    n, x = np.broadcast_arrays(np.asarray(n, dtype=np.int64), np.asarray(x, dtype=float))
    n, x = np.ascontiguousarray(n.ravel()), np.ascontiguousarray(x.ravel())
    if n.size and (n.min() < 1 or x.min() <= 0):
        raise ValueError("scaled_pairs needs n >= 1 and x > 0")
    sign0, log0 = _j0_sign_log(x)
    out = np.empty((n.size, 3))
    _points(n, x, sign0, log0, bool(with_log), out)
    return out[:, 0], out[:, 1], out[:, 2]


def scaled_pairs_grid(n_lo: int, n_hi: int, x) -> tuple[np.ndarray, np.ndarray]:
    """Unit pairs for every order ``n_lo..n_hi`` at every argument of ``x``.

    One backward recurrence per argument serves all orders, so the cost is
    ``O(len(x) * max(n_hi, x))``.

    Returns
    -------
    jm, jn : numpy.ndarray, shape (n_hi - n_lo + 1, len(x))
    """
    x = np.ascontiguousarray(np.asarray(x, dtype=float).ravel())
    if n_lo < 1 or n_hi < n_lo or (x.size and x.min() <= 0):
        raise ValueError("scaled_pairs_grid needs 1 <= n_lo <= n_hi and x > 0")
    sign0, _ = _j0_sign_log(x)
    out = np.empty((n_hi - n_lo + 1, x.size, 2))
    _grid(int(n_lo), int(n_hi), x, sign0, out)
    return out[..., 0], out[..., 1]
