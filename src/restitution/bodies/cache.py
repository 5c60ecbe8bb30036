"""On-disk cache of mode sets, keyed by every input.

The cache lives in ``$RESTITUTION_CACHE_DIR`` if set, else in the user cache directory given by
:func:`platformdirs.user_cache_dir`. A file whose stored key differs from the request, or that
cannot be read, is recomputed and rewritten, never trusted.
"""

from __future__ import annotations

import dataclasses
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
from restitution.bodies.base import ModalBody
from restitution.bodies.kinds import DEFAULT_GEOMETRY, BodyKind, body_kind
from restitution.bodies.material import Material, require_reduced
from restitution.errors import InputError, RestitutionError, describe, is_integer, is_real

__all__ = [
    "MAX_MODES",
    "CacheError",
    "cache_dir",
    "check_mode_request",
    "get_modes",
    "writable_folder",
]

MAX_MODES = body_kind(DEFAULT_GEOMETRY).max_modes
"""Most modes :func:`get_modes` accepts for a disk (each kind's limit:
:attr:`restitution.bodies.kinds.BodyKind.max_modes`). A collision then costs about N
operations per step and ~1e4-1e5 steps. The paper uses at most 1800 modes."""


class CacheError(RestitutionError):
    """The cache directory cannot be created or written."""


def _fields(kind: BodyKind) -> tuple[str, ...]:
    """The array fields of a kind's mode sets (every dataclass field but ``nu``)."""
    return tuple(f.name for f in dataclasses.fields(kind.mode_class) if f.name != "nu")


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


def writable_folder(path: str | os.PathLike) -> Path:
    """``path``, created if missing and checked writable now, before work that ends by writing
    there: a file is made in it and removed (permission bits do not stop root; a read-only
    mount or an immutable folder does).

    Raises
    ------
    CacheError
        One line naming the folder; for a folder of the cache (``RESTITUTION_CACHE_DIR``, else
        the user cache directory) naming ``RESTITUTION_CACHE_DIR`` too, the setting that moves
        it. A read-only cache failed after the work, or without saying which setting to change.
    """
    from restitution._paths import cache_root

    path = Path(path)
    try:
        path.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(dir=path, prefix=".write-check-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        why = exc.strerror or str(exc)
        root = cache_root()
        if path.absolute() != root.absolute() and root.absolute() not in path.absolute().parents:
            raise CacheError(
                f"folder {path} cannot be written ({why}); choose one that can"
            ) from None
        env = os.environ.get("RESTITUTION_CACHE_DIR")
        where = f"RESTITUTION_CACHE_DIR = {root}" if env else f"the user cache directory {root}"
        raise CacheError(
            f"the cache folder {path} cannot be written ({why}; {where}); set "
            "RESTITUTION_CACHE_DIR to a writable directory"
        ) from None
    return path


def check_mode_request(
    nu: float, count: int | None, omega_max: float | None = None, geometry: str = DEFAULT_GEOMETRY
) -> int | None:
    """Refuse at once a mode request of the wrong type, or beyond the body's ``max_modes``
    (directly or through ``omega_max``).

    Returns
    -------
    int or None
        ``count`` as a Python ``int`` (a NumPy integer is one).

    Raises
    ------
    InputError
        Saying what is allowed and feasible: ``count`` an integer (not a bool, a float or an
        array), ``omega_max`` a number (``c/R``), ``nu`` in the body's range.
    """
    kind = body_kind(geometry)
    nu = kind.check_nu(nu)
    limit = kind.max_modes
    if count is not None:
        if not is_integer(count):
            raise InputError(
                f"count must be a positive integer (the number of modes), got {describe(count)}; "
                "pass an int >= 1, e.g. count=100"
            )
        count = int(count)
        if count > limit:
            raise InputError(
                f"{count} modes of the {geometry} are not feasible here: at most {limit} "
                "(every collision step costs ~N); the paper uses up to 1800"
            )
    if omega_max is not None and not is_real(omega_max):
        raise InputError(
            f"omega_max must be a positive number (c/R), got {describe(omega_max)}; pass a "
            "finite float > 0, e.g. omega_max=40.0"
        )
    if omega_max is not None and not (math.isfinite(omega_max) and omega_max > 0):
        raise InputError(
            f"omega_max must be a positive finite number (c/R), got {omega_max!r}; pass e.g. "
            "omega_max=40.0"
        )
    if omega_max is not None:
        # Compared as frequencies first: Weyl's count of 1e300 overflows (issue 47).
        top = kind.omega_for(limit, nu)
        expected = kind.weyl_count(float(omega_max), nu) if omega_max <= top else math.inf
        if expected > limit:
            about = f"about {expected:.3g}" if math.isfinite(expected) else "unboundedly many"
            raise InputError(
                f"omega_max = {omega_max:g} c/R means {about} modes of the "
                f"{geometry} (Weyl's law), more than the feasible {limit}; use omega_max below "
                f"{kind.omega_for(limit, nu):.0f}"
            )
    return count


def _computed(kind: BodyKind, nu: float, count: int | None, omega_max: float | None):
    """The kind's modes; a request below the lowest mode is refused (not an empty set)."""
    modes = kind.compute(nu, count=count, omega_max=omega_max)
    if len(modes.omega) == 0:
        raise InputError(
            f"no mode of the {kind.geometry} (nu = {nu:g}) lies below omega_max = {omega_max:g} "
            f"c/R; its lowest lie near {kind.omega_for(1, nu):.3g} c/R: use a larger omega_max"
        )
    return modes


def _key(kind: BodyKind, nu: float, count: int | None, omega_max: float | None) -> str:
    return json.dumps(
        {
            "kind": "modeset",
            "geometry": kind.geometry,
            "nu": float(nu).hex(),
            "count": count,
            "omega_max": None if omega_max is None else float(omega_max).hex(),
            "algorithm": kind.algorithm,
            "version": __version__,
        },
        sort_keys=True,
    )


def _load(path: Path, key: str, kind: BodyKind) -> ModalBody | None:
    try:
        with np.load(path, allow_pickle=False) as data:
            if str(data["key"]) != key:
                return None
            arrays = {f: np.array(data[f]) for f in _fields(kind)}
    except (OSError, KeyError, ValueError, zipfile.BadZipFile, EOFError):
        return None
    size = arrays["omega"].size
    if any(a.shape != (size,) for a in arrays.values()):
        return None
    if not all(np.all(np.isfinite(a)) for a in arrays.values()):
        return None
    arrays["n"] = arrays["n"].astype(int)
    arrays["l"] = arrays["l"].astype(int)
    return kind.mode_class(nu=float.fromhex(json.loads(key)["nu"]), **arrays)


def _save(path: Path, key: str, modes: ModalBody, kind: BodyKind) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp.npz")
    os.close(fd)
    try:
        np.savez(tmp, key=np.array(key), **{f: getattr(modes, f) for f in _fields(kind)})
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def get_modes(
    material: Material | float,
    count: int | None = None,
    omega_max: float | None = None,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    use_cache: bool = True,
) -> ModalBody:
    """Eigenmodes of the free body ``geometry`` that couple to a head-on impact, from the disk
    cache when possible.

    Parameters
    ----------
    material : Material or float
        A reduced material (``E = rho = 1``) or the Poisson number of the body's own elasticity
        (two-dimensional for the disk, three-dimensional for the sphere).
    count, omega_max
        As for :func:`restitution.bodies.disk.modes.compute_modes`: exactly one of them.
    geometry : str
        ``"disk"`` (the paper's symmetric modes) or ``"sphere"`` (Lamb's axisymmetric spheroidal
        modes), :data:`restitution.bodies.kinds.GEOMETRIES`.
    use_cache : bool
        ``False`` bypasses the cache entirely.

    Raises
    ------
    InputError
        If an argument has the wrong type or range (:func:`check_mode_request`), or
        ``use_cache`` is not a bool.
    """
    kind = body_kind(geometry)
    nu = kind.check_nu(require_reduced(material, "the modal path"))
    count = check_mode_request(nu, count, omega_max, geometry)
    if not isinstance(use_cache, bool | np.bool_):
        raise InputError(
            f"use_cache must be True or False, got {describe(use_cache)}; pass use_cache=False "
            "to bypass the cache"
        )
    if not use_cache:
        return _computed(kind, nu, count, omega_max)
    key = _key(kind, nu, count, omega_max)
    try:
        directory = cache_dir()
    except CacheError as exc:
        warnings.warn(f"{exc}; computing without the cache", stacklevel=2)
        return _computed(kind, nu, count, omega_max)
    path = directory / f"modes-{hashlib.sha256(key.encode()).hexdigest()[:24]}.npz"
    if path.exists():
        cached = _load(path, key, kind)
        if cached is not None and len(cached.omega):  # an empty set is refused, not served
            return cached
    modes = _computed(kind, nu, count, omega_max)
    try:
        _save(path, key, modes, kind)
    except OSError:
        pass  # a read-only cache directory only costs recomputation
    return modes
