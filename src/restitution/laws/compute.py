"""A law for the user's exact Poisson number, computed on demand with the production settings.

Units: the body's reduced units (``E = rho = R = 1``); times in seconds of wall time.

The shipped laws cover a grid of Poisson numbers; in between they are interpolated with an error
(:mod:`restitution.laws.law_nu`). :func:`computed_law` computes the law of one exact ``nu``
through the same sweeps as the shipped laws (:mod:`restitution.laws.production`: the disk's
groups, the sphere's with its low-speed points, a pair's carried over from the disk's, also of
two materials, with the window scaled by :func:`restitution.limits.sweep.window_scale`), stores
every collision in the user's result store (an interrupted run resumes) and writes the law file
into the cache (``<cache>/laws``), where the next call finds it. Before it starts it states the
work: the collisions and the time they took in the shipped production, per body, and refuses
what would take longer than :data:`restitution.budget.TIME_BOUND_S` unless ``force``.
"""

from __future__ import annotations

import json
from pathlib import Path

from restitution import budget
from restitution._paths import cache_root
from restitution.errors import InputError
from restitution.laws.law import law_filename
from restitution.laws.production import (
    SETTINGS_GROUPS,
    SPHERE_GROUPS,
    low_speeds_of,
    pair_groups,
)
from restitution.limits.sweep import window_scale

__all__ = [
    "PAIR_COST_POWER",
    "PAIR_SECONDS_AT_5",
    "SECONDS_PER_COLLISION",
    "SECONDS_PER_LOW_POINT",
    "ComputePlan",
    "check_modes",
    "check_plan",
    "computed_law",
    "law_dir",
    "plan",
    "production_groups",
    "seconds_per_collision",
]

SECONDS_PER_COLLISION = {"disk": 1.1, "sphere": 1.0, "pair": 4.3}
"""Wall time of one collision of each body's production, seconds (one core, the largest of
the shipped runs): the disk's 1320 collisions took 656-1442 s, the sphere's 1872 took 32 min,
the pairs' 2052 took 146 min (README, ``make law``, ``make law-sphere``, ``make law-pair``).
A pair's own estimate scales with its mode windows (:func:`seconds_per_collision`)."""

PAIR_COST_POWER = 2.25
"""A pair's time per collision grows like its mode windows (:func:`restitution.limits.sweep.
window_scale` times the wall's) to this power: of the pairs' 146 min, the laws of ``R2/R1 = 2``
(windows 5 times the wall's) took two thirds, those of ``1.2`` and ``1.4`` (2.44 and 2.96 times)
the rest: ``(2/3) / (1/3) = 5^p / ((2.44^p + 2.96^p) / 2) / 2`` gives ``p = 2.25``."""

PAIR_SECONDS_AT_5 = 8.5
"""Seconds per collision of a pair whose windows are 5 times the wall's: two thirds of 146 min
over the 684 collisions of the three laws of ``R2/R1 = 2``."""
SECONDS_PER_LOW_POINT = {"sphere": 0.25, "disk": 2.05, "pair": 2.35}
"""Wall time of one low-speed point of each body's law, seconds: the sphere's 404 points for six
laws took about 10 minutes (docs/spheres.md); the disk's 100 points for each of nine laws took
1838 s, two disks' 91 points for each of nine laws 1925 s (both runs side by side on the two
cores, 26 Nov 2026)."""


def law_dir() -> Path:
    """Where computed laws are kept: ``<cache>/laws`` (:func:`restitution._paths.cache_root`)."""
    return cache_root() / "laws"


def production_groups(geometry: str, partner=None):
    """``(groups, kind)``: the production sweeps of the body (``kind`` ``"disk"``,
    ``"sphere"`` or ``"pair"``), as the shipped laws were computed; two disks of any two
    materials take the groups of two disks of one material
    (:func:`restitution.laws.production.pair_groups`, windows scaled by the partner's)."""
    if partner is not None:
        if geometry != "disk":
            raise InputError(
                f"laws of two {geometry}s are not computed on demand; a pair of two disks is "
                "(geometry 'disk')"
            )
        return pair_groups(partner), "pair"
    if geometry == "disk":
        return SETTINGS_GROUPS, "disk"
    if geometry == "sphere":
        return SPHERE_GROUPS, "sphere"
    raise InputError(f"no production settings for a {geometry}; use a disk or a sphere")


def seconds_per_collision(kind: str, partner=None) -> float:
    """Estimated seconds of one production collision of the body ``kind`` on one core; a pair's
    from its mode windows, :data:`PAIR_SECONDS_AT_5` ``(scale / 5)^`` :data:`PAIR_COST_POWER`
    (never below :data:`SECONDS_PER_COLLISION`'s disk value)."""
    if kind != "pair" or partner is None:
        return SECONDS_PER_COLLISION[kind]
    scale = window_scale(partner)
    return max(SECONDS_PER_COLLISION["disk"], PAIR_SECONDS_AT_5 * (scale / 5.0) ** PAIR_COST_POWER)


def check_modes(nu: float, groups, partner=None) -> None:
    """Refuse (one line, with the numbers) a pair whose largest mode window needs more modes of
    one disk than the mode cache holds (:data:`restitution.bodies.cache.MAX_MODES`): a partner
    much softer, denser or larger than the first disk."""
    if partner is None:
        return
    from restitution.bodies.cache import MAX_MODES

    largest = max(max(g.n_modes) for g in groups)
    counts = partner.counts(largest, nu)
    if max(counts) > MAX_MODES:
        raise InputError(
            f"the pair's largest mode window, {largest} modes of both disks, needs {max(counts)} "
            f"modes of one disk (the mode cache holds {MAX_MODES}): the partner has "
            f"{window_scale(partner) - 1:.3g} times the first disk's modes below one frequency "
            "(r^2 rho2/E2); laws of such pairs are not computed, collide single points with "
            "`restitution collide --radius-ratio ...`"
        )


class ComputePlan:
    """What :func:`computed_law` will do: the file, the collisions and their estimated time.

    Attributes
    ----------
    path : Path
        The law file in :func:`law_dir`.
    exists : bool
        Whether it is there already (then nothing is computed).
    collisions : int
        Collisions of the production sweeps (stored ones are reused, so this is an upper
        bound).
    seconds : float
        Estimated wall time on one core.
    """

    def __init__(self, path: Path, exists: bool, collisions: int, seconds: float):
        self.path, self.exists, self.collisions, self.seconds = path, exists, collisions, seconds

    def words(self) -> str:
        """One line for the user: what is computed and how long it takes."""
        if self.exists:
            return f"using the law computed before, {self.path}"
        return (
            f"computing the law with the production settings: {self.collisions} collisions, "
            f"about {budget.format_duration(self.seconds)} on one core (stored collisions are "
            f"reused; an interrupted run resumes), into {self.path}"
        )


def _usable(path: Path) -> bool:
    """Whether ``path`` holds a law file that loads (a damaged one is computed again)."""
    try:
        json.loads(path.read_text())["metadata"]["points"]
    except (OSError, ValueError, KeyError, TypeError):
        return False
    return True


def plan(
    nu: float, geometry: str = "disk", partner=None, out_dir=None, *, reuse: bool = True
) -> ComputePlan:
    """The plan of :func:`computed_law` with the same arguments (nothing is computed);
    ``reuse=False``: a law file already in ``out_dir`` is computed again (through the store)."""
    groups, kind = production_groups(geometry, partner)
    check_modes(nu, groups, partner)
    path = Path(out_dir or law_dir()) / law_filename(nu, geometry, partner)
    count = sum(len(g.velocities) * len(g.alphas) * len(g.n_modes) for g in groups)
    seconds = count * seconds_per_collision(kind, partner)
    seconds += len(low_speeds_of(geometry, partner)) * SECONDS_PER_LOW_POINT.get(kind, 0.0)
    return ComputePlan(path, reuse and _usable(path), count, seconds)


def check_plan(p: ComputePlan, force: bool = False) -> None:
    """Refuse a plan whose estimate exceeds :data:`restitution.budget.TIME_BOUND_S` unless
    ``force`` (one line: the collisions, the estimate, the bound)."""
    if p.exists:
        return
    per = p.seconds / max(p.collisions, 1)
    budget.check_time_total(
        "--compute",
        f"for {p.path.name}",
        p.seconds,
        f"{p.collisions} collisions of the production settings",
        lambda bound: (
            f"the interpolated law (leave out --compute) needs none; about "
            f"{int(bound // per)} collisions fit"
        ),
        force=force,
        override="--force",
    )


def computed_law(
    nu: float,
    geometry: str = "disk",
    partner=None,
    *,
    out_dir=None,
    store=None,
    workers: int | None = None,
    progress: bool | None = None,
    force: bool = False,
) -> Path:
    """The law file of the exact ``nu`` (2D for the disk, 3D for the sphere), computed with the
    production settings unless it is in ``out_dir`` already.

    Parameters
    ----------
    nu : float
        Poisson number of the body.
    geometry : {"disk", "sphere"}
    partner : Partner, optional
        A second disk (its radius ratio and, in the first disk's units, its material).
    out_dir : path, optional
        Where the law file goes [:func:`law_dir`].
    store, workers, progress
        As for :func:`restitution.laws.production.build`.
    force : bool
        Compute even when the estimate exceeds :data:`restitution.budget.TIME_BOUND_S`.

    Returns
    -------
    Path
        The law file (``law_filename(nu, geometry, partner)`` in ``out_dir``).
    """
    from restitution.laws.production import build

    p = plan(nu, geometry, partner, out_dir)
    if p.exists:
        return p.path
    check_plan(p, force)
    groups, kind = production_groups(geometry, partner)
    (written,) = build(p.path.parent, [nu], groups, store=store, workers=workers,
                       progress=progress, low_speeds=low_speeds_of(geometry, partner))  # fmt: skip
    return written
