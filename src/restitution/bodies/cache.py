"""On-disk cache of mode sets, keyed by every input.

The cache lives in ``$RESTITUTION_CACHE_DIR`` if set, else in the user cache directory given by
:func:`platformdirs.user_cache_dir`. A file whose stored key differs from the request, or that
cannot be read, is recomputed and rewritten, never trusted.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
import warnings
import zipfile
from pathlib import Path

import numpy as np
import platformdirs

from restitution._version import __version__
from restitution.bodies.disk.modes import _ALGORITHM_VERSION, ModeSet, compute_modes, weyl_count
from restitution.bodies.material import Material, require_reduced
from restitution.errors import InputError, RestitutionError

__all__ = ["MAX_MODES", "CacheError", "cache_dir", "check_mode_request", "get_modes"]

MAX_MODES = 200_000
"""Most modes :func:`get_modes` accepts. Measured with the scale-free Bessel scan
(docs/numerics.md): 1e4 modes in about 2 s, 1e5 modes in 23-44 s with 300-380 MiB peak on this
project's 2-core machine; the cost grows a little faster than N, so 2e5 modes take minutes and
about 1 GiB. A collision then costs about N operations per step and ~1e4-1e5 steps. The paper
uses at most 1800 modes."""


class CacheError(RestitutionError):
    """The cache directory cannot be created or written."""


_FIELDS = ("n", "l", "omega", "kappa", "kappa_p", "A", "B", "C", "S")


def cache_dir() -> Path:
    """Directory for cached mode sets and the default result store.

    Raises
    ------
    CacheError
        If the directory cannot be created (e.g. the path is a regular file or lies under a
        read-only directory).
    """
    env = os.environ.get("RESTITUTION_CACHE_DIR")
    path = Path(env) if env else Path(platformdirs.user_cache_dir("restitution"))
    what = "RESTITUTION_CACHE_DIR" if env else "the user cache directory"
    advice = "set RESTITUTION_CACHE_DIR to a writable directory (or give --store PATH)"
    if path.exists() and not path.is_dir():
        raise CacheError(f"{what} {path} is a file, not a directory; {advice}")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise CacheError(f"cannot create {what} {path} ({exc.strerror or exc}); {advice}") from None
    return path


def check_mode_request(nu: float, count: int | None, omega_max: float | None = None) -> None:
    """Refuse at once a mode request beyond :data:`MAX_MODES` (directly or through omega_max).

    Raises
    ------
    InputError
        Saying what is feasible.
    """
    if count is not None and isinstance(count, int | np.integer) and count > MAX_MODES:
        raise InputError(
            f"{count} modes are not feasible here: at most {MAX_MODES} (1e5 modes take about "
            "half a minute and 0.4 GiB to compute, and every collision step costs ~N); the "
            "paper uses up to 1800"
        )
    if omega_max is not None and math.isfinite(omega_max) and omega_max > 0:
        expected = weyl_count(float(omega_max), float(nu))
        if expected > MAX_MODES:
            raise InputError(
                f"omega_max = {omega_max:g} c/R means about {expected:.3g} modes (Weyl's law), "
                f"more than the feasible {MAX_MODES}; use omega_max below "
                f"{math.sqrt(8.0 * MAX_MODES / ((1.0 - nu**2) + 2.0 * (1.0 + nu))):.0f}"
            )


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

    Same parameters as :func:`restitution.bodies.disk.modes.compute_modes`;
    ``use_cache=False`` bypasses the cache entirely.
    """
    nu = require_reduced(material, "the modal path")
    check_mode_request(nu, count, omega_max)
    if not use_cache:
        return compute_modes(nu, count=count, omega_max=omega_max)
    key = _key(nu, count, omega_max)
    try:
        directory = cache_dir()
    except CacheError as exc:
        warnings.warn(f"{exc}; computing without the cache", stacklevel=2)
        return compute_modes(nu, count=count, omega_max=omega_max)
    path = directory / f"modes-{hashlib.sha256(key.encode()).hexdigest()[:24]}.npz"
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
