"""An SI law as a table, a CSV file, a pandas DataFrame and a figure: for a notebook.

Every view is the law's points (:meth:`~restitution.laws.si_law.SILaw.points`: epsilon, its
error, the range cut at 1, the status) at the asked speeds, or at :data:`DEFAULT_POINTS`
speeds evenly spaced in ``log w`` over the law's range: one source of the numbers, so the views
cannot disagree with ``restitution law``. Files are written whole or not at all
(:mod:`restitution.atomic`). pandas is optional (only :func:`to_frame` needs it).

:func:`rows` gives each point's note in full. The CSV and the DataFrame give each distinct note
once, with what the numbers are (the law, the mechanisms in them, the units): the CSV in ``#``
lines above its header, the frame in ``DataFrame.attrs``; a row has its short ``status`` and
the key of its note (``note_id``: ``"n1"``, ...; empty for none). Issue 62: a 300-character
note was repeated in most of the 301 rows.

Units: speeds ``w`` in m/s (``speed_m_s``), ``v_over_c`` reduced, epsilon dimensionless
(:data:`UNITS`).
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.errors import InputError

__all__ = [
    "COLUMNS",
    "DEFAULT_POINTS",
    "FRAME_COLUMNS",
    "UNITS",
    "about",
    "plot",
    "rows",
    "to_csv",
    "to_frame",
]

DEFAULT_POINTS = 301
"""Speeds of a view when none are asked: evenly spaced in ``log w`` over the law's range."""

COLUMNS = (
    "speed_m_s",
    "v_over_c",
    "epsilon",
    "epsilon_err",
    "epsilon_sd",
    "epsilon_sd_kind",
    "epsilon_min",
    "epsilon_max",
    "status",
    "note",
)
"""The keys of every row of :func:`rows` (those of :meth:`SIPoint.to_dict`), in this order."""

FRAME_COLUMNS = (*COLUMNS[:-1], "note_id")
"""The columns of the CSV and the DataFrame: :data:`COLUMNS` with the note's key instead of its
text (the texts are in :func:`about`'s ``notes``)."""

UNITS = {
    "speed_m_s": "m/s: the impact speed w against the partner",
    "v_over_c": "w / (k c), the law's reduced speed (k = 1 against a wall or for a pair's law, 2 "
    "for two identical grains)",
    "epsilon": "dimensionless: rebound speed / impact speed (relative speeds for two grains)",
    "epsilon_min, epsilon_max": "epsilon - epsilon_err and epsilon + epsilon_err, cut to [0, 1]",
    "epsilon_err, epsilon_sd": "the bound (an upper estimate) and one standard deviation "
    "(epsilon_sd_kind: 'standard deviation', calibrated per route on independent points, or "
    "'bound' where the route has too few; docs/errors.md)",
}
"""What the columns' numbers are, in the words of :func:`about`."""


def _speeds(si, speeds_m_s) -> np.ndarray:
    if speeds_m_s is not None:
        return np.atleast_1d(np.asarray(speeds_m_s, dtype=float))
    lo, hi = si.speed_range_m_s
    return np.geomspace(lo, hi, DEFAULT_POINTS)


def rows(si, speeds_m_s=None) -> list[dict]:
    """One dict a speed (:data:`COLUMNS`), the note in full; statuses as plain strings."""
    out = []
    for p in si.points(_speeds(si, speeds_m_s)):
        d = p.to_dict()
        d["status"] = str(d["status"])
        out.append({k: d[k] for k in COLUMNS})
    return out


def _keyed(table: list[dict]) -> tuple[list[dict], dict[str, str]]:
    """The rows with ``note_id`` instead of ``note`` (:data:`FRAME_COLUMNS`), and the notes,
    each once: ``{"n1": text, ...}`` in the order they first come."""
    notes: dict[str, str] = {}
    keys: dict[str, str] = {}
    out = []
    for r in table:
        text = r["note"]
        if text and text not in keys:
            keys[text] = f"n{len(keys) + 1}"
            notes[keys[text]] = text
        row = {k: r[k] for k in COLUMNS[:-1]}
        row["note_id"] = keys[text] if text else ""
        out.append(row)
    return out, notes


def _title(si) -> str:
    g = si.grain
    return (
        f"{g.shape}, E = {g.E:.3g} Pa, nu = {g.nu:g}, rho = {g.rho:g} kg/m^3, against {si.against}"
    )


def _mechanisms(si) -> list[str]:
    """The names of the mechanisms in the law's numbers (``waves``, ``viscous``, ...)."""
    from restitution.laws.mechanisms.bounds import law_mechanisms

    return list(law_mechanisms(si.law))


def about(si, notes: dict[str, str] | None = None) -> dict:
    """What a view's numbers are: the grain and partner (``law``), the mechanisms in them, where
    the law comes from, the units (:data:`UNITS`) and the notes its rows name by ``note_id``
    (``DataFrame.attrs`` of :func:`to_frame`; the ``#`` lines of :func:`to_csv`)."""
    return {
        "law": _title(si),
        "mechanisms": _mechanisms(si),
        "source": si.law_source,
        "units": dict(UNITS),
        "notes": dict(notes or {}),
    }


def to_csv(si, path: str | os.PathLike, speeds_m_s=None) -> Path:
    """The points as CSV: ``#`` lines saying what the numbers are and each note once
    (:func:`about`), then the header :data:`FRAME_COLUMNS` and one row a speed (an empty cell
    where a speed has no value). Read it back with ``pandas.read_csv(path, comment="#")``."""
    path = Path(path)
    table, notes = _keyed(rows(si, speeds_m_s))
    head = about(si, notes)
    lines = [
        f"law: {head['law']}",
        f"mechanisms in the numbers: {', '.join(head['mechanisms'])}",
        f"source: {head['source']}",
        *(f"units of {k}: {v}" for k, v in head["units"].items()),
        *(f"note {k}: {v}" for k, v in notes.items()),
    ]
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        for line in lines:
            fh.write("# " + " ".join(line.splitlines()) + "\n")
        writer = csv.DictWriter(fh, fieldnames=FRAME_COLUMNS, lineterminator="\n")
        writer.writeheader()
        for r in table:
            writer.writerow({k: ("" if v is None else v) for k, v in r.items()})
    return path


def to_frame(si, speeds_m_s=None):
    """The points as a pandas DataFrame: one row a speed (:data:`FRAME_COLUMNS`; NaN where a
    speed has no value), what the numbers are and the notes in ``frame.attrs``
    (:func:`about`): ``frame.attrs["notes"][frame.note_id[i]]`` is row ``i``'s note."""
    try:
        import pandas as pd
    except ImportError:
        raise InputError(
            "to_frame needs pandas, which is not installed: pip install pandas (or use "
            "rows() / to_csv(), which need nothing more)"
        ) from None
    table, notes = _keyed(rows(si, speeds_m_s))
    frame = pd.DataFrame(table, columns=list(FRAME_COLUMNS))
    numeric = [c for c in FRAME_COLUMNS if c not in ("status", "note_id", "epsilon_sd_kind")]
    frame[numeric] = frame[numeric].astype(float)
    frame.attrs.update(about(si, notes))
    return frame


def _drawn_speeds(si, speeds_m_s, marks) -> tuple[np.ndarray, tuple[float, float]]:
    """The speeds the curve is drawn at and the x range: the asked speeds and their span; else
    the span of the ``marks`` (at least a factor 10, a little wider so that no mark sits on the
    frame), the curve drawn where the law serves it (nothing is computed for a figure); else
    the law's range."""
    at = [p.speed_m_s for p in marks if p.speed_m_s > 0]
    if speeds_m_s is not None or not at:
        w = _speeds(si, speeds_m_s)
        finite = w[np.isfinite(w) & (w > 0)]
        span = (finite.min(), finite.max()) if finite.size else si.speed_range_m_s
        return w, (float(span[0]), float(span[1]))
    lo, hi = min(at), max(at)
    if hi < 10.0 * lo:
        mid = np.sqrt(lo * hi)
        lo, hi = mid / np.sqrt(10.0), mid * np.sqrt(10.0)
    pad = (hi / lo) ** 0.05  # 5 % of the span in log w
    lo, hi = lo / pad, hi * pad
    first, last = si.speed_range_m_s
    a, b = max(lo, first), min(hi, last)
    return (np.geomspace(a, b, DEFAULT_POINTS) if a < b else np.empty(0)), (lo, hi)


def _column(table: list[dict], key: str) -> np.ndarray:
    return np.array([np.nan if r[key] is None else r[key] for r in table], dtype=float)


def plot(si, path: str | os.PathLike | None = None, speeds_m_s=None, *, ax=None, marks=()):
    """epsilon(w) with its error band (cut at 1), the speeds computed by collisions marked,
    and ``marks`` (points of :meth:`SILaw.points`, e.g. the speeds a user asked) with their
    error bars; saved to ``path`` when given (the format from its suffix). Returns the Axes of
    epsilon.

    The x axis spans the asked speeds (``speeds_m_s``; else the ``marks``; else the law's
    range); the title names the grain, the partner and the mechanisms in the numbers
    (:func:`about`). On a new figure (``ax=None``) a second panel below shows the loss
    ``1 - epsilon`` on a log scale with the same band: an elastic grain's error (1e-5 of an
    epsilon near 1) is thinner than epsilon's line, not than its loss. With ``ax`` given only
    epsilon is drawn, on it.
    """
    import matplotlib.pyplot as plt

    w, (left, right) = _drawn_speeds(si, speeds_m_s, marks)
    table = rows(si, w) if w.size else []
    eps = _column(table, "epsilon")
    lo, hi = _column(table, "epsilon_min"), _column(table, "epsilon_max")
    own = ax is None
    loss_ax = None
    if own:
        fig, (ax, loss_ax) = plt.subplots(
            2, 1, sharex=True, figsize=(6.4, 5.6), gridspec_kw={"height_ratios": (3, 2)}
        )
    ax.fill_between(w, lo, hi, alpha=0.3, linewidth=0, label="epsilon +- error (cut at 1)")
    ax.plot(w, eps, lw=1.2, label="epsilon")
    computed = np.asarray(si.law.v, dtype=float) * si.speed_scale_m_s
    modal = ~np.asarray(si.law.quasistatic, dtype=bool)
    inside = modal & (computed >= left) & (computed <= right)
    at = np.asarray(si.law.epsilon_points, dtype=float)[inside]
    ax.plot(computed[inside], at, ".", ms=4, label="computed by collisions")
    shown = [p for p in marks if p.epsilon is not None]
    if shown:
        ax.errorbar([p.speed_m_s for p in shown], [p.epsilon for p in shown],
                    yerr=[p.epsilon_err for p in shown], fmt="o", ms=4, capsize=2,
                    label="asked speeds")  # fmt: skip
    ax.set_xscale("log")
    ax.set_xlim(left, right)
    ax.set_ylabel("epsilon")
    ax.set_title(f"{_title(si)}\nin the numbers: {' + '.join(_mechanisms(si))}", fontsize=9)
    ax.legend(fontsize=8)
    if loss_ax is None:
        ax.set_xlabel("impact speed w [m/s]")
    else:
        _loss_panel(loss_ax, w, eps, lo, hi, computed[inside], at, shown)
    if path is not None:
        figure = ax.figure
        with atomic.replacing(path) as tmp:
            figure.savefig(tmp, dpi=120, bbox_inches="tight")
        if own:
            plt.close(figure)
    return ax


def _loss_panel(ax, w, eps, lo, hi, computed, at, shown) -> None:
    """``1 - epsilon`` and its band on a log scale; where the band is cut at ``epsilon = 1``
    (no loss within the error) it reaches the panel's floor."""
    loss, below = 1.0 - eps, 1.0 - hi
    positive = loss[np.isfinite(loss) & (loss > 0)]
    ax.set_xlabel("impact speed w [m/s]")
    ax.set_ylabel("1 - epsilon")
    if positive.size == 0:
        return
    cut = np.isfinite(below) & (below <= 0)
    edges = below[np.isfinite(below) & (below > 0)]
    floor = positive.min() / 10.0 if cut.any() or not edges.size else edges.min() / 1.5
    ax.fill_between(w, np.maximum(below, floor), 1.0 - lo, alpha=0.3, linewidth=0)
    ax.plot(w, loss, lw=1.2)
    ax.plot(computed, 1.0 - at, ".", ms=4)
    if shown:
        ax.plot([p.speed_m_s for p in shown], [1.0 - p.epsilon for p in shown], "o", ms=4)
    ax.set_yscale("log")
    ax.set_ylim(bottom=float(floor))
