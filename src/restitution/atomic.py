"""Files written whole or not at all: a temporary file in the target's folder, then a rename.

Every file the package writes goes through :func:`replacing` (or :func:`write_text`, built on
it): the content goes to a temporary file beside the target, is flushed to disk, and only then
renamed onto the target (:func:`os.replace`, atomic on POSIX). A full disk, an error or Ctrl-C
in between leaves an existing file intact and no partial new one (the temporary file is
removed).
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["replacing", "write_text"]

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
