"""Speeds below a law's slowest point, answered by the law's low-speed route: what
:meth:`~restitution.laws.si_law.SILaw.epsilon` and :meth:`~restitution.laws.si_law.SILaw.points`
serve there, as the command line does.

Units: the law's reduced units (``v`` in ``c``).

A shipped law's slowest points come from its body's low-speed route (the disk's slow-impact
model, the sphere's Rayleigh estimate, a pair's); below them the same route holds, and answers
in about half a second a speed (:func:`restitution.laws.si_point.low_speed_at`). So that an
array of a million speeds costs seconds and not days, the speeds are answered two ways
(:func:`below_values`):

* **few speeds** (no more than a grid spanning them computes,
  :func:`restitution.laws.wall_grid.grid_evaluations`): each computed alone, as before;
* **many**: the route on the grid from the slowest asked speed to the law's slowest point
  (:data:`~restitution.laws.wall_grid.PER_DECADE` a decade and
  :data:`~restitution.laws.wall_grid.INTERIOR` speeds inside every interval), the asked speeds
  interpolated (PCHIP in ``ln v``) with :data:`~restitution.laws.wall_grid.GAP_FACTOR` times the
  measured gap of their interval in their error (:func:`restitution.laws.wall_grid.
  tabulated_records`, the elastic wall's many-speed path).

A mechanism's table (:mod:`restitution.laws.tabulated`, the damped law's) is continued below
its slowest speed by the mechanism itself (:class:`Below`: its points at asked speeds, the same
two ways), not by the elastic route, which knows none of its losses.

Either is refused beyond :data:`~restitution.laws.si_point.BELOW_BUDGET_S` of estimated time
(one line with the numbers); the last few answers are kept for the law object, so ``epsilon``
and ``epsilon_err`` of one array compute once.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from restitution.bodies.kinds import body_kind
from restitution.budget import format_duration
from restitution.errors import InputError
from restitution.laws.si_point import BELOW_BUDGET_S, low_speed_at

__all__ = ["Below", "below_seconds", "below_values"]


def _each_seconds(geometry: str) -> float:
    plan = body_kind(geometry).production
    return getattr(plan, "seconds_per_low_point", 1.0) or 1.0


def _evaluations(key: np.ndarray, lowest: float) -> tuple[int, bool]:
    """``(count, alone)``: how many route evaluations answer the speeds ``key`` (unique,
    increasing, ``c``) below ``lowest``, and whether each is computed alone."""
    from restitution.laws.wall_grid import grid_evaluations

    grid = len(grid_evaluations(float(key[0]), lowest))
    return (key.size, True) if key.size <= grid else (grid, False)


def below_seconds(law, key: np.ndarray) -> float:
    """Estimated wall time of :func:`below_values` for the speeds ``key``, seconds."""
    count, alone = _evaluations(key, float(law.v[0]))
    # Each alone: the route's four-run estimate a speed, as the points have always taken.
    return count * _each_seconds(law.geometry) * (4.0 if alone else 1.0)


def below_values(law, route, key: np.ndarray) -> tuple[np.ndarray, np.ndarray, list]:
    """epsilon, its error and the two bodies' shares (``None`` where not split) at the speeds
    ``key`` (unique, increasing, ``c``, below ``law``'s slowest point) by ``route`` (``(name,
    nu, partner)`` of :meth:`SILaw._route`); module docs. Raises :class:`InputError` beyond
    :data:`BELOW_BUDGET_S`."""
    seconds = below_seconds(law, key)
    if seconds > BELOW_BUDGET_S:
        raise InputError(
            f"{key.size} speed(s) below the law's slowest point need its low-speed route for "
            f"about {format_duration(seconds)} (bound {format_duration(BELOW_BUDGET_S)}); ask "
            "for speeds closer to the law's range (fewer decades below it), or pass "
            "outside='nan'"
        )
    _, nu, partner = route
    geometry = law.geometry
    count, alone = _evaluations(key, float(law.v[0]))
    if alone:
        found = [low_speed_at(geometry, nu, partner, float(v)) for v in key]
        return (
            np.array([f[0] for f in found]),
            np.array([f[1] for f in found]),
            [f[2] for f in found],
        )
    from restitution.laws.low_speed import low_speed_points
    from restitution.laws.wall_grid import tabulated_records

    def at(v: float):
        (rec,), _ = low_speed_points(nu, [v], geometry=geometry, partner=partner)
        shares = {"shares": rec["shares"]} if "shares" in rec else {}
        return rec["epsilon"], rec["energy_loss"], rec["estimate_err"], shares

    lowest = float(law.v[0])
    records = tabulated_records(at, [*map(float, key), lowest])
    by_v = {float(r["v"]): r for r in records}
    rows = [by_v[float(v)] for v in key]
    shares = [_shares(r) for r in rows]
    return (
        np.array([r["epsilon"] for r in rows], dtype=float),
        np.array([r["epsilon_err"] for r in rows], dtype=float),
        shares,
    )


def _shares(record: dict):
    split = record.get("shares")
    if not split or len(split) != 2 or not sum(split) > 0:
        return None
    first = float(split[0]) / float(sum(split))
    return first, 1.0 - first


@dataclass(frozen=True)
class Below:
    """A mechanism's own points below its table's slowest speed (module docs)."""

    points_at: Callable
    """The mechanism's points at a list of speeds in m/s (``epsilon``, ``epsilon_err``)."""
    seconds_per_speed: float
    """Wall time of one of its speeds, seconds."""
    words: str
    """What answers there, for the points' notes (``"the damped law"``)."""
    batch: bool = False
    """Whether ``points_at`` takes many speeds at once at the cost of a grid (the damped law:
    its viscous table and the elastic law's own continuation): then it is asked once."""
    zero_below: float | None = None
    """A speed (m/s) below which there is no rebound (a sticking speed): ``epsilon = 0 +- 0``
    there, not computed."""

    def _computed(self, key: np.ndarray, scale: float) -> np.ndarray:
        """Which of ``key`` are computed (not below :attr:`zero_below`)."""
        if self.zero_below is None:
            return np.ones(key.shape, bool)
        return key * scale >= self.zero_below

    def seconds(self, key: np.ndarray, lowest: float, scale: float = 1.0) -> float:
        """Estimated wall time of :meth:`values`, seconds."""
        key = key[self._computed(key, scale)] if self.zero_below is not None else key
        return _evaluations(key, lowest)[0] * self.seconds_per_speed if key.size else 0.0

    def values(self, key: np.ndarray, scale: float, lowest: float):
        """``(epsilon, error, shares)`` at the reduced speeds ``key`` (unique, increasing,
        below ``lowest``; ``w = scale v``), as :func:`below_values` answers an elastic law;
        ``epsilon = 0 +- 0`` below :attr:`zero_below`."""
        computed = self._computed(key, scale)
        if not computed.all():
            eps, err = np.zeros(key.size), np.zeros(key.size)
            if computed.any():
                e, d, _ = self.values(key[computed], scale, lowest)
                eps[computed], err[computed] = e, d
            return eps, err, [None] * key.size
        seconds = self.seconds(key, lowest)
        if seconds > BELOW_BUDGET_S:
            raise InputError(
                f"{key.size} speed(s) below the table's slowest point need {self.words} for "
                f"about {format_duration(seconds)} (bound {format_duration(BELOW_BUDGET_S)}); "
                "ask for speeds closer to its range, or pass outside='nan'"
            )
        count, alone = _evaluations(key, lowest)
        if alone or self.batch:
            found = self.points_at([float(v) * scale for v in key])
            eps = np.array([np.nan if p.epsilon is None else p.epsilon for p in found], float)
            err = np.array([np.nan if p.epsilon_err is None else p.epsilon_err for p in found])
            return eps, err, [None] * key.size
        from restitution.laws.wall_grid import tabulated_records

        def at(v: float):
            p = self.points_at([v * scale])[0]
            if p.epsilon is None:
                raise InputError(f"{self.words}: no value at {v * scale:.4g} m/s ({p.note})")
            return p.epsilon, 1.0 - p.epsilon**2, 2.0 * p.epsilon * p.epsilon_err, {}

        records = tabulated_records(at, [*map(float, key), lowest])
        by_v = {float(r["v"]): r for r in records}
        rows = [by_v[float(v)] for v in key]
        return (
            np.array([r["epsilon"] for r in rows], dtype=float),
            np.array([r["epsilon_err"] for r in rows], dtype=float),
            [None] * key.size,
        )
