"""Head-on collision of an elastic body with a wall, in normal coordinates (paper sections 3-4).

The body is any :class:`~restitution.bodies.base.ModalBody` (the disk: a ``ModeSet``); the text
below speaks of the disk of the paper.

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``; energies reported as fractions
of the initial kinetic energy ``E0 = (m/2) v^2``.

The disk starts undeformed with its centre at ``x0 < -1`` where the wall potential energy is
``CONTACT_TOL * E0`` and moves towards the wall at speed ``v``. It is integrated until it moves
away and provably cannot touch again: the rigid motion is away from the wall and even the sum of
all modal amplitudes cannot bring the edge to where ``exp(alpha x)`` exceeds ``CONTACT_TOL``.

**The contact law** is an object (:mod:`restitution.dynamics.contact`): the paper's exponential
wall by default, or any :class:`~restitution.dynamics.contact.base.ContactLaw` passed as
``contact_law=``. It supplies the potential and forces, the start position, the stop test, the
step's time scale and the surface nodes; ``alpha`` is its hardness. A law without a branch in the
compiled kernel runs on the NumPy path. A law that is not conservative has its step judged by
epsilon, as a damped body's (below).

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
state carried back by the exact free oscillation
(:func:`~restitution.dynamics.integrators.free_modes`): the same physics, defined independently of
where the integration begins. Every result carries the final state (``final_Q``, ``final_P`` at
centre position ``final_x0`` and time ``t_end`` after the start position was passed) so collisions
can be chained. A zero initial state is today's collision, bit for bit.

**Damping bodies** (:class:`~restitution.bodies.viscoelastic.Viscoelastic`) run Strang's
splitting from rest. Their energy balance (vibrations, rebound and dissipated energy) is not a
fair judge of the step: a kick gives a damped mode the energy ``(h f)^2 / 2m`` of an impulse,
which the exact flow then dissipates instead of handing back, so the balance drifts like
``dt^2`` with a large constant while epsilon hardly moves (a sphere of 1200 modes at ``v =
0.003``, ``tau = 0.05``: drift 1.6e-3 at ``dt = 4e-4`` with epsilon within 7e-8 of its value at
``dt = 2.5e-5``). The step of a damped body is therefore judged by epsilon: each member runs at
``dt`` and ``dt / 2``, the half step's result is kept with the Richardson estimate of its error
(:attr:`~restitution.dynamics.results.CollisionResult.step_error`), and the step shrinks until
twice that error is below ``energy_tol``. The dissipated energy is reported as what is neither
in the rebound nor in the vibrations, which converges with them (1200 modes as above: 0.0355554
at ``dt = 4e-4``, 0.0355552 at ``2.5e-5``, where the sum of the flows' losses gave 0.0372 and
0.0356).
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import replace

import numpy as np

from restitution.bodies.base import ModalBody
from restitution.bodies.viscoelastic import mode_damping
from restitution.dynamics.compiled_path import run_kernel, use_kernel
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.integrators import INTEGRATORS
from restitution.dynamics.numpy_path import run_numpy
from restitution.dynamics.results import CollisionResult
from restitution.dynamics.run import UNSTABLE, CollisionError, MemberRun
from restitution.dynamics.settings import CONTACT_TOL, CollisionSettings
from restitution.dynamics.start import check_initial, energy_before
from restitution.dynamics.steps import WorkEstimate, check_work, estimate_work, initial_step
from restitution.errors import InputError, is_real, real_array

__all__ = [
    "CONTACT_TOL",
    "STEP_JUDGES",
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


def _check_inputs(v, alpha, body: ModalBody) -> tuple[np.ndarray, np.ndarray]:
    """Validate a batch; returns ``(v, alpha)`` as equal-length float arrays, shape (B,).

    ``v`` and ``alpha`` are numbers or lists/arrays of numbers: ``None``, a string or a bool
    is refused by name, not read as ``nan``, a parse or ``1.0``.
    """

    if not isinstance(body, ModalBody):
        raise InputError(
            f"modes must be a body's mode set (a ModeSet, see get_modes), got {type(body).__name__}"
        )
    if len(body) < 1:
        raise InputError("at least one mode is needed (use --modes >= 1)")
    arrays = []
    for name, value, allowed in (
        ("v", v, "in (0, 1) (units of c)"),
        ("alpha", alpha, "> 0 (the wall hardness, 1/R)"),
    ):
        if isinstance(value, list | tuple):
            # Name the entry that is not a number (collide passes its one v as [v]); a bool
            # in a list is refused too, not read as 1.0.
            for entry in value:
                if not is_real(entry):
                    real_array(entry, name, allowed)
        arr = np.atleast_1d(real_array(value, name, allowed))
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
    # Two bodies meet at relative speed v: identical ones are the wall problem at v / 2.
    fastest = 0.6 if body.geometry.endswith("-pair") else 0.3
    if np.any(v > fastest):
        warnings.warn(
            f"v > {fastest:g} c: strains of order v/c stretch linear elasticity; results are a "
            "model extrapolation",
            stacklevel=3,
        )
    return v, alpha


def _check_law(contact_law) -> ContactLaw:
    """The contact law of a run, refused in one line when it is not a :class:`ContactLaw`."""
    if not isinstance(contact_law, ContactLaw):
        raise InputError(
            f"contact_law must be a ContactLaw (see restitution.dynamics.contact), got "
            f"{type(contact_law).__name__}; omit it for the exponential wall"
        )
    return contact_law


def _settings(settings, overrides: dict) -> CollisionSettings:
    """The settings of a run: ``settings`` (default ones when ``None``) with ``overrides``."""
    if settings is None:
        settings = CollisionSettings()
    elif not isinstance(settings, CollisionSettings):
        raise InputError(
            f"settings must be a CollisionSettings (or None for the defaults), got "
            f"{type(settings).__name__} {settings!r}; pass single options as keywords, e.g. "
            "collide(body, v, alpha, dt=1e-3)"
        )
    if overrides:
        settings = CollisionSettings(**{**settings.__dict__, **overrides})
    return settings


def _check_damped(body: ModalBody, settings: CollisionSettings, initial) -> None:
    """A viscoelastic body runs on Strang's splitting from rest (module docstring)."""
    if mode_damping(body) is None:
        return
    if settings.integrator != "split":
        raise InputError(
            f"a viscoelastic body needs integrator='split' (Strang, every substep forward), got "
            f"{settings.integrator!r}: Yoshida's composition steps backwards, where damped modes "
            "grow, and rk4 has no damping; pass integrator='split'"
        )
    if initial is not None:
        raise InputError(
            "a viscoelastic body starts at rest: its pre-collision vibration would have to be "
            "carried back in time, where damped modes grow; drop initial="
        )


def _dissipated(r: MemberRun) -> float:
    """The energy a damped body's material took, fraction of ``E0``: what is neither in the
    rebound nor in the vibrations (the body starts at rest). Its balance converges with epsilon;
    the sum of the exact flows' losses (``r.dissipated``) also counts the energy the kicks gave
    to damped modes, which vanishes only like ``dt^2`` (module docstring)."""
    return float(1.0 - r.epsilon**2 - np.sum(r.energy_after))


def start_position(
    body: ModalBody,
    v: float,
    alpha: float,
    settings: CollisionSettings | None = None,
    *,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> float:
    """The start position of the centre (``R``) for a disk at rest: where the undeformed disk's
    wall energy is ``CONTACT_TOL`` times its kinetic energy. An ``initial`` state of
    :func:`collide` is the free-flight state at the moment the centre passes this position."""
    settings = _settings(settings, {})
    contact_law = _check_law(contact_law)
    v_arr, alpha_arr = _check_inputs(v, alpha, body)
    n_phi = settings.n_phi or contact_law.nodes(body, float(alpha_arr[0]))
    quad = body.surface_quadrature(int(n_phi))
    return float(contact_law.start_position(alpha_arr, 0.5 * body.mass * v_arr**2, quad)[0])


STEP_JUDGES = ("energy", "epsilon")
"""What may judge the step of a conservative run (``step_judge`` of :func:`collide_batch`)."""


def _attempt(
    body, v, alpha, dts, pending, settings, quad, raw, attempt, initial, contact_law, step_judge
) -> np.ndarray:
    """Run the pending members, each with its own step; store results; return those to redo.

    Every member's step depends only on its own inputs and history, never on the other
    members of the batch, so a stored point does not depend on how the sweep batched it.
    """
    fixed = settings.dt is not None
    damped = mode_damping(body) is not None
    # A damped body's energy balance carries the energy its kicks give to damped modes (module
    # docstring): only a collapse of the step aborts, and epsilon judges the step. A law that
    # is not conservative has no energy balance to hold: only an overflow aborts.
    judged_by_epsilon = damped or not contact_law.conservative or step_judge == "epsilon"
    if fixed:
        abort = None
    elif damped:
        abort = 0.5
    elif not contact_law.conservative:
        abort = math.inf
    else:
        abort = max(100.0 * settings.energy_tol, 1e-4)
    run = run_kernel if use_kernel(settings, contact_law) else run_numpy
    mine = None if initial is None else (initial[0][pending], initial[1][pending])
    got = run(
        body, v[pending], alpha[pending], dts[pending], settings, quad, abort, mine, contact_law
    )
    order = INTEGRATORS[settings.integrator].order
    halves = [None] * len(got)
    if judged_by_epsilon and not fixed:
        halves = run(
            body,
            v[pending],
            alpha[pending],
            dts[pending] / 2,
            settings,
            quad,
            abort,
            mine,
            contact_law,
        )
    redo = []
    for i, r, half in zip(pending, got, halves, strict=True):
        dt = float(dts[i])
        if r is UNSTABLE or half is UNSTABLE:
            if attempt == settings.max_refinements:
                raise CollisionError(
                    f"the step stays unstable after {attempt} refinements (dt = {dt:.3g}) at "
                    f"v = {v[i]:.4g}, alpha = {alpha[i]:.4g}; raise max_refinements or lower "
                    "step_safety"
                )
            dts[i] = dt / 4.0
            redo.append(i)
            continue
        if half is not None:
            # Richardson: the error of the half step's epsilon is (eps_h - eps_h/2) / (2^p - 1);
            # twice it is the error of the rebound energy, held to energy_tol.
            error = abs(r.epsilon - half.epsilon) / (2.0**order - 1.0)
            raw[i] = replace(half, dt=dt / 2, step_error=error)
            if 2.0 * error > settings.energy_tol:
                factor = (0.5 * settings.energy_tol / (2.0 * error)) ** (1.0 / order)
                dts[i] = dt * round(min(max(factor, 0.1), 0.8), 2)
                redo.append(i)
            continue
        r = replace(r, dt=dt)
        raw[i] = r
        if not fixed and r.drift > settings.energy_tol:
            # Drift of an order-p method scales like dt^p: aim at half the tolerance. The factor
            # is rounded to two digits so that round-off in the measured drift (which differs
            # between the compiled and NumPy codes) does not leak into the step.
            factor = (0.5 * settings.energy_tol / r.drift) ** (1.0 / order)
            dts[i] = dt * round(min(max(factor, 0.1), 0.8), 2)
            redo.append(i)
    return np.array(redo, dtype=int)


def collide_batch(
    body: ModalBody,
    v,
    alpha,
    settings: CollisionSettings | None = None,
    *,
    initial=None,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
    step_judge: str = "energy",
    **overrides,
) -> list[CollisionResult]:
    """Integrate many collisions ``(v_i, alpha_i)`` on one mode set at once.

    The batch shares the mode set; every member keeps its own step, step refinements and edge
    quadrature, so its result does not depend on the other members. The compiled kernel
    (:mod:`restitution.dynamics.kernel`) runs the members on all cores; the NumPy reference path
    runs them one after the other.

    Parameters
    ----------
    body : ModalBody
        The body: its modes kept in the expansion (the disk: a ``ModeSet`` from ``get_modes``).
    v : float or array_like, shape (B,)
        Speeds towards the wall, units of ``c``, in (0, 1).
    alpha : float or array_like, shape (B,)
        Wall hardness, ``1 / R`` (the hardness of ``contact_law``); broadcast against ``v``.
    settings : CollisionSettings, optional
        Numerical settings; keyword ``overrides`` replace single fields.
    initial : (Q, P), optional
        Modal coordinates (``R``) and momenta (``m c``) of the vibrating disk, each of shape
        (N,) for every member or (B, N), in the order of ``body``: the free-flight state when
        the centre passes the start position (module docstring). Omitted: disks at rest.
    contact_law : ContactLaw, optional
        The law that pushes the body off the wall (:mod:`restitution.dynamics.contact`);
        default the paper's exponential wall.
    step_judge : {"energy", "epsilon"}
        What judges the step of an elastic body against a conservative law (:data:`STEP_JUDGES`).
        ``"energy"``: the relative energy drift, held to ``energy_tol`` (one run a member;
        what the sweeps and stores use). ``"epsilon"``: each member also runs at ``dt / 2`` and
        the Richardson estimate of epsilon's step error is held to ``energy_tol / 2`` (about
        three times the work). The drift can pass while epsilon is off: a sphere of 400 modes
        at ``v = 0.1``, ``alpha = 2000`` keeps a drift of 7.9e-8 with epsilon 1.4e-4 from its
        converged value (docs/numerics.md). A damped body or a non-conservative law is always
        judged by epsilon.

    Returns
    -------
    list of CollisionResult
        In the order of the inputs.
    """
    settings = _settings(settings, overrides)
    contact_law = _check_law(contact_law)
    if step_judge not in STEP_JUDGES:
        raise InputError(
            f"step_judge must be one of {', '.join(map(repr, STEP_JUDGES))}, not {step_judge!r}"
        )
    v, alpha = _check_inputs(v, alpha, body)
    initial = check_initial(initial, body, v.size)
    _check_damped(body, settings, initial)
    use_kernel(settings, contact_law)  # a refused backend fails before the work estimate
    damped = mode_damping(body) is not None
    check_work(body, v, alpha, settings, contact_law)
    # Each member's quadrature follows from its own alpha, never from its batch.
    n_phis = np.array([settings.n_phi or contact_law.nodes(body, float(a)) for a in alpha])
    t_start = time.perf_counter()
    if settings.dt is not None:
        dts = np.full(v.size, settings.dt)
    else:
        dts = settings.step_safety * initial_step(
            body, v, alpha, settings.integrator, settings.energy_tol, contact_law
        )
    raw: list[MemberRun | None] = [None] * v.size
    unresolved = []
    for n_phi in np.unique(n_phis):
        quad = body.surface_quadrature(int(n_phi))
        pending = np.nonzero(n_phis == n_phi)[0]
        for attempt in range(settings.max_refinements + 1):
            pending = _attempt(
                body,
                v,
                alpha,
                dts,
                pending,
                settings,
                quad,
                raw,
                attempt,
                initial,
                contact_law,
                step_judge,
            )
            if pending.size == 0:
                break
        unresolved.extend(pending.tolist())
    pending = np.array(unresolved, dtype=int)
    if pending.size and raw[pending[0]].step_error is not None:
        worst = pending[np.argmax([raw[i].step_error for i in pending])]
        raise CollisionError(
            f"epsilon's step error {raw[worst].step_error:.2e} still exceeds energy_tol / 2 = "
            f"{settings.energy_tol / 2:.1e} after {settings.max_refinements} step refinements "
            f"(dt = {raw[worst].dt:.3g}) at v = {v[worst]:.4g}, alpha = {alpha[worst]:.4g}; "
            "raise energy_tol or max_refinements"
        )
    if pending.size:
        worst = pending[np.argmax([raw[i].drift for i in pending])]
        raise CollisionError(
            f"energy drift {raw[worst].drift:.2e} still exceeds energy_tol = "
            f"{settings.energy_tol:.1e} after {settings.max_refinements} step refinements "
            f"(dt = {raw[worst].dt:.3g}) at v = {v[worst]:.4g}, alpha = {alpha[worst]:.4g}; "
            "raise energy_tol or max_refinements"
        )
    wall = time.perf_counter() - t_start
    results = []
    for i in range(v.size):
        r = raw[i]
        results.append(
            CollisionResult(
                method="modal",
                nu=body.nu,
                v=float(v[i]),
                alpha=float(alpha[i]),
                n_modes=len(body),
                epsilon=r.epsilon,
                energy_drift=r.drift,
                contact_time=r.contact_time,
                max_compression=r.max_compression,
                max_force=r.max_force,
                n_steps=int(r.steps),
                dt=float(r.dt),
                wall_time_s=wall / v.size,
                integrator=settings.integrator,
                mode_n=body.n.copy(),
                mode_l=body.l.copy(),
                mode_order=np.asarray(body.order).copy(),
                mode_energy_after=r.energy_after,
                mode_energy_mean=r.energy_mean,
                mode_energy_closest=r.energy_closest,
                history=r.history,
                energy_tol=None if r.step_error is not None else settings.energy_tol,
                mode_energy_before=energy_before(body, initial, i, v[i]),
                final_Q=r.final_Q,
                final_P=r.final_P,
                final_x0=r.final_x0,
                t_end=r.t_end,
                relaxation_time=float(getattr(body, "relaxation_time", 0.0)),
                energy_dissipated=_dissipated(r) if damped else 0.0,
                step_error=r.step_error,
            )
        )
    return results


def collide(
    body: ModalBody,
    v: float,
    alpha: float,
    settings: CollisionSettings | None = None,
    *,
    initial=None,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
    step_judge: str = "energy",
    **overrides,
) -> CollisionResult:
    """One collision of the disk with the wall (see :func:`collide_batch` for parameters;
    ``step_judge="epsilon"`` holds epsilon's own step error, not only the energy drift, to
    ``energy_tol / 2``: the default of the command ``restitution collide``).

    Examples
    --------
    >>> from restitution import get_modes
    >>> r = collide(get_modes(0.33, count=40), v=0.1, alpha=500)
    >>> 0.9 < r.epsilon < 1.0
    True
    """
    if np.ndim(v) or np.ndim(alpha):
        raise InputError("collide takes one speed v and one alpha; use collide_batch for several")
    return collide_batch(
        body,
        [v],
        [alpha],
        settings,
        initial=initial,
        contact_law=contact_law,
        step_judge=step_judge,
        **overrides,
    )[0]


def rank_modes(
    pool: ModalBody,
    count: int,
    v: float,
    alpha: float,
    settings: CollisionSettings | None = None,
    *,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
    **overrides,
) -> ModalBody:
    """The paper's mode selection: the ``count`` body of ``pool`` with the largest average
    energy during the contact of a preliminary run with the whole pool (section 4), against
    ``contact_law``."""
    if count > len(pool):
        raise InputError(f"cannot rank {count} body out of a pool of {len(pool)}")
    pre = collide(pool, v, alpha, settings, contact_law=contact_law, **overrides)
    top = np.argsort(-pre.mode_energy_mean, kind="stable")[:count]
    return pool.take(np.sort(top))
