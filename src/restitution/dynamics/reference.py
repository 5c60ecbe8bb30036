"""Reference solution of the disk-wall collision with scipy's DOP853 (adaptive, order 8).

The same Hamiltonian as :mod:`restitution.dynamics.collision`, written as a plain first-order system
``y = (x0, p0, Q, P)`` with no splitting, for tests and benchmarks. Slow: the adaptive steps
must follow every mode's oscillation. A viscoelastic body's damping enters as the force
``-gamma_k P_k`` and the energy it takes is integrated alongside (``y`` gains one component,
``int sum gamma_k P_k^2 / m dt``).
"""

from __future__ import annotations

import time

import numpy as np
from scipy.integrate import solve_ivp

from restitution.bodies.base import ModalBody
from restitution.bodies.viscoelastic import mode_damping
from restitution.dynamics.contact.base import CONTACT_TOL, ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.errors import InputError

__all__ = ["collide_dop853"]


def collide_dop853(
    body: ModalBody,
    v: float,
    alpha: float,
    *,
    t_end: float | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    n_phi: int | None = None,
    wall: str = "dense",
    contact_law: ContactLaw = EXPONENTIAL_WALL,
) -> dict:
    """Integrate one collision with ``solve_ivp(method="DOP853")``.

    The wall terms are evaluated the straightforward way, with the dense matrix ``g_k(phi_j)``
    of eq. (40) over all quadrature nodes (no grouping by order, no skipping of inactive
    nodes): an independent implementation of the same equations and the natural baseline.
    Only the contact law's node terms are shared with the modal solver.

    Parameters
    ----------
    body : ModalBody
    v, alpha : float
        Speed towards the wall (``c``) and wall hardness (``1 / R``).
    t_end : float, optional
        End time (``R / c``); by default the time for the disk to travel back to its start
        position at half its initial speed, long after separation for any epsilon > 0.5.
    rtol, atol : float
        Tolerances of DOP853.
    n_phi : int, optional
        Edge quadrature nodes (default as in the modal solver).
    wall : {"dense", "orders"}
        ``dense`` (default) as described above; ``orders`` uses the modal solver's own
        order-by-order wall terms with inactive nodes skipped
        (:meth:`~restitution.dynamics.contact.base.ContactLaw.contact_terms`), so that a
        benchmark can separate the gain of the integrator from that of the wall evaluation.
    contact_law : ContactLaw, optional
        The contact law (:mod:`restitution.dynamics.contact`); default the exponential wall.
        ``wall="dense"`` sums its node terms, so a law that replaces ``contact_terms`` needs
        ``wall="orders"``.

    Returns
    -------
    dict
        ``epsilon``, ``energy_after`` (per mode, fraction of E0), ``energy_dissipated``
        (fraction of E0), ``energy_drift`` (with the dissipated energy counted), ``nfev``,
        ``wall_time_s``, ``t_end``.
    """
    m, w = body.mass, body.omega
    N = len(body)
    quad = body.surface_quadrature(n_phi or contact_law.nodes(body, alpha))
    a = np.array([alpha], float)
    e0 = 0.5 * m * v**2
    x_start = float(contact_law.start_position(a, np.array([e0]), quad)[0])
    if t_end is None:
        t_end = 2.0 * (-1.0 - x_start) / v + 20.0

    if wall not in ("dense", "orders"):
        raise InputError(f"wall must be 'dense' or 'orders', got {wall!r}")
    if wall == "dense" and type(contact_law).contact_terms is not ContactLaw.contact_terms:
        raise InputError(
            f"the contact law {contact_law.name!r} replaces contact_terms, so the dense sum of "
            "its node terms is not its force; pass wall='orders'"
        )
    G = body.surface_matrix(quad.nodes) if wall == "dense" else None

    alpha_0d = np.asarray(float(alpha))

    def wall_terms_dense(x0, Q):
        V, F, e = contact_law.node_terms(alpha_0d, x0 + quad.height + G @ Q, quad.weight)
        return V, F, e @ G

    def wall_terms_orders(x0, Q):
        V, F, f = contact_law.contact_terms(quad, a, np.array([x0]), Q[None, :])
        return V[0], F[0], f[0]

    wall = wall_terms_dense if G is not None else wall_terms_orders

    gamma = mode_damping(body)
    gamma = np.zeros(N) if gamma is None else gamma

    def rhs(_t, y):
        x0, p0, Q, P = y[0], y[1], y[2 : 2 + N], y[2 + N : 2 + 2 * N]
        _, F, f = wall(x0, Q)
        lost = np.sum(gamma * P**2) / m
        return np.concatenate(([p0 / m, -F], P / m, -m * w**2 * Q - f - gamma * P, [lost]))

    def energy(y):
        Q, P = y[2 : 2 + N], y[2 + N : 2 + 2 * N]
        V, _, _ = wall(y[0], Q)
        modes = np.sum(P**2 / (2 * m) + 0.5 * m * (w * Q) ** 2)
        return y[1] ** 2 / (2 * m) + modes + V + y[-1]

    y0 = np.zeros(3 + 2 * N)
    y0[0], y0[1] = x_start, m * v
    start = time.perf_counter()
    sol = solve_ivp(
        rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol, dense_output=False
    )
    elapsed = time.perf_counter() - start
    y = sol.y[:, -1]
    Q, P = y[2 : 2 + N], y[2 + N : 2 + 2 * N]
    e_modes = (P**2 / (2 * m) + 0.5 * m * (w * Q) ** 2) / e0
    h = np.array(
        [energy(sol.y[:, i]) for i in range(0, sol.y.shape[1], max(1, sol.y.shape[1] // 200))]
    )
    V_end, _, _ = wall(y[0], Q)
    if V_end > CONTACT_TOL * e0:
        raise RuntimeError("DOP853 reference ended while still in contact; increase t_end")
    return {
        "epsilon": float(-y[1] / (m * v)),
        "energy_after": e_modes,
        "energy_dissipated": float(y[-1] / e0),
        "energy_drift": float(np.max(np.abs(h - h[0])) / h[0]),
        "nfev": int(sol.nfev),
        "wall_time_s": elapsed,
        "t_end": t_end,
    }
