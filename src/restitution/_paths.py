"""Where the package keeps what it computes: the cache root (no imports of the package)."""

from __future__ import annotations

import os
from pathlib import Path

import platformdirs

__all__ = ["cache_root"]


def cache_root() -> Path:
    """``RESTITUTION_CACHE_DIR`` if set, else the user cache directory of ``restitution``: the
    folder of the mode cache, the default result store and numba's compiled kernels (not
    created here; :func:`restitution.bodies.cache.cache_dir` creates and checks it)."""
    env = os.environ.get("RESTITUTION_CACHE_DIR")
    return Path(env) if env else Path(platformdirs.user_cache_dir("restitution"))
