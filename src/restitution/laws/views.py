"""An SI law as a table, a CSV file, a pandas DataFrame and a figure: for a notebook.

Every view is the law's points (:meth:`~restitution.laws.si_law.SILaw.points`: epsilon, its
error, the range cut at 1, the status) at the asked speeds, or at :data:`DEFAULT_POINTS`
speeds evenly spaced in ``log w`` over the law's range. Files are written whole or not at all
(:mod:`restitution.atomic`). pandas is optional (only :func:`to_frame` needs it).

Units: speeds ``w`` in m/s (``speed_m_s``), ``v_over_c`` reduced.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.errors import InputError

__all__ = ["COLUMNS", "DEFAULT_POINTS", "plot", "rows", "to_csv", "to_frame"]

DEFAULT_POINTS = 301
"""Speeds of a view when none are asked: evenly spaced in ``log w`` over the law's range."""

COLUMNS = (
    "speed_m_s",
    "v_over_c",
    "epsilon",
    "epsilon_err",
    "epsilon_min",
    "epsilon_max",
    "status",
    "note",
)
"""The columns of every view (those of :meth:`SIPoint.to_dict`), in this order."""


def _speeds(si, speeds_m_s) -> np.ndarray:
    if speeds_m_s is not None:
        return np.atleast_1d(np.asarray(speeds_m_s, dtype=float))
    lo, hi = si.speed_range_m_s
    return np.geomspace(lo, hi, DEFAULT_POINTS)


def rows(si, speeds_m_s=None) -> list[dict]:
    """One dict a speed (:data:`COLUMNS`); statuses as plain strings."""
    out = []
    for p in si.points(_speeds(si, speeds_m_s)):
        d = p.to_dict()
        d["status"] = str(d["status"])
        out.append({k: d[k] for k in COLUMNS})
    return out


def to_csv(si, path: str | os.PathLike, speeds_m_s=None) -> Path:
    """The points as CSV (header :data:`COLUMNS`; an empty cell where a speed has no value)."""
    path = Path(path)
    table = rows(si, speeds_m_s)
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        for r in table:
            writer.writerow({k: ("" if v is None else v) for k, v in r.items()})
    return path


def to_frame(si, speeds_m_s=None):
    """The points as a pandas DataFrame (one row a speed, :data:`COLUMNS`; NaN where a speed
    has no value)."""
    try:
        import pandas as pd
    except ImportError:
        raise InputError(
            "to_frame needs pandas, which is not installed: pip install pandas (or use "
            "rows() / to_csv(), which need nothing more)"
        ) from None
    frame = pd.DataFrame(rows(si, speeds_m_s), columns=list(COLUMNS))
    numeric = [c for c in COLUMNS if c not in ("status", "note")]
    frame[numeric] = frame[numeric].astype(float)
    return frame


def plot(si, path: str | os.PathLike | None = None, speeds_m_s=None, *, ax=None, marks=()):
    """epsilon(w) with its error band (cut at 1), the speeds computed by collisions marked,
    and ``marks`` (points of :meth:`SILaw.points`, e.g. the speeds a user asked) with their
    error bars, on ``ax`` (a new figure when ``None``); saved to ``path`` when given (the
    format from its suffix). Returns the Axes."""
    import matplotlib.pyplot as plt

    table = rows(si, speeds_m_s)
    w = np.array([r["speed_m_s"] for r in table])
    eps = np.array([np.nan if r["epsilon"] is None else r["epsilon"] for r in table])
    lo = np.array([np.nan if r["epsilon_min"] is None else r["epsilon_min"] for r in table])
    hi = np.array([np.nan if r["epsilon_max"] is None else r["epsilon_max"] for r in table])
    own = ax is None
    if own:
        fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.fill_between(w, lo, hi, alpha=0.3, linewidth=0, label="error (error_meaning)")
    ax.plot(w, eps, lw=1.2, label="epsilon")
    computed = np.asarray(si.law.v, dtype=float) * si.speed_scale_m_s
    modal = ~np.asarray(si.law.quasistatic, dtype=bool)
    inside = modal & (computed >= w.min()) & (computed <= w.max())
    at = np.asarray(si.law.epsilon_points, dtype=float)[inside]
    ax.plot(computed[inside], at, ".", ms=4, label="computed by collisions")
    shown = [p for p in marks if p.epsilon is not None]
    if shown:
        ax.errorbar([p.speed_m_s for p in shown], [p.epsilon for p in shown],
                    yerr=[p.epsilon_err for p in shown], fmt="o", ms=4, capsize=2,
                    label="asked speeds")  # fmt: skip
    ax.set_xscale("log")
    ax.set_xlabel("impact speed w [m/s]")
    ax.set_ylabel("epsilon")
    g = si.grain
    ax.set_title(
        f"{g.shape}, E = {g.E:.3g} Pa, nu = {g.nu:g}, rho = {g.rho:g} kg/m^3, against {si.against}",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    if path is not None:
        figure = ax.figure
        with atomic.replacing(path) as tmp:
            figure.savefig(tmp, dpi=120, bbox_inches="tight")
        if own:
            plt.close(figure)
    return ax
