"""A sphere's law on an elastic wall at every speed of its route's range, for exports and
constants (issue 42).

Units: the ball's reduced units (``E = rho = R = 1`` of its 3D constants); ``v`` in ``c``.

:func:`restitution.laws.route_law.wall_law` computes the asked speeds alone, served there and
nowhere between. Exports and constants need epsilon at every speed a grain meets, so
:func:`wall_grid_law` computes the wall's route on a grid: :data:`PER_DECADE` speeds a decade,
geometric, from :data:`SLOWEST` to the route's top (the half-space's reach,
:func:`restitution.quasistatic.half_space.half_space_reach`; on a plate the fastest speed where
Zener's model holds and the ball rebounds, found by bisection). Between two grid speeds the
law interpolates (PCHIP in ``v``); what that misses is measured, as for the sphere's low-speed
points (:func:`restitution.quasistatic.low_speed.interpolation_error`): the route is computed
at :data:`INTERIOR` more speeds inside every interval and each point's error gains the larger
deviation of PCHIP through the grid on its two sides. On the half-space the ball's own loss
oscillates with the speed (Rayleigh's phases ``omega tau / 2``) faster than a few speeds an
interval resolve: the interval's error gains the ball's envelope at its faster end
(:func:`restitution.quasistatic.half_space.ball_envelope`, every phase factor 1), a bound on
what PCHIP can miss of it (measured without it: deviations at speeds between the grid up to 3
times the measured gap). Below the slowest speed the exports
continue with the loss's leading form (:mod:`restitution.laws.exports.below`), above the top
they have no value.

The route's cost sets the grid: about 0.5 s a speed on the half-space and 0.3-1.5 s on a plate
(the ball's modes driven by the pulse); :func:`grid_seconds` estimates it.
"""

from __future__ import annotations

import copy
import math

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.production import low_speed_record
from restitution.laws.wall_route import (
    HALF_SPACE_ROUTE,
    PLATE_ROUTE,
    is_plate,
    route_at,
    route_top,
)

__all__ = ["INTERIOR", "PER_DECADE", "SLOWEST", "grid_seconds", "grid_speeds", "wall_grid_law"]

SLOWEST = 1e-6
"""The slowest grid speed (``c``): the sphere's low-speed points start there (5 mm/s for
steel); below it the exports' slow continuation carries the law to ``w = 0``."""

PER_DECADE = 6
"""Grid speeds per decade of ``v``."""

INTERIOR = 2
"""Speeds inside every grid interval at which the route is computed to measure what PCHIP
misses."""

HALF_SPACE_SECONDS = 0.6
"""Wall time of one speed of the half-space route on one core, seconds (0.45-0.6 s measured on
the project's 2-core machine, the ball's Rayleigh estimate over its 1600 modes)."""

PLATE_SECONDS = 1.0
"""The same on a plate, seconds (0.3-1.5 s measured: the ball's modes driven by the plate's
force history, longest at the slowest speeds)."""


def grid_speeds(top: float) -> np.ndarray:
    """The grid from :data:`SLOWEST` to ``top`` (``c``), :data:`PER_DECADE` a decade."""
    if not top > SLOWEST:
        raise InputError(f"the route's top {top:g} c lies below its slowest grid speed {SLOWEST:g}")
    n = max(2, math.ceil(PER_DECADE * math.log10(top / SLOWEST)) + 1)
    return np.geomspace(SLOWEST, top, n)


def grid_seconds(nu: float, wall) -> float:
    """Estimated wall time of :func:`wall_grid_law`, seconds (module docs)."""
    n = grid_speeds(route_top(nu, wall, SLOWEST)).size
    per = PLATE_SECONDS if is_plate(wall) else HALF_SPACE_SECONDS
    return (n + INTERIOR * (n - 1)) * per


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
    from restitution.limits.run_options import progress_of

    top = route_top(nu, wall, SLOWEST)
    v = grid_speeds(top)
    frac = np.arange(1, INTERIOR + 1) / (INTERIOR + 1)
    inside = (v[:-1, None] * (v[1:, None] / v[:-1, None]) ** frac[None, :]).ravel()
    route = route_at(nu, wall)
    bars = progress_of(progress)
    results = []
    with bars.bar(v.size + inside.size, "speeds of the wall's route") as meter:
        for x in (*v, *inside):
            results.append(route(float(x)))
            meter(1)
    at, between = results[: v.size], results[v.size :]
    loss = np.array([r[1] for r in at])
    through = PchipInterpolator(v, loss)(inside)
    gap = np.abs(through - np.array([r[1] for r in between])).reshape(-1, INTERIOR).max(axis=1)
    # The ball's part swings between the grid speeds below its envelope (module docs).
    gap = gap + np.array([r[3].get("ball_envelope", 0.0) for r in at[1:]])
    gaps = np.zeros(v.size)
    gaps[:-1] = gap
    gaps[1:] = np.maximum(gaps[1:], gap)
    records = [
        low_speed_record(float(x), eps, lo, err, float(g), details)
        for x, (eps, lo, err, details), g in zip(v, at, gaps, strict=True)
    ]
    what = PLATE_ROUTE if is_plate(wall) else HALF_SPACE_ROUTE
    parameters = {
        "route": what,
        "grid": {"slowest": SLOWEST, "per_decade": PER_DECADE, "interior": INTERIOR},
        "top": top,
        "largest_interpolation_gap": float(gap.max()) if gap.size else 0.0,
        "v_min": float(v[0]),
        "v_max": float(v[-1]),
    }
    law = EpsilonLaw.from_records(
        nu, records, key="low_speed", parameters=parameters, geometry=SPHERE.geometry
    )
    law.metadata["wall"] = wall.to_dict()
    law.metadata["source"] = (
        f"computed now on a grid of {v.size} speeds ({PER_DECADE} a decade, the PCHIP error "
        f"measured at {INTERIOR} speeds inside every interval): a sphere on an elastic "
        + ("plate" if is_plate(wall) else "half-space")
    )
    return law
