"""A grid's collisions checked against their step bound before any worker starts.

Each collision refuses, in its worker, work beyond ``max_steps``
(:func:`restitution.dynamics.steps.check_work`); a grid at a speed no collision can resolve
(``epsilon --v 1e-9``) then started a cluster, built every mode set and failed every point
(issue 64: ten failing collisions and 5 GB before exit 1). :func:`check_grid` runs the same
estimate first, in this process, on the grid's smallest mode set (the cheapest to build; a
larger one only needs more steps), and refuses the grid in one line naming the speed.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from restitution.bodies.kinds import body_kind
from restitution.errors import InputError
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import point_modes

__all__ = ["SLOWEST_COLLISION", "check_grid"]

SLOWEST_COLLISION = 1e-4
"""Slowest speed (``c``) of the shipped laws' collisions; slower ones are the low-speed
theory's (``restitution quasistatic``, and ``restitution law``, which serves them)."""


def check_grid(specs: Sequence[PointSpec], store=None, option: str = "--v") -> None:
    """Refuse the grid ``specs`` when a collision of its smallest mode count would exceed its
    step or memory bound (:func:`restitution.dynamics.steps.check_work`). The store is checked
    first (a store that cannot be written is the first thing to fix), and only the points it
    does not hold yet are checked.

    Raises
    ------
    InputError
        Naming ``option`` (the speed's option), the point, the estimate and what to do.
    StoreError, CacheError
        When the store cannot be written (the message says what to do).
    """
    from restitution.dynamics.collision import CollisionSettings
    from restitution.dynamics.steps import check_work

    with Store(store) as db:
        status = db.status(list(dict.fromkeys(specs)))
        specs = [s for s in specs if status.get(s.key()) is None]
        if specs:
            db.check_writable()
    if not specs:
        return
    smallest = min(s.n_modes for s in specs)
    groups: dict = {}
    for s in specs:
        if s.n_modes == smallest:
            groups.setdefault(s.group, []).append(s)
    largest = max(s.n_modes for s in specs)
    for group in groups.values():
        first = group[0]
        settings = CollisionSettings(integrator=first.integrator, **dict(first.options))
        modes = point_modes(first)
        # The fastest mode sets the step ("body" limit); it grows as N^(1/d) (Weyl).
        growth = (largest / smallest) ** (1.0 / body_kind(first.geometry).dimension)
        for s in sorted(group, key=lambda s: (s.v, -s.alpha)):
            try:
                v, alpha = np.array([s.v]), np.array([s.alpha])
                est = check_work(modes, v, alpha, settings, first.contact_law)
                steps = est.steps * growth
                if est.limit == "body" and steps > settings.max_steps:
                    raise InputError(
                        f"at N = {largest} each collision would need about {steps:.2g} time "
                        f"steps ({est.steps:.2g} at N = {smallest}, the fastest mode's step "
                        f"scaled as N^(1/{body_kind(first.geometry).dimension})), more than "
                        f"max_steps = {settings.max_steps}; use fewer modes (--modes)"
                    )
            except InputError as exc:
                slow = ""
                if s.v < SLOWEST_COLLISION:
                    slow = (
                        f"; collisions resolve v >= about {SLOWEST_COLLISION:g} c, slower "
                        f"impacts are the low-speed theory's: `restitution quasistatic "
                        f"--geometry {s.geometry} --nu {s.nu:g} --v {s.v:g}`, or `restitution "
                        "law`, which serves them in SI units"
                    )
                raise InputError(
                    f"{option} {s.v:g}: no collision of the grid is run (alpha = {s.alpha:g}, "
                    f"N = {s.n_modes}): {exc}{slow}"
                ) from None
