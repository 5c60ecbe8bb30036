"""Grids of collisions run through an executor, with results in the store (paper section 4).

A sweep is a list of :class:`restitution.limits.store.PointSpec`. Points already in the store (for
this code version) are skipped. The rest are grouped by mode set (``nu``, ``N``, selection,
integrator, options), sorted by ``(alpha, v)`` inside a group so that a batch shares a similar
time step, cut into batches of ``batch_size`` points and submitted to an executor; each batch
calls :func:`restitution.dynamics.collision.collide_batch` on one mode set. The parent process
writes every finished batch to the store at once, so Ctrl-C or ``kill -9`` loses at most the
points in flight. A point that failed in the solver is stored with its error message without
losing the others; a task that died with its worker (``kill -9`` of a pool process, a lost Dask
worker) is resubmitted (:data:`restitution.limits.executors.INFRASTRUCTURE_RETRIES` times) and
never stored as failed. The store is checked for writability before anything is computed.

Where the tasks run is :mod:`restitution.limits.executors`: local processes (default), a Dask
``LocalCluster`` (``workers=N``), an existing scheduler (``scheduler=ADDRESS``) or client.

The default extrapolation sets (velocities, ``alpha`` and ``N`` values) live in ONE place,
:data:`DEFAULTS`; change them with :func:`dataclasses.replace`.
"""

from __future__ import annotations

import concurrent.futures as cf
import math
import os
import time
from collections import defaultdict
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field, fields, replace
from typing import Any

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY, SweepPlan, body_kind
from restitution.bodies.pair.partner import Partner
from restitution.bodies.viscoelastic import Viscoelastic
from restitution.dynamics.contact import EXPONENTIAL_WALL, ContactLaw, law_from_key
from restitution.errors import InputError, describe, is_real_array
from restitution.limits.claims import POLL_S, Claims
from restitution.limits.defaults import (
    ALPHA_PRODUCTS,
    ALPHA_SCALE,
    check_alpha_scale,
    check_alphas,
    check_distinct,
    walls_at,
)
from restitution.limits.executors import (
    INFRASTRUCTURE_RETRIES,
    executor,
    infrastructure_message,
    is_infrastructure_failure,
)
from restitution.limits.run_options import Executor, Progress, executor_of, progress_of
from restitution.limits.store import PointSpec, Store, damaged_message
from restitution.status import Status

__all__ = [
    "DEFAULTS",
    "planned",
    "PAPER_VELOCITIES",
    "GridData",
    "SweepReport",
    "SweepSettings",
    "collide_points",
    "defaults_for",
    "grid",
    "load_grid",
    "pair_settings",
    "point_modes",
    "run_sweep",
    "window_scale",
]

PAPER_VELOCITIES: tuple[float, ...] = (0.005, 0.01, 0.02) + tuple(
    round(0.04 + 0.02 * k, 2) for k in range(14)
)
"""Speeds towards the wall of Figs. 1 and 7, units of ``c``: 0.005, 0.01, 0.02, 0.04, 0.06, ...,
0.30 (the caption's sequence; it has 17 members)."""

RANKING_POOL = 1600
"""Pool size for ``select="ranked"`` (the paper ranked 1600 modes, Table 1)."""


@dataclass(frozen=True)
class SweepSettings:
    """Everything that defines a curve computation except ``nu``; the defaults live here.

    Attributes
    ----------
    velocities : tuple of float
        Speeds towards the wall, units of ``c`` (kept in increasing order, whatever the order
        given).
    alphas : tuple of float
        Wall hardness values for the ``alpha -> infinity`` extrapolation: ``alpha`` in ``1/R``
        (``alpha_scale="absolute"``) or the products ``alpha * delta_max(v)``
        (``alpha_scale="compression"``).
    alpha_scale : {"absolute", "compression"}
        ``"absolute"``: the same ``alpha`` at every speed (as the paper's Fig. 7 appears to
        use). ``"compression"``: ``alpha = alphas[k] / delta_max(v)`` with the quasistatic
        maximal compression ``delta_max = v sqrt(ln(4/v))`` (eq. 61, units ``R``), so that the
        wall's decay length is the same fraction of the compression at every speed; slow
        collisions then get the harder walls the paper asks for (section 4, Fig. 7 discussion).
    n_modes : tuple of int
        Mode counts for the ``N -> infinity`` extrapolation (the paper: 300, 400, 600, 940).
    select : str
        Mode selection: ``"lowest"`` (the ``N`` lowest frequencies) or ``"ranked"`` (the paper's
        ranking by average energy in a preliminary run with :data:`RANKING_POOL` modes).
    integrator : str or None
        Time integrator of :mod:`restitution.dynamics.collision`; ``None``: the solver's default.
    options : tuple of (str, value)
        :class:`restitution.dynamics.collision.CollisionSettings` fields (e.g. ``energy_tol``). The
        solver's defaults of all other fields are filled in, so that every numerical setting
        is part of the store key even if a default changes.
    order : str
        Primary order of the two limits (:func:`restitution.limits.extrapolation.combined_limit`).
    batch_size : int
        Collisions per task; they share one mode set (each keeps its own time step, so a
        stored point does not depend on its batch).
    geometry : str
        The body, a kind's name (:func:`restitution.bodies.kinds.geometries`; the disk, the
        paper's, by default); it decides the modes, the compression that scales the walls and
        the variable of the ``N -> infinity`` extrapolation.
    partner : Partner or None
        ``None``: the body against the rigid wall. Else the second body of a head-on pair
        (:class:`restitution.bodies.pair.partner.Partner`): ``velocities`` are relative speeds
        of the centres (``c`` of the first body), ``n_modes`` the lowest modes of both together
        (one common frequency cutoff), the walls scaled by the pair's compression.
    relaxation_time : float
        ``tau`` (``R / c``) of a viscoelastic body
        (:class:`restitution.bodies.viscoelastic.Viscoelastic`); ``0``: elastic. A damped sweep
        runs Strang's splitting (``integrator`` ``None`` becomes ``"split"``; another is
        refused).
    contact_law : ContactLaw
        The law that pushes the body off the wall (:mod:`restitution.dynamics.contact`; a key
        is read as its law); ``alphas`` are its hardness values. Default the exponential wall,
        which ``to_dict`` and the store keys do not name.
    """

    velocities: tuple[float, ...] = PAPER_VELOCITIES
    # The walls shared with the FEM route (restitution.limits.defaults, which says why).
    alphas: tuple[float, ...] = ALPHA_PRODUCTS
    alpha_scale: str = ALPHA_SCALE
    n_modes: tuple[int, ...] = (300, 400, 600, 940)
    select: str = "lowest"
    integrator: str | None = None
    # A drift of 1e-5 of E0 moves epsilon by < 1e-4 (measured at nu = 0.9, v = 0.3, N = 300,
    # alpha = 500 against 1e-6), far below the extrapolation errors (>= 1e-3), at half the steps.
    options: tuple[tuple[str, Any], ...] = (("energy_tol", 1e-5),)
    order: str = "modes_first"
    batch_size: int = 4
    geometry: str = DEFAULT_GEOMETRY
    partner: Partner | None = None
    relaxation_time: float = 0.0
    contact_law: ContactLaw = EXPONENTIAL_WALL

    def __post_init__(self) -> None:
        if isinstance(self.contact_law, dict | str):
            object.__setattr__(self, "contact_law", law_from_key(self.contact_law))
        if not isinstance(self.contact_law, ContactLaw):
            raise InputError(
                f"contact_law must be a ContactLaw (restitution.dynamics.contact), got "
                f"{type(self.contact_law).__name__}; omit it for the exponential wall"
            )
        tau = self.relaxation_time
        if isinstance(tau, bool) or not isinstance(tau, (int, float)) or not tau >= 0:
            raise InputError(f"relaxation_time must be a number >= 0 (R/c), got {tau!r}")
        object.__setattr__(self, "relaxation_time", float(tau))
        if tau > 0:
            if self.integrator not in (None, "split"):
                raise InputError(
                    f"a viscoelastic sweep runs integrator='split', got {self.integrator!r}"
                )
            object.__setattr__(self, "integrator", "split")
        for name in ("velocities", "alphas", "n_modes"):
            values = getattr(self, name)
            # One flat sequence of numbers (issue 47: a bare float or a nested list raised a
            # TypeError deep inside).
            if not (is_real_array(values) and np.ndim(values) == 1):
                raise InputError(
                    f"{name} must be a sequence of numbers, got {describe(values)}; pass e.g. "
                    f"{name}={_EXAMPLES[name]}"
                )
            if len(values) == 0:
                raise InputError(f"{name} must not be empty")
        if not all(float(n).is_integer() for n in self.n_modes):
            raise InputError(f"n_modes must be whole numbers, got {describe(self.n_modes)}")
        # Speeds in increasing order whatever order they came in: curves and laws interpolate
        # in v (issue 47: `curve --v 0.1 0.05` computed the grid, then failed to write it).
        object.__setattr__(self, "velocities", tuple(sorted(float(v) for v in self.velocities)))
        object.__setattr__(self, "alphas", tuple(float(a) for a in self.alphas))
        object.__setattr__(self, "n_modes", tuple(int(n) for n in self.n_modes))
        for name in ("velocities", "alphas", "n_modes"):
            check_distinct(name, getattr(self, name))
        integrator, options = _solver_settings(self.integrator, self.options)
        object.__setattr__(self, "integrator", integrator)
        object.__setattr__(self, "options", options)
        body_kind(self.geometry)
        if any(not (0 < v < 1) for v in self.velocities):
            raise InputError(
                f"speeds v must lie in (0, 1): the {self.geometry}'s speed towards the wall in "
                "units of c"
            )
        check_alphas(self.alphas)
        if any(n < 1 for n in self.n_modes):
            raise InputError("numbers of modes must be >= 1")
        check_alpha_scale(self.alpha_scale)
        if self.select not in ("lowest", "ranked"):
            raise InputError(f"select must be 'lowest' or 'ranked', not {self.select!r}")
        if self.batch_size < 1:
            raise InputError("batch_size must be >= 1")
        if self.partner is not None:
            if not isinstance(self.partner, Partner):
                object.__setattr__(self, "partner", Partner.from_key(self.partner))
            if self.select != "lowest":
                raise InputError("a pair takes the lowest modes of both bodies (select='lowest')")
        if self.relaxation_time and self.select != "lowest":
            raise InputError("a viscoelastic body takes its lowest modes (select='lowest')")

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "velocities": list(self.velocities),
            "alphas": list(self.alphas),
            "alpha_scale": self.alpha_scale,
            "n_modes": list(self.n_modes),
            "select": self.select,
            "integrator": self.integrator,
            "options": {k: v for k, v in self.options},
            "order": self.order,
            "batch_size": self.batch_size,
            "geometry": self.geometry,
            **({} if self.partner is None else {"partner": self.partner.to_dict()}),
            **({"relaxation_time": self.relaxation_time} if self.relaxation_time else {}),
            **(
                {}
                if self.contact_law == EXPONENTIAL_WALL
                else {"contact_law": self.contact_law.key()}
            ),
        }

    def point(self, nu: float, v: float, alpha: float, n_modes: int) -> PointSpec:
        """The store key of one collision of this sweep: ``nu``, speed ``v`` (``c``), wall
        ``alpha`` (``1/R``) and ``n_modes`` with the sweep's solver settings, body, partner
        and contact law."""
        return PointSpec(
            nu,
            v,
            alpha,
            n_modes,
            self.select,
            self.integrator,
            self.options,
            self.geometry,
            self.partner,
            self.relaxation_time,
            self.contact_law,
        )

    def alphas_at(
        self, v: float, alphas: Iterable[float] | None = None, *, nu: float | None = None
    ) -> tuple[float, ...]:
        """Wall hardness values (``1/R``) used at speed ``v`` (units of ``c``); a sphere's
        compression scale needs its Poisson number ``nu``."""
        values = self.alphas if alphas is None else tuple(float(a) for a in alphas)
        return walls_at(
            v, values, self.alpha_scale, geometry=self.geometry, nu=nu, partner=self.partner
        )


# Not part of a stored point's key: the integrator is keyed separately, histories are not
# stored, and the two backends give the same numbers to round-off (tests/test_kernel.py).
_NOT_KEYED = ("integrator", "record", "record_interval", "backend")


_EXAMPLES = {"velocities": "(0.1, 0.2)", "alphas": "(40, 80, 160)", "n_modes": "(100, 200)"}
"""An example of each sequence of :class:`SweepSettings`, for its refusal."""


def _solver_settings(integrator: str | None, options: Any) -> tuple[str, tuple]:
    """Integrator name and the full sorted tuple of the solver's numerical settings."""
    from restitution.dynamics.collision import CollisionSettings

    opts = dict(options.items() if isinstance(options, dict) else options)
    known = {f.name for f in fields(CollisionSettings)} - set(_NOT_KEYED)
    bad = sorted(set(opts) - known)
    if bad:
        raise InputError(
            f"unknown solver option(s) {bad}; use fields of CollisionSettings except "
            f"{', '.join(_NOT_KEYED)}"
        )
    if integrator is not None:
        opts["integrator"] = integrator
    resolved = CollisionSettings(**opts)
    full = tuple(
        (f.name, getattr(resolved, f.name))
        for f in sorted(fields(CollisionSettings), key=lambda f: f.name)
        if f.name not in _NOT_KEYED
    )
    return resolved.integrator, full


DEFAULTS = SweepSettings()
"""The package's default sweep of the disk (tuned to the 10-minute budget of the full Fig. 1
grid)."""


def defaults_for(geometry: str) -> SweepSettings:
    """The default sweep of the body ``geometry``: :data:`DEFAULTS` with the kind's walls and
    mode window (:attr:`~restitution.bodies.kinds.BodyKind.alpha_products`,
    :attr:`~restitution.bodies.kinds.BodyKind.sweep_modes`); the disk's is :data:`DEFAULTS`."""
    kind = body_kind(geometry)
    return replace(
        DEFAULTS, geometry=kind.geometry, n_modes=kind.sweep_modes, alphas=kind.alpha_products
    )


def planned(geometry: str, plan: SweepPlan) -> SweepSettings:
    """The sweep of one group of a kind's plan (:class:`~restitution.bodies.kinds.SweepPlan`):
    the kind's defaults (:func:`defaults_for`) with the plan's speeds, window and batch."""
    return replace(defaults_for(geometry), **plan.fields())


def window_scale(partner: Partner, geometry: str = DEFAULT_GEOMETRY) -> float:
    """``1 + (r c1 / c2)^d``: how many times the modes of the first body alone a pair has below
    one frequency (``r = R2 / R1``, ``c2 / c1 = sqrt(E2 / rho2)`` in the first body's units,
    ``d`` the kind's dimension: a body of radius ``R`` and wave speed ``c`` has
    ``~ (R / c)^d`` times as many modes below a frequency; for disks ``1 + r^2 rho2 / E2``). A
    pair's mode windows are the wall's times this (:func:`pair_settings`)."""
    d = body_kind(geometry).dimension
    if d == 2:  # the disks' form, as their shipped pair laws were computed
        return 1.0 + partner.radius_ratio**2 * partner.density_ratio / partner.modulus_ratio
    return 1.0 + (partner.radius_ratio / partner.speed_ratio) ** d


def pair_settings(settings: SweepSettings, partner: Partner) -> SweepSettings:
    """The sweep of a body on the wall carried over to a pair with ``partner``.

    By the identity of two identical bodies and the body on a wall at half the speed: the
    relative speeds are ``w = 2 v``, the walls are read on the pair's compression scale
    (:meth:`Partner.max_compression`, ``alpha delta_pair(w)`` as ``alpha delta_max(v)``), and
    each mode window ``N`` becomes ``N (1 + r^2 rho2 / E2)`` (``r = R2/R1``), the lowest modes
    of both bodies below the frequency of the wall's ``N`` lowest: in two dimensions a body
    has ``~ R^2 / c^2`` times as many modes below one frequency. At ``r = 1`` every point is
    the wall's point at half the speed with twice the modes (the same frequency cutoff)."""
    scale = window_scale(partner, settings.geometry)
    return replace(
        settings,
        velocities=tuple(2.0 * v for v in settings.velocities),
        n_modes=tuple(int(round(n * scale)) for n in settings.n_modes),
        partner=partner,
    )


def grid(
    nus: Iterable[float],
    settings: SweepSettings = DEFAULTS,
    *,
    velocities: Iterable[float] | None = None,
    alphas: Iterable[float] | None = None,
    n_modes: Iterable[int] | None = None,
) -> list[PointSpec]:
    """All points ``nu x v x alpha x N`` of a sweep.

    Parameters
    ----------
    nus : iterable of float
        Poisson numbers.
    settings : SweepSettings
        Velocities, ``alpha`` and ``N`` sets, selection, integrator and options.
    velocities, alphas, n_modes : iterable, optional
        Override the sets of ``settings`` (``alphas`` interpreted by ``settings.alpha_scale``).
    """
    vs = settings.velocities if velocities is None else tuple(velocities)
    ns = settings.n_modes if n_modes is None else tuple(n_modes)
    return [
        settings.point(nu, v, a, n)
        for nu in nus
        for n in ns
        for v in vs
        for a in settings.alphas_at(v, alphas, nu=nu)
    ]


# -- the work done by one task -------------------------------------------------------------


def point_modes(spec: PointSpec):
    """The modes a point's collisions run with (its ``N`` lowest; of both bodies of a pair;
    damped for a viscoelastic body); ``select="ranked"`` draws from a pool instead
    (:func:`collide_points`)."""
    from restitution.bodies.cache import get_modes

    if spec.partner is not None:
        modes = spec.partner.pair(spec.nu, spec.n_modes, spec.geometry, get_modes)
    else:
        modes = get_modes(spec.nu, count=spec.n_modes, geometry=spec.geometry)
    if spec.relaxation_time:
        modes = Viscoelastic(modes, spec.relaxation_time)
    return modes


def collide_points(specs: Sequence[PointSpec]) -> list[tuple[str, Any]]:
    """Run collisions that share one mode set; the default work of a sweep task.

    Parameters
    ----------
    specs : sequence of PointSpec
        Points with equal :attr:`PointSpec.group`.

    Returns
    -------
    list of (status, payload)
        ``("ok", CollisionResult.to_dict())`` or ``("failed", message)`` per point, in order.
        If the batch as a whole fails, every point is retried alone, so one bad point never
        costs the others.
    """
    from restitution.bodies.cache import get_modes
    from restitution.dynamics.collision import CollisionSettings, collide, collide_batch, rank_modes

    first = specs[0]
    if any(s.group != first.group for s in specs):
        raise InputError("collide_points needs points that share nu, N, selection and options")
    settings = CollisionSettings(integrator=first.integrator, **dict(first.options))
    law = first.contact_law
    if first.select == "ranked" and first.relaxation_time:
        raise InputError("a viscoelastic body takes its lowest modes (select='lowest')")
    if first.select == "ranked":
        pool = get_modes(first.nu, count=max(RANKING_POOL, first.n_modes), geometry=first.geometry)
        out = []
        for s in specs:
            out.append(
                _guard(
                    lambda s=s: collide(
                        rank_modes(pool, s.n_modes, s.v, s.alpha, settings, contact_law=law),
                        s.v,
                        s.alpha,
                        settings,
                        contact_law=law,
                    )
                )
            )
        return out
    modes = point_modes(first)
    if len(specs) > 1:
        try:
            results = collide_batch(
                modes, [s.v for s in specs], [s.alpha for s in specs], settings, contact_law=law
            )
            return [(Status.OK, r.to_dict()) for r in results]
        except Exception:  # noqa: BLE001 - retried point by point below
            pass
    return [
        _guard(lambda s=s: collide(modes, s.v, s.alpha, settings, contact_law=law)) for s in specs
    ]


def _guard(run: Callable[[], Any]) -> tuple[str, Any]:
    try:
        return (Status.OK, run().to_dict())
    except Exception as exc:  # noqa: BLE001 - a failed point is data, not a crash
        return (Status.FAILED, f"{type(exc).__name__}: {exc}")


def _run_task(batch_function: Callable, specs: list[PointSpec]) -> list[tuple[str, Any]]:
    out = batch_function(specs)
    if len(out) != len(specs):
        raise RuntimeError(f"batch function returned {len(out)} outcomes for {len(specs)} points")
    return list(out)


# -- the parent loop -----------------------------------------------------------------------


@dataclass(frozen=True)
class SweepReport:
    """What a sweep did.

    Attributes
    ----------
    total : int
        Points asked for.
    skipped : int
        Points already in the store.
    computed : int
        Points computed successfully now.
    failed : tuple of (PointSpec, str)
        Points that failed now, with their error messages (also stored).
    wall_time_s : float
        Wall-clock time, seconds.
    executor : str
        Description of the executor used.
    lost : tuple of (PointSpec, str)
        Points whose worker died (infrastructure failure) on every one of
        :data:`INFRASTRUCTURE_RETRIES` + 1 attempts; not stored, so a rerun computes them.
    waited : int
        Points another sweep on the same store was computing (it had claimed them,
        :mod:`restitution.limits.claims`), which this one waited for instead of computing.
    """

    total: int
    skipped: int
    computed: int
    failed: tuple[tuple[PointSpec, str], ...] = field(default_factory=tuple)
    wall_time_s: float = 0.0
    executor: str = ""
    lost: tuple[tuple[PointSpec, str], ...] = field(default_factory=tuple)
    waited: int = 0

    @property
    def complete(self) -> bool:
        """Whether every point of this run is now stored as a success."""
        return not self.failed and not self.lost

    @property
    def rate(self) -> float:
        """Collisions computed per second of wall-clock time."""
        n = self.computed + len(self.failed)
        return n / self.wall_time_s if self.wall_time_s > 0 else float("nan")


def _cost(batch: list[PointSpec]) -> float:
    # Steps grow with the wall stiffness and every step costs ~N: a rough LPT key.
    return sum(s.n_modes * math.sqrt(s.alpha) for s in batch)


def _batches(specs: list[PointSpec], batch_size: int) -> list[list[PointSpec]]:
    groups: dict[tuple, list[PointSpec]] = defaultdict(list)
    for s in specs:
        groups[s.group].append(s)
    out = []
    for members in groups.values():
        members.sort(key=lambda s: (s.alpha, s.v))
        out += [members[i : i + batch_size] for i in range(0, len(members), batch_size)]
    out.sort(key=_cost, reverse=True)  # longest first balances the workers
    return out


def run_sweep(
    points: Iterable[PointSpec],
    *,
    store: Store | str | os.PathLike | None = None,
    executor: Executor | None = None,
    batch_size: int = DEFAULTS.batch_size,
    batch_function: Callable[[list[PointSpec]], list[tuple[str, Any]]] = collide_points,
    progress: Progress | bool | None = None,
    retry_failed: bool = False,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
) -> SweepReport:
    """Compute every point not yet in the store.

    Parameters
    ----------
    points : iterable of PointSpec
        The grid (see :func:`grid`); duplicates are computed once.
    store : Store or path, optional
        Result store; default :func:`restitution.limits.store.default_store_path`.
    executor : Executor, optional
        Where the collisions run (:class:`restitution.limits.run_options.Executor`): local
        processes on every core by default, a local Dask cluster, a scheduler or a client.
    workers, scheduler, client : optional
        The older spelling of ``executor`` (its three fields); not together with it.
    batch_size : int
        Points per task (they share a mode set and a time step).
    batch_function : callable
        ``f(list[PointSpec]) -> list[(status, payload)]`` run in the workers; the default
        :func:`collide_points` runs the real solver. Must be picklable (a module-level
        function).
    progress : Progress or bool, optional
        The progress bar with ETA on stderr
        (:class:`restitution.limits.run_options.Progress`; ``True``/``False`` its shorthand);
        default: only when stderr is a terminal.
    retry_failed : bool
        Also recompute points stored as failed. Points whose task died with its worker
        (``BrokenProcessPool``, a lost Dask worker) are never stored as failed; they are
        resubmitted up to :data:`INFRASTRUCTURE_RETRIES` times and otherwise left for the next
        run (:attr:`SweepReport.lost`). A damaged stored row
        (:func:`restitution.limits.store.damaged_message`) is computed again, as a lost one is.

    Returns
    -------
    SweepReport
    """
    where = executor_of(executor, workers=workers, scheduler=scheduler, client=client)
    progress = progress_of(progress)
    if batch_size < 1:
        raise InputError("batch_size must be >= 1")
    own_store = not isinstance(store, Store)
    db = Store(store) if own_store else store
    t0 = time.perf_counter()
    try:
        unique = list(dict.fromkeys(points))
        status = db.status(unique)
        errors = db.errors(s for s in unique if status.get(s.key()) == Status.FAILED)
        todo = [
            s
            for s in unique
            if status.get(s.key()) is None
            or (
                status[s.key()] == Status.FAILED
                and (
                    retry_failed
                    or infrastructure_message(errors.get(s.key()))
                    or damaged_message(errors.get(s.key()))
                )
            )
        ]
        skipped = len(unique) - len(todo)
        computed, failed, lost, name, waited = 0, [], [], "none", 0
        if todo:
            db.check_writable()  # fail now, not after computing
            with Claims(db.path) as claims:

                def run(specs):
                    return _execute(db, specs, batch_size, batch_function, where, progress,
                                    on_batch=claims.beat)  # fmt: skip

                computed, failed, lost, name, waited = _claimed(db, claims, todo, run)
        return SweepReport(
            total=len(unique),
            skipped=skipped,
            computed=computed,
            failed=tuple(failed),
            lost=tuple(lost),
            wall_time_s=time.perf_counter() - t0,
            executor=name,
            waited=waited,
        )
    finally:
        if own_store:
            db.close()


def _claimed(db, claims, todo, run):
    """Compute the points of ``todo`` this sweep can claim (``run``), wait for those another
    live sweep is computing (:mod:`restitution.limits.claims`) and take over those whose sweep
    is gone; returns ``(computed, failed, lost, executor, waited)``, ``waited`` the points the
    other sweeps stored."""
    computed, failed, lost, name, waited = 0, [], [], "none", 0
    pending = list(todo)
    while pending:
        mine, _ = claims.claim(s.key() for s in pending)
        ours = [s for s in pending if s.key() in mine]
        if ours:
            c, f, lost_now, name = run(ours)
            computed, failed, lost = computed + c, failed + f, lost + lost_now
        rest = [s for s in pending if s.key() not in mine]
        while rest:  # until the others stored them, or a sweep holding some is gone
            time.sleep(POLL_S)
            stored = db.status(rest)
            waited += sum(s.key() in stored for s in rest)
            rest = [s for s in rest if s.key() not in stored]
            if rest and claims.claim(s.key() for s in rest)[0]:
                break  # taken over: the outer loop computes them
        pending = rest
    return computed, failed, lost, name, waited


def _execute(db, todo, batch_size, batch_function, where: Executor, progress: Progress,
             on_batch=None):  # fmt: skip
    pending = _batches(todo, batch_size)
    computed, failed, lost, name = 0, [], [], "none"
    with progress.bar(len(todo)) as advance:
        for attempt in range(INFRASTRUCTURE_RETRIES + 1):
            retry = []
            with executor(where.workers, where.scheduler, where.client) as (pool, name):
                futures = {pool.submit(_run_task, batch_function, b): b for b in pending}
                try:
                    for future in cf.as_completed(futures):
                        batch = futures.pop(future)
                        try:
                            outcomes = future.result()
                        except Exception as exc:  # noqa: BLE001 - the whole task died
                            if is_infrastructure_failure(exc):
                                retry.append((batch, f"{type(exc).__name__}: {exc}"))
                                continue
                            failure = (Status.FAILED, f"{type(exc).__name__}: {exc}")
                            outcomes = [failure] * len(batch)
                        for spec, (state, payload) in zip(batch, outcomes, strict=True):
                            if state == Status.OK:
                                db.put(spec, payload)
                                computed += 1
                            else:
                                db.put_failure(spec, str(payload))
                                failed.append((spec, str(payload)))
                        advance(len(batch))
                        if on_batch is not None:
                            on_batch()
                except BaseException:
                    # Ctrl-C (or any error in the parent): drop the queued work; what is
                    # stored stays.
                    for future in futures:
                        future.cancel()
                    raise
            if not retry:
                break
            pending = [batch for batch, _ in retry]
            points = sum(len(b) for b in pending)
            if attempt < INFRASTRUCTURE_RETRIES:
                advance.note(
                    f"warning: {points} point(s) lost with a worker ({retry[0][1][:120]}); "
                    f"retrying ({attempt + 1}/{INFRASTRUCTURE_RETRIES})"
                )
        else:
            # Still lost after every retry: not stored, so the next run computes them.
            lost = [(spec, message) for batch, message in retry for spec in batch]
    return computed, failed, lost, name


# -- reading a grid back ---------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class GridData:
    """Energy losses of one ``(nu, v)`` on the ``alpha x N`` grid, read from the store.

    Attributes
    ----------
    nu, v : float
        Poisson number and speed towards the wall (units of ``c``).
    alpha : numpy.ndarray, shape (A,)
        Wall hardness, ``1/R``.
    n_modes : numpy.ndarray of int, shape (M,)
        Mode counts.
    loss : numpy.ndarray, shape (A, M)
        ``1 - epsilon^2``; ``nan`` where the point is missing or failed.
    drift : numpy.ndarray, shape (A, M)
        Relative energy drift of each run.
    missing : tuple of PointSpec
        Points not in the store.
    failures : tuple of (PointSpec, str)
        Points stored as failed, with their messages.
    """

    nu: float
    v: float
    alpha: np.ndarray
    n_modes: np.ndarray
    loss: np.ndarray
    drift: np.ndarray
    missing: tuple[PointSpec, ...]
    failures: tuple[tuple[PointSpec, str], ...]


def load_grid(
    store: Store,
    nu: float,
    v: float,
    settings: SweepSettings = DEFAULTS,
    *,
    alphas: Sequence[float] | None = None,
    n_modes: Sequence[int] | None = None,
) -> GridData:
    """The ``alpha x N`` grid of one ``(nu, v)`` from the store (this code version)."""
    als = np.asarray(settings.alphas_at(v, alphas, nu=nu), dtype=float)
    ns = np.asarray(settings.n_modes if n_modes is None else n_modes, dtype=int)
    loss = np.full((als.size, ns.size), np.nan)
    drift = np.full_like(loss, np.nan)
    missing, failures = [], []
    for i, a in enumerate(als):
        for j, n in enumerate(ns):
            spec = settings.point(nu, v, a, n)
            row = store.get(spec)
            if row is None:
                missing.append(spec)
            elif not row.ok:
                failures.append((spec, row.error or ""))
            else:
                loss[i, j] = row.energy_loss
                drift[i, j] = row.energy_drift
    return GridData(float(nu), float(v), als, ns, loss, drift, tuple(missing), tuple(failures))
