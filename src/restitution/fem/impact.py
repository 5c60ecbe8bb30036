"""Finite-element solution of the disk-wall and sphere-wall impact (independent check of paper
sections 3-4 and of the sphere's modal route).

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``, forces in ``E R`` (disk, per
unit thickness) or ``E R^2`` (sphere).

The half disk ``y >= 0`` (roller on the diameter, see :mod:`restitution.fem.elasticity`) is
discretised with isoparametric mass-lumped P2 + bubble triangles (``"P2+lumped"``), graded
towards the part of the arc that touches the wall (:func:`restitution.fem.mesh.graded_half_disk`).
The wall acts through the potential of eq. (41) on the arc (:mod:`restitution.fem.contact`).
Hamilton's function of the half disk is

    H = (1/2) udot^T M udot + (1/2) u^T K u + V_half(u),

with the displacement ``u`` including the rigid motion; there is no modal truncation. Mass,
energies and forces of the half disk are half of the whole disk's, so the dynamics and
``epsilon`` are the whole disk's; reported forces are doubled to the whole disk.

The sphere (``geometry="sphere"``) is the same computation on its meridian section
(:mod:`restitution.fem.section`): axisymmetric elasticity with ``u_r = 0`` on the axis and its own
lumped mass (:mod:`restitution.fem.axisymmetric`), the wall integral over its surface
``2 pi r ds``; the section's mass, energies and forces are the whole sphere's, and the meshes and
steps are sized by three-dimensional Hertz (contact radius ``a = sqrt(R delta_max)``).

Time integration: velocity Verlet (central differences) with the diagonal mass matrix, so a
step costs one sparse matrix-vector product. Second order, symplectic, explicit;
stable for ``dt < 2 / omega_max`` with ``omega_max^2 <= omega_K^2 + alpha p_max lambda_B``:
``omega_K`` is the largest frequency of the mesh (largest eigenvalue of ``M^-1 K``),
``lambda_B`` the largest eigenvalue of ``M^-1 B^T W B`` (arc quadrature against the mass) and
``p_max`` the largest wall pressure ``exp(alpha x)``. The step is ``step_safety * 2 / omega_max``
with ``p_max`` estimated in advance (:func:`pressure_estimate`); the run monitors the pressure,
and a run that met a pressure beyond the stability limit of its step, or whose relative energy
drift exceeds ``energy_tol``, is repeated with a smaller step.

Start and stop follow the modal solver (:mod:`restitution.dynamics.collision`): the undeformed disk
starts where its wall energy is ``CONTACT_TOL`` times its kinetic energy, and the run ends when
the centre moves away, the wall energy is below that fraction, and no free vibration can bring
the edge back: the ``u_x`` of an arc node ``j`` relative to the centre of mass is bounded by
``sqrt(2 E_vib chi_j)``, with ``E_vib`` the (conserved) vibrational energy and
``chi_j = c_j^T K^+ c_j`` the static compliance of that node (``c_j`` its ``u_x`` with the
translation projected out); on a facet the P2 trace is at most 1.25 times its largest node value.
The run stops when even that reach keeps ``exp(alpha x)`` below ``CONTACT_TOL`` everywhere.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.dynamics.results import CollisionResult, History
from restitution.errors import InputError, RestitutionError
from restitution.fem.contact import wall_terms
from restitution.fem.elasticity import as_material
from restitution.fem.model import FemModel, fem_model
from restitution.fem.section import contact_time, hertz_scales, peak_pressure

__all__ = [
    "CONTACT_TOL",
    "FemCollisionError",
    "FemSettings",
    "contact_angle_estimate",
    "fem_collide",
    "model_for",
    "pressure_estimate",
    "run_accepted",
    "verlet_step",
]

CONTACT_TOL = 1e-12
"""Wall energy at the start and wall-force scale at the end, as in the modal solver."""

_STOP_LOG = math.log(1.0 / CONTACT_TOL)
# Largest sum of |P2 shape functions| on an edge (Lebesgue constant of 3 equispaced points).
_P2_LEBESGUE = 1.25
INTEGRATOR = "verlet"


class FemCollisionError(RestitutionError):
    """A finite-element collision could not be integrated as requested."""


@dataclass(frozen=True)
class FemSettings:
    """Numerical settings of a finite-element collision.

    Attributes
    ----------
    refine : int
        Mesh refinement level (each level halves all element sizes).
    contact_angle : float or None
        Half-width (radians) of the arc meshed at the finest size; ``None`` takes
        :func:`contact_angle_estimate` of the speed and wall hardness.
    h_contact, h_far, grading : float
        Size function of :func:`restitution.fem.mesh.graded_half_disk` at ``refine = 0``.
    n_gauss : int
        Gauss points per arc facet of the wall integral.
    step_safety : float
        Step as a fraction of the stability limit ``2 / omega_max``.
    energy_tol : float
        Largest accepted relative energy drift ``max |H(t) - H(0)| / H(0)``.
    max_step_reductions : int
        How often the step may be reduced before the run fails.
    record : bool
        Keep time histories.
    record_interval : float
        Time between history samples, ``R / c``.
    max_time : float or None
        Bound on the simulated time, ``R / c``; ``None`` takes the approach time plus four
        quasistatic contact times plus 10.
    """

    refine: int = 1
    contact_angle: float | None = None
    h_contact: float = 0.04
    h_far: float = 0.25
    grading: float = 0.3
    n_gauss: int = 8
    step_safety: float = 0.9
    energy_tol: float = 1e-5
    max_step_reductions: int = 3
    record: bool = False
    record_interval: float = 0.02
    max_time: float | None = None

    def __post_init__(self) -> None:
        if int(self.refine) != self.refine or self.refine < 0:
            raise InputError(f"refine must be a non-negative integer, got {self.refine}")
        if not 0 < self.step_safety <= 1:
            raise InputError(f"step_safety must lie in (0, 1], got {self.step_safety}")
        if not self.energy_tol > 0:
            raise InputError(f"energy_tol must be positive, got {self.energy_tol}")


def contact_angle_estimate(
    v: float, alpha: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None
) -> float:
    """Half-width (radians) of the arc to mesh finely.

    The Hertz half-width ``a`` (:func:`restitution.fem.section.hertz_scales`; the sphere's
    contact radius needs its ``nu``) widened by the soft wall's tail: where the undeformed
    edge's gap ``(phi^2 - a^2) / 2`` is below ``7 / alpha`` the pressure is still above
    ``e^-7 ~ 1e-3`` of its peak. The zone is ``1.2 sqrt(a^2 + 14 / alpha)``, at most ``pi/2``.
    Measured extent of pressures above 1e-3 of the peak at ``alpha = 500`` (disk, nu = 0.33,
    refine 0): 0.23, 0.53, 0.85 at ``v`` = 0.01, 0.1, 0.3, against zones 0.25, 0.58, 1.06.
    Sphere (nu = 0.3, ``alpha delta_max = 40`` and ``160``, level 0): 0.257 and 0.225, 0.664 and
    0.587, 1.040 and 0.907 at ``v`` = 0.01, 0.1, 0.3, against zones 0.285 and 0.256, 0.716 and
    0.643, 1.111 and 0.997.
    """
    _, a = hertz_scales(v, geometry, nu)
    return float(min(1.2 * math.sqrt(a**2 + 14.0 / alpha), 0.5 * math.pi))


def pressure_estimate(v: float, geometry: str = DEFAULT_GEOMETRY, nu: float | None = None) -> float:
    """Largest wall pressure to plan the step for, ``E``: twice the Hertz peak (the disk's
    ``2 F/(pi a)``, the sphere's ``3 F / (2 pi a^2)``;
    :func:`restitution.fem.section.peak_pressure`).

    Measured peaks: 1.08 (nu = 0.33, v = 0.1), 1.18 (nu = 0.33, v = 0.3) and 3.5 (nu = 0.9,
    v = 0.3) times the Hertz peak (disk); 0.99-1.30 times at nu = 0.3, ``v`` = 0.01-0.3
    (sphere, the walls of :func:`contact_angle_estimate`); a larger one only costs a repeated run.
    """
    return 2.0 * peak_pressure(v, geometry, nu)


def _dot(a: np.ndarray, b: np.ndarray) -> float:
    """``a . b`` without BLAS: a threaded BLAS dot of short vectors can cost milliseconds on a
    busy machine (threads waiting for cores), a thousand times the arithmetic."""
    return float(np.einsum("i,i->", a, b))


def model_for(
    material: Material,
    v: float,
    alpha: float,
    settings: FemSettings,
    geometry: str = DEFAULT_GEOMETRY,
) -> FemModel:
    """The (cached) :class:`FemModel` that :func:`fem_collide` uses for these inputs."""
    angle = settings.contact_angle
    if angle is None:
        angle = contact_angle_estimate(v, alpha, geometry, material.nu)
    return fem_model(
        material,
        int(settings.refine),
        float(angle),
        settings.h_contact,
        settings.h_far,
        settings.grading,
        settings.n_gauss,
        geometry,
    )


def _stable_step(model: FemModel, alpha: float, pressure: float, safety: float) -> float:
    """``safety * 2 / omega_max`` with ``omega_max^2 = omega_K^2 + alpha p lambda_B``."""
    return safety * 2.0 / math.sqrt(model.omega_K**2 + alpha * pressure * model.lambda_B)


def _start_position(model: FemModel, alpha: float, e0: float) -> float:
    """Reference centre where the undeformed body's wall energy is ``CONTACT_TOL e0``."""
    q = model.quad
    integral = float(q.weight @ np.exp(alpha * (q.x_ref - q.x_ref.max())))
    return -q.x_ref.max() + math.log(CONTACT_TOL * e0 * alpha / integral) / alpha


@dataclass
class _Run:
    """Raw outcome of one fixed-step run (private, mutable while integrating)."""

    dt: float
    steps: int = 0
    epsilon: float = float("nan")
    drift: float = 0.0
    contact_time: float = 0.0
    max_compression: float = -math.inf
    max_force: float = 0.0
    max_pressure: float = 0.0
    stable: bool = True
    history: list = field(default_factory=list)


def verlet_step(
    model: FemModel,
    alpha: float,
    x_c: float,
    u: np.ndarray,
    ud: np.ndarray,
    f: np.ndarray,
    dt: float,
) -> tuple[np.ndarray, np.ndarray, float, float, np.ndarray]:
    """One velocity-Verlet step of the half disk against the wall, in place.

    Second order, symplectic and time-reversible (negating ``ud`` and stepping again retraces
    the path), explicit; stable for ``dt < 2 / omega_max`` (module docstring).

    Parameters
    ----------
    model : FemModel
    alpha : float
        Wall hardness, ``1/R``.
    x_c : float
        Reference position of the disk's centre, ``R``.
    u, ud : numpy.ndarray, shape (n,)
        Displacement (``R``) and velocity (``c``); updated in place.
    f : numpy.ndarray, shape (n,)
        Force at ``u`` (``-K u - dV/du``), ``E R``.
    dt : float
        Step, ``R / c``.

    Returns
    -------
    f : numpy.ndarray
        Force at the new ``u``.
    Ku : numpy.ndarray
        ``K u`` at the new ``u``.
    V, F : float
        Wall potential and total wall force of the half disk.
    density : numpy.ndarray
        Wall force per quadrature point.
    """
    ud += 0.5 * dt * (model.inverse_mass * f)
    u += dt * ud
    Ku = model.disk.K @ u
    V, F, grad, dens = wall_terms(model.quad, alpha, x_c, u)
    f = -Ku - grad
    ud += 0.5 * dt * (model.inverse_mass * f)
    return f, Ku, V, F, dens


def _run(model: FemModel, v: float, alpha: float, dt: float, s: FemSettings) -> _Run:
    """Integrate one collision with velocity Verlet at fixed step ``dt``."""
    disk, quad = model.disk, model.quad
    mass, r = disk.mass, model.r
    copies = disk.section.copies
    e0 = 0.5 * mass * v**2
    x_c = _start_position(model, alpha, e0)
    t_contact = contact_time(v, disk.geometry, disk.material.nu)
    t_max = s.max_time or ((-1.0 - x_c) / v + 4.0 * t_contact + 10.0)
    limit_w2 = (2.0 / dt) ** 2  # central differences are unstable beyond this omega^2
    u = np.zeros(disk.n_dofs)
    ud = v * disk.rigid
    p = v * r  # M @ ud, kept in step with ud
    V, F, grad, dens = wall_terms(quad, alpha, x_c, u)
    f = -grad
    h0 = 0.5 * _dot(ud, p) + V
    out = _Run(dt=dt)
    rec_every = max(1, int(round(s.record_interval / dt))) if s.record else 0
    comp_prev = x_c + 1.0
    t = 0.0
    check_every = 16
    while True:
        if t > t_max:
            raise FemCollisionError(
                f"the {disk.geometry} did not separate from the wall within t = {t:.3g} R/c "
                f"({out.steps} steps of dt = {dt:.3g}); raise max_time or check v and alpha"
            )
        p += 0.5 * dt * f
        f, Ku, V, F, dens = verlet_step(model, alpha, x_c, u, ud, f, dt)
        p += 0.5 * dt * f
        t += dt
        out.steps += 1

        h = 0.5 * _dot(ud, p) + 0.5 * _dot(u, Ku) + V
        if not math.isfinite(h):
            out.stable = False
            return out
        out.drift = max(out.drift, abs(h - h0) / h0)
        x0 = x_c + _dot(r, u) / mass
        comp = x0 + 1.0
        if comp > 0 or comp_prev > 0:
            if comp > 0 and comp_prev > 0:
                frac = 1.0
            elif comp > 0:
                frac = comp / (comp - comp_prev)
            else:
                frac = comp_prev / (comp_prev - comp)
            out.contact_time += frac * dt
        comp_prev = comp
        out.max_compression = max(out.max_compression, comp)
        out.max_force = max(out.max_force, copies * F)
        if F > 0:
            pmax = float(np.max(dens / quad.weight))
            out.max_pressure = max(out.max_pressure, pmax)
            if model.omega_K**2 + alpha * pmax * model.lambda_B > limit_w2:
                out.stable = False
                return out
        if s.record and out.steps % rec_every == 0:
            out.history.append((t, x0, _dot(r, ud) / mass, copies * F))
        if out.steps % check_every:
            continue
        vcom = _dot(r, ud) / mass
        if vcom >= 0 or V > CONTACT_TOL * e0:
            continue
        e_vib = max(0.5 * _dot(ud, p) + 0.5 * _dot(u, Ku) - 0.5 * mass * vcom**2, 0.0)
        reach = _P2_LEBESGUE * np.sqrt(2.0 * e_vib * model.chi)
        edge = x0 + float(np.max(quad.x_ref + reach))
        if -edge * alpha > _STOP_LOG:
            out.epsilon = -vcom / v
            return out


def run_accepted(
    model: FemModel, v: float, alpha: float, dt: float, settings: FemSettings, who: str
) -> _Run:
    """Runs of the collision from the step ``dt`` down until one is stable and drifts at most
    ``energy_tol``: an unstable run plans for half again the pressure it met (and at least
    halves the step), a drifting one aims at half the tolerance (Verlet's energy error goes
    like ``dt^2``); :class:`FemCollisionError` naming ``who`` after ``max_step_reductions``."""
    run = None
    for attempt in range(settings.max_step_reductions + 1):
        run = _run(model, v, alpha, dt, settings)
        if run.stable and run.drift <= settings.energy_tol:
            return run
        if attempt == settings.max_step_reductions:
            why = "was unstable" if not run.stable else f"drifted by {run.drift:.2e}"
            raise FemCollisionError(
                f"{who} at dt = {dt:.3g} {why} after {attempt} step reductions "
                f"(energy_tol = {settings.energy_tol:.1e}); raise max_step_reductions or "
                "energy_tol, or lower step_safety"
            )
        if not run.stable:
            pressure = 1.5 * run.max_pressure
            dt = min(0.5 * dt, _stable_step(model, alpha, pressure, settings.step_safety))
        else:
            dt *= float(np.clip(math.sqrt(0.5 * settings.energy_tol / run.drift), 0.1, 0.8))
    return run


def fem_collide(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    settings: FemSettings | None = None,
    **overrides,
) -> CollisionResult:
    """One disk-wall (or sphere-wall) collision solved with finite elements (no modal truncation).

    Parameters
    ----------
    material_or_nu : Material or float
        The body's material, or its Poisson number (``E = rho = 1``): two-dimensional for the
        disk, three-dimensional (in ``(-1, 0.5)``) for the sphere.
    v : float
        Speed towards the wall, units of ``c``, in (0, 1).
    alpha : float
        Wall hardness, ``1 / R``.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body (:mod:`restitution.fem.section`).
    settings : FemSettings, optional
        Numerical settings; keyword ``overrides`` (e.g. ``refine=2``) replace single fields.

    Returns
    -------
    CollisionResult
        ``method="fem"``, ``n_modes=0``, ``integrator="verlet"``; ``epsilon`` from the
        centre-of-mass velocity after separation, ``max_force`` for the whole disk (``E R``),
        ``dt`` and ``n_steps`` of the accepted run, ``wall_time_s`` including the mesh and
        matrix set-up. For the sphere ``max_force`` is the whole sphere's (``E R^2``).

    Raises
    ------
    InputError
        For ``v`` outside (0, 1), non-positive ``alpha``, an unknown ``geometry`` or a Poisson
        number outside the body's range.
    FemCollisionError
        When no step within ``max_step_reductions`` reductions meets ``energy_tol``.
    """
    settings = settings or FemSettings()
    if overrides:
        settings = replace(settings, **overrides)
    material = as_material(material_or_nu, geometry)
    v, alpha = float(v), float(alpha)
    if not (0.0 < v < 1.0):
        raise InputError(
            f"the speed v must lie in (0, 1) in units of c (the {geometry}'s speed towards the "
            f"wall), got {v}"
        )
    if not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the wall hardness alpha must be positive, got {alpha}")
    t_start = time.perf_counter()
    model = model_for(material, v, alpha, settings, geometry)
    dt = _stable_step(
        model, alpha, pressure_estimate(v, geometry, material.nu), settings.step_safety
    )
    run = run_accepted(model, v, alpha, dt, settings, "the run")
    wall = time.perf_counter() - t_start
    history = None
    if settings.record and run.history:
        rows = np.array(run.history)
        history = History(
            t=rows[:, 0],
            x0=rows[:, 1],
            v=rows[:, 2],
            force=rows[:, 3],
            mode_energy=np.zeros((rows.shape[0], 0)),
            Q=np.zeros((rows.shape[0], 0)),
        )
    return CollisionResult(
        method="fem",
        nu=material.nu,
        v=v,
        alpha=alpha,
        n_modes=0,
        epsilon=float(run.epsilon),
        energy_drift=float(run.drift),
        contact_time=float(run.contact_time),
        max_compression=float(run.max_compression),
        max_force=float(run.max_force),
        n_steps=int(run.steps),
        dt=float(run.dt),
        wall_time_s=wall,
        integrator=INTEGRATOR,
        history=history,
    )
