"""Computing epsilon(v): sweeps of collisions extrapolated to a hard wall and to many modes.

Paper Fig. 1. For every speed ``v`` (the body's speed towards the wall, units of
``c = sqrt(E/rho)``; the body is ``settings.geometry``, the paper's disk by default) the energy
loss ``1 - epsilon^2`` is computed on a grid of wall hardness ``alpha`` and mode counts ``N``
(:mod:`restitution.limits.sweep`) and extrapolated to ``alpha, N -> infinity``
(:mod:`restitution.limits.extrapolation`). :func:`compute_curves` does this for a whole grid of
speeds, :func:`epsilon_at` for one speed. Serving the result as a law and its exports is
:mod:`restitution.laws.law`'s job.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from restitution._version import __version__
from restitution.bodies.kinds import body_kind
from restitution.errors import InputError, describe, is_real, real
from restitution.estimate import Estimate, estimate_of
from restitution.jsonable import finite_or_none
from restitution.limits.extrapolation import (
    CombinedLimit,
    FromLoss,
    LinearLimit,
    combined_limit,
    epsilon_from_loss,
    extrapolate_modes,
)
from restitution.limits.run_options import Executor, Progress
from restitution.limits.store import Store
from restitution.limits.sweep import (
    DEFAULTS,
    SweepSettings,
    collide_points,
    defaults_for,
    grid,
    load_grid,
    run_sweep,
)

__all__ = ["Curve", "PointEpsilon", "compute_curves", "epsilon_at"]


@dataclass(frozen=True, eq=False)
class Curve:
    """Extrapolated epsilon at several speeds for one Poisson number.

    Attributes
    ----------
    nu : float
        Poisson number of the body (two-dimensional for the disk).
    settings : SweepSettings
        Grid and solver settings behind the points (and the body, ``settings.geometry``).
    velocities : numpy.ndarray, shape (K,)
        Speeds towards the wall, units of ``c``.
    limits : tuple of CombinedLimit
        The extrapolation at each speed (grid and fits included).
    """

    nu: float
    settings: SweepSettings
    velocities: np.ndarray
    limits: tuple[CombinedLimit, ...]

    @property
    def epsilon(self) -> np.ndarray:
        return np.array([c.epsilon for c in self.limits])

    @property
    def epsilon_err(self) -> np.ndarray:
        return np.array([c.epsilon_err for c in self.limits])


def compute_curves(
    nus: Iterable[float],
    settings: SweepSettings = DEFAULTS,
    *,
    store: Store | str | os.PathLike | None = None,
    run: bool = True,
    executor: Executor | None = None,
    progress: Progress | bool | None = None,
    batch_function=collide_points,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
) -> dict[float, Curve]:
    """Run (or read) the sweep of ``settings`` for every ``nu`` and extrapolate every speed.

    Parameters
    ----------
    nus : iterable of float
        Poisson numbers.
    settings : SweepSettings
        Velocities, ``alpha`` and ``N`` sets, solver settings (default :data:`DEFAULTS`).
    store : Store or path, optional
        Result store (default :func:`restitution.limits.store.default_store_path`).
    run : bool
        Compute missing points first; with ``False`` only the store is read (missing points
        become ``nan`` and are flagged).
    executor, progress, batch_function
        Passed to :func:`restitution.limits.sweep.run_sweep` (``workers``, ``scheduler``,
        ``client``: the older spelling of ``executor``).

    Returns
    -------
    dict of float to Curve

    Raises
    ------
    InputError
        If ``nus`` is not an iterable of Poisson numbers in the body's range, ``settings`` not
        a :class:`SweepSettings` or ``run`` not a bool.
    """
    _check_settings(settings)
    _check_run(run)
    if isinstance(nus, str | bytes) or is_real(nus) or not isinstance(nus, Iterable):
        raise InputError(
            f"nus must be a list of Poisson numbers, got {describe(nus)}; pass e.g. nus=[0.33]"
        )
    kind = body_kind(settings.geometry)
    nus = [kind.check_nu(nu) for nu in nus]
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        if run:
            run_sweep(
                grid(nus, settings),
                store=db,
                executor=executor,
                workers=workers,
                scheduler=scheduler,
                client=client,
                batch_size=settings.batch_size,
                batch_function=batch_function,
                progress=progress,
            )
        curves = {}
        for nu in nus:
            limits = []
            for v in settings.velocities:
                data = load_grid(db, nu, v, settings)
                limit = combined_limit(data.alpha, data.n_modes, data.loss, order=settings.order)
                lost = len(data.missing) + len(data.failures)
                if lost:
                    note = f"{len(data.failures)} failed and {len(data.missing)} missing point(s)"
                    limit = replace(
                        limit,
                        asymptotic_ok=False,
                        message="; ".join(filter(None, [limit.message, note])),
                    )
                limits.append(limit)
            curves[nu] = Curve(nu, settings, np.array(settings.velocities), tuple(limits))
        return curves
    finally:
        if own:
            db.close()


@dataclass(frozen=True, eq=False)
class PointEpsilon(FromLoss):
    """epsilon at one speed, with the grid and fits behind it.

    Attributes
    ----------
    nu, v : float
        Poisson number (two-dimensional for the disk) and speed towards the wall (``c``).
    alpha : float or None
        The fixed wall hardness (``1/R``) when only ``N -> infinity`` was taken; ``None`` when
        both limits were taken.
    energy_loss, energy_loss_err : float
        The extrapolated ``1 - epsilon^2`` and its error; :attr:`epsilon`, :attr:`epsilon_err`
        and :attr:`estimate` derive from them.
    asymptotic_ok : bool
        Whether the extrapolation passed its checks; ``message`` says why not.
    message : str
        Empty when asymptotic.
    fit : CombinedLimit or LinearLimit
        The extrapolation (grid and fits).
    settings : SweepSettings
        Grid and solver settings.
    failures : tuple of (float, int, str)
        ``(alpha, N, message)`` of grid points that failed.
    """

    nu: float
    v: float
    alpha: float | None
    energy_loss: float
    energy_loss_err: float
    asymptotic_ok: bool
    message: str
    fit: CombinedLimit | LinearLimit
    settings: SweepSettings
    failures: tuple = ()

    def to_dict(self) -> dict:
        """JSON-ready dictionary: epsilon, epsilon_err, the grid and the fits."""
        if isinstance(self.fit, CombinedLimit):
            grid_d = {
                "alpha": self.fit.to_dict(fits=False)["alpha"],
                "n_modes": [int(n) for n in self.fit.n_modes],
                "energy_loss": self.fit.to_dict(fits=False)["energy_loss_grid"],
            }
            fits = self.fit.to_dict()["fits"]
        else:
            grid_d = {
                "alpha": [self.alpha],
                "n_modes": [int(n) for n in self.fit.parameter],
                "energy_loss": [self.fit.to_dict()["y"]],
            }
            fits = {"N": self.fit.to_dict()}
        return {
            "geometry": self.settings.geometry,
            "nu": self.nu,
            "v": self.v,
            "v_units": f"c (speed of the {self.settings.geometry} towards the wall)",
            "alpha": self.alpha,
            "limits": ["N"] if self.alpha is not None else ["alpha", "N"],
            "epsilon": finite_or_none(self.epsilon),
            "epsilon_err": finite_or_none(self.epsilon_err),
            "energy_loss": finite_or_none(self.energy_loss),
            "energy_loss_err": finite_or_none(self.energy_loss_err),
            "asymptotic_ok": bool(self.asymptotic_ok),
            "message": self.message,
            "grid": grid_d,
            "fits": fits,
            "failed_points": [
                {"alpha": a, "n_modes": n, "message": m} for a, n, m in self.failures
            ],
            "settings": self.settings.to_dict(),
            "version": __version__,
        }

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return estimate_of(self.epsilon, self.epsilon_err, self.asymptotic_ok, self.message)


def _check_point(nu, v, alpha, settings, run: bool) -> tuple[float, float, float | None]:
    """``(nu, v, alpha)`` of :func:`epsilon_at` as floats, or a one-line :class:`InputError`
    naming the argument: before any store is opened, and with ``run=False`` too (a ``nu`` no
    body has would otherwise read a grid of missing points and answer ``nan``)."""
    _check_settings(settings)
    _check_run(run)
    nu = body_kind(settings.geometry).check_nu(nu)
    v = real(v, "v", "in (0, 1) (units of c)")
    if not 0.0 < v < 1.0:
        raise InputError(
            f"v must lie in (0, 1): the {settings.geometry}'s speed towards the wall in units of "
            f"c, got {v!r}; pass 0 < v < 1"
        )
    if alpha is not None:
        alpha = real(alpha, "alpha", "> 0 (the wall hardness, 1/R)")
        if not alpha > 0.0:
            raise InputError(
                f"the wall hardness alpha must be positive (1/R), got {alpha!r}; pass alpha > 0, "
                "or leave it out to take the limit alpha -> infinity too"
            )
    return nu, v, alpha


def _check_settings(settings) -> None:
    if not isinstance(settings, SweepSettings):
        raise InputError(
            f"settings must be a SweepSettings, got {describe(settings)}; pass e.g. "
            "SweepSettings(n_modes=(300, 400)) or leave it out for the defaults"
        )


def _check_run(run) -> None:
    if not isinstance(run, bool | np.bool_):
        raise InputError(
            f"run must be True or False, got {describe(run)}; pass run=False to read the store only"
        )


def epsilon_at(
    nu: float,
    v: float,
    *,
    alpha: float | None = None,
    geometry: str | None = None,
    settings: SweepSettings = DEFAULTS,
    store: Store | str | os.PathLike | None = None,
    run: bool = True,
    executor: Executor | None = None,
    progress: Progress | bool | None = None,
    batch_function=collide_points,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
) -> PointEpsilon:
    """epsilon at one speed ``v`` (units of ``c``, towards the wall) of the body
    ``settings.geometry`` (the disk by default) with Poisson number ``nu`` (two-dimensional for
    the disk), both limits alpha, N -> infinity taken (the central computation).

    ``geometry`` names the body's kind (its default sweep, :func:`restitution.limits.sweep.
    defaults_for`) when ``settings`` are not given; given both, they must name one kind.

    With ``alpha`` only ``N -> infinity`` is taken at that wall hardness; without it both limits
    on the grid ``settings.alphas_at(v) x settings.n_modes``. Missing collisions are computed first
    (unless ``run=False``); the executor keywords go to :func:`restitution.limits.sweep.run_sweep`.

    Raises
    ------
    InputError
        Before any store is read, if ``nu`` is not a number in the body's range, ``v`` not in
        ``(0, 1)``, ``alpha`` neither ``None`` nor a positive number, ``settings`` not a
        :class:`SweepSettings` or ``run`` not a bool.
    """
    if geometry is not None:
        kind = body_kind(geometry).geometry
        if settings is DEFAULTS:
            settings = defaults_for(kind)
        elif isinstance(settings, SweepSettings) and settings.geometry != kind:
            raise InputError(
                f"geometry={kind!r} and settings of a {settings.geometry}: give one (the "
                f"settings' geometry names the body)"
            )
    nu, v, alpha = _check_point(nu, v, alpha, settings, run)
    settings = replace(settings, velocities=(v,))
    if alpha is not None:
        settings = replace(settings, alphas=(alpha,), alpha_scale="absolute")
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        if run:
            run_sweep(
                grid([nu], settings),
                store=db,
                executor=executor,
                workers=workers,
                scheduler=scheduler,
                client=client,
                batch_size=settings.batch_size,
                batch_function=batch_function,
                progress=progress,
            )
        data = load_grid(db, nu, v, settings)
    finally:
        if own:
            db.close()
    failures = tuple((s.alpha, s.n_modes, m) for s, m in data.failures)
    if alpha is None:
        fit = combined_limit(data.alpha, data.n_modes, data.loss, order=settings.order)
        loss, loss_err, ok, msg = fit.limit, fit.limit_err, fit.asymptotic_ok, fit.message
    else:
        fit = extrapolate_modes(data.n_modes, data.loss[0])
        loss, loss_err, ok, msg = fit.limit, fit.limit_err, fit.asymptotic_ok, fit.message
        if not math.isfinite(epsilon_from_loss(loss, loss_err)[0]):
            ok = False
            msg = "; ".join(filter(None, [msg, f"energy loss {loss:.4g} is outside [0, 1)"]))
    if failures:
        ok = False
        msg = "; ".join(filter(None, [msg, f"{len(failures)} grid point(s) failed"]))
    return PointEpsilon(
        nu,
        v,
        alpha,
        loss,
        loss_err,
        ok,
        msg,
        fit,
        settings,
        failures,
    )
