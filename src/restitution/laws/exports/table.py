"""The law as a table of speeds: ``speed_m_s epsilon [epsilon_err]`` and its CSV.

A uniform grid of the interpolant joined with the computed speeds, for codes that interpolate
linearly between ``[v, e]`` pairs (AcuTrace style). Speeds in m/s, epsilon and its error
dimensionless; the CSV adds ``v_over_c`` (reduced speed) and the status of every row.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.errors import InputError
from restitution.laws.exports._heading import _header
from restitution.laws.si_law import SILaw

__all__ = ["speed_table", "write_csv", "write_table"]


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
    the computed speeds (from the lowest computed speed if the law refuses lower ones).

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
    return np.column_stack([w, s.epsilon(w), s.epsilon_err(w)])


def write_table(s: SILaw, path: str | os.PathLike, *, points: int = 61, columns: int = 3) -> Path:
    """Whitespace table ``speed_m_s epsilon [epsilon_err]`` with ``#`` comments.

    ``columns=2`` gives the two-column ``[v, e]`` form that AcuTrace-style codes interpolate
    linearly. Returns the path.
    """
    if columns not in (2, 3):
        raise InputError(f"a table has 2 or 3 columns, not {columns}")
    table = speed_table(s, points)[:, :columns]
    names = ["speed_m_s", "epsilon", "epsilon_err"][:columns]
    header = "\n".join([*_header(s), "columns: " + "  ".join(names) + " (piecewise linear)"])
    with atomic.replacing(path) as tmp:
        np.savetxt(tmp, table, fmt="%.8g", header=header, comments="# ")
    return Path(path)


def write_csv(s: SILaw, path: str | os.PathLike, *, points: int = 61) -> Path:
    """CSV ``speed_m_s,v_over_c,epsilon,epsilon_err,status`` with ``#`` comments."""
    w = _grid(s, points)
    path = Path(path)
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        for line in _header(s):
            fh.write(f"# {line}\n")
        writer = csv.writer(fh)
        writer.writerow(["speed_m_s", "v_over_c", "epsilon", "epsilon_err", "status"])
        for p in s.points(w):
            writer.writerow(
                [repr(p.speed_m_s), repr(p.v_over_c), repr(p.epsilon), repr(p.epsilon_err),
                 p.status]
            )  # fmt: skip
    return path
