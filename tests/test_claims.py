"""Two sweeps on one result store never compute a point twice (issue 30): claims.

Each sweep claims the points it computes; another sweep waits for claimed points instead of
recomputing them, and takes over the claims of a sweep that is gone (its process died, or, on
another host, its heartbeat is older than the lease).
"""

from __future__ import annotations

import contextlib
import math
import os
import socket
import sqlite3
import subprocess
import sys
import threading
import time

import pytest

import restitution.limits.claims as claims_module
from restitution.limits.claims import LEASE_S, Claims
from restitution.limits.store import Store
from restitution.limits.sweep import SweepSettings, grid, run_sweep

LOG = "RESTITUTION_TEST_CLAIMS_LOG"
"""Environment variable naming the file where :func:`slow_batch` logs the points it computes
(it runs in the sweep's worker processes)."""


def slow_batch(specs):
    """A stand-in for the solver that takes its time and logs every point it computes."""
    time.sleep(0.1)
    with open(os.environ[LOG], "a") as fh:  # one short append per batch
        fh.write("".join(s.key() + "\n" for s in specs))
    return [("ok", {"epsilon": math.sqrt(0.9 - s.v), "energy_drift": 1e-9}) for s in specs]


def _computed(path) -> list[str]:
    return path.read_text().split() if path.exists() else []


@pytest.fixture
def store(tmp_path, monkeypatch):
    path = tmp_path / "s.sqlite"
    Store(path).close()
    monkeypatch.setenv(LOG, str(tmp_path / "computed.log"))
    return path


def _dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_a_claimed_point_is_left_to_its_live_owner(store):
    with Claims(store) as a, Claims(store) as b:
        assert a.claim(["k1", "k2"]) == ({"k1", "k2"}, set())
        assert b.claim(["k1", "k2", "k3"]) == ({"k3"}, {"k1", "k2"})
        assert a.claim(["k1"]) == ({"k1"}, set())  # already its own
        a.release()
        assert b.claim(["k1", "k2"]) == ({"k1", "k2"}, set())


def test_claims_of_a_dead_process_are_taken_over(store):
    with sqlite3.connect(store) as conn:
        conn.execute(claims_module._SCHEMA)
        conn.execute("INSERT INTO claims VALUES ('k1', 'gone', ?, ?, ?)",
                     (socket.gethostname(), _dead_pid(), time.time()))  # fmt: skip
    with Claims(store) as b:
        assert b.claim(["k1"]) == ({"k1"}, set())


def test_claims_of_another_host_last_a_lease(store):
    now = time.time()
    with sqlite3.connect(store) as conn:
        conn.execute(claims_module._SCHEMA)
        conn.executemany(
            "INSERT INTO claims VALUES (?, 'far', 'another-host', 1, ?)",
            [("fresh", now), ("stale", now - LEASE_S - 1.0)],
        )
    with Claims(store) as b:
        assert b.claim(["fresh", "stale"]) == ({"stale"}, {"fresh"})


def test_claims_of_a_live_process_that_stopped_beating_are_taken_over(store):
    """Issue 47: on one host a claim was judged by its process alone, so the claims of a sweep
    that hung, or whose process number another program now has (a container restarted under the
    same host name), held the next sweep waiting forever. A claim whose heartbeat is older than
    the lease is taken over on every host; here its process (this one) is alive."""
    now = time.time()
    with sqlite3.connect(store) as conn:
        conn.execute(claims_module._SCHEMA)
        conn.executemany(
            "INSERT INTO claims VALUES (?, 'hung', ?, ?, ?)",
            [("fresh", socket.gethostname(), os.getpid(), now),
             ("stale", socket.gethostname(), os.getpid(), now - LEASE_S - 1.0)],
        )  # fmt: skip
    with Claims(store) as b:
        assert b.claim(["fresh", "stale"]) == ({"stale"}, {"fresh"})


def test_a_live_sweep_beats_while_it_computes(store):
    """The heartbeat thread renews a sweep's claims between its batches (a batch may take longer
    than the lease), so a live sweep keeps them."""
    with Claims(store, beat_s=0.02) as a:
        a.claim(["k1"])
        with sqlite3.connect(store) as conn:
            first = conn.execute("SELECT heartbeat FROM claims").fetchone()[0]
            deadline = time.monotonic() + 30.0
            while time.monotonic() < deadline:
                beat = conn.execute("SELECT heartbeat FROM claims").fetchone()[0]
                if beat > first:
                    break
                time.sleep(0.02)
        assert beat > first


def test_closing_releases_the_claims(store):
    with Claims(store) as a:
        a.claim(["k1"])
    with sqlite3.connect(store) as conn:
        assert conn.execute("SELECT COUNT(*) FROM claims").fetchone() == (0,)


def test_two_concurrent_sweeps_compute_every_point_once(store, monkeypatch):
    """Two sweeps of one grid started together on one store: every point is computed once, the
    later sweep waits for what the earlier claimed, and both end with every point stored."""
    monkeypatch.setattr("restitution.limits.sweep.POLL_S", 0.05)
    settings = SweepSettings(velocities=(0.1, 0.2), alphas=(20.0, 40.0), n_modes=(10, 20),
                             alpha_scale="absolute", batch_size=1)  # fmt: skip
    points = grid([0.33], settings)
    reports = [None, None]

    def sweep(i):
        reports[i] = run_sweep(points, store=store, batch_function=slow_batch, batch_size=1,
                               progress=False)  # fmt: skip

    first = threading.Thread(target=sweep, args=(0,))
    first.start()
    deadline = time.monotonic() + 60.0
    while time.monotonic() < deadline:  # until the first has claimed its points (a fixed
        # pause of 0.05 s was not always enough on a loaded machine)
        with (
            contextlib.suppress(sqlite3.OperationalError),
            contextlib.closing(sqlite3.connect(store)) as conn,
        ):
            if conn.execute("SELECT COUNT(*) FROM claims").fetchone()[0]:
                break
        time.sleep(0.01)
    second = threading.Thread(target=sweep, args=(1,))
    second.start()
    first.join(60)
    second.join(60)
    calls = _computed(store.parent / "computed.log")
    assert len(calls) == len(set(calls)) == len(points) == 8
    a, b = reports
    assert a.computed + b.computed == 8
    assert b.waited == 8 - b.computed - b.skipped and b.waited > 0
    with Store(store) as db:
        assert all(db.get(p).ok for p in points)


def test_a_sweep_takes_over_the_points_of_a_dead_one(store):
    """A sweep killed with kill -9 leaves claims; the next sweep computes those points."""
    settings = SweepSettings(velocities=(0.1,), alphas=(20.0, 40.0), n_modes=(10,),
                             alpha_scale="absolute", batch_size=1)  # fmt: skip
    points = grid([0.33], settings)
    with sqlite3.connect(store) as conn:
        conn.execute(claims_module._SCHEMA)
        conn.executemany(
            "INSERT INTO claims VALUES (?, 'killed', ?, ?, ?)",
            [(p.key(), socket.gethostname(), _dead_pid(), time.time()) for p in points],
        )
    report = run_sweep(points, store=store, batch_function=slow_batch, progress=False)
    assert report.computed == 2 and report.waited == 0
    assert sorted(_computed(store.parent / "computed.log")) == sorted(p.key() for p in points)
