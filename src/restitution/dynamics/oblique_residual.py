"""Oblique impact of a vibrating grain with one Coulomb contact and a static residual for the
modes it drops, normal and tangential (issue 63; docs/oblique.md, "A static residual for the
one-state route").

Units as :mod:`restitution.dynamics.oblique`: ``E = rho = R = 1`` of the grain, speeds in
``c``, spins in ``c / R``, times in ``R / c``, energies reported as fractions of the initial
kinetic energy ``E0``.

**Why.** :func:`~restitution.dynamics.oblique.oblique_collision` moves ``N`` modes against the
wall. Its truncated body is too stiff at the contact, normally and tangentially, so its
``beta`` at low speed lies far from the one-state contact's own limit (0.33-0.51 at 20-80
modes, ``v = 0.005``), and on hard walls its rigid stick constraint chatters (48-154 phases).
The dropped modes follow the load statically; keeping their flexibility instead of their
motion brings the route to its quasistatic twin at 20 modes (docs/oblique.md).

**The model.** The body, wall, coordinates and one Coulomb contact of
:func:`~restitution.dynamics.oblique.oblique_collision`, with the body's
:meth:`contact_residual` (the sphere's
:class:`~restitution.bodies.sphere.contact_residual.ContactResidual`: hats of the projected
radius about the contact axis):

* **normal:** the wall's forces on the nodes displaced by the residual
  (:class:`~restitution.dynamics.contact.residual_hats.HatWall`), which act on the kept
  coordinates as without it, plus the torque of the hats' motion;
* **tangential:** the contact's force ``F`` spread on the hats like the pressure, ``F p``
  (``p = P / F_n``), moves them in line by ``H_t F p``, so the pressure-weighted slip is
  ``v_s = v_kept + p . d(H_t F p)/dt = v_kept + F' C + F C' / 2`` (``C = p . H_t . p``; the
  power ``F v_s`` is then the kept motion's ``F v_kept`` plus the rate of the residual's
  energy ``F^2 C / 2``). Stick holds ``v_s = 0``, slip holds ``|F| = mu F_n``:
  :class:`~restitution.dynamics.one_state.OneStateFriction` per step (the discrete
  stick condition over the step's kept slip, clipped to Coulomb's bound). The stick force is a
  state, not the rigid constraint's: no events and no chatter.
* **Dundurs' coupling** (:attr:`ResidualSettings.tilt`, since stop 87; docs/oblique.md,
  "Dundurs' coupling"): the hats also tilt, ``V cos(psi)``, under the wall's tilting loads
  ``P1`` and the in-line forces ``T = F p``
  (:class:`~restitution.dynamics.contact.residual_hats.TiltedHatWall`, ``V = -H1 P1 - X T``),
  and the tilting loads move the surface in line by ``X^T P1``: the slip gains ``p . X^T
  dP1/dt``, and the kept motion's energy ``-P1 . X . dT/dt`` (the condensed wall energy's
  derivative in ``T``). ``T`` enters the wall's solve extrapolated from the last two steps (a
  step's lag let friction's dissipation fall by 4e-6 ``E0`` at 4000 steps per contact and 1e-6
  at 16000; extrapolated, 3e-8). Without it the kept modes of order 1 carry a share of the
  coupling that grows with their count: the residual route's drift in the modes.

**Integrator.** Velocity Verlet at a fixed step (second order; symplectic without friction),
the friction force after the drift from the half-step velocities, as
:mod:`restitution.dynamics.oblique_microslip`. The step is the smaller of ``step_safety * 2 /
omega_max`` (the kept modes and the wall's stiffness on the kept positions, a bound: the
residual only softens the contact; planned at a tenth of its ceiling and repeated at the
ceiling if met) and the Hertz contact time over ``steps_per_contact``.

**Energy.** ``E0 = kinetic + modes + V_eff + W_kept`` to the integration error (``V_eff`` the
condensed wall energy, ``W_kept = -int F v_kept dt`` and, with the tilt, ``+ int P1 . X .
dT``), reported as ``energy_balance``; friction's dissipation ``W_kept - F^2 C / 2`` (with the
tilt ``- P1 . X . T``) may not fall (checked every step; beyond
:data:`GAIN_TOL` the run is repeated at twice ``steps_per_contact``, twice at most, then
refused); after the contact it is the friction work.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Protocol, runtime_checkable

import numpy as np

from restitution.dynamics.contact.exponential import NEGLIGIBLE
from restitution.dynamics.contact.residual_hats import HatWall, TiltedHatWall
from restitution.dynamics.oblique import Grain, ObliqueCollision, RimBody, _check, collision_result
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
from restitution.dynamics.one_state import OneStateFriction
from restitution.dynamics.run import CollisionError
from restitution.errors import InputError, real

__all__ = [
    "GAIN_TOL",
    "RESIDUAL",
    "RESIDUAL_CHOICE",
    "ResidualBody",
    "ResidualSettings",
    "residual_collision",
    "residual_work",
]

RESIDUAL = "one-state residual"
"""The friction model's name in :class:`~restitution.dynamics.oblique.ObliqueCollision`."""

RESIDUAL_CHOICE = "residual"
"""The route's name among ``--friction-model``'s choices (``collide --angle``, ``law
--angle``)."""

GAIN_TOL = 1e-6
"""Friction's dissipation may fall by at most this much of ``E0`` in a run (the integration's
error; measured up to 2.3e-7)."""

_RETRIES = 6
_GAIN_RETRIES = 2  # doublings of steps_per_contact when friction's dissipation falls (below)
_REACH_MARGIN = 2.0  # the hats reach twice Hertz's compression plus the wall's negligible tail
_BEYOND_TOL = 1e-9  # a wall force beyond the hats larger than this share is refused


@runtime_checkable
class ResidualBody(RimBody, Protocol):
    """A :class:`~restitution.dynamics.oblique.RimBody` that knows the static flexibility of
    the modes it drops at its contact (the sphere's
    :class:`~restitution.bodies.sphere.cap.SphereCap`)."""

    nu: float

    def contact_residual(self, nodes, reach: float):
        """Hats (``radii``, ``normal``, ``tangential``, ``radius(count, rotation)``) out to
        the projected radius ``reach`` over the wall ``nodes``."""
        ...


@dataclass(frozen=True)
class ResidualSettings:
    """Numerical settings of :func:`residual_collision`.

    Attributes
    ----------
    steps_per_contact : int
        The step is at most the Hertz contact time over this (4000 and 8000 agree to 1e-4 in
        ``beta``, docs/oblique.md).
    step_safety : float
        Fraction of the stability bound ``2 / omega_max``.
    max_steps : int
        Refuse a run planned beyond this many steps.
    tilt : bool
        Give the residual Dundurs' coupling too (the tilting pressure and the in-line force's
        tilt, docs/oblique.md, "Dundurs' coupling"); ``False`` leaves the coupling to the kept
        modes alone, as before stop 87.
    """

    steps_per_contact: int = 4000
    step_safety: float = 0.5
    max_steps: int = 5_000_000
    tilt: bool = True

    def __post_init__(self):
        if not (isinstance(self.steps_per_contact, int) and self.steps_per_contact >= 100):
            raise InputError(
                f"steps_per_contact must be an integer >= 100, got {self.steps_per_contact!r}"
            )
        check_step_settings(self.step_safety, self.max_steps)
        if not isinstance(self.tilt, bool):
            raise InputError(f"tilt must be True or False, got {self.tilt!r}")


def _residual_body(body) -> ResidualBody:
    if not isinstance(body, ResidualBody):
        raise InputError(
            f"the static residual needs a body that knows its dropped modes' flexibility at the "
            f"contact (the sphere's cap_modes(...)); {type(body).__name__} does not: use "
            "oblique_collision without the residual"
        )
    return body


def _reach(body, v_n: float, alpha: float) -> float:
    """The hats' projected radius: ``sqrt(2 (2 delta + NEGLIGIBLE / alpha))``, ``delta``
    Hertz's largest compression from the contact time estimate (``t_c = 2.9433 delta / v``)."""
    delta = float(body.contact_time_estimate(v_n)) * v_n / 2.9433
    return math.sqrt(2.0 * (_REACH_MARGIN * delta + NEGLIGIBLE / alpha))


def residual_collision(
    body: RimBody,
    v_normal: float,
    v_tangential: float,
    mu: float,
    alpha: float,
    *,
    spin: float = 0.0,
    rotation: float = 0.0,
    settings: ResidualSettings | None = None,
    n_nodes: int | None = None,
) -> ObliqueCollision:
    """One oblique collision with one Coulomb contact and the dropped modes' static residual
    (module docs).

    Parameters as :func:`restitution.dynamics.oblique.oblique_collision`; ``body`` must know
    its residual (:class:`ResidualBody`: the sphere's cap); ``settings`` the step
    (:class:`ResidualSettings`). The result's ``friction`` is ``"one-state residual"``,
    ``regularisation`` ``None``, ``phases`` one entry and ``steps`` the Verlet steps.

    Examples
    --------
    >>> from restitution.bodies.sphere.cap import cap_modes
    >>> from restitution.bodies.sphere.modes import compute_sphere_modes
    >>> cap = cap_modes(compute_sphere_modes(0.3, count=6), azimuthal=1)
    >>> out = residual_collision(cap, 0.01, 0.01, 0.5, 300.0)
    >>> round(out.epsilon_normal, 4), round(out.beta, 3), abs(out.energy_balance) < 1e-5
    (0.9996, 0.327, True)
    """
    s = settings if settings is not None else ResidualSettings()
    if not isinstance(s, ResidualSettings):
        raise InputError(f"settings must be ResidualSettings, got {type(s).__name__}")
    v_n, v_t, w0, mu, alpha = _check(
        body, v_normal, v_tangential, mu, alpha, spin, "stick-slip", None, 1e-10
    )
    body = _residual_body(body)
    rot = real(rotation, "rotation", "(radians)")
    if not math.isfinite(rot):
        raise InputError(f"pass a finite rotation (radians), got {rot}")
    G = Grain(body, alpha, n_nodes)
    hats = body.contact_residual(G.nodes, _reach(body, v_n, alpha))
    e0 = 0.5 * G.m * (v_n**2 + v_t**2) + 0.5 * G.inertia * w0**2
    ceiling = stiffness_ceiling(G) * alpha * alpha * e0
    t_c = float(body.contact_time_estimate(v_n))
    t_max = 4.0 * approach_time(G, v_n) + 20.0 * t_c
    inputs = (v_n, v_t, w0, mu, alpha, rot)
    for attempt in range(_GAIN_RETRIES + 1):
        try:
            return run_planned(
                lambda plan, s=s: _run(G, hats, s, inputs, e0, plan, t_c, t_max),
                ceiling,
                _RETRIES,
                "soften the wall",
            )
        except _Gain as exc:
            if attempt == _GAIN_RETRIES:
                raise CollisionError(
                    f"friction's dissipation fell by {exc.gain:.2g} E0 during the run (more "
                    f"than {GAIN_TOL:g}) at {s.steps_per_contact} steps per contact time, "
                    f"after {_GAIN_RETRIES} doublings: lower the speed or the modes, or pass "
                    "ResidualSettings(steps_per_contact=...) larger still"
                ) from None
            s = replace(s, steps_per_contact=2 * s.steps_per_contact)
    raise AssertionError("unreachable")  # pragma: no cover


class _Gain(Exception):
    """Friction's dissipation fell by ``gain`` (a share of ``E0``) in a run: the step is too
    long for the stick force's compliance (:func:`residual_collision` halves it)."""

    def __init__(self, gain: float) -> None:
        super().__init__(gain)
        self.gain = gain


def _step(G, s: ResidualSettings, plan: float, t_c: float) -> float:
    wmax2 = float(G.w2.max()) if G.N else 0.0
    return min(planned_step(s.step_safety, wmax2, plan), t_c / s.steps_per_contact)


class _Contact:
    """The wall, the hats and the friction of one run: the forces at a placed state (with the
    tilt, ``T`` is the hats' in-line forces of the last step: the coupling lags a step)."""

    def __init__(self, G, hats, alpha: float, tilt: bool = False) -> None:
        self.G, self.hats, self.alpha, self.tilt = G, hats, alpha, tilt
        if tilt:
            self.wall = TiltedHatWall(hats.normal, hats.radii, alpha, hats.tilt, hats.cross)
        else:
            self.wall = HatWall(hats.normal, hats.radii, alpha)
        self.cutoff = -NEGLIGIBLE / alpha

    def place(self, x0, th, Q, Qd, T=None):
        G = self.G
        placed = G.nodes.jacobian(x0, th, Q, Qd, float(np.abs(Q) @ G.reach_k), self.cutoff)
        if placed is None:
            return None
        idx, weight, X, Yr, eta, J = placed
        rho, drho = self.hats.radius(idx.size, th)
        log_e = np.log(weight) + self.alpha * X
        P1 = None
        if self.tilt:
            cos, dcos = self.hats.azimuth(idx.size, th)
            T = np.zeros(len(self.hats)) if T is None else T
            e, P, P1, slope, tilt_slope, tilt_value = self.wall.solve_tilted(log_e, rho, cos, T)
            slope = slope + cos * tilt_slope
            tilt_torque = -float(e @ (tilt_value * dcos))
        else:
            e, P, slope = self.wall.solve(log_e, rho)
            tilt_torque = 0.0
        Fn = float(e.sum())
        if Fn <= 0.0:
            return None
        p = e / Fn
        if self.wall.beyond > _BEYOND_TOL:
            raise CollisionError(
                f"the contact reached beyond the residual's hats ({self.wall.beyond:.2g} of the "
                "wall force): lower the speed or harden the wall"
            )
        torque = tilt_torque - float(e @ (slope * drho))  # the hats' own motion as it turns
        return {"e": e, "P": P, "P1": P1, "Fn": Fn, "p": p, "lever": float(p @ (X - x0)),
                "Yr": Yr, "J": J, "peta": float(p @ eta), "hat_torque": torque}  # fmt: skip


def _run(G, hats, s, inputs, e0, plan, t_c, t_max) -> ObliqueCollision:
    v_n, v_t, w0, mu, alpha, rot = inputs
    N, m, I, w2 = G.N, G.m, G.inertia, G.w2
    wmax2 = float(w2.max()) if N else 0.0
    limit = wmax2 + plan
    dt = _step(G, s, plan, t_c)
    if t_max / dt > s.max_steps:
        raise InputError(
            f"the residual run would take up to {t_max / dt:.3g} Verlet steps (dt = {dt:.3g} "
            f"R/c over {t_max:.3g} R/c), more than max_steps = {s.max_steps}: lower "
            "steps_per_contact or the modes, or soften the wall"
        )
    contact = _Contact(G, hats, alpha, s.tilt)
    friction = OneStateFriction(hats.tangential)
    K = len(hats)
    T_used = np.zeros(K)  # the hats' in-line forces the last wall solve took
    T_last = np.zeros(K)  # the friction's in-line forces on the hats a step before
    P1_old, pr_old = np.zeros(K), None
    x0, th = G.start_position(0.5 * m * v_n**2), rot
    Q, Qd = np.zeros(N), np.zeros(N)
    vx, vy, om = v_n, v_t, -w0

    def accel(pl, Q, F):
        if pl is None:
            return 0.0, 0.0, 0.0, -w2 * Q, 0.0
        ath = (float(pl["e"] @ pl["Yr"]) + pl["hat_torque"] + F * pl["lever"]) / I
        aQ = -w2 * Q + pl["J"].pull(-pl["e"], F * pl["p"]) / m
        nX, _ = pl["J"].norms()
        bound = alpha * float(pl["e"] @ (1.0 / m + pl["Yr"] ** 2 / I + nX / m))
        return -pl["Fn"] / m, F / m, ath, aQ, bound

    def slip(pl, vy, om, Qd):
        return vy + om * pl["lever"] + float(pl["p"] @ pl["J"].dY(Qd))

    pl = contact.place(x0, th, Q, Qd)
    F = 0.0
    ax, ay, ath, aQ, _ = accel(pl, Q, F)
    s_cur = None if pl is None else vy + om * pl["lever"] + pl["peta"]
    work = lever_int = tau_int = 0.0  # friction's work on the kept motion, the two moments
    t, steps, gain, top = 0.0, 0, 0.0, 0.0
    while True:
        if t > t_max:
            raise CollisionError(
                f"the grain did not leave the wall within t = {t_max:.3g} R/c; check v and alpha"
            )
        vx, vy, om = vx + 0.5 * dt * ax, vy + 0.5 * dt * ay, om + 0.5 * dt * ath
        Qd = Qd + 0.5 * dt * aQ
        lev = 0.0 if pl is None else F * (1.0 - pl["lever"])
        tau = 0.0 if pl is None else float(pl["e"] @ pl["Yr"]) + pl["hat_torque"]
        if pl is not None:
            work += 0.25 * dt * F * (s_cur + slip(pl, vy, om, Qd))
        x0, th, Q = x0 + dt * vx, th + dt * om, Q + dt * Qd
        T_now = np.zeros(K) if pl is None else F * pl["P"] / pl["Fn"]
        T_new = 2.0 * T_now - T_last  # extrapolated to the step's end: the lag's second order
        T_last = T_now
        pl = contact.place(x0, th, Q, Qd, T_new)
        if pl is None:
            F = friction.step(np.zeros(1), 0.0, 0.0, mu)
            P1_new, pr_old = np.zeros(K), None
        else:
            s_half = vy + om * pl["lever"] + pl["peta"]
            ds = s_half * dt
            P1_new = P1_old if pl["P1"] is None else pl["P1"]
            if pl["P1"] is not None:
                pr = pl["P"] / pl["Fn"]
                pbar = pr if pr_old is None else 0.5 * (pr + pr_old)
                ds += float(pbar @ (hats.cross.T @ (P1_new - P1_old)))  # the tilt's slip
                work -= float(0.5 * (P1_new + P1_old) @ (hats.cross @ (T_new - T_used)))
                pr_old = pr
            F = friction.step(pl["P"], 0.0, ds, mu)
        T_used, P1_old = T_new, P1_new
        ax, ay, ath, aQ, bound = accel(pl, Q, F)
        if wmax2 + bound > limit:
            raise Unstable(bound)
        vx, vy, om = vx + 0.5 * dt * ax, vy + 0.5 * dt * ay, om + 0.5 * dt * ath
        Qd = Qd + 0.5 * dt * aQ
        spring = V = 0.0
        if pl is not None:
            s_cur = slip(pl, vy, om, Qd)
            work += 0.25 * dt * F * (s_half + s_cur)
            pr = pl["P"] / pl["Fn"]
            spring = 0.5 * F * F * float(pr @ hats.tangential @ pr)
            if pl["P1"] is not None:
                spring += F * float(pl["P1"] @ (hats.cross @ pr))
            V = contact.wall.energy(pl["e"])
            lever_int += 0.5 * dt * (lev + F * (1.0 - pl["lever"]))
            tau_int += 0.5 * dt * (tau + float(pl["e"] @ pl["Yr"]) + pl["hat_torque"])
        else:
            lever_int += 0.5 * dt * lev
            tau_int += 0.5 * dt * tau
        dissipated = -work - spring
        gain, top = max(gain, top - dissipated), max(top, dissipated)
        t += dt
        steps += 1
        if not math.isfinite(vx + vy + om + float(Qd @ Qd)):
            raise Unstable(REPLAN * limit)
        if left_the_wall(G, x0, th, Q, vx, vy, om, Qd, alpha):
            break
    if gain > GAIN_TOL * e0:
        raise _Gain(gain / e0)
    inputs_out = (v_n, v_t, w0, mu, alpha, RESIDUAL, None)
    return collision_result(G, (Q, vx, vy, om, Qd), V, (-work, lever_int, tau_int), e0,
                            v_t - w0, inputs_out, ((RESIDUAL, 0.0),), t, steps, None)  # fmt: skip


# Wall time of a run over its planned steps times one timed force evaluation (the nodes placed a
# step apart, the hats' solve warm, the products): 1.91-3.23 in five runs with the tilt's
# residual (the rigid sphere at alpha = 500; 20 modes at 2000 and 8000; 40 at 8000, and at 2000
# with v = 0.02; v = 0.005, tan(theta)/mu = 0.3, orders 0 and 1; one core of this 2-core
# machine, 5 Dec 2026, stop 87; 1.56-1.77 without it, stop 86; law's four points of the steel
# ball: 2.16): the solve takes more Newton steps in the run than in the timed evaluation, most
# at alpha = 8000 through the stick/slip changes.
_STEP_OVER_TIMING = 2.3
_WORK_SPREAD = 1.5


def residual_work(
    body: RimBody,
    v_normal: float,
    v_tangential: float,
    alpha: float,
    *,
    spin: float = 0.0,
    settings: ResidualSettings | None = None,
    n_nodes: int | None = None,
    repeats: int = 4,
) -> ObliqueWork:
    """The estimated time and memory of :func:`residual_collision` before it starts: its
    planned steps (approach, contact and departure) times one force evaluation at the
    compression ``v t_c / pi``, timed here (best of ``repeats``), times a measured factor;
    ``spread`` the measured ratio's range either way. Builds the residual (a few seconds)."""
    import time

    s = settings if settings is not None else ResidualSettings()
    v_n, v_t, w0 = float(v_normal), float(v_tangential), float(spin)
    body = _residual_body(body)
    G = Grain(body, alpha, n_nodes)
    e0 = 0.5 * G.m * (v_n**2 + v_t**2) + 0.5 * G.inertia * w0**2
    t_c = float(body.contact_time_estimate(v_n))
    dt = _step(G, s, PILOT * stiffness_ceiling(G) * alpha * alpha * e0, t_c)
    steps = (2.0 * approach_time(G, v_n) + t_c) / dt
    hats = body.contact_residual(G.nodes, _reach(body, v_n, alpha))
    x0 = -1.0 + v_n * t_c / math.pi
    Q = np.zeros(G.N)
    contact = _Contact(G, hats, alpha, s.tilt)
    for x in np.linspace(-1.0, x0, 41):  # warm, as the run's solves start from the step before
        contact.place(x, 0.0, Q, Q)
    best = math.inf
    for i in range(repeats):  # a step apart, as the run's: its solve has a step to make
        start = time.perf_counter()
        pl = contact.place(x0 + (i % 2) * v_n * dt, 0.0, Q, Q)
        if pl is not None:
            _ = (pl["J"].pull(-pl["e"], pl["p"]), pl["J"].norms(), pl["J"].dY(Q))
        best = min(best, time.perf_counter() - start)
    K = len(hats)
    memory = float(body.wall_node_memory(alpha, n_nodes)) + 8.0 * (
        6 * K * K + 4 * len(G.nodes) + 4 * len(G.nodes) * max(G.N, 1) // 8
    )
    return ObliqueWork(G.N, len(G.nodes), steps * _STEP_OVER_TIMING * best, memory, _WORK_SPREAD)
