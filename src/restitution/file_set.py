"""A set of files written into a user's folder as one unit, touching only the package's own files.

:func:`file_set` yields a staging folder inside the target folder; every file of the set is
written there (by its final name) and, when the set is complete, moved into the folder. What the
set wrote is recorded in a manifest beside it (``.restitution-<set>.json``: each file's name and
SHA-256), and the manifest is the only licence to replace or remove a file:

* a file of the folder that no manifest names, or that was changed since the package wrote it
  (its digest differs), is never replaced or removed: the set is refused before anything moves
  (:class:`~restitution.errors.OutputError`, naming the file), and the folder is left as it was;
* a file the previous set of the same name wrote, unchanged, and not in the new set (a closed
  form this run could not fit, the snippets of a run with a constant) is removed, so the set
  never mixes two runs.

Moving the files in takes one rename each and no space, but it is not one atomic step. Before
the first rename the staging folder gets a journal (``.commit``: the names to move and to
remove); a run killed while it moves leaves that folder behind, and the next set written into
the folder (or :func:`recover`) finishes its moves first. A staging folder without a journal is
an unfinished set and is removed. A live set holds an ``flock`` on its staging folder, so a
concurrent run never touches it, and an exclusive lock on the target folder while it moves.
"""

from __future__ import annotations

import contextlib
import fcntl
import hashlib
import json
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from restitution import atomic
from restitution.errors import OutputError

__all__ = ["file_set", "manifest_path", "recover"]

STAGING_PREFIX = ".restitution-staging-"
"""Name prefix of the staging folders (hidden, in the target folder's file system)."""

_JOURNAL = ".commit"
_FORMAT = "restitution-file-set"


def manifest_path(folder: str | os.PathLike, name: str) -> Path:
    """The manifest of the set ``name`` in ``folder``."""
    return Path(folder) / f".restitution-{name}.json"


def _digest(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _read_manifest(path: Path) -> dict[str, str]:
    """The files a manifest names, ``{name: sha256}``; an unreadable or foreign manifest names
    none (so nothing is removed or replaced on its word)."""
    try:
        d = json.loads(path.read_text())
        if d.get("format") != _FORMAT or not isinstance(d.get("files"), dict):
            return {}
        return {
            str(k): str(v)
            for k, v in d["files"].items()
            if isinstance(k, str) and "/" not in k and k not in ("", ".", "..")
        }
    except (OSError, ValueError, AttributeError):
        return {}


def _owned(folder: Path) -> dict[str, str]:
    """Every file the package's manifests in ``folder`` name, ``{name: sha256}``."""
    owned: dict[str, str] = {}
    for manifest in sorted(folder.glob(".restitution-*.json")):
        owned.update(_read_manifest(manifest))
    return owned


def _unchanged(path: Path, digest: str | None) -> bool:
    try:
        return digest is not None and path.is_file() and _digest(path) == digest
    except OSError:
        return False


@contextlib.contextmanager
def _locked(path: Path, *, block: bool) -> Iterator[bool]:
    """An ``flock`` on the folder ``path``; yields whether it was had (never waits unless
    ``block``)."""
    fd = os.open(path, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | (0 if block else fcntl.LOCK_NB))
        except BlockingIOError:
            yield False
            return
        yield True
    finally:
        os.close(fd)


def _remove_tree(stage: Path) -> None:
    for leftover in stage.iterdir() if stage.exists() else ():
        with contextlib.suppress(OSError):
            leftover.unlink()
    with contextlib.suppress(OSError):
        stage.rmdir()


def _move_in(stage: Path, out: Path, journal: dict) -> None:
    """Carry out a journal: move its files in, remove its stale ones, write its manifest."""
    for name in journal["move"]:
        with contextlib.suppress(FileNotFoundError):  # moved before a kill
            os.replace(stage / name, out / name)
    for name, digest in journal["remove"].items():
        if _unchanged(out / name, digest):
            with contextlib.suppress(FileNotFoundError):
                (out / name).unlink()
    atomic.write_text(
        manifest_path(out, journal["set"]),
        json.dumps({"format": _FORMAT, "files": journal["files"]}, indent=1, sort_keys=True) + "\n",
    )


def recover(folder: str | os.PathLike) -> int:
    """Finish or remove the staging folders that killed runs left in ``folder``; return how
    many were handled. A folder with a journal is finished (its moves carried out), one without
    is removed; one whose run is alive (it holds its lock) is left alone."""
    out = Path(folder)
    handled = 0
    for stage in sorted(out.glob(f"{STAGING_PREFIX}*")):
        if not stage.is_dir() or stage.is_symlink():
            continue
        with _locked(stage, block=False) as free:
            if not free:
                continue
            try:
                journal = json.loads((stage / _JOURNAL).read_text())
            except (OSError, ValueError):
                journal = None
            if isinstance(journal, dict) and isinstance(journal.get("set"), str):
                _move_in(stage, out, journal)
            _remove_tree(stage)
            handled += 1
    return handled


@contextlib.contextmanager
def file_set(
    folder: str | os.PathLike, name: str = "export", *, prune: bool = True
) -> Iterator[Path]:
    """Write a set of files into ``folder`` as one unit (module docs): yield a staging folder
    to write every file of the set into, by its final name; on success they are moved into
    ``folder``, the files the previous set ``name`` wrote and this one does not are removed
    (kept and still listed with ``prune=False``: sets that add to a folder, as the figures of
    several runs), and the manifest is renewed.

    A full disk, an error or Ctrl-C while the set is written leaves the folder as it was (the
    staging folder is removed).

    Raises
    ------
    OutputError
        Before anything moves, when a file of the set would replace a file that the package
        did not write, or that was changed since it did.
    """
    if "/" in name or not name:
        raise ValueError(f"a set's name is one word, got {name!r}")
    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    with _locked(out, block=True):
        recover(out)
    manifest = manifest_path(out, name)
    stage = Path(tempfile.mkdtemp(prefix=STAGING_PREFIX, dir=out))
    try:
        with _locked(stage, block=True):
            yield stage
            names = sorted(p.name for p in stage.iterdir() if p.is_file())
            with _locked(out, block=True):
                owned = _owned(out)
                for n in names:
                    if (out / n).exists() and not _unchanged(out / n, owned.get(n)):
                        why = "was changed since restitution wrote it" if n in owned else (
                            "was not written by restitution")  # fmt: skip
                        raise OutputError(
                            f"{out / n} exists and {why}; it is left as it is and nothing was "
                            "written: move it away, or write into another folder"
                        )
                files = {n: _digest(stage / n) for n in names}
                before = {n: d for n, d in _read_manifest(manifest).items() if n not in files}
                kept = {} if prune else {n: d for n, d in before.items() if (out / n).exists()}
                journal = {
                    "move": names,
                    "remove": before if prune else {},
                    "files": {**kept, **files},
                    "set": name,
                }
                try:
                    atomic.write_text(stage / _JOURNAL, json.dumps(journal))
                    _move_in(stage, out, journal)
                except BaseException:
                    # Interrupted between renames (Ctrl-C): finish them rather than leave
                    # the folder mixing two sets; a failure here leaves the journal for
                    # recover() on the next set.
                    if (stage / _JOURNAL).exists():
                        _move_in(stage, out, journal)
                        (stage / _JOURNAL).unlink()
                    raise
    except BaseException:
        if not (stage / _JOURNAL).exists():
            _remove_tree(stage)
        raise
    else:
        _remove_tree(stage)
