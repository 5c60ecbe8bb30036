"""A mechanism's law at every speed, tabulated once: the law object that Python, the tables and
the exports serve when each speed of the mechanism costs about a second (plastic flow, adhesion).

Units: SI at the edge (speeds in m/s); the table in the grain's reduced units (``v`` in ``c``,
as the elastic law it is built on).

The command line answers such a mechanism speed by speed (one force pulse and the spectrum of the
modes it drives per speed). A law at every speed (``restitution.si_law(..., yield_stress=...)``,
exports) is instead a table, built once (:func:`mechanism_table`):

* **Where.** The table's speeds are speeds of the elastic law the mechanism adds its losses to,
  :data:`PER_DECADE` a decade (the computed points nearest a geometric grid, both ends kept), so
  that every table point carries the status its elastic point has (computed, computed not
  asymptotic, quasistatic) and the statuses between them follow the same rules as the elastic
  law's (:func:`restitution.laws.si_point.point_status`). The table stops below the first speed
  where the mechanism gives no value (the grain does not rebound, or its contact leaves the
  model): it serves nothing there, as the command line answers nothing. A grain that sticks
  below a speed (adhesion) starts the table at the first speed with a rebound; below it the
  mechanism answers (``epsilon = 0`` below its sticking speed).
* **What interpolation misses.** Between two table speeds the law interpolates epsilon (PCHIP in
  ``ln v``: :data:`~restitution.laws.law_point.LOG_V`; in ``v`` a table of four speeds a decade
  missed up to 5 times the error it measured). What that misses is measured twice: the
  mechanism is computed at the geometric middle of every interval, and the same interpolation
  through the table's speeds is compared with the elastic law at every one of its own points
  inside the interval (free: the structure of the waves' loss, which one middle can miss);
  each table point's error gains :data:`GAP_FACTOR` times the larger of the two in the
  intervals beside it (the
  measured error of the table, kept per point as ``interpolation_err``). Between collision points
  the law's own leave-one-out estimate is joined to it in quadrature
  (:meth:`~restitution.laws.law.EpsilonLaw.interpolation_err`); between quasistatic ones the
  points' errors alone hold it. :func:`restitution.laws.tabulated.coverage` (and
  ``tests/test_tabulated.py``) compares the table with the mechanism computed at speeds between
  the table's own and its middles.
* **Cost.** ``2 n - 1`` evaluations for ``n`` table speeds (about 23 speeds for the sphere's
  law from ``1e-6`` to ``0.3 c``: 45 pulses, 40-60 s at about a second each on two cores),
  estimated and told before it starts.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_point import LOG_V, QUASISTATIC_ROUTE
from restitution.laws.shaped_table import shaped_records

__all__ = ["GAP_FACTOR", "PER_DECADE", "Coverage", "coverage", "mechanism_table", "table_speeds"]

PER_DECADE = 4
"""Table speeds a decade of ``v``."""

GAP_FACTOR = 2.0
"""A table point's error gains this times the larger deviation of PCHIP measured at the middle
of the two intervals beside it (as :data:`restitution.laws.wall_grid.GAP_FACTOR`: the deviation
at speeds between the measured ones reached 1.1 times the measured one on an elastic plate's
grid)."""


def table_speeds(v: np.ndarray, per_decade: int = PER_DECADE) -> np.ndarray:
    """Indices into the increasing speeds ``v`` (``c``) of the table: the points nearest a
    geometric grid of ``per_decade`` a decade from ``v[0]`` to ``v[-1]``, both ends kept,
    each once."""
    v = np.asarray(v, dtype=float)
    if v.size < 2:
        raise InputError("a table needs an elastic law of at least two speeds")
    n = max(2, math.ceil(per_decade * math.log10(v[-1] / v[0])) + 1)
    target = np.log(np.geomspace(v[0], v[-1], n))
    idx = np.abs(np.log(v)[None, :] - target[:, None]).argmin(axis=1)
    return np.unique(np.concatenate([[0], idx, [v.size - 1]]))


def _middles(v: np.ndarray) -> np.ndarray:
    """The geometric middle of every interval of ``v``, shape ``(K - 1,)``."""
    return np.sqrt(v[:-1] * v[1:])


def _served(p) -> bool:
    """Whether a mechanism's point has a rebound to tabulate (a value above zero)."""
    return p.epsilon is not None and p.epsilon > 0.0 and p.epsilon_err is not None


def mechanism_table(
    si,
    points_at: Callable[[Sequence[float]], Sequence],
    *,
    words: str,
    mechanisms: Sequence[str],
    parameters: dict,
    seconds_per_speed: float,
    note=None,
    progress=False,
    per_decade: int = PER_DECADE,
    zero_below: float | None = None,
    shape: Callable[[np.ndarray], np.ndarray] | None = None,
):
    """The law of a mechanism at every speed of the elastic law ``si`` (module docs).

    Parameters
    ----------
    si : SILaw
        The elastic law the mechanism adds its losses to.
    points_at : callable
        The mechanism's points at a list of speeds in m/s (each with ``epsilon``,
        ``epsilon_err`` and ``status``; ``epsilon`` ``None`` or 0 where there is no rebound),
        e.g. :meth:`restitution.laws.plastic.PlasticLaw.points`.
    words : str
        What the table is, for its source and the note (``"plastic flow"``).
    mechanisms : sequence of str
        The mechanisms in its numbers (:func:`restitution.laws.mechanisms.bounds.law_mechanisms`
        reads them back).
    parameters : dict
        What the mechanism was computed with (JSON values), kept under ``metadata["tabulated"]``.
    seconds_per_speed : float
        Wall time of one speed, for the estimate told first.
    note : callable, optional
        Called with the estimate before anything is computed.
    progress : Progress or bool
        A bar over the evaluations on stderr (:func:`restitution.limits.run_options.progress_of`).
    zero_below : float, optional
        The speed (m/s) below which the mechanism gives no rebound (``epsilon = 0``: a grain
        that sticks), answered so without computing; between it and the table's first speed
        the mechanism answers (:class:`~restitution.laws.below_route.Below`).
    shape : callable, optional
        A closed form ``s(w)`` of the mechanism's contact at speeds in m/s (Thornton's
        ``epsilon_T(w / v_y)``): the table then holds every speed of the elastic law between
        its computed ones, the closed form at each and the rest interpolated
        (:mod:`restitution.laws.shaped_table`).

    Returns
    -------
    SILaw
        The table as a law of the grain against its partner.
    """
    from restitution.budget import format_duration
    from restitution.laws.below_route import Below
    from restitution.laws.routes.base import check_speed_count
    from restitution.laws.si_law import SILaw
    from restitution.limits.run_options import progress_of

    law = si.law
    v_all = np.asarray(law.v, dtype=float)
    idx = table_speeds(v_all, per_decade)
    v = v_all[idx]
    mid = _middles(v)
    count = v.size + mid.size
    check_speed_count(count, seconds_per_speed, f"the table of {words}")
    if note is not None:
        note(f"note: {words}: its law at every speed is tabulated now at {v.size} speeds and "
             f"the {mid.size} middles that measure the interpolation (about "
             f"{format_duration(count * seconds_per_speed)})")  # fmt: skip
    scale = si.speed_scale_m_s
    order = np.concatenate([v, mid])
    found = []
    with progress_of(progress).bar(count, f"{words}: speeds of its table") as meter:
        for x in order:
            found.append(points_at([float(x) * scale])[0])
            meter(1)
    at, between = found[: v.size], found[v.size :]
    # Below the first rebound (a grain that sticks) the table starts later; above the next
    # speed without one (a crushed contact) it stops.
    start = next((i for i, p in enumerate(at) if _served(p)), v.size)
    full = v.size
    keep = next((i for i in range(start, full) if not _served(at[i])), full)
    if keep - start < 2:
        raise InputError(
            f"{words}: fewer than two speeds of the elastic law have a rebound "
            f"({at[min(keep, v.size - 1)].note}); no law at every speed is tabulated"
        )
    reason = _why_stopped(at[keep]) if keep < full else None
    v, idx, at = v[start:keep], idx[start:keep], at[start:keep]
    mid, between = mid[start : keep - 1], between[start : keep - 1]
    if shape is not None:
        records, interval = shaped_records(law, idx, at, shape, scale, _parts)
        served = PchipInterpolator(np.log([r["v"] for r in records]),
                                   [r["epsilon"] for r in records])  # fmt: skip
        gap = _middle_gaps(served, mid, between)
        how = (f"computed at {v.size} speeds ({per_decade} a decade); at the {len(records)} "
               "speeds of the elastic law between them, its closed form and the rest "
               "interpolated")  # fmt: skip
    else:
        eps = np.array([p.epsilon for p in at], dtype=float)
        gap = _middle_gaps(PchipInterpolator(np.log(v), eps), mid, between)  # as served: LOG_V
        gap = np.maximum(gap, _elastic_gap(law, idx))
        elastic = law._records() if hasattr(law, "_records") else [{} for _ in law.v]
        records = []
        for i, (x, p) in enumerate(zip(v, at, strict=True)):
            record = {"v": float(x), "epsilon": float(p.epsilon),
                      "mechanism_err": float(p.epsilon_err),
                      "asymptotic_ok": bool(law.asymptotic_ok[idx[i]]), "computed": True,
                      **_parts(p)}  # fmt: skip
            if elastic[idx[i]].get("route") == QUASISTATIC_ROUTE:
                record["route"] = QUASISTATIC_ROUTE
            records.append(record)
        interval = np.minimum(np.arange(v.size), v.size - 2)
        how = f"tabulated at {v.size} speeds ({per_decade} a decade)"
    # A record inside an interval gains its interval's measured miss, a computed speed the
    # larger of the two intervals beside it.
    extra = gap[interval]
    for i, record in enumerate(records):
        k = interval[i]
        if record["computed"] and k > 0 and record["v"] == float(v[k]):
            extra[i] = max(extra[i], gap[k - 1])
    extra = GAP_FACTOR * extra
    for record, e in zip(records, extra, strict=True):
        record["epsilon_err"] = record["mechanism_err"] + float(e)
        record["interpolation_err"] = float(e)
    top = float(v[-1]) * scale
    stop = "" if reason is None else f"; served up to {top:.4g} m/s: above, {reason}"
    table = EpsilonLaw.from_records(
        float(law.nu),
        records,
        key="tabulated",
        parameters={
            **parameters,
            "per_decade": per_decade,
            "gap_factor": GAP_FACTOR,
            "largest_interpolation_err": float(extra.max()),
        },
        geometry=law.geometry,
        partner=law.partner,
    )
    table.metadata["mechanisms"] = list(mechanisms)
    table.metadata["interpolate_in"] = LOG_V
    table.metadata["source"] = (
        f"{si.law_source}, with {words}: {how} (what the interpolation misses measured at "
        f"every interval's middle){stop}"
    )
    below = Below(points_at, seconds_per_speed, words, zero_below=zero_below)
    return SILaw(si.grain, si.against, table, partner_grain=si.partner_grain, below=below)


def _middle_gaps(served, mid: np.ndarray, between) -> np.ndarray:
    """``|served - mechanism|`` at the middle of every interval of computed speeds, shape
    ``(len(mid),)``; a middle without a value (the rebound ends inside the interval) measures
    nothing, and its interval takes the largest measured one."""
    gap = np.array(
        [abs(float(served(math.log(m))) - p.epsilon) if _served(p) else np.nan
         for m, p in zip(mid, between, strict=True)]
    )  # fmt: skip
    if np.isnan(gap).any():
        fill = np.nanmax(gap) if np.isfinite(gap).any() else 0.0
        gap = np.where(np.isnan(gap), fill, gap)
    return gap


def _elastic_gap(law, idx: np.ndarray) -> np.ndarray:
    """What PCHIP in ``ln v`` through the elastic law's points ``idx`` misses of the elastic
    law at its own points inside each interval, shape ``(len(idx) - 1,)``: the structure of the
    waves' loss (the sphere's slow loss turns where the contact time beats against its modes)
    that one middle per interval can miss in the mechanism's, measured at no cost on the
    elastic law the mechanism adds its losses to."""
    v = np.asarray(law.v, dtype=float)
    eps = np.asarray(law.epsilon(v, outside="nan"), dtype=float)
    inside = slice(int(idx[0]), int(idx[-1]) + 1)
    v, eps = v[inside], eps[inside]
    miss = np.abs(PchipInterpolator(np.log(v[idx - idx[0]]), eps[idx - idx[0]])(np.log(v)) - eps)
    j = np.clip(np.searchsorted(v[idx - idx[0]], v, side="right") - 1, 0, idx.size - 2)
    out = np.zeros(idx.size - 1)
    np.maximum.at(out, j, miss)
    return out


def _why_stopped(p) -> str:
    """Why the table stops at the point ``p`` (the first without a rebound): its note's first
    clause."""
    return "no rebound" if p.epsilon == 0.0 else (p.note or "no value").split(";")[0]


def _parts(p) -> dict:
    """The numeric parts of a mechanism's point (``loss_plastic``, ``loss_viscous``,
    ``loss_waves``, ...), kept in its table record."""
    parts = dict(getattr(p, "parts", None) or ())
    return {
        k: float(x)
        for k, x in parts.items()
        if k.startswith("loss_") and isinstance(x, int | float) and not isinstance(x, bool)
    }


@dataclass(frozen=True)
class Coverage:
    """How a table's stated errors cover the mechanism computed at speeds between its own."""

    speeds_m_s: tuple[float, ...]
    misses: tuple[float, ...]
    """``|table - direct|`` at each speed."""
    stated: tuple[float, ...]
    """The table's error at each speed (its ``epsilon_err``)."""
    direct_err: tuple[float, ...]
    """The direct point's own error."""

    @property
    def covered(self) -> float:
        """Fraction of speeds whose miss lies within the table's stated error."""
        m, s = np.asarray(self.misses), np.asarray(self.stated)
        return float(np.mean(m <= s))

    @property
    def largest_ratio(self) -> float:
        """The largest miss over its stated error."""
        return float(np.max(np.asarray(self.misses) / np.asarray(self.stated)))


def coverage(table, points_at, speeds_m_s) -> Coverage:
    """The table ``table`` (an SILaw from :func:`mechanism_table`) against the mechanism's own
    points at ``speeds_m_s`` (those with a rebound and inside the table)."""
    w = np.asarray(speeds_m_s, dtype=float)
    direct = points_at(list(map(float, w)))
    eps = table.epsilon(w, outside="nan")
    err = table.epsilon_err(w, outside="nan")
    keep = [i for i, p in enumerate(direct) if _served(p) and np.isfinite(eps[i])]
    return Coverage(
        tuple(float(w[i]) for i in keep),
        tuple(abs(float(eps[i]) - direct[i].epsilon) for i in keep),
        tuple(float(err[i]) for i in keep),
        tuple(float(direct[i].epsilon_err) for i in keep),
    )
