"""Sweeps: skipping stored points, failures, Dask versus local processes, kill and resume.

The bookkeeping tests use a cheap stand-in for the solver on an in-process Dask cluster; the
executor tests run the real solver on tiny grids (10-20 modes, soft walls alpha = 20-50, where
a collision takes a fraction of a second).
"""

import math
import os
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest
from numpy.testing import assert_array_equal

from restitution.errors import InputError
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import (
    DEFAULTS,
    PAPER_VELOCITIES,
    SweepSettings,
    _batches,
    grid,
    load_grid,
    run_sweep,
)


def fake_loss(spec):
    """Synthetic energy loss with known limits: 0.1 + v at alpha, N -> infinity."""
    return 0.1 + spec.v + 2.0 / spec.alpha + 0.5 / math.sqrt(spec.n_modes)


def fake_batch(specs):
    """Stand-in for the solver: v = 0.013 fails alone; N = 99 kills its whole task."""
    if any(s.n_modes == 99 for s in specs):
        raise RuntimeError("worker crashed")
    out = []
    for s in specs:
        if s.v == 0.013:
            out.append(("failed", "CollisionError: synthetic failure"))
        else:
            loss = fake_loss(s)
            out.append(("ok", {"epsilon": math.sqrt(1 - loss), "energy_drift": 1e-9}))
    return out


def test_paper_velocities():
    # Fig. 7 caption: 0.005, 0.01, 0.02, 0.04, 0.06, ..., 0.30.
    assert PAPER_VELOCITIES[:4] == (0.005, 0.01, 0.02, 0.04)
    assert PAPER_VELOCITIES[-1] == 0.30 and np.allclose(np.diff(PAPER_VELOCITIES[3:]), 0.02)


def test_sweep_stores_points_and_skips_them_on_rerun(tmp_path, client):
    settings = SweepSettings(
        velocities=(0.05, 0.1),
        alphas=(100.0, 200.0, 400.0),
        n_modes=(50, 100),
        alpha_scale="absolute",
    )
    points = grid([0.33, 0.9], settings)
    report = run_sweep(
        points, store=tmp_path / "s.sqlite", client=client, batch_function=fake_batch
    )
    assert (report.total, report.computed, report.skipped, report.failed) == (24, 24, 0, ())
    again = run_sweep(points, store=tmp_path / "s.sqlite", client=client, batch_function=fake_batch)
    assert (again.computed, again.skipped) == (0, 24)
    with Store(tmp_path / "s.sqlite") as db:
        assert len(db) == 24
        data = load_grid(db, 0.9, 0.1, settings)
    expected = [[fake_loss(PointSpec(0.9, 0.1, a, n)) for n in (50, 100)] for a in settings.alphas]
    np.testing.assert_allclose(data.loss, expected, rtol=1e-12)


def test_failures_are_recorded_and_never_lose_other_points(tmp_path, client):
    path = tmp_path / "f.sqlite"
    points = grid(
        [0.33],
        SweepSettings(
            velocities=(0.013, 0.05), alphas=(100.0,), n_modes=(50, 99), alpha_scale="absolute"
        ),
    )
    report = run_sweep(points, store=path, client=client, batch_function=fake_batch, batch_size=1)
    assert report.computed == 1  # (0.05, N = 50)
    messages = sorted(m for _, m in report.failed)
    assert messages == [
        "CollisionError: synthetic failure",
        "RuntimeError: worker crashed",
        "RuntimeError: worker crashed",
    ]
    with Store(path) as db:
        assert len(db) == 4
        assert sum(r.ok for r in db) == 1
    # Failed points are not retried unless asked.
    assert run_sweep(points, store=path, client=client, batch_function=fake_batch).skipped == 4
    retry = run_sweep(
        points, store=path, client=client, batch_function=fake_batch, retry_failed=True
    )
    assert retry.skipped == 1 and len(retry.failed) == 3


def test_sweep_on_a_scheduler_address(tmp_path, client):
    # The --scheduler path: a new distributed.Client connects to an existing cluster.
    points = grid(
        [0.33],
        SweepSettings(
            velocities=(0.05,), alphas=(100.0,), n_modes=(50, 100), alpha_scale="absolute"
        ),
    )
    report = run_sweep(
        points,
        store=tmp_path / "a.sqlite",
        scheduler=client.scheduler.address,
        batch_function=fake_batch,
    )
    assert report.computed == 2 and report.executor.startswith("dask scheduler")


def test_batches_share_a_mode_set_and_a_wall():
    points = grid([0.33, 0.9], SweepSettings(velocities=(0.1, 0.2, 0.3), alphas=(50.0, 100.0)))
    batches = _batches(points, 4)
    assert sum(len(b) for b in batches) == len(points)
    for b in batches:
        assert len({s.group for s in b}) == 1
        assert [(s.alpha, s.v) for s in b] == sorted((s.alpha, s.v) for s in b)
    costs = [sum(s.n_modes * math.sqrt(s.alpha) for s in b) for b in batches]
    assert costs == sorted(costs, reverse=True)


def test_alphas_scaled_with_the_compression():
    # alpha = (alpha * delta_max) / delta_max(v), delta_max = v sqrt(ln(4/v)) (paper eq. 61).
    settings = SweepSettings(velocities=(0.01, 0.1), alphas=(25.0, 50.0), alpha_scale="compression")
    points = grid([0.33], settings, n_modes=(20,))
    delta = {v: v * math.sqrt(math.log(4.0 / v)) for v in settings.velocities}
    products = sorted((p.v, p.alpha * delta[p.v]) for p in points)
    np.testing.assert_allclose(products, [(0.01, 25), (0.01, 50), (0.1, 25), (0.1, 50)], rtol=1e-14)
    assert settings.alphas_at(0.1)[0] == pytest.approx(25.0 / delta[0.1], rel=1e-14)


def test_settings_and_options_are_checked(tmp_path):
    with pytest.raises(InputError, match="units of c"):
        SweepSettings(velocities=(0.1, 1.5))
    with pytest.raises(InputError):
        SweepSettings(alphas=())
    with pytest.raises(InputError):
        SweepSettings(n_modes=(0,))
    with pytest.raises(InputError, match="unknown solver option"):
        SweepSettings(options={"energy_toll": 1e-6})
    with pytest.raises(InputError, match="alpha_scale"):
        SweepSettings(alpha_scale="log")
    with pytest.raises(InputError, match="at most one"):
        run_sweep([], store=tmp_path / "x.sqlite", workers=1, scheduler="tcp://nowhere:1")
    assert DEFAULTS.n_modes[-1] == 940  # the paper's largest N (Fig. 7, 8)


TINY = SweepSettings(velocities=(0.05, 0.2), alphas=(20.0, 40.0), n_modes=(10,), batch_size=2)


def _rows(path):
    with Store(path) as db:
        return {
            r.spec: (r.status, r.epsilon, r.energy_drift, r.contact_time, r.max_force, r.n_steps)
            for r in db
        }


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_dask_local_cluster_matches_local_processes(tmp_path):
    # Real solver, same batches: a Dask LocalCluster gives bit-identical results to the local
    # process pool (both run single-threaded BLAS in worker processes).
    points = grid([0.33], TINY)
    local = run_sweep(points, store=tmp_path / "local.sqlite", batch_size=2, progress=False)
    dask = run_sweep(points, store=tmp_path / "dask.sqlite", workers=1, batch_size=2)
    assert local.computed == dask.computed == len(points) == 4
    assert "dask LocalCluster" in dask.executor and "local processes" in local.executor
    a, b = _rows(tmp_path / "local.sqlite"), _rows(tmp_path / "dask.sqlite")
    assert a.keys() == b.keys()
    for spec in a:
        assert a[spec][0] == "ok"
        assert_array_equal(a[spec][1:], b[spec][1:])
        assert 0.5 < a[spec][1] < 1.0


_SCRIPT = """
import sys
from restitution.limits.sweep import SweepSettings, grid, run_sweep

if __name__ == "__main__":
    settings = SweepSettings(
        velocities=(0.05, 0.1, 0.15, 0.2), alphas=(20.0, 30.0, 40.0, 50.0), n_modes=(20,)
    )
    run_sweep(grid([0.33], settings), store=sys.argv[1], batch_size=1, progress=False)
"""


def _count(path):
    try:
        conn = sqlite3.connect(f"file:{path}?mode=ro", uri=True, timeout=5)
        try:
            return conn.execute("SELECT COUNT(*) FROM collisions").fetchone()[0]
        finally:
            conn.close()
    except sqlite3.Error:
        return 0


def test_kill_and_resume(tmp_path):
    script = tmp_path / "sweep_script.py"
    script.write_text(textwrap.dedent(_SCRIPT))
    path = tmp_path / "resume.sqlite"
    proc = subprocess.Popen([sys.executable, str(script), str(path)], start_new_session=True)
    try:
        deadline = time.monotonic() + 300
        while _count(path) < 2 and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert proc.poll() is None, "the sweep finished before it could be killed"
        os.kill(proc.pid, signal.SIGKILL)  # kill -9 of the sweep process
        proc.wait(30)
    finally:
        try:
            os.killpg(proc.pid, signal.SIGKILL)  # its orphaned workers, started by this test
        except ProcessLookupError:
            pass
    before = _rows(path)
    assert 2 <= len(before) < 16
    settings = SweepSettings(
        velocities=(0.05, 0.1, 0.15, 0.2), alphas=(20.0, 30.0, 40.0, 50.0), n_modes=(20,)
    )
    report = run_sweep(grid([0.33], settings), store=path, batch_size=4, progress=False)
    assert report.skipped == len(before)
    assert report.computed == 16 - len(before) and report.failed == ()
    after = _rows(path)
    assert len(after) == 16 and all(r[0] == "ok" for r in after.values())
    assert all(after[s] == before[s] for s in before)  # nothing lost or rewritten
    with Store(path) as db:
        assert len(db) == 16  # no duplicate rows


def test_run_options_are_objects_and_the_old_keywords_their_shorthand(tmp_path, client):
    """Issue 40: where a sweep runs is one Executor, what it shows one Progress."""
    from restitution.limits.run_options import Executor, Progress, executor_of, progress_of

    assert executor_of(workers=2) == Executor(workers=2)
    assert executor_of(Executor(scheduler="tcp://x:1")).scheduler == "tcp://x:1"
    with pytest.raises(InputError, match="at most one"):
        Executor(workers=2, scheduler="tcp://x:1")
    with pytest.raises(InputError, match="not both"):
        executor_of(Executor(workers=2), workers=2)
    assert progress_of(None) == Progress() and progress_of(True).shown
    assert list(Progress(False).track([1, 2, 3], "items")) == [1, 2, 3]
    with pytest.raises(InputError, match="progress must be"):
        progress_of("yes")
    # The same sweep through an Executor and through the old keyword.
    settings = SweepSettings(velocities=(0.02,), alphas=(10.0, 20.0), n_modes=(5, 6),
                             alpha_scale="absolute")  # fmt: skip
    points = grid([0.33], settings)
    one = run_sweep(points, store=tmp_path / "a.sqlite", executor=Executor(client=client),
                    batch_function=fake_batch, progress=Progress(False))  # fmt: skip
    two = run_sweep(points, store=tmp_path / "b.sqlite", client=client,
                    batch_function=fake_batch, progress=False)  # fmt: skip
    assert one.computed == two.computed == 4 and one.executor == two.executor
