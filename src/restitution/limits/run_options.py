"""How a long computation runs, as small objects: where (an executor) and what it shows (progress).

Units: none (counts of collisions or points).

:class:`Executor` names where a sweep's collisions run -- local processes on every core (the
default), a local Dask cluster of ``workers`` processes, an existing Dask ``scheduler`` or a
``client`` -- so that sweeps, curves, laws and the paper take one argument instead of three
keywords. :class:`Progress` says whether a progress bar is drawn on stderr (by default only on a
terminal) and draws it, as diffrax's progress meters do; ``progress=True``/``False``/``None``
is shorthand for ``Progress(True)``/``Progress(False)``/``Progress()`` wherever one is taken.
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any

from restitution.errors import InputError

__all__ = ["Executor", "Meter", "Progress", "executor_of", "progress_of"]


@dataclass(frozen=True)
class Executor:
    """Where a sweep's collisions run (at most one field given).

    Attributes
    ----------
    workers : int or None
        A local Dask cluster of this many single-threaded worker processes.
    scheduler : str or None
        The address of an existing Dask scheduler (e.g. ``"tcp://host:8786"``).
    client : distributed.Client or None
        An existing Dask client.

    With none of them, local processes on every core.
    """

    workers: int | None = None
    scheduler: str | None = None
    client: Any = None

    def __post_init__(self) -> None:
        if sum(x is not None for x in (self.workers, self.scheduler, self.client)) > 1:
            raise InputError("give at most one of workers, scheduler and client")

    def keywords(self) -> dict:
        """``workers``, ``scheduler`` and ``client`` as keywords."""
        return {"workers": self.workers, "scheduler": self.scheduler, "client": self.client}


def executor_of(executor: Executor | None = None, *, workers=None, scheduler=None, client=None):
    """The :class:`Executor` of a call that takes one, or the older three keywords (not both)."""
    loose = Executor(workers, scheduler, client)
    if executor is None:
        return loose
    if not isinstance(executor, Executor):
        raise InputError(
            f"executor must be an Executor, got {type(executor).__name__}; e.g. Executor(workers=2)"
        )
    if loose != Executor():
        raise InputError("give executor= or workers/scheduler/client, not both")
    return executor


@dataclass(frozen=True)
class Meter:
    """A running bar: call it with the number of items done since the last call; ``note``
    prints a line on stderr without breaking the bar."""

    advance: Callable[[int], None]
    note: Callable[[str], None]

    def __call__(self, n: int = 1) -> None:
        self.advance(n)


@dataclass(frozen=True)
class Progress:
    """Whether and how a progress bar is drawn on stderr (stdout may carry JSON).

    Attributes
    ----------
    enabled : bool or None
        ``True``: always; ``False``: never; ``None``: only when stderr is a terminal.
    """

    enabled: bool | None = None

    @property
    def shown(self) -> bool:
        """Whether the bar is drawn here and now."""
        return sys.stderr.isatty() if self.enabled is None else bool(self.enabled)

    @contextlib.contextmanager
    def bar(self, total: int, description: str = "collisions") -> Iterator[Meter]:
        """A bar over ``total`` items; yields its :class:`Meter` (``meter(n)`` advances it,
        ``meter.note(text)`` prints a line on stderr above it)."""
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            TextColumn,
            TimeElapsedColumn,
            TimeRemainingColumn,
        )
        from rich.progress import Progress as RichProgress

        with RichProgress(
            TextColumn(description),
            BarColumn(),
            MofNCompleteColumn(),
            TimeElapsedColumn(),
            TextColumn("ETA"),
            TimeRemainingColumn(),
            console=Console(stderr=True),
            disable=not self.shown,
            transient=False,
        ) as rich_bar:
            task = rich_bar.add_task(description, total=total)
            yield Meter(lambda n: rich_bar.advance(task, n), rich_bar.console.print)

    def track(self, items: Iterable, description: str) -> Iterator:
        """``items`` one by one, the bar advancing after each."""
        items = list(items)
        with self.bar(len(items), description) as advance:
            for item in items:
                yield item
                advance(1)


def progress_of(progress: Progress | bool | None) -> Progress:
    """A :class:`Progress` from one, or from the shorthand ``True``/``False``/``None``."""
    if isinstance(progress, Progress):
        return progress
    if progress is None or isinstance(progress, bool):
        return Progress(progress)
    raise InputError(
        f"progress must be a Progress, True, False or None, got {type(progress).__name__}"
    )
