"""What one integration of one collision returns, whichever path ran it (the driver's contract).

Units: ``E = rho = R = 1``; times in ``R / c``; energies absolute unless said otherwise.

Both paths (:mod:`restitution.dynamics.compiled_path` and :mod:`restitution.dynamics.numpy_path`)
return, per member, a :class:`MemberRun` or :data:`UNSTABLE` (the step must shrink); the driver
(:mod:`restitution.dynamics.collision`) refines steps and builds the public
:class:`~restitution.dynamics.results.CollisionResult` from them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.dynamics.results import History
from restitution.errors import RestitutionError

__all__ = ["UNSTABLE", "CollisionError", "MemberRun", "Unstable", "contact_mean", "timeout_message"]


class CollisionError(RestitutionError):
    """A collision could not be integrated to the requested accuracy."""


class Unstable(Exception):
    """Internal: a run's energy drift exploded; the step must shrink."""


UNSTABLE = "unstable"
"""Marker a path returns for a member whose step must shrink."""


@dataclass(frozen=True, eq=False)
class MemberRun:
    """Raw result of one member's integration with one step.

    Attributes
    ----------
    epsilon : float
        Rebound speed over approach speed.
    energy_after, energy_mean, energy_closest : numpy.ndarray, shape (N,)
        Mode energies after the contact, averaged over the contact, and at the closest approach,
        fractions of ``E0``.
    steps : int
    t_end : float
        Time from the passing of the start position to the stop, ``R / c``.
    final_Q, final_P : numpy.ndarray, shape (N,)
        Modal state at the stop.
    final_x0 : float
        Centre position at the stop, ``R``.
    drift : float
        Largest relative energy drift.
    contact_time, max_compression, max_force : float
    history : History or None
        Recorded time histories (NumPy path with ``record=True`` only).
    dt : float or None
        The step, set by the driver.
    dissipated : float
        Energy the modes' damping took during the run, fraction of ``E0`` (elastic: 0).
    step_error : float or None
        A damped body's estimate of epsilon's error from the step (Richardson, the driver sets
        it); ``None``: the energy drift judged the step.
    """

    epsilon: float
    energy_after: np.ndarray
    steps: int
    t_end: float
    final_Q: np.ndarray
    final_P: np.ndarray
    final_x0: float
    drift: float
    contact_time: float
    max_compression: float
    max_force: float
    energy_mean: np.ndarray
    energy_closest: np.ndarray
    history: History | None = None
    dt: float | None = None
    dissipated: float = 0.0
    step_error: float | None = None


def contact_mean(summed: np.ndarray, contact: float, e0: float) -> np.ndarray:
    """Contact average of the mode energies from their contact-time integral, fractions of
    ``E0`` (the integral itself when the body never touched)."""
    return summed / (contact * e0) if contact > 0 else summed


def timeout_message(t: float, steps: int, dt: float, settings=None) -> str:
    """Why a collision did not end: the step bound ``max_steps`` of ``settings`` (a
    :class:`~restitution.dynamics.settings.CollisionSettings`) was reached, or the time bound.

    The step bound is met when the step is small: ``dt`` given, or refined until the energy
    drift stays below ``energy_tol``. Then the advice is to raise ``energy_tol`` (or ``dt``) or
    ``max_steps``, never to tighten the tolerance further.
    """
    if settings is not None and steps >= settings.max_steps:
        if settings.dt is None:
            cause = (
                f"the step dt = {dt:.3g} that energy_tol = {settings.energy_tol:.3g} asks for "
                f"needs more than max_steps = {settings.max_steps} steps (t = {t:.3g} R/c "
                "reached without separation): raise energy_tol (default 1e-6) or max_steps"
            )
        else:
            cause = (
                f"the fixed step dt = {dt:.3g} needs more than max_steps = "
                f"{settings.max_steps} steps (t = {t:.3g} R/c reached without separation): "
                "raise dt or max_steps"
            )
        return f"the collision did not end: {cause}"
    return (
        f"the disk did not separate from the wall within t = {t:.3g} R/c ({steps} steps of "
        f"dt = {dt:.3g}); this indicates an unstable step or an unphysical input: reduce dt or "
        "energy_tol, or check alpha and v (a vibrating disk may also leave very slowly: raise "
        "max_steps)"
    )
