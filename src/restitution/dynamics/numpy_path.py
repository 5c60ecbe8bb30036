"""The NumPy reference path of the collision: every member stepped by the integrators of
:mod:`restitution.dynamics.integrators`, with recorded histories when asked.

Units: ``E = rho = R = 1``; times in ``R / c``. The compiled kernel
(:mod:`restitution.dynamics.kernel`) performs the same arithmetic; the two agree to round-off.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from restitution.bodies.base import ModalBody
from restitution.bodies.viscoelastic import mode_damping
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.integrators import (
    INTEGRATORS,
    System,
    initial_state,
    mode_energies,
    total_energy,
)
from restitution.dynamics.results import History
from restitution.dynamics.run import (
    UNSTABLE,
    CollisionError,
    MemberRun,
    Unstable,
    contact_mean,
    timeout_message,
)
from restitution.dynamics.settings import CollisionSettings
from restitution.dynamics.start import start_of

__all__ = ["run_numpy"]


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
    body: ModalBody,
    v: np.ndarray,
    alpha: np.ndarray,
    dt: float,
    settings: CollisionSettings,
    quad,
    abort_drift: float | None = None,
    initial=None,
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> list[MemberRun]:
    """Integrate a batch with one fixed step; returns one dict of raw results per member.

    With ``abort_drift``, a run whose energy drift exceeds it (or overflows) stops at once with
    :class:`Unstable` so that the caller can retry with a smaller step.
    """
    integrator = INTEGRATORS[settings.integrator]
    m = body.mass
    B = v.size
    e0 = 0.5 * m * v**2
    begin = start_of(body, v, alpha, quad, initial, contact_law)
    system = System(
        omega=body.omega,
        mass=m,
        quad=quad,
        alpha=alpha,
        damping=mode_damping(body),
        law=contact_law,
    )
    state = initial_state(system, begin.x0, m * v, begin.Q, begin.P)
    t_max = float(np.max(begin.t_max))
    N = len(body)
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
            raise CollisionError(timeout_message(state.t, steps, dt, settings))
        state = integrator.step(system, state, dt)
        steps += 1
        a = active
        e_all = mode_energies(system, state)
        h = state.p0**2 / (2.0 * m) + e_all.sum(axis=1) + state.V + state.dissipated
        if not np.all(np.isfinite(h)):
            if abort_drift is not None:
                raise Unstable()
            raise CollisionError(
                f"the integration overflowed at t = {state.t:.3g} with dt = {dt:.3g}; "
                "the step is far too large for this wall hardness: reduce dt"
            )
        track.drift[a] = np.maximum(track.drift[a], np.abs(h - track.h0[a]) / track.h0[a])
        if abort_drift is not None and np.any(track.drift[a] > abort_drift):
            raise Unstable()
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
        done = leaving & contact_law.separated(gap, system.alpha, state.V, track.e0[a])
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
                "dissipated": float(np.broadcast_to(state.dissipated, state.x0.shape)[i])
                / e0[orig],
            }  # the rest is known when every member has finished
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
        history = None
        if record:
            rows = hist[i]
            history = History(
                t=np.array([x[0] for x in rows]),
                x0=np.array([x[1] for x in rows]),
                v=np.array([x[2] for x in rows]),
                force=np.array([x[3] for x in rows]),
                mode_energy=np.array([x[4] for x in rows]) / e0[i],
                Q=np.array([x[5] for x in rows]),
            )
        out.append(
            MemberRun(
                **r,
                drift=float(track.drift[i]),
                contact_time=float(contact),
                max_compression=float(track.max_comp[i]),
                max_force=float(track.max_force[i]),
                energy_mean=contact_mean(track.mean_e[i], contact, e0[i]),
                energy_closest=track.closest_e[i] / e0[i],
                history=history,
            )
        )
    return out


def run_numpy(
    body, v, alpha, dts, settings, quad, abort, initial, contact_law=EXPONENTIAL_WALL
) -> list[MemberRun | str]:
    """Run members one by one on the NumPy reference path (same contract as the kernel)."""
    out: list[MemberRun | str] = []
    for i in range(v.size):
        one = None if initial is None else (initial[0][i : i + 1], initial[1][i : i + 1])
        a = alpha[i : i + 1]
        try:
            out.append(
                _run(body, v[i : i + 1], a, dts[i], settings, quad, abort, one, contact_law)[0]
            )
        except Unstable:
            out.append(UNSTABLE)
    return out
