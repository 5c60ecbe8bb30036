"""Oblique impact of a vibrating grain with Coulomb friction point by point (microslip), in modes.

Units as :mod:`restitution.dynamics.oblique`: ``E = rho = R = 1`` of the grain, speeds in
``c``, spins in ``c / R``, times in ``R / c``, energies reported as fractions of the initial
kinetic energy ``E0``. docs/oblique.md ("Microslip in the modal route") gives the measured
checks.

**The model.** The body, wall, coordinates and kinetic energy of
:func:`restitution.dynamics.oblique.oblique_collision`, with friction per wall node instead of
one Coulomb contact: node ``j`` carries its own tangential force ``t_j`` (on the grain, along
the wall, in the plane of incidence), regularised as the finite-element judge's
(:mod:`restitution.fem.oblique_impact`): a tangential spring ``kappa`` times as stiff as the
wall's normal stiffness at that node, ``alpha e_j``, an elastic predictor and a return to the
Coulomb bound each step,

    t_j <- clip(t_j - kappa alpha e_j s_j dt, -mu e_j, mu e_j),     s_j = Y_j',

so each node sticks or slips on its own: Mindlin and Deresiewicz's annulus of microslip (law
(b) of docs/oblique.md), where ``oblique_collision`` has one state for the whole contact (law
(a)). A stuck node moves elastically by at most ``mu / (kappa alpha)``: Coulomb's law point by
point is the limit ``kappa -> infinity``. A node leaving the contact takes its bound ``mu e_j``
to zero and its force with it; nodes outside the active set carry none.

**Generalised forces** (``e_j = w_j exp(alpha X_j)``, ``Y_j - y0`` and ``X_j - x0`` the lever
arms, ``M = diag(m, m, I, m, ...)``):

    x0: -sum e_j,    y0: sum t_j,    Theta: sum e_j (Y_j - y0) + sum t_j (X_j - x0),
    Q_k: -m omega_k^2 Q_k - sum e_j dX_j/dQ_k + sum t_j dY_j/dQ_k.

**Integrator.** Velocity Verlet with a fixed step (second order; symplectic without friction),
the friction force updated after the drift with the half-step velocities, as the finite-element
judge. The work of friction is booked exactly as the kicks change the kinetic energy (``sum_j
t_j`` times the mean of ``s_j`` over each half kick), so the energy balance holds the
integration error of the conservative forces only. Stable for ``dt < 2 / omega_max``, and the
wall's and the springs' stiffness is bounded by its ``M^-1``-weighted trace:

    omega_max^2 <= omega_N^2 + alpha sum_j e_j (|a_j|^2 + kappa |b_j|^2),
    |a_j|^2 = 1/m + (Y_j - y0)^2 / I + |dX_j/dQ|^2 / m,
    |b_j|^2 = 1/m + (X_j - x0)^2 / I + |dY_j/dQ|^2 / m.

The step is ``step_safety * 2 / omega_max`` for a planned bound: the wall force ``sum e_j =
alpha V`` is at most ``alpha E0`` (energy), so ``alpha^2 E0`` times the largest ``|a_j|^2 +
kappa |b_j|^2`` of the nodes near the pole, with a margin of 1.2, bounds the whole run (the
ceiling; measured 10-100 times the largest value met, as the wall's energy at its peak is a
small part of ``E0``). A run is first planned for a tenth of the ceiling; one that meets a
larger bound is repeated at the ceiling (or 1.5 times the bound met, if larger).

Start and stop as :func:`~restitution.dynamics.oblique.oblique_collision`: the undeformed grain
starts where its wall energy is ``CONTACT_TOL`` of the normal kinetic energy, and the run ends
when the grain moves away and even its free vibration cannot bring a node within ``STOP_LOG /
alpha`` of the wall.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.dynamics.contact.exponential import NEGLIGIBLE
from restitution.dynamics.oblique import (
    Grain,
    ObliqueCollision,
    RimBody,
    _check,
    collision_result,
)
from restitution.dynamics.oblique_cost import ObliqueWork
from restitution.dynamics.oblique_verlet import (
    PILOT,
    REPLAN,
    Unstable,
    approach_time,
    check_step_settings,
    left_the_wall,
    planned_step,
    run_planned,
    stiffness_ceiling,
)
from restitution.dynamics.run import CollisionError
from restitution.errors import InputError, real

__all__ = ["MICROSLIP", "MicroslipSettings", "microslip_collision", "microslip_work"]

MICROSLIP = "microslip"
"""The friction model's name in :class:`~restitution.dynamics.oblique.ObliqueCollision`."""

_RETRIES = 8


@dataclass(frozen=True)
class MicroslipSettings:
    """Numerical settings of :func:`microslip_collision`.

    Attributes
    ----------
    kappa : float
        Tangential spring over the wall's normal stiffness, node by node (Coulomb's law is
        ``kappa -> infinity``; the finite-element judge's default is 64).
    step_safety : float
        Fraction of the stability bound ``2 / omega_max`` taken as the step.
    max_steps : int
        Refuse a run planned beyond this many steps (the message says the steps, the step and
        the time span; :func:`microslip_work` estimates the wall time).
    """

    kappa: float = 64.0
    step_safety: float = 0.5
    max_steps: int = 5_000_000

    def __post_init__(self):
        k = real(self.kappa, "kappa", "> 0 (try 16-1024)")
        if not (math.isfinite(k) and k > 0.0):
            raise InputError(f"kappa must be a finite number > 0 (try 16-1024), got {k}")
        check_step_settings(self.step_safety, self.max_steps)


def microslip_collision(
    body: RimBody,
    v_normal: float,
    v_tangential: float,
    mu: float,
    alpha: float,
    *,
    spin: float = 0.0,
    rotation: float = 0.0,
    settings: MicroslipSettings | None = None,
    n_nodes: int | None = None,
) -> ObliqueCollision:
    """One oblique collision with friction point by point (module docs).

    Parameters as :func:`restitution.dynamics.oblique.oblique_collision`; ``settings`` the
    regularisation ``kappa`` and the step (:class:`MicroslipSettings`). The result's
    ``friction`` is ``"microslip"``, its ``regularisation`` is ``kappa`` (a ratio, not a
    speed), ``phases`` holds one entry and ``steps`` the Verlet steps of the accepted run.

    Examples
    --------
    >>> from restitution.bodies.disk.modes import compute_modes
    >>> from restitution.bodies.disk.rim import rim_modes
    >>> rim = rim_modes(compute_modes(0.33, count=6))
    >>> out = microslip_collision(rim, 0.05, 0.05, 0.5, 100.0)
    >>> round(out.epsilon_normal, 3), round(out.beta, 2), abs(out.energy_balance) < 1e-3
    (0.963, 0.18, True)
    """
    s = settings if settings is not None else MicroslipSettings()
    if not isinstance(s, MicroslipSettings):
        raise InputError(f"settings must be MicroslipSettings, got {type(s).__name__}")
    v_n, v_t, w0, mu, alpha = _check(
        body, v_normal, v_tangential, mu, alpha, spin, "stick-slip", None, 1e-10
    )
    rot = real(rotation, "rotation", "(radians)")
    if not math.isfinite(rot):
        raise InputError(f"pass a finite rotation (radians), got {rot}")
    G = Grain(body, alpha, n_nodes)
    e0 = 0.5 * G.m * (v_n**2 + v_t**2) + 0.5 * G.inertia * w0**2
    ceiling = stiffness_ceiling(G, float(s.kappa)) * alpha * alpha * e0
    t_max = 4.0 * approach_time(G, v_n) + 20.0 * float(body.contact_time_estimate(v_n))
    return run_planned(
        lambda plan: _run(G, s, v_n, v_t, w0, mu, alpha, rot, e0, plan, t_max),
        ceiling,
        _RETRIES,
        "lower kappa or soften the wall",
    )


# Wall time of a run over its planned steps times one timed evaluation of the active nodes'
# Jacobians and their products at the compression v t_c / pi (microslip_work): median 1.30 of
# 11 runs (disk at 40, 160, 320 modes, alpha = 2000, v = 0.005, tan(theta)/mu = 0.3 and 2; 20
# modes at alpha = 100, 500 and v = 0.005-0.2; the sphere's orders 0, 1 of 20 modes and all its
# orders at psi = 0.25), range 0.96 to 4.83 (the slow end: the disk's 20 modes, where the
# per-step overhead outweighs the timed products); OPENBLAS_NUM_THREADS=1, this 2-core machine
# beside one other run, 4 Dec 2026, with the Jacobians unformed (stop 80; with them formed:
# median 1.11 of 20 runs, range 0.88 to 4.8, 3 Dec 2026).
_STEP_OVER_TIMING = 1.30
_WORK_SPREAD = 4.5


def microslip_work(
    body: RimBody,
    v_normal: float,
    v_tangential: float,
    alpha: float,
    *,
    spin: float = 0.0,
    settings: MicroslipSettings | None = None,
    n_nodes: int | None = None,
    repeats: int = 5,
) -> ObliqueWork:
    """The estimated time and memory of :func:`microslip_collision` before it starts: its
    planned Verlet steps (approach, contact and departure at the first plan's step) times one
    step, timed here (the Jacobians of the nodes active at the compression ``v t_c / pi`` and
    their products, best of ``repeats``) times a measured factor; ``spread`` the measured
    ratio's range either way."""
    import time

    s = settings if settings is not None else MicroslipSettings()
    v_n, v_t, w0 = float(v_normal), float(v_tangential), float(spin)
    G = Grain(body, alpha, n_nodes)
    e0 = 0.5 * G.m * (v_n**2 + v_t**2) + 0.5 * G.inertia * w0**2
    plan = PILOT * stiffness_ceiling(G, float(s.kappa)) * alpha * alpha * e0
    dt = planned_step(s.step_safety, float(G.w2.max()) if G.N else 0.0, plan)
    t_c = float(body.contact_time_estimate(v_n))
    steps = (2.0 * approach_time(G, v_n) + t_c) / dt
    x0 = -1.0 + v_n * t_c / math.pi
    Q = np.zeros(G.N)
    best = math.inf
    active = 0
    for _ in range(repeats):
        start = time.perf_counter()
        placed = G.nodes.jacobian(x0, 0.0, Q, Q, 0.0, -NEGLIGIBLE / alpha)
        if placed is not None:
            _, _, X, Yr, _, J = placed
            e = np.exp(alpha * X)
            _ = (J.pull(-e, e), J.dY(Q), J.norms())
            active = X.size
        best = min(best, time.perf_counter() - start)
    # the nodes' build is the peak; a step adds products over the active rows only
    memory = float(body.wall_node_memory(alpha, n_nodes)) + 8.0 * (
        4 * max(active, 1) * max(G.N, 1) + 4 * len(G.nodes)
    )
    return ObliqueWork(G.N, len(G.nodes), steps * _STEP_OVER_TIMING * best, memory, _WORK_SPREAD)


def _run(G, s, v_n, v_t, w0, mu, alpha, rot, e0, plan, t_max) -> ObliqueCollision:
    N, m, I = G.N, G.m, G.inertia
    nodes, kappa, w2 = G.nodes, float(s.kappa), G.w2
    cutoff = -NEGLIGIBLE / alpha
    wmax2 = float(w2.max()) if N else 0.0
    limit = wmax2 + plan
    dt = planned_step(s.step_safety, wmax2, plan)
    if t_max / dt > s.max_steps:
        raise InputError(
            f"the microslip run would take up to {t_max / dt:.3g} Verlet steps (dt = {dt:.3g} "
            f"R/c over {t_max:.3g} R/c), more than max_steps = {s.max_steps}: lower kappa or "
            "the modes, or soften the wall"
        )
    x0, th = G.start_position(0.5 * m * v_n**2), rot
    Q, Qd = np.zeros(N), np.zeros(N)
    vx, vy, om = v_n, v_t, -w0
    tang = np.zeros(len(nodes))  # t_j of every node (zero off the active set)

    def place(x0, th, Q, Qd):
        """``(index, X - x0, Y - y0, J, e, dY/dQ @ Qd)`` of the active nodes (``J`` their
        :class:`~restitution.bodies.node_jacobian.NodeJacobian`), or ``None``: two passes (``Q``,
        ``Qd``)."""
        placed = nodes.jacobian(x0, th, Q, Qd, float(np.abs(Q) @ G.reach_k), cutoff)
        if placed is None:
            return None
        idx, weight, X, Yr, eta, J = placed
        return idx, X - x0, Yr, J, weight * np.exp(alpha * X), eta

    def accel(pl, Q, ft):
        """``(ax, ay, theta'', Q'')`` and the stiffness bound (module docs): one pass."""
        if pl is None:
            return 0.0, 0.0, 0.0, -w2 * Q, 0.0
        _, Xr, Yr, J, e, _ = pl
        ath = (float(e @ Yr) + float(ft @ Xr)) / I
        aQ = -w2 * Q + J.pull(-e, ft) / m
        nX, nY = J.norms()
        a2 = 1.0 / m + Yr**2 / I + nX / m
        b2 = 1.0 / m + Xr**2 / I + nY / m
        bound = alpha * float(e @ (a2 + kappa * b2))
        return -float(e.sum()) / m, float(ft.sum()) / m, ath, aQ, bound

    def moments(pl, ft):
        """``sum t_j (R - (X_j - x0))`` and ``sum e_j (Y_j - y0)``: the two corrections."""
        return (0.0, 0.0) if pl is None else (float(ft @ (1.0 - pl[1])), float(pl[4] @ pl[2]))

    # The slip s_j = vy + om (X_j - x0) + dY_j/dQ @ Qd is linear in Qd: with the nodes placed
    # (dY/dQ @ Qd from the placing pass) and dY/dQ @ Q'' after each force (one pass), every
    # kick's slip follows without another pass over the modes.
    pl = place(x0, th, Q, Qd)
    ft = np.zeros(0 if pl is None else pl[0].size)
    ax, ay, ath, aQ, bound = accel(pl, Q, ft)
    s_cur = yQd = yaQ = None
    if pl is not None:
        yQd, yaQ = pl[5], pl[3].dY(aQ)  # dY/dQ @ Qd and @ Q''
        s_cur = vy + om * pl[1] + yQd
    work = lever_int = tau_int = 0.0  # friction's work on the grain (<= 0), the two moments
    t, steps, bound_max = 0.0, 0, bound
    while True:
        if t > t_max:
            raise CollisionError(
                f"the grain did not leave the wall within t = {t_max:.3g} R/c; check v and alpha"
            )
        # first half kick, with the friction of the step before
        vx, vy, om = vx + 0.5 * dt * ax, vy + 0.5 * dt * ay, om + 0.5 * dt * ath
        Qd = Qd + 0.5 * dt * aQ
        lev, tau = moments(pl, ft)
        if pl is not None:
            s_half = vy + om * pl[1] + (yQd + 0.5 * dt * yaQ)
            work += 0.25 * dt * float(ft @ (s_cur + s_half))
        # drift, then the nodes' friction: elastic predictor and return to the bound
        x0, th, Q = x0 + dt * vx, th + dt * om, Q + dt * Qd
        pl = place(x0, th, Q, Qd)
        if pl is None:
            tang[:] = 0.0
            ft = np.zeros(0)
        else:
            idx, e, yQd = pl[0], pl[4], pl[5]
            prev = tang[idx]
            tang[:] = 0.0
            s_half = vy + om * pl[1] + yQd
            cap = mu * e
            ft = np.clip(prev - kappa * alpha * e * s_half * dt, -cap, cap)
            tang[idx] = ft
        ax, ay, ath, aQ, bound = accel(pl, Q, ft)
        bound_max = max(bound_max, bound)
        if wmax2 + bound > limit:
            raise Unstable(bound)
        # second half kick
        vx, vy, om = vx + 0.5 * dt * ax, vy + 0.5 * dt * ay, om + 0.5 * dt * ath
        Qd = Qd + 0.5 * dt * aQ
        if pl is not None:
            yaQ = pl[3].dY(aQ)
            yQd = yQd + 0.5 * dt * yaQ
            s_cur = vy + om * pl[1] + yQd
            work += 0.25 * dt * float(ft @ (s_half + s_cur))
        lev2, tau2 = moments(pl, ft)
        lever_int += 0.5 * dt * (lev + lev2)
        tau_int += 0.5 * dt * (tau + tau2)
        t += dt
        steps += 1
        V = 0.0 if pl is None else float(pl[4].sum()) / alpha
        h = 0.5 * m * (vx**2 + vy**2 + float(Qd @ Qd + w2 @ (Q * Q))) + 0.5 * I * om**2 + V
        if not math.isfinite(h):
            raise Unstable(REPLAN * limit)
        if left_the_wall(G, x0, th, Q, vx, vy, om, Qd, alpha):
            break
    inputs = (v_n, v_t, w0, mu, alpha, MICROSLIP, kappa)
    return collision_result(G, (Q, vx, vy, om, Qd), V, (-work, lever_int, tau_int), e0,
                            v_t - w0, inputs, ((MICROSLIP, 0.0),), t, steps, None)  # fmt: skip
