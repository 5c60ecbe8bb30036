"""Where the package keeps what it computes: the cache root (no imports of the package)."""

from __future__ import annotations

import os
from pathlib import Path

import platformdirs

__all__ = ["cache_root", "numba_cache_dir"]


def cache_root() -> Path:
    """``RESTITUTION_CACHE_DIR`` if set, else the user cache directory of ``restitution``: the
    folder of the mode cache, the default result store and numba's compiled kernels (not
    created here; :func:`restitution.bodies.cache.cache_dir` creates and checks it)."""
    env = os.environ.get("RESTITUTION_CACHE_DIR")
    return Path(env) if env else Path(platformdirs.user_cache_dir("restitution"))


def numba_cache_dir() -> Path:
    """Where numba keeps the compiled kernels: ``numba`` in :func:`cache_root` if it can be
    created and written, else a folder of this user in the system's temporary directory. An
    unwritable cache made numba fall back to writing next to the package's sources (issue 47)."""
    import tempfile

    wanted = cache_root() / "numba"
    try:
        wanted.mkdir(parents=True, exist_ok=True)
        if os.access(wanted, os.W_OK | os.X_OK):
            return wanted
    except OSError:
        pass
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    return Path(tempfile.gettempdir()) / f"restitution-numba-{uid}"
