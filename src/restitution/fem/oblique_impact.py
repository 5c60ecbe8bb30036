"""Finite-element oblique impact of the whole disk on the exponential wall with Coulomb friction.

Units: ``E = rho = R = 1`` (the disk's two-dimensional constants); speeds in ``c``, spins in
``c / R``, times in ``R / c``, forces in ``E R`` per unit thickness, energies reported as
fractions of the kinetic energy before, ``E0 = m (v_n^2 + v_t^2) / 2``.

The independent judge of :func:`restitution.dynamics.oblique.oblique_collision` (the modal
route, one stick/slip state for the whole contact): the whole disk
(:mod:`restitution.fem.whole_disk`), no modal truncation, friction point by point.

**Kinematics: one co-rotated frame.** Nodes sit at ``x_i = x_c + X_i + u_i`` (``u`` the global
displacement, rigid motion included). A linear strain of ``u`` would count a rigid rotation
``theta`` as a growth of the rim by ``theta^2 / 2`` (0.1 rad: 5e-3 R, several per cent of a
compression): the elastic energy is taken in the frame of the best-fitting rotation instead,

    V_el = (1/2) d^T K d,   d_i = R(theta)^T (x_i - c) - X_i,
    theta = atan2(S, C),   S = sum m_i X_i x (x_i - c),   C = sum m_i X_i . (x_i - c),

(``c`` the centre of mass, ``X`` relative to it). ``V_el`` is invariant under rigid motions, so
momentum and angular momentum are kept; its exact gradient, with ``K`` annihilating the rigid
motions, is

    dV_el/dx_i = R (K d)_i - g m_i R J X_i / rho,   g = (K d) . (J d),   rho = sqrt(S^2 + C^2)

(``J`` the quarter turn). The strain in that frame is linear (as in the modal route); the
rotation is exact, with its centrifugal and Coriolis couplings, which the modal route leaves out.

**Wall and friction, per rim quadrature point ``j``.** The normal force is the head-on wall's
``p_j = w_j exp(alpha x_j)`` (:mod:`restitution.fem.contact`: potential ``p_j / alpha``). The
tangential force ``t_j`` (on the disk, along ``y``) is a Coulomb law regularised by a
tangential spring as stiff as the wall, times ``kappa``: per step

    t_j <- clip(t_j - kappa alpha p_j s_j dt, -mu p_j, mu p_j),   s_j = y-velocity of the point,

(an elastic predictor and a return to the Coulomb bound). A stuck point moves elastically by at
most ``mu / (kappa alpha)``: the Coulomb law is the limit ``kappa -> infinity``. The power
``sum t_j s_j`` is booked exactly as the kicks of the integrator change the kinetic energy, so
the energy balance holds the integration error of the conservative forces only.

**Integrator.** Velocity Verlet with the lumped mass (second order, explicit; symplectic without
friction). Stable for ``dt < 2 / omega_max``,

    omega_max^2 <= omega_K^2 + alpha p_max (lambda_x + kappa lambda_y),

``p_max`` the largest wall pressure: friction adds ``kappa alpha p_max lambda_y`` (its spring in
stick; sliding points add a non-symmetric ``mu alpha p`` coupling, below the wall's own term for
``mu <= kappa``). The step is ``step_safety * 2 / omega_max`` with ``p_max`` planned as twice the
Hertz peak; a run that meets a larger pressure, or whose energy error exceeds ``energy_tol``, is
repeated with a smaller step (as :func:`restitution.fem.impact.run_accepted`).

**Start and stop** as the head-on FEM: the undeformed disk starts where its wall energy is
``CONTACT_TOL E0``; the run ends when the centre moves away, the wall energy is below that
fraction and no free vibration (energy ``E_vib``) can bring a rim point back:
``x_c + max_j [(R X_j)_x + 1.25 sqrt(2 E_vib chi_j)] < -ln(1 / CONTACT_TOL) / alpha``.

**Outputs** from the rigid-body parts: velocity of the centre of mass (momentum over mass), spin
from the angular momentum about it over the current moment of inertia (positive in the rolling
sense of ``v_t > 0``, as the modal route's); ``epsilon_normal = -vx / v_n``, ``beta = -v_c / v_t``
with ``v_c = vy - R spin``; the vibration energy is the rest of the mechanical energy.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, replace

import numpy as np

from restitution.bodies.material import Material
from restitution.errors import InputError
from restitution.fem.elasticity import as_material
from restitution.fem.graded import graded_settings
from restitution.fem.impact import CONTACT_TOL, FemCollisionError, pressure_estimate
from restitution.fem.section import contact_time
from restitution.fem.whole_disk import PLANAR_GEOMETRY, WholeDisk, whole_disk_model

__all__ = ["FemObliqueSettings", "FemOblique", "fem_oblique_collide", "oblique_model_for"]

_STOP_LOG = math.log(1.0 / CONTACT_TOL)
_P2_LEBESGUE = 1.25


@dataclass(frozen=True)
class FemObliqueSettings:
    """Numerical settings of a finite-element oblique collision.

    Attributes
    ----------
    level : int
        Mesh level of :func:`restitution.fem.graded.graded_settings` (each halves all sizes).
    kappa : float
        Tangential spring of the friction law over the wall's normal stiffness ``alpha p``.
    step_safety : float
        Step as a fraction of the stability limit.
    energy_tol : float
        Largest accepted energy error ``max |H + W - H0| / E0`` (``W`` the friction work).
    max_step_reductions : int
    rolling_margin : float
        Extra half-width (radians) of the finely meshed arc for the material that rolls into
        the contact; ``None`` estimates it from the spin (``min(v_t, 4 mu v_n)`` over a contact
        time, at most 0.5).
    n_gauss : int
        Gauss points per rim facet.
    """

    level: int = 0
    kappa: float = 4.0
    step_safety: float = 0.9
    energy_tol: float = 1e-5
    max_step_reductions: int = 4
    rolling_margin: float | None = None
    n_gauss: int = 8

    def __post_init__(self) -> None:
        if int(self.level) != self.level or self.level < 0:
            raise InputError(f"level must be a non-negative integer, got {self.level}")
        if not self.kappa > 0:
            raise InputError(f"kappa must be positive (try 1-16), got {self.kappa}")
        if not 0 < self.step_safety <= 1:
            raise InputError(f"step_safety must lie in (0, 1], got {self.step_safety}")


@dataclass(frozen=True)
class FemOblique:
    """What :func:`fem_oblique_collide` returns (speeds ``c``, spins ``c / R``, energies in
    ``E0``).

    Attributes
    ----------
    v_normal, v_tangential_before, mu, alpha, nu : float
    epsilon_normal, beta : float
    v_tangential, spin, contact_velocity : float
        After: centre, spin (rolling sense), ``v_c = v_t - R spin``.
    translation_energy, rotation_energy, vibration_energy, friction_work, wall_energy : float
    energy_balance : float
        ``1 -`` their sum: the integration error.
    energy_error : float
        Largest ``|H + W - H0| / E0`` during the run (``W`` the friction work).
    max_rotation : float
        Largest ``|theta|`` while in contact (wall energy above ``CONTACT_TOL E0``), radians.
    level, kappa, dt, steps, n_dofs, rim_points, wall_time_s : float or int
    """

    v_normal: float
    v_tangential_before: float
    mu: float
    alpha: float
    nu: float
    epsilon_normal: float
    beta: float
    v_tangential: float
    spin: float
    contact_velocity: float
    translation_energy: float
    rotation_energy: float
    vibration_energy: float
    friction_work: float
    wall_energy: float
    energy_balance: float
    energy_error: float
    max_rotation: float
    level: int
    kappa: float
    dt: float
    steps: int
    n_dofs: int
    rim_points: int
    wall_time_s: float

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return asdict(self)


def oblique_model_for(
    material: Material, v: float, v_t: float, mu: float, alpha: float, s: FemObliqueSettings
) -> WholeDisk:
    """The (cached) :class:`WholeDisk` of these inputs: the head-on judge's graded mesh
    (:func:`restitution.fem.graded.graded_settings` at ``v``, ``alpha``, ``level``) with the
    fine arc widened by the rolling margin."""
    g = graded_settings(v, alpha, s.level)
    margin = s.rolling_margin
    if margin is None:
        margin = min(0.5, min(abs(v_t), 4.0 * mu * v) * contact_time(v))
    angle = min(g.contact_angle + margin, 0.5 * math.pi)
    return whole_disk_model(material, g.refine, angle, g.h_contact, g.h_far, g.grading, s.n_gauss)


def _rot(theta: float) -> tuple[float, float]:
    return math.cos(theta), math.sin(theta)


class _Elastic:
    """The co-rotated elastic energy and its gradient (module docstring)."""

    def __init__(self, model: WholeDisk):
        self.m = model
        self.K = model.disk.K
        self.mX = model.node_mass * model.X  # (2, nodes)
        self.mJX = model.node_mass * np.stack([-model.X[1], model.X[0]])

    def __call__(self, u: np.ndarray) -> tuple[np.ndarray, float, float]:
        """Force ``-dV_el/du``, ``V_el`` and ``theta`` at the displacement ``u``."""
        m = self.m
        qx = m.X[0] + u[m.ix]
        qy = m.X[1] + u[m.iy]
        cx = float(m.node_mass @ qx) / m.mass
        cy = float(m.node_mass @ qy) / m.mass
        qx -= cx
        qy -= cy
        S = float(self.mX[0] @ qy - self.mX[1] @ qx)
        C = float(self.mX[0] @ qx + self.mX[1] @ qy)
        theta = math.atan2(S, C)
        rho = math.hypot(S, C)
        co, si = _rot(theta)
        d = np.empty_like(u)
        d[m.ix] = co * qx + si * qy - m.X[0]
        d[m.iy] = -si * qx + co * qy - m.X[1]
        Kd = self.K @ d
        kx, ky = Kd[m.ix], Kd[m.iy]
        g = float(ky @ d[m.ix] - kx @ d[m.iy])
        gx = kx - (g / rho) * self.mJX[0]
        gy = ky - (g / rho) * self.mJX[1]
        f = np.empty_like(u)
        f[m.ix] = -(co * gx - si * gy)
        f[m.iy] = -(si * gx + co * gy)
        return f, 0.5 * float(d @ Kd), theta


def _step_for(model: WholeDisk, alpha: float, pressure: float, kappa: float, safety: float):
    return (
        safety
        * 2.0
        / math.sqrt(model.omega_K**2 + alpha * pressure * (model.lambda_x + kappa * model.lambda_y))
    )


def _run(model: WholeDisk, v: float, v_t: float, mu: float, alpha: float, dt: float, kappa: float):
    """One fixed-step run; returns a dict of the raw outcome."""
    q = model.quad
    ix, iy, nm = model.ix, model.iy, model.node_mass
    mass = model.mass
    elastic = _Elastic(model)
    e0 = 0.5 * mass * (v**2 + v_t**2)
    integral = float(q.weight @ np.exp(alpha * (q.x_ref - q.x_ref.max())))
    x_c = -q.x_ref.max() + math.log(CONTACT_TOL * 0.5 * mass * v**2 * alpha / integral) / alpha
    t_max = (-1.0 - x_c) / v + 4.0 * contact_time(v) + 10.0
    limit_w2 = (2.0 / dt) ** 2
    n = model.disk.n_dofs
    u = np.zeros(n)
    ud = np.zeros(n)
    ud[ix] = v
    ud[iy] = v_t
    minv = model.inverse_mass
    tan = np.zeros(q.size)

    def wall(u):
        x = x_c + q.x_ref + q.Bx @ u
        p = q.weight * np.exp(alpha * x)
        return p

    p = wall(u)
    fe, V_el, theta = elastic(u)
    f = fe - q.BxT @ p + q.ByT @ tan
    h0 = 0.5 * float(ud @ (ud / minv)) + V_el + p.sum() / alpha
    work = 0.0  # work of friction on the disk (negative: dissipated)
    out = {"stable": True, "drift": 0.0, "steps": 0, "max_rotation": 0.0, "max_pressure": 0.0}
    t = 0.0
    while True:
        if t > t_max:
            raise FemCollisionError(
                f"the disk did not separate from the wall within t = {t:.3g} R/c; check v, alpha"
            )
        s_old = q.By @ ud
        ud_half = ud + 0.5 * dt * (minv * f)
        s_half = q.By @ ud_half
        work += 0.25 * dt * float(tan @ (s_old + s_half))
        u += dt * ud_half
        p = wall(u)
        cap = mu * p
        np.clip(tan - kappa * alpha * p * s_half * dt, -cap, cap, out=tan)
        fe, V_el, theta = elastic(u)
        f = fe - q.BxT @ p + q.ByT @ tan
        ud = ud_half + 0.5 * dt * (minv * f)
        work += 0.25 * dt * float(tan @ (s_half + q.By @ ud))
        t += dt
        out["steps"] += 1
        V = float(p.sum()) / alpha
        if V > CONTACT_TOL * e0:
            out["max_rotation"] = max(out["max_rotation"], abs(theta))
        h = 0.5 * float(ud @ (ud / minv)) + V_el + V
        if not math.isfinite(h):
            out["stable"] = False
            return out
        out["drift"] = max(out["drift"], abs(h - work - h0) / e0)
        if V > 0:
            pmax = float(np.max(p / q.weight))
            out["max_pressure"] = max(out["max_pressure"], pmax)
            if model.omega_K**2 + alpha * pmax * (model.lambda_x + kappa * model.lambda_y) > (
                limit_w2
            ):
                out["stable"] = False
                return out
        if out["steps"] % 16:
            continue
        vx = float(nm @ ud[ix]) / mass
        if vx >= 0 or V > CONTACT_TOL * e0:
            continue
        vy = float(nm @ ud[iy]) / mass
        qx = model.X[0] + u[ix]
        qy = model.X[1] + u[iy]
        cx, cy = float(nm @ qx) / mass, float(nm @ qy) / mass
        rx, ry = qx - cx, qy - cy
        wx, wy = ud[ix] - vx, ud[iy] - vy
        L = float(nm @ (rx * wy - ry * wx))
        inertia = float(nm @ (rx**2 + ry**2))
        e_trans = 0.5 * mass * (vx**2 + vy**2)
        e_rot = 0.5 * L**2 / inertia
        e_vib = max(0.5 * float(ud @ (ud / minv)) + V_el - e_trans - e_rot, 0.0)
        co, si = _rot(theta)
        rim_x = x_c + cx + co * q.x_ref - si * q.y_ref
        reach = _P2_LEBESGUE * np.sqrt(2.0 * e_vib * model.chi)
        if -float(np.max(rim_x + reach)) * alpha > _STOP_LOG:
            spin = -L / inertia
            out.update(
                vx=vx,
                vy=vy,
                spin=spin,
                e0=e0,
                e_trans=e_trans,
                e_rot=e_rot,
                e_vib=e_vib,
                work=-work,
                wall_energy=V,
                balance=1.0 - (e_trans + e_rot + e_vib - work + V) / e0,
                dt=dt,
            )
            return out


def fem_oblique_collide(
    material_or_nu: Material | float,
    v_normal: float,
    v_tangential: float,
    mu: float,
    alpha: float,
    *,
    settings: FemObliqueSettings | None = None,
    **overrides,
) -> FemOblique:
    """One oblique impact of the whole finite-element disk (no spin before), Coulomb friction.

    Parameters
    ----------
    material_or_nu : Material or float
        The disk's two-dimensional constants, or its Poisson number (``E = rho = 1``).
    v_normal : float
        Speed towards the wall, ``c``, in (0, 1).
    v_tangential : float
        Tangential speed of the centre, ``c`` (``tan(theta) = v_tangential / v_normal``).
    mu : float
        Friction coefficient, ``>= 0``.
    alpha : float
        Wall hardness, ``1 / R``.
    settings : FemObliqueSettings, optional
        Keyword ``overrides`` replace single fields (``level=1``, ``kappa=8``).

    Returns
    -------
    FemOblique

    Raises
    ------
    InputError
        For inputs out of range.
    FemCollisionError
        When no step within ``max_step_reductions`` reductions is stable and meets
        ``energy_tol``, or the rotation leaves the quadrature's rim.
    """
    s = settings or FemObliqueSettings()
    if overrides:
        s = replace(s, **overrides)
    material = as_material(material_or_nu, PLANAR_GEOMETRY)
    v, v_t, mu, alpha = float(v_normal), float(v_tangential), float(mu), float(alpha)
    if not 0.0 < v < 1.0:
        raise InputError(f"the normal speed must lie in (0, 1) in units of c, got {v}")
    if not (math.isfinite(v_t) and math.isfinite(mu) and mu >= 0):
        raise InputError(f"need a finite v_tangential and mu >= 0, got {v_t}, {mu}")
    if not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the wall hardness alpha must be positive, got {alpha}")
    start = time.perf_counter()
    model = oblique_model_for(material, v, v_t, mu, alpha, s)
    dt = _step_for(model, alpha, pressure_estimate(v), s.kappa, s.step_safety)
    for attempt in range(s.max_step_reductions + 1):
        run = _run(model, v, v_t, mu, alpha, dt, s.kappa)
        if run["stable"] and run["drift"] <= s.energy_tol:
            break
        if attempt == s.max_step_reductions:
            why = "was unstable" if not run["stable"] else f"drifted by {run['drift']:.2e}"
            raise FemCollisionError(
                f"the oblique run at dt = {dt:.3g} {why} after {attempt} step reductions; "
                "raise max_step_reductions or energy_tol, or lower step_safety"
            )
        if not run["stable"]:
            dt = min(0.5 * dt, _step_for(model, alpha, 1.5 * run["max_pressure"], s.kappa, 0.9))
        else:
            dt *= float(np.clip(math.sqrt(0.5 * s.energy_tol / run["drift"]), 0.1, 0.8))
    if run["max_rotation"] > 0.5 * math.pi - 0.3:
        raise FemCollisionError(
            f"the disk turned by {run['max_rotation']:.2f} rad during the contact, beyond the "
            "rim the wall integral covers; lower v_tangential"
        )
    e0 = run["e0"]
    v_c0 = v_t
    v_c = run["vy"] - run["spin"]
    return FemOblique(
        v_normal=v,
        v_tangential_before=v_t,
        mu=mu,
        alpha=alpha,
        nu=material.nu,
        epsilon_normal=-run["vx"] / v,
        beta=-v_c / v_c0 if v_c0 != 0 else float("nan"),
        v_tangential=run["vy"],
        spin=run["spin"],
        contact_velocity=v_c,
        translation_energy=run["e_trans"] / e0,
        rotation_energy=run["e_rot"] / e0,
        vibration_energy=run["e_vib"] / e0,
        friction_work=run["work"] / e0,
        wall_energy=run["wall_energy"] / e0,
        energy_balance=run["balance"],
        energy_error=run["drift"],
        max_rotation=run["max_rotation"],
        level=int(s.level),
        kappa=float(s.kappa),
        dt=run["dt"],
        steps=int(run["steps"]),
        n_dofs=int(model.disk.n_dofs),
        rim_points=int(model.quad.size),
        wall_time_s=time.perf_counter() - start,
    )
