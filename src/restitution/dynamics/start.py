"""Where a collision begins: the start position, a vibrating body's earlier start, time bounds.

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``, ``Q`` in ``R``, ``P`` in ``m c``.

A body at rest starts undeformed with its centre where its wall energy is ``CONTACT_TOL * E0``
(:meth:`~restitution.dynamics.contact.base.ContactLaw.start_position` of the contact law).
A vibrating body's ``initial = (Q, P)`` is its *free-flight* state at the moment the centre
passes that position; the integration begins earlier by the vibration's reach (the bound on the
surface displacement that the stop test uses), with the state carried back by the exact free
oscillation (:func:`~restitution.dynamics.integrators.free_modes`), so that no surface point is
closer to the wall than the undeformed tip at the start position.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.bodies.base import ModalBody
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.integrators import free_modes
from restitution.errors import InputError

__all__ = ["Start", "check_initial", "energy_before", "start_of", "time_bound"]


@dataclass(frozen=True)
class Start:
    """Where and in which state the integration of each member begins (private).

    ``x0``: centre position (``R``); ``Q``, ``P``: modal state there, shape (B, N), or ``None``
    for disks at rest; ``lead``: time (``R / c``) from there to the start position proper;
    ``t_max``: bound of the simulated time (``R / c``, :func:`time_bound`).
    """

    x0: np.ndarray
    Q: np.ndarray | None
    P: np.ndarray | None
    lead: np.ndarray
    t_max: np.ndarray


def start_of(
    body: ModalBody,
    v: np.ndarray,
    alpha: np.ndarray,
    quad,
    initial,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> Start:
    """Start of each member: the standard position, or earlier when a vibrating edge reaches.

    ``initial`` is ``None`` or ``(Q, P)`` of shape (B, N): the free-flight state at the moment
    the centre passes the standard start position (module docstring) of ``contact_law``.
    """
    m = body.mass
    x_start = contact_law.start_position(alpha, 0.5 * m * v**2, quad)
    if initial is None:
        return Start(x_start, None, None, np.zeros(v.size), time_bound(body, v, x_start))
    Q, P = initial
    energy = P**2 / (2.0 * m) + 0.5 * m * (body.omega * Q) ** 2
    reach = np.sqrt(2.0 * energy / m) / body.omega @ quad.g_max
    # Every edge point then lies at most as close to the wall as the undeformed disk's edge at
    # the standard start, so the wall energy is at most CONTACT_TOL * E0 there, as for a disk
    # at rest (and a zero state starts exactly where a disk at rest does).
    x_begin = x_start - reach
    lead = reach / v
    Qb, Pb = free_modes(body.omega, m, Q, P, -lead[:, None])
    # A vibrating disk may leave far slower than it came (measured: epsilon = 0.054 in a
    # thermal ensemble), so its time bound is 100 times a disk at rest's; max_steps still holds.
    t_max = np.where(reach > 0, 100.0, 1.0) * time_bound(body, v, x_begin)
    return Start(x_begin, Qb, Pb, lead, t_max)


def check_initial(initial, body: ModalBody, size: int):
    """Validate ``initial = (Q, P)``; returns arrays of shape (B, N) or ``None``."""
    if initial is None:
        return None
    N = len(body)
    try:
        Q, P = initial
        Q = np.asarray(Q, dtype=float)
        P = np.asarray(P, dtype=float)
    except (TypeError, ValueError):
        raise InputError(
            "initial must be a pair (Q, P) of modal coordinates and momenta, each of "
            f"length {N} (one per mode) or shape (B, {N}) for a batch"
        ) from None
    out = []
    for name, arr in (("Q", Q), ("P", P)):
        if (
            arr.ndim not in (1, 2)
            or arr.shape[-1] != N
            or (arr.ndim == 2 and arr.shape[0] not in (1, size))
        ):
            raise InputError(
                f"initial {name} has shape {arr.shape}; give ({N},) for every collision or "
                f"({size}, {N}), one row per collision"
            )  # fmt: skip
        if not np.all(np.isfinite(arr)):
            raise InputError(f"initial {name} contains non-finite values")
        out.append(np.broadcast_to(np.atleast_2d(arr), (size, N)).copy())
    return tuple(out)


def time_bound(body: ModalBody, v: np.ndarray, x_start: np.ndarray) -> np.ndarray:
    """Bound of the simulated time of each member, ``R / c``."""
    return (-1.0 - x_start) / v + 20.0 * body.contact_time_estimate(v) + 50.0


def energy_before(body: ModalBody, initial, i: int, v: float) -> np.ndarray:
    """Energy per mode at the start, fraction of ``E0`` (zeros for a disk at rest)."""
    if initial is None:
        return np.zeros(len(body))
    m = body.mass
    Q, P = initial[0][i], initial[1][i]
    return (P**2 / (2.0 * m) + 0.5 * m * (body.omega * Q) ** 2) / (0.5 * m * v**2)
