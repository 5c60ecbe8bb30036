"""Snippets for DEM codes, one module per code, each registering itself in :data:`DEM_TARGETS`.

A snippet gives a code one constant epsilon (dimensionless) per pair of particle types, with
the material's constants in SI units, and comments saying what the law is for. Importing this
package imports every public module in it (names not starting with ``_``), in the order of their
names, and each registers its :class:`DemTarget`; a new code is one new module here that calls
:func:`register_dem_target` (docs/architecture.md, "Adding a DEM target").
"""

from __future__ import annotations

import importlib
import pkgutil

from restitution.laws.exports.dem._registry import DEM_TARGETS, DemTarget, register_dem_target

__all__ = ["DEM_TARGETS", "DemTarget", "register_dem_target"]


def _import_targets() -> None:
    """Import the public modules of this package by name: each registers its target."""
    for module in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        if not module.name.startswith("_"):
            importlib.import_module(f"{__name__}.{module.name}")


_import_targets()
