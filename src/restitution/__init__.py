"""restitution: the coefficient of restitution of elastic bodies from their vibrational modes.

Reproduces and extends F. Gerl and A. Zippelius, "Coefficient of restitution for elastic disks".
Reduced units throughout: two-dimensional Young modulus E = 1, mass per area rho = 1, radius
R = 1, so velocities are in units of c = sqrt(E / rho) and the disk mass is pi
(:data:`UNITS`). SI units enter only through :func:`si_law` and :class:`Grain`.

The package is layered (docs/architecture.md): bodies -> dynamics -> vibrating, quasistatic ->
limits -> laws -> reproduction, fem, cli. No module imports this root; it only re-exports.
"""

import os as _os

# Numba writes its compiled kernels (cache=True) next to the sources unless told otherwise; send
# them to the package's cache instead, so an installed package's tree is never written. numba
# reads NUMBA_CACHE_DIR once, when it is first imported (by the imports below).
if "NUMBA_CACHE_DIR" not in _os.environ:
    from restitution._paths import numba_cache_dir as _numba_cache_dir

    _os.environ["NUMBA_CACHE_DIR"] = str(_numba_cache_dir())

from restitution._version import __version__  # noqa: E402
from restitution.bodies.cache import CacheError, get_modes
from restitution.bodies.disk.modes import ModeError, ModeSet, compute_modes, weyl_count
from restitution.bodies.material import Material, MaterialError
from restitution.dynamics.collision import (
    CollisionError,
    CollisionSettings,
    collide,
    collide_batch,
)
from restitution.dynamics.results import UNITS, CollisionResult
from restitution.errors import InputError, RestitutionError
from restitution.estimate import Estimate
from restitution.laws import making as _making  # noqa: F401  (registers the computing routes)
from restitution.laws.api import si_law
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.making.oblique_fit import ObliqueFit, oblique_fit
from restitution.laws.plastic import PlasticLaw, plastic_law
from restitution.laws.request import LawRequest
from restitution.laws.serve import LawAnswer, serve
from restitution.laws.si_law import SILaw
from restitution.laws.units import Grain
from restitution.limits.curves import PointEpsilon, epsilon_at
from restitution.limits.store import StoreError

__all__ = [
    "__version__",
    "UNITS",
    "CacheError",
    "CollisionError",
    "CollisionResult",
    "CollisionSettings",
    "EpsilonLaw",
    "Estimate",
    "Grain",
    "InputError",
    "LawAnswer",
    "LawRequest",
    "Material",
    "MaterialError",
    "ModeError",
    "ModeSet",
    "ObliqueFit",
    "PlasticLaw",
    "PointEpsilon",
    "RestitutionError",
    "SILaw",
    "StoreError",
    "collide",
    "collide_batch",
    "compute_modes",
    "epsilon_at",
    "get_modes",
    "law",
    "oblique_fit",
    "plastic_law",
    "serve",
    "si_law",
    "weyl_count",
]
