"""Sequences of collisions of one disk whose vibrations carry over from one impact to the next.

Two geometries (:func:`restitution.vibrating.vibration.next_initial_state` does the hand-over):

* ``gravity=g``: the disk bounces on the wall (the floor) under a constant acceleration ``g``
  towards it (paper, section 5's picture). Gravity acts during the flights only; during each
  collision run (a few ``R / c`` against flights of ``2 v / g``) it is neglected, and every
  collision reports the neglected momentum ``g t_end`` relative to its speed and the neglected
  work ``m g (x_start - final_x0)``.
* ``walls_distance=L``: the disk flies back and forth between two identical walls.

The wall hardness ``alpha`` is a property of the wall: it is the same for every collision of a
sequence (unlike the sweeps, which scale it with the compression of each speed).

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``, energies in reduced units
``E R^2`` (``m = pi``), ``g`` in ``c^2 / R``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from restitution.bodies.disk.modes import ModeSet
from restitution.dynamics.collision import CollisionSettings, collide, start_position
from restitution.dynamics.results import CollisionResult
from restitution.errors import InputError
from restitution.vibrating.vibration import next_initial_state

__all__ = [
    "Sequence",
    "bounce",
    "constant_epsilon_speeds",
    "memoryless_speeds",
]


@dataclass(frozen=True, eq=False)
class Sequence:
    """A chain of collisions, one entry per collision ``k = 0 .. K-1``.

    Attributes
    ----------
    gravity, walls_distance : float or None
        The geometry (one of them is set).
    alpha : float
        Wall hardness, ``1/R``.
    n_modes : int
        Modes of the mode set.
    v : numpy.ndarray, shape (K,)
        Impact speed (at the start position), ``c``.
    epsilon : numpy.ndarray, shape (K,)
        ``-v_final / v`` of each collision.
    vibration_before, vibration_after : numpy.ndarray, shape (K,)
        Vibrational energy (sum over the modes) before and after each collision, reduced units.
    contact_time, energy_drift : numpy.ndarray, shape (K,)
        Contact time (``R / c``) and relative energy drift of each collision run.
    time : numpy.ndarray, shape (K,)
        Time of each reference instant since the first one, ``R / c``.
    flight_time : numpy.ndarray, shape (K,)
        From the stop of collision ``k`` to the reference instant of ``k + 1`` (``nan`` after the
        last), ``R / c``.
    x_start, x_end : numpy.ndarray, shape (K,)
        Centre position at each reference instant and where each run stopped, ``R``.
    t_end : numpy.ndarray, shape (K,)
        Duration of each collision run from the reference instant, ``R / c``.
    """

    gravity: float | None
    walls_distance: float | None
    alpha: float
    n_modes: int
    v: np.ndarray
    epsilon: np.ndarray
    vibration_before: np.ndarray
    vibration_after: np.ndarray
    contact_time: np.ndarray
    energy_drift: np.ndarray
    time: np.ndarray
    flight_time: np.ndarray
    x_start: np.ndarray
    x_end: np.ndarray
    t_end: np.ndarray

    @property
    def translation_before(self) -> np.ndarray:
        """``(m/2) v_k^2``, reduced units."""
        return 0.5 * math.pi * self.v**2

    @property
    def translation_after(self) -> np.ndarray:
        """``(m/2) (epsilon_k v_k)^2``, reduced units."""
        return 0.5 * math.pi * (self.epsilon * self.v) ** 2

    @property
    def potential_before(self) -> np.ndarray:
        """Gravitational energy ``-m g x0`` at each reference instant (0 without gravity)."""
        g = self.gravity or 0.0
        return -math.pi * g * self.x_start

    @property
    def total_before(self) -> np.ndarray:
        """Translation + vibration + gravity at each reference instant, reduced units."""
        return self.translation_before + self.vibration_before + self.potential_before

    @property
    def neglected_work(self) -> np.ndarray:
        """Work of gravity during each collision run, neglected: ``m g (x_start - x_end)``."""
        g = self.gravity or 0.0
        return math.pi * g * (self.x_start - self.x_end)

    @property
    def neglected_impulse(self) -> np.ndarray:
        """Velocity gravity would have added during each run, relative to the impact speed:
        ``g t_end / v`` (small when neglecting gravity in the contact is fine)."""
        g = self.gravity or 0.0
        return g * self.t_end / self.v

    def to_dict(self) -> dict:
        """JSON-ready: geometry and one record per collision."""
        keys = ("v", "epsilon", "vibration_before", "vibration_after", "contact_time",
                "energy_drift", "time", "flight_time", "x_start", "x_end")  # fmt: skip
        rows = [
            {k: float(getattr(self, k)[i]) for k in keys}
            | {
                "total_energy_before": float(self.total_before[i]),
                "neglected_impulse": float(self.neglected_impulse[i]),
            }
            for i in range(self.v.size)
        ]
        return {
            "gravity": self.gravity,
            "walls_distance": self.walls_distance,
            "alpha": self.alpha,
            "n_modes": self.n_modes,
            "collisions": rows,
        }


def bounce(
    modes: ModeSet,
    v: float,
    alpha: float,
    collisions: int,
    *,
    gravity: float | None = None,
    walls_distance: float | None = None,
    initial=None,
    settings: CollisionSettings | None = None,
    progress: Callable[[int], None] | None = None,
    **overrides,
) -> Sequence:
    """``collisions`` successive collisions of one disk, its vibrations carried over.

    Parameters
    ----------
    v : float
        First impact speed, ``c``.
    alpha : float
        Wall hardness (the same wall throughout), ``1/R``.
    gravity, walls_distance : float
        Exactly one: acceleration towards the wall (``c^2/R``) or distance between two walls
        (``R``); see :func:`restitution.vibrating.vibration.next_initial_state`.
    initial : (Q, P), optional
        Modal state at the first reference instant; omitted: the disk at rest.
    progress : callable, optional
        Called with the number of collisions done after each.
    """
    if not isinstance(collisions, int | np.integer) or collisions < 1:
        raise InputError(f"the number of collisions must be a positive integer, got {collisions}")
    if (gravity is None) == (walls_distance is None):
        raise InputError("give exactly one of gravity (c^2/R) and walls_distance (R)")
    rows: list[tuple[CollisionResult, float, float]] = []
    flights: list[float] = []
    clock = 0.0
    speed, state = v, initial
    for k in range(collisions):
        x0 = start_position(modes, speed, alpha, settings)
        r = collide(modes, speed, alpha, settings, initial=state, **overrides)
        rows.append((r, x0, clock))
        if progress is not None:
            progress(k + 1)
        if k == collisions - 1:
            break
        h = next_initial_state(r, modes, gravity=gravity, walls_distance=walls_distance,
                               settings=settings)  # fmt: skip
        flights.append(h.flight_time)
        clock += r.t_end + h.flight_time
        speed, state = h.v, (h.Q, h.P)
    e_unit = [0.5 * math.pi * r.v**2 for r, _, _ in rows]
    return Sequence(
        gravity=gravity,
        walls_distance=walls_distance,
        alpha=float(alpha),
        n_modes=len(modes),
        v=np.array([r.v for r, _, _ in rows]),
        epsilon=np.array([r.epsilon for r, _, _ in rows]),
        vibration_before=np.array(
            [r.mode_energy_before.sum() * e for (r, _, _), e in zip(rows, e_unit, strict=True)]
        ),  # fmt: skip
        vibration_after=np.array(
            [r.mode_energy_after.sum() * e for (r, _, _), e in zip(rows, e_unit, strict=True)]
        ),  # fmt: skip
        contact_time=np.array([r.contact_time for r, _, _ in rows]),
        energy_drift=np.array([r.energy_drift for r, _, _ in rows]),
        time=np.array([c for _, _, c in rows]),
        flight_time=np.array([*flights, math.nan]),
        x_start=np.array([x for _, x, _ in rows]),
        x_end=np.array([r.final_x0 for r, _, _ in rows]),
        t_end=np.array([r.t_end for r, _, _ in rows]),
    )


def constant_epsilon_speeds(v: float, epsilon: float, collisions: int) -> np.ndarray:
    """Impact speeds ``v epsilon^k`` of a disk with a constant coefficient of restitution
    (the flight returns the departure speed), shape (collisions,)."""
    return v * epsilon ** np.arange(collisions)


def memoryless_speeds(
    modes: ModeSet,
    v: float,
    alpha: float,
    collisions: int,
    settings: CollisionSettings | None = None,
    **overrides,
) -> np.ndarray:
    """Impact speeds of a disk that is at rest at every impact (its vibrations forgotten
    between collisions): ``v_{k+1} = epsilon_rest(v_k) v_k`` with the same modes and wall."""
    speeds = [v]
    for _ in range(collisions - 1):
        speeds.append(collide(modes, speeds[-1], alpha, settings, **overrides).epsilon * speeds[-1])
    return np.array(speeds)
