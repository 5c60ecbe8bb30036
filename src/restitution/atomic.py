"""Files written whole or not at all: a temporary file in the target's folder, then a rename.

Every file the package writes goes through :func:`replacing` (or :func:`write_text`, built on
it): the content goes to a temporary file beside the target, is flushed to disk, and only then
renamed onto the target (:func:`os.replace`, atomic on POSIX). A full disk, an error or Ctrl-C
in between leaves an existing file intact and no partial new one (the temporary file is
removed).
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from restitution.errors import OutputError

__all__ = [
    "check_output_dir",
    "check_output_file",
    "replacing",
    "write_text",
    "writing",
]

# The permissions a plain open() would give a new file (mkstemp makes it 0600).
_UMASK = os.umask(0)
os.umask(_UMASK)
_MODE = 0o666 & ~_UMASK


@contextlib.contextmanager
def replacing(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path beside ``path`` to write to; on success it replaces ``path``.

    The temporary name ends with the target's suffix, so writers that infer the format from it
    (matplotlib's ``savefig``, NumPy's ``savetxt``) write the same bytes. On any exception the
    temporary file is removed and ``path`` is left as it was. A symbolic link is followed (the
    file it points to is replaced, not the link). A target that exists and is not a regular file
    (a device such as ``/dev/full`` or ``/dev/stdout``, a pipe) is written in place: it cannot be
    replaced, and renaming onto it would swap the device for a file.
    """
    target = Path(path)
    if target.is_symlink():
        target = target.resolve()
    if target.exists() and not target.is_file():
        yield target
        return
    fd, tmp = tempfile.mkstemp(
        prefix=f".{target.name}.", suffix=f".part{target.suffix}", dir=target.parent
    )
    os.close(fd)
    try:
        yield Path(tmp)
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp, _MODE)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def write_text(path: str | os.PathLike, text: str, *, newline: str | None = None) -> None:
    """Write ``text`` to ``path`` whole or not at all (see :func:`replacing`)."""
    with replacing(path) as tmp, open(tmp, "w", newline=newline) as fh:
        fh.write(text)


# -- checks before anything is computed ----------------------------------------------------


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


@contextlib.contextmanager
def writing(path: Path, option: str) -> Iterator[None]:
    """Turn an ``OSError`` while writing ``path`` into one clear :class:`OutputError`."""
    try:
        yield
    except OSError as exc:
        advice = "choose a writable location"
        if exc.errno in (errno.ENOSPC, errno.EDQUOT):
            advice = "its disk is full: free some space there, or choose another location"
        raise OutputError(f"cannot write {option} {path}: {_reason(exc)}; {advice}") from None


def check_output_file(path: Path, option: str) -> None:
    """Fail before any computation when ``path`` cannot be created or written; its folder is
    created if missing, as :func:`check_output_dir` creates an output folder (one rule for
    ``--output``, ``--out`` and ``--export``)."""
    if path.is_dir():
        raise OutputError(f"{option} {path} is a directory; give a file name")
    parent = path.parent
    if parent.exists() and not parent.is_dir():
        raise OutputError(f"{option} {path}: {parent} is a file, not a directory")
    existed = path.exists()
    with writing(path, option):
        parent.mkdir(parents=True, exist_ok=True)
        with open(path, "ab"):
            pass
    if not existed:
        with contextlib.suppress(OSError):
            path.unlink()


def check_output_dir(path: Path, option: str) -> None:
    """Create ``path`` if needed and prove that a file can be written in it."""
    if path.exists() and not path.is_dir():
        raise OutputError(f"{option} {path} is a file, not a directory")
    with writing(path, option):
        path.mkdir(parents=True, exist_ok=True)
        probe = path / f".restitution-write-test-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
