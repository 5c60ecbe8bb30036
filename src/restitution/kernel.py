"""Compiled collision kernel: the splitting integrators and all bookkeeping in one loop (numba).

Units: ``E = rho = R = 1``; times in ``R / c``.

This is the production path of :func:`restitution.collision.collide_batch` for the symplectic
splittings ``split`` (Strang, second order) and ``split4`` (Yoshida, fourth order). It performs,
per batch member and entirely in compiled code, exactly the arithmetic of the NumPy reference
path (:mod:`restitution.integrators`, :mod:`restitution.wall` and ``collision._run``):

* the wall terms order by order (eqs. 40-42, 45) over the prefix of provably active nodes;
* the half kicks of the wall and the exact harmonic free flow (the two half kicks between
  substeps merged into one, fused with the flow and the order sums in one pass over the
  modes);
* energy drift, contact time, compression, force, contact-averaged and closest mode energies;
* the rigorous stop test every ``CHECK_EVERY`` steps.

Only the summation order of reductions and the merged kicks differ from the NumPy path, so the
two agree to round-off (checked to 1e-12 in ``tests/test_kernel.py``). Members of a batch are
independent: a pool of threads (``numba.get_num_threads()`` of them) takes them one at a time,
and each has its own step, so a member's result never depends on which other points share its
batch or which thread ran it (the same compiled function runs every member, bit for bit).
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np
from numba import njit

__all__ = ["CHECK_EVERY", "STATUS_OK", "STATUS_UNSTABLE", "STATUS_TIMEOUT", "run_batch"]

CHECK_EVERY = 8
"""Steps between two evaluations of the stop test (as in the NumPy path)."""

STATUS_OK = 0
STATUS_UNSTABLE = 1  # drift above the abort level, or overflow
STATUS_TIMEOUT = 2  # no separation within t_max or max_steps

# Nodes whose exponent is certainly below -_NEGLIGIBLE are skipped (see wall.active_nodes).
_NEGLIGIBLE = 40.0

# Reassociation lets the compiler vectorise the sums over orders and modes; it changes results
# only at round-off. No "nnan"/"ninf": the overflow test relies on isfinite.
_FAST = {"reassoc", "contract", "nsz"}


@njit(cache=True, nogil=True, fastmath=_FAST)
def _order_sums(Q, C, S, starts, ab):
    """Per-order amplitudes ``a_i = sum Q_k C_k``, ``b_i = sum Q_k S_k`` into ``ab``."""
    K = starts.size - 1
    for i in range(K):
        a = 0.0
        b = 0.0
        for k in range(starts[i], starts[i + 1]):
            a += Q[k] * C[k]
            b += Q[k] * S[k]
        ab[i] = a
        ab[K + i] = b


@njit(cache=True, nogil=True, fastmath=_FAST)
def _rows_dot(trig, J, ab, x):
    """``x[j] = trig[j] . ab`` for ``j < J``, four rows at a time (four independent sums
    sharing each load of ``ab``)."""
    K2 = ab.size
    j = 0
    while j + 4 <= J:
        r0 = trig[j]
        r1 = trig[j + 1]
        r2 = trig[j + 2]
        r3 = trig[j + 3]
        s0 = 0.0
        s1 = 0.0
        s2 = 0.0
        s3 = 0.0
        for i in range(K2):
            t = ab[i]
            s0 += r0[i] * t
            s1 += r1[i] * t
            s2 += r2[i] * t
            s3 += r3[i] * t
        x[j] = s0
        x[j + 1] = s1
        x[j + 2] = s2
        x[j + 3] = s3
        j += 4
    while j < J:
        row = trig[j]
        s0 = 0.0
        for i in range(K2):
            s0 += row[i] * ab[i]
        x[j] = s0
        j += 1


@njit(cache=True, nogil=True, fastmath=_FAST)
def _rows_sum(e, trig, J, cs):
    """``cs = sum_{j < J} e[j] trig[j]``, four rows per pass over ``cs``."""
    K2 = cs.size
    for i in range(K2):
        cs[i] = 0.0
    j = 0
    while j + 4 <= J:
        r0 = trig[j]
        r1 = trig[j + 1]
        r2 = trig[j + 2]
        r3 = trig[j + 3]
        e0 = e[j]
        e1 = e[j + 1]
        e2 = e[j + 2]
        e3 = e[j + 3]
        for i in range(K2):
            cs[i] += e0 * r0[i] + e1 * r1[i] + e2 * r2[i] + e3 * r3[i]
        j += 4
    while j < J:
        row = trig[j]
        ej = e[j]
        for i in range(K2):
            cs[i] += ej * row[i]
        j += 1


@njit(cache=True, nogil=True, fastmath=_FAST)
def _wall(x0, alpha, cos_phi, weight, trig, ab, cs, x, e):
    """Wall potential ``V`` and force ``F`` from the per-order amplitudes ``ab``.

    Writes the per-order cosine/sine sums ``cs`` of the edge force; the generalised force of
    mode ``k`` of order column ``i`` is ``C_k cs[i] + S_k cs[K + i]`` (formed where it is used,
    never stored). ``x`` and ``e`` are work arrays of the quadrature's size.
    """
    M = cos_phi.size
    K2 = ab.size
    reach = x0
    for i in range(K2):
        reach += abs(ab[i])
    bound = -reach - _NEGLIGIBLE / alpha
    J = 0
    while J < M and cos_phi[J] >= bound:
        J += 1
    if J == 0:
        cs[:] = 0.0
        return 0.0, 0.0
    # The two products over the active nodes are written out, four rows at a time, instead of
    # BLAS gemv calls: as fast on one thread, and BLAS called from both threads of a batch
    # contends (old / new 1.09-1.22x on the 32-speed batch, benchmarks/bench_kernel.py).
    _rows_dot(trig, J, ab, x)
    F = 0.0
    # The prefix bound J is loose; past the last node whose exponent exceeds -_NEGLIGIBLE the
    # terms are below exp(-40) of the force and the second product can stop there.
    last = 0
    for j in range(J):
        ax = alpha * (x0 + cos_phi[j] + x[j])
        ej = math.exp(ax) * weight[j]
        e[j] = ej
        F += ej
        if ax > -_NEGLIGIBLE:
            last = j + 1
    if last == 0:
        cs[:] = 0.0
    else:
        _rows_sum(e, trig, last, cs)
    return F / alpha, F


@njit(cache=True, nogil=True, fastmath=_FAST)
def _kick_flow(kick, Q, P, C, S, starts, cs, rot_c, rot_so, rot_st, ab):
    """Kick ``P -= kick f`` (``f`` from ``cs``), exact free flow, and the per-order sums of
    the new ``Q`` for the next wall evaluation, in one pass over the modes.

    Modes are ordered by angular order here: those of order column ``i`` are the contiguous
    slice ``starts[i]:starts[i + 1]``. ``starts`` is unsigned: with signed bounds numba wraps
    negative indices, which keeps LLVM from vectorising these loops (2x slower).
    """
    K = starts.size - 1
    for i in range(K):
        c_i = cs[i]
        s_i = cs[K + i]
        a = 0.0
        b = 0.0
        for k in range(starts[i], starts[i + 1]):
            ck = C[k]
            sk = S[k]
            pk = P[k] - kick * (ck * c_i + sk * s_i)
            qk = Q[k]
            qn = qk * rot_c[k] + pk * rot_so[k]
            Q[k] = qn
            P[k] = pk * rot_c[k] - qk * rot_st[k]
            a += qn * ck
            b += qn * sk
        ab[i] = a
        ab[K + i] = b


@njit(cache=True, nogil=True, fastmath=_FAST)
def _close(half, Q, P, C, S, starts, cs, omega, m, out_e):
    """Closing half kick of a step fused with the mode energies (into ``out_e``); returns
    their sum."""
    K = starts.size - 1
    esum = 0.0
    for i in range(K):
        c_i = cs[i]
        s_i = cs[K + i]
        for k in range(starts[i], starts[i + 1]):
            pk = P[k] - half * (C[k] * c_i + S[k] * s_i)
            P[k] = pk
            ek = pk * pk / (2.0 * m) + 0.5 * m * (omega[k] * Q[k]) ** 2
            out_e[k] = ek
            esum += ek
    return esum


@njit(cache=True, nogil=True, fastmath=_FAST)
def _member(
    v,
    alpha,
    x_start,
    dt,
    t_max,
    omega,
    mass,
    quad,
    weights,
    rotations,
    rot_of,
    max_steps,
    abort_drift,
    stop_log,
    contact_tol,
    Q,
    P,
    out_e,
    out_mean,
    out_closest,
):
    """Integrate one collision from the modal state ``(Q, P)`` (advanced in place to the final
    state); returns (status, epsilon, drift, contact, max_comp, max_force, steps, t, x0). Mode
    energies after, contact-summed and at closest approach go to ``out_*``.

    A step of ``n`` Strang substeps makes ``n + 1`` passes over the modes: ``n`` of
    :func:`_kick_flow` (the closing half kick of a substep and the opening half kick of the
    next use the same wall evaluation and are one kick of ``(h_s + h_{s+1}) / 2``) and
    :func:`_close` (the step's last half kick with the energies), so that the bookkeeping, the
    stop test and a return always see the state after the full step. The contact mean and the
    closest copy stay flat loops over ``out_e`` after the stability tests (fused into the
    closing pass they were slower and would touch them before an unstable return).
    """
    cos_phi, weight, trig, C, S, starts, g_max = quad
    N = omega.size
    K2 = trig.shape[1]
    M = cos_phi.size
    ab = np.zeros(K2)
    cs = np.zeros(K2)
    xw = np.empty(M)
    ew = np.empty(M)
    m = mass
    e0 = 0.5 * m * v * v
    x0 = x_start
    p0 = m * v
    _order_sums(Q, C, S, starts, ab)
    V, F = _wall(x0, alpha, cos_phi, weight, trig, ab, cs, xw, ew)
    h0 = p0 * p0 / (2.0 * m) + V
    for k in range(N):
        h0 += P[k] * P[k] / (2.0 * m) + 0.5 * m * (omega[k] * Q[k]) ** 2
    drift = 0.0
    contact = 0.0
    max_comp = -np.inf
    max_force = 0.0
    for k in range(N):
        out_mean[k] = 0.0
        out_closest[k] = 0.0
    comp_prev = x0 + 1.0
    t = 0.0
    steps = 0
    n_sub = weights.size
    while True:
        if steps >= max_steps or t > t_max:
            return STATUS_TIMEOUT, 0.0, drift, contact, max_comp, max_force, steps, t, x0
        kick = 0.5 * (weights[0] * dt)
        for s in range(n_sub):
            h_dt = weights[s] * dt
            p0 = p0 - kick * F
            r = rot_of[s]
            _kick_flow(
                kick, Q, P, C, S, starts, cs, rotations[r, 0], rotations[r, 1], rotations[r, 2], ab
            )
            x0 = x0 + p0 * (h_dt / m)
            V, F = _wall(x0, alpha, cos_phi, weight, trig, ab, cs, xw, ew)
            t = t + h_dt
            if s + 1 < n_sub:
                kick = 0.5 * h_dt + 0.5 * (weights[s + 1] * dt)
        half = 0.5 * (weights[n_sub - 1] * dt)
        p0 = p0 - half * F
        steps += 1
        comp = x0 + 1.0
        if comp > 0.0 and comp_prev > 0.0:
            frac = 1.0
        elif comp > 0.0 and comp_prev <= 0.0:
            frac = comp / (comp - comp_prev)
        elif comp <= 0.0 and comp_prev > 0.0:
            frac = comp_prev / (comp_prev - comp)
        else:
            frac = 0.0
        esum = _close(half, Q, P, C, S, starts, cs, omega, m, out_e)
        h = p0 * p0 / (2.0 * m) + esum + V
        if not math.isfinite(h):
            return STATUS_UNSTABLE, 0.0, drift, contact, max_comp, max_force, steps, t, x0
        drift = max(drift, abs(h - h0) / h0)
        if abort_drift > 0.0 and drift > abort_drift:
            return STATUS_UNSTABLE, 0.0, drift, contact, max_comp, max_force, steps, t, x0
        contact += frac * dt
        if frac > 0.0:
            w = frac * dt
            for k in range(N):
                out_mean[k] += w * out_e[k]
        if comp > max_comp:
            for k in range(N):
                out_closest[k] = out_e[k]
            max_comp = comp
        max_force = max(max_force, F)
        comp_prev = comp
        if steps % CHECK_EVERY or p0 >= 0.0:
            continue
        reach = 0.0
        for k in range(N):
            reach += math.sqrt(2.0 * out_e[k] / m) / omega[k] * g_max[k]
        gap = -(x0 + 1.0 + reach)
        if gap * alpha > stop_log and V < contact_tol * e0:
            return STATUS_OK, -p0 / (m * v), drift, contact, max_comp, max_force, steps, t, x0


@njit(cache=True, nogil=True, fastmath=_FAST)
def _one(
    b,
    v,
    alpha,
    x_start,
    dt,
    t_max,
    omega,
    mass,
    quad,
    weights,
    max_steps,
    abort_drift,
    stop_log,
    contact_tol,
    out_Q,
    out_P,
    out_e,
    out_mean,
    out_closest,
    out_scalar,
):
    """Member ``b`` of a batch: its rotations for its own step, then :func:`_member`.

    ``out_Q[b]``, ``out_P[b]`` hold the member's initial modal state and receive its final one.
    """
    N = omega.size
    # Substeps of equal weight share one rotation (Yoshida's first and last): fewer arrays to
    # keep in cache.
    rot_of = np.arange(weights.size)
    for s in range(weights.size):
        for r in range(s):
            if weights[r] == weights[s]:
                rot_of[s] = rot_of[r]
                break
    rotations = np.empty((weights.size, 3, N))
    for s in range(weights.size):
        if rot_of[s] != s:
            continue
        for k in range(N):
            arg = omega[k] * (weights[s] * dt[b])
            sn = math.sin(arg)
            mw = mass * omega[k]
            rotations[s, 0, k] = math.cos(arg)
            rotations[s, 1, k] = sn / mw
            rotations[s, 2, k] = mw * sn
    res = _member(
        v[b],
        alpha[b],
        x_start[b],
        dt[b],
        t_max[b],
        omega,
        mass,
        quad,
        weights,
        rotations,
        rot_of,
        max_steps,
        abort_drift,
        stop_log,
        contact_tol,
        out_Q[b],
        out_P[b],
        out_e[b],
        out_mean[b],
        out_closest[b],
    )
    status, eps, drift, contact, max_comp, max_force, steps, t_end, x_end = res
    out_scalar[b, 0] = status
    out_scalar[b, 1] = eps
    out_scalar[b, 2] = drift
    out_scalar[b, 3] = contact
    out_scalar[b, 4] = max_comp
    out_scalar[b, 5] = max_force
    out_scalar[b, 6] = steps
    out_scalar[b, 7] = t_end
    out_scalar[b, 8] = x_end


def run_batch(
    omega: np.ndarray,
    mass: float,
    quad,
    v: np.ndarray,
    alpha: np.ndarray,
    x_start: np.ndarray,
    dt: np.ndarray,
    t_max: np.ndarray,
    weights: tuple[float, ...],
    max_steps: int,
    abort_drift: float | None,
    stop_log: float,
    contact_tol: float,
    Q0: np.ndarray | None = None,
    P0: np.ndarray | None = None,
) -> dict[str, np.ndarray]:
    """Integrate ``B`` independent collisions, each with its own step ``dt[b]``.

    Parameters
    ----------
    omega : numpy.ndarray, shape (N,)
        Mode frequencies, ``c / R``.
    mass : float
        Disk mass.
    quad : restitution.wall.WallQuadrature
        Edge quadrature for these modes.
    v, alpha, x_start, dt, t_max : numpy.ndarray, shape (B,)
        Speed towards the wall (``c``), wall hardness (``1/R``), start position of the centre
        (``R``), step and time bound (``R / c``).
    weights : tuple of float
        Composition weights of the Strang steps within one step: ``(1,)`` is Strang splitting,
        Yoshida's ``(w1, w0, w1)`` the fourth-order composition.
    max_steps : int
        Bound on the steps of one member.
    abort_drift : float or None
        Stop a member as unstable once its relative energy drift exceeds this.
    stop_log, contact_tol : float
        Stop test: ``alpha * gap > stop_log`` and ``V < contact_tol * E0``.
    Q0, P0 : numpy.ndarray, shape (B, N), optional
        Modal coordinates (``R``) and momenta (``m c``) at the start; zero (disk at rest in its
        undeformed shape) when omitted.

    Returns
    -------
    dict
        ``status`` (B,) int; ``epsilon``, ``drift``, ``contact_time``, ``max_compression``,
        ``max_force``, ``steps``, ``t_end`` (B,); ``energy`` (B, N) mode energies at the end,
        ``energy_sum`` (B, N) contact-time integral of the mode energies, ``energy_closest``
        (B, N) at the closest approach. Energies are absolute (not divided by ``E0``).
        ``final_Q``, ``final_P`` (B, N) and ``final_x0`` (B,): the state where the run stopped.
    """
    B, N = v.size, omega.size
    # Modes sorted by order (stable, so each order keeps its original sequence); results are
    # mapped back to the caller's order at the end.
    perm = np.argsort(quad.column, kind="stable")
    starts = np.searchsorted(quad.column[perm], np.arange(quad.n_orders + 1)).astype(np.uint64)
    out_Q = np.zeros((B, N)) if Q0 is None else np.array(np.asarray(Q0, float)[:, perm])
    out_P = np.zeros((B, N)) if P0 is None else np.array(np.asarray(P0, float)[:, perm])
    out_e = np.zeros((B, N))
    out_mean = np.zeros((B, N))
    out_closest = np.zeros((B, N))
    out_scalar = np.zeros((B, 9))
    quad_arrays = (
        np.ascontiguousarray(quad.cos_phi, dtype=np.float64),
        np.ascontiguousarray(quad.weight, dtype=np.float64),
        np.ascontiguousarray(quad.trig, dtype=np.float64),
        np.ascontiguousarray(quad.C[perm], dtype=np.float64),
        np.ascontiguousarray(quad.S[perm], dtype=np.float64),
        starts,
        np.ascontiguousarray(quad.g_max[perm], dtype=np.float64),
    )
    args = (
        np.ascontiguousarray(v, dtype=np.float64),
        np.ascontiguousarray(alpha, dtype=np.float64),
        np.ascontiguousarray(x_start, dtype=np.float64),
        np.ascontiguousarray(dt, dtype=np.float64),
        np.ascontiguousarray(t_max, dtype=np.float64),
        np.ascontiguousarray(omega[perm], dtype=np.float64),
        float(mass),
        quad_arrays,
        np.asarray(weights, dtype=np.float64),
        int(max_steps),
        -1.0 if abort_drift is None else float(abort_drift),
        float(stop_log),
        float(contact_tol),
        out_Q,
        out_P,
        out_e,
        out_mean,
        out_closest,
        out_scalar,
    )

    def member(b: int) -> None:
        _one(b, *args)

    # Members differ in cost (slow speeds take many more steps), so the threads take them one
    # at a time, in the caller's order; the compiled member releases the GIL. (A numba prange
    # splits the members into fixed contiguous halves whatever the chunk size, which left one
    # core idle for a third of a sorted 32-speed batch.)
    workers = min(numba.get_num_threads(), B)
    if workers == 1:
        for b in range(B):
            member(b)
    else:
        with ThreadPoolExecutor(max_workers=workers) as pool:
            list(pool.map(member, range(B)))
    back = np.empty_like(perm)
    back[perm] = np.arange(N)
    return {
        "status": out_scalar[:, 0].astype(int),
        "epsilon": out_scalar[:, 1],
        "drift": out_scalar[:, 2],
        "contact_time": out_scalar[:, 3],
        "max_compression": out_scalar[:, 4],
        "max_force": out_scalar[:, 5],
        "steps": out_scalar[:, 6].astype(int),
        "t_end": out_scalar[:, 7],
        "energy": out_e[:, back],
        "energy_sum": out_mean[:, back],
        "energy_closest": out_closest[:, back],
        "final_Q": out_Q[:, back],
        "final_P": out_P[:, back],
        "final_x0": out_scalar[:, 8],
    }
