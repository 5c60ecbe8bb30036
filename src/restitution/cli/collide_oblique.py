"""``restitution collide --angle DEG --friction MU``: one oblique impact on the wall with Coulomb
friction.

A thin layer over :func:`restitution.dynamics.oblique.oblique_collision` (one stick/slip state,
the default ``--friction-model stick-slip``),
:func:`restitution.dynamics.oblique_microslip.microslip_collision` (``--friction-model
microslip``: friction at every wall node, ``--kappa``) and
:func:`restitution.dynamics.oblique_residual.residual_collision` (``--friction-model
residual``: one state, the dropped modes' static residual; the kinds whose ``oblique_residual``
is set) (docs/oblique.md, "The modal oblique collision", "Microslip in the modal route", "The
sphere" and "A static residual for the one-state route"): the options become one
:class:`ObliqueRequest`, where every refusal is made before a mode is computed; then the
body's modes of both symmetries are built (the disk's rim, the sphere's cap), the work
estimated, told on stderr and refused beyond the bound of one run, the collision run, and one
:class:`~restitution.cli.report.Report` printed as text, JSON or CSV (one row per mode).

Units: ``E = rho = R = 1`` of the body (the disk's two-dimensional constants, the sphere's
three-dimensional ones); ``--v`` is the normal speed towards the wall in ``c``, the tangential
speed is ``v tan(angle)``; spins in ``c / R``; energies are fractions of the initial kinetic
energy ``E0 = (m/2) v^2 / cos(angle)^2``.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass

from restitution import budget
from restitution.bodies.cache import check_mode_request, get_modes
from restitution.bodies.kinds import body_kind, kinds
from restitution.cli._common import (
    EXIT_NOT_CONVERGED,
    LINEAR_SPEED,
    PARTNER_OPTIONS,
    body_nu,
    given,
    note,
    nu_inputs,
    positive_finite,
    refuse_ignored,
    stretched,
)
from restitution.cli.report import Report, emit, rich_text
from restitution.dynamics.friction import default_friction_route, friction_route, refuse_kappa
from restitution.dynamics.oblique_cost import check_reach
from restitution.dynamics.oblique_microslip import MicroslipSettings
from restitution.errors import InputError
from restitution.status import Status

STICK_SLIP = default_friction_route().name
"""``--friction-model``'s default (the registered routes' first: one stick/slip state for the
contact)."""
DEFAULT_KAPPA = MicroslipSettings().kappa
"""``--kappa``'s default (the finite-element judge's)."""

__all__ = [
    "DEFAULT_KAPPA",
    "STICK_SLIP",
    "ObliqueRequest",
    "collide_oblique",
    "oblique_request",
]


_NOT_OBLIQUE = {
    **PARTNER_OPTIONS,
    "excite": "--excite",
    "mode_index": "--mode-index",
    "amplitude": "--amplitude",
    "phase": "--phase",
    "temperature": "--temperature",
    "samples": "--samples",
    "seed": "--seed",
    "plot": "--plot",
    "method": "--method",
    "mesh_refine": "--mesh-refine",
    "select": "--select",
    "integrator": "--integrator",
    "energy_tol": "--energy-tol",
    "step_check": "--step-check",
    "relaxation_time": "--relaxation-time",
}
"""Options of ``collide`` the oblique route does not take (parameter -> flag): a wall, not a
second body; a body at rest; the modal route with DOP853 phase by phase (its own tolerance, no
step judge); no damping."""


def _oblique_kinds() -> list[str]:
    return [k.geometry for k in kinds().values() if k.oblique_body is not None]


@dataclass(frozen=True)
class ObliqueRequest:
    """What ``collide --angle --friction`` asks, checked.

    Attributes
    ----------
    geometry : str
        The body kind.
    nu, plane : float, str or None
        ``--nu`` and ``--plane`` as given; ``nu_body`` the Poisson number the modes take.
    v : float
        Normal speed towards the wall, ``c``, in (0, 1).
    angle : float
        Angle of incidence from the wall's normal, degrees, in [0, 90).
    mu : float
        Coulomb's friction coefficient, >= 0.
    alpha : float
        Wall hardness, ``1 / R``.
    modes : int
        Symmetric (axisymmetric) modes, the head-on count; the disk's rim holds about twice as
        many, the sphere's cap about seven (20) to nine (40) times as many.
    force : bool
        Run beyond the time bound of one run.
    friction_model : str
        The friction route's name (:mod:`restitution.dynamics.friction`): ``"stick-slip"``
        (one state for the contact), ``"microslip"`` (every wall node), ``"residual"`` (one
        state, the dropped modes' static residual), ...
    kappa : float or None
        The tangential spring over the normal stiffness of a route that takes it (microslip);
        ``None`` with the others.
    """

    geometry: str
    nu: float
    plane: str | None
    nu_body: float
    v: float
    angle: float
    mu: float
    alpha: float
    modes: int
    force: bool = False
    friction_model: str = STICK_SLIP
    kappa: float | None = None

    @property
    def route(self):
        """The friction route (:mod:`restitution.dynamics.friction`)."""
        return friction_route(self.friction_model)

    @property
    def v_tangential(self) -> float:
        """Tangential speed of the centre before, ``v tan(angle)``, ``c``."""
        return self.v * math.tan(math.radians(self.angle))

    def inputs(self) -> dict:
        """The ``inputs`` of the JSON envelope."""
        return {
            "geometry": self.geometry,
            **nu_inputs(self.nu, self.plane, self.geometry),
            "v": self.v,
            "angle": self.angle,
            "friction": self.mu,
            "alpha": self.alpha,
            "modes": self.modes,
            "friction_model": self.friction_model,
            "kappa": self.kappa,
        }


def oblique_request(ctx, angle: float | None, mu: float | None) -> ObliqueRequest:
    """The request of ``collide``'s options with ``--angle`` and ``--friction``, or a one-line
    refusal (:class:`InputError`) before anything is computed."""
    p = ctx.params
    geometry = p["geometry"]
    if body_kind(geometry).oblique_body is None:
        raise InputError(
            f"oblique impacts are computed for the {', '.join(_oblique_kinds())} so far; leave "
            f"out --angle and --friction for a head-on collision of the {geometry}"
        )
    if angle is None or mu is None:
        missing, present = ("--friction", "--angle") if mu is None else ("--angle", "--friction")
        raise InputError(
            f"{present} needs {missing}: an oblique impact is --angle DEG (from the wall's "
            "normal, 0 is head-on) with --friction MU (Coulomb's coefficient, 0 frictionless)"
        )
    if not (math.isfinite(angle) and 0.0 <= angle < 90.0):
        raise InputError(f"--angle must lie in [0, 90) degrees from the wall's normal, got {angle}")
    if not (math.isfinite(mu) and mu >= 0.0):
        raise InputError(f"--friction must be a number >= 0 (Coulomb's coefficient), got {mu}")
    refuse_ignored(ctx, _NOT_OBLIQUE, "with --angle (an oblique impact on the wall, at rest)")
    v = p["v"]
    if not (0.0 < v < 1.0):
        raise InputError(f"--v must lie in (0, 1) (the normal speed, units of c), got {v}")
    alpha = positive_finite("--alpha", p["alpha"])
    check_reach(v, alpha, ("--v", "--alpha"))
    modes = p["n_modes"] if given(ctx, "n_modes") else body_kind(geometry).oblique_modes
    if modes < 1:
        raise InputError(f"--modes must be at least 1, got {modes}")
    nu_body = body_nu(p["nu"], p["plane"], geometry)
    check_mode_request(nu_body, modes, None, geometry)
    route = friction_route(p.get("friction_model"), body_kind(geometry))
    kappa = p.get("kappa")
    refuse_kappa(route, kappa)
    if route.takes_kappa:
        kappa = positive_finite("--kappa", DEFAULT_KAPPA if kappa is None else kappa)
    return ObliqueRequest(geometry, p["nu"], p["plane"], nu_body, v, float(angle), float(mu),
                          alpha, int(modes), bool(p["force"]), route.name, kappa)  # fmt: skip


def collide_oblique(ctx, angle, mu, fmt: str, strict: bool) -> None:
    """``collide --angle DEG --friction MU``: the request, the work, the run, the report."""
    from restitution.dynamics.oblique_cost import SUSPECT, suspect_advice
    from restitution.dynamics.run import CollisionError

    req = oblique_request(ctx, angle, mu)
    modes = get_modes(req.nu_body, count=req.modes, geometry=req.geometry)
    rim = body_kind(req.geometry).oblique_body(modes)
    route = req.route
    nodes = rim.wall_node_count(req.alpha)
    budget.check_memory_total(  # before the estimates below, which make the nodes
        "--modes",
        req.modes,
        rim.wall_node_memory(req.alpha),
        f"the {len(rim)} modes of both symmetries on the wall's {nodes} nodes",
        lambda _limit: "ask for fewer modes",
    )
    work = route.work(rim, req.v, req.v_tangential, req.alpha, req.kappa)
    budget.check_memory_total(
        "--modes",
        req.modes,
        work.memory_bytes,
        f"the {len(rim)} modes of both symmetries on {work.nodes} nodes",
        lambda _limit: "fewer modes or a softer wall (--alpha)",
    )
    budget.check_time_total(
        "--modes",
        req.modes,
        work.seconds,
        f"{route.plan(work)}, {len(rim)} modes of both symmetries; measured runs took up to "
        f"{work.spread:g} times the estimate",
        lambda limit: f"about {work.modes_within(limit, req.modes)} modes fit",
        force=req.force,
        override="--force",
    )
    note(
        f"note: oblique impact with {req.modes} modes ({len(rim)} of both symmetries), "
        f"{req.friction_model} friction: about {budget.format_duration(work.seconds)} expected"
    )
    start = time.perf_counter()
    try:
        result = route.collision(rim, req.v, req.v_tangential, req.mu, req.alpha, req.kappa)
    except CollisionError as exc:
        raise CollisionError(
            f"{exc} (rtol and the step are arguments of the {route.name} route's collision "
            "function, restitution.dynamics.friction, not options of the command)"
        ) from exc
    wall = time.perf_counter() - start
    status, advice = stretched(Status.OK, None, req.v, LINEAR_SPEED, result)
    suspect = suspect_advice(req.modes, req.alpha, req.mu)
    if suspect is not None and status == Status.OK:
        status, advice = SUSPECT, suspect
    rows = _mode_rows(rim, result)
    payload = {
        "v_tangential": req.v_tangential,
        "epsilon_normal": result.epsilon_normal,
        "beta": result.beta,
        "beta_meaning": "-v_c(after)/v_c(before), v_c = v_t - R omega the rigid contact "
        "point's tangential velocity: -1 smooth, +1 reversed; null at angle 0",
        "v_tangential_after": result.v_tangential,
        "spin_after": result.spin,
        "contact_velocity_after": result.contact_velocity,
        "e0": result.e0,
        "translation_energy": result.translation_energy,
        "rotation_energy": result.rotation_energy,
        "vibration_energy": result.vibration_energy,
        "friction_work": result.friction_work,
        "wall_energy": result.wall_energy,
        "energy_balance": result.energy_balance,
        "normal_impulse": result.normal_impulse,
        "tangential_impulse": result.tangential_impulse,
        "lever_correction": result.lever_correction,
        "normal_torque_correction": result.normal_torque_correction,
        "phases": [{"phase": name, "t": t} for name, t in result.phases],
        "t_end": result.t_end,
        "steps": result.steps,
        "step_kind": route.integrator,
        "rim_modes": len(rim),
        "estimated_time_s": work.seconds,
        "wall_time_s": wall,
        "mode_energies_after": rows,
    }
    emit(Report("collide", req.inputs(), payload, status, advice, _units(req.geometry),
                text=lambda: _text(req, result, len(rim), wall, status, advice),
                rows=lambda: rows), fmt)  # fmt: skip
    if status != Status.OK:
        if fmt != "json":
            note(f"warning: status {status}: {advice}")
        if strict:
            sys.exit(EXIT_NOT_CONVERGED)


def _units(geometry: str) -> dict:
    """The body's units with the oblique impact's speeds, spins, angles and energies."""
    units = dict(body_kind(geometry).units)
    mass = units["energy"].rsplit(", ", 1)[-1]
    units.update(
        speed=f"c = sqrt(E/rho) (v: the {geometry}'s normal speed towards the wall; the "
        "tangential speed is v tan(angle))",
        spin="c/R (positive in the rolling sense of a positive tangential speed)",
        angle="degrees from the wall's normal",
        impulse=f"momentum: the mass ({mass}) times c",
        energy="fraction of the initial kinetic energy E0 = (m/2) (v^2 + v_tangential^2), "
        f"{mass}; e0 in E R^dimension",
    )
    return units


def _mode_rows(rim, result) -> list[dict]:
    """One row per mode of the body, in its order: family, labels (the body's
    ``mode_labels``), frequency, energy after (fraction of E0)."""
    return [
        {
            "index": i,
            **labels,
            "omega": float(rim.omega[i]),
            "energy_after": float(result.mode_energy[i]),
        }
        for i, labels in enumerate(rim.mode_labels())
    ]


def _text(req, result, n_rim, wall, status, advice) -> str:
    route = req.route

    def draw(console):
        beta = "undefined at angle 0" if math.isnan(result.beta) else f"{result.beta:.6f}"
        contact = route.contact(result)
        console.print(
            f"[bold]epsilon_normal = {result.epsilon_normal:.8f}  beta = {beta}  "
            f"spin after = {result.spin:.6g} c/R[/bold]\n"
            f"oblique impact of the {req.geometry}, nu = {req.nu_body:g}: v = {req.v:g} c "
            f"normal, {req.v_tangential:.6g} c tangential ({req.angle:g} degrees from the "
            f"normal), friction mu = {req.mu:g} ({route.describe(req.kappa)}), "
            f"alpha = {req.alpha:g}, {req.modes} modes "
            f"({n_rim} of both symmetries)\n"
            f"after (fractions of E0): translation {result.translation_energy:.6g}, rotation "
            f"{result.rotation_energy:.6g}, left in the modes {result.vibration_energy:.6g}, "
            f"friction work {result.friction_work:.6g}; energy balance "
            f"{result.energy_balance:.2e}\n"
            f"contact: {contact}, stop at {result.t_end:.4g} R/c, {result.steps} "
            f"{route.integrator} steps, {wall:.2f} s"
        )
        if status != Status.OK:
            console.print(f"[yellow]status {status}: {advice}[/yellow]")

    return rich_text(draw)
