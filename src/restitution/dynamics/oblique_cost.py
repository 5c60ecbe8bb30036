"""The oblique route's cost and reach: the work of one oblique impact
(:func:`restitution.dynamics.oblique.oblique_collision`) before it starts, and the regime where
its results are suspect.

Units: seconds and bytes; speeds in ``c``, ``alpha`` in ``1 / R``, mode counts as named.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.dynamics.contact.exponential import NEGLIGIBLE
from restitution.errors import InputError
from restitution.status import Status

__all__ = [
    "SUSPECT",
    "SUSPECT_ALPHA",
    "SUSPECT_MODES",
    "SUSPECT_MU",
    "SLOWEST_APPROACH",
    "ObliqueWork",
    "check_reach",
    "oblique_work",
    "suspect_advice",
    "timed_work",
]

# Wall time of one oblique impact (DOP853 phase by phase, rtol = 1e-10, a Python right-hand
# side), fitted in logs to 60 runs on the project's 2-core machine (load average 2-3, shared):
# 20, 80, 160 symmetric modes (40, 161, 323 on the rim) at alpha = 100, 500, 2000 and v =
# 0.005, 0.05, 0.2, each at (mu, angle) = (0.5, 45 deg) (up to 287 stick/slip phases) and
# (0.1, 80 deg) (gross slip), five runs of 320 modes and two of 640 at alpha = 4000. Measured
# over estimated: 0.34 to 3.55 (0.36 s to 196 s). The cost per right-hand side grows with the
# rim modes times the nodes in contact, the steps with the wall's stiffness and the phases;
# the phases are not known before the run, hence the spread.
_LOG_C = -21.319
_RIM_EXP = 1.096  # rim modes
_NODES_EXP = 2.512  # rim nodes of the wall's quadrature
_WIDTH_EXP = 0.761  # compression plus the wall's reach NEGLIGIBLE / alpha: the contact's width
_STIFF_EXP = 0.146  # alpha v
SPREAD = 3.6
"""Measured times lie within this factor of the estimate (either way)."""

# A body without the rim's node spacing (the sphere's cap, bodies/sphere/cap.py): its work is
# one placement of its wall nodes (and the projection of their forces) at the compression
# v t_c / pi, timed before the run, times a count of such evaluations: the median of wall time
# over that timing in seven runs of 20 and 40 axisymmetric modes (146 and 375 in the cap) at
# alpha = 100, 500, 1000, v = 0.005 and 0.05, (mu, angle) = (0.5, 45 deg) and (0.1, 80 deg)
# (17-95 s on this shared 2-core machine, OPENBLAS_NUM_THREADS=1): 4.5 x 6000. Measured over
# estimated 0.24 to 1.49: the per-step overhead of the integrator and the events is not in the
# timing, and weighs more with fewer modes.
_CAP_EVALUATIONS = 27000.0
_CAP_SPREAD = 4.2

_STORED_STEPS = 5000  # steps whose states solve_ivp keeps (measured up to 3950)
_NODE_ARRAYS = 10  # arrays of (nodes, rim modes) alive at once: the shapes and their products

SUSPECT = Status.SUSPECT
"""Status of a result in the regime where the route is not trusted (:func:`suspect_advice`):
:attr:`restitution.status.Status.SUSPECT`."""

SUSPECT_MODES = 320
"""Above this many symmetric modes ..."""
SUSPECT_ALPHA = 4000.0
"""... with a wall at least this hard ..."""
SUSPECT_MU = 0.1
"""... and friction above this (the one coefficient measured smooth there), a result is
suspect: docs/oblique.md, "Caution, 640 modes and alpha = 4000"."""


SLOWEST_APPROACH = 0.05
"""Smallest ``alpha v`` (``v`` the normal speed in ``c``, ``alpha`` in ``1 / R``) the route
takes. The grain starts where the wall's energy is ``1e-12`` of ``E0`` and crosses the wall's
tail in about ``27 / (alpha v)`` ``R / c``; measured at 20 modes, ``mu = 0.5``, 30 degrees:
``alpha v = 0.05`` (``v = 1e-4``, ``alpha = 500``) took 442 stick/slip phases in 7 s, ``alpha v =
0.01`` and 0.005 chattered beyond 1000 phases (20-26 s, then an error) and ``v = 1e-9`` overflowed
in the approach and ran on for minutes."""

_HARDEST_ADVISED = 1e4


def check_reach(v_normal: float, alpha: float, names: tuple[str, str] = ("v", "alpha")) -> None:
    """Refuse an impact slower than :data:`SLOWEST_APPROACH` on its wall (``names``: how the
    caller calls the speed and the hardness, ``("--v", "--alpha")`` on the command line).

    >>> check_reach(0.05, 500.0)
    """
    if alpha * v_normal < SLOWEST_APPROACH:
        v, a = names
        harder = SLOWEST_APPROACH / v_normal
        # A wall harder than this costs more than a run is worth (nodes grow as sqrt(alpha)).
        wall = f" or {a} to at least {harder:.3g}" if harder <= _HARDEST_ADVISED else ""
        raise InputError(
            f"{a} * {v} = {alpha * v_normal:.3g} is below {SLOWEST_APPROACH:g}, the slowest "
            "approach of the oblique route (the grain crawls through the wall's tail and the "
            f"contact chatters between stick and slip); raise {v} to at least "
            f"{SLOWEST_APPROACH / alpha:.3g}{wall}"
        )


@dataclass(frozen=True)
class ObliqueWork:
    """The estimated work of one oblique impact.

    Attributes
    ----------
    rim_modes, nodes : int
        Modes of the rim (both families) and rim nodes of the wall's quadrature.
    seconds : float
        Estimated wall time on one core, s (within :data:`SPREAD` of the measured runs).
    memory_bytes : float
        Working memory, bytes.
    spread : float
        Measured times lay within this factor of the estimate (either way).
    """

    rim_modes: int
    nodes: int
    seconds: float
    memory_bytes: float
    spread: float = SPREAD

    def modes_within(self, seconds: float, modes: int) -> int:
        """The count of modes that would take ``seconds``, scaled from ``modes`` (this work's
        count, symmetric or on the rim) by the fit's power of the rim modes."""
        return int(modes * (seconds / self.seconds) ** (1.0 / _RIM_EXP))


def oblique_work(body, v_normal: float, alpha: float) -> ObliqueWork:
    """The estimated time and memory of ``oblique_collision(body, v_normal, ..., alpha)``.

    Parameters
    ----------
    body : RimBody
        The grain's modes (:class:`restitution.dynamics.oblique.RimBody`); a body with the
        rim's ``node_spacing`` (the disk) by the fit above, another by :func:`timed_work`.
    v_normal, alpha : float
        Normal speed (``c``) and wall hardness (``1 / R``).
    """
    if not hasattr(body, "node_spacing"):
        return timed_work(body, v_normal, alpha)
    n = len(body)
    nodes = int(body.wall_node_count(alpha))
    compression = v_normal * float(body.contact_time_estimate(v_normal)) / math.pi
    log_s = (
        _LOG_C
        + _RIM_EXP * math.log(max(n, 1))
        + _NODES_EXP * math.log(nodes)
        + _WIDTH_EXP * math.log(compression + NEGLIGIBLE / alpha)
        + _STIFF_EXP * math.log(alpha * v_normal)
    )
    memory = max(
        8.0 * (_NODE_ARRAYS * nodes * n + _STORED_STEPS * (8 + 2 * n)),
        float(body.wall_node_memory(alpha)),
    )
    return ObliqueWork(n, nodes, math.exp(log_s), memory)


def timed_work(body, v_normal: float, alpha: float, repeats: int = 5) -> ObliqueWork:
    """The work of an oblique impact of ``body`` from one placement of its wall nodes at a
    compression ``v t_c / pi`` (``t_c`` the body's contact time estimate), timed here (best of
    ``repeats``), times :data:`_CAP_EVALUATIONS` (measured; spread :data:`_CAP_SPREAD`)."""
    import time

    import numpy as np

    nodes = body.wall_nodes(alpha)
    n = len(body)
    x0 = -1.0 + v_normal * float(body.contact_time_estimate(v_normal)) / math.pi
    zero = np.zeros(n)
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        placed = nodes.place(x0, 0.0, zero, zero, 0.0, -NEGLIGIBLE / alpha)
        if placed is not None:
            weight, X = placed[0], placed[1]
            e = weight * np.exp(alpha * X)
            placed[5](e, e / max(float(np.sum(e)), 1e-300))
        best = min(best, time.perf_counter() - start)
    count = len(nodes)
    memory = max(
        8.0 * (4 * count * max(n, 1) + _STORED_STEPS * (8 + 2 * n)),
        float(body.wall_node_memory(alpha)),
    )
    return ObliqueWork(n, count, _CAP_EVALUATIONS * best, memory, _CAP_SPREAD)


def suspect_advice(n_modes: int, alpha: float, mu: float) -> str | None:
    """What to do with a result of ``n_modes`` symmetric modes (the head-on count; the rim
    holds about twice as many), wall ``alpha`` and friction ``mu`` in the suspect regime
    (:data:`SUSPECT_MODES`, :data:`SUSPECT_ALPHA`, :data:`SUSPECT_MU`); ``None`` outside it.

    >>> suspect_advice(160, 4000.0, 0.5) is None
    True
    """
    if n_modes > SUSPECT_MODES and alpha >= SUSPECT_ALPHA and mu > SUSPECT_MU:
        return (
            f"more than {SUSPECT_MODES} modes on a wall of alpha >= {SUSPECT_ALPHA:g} with "
            f"friction above {SUSPECT_MU:g}: there the contact can break into dozens of "
            "stick/slip phases with an erratic force (epsilon_normal 1.019 at 640 modes, alpha "
            "= 4000, mu = 0.5), possibly a friction instability of the model (docs/oblique.md); "
            f"compare with the same impact at {SUSPECT_MODES} modes or a softer wall before "
            "using the number"
        )
    return None
