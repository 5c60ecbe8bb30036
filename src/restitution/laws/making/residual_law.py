"""A law through the static residual (issue 46): the production's speeds, each by the residual
route, joined with the low-speed points.

Units: the body's reduced units (``E = rho = R = 1``; a pair's: the first body's); speeds in
``c`` (a pair's relative speed); times in seconds of wall time.

Today's production (:func:`restitution.laws.making.compute.computed_law`) reaches ``N ->
infinity`` by extrapolating windows of up to 10^4-10^5 modes. This route computes the same
speeds (the modal
groups' speeds, :func:`residual_speeds`) with 200, 400 and 800 kept modes (a pair's times its
window scale) whose dropped modes follow the contact statically
(:func:`restitution.limits.residual_point.residual_point`: the same walls and hard-wall limit,
the mode error from the last two doublings), then one round of the laws' refinement
(:func:`restitution.laws.making.refine.turning_speeds`: a point wherever PCHIP and a spline disagree
between two speeds by more than the points' errors) by the same route, and joins the kind's
low-speed points as the production does. Every point says where it comes from: ``route`` is
``"residual"`` (the modal production's points: ``"modal"`` or none; the low-speed theory's
``"quasistatic"``), and the law's ``metadata["residual"]`` holds the route's settings.

The file is the modal route's name with ``_residual`` (:func:`residual_filename`): the two
routes' laws of one body never replace each other. Interrupted runs resume: every finished point
is kept in ``<cache>/residual_points/<law file>`` (written whole), keyed by speed and code
version (the solver's and the route's own modules', :data:`ROUTE_MODULES`), each with a content
digest: a kept point changed after it was written, or holding an impossible value, is computed
again, never used (:class:`_Kept`). A law file found in the cache is served only when its own
digest matches (:func:`restitution.laws.making.compute.set_aside`).

Two runs of one law at once never compute a speed twice: each claims the speeds it is about to
compute (:class:`restitution.limits.claims.Claims`, in ``<cache>/residual_points/claims.sqlite``,
keyed by law file, speed and code version), computes those, then waits for the speeds another
live run holds and reads them from the kept points; a claim of a run that is gone is taken over
(the claims module's rules). Every run merges the points others kept before it writes the file
(under an ``flock`` on its folder), so none is lost. A kept point that cannot be written (a full
disk) ends the run with one :class:`~restitution.errors.OutputError` naming the folder and what
to do; the points kept before it stay and are not computed again.
"""

from __future__ import annotations

import concurrent.futures as cf
import contextlib
import errno
import fcntl
import json
import math
import os
import sqlite3
import time
import warnings
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from restitution import atomic, budget
from restitution._paths import cache_root
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.errors import InputError, OutputError, is_real
from restitution.jsonable import content_digest, json_default
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.low_speed import low_speed_points, low_speeds_of
from restitution.laws.making.compute import law_dir, production_groups, set_aside
from restitution.laws.making.refine import FACTOR, PER_INTERVAL, RULE, turning_speeds
from restitution.limits.claims import POLL_S, Claims
from restitution.limits.residual_point import NODES_PER_CONTACT, RESIDUAL_MODES, residual_point
from restitution.limits.run_options import Executor, progress_of
from restitution.limits.sweep import window_scale
from restitution.provenance import code_version, source_digest
from restitution.status import Status

__all__ = [
    "RESIDUAL_ROUTE",
    "ResidualPlan",
    "check_residual_plan",
    "check_route",
    "residual_law",
    "residual_plan",
    "residual_filename",
    "residual_record",
    "residual_speeds",
]

RESIDUAL_ROUTE = "residual"
"""``route`` of a law point computed with the static residual."""

ROUTE_TEXT = (
    "the kept modes in motion, the modes above them static (residual flexibility) at 200, 400 "
    "and 800 kept modes, the mode error the larger change of the last two doublings; energy loss "
    "1 - epsilon^2 extrapolated linearly in 1/alpha (alpha -> infinity) "
    "(restitution.limits.residual_point)"
)


def _model(model: str) -> str:
    """The kind's model sentence with its modal extrapolation replaced by this route's."""
    head, marker, _ = model.partition("energy loss 1 - epsilon^2")
    return f"{head if marker else model + ' '}{ROUTE_TEXT}."


def check_route(geometry: str, partner=None) -> None:
    """Refuse, in one line, a body the residual route does not take: a kind without the plan
    (its measured cost) or a pair of unequal radii (its bodies' nodes differ)."""
    kind = body_kind(geometry)
    plan = kind.production if partner is None else kind.pair_production
    if plan is None or plan.residual_seconds_per_point is None or not plan.groups:
        who = f"two {geometry}s" if partner is not None else f"the {geometry}"
        raise InputError(
            f"the residual route has no production plan for {who}; leave out --route residual "
            "(the modal route)"
        )
    if partner is not None and partner.radius_ratio != 1.0:
        raise InputError(
            f"the residual route takes pairs of equal radii (got R2/R1 = "
            f"{partner.radius_ratio:g}); leave out --route residual (the modal route)"
        )


def residual_filename(nu: float, geometry: str = DEFAULT_GEOMETRY, partner=None) -> str:
    """The law file's name: the modal route's (:func:`~restitution.laws.law.law_filename`) with
    ``_residual`` before ``.json``, so that a law of either route never replaces the other's."""
    name = law_filename(nu, geometry, partner)
    return f"{name.removesuffix('.json')}_{RESIDUAL_ROUTE}.json"


def residual_speeds(geometry: str = DEFAULT_GEOMETRY, partner=None) -> tuple[float, ...]:
    """The speeds of the modal production of the body (with ``partner``: of the pair), which
    this route computes."""
    groups = production_groups(geometry, partner)
    return tuple(sorted({float(v) for g in groups for v in g.velocities}))


def _seconds_per_point(geometry: str, partner=None) -> float:
    kind = body_kind(geometry)
    if partner is None:
        return kind.production.residual_seconds_per_point
    return kind.pair_production.residual_seconds_per_point * window_scale(partner, geometry)


@dataclass(frozen=True)
class ResidualPlan:
    """What :func:`residual_law` will do: the file, the speeds and the estimated time.

    ``seconds``: on one core, the production's speeds, at most one refining point per interval
    and the low-speed points; ``workers``: processes the points run on.
    """

    path: Path
    exists: bool
    speeds: int
    low_points: int
    seconds: float

    def words(self) -> str:
        if self.exists:
            return f"using the law computed before, {self.path}"
        return (
            f"computing the law by the residual route: {self.speeds} speeds (and at most "
            f"{max(self.speeds - 1, 0)} refining ones), {self.low_points} low-speed points, "
            f"about {budget.format_duration(self.seconds)} on one core (finished points are "
            f"kept; an interrupted run resumes), into {self.path}"
        )


def residual_plan(
    nu: float, geometry: str = DEFAULT_GEOMETRY, partner=None, out_dir=None, *, reuse=True
) -> ResidualPlan:
    """The plan of :func:`residual_law` with the same arguments (nothing is computed)."""
    from restitution.laws.making.compute import _usable, seconds_per_low_point

    check_route(geometry, partner)
    path = Path(out_dir or law_dir()) / residual_filename(nu, geometry, partner)
    speeds = residual_speeds(geometry, partner)
    low = low_speeds_of(geometry, partner, nu)
    seconds = (2 * len(speeds) - 1) * _seconds_per_point(geometry, partner)
    seconds += len(low) * seconds_per_low_point(geometry, partner)
    return ResidualPlan(path, reuse and _usable(path), len(speeds), len(low), seconds)


def check_residual_plan(p: ResidualPlan, force: bool = False) -> None:
    """Refuse a plan whose estimate exceeds :data:`restitution.budget.TIME_BOUND_S` unless
    ``force`` (one line: the speeds, the estimate, the bound)."""
    if p.exists:
        return
    budget.check_time_total(
        "--route residual", f"for {p.path.name}", p.seconds, f"{p.speeds} speeds",
        lambda bound: f"about {int(bound // max(p.seconds / max(p.speeds, 1), 1e-9))} speeds fit",
        force=force, override="--force",
    )  # fmt: skip


def residual_record(point) -> dict:
    """One :class:`~restitution.limits.residual_point.ResidualPoint` as a law's
    ``metadata["points"]`` holds it (``route`` ``"residual"``; status ``ok`` where the hard-wall
    fit passed its checks, else ``not-asymptotic``)."""
    return {
        "v": point.v,
        "epsilon": point.epsilon,
        "epsilon_err": point.epsilon_err,
        "energy_loss": point.energy_loss,
        "energy_loss_err": point.energy_loss_err,
        "asymptotic_ok": point.asymptotic_ok,
        "status": Status.OK if point.asymptotic_ok else Status.NOT_ASYMPTOTIC,
        "route": RESIDUAL_ROUTE,
        "message": point.message,
        "residual": {
            "walls": list(point.walls),
            "alpha": list(point.alphas),
            "n_modes": list(point.modes),
            "energy_loss_grid": point.losses.tolist(),
            "mode_err": point.mode_err.tolist(),
            "step_err": point.step_err.tolist(),
            "alpha_err": point.alpha_err,
            "curvature": point.curvature,
            "seconds": round(point.seconds, 2),
        },
    }


ROUTE_MODULES = ("restitution.limits.residual_point", "restitution.limits.extrapolation")
"""Modules outside the solver's code version that make a point's numbers (its kept sets, walls
and error budget): part of the version of kept points and of the law."""


def _version(geometry: str, pair: bool) -> str:
    """The solver's code version (:func:`~restitution.provenance.code_version`) and the
    route's own modules' digest."""
    route = source_digest(ROUTE_MODULES, tag="residual.").partition("+")[2]
    return f"{code_version(geometry, pair=pair)}/{route}"


def _point(task) -> dict:
    geometry, nu, v, partner = task
    return residual_record(residual_point(geometry, nu, v, partner=partner))


def _impossible(record) -> str | None:
    """Why a kept point's values cannot be a point of a law (``None``: they can): ``v`` not a
    finite number > 0, ``epsilon`` outside ``(0, 1]``, its error not a finite number >= 0."""
    if not isinstance(record, dict):
        return "it is not an object"
    v, eps, err = (record.get(k) for k in ("v", "epsilon", "epsilon_err"))
    if not all(is_real(x) and math.isfinite(x) for x in (v, eps, err)):
        return "its v, epsilon or error is not a finite number"
    if not (v > 0 and 0 < eps <= 1 and err >= 0):
        return f"it holds epsilon = {eps!r} +- {err!r} at v = {v!r}"
    return None


class _Kept:
    """The finished points of one law, kept whole in a JSON file (module docs).

    The file holds ``code_version``, ``points`` (record by ``repr`` of its speed) and
    ``digests``: for each point ``"sha256:<hex>"`` of the canonical JSON of its code version, key
    and record (:func:`restitution.jsonable.content_digest`). A point is used only when its
    digest matches and its values are possible (:func:`_impossible`); the others (changed after
    they were written, kept before points carried a digest, an epsilon of 1.7) are dropped with
    one warning and computed again. Several runs may keep points in one file at once: each
    merges the file's points into its own before it writes (:meth:`add`, under :func:`_locked`).
    """

    def __init__(self, path: Path, version: str) -> None:
        self.path, self.version = path, version
        self.points: dict[str, dict] = {}
        self.digests: dict[str, str] = {}
        dropped = self.refresh()
        if dropped:
            warnings.warn(
                f"{len(dropped)} kept point(s) of {path} are not used and are computed again: "
                f"changed after they were written, kept before points carried a digest, or "
                f"impossible: v = {', '.join(dropped[:3])}{', ...' if len(dropped) > 3 else ''}",
                stacklevel=3,
            )

    def refresh(self) -> list[str]:
        """Take in the file's intact points of this code version that this run lacks (those
        another run kept since); returns the dropped ones, ``"<key> (<why>)"``."""
        try:
            stored = json.loads(self.path.read_text())
            if stored.get("code_version") != self.version:
                return []
            points, digests = dict(stored["points"]), stored.get("digests") or {}
            if not isinstance(digests, dict):
                digests = {}
        except (OSError, ValueError, KeyError, TypeError, AttributeError, RecursionError):
            return []
        dropped = []
        for key, record in points.items():
            if key in self.points:
                continue
            try:
                intact = digests.get(key) == self._digest(key, record)
            except (ValueError, TypeError, RecursionError):  # not JSON as written
                intact = False
            why = _impossible(record) or (None if intact else "its digest does not match")
            if why is None and key != repr(float(record["v"])):
                why = f"its speed {record['v']!r} is not the one it is kept under ({key})"
            if why is None:
                self.points[key], self.digests[key] = record, digests[key]
            else:
                dropped.append(f"{key} ({why})")
        return dropped

    def _digest(self, key: str, record: dict) -> str:
        return content_digest({"code_version": self.version, "key": key, "record": record})

    def add(self, record: dict) -> None:
        """Keep ``record`` with the points other runs kept meanwhile; a file that cannot be
        written (a full disk) is an :class:`~restitution.errors.OutputError` (:meth:`failed`)
        and leaves the points kept before as they were."""
        key = repr(float(record["v"]))
        # The record as a reader parses it, so that its digest is the one read back.
        record = json.loads(json.dumps(record, default=json_default))
        self.points[key], self.digests[key] = record, self._digest(key, record)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            with _locked(self.path.parent):
                self.refresh()
                doc = {"code_version": self.version, "points": self.points,
                       "digests": self.digests}  # fmt: skip
                atomic.write_text(self.path, json.dumps(doc))
        except OSError as exc:
            raise self.failed(exc.strerror or str(exc), exc.errno) from None

    def failed(self, reason: str, code: int | None = None) -> OutputError:
        """The one-line error of a folder the points cannot be kept in: why, and what to do."""
        folder = self.path.parent
        if code in (errno.ENOSPC, errno.EDQUOT) or "full" in reason:
            advice = "free some space there"
        else:
            advice = "make it writable"
        return OutputError(
            f"cannot keep the computed points of --route residual in {folder} ({reason}): "
            f"{advice}, or set RESTITUTION_CACHE_DIR to a folder on another disk, and run again "
            f"(the points kept before are used, not computed again)"
        )


@contextlib.contextmanager
def _locked(folder: Path) -> Iterator[None]:
    """An exclusive ``flock`` on ``folder`` (waits for it): one run at a time reads, merges
    and writes a kept-points file there."""
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def _key(task) -> str:
    return repr(float(task[2]))


def _claims(kept: _Kept) -> Claims:
    """The claims on speeds of the residual route, beside the kept points."""
    try:
        kept.path.parent.mkdir(parents=True, exist_ok=True)
        return Claims(kept.path.parent / "claims.sqlite")
    except (OSError, sqlite3.Error) as exc:
        raise kept.failed(getattr(exc, "strerror", None) or str(exc),
                          getattr(exc, "errno", None)) from None  # fmt: skip


def _claim_key(kept: _Kept, task) -> str:
    """A speed's claim: the law file, the speed and the code version (runs of another code
    version compute their own points)."""
    return f"{kept.path.name} v={_key(task)} {kept.version}"


def _claim(claims: Claims, kept: _Kept, tasks) -> set[str]:
    """The speeds of ``tasks`` (their :func:`_key`) this run holds now (claimed or taken over)."""
    try:
        mine, _ = claims.claim(_claim_key(kept, t) for t in tasks)
    except sqlite3.Error as exc:
        raise kept.failed(str(exc)) from None
    return {_key(t) for t in tasks if _claim_key(kept, t) in mine}


def _compute(tasks, kept: _Kept, executor: Executor, meter, claims: Claims) -> list[dict]:
    """The records of ``tasks``: the kept ones, those this run computes (the speeds it can
    claim, first) and those another live run computes (waited for and read from the kept
    points; taken over if that run is gone)."""
    pending = [t for t in tasks if _key(t) not in kept.points]
    if not pending:
        return [kept.points[_key(t)] for t in tasks]
    with meter.bar(len(tasks), "speeds") as bar:
        bar(len(tasks) - len(pending))
        told = False
        while pending:
            mine = _claim(claims, kept, pending)
            # Points kept by a run whose claims were just released are read, not recomputed.
            kept.refresh()
            done = [t for t in pending if _key(t) in kept.points]
            bar(len(done))
            pending = [t for t in pending if _key(t) not in kept.points]
            ours = [t for t in pending if _key(t) in mine]
            if ours:
                _run(ours, kept, executor, bar, claims)
            rest = [t for t in pending if _key(t) not in mine]
            if rest and not told:
                bar.note(f"{len(rest)} speed(s) are being computed by another run of this law; "
                         "waiting for them")  # fmt: skip
                told = True
            while rest:  # until the other runs kept them, or one holding some is gone
                time.sleep(POLL_S)
                kept.refresh()
                done = [t for t in rest if _key(t) in kept.points]
                bar(len(done))
                rest = [t for t in rest if _key(t) not in kept.points]
                if rest and _claim(claims, kept, rest):
                    break  # taken over: the outer loop computes them
            pending = rest
    return [kept.points[_key(t)] for t in tasks]


def _run(tasks, kept: _Kept, executor: Executor, bar, claims: Claims) -> None:
    """Compute ``tasks`` on the executor's workers and keep each as it finishes. On any error
    (a point that cannot be kept, a failed point, Ctrl-C) the queued points are dropped before
    the error leaves, so that no worker or thread outlives it."""
    from restitution.limits.executors import executor as pool_of

    with pool_of(**executor.keywords()) as (pool, _):
        futures = [pool.submit(_point, t) for t in tasks]
        try:
            for future in cf.as_completed(futures):
                kept.add(future.result())
                bar(1)
                with contextlib.suppress(sqlite3.Error):  # a missed beat: the thread beats too
                    claims.beat()
        except BaseException:
            for future in futures:
                future.cancel()
            raise


def residual_law(
    nu: float,
    geometry: str = DEFAULT_GEOMETRY,
    partner=None,
    *,
    out_dir=None,
    executor: Executor | None = None,
    progress=None,
    force: bool = False,
    speeds=None,
    low_speeds=None,
    refine_rounds: int = 1,
) -> Path:
    """The law file of ``nu`` by the residual route (module docs), unless it is in ``out_dir``
    already; refused beyond :data:`restitution.budget.TIME_BOUND_S` unless ``force``.

    ``speeds``/``low_speeds``: instead of the production's (:func:`residual_speeds`,
    :func:`~restitution.laws.low_speed.low_speeds_of`; ``()`` for none);
    ``refine_rounds``: rounds of refining points (``0``: none); ``executor``: where the points
    run (:class:`~restitution.limits.run_options.Executor`, default local processes on every
    core)."""
    p = residual_plan(nu, geometry, partner, out_dir)
    if p.exists:
        return p.path
    check_residual_plan(p, force)
    set_aside(p.path)  # a changed or unverifiable file there is computed again, not served
    meter = progress_of(progress)
    executor = executor or Executor()
    pair = partner is not None
    version = _version(geometry, pair)
    kept = _Kept(cache_root() / "residual_points" / p.path.name, version)
    speeds = residual_speeds(geometry, partner) if speeds is None else tuple(speeds)
    parameters = {
        "route": ROUTE_TEXT,
        "n_modes": list(RESIDUAL_MODES),
        "window_scale": window_scale(partner, geometry) if pair else 1.0,
        "nodes_per_contact": NODES_PER_CONTACT,
        "walls": list(body_kind(geometry).alpha_products),
        "code_version": version,
    }
    with _claims(kept) as claims:  # another run of this law computes none of these speeds
        tasks = [(geometry, nu, float(v), partner) for v in speeds]
        records = _compute(tasks, kept, executor, meter, claims)
        law_ = EpsilonLaw.from_records(
            nu, records, key=RESIDUAL_ROUTE, parameters=parameters, geometry=geometry,
            partner=partner,
        )  # fmt: skip
        law_.metadata["model"] = _model(law_.metadata["model"])
        done = []
        for _ in range(refine_rounds):
            flagged = turning_speeds(law_)
            if not flagged:
                break
            tasks = [(geometry, nu, v, partner) for v, _ in flagged]
            new = _compute(tasks, kept, executor, meter, claims)
            done.append({"speeds": [v for v, _ in flagged],
                         "ratios": [round(r, 3) for _, r in flagged], "dropped": []})  # fmt: skip
            law_ = law_.joined(new, key="refined", parameters={
                "rule": RULE, "factor": FACTOR, "per_interval": PER_INTERVAL, "rounds": done,
                "code_version": version,
            })  # fmt: skip
    low = tuple(low_speeds_of(geometry, partner, nu) if low_speeds is None else low_speeds)
    if low:
        records, parameters = low_speed_points(
            nu, low, geometry=geometry, partner=partner, progress=meter
        )
        law_ = law_.joined(records, key="low_speed", parameters=parameters)
    p.path.parent.mkdir(parents=True, exist_ok=True)
    return law_.to_json(p.path)
