"""Oblique impact of a vibrating grain on a rigid wall with Coulomb friction, in normal modes.

Units: ``E = rho = R = 1`` of the grain (the disk: two-dimensional constants, energies per unit
thickness ``E R^2``; the sphere: three-dimensional ones, ``E R^3``); speeds in ``c``, spins in
``c / R``, times in ``R / c``; energies reported as fractions of the initial kinetic energy
``E0`` (translation and rotation). docs/oblique.md ("The modal oblique collision", "The
sphere's modal oblique collision") gives the equations and the measured checks. The equations
are written below for the disk's rim; the sphere's nodes obey the same two coordinates ``X``,
``Y`` with their rest position and displacement in the plane of incidence
(:mod:`restitution.bodies.sphere.cap_nodes`), so everything after the node positions holds for
both.

**Coordinates.** The grain's centre ``(x0, y0)``, its rotation angle ``Theta`` (counter-clockwise)
and the modal coordinates ``Q_k`` of its rim in the body frame
(:class:`~restitution.bodies.disk.rim.Rim`: both mode families). The material point at angle
``phi`` sits at

    X = x0 + (1 + u_r) cos(phi + Theta) - u_phi sin(phi + Theta)
    Y = y0 + (1 + u_r) sin(phi + Theta) + u_phi cos(phi + Theta),

``u_r = sum_k Q_k U_rk(phi)``, ``u_phi = sum_k Q_k U_phik(phi)``: the rotation is exact (the
contact point travels over the rim as the grain rolls), the deformation linear. The kinetic
energy is ``(m/2)(vx^2 + vy^2) + (I/2) Theta'^2 + (m/2) sum Q_k'^2``: the modes carry no linear
and no angular momentum (they are orthogonal to the rigid motions), and the centrifugal and
Coriolis couplings of the rotating frame, ``(Theta'^2/2) int rho (2 r.u + u^2)`` and
``Theta' int rho u x u'``, are left out: relative size ``(Theta' / omega_1)^2`` and
``Theta' / omega_1`` on the modes (``omega_1`` the lowest mode; ``Theta' ~ v_t / R << c / R``).

**The wall.** The paper's exponential wall at ``x = 0`` (eq. 41), ``V = (1/alpha) sum_j w_j
exp(alpha X_j)`` over a uniform grid of material angles on the whole rim (the head-on
quadrature's spacing, :meth:`~restitution.bodies.disk.rim.Rim.node_spacing`), pushes node ``j``
with ``e_j = w_j exp(alpha X_j)``; ``F_n = sum e_j``.

**Friction.** One Coulomb contact whose tangential force ``F_t`` is spread over the nodes like the
pressure, ``t_j = F_t p_j``, ``p_j = e_j / F_n``. Its power ``sum t_j Y_j' = F_t v_s`` defines the
slip velocity

    v_s = sum_j p_j Y_j' = vy + Theta' l + sum_k Q_k' g_k,
    l = sum_j p_j (X_j - x0),   g_k = sum_j p_j dY_j/dQ_k,

the pressure-weighted tangential velocity of the rim in contact: rigid translation, rigid
rotation with lever ``l`` (``R`` less the compression) and the modes' tangential surface
velocity. Coulomb: ``|F_t| <= mu F_n``; slip ``F_t = -s mu F_n``, ``s = sign(v_s)``; stick
``v_s = 0``. The equations of motion (``M = diag(m, m, I, m, ...)``, generalised velocities
``u = (vx, vy, Theta', Q')``, ``Gamma = (0, 1, l, g)`` so that ``v_s = Gamma . u``):

    m vx' = -F_n,   m vy' = F_t,   I Theta'' = tau_n + F_t l,
    m Q_k'' = -m omega_k^2 Q_k - sum_j e_j dX_j/dQ_k + F_t g_k,

``tau_n = sum_j e_j (Y_j - y0)`` the torque of the normal forces. Two friction models
(:data:`FRICTION_MODELS`):

* ``"stick-slip"``, the exact switch: in stick ``F_t`` is the force that keeps ``v_s' = 0``,

      F_stick = -(Gamma . M^-1 f + c) / (Gamma . M^-1 Gamma),
      c = Theta' sum_j p_j (2 xi_j - Theta' (Y_j - y0))
          + alpha sum_j p_j (X_j' - Xbar') (Y_j' - v_s),

  ``f`` the conservative generalised forces, ``xi_j = sum_k Q_k' dX_j/dQ_k`` the modal part of
  ``X_j'``, ``Xbar' = sum p_j X_j'``; the ``alpha`` term is the pressure's drift over the rim
  (``p_j' = alpha p_j (X_j' - Xbar')``). Phases of DOP853 with events: slip ends when ``v_s``
  reaches 0 (then stick if ``|F_stick| <= mu F_n``, else slip reversed), stick ends when
  ``|F_stick|`` reaches ``mu F_n``.
* ``"regularised"``: ``F_t = -mu F_n v_s / sqrt(v_s^2 + eta^2)``, one smooth DOP853 run; it
  tends to the switch as ``eta -> 0`` (first order, tests), as a check of the switch's stick
  force.

The friction work ``W = -int F_t v_s dt >= 0`` is integrated with the state, so that

    E0 = (m/2)(vx^2 + vy^2) + (I/2) Theta'^2 + E_modes + W + V      (after the contact)

holds to the integration error: :attr:`ObliqueCollision.energy_balance`.

**Impulse ratio.** For a rigid body (``l = R``, ``tau_n = 0``) in gross slip ``F_t = -mu F_n``
throughout, so with ``J_n = m v_n (1 + e)`` the contact point's velocity changes by
``Delta v_c = J_t / m + R^2 J_t / I = -K mu v_n (1 + e)``, ``K = 1 + m R^2 / I`` (3 for the disk),
and ``beta = -1 + K mu (1 + e) / tan(theta)``. The modes change it in three places: ``e < 1``
(the vibrations' share, measured), the lever ``l = R - delta`` (compression, first order in
``v``) and the normal forces' torque ``tau_n`` of a pressure pushed off the centre line by the
antisymmetric modes (:attr:`ObliqueCollision.lever_correction` and
:attr:`ObliqueCollision.normal_torque_correction` give both exactly).

A body enters through :class:`RimBody`, which places its own nodes (:class:`WallNodes`): the
disk's :func:`~restitution.bodies.disk.rim.rim_modes`, the sphere's
:func:`~restitution.bodies.sphere.cap.cap_modes`; with zero friction the symmetric
(axisymmetric) family alone moves and the run is the head-on collision of
:mod:`restitution.dynamics.collision` with the same modes, wall and node rings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
from scipy.integrate import solve_ivp

from restitution.dynamics.contact.base import CONTACT_TOL
from restitution.dynamics.contact.exponential import NEGLIGIBLE, STOP_LOG
from restitution.dynamics.run import CollisionError
from restitution.errors import InputError, is_real, real

__all__ = [
    "FRICTION_MODELS",
    "Grain",
    "ObliqueCollision",
    "ObliqueHistory",
    "RimBody",
    "WallNodes",
    "collision_result",
    "impulse_ratio_beta",
    "oblique_collision",
]

FRICTION_MODELS = ("stick-slip", "regularised")
"""The friction models of :func:`oblique_collision` (module docs)."""

_PHASES = 1000  # more stick/slip phases than this is chatter (measured: up to 287)
_NAMES = {1.0: "slip+", -1.0: "slip-", 0.0: "stick"}
_WORK_TOL = 1e-9  # friction work below -this E0 is a slip against its direction, not rounding


@runtime_checkable
class WallNodes(Protocol):
    """A body's surface nodes against the wall (the disk's
    :class:`~restitution.bodies.disk.rim.RimNodes`, the sphere's
    :class:`~restitution.bodies.sphere.cap_nodes.CapNodes`)."""

    reach: np.ndarray
    """Shape (N,): bounds every node's displacement along the wall's normal per unit ``|Q_k|``,
    at any rotation, ``R``."""

    def start_integral(self, alpha: float) -> float:
        """``sum_j w_j exp(alpha (h_j - 1))`` of the undeformed, unturned body (``h_j`` the
        node's height along the impact axis)."""
        ...

    def place(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes that may reach ``x = cutoff`` for the centre at ``x0``, the body turned by
        ``rotation`` about the axis normal to the plane of incidence (counter-clockwise) and
        modal coordinates and velocities ``Q``, ``Qd`` (shape (N,)): ``None`` if none may, else
        ``(weight, X, Y - y0, xi, eta, project)``: weights (shape () or (M,)), positions
        (M,), the modal velocities ``xi = sum_k Qd_k dX/dQ_k``, ``eta = sum_k Qd_k dY/dQ_k``
        (M,), and ``project(e, p) -> (e @ dX/dQ, p @ dY/dQ)`` (shapes (N,)) for nodal forces
        ``e`` and their fractions ``p = e / sum(e)``."""
        ...

    def jacobian(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes of :meth:`place` with their identity and their Jacobians, for friction
        point by point (:mod:`restitution.dynamics.oblique_microslip`): ``None`` or ``(index,
        weight, X, Y - y0, eta, J)``, ``index`` (M,) into the node grid (a node keeps its index
        from step to step), ``eta = dY/dQ @ Qd`` (M,) and ``J`` a
        :class:`~restitution.bodies.node_jacobian.NodeJacobian` (the Jacobians unformed)."""
        ...

    def jacobians(self, x0, rotation, Q, reach: float, cutoff: float):
        """:meth:`jacobian` at ``Qd = 0`` with the Jacobians formed, (M, N) each: ``None`` or
        ``(index, weight, X, Y - y0, dX/dQ, dY/dQ)`` (for checks)."""
        ...


@runtime_checkable
class RimBody(Protocol):
    """What an oblique collision needs of a body: its modes in the plane of incidence's
    symmetry, with rigid translation and rotation left to the collision (the disk's
    :class:`~restitution.bodies.disk.rim.Rim`, the sphere's
    :class:`~restitution.bodies.sphere.cap.SphereCap`)."""

    omega: np.ndarray
    """Frequencies, shape (N,), ``c / R``."""

    def __len__(self) -> int: ...

    @property
    def mass(self) -> float: ...

    @property
    def inertia(self) -> float:
        """Moment of inertia about the axis normal to the plane of incidence."""
        ...

    def wall_nodes(self, alpha: float, n_nodes: int | None = None) -> WallNodes:
        """The surface nodes that resolve the wall of hardness ``alpha`` (``n_nodes`` of the
        body's own kind: rim nodes, rings)."""
        ...

    def wall_node_count(self, alpha: float, n_nodes: int | None = None) -> int:
        """How many nodes :meth:`wall_nodes` makes, known before they are made."""
        ...

    def wall_node_memory(self, alpha: float, n_nodes: int | None = None) -> float:
        """Bytes that making and keeping :meth:`wall_nodes` takes (its peak), known before."""
        ...

    def contact_time_estimate(self, v):
        """Quasistatic contact time at normal speed ``v``, ``R / c``."""
        ...


@dataclass(frozen=True)
class ObliqueHistory:
    """The collision in time, arrays of shape (T,) at the integrator's steps: ``t`` (``R / c``)
    from the start position, ``normal_force`` and ``tangential_force`` (``E R``), ``slip``
    (``v_s``, ``c``), ``phase`` (+1 slip+, -1 slip-, 0 stick)."""

    t: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    slip: np.ndarray
    phase: np.ndarray


@dataclass(frozen=True)
class ObliqueCollision:
    """What :func:`oblique_collision` returns. Speeds ``c``, spins ``c / R`` (positive in the
    rolling sense of ``v_tangential > 0``), energies fractions of ``e0``.

    Attributes
    ----------
    v_normal, v_tangential_before, spin_before, mu, alpha : float
        The inputs.
    friction : str
        The friction model; ``regularisation`` its ``eta`` (``c``; ``None`` for the switch).
    epsilon_normal : float
        ``-(normal velocity after) / v_normal``.
    beta : float
        ``-v_c(after) / v_c(before)``, ``v_c = v_t - R omega`` the rigid contact point's
        tangential velocity (Foerster et al. 1994: -1 smooth, +1 reversed; ``nan`` if
        ``v_c(before) = 0``).
    v_tangential, spin, contact_velocity : float
        After the collision: centre, spin, ``v_c``.
    e0 : float
        Initial kinetic energy, ``E R^2`` (translation and rotation).
    translation_energy, rotation_energy, vibration_energy : float
        After the collision.
    mode_energy : numpy.ndarray, shape (N,)
        Per mode of the body, in its order.
    friction_work : float
        ``-int F_t v_s dt``.
    wall_energy : float
        Wall potential at the stop (below ``CONTACT_TOL``).
    energy_balance : float
        1 minus all of the above: the integration error.
    normal_impulse, tangential_impulse : float
        ``int F_n dt``, ``int F_t dt`` (``rho R^3 c``).
    lever_correction, normal_torque_correction : float
        ``beta`` less the rigid impulse ratio with this ``e`` splits into these two:
        ``(R / I) int F_t (R - l) dt / v_c`` and ``-(R / I) int tau_n dt / v_c``.
    phases : tuple of (str, float)
        ``("slip+" | "slip-" | "stick", start time)``.
    t_end, steps : float, int
        Time of the stop after the start position (``R / c``), integrator steps.
    history : ObliqueHistory or None
    """

    v_normal: float
    v_tangential_before: float
    spin_before: float
    mu: float
    alpha: float
    friction: str
    regularisation: float | None
    epsilon_normal: float
    beta: float
    v_tangential: float
    spin: float
    contact_velocity: float
    e0: float
    translation_energy: float
    rotation_energy: float
    vibration_energy: float
    mode_energy: np.ndarray
    friction_work: float
    wall_energy: float
    energy_balance: float
    normal_impulse: float
    tangential_impulse: float
    lever_correction: float
    normal_torque_correction: float
    phases: tuple
    t_end: float
    steps: int
    history: ObliqueHistory | None = None


def impulse_ratio_beta(mu, tan_theta, epsilon_normal, inertia_factor: float = 3.0):
    """``beta = -1 + K mu (1 + e) / tan(theta)`` of a rigid body in gross slip (module docs;
    ``K = 1 + m R^2 / I``: 3 disk, 7/2 solid sphere).

    >>> round(impulse_ratio_beta(0.1, math.tan(math.radians(80.0)), 1.0), 9)
    -0.894203812
    """
    return -1.0 + inertia_factor * mu * (1.0 + epsilon_normal) / tan_theta


class Grain:
    """The body on its wall nodes and the forces of one state (the two friction routes':
    this module's and :mod:`restitution.dynamics.oblique_microslip`)."""

    def __init__(self, body: RimBody, alpha: float, n_nodes: int | None):
        self.m, self.inertia, self.alpha = float(body.mass), float(body.inertia), float(alpha)
        self.N = len(body)
        self.nodes = body.wall_nodes(alpha, n_nodes)
        self.w2 = np.asarray(body.omega, float) ** 2
        self.reach_k = np.asarray(self.nodes.reach, float)

    def start_position(self, e0: float) -> float:
        """``x0`` where the undeformed grain's wall energy is ``CONTACT_TOL e0`` (as the head-on
        :meth:`~restitution.dynamics.contact.exponential.ExponentialWall.start_position`)."""
        a = self.alpha
        integral = self.nodes.start_integral(a)
        return -1.0 + math.log(CONTACT_TOL * e0 * a / integral) / a

    def terms(self, y):
        """Everything of state ``y`` the equations need (see :func:`oblique_collision`)."""
        N, a = self.N, self.alpha
        x0, th = y[0], y[1]
        Q, vx, vy, om, Qd = y[2 : 2 + N], y[2 + N], y[3 + N], y[4 + N], y[5 + N : 5 + 2 * N]
        reach = float(np.abs(Q) @ self.reach_k)
        # Nodes below the cutoff carry a negligible part of the wall force. Leaving the wall
        # (every node below it) the band follows the highest possible node, so that the
        # weights p = e / Fn stay whole to exp(-NEGLIGIBLE): with the fixed cutoff alone the
        # nodes dropped in the tail were ~1e-5 of p and made v_s jump by more than the slip
        # event's hair (measured: 5e-11 at Fn = 5e-13 as a rigid disk rolled off at alpha =
        # 100; on one CPU's rounding, 1000 zero-length slip phases).
        cutoff = min(-NEGLIGIBLE / a, x0 + 1.0 + reach - NEGLIGIBLE / a)
        placed = self.nodes.place(x0, th, Q, Qd, reach, cutoff)
        if placed is None:
            return None
        weight, X, Yr, xi, eta, project = placed
        e = weight * np.exp(a * X)
        Fn = float(e.sum())
        if Fn == 0.0:  # every active node far out (a ringing grain leaving): no contact
            return None
        p = e / Fn
        lever = float(p @ (X - x0))
        fQ, g = project(e, p)
        Xd = vx - om * Yr + xi
        Yd = vy + om * (X - x0) + eta
        vs = float(p @ Yd)
        return {
            "Fn": Fn,
            "V": Fn / a,
            "tau": float(e @ Yr),
            "fQ": fQ,
            "lever": lever,
            "g": g,
            "vs": vs,
            "p": p,
            "Yr": Yr,
            "xi": xi,
            "Xd": Xd,
            "Yd": Yd,
        }

    def stick_force(self, y, k) -> float:
        """``F_t`` that keeps ``v_s' = 0`` (module docs)."""
        N, m, I = self.N, self.m, self.inertia
        Q, om = y[2 : 2 + N], y[4 + N]
        p = k["p"]
        fQ = -m * self.w2 * Q - k["fQ"]
        drive = k["lever"] * k["tau"] / I + float(k["g"] @ fQ) / m
        Xbar = float(p @ k["Xd"])
        c = om * float(p @ (2.0 * k["xi"] - om * k["Yr"]))
        c += self.alpha * float(p @ ((k["Xd"] - Xbar) * (k["Yd"] - k["vs"])))
        mobility = 1.0 / m + k["lever"] ** 2 / I + float(k["g"] @ k["g"]) / m
        return -(drive + c) / mobility

    def rhs(self, y, Ft_of):
        """``dy/dt``; ``Ft_of(y, terms)`` gives the friction force."""
        N, m, I = self.N, self.m, self.inertia
        Q, vx, om, Qd = y[2 : 2 + N], y[2 + N], y[4 + N], y[5 + N : 5 + 2 * N]
        out = np.empty_like(y)
        out[0], out[1], out[2 : 2 + N] = vx, om, Qd
        k = self.terms(y)
        if k is None:
            out[2 + N], out[3 + N], out[4 + N] = 0.0, 0.0, 0.0
            out[5 + N : 5 + 2 * N] = -self.w2 * Q
            out[5 + 2 * N :] = 0.0
            return out
        Ft = Ft_of(y, k)
        out[2 + N] = -k["Fn"] / m
        out[3 + N] = Ft / m
        out[4 + N] = (k["tau"] + Ft * k["lever"]) / I
        out[5 + N : 5 + 2 * N] = -self.w2 * Q - (k["fQ"] - Ft * k["g"]) / m
        out[5 + 2 * N] = -Ft * k["vs"]  # friction work
        out[6 + 2 * N] = Ft * (1.0 - k["lever"])  # int F_t (R - l) dt
        out[7 + 2 * N] = k["tau"]  # int tau_n dt
        return out

    def free_reach(self, y) -> float:
        """Bound on the rim's displacement over the free vibration from ``y``, ``R``."""
        N = self.N
        Q, Qd = y[2 : 2 + N], y[5 + N : 5 + 2 * N]
        with np.errstate(divide="ignore", invalid="ignore"):
            amp = np.sqrt(Q**2 + np.where(self.w2 > 0, Qd**2 / self.w2, 0.0))
        return float(amp @ self.reach_k)


def _check(body, v_normal, v_tangential, mu, alpha, spin, friction, regularisation, rtol):
    if not isinstance(body, RimBody):
        raise InputError(
            f"body must hold its modes of both symmetries with wall nodes (RimBody), got "
            f"{type(body).__name__}; for the disk pass restitution.bodies.disk.rim.rim_modes("
            "modes), for the sphere restitution.bodies.sphere.cap.cap_modes(modes)"
        )
    v_n = real(v_normal, "v_normal", "in (0, 1) (c)")
    v_t = real(v_tangential, "v_tangential", "(c)")
    w0 = real(spin, "spin", "(c/R)")
    mu = real(mu, "mu", ">= 0")
    alpha = real(alpha, "alpha", "> 0 (1/R)")
    for bad, what in (
        (not 0.0 < v_n < 1.0, f"v_normal in (0, 1) c, got {v_n}"),
        (not (math.isfinite(v_t) and math.isfinite(w0)), "finite v_tangential and spin"),
        (not (math.isfinite(mu) and mu >= 0.0), f"a finite mu >= 0, got {mu}"),
        (not (math.isfinite(alpha) and alpha > 0.0), f"alpha > 0 (1/R), got {alpha}"),
        (friction not in FRICTION_MODELS, f"friction one of {FRICTION_MODELS}, got {friction!r}"),
        (not (is_real(rtol) and 1e-14 <= rtol <= 1e-4), f"rtol in [1e-14, 1e-4], got {rtol!r}"),
    ):
        if bad:
            raise InputError(f"pass {what}")
    if (friction == FRICTION_MODELS[1]) != (regularisation is not None):
        raise InputError(
            f"regularisation (eta, c) goes with friction={FRICTION_MODELS[1]!r} and only with "
            f"it; got friction={friction!r}, regularisation={regularisation!r}"
        )
    if regularisation is not None:
        eta = real(regularisation, "regularisation", "> 0 (c)")
        if not (math.isfinite(eta) and eta > 0.0):
            raise InputError(f"regularisation must be a finite speed > 0 (c), got {eta}")
    return v_n, v_t, w0, mu, alpha


def oblique_collision(
    body: RimBody,
    v_normal: float,
    v_tangential: float,
    mu: float,
    alpha: float,
    *,
    spin: float = 0.0,
    rotation: float = 0.0,
    friction: str = FRICTION_MODELS[0],
    regularisation: float | None = None,
    rtol: float = 1e-10,
    n_nodes: int | None = None,
    history: bool = False,
) -> ObliqueCollision:
    """One oblique collision of a vibrating grain with the rigid wall, Coulomb friction.

    Parameters
    ----------
    body : RimBody
        The grain's rim in both mode families (the disk: ``rim_modes(get_modes(nu,
        count=N))``; a rim without modes is the rigid grain on the exponential wall).
    v_normal : float
        Speed towards the wall, ``c``, in (0, 1).
    v_tangential, spin : float
        Centre tangential speed (``c``) and spin (``c / R``, positive in the rolling sense of
        ``v_tangential > 0``) before; ``tan(theta) = v_tangential / v_normal`` at no spin.
    mu : float
        Friction coefficient ``>= 0``.
    alpha : float
        Hardness of the exponential wall, ``1 / R``.
    rotation : float
        The body's angle before (radians, counter-clockwise): the material point that meets
        the wall is turned by ``-rotation`` from the modes' pole. A body whose modes span a
        space closed under rotations (every order of both families) gives the same impact at
        any angle, up to its wall nodes.
    friction : {"stick-slip", "regularised"}
        The exact switch, or ``F_t = -mu F_n v_s / sqrt(v_s^2 + eta^2)`` with ``eta =
        regularisation`` (``c``), module docs.
    rtol : float
        DOP853's relative tolerance (absolute tolerances scale with the state's sizes).
    n_nodes : int, optional
        Wall nodes in the body's own count (:meth:`RimBody.wall_nodes`: the disk's rim nodes
        on the whole circle, the sphere's rings; default: the head-on quadrature's spacing).
    history : bool
        Keep :class:`ObliqueHistory`.

    Examples
    --------
    >>> from restitution.bodies.disk.modes import compute_modes
    >>> from restitution.bodies.disk.rim import rim_modes
    >>> rim = rim_modes(compute_modes(0.33, count=6))
    >>> out = oblique_collision(rim, 0.05, 0.05, 0.5, 100.0)
    >>> round(out.epsilon_normal, 4), round(out.beta, 4), abs(out.energy_balance) < 1e-9
    (0.9704, 0.2026, True)
    """
    v_n, v_t, w0, mu, alpha = _check(
        body, v_normal, v_tangential, mu, alpha, spin, friction, regularisation, rtol
    )
    rot = real(rotation, "rotation", "(radians)")
    if not math.isfinite(rot):
        raise InputError(f"pass a finite rotation (radians), got {rot}")
    G = Grain(body, alpha, n_nodes)
    N, m, I = G.N, G.m, G.inertia
    e0 = 0.5 * m * (v_n**2 + v_t**2) + 0.5 * I * w0**2
    x_start = G.start_position(0.5 * m * v_n**2)
    y = np.zeros(8 + 2 * N)
    y[0], y[1], y[2 + N], y[3 + N], y[4 + N] = x_start, rot, v_n, v_t, -w0
    vc0 = v_t - w0
    t_max = 4.0 * (-1.0 - x_start) / v_n + 20.0 * float(body.contact_time_estimate(v_n))

    # Absolute tolerances from the sizes: positions to delta_max ~ v, velocities to v.
    speed = math.hypot(v_n, vc0)
    scale = np.empty_like(y)
    scale[:2] = 1.0
    scale[2 : 2 + N] = v_n
    scale[2 + N : 5 + 2 * N] = speed
    scale[5 + 2 * N :] = e0
    atol = 1e-3 * rtol * scale

    def ft_slip(sign):
        return lambda _y, k: -sign * mu * k["Fn"]

    def ft_stick(yy, k):
        return G.stick_force(yy, k)

    def ft_reg(_y, k):
        vs = k["vs"]
        return -mu * k["Fn"] * vs / math.hypot(vs, regularisation)

    def separation(_t, yy):
        if yy[2 + N] >= 0.0:
            return -1.0
        return -(yy[0] + 1.0 + G.free_reach(yy)) - STOP_LOG / alpha

    separation.terminal, separation.direction = True, 1.0

    # A slip ends when v_s has passed zero by a hair (dv): at a grazing point (v_s = 0 with
    # |F_stick| = mu F_n) the restarted slip would otherwise find its own start again. A slip
    # that starts from a stick starts at the v_s the stick held, which may lie up to about dv on
    # the wrong side of zero; measured from zero the event would then start below its root and
    # never fire, and the slip would run against its direction with friction doing work on the
    # grain (80 modes, alpha = 2000, v = 0.01, mu = 0.5, 45 degrees: friction work -0.37 E0,
    # beta 1.79). So the hair is counted from the start's v_s when that lies on the wrong side.
    dv, sliding = 1e-2 * rtol * speed, [1.0, 0.0]  # direction, its v_s at the start if < 0

    def slip_zero(_t, yy):
        k = G.terms(yy)
        s, base = sliding
        return s * (1.0 if k is None else 1.0 + (k["vs"] * s - base) / dv)

    slip_zero.terminal = True

    def cone(sign):
        def event(_t, yy):
            k = G.terms(yy)
            if k is None:
                return 1.0
            return mu * k["Fn"] - sign * G.stick_force(yy, k)

        event.terminal, event.direction = True, -1.0
        return event

    cone_plus, cone_minus = cone(1.0), cone(-1.0)

    def phase_of(yy, prefer: float | None = None) -> float:
        """Stick if the cone holds the stick force, else slip against it."""
        k = G.terms(yy)
        if k is None:
            return 0.0 if prefer is None else prefer
        F = G.stick_force(yy, k)
        if abs(F) <= mu * k["Fn"]:
            return 0.0
        return -math.copysign(1.0, F)

    if friction == FRICTION_MODELS[1]:
        phase = None
    elif mu == 0.0:
        phase = 1.0 if vc0 >= 0.0 else -1.0
    elif vc0 != 0.0:
        phase = math.copysign(1.0, vc0)
    else:
        phase = phase_of(y, 0.0)

    t0, steps, phases, pieces = 0.0, 0, [], []
    for _ in range(_PHASES):
        if phase is None:
            Ft_of, events = ft_reg, [separation]
        elif mu == 0.0:
            Ft_of, events = (lambda _y, _k: 0.0), [separation]
        elif phase == 0.0:
            Ft_of, events = ft_stick, [separation, cone_plus, cone_minus]
        else:
            k = G.terms(y)
            start = 0.0 if k is None else k["vs"] * phase
            slip_zero.direction, sliding[:] = -phase, [phase, min(start, 0.0)]
            Ft_of, events = ft_slip(phase), [separation, slip_zero]
        phases.append((_NAMES[phase] if phase is not None else "regularised", t0))

        def fun(_t, yy, Ft_of=Ft_of):
            return G.rhs(yy, Ft_of)

        # On hard walls (alpha ~ 1e4-1e5: real grains) the probe of DOP853's first step and
        # its trial steps can overshoot deep into the wall: exp(alpha X) overflows and the
        # derivative is inf or nan. The probe then bounds the first step by the derivative at
        # the start, and a trial step's error is not below 1, so it is rejected and retried
        # shorter; the accepted states stay finite (checked below), hence no warnings of them.
        with np.errstate(over="ignore", invalid="ignore"):
            sol = solve_ivp(
                fun, (t0, t_max), y, method="DOP853", rtol=rtol, atol=atol, events=events
            )
        steps += sol.t.size - 1
        if sol.status == -1:
            raise CollisionError(
                f"the oblique collision's integration failed ({sol.message}); loosen rtol"
            )
        if history:
            pieces.append((sol.t, sol.y, phase))
        if sol.status == 0:
            raise CollisionError(
                f"the grain did not leave the wall within t = {t_max:.3g} R/c; check v and alpha"
            )
        which = next(i for i, ev in enumerate(sol.t_events) if len(ev))
        t0, y = float(sol.t_events[which][0]), sol.y_events[which][0].copy()
        if not np.all(np.isfinite(y)):
            raise CollisionError(
                f"the oblique collision's state became non-finite at t = {t0:.3g} R/c (an "
                "overflow of exp(alpha X) on an accepted step); tighten rtol or soften the wall"
            )
        if events[which] is separation:
            break
        if events[which] is slip_zero:
            phase = phase_of(y, phase)
        else:  # F_stick reached +mu F_n (cone_plus): the wall pushes to +y, the rim slides to -y
            phase = -1.0 if events[which] is cone_plus else 1.0
    else:
        last = ", ".join(f"{name} at {t:.9g}" for name, t in phases[-4:])
        raise CollisionError(
            f"more than {_PHASES} stick/slip phases (the last: {last} R/c): the contact chatters "
            "between stick and slip; tighten rtol, or use friction='regularised'"
        )
    if y[5 + 2 * N] < -_WORK_TOL * e0:  # Coulomb friction only takes energy
        raise CollisionError(
            f"friction did work {y[5 + 2 * N] / e0:.3g} E0 on the grain: a slip ran against its "
            "direction (an event missed); tighten rtol, or use friction='regularised'"
        )
    return _result(
        G, y, t0, steps, phases, pieces, e0, vc0,
        (v_n, v_t, w0, mu, alpha, friction, regularisation),
    )  # fmt: skip


def _result(G, y, t_end, steps, phases, pieces, e0, vc0, inputs) -> ObliqueCollision:
    N = G.N
    k = G.terms(y)
    hist = _history(G, pieces, inputs[3], inputs[6]) if pieces else None
    state = (y[2 : 2 + N], y[2 + N], y[3 + N], y[4 + N], y[5 + N : 5 + 2 * N])
    integrals = (y[5 + 2 * N], y[6 + 2 * N], y[7 + 2 * N])
    return collision_result(G, state, 0.0 if k is None else k["V"], integrals, e0, vc0, inputs,
                            phases, t_end, steps, hist)  # fmt: skip


def collision_result(
    G: Grain, state, V, integrals, e0, vc0, inputs, phases, t_end, steps, history
) -> ObliqueCollision:
    """The :class:`ObliqueCollision` of a final state, for both friction routes (this module's
    and :mod:`restitution.dynamics.oblique_microslip`): ``state = (Q, vx, vy, om, Qd)``, ``V``
    the wall's energy, ``integrals = (friction's dissipated work, int F_t (R - l) dt, int
    tau_n dt)``, ``e0`` the initial energy, ``vc0`` the contact point's tangential velocity
    before, ``inputs = (v_n, v_t, w0, mu, alpha, friction, regularisation)``."""
    m, I = G.m, G.inertia
    v_n, v_t, w0, mu, alpha, friction, eta = inputs
    Q, vx, vy, om, Qd = state
    W, lever_int, tau_int = integrals
    modes = 0.5 * m * (Qd**2 + G.w2 * Q**2) / e0
    trans = 0.5 * m * (vx**2 + vy**2) / e0
    rot = 0.5 * I * om**2 / e0
    vc = vy + om
    return ObliqueCollision(
        v_normal=v_n,
        v_tangential_before=v_t,
        spin_before=w0,
        mu=mu,
        alpha=alpha,
        friction=friction,
        regularisation=eta,
        epsilon_normal=float(-vx / v_n),
        beta=float(-vc / vc0) if vc0 else math.nan,
        v_tangential=float(vy),
        spin=float(-om),
        contact_velocity=float(vc),
        e0=float(e0),
        translation_energy=float(trans),
        rotation_energy=float(rot),
        vibration_energy=float(modes.sum()),
        mode_energy=modes,
        friction_work=float(W / e0),
        wall_energy=float(V / e0),
        energy_balance=float(1.0 - trans - rot - modes.sum() - W / e0 - V / e0),
        normal_impulse=float(m * (v_n - vx)),
        tangential_impulse=float(m * (vy - v_t)),
        lever_correction=float(lever_int / I / vc0) if vc0 else math.nan,
        normal_torque_correction=float(-tau_int / I / vc0) if vc0 else math.nan,
        phases=tuple(phases),
        t_end=float(t_end),
        steps=int(steps),
        history=history,
    )


def _history(G, pieces, mu, eta) -> ObliqueHistory:
    ts, fn, ft, vs, ph = [], [], [], [], []
    for t, Y, phase in pieces:
        for i in range(t.size):
            k = G.terms(Y[:, i])
            if k is None:
                f_n = f_t = v = 0.0
            else:
                f_n, v = k["Fn"], k["vs"]
                if phase is None:
                    f_t = -mu * f_n * v / math.hypot(v, eta)
                elif phase == 0.0:
                    f_t = G.stick_force(Y[:, i], k)
                else:
                    f_t = -phase * mu * f_n
            ts.append(t[i])
            fn.append(f_n)
            ft.append(f_t)
            vs.append(v)
            ph.append(np.nan if phase is None else phase)
    return ObliqueHistory(*(np.array(a) for a in (ts, fn, ft, vs, ph)))
