"""A collision with a static residual: the kept modes in motion, the modes above them following
the contact statically (the mode-acceleration method, or residual flexibility; issue 46).

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``, energies absolute.

**Why.** A truncated modal body is too stiff at the contact: the modes it drops are what make up
the contact's local compliance (Hertz's field), and the loss converges only like ``N^(-1/2)``
(disk) in the number of modes. The dropped modes are fast against the contact time, so they
follow the load statically; their compliance is kept instead of their motion.

**The model.** With the kept modes' coordinates ``Q_k`` and the node forces ``f_j`` (the
exponential wall: ``f_j = w_j exp(alpha x_j)``), every surface node sits at::

    x_j = x0 + height_j + sum_k g_k(node_j) Q_k - sum_i G_ji f_i

where ``G`` is the static flexibility of the dropped modes between the nodes (the body's
``residual_flexibility``; the disk: :func:`restitution.bodies.disk.static.residual_flexibility`).
The dropped modes' coordinates are eliminated by their static equilibrium, which is the minimum
of their elastic energy plus the wall's; so the kept system is Hamiltonian with the condensed
potential::

    V_eff(x0, Q) = min_u [ sum_j w_j exp(alpha (x_j^kept + u_j)) / alpha + u^T G^-1 u / 2 ]
                 = sum_j f_j / alpha + f^T G f / 2     (at the minimum, u = -G f)

and, by the envelope theorem, the forces on ``x0`` and ``Q`` are the wall's forces at that
minimum: ``F = sum f_j``, ``f_k = sum_j g_k(node_j) f_j``, as without the residual. Each force
evaluation solves ``u + G W exp(alpha (x^kept + u)) = 0`` by Newton's method (the Jacobian
``I + G D``, ``D = diag(alpha f)``, is solved through the symmetric positive definite
``I + D^(1/2) G D^(1/2)``; a line search on the residual keeps it monotone), warm-started from
the previous evaluation, on the prefix of nodes the force can reach.

**What judges the step.** The energy ``p0^2 / (2m) + sum_k E_k + V_eff`` is conserved by the
exact dynamics and the splitting keeps it bounded; its largest relative drift is reported, as
for the plain modal collision. Because the drift is no judge of epsilon
(docs/numerics.md, "The drift is not a judge of epsilon"), :func:`collide_residual` also runs
the collision at half the step when asked (``richardson=True``) and reports Richardson's
estimate ``|eps(dt) - eps(dt/2)| / 15`` of the fourth-order method.

Without the residual (``residual=False``) this is the paper's collision on the same nodes, which
the package's own collision computes; the tests compare the two.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.linalg import cho_factor, cho_solve

from restitution.bodies.base import ModalBody
from restitution.dynamics.contact.base import CONTACT_TOL
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL, NEGLIGIBLE, STOP_LOG
from restitution.dynamics.integrators import YOSHIDA, free_modes
from restitution.dynamics.residual_kernel import (
    NEWTON_FAILED,
    NODES_EXHAUSTED,
    OK,
    OVERFLOW,
    STALL_TOL,
    STEPS_EXHAUSTED,
    run_residual,
)
from restitution.errors import InputError, RestitutionError

__all__ = ["ResidualCollision", "collide_residual", "supports_residual"]

STEP_FACTOR = 0.2
"""Default step ``STEP_FACTOR * min(1 / (alpha v), 1 / omega_max)``, the package's automatic
step for the fourth-order splitting (docs/numerics.md, "Automatic step")."""

DEPTH_MARGIN = 2.0
"""The residual's nodes reach ``DEPTH_MARGIN`` times the quasistatic largest compression (plus
the wall's reach) below the tip; a contact that reaches the last of them is refused."""

WALL_SPACING = 0.12
"""The bodies' node rule: a spacing ``WALL_SPACING / sqrt(s)`` for a contact of depth ``1/s``
(:meth:`~restitution.bodies.base.ModalBody.contact_nodes`); ``nodes_per_contact`` asks it for
the ``s`` that puts that many nodes across the contact's half-width."""

_KERNEL_FAILURES = {
    NEWTON_FAILED: "the residual's contact solve did not converge; this is a bug",
    NODES_EXHAUSTED: "the contact reached the last of the residual's {count} nodes; raise "
    "DEPTH_MARGIN (a bug for a body at rest)",
    STEPS_EXHAUSTED: "the collision did not end within max_steps steps of {dt:.3g}; raise "
    "max_steps",
    OVERFLOW: "the integration overflowed with dt = {dt:.3g}: reduce the step",
}

_NEWTON_TOL = 1e-13
"""Newton's step on ``u`` ends once it is below this times the wall's decay length ``1/alpha``."""


def supports_residual(body: ModalBody) -> bool:
    """Whether ``body`` can give the static flexibility of the modes it leaves out."""
    return callable(getattr(body, "residual_flexibility", None))


@dataclass(frozen=True)
class ResidualCollision:
    """One collision with (or without) the static residual.

    ``epsilon``: ``-v_after / v``; ``loss``: ``1 - epsilon^2``; ``mode_loss``: the kept modes'
    energy after the collision over ``E0`` (equals ``loss`` up to the drift); ``drift``: largest
    relative energy drift; ``step_error``: Richardson's estimate of epsilon's step error
    (``None`` unless asked); ``dt``, ``steps``; ``nodes``: nodes the residual holds;
    ``active``: most nodes in contact at once; ``modes``: kept modes; ``residual``: whether the
    dropped modes' static compliance was in.
    """

    epsilon: float
    loss: float
    mode_loss: float
    drift: float
    step_error: float | None
    dt: float
    steps: int
    nodes: int
    active: int
    modes: int
    residual: bool


class _Contact:
    """The condensed wall: node forces at the static equilibrium of the dropped modes."""

    def __init__(
        self, quad, count: int, G: np.ndarray, alpha: float, end_cut: float = -math.inf
    ) -> None:
        self.height = quad.height[:count]
        self.weight = quad.weight[:count]
        self.basis = quad.basis[:count]
        self.edge, self.edge_t = quad.edge, quad.edge_t
        self.G = G
        self.alpha = alpha
        self.u = np.zeros(count)
        self.most = 0
        self.end_cut = end_cut

    def kept_position(self, x0: float, Q: np.ndarray) -> np.ndarray:
        return x0 + self.height + self.basis @ (self.edge_t @ Q)

    def _solve(self, xk: np.ndarray, n: int) -> np.ndarray:
        """Newton on the first ``n`` nodes; returns their forces (``u`` updated in place)."""
        a, G, w = self.alpha, self.G[:n, :n], self.weight[:n]
        u = self.u[:n].copy()
        for _ in range(100):
            f = w * np.exp(a * (xk[:n] + u))
            F = u + G @ f
            d = np.sqrt(a * f)
            chol = cho_factor(np.eye(n) + d[:, None] * G * d[None, :])
            z = cho_solve(chol, d * F)
            du = -(F - G @ (d * z))
            norm = np.max(np.abs(F))
            lam = 1.0
            while True:
                trial = u + lam * du
                Ft = trial + G @ (w * np.exp(a * (xk[:n] + trial)))
                if np.max(np.abs(Ft)) <= (1.0 - 0.25 * lam) * norm or lam < 1e-8:
                    break
                lam *= 0.5
            if lam < 1e-8 and np.max(np.abs(du)) * a < STALL_TOL:
                break  # the round-off floor (residual_kernel.STALL_TOL)
            u = trial
            if np.max(np.abs(lam * du)) * a < _NEWTON_TOL:
                break
        else:
            raise RestitutionError("the residual's contact solve did not converge; this is a bug")
        return w * np.exp(a * (xk[:n] + u))

    def forces(self, x0: float, Q: np.ndarray) -> tuple[np.ndarray, float, np.ndarray]:
        """Node forces (on all nodes), the condensed potential and the kept positions."""
        xk = self.kept_position(x0, Q)
        a, count = self.alpha, xk.size
        cut = -(NEGLIGIBLE + 5.0) / a
        n = int(np.flatnonzero(xk + self.u > cut)[-1]) + 1 if np.any(xk + self.u > cut) else 0
        f = np.zeros(count)
        while n:
            f[:n] = self._solve(xk, n)
            self.u = -self.G[:, :n] @ f[:n]
            reach = np.flatnonzero(xk + self.u > cut)
            wider = int(reach[-1]) + 1 if reach.size else 0
            if wider <= n:
                break
            n = wider
        if n == 0:
            self.u = np.zeros(count)
        if n >= count and a * (xk[count - 1] + self.u[count - 1]) > self.end_cut:
            raise RestitutionError(
                f"the contact reached the last of the residual's {count} nodes; raise "
                "DEPTH_MARGIN (a bug for a body at rest)"
            )
        self.most = max(self.most, n)
        V = f[:n].sum() / a + 0.5 * f[:n] @ (self.G[:n, :n] @ f[:n])
        return f, V, xk


def _run(
    body, v, alpha, dt, contact: _Contact, x_start, max_steps
) -> tuple[float, float, float, int]:
    m, w = body.mass, body.omega
    e0 = 0.5 * m * v * v
    x0, p0 = x_start, m * v
    Q = np.zeros(len(body))
    P = np.zeros(len(body))
    f, V, _ = contact.forces(x0, Q)
    h0 = p0 * p0 / (2.0 * m) + V
    drift, steps, touched = 0.0, 0, False

    def free(x0, Q, P, tau):
        return (x0 + p0 * tau / m, *free_modes(w, m, Q, P, tau))

    while True:
        for weight in YOSHIDA:
            tau = weight * dt
            x0, Q, P = free(x0, Q, P, 0.5 * tau)
            f, V, _ = contact.forces(x0, Q)
            p0 -= tau * f.sum()
            P = P - tau * (contact.edge @ (contact.basis.T @ f))
            x0, Q, P = free(x0, Q, P, 0.5 * tau)
        steps += 1
        f, V, xk = contact.forces(x0, Q)
        modal = float(np.sum(P * P / (2.0 * m) + 0.5 * m * (w * Q) ** 2))
        h = p0 * p0 / (2.0 * m) + modal + V
        if not math.isfinite(h):
            raise RestitutionError(
                f"the integration overflowed with dt = {dt:.3g}: reduce the step"
            )
        drift = max(drift, abs(h - h0) / h0)
        touched = touched or V > CONTACT_TOL * e0 * 1e6
        gap = -float(np.max(xk + contact.u))
        if touched and p0 < 0.0 and V < CONTACT_TOL * e0 and gap * alpha > STOP_LOG:
            return -p0 / (m * v), modal / e0, drift, steps
        if steps >= max_steps:
            raise RestitutionError(
                f"the collision did not end within {max_steps} steps of {dt:.3g}; raise max_steps"
            )


def collide_residual(
    body: ModalBody,
    v: float,
    alpha: float,
    *,
    residual: bool = True,
    dt: float | None = None,
    step_factor: float = STEP_FACTOR,
    n_nodes: int | None = None,
    richardson: bool = False,
    max_steps: int = 2_000_000,
    nodes_per_contact: float | None = None,
    backend: str = "compiled",
) -> ResidualCollision:
    """One collision of ``body`` (at rest, speed ``v`` in ``c``) with the exponential wall of
    hardness ``alpha`` (``1 / R``), its modes above the set following the contact statically.

    ``n_nodes``: the surface quadrature's nodes (default the body's own for ``alpha``);
    ``dt``: a fixed step (default ``step_factor * min(1/(alpha v), 1/omega_max)``);
    ``richardson``: also run at ``dt / 2`` and report the step error (the result is the
    finer run's); ``nodes_per_contact``: instead of the wall's node spacing, about this many
    nodes across the contact's half-width ``sqrt(2 delta_max)`` (never more nodes than the
    wall's rule; the residual resolves the contact, not the wall's decay length);
    ``backend``: ``"compiled"`` (:mod:`restitution.dynamics.residual_kernel`) or ``"numpy"``
    (the reference loop).
    """
    if backend not in ("compiled", "numpy"):
        raise InputError(f"backend must be 'compiled' or 'numpy', got {backend!r}")
    if not (math.isfinite(v) and v > 0.0 and math.isfinite(alpha) and alpha > 0.0):
        raise InputError(f"v and alpha must be positive numbers, got v = {v}, alpha = {alpha}")
    if residual and not supports_residual(body):
        raise InputError(
            f"the {body.geometry} has no static residual yet: run it with residual=False"
        )
    compression = v * body.contact_time_estimate(v) / math.pi
    if n_nodes is None:
        s = alpha
        if nodes_per_contact is not None:
            s = min(alpha, (WALL_SPACING * nodes_per_contact) ** 2 / (2.0 * compression))
        n_nodes = body.contact_nodes(s)
    quad = body.surface_quadrature(n_nodes)
    e0 = 0.5 * body.mass * v * v
    x_start = float(EXPONENTIAL_WALL.start_position(np.array([alpha]), np.array([e0]), quad)[0])
    depth = DEPTH_MARGIN * compression + (NEGLIGIBLE + 20.0) / alpha
    count = int(np.searchsorted(-quad.height, -(1.0 - depth), side="right")) + 1
    # The hats need one node beyond the last. Where the rule asks for more nodes than the
    # surface has (a soft wall far below the centre: the disk at nu = 0.2, v = 0.3, alpha
    # delta_max = 40), the contact may reach the surface's last hat, provided the force there is
    # negligible (exponent below -NEGLIGIBLE, as the plain kernel skips such nodes).
    end_cut = -NEGLIGIBLE if count >= quad.nodes.size - 1 else -math.inf
    count = min(count, quad.nodes.size - 1)
    if residual:
        G = body.residual_flexibility(quad, count)
    else:
        G = np.zeros((count, count))
    step = (
        dt
        if dt is not None
        else step_factor * min(1.0 / (alpha * v), 1.0 / float(body.omega.max()))
    )

    def once(step):
        if backend == "numpy":
            contact = _Contact(quad, count, G, alpha, end_cut)
            eps, mode_loss, drift, steps = _run(body, v, alpha, step, contact, x_start, max_steps)
            return eps, mode_loss, drift, steps, contact.most
        edge = sparse.csr_matrix(quad.edge_t)
        out = run_residual(
            x_start, v, float(body.mass), np.ascontiguousarray(body.omega, dtype=float),
            np.ascontiguousarray(quad.basis[:count], dtype=float),
            edge.indptr.astype(np.int64), edge.indices.astype(np.int64),
            np.ascontiguousarray(edge.data, dtype=float),
            np.ascontiguousarray(quad.height[:count]), np.ascontiguousarray(quad.weight[:count]),
            np.ascontiguousarray(G), float(alpha), float(step), int(max_steps), CONTACT_TOL,
            STOP_LOG, -(NEGLIGIBLE + 5.0) / alpha, _NEWTON_TOL, end_cut,
        )  # fmt: skip
        eps, mode_loss, drift, steps, most, status = out
        if status != OK:
            raise RestitutionError(_KERNEL_FAILURES[status].format(count=count, dt=step))
        return eps, mode_loss, drift, steps, most

    eps, mode_loss, drift, steps, most = once(step)
    error = None
    if richardson:
        coarse = eps
        step *= 0.5
        eps, mode_loss, drift2, steps, most2 = once(step)
        drift, most = max(drift, drift2), max(most, most2)
        error = abs(coarse - eps) / 15.0
    return ResidualCollision(
        epsilon=float(eps),
        loss=float(1.0 - eps * eps),
        mode_loss=float(mode_loss),
        drift=float(drift),
        step_error=error,
        dt=float(step),
        steps=int(steps),
        nodes=int(count),
        active=int(most),
        modes=len(body),
        residual=bool(residual),
    )
