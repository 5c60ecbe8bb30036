"""The walls of the ``alpha -> infinity`` extrapolation: default values and how they are read.

Units: ``alpha`` in ``1/R``; ``v`` in ``c`` (speed towards the wall); compressions in ``R``.

One home for what the modal sweeps (:class:`restitution.limits.sweep.SweepSettings`) and the FEM
route (:func:`restitution.fem.limits.fem_epsilon`) share, so both extrapolate from the same
walls: the default products :data:`ALPHA_PRODUCTS` ``alpha * delta_max(v)``, the default scale
:data:`ALPHA_SCALE`, the checks of such values and :func:`walls_at`, which turns them into wall
hardness values at one speed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.errors import InputError

__all__ = [
    "ALPHA_PRODUCTS",
    "ALPHA_SCALE",
    "ALPHA_SCALES",
    "check_alpha_scale",
    "check_alphas",
    "check_distinct",
    "default_products",
    "walls_at",
]

ALPHA_PRODUCTS: tuple[float, ...] = body_kind(DEFAULT_GEOMETRY).alpha_products
"""Default wall hardness values of the disk, as products ``alpha * delta_max(v)``
(``ALPHA_SCALE``; every kind's: :attr:`restitution.bodies.kinds.BodyKind.alpha_products`, whose
declaration says why)."""

ALPHA_SCALES: tuple[str, ...] = ("absolute", "compression")
"""How wall hardness values are read: ``alpha`` in ``1/R``, or products ``alpha * delta_max``."""

ALPHA_SCALE = "compression"
"""Default reading of the wall hardness values (one of :data:`ALPHA_SCALES`)."""


def default_products(geometry: str = DEFAULT_GEOMETRY) -> tuple[float, ...]:
    """The default walls ``alpha * delta_max(v)`` of the body ``geometry``
    (:attr:`restitution.bodies.kinds.BodyKind.alpha_products`)."""
    return body_kind(geometry).alpha_products


def check_distinct(name: str, values: Sequence) -> None:
    """Refuse repeated values of the set ``name`` (a repeated point adds nothing)."""
    if len(set(values)) != len(values):
        raise InputError(
            f"{name} has repeated values {list(values)}; give distinct values "
            "(a repeated point adds nothing to an extrapolation)"
        )


def check_alphas(alphas: Sequence[float]) -> None:
    """Refuse wall hardness values (or products) that are not positive and finite."""
    if any(not (a > 0 and math.isfinite(a)) for a in alphas):
        raise InputError("wall hardness alpha must be positive (units 1/R)")


def check_alpha_scale(alpha_scale: str) -> None:
    """Refuse an ``alpha_scale`` outside :data:`ALPHA_SCALES`."""
    if alpha_scale not in ALPHA_SCALES:
        raise InputError(f"alpha_scale must be 'absolute' or 'compression', not {alpha_scale!r}")


def walls_at(
    v: float,
    alphas: Sequence[float],
    alpha_scale: str,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    nu: float | None = None,
    partner=None,
) -> tuple[float, ...]:
    """Wall hardness values (``1/R``) at speed ``v`` (``c``).

    ``"absolute"``: ``alphas`` as given. ``"compression"``: ``alphas[k] / delta_max(v)`` with
    the body's quasistatic maximal compression against a rigid wall
    (:attr:`restitution.bodies.kinds.BodyKind.max_compression`): for the disk
    ``delta_max = v sqrt(ln(4/v))`` (eq. 61, independent of ``nu``), for the sphere Hertz's
    ``(15 m v^2 / (16 E*))^(2/5)``, which needs the sphere's Poisson number ``nu``. With a
    ``partner`` (:class:`restitution.bodies.pair.partner.Partner`) ``v`` is the relative speed
    of a pair and ``delta_max`` the pair's approach of the centres
    (:meth:`~restitution.bodies.pair.partner.Partner.max_compression`).
    """
    values = tuple(alphas)
    if alpha_scale == "absolute":
        return values
    if partner is not None:
        delta = partner.max_compression(float(v), geometry, nu)
    else:
        kind = body_kind(geometry)
        if nu is None and kind.scales_need_nu:
            raise InputError(f"the walls of a {geometry} at a compression scale need its nu")
        delta = kind.max_compression(float(v), 0.0 if nu is None else float(nu))
    if not (math.isfinite(delta) and delta > 0.0):  # v = 1e-300: delta_max underflows to 0
        raise InputError(
            f"at v = {float(v):g} c the quasistatic compression delta_max = {delta:g} R is not "
            "a finite positive number, so walls at a compression scale (alpha / delta_max) have "
            "no hardness; give a faster v, or absolute walls (alpha_scale 'absolute')"
        )
    return tuple(a / delta for a in values)
