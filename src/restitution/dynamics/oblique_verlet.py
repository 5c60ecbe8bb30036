"""What the oblique routes that take Verlet steps share (the microslip route,
:mod:`restitution.dynamics.oblique_microslip`, and the residual route,
:mod:`restitution.dynamics.oblique_residual`): the step's settings' checks, the stiffness
ceiling that plans the step, the plan repeated when a run meets a larger bound, and the time to
cross the wall's tail.

Units as :mod:`restitution.dynamics.oblique`: ``E = rho = R = 1`` of the grain, times in ``R /
c``.

**The plan.** Velocity Verlet is stable for ``dt < 2 / omega_max``; the wall's (and a
tangential spring's) stiffness is bounded by its ``M^-1``-weighted trace (module docs of
:mod:`~restitution.dynamics.oblique_microslip`). With the wall force ``sum e_j = alpha V`` at most
``alpha E0``, ``alpha^2 E0`` times :func:`stiffness_ceiling` bounds the whole run. A run is first
planned for :data:`PILOT` of that ceiling (the wall energy's peak is a small part of ``E0``);
one that meets a larger bound raises :class:`Unstable` and is repeated at the ceiling (or
:data:`REPLAN` times the bound met, if larger), at most ``retries`` times
(:func:`run_planned`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from restitution.dynamics.contact.exponential import STOP_LOG
from restitution.dynamics.run import CollisionError
from restitution.errors import InputError, real

__all__ = [
    "PILOT",
    "REPLAN",
    "Unstable",
    "approach_time",
    "check_step_settings",
    "left_the_wall",
    "planned_step",
    "run_planned",
    "stiffness_ceiling",
]

REPLAN = 1.5
"""A run that met a bound above its plan is repeated at this many times that bound."""
PILOT = 0.1
"""The first plan, of the ceiling: the wall energy's peak is a small part of ``E0``."""
_PLAN_REACH = 0.5  # nodes within this of the wall at rest plan the step (60 degrees about the pole)
_PLAN_MARGIN = 1.2


class Unstable(Exception):
    """The stiffness bound exceeded the plan: repeat with a smaller step."""

    def __init__(self, bound: float):
        super().__init__(bound)
        self.bound = bound


def check_step_settings(step_safety, max_steps) -> None:
    """Refuse a ``step_safety`` outside (0, 1) or ``max_steps`` below 1, in one line."""
    s = real(step_safety, "step_safety", "in (0, 1)")
    if not 0.0 < s < 1.0:
        raise InputError(f"step_safety must lie in (0, 1), got {s}")
    if int(max_steps) < 1:
        raise InputError(f"max_steps must be at least 1, got {max_steps}")


def approach_time(G, v_n: float) -> float:
    """Time to cross the wall's tail from the start to the undeformed contact, ``R / c``
    (``G`` a :class:`~restitution.dynamics.oblique.Grain`)."""
    return (-1.0 - G.start_position(0.5 * G.m * v_n**2)) / v_n


def stiffness_ceiling(G, kappa: float = 0.0) -> float:
    """``max_j (|a_j|^2 + kappa |b_j|^2)`` over the nodes within ``_PLAN_REACH`` of the wall
    at rest, times ``_PLAN_MARGIN``: the wall's normal term and a tangential spring ``kappa``
    times as stiff (module docs)."""
    rest = np.zeros(G.N)
    _, _, X, Yr, _, J = G.nodes.jacobian(-1.0, 0.0, rest, rest, 0.0, -_PLAN_REACH)
    nX, nY = J.norms()
    a2 = 1.0 / G.m + Yr**2 / G.inertia + nX / G.m
    b2 = 1.0 / G.m + (X + 1.0) ** 2 / G.inertia + nY / G.m
    return _PLAN_MARGIN * float(np.max(a2 + kappa * b2))


def run_planned(run: Callable[[float], object], ceiling: float, retries: int, advice: str):
    """``run(plan)`` from :data:`PILOT` of ``ceiling``, repeated on :class:`Unstable` (module
    docs); refused with ``advice`` after ``retries`` plans."""
    plan = PILOT * ceiling
    for _ in range(retries):
        try:
            return run(plan)
        except Unstable as exc:
            plan = max(ceiling, REPLAN * exc.bound) if plan < ceiling else REPLAN * exc.bound
    raise CollisionError(f"the Verlet step did not settle after {retries} plans; {advice}")


def left_the_wall(G, x0, th, Q, vx, vy, om, Qd, alpha: float) -> bool:
    """Whether the grain moves away (``vx < 0``) and even its free vibration cannot bring a node
    within ``STOP_LOG / alpha`` of the wall (the oblique routes' stop)."""
    if vx >= 0.0:
        return False
    y = np.concatenate(([x0, th], Q, [vx, vy, om], Qd))
    return -(x0 + 1.0 + G.free_reach(y)) > STOP_LOG / alpha


def planned_step(step_safety: float, wmax2: float, plan: float) -> float:
    """``step_safety * 2 / omega_max`` for the modes' ``omega_max^2 = wmax2`` and the plan."""
    return step_safety * 2.0 / math.sqrt(wmax2 + plan)
