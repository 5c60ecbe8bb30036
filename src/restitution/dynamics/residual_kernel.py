"""The collision with a static residual as one compiled loop (numba): the fast path of
:mod:`restitution.dynamics.residual`, whose NumPy loop stays the reference.

Units: ``E = rho = R = 1``; times in ``R / c``; energies absolute.

Same arithmetic as the NumPy path (Yoshida's composition of Strang steps, the condensed wall
solved by Newton's method through the Cholesky factor of ``I + D^(1/2) G D^(1/2)``, a line
search on the residual), written out in loops over the active prefix of the nodes so that no
array is allocated per step. The two paths agree to round-off (the tests: 1e-10 in epsilon).
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["NEWTON_FAILED", "NODES_EXHAUSTED", "OK", "OVERFLOW", "STEPS_EXHAUSTED", "run_residual"]

OK, NEWTON_FAILED, NODES_EXHAUSTED, STEPS_EXHAUSTED, OVERFLOW = 0, 1, 2, 3, 4
"""Status codes of :func:`run_residual`."""

_YOSHIDA_1 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
_YOSHIDA_0 = 1.0 - 2.0 * _YOSHIDA_1


@numba.njit(cache=True)
def _positions(x0, height, g, Q, xk):
    count, N = g.shape
    for j in range(count):
        s = 0.0
        for k in range(N):
            s += g[j, k] * Q[k]
        xk[j] = x0 + height[j] + s


@numba.njit(cache=True)
def _gf(G, f, n, out):
    """``out[:rows] = -G[:rows, :n] @ f[:n]`` for all rows of ``out``."""
    for i in range(out.size):
        s = 0.0
        for j in range(n):
            s += G[i, j] * f[j]
        out[i] = -s


@numba.njit(cache=True)
def _residual(u, xk, w, G, a, n, f, F):
    """``f = w exp(a (xk + u))`` and ``F = u + G f`` on the first ``n`` nodes; max |F|."""
    for j in range(n):
        f[j] = w[j] * math.exp(a * (xk[j] + u[j]))
    big = 0.0
    for i in range(n):
        s = u[i]
        for j in range(n):
            s += G[i, j] * f[j]
        F[i] = s
        big = max(big, abs(s))
    return big


@numba.njit(cache=True)
def _newton(xk, w, G, a, n, u, tol):
    """Solve ``u + G w exp(a (xk + u)) = 0`` on the first ``n`` nodes in place; False if it
    did not converge."""
    f = np.empty(n)
    F = np.empty(n)
    d = np.empty(n)
    z = np.empty(n)
    du = np.empty(n)
    trial = np.empty(n)
    A = np.empty((n, n))
    for _ in range(100):
        norm = _residual(u, xk, w, G, a, n, f, F)
        for j in range(n):
            d[j] = math.sqrt(a * f[j])
        for i in range(n):
            for j in range(n):
                A[i, j] = d[i] * G[i, j] * d[j]
            A[i, i] += 1.0
        L = np.linalg.cholesky(A)
        for i in range(n):  # forward: L y = d F
            s = d[i] * F[i]
            for j in range(i):
                s -= L[i, j] * z[j]
            z[i] = s / L[i, i]
        for i in range(n - 1, -1, -1):  # back: L^T z = y
            s = z[i]
            for j in range(i + 1, n):
                s -= L[j, i] * z[j]
            z[i] = s / L[i, i]
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += G[i, j] * d[j] * z[j]
            du[i] = -(F[i] - s)
        lam = 1.0
        while True:
            for j in range(n):
                trial[j] = u[j] + lam * du[j]
            t_norm = _residual(trial, xk, w, G, a, n, f, F)
            if t_norm <= (1.0 - 0.25 * lam) * norm or lam < 1e-8:
                break
            lam *= 0.5
        step = 0.0
        for j in range(n):
            step = max(step, abs(lam * du[j]))
            u[j] = trial[j]
        if step * a < tol:
            return True
    return False


@numba.njit(cache=True)
def _forces(x0, Q, height, w, g, G, a, cut, tol, u, xk, f):
    """Node forces (``f``, all nodes), the condensed potential; ``u`` updated. Returns
    ``(V, n, status)``."""
    count = height.size
    _positions(x0, height, g, Q, xk)
    n = 0
    for j in range(count):
        if xk[j] + u[j] > cut:
            n = j + 1
    for j in range(count):
        f[j] = 0.0
    while n > 0:
        if n >= count:
            return 0.0, n, NODES_EXHAUSTED
        if not _newton(xk, w, G, a, n, u, tol):
            return 0.0, n, NEWTON_FAILED
        for j in range(n):
            f[j] = w[j] * math.exp(a * (xk[j] + u[j]))
        _gf(G, f, n, u)
        wider = 0
        for j in range(count):
            if xk[j] + u[j] > cut:
                wider = j + 1
        if wider <= n:
            break
        n = wider
    if n == 0:
        for j in range(count):
            u[j] = 0.0
    V = 0.0
    for i in range(n):
        V += f[i] / a
        s = 0.0
        for j in range(n):
            s += G[i, j] * f[j]
        V += 0.5 * f[i] * s
    return V, n, 0


@numba.njit(cache=True)
def run_residual(x_start, v, m, omega, g, height, w, G, a, dt, max_steps, contact_tol,
                 stop_log, cut, tol):  # fmt: skip
    """One collision; returns ``(epsilon, modal energy / E0, drift, steps, most active nodes,
    status)`` (status :data:`OK` or the reason it stopped)."""
    N = omega.size
    count = height.size
    e0 = 0.5 * m * v * v
    x0 = x_start
    p0 = m * v
    Q = np.zeros(N)
    P = np.zeros(N)
    u = np.zeros(count)
    xk = np.empty(count)
    f = np.empty(count)
    weights = (_YOSHIDA_1, _YOSHIDA_0, _YOSHIDA_1)
    cs = np.empty((3, N))
    sn = np.empty((3, N))
    for i in range(3):
        for k in range(N):
            cs[i, k] = math.cos(omega[k] * 0.5 * weights[i] * dt)
            sn[i, k] = math.sin(omega[k] * 0.5 * weights[i] * dt)
    V, n, status = _forces(x0, Q, height, w, g, G, a, cut, tol, u, xk, f)
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
                for k in range(N):
                    mw = m * omega[k]
                    q, pk = Q[k], P[k]
                    Q[k] = q * cs[i, k] + pk * sn[i, k] / mw
                    P[k] = pk * cs[i, k] - mw * q * sn[i, k]
                if half == 0:
                    V, n, status = _forces(x0, Q, height, w, g, G, a, cut, tol, u, xk, f)
                    if status != 0:
                        return 0.0, 0.0, drift, step, n, status
                    most = max(most, n)
                    total = 0.0
                    for j in range(n):
                        total += f[j]
                    p0 -= tau * total
                    for k in range(N):
                        s = 0.0
                        for j in range(n):
                            s += g[j, k] * f[j]
                        P[k] -= tau * s
        V, n, status = _forces(x0, Q, height, w, g, G, a, cut, tol, u, xk, f)
        if status != 0:
            return 0.0, 0.0, drift, step, n, status
        modal = 0.0
        for k in range(N):
            modal += P[k] * P[k] / (2.0 * m) + 0.5 * m * (omega[k] * Q[k]) ** 2
        hh = p0 * p0 / (2.0 * m) + modal + V
        if not math.isfinite(hh):
            return 0.0, 0.0, drift, step, n, OVERFLOW
        drift = max(drift, abs(hh - h0) / h0)
        if V > contact_tol * e0 * 1e6:
            touched = True
        top = -1e300
        for j in range(count):
            top = max(top, xk[j] + u[j])
        if touched and p0 < 0.0 and V < contact_tol * e0 and -top * a > stop_log:
            return -p0 / (m * v), modal / e0, drift, step, most, OK
    return 0.0, 0.0, drift, max_steps, most, STEPS_EXHAUSTED
