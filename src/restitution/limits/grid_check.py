"""A grid's collisions checked against their step bound before any worker starts.

Each collision refuses, in its worker, work beyond ``max_steps``
(:func:`restitution.dynamics.steps.check_work`); a grid at a speed no collision can resolve
(``epsilon --v 1e-9``) then started a cluster, built every mode set and failed every point
(issue 64: ten failing collisions and 5 GB before exit 1). :func:`check_grid` runs the same
estimate first, in this process, on the grid's smallest mode set (the cheapest to build; a
larger one only needs more steps), and refuses the grid in one line naming the speed.

A body's modes have a reach of their own (the sphere's near ``nu = 0.5``, where its Bessel
functions underflow: 2400 modes up to ``nu ~ 0.4996``, 19200 up to ``nu ~ 0.46``); beyond it
every collision of a window fails in its worker, one batch after another (the sphere's
production at ``nu = 0.4999``: 612 failed collisions in 12 minutes). :func:`check_mode_sets`
builds each mode set of a grid first, smallest first, and refuses the grid in one line naming
the window.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from restitution import budget
from restitution.bodies.kinds import body_kind
from restitution.errors import InputError
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import point_modes
from restitution.status import Status

__all__ = ["SLOWEST_COLLISION", "GridWork", "check_grid", "check_mode_sets"]

SLOWEST_COLLISION = 1e-4
"""Slowest speed (``c``) of the shipped laws' collisions; slower ones are the low-speed
theory's (``restitution quasistatic``, and ``restitution law``, which serves them)."""


@contextlib.contextmanager
def _interrupt_deferred() -> Iterator[None]:
    """Ctrl-C held back until the block ends, then raised: the block builds modes and compiles
    numba's kernels in this process, and a KeyboardInterrupt raised inside llvmlite's ctypes
    callback is printed as "Exception ignored" and lost (the sweep then ran to its end). A second
    Ctrl-C raises at once. Only where Ctrl-C raises KeyboardInterrupt (Python's default handler,
    in the main thread)."""
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGINT) is not signal.default_int_handler
    ):
        yield
        return
    got: list[int] = []

    def hold(signum, frame) -> None:
        if got:  # pressed again: the user insists, stop at once
            raise KeyboardInterrupt
        got.append(signum)

    signal.signal(signal.SIGINT, hold)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    if got:
        raise KeyboardInterrupt


def check_grid(specs: Sequence[PointSpec], store=None, option: str = "--v") -> GridWork:
    """Refuse the grid ``specs`` when a collision of its smallest mode count would exceed its
    step or memory bound (:func:`restitution.dynamics.steps.check_work`). The store is checked
    first (a store that cannot be written is the first thing to fix), and only the points it
    does not hold yet are checked; returns their count and estimated time.

    Raises
    ------
    InputError
        Naming ``option`` (the speed's option), the point, the estimate and what to do.
    StoreError, CacheError
        When the store cannot be written (the message says what to do).
    """
    with _interrupt_deferred():
        return _check_grid(specs, store, option)


def _check_grid(specs: Sequence[PointSpec], store, option: str) -> GridWork:
    from restitution.dynamics.collision import CollisionSettings
    from restitution.dynamics.steps import check_work

    with Store(store) as db:
        status = db.status(list(dict.fromkeys(specs)))
        specs = [s for s in specs if status.get(s.key()) is None]
        if specs:
            db.check_writable()
    if not specs:
        return GridWork(0, 0.0)
    smallest = min(s.n_modes for s in specs)
    counts = sorted({s.n_modes for s in specs})
    seconds = 0.0
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
                for n in counts:  # the same collision at every mode count of the grid
                    grown = (n / smallest) ** (1.0 / body_kind(first.geometry).dimension)
                    at_n = est.steps * (grown if est.limit == "body" else 1.0)
                    seconds += budget.collision_seconds(at_n, n)
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
    return GridWork(len(specs), seconds)


@dataclass(frozen=True)
class GridWork:
    """What a grid leaves to compute (:func:`check_grid`).

    Attributes
    ----------
    collisions : int
        Points the store does not hold.
    seconds : float
        Their estimated time on one core (:func:`restitution.budget.collision_seconds` of each
        collision's estimated steps; the mode sets' building not counted).
    """

    collisions: int
    seconds: float

    def words(self) -> str:
        """One line for the user."""
        return (
            f"{self.collisions} collisions to compute, their steps about "
            f"{budget.format_duration(self.seconds)} of one core (estimated; starting the "
            "workers and building the modes come on top)"
        )


def check_mode_sets(specs: Sequence[PointSpec], store=None) -> None:
    """Build every mode set of the grid ``specs`` that its points not yet stored need, smallest
    first, through the mode cache the workers read (so nothing is built twice), and refuse the
    grid when one cannot be built.

    Raises
    ------
    InputError
        Naming the window, why its modes cannot be built and how many collisions would fail.
    StoreError, CacheError
        When the store or the mode cache cannot be used (the message says what to do).
    """
    with Store(store) as db:
        status = db.status(list(dict.fromkeys(specs)))
    todo = [s for s in specs if status.get(s.key()) != Status.OK]
    firsts: dict = {}
    for s in sorted(todo, key=lambda s: s.n_modes):
        firsts.setdefault(s.group, s)
    with _interrupt_deferred():
        _build_all(firsts, todo)


def _build_all(firsts: dict, todo: list) -> None:
    """:func:`check_mode_sets`'s building, window by window."""
    for first in firsts.values():
        try:
            point_modes(first)
        except InputError as exc:
            why = str(exc).split("; ", 1)[0]  # its advice is for one mode request, not a grid
            doomed = sum(_body(s) == _body(first) and s.n_modes >= first.n_modes for s in todo)
            raise InputError(
                f"the {first.geometry} modes of the window N = {first.n_modes} cannot be built "
                f"at nu = {first.nu:g} ({why}), so the grid's {doomed} collisions with N >= "
                f"{first.n_modes} would all fail"
            ) from None


def _body(spec: PointSpec) -> tuple:
    """A point's mode set but its size: its :attr:`PointSpec.group` without ``n_modes``."""
    group = spec.group
    return group[:2] + group[3:]
