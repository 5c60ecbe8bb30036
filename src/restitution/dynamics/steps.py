"""The time step of a collision and the work it will take, known before anything runs.

Units: ``E = rho = R = 1``; times in ``R / c``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.bodies.base import ModalBody
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.integrators import INTEGRATORS
from restitution.dynamics.settings import DEFAULT_ENERGY_TOL, CollisionSettings
from restitution.errors import InputError

__all__ = [
    "MAX_MEMORY_BYTES",
    "QUADRATURE_PEAK",
    "WorkEstimate",
    "check_work",
    "estimate_work",
    "initial_step",
]

# Step coefficient c of dt = c * min(1 / (alpha v), 1 / omega_max) that gives an energy drift
# of about 1e-6, measured per integrator at nu = 0.33 (v = 0.005-0.3, alpha = 500-4000,
# N = 400-1600); see docs/numerics.md.
_STEP_COEFF = {"split4": 0.2, "split": 0.03, "rk4": 0.2}


def initial_step(
    body: ModalBody,
    v: np.ndarray,
    alpha: np.ndarray,
    integrator: str,
    energy_tol: float,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> np.ndarray:
    """First guess of the step for each collision, ``R / c``.

    Two time scales limit the step. An edge point arriving at the wall with speed ``~v`` is
    stopped by the contact law in its :meth:`~restitution.dynamics.contact.base.ContactLaw.
    step_time` (the exponential wall: within the decay length ``1/alpha``, in a time
    ``1 / (alpha v)``); and the wall force, which depends on every mode, varies on the period
    of the fastest mode, ``1 / omega_max``. The step is ``c`` times the smaller, with ``c``
    calibrated per integrator for a drift of 1e-6 and scaled as ``energy_tol^(1/order)``.
    The driver measures the actual drift (or, for a law that is not conservative, epsilon's
    step error) and refines the step when needed.
    """
    order = INTEGRATORS[integrator].order
    coeff = _STEP_COEFF[integrator] * (energy_tol / 1e-6) ** (1.0 / order)
    w_max = float(body.omega.max())
    return coeff * np.minimum(contact_law.step_time(alpha, v), 1.0 / w_max)


QUADRATURE_PEAK = 4.0
"""Peak memory of building a body's surface quadrature over the basis table it keeps (the
temporaries of its trigonometric and Legendre columns). Measured as the growth of the peak
resident memory of one :func:`collide_batch` (issue 47: the estimate without it was about 3
times low, and ``epsilon --nu 0.33 --v 1e-9`` grew to 10-12 GB): the disk 2.75 (n_phi = 0.41 M
and 0.83 M, N = 300), the sphere 3.27 (58 k and 117 k nodes, N = 400); 4 leaves a fifth for
other mode sets."""

MAX_MEMORY_BYTES = 4 * 2**30
"""Largest working memory (quadrature and batch arrays) a collision run may plan to use."""


@dataclass(frozen=True)
class WorkEstimate:
    """Up-front estimate of the work of one batch (the largest member).

    Attributes
    ----------
    steps : float
        Expected time steps of one run: (approach + contact + departure time) / dt.
    t_end : float
        Expected simulated time, ``R / c``: the approach from the start position and back at
        speed ``v`` plus the quasistatic contact time.
    dt : float
        First step, ``R / c``.
    n_phi : int
        Nodes of the edge quadrature.
    memory_bytes : float
        Working memory of the quadrature and the batch arrays, bytes.
    limit : str
        What makes it large: ``"fixed"`` (the given ``dt``), ``"tolerance"`` (an
        ``energy_tol`` below the default whose step alone breaks ``max_steps``),
        ``"approach"`` (the start is far from the wall for this ``v`` and ``alpha``),
        ``"wall"`` (``alpha v`` forces a tiny step) or ``"body"`` (the fastest mode forces a
        tiny step).
    """

    steps: float
    t_end: float
    dt: float
    n_phi: int
    memory_bytes: float
    limit: str


def estimate_work(
    body: ModalBody,
    v: np.ndarray,
    alpha: np.ndarray,
    settings: CollisionSettings,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> WorkEstimate:
    """Estimate steps and memory of :func:`collide_batch` before anything is allocated.

    The body starts where its wall energy is ``CONTACT_TOL E0``, the contact law's
    :meth:`~restitution.dynamics.contact.base.ContactLaw.approach_gap` from the wall (the
    exponential wall: with the body's :meth:`~restitution.bodies.base.ModalBody.
    depth_transform`); it flies that distance at ``v`` in and out, and touches for its
    quasistatic contact time. The law's node demand sizes the memory.
    """
    v = np.asarray(v, dtype=float)
    alpha = np.asarray(alpha, dtype=float)
    e0 = 0.5 * body.mass * v**2
    gap = contact_law.approach_gap(body, alpha, e0)
    flight = 2.0 * gap / v
    t_end = flight + body.contact_time_estimate(v)
    wall_time = contact_law.step_time(alpha, v)
    if settings.dt is not None:
        dt = np.full(v.size, settings.dt)
    else:
        dt = settings.step_safety * initial_step(
            body, v, alpha, settings.integrator, settings.energy_tol, contact_law
        )
    steps = t_end / dt
    worst = int(np.argmax(steps))
    if settings.dt is not None:
        limit = "fixed"
    elif (
        settings.energy_tol < DEFAULT_ENERGY_TOL
        and steps[worst]
        * (settings.energy_tol / DEFAULT_ENERGY_TOL)
        ** (1.0 / INTEGRATORS[settings.integrator].order)
        <= settings.max_steps
    ):
        limit = "tolerance"  # the default tolerance's step would fit
    elif flight[worst] >= 0.5 * t_end[worst]:  # ">=": an infinite flight (v = 1e-300) too
        limit = "approach"
    elif wall_time[worst] * float(body.omega.max()) < 1.0:
        limit = "wall"  # the exponential wall: alpha v > omega_max
    else:
        limit = "body"
    n_phi = settings.n_phi or contact_law.nodes(body, float(alpha.max()))
    orders = np.unique(body.order).size
    # trig (n_phi x 2K) at its construction's peak and a few (B x n_phi) and (B x N) work
    # arrays, 8 bytes each.
    memory = 8.0 * (QUADRATURE_PEAK * n_phi * (2 * orders + 4) + 6 * v.size * (n_phi + len(body)))
    return WorkEstimate(
        steps=float(steps[worst]),
        t_end=float(t_end[worst]),
        dt=float(dt[worst]),
        n_phi=int(n_phi),
        memory_bytes=float(memory),
        limit=limit,
    )


def check_work(
    body: ModalBody,
    v: np.ndarray,
    alpha: np.ndarray,
    settings: CollisionSettings,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> WorkEstimate:
    """Refuse a batch whose estimated work exceeds ``settings.max_steps`` or the memory bound.

    Raises
    ------
    InputError
        Saying the estimate and what to change.
    """
    est = estimate_work(body, v, alpha, settings, contact_law)
    if est.memory_bytes > MAX_MEMORY_BYTES:
        raise InputError(
            f"alpha up to {float(np.max(alpha)):.3g} needs {est.n_phi:.3g} edge quadrature "
            f"nodes, about {est.memory_bytes / 2**30:.3g} GiB (limit "
            f"{MAX_MEMORY_BYTES / 2**30:g} GiB); lower alpha or set a smaller n_phi"
        )
    if est.steps > settings.max_steps:
        advice = {
            "approach": "the body starts where the wall energy is 1e-12 of E0 and needs that "
            "long to arrive: raise v or alpha (alpha * v of order 1-100 is typical)",
            "wall": "the step must resolve 1/(alpha v): lower alpha",
            "body": "the step must resolve the fastest mode: use fewer modes",
            "fixed": "the step is the given dt: raise dt or max_steps",
            "tolerance": f"energy_tol = {settings.energy_tol:.3g} asks for that step: raise "
            f"energy_tol (default {DEFAULT_ENERGY_TOL:g}) or max_steps",
        }[est.limit]
        if est.limit != "fixed" and settings.step_safety < 1.0:
            # The step the limit asks for is scaled by step_safety: name it (issue 47: a tiny
            # step_safety was blamed on alpha).
            advice = (
                f"step_safety = {settings.step_safety:.3g} shrinks every step that much: raise "
                f"it towards 1; else {advice}"
            )
        if "max_steps" not in advice:
            advice += f", or raise max_steps (now {settings.max_steps})"
        raise InputError(
            f"this collision would need about {est.steps:.2g} time steps (simulated time "
            f"{est.t_end:.3g} R/c at dt = {est.dt:.3g} R/c), more than max_steps = "
            f"{settings.max_steps}; {advice}"
        )
    return est
