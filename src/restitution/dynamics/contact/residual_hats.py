"""The exponential wall on a body whose dropped modes follow the load statically, on hats of the
projected radius about the contact axis (issue 63; the oblique route's counterpart of
:mod:`restitution.dynamics.residual`).

Units: ``E = rho = R = 1``; forces in ``E R^2``, displacements in ``R``.

**The model.** Hat ``i`` (:class:`~restitution.bodies.sphere.contact_residual.ContactResidual`)
carries the load ``P_i = sum_j phi_i(rho_j) e_j`` of the wall nodes on it and moves them along
the wall's normal by ``U_i``; node ``j`` at its kept position ``X_j`` (the rigid motion and the
kept modes) sits at ``X_j + sum_i phi_i(rho_j) U_i`` and feels ``e_j = w_j exp(alpha (X_j +
phi_j . U))``. The dropped modes' equilibrium is ``U = -H P`` (``H`` their flexibility between
the hats), the minimum over ``U`` of the wall's energy plus theirs::

    V_eff = min_U [ sum_j w_j exp(alpha (X_j + phi_j . U)) / alpha + U . H^-1 . U / 2 ]
          = sum_j e_j / alpha + P . H . P / 2                       (at U = -H P)

so by the envelope theorem the forces on the kept coordinates are the wall's ``e_j`` on the kept
positions, as without the residual, plus the hats' own motion: ``phi_j`` depends on the body's
rotation through ``rho_j``, a torque ``-sum_j e_j (dU/drho)_j drho_j/dTheta``
(:meth:`HatWall.solve` returns each node's slope ``dU/drho``).

**The solve.** Newton's method on ``U + H P(U) = 0`` (Jacobian ``I + alpha H B``, ``B = Phi
diag(e) Phi^T`` tridiagonal), damped so that the largest miss ``alpha |U + H P|`` falls,
warm-started from the last solve, to ``alpha |U + H P| < 1e-11`` (each hat's log-force).
"""

from __future__ import annotations

import numpy as np

from restitution.dynamics.run import CollisionError

__all__ = ["HatWall", "TiltedHatWall"]

_TOL = 1e-11  # alpha |U + H P|: each hat's miss in log-force
_ITERATIONS = 100
_EXP_CAP = 200.0  # a trial step's exponent is capped: its products stay finite, and it is rejected


def _times_band(H: np.ndarray, d: np.ndarray, off: np.ndarray) -> np.ndarray:
    """``H @ B`` for the symmetric tridiagonal ``B`` of diagonal ``d`` and off-diagonal
    ``off`` (the hats' ``Phi diag(w) Phi^T``), column by column: ``O(K^2)``, not a dense
    product."""
    HB = H * d[None, :]
    HB[:, 1:] += H[:, :-1] * off[None, :]
    HB[:, :-1] += H[:, 1:] * off[None, :]
    return HB


def _damped_newton(wall, x, residual, jacobian):
    """Newton's method on ``residual(x) -> (miss, state)`` from ``x`` with ``jacobian(state)``,
    each step halved until the largest miss ``alpha |miss|`` falls, to ``alpha |miss| < _TOL``
    (module docs); counts ``wall.iterations`` and returns the solution and its state."""
    a = wall.alpha
    miss, state = residual(x)
    for _ in range(_ITERATIONS):
        wall.iterations += 1
        worst = a * float(np.max(np.abs(miss)))
        if worst < _TOL:
            return x, state
        step = -np.linalg.solve(jacobian(state), miss)
        lam = 1.0
        while True:
            trial = x + lam * step
            miss_t, state_t = residual(trial)
            if a * float(np.max(np.abs(miss_t))) < worst:
                break
            lam *= 0.5
            if lam < 1e-6:
                raise CollisionError(
                    "the residual's wall solve stalled (no step lowers its miss "
                    f"{worst:.3g}); soften the wall or lower the speed"
                )
        x, miss, state = trial, miss_t, state_t
    raise CollisionError(
        "the residual's wall solve did not converge in "
        f"{_ITERATIONS} Newton steps; soften the wall or lower the speed"
    )


class HatWall:
    """The wall's forces with the residual ``H`` on hats peaking at ``radii`` (``K + 1``; the
    last hat falls to zero at ``radii[K]``), hardness ``alpha`` (module docs)."""

    def __init__(self, H: np.ndarray, radii: np.ndarray, alpha: float) -> None:
        self.H, self.alpha = np.asarray(H, float), float(alpha)
        self.K = self.H.shape[0]
        self.radii = np.asarray(radii, float)[: self.K + 1]
        self.U = np.zeros(self.K)
        self.P = np.zeros(self.K)
        self.iterations = 0
        self.beyond = 0.0
        """The largest share of the wall force met on nodes beyond the hats (no residual)."""

    def _hats(self, rho: np.ndarray):
        """Each node's lower hat ``k`` (``K``: beyond them), its weights ``lo`` on ``k`` and
        ``hi`` on ``k + 1``, and ``d(hi)/drho``."""
        r, K = self.radii, self.K
        k = np.clip(np.searchsorted(r, rho, side="right") - 1, 0, K)
        inside = rho < r[0]
        width = r[np.minimum(k + 1, K)] - r[k]
        width = np.where(width > 0.0, width, 1.0)
        out = inside | (k >= K)
        f = np.where(out, 0.0, (rho - r[k]) / width)
        df = np.where(out, 0.0, 1.0 / width)
        lo = np.where(k < K, 1.0 - f, 0.0)
        hi = np.where(k + 1 < K, f, 0.0)
        return k, lo, hi, df

    def solve(self, log_e: np.ndarray, rho: np.ndarray):
        """Node forces ``e``, hat loads ``P`` (a copy) and each node's ``dU/drho`` from the
        nodes' ``log(w_j) + alpha X_j`` at their kept positions and their radii ``rho``."""
        a, K, H = self.alpha, self.K, self.H
        k, lo, hi, df = self._hats(rho)
        size = K + 2

        def state(U):
            Up = np.r_[U, 0.0, 0.0]
            e = np.exp(np.minimum(log_e + a * (lo * Up[k] + hi * Up[k + 1]), _EXP_CAP))
            P = (np.bincount(k, lo * e, size) + np.bincount(k + 1, hi * e, size))[:K]
            return e, P

        def residual(U):
            e, P = state(U)
            return U + H @ P, (e, P)

        def jacobian(st):
            e = st[0]
            d = (np.bincount(k, lo * lo * e, size) + np.bincount(k + 1, hi * hi * e, size))[:K]
            off = np.bincount(k, lo * hi * e, size)[: K - 1]
            HB = _times_band(H, d, off)
            HB *= a
            HB[diagonal, diagonal] += 1.0
            return HB

        diagonal = np.arange(K)
        U, (e, P) = _damped_newton(self, self.U, residual, jacobian)
        self.U, self.P = U, P
        Up = np.r_[U, 0.0, 0.0]
        slope = np.where(k < K, df * (Up[k + 1] - Up[k]), 0.0)
        total = float(e.sum())
        if total > 0.0:
            self.beyond = max(self.beyond, float(e[k >= K].sum()) / total)
        return e, P.copy(), slope

    def energy(self, e: np.ndarray) -> float:
        """The condensed wall energy ``sum e / alpha + P . H . P / 2`` of the last solve."""
        return float(e.sum()) / self.alpha + 0.5 * float(self.P @ self.H @ self.P)


class TiltedHatWall(HatWall):
    """:class:`HatWall` with Dundurs' coupling (docs/oblique.md, "Dundurs' coupling"): beside
    the hats' axisymmetric displacement ``U``, a tilting one ``V cos(psi)`` (``psi`` the node's
    azimuth about the contact axis from the line of the friction force) carrying the tilting
    loads ``P1 = sum_j phi_j cos(psi_j) e_j``; the in-line forces ``T`` on the hats (the
    friction spread like the pressure) tilt them too. Equilibrium ``U = -H P``, ``V = -H1 P1 -
    X T``: the minimum over ``U, V`` of the wall's energy plus ``U . H^-1 . U / 2 + (V + X T) .
    H1^-1 . (V + X T) / 2``, whose value is ``sum e / alpha + P . H . P / 2 + P1 . H1 . P1 /
    2`` and whose derivative in ``T`` is ``-X^T P1``. Newton's method on both, damped as
    :class:`HatWall`'s."""

    def __init__(self, H, radii, alpha: float, tilt, cross) -> None:
        super().__init__(H, radii, alpha)
        self.H1, self.X = np.asarray(tilt, float), np.asarray(cross, float)
        self.V = np.zeros(self.K)
        self.P1 = np.zeros(self.K)

    def solve_tilted(self, log_e, rho, cos, T):
        """Node forces ``e``, hat loads ``P`` and ``P1`` (copies), each node's ``dU/drho``, its
        tilt's ``dV/drho`` and ``V`` at the node, from the nodes' ``log(w_j) + alpha X_j``, radii
        ``rho``, ``cos(psi)`` and the hats' in-line forces ``T``."""
        a, K, H, H1 = self.alpha, self.K, self.H, self.H1
        k, lo, hi, df = self._hats(rho)
        size = K + 2
        shift = self.X @ T

        def spread(w):
            return (np.bincount(k, lo * w, size) + np.bincount(k + 1, hi * w, size))[:K]

        def state(U, V):
            Up, Vp = np.r_[U, 0.0, 0.0], np.r_[V, 0.0, 0.0]
            g = lo * (Up[k] + cos * Vp[k]) + hi * (Up[k + 1] + cos * Vp[k + 1])
            e = np.exp(np.minimum(log_e + a * g, _EXP_CAP))
            return e, spread(e), spread(cos * e)

        def band(w):
            d = (np.bincount(k, lo * lo * w, size) + np.bincount(k + 1, hi * hi * w, size))[:K]
            return d, np.bincount(k, lo * hi * w, size)[: K - 1]

        def residual(UV):
            U, V = UV[:K], UV[K:]
            e, P, P1 = state(U, V)
            return np.r_[U + H @ P, V + H1 @ P1 + shift], (e, P, P1)

        def jacobian(st):
            e = st[0]
            B00, B01, B11 = band(e), band(cos * e), band(cos * cos * e)
            jac = np.empty((2 * K, 2 * K))
            jac[:K, :K], jac[:K, K:] = _times_band(H, *B00), _times_band(H, *B01)
            jac[K:, :K], jac[K:, K:] = _times_band(H1, *B01), _times_band(H1, *B11)
            jac *= a
            jac[np.diag_indices(2 * K)] += 1.0
            return jac

        UV, (e, P, P1) = _damped_newton(self, np.r_[self.U, self.V], residual, jacobian)
        U, V = UV[:K], UV[K:]
        self.U, self.V, self.P, self.P1 = U, V, P, P1
        Up, Vp = np.r_[U, 0.0, 0.0], np.r_[V, 0.0, 0.0]
        inside = k < K
        slope = np.where(inside, df * (Up[k + 1] - Up[k]), 0.0)
        tilt_slope = np.where(inside, df * (Vp[k + 1] - Vp[k]), 0.0)
        tilt_value = lo * Vp[k] + hi * Vp[k + 1]
        total = float(e.sum())
        if total > 0.0:
            self.beyond = max(self.beyond, float(e[k >= K].sum()) / total)
        return e, P.copy(), P1.copy(), slope, tilt_slope, tilt_value

    def energy(self, e: np.ndarray) -> float:
        """The condensed wall energy ``sum e / alpha + P . H . P / 2 + P1 . H1 . P1 / 2`` of
        the last solve."""
        return super().energy(e) + 0.5 * float(self.P1 @ self.H1 @ self.P1)
