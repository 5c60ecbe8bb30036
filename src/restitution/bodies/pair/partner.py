"""The second body of a pair, by its constants: what the sweeps, the store and the laws key on.

Units: the first body's, ``E1 = rho1 = R1 = 1`` (for disks its 2D plane-stress constants);
speeds ``w`` (the relative normal speed of the centres) in ``c1``; compressions in ``R1``.

A :class:`Partner` is the second body before any mode exists: its radius, modulus and density
in units of the first body's and its own Poisson number (``None``: the first body's). It knows
what the layers above need to plan a pair's collisions -- the quasistatic compression that scales
the walls (:meth:`Partner.max_compression`), how many of each body's own modes lie below a
common frequency (:meth:`Partner.counts`) -- and it builds the :class:`BodyPair` of the
``N`` lowest modes of both (:meth:`Partner.pair`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, kinds
from restitution.bodies.pair.body import BodyPair, pair_of
from restitution.errors import InputError

__all__ = ["Partner", "UnequalPairError"]


def _sized() -> list[str]:
    """The kinds whose pairs have a compression scale."""
    return [k.geometry + "s" for k in kinds().values() if k.pair_compression is not None]


_MARGIN = 1.1
"""Each body's own modes asked for: this factor above its Weyl share of the common cutoff (then
checked against the pair's ``N``-th frequency, and all ``N`` taken where it falls short)."""


RATIO_RANGE = (1e-12, 1e12)
"""The partner's ratios (radius, modulus, density) the pair takes: beyond, one body is a wall to
the other within the package's numbers (a density ratio of 1e-300 divided by zero in the
kernel, issue 47); collide with the wall instead."""


_BEYOND = {
    "radius ratio": "the smaller body meets the larger one as a wall (an elastic half-space of "
    "the larger one's material)",
    "modulus ratio": "the softer body meets the stiffer one as a rigid wall",
    "density ratio": "the lighter body meets the denser one as a wall that does not move",
}
"""What a partner beyond :data:`RATIO_RANGE` is to the other body, by the ratio."""


class UnequalPairError(InputError):
    """A pair too unequal in size for its modes: the ``n_modes`` lowest modes of the pair all
    belong to one body, and the other (``still``: 0 the first, 1 the second) would not vibrate
    unless about ``need`` modes were kept (a body takes at most ``most``). A command with its
    own words for the way out (the smaller body on an elastic wall) catches this one."""

    def __init__(self, message: str, *, still: int, need: int, most: int) -> None:
        super().__init__(message)
        self.still = still
        self.need = need
        self.most = most


def _positive(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating | np.integer):
        raise InputError(f"the partner's {name} must be a positive number, got {value!r}")
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"the partner's {name} must be a positive number, got {value!r}")
    lo, hi = RATIO_RANGE
    if not lo <= value <= hi:
        raise InputError(
            f"the partner's {name} {value:g} is outside {lo:g} ... {hi:g}: "
            f"{_BEYOND.get(name, 'to one body the other is then a wall')}; collide with the "
            "wall instead (no partner)"
        )
    return value


@dataclass(frozen=True)
class Partner:
    """The second body of a head-on pair, in units of the first (module docs).

    Attributes
    ----------
    radius_ratio, modulus_ratio, density_ratio : float
        ``R2 / R1``, ``E2 / E1``, ``rho2 / rho1`` (for disks the 2D constants).
    nu : float or None
        The second body's own Poisson number; ``None``: the first body's (one material).
    """

    radius_ratio: float = 1.0
    modulus_ratio: float = 1.0
    density_ratio: float = 1.0
    nu: float | None = None

    def __post_init__(self) -> None:
        for name in ("radius_ratio", "modulus_ratio", "density_ratio"):
            object.__setattr__(self, name, _positive(name.replace("_", " "), getattr(self, name)))
        if self.nu is not None:
            if isinstance(self.nu, bool) or not isinstance(self.nu, int | float | np.floating):
                raise InputError(f"the partner's Poisson number must be a number, got {self.nu!r}")
            object.__setattr__(self, "nu", float(self.nu))

    # -- identity ---------------------------------------------------------------------------

    @property
    def same_material(self) -> bool:
        """Whether both bodies are of one material (only the radii may differ)."""
        return self.modulus_ratio == 1.0 and self.density_ratio == 1.0 and self.nu is None

    def key(self) -> tuple[tuple[str, float | None], ...]:
        """Sorted ``(name, value)`` pairs: the partner's part of a store key."""
        return (
            ("density_ratio", self.density_ratio),
            ("modulus_ratio", self.modulus_ratio),
            ("nu", self.nu),
            ("radius_ratio", self.radius_ratio),
        )

    @classmethod
    def from_key(cls, key) -> Partner:
        """The partner of :meth:`key` (a sequence of pairs or a dict)."""
        return cls(**dict(key.items() if isinstance(key, dict) else key))

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return dict(self.key())

    def nu2(self, nu1: float) -> float:
        """The second body's Poisson number when the first body's is ``nu1``."""
        return float(nu1) if self.nu is None else self.nu

    @property
    def speed_ratio(self) -> float:
        """``c2 / c1 = sqrt(E2 rho1 / (E1 rho2))``."""
        return math.sqrt(self.modulus_ratio / self.density_ratio)

    # -- quasistatic scales (disks) -----------------------------------------------------------

    def max_compression(self, w, geometry: str = DEFAULT_GEOMETRY, nu1: float | None = None):
        """The pair's quasistatic largest approach of the centres at relative speed ``w``
        (``c1``), ``R1``: the kind's :attr:`~restitution.bodies.kinds.BodyKind.pair_compression`
        (for disks eq. (61) of the disk on a wall written for the pair, the pair's 2D Hertz law:
        :func:`restitution.bodies.disk.contact.pair_max_compression`; for spheres Hertz's 3D
        law of the pair, :func:`restitution.bodies.sphere.surface.pair_max_compression`, which
        needs the first body's Poisson number ``nu1``). The sweeps scale the pair's walls with
        it, as a body's on the wall with its own compression."""
        kind = body_kind(geometry)
        compression = kind.pair_compression
        if compression is None:
            raise InputError(
                f"the compression of a pair of {geometry}s is not implemented; pairs of "
                f"different bodies are computed for {', '.join(_sized())}"
            )
        if nu1 is None and kind.scales_need_nu:
            raise InputError(f"the compression of two {geometry}s needs the first one's nu")
        nu1 = 0.0 if nu1 is None else float(nu1)
        return compression(
            w, self.radius_ratio, self.modulus_ratio, self.density_ratio, nu1, self.nu2(nu1)
        )

    # -- modes ----------------------------------------------------------------------------------

    def counts(self, n_modes: int, nu1: float, geometry: str = DEFAULT_GEOMETRY) -> tuple[int, int]:
        """How many of each body's own lowest modes to compute so that the pair's ``n_modes``
        lowest lie among them: each body's Weyl share of the common cutoff (frequencies in
        ``c1 / R1``: the second body's own ``omega`` times ``c2 R1 / (c1 R2)``), times
        :data:`_MARGIN`, plus 20; at most ``n_modes``."""
        kind = body_kind(geometry)
        nu2 = self.nu2(nu1)
        scale2 = self.speed_ratio / self.radius_ratio

        def total(omega: float) -> float:
            return kind.weyl_count(omega, nu1) + kind.weyl_count(omega / scale2, nu2)

        lo, hi = 0.0, 1.0
        while total(hi) < n_modes:
            hi *= 2.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if total(mid) < n_modes else (lo, mid)
        shares = (kind.weyl_count(hi, nu1), kind.weyl_count(hi / scale2, nu2))
        return tuple(min(int(n_modes), int(math.ceil(_MARGIN * s)) + 20) for s in shares)

    def pair(
        self, nu1: float, n_modes: int, geometry: str = DEFAULT_GEOMETRY, get_modes=None
    ) -> BodyPair:
        """The :class:`BodyPair` of the ``n_modes`` lowest modes of both bodies together.

        ``get_modes(nu, count, geometry=...)`` supplies each body's own modes (default
        :func:`restitution.bodies.cache.get_modes`). Each body is asked for :meth:`counts`; if
        the pair's ``n_modes``-th frequency lies above what a body was asked for, that body is
        asked again for all ``n_modes`` (so the selection never depends on the estimate)."""
        if get_modes is None:
            from restitution.bodies.cache import get_modes
        n_modes = int(n_modes)
        if n_modes < 1:
            raise InputError(f"a pair needs at least one mode, got {n_modes}")
        nu2 = self.nu2(nu1)
        counts = list(self.counts(n_modes, nu1, geometry))
        while True:
            if nu2 == float(nu1):  # one mode set serves both
                both = get_modes(nu1, max(counts), geometry=geometry)
                first = both.take(np.arange(counts[0]))
                second = both.take(np.arange(counts[1]))
            else:
                first = get_modes(nu1, counts[0], geometry=geometry)
                second = get_modes(nu2, counts[1], geometry=geometry)
            whole = pair_of(
                first,
                second,
                radius_ratio=self.radius_ratio,
                modulus_ratio=self.modulus_ratio,
                density_ratio=self.density_ratio,
            )
            if len(whole) < n_modes:
                counts = [n_modes, n_modes]
                continue
            pair = whole.lowest(n_modes)
            cutoff = float(pair.omega.max())
            short = [
                i
                for i, body in enumerate((first, second))
                if counts[i] < n_modes and float(whole.omega[whole.member == i].max()) <= cutoff
            ]
            if not short:
                _both_vibrate(pair, whole, n_modes, self, geometry)
                return pair
            for i in short:
                counts[i] = n_modes


def _both_vibrate(pair, whole, n_modes: int, partner: Partner, geometry: str) -> None:
    """Refuse a pair whose ``n_modes`` lowest modes all belong to one body: the other would
    be rigid, and epsilon would come out near 1 with nothing flagged (issue 47: a radius ratio
    of 1e-6 or 100 with 20 modes)."""
    for i, name in enumerate(("first", "second")):
        if np.any(pair.member == i):
            continue
        lowest = float(whole.omega[whole.member == i].min())
        cutoff = float(pair.omega.max())
        dimension = 3 if geometry == "sphere" else 2
        most = body_kind(geometry).max_modes
        need = int(math.ceil(n_modes * (lowest / cutoff) ** dimension)) + 1
        advice = (
            f"use about {need} modes or more"
            if need <= most
            else f"it would need about {need:.2g} modes, more than the {most} a body takes: "
            "to the smaller body the larger one is a wall (an elastic half-space of its "
            "material); collide with the wall instead"
        )
        other = "second" if name == "first" else "first"
        raise UnequalPairError(
            f"the {n_modes} lowest modes of the pair (R2/R1 = {partner.radius_ratio:g}) all "
            f"belong to the {other} body: the {name} body's lowest mode (omega = {lowest:.4g} "
            f"c1/R1) lies above them (up to {cutoff:.4g} c1/R1), so it would not vibrate; "
            f"{advice}",
            still=i,
            need=need,
            most=most,
        )
