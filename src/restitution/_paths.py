"""Where the package keeps what it computes: the cache root (no imports of the package)."""

from __future__ import annotations

import atexit
import os
import shutil
import stat
import tempfile
import warnings
from pathlib import Path

import platformdirs

__all__ = ["cache_root", "numba_cache_dir"]


def cache_root() -> Path:
    """``RESTITUTION_CACHE_DIR`` if set, else the user cache directory of ``restitution``: the
    folder of the mode cache, the default result store and numba's compiled kernels (not
    created here; :func:`restitution.bodies.cache.cache_dir` creates and checks it)."""
    env = os.environ.get("RESTITUTION_CACHE_DIR")
    return Path(env) if env else Path(platformdirs.user_cache_dir("restitution"))


def _untrusted_cache(path: Path) -> str | None:
    """Why ``path`` (symlinks followed: the user may keep a cache on another disk) cannot hold
    numba's kernels, or None: it must be a directory of this user that others cannot write.
    numba's index files are pickles, and loading a pickle runs code, so a folder another user
    owns or can write is refused, also for root (it is how a user would reach root)."""
    st = os.stat(path)
    if not stat.S_ISDIR(st.st_mode):
        return "not a directory"
    if st.st_uid != os.getuid():
        return f"owned by uid {st.st_uid}, not by this user (uid {os.getuid()})"
    if st.st_mode & 0o002:
        return f"writable by every user (mode {stat.S_IMODE(st.st_mode):04o})"
    return None


def _not_private(path: Path) -> str | None:
    """Why ``path`` is not a private folder of this user, or None: a real directory (not a
    symlink), owned by this user, with no permission bits for group or others."""
    st = os.lstat(path)
    if stat.S_ISLNK(st.st_mode):
        return "a symbolic link"
    if not stat.S_ISDIR(st.st_mode):
        return "not a directory"
    if st.st_uid != os.getuid():
        return f"owned by uid {st.st_uid}, not by this user (uid {os.getuid()})"
    if st.st_mode & 0o077:
        return f"mode {stat.S_IMODE(st.st_mode):04o}, open to other users (0700 wanted)"
    return None


def _fresh_private() -> Path:
    """A new private folder (``tempfile.mkdtemp``: mode 0700, this user's) for this process's
    kernels, removed when the process exits."""
    fresh = Path(tempfile.mkdtemp(prefix="restitution-numba-"))
    atexit.register(shutil.rmtree, fresh, ignore_errors=True)
    return fresh


def numba_cache_dir() -> Path:
    """Where numba keeps the compiled kernels.

    ``numba`` in :func:`cache_root` if it can be created and written and is this user's
    (a directory owned by this user that other users cannot write; symlinks are followed).
    Else the fixed folder ``restitution-numba-<uid>`` of the system's temporary directory,
    created with mode 0700 and used only if it is a private folder of this user (a real
    directory, not a symlink, owned by this user, no group or other permissions): numba's
    index files are pickles, and a folder planted there by another user would run their code.
    A folder that fails a check is not used: a :class:`RuntimeWarning` names it, and this
    process compiles into a fresh private folder (``tempfile.mkdtemp``) removed at exit.

    An unwritable cache made numba fall back to writing next to the package's sources
    (issue 47); a fallback folder of another user was used unchecked (hostile-input issue).
    """
    wanted = cache_root() / "numba"
    try:
        wanted.mkdir(parents=True, exist_ok=True)
        writable = os.access(wanted, os.W_OK | os.X_OK)
        why = _untrusted_cache(wanted) if writable and hasattr(os, "getuid") else None
    except OSError:
        writable, why = False, None
    if writable and why is None:
        return wanted
    if why is not None:
        warnings.warn(
            f"numba's cache folder {wanted} is {why}; it is not used (its files could run "
            "another user's code). Fix its owner or mode, or set RESTITUTION_CACHE_DIR to a "
            "folder of yours.",
            RuntimeWarning,
            stacklevel=2,
        )
    tmp = Path(tempfile.gettempdir())
    if not hasattr(os, "getuid"):  # Windows: the temporary directory is the user's own
        fixed = tmp / "restitution-numba-user"
        fixed.mkdir(exist_ok=True)
        return fixed
    fixed = tmp / f"restitution-numba-{os.getuid()}"
    try:
        os.mkdir(fixed, 0o700)
    except FileExistsError:
        pass
    why = _not_private(fixed)
    if why is None:
        return fixed
    fresh = _fresh_private()
    warnings.warn(
        f"numba's fallback cache folder {fixed} is {why}; it is not used (its files could run "
        f"another user's code), this process compiles into {fresh}. Remove {fixed}, or set "
        "RESTITUTION_CACHE_DIR to a writable folder of yours.",
        RuntimeWarning,
        stacklevel=2,
    )
    return fresh
