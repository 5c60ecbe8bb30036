"""The SQLite result store: keys, upserts, concurrency, foreign files."""

import dataclasses
import multiprocessing
import sqlite3

import numpy as np
import pytest

from restitution.limits import store as store_module
from restitution.limits.store import PointSpec, Store, StoreError, default_store_path

SPEC = PointSpec(nu=0.33, v=0.1, alpha=500.0, n_modes=40, options={"energy_tol": 1e-6})


def _result(eps=0.9):
    # The shape of CollisionResult.to_dict(), with numpy scalars as the solver produces them.
    return {
        "method": "modal",
        "epsilon": np.float64(eps),
        "energy_loss": 1 - eps**2,
        "energy_drift": 1e-7,
        "n_steps": np.int64(1234),
        "dt": 1e-3,
        "contact_time": 5.0,
        "max_compression": 0.01,
        "max_force": 2.0,
        "wall_time_s": 0.5,
        "mode_energies_after": [{"n": 2, "l": 0, "energy": 0.01}],
    }


def test_round_trip(tmp_path):
    with Store(tmp_path / "r.sqlite") as db:
        assert db.get(SPEC) is None
        db.put(SPEC, _result())
        row = db.get(SPEC)
        assert row.ok and row.spec == SPEC
        assert row.epsilon == 0.9 and row.n_steps == 1234
        assert row.energy_loss == pytest.approx(0.19, rel=1e-14)
        assert row.result["mode_energies_after"][0]["n"] == 2
        assert db.points(nu=0.33)[0].spec == SPEC
        assert db.points(nu=0.5) == []
        assert row.code_version == store_module.code_version("disk")
        assert row.code_version.startswith(store_module.__version__)
    # WAL mode is persistent in the file.
    conn = sqlite3.connect(tmp_path / "r.sqlite")
    assert conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    conn.close()


def test_key_depends_on_every_input_and_the_version(monkeypatch):
    changes = {
        "nu": 0.34,
        "v": 0.1000000001,
        "alpha": 501.0,
        "n_modes": 41,
        "select": "ranked",
        "integrator": "rk4",
        "options": {"energy_tol": 1e-7},
        "geometry": "sphere",
    }
    keys = {SPEC.key()}
    for name, value in changes.items():
        keys.add(dataclasses.replace(SPEC, **{name: value}).key())
    assert len(keys) == len(changes) + 1
    # The code version is part of the key: another version or solver source, another key.
    monkeypatch.setattr(
        store_module, "code_version", lambda geometry="disk", pair=False: "999.0+0123456789ab"
    )
    assert SPEC.key() not in keys


def test_failure_is_recorded_and_replaced_by_a_later_success(tmp_path):
    with Store(tmp_path / "r.sqlite") as db:
        db.put_failure(SPEC, "CollisionError: drift too large")
        row = db.get(SPEC)
        assert row.status == "failed" and "drift" in row.error and np.isnan(row.epsilon)
        db.put(SPEC, _result(0.8))
        db.put_failure(SPEC, "a later failure never replaces a success")
        db.put(SPEC, _result(0.7))  # nor does a repeated success
        assert db.get(SPEC).epsilon == 0.8
        assert len(db) == 1


def _writer(path, worker, count):
    with Store(path) as db:
        for i in range(count):
            # Half the keys are shared between writers: concurrent writes of one point.
            spec = PointSpec(0.33, 0.01 * (i + 1), 100.0 + (worker if i % 2 else 0), 20)
            db.put(spec, _result(0.5 + 0.001 * i))


def test_concurrent_writers(tmp_path):
    path = tmp_path / "c.sqlite"
    Store(path).close()
    # fork: cheap, and no connection is open in the parent while the children write.
    ctx = multiprocessing.get_context("fork")
    procs = [ctx.Process(target=_writer, args=(path, w, 40)) for w in range(3)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(120)
    assert [p.exitcode for p in procs] == [0, 0, 0]
    with Store(path) as db:
        # 20 shared keys + 3 x 20 own keys; no duplicates, no losses.
        assert len(db) == 20 + 3 * 20
        assert len({r.spec.key() for r in db}) == len(db)


def test_foreign_text_file_is_refused_and_kept(tmp_path):
    path = tmp_path / "results.sqlite"
    path.write_text("my notes, not a database\n")
    with pytest.raises(StoreError, match="not a SQLite database") as info:
        Store(path)
    assert str(path) in str(info.value) and "--store PATH" in str(info.value)
    assert "delete" not in str(info.value).lower()
    assert path.read_text() == "my notes, not a database\n"


def test_corrupt_sqlite_file_is_refused_and_kept(tmp_path):
    path = tmp_path / "results.sqlite"
    path.write_bytes(b"SQLite format 3\x00" + b"\xff" * 200)  # a header, then garbage
    with pytest.raises(StoreError, match="not a restitution store") as info:
        Store(path)
    assert str(path) in str(info.value)
    assert path.read_bytes() == b"SQLite format 3\x00" + b"\xff" * 200


def test_foreign_sqlite_file_is_refused_and_kept(tmp_path):
    path = tmp_path / "other.sqlite"
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE things (a)")
    conn.commit()
    conn.close()
    before = path.read_bytes()
    with pytest.raises(StoreError, match="other tables"):
        Store(path)
    assert path.read_bytes() == before


def test_store_without_marker_is_refused(tmp_path):
    path = tmp_path / "m.sqlite"
    Store(path).close()
    conn = sqlite3.connect(path)
    conn.execute("UPDATE meta SET value = 'someone-else' WHERE key = 'schema'")
    conn.commit()
    conn.close()
    with pytest.raises(StoreError, match="schema marker"):
        Store(path)


def test_default_path_is_in_the_cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    assert default_store_path() == tmp_path / "cache" / "results.sqlite"
    with Store() as db:
        assert db.path == tmp_path / "cache" / "results.sqlite"
