"""A law for the user's exact Poisson number, computed on demand with the production settings.

Units: the body's reduced units (``E = rho = R = 1``); times in seconds of wall time.

The shipped laws cover a grid of Poisson numbers; in between they are interpolated with an error
(:mod:`restitution.laws.law_nu`). :func:`computed_law` computes the law of one exact ``nu``
through the same sweeps as the shipped laws (:mod:`restitution.laws.production`: the disk's
groups, the sphere's with its low-speed points, a pair's carried over from the disk's), stores
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

__all__ = [
    "SECONDS_PER_COLLISION",
    "SECONDS_PER_LOW_POINT",
    "ComputePlan",
    "check_plan",
    "computed_law",
    "law_dir",
    "plan",
    "production_groups",
]

SECONDS_PER_COLLISION = {"disk": 1.1, "sphere": 1.0, "pair": 4.3}
"""Wall time of one collision of each body's production, seconds (one core, the largest of
the shipped runs): the disk's 1320 collisions took 656-1442 s, the sphere's 1872 took 32 min,
the pairs' 2052 took 146 min (README, ``make law``, ``make law-sphere``, ``make law-pair``)."""

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
    ``"sphere"`` or ``"pair"``), as the shipped laws were computed."""
    if partner is not None:
        if geometry != "disk" or not partner.same_material:
            raise InputError(
                "laws are computed on demand for a disk on a wall, a sphere on a wall, or two "
                "disks of one material; compute another pair with `restitution curve "
                "--radius-ratio ... --modulus-ratio ... --density-ratio ...`"
            )
        return pair_groups(partner.radius_ratio), "pair"
    if geometry == "disk":
        return SETTINGS_GROUPS, "disk"
    if geometry == "sphere":
        return SPHERE_GROUPS, "sphere"
    raise InputError(f"no production settings for a {geometry}; use a disk or a sphere")


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
    path = Path(out_dir or law_dir()) / law_filename(nu, geometry, partner)
    count = sum(len(g.velocities) * len(g.alphas) * len(g.n_modes) for g in groups)
    seconds = count * SECONDS_PER_COLLISION[kind]
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
        A second disk of the same material (its radius ratio).
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
