"""Head-on collision of an elastic disk with a wall, in normal coordinates (paper sections 3-4).

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``; energies reported as fractions
of the initial kinetic energy ``E0 = (m/2) v^2``.

The disk starts undeformed with its centre at ``x0 < -1`` where the wall potential energy is
``CONTACT_TOL * E0`` and moves towards the wall at speed ``v``. It is integrated until it moves
away and provably cannot touch again: the rigid motion is away from the wall and even the sum of
all modal amplitudes cannot bring the edge to where ``exp(alpha x)`` exceeds ``CONTACT_TOL``.

The step is chosen automatically (see :func:`initial_step`) and the run is repeated with a
smaller step while the relative energy drift exceeds ``energy_tol``; after ``max_refinements``
the point fails with :class:`CollisionError`, whose message says what to change. A bound on the
simulated time prevents hanging.

**Vibrating disks.** A collision may start from any modal state ``(Q, P)`` (``initial=`` of
:func:`collide_batch`; ``Q`` in ``R``, ``P`` in ``m c``, in the order of the mode set). That state
is the *free-flight* state at the moment the centre passes the start position above: the disk's
translation and its free oscillation, without the wall. The integration begins earlier by the
vibration's reach (the bound on the edge displacement that the stop test uses), so that no edge
point is closer to the wall than the undeformed disk's edge at the start position, with the
state carried back by the exact free oscillation (:func:`~restitution.dynamics.integrators.free_modes`):
the same physics, defined independently of where the integration begins. Every
result carries the final state (``final_Q``, ``final_P`` at centre position ``final_x0`` and time
``t_end`` after the start position was passed) so collisions can be chained. A zero initial state
is today's collision, bit for bit.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, replace

import numpy as np

from restitution.bodies.disk.modes import ModeSet
from restitution.dynamics.integrators import (
    INTEGRATORS,
    System,
    free_modes,
    initial_state,
    mode_energies,
    total_energy,
)
from restitution.dynamics.results import CollisionResult, History
from restitution.dynamics.wall import default_n_phi, wall_quadrature
from restitution.errors import InputError, RestitutionError

__all__ = [
    "CONTACT_TOL",
    "CollisionError",
    "CollisionSettings",
    "WorkEstimate",
    "check_work",
    "collide",
    "collide_batch",
    "estimate_work",
    "initial_step",
    "rank_modes",
    "start_position",
]

CONTACT_TOL = 1e-12
"""Wall potential energy at the start, and the wall force scale at the end, relative to E0."""

_STOP_LOG = math.log(1.0 / CONTACT_TOL)

_BACKENDS = ("auto", "compiled", "numpy")
# Strang steps composing one step of each splitting that the compiled kernel runs.
_KERNEL_WEIGHTS = {name: INTEGRATORS[name].weights for name in ("split", "split4")}


class CollisionError(RestitutionError):
    """A collision could not be integrated to the requested accuracy."""


class _Unstable(Exception):
    """Internal: a run's energy drift exploded; the step must shrink."""


@dataclass(frozen=True)
class CollisionSettings:
    """Numerical settings of a collision run.

    Attributes
    ----------
    integrator : {"split4", "split", "rk4"}
        Time integrator (see :mod:`restitution.dynamics.integrators`); the default ``split4`` is the
        fourth-order symplectic composition of the exact-free-flow splitting.
    n_phi : int or None
        Nodes of the edge quadrature on ``[0, pi/2]``; ``None`` picks
        :func:`restitution.dynamics.wall.default_n_phi`.
    energy_tol : float
        Largest accepted relative energy drift ``max |H(t) - H(0)| / H(0)``.
    dt : float or None
        Fixed step in ``R / c``. ``None`` chooses it automatically and refines it until the
        drift is below ``energy_tol``; a fixed step is never refined (the drift is reported).
    max_refinements : int
        How often the automatic step may be reduced before the run fails.
    step_safety : float
        Multiplies the automatic first step; smaller is more cautious.
    record : bool
        Keep time histories (:class:`restitution.dynamics.results.History`).
    record_interval : float
        Time between history samples, ``R / c``.
    max_steps : int
        Hard bound on the number of steps of one run.
    backend : {"auto", "compiled", "numpy"}
        ``compiled`` runs the splittings in the numba kernel (:mod:`restitution.dynamics.kernel`);
        ``numpy`` runs the NumPy reference path (needed for ``rk4`` and recorded histories);
        ``auto`` takes the kernel whenever it applies. Both give the same numbers to round-off.
    """

    integrator: str = "split4"
    n_phi: int | None = None
    energy_tol: float = 1e-6
    dt: float | None = None
    max_refinements: int = 6
    step_safety: float = 1.0
    record: bool = False
    record_interval: float = 0.02
    max_steps: int = 2_000_000
    backend: str = "auto"

    def __post_init__(self) -> None:
        if self.integrator not in INTEGRATORS:
            raise InputError(
                f"unknown integrator {self.integrator!r}; choose one of {sorted(INTEGRATORS)}"
            )
        _require(
            _is_real(self.energy_tol) and 0 < self.energy_tol < 1,
            f"energy_tol must be a number in (0, 1) (relative energy drift), got "
            f"{self.energy_tol!r}",
        )
        _require(
            self.dt is None or (_is_real(self.dt) and self.dt > 0),
            f"dt must be None (automatic) or a positive number in R/c, got {self.dt!r}",
        )
        _require(
            self.n_phi is None or (_is_int(self.n_phi) and self.n_phi >= 16),
            f"n_phi must be None (automatic) or an integer >= 16, got {self.n_phi!r}",
        )
        _require(
            _is_int(self.max_refinements) and self.max_refinements >= 0,
            f"max_refinements must be an integer >= 0, got {self.max_refinements!r}",
        )
        _require(
            _is_real(self.step_safety) and self.step_safety > 0,
            f"step_safety must be a positive number (it multiplies the automatic step), got "
            f"{self.step_safety!r}",
        )
        _require(
            isinstance(self.record, bool | np.bool_),
            f"record must be True or False, got {self.record!r}",
        )
        _require(
            _is_real(self.record_interval) and self.record_interval > 0,
            f"record_interval must be a positive time in R/c, got {self.record_interval!r}",
        )
        _require(
            _is_int(self.max_steps) and self.max_steps >= 1,
            f"max_steps must be a positive integer, got {self.max_steps!r}",
        )
        _require(
            self.backend in _BACKENDS,
            f"unknown backend {self.backend!r}; choose one of {_BACKENDS}",
        )


def _require(condition: bool, message: str) -> None:
    if not condition:
        raise InputError(message)


def _is_int(value) -> bool:
    return isinstance(value, int | np.integer) and not isinstance(value, bool | np.bool_)


def _is_real(value) -> bool:
    return (
        isinstance(value, int | float | np.integer | np.floating)
        and not isinstance(value, bool | np.bool_)
        and math.isfinite(value)
    )


def _check_inputs(v, alpha, modes: ModeSet) -> tuple[np.ndarray, np.ndarray]:
    """Validate a batch; returns ``(v, alpha)`` as equal-length float arrays, shape (B,)."""
    if not isinstance(modes, ModeSet):
        raise InputError(f"modes must be a ModeSet (see get_modes), got {type(modes).__name__}")
    if len(modes) < 1:
        raise InputError("at least one mode is needed (use --modes >= 1)")
    arrays = []
    for name, value in (("v", v), ("alpha", alpha)):
        try:
            arr = np.atleast_1d(np.asarray(value, dtype=float))
        except (TypeError, ValueError):
            raise InputError(f"{name} must be a number or a 1-D list of numbers") from None
        if arr.ndim != 1:
            raise InputError(f"{name} must be a number or a 1-D list, got shape {arr.shape}")
        if arr.size == 0:
            raise InputError(f"{name} is empty: give at least one collision")
        arrays.append(arr)
    v, alpha = arrays
    if v.size != alpha.size and 1 not in (v.size, alpha.size):
        raise InputError(
            f"v has {v.size} values and alpha {alpha.size}: give equally many, or one of them "
            "as a single number"
        )
    v, alpha = (a.astype(float).copy() for a in np.broadcast_arrays(v, alpha))
    if not np.all(np.isfinite(v)) or np.any(v <= 0) or np.any(v >= 1):
        raise InputError(
            f"the speed v must lie in (0, 1) in units of c (the disk's speed towards the wall), "
            f"got {v.tolist()}"
        )
    if not np.all(np.isfinite(alpha)) or np.any(alpha <= 0):
        raise InputError(f"the wall hardness alpha must be positive, got {alpha.tolist()}")
    if np.any(v > 0.3):
        warnings.warn(
            "v > 0.3 c: strains of order v/c stretch linear elasticity; results are a model "
            "extrapolation",
            stacklevel=3,
        )
    return v, alpha


def start_position(
    modes: ModeSet, v: float, alpha: float, settings: CollisionSettings | None = None
) -> float:
    """The start position of the centre (``R``) for a disk at rest: where the undeformed disk's
    wall energy is ``CONTACT_TOL`` times its kinetic energy. An ``initial`` state of
    :func:`collide` is the free-flight state at the moment the centre passes this position."""
    settings = settings or CollisionSettings()
    v_arr, alpha_arr = _check_inputs(v, alpha, modes)
    n_phi = settings.n_phi or default_n_phi(float(alpha_arr[0]), int(modes.n.max()))
    quad = wall_quadrature(modes, int(n_phi))
    return float(_start_position(alpha_arr, 0.5 * modes.mass * v_arr**2, quad)[0])


def _start_position(alpha: np.ndarray, e0: np.ndarray, quad) -> np.ndarray:
    """Centre position where the undeformed disk's wall energy is ``CONTACT_TOL * E0``."""
    # V(x0) = exp(alpha (x0 + 1)) * I / alpha with I = int exp(alpha (cos phi - 1)) dphi.
    integral = np.exp(alpha[:, None] * (quad.cos_phi[None, :] - 1.0)) @ quad.weight
    return -1.0 + np.log(CONTACT_TOL * e0 * alpha / integral) / alpha


@dataclass(frozen=True)
class _Start:
    """Where and in which state the integration of each member begins (private).

    ``x0``: centre position (``R``); ``Q``, ``P``: modal state there, shape (B, N), or ``None``
    for disks at rest; ``lead``: time (``R / c``) from there to the start position proper;
    ``t_max``: bound of the simulated time (``R / c``, :func:`_t_max`).
    """

    x0: np.ndarray
    Q: np.ndarray | None
    P: np.ndarray | None
    lead: np.ndarray
    t_max: np.ndarray


def _start(modes: ModeSet, v: np.ndarray, alpha: np.ndarray, quad, initial) -> _Start:
    """Start of each member: the standard position, or earlier when a vibrating edge reaches.

    ``initial`` is ``None`` or ``(Q, P)`` of shape (B, N): the free-flight state at the moment
    the centre passes the standard start position (module docstring).
    """
    m = modes.mass
    x_start = _start_position(alpha, 0.5 * m * v**2, quad)
    if initial is None:
        return _Start(x_start, None, None, np.zeros(v.size), _t_max(v, x_start))
    Q, P = initial
    energy = P**2 / (2.0 * m) + 0.5 * m * (modes.omega * Q) ** 2
    reach = np.sqrt(2.0 * energy / m) / modes.omega @ quad.g_max
    # Every edge point then lies at most as close to the wall as the undeformed disk's edge at
    # the standard start, so the wall energy is at most CONTACT_TOL * E0 there, as for a disk
    # at rest (and a zero state starts exactly where a disk at rest does).
    x_begin = x_start - reach
    lead = reach / v
    Qb, Pb = free_modes(modes.omega, m, Q, P, -lead[:, None])
    # A vibrating disk may leave far slower than it came (measured: epsilon = 0.054 in a
    # thermal ensemble), so its time bound is 100 times a disk at rest's; max_steps still holds.
    t_max = np.where(reach > 0, 100.0, 1.0) * _t_max(v, x_begin)
    return _Start(x_begin, Qb, Pb, lead, t_max)


def _check_initial(initial, modes: ModeSet, size: int):
    """Validate ``initial = (Q, P)``; returns arrays of shape (B, N) or ``None``."""
    if initial is None:
        return None
    N = len(modes)
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


def _contact_time_estimate(v: np.ndarray) -> np.ndarray:
    """Quasistatic contact time, eq. (61) with prefactor pi (paper section 5), ``R / c``."""
    return math.pi * np.sqrt(np.log(4.0 / v))


# Step coefficient c of dt = c * min(1 / (alpha v), 1 / omega_max) that gives an energy drift
# of about 1e-6, measured per integrator at nu = 0.33 (v = 0.005-0.3, alpha = 500-4000,
# N = 400-1600); see docs/numerics.md.
_STEP_COEFF = {"split4": 0.2, "split": 0.03, "rk4": 0.2}


def initial_step(
    modes: ModeSet, v: np.ndarray, alpha: np.ndarray, integrator: str, energy_tol: float
) -> np.ndarray:
    """First guess of the step for each collision, ``R / c``.

    Two time scales limit the step. An edge point arriving at the wall with speed ``~v`` is
    stopped within the decay length ``1/alpha`` of the exponential potential, in a time
    ``1 / (alpha v)``; and the wall force, which depends on every mode, varies on the period
    of the fastest mode, ``1 / omega_max``. The step is ``c`` times the smaller, with ``c``
    calibrated per integrator for a drift of 1e-6 and scaled as ``energy_tol^(1/order)``.
    The driver measures the actual drift and refines the step when needed.
    """
    order = INTEGRATORS[integrator].order
    coeff = _STEP_COEFF[integrator] * (energy_tol / 1e-6) ** (1.0 / order)
    w_max = float(modes.omega.max())
    return coeff * np.minimum(1.0 / (alpha * v), 1.0 / w_max)


_MAX_MEMORY_BYTES = 4 * 2**30
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
        What makes it large: ``"approach"`` (the start is far from the wall for this ``v`` and
        ``alpha``), ``"wall"`` (``alpha v`` forces a tiny step) or ``"modes"`` (the fastest
        mode forces a tiny step).
    """

    steps: float
    t_end: float
    dt: float
    n_phi: int
    memory_bytes: float
    limit: str


def estimate_work(
    modes: ModeSet, v: np.ndarray, alpha: np.ndarray, settings: CollisionSettings
) -> WorkEstimate:
    """Estimate steps and memory of :func:`collide_batch` before anything is allocated.

    The start position solves ``V(x0) = CONTACT_TOL E0`` with the wall integral approximated
    by ``min(pi/2, sqrt(pi / (2 alpha)))`` (the Gaussian peak at ``phi = 0``); the disk flies
    that distance at ``v`` in and out, and touches for the quasistatic time of eq. (61).
    """
    v = np.asarray(v, dtype=float)
    alpha = np.asarray(alpha, dtype=float)
    e0 = 0.5 * modes.mass * v**2
    integral = np.minimum(0.5 * math.pi, np.sqrt(0.5 * math.pi / alpha))
    with np.errstate(over="ignore", divide="ignore"):
        gap = np.maximum(0.0, -np.log(CONTACT_TOL * e0 * alpha / integral) / alpha)
    flight = 2.0 * gap / v
    t_end = flight + _contact_time_estimate(v)
    if settings.dt is not None:
        dt = np.full(v.size, settings.dt)
    else:
        dt = settings.step_safety * initial_step(
            modes, v, alpha, settings.integrator, settings.energy_tol
        )
    steps = t_end / dt
    worst = int(np.argmax(steps))
    if flight[worst] > 0.5 * t_end[worst]:
        limit = "approach"
    elif alpha[worst] * v[worst] > float(modes.omega.max()):
        limit = "wall"
    else:
        limit = "modes"
    n_max = int(modes.n.max())
    n_phi = settings.n_phi or default_n_phi(float(alpha.max()), n_max)
    orders = np.unique(modes.n).size
    # trig (n_phi x 2K) and a few (B x n_phi) and (B x N) work arrays, 8 bytes each.
    memory = 8.0 * (n_phi * (2 * orders + 4) + 6 * v.size * (n_phi + len(modes)))
    return WorkEstimate(
        steps=float(steps[worst]),
        t_end=float(t_end[worst]),
        dt=float(dt[worst]),
        n_phi=int(n_phi),
        memory_bytes=float(memory),
        limit=limit,
    )


def check_work(
    modes: ModeSet, v: np.ndarray, alpha: np.ndarray, settings: CollisionSettings
) -> WorkEstimate:
    """Refuse a batch whose estimated work exceeds ``settings.max_steps`` or the memory bound.

    Raises
    ------
    InputError
        Saying the estimate and what to change.
    """
    est = estimate_work(modes, v, alpha, settings)
    if est.memory_bytes > _MAX_MEMORY_BYTES:
        raise InputError(
            f"alpha up to {float(np.max(alpha)):.3g} needs {est.n_phi:.3g} edge quadrature "
            f"nodes, about {est.memory_bytes / 2**30:.3g} GiB (limit "
            f"{_MAX_MEMORY_BYTES / 2**30:g} GiB); lower alpha or set a smaller n_phi"
        )
    if est.steps > settings.max_steps:
        advice = {
            "approach": "the disk starts where the wall energy is 1e-12 of E0 and needs that "
            "long to arrive: raise v or alpha (alpha * v of order 1-100 is typical)",
            "wall": "the step must resolve 1/(alpha v): lower alpha",
            "modes": "the step must resolve the fastest mode: use fewer modes",
        }[est.limit]
        raise InputError(
            f"this collision would need about {est.steps:.2g} time steps (simulated time "
            f"{est.t_end:.3g} R/c at dt = {est.dt:.3g} R/c), more than max_steps = "
            f"{settings.max_steps}; {advice}"
        )
    return est


def _edge_reach(system: System, e: np.ndarray, g_max: np.ndarray) -> np.ndarray:
    """Upper bound of the edge displacement any future free vibration can reach, ``R``.

    ``e`` (shape (B, N)) are the mode energies; ``g_max = |C| + |S|`` bounds each shape.
    """
    amp = np.sqrt(2.0 * e / system.mass) / system.omega
    return amp @ g_max


@dataclass
class _Track:
    """Per-member bookkeeping while integrating (mutable, private)."""

    e0: np.ndarray
    h0: np.ndarray
    drift: np.ndarray
    contact: np.ndarray
    max_comp: np.ndarray
    max_force: np.ndarray
    mean_e: np.ndarray
    closest_e: np.ndarray


def _run(
    modes: ModeSet,
    v: np.ndarray,
    alpha: np.ndarray,
    dt: float,
    settings: CollisionSettings,
    quad,
    abort_drift: float | None = None,
    initial=None,
) -> list[dict]:
    """Integrate a batch with one fixed step; returns one dict of raw results per member.

    With ``abort_drift``, a run whose energy drift exceeds it (or overflows) stops at once with
    :class:`_Unstable` so that the caller can retry with a smaller step.
    """
    integrator = INTEGRATORS[settings.integrator]
    m = modes.mass
    B = v.size
    e0 = 0.5 * m * v**2
    begin = _start(modes, v, alpha, quad, initial)
    system = System(omega=modes.omega, mass=m, quad=quad, alpha=alpha)
    state = initial_state(system, begin.x0, m * v, begin.Q, begin.P)
    t_max = float(np.max(begin.t_max))
    N = len(modes)
    track = _Track(
        e0=e0,
        h0=total_energy(system, state),
        drift=np.zeros(B),
        contact=np.zeros(B),
        max_comp=np.full(B, -np.inf),
        max_force=np.zeros(B),
        mean_e=np.zeros((B, N)),
        closest_e=np.zeros((B, N)),
    )
    active = np.arange(B)  # original indices of the members still integrated
    results: list[dict | None] = [None] * B
    record = settings.record
    rec_every = max(1, int(round(settings.record_interval / dt))) if record else 0
    hist: list[list] = [[] for _ in range(B)] if record else []
    comp_prev = state.x0 + 1.0
    steps = 0
    check_every = 8
    while active.size:
        if steps >= settings.max_steps or state.t > t_max:
            raise CollisionError(_timeout_message(state.t, steps, dt))
        state = integrator.step(system, state, dt)
        steps += 1
        a = active
        e_all = mode_energies(system, state)
        h = state.p0**2 / (2.0 * m) + e_all.sum(axis=1) + state.V
        if not np.all(np.isfinite(h)):
            if abort_drift is not None:
                raise _Unstable()
            raise CollisionError(
                f"the integration overflowed at t = {state.t:.3g} with dt = {dt:.3g}; "
                "the step is far too large for this wall hardness: reduce dt"
            )
        track.drift[a] = np.maximum(track.drift[a], np.abs(h - track.h0[a]) / track.h0[a])
        if abort_drift is not None and np.any(track.drift[a] > abort_drift):
            raise _Unstable()
        comp = state.x0 + 1.0
        both = (comp > 0) & (comp_prev > 0)
        enter = (comp > 0) & (comp_prev <= 0)
        leave = (comp <= 0) & (comp_prev > 0)
        frac = np.where(both, 1.0, 0.0)
        frac = np.where(enter, comp / (comp - comp_prev), frac)
        frac = np.where(leave, comp_prev / (comp_prev - comp), frac)
        track.contact[a] += frac * dt
        in_contact = frac > 0
        closer = comp > track.max_comp[a]
        if np.any(in_contact | closer):
            sel = np.nonzero(in_contact | closer)[0]
            e_sel = e_all[sel]
            ic = in_contact[sel]
            track.mean_e[a[sel[ic]]] += (frac[sel[ic]] * dt)[:, None] * e_sel[ic]
            cl = closer[sel]
            track.closest_e[a[sel[cl]]] = e_sel[cl]
        track.max_comp[a] = np.maximum(track.max_comp[a], comp)
        track.max_force[a] = np.maximum(track.max_force[a], state.F)
        comp_prev = comp
        if record and steps % rec_every == 0:
            for i, orig in enumerate(a):
                hist[orig].append(
                    (state.t, state.x0[i], state.p0[i] / m, state.F[i], e_all[i], state.Q[i])
                )
        if steps % check_every:
            continue
        leaving = state.p0 < 0
        if not np.any(leaving):
            continue
        e = e_all
        reach = _edge_reach(system, e, quad.g_max)
        gap = -(state.x0 + 1.0 + reach)
        done = leaving & (gap * system.alpha > _STOP_LOG) & (state.V < CONTACT_TOL * track.e0[a])
        if not np.any(done):
            continue
        for i in np.nonzero(done)[0]:
            orig = a[i]
            results[orig] = {
                "epsilon": float(-state.p0[i] / (m * v[orig])),
                "energy_after": e[i] / e0[orig],
                "steps": steps,
                "t_end": state.t - float(begin.lead[orig]),
                "final_Q": state.Q[i].copy(),
                "final_P": state.P[i].copy(),
                "final_x0": float(state.x0[i]),
            }
        keep = ~done
        active = a[keep]
        state = state.take(np.nonzero(keep)[0])
        system = replace(system, alpha=system.alpha[keep])
        comp_prev = comp_prev[keep]
    out = []
    for i in range(B):
        r = results[i]
        assert r is not None
        contact = track.contact[i]
        r.update(
            drift=float(track.drift[i]),
            contact_time=float(contact),
            max_compression=float(track.max_comp[i]),
            max_force=float(track.max_force[i]),
            energy_mean=track.mean_e[i] / (contact * e0[i]) if contact > 0 else track.mean_e[i],
            energy_closest=track.closest_e[i] / e0[i],
        )
        if record:
            rows = hist[i]
            r["history"] = History(
                t=np.array([x[0] for x in rows]),
                x0=np.array([x[1] for x in rows]),
                v=np.array([x[2] for x in rows]),
                force=np.array([x[3] for x in rows]),
                mode_energy=np.array([x[4] for x in rows]) / e0[i],
                Q=np.array([x[5] for x in rows]),
            )
        out.append(r)
    return out


def _timeout_message(t: float, steps: int, dt: float) -> str:
    return (
        f"the disk did not separate from the wall within t = {t:.3g} R/c ({steps} steps of "
        f"dt = {dt:.3g}); this indicates an unstable step or an unphysical input: reduce dt or "
        "energy_tol, or check alpha and v (a vibrating disk may also leave very slowly: raise "
        "max_steps)"
    )


def _t_max(v: np.ndarray, x_start: np.ndarray) -> np.ndarray:
    """Bound of the simulated time of each member, ``R / c``."""
    return (-1.0 - x_start) / v + 20.0 * _contact_time_estimate(v) + 50.0


def _use_kernel(settings: CollisionSettings) -> bool:
    """Whether the compiled kernel runs this setting (splittings, no recorded history)."""
    if settings.backend == "numpy":
        return False
    supported = settings.integrator in _KERNEL_WEIGHTS and not settings.record
    if settings.backend == "compiled" and not supported:
        raise InputError(
            f"the compiled backend runs the integrators {sorted(_KERNEL_WEIGHTS)} without "
            "recorded histories; use backend='numpy' (or 'auto') for "
            f"integrator={settings.integrator!r}, record={settings.record}"
        )
    return supported


def _run_kernel(modes, v, alpha, dts, settings, quad, abort, initial) -> list[dict | str]:
    """Run members on the compiled kernel; a dict per finished member, else ``"unstable"``."""
    from restitution.dynamics.kernel import STATUS_OK, STATUS_TIMEOUT, run_batch

    m = modes.mass
    e0 = 0.5 * m * v**2
    begin = _start(modes, v, alpha, quad, initial)
    got = run_batch(
        modes.omega,
        m,
        quad,
        v,
        alpha,
        begin.x0,
        dts,
        begin.t_max,
        _KERNEL_WEIGHTS[settings.integrator],
        settings.max_steps,
        abort,
        _STOP_LOG,
        CONTACT_TOL,
        begin.Q,
        begin.P,
    )
    out: list[dict | str] = []
    for i in range(v.size):
        status = got["status"][i]
        if status == STATUS_TIMEOUT:
            raise CollisionError(_timeout_message(got["t_end"][i], got["steps"][i], dts[i]))
        if status != STATUS_OK:
            if abort is None:
                raise CollisionError(
                    f"the integration overflowed at t = {got['t_end'][i]:.3g} with "
                    f"dt = {dts[i]:.3g}; the step is far too large for this wall hardness: "
                    "reduce dt"
                )
            out.append("unstable")
            continue
        contact = got["contact_time"][i]
        summed = got["energy_sum"][i]
        out.append(
            {
                "epsilon": float(got["epsilon"][i]),
                "energy_after": got["energy"][i] / e0[i],
                "steps": int(got["steps"][i]),
                "t_end": float(got["t_end"][i] - begin.lead[i]),
                "final_Q": got["final_Q"][i],
                "final_P": got["final_P"][i],
                "final_x0": float(got["final_x0"][i]),
                "drift": float(got["drift"][i]),
                "contact_time": float(contact),
                "max_compression": float(got["max_compression"][i]),
                "max_force": float(got["max_force"][i]),
                "energy_mean": summed / (contact * e0[i]) if contact > 0 else summed,
                "energy_closest": got["energy_closest"][i] / e0[i],
            }
        )
    return out


def _run_numpy(modes, v, alpha, dts, settings, quad, abort, initial) -> list[dict | str]:
    """Run members one by one on the NumPy reference path (same contract as the kernel)."""
    out: list[dict | str] = []
    for i in range(v.size):
        one = None if initial is None else (initial[0][i : i + 1], initial[1][i : i + 1])
        try:
            out.append(
                _run(modes, v[i : i + 1], alpha[i : i + 1], dts[i], settings, quad, abort, one)[0]
            )
        except _Unstable:
            out.append("unstable")
    return out


def _attempt(modes, v, alpha, dts, pending, settings, quad, raw, attempt, initial) -> np.ndarray:
    """Run the pending members, each with its own step; store results; return those to redo.

    Every member's step depends only on its own inputs and history, never on the other
    members of the batch, so a stored point does not depend on how the sweep batched it.
    """
    fixed = settings.dt is not None
    abort = None if fixed else max(100.0 * settings.energy_tol, 1e-4)
    run = _run_kernel if _use_kernel(settings) else _run_numpy
    mine = None if initial is None else (initial[0][pending], initial[1][pending])
    got = run(modes, v[pending], alpha[pending], dts[pending], settings, quad, abort, mine)
    order = INTEGRATORS[settings.integrator].order
    redo = []
    for i, r in zip(pending, got, strict=True):
        dt = float(dts[i])
        if isinstance(r, str):
            if attempt == settings.max_refinements:
                raise CollisionError(
                    f"the step stays unstable after {attempt} refinements (dt = {dt:.3g}) at "
                    f"v = {v[i]:.4g}, alpha = {alpha[i]:.4g}; raise max_refinements or lower "
                    "step_safety"
                )
            dts[i] = dt / 4.0
            redo.append(i)
            continue
        r["dt"] = dt
        raw[i] = r
        if not fixed and r["drift"] > settings.energy_tol:
            # Drift of an order-p method scales like dt^p: aim at half the tolerance. The factor
            # is rounded to two digits so that round-off in the measured drift (which differs
            # between the compiled and NumPy codes) does not leak into the step.
            factor = (0.5 * settings.energy_tol / r["drift"]) ** (1.0 / order)
            dts[i] = dt * round(min(max(factor, 0.1), 0.8), 2)
            redo.append(i)
    return np.array(redo, dtype=int)


def collide_batch(
    modes: ModeSet,
    v,
    alpha,
    settings: CollisionSettings | None = None,
    *,
    initial=None,
    **overrides,
) -> list[CollisionResult]:
    """Integrate many collisions ``(v_i, alpha_i)`` on one mode set at once.

    The batch shares the mode set; every member keeps its own step, step refinements and edge
    quadrature, so its result does not depend on the other members. The compiled kernel
    (:mod:`restitution.dynamics.kernel`) runs the members on all cores; the NumPy reference path runs
    them one after the other.

    Parameters
    ----------
    modes : ModeSet
        Modes kept in the expansion.
    v : float or array_like, shape (B,)
        Speeds towards the wall, units of ``c``, in (0, 1).
    alpha : float or array_like, shape (B,)
        Wall hardness, ``1 / R``; broadcast against ``v``.
    settings : CollisionSettings, optional
        Numerical settings; keyword ``overrides`` replace single fields.
    initial : (Q, P), optional
        Modal coordinates (``R``) and momenta (``m c``) of the vibrating disk, each of shape
        (N,) for every member or (B, N), in the order of ``modes``: the free-flight state when
        the centre passes the start position (module docstring). Omitted: disks at rest.

    Returns
    -------
    list of CollisionResult
        In the order of the inputs.
    """
    settings = settings or CollisionSettings()
    if overrides:
        settings = CollisionSettings(**{**settings.__dict__, **overrides})
    v, alpha = _check_inputs(v, alpha, modes)
    initial = _check_initial(initial, modes, v.size)
    check_work(modes, v, alpha, settings)
    n_max = int(modes.n.max())
    # Each member's quadrature follows from its own alpha, never from its batch.
    n_phis = np.array([settings.n_phi or default_n_phi(float(a), n_max) for a in alpha])
    t_start = time.perf_counter()
    if settings.dt is not None:
        dts = np.full(v.size, settings.dt)
    else:
        dts = settings.step_safety * initial_step(
            modes, v, alpha, settings.integrator, settings.energy_tol
        )
    raw: list[dict | None] = [None] * v.size
    unresolved = []
    for n_phi in np.unique(n_phis):
        quad = wall_quadrature(modes, int(n_phi))
        pending = np.nonzero(n_phis == n_phi)[0]
        for attempt in range(settings.max_refinements + 1):
            pending = _attempt(modes, v, alpha, dts, pending, settings, quad, raw, attempt, initial)
            if pending.size == 0:
                break
        unresolved.extend(pending.tolist())
    pending = np.array(unresolved, dtype=int)
    if pending.size:
        worst = pending[np.argmax([raw[i]["drift"] for i in pending])]
        raise CollisionError(
            f"energy drift {raw[worst]['drift']:.2e} still exceeds energy_tol = "
            f"{settings.energy_tol:.1e} after {settings.max_refinements} step refinements "
            f"(dt = {raw[worst]['dt']:.3g}) at v = {v[worst]:.4g}, alpha = {alpha[worst]:.4g}; "
            "raise energy_tol or max_refinements"
        )
    wall = time.perf_counter() - t_start
    results = []
    for i in range(v.size):
        r = raw[i]
        results.append(
            CollisionResult(
                method="modal",
                nu=modes.nu,
                v=float(v[i]),
                alpha=float(alpha[i]),
                n_modes=len(modes),
                epsilon=r["epsilon"],
                energy_drift=r["drift"],
                contact_time=r["contact_time"],
                max_compression=r["max_compression"],
                max_force=r["max_force"],
                n_steps=int(r["steps"]),
                dt=float(r["dt"]),
                wall_time_s=wall / v.size,
                integrator=settings.integrator,
                mode_n=modes.n.copy(),
                mode_l=modes.l.copy(),
                mode_energy_after=r["energy_after"],
                mode_energy_mean=r["energy_mean"],
                mode_energy_closest=r["energy_closest"],
                history=r.get("history"),
                energy_tol=settings.energy_tol,
                mode_energy_before=_energy_before(modes, initial, i, v[i]),
                final_Q=r["final_Q"],
                final_P=r["final_P"],
                final_x0=r["final_x0"],
                t_end=r["t_end"],
            )
        )
    return results


def _energy_before(modes: ModeSet, initial, i: int, v: float) -> np.ndarray:
    """Energy per mode at the start, fraction of ``E0`` (zeros for a disk at rest)."""
    if initial is None:
        return np.zeros(len(modes))
    m = modes.mass
    Q, P = initial[0][i], initial[1][i]
    return (P**2 / (2.0 * m) + 0.5 * m * (modes.omega * Q) ** 2) / (0.5 * m * v**2)


def collide(
    modes: ModeSet,
    v: float,
    alpha: float,
    settings: CollisionSettings | None = None,
    *,
    initial=None,
    **overrides,
) -> CollisionResult:
    """One collision of the disk with the wall (see :func:`collide_batch` for parameters).

    Examples
    --------
    >>> from restitution import get_modes
    >>> r = collide(get_modes(0.33, count=40), v=0.1, alpha=500)
    >>> 0.9 < r.epsilon < 1.0
    True
    """
    if np.ndim(v) or np.ndim(alpha):
        raise InputError("collide takes one speed v and one alpha; use collide_batch for several")
    return collide_batch(modes, [v], [alpha], settings, initial=initial, **overrides)[0]


def rank_modes(
    pool: ModeSet,
    count: int,
    v: float,
    alpha: float,
    settings: CollisionSettings | None = None,
    **overrides,
) -> ModeSet:
    """The paper's mode selection: the ``count`` modes of ``pool`` with the largest average
    energy during the contact of a preliminary run with the whole pool (section 4)."""
    if count > len(pool):
        raise InputError(f"cannot rank {count} modes out of a pool of {len(pool)}")
    pre = collide(pool, v, alpha, settings, **overrides)
    top = np.argsort(-pre.mode_energy_mean, kind="stable")[:count]
    return pool.take(np.sort(top))
