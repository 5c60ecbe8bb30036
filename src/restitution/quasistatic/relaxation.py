"""Static relaxation of the disk against the wall at a fixed centre position (paper section 5).

Units: ``E = rho = R = 1``; lengths in ``R``, forces in ``E R``, energies in ``E R^2``.

With the momenta zero, the energy (41) (corrected per ERRATA: ``(m/2) omega^2 Q^2``) at a fixed
centre position ``x0`` is::

    U(Q; x0) = (m/2) sum_k omega_k^2 Q_k^2 + (1/alpha) int_{-pi/2}^{pi/2} exp(alpha x(phi)) dphi,
    x(phi) = x0 + cos(phi) + sum_k Q_k g_k(phi),
    g_k(phi) = C_k cos(n_k phi) cos(phi) - S_k sin(n_k phi) sin(phi)                 (40)

``U`` is strictly convex in ``Q`` (a positive quadratic plus the integral of an exponential of a
linear function), so it has one minimum, found here by Newton's method with the exact Hessian
``m diag(omega^2) + alpha G^T diag(w e^{alpha x}) G`` and a backtracking line search. The
Hessian is inverted with the Woodbury identity over the quadrature nodes that carry force
(their number is far below the number of modes). The force on the disk at the minimum is
``F = int exp(alpha x) dphi = dU_min/dx0`` (envelope theorem), recorded against the
compression ``delta = x0 + 1``.

Fixing ``x0`` and minimising over the modes, which exclude the rigid translation, is the
static problem of a disk pressed against the wall and held by a uniform body force: the
quasistatic problem of section 5.

Quadrature: the trapezoidal rule on ``M`` uniform nodes of ``[0, pi/2]``, doubled (``x(phi)``
is even). The even extension of the integrand is smooth and negligible at ``pi/2``, so the rule
converges spectrally once the node spacing resolves both ``cos(n_max phi)`` and the edge of the
contact zone, whose width is ``~ (alpha kappa)^(-2/3)``; :func:`default_n_phi` takes 16 nodes
per period of ``n_max`` and a spacing of at most ``0.1 / sqrt(alpha)``. The tests check the
convergence in ``M``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.disk.modes import ModeSet
from restitution.errors import InputError, RestitutionError

__all__ = [
    "RelaxationCurve",
    "RelaxationError",
    "StaticState",
    "centre_offset",
    "default_n_phi",
    "relax",
    "relaxation_curve",
]


# Largest increase of an exponent alpha x(phi) in one Newton step.
_MAX_RISE = 20.0
# Largest compression step of the continuation, times alpha.
_STEP_RISE = 8.0
# Relative Newton decrement below which full steps are taken without line search.
_LOCAL = 1e-8


class RelaxationError(RestitutionError):
    """Newton's method did not converge."""


def default_n_phi(alpha: float, n_max: int) -> int:
    """Quadrature nodes on ``[0, pi/2]``: 16 per period of ``cos(n_max phi)``, spacing
    ``<= 0.1/sqrt(alpha)``, at least 256."""
    spacing = min(0.1 / math.sqrt(alpha), 2.0 * math.pi / (16.0 * max(n_max, 1)))
    return max(256, int(math.ceil(0.5 * math.pi / spacing)) + 1)


def _edge(modes: ModeSet, n_phi: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Nodes, weights, ``cos(phi)`` and the dense edge matrix ``g_k(phi_j)`` of the wall."""
    quad = modes.surface_quadrature(n_phi)
    G = modes.surface_matrix(quad.nodes)
    return quad.nodes, quad.weight, quad.height, np.ascontiguousarray(G)


@dataclass(frozen=True, eq=False)
class StaticState:
    """The relaxed disk at one centre position.

    Attributes
    ----------
    delta : float
        Compression ``x0 + 1``, ``R``.
    force : float
        Wall force ``int exp(alpha x) dphi``, ``E R``.
    energy : float
        ``U`` at the minimum (elastic + wall), ``E R^2``.
    elastic_energy : float
        ``(m/2) sum omega^2 Q^2``, ``E R^2``.
    edge_gap : float
        ``x(phi = 0)``: where the front point sits relative to the wall (negative: short of
        it), ``R``.
    Q : numpy.ndarray, shape (N,)
        Modal amplitudes, ``R``.
    iterations : int
        Newton iterations used.
    """

    delta: float
    force: float
    energy: float
    elastic_energy: float
    edge_gap: float
    Q: np.ndarray
    iterations: int


class _Problem:
    """Energy, gradient and Newton step of ``U(Q; x0)`` on a fixed quadrature."""

    def __init__(self, modes: ModeSet, alpha: float, n_phi: int):
        self.alpha = float(alpha)
        self.k = modes.mass * modes.omega**2  # diagonal of the elastic Hessian
        _, self.w, self.cos_phi, self.G = _edge(modes, n_phi)
        # G D^-1 and the node-node matrix K = G D^-1 G^T do not change during the
        # minimisation: one matrix product here, only matrix-vector products per iteration.
        self.GD = self.G / self.k[None, :]
        # One matrix-vector product per row keeps this out of threaded BLAS-3 (see _pcg).
        self.K = np.array([self.G @ row for row in self.GD])

    def parts(self, x0: float, Q: np.ndarray):
        x = x0 + self.cos_phi + self.G @ Q
        with np.errstate(over="ignore"):
            e = self.w * np.exp(self.alpha * x)
        elastic = 0.5 * float(np.dot(self.k * Q, Q))
        return x, e, elastic, elastic + float(e.sum()) / self.alpha

    def newton_step(self, Q: np.ndarray, e: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        grad = self.k * Q + self.G.T @ e
        # Woodbury: (D + G^T S^2 G)^-1 = D^-1 - D^-1 G^T S (I + S G D^-1 G^T S)^-1 S G D^-1
        active = np.flatnonzero(e > 1e-30 * e.max())
        Ga = self.G[active]
        s = np.sqrt(self.alpha * e[active])
        Dinv_g = grad / self.k
        GDinv = self.GD[active]
        inner = (s[:, None] * self.K[np.ix_(active, active)]) * s[None, :]
        inner[np.diag_indices_from(inner)] += 1.0
        # The inner matrix is >= I and its condition number stays below ~1e4 (about 2e3 at
        # alpha = 8000, delta = 0.3), so preconditioned conjugate gradients solve it with
        # matrix-vector products only. (A Cholesky factorisation is faster on an idle
        # machine, but multithreaded LAPACK calls slow down by 10-100x on a loaded one.)
        rhs = s * (Ga @ Dinv_g)
        corr = _pcg(inner, rhs)
        step = -(Dinv_g - GDinv.T @ (s * corr))
        return step, grad


def _newton(prob: _Problem, delta: float, Q0: np.ndarray, tol: float, max_iter: int):
    """Damped Newton iteration on the convex ``U(Q; x0 = delta - 1)`` from ``Q0``."""
    x0 = float(delta) - 1.0
    Q = np.array(Q0, dtype=float)
    x, e, el, U = prob.parts(x0, Q)
    last_dec = math.inf
    iterations = 0
    for _ in range(max_iter):
        iterations += 1
        step, grad = prob.newton_step(Q, e)
        dec = -float(np.dot(grad, step))
        scale = float(e.sum()) / prob.alpha + el
        if dec <= tol * scale:
            break
        if dec <= _LOCAL * scale:
            # Inside the region of quadratic convergence: full steps, no line search (whose
            # energy comparison is at round-off here). Stop if round-off stalls the decrement.
            if dec > 0.1 * last_dec:
                break
            Q = Q + step
            x, e, el, U = prob.parts(x0, Q)
            last_dec = dec
            continue
        # Cap the step so that no exponent alpha x grows by more than _MAX_RISE: the line
        # search then never meets overflowing energies.
        rise = prob.alpha * float(np.max(prob.G @ step))
        t = min(1.0, _MAX_RISE / rise) if rise > 0 else 1.0
        while True:
            Qn = Q + t * step
            xn, en, eln, Un = prob.parts(x0, Qn)
            if np.isfinite(Un) and Un <= U - 0.25 * t * dec:
                break
            t *= 0.5
            if t < 1e-12:
                raise RelaxationError(
                    f"line search failed at delta = {delta} (alpha = {prob.alpha}); "
                    "use relaxation_curve (continuation) or a finer quadrature"
                )
        Q, x, e, el, U = Qn, xn, en, eln, Un
        last_dec = dec
    else:
        raise RelaxationError(
            f"Newton's method did not converge in {max_iter} iterations at delta = {delta}; "
            "raise max_iter or use relaxation_curve (continuation)"
        )
    return StaticState(
        delta=float(delta),
        force=float(e.sum()),
        energy=U,
        elastic_energy=el,
        edge_gap=float(x[0]),
        Q=Q,
        iterations=iterations,
    )


def _check(alpha: float, delta) -> None:
    if not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"alpha must be positive and finite, got {alpha}")
    if not np.all(np.isfinite(delta)):
        raise InputError(f"compressions delta must be finite, got {delta}")


def _pcg(A: np.ndarray, b: np.ndarray, rtol: float = 1e-13, max_iter: int = 5000) -> np.ndarray:
    """Solve the symmetric positive definite ``A x = b`` by Jacobi-preconditioned CG."""
    dinv = 1.0 / np.diag(A)
    x = np.zeros_like(b)
    r = b.copy()
    z = dinv * r
    p = z.copy()
    rz = float(r @ z)
    bnorm = float(np.linalg.norm(b))
    if bnorm == 0.0:
        return x
    for _ in range(max_iter):
        Ap = A @ p
        a = rz / float(p @ Ap)
        x += a * p
        r -= a * Ap
        if float(np.linalg.norm(r)) <= rtol * bnorm:
            return x
        z = dinv * r
        rz_new = float(r @ z)
        p = z + (rz_new / rz) * p
        rz = rz_new
    # Round-off can stall CG short of rtol on an ill-conditioned system; a direct solve
    # settles it.
    return np.linalg.solve(A, b)


def relax(
    modes: ModeSet,
    delta: float,
    alpha: float,
    *,
    n_phi: int | None = None,
    Q0: np.ndarray | None = None,
    tol: float = 1e-20,
    max_iter: int = 200,
) -> StaticState:
    """Minimise ``U(Q; x0 = delta - 1)`` over the modal amplitudes.

    Parameters
    ----------
    modes : ModeSet
        The modes to relax (``N`` of them).
    delta : float
        Compression ``x0 + 1`` in ``R``; any real value (negative: short of the wall).
    alpha : float
        Wall hardness, ``1 / R``.
    n_phi : int, optional
        Quadrature nodes on ``[0, pi/2]``; default :func:`default_n_phi`.
    Q0 : numpy.ndarray, shape (N,), optional
        Starting amplitudes. Without it the minimum is reached by continuation in ``delta``
        (:func:`relaxation_curve`), which is robust; from a distant ``Q0`` Newton's method on
        the exponential needs about ``alpha * |x error|`` damped steps.
    tol : float
        Stop when the Newton decrement ``-grad . step`` is below ``tol`` times the energy
        scale ``F / alpha + elastic energy``.
    max_iter : int
        Newton iterations before :class:`RelaxationError`.

    Returns
    -------
    StaticState
    """
    _check(alpha, delta)
    n_phi = n_phi or default_n_phi(alpha, int(np.max(modes.n, initial=1)))
    if Q0 is None:
        return _continuation(modes, np.array([float(delta)]), alpha, n_phi, tol)[0]
    return _newton(_Problem(modes, alpha, n_phi), delta, Q0, tol, max_iter)


@dataclass(frozen=True)
class RelaxationCurve:
    """Force against compression of the statically relaxed disk.

    Attributes
    ----------
    delta : numpy.ndarray, shape (K,)
        Compressions ``x0 + 1``, ``R``.
    force : numpy.ndarray, shape (K,)
        Wall force at the minimum, ``E R``.
    energy, elastic_energy : numpy.ndarray, shape (K,)
        Total and elastic energy at the minimum, ``E R^2``.
    edge_gap : numpy.ndarray, shape (K,)
        ``x(phi = 0)`` at the minimum, ``R``.
    iterations : numpy.ndarray of int, shape (K,)
    nu, alpha : float
    n_modes, n_phi : int
    """

    delta: np.ndarray
    force: np.ndarray
    energy: np.ndarray
    elastic_energy: np.ndarray
    edge_gap: np.ndarray
    iterations: np.ndarray
    nu: float
    alpha: float
    n_modes: int
    n_phi: int


def relaxation_curve(
    modes: ModeSet,
    delta: np.ndarray,
    alpha: float = 500.0,
    *,
    n_phi: int | None = None,
    tol: float = 1e-20,
) -> RelaxationCurve:
    """Relax at each compression in ``delta`` (sorted ascending) by continuation in ``delta``.

    Parameters
    ----------
    modes : ModeSet
    delta : array_like, shape (K,)
        Compressions in ``R``.
    alpha : float
        Wall hardness, ``1 / R`` (the paper's Fig. 10 uses 500).
    n_phi : int, optional
        Quadrature nodes on ``[0, pi/2]``; default :func:`default_n_phi`.
    tol : float
        Passed to :func:`relax`.
    """
    delta = np.sort(np.atleast_1d(np.asarray(delta, dtype=float)))
    _check(alpha, delta)
    n_phi = n_phi or default_n_phi(alpha, int(np.max(modes.n, initial=1)))
    out = _continuation(modes, delta, alpha, n_phi, tol)
    return RelaxationCurve(
        delta=delta,
        force=np.array([s.force for s in out]),
        energy=np.array([s.energy for s in out]),
        elastic_energy=np.array([s.elastic_energy for s in out]),
        edge_gap=np.array([s.edge_gap for s in out]),
        iterations=np.array([s.iterations for s in out]),
        nu=float(modes.nu),
        alpha=float(alpha),
        n_modes=len(modes),
        n_phi=int(n_phi),
    )


def _continuation(
    modes: ModeSet, delta: np.ndarray, alpha: float, n_phi: int, tol: float
) -> list[StaticState]:
    """Minima at the sorted compressions ``delta`` by continuation.

    Starts where the wall is negligible (``Q = 0`` is exact to ``e^{-20}``) and walks up in
    sub-steps of at most ``_STEP_RISE / alpha``, each started from the linear extrapolation of
    the two previous minima, so that Newton's method needs a handful of iterations.
    """
    prob = _Problem(modes, alpha, n_phi)
    h = _STEP_RISE / alpha
    d_prev, Q_prev = None, None
    d_last, Q_last = min(-_MAX_RISE / alpha, float(delta[0])), np.zeros(len(modes))
    out = []
    for d in delta:
        while True:
            target = min(d, d_last + h)
            if Q_prev is None or target <= d_last:
                guess = Q_last
            else:
                guess = Q_last + (Q_last - Q_prev) * (target - d_last) / (d_last - d_prev)
            st = _newton(prob, target, guess, tol, 200)
            if target > d_last:
                d_prev, Q_prev = d_last, Q_last
                d_last, Q_last = target, st.Q
            if target >= d:
                break
        out.append(st)
    return out


def centre_offset(modes: ModeSet) -> tuple[float, float]:
    """Mean displacement of the disk relative to its far end, under a unit point load.

    For a point load ``P`` at ``phi = 0`` balanced by a uniform body force, the modal static
    response ``Q_k = -P C_k / (m omega_k^2)`` gives the centre-of-mass approach
    ``P sum C_k^2 / (m omega^2)`` and the diameter compression
    ``P sum C_k^2 (1 + (-1)^n) / (m omega^2)``; both diverge logarithmically, their difference
    ``(P / (pi E)) c'`` with ``c' = -(pi E / m) sum_k (-1)^n_k C_k^2 / omega_k^2`` converges
    (conditionally). Returns the Cesaro mean of the partial sums over the upper half of the
    mode set and their standard deviation there (the uncertainty).

    The result matches ``-2/pi - nu/4`` (the ``"centre"`` law of
    :mod:`restitution.quasistatic.hertz` minus the ``"diameter"`` law); see ``docs/quasistatic.md``.

    Parameters
    ----------
    modes : ModeSet
        Sorted by frequency; a few hundred modes or more.

    Returns
    -------
    value, spread : float
        ``c'`` and the standard deviation of its partial sums (dimensionless).
    """
    terms = -(math.pi / modes.mass) * (-1.0) ** modes.n * modes.C**2 / modes.omega**2
    partial = np.cumsum(terms)
    upper = partial[len(partial) // 2 :]
    return float(upper.mean()), float(upper.std())
