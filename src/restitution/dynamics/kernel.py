"""Compiled collision kernel: the splitting integrators and all bookkeeping in one loop (numba).

Units: ``E = rho = R = 1``; times in ``R / c``.

This is the production path of :func:`restitution.dynamics.collision.collide_batch` for the
symplectic splittings ``split`` (Strang, second order) and ``split4`` (Yoshida, fourth order). It
performs, per batch member and entirely in compiled code, exactly the arithmetic of the NumPy
reference path (:mod:`restitution.dynamics.integrators`, :mod:`restitution.dynamics.contact` and
:mod:`restitution.dynamics.numpy_path`):

* the wall terms order by order (eqs. 40-42, 45) over the prefix of provably active nodes, of
  the contact law the kernel is given (below);
* the half kicks of the wall and the exact harmonic free flow (the two half kicks between
  substeps merged into one, fused with the flow and the order sums in one pass over the
  modes);
* energy drift, contact time, compression, force, contact-averaged and closest mode energies;
* the rigorous stop test every ``CHECK_EVERY`` steps, and there a stop flag that the caller
  raises on Ctrl-C (:func:`_in_threads`), so an interrupt ends a long collision within a few
  steps;
* for a viscoelastic body, each mode's exact damped flow (:mod:`restitution.dynamics.damping`)
  in a loop of its own (:func:`_kick_flow_damped`), with the dissipated energy counted in the
  energy balance; an elastic body runs the rotation loop, bit for bit as before.

**Contact laws.** The kernel dispatches on the law's branch number (``law``, one of
:data:`KERNEL_LAWS`, from :attr:`~restitution.dynamics.contact.base.ContactLaw.kernel`) as it
does on damping: :func:`_cutoff`, :func:`_law_nodes` and :func:`_separated` each hold one branch
per law, the law's numbers ``law_params`` beside it
(:meth:`~restitution.dynamics.contact.base.ContactLaw.kernel_parameters`). The exponential wall
is branch 0, the arithmetic of every earlier kernel. A law of its own is one more branch in each
of the three and one entry of :data:`KERNEL_LAWS`; a law without one runs on the NumPy path.

Only the summation order of reductions and the merged kicks differ from the NumPy path, so the
two agree to round-off (checked to 1e-12 in ``tests/test_kernel.py``). Members of a batch are
independent: a pool of threads (``numba.get_num_threads()`` of them) takes them one at a time,
and each has its own step, so a member's result never depends on which other points share its
batch or which thread ran it (the same compiled function runs every member, bit for bit).

A single collision of at least ``SPLIT_MIN_MODES`` modes runs on two threads when numba has
two: the angular orders form two groups of about equal cost, each thread advances one, and
the threads meet (:mod:`restitution.dynamics.spin`) to add their partial sums at every wall
evaluation and energy check, about 7 times per step. How the sums are grouped depends on the
mode set only, so one thread or two give the same bits.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor
from typing import NamedTuple

import numba
import numpy as np
from numba import njit

from restitution.dynamics.contact.exponential import NEGLIGIBLE
from restitution.dynamics.damping import fill_damped_flow
from restitution.dynamics.spin import LINE, barrier

__all__ = [
    "CHECK_EVERY",
    "KERNEL_LAWS",
    "LAW_EXPONENTIAL",
    "STATUS_INTERRUPTED",
    "STATUS_OK",
    "STATUS_TIMEOUT",
    "STATUS_UNSTABLE",
    "run_batch",
]

CHECK_EVERY = 8
"""Steps between two evaluations of the stop test (as in the NumPy path)."""

STATUS_OK = 0
STATUS_UNSTABLE = 1  # drift above the abort level, or overflow
STATUS_TIMEOUT = 2  # no separation within t_max or max_steps
STATUS_INTERRUPTED = 3  # the caller raised the stop flag (Ctrl-C)

LAW_EXPONENTIAL = 0
"""Branch of the exponential wall (:class:`restitution.dynamics.contact.exponential.
ExponentialWall`)."""

KERNEL_LAWS: dict[str, int] = {"exponential": LAW_EXPONENTIAL}
"""The contact laws this kernel runs: branch number by the law's
:attr:`~restitution.dynamics.contact.base.ContactLaw.kernel` name."""

SPLIT_MIN_MODES = 2000
"""A single collision with at least this many modes runs on two threads when numba has two
(measured in ``benchmarks/bench_kernel.py``; below it the meetings cost more than they save)."""

# Work of one order between two meetings, in modes' worth: its two columns of the second wall
# product (about 80 rows at N = 1e4, about 0.13 ns per element) against 4/3 passes over a mode
# (about 1.2 ns each) per wall evaluation. The first product is split by columns instead
# (_dot_split). Only speed depends on it; spin counts at 8, 15 and 30 were within the noise.
_COLUMN_COST = 12.0

# The exponential wall skips nodes whose exponent is certainly below -_NEGLIGIBLE (see
# restitution.dynamics.contact.surface.active_nodes).
_NEGLIGIBLE = NEGLIGIBLE


class _Quadrature(NamedTuple):
    """The body's surface quadrature in the kernel's layout: modes sorted by order, the columns
    of ``basis`` grouped (:func:`_group_columns`)."""

    height: np.ndarray  # (M,) undeformed surface position along the axis, R
    weight: np.ndarray  # (M,) quadrature weights
    basis: np.ndarray  # (M, 2K) basis values, columns group by group
    C: np.ndarray  # (N,) normal surface amplitudes, modes sorted by order
    S: np.ndarray  # (N,) tangential surface amplitudes
    starts: np.ndarray  # (K + 1,) uint64: modes of order column i are starts[i]:starts[i+1]
    g_max: np.ndarray  # (N,) |C| + |S|
    cols: np.ndarray  # (3,) int64: order columns of the two groups, [0, kc, K]
    ucols: np.ndarray  # (3,) uint64: 2 cols, the groups' column ranges of basis, ab and cs
    dcols: np.ndarray  # (3,) uint64: the two parts of the first wall product (_dot_split)


class _Control(NamedTuple):
    """Stepping and stop control shared by every member."""

    weights: np.ndarray  # Strang substep weights of one step
    max_steps: int
    abort_drift: float  # stop as unstable above this drift; <= 0: never
    stop_log: float  # stop when alpha * gap > stop_log ...
    contact_tol: float  # ... and V < contact_tol * E0
    stop: np.ndarray  # (1,) int64: the caller sets it to end every member at its next check
    law: int  # the contact law's branch (KERNEL_LAWS)
    law_params: np.ndarray  # its numbers (ContactLaw.kernel_parameters)


class _Members(NamedTuple):
    """Per-member inputs, shape (B,) each."""

    v: np.ndarray  # speed towards the wall, c
    alpha: np.ndarray  # wall hardness, 1/R
    x_start: np.ndarray  # centre position at the start, R
    dt: np.ndarray  # step, R/c
    t_max: np.ndarray  # bound of the simulated time, R/c


class _Outputs(NamedTuple):
    """Per-member results: modal arrays (B, N) in the kernel's mode order, scalars (B,)."""

    Q: np.ndarray  # initial state in, final state out
    P: np.ndarray
    energy: np.ndarray  # mode energies at the end
    energy_sum: np.ndarray  # contact-time integral of the mode energies
    energy_closest: np.ndarray  # mode energies at the closest approach
    status: np.ndarray  # int64: STATUS_*
    epsilon: np.ndarray
    drift: np.ndarray
    contact_time: np.ndarray
    max_compression: np.ndarray
    max_force: np.ndarray
    steps: np.ndarray  # int64
    t_end: np.ndarray
    x_end: np.ndarray
    dissipated: np.ndarray  # energy dissipated by the modes' damping (absolute)


# Reassociation lets the compiler vectorise the sums over orders and modes; it changes results
# only at round-off. No "nnan"/"ninf": the overflow test relies on isfinite.
_FAST = {"reassoc", "contract", "nsz"}


@njit(cache=True, nogil=True, fastmath=_FAST)
def _order_sums(Q, C, S, starts, ab):
    """Per-order amplitudes ``a_i = sum Q_k C_k``, ``b_i = sum Q_k S_k`` into ``ab = [a, b]``.

    Called with one group's views: its slice of ``starts`` and its columns of ``ab`` (see
    :func:`_wall`); ``K`` is then the group's number of orders.
    """
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
def _rows_dot(trig, J, ab, x, c0, c1):
    """``x[j] = sum_{c0 <= i < c1} trig[j, i] ab[i]`` for ``j < J``, four rows at a time (four
    independent sums sharing each load of ``ab``). The bounds are unsigned, so the loops
    vectorise."""
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
        for i in range(c0, c1):
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
        for i in range(c0, c1):
            s0 += row[i] * ab[i]
        x[j] = s0
        j += 1


@njit(cache=True, nogil=True, fastmath=_FAST)
def _rows_dot2(trig, J, ab, x, y, c0, c1, c2):
    """:func:`_rows_dot` for two adjacent column ranges at once (both groups on one thread):
    ``x`` over ``c0 <= i < c1`` and ``y`` over ``c1 <= i < c2``, each row read once. Each
    range is summed by the same loop as in :func:`_rows_dot`, so the results are the same."""
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
        for i in range(c0, c1):
            t = ab[i]
            s0 += r0[i] * t
            s1 += r1[i] * t
            s2 += r2[i] * t
            s3 += r3[i] * t
        x[j] = s0
        x[j + 1] = s1
        x[j + 2] = s2
        x[j + 3] = s3
        s0 = 0.0
        s1 = 0.0
        s2 = 0.0
        s3 = 0.0
        for i in range(c1, c2):
            t = ab[i]
            s0 += r0[i] * t
            s1 += r1[i] * t
            s2 += r2[i] * t
            s3 += r3[i] * t
        y[j] = s0
        y[j + 1] = s1
        y[j + 2] = s2
        y[j + 3] = s3
        j += 4
    while j < J:
        row = trig[j]
        s0 = 0.0
        for i in range(c0, c1):
            s0 += row[i] * ab[i]
        x[j] = s0
        s0 = 0.0
        for i in range(c1, c2):
            s0 += row[i] * ab[i]
        y[j] = s0
        j += 1


@njit(cache=True, nogil=True, fastmath=_FAST)
def _rows_sum(e, trig, J, cs, c0, c1):
    """``cs[i] = sum_{j < J} e[j] trig[j, i]`` for the columns ``c0 <= i < c1`` (unsigned
    bounds, so the loops vectorise), four rows per pass over ``cs``."""
    for i in range(c0, c1):
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
        for i in range(c0, c1):
            cs[i] += e0 * r0[i] + e1 * r1[i] + e2 * r2[i] + e3 * r3[i]
        j += 4
    while j < J:
        row = trig[j]
        ej = e[j]
        for i in range(c0, c1):
            cs[i] += ej * row[i]
        j += 1


@njit(cache=True, nogil=True, fastmath=_FAST)
def _cutoff(law, law_params, alpha):
    """The law's :meth:`~restitution.dynamics.contact.base.ContactLaw.cutoff`, ``R``: nodes
    certainly farther from the wall are skipped."""
    if law == LAW_EXPONENTIAL:
        return _NEGLIGIBLE / alpha
    return math.inf  # no other branch yet: every node counts (run_batch refuses such a law)


# Inlined into _wall (numba IR), so that the node loop is compiled inside it as before laws
# were objects: the same machine code for the exponential wall.
@njit(cache=True, nogil=True, fastmath=_FAST, inline="always")
def _law_nodes(law, law_params, alpha, x0, cos_phi, weight, x_a, x_b, J, e):
    """The law on the first ``J`` nodes at ``x_j = x0 + cos_phi[j] + x_a[j] + x_b[j]``: each
    node's share of the force, weight included, into ``e``; returns ``(V, F, last)``, ``last``
    the number of leading nodes whose force is not negligible (the second wall product stops
    there). :meth:`~restitution.dynamics.contact.base.ContactLaw.node_terms`, branch by branch.
    """
    if law == LAW_EXPONENTIAL:
        F = 0.0
        # The prefix bound J is loose; past the last node whose exponent exceeds -_NEGLIGIBLE
        # the terms are below exp(-40) of the force and the second product can stop there.
        last = 0
        for j in range(J):
            ax = alpha * (x0 + cos_phi[j] + (x_a[j] + x_b[j]))
            ej = math.exp(ax) * weight[j]
            e[j] = ej
            F += ej
            if ax > -_NEGLIGIBLE:
                last = j + 1
        return F / alpha, F, last
    return math.nan, math.nan, 0  # no other branch yet (run_batch refuses such a law)


@njit(cache=True, nogil=True, fastmath=_FAST)
def _separated(law, law_params, gap, alpha, V, e0, stop_log, contact_tol):
    """The law's stop test (:meth:`~restitution.dynamics.contact.base.ContactLaw.separated`) of
    a body moving away whose surface stays ``gap`` from the wall."""
    if law == LAW_EXPONENTIAL:
        return gap * alpha > stop_log and V < contact_tol * e0
    return False  # no other branch yet (run_batch refuses such a law)


@njit(cache=True, nogil=True, fastmath=_FAST)
def _wall(x0, alpha, cos_phi, weight, trig, ab, cs, e, ucols, dcols, g0, g1, sync, law, params):
    """Wall potential ``V`` and force ``F`` of the contact law ``law`` (with its numbers
    ``params``) from the per-order amplitudes ``ab``.

    The orders form two groups; group ``g`` has the orders ``cols[g] <= i < cols[g + 1]``
    and the contiguous columns ``ucols[g] <= c < ucols[g + 1]`` (``ucols = 2 cols``) of
    ``trig``, ``ab`` and ``cs``: first its cosine, then its sine columns (see
    :func:`_order_sums`). This call writes the per-order cosine/sine sums ``cs`` of the edge
    force for this thread's groups ``g0 <= g < g1``; the generalised force of mode ``k`` of
    order ``i`` in group ``[lo, hi)`` is ``C_k cs[lo + i] + S_k cs[hi + i]`` (formed where it is
    used, never stored). The first product, the edge displacement, is summed in two parts over
    the columns ``dcols[p] <= c < dcols[p + 1]`` (:func:`_dot_split`), part ``p`` by thread
    ``p`` when two threads share the collision. ``e`` is a work array of the quadrature's size.

    Both groups' partial sums meet in ``sync = (flags, me, nthreads, red, xs)`` (see
    :func:`_meet`) and are always added in group order, so the result is the same whether one
    thread does both groups or two threads one each.
    """
    flags, me, nthreads, red, xs = sync
    M = cos_phi.size
    par = (flags[me * LINE] + 1) & 1
    for g in range(g0, g1):
        r = 0.0
        for i in range(ucols[g], ucols[g + 1]):
            r += abs(ab[i])
        red[par, g, 0] = r
    barrier(flags, me, nthreads)
    reach = x0 + red[par, 0, 0] + red[par, 1, 0]
    bound = -reach - _cutoff(law, params, alpha)
    J = 0
    while J < M and cos_phi[J] >= bound:
        J += 1
    if J == 0:
        for i in range(ucols[g0], ucols[g1]):
            cs[i] = 0.0
        return 0.0, 0.0
    # The two products over the active nodes are written out, four rows at a time, instead of
    # BLAS gemv calls: as fast on one thread, and BLAS called from both threads of a batch
    # contends (old / new 1.09-1.22x on the 32-speed batch, benchmarks/bench_kernel.py).
    par = (flags[me * LINE] + 1) & 1
    if dcols[1] == dcols[2]:
        # No second part (fewer than SPLIT_MIN_MODES modes): xs[., 1] stays zero.
        _rows_dot(trig, J, ab, xs[par, 0], dcols[0], dcols[2])
    elif g1 - g0 == 2:
        _rows_dot2(trig, J, ab, xs[par, 0], xs[par, 1], dcols[0], dcols[1], dcols[2])
    else:
        _rows_dot(trig, J, ab, xs[par, g0], dcols[g0], dcols[g1])
    barrier(flags, me, nthreads)
    x_a = xs[par, 0]
    x_b = xs[par, 1]
    V, F, last = _law_nodes(law, params, alpha, x0, cos_phi, weight, x_a, x_b, J, e)
    # Column by column, so one call for all of this thread's columns.
    _rows_sum(e, trig, last, cs, ucols[g0], ucols[g1])
    return V, F


@njit(cache=True, nogil=True, fastmath=_FAST)
def _meet(parts, slot, g0, g1, sync):
    """Sum of a scalar over both groups, ``parts[g]`` being group ``g``'s share (set for this
    thread's groups ``g0 <= g < g1``); added in group order, the same in both threading modes.

    Shared values are double-buffered by the parity of the meeting that publishes them: a
    thread reads them before its next meeting, and the other thread rewrites that buffer only
    after the meeting after that.
    """
    flags, me, nthreads, red, xs = sync
    par = (flags[me * LINE] + 1) & 1
    for g in range(g0, g1):
        red[par, g, slot] = parts[g]
    barrier(flags, me, nthreads)
    return red[par, 0, slot] + red[par, 1, slot]


@njit(cache=True, nogil=True, fastmath=_FAST)
def _kick_flow(kick, Q, P, C, S, starts, cs, rot_c, rot_so, rot_st, ab):
    """Kick ``P -= kick f`` (``f`` from ``cs``), exact free flow, and the per-order sums of
    the new ``Q`` for the next wall evaluation, in one pass over the modes.

    Modes are ordered by angular order here: those of order column ``i`` are the contiguous
    slice ``starts[i]:starts[i + 1]``. ``starts`` is unsigned: with signed bounds numba wraps
    negative indices, which keeps LLVM from vectorising these loops (2x slower). Called with one
    group's views of ``starts``, ``cs`` and ``ab``, as :func:`_order_sums` (views, not offset
    indices: those measured about 5% slower).
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
def _kick_flow_damped(kick, Q, P, C, S, starts, cs, flow, omega, m, ab):
    """:func:`_kick_flow` for damped modes: the exact damped flow ``flow = (a, b, c, d)``
    (:mod:`restitution.dynamics.damping`) instead of the rotation; returns the energy the flow
    dissipated (each mode's energy before it minus after it). A loop of its own, so the
    elastic loop keeps its three coefficients and its speed."""
    K = starts.size - 1
    fa = flow[0]
    fb = flow[1]
    fc = flow[2]
    fd = flow[3]
    lost = 0.0
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
            qn = qk * fa[k] + pk * fb[k]
            pn = pk * fd[k] - qk * fc[k]
            Q[k] = qn
            P[k] = pn
            mw2 = m * omega[k] * omega[k]
            lost += (pk * pk - pn * pn) / (2.0 * m) + 0.5 * mw2 * (qk * qk - qn * qn)
            a += qn * ck
            b += qn * sk
        ab[i] = a
        ab[K + i] = b
    return lost


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
def _member(b, omega, mass, quad, ctl, members, rotations, rot_of, out, ab, g0, g1, sync, damped):
    """Integrate member ``b`` from its modal state ``out.Q[b], out.P[b]`` (advanced in place to
    the final state); returns (status, epsilon, drift, contact, max_comp, max_force, steps, t,
    x0, dissipated). Mode energies after, contact-summed and at closest approach go to ``out``.

    The order columns form two groups (``cols`` in ``quad``); this call advances the modes of
    groups ``g0 <= g < g1``: both groups on one thread, or one each on two threads that meet
    in ``sync`` to add their partial wall and energy sums (:func:`_wall`, :func:`_meet`). The
    centre of mass, the bookkeeping and every decision are computed by both threads from the
    same sums, so they take the same path and return the same result, bit for bit, as one
    thread would. ``ab`` (the per-order amplitudes, in the columns of ``trig``) is shared:
    each thread writes its groups' columns, and the first wall product reads them all.

    A step of ``n`` Strang substeps makes ``n + 1`` passes over the modes: ``n`` of
    :func:`_kick_flow` (the closing half kick of a substep and the opening half kick of the
    next use the same wall evaluation and are one kick of ``(h_s + h_{s+1}) / 2``) and
    :func:`_close` (the step's last half kick with the energies), so that the bookkeeping, the
    stop test and a return always see the state after the full step. The contact mean and the
    closest copy stay flat loops over ``out_e`` after the stability tests (fused into the
    closing pass they were slower and would touch them before an unstable return).

    ``damped``: the modes are damped and ``rotations[r]`` holds their exact flows
    ``(a, b, c, d)`` (:func:`_kick_flow_damped`); each group's dissipated energy is summed and
    counted in the energy balance, so the drift still measures the splitting error alone.
    """
    cos_phi, weight, trig, C, S, starts, g_max, cols, ucols, dcols = quad
    weights = ctl.weights
    max_steps = ctl.max_steps
    abort_drift = ctl.abort_drift
    stop_log = ctl.stop_log
    contact_tol = ctl.contact_tol
    law = ctl.law
    params = ctl.law_params
    v = members.v[b]
    alpha = members.alpha[b]
    x_start = members.x_start[b]
    dt = members.dt[b]
    t_max = members.t_max[b]
    Q = out.Q[b]
    P = out.P[b]
    out_e = out.energy[b]
    out_mean = out.energy_sum[b]
    out_closest = out.energy_closest[b]
    K2 = trig.shape[1]
    M = cos_phi.size
    k0 = starts[cols[g0]]
    k1 = starts[cols[g1]]
    cs = np.zeros(K2)
    ew = np.empty(M)
    parts = np.zeros(2)
    lost = np.zeros(2)  # energy dissipated so far, per group of orders
    m = mass
    e0 = 0.5 * m * v * v
    x0 = x_start
    p0 = m * v
    for g in range(g0, g1):
        lo, hi = cols[g], cols[g + 1]
        _order_sums(Q, C, S, starts[lo : hi + 1], ab[2 * lo : 2 * hi])
    V, F = _wall(
        x0, alpha, cos_phi, weight, trig, ab, cs, ew, ucols, dcols, g0, g1, sync, law, params
    )
    for g in range(g0, g1):
        h = 0.0
        for k in range(starts[cols[g]], starts[cols[g + 1]]):
            h += P[k] * P[k] / (2.0 * m) + 0.5 * m * (omega[k] * Q[k]) ** 2
        parts[g] = h
    h0 = p0 * p0 / (2.0 * m) + V + _meet(parts, 1, g0, g1, sync)
    drift = 0.0
    contact = 0.0
    max_comp = -np.inf
    max_force = 0.0
    for k in range(k0, k1):
        out_mean[k] = 0.0
        out_closest[k] = 0.0
    comp_prev = x0 + 1.0
    t = 0.0
    steps = 0
    n_sub = weights.size
    while True:
        if steps >= max_steps or t > t_max:
            return STATUS_TIMEOUT, 0.0, drift, contact, max_comp, max_force, steps, t, x0, 0.0
        kick = 0.5 * (weights[0] * dt)
        for s in range(n_sub):
            h_dt = weights[s] * dt
            p0 = p0 - kick * F
            r = rot_of[s]
            for g in range(g0, g1):
                lo, hi = cols[g], cols[g + 1]
                if lo == hi:
                    continue
                if damped:
                    lost[g] += _kick_flow_damped(
                        kick,
                        Q,
                        P,
                        C,
                        S,
                        starts[lo : hi + 1],
                        cs[2 * lo : 2 * hi],
                        rotations[r],
                        omega,
                        m,
                        ab[2 * lo : 2 * hi],
                    )
                    continue
                _kick_flow(
                    kick,
                    Q,
                    P,
                    C,
                    S,
                    starts[lo : hi + 1],
                    cs[2 * lo : 2 * hi],
                    rotations[r, 0],
                    rotations[r, 1],
                    rotations[r, 2],
                    ab[2 * lo : 2 * hi],
                )
            x0 = x0 + p0 * (h_dt / m)
            V, F = _wall(
                x0, alpha, cos_phi, weight, trig, ab, cs, ew, ucols, dcols, g0, g1, sync, law,
                params,
            )  # fmt: skip
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
        for g in range(g0, g1):
            lo, hi = cols[g], cols[g + 1]
            if lo == hi:
                continue  # parts[g] stays 0.0
            parts[g] = _close(
                half, Q, P, C, S, starts[lo : hi + 1], cs[2 * lo : 2 * hi], omega, m, out_e
            )
            if damped:
                parts[g] += lost[g]
        h = p0 * p0 / (2.0 * m) + _meet(parts, 1, g0, g1, sync) + V
        if not math.isfinite(h):
            return STATUS_UNSTABLE, 0.0, drift, contact, max_comp, max_force, steps, t, x0, 0.0
        drift = max(drift, abs(h - h0) / h0)
        if abort_drift > 0.0 and drift > abort_drift:
            return STATUS_UNSTABLE, 0.0, drift, contact, max_comp, max_force, steps, t, x0, 0.0
        contact += frac * dt
        if frac > 0.0:
            w = frac * dt
            for k in range(k0, k1):
                out_mean[k] += w * out_e[k]
        if comp > max_comp:
            for k in range(k0, k1):
                out_closest[k] = out_e[k]
            max_comp = comp
        max_force = max(max_force, F)
        comp_prev = comp
        if steps % CHECK_EVERY:
            continue
        # The stop flag, read by the first thread and passed on through a meeting, so that the
        # two threads of a shared member leave at the same step.
        parts[0] = float(ctl.stop[0]) if g0 == 0 else 0.0
        parts[1] = 0.0
        if _meet(parts, 0, g0, g1, sync) != 0.0:
            return STATUS_INTERRUPTED, 0.0, drift, contact, max_comp, max_force, steps, t, x0, 0.0
        if p0 >= 0.0:
            continue
        for g in range(g0, g1):
            reach = 0.0
            for k in range(starts[cols[g]], starts[cols[g + 1]]):
                reach += math.sqrt(2.0 * out_e[k] / m) / omega[k] * g_max[k]
            parts[g] = reach
        gap = -(x0 + 1.0 + _meet(parts, 2, g0, g1, sync))
        if _separated(law, params, gap, alpha, V, e0, stop_log, contact_tol):
            dissipated = _meet(lost, 3, g0, g1, sync) if damped else 0.0
            eps = -p0 / (m * v)
            return STATUS_OK, eps, drift, contact, max_comp, max_force, steps, t, x0, dissipated


@njit(cache=True, nogil=True, fastmath=_FAST)
def _one(b, part, omega, gamma, mass, quad, ctl, members, out, shared):
    """Member ``b`` of a batch: its rotations for its own step, then :func:`_member`.

    ``part`` is -1 for a member run by one thread (both groups of orders); 0 or 1 for the two
    threads that share a member, each advancing one group and meeting the other through the
    ``shared`` arrays ``(flags, red, xs, ab)`` (fresh zeros, unused when ``part`` is -1).
    ``out.Q[b]``, ``out.P[b]`` hold the member's initial modal state and receive its final one.
    ``gamma`` holds the modes' damping rates; all zero: the elastic body, with rotations.
    """
    N = omega.size
    M = quad.height.size
    starts = quad.starts
    cols = quad.cols
    weights = ctl.weights
    if part < 0:
        g0, g1, me, nthreads = 0, 2, 0, 1
        flags = np.zeros(2 * LINE, dtype=np.int64)
        red = np.zeros((2, 2, 4))
        xs = np.zeros((2, 2, M))
        ab = np.zeros(quad.basis.shape[1])
    else:
        g0, g1, me, nthreads = part, part + 1, part, 2
        flags, red, xs, ab = shared
    sync = (flags, me, nthreads, red, xs)
    # Substeps of equal weight share one rotation (Yoshida's first and last): fewer arrays to
    # keep in cache. Each thread fills the rotations of its own modes only.
    rot_of = np.arange(weights.size)
    for s in range(weights.size):
        for r in range(s):
            if weights[r] == weights[s]:
                rot_of[s] = rot_of[r]
                break
    damped = False
    for k in range(N):
        if gamma[k] != 0.0:
            damped = True
            break
    rotations = np.empty((weights.size, 4, N))
    for s in range(weights.size):
        if rot_of[s] != s:
            continue
        if damped:
            h = weights[s] * members.dt[b]
            fill_damped_flow(
                omega, gamma, mass, h, rotations[s], starts[cols[g0]], starts[cols[g1]]
            )
            continue
        for k in range(starts[cols[g0]], starts[cols[g1]]):
            arg = omega[k] * (weights[s] * members.dt[b])
            sn = math.sin(arg)
            mw = mass * omega[k]
            rotations[s, 0, k] = math.cos(arg)
            rotations[s, 1, k] = sn / mw
            rotations[s, 2, k] = mw * sn
    res = _member(
        b, omega, mass, quad, ctl, members, rotations, rot_of, out, ab, g0, g1, sync, damped
    )
    if g0 > 0:
        return
    status, eps, drift, contact, max_comp, max_force, steps, t_end, x_end, dissipated = res
    out.status[b] = status
    out.epsilon[b] = eps
    out.drift[b] = drift
    out.contact_time[b] = contact
    out.max_compression[b] = max_comp
    out.max_force[b] = max_force
    out.steps[b] = steps
    out.t_end[b] = t_end
    out.x_end[b] = x_end
    out.dissipated[b] = dissipated


def _threads() -> int:
    """Threads the kernel may use: numba's setting (``NUMBA_NUM_THREADS``,
    ``numba.set_num_threads``)."""
    return numba.get_num_threads()


def _order_groups(counts: np.ndarray) -> np.ndarray:
    """Split the order columns into two groups of about equal cost per step: ``[0, kc, K]``.

    The split fixes how partial sums are grouped, so it depends on the mode set only, never on
    the number of threads: a collision gives the same result, bit for bit, on one thread or
    two. Below ``SPLIT_MIN_MODES`` modes (never split) the second group is empty: two partial
    sums per wall row made a step 7% slower at N = 1600 (about 3% at N = 3200, none at 1e4).
    """
    K = counts.size
    if counts.sum() < SPLIT_MIN_MODES:
        return np.array([0, K, K], dtype=np.int64)
    cost = np.cumsum(counts + _COLUMN_COST)
    kc = int(np.searchsorted(cost, 0.5 * cost[-1]))
    return np.array([0, kc, K], dtype=np.int64)


def _dot_split(cols: np.ndarray) -> np.ndarray:
    """Column ranges of the two partial sums of the first wall product, ``[0, D, 2K]``.

    Split at the middle column rather than between the order groups: all of ``ab`` is
    published before that product, and equal halves keep the two threads level between
    meetings (split by order groups, the thread with fewer columns waited at every wall
    evaluation). No split (``D = 2K``) when the second group is empty.
    """
    K = int(cols[-1])
    middle = K if cols[1] < K else 2 * K
    return np.array([0, middle, 2 * K], dtype=np.uint64)


def _group_columns(cols: np.ndarray) -> np.ndarray:
    """Columns of ``quad.trig`` (cosine parts ``0..K-1``, then sine parts ``K..2K-1``) in the
    kernel's order: group by group, each group's cosine columns then its sine columns, so that
    a group's share of the wall products is one contiguous range."""
    K = int(cols[-1])
    idx = [
        np.r_[np.arange(lo, hi), K + np.arange(lo, hi)]
        for lo, hi in zip(cols[:-1], cols[1:], strict=True)
    ]
    return np.concatenate(idx).astype(np.intp)


def _in_threads(workers: int, work, items, stop: np.ndarray) -> None:
    """Run ``work`` over ``items`` on ``workers`` threads while this thread waits; an exception
    here (Ctrl-C) raises ``stop`` first, so the compiled members return at their next check
    and the threads are joined before it propagates."""
    pool = ThreadPoolExecutor(max_workers=workers)
    try:
        list(pool.map(work, items))
    except BaseException:
        stop[0] = 1
        raise
    finally:
        pool.shutdown(wait=True)


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
    damping: np.ndarray | None = None,
    stop: np.ndarray | None = None,
    law: int = LAW_EXPONENTIAL,
    law_params: np.ndarray | None = None,
) -> dict[str, np.ndarray]:
    """Integrate ``B`` independent collisions, each with its own step ``dt[b]``.

    Parameters
    ----------
    omega : numpy.ndarray, shape (N,)
        Mode frequencies, ``c / R``.
    mass : float
        Disk mass.
    quad : restitution.bodies.base.SurfaceQuadrature
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
        Stop test of the exponential wall: ``alpha * gap > stop_log`` and
        ``V < contact_tol * E0``.
    Q0, P0 : numpy.ndarray, shape (B, N), optional
        Modal coordinates (``R``) and momenta (``m c``) at the start; zero (disk at rest in its
        undeformed shape) when omitted.
    damping : numpy.ndarray, shape (N,), optional
        Damping rate ``gamma_k`` of every mode (``c / R``, :mod:`restitution.dynamics.damping`);
        omitted or all zero: the elastic body. Only with positive ``weights`` (Strang).
    stop : numpy.ndarray, shape (1,), int64, optional
        A flag the members read every ``CHECK_EVERY`` steps: once it is nonzero each returns
        with status ``STATUS_INTERRUPTED``. The members always run in worker threads, so
        Ctrl-C (``KeyboardInterrupt`` in the waiting main thread) raises it and returns within
        ``CHECK_EVERY`` steps instead of when the collision ends.
    law : int
        The contact law's branch, one of :data:`KERNEL_LAWS` (default: the exponential wall).
    law_params : numpy.ndarray, optional
        Its numbers (:meth:`~restitution.dynamics.contact.base.ContactLaw.kernel_parameters`).

    Returns
    -------
    dict
        ``status`` (B,) int; ``epsilon``, ``drift``, ``contact_time``, ``max_compression``,
        ``max_force``, ``steps``, ``t_end`` (B,); ``energy`` (B, N) mode energies at the end,
        ``energy_sum`` (B, N) contact-time integral of the mode energies, ``energy_closest``
        (B, N) at the closest approach. Energies are absolute (not divided by ``E0``).
        ``final_Q``, ``final_P`` (B, N) and ``final_x0`` (B,): the state where the run stopped.
        ``dissipated`` (B,): the energy the damping took (absolute; zero for an elastic body).
    """
    if law not in KERNEL_LAWS.values():
        raise ValueError(f"no kernel branch {law!r}; the kernel runs {KERNEL_LAWS}")
    B, N = v.size, omega.size
    # Modes sorted by order (stable, so each order keeps its original sequence); results are
    # mapped back to the caller's order at the end.
    perm = np.argsort(quad.column, kind="stable")
    counts = np.bincount(quad.column, minlength=quad.n_orders)
    starts = np.r_[0, np.cumsum(counts)].astype(np.uint64)
    cols = _order_groups(counts)
    scalar = np.zeros(B)
    out = _Outputs(
        Q=np.zeros((B, N)) if Q0 is None else np.array(np.asarray(Q0, float)[:, perm]),
        P=np.zeros((B, N)) if P0 is None else np.array(np.asarray(P0, float)[:, perm]),
        energy=np.zeros((B, N)),
        energy_sum=np.zeros((B, N)),
        energy_closest=np.zeros((B, N)),
        status=np.zeros(B, dtype=np.int64),
        epsilon=scalar.copy(),
        drift=scalar.copy(),
        contact_time=scalar.copy(),
        max_compression=scalar.copy(),
        max_force=scalar.copy(),
        steps=np.zeros(B, dtype=np.int64),
        t_end=scalar.copy(),
        x_end=scalar.copy(),
        dissipated=scalar.copy(),
    )
    kquad = _Quadrature(
        height=np.ascontiguousarray(quad.height, dtype=np.float64),
        weight=np.ascontiguousarray(quad.weight, dtype=np.float64),
        basis=np.ascontiguousarray(quad.basis[:, _group_columns(cols)], dtype=np.float64),
        C=np.ascontiguousarray(quad.C[perm], dtype=np.float64),
        S=np.ascontiguousarray(quad.S[perm], dtype=np.float64),
        starts=starts,
        g_max=np.ascontiguousarray(quad.g_max[perm], dtype=np.float64),
        cols=cols,
        ucols=(2 * cols).astype(np.uint64),
        dcols=_dot_split(cols),
    )
    ctl = _Control(
        weights=np.asarray(weights, dtype=np.float64),
        max_steps=int(max_steps),
        abort_drift=-1.0 if abort_drift is None else float(abort_drift),
        stop_log=float(stop_log),
        contact_tol=float(contact_tol),
        stop=np.zeros(1, dtype=np.int64) if stop is None else stop,
        law=int(law),
        law_params=np.zeros(0) if law_params is None else np.asarray(law_params, np.float64),
    )
    members = _Members(
        *(np.ascontiguousarray(a, dtype=np.float64) for a in (v, alpha, x_start, dt, t_max))
    )
    gamma = np.zeros(N) if damping is None else np.asarray(damping, dtype=np.float64)[perm]
    if np.any(gamma != 0.0) and min(weights) <= 0.0:
        raise ValueError("damped modes need a splitting with positive substeps (Strang)")
    args = (
        np.ascontiguousarray(omega[perm], dtype=np.float64),
        np.ascontiguousarray(gamma),
        float(mass),
        kquad,
        ctl,
        members,
        out,
    )
    threads = _threads()
    if B == 1 and threads >= 2 and N >= SPLIT_MIN_MODES:
        # One large collision: two threads, one group of orders each, in lock step.
        shared = (
            np.zeros(2 * LINE, dtype=np.int64),
            np.zeros((2, 2, 4)),
            np.zeros((2, 2, quad.height.size)),
            np.zeros(kquad.basis.shape[1]),
        )
        _in_threads(2, lambda part: _one(0, part, *args, shared), (0, 1), ctl.stop)
    else:
        # Members differ in cost (fast speeds take more steps at a given step), so the
        # threads take them one at a time, in the caller's order; the compiled member
        # releases the GIL. (A numba prange splits the members into fixed contiguous halves
        # whatever the chunk size, which left one core idle for a third of a sorted 32-speed
        # batch.)
        unused = (
            np.zeros(2 * LINE, dtype=np.int64),
            np.zeros((2, 2, 4)),
            np.zeros((2, 2, 1)),
            np.zeros(1),
        )

        def member(b: int) -> None:
            _one(b, -1, *args, unused)

        _in_threads(min(threads, B), member, range(B), ctl.stop)
    back = np.empty_like(perm)
    back[perm] = np.arange(N)
    return {
        "status": out.status.astype(int),
        "epsilon": out.epsilon,
        "drift": out.drift,
        "contact_time": out.contact_time,
        "max_compression": out.max_compression,
        "max_force": out.max_force,
        "steps": out.steps.astype(int),
        "t_end": out.t_end,
        "energy": out.energy[:, back],
        "energy_sum": out.energy_sum[:, back],
        "energy_closest": out.energy_closest[:, back],
        "final_Q": out.Q[:, back],
        "final_P": out.P[:, back],
        "final_x0": out.x_end,
        "dissipated": out.dissipated,
    }
