"""Computing a paper run: the sweep, the extrapolated curves and the data of every figure.

:func:`compute_paper` runs the stages of :data:`STAGES` in order (each timed, each reported to
an ``on_stage`` callback) and returns :class:`PaperData`, every number behind the figures and
Table 1. Nothing is written here (see :mod:`restitution.reproduction.paper.build`) and nothing is
judged (see :mod:`restitution.reproduction.claims`).

Units: two-dimensional ``E = rho = R = 1``; speeds in ``c = sqrt(E/rho)`` unless a field says
``c_L``; times in ``R/c``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from restitution.limits.sweep import SweepReport, SweepSettings
from restitution.reproduction.paper.settings import FULL, PaperSettings, speed_factor

__all__ = [
    "STAGES",
    "PaperData",
    "StageEvent",
    "compute_paper",
    "speed_unit_sweep",
    "sweep_contact_times",
]

STAGES: tuple[tuple[str, str], ...] = (
    ("sweep", "Sweep of section 4 (collisions for Figs. 1, 7, 8, 11, 12)"),
    ("sweep_cl", "Sweep at the speeds read in c_L (second Fig. 1)"),
    ("curves", "Figs. 1, 7, 8: extrapolation to a hard wall and infinitely many modes"),
    ("fig02", "Fig. 2: mode shapes"),
    ("fig03", "Fig. 3: spectrum"),
    ("fig05", "Fig. 5: snapshots of a collision"),
    ("fig06", "Fig. 6: mode energy at closest approach"),
    ("table1", "Table 1: the ten most important modes"),
    ("fig10", "Fig. 10: force against compression"),
    ("fig11", "Fig. 11: contact time and compression"),
    ("fig12", "Fig. 12: Rayleigh's estimate"),
    ("figures", "Writing the figures"),
    ("report", "Writing the report"),
)
"""``(key, label)`` of every stage of :func:`build_paper`, in order."""


@dataclass(frozen=True)
class StageEvent:
    """Progress of :func:`build_paper`, passed to its ``on_stage`` callback.

    Attributes
    ----------
    kind : {"start", "done"}
    key, label : str
        The stage (see :data:`STAGES`).
    index : int
        Position of the stage in :data:`STAGES` (0-based).
    seconds : float
        Wall-clock time of the stage (``"done"`` only).
    own_progress : bool
        The stage shows its own progress bar (the sweep); a caller's live display should
        pause until the stage is done.
    """

    kind: str
    key: str
    label: str
    index: int
    seconds: float = 0.0
    own_progress: bool = False


@dataclass(frozen=True, eq=False)
class PaperData:
    """Every number behind the figures and Table 1 of one run.

    Attributes
    ----------
    settings : PaperSettings
    sweep_report : SweepReport
        What the sweep computed and what it found in the store.
    curves : dict of float to restitution.limits.curves.Curve
        Extrapolated epsilon(v) per Poisson number.
    fig01 : restitution.reproduction.figures.fig01_epsilon.Fig01Data
    fig07, fig08 : tuple
        One ``Fig07Data`` / ``Fig08Data`` per Poisson number (order of ``settings.nus``).
    fig02, fig03, fig05, fig06, table1, fig10, fig11, fig12
        The data of the other figure modules.
    fig01_units : dict of str to Fig01Data
        Fig. 1 for every unit of :attr:`PaperSettings.speed_units` (``"c"`` is ``fig01``);
        speeds of each in that unit.
    sweep_reports : dict of str to SweepReport
        The sweep of every speed unit (``"c"`` is ``sweep_report``).
    contact_points : tuple of (float, float, int)
        ``(v, alpha, N)`` of the sweep collisions behind the dynamic points of Fig. 11.
    timings : tuple of (str, float)
        ``(stage label, seconds)``.
    """

    settings: PaperSettings
    sweep_report: SweepReport
    curves: dict
    fig01: Any
    fig07: tuple
    fig08: tuple
    fig02: Any
    fig03: Any
    fig05: Any
    fig06: Any
    table1: Any
    fig10: Any
    fig11: Any
    fig12: Any
    contact_points: tuple[tuple[float, float, int], ...]
    timings: tuple[tuple[str, float], ...]
    fig01_units: dict
    sweep_reports: dict


class _Stages:
    """Runs the stages in order, timing each and telling the callback."""

    def __init__(self, on_stage: Callable[[StageEvent], None] | None) -> None:
        self.on_stage = on_stage
        self.timings: list[tuple[str, float]] = []
        self._index = {key: i for i, (key, _) in enumerate(STAGES)}
        self._label = dict(STAGES)

    def run(self, key: str, fn: Callable[[], Any], own_progress: bool = False) -> Any:
        label, index = self._label[key], self._index[key]
        if self.on_stage is not None:
            self.on_stage(StageEvent("start", key, label, index, own_progress=own_progress))
        t0 = time.perf_counter()
        out = fn()
        seconds = time.perf_counter() - t0
        self.timings.append((label, seconds))
        if self.on_stage is not None:
            self.on_stage(StageEvent("done", key, label, index, seconds, own_progress))
        return out


def sweep_contact_times(
    store, nu: float, settings: SweepSettings, v_max: float = math.inf
) -> tuple[np.ndarray, np.ndarray, tuple[tuple[float, float, int], ...]]:
    """Contact times of the sweep's collisions with the hardest wall and the most modes.

    The paper's Fig. 11 takes its dynamic points "from the collisions with the hardest
    potential used for any velocity"; the sweep already holds them, so nothing is recomputed.

    Parameters
    ----------
    store : restitution.limits.store.Store
        The sweep's result store.
    nu : float
        Poisson number.
    settings : SweepSettings
        The sweep (speeds, ``alpha`` and ``N`` sets, solver settings).
    v_max : float
        Largest speed to include, ``c``.

    Returns
    -------
    v, contact_time : numpy.ndarray, shape (J,)
        Speeds (``c``) and contact times (``R/c``) of the points found in the store.
    points : tuple of (v, alpha, N)
        Where each point came from.
    """
    vs, taus, where = [], [], []
    n = max(settings.n_modes)
    for v in settings.velocities:
        if v > v_max:
            continue
        alpha = max(settings.alphas_at(v))
        row = store.get(settings.point(nu, v, alpha, n))
        if row is not None and row.ok and math.isfinite(row.contact_time):
            vs.append(v)
            taus.append(row.contact_time)
            where.append((float(v), float(alpha), int(n)))
    return np.asarray(vs, float), np.asarray(taus, float), tuple(where)


def speed_unit_sweep(settings: SweepSettings, nu: float, unit: str) -> SweepSettings:
    """The sweep ``settings`` with the paper's speeds read in ``unit`` (converted to ``c``).

    ``unit = "c_L"`` multiplies every speed by ``1/sqrt(1 - nu^2)`` (2.294 at ``nu = 0.9``,
    1.059 at ``nu = 0.33``); ``alpha`` follows the compression at the converted speed.
    """
    f = speed_factor(nu, unit)
    if f == 1.0:
        return settings
    return replace(settings, velocities=tuple(float(v) * f for v in settings.velocities))


def compute_paper(
    settings: PaperSettings = FULL,
    *,
    store=None,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
    progress: bool | None = None,
    on_stage: Callable[[StageEvent], None] | None = None,
) -> PaperData:
    """Compute the data of every figure and of Table 1.

    Parameters
    ----------
    settings : PaperSettings
        Sizes (:data:`FULL` or :data:`QUICK`).
    store : restitution.limits.store.Store or path, optional
        Result store of the sweep; default :func:`restitution.limits.store.default_store_path`
        (the same as ``restitution curve``).
    workers, scheduler, client
        Executor of the sweep (:func:`restitution.limits.sweep.run_sweep`).
    progress : bool, optional
        The sweep's progress bar (default: when stderr is a terminal).
    on_stage : callable, optional
        Called with a :class:`StageEvent` at the start and end of every stage.
    """
    from restitution.limits.curves import compute_curves
    from restitution.limits.store import Store
    from restitution.limits.sweep import grid, run_sweep
    from restitution.quasistatic.hertz import contact_law
    from restitution.reproduction.figures import (
        fig01_epsilon,
        fig02_shapes,
        fig03_spectrum,
        fig05_snapshots,
        fig06_mode_energy,
        fig07_alpha,
        fig08_modes,
        fig10_force,
        fig11_contact,
        fig12_rayleigh,
        table1,
    )

    s = settings
    stages = _Stages(on_stage)
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        report = stages.run(
            "sweep",
            lambda: run_sweep(
                grid(s.nus, s.sweep),
                store=db,
                workers=workers,
                scheduler=scheduler,
                client=client,
                batch_size=s.sweep.batch_size,
                progress=progress,
            ),
            own_progress=True,
        )

        def unit_sweeps():
            reports = {}
            for unit in s.speed_units[1:]:
                points = [
                    p for nu in s.nus for p in grid([nu], speed_unit_sweep(s.sweep, nu, unit))
                ]
                reports[unit] = run_sweep(
                    points,
                    store=db,
                    workers=workers,
                    scheduler=scheduler,
                    client=client,
                    batch_size=s.sweep.batch_size,
                    progress=progress,
                )
            return reports

        reports = {"c": report, **stages.run("sweep_cl", unit_sweeps, own_progress=True)}

        def curves_stage():
            curves = compute_curves(s.nus, s.sweep, store=db, run=False)
            f01 = fig01_epsilon.compute(s.nus, s.sweep, curves=curves)
            f07 = tuple(fig07_alpha.compute(nu, s.sweep, curve=curves[float(nu)]) for nu in s.nus)
            f08 = tuple(fig08_modes.compute(nu, s.sweep, curve=curves[float(nu)]) for nu in s.nus)
            units = {"c": f01}
            for unit in s.speed_units[1:]:
                at = {}
                for nu in s.nus:
                    sw = speed_unit_sweep(s.sweep, nu, unit)
                    at.update(compute_curves([nu], sw, store=db, run=False))
                scale = {float(nu): speed_factor(nu, unit) for nu in s.nus}
                units[unit] = fig01_epsilon.compute(s.nus, curves=at, speed_unit=unit, scale=scale)
            return curves, f01, f07, f08, units

        curves, f01, f07, f08, f01_units = stages.run("curves", curves_stage)
        f02 = stages.run(
            "fig02",
            lambda: fig02_shapes.compute(s.nu, which=s.shape_modes, amplitude=s.shape_amplitude),
        )
        f03 = stages.run("fig03", lambda: fig03_spectrum.compute(s.nu, s.spectrum_omega_max))
        f05 = stages.run(
            "fig05",
            lambda: fig05_snapshots.compute(
                nu=s.nu, v=s.snapshot_v, alpha=s.snapshot_alpha, count=s.snapshot_modes
            ),
        )
        f06 = stages.run(
            "fig06",
            lambda: fig06_mode_energy.compute(
                nu=s.nu, v=s.collision_v, alpha=s.collision_alpha, count=s.collision_modes
            ),
        )
        t1 = stages.run(
            "table1",
            lambda: table1.compute(
                nu=s.nu, alpha=s.collision_alpha, v=s.collision_v, count=s.collision_modes
            ),
        )

        def fig10_stage():
            loops = fig10_force.dynamic_loops(s.nu, s.loop_speeds, s.loop_alpha, s.loop_modes)
            return fig10_force.compute(
                s.nu,
                n_modes=s.relax_modes,
                alpha=s.relax_alpha,
                delta_max=s.relax_delta_max,
                n_delta=s.relax_points,
                dynamic=loops,
            )

        f10 = stages.run("fig10", fig10_stage)

        def fig11_stage():
            v_star = contact_law(s.nu, "paper").max_speed()
            dv, dt, where = sweep_contact_times(db, s.nu, s.sweep, v_max=v_star)
            data = fig11_contact.compute(s.nu, n_v=s.contact_points, dynamic=(dv, dt))
            return data, where

        f11, contact_points = stages.run("fig11", fig11_stage)

        def fig12_stage():
            c = curves[float(s.nu)] if float(s.nu) in curves else None
            dv, dl, ok = [], [], []
            if c is not None:
                for v, lim in zip(c.velocities, c.limits, strict=True):
                    if v <= s.rayleigh_v_max and math.isfinite(lim.limit):
                        dv.append(float(v))
                        dl.append(float(lim.limit))
                        ok.append(bool(lim.asymptotic_ok))
            return fig12_rayleigh.compute(
                s.nu,
                law=s.law,
                n_modes=s.rayleigh_modes,
                v_min=s.rayleigh_v_min,
                v_max=s.rayleigh_v_max,
                n_v=s.rayleigh_points,
                dynamic=(dv, dl, ok),
            )

        f12 = stages.run("fig12", fig12_stage)
    finally:
        if own:
            db.close()
    return PaperData(
        settings=s,
        sweep_report=report,
        curves=curves,
        fig01=f01,
        fig07=f07,
        fig08=f08,
        fig02=f02,
        fig03=f03,
        fig05=f05,
        fig06=f06,
        table1=t1,
        fig10=f10,
        fig11=f11,
        fig12=f12,
        contact_points=contact_points,
        timings=tuple(stages.timings),
        fig01_units=f01_units,
        sweep_reports=reports,
    )
