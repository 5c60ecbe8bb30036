"""A law for the user's exact Poisson number, computed on demand with the production settings.

Units: the body's reduced units (``E = rho = R = 1``); times in seconds of wall time.

The shipped laws cover a grid of Poisson numbers; in between they are interpolated with an error
(:mod:`restitution.laws.law_nu`). :func:`computed_law` computes the law of one exact ``nu``
through the same sweeps as the shipped laws (:mod:`restitution.laws.making.production`: the disk's
groups, the sphere's with its low-speed points, a pair's carried over from the disk's, also of
two materials, with the window scaled by :func:`restitution.limits.sweep.window_scale`), stores
every collision in the user's result store (an interrupted run resumes) and writes the law file
into the cache (``<cache>/laws``), where the next call finds it: a file there is served only
when this package wrote it and nothing changed it since (its content digest matches,
:meth:`~restitution.laws.law.EpsilonLaw.to_json`); any other (edited, damaged, or written
before files carried a digest) is moved to ``<name>.corrupt`` with a warning and the law is
computed again (:func:`set_aside`), its collisions from the result store. Before it starts it
states the work: the collisions and the time they took in the shipped production, per body, and
refuses what would take longer than :data:`restitution.budget.TIME_BOUND_S` unless ``force``.
"""

from __future__ import annotations

import os
import warnings
from pathlib import Path

from restitution import budget
from restitution._paths import cache_root
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.errors import CorruptFileError, InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.low_speed import low_speeds_of
from restitution.laws.making import production
from restitution.laws.making.production import pair_groups
from restitution.limits.sweep import window_scale

__all__ = [
    "ComputePlan",
    "check_modes",
    "check_plan",
    "computed_law",
    "law_dir",
    "plan",
    "production_groups",
    "seconds_per_collision",
    "seconds_per_low_point",
    "set_aside",
]


def law_dir() -> Path:
    """Where computed laws are kept: ``<cache>/laws`` (:func:`restitution._paths.cache_root`)."""
    return cache_root() / "laws"


def production_groups(geometry: str, partner=None) -> tuple:
    """The production sweeps of the body ``geometry`` as the shipped laws were computed
    (:func:`restitution.laws.making.production.production_groups`); with a ``partner`` those of
    two such bodies of any two materials (:func:`restitution.laws.making.production.pair_groups`,
    windows scaled by the partner's)."""
    if partner is not None:
        return pair_groups(partner, geometry=geometry)
    return production.production_groups(geometry)


def seconds_per_collision(geometry: str, partner=None) -> float:
    """Estimated seconds of one production collision of the body ``geometry`` on one core, as
    measured in the shipped production (its kind's
    :attr:`~restitution.bodies.kinds.ProductionPlan.seconds_per_collision`); a pair's from its
    mode windows, :attr:`~restitution.bodies.kinds.PairPlan.seconds_at_5` ``(scale / 5)^``
    :attr:`~restitution.bodies.kinds.PairPlan.cost_power` (never below the body's own)."""
    kind = body_kind(geometry)
    own = kind.production.seconds_per_collision
    if partner is None:
        return own
    pairs = kind.pair_production
    scale = window_scale(partner, geometry)
    return max(own, pairs.seconds_at_5 * (scale / 5.0) ** pairs.cost_power)


def seconds_per_low_point(geometry: str, partner=None) -> float:
    """Seconds of one low-speed point of the body's (with a ``partner``: the pair's) law."""
    kind = body_kind(geometry)
    plan = kind.production if partner is None else kind.pair_production
    return plan.seconds_per_low_point


def check_modes(nu: float, groups, partner=None) -> None:
    """Refuse (one line, with the numbers) a pair whose largest mode window needs more modes of
    one body than its kind computes (:attr:`~restitution.bodies.kinds.BodyKind.max_modes`): a
    partner much softer, denser or larger than the first body."""
    groups = tuple(groups)
    if partner is None or not groups:
        return
    geometry = groups[0].geometry
    kind = body_kind(geometry)
    largest = max(max(g.n_modes) for g in groups)
    counts = partner.counts(largest, nu, geometry)
    if max(counts) > kind.max_modes:
        name = kind.geometry
        raise InputError(
            f"the pair's largest mode window, {largest} modes of both {name}s, needs "
            f"{max(counts)} modes of one {name} (at most {kind.max_modes} are computed): the "
            f"partner has {window_scale(partner, geometry) - 1:.3g} times the first {name}'s "
            "modes below one frequency; laws of such pairs are not computed, collide single "
            f"points with `restitution collide{(' ' + kind.option) if kind.option else ''} "
            "--radius-ratio ...`"
        )


class ComputePlan:
    """What :func:`computed_law` will do: the file, the collisions and their estimated time.

    Attributes
    ----------
    path : Path
        The law file in :func:`law_dir`.
    exists : bool
        Whether it is there already, as this package wrote it (its content digest matches;
        then nothing is computed). A file there that is not is computed again.
    collisions : int
        Collisions of the production sweeps and of at most one refining point per interval
        of their speeds (stored ones are reused, so this is an upper bound).
    seconds : float
        Estimated wall time on one core.
    low_points : int
        Speeds computed by the low-speed route.
    """

    def __init__(
        self, path: Path, exists: bool, collisions: int, seconds: float, low_points: int = 0
    ):
        self.path, self.exists, self.collisions, self.seconds = path, exists, collisions, seconds
        self.low_points = low_points

    def words(self) -> str:
        """One line for the user: what is computed and how long it takes."""
        if self.exists:
            return f"using the law computed before, {self.path}"
        if not self.collisions:
            return (
                f"computing the law by its low-speed route ({self.low_points} speeds, no "
                f"collisions): about {budget.format_duration(self.seconds)} on one core, into "
                f"{self.path}"
            )
        return (
            f"computing the law with the production settings: {self.collisions} collisions, "
            f"about {budget.format_duration(self.seconds)} on one core (stored collisions are "
            f"reused; an interrupted run resumes), into {self.path}"
        )


def _unusable(path: Path) -> str | None:
    """Why the law file ``path`` is not served from the cache, in a few words, or ``None`` when
    it is: a file this package wrote (:meth:`~restitution.laws.law.EpsilonLaw.to_json`), unchanged
    since (its content digest matches) and a valid law. A file without a digest (written by
    hand or by an older version) cannot be verified: it is computed again, from the result
    store's collisions (or the residual route's kept points), not served."""
    try:
        EpsilonLaw.from_json(path, require_digest=True)
    except CorruptFileError as exc:
        return exc.reason
    except InputError:
        return "it is not a valid law file"
    return None


def _usable(path: Path) -> bool:
    """Whether ``path`` holds a law this package wrote, unchanged (:func:`_unusable`)."""
    return _unusable(path) is None


def set_aside(path: Path) -> None:
    """Move a law file of the cache that is not served (:func:`_unusable`: changed after it was
    written, without a digest, not a valid law) to ``<name>.corrupt`` before the law is
    computed again, with one warning that says so (nothing when ``path`` is absent or
    served)."""
    why = _unusable(path)
    if why is None or not (path.exists() or path.is_symlink()):
        return
    aside = path.with_name(path.name + ".corrupt")
    try:
        os.replace(path, aside)
        where = f"moved to {aside.name}"
    except OSError:  # the computed law replaces it
        where = "it is replaced"
    warnings.warn(
        f"the cached law {path} is not served ({why}); {where}, and the law is computed again",
        stacklevel=3,
    )


def plan(
    nu: float, geometry: str = DEFAULT_GEOMETRY, partner=None, out_dir=None, *, reuse: bool = True
) -> ComputePlan:
    """The plan of :func:`computed_law` with the same arguments (nothing is computed);
    ``reuse=False``: a law file already in ``out_dir`` is computed again (through the store)."""
    groups = production_groups(geometry, partner)
    check_modes(nu, groups, partner)
    path = Path(out_dir or law_dir()) / law_filename(nu, geometry, partner)
    count = sum(len(g.velocities) * len(g.alphas) * len(g.n_modes) for g in groups)
    # At most one refining point per interval of the groups' speeds (restitution.laws.making.refine,
    # one round), each with a group's grid: an upper bound (the sphere's laws took 14-18 of 25).
    speeds = sum(len(g.velocities) for g in groups)
    count += max(speeds - 1, 0) * max((len(g.alphas) * len(g.n_modes) for g in groups), default=0)
    seconds = count * seconds_per_collision(geometry, partner)
    low = low_speeds_of(geometry, partner, nu)
    if low:
        seconds += len(low) * seconds_per_low_point(geometry, partner)
    return ComputePlan(path, reuse and _usable(path), count, seconds, len(low))


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
    geometry: str = DEFAULT_GEOMETRY,
    partner=None,
    *,
    out_dir=None,
    store=None,
    executor=None,
    progress=None,
    force: bool = False,
    workers: int | None = None,
) -> Path:
    """The law file of the exact ``nu`` (2D for the disk, 3D for the sphere), computed with the
    production settings unless it is in ``out_dir`` already.

    Parameters
    ----------
    nu : float
        Poisson number of the body.
    geometry : str
        The body's kind (one with production settings: the disk, the sphere).
    partner : Partner, optional
        A second disk (its radius ratio and, in the first disk's units, its material).
    out_dir : path, optional
        Where the law file goes [:func:`law_dir`].
    store, executor, progress, workers
        As for :func:`restitution.laws.making.production.build`.
    force : bool
        Compute even when the estimate exceeds :data:`restitution.budget.TIME_BOUND_S`.

    Returns
    -------
    Path
        The law file (``law_filename(nu, geometry, partner)`` in ``out_dir``).
    """
    from restitution.laws.making.production import build

    p = plan(nu, geometry, partner, out_dir)
    if p.exists:
        return p.path
    check_plan(p, force)
    set_aside(p.path)
    groups = production_groups(geometry, partner)
    (written,) = build(p.path.parent, [nu], groups, store=store, executor=executor,
                       workers=workers, progress=progress,
                       low_speeds=low_speeds_of(geometry, partner, nu),
                       geometry=geometry, partner=partner)  # fmt: skip
    return written
