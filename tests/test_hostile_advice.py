"""Advice that failed when followed, raw warnings and tracebacks (the hostile-input issue).

Each case is followed as a user would: the advised command is run and must do what the advice
said; a refusal is one line that names the setting to change. Heavy work is replaced by
stand-ins (module-level functions: sweep tasks must pickle) or refused before it starts.

Read-only folders are made with ``chmod`` (or, as root, which ignores permissions, with
``chattr +i``); those tests skip when neither is possible, and a stand-in for the failing write
covers the same path everywhere.
"""

import errno
import json
import signal
import sqlite3
import threading
import time
import warnings
from multiprocessing import resource_tracker

import pytest
from _cli_checks import one_line_error
from _read_only import read_only

from restitution.bodies.cache import CacheError
from restitution.bodies.wall import HalfSpace
from restitution.errors import InputError
from restitution.laws.units import Grain
from restitution.limits import executors
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import run_sweep

# -- helpers -------------------------------------------------------------------------------


def ok_batch(specs):
    """Stand-in for the solver: every collision ends with epsilon 0.9."""
    return [("ok", {"epsilon": 0.9, "energy_drift": 1e-9}) for _ in specs]


def error_line(code, err, *words):
    """Like :func:`one_line_error`, after the command's ``note:`` lines (its plan)."""
    rest = "\n".join(x for x in err.splitlines() if not x.startswith("note: "))
    return one_line_error(code, rest, *words)


@pytest.fixture
def no_sweep(monkeypatch):
    """Make any sweep fail the test: refusals must come before it."""
    import restitution.limits.curves as curves

    def refuse(*args, **kwargs):
        raise AssertionError("the sweep started instead of being refused up front")

    monkeypatch.setattr(curves, "compute_curves", refuse)


# -- 1. damaged rows: the advised rerun computes them again ---------------------------------

POINTS = [PointSpec(0.33, v, 500.0, 10) for v in (0.1, 0.2, 0.3)]


def _damage(path, spec, sql):
    with sqlite3.connect(path) as conn:
        conn.execute(f"UPDATE collisions SET {sql} WHERE key = ?", (spec.key(),))


@pytest.mark.parametrize("damage", ["epsilon = 1.7", "result = '{not json'", "energy_drift = NULL"])
def test_a_damaged_row_is_computed_again_by_the_advised_rerun(tmp_path, client, damage):
    """A damaged ``ok`` row read as failed ("compute it again ... rerun", or "rerun with
    --retry-failed" as the failed points' advice says), but the sweep skipped it (its status was
    still ``ok``) and the store would not replace it (only failed rows were replaced): following
    either advice recomputed nothing. Now the rerun computes it, with or without retry."""
    path = tmp_path / "s.sqlite"
    run_sweep(POINTS, store=path, client=client, batch_function=ok_batch)
    bad = POINTS[1]
    for retry in (False, True):
        _damage(path, bad, damage)
        with Store(path) as db:
            point = db.get(bad)
            assert point.status == "failed" and "damaged stored row" in point.error
            assert "rerun" in point.error
            assert db.status([bad]) == {bad.key(): "failed"}
            assert bad.key() in db.errors([bad])
        report = run_sweep(POINTS, store=path, client=client, batch_function=ok_batch,
                           retry_failed=retry)  # fmt: skip
        assert (report.computed, report.skipped) == (1, 2)
        with Store(path) as db:
            point = db.get(bad)
            assert point.status == "ok" and point.epsilon == 0.9 and point.error is None
            assert len(db) == 3


def test_a_result_no_collision_can_have_is_stored_as_a_failure(tmp_path):
    """A "success" with epsilon outside [0, 1] was written as ``ok`` and read back as a damaged
    row; it is stored as the failure it is, saying why."""
    spec = POINTS[0]
    with Store(tmp_path / "s.sqlite") as db:
        db.put(spec, {"epsilon": 1.5, "energy_drift": 1e-9})
        point = db.get(spec)
    assert point.status == "failed"
    assert "outside [0, 1]" in point.error and "damaged" not in point.error


# -- 2. the advised production at a nu its modes cannot reach --------------------------------


def test_the_advised_sphere_production_near_nu_half_is_refused_in_seconds(
    cli, tmp_path, monkeypatch, no_sweep
):
    """``law`` advised ``curve --geometry sphere --nu 0.4999 --production`` (612 collisions,
    12 minutes), and every collision failed: at nu = 0.4999 the sphere's 2400 modes of the
    smallest window cannot be built (its Bessel functions underflow at order l = 154; the
    step estimate is not the limit there). The advised command now refuses before the sweep,
    naming the window."""
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    code, out, err = cli("curve", "--geometry", "sphere", "--nu", "0.4999", "--production",
                         "--out", str(tmp_path / "out"), "--store", str(tmp_path / "s.sqlite"),
                         "--no-progress")  # fmt: skip
    error_line(code, err, "nu = 0.4999", "N = 2400", "cannot be built", "order limit",
               "would all fail")  # fmt: skip


# -- 3. raw warnings and tracebacks -----------------------------------------------------------


def test_pool_workers_never_see_ctrl_c():
    """A Ctrl-C reaches the whole process group: the pool's workers printed a
    ``KeyboardInterrupt`` traceback each (while importing the package, or in a task). They are
    spawned with SIGINT blocked; the sweep process takes it and stops them."""
    with executors.executor(None, None, None) as (pool, _):
        blocked = pool.submit(signal.pthread_sigmask, signal.SIG_BLOCK, []).result(timeout=60)
    assert signal.SIGINT in blocked
    assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])  # ours is back


def test_an_interrupted_pool_releases_its_semaphores_at_once(monkeypatch):
    """Interrupted, the pool was shut down without waiting: its manager thread kept the five
    semaphores of its queues, and a process that then ended hard (a second Ctrl-C) left them
    to multiprocessing's resource tracker, which printed ``There appear to be 5 leaked
    semaphore objects to clean up at shutdown``. Now they are released before the interrupt
    leaves the executor."""
    released = []
    unregister = resource_tracker.unregister

    def record(name, rtype):
        released.append(rtype)
        unregister(name, rtype)

    monkeypatch.setattr(resource_tracker, "unregister", record)
    with pytest.raises(KeyboardInterrupt), executors.executor(None, None, None) as (pool, _):
        pool.submit(time.sleep, 60)
        time.sleep(0.5)
        raise KeyboardInterrupt
    assert released.count("semaphore") >= 5
    assert not [t for t in threading.enumerate() if "QueueFeeder" in t.name]


def test_a_sphere_too_slow_for_rayleigh_is_one_line(cli):
    """``quasistatic --geometry sphere --v 1e-300`` ended in a ZeroDivisionError (1e-50: a
    2.6 TiB allocation); below 1e-16 c it is refused as ``law`` refuses it."""
    for v in ("1e-300", "1e-50"):
        code, out, err = cli("quasistatic", "--geometry", "sphere", "--v", v)
        one_line_error(code, err, f"--v {v}", "1e-16")
    code, out, err = cli("quasistatic", "--geometry", "sphere", "--radius-ratio", "2", "--v",
                         "1e-300")  # fmt: skip
    one_line_error(code, err, "--v 1e-300", "1e-16")


def test_walls_at_a_compression_scale_of_a_vanishing_compression_are_one_line(cli, tmp_path):
    """``epsilon --geometry sphere --v 1e-300``: Hertz's compression underflows to 0 and the
    walls alpha / delta_max ended in a ZeroDivisionError."""
    code, out, err = cli("epsilon", "--geometry", "sphere", "--nu", "0.3", "--v", "1e-300",
                         "--store", str(tmp_path / "s.sqlite"))  # fmt: skip
    one_line_error(code, err, "delta_max = 0 R", "--alpha-scale")


def test_a_speed_unit_that_overflows_is_refused_without_a_numpy_warning(cli):
    """E and rho each a float, their ratio not: c = sqrt(E / rho) = 0 printed numpy's
    ``divide by zero encountered in divide`` and served v/c = inf; c = inf made every speed 0
    ("need v > 0 and spread >= 0")."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        for E, rho, c in ((1e-300, 1e300, "= 0 m/s"), (2.1e11, 1e-300, "= inf m/s")):
            with pytest.raises(InputError, match="not a finite speed") as info:
                Grain(E, 0.3, rho, "sphere")
            assert c in str(info.value)
    code, out, err = cli("law", "--E", "1e-300", "--nu", "0.3", "--rho", "1e300", "--shape",
                         "sphere", "--against", "wall", "--speed", "1")  # fmt: skip
    line = one_line_error(code, err, "c = sqrt(E / rho) = 0 m/s", "check the units")
    assert "encountered" not in line


# -- 4. a read-only cache ---------------------------------------------------------------------


def test_a_read_only_cache_is_named_before_the_work(cli, tmp_path, monkeypatch, no_sweep):
    """A read-only cache failed ("cannot open result store ...: unable to open database file",
    "Operation not permitted (.../laws)") without naming the setting that moves it. Now the
    default store and the computed laws' folder are checked before any work, in one line
    naming RESTITUTION_CACHE_DIR and the folder."""
    cache = tmp_path / "cache"
    cache.mkdir()
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(cache))
    with read_only(cache):
        code, out, err = cli("epsilon", "--nu", "0.33", "--v", "0.1")
        one_line_error(code, err, "RESTITUTION_CACHE_DIR", str(cache), "--store")
        code, out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                             "sphere", "--against", "grain", "--partner-E", "70e9",
                             "--partner-nu", "0.3", "--partner-rho", "2700", "--speed", "1",
                             "--compute")  # fmt: skip
        error_line(code, err, "RESTITUTION_CACHE_DIR", str(cache / "laws"))


def test_a_cache_folder_that_refuses_writes_names_the_setting(tmp_path, monkeypatch):
    """The same check where no folder can be made read-only: the write it makes fails."""
    import restitution.bodies.cache as cache_module
    from restitution.bodies.cache import writable_folder

    cache = tmp_path / "cache"
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(cache))

    def refuse(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    assert writable_folder(cache / "laws") == cache / "laws"
    monkeypatch.setattr(cache_module.tempfile, "mkstemp", refuse)
    with pytest.raises(CacheError, match="RESTITUTION_CACHE_DIR") as info:
        writable_folder(cache / "laws")
    assert str(cache / "laws") in str(info.value) and "Permission denied" in str(info.value)
    with pytest.raises(CacheError, match="RESTITUTION_CACHE_DIR") as info:
        Store()
    assert "--store" in str(info.value)
    with pytest.raises(CacheError) as info:  # a folder elsewhere: named, no setting to change
        writable_folder(tmp_path / "elsewhere")
    assert "RESTITUTION_CACHE_DIR" not in str(info.value)


# -- 5. Ctrl-C in the FEM wall reference --------------------------------------------------------


class _Result:
    def __init__(self, nu, wall, v):
        self.d = {"nu": nu, "wall": wall.to_dict(), "v": v, "epsilon": 0.9,
                  "epsilon_err": 0.01, "settings": {"wall_time_s": 1.0}}  # fmt: skip

    def to_dict(self):
        return self.d


def _fem(interrupt_at):
    """A stand-in for the FEM runs: the ``interrupt_at``-th call is a Ctrl-C."""
    calls = []

    def run(nu, wall, v, levels, on_run=None):
        calls.append(v)
        if len(calls) == interrupt_at:
            raise KeyboardInterrupt
        return _Result(nu, wall, v)

    return run


def _exit_status(main, argv):
    """The exit status of ``main(argv)``; a Ctrl-C that escapes it (a traceback) fails."""
    try:
        main(argv)
    except SystemExit as exc:
        return exc.code
    except KeyboardInterrupt:
        pytest.fail("Ctrl-C escaped as a KeyboardInterrupt: the user sees a traceback")
    return 0


def test_ctrl_c_in_the_wall_reference_is_one_line_and_the_advice_resumes(
    tmp_path, monkeypatch, capsys
):
    """Ctrl-C in ``python -m restitution.fem.wall_reference`` gave a traceback. It ends with
    one line and status 130; the same command again would start the file afresh (only
    --append adds to it), so the line says how to compute the rest, and following it does."""
    import restitution.fem.wall_reference as ref

    out = tmp_path / "ref.json"
    points = ["0.3:0.001", "0.3:0.0005:1.2", "0.3:0.0002"]
    monkeypatch.setattr(ref, "fem_wall_epsilon", _fem(interrupt_at=2))
    assert _exit_status(ref.main, [str(out), *points]) == 130
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if x.strip()]
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith("interrupted; the 1 point(s) finished are kept in")
    assert [p["v"] for p in json.loads(out.read_text())["points"]] == [0.001]
    advice = lines[0].split("only these points: ")[1].split()
    assert advice == ["0.3:0.0005:1.2", "0.3:0.0002"]
    monkeypatch.setattr(ref, "fem_wall_epsilon", _fem(interrupt_at=0))
    ref.main([str(out), "--append", *advice])
    doc = json.loads(out.read_text())
    assert sorted(p["v"] for p in doc["points"]) == [0.0002, 0.0005, 0.001]
    kinds = {p["v"]: p["wall"]["kind"] for p in doc["points"]}
    assert kinds[0.001] == HalfSpace(1.0, 1.0, 0.3).to_dict()["kind"]


def test_ctrl_c_before_the_first_wall_point_says_nothing_was_written(tmp_path, monkeypatch, capsys):
    import restitution.fem.wall_reference as ref

    out = tmp_path / "ref.json"
    monkeypatch.setattr(ref, "fem_wall_epsilon", _fem(interrupt_at=1))
    assert _exit_status(ref.main, [str(out), "0.3:0.001"]) == 130
    err = capsys.readouterr().err.strip()
    assert err == (
        f"interrupted before the first point finished; {out} was not written; run the same "
        "command again to start over"
    )
    assert not out.exists()
