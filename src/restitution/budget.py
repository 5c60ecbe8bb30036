"""What this machine can give one run, and the one-line refusal of what it cannot.

The one home of the package's machine-aware limits (issue 30): every entry point estimates the
memory and the time of its work before it starts and refuses, naming the input at fault, the
numbers (needed against available) and the largest value that fits. Memory is never
overridden; the time bound may be (``--force`` on the command line, ``force=True`` in the
library).

The fixed 4 GiB bound of one collision batch's working memory,
:data:`restitution.dynamics.steps.MAX_MEMORY_BYTES`, is older and stays where it is (the
dynamics' source is part of the result store's code version).

Units: bytes and seconds.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable

from restitution.errors import InputError

__all__ = [
    "MEMORY_SHARE",
    "NEVER_S",
    "TIME_BOUND_S",
    "available_memory",
    "check_memory",
    "check_memory_total",
    "check_time",
    "check_time_total",
    "collision_seconds",
    "cpu_count",
    "format_bytes",
    "format_duration",
    "memory_budget",
    "named",
]

MEMORY_SHARE = 0.5
"""Share of the memory available at the check that one run may plan to use: the rest is left
to the other processes of this (shared) machine and to the slack of the estimates."""

TIME_BOUND_S = 3600.0
"""Longest estimated wall time of one run, seconds, unless forced."""

NEVER_S = 30 * 86400.0
"""Estimated seconds beyond which a run is refused even when forced (30 days): it would not end
on any machine this package plans for, so forcing is not offered."""

# Wall time of one time step of a collision of N modes: 17 us + 13 ns * N. Measured on the
# project's 2-core machine (load average about 3.5, shared with a long computation) with
# restitution.vibrating.sequences.bounce, 4 collisions each at N = 10, 40, 160, 640, alpha =
# 500 and 2000, v = 0.01 and 0.1, under gravity and between two walls, against the steps of
# restitution.dynamics.steps.estimate_work at the first speed: the least-squares fit (in log)
# is within a factor 2 of every one of the 32 cases (per collision 6 ms to 320 ms). It covers
# step refinements, the start positions and the hand-over between collisions.
_SECONDS_PER_STEP = 17e-6
_SECONDS_PER_MODE_STEP = 13e-9


def available_memory() -> int:
    """Memory a new computation can have now, bytes.

    ``MemAvailable`` of ``/proc/meminfo`` (Linux); elsewhere the physical memory
    (``os.sysconf``).
    """
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (OSError, ValueError, AttributeError):  # pragma: no cover - no sysconf
        return 2**32


def memory_budget() -> float:
    """Bytes one run may plan to use: :data:`MEMORY_SHARE` of :func:`available_memory`."""
    return MEMORY_SHARE * available_memory()


def cpu_count() -> int:
    """Cores this process may run on (its CPU affinity where known)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def collision_seconds(steps: float, n_modes: int) -> float:
    """Estimated wall time of one collision of ``n_modes`` modes taking ``steps`` time steps,
    seconds, on one core of this machine (measurement in the module source)."""
    return float(steps) * (_SECONDS_PER_STEP + _SECONDS_PER_MODE_STEP * n_modes)


def format_bytes(n: float) -> str:
    """``n`` bytes with a binary unit, three significant digits (``"1.5 GiB"``)."""
    for unit, size in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.3g} B"


def format_duration(seconds: float) -> str:
    """``seconds`` in ms, s, min, h or days, three significant digits (``"2.5 h"``)."""
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s" if seconds >= 1 else f"{seconds * 1e3:.3g} ms"


def named(name: str, value) -> str:
    """``--samples 5`` for an option, ``samples = 5`` for a parameter."""
    return f"{name} {value}" if name.startswith("-") else f"{name} = {value}"


def _fit(limit: float, per_item: float, item: str) -> str:
    count = math.floor(limit / per_item) if per_item > 0 else 0
    return f"at most {count} {item}s fit" if count >= 1 else f"not even one {item} fits"


def check_memory(
    name: str, value: int, per_item: float, item: str, what: str, fixed: float = 0.0
) -> float:
    """Refuse ``value`` items of ``per_item`` bytes each (plus ``fixed`` bytes) beyond
    :func:`memory_budget`; returns the bytes needed.

    Parameters
    ----------
    name : str
        The input at fault as the caller knows it (``"--samples"`` or ``"samples"``).
    value : int
        Its value: the number of items.
    per_item, fixed : float
        Bytes per item and bytes independent of the count.
    item, what : str
        What one item is (``"sample"``) and what the memory holds (``"the thermal states"``).

    Raises
    ------
    InputError
        One line: the bytes needed and available, and the largest count that fits.
    """
    return check_memory_total(
        name,
        value,
        fixed + value * per_item,
        f"{what} ({format_bytes(per_item)} per {item})",
        lambda budget: _fit(budget - fixed, per_item, item),
    )


def check_memory_total(
    name: str, value, need: float, what: str, fit: Callable[[float], str]
) -> float:
    """Refuse an input whose work needs ``need`` bytes beyond :func:`memory_budget`; returns
    ``need``. The general form of :func:`check_memory`, for costs that are not a count times
    a size (a mesh level, a speed).

    Parameters
    ----------
    name, value
        The input at fault as the caller knows it (``"--mesh-refine"``) and its value.
    need : float
        Estimated bytes.
    what : str
        What the memory holds and how it was estimated.
    fit : callable
        ``fit(budget)``: the largest (or smallest) value that fits in ``budget`` bytes, in
        words (``"--mesh-refine 3 is the finest that fits"``).

    Raises
    ------
    InputError
        One line: the bytes needed and available, and what fits.
    """
    available = available_memory()
    budget = MEMORY_SHARE * available
    if need > budget:
        raise InputError(
            f"{named(name, value)} needs about {format_bytes(need)} of memory for {what}, "
            f"more than the {format_bytes(budget)} one run may use here ({MEMORY_SHARE:.0%} "
            f"of the {format_bytes(available)} available now); {fit(budget)}"
        )
    return need


def check_time(
    name: str,
    value: int,
    per_item: float,
    item: str,
    what: str,
    *,
    force: bool,
    override: str,
    bound: float | None = None,
) -> float:
    """Refuse ``value`` items of ``per_item`` seconds each beyond ``bound`` seconds unless
    ``force``; returns the estimated seconds.

    Parameters
    ----------
    name, value, item : see :func:`check_memory`
    per_item : float
        Estimated seconds per item.
    what : str
        How the estimate was made (``"about 1800 steps of 40 modes each"``).
    force : bool
        Run anyway.
    override : str
        How the caller forces (``"--force"`` or ``"force=True"``).
    bound : float, optional
        Longest allowed time, seconds; default :data:`TIME_BOUND_S`.

    Raises
    ------
    InputError
        One line: the estimated and allowed time, and the largest count that fits.
    """
    return check_time_total(
        name,
        value,
        value * per_item,
        f"{format_duration(per_item)} per {item}: {what}",
        lambda limit: _fit(limit, per_item, item),
        force=force,
        override=override,
        bound=bound,
    )


def check_time_total(
    name: str,
    value,
    need: float,
    what: str,
    fit: Callable[[float], str],
    *,
    force: bool,
    override: str,
    bound: float | None = None,
) -> float:
    """Refuse an input whose work would take ``need`` seconds beyond ``bound`` unless
    ``force``; returns ``need``. The general form of :func:`check_time`, for costs that are
    not a count times a duration (a mesh level, a speed).

    Parameters
    ----------
    name, value, need, what : see :func:`check_memory_total` (``need`` in seconds)
    fit : callable
        ``fit(bound)``: what fits in ``bound`` seconds, in words; ``" in it"`` follows.
    force, override, bound : see :func:`check_time`

    Raises
    ------
    InputError
        One line: the estimated and allowed time, what fits, and how to force.
    """
    bound = TIME_BOUND_S if bound is None else bound
    if need > bound and (not force or need > NEVER_S):
        # Forcing is offered only where a forced run ends (issue 47: advice that fails when
        # followed; compare-fem --v 1e-300 offered --force for 7.6e295 days).
        how = (
            f", or give {override} (it lifts the time bound, never the memory bound)"
            if need <= NEVER_S
            else f"; {override} is no way out: a run of over {format_duration(NEVER_S)} would "
            "not end"
        )
        raise InputError(
            f"{named(name, value)} would take about {format_duration(need)} ({what}), more "
            f"than the {format_duration(bound)} bound of one run; {fit(bound)} in it{how}"
        )
    return need
