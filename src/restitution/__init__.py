"""restitution: the coefficient of restitution of elastic disks from their vibrational modes.

Reproduces and extends F. Gerl and A. Zippelius, "Coefficient of restitution for elastic disks".
Units throughout: two-dimensional Young modulus E = 1, mass per area rho = 1, radius R = 1, so
velocities are in units of c = sqrt(E / rho) and the disk mass is pi.
"""

__version__ = "0.1.0"

from restitution.cache import CacheError, get_modes  # noqa: E402
from restitution.collision import (  # noqa: E402
    CollisionError,
    CollisionSettings,
    collide,
    collide_batch,
)
from restitution.errors import InputError, RestitutionError  # noqa: E402
from restitution.law import EpsilonLaw, law  # noqa: E402
from restitution.material import Material, MaterialError  # noqa: E402
from restitution.modes import ModeError, ModeSet, compute_modes, weyl_count  # noqa: E402
from restitution.results import UNITS, CollisionResult  # noqa: E402
from restitution.si_law import SILaw, si_law  # noqa: E402
from restitution.store import StoreError  # noqa: E402
from restitution.units import Grain  # noqa: E402

__all__ = [
    "__version__",
    "UNITS",
    "CacheError",
    "CollisionError",
    "CollisionResult",
    "CollisionSettings",
    "EpsilonLaw",
    "Grain",
    "InputError",
    "Material",
    "MaterialError",
    "ModeError",
    "ModeSet",
    "RestitutionError",
    "SILaw",
    "StoreError",
    "collide",
    "collide_batch",
    "compute_modes",
    "get_modes",
    "law",
    "si_law",
    "weyl_count",
]
