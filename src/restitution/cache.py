"""On-disk cache of mode sets, keyed by every input.

The cache lives in ``$RESTITUTION_CACHE_DIR`` if set, else in the user cache directory given by
:func:`platformdirs.user_cache_dir`. A file whose stored key differs from the request, or that
cannot be read, is recomputed and rewritten, never trusted.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import zipfile
from pathlib import Path

import numpy as np
import platformdirs

from restitution import __version__
from restitution.material import Material, require_reduced
from restitution.modes import _ALGORITHM_VERSION, ModeSet, compute_modes

__all__ = ["cache_dir", "get_modes"]

_FIELDS = ("n", "l", "omega", "kappa", "kappa_p", "A", "B", "C", "S")


def cache_dir() -> Path:
    """Directory for cached mode sets and the default result store."""
    env = os.environ.get("RESTITUTION_CACHE_DIR")
    path = Path(env) if env else Path(platformdirs.user_cache_dir("restitution"))
    path.mkdir(parents=True, exist_ok=True)
    return path


def _key(nu: float, count: int | None, omega_max: float | None) -> str:
    return json.dumps(
        {
            "kind": "modeset",
            "nu": float(nu).hex(),
            "count": count,
            "omega_max": None if omega_max is None else float(omega_max).hex(),
            "algorithm": _ALGORITHM_VERSION,
            "version": __version__,
        },
        sort_keys=True,
    )


def _load(path: Path, key: str) -> ModeSet | None:
    try:
        with np.load(path, allow_pickle=False) as data:
            if str(data["key"]) != key:
                return None
            arrays = {f: np.array(data[f]) for f in _FIELDS}
    except (OSError, KeyError, ValueError, zipfile.BadZipFile, EOFError):
        return None
    size = arrays["omega"].size
    if any(a.shape != (size,) for a in arrays.values()):
        return None
    if not all(np.all(np.isfinite(a)) for a in arrays.values()):
        return None
    arrays["n"] = arrays["n"].astype(int)
    arrays["l"] = arrays["l"].astype(int)
    return ModeSet(nu=float.fromhex(json.loads(key)["nu"]), **arrays)


def _save(path: Path, key: str, modes: ModeSet) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp.npz")
    os.close(fd)
    try:
        np.savez(tmp, key=np.array(key), **{f: getattr(modes, f) for f in _FIELDS})
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def get_modes(
    material: Material | float,
    count: int | None = None,
    omega_max: float | None = None,
    *,
    use_cache: bool = True,
) -> ModeSet:
    """Symmetric eigenmodes of the free disk, from the disk cache when possible.

    Same parameters as :func:`restitution.modes.compute_modes`; ``use_cache=False`` bypasses
    the cache entirely.
    """
    nu = require_reduced(material, "the modal path")
    if not use_cache:
        return compute_modes(nu, count=count, omega_max=omega_max)
    key = _key(nu, count, omega_max)
    path = cache_dir() / f"modes-{hashlib.sha256(key.encode()).hexdigest()[:24]}.npz"
    if path.exists():
        cached = _load(path, key)
        if cached is not None:
            return cached
    modes = compute_modes(nu, count=count, omega_max=omega_max)
    try:
        _save(path, key, modes)
    except OSError:
        pass  # a read-only cache directory only costs recomputation
    return modes
