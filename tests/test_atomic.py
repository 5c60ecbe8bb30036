"""Every file the package writes is written whole or not at all (restitution.atomic)."""

from __future__ import annotations

import errno
import json
import os
import stat

import numpy as np
import pytest

from restitution import atomic
from restitution.laws.law import EpsilonLaw


def _full_disk(*args, **kwargs):
    raise OSError(errno.ENOSPC, "No space left on device")


def test_a_failed_write_keeps_the_old_file_and_leaves_no_part(tmp_path):
    path = tmp_path / "law.json"
    path.write_text('{"old": true}')
    with pytest.raises(OSError, match="No space"):
        with atomic.replacing(path) as tmp:
            tmp.write_text('{"new": ')  # half written, then the disk is full
            _full_disk()
    assert path.read_text() == '{"old": true}'
    assert sorted(p.name for p in tmp_path.iterdir()) == ["law.json"]


def test_a_new_file_appears_whole_with_the_usual_permissions(tmp_path):
    path = tmp_path / "table.txt"
    atomic.write_text(path, "a\nb\n")
    assert path.read_text() == "a\nb\n"
    mask = os.umask(0)
    os.umask(mask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~mask
    # The temporary name keeps the suffix, so writers that read the format from it agree.
    with atomic.replacing(tmp_path / "x.png") as tmp:
        assert tmp.suffix == ".png" and tmp.parent == tmp_path
        tmp.write_bytes(b"png")
    assert (tmp_path / "x.png").read_bytes() == b"png"


def test_law_exports_survive_a_full_disk(tmp_path, monkeypatch):
    law = EpsilonLaw.from_points(
        0.33, np.array([0.01, 0.1, 0.2]), np.array([0.99, 0.95, 0.9]), np.full(3, 1e-3)
    )
    path = law.to_json(tmp_path / "law.json")
    before = path.read_text()
    assert json.loads(before)
    other = EpsilonLaw.from_points(  # another law, so that a replaced file would show
        0.33, np.array([0.01, 0.1, 0.2]), np.array([0.98, 0.94, 0.8]), np.full(3, 1e-3)
    )
    monkeypatch.setattr(os, "replace", _full_disk)  # the rename fails, as on a full disk
    with pytest.raises(OSError):
        other.to_json(path)
    assert path.read_text() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["law.json"]


def test_a_device_is_written_in_place_never_replaced(tmp_path):
    # /dev/full stays the device (renaming onto it would swap it for a regular file).
    with pytest.raises(OSError, match="No space"):
        atomic.write_text("/dev/full", "x" * 100_000)
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)
    assert not [p for p in os.listdir("/dev") if p.startswith(".full.")]


def test_a_link_is_followed(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(real)
    atomic.write_text(link, "new")
    assert link.is_symlink() and real.read_text() == "new"


def test_an_export_without_a_constant_leaves_no_snippet_of_an_earlier_one(tmp_path):
    """law --export twice into one folder, first with a constant, then without: the second
    folder holds the second law's files only (the audit's mixed folder), and the manifest that
    names them (restitution.file_set)."""
    from restitution.laws import exports
    from restitution.laws.si_law import si_law

    s = si_law(63e9, 0.2481, 2500, "cylinder", "wall")
    first = exports.write_folder(s, exports.constant_at(s, 1.0), tmp_path / "x")
    assert (tmp_path / "x" / "epsilon_lammps.in").exists()
    second = exports.write_folder(s, None, tmp_path / "x")
    assert sorted(p.name for p in (tmp_path / "x").iterdir()) == sorted(
        [*(p.name for p in second.paths), ".restitution-export.json"]
    )
    assert len(second.paths) < len(first.paths)
