"""A set of files in a user's folder touches only the package's own files (restitution.file_set).

Issue 64 ("data lost"): `law --export .` deleted a user's epsilon.py, epsilon_analysis.ipynb and
epsilon.tex (every file matching the export's family globs), and a SIGKILL during the renames
left a folder mixing two materials' files and a staging folder that was never removed.
"""

from __future__ import annotations

import errno
import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

from restitution import atomic
from restitution.errors import OutputError
from restitution.file_set import STAGING_PREFIX, file_set, manifest_path, recover


def _full_disk(*args, **kwargs):
    raise OSError(errno.ENOSPC, "No space left on device")


def _names(folder):
    return sorted(p.name for p in folder.iterdir())


def _write(folder, files, name="export", **kw):
    with file_set(folder, name, **kw) as stage:
        for n, text in files.items():
            atomic.write_text(stage / n, text)


def test_a_failed_set_leaves_the_folder_as_it_was(tmp_path):
    out = tmp_path / "out"
    _write(out, {"epsilon.csv": "old csv", "epsilon_lammps.in": "old snippet"})
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    with pytest.raises(OSError, match="No space"):
        with file_set(out) as stage:
            atomic.write_text(stage / "epsilon.csv", "new csv")
            _full_disk()
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before


def test_the_users_files_of_the_same_family_are_never_removed(tmp_path):
    """The audit's case: the user's epsilon.py, notebook and TeX file beside an export."""
    out = tmp_path
    mine = {"epsilon.py": "print(1)\n", "epsilon_analysis.ipynb": "{}", "epsilon.tex": "\\x"}
    for n, text in mine.items():
        (out / n).write_text(text)
    _write(out, {"epsilon.csv": "a", "epsilon_lammps.in": "b"})
    _write(out, {"epsilon.csv": "c"})  # the second export writes no snippet
    for n, text in mine.items():
        assert (out / n).read_text() == text
    assert not (out / "epsilon_lammps.in").exists()  # its own stale file, unchanged: removed
    assert (out / "epsilon.csv").read_text() == "c"
    assert json.loads(manifest_path(out, "export").read_text())["files"].keys() == {"epsilon.csv"}


def test_a_real_export_into_a_users_project_keeps_their_files(tmp_path):
    from restitution.laws import exports
    from restitution.laws.si_law import si_law

    s = si_law(63e9, 0.2481, 2500, "cylinder", "wall")
    mine = {"epsilon.py": "x = 1\n", "epsilon_analysis.ipynb": "{}", "epsilon.tex": "t"}
    for n, text in mine.items():
        (tmp_path / n).write_text(text)
    first = exports.write_folder(s, exports.constant_at(s, 1.0), tmp_path)
    second = exports.write_folder(s, None, tmp_path)
    assert len(second.paths) < len(first.paths)
    for n, text in mine.items():
        assert (tmp_path / n).read_text() == text
    ours = {p.name for p in second.paths}
    assert set(_names(tmp_path)) == ours | set(mine) | {".restitution-export.json"}


def test_a_file_the_package_did_not_write_is_never_replaced(tmp_path):
    (tmp_path / "epsilon.csv").write_text("the user's own table")
    with pytest.raises(OutputError, match=r"epsilon\.csv exists and was not written"):
        _write(tmp_path, {"epsilon.csv": "new", "epsilon.h": "header"})
    assert _names(tmp_path) == ["epsilon.csv"]
    assert (tmp_path / "epsilon.csv").read_text() == "the user's own table"


def test_a_file_changed_since_it_was_written_is_neither_replaced_nor_removed(tmp_path):
    _write(tmp_path, {"epsilon.csv": "a", "epsilon_lammps.in": "b"})
    (tmp_path / "epsilon_lammps.in").write_text("b, edited by hand")
    _write(tmp_path, {"epsilon.csv": "c"})  # would remove the stale snippet, were it unchanged
    assert (tmp_path / "epsilon_lammps.in").read_text() == "b, edited by hand"
    (tmp_path / "epsilon.csv").write_text("c, edited by hand")
    with pytest.raises(OutputError, match="was changed since restitution wrote it"):
        _write(tmp_path, {"epsilon.csv": "d"})
    assert (tmp_path / "epsilon.csv").read_text() == "c, edited by hand"


def test_a_set_that_adds_keeps_the_files_of_earlier_runs(tmp_path):
    _write(tmp_path, {"law_nu0.2.json": "a"}, "curve", prune=False)
    _write(tmp_path, {"law_nu0.3.json": "b"}, "curve", prune=False)
    assert _names(tmp_path) == [".restitution-curve.json", "law_nu0.2.json", "law_nu0.3.json"]
    # Files written by another set of the package may be replaced too (they are its own).
    _write(tmp_path, {"law_nu0.2.json": "c"}, "export")
    assert (tmp_path / "law_nu0.2.json").read_text() == "c"


def test_an_unfinished_staging_folder_is_removed_and_a_live_one_left(tmp_path):
    dead = tmp_path / f"{STAGING_PREFIX}dead"
    dead.mkdir()
    (dead / "epsilon.csv").write_text("half a set")
    with file_set(tmp_path) as stage:
        atomic.write_text(stage / "epsilon.h", "h")
        assert recover(tmp_path) == 0  # the live set (this one) holds its lock
        assert stage.exists()
    assert _names(tmp_path) == [".restitution-export.json", "epsilon.h"]


_KILLED = textwrap.dedent(
    """
    import os, sys, time
    from restitution import atomic, file_set as fs
    out = sys.argv[1]
    real, count = os.replace, [0]
    def slow(a, b):
        real(a, b)
        count[0] += 1
        if count[0] == 3:  # the journal's rename, then two of the set's
            print("moving", flush=True)
            time.sleep(60)
    with fs.file_set(out) as stage:
        for k in range(5):
            atomic.write_text(stage / f"epsilon_{k}.txt", "second")
        os.replace = slow
    """
)


def test_a_set_killed_while_it_moves_is_finished_by_the_next(tmp_path):
    """SIGKILL after two of five renames (the audit's mixed folder of two materials): the
    next set written into the folder, or recover(), first finishes the killed one."""
    out = tmp_path / "out"
    _write(out, {f"epsilon_{k}.txt": "first" for k in range(5)})
    proc = subprocess.Popen(
        [sys.executable, "-c", _KILLED, str(out)], stdout=subprocess.PIPE, text=True
    )
    assert proc.stdout.readline().strip() == "moving"
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    texts = [(out / f"epsilon_{k}.txt").read_text() for k in range(5)]
    assert sorted(texts) == ["first"] * 3 + ["second"] * 2  # mixed, as a kill leaves it
    assert recover(out) == 1
    assert [(out / f"epsilon_{k}.txt").read_text() for k in range(5)] == ["second"] * 5
    assert not list(out.glob(f"{STAGING_PREFIX}*"))


def test_ctrl_c_between_renames_finishes_the_set(tmp_path, monkeypatch):
    out = tmp_path / "out"
    _write(out, {f"epsilon_{k}.txt": "first" for k in range(4)})
    real, count = os.replace, [0]

    def interrupted(a, b):
        real(a, b)
        count[0] += 1
        if count[0] == 2:  # the journal's rename, then one of the set's
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        with file_set(out) as stage:
            for k in range(4):
                atomic.write_text(stage / f"epsilon_{k}.txt", "second")
            monkeypatch.setattr(os, "replace", interrupted)
    monkeypatch.undo()
    assert [(out / f"epsilon_{k}.txt").read_text() for k in range(4)] == ["second"] * 4
    assert not list(out.glob(f"{STAGING_PREFIX}*"))


def test_a_staging_folder_is_private_to_its_run(tmp_path):
    """Two runs into one folder: the second does not touch the first's staging folder while
    the first is alive, and both sets land whole."""
    with file_set(tmp_path, "a") as first:
        atomic.write_text(first / "one.txt", "1")
        _write(tmp_path, {"two.txt": "2"}, "b")
        assert first.exists() and (first / "one.txt").exists()
    assert _names(tmp_path) == [".restitution-a.json", ".restitution-b.json", "one.txt", "two.txt"]


def test_a_full_disk_during_an_export_names_the_option_and_the_folder(cli, tmp_path, monkeypatch):
    """Issue 64: a full disk during --export said only "No space left on device"."""
    from _cli_checks import one_line_error

    from restitution import file_set as fs

    monkeypatch.setattr(fs, "_digest", _full_disk)  # the first read-back of a staged file
    out = tmp_path / "out"
    code, _, err = cli("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--shape",
                       "cylinder", "--against", "wall", "--speed", "1",
                       "--export", str(out))  # fmt: skip
    one_line_error(code, err, f"--export {out}", "No space left", "free some space")
    assert _names(out) == []
