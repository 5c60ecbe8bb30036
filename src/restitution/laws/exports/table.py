"""The law as a table of speeds: ``speed_m_s epsilon [epsilon_err]`` and its CSV.

A uniform grid of the interpolant joined with the computed speeds, for codes that interpolate
linearly between ``[v, e]`` pairs (AcuTrace style). Below the lowest computed speed the table
carries rows of the slow-impact continuation (:mod:`~restitution.laws.exports.below`) down to
``w = 0``, so that a code interpolating it has a value at every speed up to the law's largest;
their error column is the continuation's bound. Speeds in m/s, epsilon and its error
dimensionless; the CSV (the law's own points, from its lowest served speed) adds ``v_over_c``
(reduced speed), the status of every row and, after it, ``epsilon_sd`` (one standard deviation
where the route's errors are calibrated, docs/errors.md) with ``epsilon_sd_kind``
(``standard deviation`` or ``bound``: where the route has no calibration, the sd is the bound).
The sd columns come last so that a reader of the first five columns is unchanged.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.errors import InputError
from restitution.laws.calibration import SD_MEANING, sd_words
from restitution.laws.exports._heading import _header
from restitution.laws.exports.below import slow_continuation
from restitution.laws.si_law import SILaw

__all__ = ["speed_table", "write_csv", "write_table"]

BELOW_DECADES = 6
"""Rows of the continuation below the lowest computed speed ``w0``: at ``w0 10^-k``,
``k = 1 ... BELOW_DECADES``, and at ``w = 0``."""


def _grid(s: SILaw, points: int) -> np.ndarray:
    if points < 2:
        raise InputError("a table needs at least 2 points")
    computed = np.asarray(s.law.v, dtype=float) * s.speed_scale_m_s
    lo, hi = s.speed_range_m_s
    try:
        s.epsilon(lo)
    except InputError:  # a law that serves only its computed speeds
        lo = float(computed[0])
    w = np.union1d(np.linspace(lo, hi, points), computed)
    return w[(w >= lo) & (w <= hi)]


def speed_table(s: SILaw, points: int = 61) -> np.ndarray:
    """``[speed_m_s, epsilon, epsilon_err]`` on a uniform grid of ``[0, w_max]`` joined with
    the computed speeds (from the lowest computed speed if the law refuses lower ones), after
    rows of the slow-impact continuation at ``w0 10^-k`` (:data:`BELOW_DECADES`) and ``w = 0``.

    Parameters
    ----------
    s : SILaw
        The law in SI units.
    points : int
        Rows, at least 2.

    Returns
    -------
    numpy.ndarray, shape (K, 3)
        ``K >= points`` rows.
    """
    w = _grid(s, points)
    rows = np.column_stack([w, s.epsilon(w), s.epsilon_err(w)])
    below = slow_continuation(s, float(w[0]), float(rows[0, 1]))
    slow = np.concatenate([[0.0], w[0] * 10.0 ** -np.arange(BELOW_DECADES, 0, -1)])
    return np.vstack([np.column_stack([slow, below(slow), below.error_bound(slow)]), rows])


def write_table(s: SILaw, path: str | os.PathLike, *, points: int = 61, columns: int = 3) -> Path:
    """Whitespace table ``speed_m_s epsilon [epsilon_err]`` with ``#`` comments.

    ``columns=2`` gives the two-column ``[v, e]`` form that AcuTrace-style codes interpolate
    linearly. Returns the path.
    """
    if columns not in (2, 3):
        raise InputError(f"a table has 2 or 3 columns, not {columns}")
    table = speed_table(s, points)[:, :columns]
    names = ["speed_m_s", "epsilon", "epsilon_err"][:columns]
    below = slow_continuation(s, float(table[BELOW_DECADES + 1, 0]), table[BELOW_DECADES + 1, 1])
    header = "\n".join([
        *_header(s),
        f"rows {below.describe()} (not computed points; the error column there is that bound)",
        "columns: " + "  ".join(names) + " (piecewise linear)",
    ])  # fmt: skip
    with atomic.replacing(path) as tmp:
        np.savetxt(tmp, table, fmt="%.8g", header=header, comments="# ")
    return Path(path)


def write_csv(s: SILaw, path: str | os.PathLike, *, points: int = 61) -> Path:
    """CSV ``speed_m_s,v_over_c,epsilon,epsilon_err,status,epsilon_sd,epsilon_sd_kind`` with
    ``#`` comments (module docstring); ``epsilon_sd`` is the calibrated standard deviation or,
    where the route has none, the bound (``epsilon_sd_kind`` says which)."""
    w = _grid(s, points)
    path = Path(path)
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        for line in _header(s):
            fh.write(f"# {line}\n")
        fh.write(f"# {SD_MEANING}\n")
        writer = csv.writer(fh)
        writer.writerow(["speed_m_s", "v_over_c", "epsilon", "epsilon_err", "status",
                         "epsilon_sd", "epsilon_sd_kind"])  # fmt: skip
        for p in s.points(w):
            writer.writerow(
                [repr(p.speed_m_s), repr(p.v_over_c), repr(p.epsilon), repr(p.epsilon_err),
                 p.status, "" if p.sd is None else repr(p.sd),
                 "" if p.sd is None else sd_words(p.sd_calibrated)]
            )  # fmt: skip
    return path
