"""Roots of a body's frequency equation, order by order, and the null vectors of its 2 x 2
boundary matrices: the numerics every body's modes share (disk and sphere).

The frequency function ``f(order, omega)`` is sampled on a grid per order (by the caller, who
knows where it is finite and how to evaluate it fast). Sign changes between grid points give
brackets; a discrete local minimum of ``|f|`` without a sign change on either side may hide a
near-degenerate pair in one cell, so ``s f`` (``s`` the sign there) is minimised and, if it
crosses zero, the cell holds two roots bracketed on either side of the minimiser. Every bracket
is polished with Chandrupatla's method (:func:`scipy.optimize.elementwise.find_root`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.optimize.elementwise import find_minimum, find_root

__all__ = ["bracket_and_polish", "null_vector"]


def bracket_and_polish(
    func: Callable[[np.ndarray, np.ndarray], np.ndarray],
    orders: np.ndarray,
    grid: np.ndarray,
    f: np.ndarray,
    inside: np.ndarray,
    failed: Callable[[], Exception],
) -> tuple[np.ndarray, np.ndarray]:
    """Roots of ``func`` from its samples ``f`` on ``grid``, order by order.

    Parameters
    ----------
    func : callable
        ``func(orders, omega)`` elementwise, for the refinement and the polishing.
    orders : numpy.ndarray of int, shape (K,)
    grid, f : numpy.ndarray, shape (K, M)
        Frequencies (``c / R``) and the function's values there; finite where ``inside``.
    inside : numpy.ndarray of bool, shape (K, M)
        The grid points that belong to each order's scan (above its frequency floor).
    failed : callable
        Makes the exception raised when a polishing fails (a bug, never a user error).

    Returns
    -------
    orders, omega : numpy.ndarray, shape (R,)
        One entry per root found, unsorted (``omega`` is the lower bracket end, float, when no
        root is found).
    """
    valid = inside[:, 1:] & inside[:, :-1]
    sign_change = valid & (np.sign(f[:, :-1]) * np.sign(f[:, 1:]) < 0)
    lo_n, lo_w, hi_w = [], [], []
    ri, ci = np.nonzero(sign_change)
    lo_n.append(orders[ri])
    lo_w.append(grid[ri, ci])
    hi_w.append(grid[ri, ci + 1])

    a = np.abs(f)
    interior = (
        valid[:, :-1]
        & valid[:, 1:]
        & (a[:, 1:-1] < a[:, :-2])
        & (a[:, 1:-1] < a[:, 2:])
        & ~sign_change[:, :-1]
        & ~sign_change[:, 1:]
    )
    ri, ci = np.nonzero(interior)
    ci = ci + 1
    if ri.size:
        s = np.sign(f[ri, ci])
        nloc = orders[ri]

        def signed(w, nloc, s):
            return s * func(nloc, w)

        res = find_minimum(
            signed,
            (grid[ri, ci - 1], grid[ri, ci], grid[ri, ci + 1]),
            args=(nloc, s),
            tolerances={"xatol": 1e-13, "xrtol": 1e-13},
        )
        crossed = res.f_x < 0
        lo_n += [nloc[crossed], nloc[crossed]]
        lo_w += [grid[ri, ci - 1][crossed], res.x[crossed]]
        hi_w += [res.x[crossed], grid[ri, ci + 1][crossed]]

    rn = np.concatenate(lo_n)
    lo = np.concatenate(lo_w)
    hi = np.concatenate(hi_w)
    if rn.size == 0:
        return rn, lo
    root = find_root(
        lambda w, nloc: func(nloc, w),
        (lo, hi),
        args=(rn,),
        tolerances={"xatol": 1e-14, "xrtol": 4e-16},
    )
    if not np.all(root.success):
        raise failed()
    return rn, root.x


def null_vector(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(A, B)`` spanning the null space of the 2 x 2 matrices ``m`` (shape (N, 2, 2)).

    The columns are normalised first, then the null vector is taken from the better-conditioned
    row and scaled back, so widely different column scales do not lose digits.
    """
    c0 = np.hypot(m[:, 0, 0], m[:, 1, 0])
    c1 = np.hypot(m[:, 0, 1], m[:, 1, 1])
    mt = m / np.stack([c0, c1], axis=-1)[:, None, :]
    r0 = np.hypot(mt[:, 0, 0], mt[:, 0, 1])
    r1 = np.hypot(mt[:, 1, 0], mt[:, 1, 1])
    use0 = r0 >= r1
    a_t = np.where(use0, mt[:, 0, 1], mt[:, 1, 1])
    b_t = np.where(use0, -mt[:, 0, 0], -mt[:, 1, 0])
    return a_t / c0, b_t / c1
