"""Hostile input, faults and lost work (issue 14): every case a clear error or a correct result.

Each case of the issue has a test here with small sizes. Command-line cases call
:func:`restitution.cli.main` in this process and check the documented exit status and that
stderr is exactly one line starting with ``error:`` (no traceback). Cases that used to hang
check that the refusal comes before any integration (the integrator loop is replaced by one
that fails the test).

Read-only files are made with ``chmod`` (or, as root, which ignores permissions, with
``chattr +i``); the tests that need one skip when neither is possible.
"""

import concurrent.futures as cf
import contextlib
import json
import os
import signal
import socket
import sqlite3
import subprocess
import threading
from dataclasses import replace

import numpy as np
import pytest
from _cli_checks import one_line_error
from _read_only import read_only

import restitution
from restitution import get_modes
from restitution.bodies.cache import MAX_MODES, CacheError, cache_dir
from restitution.cli import _common
from restitution.dynamics.collision import (
    CollisionSettings,
    collide,
    collide_batch,
    estimate_work,
)
from restitution.errors import InputError, RestitutionError, SchedulerError
from restitution.limits.executors import probe_scheduler
from restitution.limits.store import PointSpec, Store, StoreError
from restitution.limits.sweep import DEFAULTS, grid, run_sweep

# -- helpers -------------------------------------------------------------------------------


@pytest.fixture
def no_integration(monkeypatch):
    """Make any time integration fail the test: refusals must come before it."""
    import restitution.dynamics.collision as collision

    def refuse(*args, **kwargs):
        raise AssertionError("the collision was integrated instead of refused up front")

    monkeypatch.setattr(collision, "_attempt", refuse)  # every integration attempt goes through it


@pytest.fixture(scope="module")
def small():
    return get_modes(0.33, count=20)


@pytest.fixture
def silent_server():
    """A TCP server that accepts connections and never answers (like a dashboard port)."""
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    srv.settimeout(0.2)
    held, stop = [], threading.Event()

    def serve():
        while not stop.is_set():
            with contextlib.suppress(OSError):
                held.append(srv.accept()[0])

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    yield f"tcp://127.0.0.1:{srv.getsockname()[1]}"
    stop.set()
    thread.join()
    for conn in held:
        conn.close()
    srv.close()


# Stand-ins for the solver in sweep tests (module level: they must pickle).


def ok_batch(specs):
    return [("ok", {"epsilon": 0.9, "energy_drift": 1e-9}) for _ in specs]


def die_once(specs):
    """The first call kills its own worker process (kill -9); later calls succeed."""
    try:
        fd = os.open(os.environ["RESTITUTION_TEST_MARKER"], os.O_CREAT | os.O_EXCL)
    except FileExistsError:
        return ok_batch(specs)
    os.close(fd)
    os.kill(os.getpid(), signal.SIGKILL)
    return []  # pragma: no cover


def always_broken(specs):
    raise cf.process.BrokenProcessPool("a process in the pool was terminated abruptly")


def always_killed(specs):
    from types import SimpleNamespace

    from distributed import KilledWorker

    # What the scheduler raises after a task's workers died allowed_failures + 1 times.
    raise KilledWorker("collide_points", SimpleNamespace(address="tcp://10.0.0.1:4242"), 3)


def touch_marker(specs):
    open(os.environ["RESTITUTION_TEST_MARKER"], "w").close()
    return ok_batch(specs)


POINTS = [PointSpec(0.33, v, 100.0, 10) for v in (0.05, 0.1, 0.15, 0.2)]


# -- hangs: refused up front with an estimate -------------------------------------------------


@pytest.mark.parametrize(
    ("v", "alpha", "cause"),
    [(1e-9, 500.0, "raise v or alpha"), (0.1, 1e7, "lower alpha"), (0.1, 1e-6, "raise v")],
)
def test_hopeless_collisions_are_refused_with_the_estimate(small, no_integration, v, alpha, cause):
    with pytest.raises(InputError, match="time steps") as info:
        collide(small, v, alpha)
    assert "max_steps = 2000000" in str(info.value) and cause in str(info.value)


def test_hopeless_collision_at_the_command_line(cli, no_integration):
    code, out, err = cli("collide", "--v", "1e-9", "--modes", "20", "--json")
    one_line_error(code, err, "time steps", "raise v or alpha")
    assert out == ""


def test_work_estimate_is_near_the_steps_taken(small):
    # Measured: estimate 1735 / 5500 steps, taken 2288 / 5160 (the driver refines the step).
    for v, alpha in [(0.1, 500.0), (0.1, 5.0)]:
        est = estimate_work(small, np.array([v]), np.array([alpha]), CollisionSettings())
        taken = collide(small, v, alpha).n_steps
        assert 0.5 < est.steps / taken < 2.0, (v, alpha, est.steps, taken)


@pytest.mark.parametrize(
    "args",
    [
        ("modes", "--count", "1000000"),
        ("modes", "--omega-max", "1e4"),
        ("collide", "--v", "0.1", "--modes", "1000000"),
        ("quasistatic", "--v", "0.1", "--modes", "1000000"),
        ("compare-fem", "--modes", "20,1000000"),
    ],
)
def test_a_million_modes_is_refused_up_front(cli, monkeypatch, args):
    import dataclasses

    from restitution.bodies import kinds

    def refuse(*a, **k):
        raise AssertionError("modes were computed instead of refused")

    disk = dataclasses.replace(kinds.KINDS["disk"], compute=refuse)
    monkeypatch.setitem(kinds.KINDS, "disk", disk)
    code, _, err = cli(*args)
    one_line_error(code, err, str(MAX_MODES))


def test_mode_count_limit_in_the_library():
    with pytest.raises(InputError, match="not feasible"):
        get_modes(0.33, count=MAX_MODES + 1)


@pytest.mark.parametrize(
    "field",
    [
        {"step_safety": 0},
        {"step_safety": -1},
        {"step_safety": float("nan")},
        {"max_refinements": -1},
        {"max_refinements": 1.5},
        {"max_steps": 0},
        {"energy_tol": 0.0},
        {"energy_tol": float("inf")},
        {"n_phi": 4},
        {"record_interval": 0.0},
        {"record": "yes"},
        {"dt": -0.1},
    ],
)
def test_every_settings_field_is_checked(small, field):
    with pytest.raises(InputError, match=next(iter(field))):
        CollisionSettings(**field)
    with pytest.raises(InputError):
        collide(small, 0.1, 500.0, **field)


def test_non_dask_server_is_refused_within_the_deadline(silent_server):
    with pytest.raises(SchedulerError, match="did not answer as a Dask scheduler"):
        probe_scheduler(silent_server, timeout=1.0)


@pytest.mark.parametrize(
    ("address", "words"),
    [("notanaddress", "not a Dask scheduler address"), ("tcp://127.0.0.1:1", "cannot reach")],
)
def test_bad_scheduler_addresses(address, words):
    with pytest.raises(SchedulerError, match=words):
        probe_scheduler(address, timeout=1.0)


def test_scheduler_errors_at_the_command_line(cli, tmp_path):
    store = str(tmp_path / "s.sqlite")
    args = ("epsilon", "--nu", "0.33", "--v", "0.1", "--modes", "10", "14", "20")
    code, _, err = cli(*args, "--store", store, "--scheduler", "notanaddress")
    one_line_error(code, err, "tcp://HOST:8786")


def test_a_live_scheduler_passes_the_probe(client):
    assert probe_scheduler(client.scheduler.address)["type"] == "Scheduler"


# -- tracebacks that are now one line ---------------------------------------------------------


@pytest.mark.parametrize("alpha", ["1e300", "1e14"])
def test_absurd_wall_hardness(cli, no_integration, alpha):
    code, _, err = cli("collide", "--v", "0.1", "--alpha", alpha, "--modes", "20")
    one_line_error(code, err, "GiB")


def test_unknown_figure_format(cli, tmp_path):
    code, _, err = cli("modes", "--count", "20", "--plot-spectrum", str(tmp_path / "x.xyz"))
    one_line_error(code, err, "unknown figure format", ".png")


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_output_to_a_full_disk(cli):
    code, _, err = cli("modes", "--count", "20", "--output", "/dev/full")
    one_line_error(code, err, "No space left")


def test_output_into_a_read_only_directory(cli, tmp_path):
    folder = tmp_path / "ro"
    folder.mkdir()
    with read_only(folder):
        code, _, err = cli("modes", "--count", "20", "--output", str(folder / "m.csv"))
    one_line_error(code, err, "cannot write --output")


def test_curve_refuses_an_unwritable_out_before_computing(cli, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    store = tmp_path / "s.sqlite"
    args = ("curve", "--nu", "0.33", "--v", "0.1", "--modes", "10", "14", "20")
    code, _, err = cli(*args, "--store", str(store), "--out", str(blocker / "out"))
    one_line_error(code, err, "--out")
    assert not store.exists()  # nothing was computed


def _damaged_store(path):
    with Store(path) as db:
        for i in range(200):
            db.put_failure(PointSpec(0.33, 0.001 * (i + 1), 500.0, 20), "x" * 500)
    size = path.stat().st_size
    rng = np.random.default_rng(1)
    with open(path, "r+b") as fh:
        for page in range(3, size // 4096, 2):
            fh.seek(page * 4096 + 10)
            fh.write(rng.bytes(2000))


def test_damaged_store_is_one_clear_error(cli, tmp_path):
    path = tmp_path / "damaged.sqlite"
    _damaged_store(path)
    before = path.read_bytes()
    with pytest.raises(StoreError, match="damaged") as info:
        with Store(path) as db:
            db.points()
    assert "delete" not in str(info.value).lower() and ".recover" in str(info.value)
    assert path.read_bytes() == before
    args = ("epsilon", "--nu", "0.33", "--v", "0.1", "--modes", "10", "14", "20")
    code, _, err = cli(*args, "--store", str(path))
    one_line_error(code, err, "damaged")


def test_cache_dir_that_is_a_file(cli, tmp_path, monkeypatch):
    bad = tmp_path / "not-a-dir"
    bad.write_text("")
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(bad))
    with pytest.raises(CacheError, match="is a file"):
        cache_dir()
    with pytest.warns(UserWarning, match="without the cache"):
        modes = get_modes(0.33, count=5)  # the cache is optional
    assert len(modes) == 5
    code, _, err = cli("epsilon", "--nu", "0.33", "--v", "0.1")
    one_line_error(code, err, "RESTITUTION_CACHE_DIR")


def test_cache_dir_under_a_read_only_directory(tmp_path, monkeypatch):
    parent = tmp_path / "ro"
    parent.mkdir()
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(parent / "cache"))
    with read_only(parent):
        with pytest.raises(CacheError, match="cannot create"):
            cache_dir()
        with pytest.raises(CacheError, match="--store PATH"):
            Store()


@pytest.mark.parametrize(
    ("v", "alpha", "words"),
    [
        ([[0.1, 0.2]], [500.0], "1-D"),
        ([], [], "empty"),
        ([0.1, 0.2, 0.3], [500.0, 600.0], "equally many"),
        ([0.1, "x"], 500.0, "numbers"),
    ],
)
def test_bad_batches(small, v, alpha, words):
    with pytest.raises(InputError, match=words):
        collide_batch(small, v, alpha)


def test_collide_takes_one_speed(small):
    with pytest.raises(InputError, match="collide_batch"):
        collide(small, [0.1, 0.2], 500.0)
    with pytest.raises(InputError, match="ModeSet"):
        collide("modes", 0.1, 500.0)


# -- lost or stuck work ---------------------------------------------------------------------


def test_read_only_store_fails_before_computing(tmp_path, monkeypatch, client):
    path = tmp_path / "s.sqlite"
    run_sweep(POINTS[:1], store=path, client=client, batch_function=ok_batch)
    marker = tmp_path / "computed"
    monkeypatch.setenv("RESTITUTION_TEST_MARKER", str(marker))
    with read_only(path):
        with pytest.raises(StoreError, match="cannot be written") as info:
            run_sweep(POINTS, store=path, client=client, batch_function=touch_marker)
    assert not marker.exists()  # refused before any work
    assert "delete" not in str(info.value).lower()


def test_killed_pool_worker_is_retried_not_stored_as_failed(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_TEST_MARKER", str(tmp_path / "died"))
    path = tmp_path / "s.sqlite"
    report = run_sweep(POINTS, store=path, batch_function=die_once, batch_size=1, progress=False)
    assert (tmp_path / "died").exists()  # a worker really was killed
    assert report.computed == len(POINTS) and report.failed == () and report.lost == ()
    with Store(path) as db:
        assert all(p.ok for p in db.points())


@pytest.mark.parametrize(
    ("broken", "name"), [(always_broken, "BrokenProcessPool"), (always_killed, "KilledWorker")]
)
def test_persistent_infrastructure_failure_is_left_for_the_next_run(tmp_path, client, broken, name):
    path = tmp_path / "s.sqlite"
    report = run_sweep(POINTS, store=path, client=client, batch_function=broken)
    assert len(report.lost) == len(POINTS) and report.failed == () and not report.complete
    assert report.lost[0][1].startswith(name)
    with Store(path) as db:
        assert len(db) == 0  # nothing stored as failed
    again = run_sweep(POINTS, store=path, client=client, batch_function=ok_batch)
    assert again.computed == len(POINTS) and again.complete


def test_infrastructure_failures_stored_by_older_code_are_retried(tmp_path, client):
    path = tmp_path / "s.sqlite"
    with Store(path) as db:
        db.put_failure(POINTS[0], "BrokenProcessPool: A process in the pool was terminated")
        db.put_failure(POINTS[1], "CollisionError: energy drift still exceeds energy_tol")
    report = run_sweep(POINTS, store=path, client=client, batch_function=ok_batch)
    assert report.skipped == 1 and report.computed == 3  # the physics failure stays
    with Store(path) as db:
        assert not db.get(POINTS[1]).ok and db.get(POINTS[0]).ok


def test_valid_store_that_cannot_be_opened_is_never_called_foreign(tmp_path):
    path = tmp_path / "s.sqlite"
    Store(path).close()
    with Store(path) as db:
        for exc in (
            sqlite3.OperationalError("unable to open database file"),
            sqlite3.OperationalError("attempt to write a readonly database"),
        ):
            message = str(db._error(exc, opening=True))
            assert "not a restitution store" not in message
            assert "delete" not in message.lower() and "writable" in message


# -- the commands: failed points, --retry-failed, status, --strict, --quiet --------------------

GRID = ("--alphas", "20", "30", "40", "--alpha-scale", "absolute", "--modes", "10", "14", "20")


@pytest.fixture(scope="module")
def failing_store(tmp_path_factory):
    """A store where one point of the v = 0.2 grid is recorded as a physics failure."""
    path = tmp_path_factory.mktemp("failing") / "s.sqlite"
    settings = replace(
        DEFAULTS,
        velocities=(0.2,),
        alphas=(20.0, 30.0, 40.0),
        n_modes=(10, 14, 20),
        alpha_scale="absolute",
    )
    spec = grid([0.33], settings)[4]
    with Store(path) as db:
        db.put_failure(spec, "CollisionError: synthetic failure")
    return path, spec


def test_failed_points_make_curve_and_epsilon_exit_non_zero(cli, tmp_path, failing_store):
    path, spec = failing_store
    base = ("--nu", "0.33", "--v", "0.2", *GRID, "--store", str(path), "--no-progress")
    code, out, err = cli("curve", *base, "--out", str(tmp_path / "out"))
    assert code == 1, err
    assert "synthetic failure" in err and "--retry-failed" in err
    assert (tmp_path / "out" / "fig01_epsilon.png").exists()  # the rest is still written
    code, out, err = cli("epsilon", *base, "--json")
    assert code == 1
    doc = json.loads(out)
    assert doc["status"] == "points-failed" and "--retry-failed" in doc["advice"]
    code, out, err = cli("epsilon", *base, "--retry-failed", "--json")
    assert code == 0, err
    assert json.loads(out)["status"] in ("ok", "not-asymptotic")
    with Store(path) as db:
        assert db.get(spec).ok


def test_two_mode_counts_give_no_error_bar_and_strict_fails(cli, tmp_path):
    # Its own store: the module's failing store holds a failed point of this grid until another
    # test retries it, so sharing it made this test depend on the order (pytest-xdist).
    path = tmp_path / "s.sqlite"
    args = ("epsilon", "--nu", "0.33", "--v", "0.2", "--alphas", "20", "30")
    args += ("--alpha-scale", "absolute", "--modes", "10", "14", "--store", str(path))
    code, out, err = cli(*args, "--no-progress")
    assert code == 0 and "+- unknown" in out and "0.000000" not in out
    assert "not-asymptotic" in err
    code, out, err = cli(*args, "--no-progress", "--strict")
    assert code == _common.EXIT_NOT_CONVERGED


def test_repeated_mode_counts_are_refused(cli, tmp_path):
    args = ("epsilon", "--nu", "0.33", "--v", "0.1", "--modes", "20", "20", "20")
    code, _, err = cli(*args, "--store", str(tmp_path / "s.sqlite"))
    one_line_error(code, err, "repeated")


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("epsilon", "--nu", "0.33", "--v", "0.1", "--alpha", "500", "--alphas", "40", "80"),
         "--alpha"),
        (("collide", "--v", "0.1", "--method", "fem", "--modes", "5", "--select", "ranked"),
         "--modes, --select"),
        (("collide", "--v", "0.1", "--mesh-refine", "2"), "--mesh-refine"),
    ],
)  # fmt: skip
def test_ignored_options_are_refused(cli, args, words):
    code, _, err = cli(*args)
    one_line_error(code, err, words, "no effect" if args[0] == "collide" else "one or the other")


def test_fixed_step_with_large_drift_says_so(small):
    # dt = 0.02 at v = 0.1, alpha = 500 (N = 20): drift 7.7e-4 and epsilon 0.93600 against
    # 0.92833 with the automatic step (measured).
    r = collide(small, 0.1, 500.0, dt=0.02)
    assert r.energy_drift > r.energy_tol
    assert r.status == "drift-exceeded" and "dt" in r.advice
    d = r.to_dict()
    assert d["status"] == "drift-exceeded" and d["advice"] == r.advice
    good = collide(small, 0.1, 500.0)
    assert good.status == "ok" and good.advice is None
    assert abs(r.epsilon - good.epsilon) > 1e-3  # the warning is not idle


def test_strict_json_has_no_bare_nan():
    text = _common.dumps({"a": float("nan"), "b": [1.0, float("inf")], "c": np.float64("nan")})

    def refuse(name):
        raise AssertionError(f"bare {name} in JSON")

    assert json.loads(text, parse_constant=refuse) == {"a": None, "b": [1.0, None], "c": None}


ENVELOPE = {"version", "command", "units", "inputs", "status", "advice"}


@pytest.mark.parametrize(
    "args",
    [
        ("collide", "--v", "0.1", "--modes", "10", "--json"),
        ("modes", "--count", "10", "--format", "json"),
        ("quasistatic", "--v", "0.05", "--modes", "20", "--json"),
    ],
)
def test_every_json_has_the_same_envelope(cli, args):
    code, out, err = cli(*args)
    assert code == 0, err
    doc = json.loads(out, parse_constant=lambda name: pytest.fail(f"bare {name}"))
    assert ENVELOPE <= doc.keys()
    assert doc["version"] == restitution.__version__ and doc["units"] == restitution.UNITS
    assert doc["command"] == args[0] and doc["status"] == "ok"
    assert doc["inputs"]["nu"] == pytest.approx(0.33)


def test_quiet_silences_stderr(cli):
    args = ("collide", "--v", "0.35", "--alpha", "100", "--modes", "10", "--energy-tol", "1e-4")
    code, _, err = cli(*args)
    assert code == 0 and "linear elasticity" in err
    for quiet in (("--quiet", *args, "--json"), (*args, "--json", "-q")):
        code, out, err = cli(*quiet)
        assert code == 0 and err == "" and json.loads(out)["epsilon"] > 0
        # What -q silences on stderr the JSON still says (issue 30).
        assert json.loads(out)["status"] == "large-deformation"


def test_errors_are_exported():
    for name in ("CollisionError", "StoreError", "CacheError", "ModeError", "InputError"):
        err = getattr(restitution, name)
        assert issubclass(err, RestitutionError) and name in restitution.__all__


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("collide", "--v", "0.1", "--modes", "10", "--excite", "thermal", "--temperature", "-2"),
         "--temperature"),
        (("collide", "--v", "0.1", "--modes", "10", "--excite", "thermal", "--temperature", "1",
          "--samples", "0"), "--samples"),
        (("collide", "--v", "0.1", "--modes", "10", "--excite", "loud"), "unknown --excite"),
        (("bounce", "--v", "0.1", "--modes", "10", "--walls-distance", "0.5"), "--walls-distance"),
    ],
)  # fmt: skip
def test_bad_vibrating_input_is_one_line(cli, no_integration, args, words):
    code, _, err = cli(*args)
    one_line_error(code, err, words)


def test_laws_refuse_wrong_types_and_damaged_files_in_one_line(tmp_path):
    """Issue 30: wrong types at the law edge are InputErrors, not tracebacks; a law file that
    holds an impossible epsilon (1.7) or a non-number is refused on loading, not served."""
    import json
    from importlib import resources

    import restitution

    for bad in ({"E": "x"}, {"nu": None}, {"rho": [1]}, {"E": True}):
        args = {"E": 210e9, "nu": 0.3, "rho": 7850.0, "geometry": "sphere", "against": "wall"}
        with pytest.raises(InputError, match="must be a number"):
            restitution.si_law(**{**args, **bad})
    with pytest.raises(InputError, match="speeds must be numbers"):
        restitution.law(0.33).epsilon("x")
    text = resources.files("restitution.laws").joinpath("data", "law_nu0.33.json").read_text()
    for value, words in ((1.7, "0 < epsilon <= 1"), ("x", "not a valid law file")):
        doc = json.loads(text)
        doc["metadata"]["points"][3]["epsilon"] = value
        path = tmp_path / "damaged.json"
        path.write_text(json.dumps(doc))
        with pytest.raises(RestitutionError, match=words):
            restitution.law(path=path)


def test_a_negative_seed_is_one_line(capsys):
    """Issue 30: ``--seed -1`` was a numpy traceback."""
    from restitution.cli import main

    with pytest.raises(SystemExit):
        main(["collide", "--excite", "thermal", "--temperature", "0.1", "--seed", "-1",
              "--v", "0.1", "--modes", "10", "--samples", "2"])  # fmt: skip
    err = capsys.readouterr().err
    assert "the seed must be an integer >= 0" in err and "Traceback" not in err


def test_numba_compiles_into_the_package_cache_not_the_source_tree(tmp_path):
    """Issue 30: the compiled kernels were cached beside the sources (``__pycache__`` of an
    installed package). Importing the package points numba's cache at the package's cache
    unless the user chose one."""
    import sys

    code = (
        "import restitution, numba, os; "
        "print(numba.config.CACHE_DIR); print(os.environ['NUMBA_CACHE_DIR'])"
    )
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["RESTITUTION_CACHE_DIR"] = str(tmp_path)
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True).stdout.split()  # fmt: skip
    assert out == [str(tmp_path / "numba")] * 2
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "mine")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True).stdout.split()  # fmt: skip
    assert out == [str(tmp_path / "mine")] * 2


@pytest.mark.slow
@pytest.mark.parametrize("after_s", [0.0, 0.5, 1.5, 3.0, 6.0])
def test_ctrl_c_of_a_dask_sweep_stops_it_without_a_traceback(tmp_path, after_s):
    """Ctrl-C of ``curve --workers 2`` reaches the whole process group, workers included (as a
    terminal sends it). Workers interrupted while they started printed KeyboardInterrupt
    tracebacks, and the cluster's exit handler an AssertionError (issue 30); the workers then
    ignored SIGINT, but so did the sweep while they started, and a Ctrl-C in its first seconds
    was lost: the sweep ran to its end and exited 0 (issue 47). Now the workers never see it and
    the sweep takes it from the first second: exit 130, never a traceback. Not covered: a
    Ctrl-C while Python still imports the package (before the command's code runs) prints
    Python's own KeyboardInterrupt traceback; so the clock starts when the sweep has opened its
    store (under load the imports alone took over 1.5 s)."""
    import sys
    import time

    env = {**os.environ, "RESTITUTION_CACHE_DIR": str(tmp_path / "cache")}
    # Six speeds and N up to 6400: with numba's kernels cached, three speeds up to 3200 ended
    # 5.5 s after the store opened on an idle machine, before the latest Ctrl-C (stop 66).
    args = [sys.executable, "-c", "from restitution.cli import main; main()", "curve", "--nu",
            "0.33", "--v", "0.05", "0.1", "0.15", "0.2", "0.25", "0.3", "--modes", "400", "800",
            "1600", "3200", "6400",
            "--workers", "2", "--out", str(tmp_path / "out"), "--no-progress",
            "--store", str(tmp_path / "s.db")]  # fmt: skip

    def as_a_shell_starts_it():
        # A shell starts a command with Ctrl-C at its default. A parent that ignores or blocks
        # it would pass that on (an ignored signal stays ignored in a child). Suspected, not
        # confirmed, cause of 4 of 5 cases exiting 0 in one full `make test-slow` (stop 54).
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})

    proc = subprocess.Popen(args, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True,
                            preexec_fn=as_a_shell_starts_it)  # fmt: skip  # noqa: PLW1509
    try:
        store = tmp_path / "s.db"
        deadline = time.monotonic() + 120.0
        while not store.exists() and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert store.exists(), "the sweep never opened its store"
        time.sleep(after_s)
        assert proc.poll() is None, "the sweep ended before the Ctrl-C: give it more to do"
        os.killpg(proc.pid, signal.SIGINT)
        out, err = proc.communicate(timeout=240)
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
    text = err.decode()
    assert "Traceback" not in text and "Error" not in text.replace("error:", ""), text
    assert proc.returncode == 130, text


# -- issue 47 ---------------------------------------------------------------------------------


def test_speeds_in_any_order_are_computed_and_written(cli, tmp_path):
    """`curve --v 0.1 0.05` computed the whole grid, then failed on `x must be strictly
    increasing` and wrote nothing; the sweep now keeps its speeds in increasing order."""
    from restitution.limits.sweep import SweepSettings

    assert SweepSettings(velocities=(0.1, 0.05)).velocities == (0.05, 0.1)
    out = tmp_path / "out"
    code, _, err = cli("curve", "--nu", "0.33", "--v", "0.1", "0.05", "--modes", "20", "30",
                       "40", "--store", str(tmp_path / "s.sqlite"), "--out", str(out))  # fmt: skip
    assert code in (0, 1), err  # 1: few modes are not asymptotic (a warning, files written)
    assert "Traceback" not in err
    written = json.loads((out / "law_nu0.33.json").read_text())
    assert [p["v"] for p in written["metadata"]["points"]] == [0.05, 0.1]


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (("modes", "--nu", "0.33", "--omega-max", "1e300"), "more than the feasible"),
        (("modes", "--nu", "0.33", "--omega-max", "1e-300"), "no mode of the disk"),
        (("modes", "--nu", "0.33", "--omega-max", "1.0"), "no mode of the disk"),
        (("modes", "--geometry", "sphere", "--nu", "0.3", "--omega-max", "1e-300"),
         "no mode of the sphere"),
        (("collide", "--nu", "0.33", "--v", "0.1", "--modes", "20", "--density-ratio", "1e-300"),
         "outside 1e-12 ... 1e+12"),
        (("collide", "--nu", "0.33", "--v", "0.1", "--modes", "20", "--radius-ratio", "100"),
         "use about 11959 modes"),
        (("collide", "--nu", "0.33", "--v", "0.1", "--modes", "20", "--radius-ratio", "1e-6"),
         "collide with the wall instead"),
    ],
)  # fmt: skip
def test_frequencies_and_ratios_beyond_the_body_are_refused(cli, args, match):
    """Issue 47: OverflowError, an empty concatenate, ZeroDivisionError in the kernel, and a
    pair in which one body gets no modes answering epsilon = 1 with status ok."""
    code, _, err = cli(*args)
    one_line_error(code, err, match)


def test_epsilon_beyond_the_linear_range_is_not_ok(cli, tmp_path):
    """Issue 47: `epsilon --v 0.9999` said ok where `collide` said large-deformation; both now
    judge the speed alike (v > 0.3 c: linear elasticity stretched)."""
    store = str(tmp_path / "s.sqlite")
    code, out, _ = cli("epsilon", "--nu", "0.33", "--v", "0.5", "--modes", "40", "80", "160",
                       "--alpha", "100", "--json", "--store", store)  # fmt: skip
    assert code == 0
    d = json.loads(out)
    assert d["status"] == "large-deformation" and "use v <= 0.3" in d["advice"]


@pytest.mark.parametrize("kind", ["deep", "device"])
def test_law_files_that_are_not_law_files_are_refused_before_reading(cli, tmp_path, kind):
    """Issue 47: a deeply nested JSON file raised RecursionError; --law-file /dev/zero grew
    without bound and ignored Ctrl-C."""
    if kind == "deep":
        path = tmp_path / "deep.json"
        path.write_text("[" * 100_000 + "]" * 100_000)
        match = "nested too deeply"
    else:
        path = "/dev/zero"
        if not os.path.exists(path):
            pytest.skip("no /dev/zero here")
        match = "not a regular file"
    steel = ("--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "cylinder")
    code, _, err = cli("law", *steel, "--against", "wall", "--speed", "1", "--law-file", str(path))
    one_line_error(code, err, match)


def test_stored_rows_are_range_checked_when_read(tmp_path):
    """Issue 47: a store row that is not JSON gave a traceback, and values read back from a
    store were not range-checked the way law files are. A damaged row is now a failed point
    that says why and what to do; a row whose inputs are unreadable is one clear error."""
    from restitution.dynamics.collision import collide as run

    path = tmp_path / "s.sqlite"
    good, bad, broken = (PointSpec(0.33, v, 500.0, 10) for v in (0.1, 0.2, 0.3))
    modes = get_modes(0.33, count=10)
    with Store(path) as db:
        for spec in (good, bad, broken):
            db.put(spec, run(modes, spec.v, spec.alpha))
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE collisions SET epsilon = 1.7 WHERE key = ?", (bad.key(),))
        conn.execute("UPDATE collisions SET result = '{not json' WHERE key = ?", (broken.key(),))
    with Store(path) as db:
        assert db.get(good).status == "ok"
        for spec, why in ((bad, "outside [0, 1]"), (broken, "not JSON")):
            p = db.get(spec)
            assert p.status == "failed" and why in p.error and "fresh store" in p.error
            assert np.isnan(p.epsilon)
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE collisions SET inputs = '{' WHERE key = ?", (good.key(),))
    with Store(path) as db:
        assert "not JSON" in db.get(good).error
        with pytest.raises(StoreError, match="inputs are not JSON"):
            db.points(all_versions=True)


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (("curve", "--out", ""), "'--out': is empty"),
        (("law", "--export", " "), "'--export': is empty"),
        (("collide", "--bogus"), "No such option '--bogus'"),
        # A bad speed in the command's words, not the library's ("speeds ... array(...)").
        (
            (
                "law",
                "--E",
                "210e9",
                "--nu",
                "0.3",
                "--rho",
                "7850",
                "--shape",
                "sphere",
                "--against",
                "wall",
                "--speed",
                "1",
                "--speed",
                "-1",
            ),
            "--speed must be a finite number > 0 (m/s), got -1.0",
        ),  # fmt: skip
    ],
)
def test_usage_errors_are_one_line_and_an_empty_path_is_refused(cli, tmp_path, args, match,
                                                                monkeypatch):  # fmt: skip
    """Issue 47: `--out ''` wrote into the working directory; click's usage errors took four
    lines."""
    monkeypatch.chdir(tmp_path)
    code, _, err = cli(*args)
    one_line_error(code, err, match)
    assert list(tmp_path.iterdir()) == []


def test_a_store_that_fills_during_a_sweep_reports_the_full_disk(tmp_path, monkeypatch):
    """Issue 47: the clear error of a store whose disk filled during a sweep was masked by a
    traceback from releasing the sweep's claims on that same full disk."""
    from restitution.limits.claims import Claims
    from restitution.limits.sweep import SweepSettings, grid, run_sweep

    def full(self, spec, result):
        raise StoreError("the result store's disk is full; free space or use another --store")

    def release(self):
        raise sqlite3.OperationalError("database or disk is full")

    monkeypatch.setattr(Store, "put", full)
    monkeypatch.setattr(Claims, "release", release)
    settings = SweepSettings(velocities=(0.1,), n_modes=(10,), alphas=(40.0,))
    with pytest.raises(StoreError, match="disk is full; free space"):
        run_sweep(grid([0.33], settings), store=tmp_path / "s.sqlite", workers=1,
                  progress=False)  # fmt: skip


@pytest.mark.parametrize(
    ("fields", "match"),
    [
        ({"velocities": 0.1}, "velocities must be a sequence of numbers"),
        ({"n_modes": [[10]]}, "n_modes must be a sequence of numbers"),
        ({"n_modes": [10.5]}, "n_modes must be whole numbers"),
        ({"alphas": "40"}, r"alphas=\(40, 80, 160\)"),
    ],
)
def test_sweep_settings_of_the_wrong_shape_are_one_clear_error(fields, match):
    """Issue 47: API settings given as a bare number or a nested list raised TypeError."""
    from restitution.limits.sweep import SweepSettings

    with pytest.raises(InputError, match=match):
        SweepSettings(**fields)
    assert SweepSettings(n_modes=np.array([10, 20])).n_modes == (10, 20)


def test_an_unwritable_cache_sends_numba_to_a_temporary_folder(tmp_path):
    """Issue 47: with a cache directory that cannot be made, numba wrote its kernels next to
    the package's sources; it now gets a folder of this user in the temporary directory."""
    import sys
    import tempfile

    blocker = tmp_path / "a-file"
    blocker.write_text("")
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["RESTITUTION_CACHE_DIR"] = str(blocker / "cache")
    code = "import os, restitution; print(os.environ['NUMBA_CACHE_DIR'])"
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True).stdout.strip()  # fmt: skip
    assert out.startswith(tempfile.gettempdir()) and "restitution-numba-" in out


def test_a_refused_step_count_names_step_safety_and_max_steps():
    """Issue 47: a tiny step_safety or max_steps was blamed on alpha alone."""
    modes = get_modes(0.33, count=20)
    with pytest.raises(InputError, match="step_safety = 1e-06 shrinks every step"):
        collide(modes, 0.1, 100.0, CollisionSettings(step_safety=1e-6))
    with pytest.raises(InputError, match=r"raise max_steps \(now 10\)"):
        collide(modes, 0.1, 100.0, CollisionSettings(max_steps=10))
    # Following the advice works: the default step_safety and max_steps run it.
    assert 0 < collide(modes, 0.1, 100.0).epsilon <= 1


def test_a_curve_that_cannot_finish_writing_leaves_the_folder_as_it_was(cli, tmp_path, monkeypatch):
    """Issue 47 (a folder mixing two runs): the disk fills while `curve` writes its last file;
    the run's figures and law files appear together or not at all, the earlier file stays,
    and the error is one line."""
    import errno

    from restitution.laws.law import EpsilonLaw

    out = tmp_path / "out"
    out.mkdir()
    (out / "law_nu0.33.json").write_text("an earlier run's law")

    def full(self, path, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(EpsilonLaw, "to_table", full)
    code, _, err = cli("curve", "--nu", "0.33", "--v", "0.1", "0.2", *GRID, "--store",
                       str(tmp_path / "s.sqlite"), "--no-progress", "--out", str(out))  # fmt: skip
    one_line_error(code, err, "No space left")
    assert sorted(p.name for p in out.iterdir()) == ["law_nu0.33.json"]
    assert (out / "law_nu0.33.json").read_text() == "an earlier run's law"


def test_a_radius_ratio_given_to_seven_digits_is_the_shipped_pairs(cli):
    """Issue 47 (a self-contradicting refusal): --partner-radius-ratio 1.4000001 found the law
    file of 1.4 and refused it as another pair; ratios are read to six significant digits, as
    the files name them, so it is served by that law."""
    base = ("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "cylinder",
            "--against", "grain", "--speed", "1", "--json")  # fmt: skip
    code, out, err = cli(*base, "--partner-radius-ratio", "1.4000001")
    assert code == 0, err
    code, same, err = cli(*base, "--partner-radius-ratio", "1.4")
    first, second = json.loads(out), json.loads(same)
    assert first["points"][0]["epsilon"] == second["points"][0]["epsilon"]


def test_a_disk_poisson_number_near_minus_one_is_refused_at_once(cli):
    """Issue 47 (a 10-minute scan; NaN amplitudes served as ok): the disk takes 2D nu above
    -0.999, where its mode scan was measured (600 modes in 8 s, every amplitude finite); at
    -0.9999 it took 17 s for 100 modes and their normalisation failed. Refused in one line,
    before any scan."""
    code, _, err = cli("modes", "--nu", "-0.9999", "--count", "600")
    one_line_error(code, err, "(-0.999, 1)")
    modes = get_modes(-0.998, count=40)
    assert np.all(np.isfinite(modes.C)) and np.all(np.isfinite(modes.S))


# -- issue 47, the rerun of the audit's classes (session of stop 54) ---------------------------

_STEEL = ("--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere", "--against", "wall")


@pytest.mark.parametrize(
    ("args", "match"),
    [
        # Underflowing reduced speeds reached the routes' quadratures (ZeroDivisionError,
        # "Maximum allowed size exceeded") and the FEM's start gap (math domain error).
        ((*_STEEL, "--speed", "1e-300"), "below 1e-16 c the vibrational loss"),
        ((*_STEEL, "--speed", "1", "--reference-speed", "1e-300"), "is 1.93e-304 c of this grain"),
        (("law", "--E", "1e300", *_STEEL[2:], "--speed", "1"), "c = 1.13e+148 m/s"),
        (("compare-fem", "--nu", "0.33", "--v", "1e-300"), "more than the 1 h bound"),
        # Forcing was offered (and taken) for a run of 7.6e295 days: advice that fails.
        (("compare-fem", "--nu", "0.33", "--v", "1e-300", "--force"), "--force is no way out"),
        # An infinite approach was blamed on the modes ("use fewer modes").
        (("collide", "--nu", "0.33", "--v", "1e-300", "--modes", "20"), "raise v or alpha"),
        # At rest there is no collision: the routes refused 0 in their own words.
        ((*_STEEL, "--speed", "0"), "--speed must be a finite number > 0 (m/s), got 0.0"),
    ],
)
def test_extreme_speeds_and_moduli_end_in_one_line(cli, args, match):
    if args[0] not in ("compare-fem", "collide", "law"):
        args = ("law", *args)
    code, _, err = cli(*args)
    one_line_error(code, err, match)


@pytest.mark.parametrize(
    ("args", "option", "python_only"),
    [
        (("collide", "--nu", "0.33", "--v", "0.1", "--modes", "20", "--energy-tol", "1e-300"),
         "--energy-tol", "max_steps"),
        (("collide", "--nu", "0.33", "--v", "0.1", "--modes", "20", "--alpha", "1e300"),
         None, "n_phi"),
    ],
)  # fmt: skip
def test_refusals_name_the_commands_options(cli, args, option, python_only):
    """Issue 47: the command line's refusals named Python arguments (`raise energy_tol or
    max_steps`); now an argument the command has is its option, one it lacks is marked as a
    setting of the Python API, where the advice can be followed."""
    import re

    code, _, err = cli(*args)
    one_line_error(code, err, python_only)
    if option is not None:
        assert option in err and "energy_tol" not in err
    assert f"{python_only} (a setting of the Python API only)" in err
    assert not re.search(rf"{python_only}(?! \(a setting)", err)


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_a_bounce_estimate_covers_the_steps_it_takes(monkeypatch):
    """Issue 47: the `bounce` time estimate was 3.5-7.5 times optimistic. It counted every
    collision as the first one from rest; the later ones start vibrating and refine their steps.
    The estimate's steps now cover every step the integrator takes (counted, every run of every
    refinement; no clock): here the case that needed the most in the benchmark's 32 sequences
    (N = 10, v = 0.1, alpha = 2000 under gravity) and two others. Its seconds are those steps
    times the per-step cost that ``benchmarks/bench_bounce_estimate.py`` measures."""
    import restitution.dynamics.collision as collision
    from restitution.bodies.cache import get_modes
    from restitution.bodies.material import Material
    from restitution.budget import collision_seconds
    from restitution.vibrating.sequences import bounce, check_bounce_time

    counted = [0]
    for name in ("run_kernel", "run_numpy"):
        original = getattr(collision, name)

        def run(*args, _original=original, **kwargs):
            got = _original(*args, **kwargs)
            counted[0] += sum(getattr(member, "steps", 0) for member in got)
            return got

        monkeypatch.setattr(collision, name, run)
    for n, v, alpha, flight in [(10, 0.1, 2000.0, {"gravity": 1e-4}),
                                (40, 0.1, 500.0, {"gravity": 1e-4}),
                                (160, 0.01, 2000.0, {"walls_distance": 2.5})]:  # fmt: skip
        modes = get_modes(Material(nu=0.33), count=n)
        estimate_s = check_bounce_time(modes, v, alpha, 8)
        counted[0] = 0
        bounce(modes, v, alpha, 8, **flight)
        assert counted[0] * collision_seconds(1, n) <= estimate_s, (n, v, alpha, counted[0])


@pytest.mark.parametrize(("geometry", "count", "alpha"), [("disk", 300, 2e8), ("sphere", 400, 5e5)])
def test_the_memory_estimate_covers_the_quadrature_it_builds(geometry, count, alpha):
    """Issue 47: `epsilon --nu 0.33 --v 1e-9` was not refused and grew to 10-12 GB: the
    estimate of a collision's memory counted the basis table the surface quadrature keeps, not
    the temporaries of building it (the peak resident memory of one collision grew 2.75 times
    the estimate for the disk, 3.27 for the sphere). The allocations of building the quadrature
    are traced here (numpy reports them to tracemalloc) and must lie within the estimate of the
    whole collision."""
    import tracemalloc

    from restitution.bodies.cache import get_modes
    from restitution.dynamics.collision import CollisionSettings
    from restitution.dynamics.steps import estimate_work

    nu = 0.33 if geometry == "disk" else 0.3
    body = get_modes(nu, count, geometry=geometry)
    est = estimate_work(body, np.array([1e-9]), np.array([alpha]), CollisionSettings())
    tracemalloc.start()
    try:
        body.surface_quadrature(est.n_phi)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak > 2**24  # a table of tens of MB: what the estimate is about
    assert peak <= est.memory_bytes, (peak / 2**20, est.memory_bytes / 2**20)
