"""Epsilon as a random variable: collisions of disks with thermally excited modes, and the
phase dependence of epsilon on one excited mode.

Every collision of an ensemble starts from its own canonical modal state
(:func:`restitution.vibrating.vibration.thermal_state`) at the reference instant and at the same
speed ``v``; the ensemble's epsilon is then a random variable. Energies are reported as fractions of
the initial kinetic energy ``E0 = (m/2) v^2``, per sample summed over the modes; the temperature is
given both in reduced units (``E R^2``) and as a fraction of ``E0``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from restitution.bodies.disk.modes import ModeSet
from restitution.budget import check_memory
from restitution.dynamics.collision import CollisionError, CollisionSettings, collide_batch
from restitution.errors import InputError
from restitution.vibrating.sequences import check_collisions_time
from restitution.vibrating.vibration import (
    STEP_JUDGE,
    kinetic_energy,
    single_mode_state,
    thermal_state,
)

__all__ = [
    "Ensemble",
    "check_ensemble_memory",
    "collide_states",
    "ensemble_bytes_per_sample",
    "SinusoidFit",
    "fit_sinusoid",
    "phase_scan",
    "temperature_for",
    "thermal_ensemble",
]


@dataclass(frozen=True, eq=False)
class Ensemble:
    """Collisions at one speed from independent thermal states of the modes.

    Attributes
    ----------
    v, alpha : float
        Speed towards the wall (``c``) and wall hardness (``1/R``).
    temperature : float
        Mean energy per mode, reduced units (``E R^2``).
    n_modes : int
        Modes of the mode set (the ``n_modes`` lowest frequencies).
    seed : int or None
        Seed of the thermal states.
    epsilon : numpy.ndarray, shape (S,)
        ``-v_final / v`` of each sample.
    mode_energy_before, mode_energy_after : numpy.ndarray, shape (S,)
        Vibrational energy (sum over modes) at the reference instant and after the collision,
        fractions of ``E0``.
    energy_drift, contact_time : numpy.ndarray, shape (S,)
        Relative energy drift of each run and its contact time (``R / c``).
    failures : tuple of str
        Messages of the samples that could not be integrated (left out of every array and
        statistic; :func:`collide_states`).
    """

    v: float
    alpha: float
    temperature: float
    n_modes: int
    seed: int | None
    epsilon: np.ndarray
    mode_energy_before: np.ndarray
    mode_energy_after: np.ndarray
    energy_drift: np.ndarray
    contact_time: np.ndarray
    failures: tuple[str, ...] = ()

    @property
    def kinetic_energy_before(self) -> np.ndarray:
        """Translational energy before, fraction of ``E0`` (1 by definition)."""
        return np.ones_like(self.epsilon)

    @property
    def kinetic_energy_after(self) -> np.ndarray:
        """Translational energy after, fraction of ``E0``: ``epsilon^2``."""
        return self.epsilon**2

    @property
    def temperature_fraction(self) -> float:
        """Temperature in units of ``E0 = (m/2) v^2``: ``(v_th / v)^2``."""
        return self.temperature / (0.5 * math.pi * self.v**2)  # m = pi

    @property
    def v_over_v_thermal(self) -> float:
        """``v / v_th`` with ``(m/2) v_th^2 = T``."""
        return 1.0 / math.sqrt(self.temperature_fraction) if self.temperature > 0 else math.inf

    @property
    def balance_error(self) -> np.ndarray:
        """``|E_after - E_before| / E_before`` of each sample (translation plus modes)."""
        before = 1.0 + self.mode_energy_before
        return np.abs(self.epsilon**2 + self.mode_energy_after - before) / before

    def summary(self) -> dict:
        """Mean, spread (standard deviation), extremes and the fraction above 1 of epsilon."""
        eps = self.epsilon
        if eps.size == 0:
            return {"samples": 0, "mean": None, "spread": None, "mean_error": None,
                    "min": None, "max": None, "fraction_above_1": None,
                    "failed": len(self.failures)}  # fmt: skip
        return {
            "samples": int(eps.size),
            "mean": float(eps.mean()),
            "spread": float(eps.std(ddof=1)) if eps.size > 1 else 0.0,
            "mean_error": float(eps.std(ddof=1) / math.sqrt(eps.size)) if eps.size > 1 else None,
            "min": float(eps.min()),
            "max": float(eps.max()),
            "fraction_above_1": float(np.mean(eps > 1.0)),
            "failed": len(self.failures),
        }

    def to_dict(self) -> dict:
        """JSON-ready: the summary of epsilon, the temperature in both units, and per sample
        ``epsilon``, ``mode_energy_before``, ``mode_energy_after`` (sums over the modes),
        ``kinetic_energy_before``, ``kinetic_energy_after`` (fractions of ``E0``)."""
        return {
            "v": self.v,
            "alpha": self.alpha,
            "n_modes": self.n_modes,
            "seed": self.seed,
            "temperature": {
                "per_mode_reduced": self.temperature,
                "per_mode_fraction_of_E0": self.temperature_fraction,
                "v_over_v_thermal": self.v_over_v_thermal,
            },
            **self.summary(),
            "max_energy_drift": float(self.energy_drift.max()) if self.epsilon.size else None,
            "failures": list(self.failures),
            "per_sample": [
                {
                    "epsilon": float(e),
                    "mode_energy_before": float(b),
                    "mode_energy_after": float(a),
                    "kinetic_energy_before": 1.0,
                    "kinetic_energy_after": float(e * e),
                    "energy_drift": float(d),
                    "contact_time": float(c),
                }
                for e, b, a, d, c in zip(
                    self.epsilon,
                    self.mode_energy_before,
                    self.mode_energy_after,
                    self.energy_drift,
                    self.contact_time,
                    strict=True,
                )
            ],
        }


def collide_states(
    modes: ModeSet,
    v,
    alpha,
    Q,
    P,
    settings: CollisionSettings | None = None,
    *,
    step_judge: str = STEP_JUDGE,
    **overrides,
) -> list:
    """Collide a batch from the states ``(Q[i], P[i])``; a member that fails gives its error
    message (a string) in place of its result, and never loses the others.

    The step is judged by ``step_judge`` (default :data:`~restitution.vibrating.vibration.
    STEP_JUDGE`, epsilon's Richardson error, as ``restitution collide`` judges a disk at rest),
    so a zero state is the collision of the disk at rest.

    A vibrating disk can leave the wall very slowly (``v' << v``); the solver allows it 100
    times the time bound of a disk at rest (:func:`restitution.dynamics.start.start_of`), and a
    member that still does not separate within that bound or ``max_steps`` comes back as its
    message.
    """
    v = np.broadcast_to(np.asarray(v, dtype=float), (len(Q),))
    try:
        return collide_batch(modes, v, alpha, settings, initial=(Q, P), step_judge=step_judge,
                             **overrides)  # fmt: skip
    except CollisionError:
        pass
    out: list = []
    for i in range(len(Q)):
        try:
            one = collide_batch(modes, v[i : i + 1], alpha, settings,
                                initial=(Q[i : i + 1], P[i : i + 1]), step_judge=step_judge,
                                **overrides)  # fmt: skip
            out.append(one[0])
        except CollisionError as exc:
            out.append(str(exc))
    return out


# Bytes per sample besides the states, measured with tracemalloc: the memory held during the
# loop of thermal_ensemble grew by 262-330 B per sample (N = 5, 40, 400; samples 64 to 256):
# the five lists of Python floats and the arrays made of them (203 B alone) and what the
# collision path keeps per collision. The JSON document of the command line (Ensemble.to_dict,
# then the CLI's dumps) peaked at 2821 B per sample (2e4 samples); the arrays of the Ensemble,
# 40 B, are alive then, the states no longer are.
_RECORD_BYTES = 350.0
_JSON_BYTES = 2900.0


def ensemble_bytes_per_sample(n_modes: int, *, json: bool = False) -> float:
    """Peak memory of :func:`thermal_ensemble` per sample, bytes.

    Drawing the states holds ``Q``, ``P`` and one temporary array of the same shape (three
    times ``N`` doubles); the collisions then run with ``Q``, ``P`` and the per-sample results.
    With ``json``, the JSON document of the command line (after the states are gone) counts
    too.
    """
    states = 8.0 * n_modes
    per = max(3 * states, 2 * states + _RECORD_BYTES)
    return max(per, 40.0 + _JSON_BYTES) if json else per


def check_ensemble_memory(
    samples: int, n_modes: int, *, json: bool = False, name: str = "samples"
) -> float:
    """Refuse an ensemble whose thermal states (and results) would not fit in this machine's
    memory budget (:func:`restitution.budget.check_memory`); returns the bytes needed.

    Parameters
    ----------
    samples : int
        Collisions of the ensemble.
    n_modes : int
        Modes of the mode set.
    json : bool
        Count the JSON document the command line prints too.
    name : str
        The input as the caller knows it (``"--samples"`` on the command line).

    Raises
    ------
    InputError
        One line with the bytes needed and available and the most samples that fit.
    """
    for label, value in (("samples", samples), ("n_modes", n_modes)):
        if not isinstance(value, int | np.integer) or isinstance(value, bool) or value < 1:
            raise InputError(f"{label} must be a positive integer, got {value!r}")
    per = ensemble_bytes_per_sample(n_modes, json=json)
    what = f"the thermal states of {n_modes} modes" + (" and the JSON output" if json else "")
    return check_memory(name, int(samples), per, "sample", what)


def thermal_ensemble(
    modes: ModeSet,
    v: float,
    alpha: float,
    temperature: float,
    samples: int,
    seed: int | None = 0,
    settings: CollisionSettings | None = None,
    *,
    batch_size: int = 64,
    progress: Callable[[int], None] | None = None,
    force: bool = False,
    step_judge: str = STEP_JUDGE,
    **overrides,
) -> Ensemble:
    """``samples`` collisions at speed ``v``, each from its own thermal state at ``temperature``
    (mean energy per mode, reduced units), drawn with ``numpy.random.default_rng(seed)``.

    The states are drawn all at once, so a sample does not depend on ``batch_size``;
    ``progress`` is called with the number of collisions finished after every batch. An
    ensemble whose states would not fit in memory is refused before anything is drawn
    (:func:`check_ensemble_memory`), one that would take longer than
    :data:`restitution.budget.TIME_BOUND_S` too unless ``force``
    (:func:`restitution.vibrating.sequences.check_collisions_time`). Every collision's step
    is judged by ``step_judge`` (:func:`collide_states`): at zero temperature every sample is
    the collision of the disk at rest.
    """
    if not isinstance(samples, int | np.integer) or isinstance(samples, bool) or samples < 1:
        raise InputError(f"samples must be a positive integer, got {samples!r}")
    if not isinstance(batch_size, int) or batch_size < 1:
        raise InputError(f"batch_size must be a positive integer, got {batch_size!r}")
    if seed is not None and (
        not isinstance(seed, int | np.integer) or isinstance(seed, bool) or seed < 0
    ):
        raise InputError(f"the seed must be an integer >= 0 (or None), got {seed!r}")
    check_ensemble_memory(samples, len(modes))
    check_collisions_time(modes, v, alpha, int(samples), settings, force=force, name="samples",
                          item="sample", step_judge=step_judge, **overrides)  # fmt: skip
    Q, P = thermal_state(modes, temperature, np.random.default_rng(seed), size=int(samples))
    out = {k: [] for k in ("eps", "before", "after", "drift", "contact")}
    failures: list[str] = []
    for start in range(0, samples, batch_size):
        stop = min(start + batch_size, samples)
        res = collide_states(modes, v, alpha, Q[start:stop], P[start:stop], settings,
                             step_judge=step_judge, **overrides)  # fmt: skip
        for r in res:
            if isinstance(r, str):
                failures.append(r)
                continue
            out["eps"].append(r.epsilon)
            out["before"].append(float(r.mode_energy_before.sum()))
            out["after"].append(float(r.mode_energy_after.sum()))
            out["drift"].append(r.energy_drift)
            out["contact"].append(r.contact_time)
        if progress is not None:
            progress(stop)
    return Ensemble(
        v=float(v),
        alpha=float(alpha),
        temperature=float(temperature),
        n_modes=len(modes),
        seed=seed,
        epsilon=np.array(out["eps"]),
        mode_energy_before=np.array(out["before"]),
        mode_energy_after=np.array(out["after"]),
        energy_drift=np.array(out["drift"]),
        contact_time=np.array(out["contact"]),
        failures=tuple(failures),
    )


def phase_scan(
    modes: ModeSet,
    v: float,
    alpha: float,
    index: int,
    energy: float,
    phases,
    settings: CollisionSettings | None = None,
    *,
    step_judge: str = STEP_JUDGE,
    **overrides,
) -> np.ndarray:
    """Epsilon of collisions at speed ``v`` with mode ``index`` excited to ``energy`` (reduced
    units) at each of ``phases`` (radians, at the reference instant); shape of ``phases``. The
    step is judged by ``step_judge`` (:func:`collide_states`)."""
    phases = np.atleast_1d(np.asarray(phases, dtype=float))
    states = [single_mode_state(modes, index, energy, float(p)) for p in phases]
    Q = np.array([q for q, _ in states])
    P = np.array([p for _, p in states])
    res = collide_batch(modes, np.full(phases.size, v), alpha, settings, initial=(Q, P),
                        step_judge=step_judge, **overrides)  # fmt: skip
    return np.array([r.epsilon for r in res])


@dataclass(frozen=True)
class SinusoidFit:
    """Least-squares fit ``epsilon(phi) = mean + amplitude cos(phi - phase)``.

    ``residual`` is the root mean square of the data minus the fit: zero to first order in the
    mode's amplitude, so it measures the second-order (and higher) terms.
    """

    mean: float
    amplitude: float
    phase: float
    residual: float


def fit_sinusoid(phases, values) -> SinusoidFit:
    """Fit ``values = mean + a cos(phases - phase0)`` by linear least squares (``a >= 0``)."""
    phi = np.asarray(phases, dtype=float)
    y = np.asarray(values, dtype=float)
    if phi.shape != y.shape or phi.size < 4:
        raise InputError("fit_sinusoid needs equally many phases and values, at least 4")
    design = np.column_stack([np.ones_like(phi), np.cos(phi), np.sin(phi)])
    coef, *_ = np.linalg.lstsq(design, y, rcond=None)
    resid = y - design @ coef
    return SinusoidFit(
        mean=float(coef[0]),
        amplitude=float(math.hypot(coef[1], coef[2])),
        phase=float(math.atan2(coef[2], coef[1])),
        residual=float(np.sqrt(np.mean(resid**2))),
    )


def temperature_for(modes: ModeSet, v: float, v_over_v_thermal: float) -> float:
    """Temperature (reduced units) at which ``v / v_th`` takes the given value:
    ``T = (m/2) v^2 / (v / v_th)^2``."""
    if not (math.isfinite(v_over_v_thermal) and v_over_v_thermal > 0):
        raise InputError(f"v / v_thermal must be positive, got {v_over_v_thermal}")
    return float(kinetic_energy(modes, v)) / v_over_v_thermal**2
