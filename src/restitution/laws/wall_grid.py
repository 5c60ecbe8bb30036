"""A sphere's law on an elastic wall at every speed of its route's range, for exports and
constants (issue 42).

Units: the ball's reduced units (``E = rho = R = 1`` of its 3D constants); ``v`` in ``c``.

:func:`restitution.laws.route_law.wall_law` computes the asked speeds alone, served there and
nowhere between. Exports and constants need epsilon at every speed a grain meets, so
:func:`wall_grid_law` computes the wall's route on a grid: :data:`PER_DECADE` speeds a decade,
geometric, from :data:`SLOWEST` to the route's top (the half-space's reach,
:func:`restitution.quasistatic.half_space.half_space_reach`; on a plate the fastest speed where
Zener's model holds, the ball rebounds and the value is informative, found by bisection:
:func:`restitution.laws.wall_route.route_top`). Between two grid speeds the law interpolates
(PCHIP in ``v``); what that misses is measured, as for the sphere's low-speed points
(:func:`restitution.quasistatic.low_speed.interpolation_error`): the route is computed at
:data:`INTERIOR` more speeds inside every interval and each point's error gains the larger
deviation of PCHIP through the grid on its two sides, of the loss and of the route's own error
together (the served error is interpolated too: between the grid speeds of a 3 mm glass plate
the interpolated own error fell below the route's by more than the loss's gap). On the
half-space the ball's own loss oscillates with the speed (Rayleigh's phases ``omega tau / 2``)
faster than a few speeds an interval resolve: the interval's error gains the ball's envelope
at its faster end (:func:`restitution.quasistatic.half_space.ball_envelope`, every phase factor
1), a bound on what PCHIP can miss of it (measured without it: deviations at speeds between the
grid up to 3 times the measured gap). Below the slowest speed the exports continue with the
loss's leading form (:mod:`restitution.laws.exports.below`), above the top they have no value.

The route's cost sets the grid: about 0.5 s a speed on the half-space and 0.3-1.5 s on a plate
(the ball's modes driven by the pulse); :func:`grid_seconds` estimates it
(:func:`restitution.laws.wall_route.route_cost`, speed by speed), and :func:`wall_grid_law`
refuses a grid beyond the bound of one run before it starts.

**Many asked speeds** (:func:`tabulated_records`): the law at the asked speeds
(:func:`restitution.laws.route_law.wall_law`) computes each alone while they are fewer than
the speeds of a grid spanning them (:func:`grid_evaluations`); beyond, the route is computed
on that grid (the same :data:`PER_DECADE` and :data:`INTERIOR`) and the asked speeds are
interpolated (PCHIP in ``ln v``), each with :data:`GAP_FACTOR` times the measured gap of its
interval in its error (1000 speeds from 0.01 to 10 m/s on glass: 55 evaluations instead of
1000, 20 s instead of about 800 s on the block, 27 s instead of about 470 s on a plate).
"""

from __future__ import annotations

import copy
import math

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.low_speed import low_speed_record
from restitution.laws.partners.base import partner_of_body
from restitution.laws.wall_route import (
    HALF_SPACE_ROUTE,
    PLATE_ROUTE,
    is_plate,
    route_at,
    route_top,
)

__all__ = [
    "GAP_FACTOR",
    "INTERIOR",
    "PER_DECADE",
    "SLOWEST",
    "grid_evaluations",
    "grid_seconds",
    "grid_speeds",
    "route_grid_law",
    "tabulated_records",
    "wall_grid_law",
]

SLOWEST = 1e-6
"""The slowest grid speed (``c``): the sphere's low-speed points start there (5 mm/s for
steel); below it the exports' slow continuation carries the law to ``w = 0``."""

PER_DECADE = 6
"""Grid speeds per decade of ``v``."""

INTERIOR = 2
"""Speeds inside every grid interval at which the route is computed to measure what PCHIP
misses."""


def grid_speeds(top: float, slowest: float = SLOWEST) -> np.ndarray:
    """The grid from ``slowest`` (default :data:`SLOWEST`) to ``top`` (``c``),
    :data:`PER_DECADE` a decade."""
    if not top > slowest:
        raise InputError(f"the route's top {top:g} c lies below its slowest grid speed {slowest:g}")
    n = max(2, math.ceil(PER_DECADE * math.log10(top / slowest)) + 1)
    return np.geomspace(slowest, top, n)


def _interior(v: np.ndarray) -> np.ndarray:
    """:data:`INTERIOR` speeds inside every interval of ``v`` (geometric), shape
    ``(INTERIOR (K - 1),)``."""
    frac = np.arange(1, INTERIOR + 1) / (INTERIOR + 1)
    return (v[:-1, None] * (v[1:, None] / v[:-1, None]) ** frac[None, :]).ravel()


def grid_evaluations(slowest: float, top: float) -> list[float]:
    """The speeds (``c``) the route is computed at for a grid from ``slowest`` to ``top``: the
    grid's and :data:`INTERIOR` inside each interval."""
    v = grid_speeds(top, slowest)
    return [*map(float, v), *map(float, _interior(v))]


def grid_seconds(nu: float, wall) -> float:
    """Estimated wall time of :func:`wall_grid_law`, seconds (module docs): the route's cost
    at every speed it computes (:func:`restitution.laws.wall_route.route_cost`)."""
    from restitution.laws.wall_route import route_cost

    speeds = grid_evaluations(SLOWEST, route_top(nu, wall, SLOWEST))
    return float(route_cost(nu, wall, speeds)[0].sum())


def _measured(route, v: np.ndarray, meter=None, *, log: bool = False):
    """The route at the grid ``v`` and inside its intervals: ``(at, gap)``, ``at`` the route's
    results at ``v``, ``gap`` (shape (K-1,)) what PCHIP through them (in ``v``, or in ``ln v``
    with ``log``) misses in each interval: the largest deviation at the :data:`INTERIOR`
    speeds of the loss and of the route's own error together (the served error is interpolated
    too: on a plate its model error bends where its largest ratio changes), plus the ball's
    envelope at the interval's faster end (module docs)."""
    inside = _interior(v)
    results = []
    for x in (*v, *inside):
        results.append(route(float(x)))
        if meter is not None:
            meter(1)
    at, between = results[: v.size], results[v.size :]
    x, y = (np.log(v), np.log(inside)) if log else (v, inside)
    missed = sum(
        np.abs(PchipInterpolator(x, [r[k] for r in at])(y) - [r[k] for r in between])
        for k in (1, 2)  # the loss and its own error
    )
    gap = missed.reshape(-1, INTERIOR).max(axis=1)
    # The ball's part swings between the grid speeds below its envelope (module docs).
    return at, gap + np.array([r[3].get("ball_envelope", 0.0) for r in at[1:]])


GAP_FACTOR = 2.0
"""What PCHIP misses at an asked speed interpolated from the grid (:func:`tabulated_records`):
this times the deviation measured at the :data:`INTERIOR` speeds of its interval. Measured at
58 speeds between them on a 3 mm glass plate under a 5 mm steel ball (0.01-10 m/s): the
deviation reached 1.1 times the measured one."""


def tabulated_records(route, speeds) -> list[dict]:
    """Law points at ``speeds`` (``c``, increasing, at least two) interpolated from the route
    on a grid spanning them (module docs): the loss and the route's own error by PCHIP in
    ``ln v`` (the grid is geometric; the gap measured with the same), epsilon
    ``sqrt(1 - loss)``, the shares linear in ``ln v``, and :data:`GAP_FACTOR` times the
    larger measured gap of the speed's interval and its neighbours added to its error (none at
    the grid's ends, the slowest and fastest asked speeds, computed there). ``route`` is
    :func:`restitution.laws.wall_route.route_at`'s; what it raises (a speed where it does not
    hold) passes through."""
    x = np.asarray(sorted({float(s) for s in speeds}), dtype=float)
    v = grid_speeds(float(x[-1]), float(x[0]))
    at, gap = _measured(route, v, log=True)
    loss = PchipInterpolator(np.log(v), np.array([r[1] for r in at]))(np.log(x))
    own = PchipInterpolator(np.log(v), np.array([r[2] for r in at]))(np.log(x))
    j = np.clip(np.searchsorted(v, x, side="right") - 1, 0, v.size - 2)
    on_grid = np.isclose(x, v[j], rtol=1e-12, atol=0.0) | np.isclose(
        x, v[j + 1], rtol=1e-12, atol=0.0
    )
    # An interval's gap, or its neighbour's where larger: the deviation measured at two
    # speeds of an interval may pass near zero where it is larger between them.
    near = gap.copy()
    near[1:] = np.maximum(near[1:], gap[:-1])
    near[:-1] = np.maximum(near[:-1], gap[1:])
    shares = np.array([r[3].get("shares", [0.0, 0.0]) for r in at], dtype=float)
    out = []
    for i, s in enumerate(x):
        t = math.log(s / v[j[i]]) / math.log(v[j[i] + 1] / v[j[i]])
        split = (1.0 - t) * shares[j[i]] + t * shares[j[i] + 1]
        details = {"shares": [float(a) for a in split], "tabulated": True}
        g = 0.0 if on_grid[i] else GAP_FACTOR * float(near[j[i]])
        lo = float(loss[i])
        out.append(low_speed_record(float(s), math.sqrt(max(1.0 - lo, 0.0)), lo, float(own[i]),
                                    g, details))  # fmt: skip
    return out


def wall_grid_law(nu: float, wall, *, progress=False) -> EpsilonLaw:
    """The law of a sphere (``nu``) on ``wall`` at every speed from :data:`SLOWEST` to its
    route's top (module docs): quasistatic points, interpolated between them with the measured
    PCHIP error in each point's error. Kept for the process (a copy each call): a law of the
    same ball and wall is not computed twice."""
    key = (float(nu), wall)
    if key not in _KEPT:
        if len(_KEPT) >= 8:
            _KEPT.pop(next(iter(_KEPT)))
        _KEPT[key] = _grid_law(float(nu), wall, progress)
    return copy.deepcopy(_KEPT[key])


_KEPT: dict = {}
"""The grid laws of this process, by ``(nu, wall)`` (walls are frozen dataclasses)."""


def _grid_law(nu: float, wall, progress) -> EpsilonLaw:
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.laws.wall_route import check_route_cost

    top = route_top(nu, wall, SLOWEST)
    check_route_cost(nu, wall, grid_evaluations(SLOWEST, top), "speeds of the wall's grid")
    what = PLATE_ROUTE if is_plate(wall) else HALF_SPACE_ROUTE
    law = route_grid_law(route_at(nu, wall), nu, top, geometry=SPHERE.geometry, name=what,
                         what="speeds of the wall's route", progress=progress)  # fmt: skip
    kind = partner_of_body(wall)
    kind.write(law, wall)
    law.metadata["source"] = (
        f"computed now on a grid of {law.v.size} speeds ({PER_DECADE} a decade, the PCHIP error "
        f"measured at {INTERIOR} speeds inside every interval): a sphere on an elastic " + kind.name
    )
    return law


def route_grid_law(
    route, nu: float, top: float, *, geometry: str, name: str, partner=None, what: str,
    progress=False,
) -> EpsilonLaw:  # fmt: skip
    """The law of a low-speed ``route`` (``v -> (epsilon, loss, loss_err, details)``, as
    :func:`restitution.laws.wall_route.route_at`'s) on the grid from :data:`SLOWEST` to ``top``
    (``c``): quasistatic points, each with the larger measured PCHIP gap of its two intervals in
    its error (module docs). ``name`` is the route's, ``what`` the progress bar's words; the
    caller checks the cost first."""
    from restitution.limits.run_options import progress_of

    v = grid_speeds(top)
    bars = progress_of(progress)
    with bars.bar(v.size + INTERIOR * (v.size - 1), what) as meter:
        at, gap = _measured(route, v, meter)
    gaps = np.zeros(v.size)
    gaps[:-1] = gap
    gaps[1:] = np.maximum(gaps[1:], gap)
    records = [
        low_speed_record(float(x), eps, lo, err, float(g), details)
        for x, (eps, lo, err, details), g in zip(v, at, gaps, strict=True)
    ]
    parameters = {
        "route": name,
        "grid": {"slowest": SLOWEST, "per_decade": PER_DECADE, "interior": INTERIOR},
        "top": top,
        "largest_interpolation_gap": float(gap.max()) if gap.size else 0.0,
        "v_min": float(v[0]),
        "v_max": float(v[-1]),
    }
    return EpsilonLaw.from_records(
        nu, records, key="low_speed", parameters=parameters, geometry=geometry, partner=partner
    )
