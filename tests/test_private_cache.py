"""numba's compiled kernels go only to folders of this user (hostile-input issue).

numba's index files are pickles, and loading a pickle runs code: a cache folder another user
planted (``<tmp>/restitution-numba-<uid>`` made beforehand with mode 0777, or a symlink at that
name) was used unchecked. These tests run as root on the project's machine, where
``os.access`` grants everything: an unwritable cache root is made by putting it under a
regular file (its ``mkdir`` fails), and "another user" by ``os.chown`` to uid 12345.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

import pytest

from restitution import _paths

OTHER_UID = 12345
"""A uid that is not ours, for folders "another user" made."""

needs_posix = pytest.mark.skipif(not hasattr(os, "getuid"), reason="uids and modes are POSIX")
needs_root = pytest.mark.skipif(
    not hasattr(os, "geteuid") or os.geteuid() != 0, reason="chown to another uid needs root"
)


@pytest.fixture
def tmp(monkeypatch, tmp_path):
    """The system's temporary directory, moved to a fresh folder, with a cache root that
    cannot be created (under a regular file): numba is sent to the fallback folder."""
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(blocker / "cache"))
    folder = tmp_path / "tmp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


def fixed_name(tmp: Path) -> Path:
    return tmp / f"restitution-numba-{os.getuid()}"


def assert_private(path: Path) -> None:
    st = os.lstat(path)
    assert stat.S_ISDIR(st.st_mode) and not stat.S_ISLNK(st.st_mode)
    assert st.st_uid == os.getuid()
    assert stat.S_IMODE(st.st_mode) & 0o077 == 0


def quiet_call() -> Path:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return _paths.numba_cache_dir()


def rejected_call(match: str) -> Path:
    with pytest.warns(RuntimeWarning, match=match) as record:
        got = _paths.numba_cache_dir()
    assert len(record) == 1
    return got


@needs_posix
def test_the_fallback_folder_is_made_private_and_reused(tmp):
    first = quiet_call()
    assert first == fixed_name(tmp)
    assert_private(first)
    assert stat.S_IMODE(os.lstat(first).st_mode) == 0o700
    (first / "kernel.nbi").write_text("kept")
    assert quiet_call() == first  # the second process finds its own folder and keeps it
    assert (first / "kernel.nbi").read_text() == "kept"


@needs_posix
def test_a_fallback_folder_open_to_every_user_is_refused(tmp):
    planted = fixed_name(tmp)
    planted.mkdir()
    planted.chmod(0o777)
    (planted / "index.nbi").write_text("another user's pickle")
    got = rejected_call(rf"{planted}.*mode 0777.*Remove .*RESTITUTION_CACHE_DIR")
    assert got != planted and got.parent == tmp and got.name.startswith("restitution-numba-")
    assert_private(got)
    assert (planted / "index.nbi").read_text() == "another user's pickle"  # not touched
    assert stat.S_IMODE(planted.stat().st_mode) == 0o777


@needs_root
def test_a_fallback_folder_of_another_user_is_refused(tmp):
    planted = fixed_name(tmp)
    planted.mkdir(mode=0o700)
    os.chown(planted, OTHER_UID, OTHER_UID)
    got = rejected_call(rf"{planted}.*owned by uid {OTHER_UID}")
    assert got != planted
    assert_private(got)


@needs_posix
def test_a_symlink_at_the_fallback_name_is_refused(tmp, tmp_path):
    target = tmp_path / "elsewhere"
    target.mkdir(mode=0o700)  # private and ours: the link itself is what is refused
    fixed_name(tmp).symlink_to(target)
    got = rejected_call(rf"{fixed_name(tmp)}.*symbolic link")
    assert got.parent == tmp and got != fixed_name(tmp)
    assert_private(got)
    assert list(target.iterdir()) == []


@needs_root
def test_a_cache_root_of_another_user_is_refused(monkeypatch, tmp_path):
    root = tmp_path / "shared"
    (root / "numba").mkdir(parents=True)
    os.chown(root / "numba", OTHER_UID, OTHER_UID)
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(root))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    got = rejected_call(rf"{root / 'numba'}.*owned by uid {OTHER_UID}.*RESTITUTION_CACHE_DIR")
    assert got == fixed_name(tmp_path)
    assert_private(got)


@needs_posix
def test_a_cache_root_every_user_can_write_is_refused(monkeypatch, tmp_path):
    root = tmp_path / "open"
    (root / "numba").mkdir(parents=True)
    (root / "numba").chmod(0o777)
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(root))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    assert rejected_call("writable by every user") == fixed_name(tmp_path)


@needs_posix
def test_a_cache_root_of_ours_is_used_through_a_symlink_too(monkeypatch, tmp_path):
    """RESTITUTION_CACHE_DIR set by the user to a folder they own (here reached through a
    symlink, as a cache moved to another disk is) is used as before, without a warning."""
    disk = tmp_path / "disk"
    disk.mkdir()
    (tmp_path / "link").symlink_to(disk)
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "link"))
    assert quiet_call() == tmp_path / "link" / "numba"
    assert (disk / "numba").is_dir()


@needs_posix
def test_importing_the_package_refuses_a_planted_folder(tmp_path):
    """End to end: ``import restitution`` sets NUMBA_CACHE_DIR to a private folder and says why
    it passed over the planted one."""
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    planted = fixed_name(tmp)
    planted.mkdir()
    planted.chmod(0o777)
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(TMPDIR=str(tmp), RESTITUTION_CACHE_DIR=str(blocker / "cache"))
    code = "import os, restitution; print(os.environ['NUMBA_CACHE_DIR'])"
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    used = Path(run.stdout.strip())
    assert used != planted and used.parent == tmp
    assert "RuntimeWarning" in run.stderr and str(planted) in run.stderr
    assert not used.exists()  # this process's own folder is removed when it exits
