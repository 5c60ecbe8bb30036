"""Vibrating disks: modal states, excitations and the hand-over from one collision to the next.

A collision of :func:`restitution.dynamics.collision.collide` may start from a modal state ``(Q,
P)`` (``Q`` in ``R``, ``P`` in ``m c``, in the order of the mode set). That state is the
*free-flight* state of the disk at the **reference instant**: the moment its centre passes the
start position :func:`restitution.dynamics.collision.start_position` of the speed ``v`` and wall
``alpha`` of that collision, moving towards the wall (the wall is at ``x = 0``, the undeformed
disk touches it at ``x0 = -1``). Free flight means the disk's own oscillation, without the wall.

Units: ``E = rho = R = 1``, so the mass is ``m = pi``, energies are in ``E R^2 = m c^2 / pi``
(reduced units) unless a name says *fraction*: then they are fractions of the collision's
initial kinetic energy ``E0 = (m/2) v^2``.

Definitions used throughout (``docs/vibrating.md``):

* A mode's energy is ``P^2 / (2m) + (m/2) omega^2 Q^2``.
* **Phase** of a mode at the reference instant: ``Q = A cos(phi)``,
  ``P = -m omega A sin(phi)`` with ``A = sqrt(2 E_k / m) / omega``; free flight advances
  ``phi`` by ``omega t``.
* **Temperature** ``T``: the mean energy per mode of the canonical (thermal) state, reduced
  units. Each mode's energy is exponential with mean ``T`` and its phase uniform; equivalently
  ``Q`` and ``P`` are Gaussian with variances ``T / (m omega^2)`` and ``m T``.
* **Thermal speed** ``v_th``: ``(m/2) v_th^2 = T``, so ``T / E0 = (v_th / v)^2``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.disk.modes import ModeSet
from restitution.dynamics.collision import CollisionSettings, start_position
from restitution.dynamics.integrators import free_modes
from restitution.dynamics.results import CollisionResult
from restitution.errors import InputError

__all__ = [
    "STEP_JUDGE",
    "Handoff",
    "after_flight",
    "kinetic_energy",
    "mirror_state",
    "mode_energies",
    "next_initial_state",
    "phase_of",
    "single_mode_state",
    "thermal_speed",
    "thermal_state",
]


STEP_JUDGE = "epsilon"
"""What judges the time step of every collision of a vibrating disk (``step_judge`` of
:func:`restitution.dynamics.collision.collide_batch`): each run is repeated at half the step and
epsilon's Richardson error is held to ``energy_tol / 2``, as ``restitution collide`` judges a
disk at rest (docs/numerics.md), so that a zero state (zero temperature, zero amplitude) is that
collision (bit for bit for one state; a batch of them may differ in the last bits).
``"energy"`` (the drift alone, 1.1-6.1 times fewer steps) stays available: at ``v = 0.05``,
``alpha = 500``, 60 modes it leaves epsilon 4.8e-6 off (docs/vibrating.md)."""


def kinetic_energy(modes: ModeSet, v) -> np.ndarray | float:
    """Translational kinetic energy ``(m/2) v^2`` (reduced units) of speed ``v`` (``c``)."""
    return 0.5 * modes.mass * np.asarray(v, dtype=float) ** 2


def thermal_speed(modes: ModeSet, temperature: float) -> float:
    """Speed ``v_th`` with ``(m/2) v_th^2 = temperature`` (``c``; temperature reduced units)."""
    return math.sqrt(2.0 * temperature / modes.mass)


def mode_energies(modes: ModeSet, Q, P) -> np.ndarray:
    """Energy of every mode, ``P^2/(2m) + (m/2) omega^2 Q^2``, reduced units; shape of ``Q``."""
    m = modes.mass
    Q = np.asarray(Q, dtype=float)
    P = np.asarray(P, dtype=float)
    return P**2 / (2.0 * m) + 0.5 * m * (modes.omega * Q) ** 2


def phase_of(modes: ModeSet, Q, P) -> np.ndarray:
    """Phase ``phi`` of every mode (inverse of :func:`single_mode_state`), radians in
    ``(-pi, pi]``."""
    m = modes.mass
    return np.arctan2(-np.asarray(P, dtype=float) / (m * modes.omega), np.asarray(Q, float))


def _index(modes: ModeSet, index) -> int:
    if isinstance(index, bool | np.bool_) or not isinstance(index, int | np.integer):
        raise InputError(f"the mode index must be an integer, got {index!r}")
    if not 0 <= index < len(modes):
        raise InputError(
            f"mode index {index} is outside the mode set: give 0 <= index < {len(modes)} "
            "(modes are sorted by frequency)"
        )
    return int(index)


def single_mode_state(
    modes: ModeSet, index: int, energy: float, phase: float
) -> tuple[np.ndarray, np.ndarray]:
    """One mode excited with ``energy`` (reduced units) and ``phase`` (radians); the others
    at rest.

    ``Q = A cos(phase)``, ``P = -m omega A sin(phase)``, ``A = sqrt(2 energy / m) / omega``,
    at the reference instant (module docstring). Returns ``(Q, P)``, each of shape (N,).

    Examples
    --------
    >>> from restitution import get_modes
    >>> ms = get_modes(0.33, count=5)
    >>> Q, P = single_mode_state(ms, 0, 0.2, 0.0)
    >>> round(float(mode_energies(ms, Q, P).sum()), 12)
    0.2
    """
    k = _index(modes, index)
    if not (math.isfinite(energy) and energy >= 0):
        raise InputError(f"the mode energy must be a number >= 0, got {energy}")
    if not math.isfinite(phase):
        raise InputError(f"the phase must be a finite number of radians, got {phase}")
    m = modes.mass
    w = float(modes.omega[k])
    amp = math.sqrt(2.0 * energy / m) / w
    Q = np.zeros(len(modes))
    P = np.zeros(len(modes))
    Q[k] = amp * math.cos(phase)
    P[k] = -m * w * amp * math.sin(phase)
    return Q, P


def thermal_state(
    modes: ModeSet, temperature: float, rng: np.random.Generator | int, size: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Canonical state of the modes at ``temperature`` (mean energy per mode, reduced units).

    ``Q`` and ``P`` are independent Gaussians with variances ``T / (m omega^2)`` and ``m T``:
    each mode's energy is exponential with mean ``T`` and its phase uniform.

    Parameters
    ----------
    rng : numpy.random.Generator or int
        The generator, or a seed for :func:`numpy.random.default_rng`.
    size : int, optional
        Number of independent states; ``None`` gives one state of shape (N,), else (size, N).
    """
    if not (math.isfinite(temperature) and temperature >= 0):
        raise InputError(f"the temperature must be a number >= 0, got {temperature}")
    if size is not None and (not isinstance(size, int | np.integer) or size < 1):
        raise InputError(f"the number of thermal states must be a positive integer, got {size}")
    if not isinstance(rng, np.random.Generator):
        rng = np.random.default_rng(rng)
    m = modes.mass
    shape = (len(modes),) if size is None else (int(size), len(modes))
    Q = rng.standard_normal(shape) * (math.sqrt(temperature / m) / modes.omega)
    P = rng.standard_normal(shape) * math.sqrt(m * temperature)
    return Q, P


def mirror_state(modes: ModeSet, Q, P) -> tuple[np.ndarray, np.ndarray]:
    """The state seen from a wall on the other side (reflection ``x -> -x``).

    The reflection maps ``phi -> pi - phi``; a mode with ``n`` directional nodes
    (``u_r ~ cos n phi``, ``u_phi ~ sin n phi``) goes into ``(-1)^n`` times itself.
    """
    sign = np.where(modes.n % 2 == 0, 1.0, -1.0)
    return np.asarray(Q, dtype=float) * sign, np.asarray(P, dtype=float) * sign


def after_flight(
    result: CollisionResult, modes: ModeSet, duration: float, *, reverse: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """The modal state ``duration`` (``R / c``) after ``result``'s run stopped.

    The run stops where the disk provably cannot touch the wall again (``result.final_x0``),
    so from there the modes oscillate freely. With ``reverse`` every modal momentum is reversed
    first (time reversal). ``duration`` may be negative: the free-flight state earlier.
    """
    _check_result(result, modes)
    if not math.isfinite(duration):
        raise InputError(f"the flight duration must be a finite time in R/c, got {duration}")
    P = -result.final_P if reverse else result.final_P
    return free_modes(modes.omega, modes.mass, result.final_Q, P, duration)


def _check_result(result: CollisionResult, modes: ModeSet) -> None:
    if result.method != "modal" or result.final_Q.size != len(modes):
        raise InputError(
            "the earlier collision must be a modal run on the same mode set "
            f"({len(modes)} modes), got {result.method} with {result.final_Q.size} modes"
        )


@dataclass(frozen=True, eq=False)
class Handoff:
    """The initial condition of the next collision of a chain.

    Attributes
    ----------
    v : float
        Speed towards the next wall at its start position, ``c``.
    Q, P : numpy.ndarray, shape (N,)
        Modal state at the next reference instant (``initial=(Q, P)`` of ``collide``), in the
        next wall's frame (mirrored for the opposite wall).
    flight_time : float
        Time from the stop of the earlier run to the next reference instant, ``R / c``.
    x_from, x_to : float
        Centre position at the stop of the earlier run and at the next start position, each
        in the frame of its own wall (``R``).
    """

    v: float
    Q: np.ndarray
    P: np.ndarray
    flight_time: float
    x_from: float
    x_to: float


FASTEST_RETURN = 0.3
"""Fastest impact speed (``c``) a flight under gravity may bring (the model's linear elasticity
is stretched beyond it, as ``collide`` warns)."""


def _too_fast(modes, u, x_from, alpha, g, w, settings) -> str:
    """The refusal of a gravity that brings the disk back faster than :data:`FASTEST_RETURN`:
    the speed it would reach and the largest gravity that keeps the next impact below it."""
    fall = start_position(modes, FASTEST_RETURN, alpha, settings) - x_from
    most = (FASTEST_RETURN**2 - u * u) / (2.0 * fall) if fall > 0 else math.nan
    fits = (
        f"; gravity <= {most:.2g} c^2/R keeps this return below it" if math.isfinite(most) else ""
    )
    return (
        f"gravity = {g:g} c^2/R brings the disk, which left the wall at {u:.3g} c, back at "
        f"{w:.3g} c, above the {FASTEST_RETURN} c up to which the model holds{fits}: lower "
        "--gravity"
    )


def _solve_gravity_speed(modes, u, x_from, alpha, g, settings) -> float:
    """Speed ``w`` at the next start position under gravity: ``w^2 = u^2 + 2 g (x(w) - x_from)``.

    The start position depends on ``w`` only through ``ln w``, so the fixed point converges in
    a few steps (contraction factor ``~ g / (alpha w^2)``).
    """
    w = u
    for _ in range(60):
        x_to = start_position(modes, w, alpha, settings)
        w_new = math.sqrt(u * u + 2.0 * g * (x_to - x_from))
        if w_new >= FASTEST_RETURN:
            raise InputError(_too_fast(modes, u, x_from, alpha, g, w_new, settings))
        if abs(w_new - w) <= 1e-15 * w:
            return w_new
        w = w_new
    raise InputError(  # pragma: no cover - only for absurd gravity
        f"the return speed under gravity g = {g} did not converge; lower the gravity"
    )


def next_initial_state(
    result: CollisionResult,
    modes: ModeSet,
    *,
    reverse: bool = False,
    gravity: float | None = None,
    walls_distance: float | None = None,
    settings: CollisionSettings | None = None,
) -> Handoff:
    """Carry the final state of ``result`` to the reference instant of the next collision.

    The run stopped at ``result.final_x0`` moving away from the wall at ``u = epsilon v``; the
    next collision's state is the free-flight state when the centre passes *its* start
    position ``start_position(modes, v_next, alpha)`` (same wall hardness). In between the
    modes oscillate freely (:func:`~restitution.dynamics.integrators.free_modes`) for the flight
    time, computed exactly for one of three flights (give exactly one):

    ``reverse=True``
        Time reversal: every momentum (translation and modes) is reversed at the stop; the
        disk flies back to the same wall at ``v_next = u``, flight time
        ``(start_position(u) - final_x0) / u`` (may be negative: the free-flight state is
        then the one extrapolated backwards, which is what the reference instant means).
    ``gravity=g``
        A constant acceleration ``g`` (``c^2 / R``) towards the wall (a disk bouncing on the
        floor). ``v_next`` solves ``v_next^2 = u^2 + 2 g (start_position(v_next) - final_x0)``
        and the flight lasts ``(u + v_next) / g``. Gravity during the collision run itself is
        neglected (the caller should check ``g * t_end << v``).
    ``walls_distance=L``
        A second, identical wall facing the first at distance ``L`` (``R``, between the wall
        surfaces, so a disk fits if ``L > 2``). The disk flies at ``u`` to the other wall;
        flight time ``(L + final_x0 + start_position(u)) / u``; the state is mirrored
        (:func:`mirror_state`) into the other wall's frame.
    """
    _check_result(result, modes)
    chosen = [reverse, gravity is not None, walls_distance is not None]
    if sum(bool(c) for c in chosen) != 1:
        raise InputError("choose exactly one flight: reverse=True, gravity=g or walls_distance=L")
    alpha = result.alpha
    u = result.epsilon * result.v
    x_from = result.final_x0
    if not (math.isfinite(u) and u > 0 and math.isfinite(x_from)):
        raise InputError(
            f"the earlier collision has no usable final state (epsilon {result.epsilon}, "
            f"final_x0 {x_from})"
        )
    if reverse:
        x_to = start_position(modes, u, alpha, settings)
        t = (x_to - x_from) / u
        Q, P = after_flight(result, modes, t, reverse=True)
        return Handoff(v=u, Q=Q, P=P, flight_time=t, x_from=x_from, x_to=x_to)
    if gravity is not None:
        if not (math.isfinite(gravity) and gravity > 0):
            raise InputError(f"gravity must be a positive acceleration in c^2/R, got {gravity}")
        w = _solve_gravity_speed(modes, u, x_from, alpha, gravity, settings)
        x_to = start_position(modes, w, alpha, settings)
        t = (u + w) / gravity
        Q, P = after_flight(result, modes, t)
        return Handoff(v=w, Q=Q, P=P, flight_time=t, x_from=x_from, x_to=x_to)
    L = walls_distance
    if not (math.isfinite(L) and L > 2):
        raise InputError(
            f"the walls' distance must exceed the disk's diameter 2 R, got {walls_distance}"
        )
    x_to = start_position(modes, u, alpha, settings)
    distance = L + x_from + x_to
    if distance <= 0:
        raise InputError(
            f"walls {L} R apart are too close for this collision: the disk reaches the other "
            f"wall's start position before leaving this one's reach ({distance:.3g} R); "
            "increase the distance"
        )
    t = distance / u
    Q, P = mirror_state(modes, *after_flight(result, modes, t))
    return Handoff(v=u, Q=Q, P=P, flight_time=t, x_from=x_from, x_to=x_to)
