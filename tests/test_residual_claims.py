"""Two runs of one law by the residual route never compute a speed twice, and a full cache disk
ends a run in one line (hostile-input issue): :mod:`restitution.laws.making.residual_law` with the
claims of :mod:`restitution.limits.claims`.

No collision runs: the point function is replaced by :func:`_fake_point`, which sleeps briefly and
logs the speed it computes. The points run on one thread of the test's process (:class:`_OneThread`,
given as the executor's ``client``), so the replaced function is the one that runs.
"""

from __future__ import annotations

import errno
import socket
import sqlite3
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

import restitution.limits.claims as claims_module
from restitution import atomic
from restitution.errors import OutputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.making import residual_law as rl
from restitution.limits.run_options import Executor

SPEEDS = (0.1, 0.2, 0.3, 0.4)
NAME = "law_nu0.33_residual.json"


class _OneThread:
    """A stand-in for a Dask client whose executor is one thread of this process."""

    class scheduler:  # noqa: N801 - the attribute a client has
        address = "one thread of the test process"

    def __init__(self) -> None:
        self.pool = ThreadPoolExecutor(max_workers=1)

    def get_executor(self, pure: bool) -> ThreadPoolExecutor:  # noqa: ARG002 - a client's
        return self.pool


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(rl, "POLL_S", 0.02)
    return tmp_path / "cache" / "residual_points"


@pytest.fixture
def calls(tmp_path, monkeypatch):
    """The speeds :func:`_fake_point` computed, in order (from its log file)."""
    log = tmp_path / "computed.log"
    monkeypatch.setattr(rl, "_point", lambda task: _fake_point(task, log))
    return lambda: [float(x) for x in log.read_text().split()] if log.exists() else []


def _fake_point(task, log, seconds=0.1) -> dict:
    time.sleep(seconds)
    v = task[2]
    with open(log, "a") as fh:
        fh.write(f"{v!r}\n")
    eps = 0.95 - 0.1 * v
    return {"v": v, "epsilon": eps, "epsilon_err": 1e-3, "energy_loss": 1 - eps**2,
            "energy_loss_err": 2e-3, "asymptotic_ok": True, "status": "ok",
            "route": rl.RESIDUAL_ROUTE, "message": ""}  # fmt: skip


def _law(out_dir, client: _OneThread):
    return rl.residual_law(0.33, out_dir=out_dir, speeds=SPEEDS, low_speeds=(), refine_rounds=0,
                           executor=Executor(client=client))  # fmt: skip


def _in_threads(n, target, timeout=60.0) -> list:
    """Run ``target(i)`` in ``n`` threads at once; their results (an exception is raised)."""
    results, errors = [None] * n, []

    def run(i):
        try:
            results[i] = target(i)
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            errors.append(exc)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout)
    assert not any(t.is_alive() for t in threads), "a run did not finish (waiting forever?)"
    if errors:
        raise errors[0]
    return results


def test_two_runs_of_one_law_compute_each_speed_once(tmp_path, cache, calls, monkeypatch):
    """Two runs of the same law at once (two threads: each its own claims, as two processes):
    the first point waits until both runs are computing, so they overlap. Each speed is computed
    once in all (measured without claims: 8 computations of 4 speeds), and both runs' laws hold
    all four speeds."""
    entered, both_in = [], threading.Event()
    compute = rl._compute

    def counted(*args, **kwargs):
        entered.append(1)
        if len(entered) >= 2:
            both_in.set()
        return compute(*args, **kwargs)

    monkeypatch.setattr(rl, "_compute", counted)
    log = tmp_path / "computed.log"

    def first_waits(task):
        assert both_in.wait(30.0), "the second run never started computing"
        return _fake_point(task, log)

    monkeypatch.setattr(rl, "_point", first_waits)
    clients = [_OneThread(), _OneThread()]
    try:
        paths = _in_threads(2, lambda i: _law(tmp_path / "out", clients[i]))
    finally:
        for c in clients:
            c.pool.shutdown()
    assert len(entered) == 2  # both runs computed; neither found the other's finished law
    assert sorted(calls()) == list(SPEEDS)
    for path in paths:
        assert list(EpsilonLaw.from_json(path).v) == list(SPEEDS)


def _dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_a_claim_left_by_a_dead_run_is_taken_over(tmp_path, cache, monkeypatch):
    """A run killed while it computed 0.2 left its claim (a process that no longer exists): the
    next run takes it over at once and computes 0.2 under its own claim, once."""
    cache.mkdir(parents=True)
    version = rl._version("disk", False)
    kept = rl._Kept(cache / NAME, version)
    key = rl._claim_key(kept, ("disk", 0.33, 0.2, None))
    with sqlite3.connect(cache / "claims.sqlite") as conn:
        conn.execute(claims_module._SCHEMA)
        conn.execute("INSERT INTO claims VALUES (?, 'killed', ?, ?, ?)",
                     (key, socket.gethostname(), _dead_pid(), time.time()))  # fmt: skip
    log, owners = tmp_path / "computed.log", {}

    def point(task):
        if task[2] == 0.2:
            with sqlite3.connect(cache / "claims.sqlite") as conn:
                owners[task[2]] = conn.execute(
                    "SELECT owner FROM claims WHERE key = ?", (key,)
                ).fetchone()
        return _fake_point(task, log)

    monkeypatch.setattr(rl, "_point", point)
    client = _OneThread()
    try:
        (path,) = _in_threads(1, lambda i: _law(tmp_path / "out", client))
    finally:
        client.pool.shutdown()
    assert owners[0.2] is not None and owners[0.2][0] != "killed"
    assert sorted(float(x) for x in log.read_text().split()) == list(SPEEDS)
    assert list(EpsilonLaw.from_json(path).v) == list(SPEEDS)


def test_a_full_cache_disk_ends_the_run_in_one_line_and_keeps_the_points(
    tmp_path, cache, calls, monkeypatch, capfd
):
    """The kept-points file cannot be written after its first point (ENOSPC): one
    OutputError line naming the folder and what to do, the queued points dropped, no thread's
    traceback; the next run (space freed) computes only the points not kept."""
    real_write, writes = atomic.write_text, []

    def full_after_one(path, text, **kwargs):
        writes.append(path)
        if len(writes) > 1:
            raise OSError(errno.ENOSPC, "No space left on device", str(path))
        real_write(path, text, **kwargs)

    monkeypatch.setattr(atomic, "write_text", full_after_one)
    hooked = []
    monkeypatch.setattr(threading, "excepthook", hooked.append)
    client = _OneThread()
    try:
        with pytest.raises(OutputError) as info:
            _law(tmp_path / "out", client)
        client.pool.shutdown(wait=True)
        message = str(info.value)
        assert "\n" not in message
        assert str(cache) in message and "No space left on device" in message
        assert "free some space there" in message and "RESTITUTION_CACHE_DIR" in message
        assert hooked == [] and "Traceback" not in capfd.readouterr().err
        first = calls()
        assert 2 <= len(first) < len(SPEEDS)  # the rest was dropped, not computed for nothing
        kept = rl._Kept(cache / NAME, rl._version("disk", False))
        assert list(kept.points) == [repr(first[0])]  # the point kept before the disk filled
        monkeypatch.setattr(atomic, "write_text", real_write)
        client = _OneThread()
        path = _law(tmp_path / "out", client)
    finally:
        client.pool.shutdown()
    assert sorted(calls()[len(first) :] + first[:1]) == list(SPEEDS)
    assert list(EpsilonLaw.from_json(path).v) == list(SPEEDS)
