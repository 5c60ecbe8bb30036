"""Where the tasks of a sweep run, and how their infrastructure fails.

Executors (library interfaces only, no home-made distribution), all driven through
:func:`concurrent.futures.as_completed` by :mod:`restitution.limits.sweep`:

* default: :class:`concurrent.futures.ProcessPoolExecutor` on all cores (spawned processes,
  which never see Ctrl-C: the sweep process takes it and stops them);
* ``workers=N``: a :class:`distributed.LocalCluster` with ``N`` single-threaded workers, at most
  what this machine runs (:func:`check_workers`: two per core, and their measured memory within
  the budget of :mod:`restitution.budget`);
* ``scheduler=ADDRESS``: an existing Dask cluster, probed first (:func:`probe_scheduler`) so
  that a wrong address fails at once with one clear message instead of hanging;
* ``client=``: an existing :class:`distributed.Client`.

A task that dies with its worker (``BrokenProcessPool``, a lost Dask worker) says nothing about
its points: :func:`is_infrastructure_failure` tells such failures from the solver's.
"""

from __future__ import annotations

import asyncio
import concurrent.futures as cf
import contextlib
import logging
import multiprocessing
import numbers
import os
import signal
import sys
import threading
import time
from collections.abc import Iterator
from multiprocessing import resource_tracker
from typing import Any

import restitution.budget as budget
from restitution.errors import InputError, SchedulerError

__all__ = [
    "INFRASTRUCTURE_RETRIES",
    "SCHEDULER_TIMEOUT_S",
    "WORKER_BYTES",
    "WORKERS_PER_CORE",
    "check_workers",
    "executor",
    "infrastructure_message",
    "is_infrastructure_failure",
    "probe_scheduler",
]


@contextlib.contextmanager
def _single_threaded_children() -> Iterator[None]:
    """One BLAS/OpenMP thread in worker processes started inside this block.

    The workers already fill the cores; threaded BLAS in each would oversubscribe them. The
    variables are inherited by processes spawned now and restored afterwards.
    """
    names = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS")
    saved = {k: os.environ.get(k) for k in names}
    os.environ.update({k: "1" for k in names})
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


class _Deferred:
    """A Ctrl-C taken while the workers started, to be raised once they run."""

    def __init__(self) -> None:
        self.taken = False

    def take(self, signum, frame) -> None:  # noqa: ARG002 - a signal handler's signature
        self.taken = True

    def raise_if_taken(self) -> None:
        """Raise the Ctrl-C taken while the workers started (the caller holds the cluster)."""
        if self.taken:
            raise KeyboardInterrupt


@contextlib.contextmanager
def _children_without_sigint() -> Iterator[_Deferred]:
    """Worker processes started inside this block never see Ctrl-C (SIGINT); one pressed
    meanwhile is kept and raised by :meth:`_Deferred.raise_if_taken` once they run.

    The sweep stops its workers when it is interrupted. Interrupted themselves while they
    started, the workers printed tracebacks and left the cluster in a state its exit handler
    asserted on (issue 30: tracebacks after Ctrl-C of ``curve --workers 2``). The block used to
    ignore SIGINT process-wide, so a Ctrl-C in its first seconds was lost and the sweep ran to
    its end (issue 47). Now SIGINT is *blocked* in this thread: every thread started here (Dask's
    event loop, the thread that spawns the workers) inherits the mask, and so do the worker
    processes (a signal mask survives fork and exec, and Python leaves it alone), while this
    process takes the signal through a handler that only records it: in another of its threads,
    or, pending, when the mask is lifted.
    """
    deferred = _Deferred()
    if threading.current_thread() is not threading.main_thread():
        yield deferred
        return
    # multiprocessing starts its resource tracker with SIGINT blocked and then *unblocks* it in
    # the starting thread (Dask's event loop): started now, before the mask, it is left alone.
    resource_tracker.ensure_running()
    old = signal.signal(signal.SIGINT, deferred.take)
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield deferred
    finally:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})  # a pending one: taken
        signal.signal(signal.SIGINT, old)


@contextlib.contextmanager
def _sigint_blocked() -> Iterator[None]:
    """SIGINT blocked in this thread for the block; one pressed meanwhile is taken after it.

    Processes spawned inside inherit the blocked SIGINT for their lifetime (a signal mask
    survives fork and exec): a Ctrl-C reaches the whole foreground process group, and pool
    workers hit by it printed a ``KeyboardInterrupt`` traceback each (half of them while
    importing the package). The sweep process takes the Ctrl-C and stops them.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    # Started inside the block, the tracker would unblock SIGINT here (as it does in
    # _children_without_sigint); started now, it is left alone.
    resource_tracker.ensure_running()
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)  # a pending Ctrl-C is taken now


class _Pool(cf.ProcessPoolExecutor):
    """A process pool whose workers never see Ctrl-C (:func:`_sigint_blocked`): they are
    spawned as tasks are submitted, so every submit spawns with SIGINT blocked."""

    def submit(self, fn, /, *args, **kwargs):
        with _sigint_blocked():
            return super().submit(fn, *args, **kwargs)


_STOP_WAIT_S = 10.0
"""Seconds an interrupted sweep waits for its stopped pool to release its queues."""


def _stop(pool: cf.ProcessPoolExecutor) -> None:
    """Stop an interrupted pool now: cancel its tasks, end its workers and wait (bounded) for
    its manager thread, so that its queues' semaphores are released before the process exits.

    The interrupted sweep used to leave the manager thread holding them; a second Ctrl-C or a
    hard exit then skipped their release, and multiprocessing's resource tracker printed
    ``There appear to be 5 leaked semaphore objects to clean up at shutdown``. A Ctrl-C
    pressed meanwhile waits for the end of this (it is raised then).
    """
    with _sigint_blocked():
        processes = list((getattr(pool, "_processes", None) or {}).values())
        manager = getattr(pool, "_executor_manager_thread", None)
        pool.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            process.terminate()
        if manager is not None:  # it joins the ended workers and closes the queues
            manager.join(_STOP_WAIT_S)


def _exit_with_parent(parent: int) -> None:
    """Worker initializer: end this worker when the sweep process is gone (e.g. ``kill -9``).

    Pool workers would otherwise wait for work forever: every worker holds both ends of the
    task queue, so the parent's death never reaches them as end-of-file.
    """

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(1)

    threading.Thread(target=watch, daemon=True, name="exit-with-parent").start()


WORKERS_PER_CORE = 2
"""Most single-threaded workers per core: more only share the cores and add their memory."""

WORKER_BYTES = 256 * 2**20
"""Memory of one Dask worker process, bytes. Measured once on the project's machine with
psutil (``Process().memory_info().rss`` inside the worker, through ``Client.submit``): 62 MiB
idle, 224-225 MiB after a batch of 4 collisions (``collide_batch`` at 40, 400 and 1600 modes,
alpha 500-4000) in a ``LocalCluster(n_workers=1, threads_per_worker=1, processes=True)``;
the nannies run inside the parent process. Rounded up to 256 MiB."""


def check_workers(workers) -> int:
    """Refuse a number of local Dask workers this machine cannot run usefully.

    At most :data:`WORKERS_PER_CORE` per core (:func:`restitution.budget.cpu_count`), and no
    more than the memory budget (:func:`restitution.budget.memory_budget`) holds at
    :data:`WORKER_BYTES` each. Returns ``workers`` as an int.

    Raises
    ------
    InputError
        One line: a non-integer or a count below 1, or the cores and memory needed against
        those available and the most workers that fit.
    """
    if not isinstance(workers, numbers.Integral) or isinstance(workers, bool):
        raise InputError(f"workers must be a whole number >= 1, got {workers!r}")
    if workers < 1:
        raise InputError(f"workers must be >= 1, got {workers}")
    cores = budget.cpu_count()
    by_cores = WORKERS_PER_CORE * cores
    available = budget.available_memory()
    allowed = budget.MEMORY_SHARE * available
    by_memory = int(allowed // WORKER_BYTES)
    fit = min(by_cores, by_memory)
    if workers > fit:
        size = budget.format_bytes
        raise InputError(
            f"workers = {workers} is more than this machine can run: {cores} cores take at most "
            f"{by_cores} single-threaded workers ({WORKERS_PER_CORE} per core), and {workers} "
            f"workers need about {size(workers * WORKER_BYTES)} of memory "
            f"({size(WORKER_BYTES)} each), against the {size(allowed)} one run may use here "
            f"({budget.MEMORY_SHARE:.0%} of the {size(available)} available now, room for "
            f"{by_memory}); at most {fit} workers fit"
        )
    return int(workers)


SCHEDULER_TIMEOUT_S = 10.0
"""Seconds to wait for a Dask scheduler to accept a connection and answer."""


def probe_scheduler(address: str, timeout: float = SCHEDULER_TIMEOUT_S) -> dict:
    """Ask ``address`` for its identity; returns it if it is a Dask scheduler.

    ``distributed.Client`` waits forever for the handshake of a server that accepts the
    connection but never answers (say, a dashboard or web port given by mistake); this probe
    has one overall deadline.

    Raises
    ------
    SchedulerError
        If the address is malformed, nothing answers within ``timeout`` seconds, or the server
        is not a Dask scheduler; the message says what to do.
    """
    from distributed.comm import connect

    async def ask() -> dict:
        comm = await connect(address, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    hint = "give the scheduler's address, e.g. tcp://HOST:8786 (not the dashboard's)"
    try:
        reply = asyncio.run(asyncio.wait_for(ask(), timeout + 1.0))
    except ValueError as exc:
        raise SchedulerError(
            f"{address!r} is not a Dask scheduler address ({exc}); {hint}"
        ) from None
    except TimeoutError:
        raise SchedulerError(
            f"{address} did not answer as a Dask scheduler within {timeout:g} s; {hint}"
        ) from None
    except OSError as exc:
        raise SchedulerError(f"cannot reach Dask scheduler {address}: {exc}; {hint}") from None
    except Exception as exc:  # noqa: BLE001 - a server speaking another protocol
        raise SchedulerError(
            f"{address} did not answer as a Dask scheduler ({type(exc).__name__}: {exc}); {hint}"
        ) from None
    if not isinstance(reply, dict) or reply.get("type") != "Scheduler":
        kind = reply.get("type") if isinstance(reply, dict) else type(reply).__name__
        raise SchedulerError(f"{address} is a Dask {kind}, not a scheduler; {hint}")
    return reply


@contextlib.contextmanager
def executor(
    workers: int | None, scheduler: str | None, client: Any
) -> Iterator[tuple[cf.Executor, str]]:
    if client is not None:
        yield client.get_executor(pure=False), f"dask client {client.scheduler.address}"
        return
    if scheduler is not None:
        from distributed import Client

        probe_scheduler(scheduler)
        try:
            c = Client(scheduler, timeout=SCHEDULER_TIMEOUT_S)
        except (OSError, ValueError) as exc:
            raise SchedulerError(f"cannot connect to Dask scheduler {scheduler}: {exc}") from None
        with c:
            yield c.get_executor(pure=False), f"dask scheduler {scheduler}"
        return
    if workers is not None:
        workers = check_workers(workers)
        from distributed import Client, LocalCluster

        if sys.stderr.isatty():
            print(
                f"starting {workers} workers (a Ctrl-C now stops the sweep once they run)",
                file=sys.stderr,
            )
        with _single_threaded_children(), _children_without_sigint() as deferred:
            cluster = LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",  # any free port; never collide with 8787
                # No log lines from the workers: a Ctrl-C cancels their tasks, which Dask logs as
                # warnings ("ended with CancelledError"), and a worker whose heartbeat is in
                # flight while the scheduler closes logs an ERROR with a traceback (seen once in
                # 80 Ctrl-C runs). A task's own exception reaches the sweep through its future,
                # and a lost worker is retried (is_infrastructure_failure): nothing is hidden.
                silence_logs=logging.CRITICAL,
            )
        with cluster, Client(cluster) as c:
            deferred.raise_if_taken()  # inside: the cluster closes as after any Ctrl-C
            yield c.get_executor(pure=False), f"dask LocalCluster, {workers} workers"
        return
    n = budget.cpu_count()
    with _single_threaded_children():
        context = multiprocessing.get_context("spawn")  # safe with the parent's threads
        pool = _Pool(
            max_workers=n,
            mp_context=context,
            initializer=_exit_with_parent,
            initargs=(os.getpid(),),
        )
        try:
            yield pool, f"local processes, {n} workers"
        except BaseException:
            # Interrupted: stop the workers now instead of letting them finish their batches
            # (their results could no longer be stored anyway).
            _stop(pool)
            raise
        pool.shutdown(wait=True)


INFRASTRUCTURE_RETRIES = 3
"""How often a batch lost to an infrastructure failure (a dead worker) is resubmitted."""

_INFRASTRUCTURE_ERRORS = frozenset(
    {"KilledWorker", "CommClosedError", "StreamClosedError", "FutureCancelledError"}
)


def is_infrastructure_failure(exc: BaseException) -> bool:
    """Whether a task died for reasons outside the computation (a killed or lost worker).

    Such a task says nothing about its points, so they are retried, never stored as failed.
    """
    return (
        isinstance(exc, cf.BrokenExecutor | cf.CancelledError | ConnectionError)
        or type(exc).__name__ in _INFRASTRUCTURE_ERRORS
    )


def infrastructure_message(message: str | None) -> bool:
    """A stored failure message that names an infrastructure failure (older code stored them)."""
    head = (message or "").split(":", 1)[0]
    return head in _INFRASTRUCTURE_ERRORS or head in ("BrokenProcessPool", "CancelledError")
