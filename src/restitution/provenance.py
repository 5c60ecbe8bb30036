"""Which code computed a number: version strings with a digest of the sources behind it.

:func:`code_version` names the modal solver (every module of the packages in
:data:`SOLVER_PACKAGES`, found automatically, so a new solver module is never forgotten); the
result store keys its rows with it and the laws record it. :func:`fem_code_version` names the
FEM route (the modules in :data:`FEM_MODULES`). Both are :func:`source_digest`: the package
version, a tag and the first 12 hex digits of a SHA-256 over every module's name and source.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
from pathlib import Path

from restitution._version import __version__

__all__ = [
    "DECLARATIONS",
    "FEM_MODULES",
    "PAIR",
    "DISK_QUASISTATIC_MODULES",
    "QUASISTATIC_MODULES",
    "ROUTE_MODULES",
    "SOLVER_PACKAGES",
    "code_version",
    "fem_code_version",
    "package_modules",
    "quasistatic_code_version",
    "source_digest",
]

SOLVER_PACKAGES: tuple[str, ...] = ("restitution.bodies", "restitution.dynamics")
"""Packages whose every module (recursively) determines a collision's numbers."""

FEM_MODULES: tuple[str, ...] = (
    "restitution.fem.contact",
    "restitution.fem.elasticity",
    "restitution.fem.graded",
    "restitution.fem.impact",
    "restitution.fem.limits",
    "restitution.fem.mesh",
    "restitution.fem.model",
    "restitution.fem.richardson",
    "restitution.fem.section",
    "restitution.limits.extrapolation",
    "restitution.bodies.material",
    "restitution.bodies.disk.contact",
    "restitution.bodies.sphere.surface",
)
"""Modules whose source determines an FEM reference value (:mod:`restitution.fem.section` sets
the Lame constants, the mesh's copies and, with the bodies' contact scales, the graded mesh)."""


def package_modules(package: str) -> tuple[str, ...]:
    """Every module of ``package`` and its subpackages (from the ``*.py`` files on disk),
    sorted by name; ``()`` when the package has no source directory (e.g. a zip install)."""
    spec = importlib.util.find_spec(package)
    roots = list(getattr(spec, "submodule_search_locations", None) or ())
    names = set()
    for root in map(Path, roots):
        for path in root.rglob("*.py"):
            parts = path.relative_to(root).with_suffix("").parts
            if parts[-1] == "__init__":
                parts = parts[:-1]
            names.add(".".join((package, *parts)))
    return tuple(sorted(names))


def source_digest(modules: tuple[str, ...], tag: str = "") -> str:
    """``__version__ + "+" + tag + digest``, e.g. ``0.1.0+3fa2...`` or ``0.1.0+fem.3fa2...``.

    The digest is the first 12 hex digits of a SHA-256 over each module's name, a NUL byte and
    its source, in the given order. Without readable sources (e.g. a zip install) the result is
    ``__version__`` alone.
    """
    digest = hashlib.sha256()
    if not modules:
        return __version__
    for name in modules:
        try:
            origin = getattr(importlib.util.find_spec(name), "origin", None)
        except ModuleNotFoundError:
            return __version__
        try:
            with open(origin, "rb") as fh:
                digest.update(name.encode() + b"\0" + fh.read())
        except (OSError, TypeError):
            return __version__
    return f"{__version__}+{tag}{digest.hexdigest()[:12]}"


PAIR = "pair"
"""The body folder of two bodies as one (:mod:`restitution.bodies.pair`): part of the code
version of a pair's collisions besides the folder of its bodies' kind."""


DECLARATIONS: tuple[str, ...] = ("restitution.bodies.kinds", "kind")
"""The registry of body kinds (``restitution.bodies.kinds``) and each kind's declaration
(``restitution.bodies.<name>.kind``): names, defaults, plans of sweeps and laws, texts. They
compute no number of a collision (a collision's walls and mode counts are keys of their own),
so they are not part of a code version: a new shipped Poisson number or a reworded model leaves
stored collisions valid."""


def _declaration(module: str) -> bool:
    return module == DECLARATIONS[0] or (
        module.startswith(BODIES + ".") and module.rsplit(".", 1)[-1] == DECLARATIONS[1]
    )


def _body_modules(packages: tuple[str, ...], geometry: str, pair: bool = False) -> tuple[str, ...]:
    """Every module of ``packages`` except the folders of bodies other than ``geometry`` (and
    :data:`PAIR` when ``pair``) and the kinds' declarations (:data:`DECLARATIONS`)."""
    own = {geometry, PAIR} if pair else {geometry}
    others = tuple(f"{BODIES}.{name}." for name in body_folders() if name not in own)
    modules: tuple[str, ...] = ()
    for package in packages:
        modules += tuple(
            m
            for m in package_modules(package)
            if not (m + ".").startswith(others) and not _declaration(m)
        )
    return tuple(sorted(modules))


@functools.cache
def code_version(geometry: str, *, pair: bool = False) -> str:
    """``restitution.__version__`` plus a digest of the solver's source, e.g. ``0.1.0+3fa2...``.

    The sources are every module of :data:`SOLVER_PACKAGES` except the folders of other bodies
    (``restitution.bodies.<name>`` for every ``name`` but ``geometry``): any edit of the solver
    of this body changes it, so a result store never serves numbers of other code, and adding
    a body (a sphere) leaves the stored numbers of the others valid. With ``pair`` the version
    is that of two bodies of the kind ``geometry`` meeting head-on: the folder
    :data:`PAIR` joins the sources (a single body's version does not depend on it).
    """
    return source_digest(_body_modules(SOLVER_PACKAGES, geometry, pair))


BODIES = "restitution.bodies"


def body_folders() -> tuple[str, ...]:
    """Names of the body implementations: the subpackages of :mod:`restitution.bodies`."""
    spec = importlib.util.find_spec(BODIES)
    roots = list(getattr(spec, "submodule_search_locations", None) or ())
    return tuple(sorted({p.parent.name for r in map(Path, roots) for p in r.glob("*/__init__.py")}))


QUASISTATIC_MODULES: tuple[str, ...] = (
    "restitution.quasistatic.hertz",
    "restitution.quasistatic.hertz_pair",
    "restitution.quasistatic.hertz_sphere",
    "restitution.quasistatic.low_speed",
    "restitution.quasistatic.pulse",
    "restitution.quasistatic.rayleigh",
)
"""Modules of the quasistatic layer whose source determines a sphere's low-speed law point (the
estimate and what it imports)."""

DISK_QUASISTATIC_MODULES: tuple[str, ...] = (
    "restitution.quasistatic.hertz",
    "restitution.quasistatic.hertz_pair",
    "restitution.quasistatic.slow_disk",
)
"""The same for the disk's low-speed points (:mod:`restitution.quasistatic.slow_disk`)."""

ROUTE_MODULES: dict[str, tuple[str, ...]] = {
    "rayleigh": QUASISTATIC_MODULES,
    "slow-modal": DISK_QUASISTATIC_MODULES,
}
"""The modules of each low-speed route, by the route's name (a body kind's
``low_speed_route``)."""


@functools.cache
def quasistatic_code_version(geometry: str, route: str, *, pair: bool = False) -> str:
    """``__version__`` plus a digest of the low-speed ``route`` (:data:`ROUTE_MODULES`: the
    sphere's Rayleigh estimate, :data:`QUASISTATIC_MODULES`; the disk's and two disks' slow
    modal model, :data:`DISK_QUASISTATIC_MODULES`) and the body's modes (the body layer but
    other bodies' folders; with ``pair`` the folder :data:`PAIR` too), e.g.
    ``0.1.0+quasistatic.3fa2...``: the version of a law's low-speed points."""
    modules = _body_modules(("restitution.bodies",), geometry, pair) + ROUTE_MODULES[route]
    return source_digest(tuple(sorted(modules)), "quasistatic.")


def fem_code_version() -> str:
    """``__version__`` plus a digest of the FEM route's sources, e.g. ``0.1.0+fem.3fa2...``."""
    return source_digest(FEM_MODULES, "fem.")
