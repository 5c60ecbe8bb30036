"""The collision with a static residual as one compiled loop (numba): the fast path of
:mod:`restitution.dynamics.residual`, whose NumPy loop stays the reference.

Units: ``E = rho = R = 1``; times in ``R / c``; energies absolute.

The same model and step as the NumPy path (Yoshida's composition of Strang steps, the
condensed wall solved on the active prefix of the nodes, a line search on the residual), with
one change in the solver: a chord method. The Newton matrix ``B = (I + G D)^(-1)``
(``D = diag(alpha f)``; formed as ``I - G D^(1/2) (I + D^(1/2) G D^(1/2))^(-1) D^(1/2)``, whose
middle factor is symmetric positive definite) is kept between calls and formed anew only when
the active node count changes or an iteration reduces the residual by less than half; an
iteration is then two matrix-vector products. Both solvers stop at the same tolerance on the
step, so the paths agree to that tolerance and round-off (the tests: 1e-10 in epsilon).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from restitution.dynamics.integrators import YOSHIDA

__all__ = [
    "NEWTON_FAILED",
    "NODES_EXHAUSTED",
    "OK",
    "OVERFLOW",
    "STALL_TOL",
    "STEPS_EXHAUSTED",
    "run_residual",
]

OK, NEWTON_FAILED, NODES_EXHAUSTED, STEPS_EXHAUSTED, OVERFLOW = 0, 1, 2, 3, 4
"""Status codes of :func:`run_residual`."""

STALL_TOL = 1e-9
"""The contact solve also stops where no step along the Newton direction lowers the residual
(the line search falls below ``1e-8``) and that step is below ``STALL_TOL`` in ``alpha u``:
round-off, not divergence. The step tolerance (``1e-13`` in ``alpha u``) is about the
round-off of ``u + G f`` itself on hard walls (``alpha delta_max = 320``: ``alpha`` times one
unit in the last place of ``u`` is 7e-14; measured a stalled step of 1.006e-13), where the
solve used to fail as "did not converge"."""


@numba.njit(cache=True)
def _residual(u, xk, w, Gn, a, n, f, F):
    """``f = w exp(a (xk + u))`` and ``F = u + G f`` on the first ``n`` nodes; max |F|."""
    for j in range(n):
        f[j] = w[j] * math.exp(a * (xk[j] + u[j]))
    F[:n] = u[:n] + np.dot(Gn, f[:n])
    return np.max(np.abs(F[:n]))


@numba.njit(cache=True)
def _factor(u, xk, w, G, a, n, gbuf, bbuf):
    """The Newton matrix ``B`` at ``u`` (module docstring) into ``bbuf``, and ``G``'s leading
    block into ``gbuf`` (both contiguous ``n x n``)."""
    Gn = gbuf[: n * n].reshape((n, n))
    Gn[:, :] = G[:n, :n]
    d = np.empty(n)
    for j in range(n):
        d[j] = math.sqrt(a * w[j] * math.exp(a * (xk[j] + u[j])))
    A = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            A[i, j] = d[i] * Gn[i, j] * d[j]
        A[i, i] += 1.0
    H = np.linalg.inv(A)
    for i in range(n):
        for j in range(n):
            H[i, j] *= d[i] * d[j]
    Bn = bbuf[: n * n].reshape((n, n))
    Bn[:, :] = -np.dot(Gn, H)
    for i in range(n):
        Bn[i, i] += 1.0


@numba.njit(cache=True)
def _newton(xk, w, G, a, n, u, tol, gbuf, bbuf, state):
    """Solve ``u + G w exp(a (xk + u)) = 0`` on the first ``n`` nodes in place by the chord
    method (module docstring); False if it did not converge."""
    f = np.empty(n)
    F = np.empty(n)
    trial = np.empty(n)
    if state[0] != n:
        _factor(u, xk, w, G, a, n, gbuf, bbuf)
        state[0] = n
    Gn = gbuf[: n * n].reshape((n, n))
    Bn = bbuf[: n * n].reshape((n, n))
    norm = _residual(u, xk, w, Gn, a, n, f, F)
    for _ in range(200):
        du = -np.dot(Bn, F[:n])
        if np.max(np.abs(du)) * a < tol:
            u[:n] += du
            return True
        lam = 1.0
        while True:
            trial[:] = u[:n] + lam * du
            t_norm = _residual(trial, xk, w, Gn, a, n, f, F)
            if t_norm <= (1.0 - 0.25 * lam) * norm or lam < 1e-8:
                break
            lam *= 0.5
        if lam < 1e-8 and np.max(np.abs(du)) * a < STALL_TOL:
            return True  # the round-off floor: no step reduces the residual (module docstring)
        u[:n] = trial
        if t_norm > 0.5 * norm:
            _factor(u, xk, w, G, a, n, gbuf, bbuf)
            norm = _residual(u, xk, w, Gn, a, n, f, F)
        else:
            norm = t_norm
    return False


@numba.njit(cache=True)
def _edge(Q, indptr, indices, data, c):
    """``c = E Q`` for the sparse edge map ``E`` (CSR: ``indptr, indices, data``; rows the
    surface basis's columns, columns the modes)."""
    for r in range(c.size):
        acc = 0.0
        for k in range(indptr[r], indptr[r + 1]):
            acc += data[k] * Q[indices[k]]
        c[r] = acc


@numba.njit(cache=True)
def _edge_back(b, indptr, indices, data, scale, P):
    """``P += scale E^T b`` (``E`` as in :func:`_edge`)."""
    for r in range(b.size):
        br = scale * b[r]
        for k in range(indptr[r], indptr[r + 1]):
            P[indices[k]] += data[k] * br


@numba.njit(cache=True)
def _forces(x0, Q, height, w, basis, edge, G, a, cut, tol, u, xk, f, gbuf, bbuf, state,
            end_cut):  # fmt: skip
    """Node forces (``f``, all nodes), the condensed potential; ``u`` updated. Returns
    ``(V, n, status)``. The kept positions are ``basis (E Q)``: the modes summed per column
    of the surface basis first (``edge = (indptr, indices, data, c)``, ``c`` a buffer)."""
    count = height.size
    indptr, indices, data, c = edge
    _edge(Q, indptr, indices, data, c)
    xk[:] = x0 + height + np.dot(basis, c)
    n = 0
    for j in range(count):
        if xk[j] + u[j] > cut:
            n = j + 1
    f[:] = 0.0
    while n > 0:
        if n > count or (n == count and a * (xk[count - 1] + u[count - 1]) > end_cut):
            return 0.0, n, NODES_EXHAUSTED
        if not _newton(xk, w, G, a, n, u, tol, gbuf, bbuf, state):
            return 0.0, n, NEWTON_FAILED
        for j in range(n):
            f[j] = w[j] * math.exp(a * (xk[j] + u[j]))
        # G is symmetric: -G[:, :n] f = -f G[:n, :], the first n rows (contiguous)
        u[:] = -np.dot(f[:n], G.ravel()[: n * count].reshape((n, count)))
        wider = 0
        for j in range(count):
            if xk[j] + u[j] > cut:
                wider = j + 1
        if wider <= n:
            break
        n = wider
    if n == 0:
        u[:] = 0.0
        return 0.0, 0, OK
    V = 0.0
    for i in range(n):
        V += f[i] / a - 0.5 * f[i] * u[i]  # f^T G f / 2 with u = -G f
    return V, n, OK


@numba.njit(cache=True)
def run_residual(x_start, v, m, omega, basis, indptr, indices, data, height, w, G, a, dt,
                 max_steps, contact_tol, stop_log, cut, tol, end_cut):  # fmt: skip
    """One collision; returns ``(epsilon, modal energy / E0, drift, steps, most active nodes,
    status)`` (status :data:`OK` or the reason it stopped). ``basis`` (count x K) and the
    sparse edge map (CSR ``indptr, indices, data``, K x N) give the nodes' displacement per
    mode coordinate as ``basis E``, never formed densely: a step costs ``count K`` and the
    map's entries, not ``count N``. A contact over all ``count`` nodes is refused unless the
    last node's exponent ``a (x + u)`` is below ``end_cut`` (``-inf``: always refused)."""
    N = omega.size
    count = height.size
    K = basis.shape[1]
    edge = (indptr, indices, data, np.empty(K))
    e0 = 0.5 * m * v * v
    x0 = x_start
    p0 = m * v
    Q = np.zeros(N)
    P = np.zeros(N)
    u = np.zeros(count)
    xk = np.empty(count)
    f = np.zeros(count)
    gbuf = np.zeros(count * count)
    bbuf = np.zeros(count * count)
    state = np.zeros(1, dtype=np.int64)
    weights = YOSHIDA
    cs = np.empty((3, N))
    sn = np.empty((3, N))
    for i in range(3):
        for k in range(N):
            cs[i, k] = math.cos(omega[k] * 0.5 * weights[i] * dt)
            sn[i, k] = math.sin(omega[k] * 0.5 * weights[i] * dt)
    mw = m * omega
    V, n, status = _forces(x0, Q, height, w, basis, edge, G, a, cut, tol, u, xk, f, gbuf,
                               bbuf, state, end_cut)  # fmt: skip
    h0 = p0 * p0 / (2.0 * m) + V
    drift = 0.0
    most = n
    touched = False
    modal = 0.0
    for step in range(1, max_steps + 1):
        for i in range(3):
            tau = weights[i] * dt
            for half in range(2):
                x0 += p0 * 0.5 * tau / m
                q = Q.copy()
                Q[:] = q * cs[i] + P * sn[i] / mw
                P[:] = P * cs[i] - mw * q * sn[i]
                if half == 0:
                    V, n, status = _forces(x0, Q, height, w, basis, edge, G, a, cut, tol, u,
                                           xk, f, gbuf, bbuf, state, end_cut)  # fmt: skip
                    if status != OK:
                        return 0.0, 0.0, drift, step, n, status
                    most = max(most, n)
                    if n > 0:
                        p0 -= tau * np.sum(f[:n])
                        b = np.dot(f[:n], basis[:n])
                        _edge_back(b, indptr, indices, data, -tau, P)
        V, n, status = _forces(x0, Q, height, w, basis, edge, G, a, cut, tol, u, xk, f, gbuf,
                               bbuf, state, end_cut)  # fmt: skip
        if status != OK:
            return 0.0, 0.0, drift, step, n, status
        modal = np.sum(P * P) / (2.0 * m) + 0.5 * m * np.sum((omega * Q) ** 2)
        hh = p0 * p0 / (2.0 * m) + modal + V
        if not math.isfinite(hh):
            return 0.0, 0.0, drift, step, n, OVERFLOW
        drift = max(drift, abs(hh - h0) / h0)
        if V > contact_tol * e0 * 1e6:
            touched = True
        top = np.max(xk + u)
        if touched and p0 < 0.0 and V < contact_tol * e0 and -top * a > stop_log:
            return -p0 / (m * v), modal / e0, drift, step, most, OK
    return 0.0, 0.0, drift, max_steps, most, STEPS_EXHAUSTED
