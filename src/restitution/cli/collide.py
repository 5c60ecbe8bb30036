"""``restitution collide``: one collision of a disk or a sphere with the wall."""

from __future__ import annotations

import math
import sys
import time
import warnings
from pathlib import Path

import click

from restitution.bodies.cache import check_mode_request, get_modes
from restitution.bodies.kinds import body_kind, kinds
from restitution.bodies.viscoelastic import Viscoelastic
from restitution.cli._common import (
    EXIT_FAILED_POINTS,
    EXIT_NOT_CONVERGED,
    LINEAR_SPEED,
    LiveChoice,
    PathOption,
    body_nu,
    force_option,
    geometry_option,
    material_from,
    note,
    nu_inputs,
    nu_option,
    pair_units,
    partner_from,
    partner_options,
    plane_option,
    positive_finite,
    quiet,
    quiet_option,
    refuse_ignored,
    stretched,
    strict_option,
)
from restitution.cli.report import (
    Report,
    emit,
    format_options,
    no_table,
    output_format,
    rich_text,
)
from restitution.dynamics.friction import friction_names, routes_help
from restitution.errors import InputError
from restitution.status import Status

_EXCITE_OPTIONS = {
    "mode_index": "--mode-index",
    "amplitude": "--amplitude",
    "phase": "--phase",
    "temperature": "--temperature",
    "samples": "--samples",
    "seed": "--seed",
    "plot": "--plot",
}
_EXCITATIONS = ("none", "mode", "thermal")

_NO_MODES = "finite elements have no modes; --method modal gives one row per mode"
"""Why ``collide --method fem`` answers no table (``--format csv``)."""

_LONG_RUN_STEPS = 200_000
"""Runs expected to take more steps than this are announced with their estimate."""


def _summary(result, top: int = 10) -> str:
    """The collision for people: epsilon, the run, the modes with most energy after it."""
    return rich_text(lambda console: _print_summary(console, result, top))


def _print_summary(console, result, top: int) -> None:
    from rich.table import Table

    console.print(
        f"[bold]epsilon = {result.epsilon:.8f}[/bold]  (1 - eps^2 = {result.energy_loss:.6g})\n"
        f"method {result.method}, nu = {result.nu}, v = {result.v} c towards the wall, "
        f"alpha = {result.alpha}, modes = {result.n_modes}, integrator {result.integrator}\n"
        f"contact time {result.contact_time:.5g} R/c, "
        f"max compression {result.max_compression:.5g} R, "
        f"max force {result.max_force:.5g} E, energy drift {result.energy_drift:.2e}, "
        f"dt {result.dt:.3g}, {result.n_steps} steps, {result.wall_time_s:.2f} s"
    )
    if result.step_error is not None:
        console.print(
            f"epsilon's step error {result.step_error:.1e} (Richardson: the run at dt against "
            f"one at 2 dt)"
        )
    if result.relaxation_time:
        console.print(
            f"damping: tau = {result.relaxation_time:g} R/c; dissipated "
            f"{result.energy_dissipated:.6g}, left in the vibrations "
            f"{float(result.mode_energy_after.sum()):.6g} (fractions of E0)"
        )
    if result.mode_n.size:
        import numpy as np

        table = Table(title=f"{top} modes with most energy after the collision (fraction of E0)")
        for col in ("n", "l", "after", "mean over contact", "at closest approach"):
            table.add_column(col, justify="right")
        for i in np.argsort(-result.mode_energy_after)[:top]:
            table.add_row(
                str(result.mode_n[i]),
                str(result.mode_l[i]),
                f"{result.mode_energy_after[i]:.7f}",
                f"{result.mode_energy_mean[i]:.7f}",
                f"{result.mode_energy_closest[i]:.7f}",
            )
        console.print(table)
    if result.status != Status.OK:
        console.print(f"[yellow]status {result.status}: {result.advice}[/yellow]")


def _mode_rows(result, modes) -> list[dict]:
    """One row per mode of a modal collision, in the order of the mode set ``modes`` (``index``;
    ``body`` 1 or 2 for a pair): its labels, frequency and energies (fractions of E0)."""
    member = getattr(modes, "member", None)
    rows = []
    for i in range(result.mode_n.size):
        row = {"index": i, "n": int(result.mode_n[i]), "l": int(result.mode_l[i])}
        if member is not None:
            row["body"] = int(member[i]) + 1
        row["omega"] = float(modes.omega[i])
        for key, values in (("energy_before", result.mode_energy_before),
                            ("energy_after", result.mode_energy_after),
                            ("energy_mean", result.mode_energy_mean),
                            ("energy_closest", result.mode_energy_closest)):  # fmt: skip
            row[key] = float(values[i]) if len(values) else 0.0
        rows.append(row)
    return rows


def _vibrating() -> str:
    """The kinds whose collisions may start ringing (``collide --excite``), in words."""
    return ", ".join(f"{k.geometry}s" for k in kinds().values() if k.vibrating)


@click.command()
@nu_option
@plane_option
@geometry_option
@click.option(
    "--v",
    "v",
    type=float,
    required=True,
    help="Speed of the disk towards the wall in units of c = sqrt(E/rho), in (0, 1). "
    "Two identical disks approaching each other at +-v collide like this.",
)
@click.option(
    "--alpha",
    type=float,
    default=500.0,
    show_default=True,
    help="Wall hardness alpha of V = exp(alpha x)/alpha, in 1/R.",
)
@click.option(
    "--modes",
    "n_modes",
    type=int,
    default=1600,
    show_default=True,
    help="Number of modes kept (with --angle: 160 unless given, as that route is slower; "
    "docs/oblique.md).",
)
@click.option(
    "--select",
    type=click.Choice(["lowest", "ranked"]),
    default="lowest",
    show_default=True,
    help="lowest: the N lowest frequencies; ranked: the N modes with most average "
    "energy in a preliminary run with the 2N lowest (paper, section 4).",
)
@click.option(
    "--integrator",
    type=click.Choice(["split4", "split", "rk4"]),
    default="split4",
    show_default=True,
)
@click.option(
    "--method",
    type=click.Choice(["modal", "fem"]),
    default="modal",
    show_default=True,
    help="modal: normal-mode expansion (paper); fem: independent finite elements.",
)
@click.option(
    "--mesh-refine",
    type=int,
    default=1,
    show_default=True,
    help="Mesh refinement level for --method fem (1: epsilon within ~1e-5 of level 2 "
    "at nu = 0.33, v = 0.1, in seconds; each level halves the element size).",
)
@force_option("--method fem, --excite thermal and --angle: ")
@click.option(
    "--energy-tol",
    type=float,
    default=1e-6,
    show_default=True,
    help="Largest accepted relative energy drift; the step is refined until met.",
)
@click.option(
    "--step-check",
    type=click.Choice(["epsilon", "energy"]),
    default="epsilon",
    show_default=True,
    help="What judges the time step of a modal run. epsilon: each run is repeated at half the "
    "step and epsilon's Richardson error is held to energy-tol/2 (about three times the work). "
    "energy: the energy drift alone (the sweeps' judge), which can pass while epsilon is off "
    "(a sphere of 400 modes at v = 0.1, alpha = 2000: drift 8e-8, epsilon off by 1.4e-4). "
    "--excite mode and thermal take it too, so a zero excitation is the collision at rest.",
)
@click.option(
    "--excite",
    default="none",
    show_default=True,
    help="Vibrations of the disk when its centre passes the start position: none (at rest), "
    "mode (one mode, --mode-index/--amplitude/--phase) or thermal (every mode canonical at "
    "--temperature; --samples collisions). See docs/vibrating.md.",
)
@click.option(
    "--mode-index",
    type=int,
    default=None,
    help="--excite mode: index of the mode in the set (0: lowest frequency).",
)
@click.option(
    "--amplitude",
    type=float,
    default=None,
    help="--excite mode: the mode's energy, fraction of (m/2) v^2.",
)
@click.option(
    "--phase",
    type=float,
    default=None,
    help="--excite mode: phase in radians (Q = A cos phase, P = -m omega A sin phase).",
)
@click.option(
    "--temperature",
    type=float,
    default=None,
    help="--excite thermal: mean energy per mode, fraction of (m/2) v^2 "
    "(= (v_th/v)^2 with (m/2) v_th^2 = T).",
)
@click.option(
    "--samples",
    type=int,
    default=None,
    help="--excite thermal: number of collisions, each from its own thermal state [default: 1].",
)
@click.option(
    "--seed",
    type=int,
    default=None,
    help="--excite thermal: seed of the thermal states [default: 0].",
)
@click.option(
    "--plot",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="--excite thermal: draw the histogram of epsilon to this file.",
)
@click.option(
    "--relaxation-time",
    type=float,
    default=0.0,
    show_default=True,
    help="A damping material: Kelvin-Voigt relaxation time tau in R/c (viscosities = tau x "
    "moduli); every mode is damped at tau omega^2 and the dissipated energy is reported. Runs "
    "--integrator split (docs/damping.md). 0: elastic.",
)
@click.option(
    "--angle",
    type=float,
    default=None,
    help="An oblique impact: angle of incidence from the wall's normal, degrees in [0, 90); "
    "--v stays the normal speed, the tangential one is v tan(angle). Needs --friction; the "
    "disk and the sphere (docs/oblique.md).",
)
@click.option(
    "--friction",
    "friction",
    type=float,
    default=None,
    help="With --angle: Coulomb's friction coefficient mu >= 0 of the wall (0: frictionless, "
    "the head-on epsilon).",
)
@click.option(
    "--friction-model",
    "friction_model",
    type=LiveChoice(friction_names),
    default=None,
    help=f"With --angle: {routes_help()} (docs/oblique.md).",
)
@click.option(
    "--kappa",
    type=float,
    default=None,
    help="With --friction-model microslip: the tangential spring over the wall's normal "
    "stiffness at each node; Coulomb's law is kappa -> infinity. Default 64.",
)
@partner_options
@format_options
@strict_option
@quiet_option
@click.pass_context
def collide(
    ctx,
    nu,
    plane,
    geometry,
    v,
    alpha,
    n_modes,
    select,
    integrator,
    method,
    mesh_refine,
    force,
    energy_tol,
    step_check,
    excite,
    mode_index,
    amplitude,
    phase,
    temperature,
    samples,
    seed,
    plot,
    radius_ratio,
    partner_nu,
    modulus_ratio,
    density_ratio,
    relaxation_time,
    angle,
    friction,
    friction_model,
    kappa,
    fmt,
    as_json,
    strict,
):
    """Head-on collision of an elastic disk or sphere with a hard wall: epsilon and where the
    energy goes.

    Units: E = rho = R = 1 of the body's own constants; v in c, times in R/c; mode energies as
    fractions of the initial kinetic energy. With --excite the disk vibrates before the impact
    (docs/vibrating.md). With --radius-ratio (or another partner option) the body meets a second
    body instead of the wall: units of the first body, v the relative speed, energies fractions
    of the kinetic energy in the centre-of-mass frame (docs/two-disks.md). With --method fem a
    run that would not fit in memory, or take more than the bound of one run (unless --force),
    is refused before its mesh is made. With --angle and --friction the disk hits the wall
    obliquely with Coulomb friction: epsilon_normal, beta, the spin, the friction work and the
    energy left in the modes (docs/oblique.md).
    """
    fmt = output_format(fmt, as_json)
    if angle is not None or friction is not None:
        from restitution.cli.collide_oblique import collide_oblique

        return collide_oblique(ctx, angle, friction, fmt, strict)
    refuse_ignored(
        ctx,
        {"friction_model": "--friction-model", "kappa": "--kappa"},
        "without --angle and --friction (an oblique impact)",
    )
    body = body_nu(nu, plane, geometry)
    if method != "fem" and excite != "thermal":  # one collision bounds its steps itself
        refuse_ignored(
            ctx, {"force": "--force"}, "without --method fem, --excite thermal or --angle"
        )
    partner = partner_from(ctx, nu, plane, geometry)
    integrator = _damped_integrator(ctx, relaxation_time, integrator, excite, method, select)
    if partner is not None:
        return _pair(ctx, body, partner, geometry, v, alpha, n_modes, integrator, energy_tol,
                     step_check, fmt, strict, relaxation_time)  # fmt: skip
    kind = body_kind(geometry)
    material = material_from(nu, plane) if kind.planar else None
    if not kind.vibrating and excite != "none":
        raise InputError(
            f"--excite is available for {_vibrating()} only; leave it out for a {geometry}"
        )
    if excite != "none":
        return _excited(ctx, material, plane, v, alpha, n_modes, select, integrator, method,
                        energy_tol, step_check, excite, fmt, strict, force)  # fmt: skip
    refuse_ignored(ctx, _EXCITE_OPTIONS, "without --excite mode or --excite thermal")
    _check_up_front(v, alpha, integrator, energy_tol)
    if n_modes < 1:
        raise InputError(f"--modes must be at least 1, got {n_modes}")
    if method == "fem":
        if fmt == "csv":
            raise no_table("collide", _NO_MODES)
        refuse_ignored(
            ctx,
            {
                "n_modes": "--modes",
                "select": "--select",
                "integrator": "--integrator",
                "energy_tol": "--energy-tol",
                "step_check": "--step-check",
            },
            "with --method fem (finite elements use --mesh-refine)",
        )
        _check_fem(material if kind.planar else body, v, alpha, mesh_refine, geometry,
                   force)  # fmt: skip
    else:
        refuse_ignored(ctx, {"mesh_refine": "--mesh-refine"}, "with --method modal")
        check_mode_request(body, 2 * n_modes if select == "ranked" else n_modes, None, geometry)
    start = time.perf_counter()
    ms = None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if method == "fem":
            from restitution.fem import fem_collide

            result = fem_collide(
                material if kind.planar else body,
                v,
                alpha,
                refine=mesh_refine,
                geometry=geometry,
            )
        else:
            from restitution.dynamics.collision import collide as run
            from restitution.dynamics.collision import rank_modes

            if select == "ranked":
                pool = get_modes(body, count=2 * n_modes, geometry=geometry)
                ms = rank_modes(
                    pool, n_modes, v, alpha, integrator=integrator, energy_tol=energy_tol
                )
            else:
                ms = get_modes(body, count=n_modes, geometry=geometry)
            if relaxation_time:
                ms = Viscoelastic(ms, relaxation_time)
            long_run = _announce(ms, v, alpha, integrator, energy_tol)
            with _elapsed(long_run):
                result = run(ms, v, alpha, integrator=integrator, energy_tol=energy_tol,
                             step_judge=step_check)  # fmt: skip
    wall = time.perf_counter() - start
    status, advice = stretched(result.status, result.advice, v, LINEAR_SPEED, result)
    inputs = {"geometry": geometry, **nu_inputs(nu, plane, geometry), "v": v, "alpha": alpha,
              "method": method}  # fmt: skip
    if method == "fem":
        inputs["mesh_refine"] = mesh_refine
    else:
        inputs.update(
            modes=n_modes,
            select=select,
            integrator=integrator,
            energy_tol=energy_tol,
            step_check=step_check,
            relaxation_time=relaxation_time,
        )
    payload = {**result.to_dict(), "wall_time_s": wall,
               "select": select if method == "modal" else None}  # fmt: skip
    rows = None if ms is None else (lambda: _mode_rows(result, ms))
    emit(Report("collide", inputs, payload, status, advice, text=lambda: _summary(result),
                rows=rows, no_table=_NO_MODES), fmt)  # fmt: skip
    if status != Status.OK:
        if fmt != "json":  # the JSON says it in "status"
            note(f"warning: status {status}: {advice}")
        if strict:
            sys.exit(EXIT_NOT_CONVERGED)


def _check_fem(material, v: float, alpha: float, refine: int, geometry: str, force: bool):
    """Refuse an FEM run that would not fit in memory, or (unless ``--force``) take longer than
    the bound of one run, before its mesh is made (:func:`restitution.fem.cost.check_collide`)."""
    from restitution.fem.cost import check_collide

    if refine < 0:
        raise InputError(f"--mesh-refine must be a level >= 0, got {refine}")
    check_collide(material, v, alpha, refine, geometry=geometry, force=force,
                  name="--mesh-refine", override="--force")  # fmt: skip


def _pair(ctx, body, partner, geometry, v, alpha, n_modes, integrator, energy_tol, step_check, fmt,
          strict, relaxation_time=0.0):  # fmt: skip
    """``collide --radius-ratio ...``: two bodies head-on (:mod:`restitution.bodies.pair`)."""
    import numpy as np

    from restitution.dynamics.collision import collide as run

    refuse_ignored(ctx, _EXCITE_OPTIONS, "for two bodies (they meet at rest)")
    refuse_ignored(
        ctx,
        {"mesh_refine": "--mesh-refine", "select": "--select", "excite": "--excite",
         "method": "--method"},
        "for two bodies (the modal route with the lowest modes of both)",
    )  # fmt: skip
    _check_up_front(v, alpha, integrator, energy_tol)
    if n_modes < 1:
        raise InputError(f"--modes must be at least 1, got {n_modes}")
    nu2 = partner.nu2(body)
    check_mode_request(body, n_modes, None, geometry)
    check_mode_request(nu2, n_modes, None, geometry)
    pair = partner.pair(body, n_modes, geometry, get_modes)
    if relaxation_time:
        pair = Viscoelastic(pair, relaxation_time)
    start = time.perf_counter()
    long_run = _announce(pair, v, alpha, integrator, energy_tol)
    with warnings.catch_warnings(), _elapsed(long_run):
        warnings.simplefilter("ignore")
        result = run(pair, v, alpha, integrator=integrator, energy_tol=energy_tol,
                     step_judge=step_check)  # fmt: skip
    first, second = pair.member_energies(result.mode_energy_after)
    # Two identical bodies at relative speed 2v are the wall problem at v.
    status, advice = stretched(result.status, result.advice, v, 2 * LINEAR_SPEED, result)
    counts = [int(c) for c in np.bincount(pair.member, minlength=2)]
    detail = {
        "geometry": pair.geometry,
        "reduced_mass": pair.mass,
        "masses": list(pair.member_masses),
        "modes": counts,
        "energy_after": [first, second],
        "speed_meaning": "relative normal speed of the two centres, c of the first body",
    }
    inputs = {"geometry": geometry, "nu": body, "partner_nu": nu2, "v": v,
              "alpha": alpha, "modes": n_modes, "integrator": integrator,
              "energy_tol": energy_tol, "step_check": step_check,
              "radius_ratio": partner.radius_ratio,
              "modulus_ratio": partner.modulus_ratio,
              "density_ratio": partner.density_ratio,
              "relaxation_time": relaxation_time}  # fmt: skip
    units = pair_units(geometry)
    payload = {**result.to_dict(), "wall_time_s": time.perf_counter() - start, "pair": detail}

    def text() -> str:
        return _summary(result) + (
            f"two {geometry}s: R2/R1 = {partner.radius_ratio:g}, E2/E1 = "
            f"{partner.modulus_ratio:g}, rho2/rho1 = {partner.density_ratio:g}, nu2 = "
            f"{nu2:g}; v is the relative speed; modes {counts[0]} + {counts[1]}; "
            f"energy left in the first body {first:.6g}, in the second {second:.6g} (fractions "
            "of the kinetic energy in the centre-of-mass frame)"
        )

    emit(Report("collide", inputs, payload, status, advice, units, text,
                lambda: _mode_rows(result, pair)), fmt)  # fmt: skip
    if status != Status.OK:
        if fmt != "json":
            note(f"warning: status {status}: {advice}")
        if strict:
            sys.exit(EXIT_NOT_CONVERGED)


def _damped_integrator(ctx, tau: float, integrator: str, excite, method, select) -> str:
    """The integrator of a run with ``--relaxation-time tau``: Strang's splitting when the user
    left ``--integrator`` at its default; the options a damped body cannot take are refused."""
    if not (math.isfinite(tau) and tau >= 0):
        raise InputError(f"--relaxation-time must be a finite number >= 0 (R/c), got {tau}")
    if tau == 0:
        return integrator
    for name, value, allowed, why in (
        ("--excite", excite, "none", "a damped body starts at rest"),
        ("--method", method, "modal", "the FEM route has no damping"),
        ("--select", select, "lowest", "a damped body takes its lowest modes"),
    ):
        if value != allowed:
            raise InputError(f"{name} {value} does not go with --relaxation-time: {why}")
    if ctx.get_parameter_source("integrator") == click.core.ParameterSource.DEFAULT:
        return "split"
    if integrator != "split":
        raise InputError(
            f"--relaxation-time runs --integrator split, got {integrator}: Yoshida's split4 "
            "steps backwards, where damped modes grow; leave --integrator out"
        )
    return integrator


def _check_up_front(v: float, alpha: float, integrator: str, energy_tol: float) -> None:
    """Refuse bad collision inputs before any mode is computed.

    The solver settings (``--integrator``, ``--energy-tol``) are checked by the library's
    :class:`restitution.dynamics.collision.CollisionSettings`. ``--v`` and ``--alpha`` are
    checked here because the library checks them only once the modes exist (after
    :func:`restitution.bodies.cache.get_modes`), and its work estimate would otherwise meet a
    speed of 0 first.
    """
    from restitution.dynamics.collision import CollisionSettings

    if not (0 < v < 1):
        raise InputError(f"--v must lie in (0, 1) (units of c), got {v}")
    positive_finite("--alpha", alpha)
    CollisionSettings(integrator=integrator, energy_tol=energy_tol)


def _elapsed(enabled: bool):
    """A spinner with the elapsed time on stderr while a long run integrates (terminals only)."""
    import contextlib

    from rich.console import Console

    if not enabled or quiet() or not sys.stderr.isatty():
        return contextlib.nullcontext()
    return Console(stderr=True).status("integrating the collision ...")


def _announce(modes, v: float, alpha: float, integrator: str, energy_tol: float) -> bool:
    """Say the estimated work of a long run before it starts; returns whether it is long."""
    import numpy as np

    from restitution.dynamics.collision import CollisionSettings, check_work

    settings = CollisionSettings(integrator=integrator, energy_tol=energy_tol)
    est = check_work(modes, np.array([v]), np.array([alpha]), settings)  # refuses the infeasible
    if est.steps > _LONG_RUN_STEPS:
        note(
            f"note: about {est.steps:.2g} time steps of {len(modes)} modes expected "
            f"(simulated time {est.t_end:.3g} R/c, dt = {est.dt:.3g} R/c); this may take a while"
        )
    return est.steps > _LONG_RUN_STEPS


def _excited(ctx, material, plane, v, alpha, n_modes, select, integrator, method, energy_tol,
             step_check, excite, fmt, strict, force=False):  # fmt: skip
    """``collide --excite mode|thermal``: a vibrating disk (thin layer over
    :mod:`restitution.vibrating.vibration` and :mod:`restitution.vibrating.ensemble`)."""
    import math

    p = ctx.params
    if excite not in _EXCITATIONS:
        raise InputError(f"unknown --excite {excite!r}; choose one of {', '.join(_EXCITATIONS)}")
    if method != "modal":
        raise InputError("--excite needs --method modal (the FEM path starts at rest)")
    if select != "lowest":
        raise InputError("--excite uses the lowest modes; --select ranked has no effect there")
    _check_up_front(v, alpha, integrator, energy_tol)
    if n_modes < 1:
        raise InputError(f"--modes must be at least 1, got {n_modes}")
    check_mode_request(material.nu, n_modes)
    if excite == "mode":
        names = ("temperature", "samples", "seed", "plot")
        refuse_ignored(ctx, {k: _EXCITE_OPTIONS[k] for k in names}, "with --excite mode")
        if p["amplitude"] is None:
            raise InputError("--excite mode needs --amplitude (the mode's energy / (m/2) v^2)")
        if not (math.isfinite(p["amplitude"]) and p["amplitude"] >= 0):
            raise InputError(f"--amplitude must be a number >= 0, got {p['amplitude']}")
    else:
        names = ("mode_index", "amplitude", "phase")
        refuse_ignored(ctx, {k: _EXCITE_OPTIONS[k] for k in names}, "with --excite thermal")
        if p["temperature"] is None:
            raise InputError("--excite thermal needs --temperature (energy per mode / (m/2) v^2)")
        if not (math.isfinite(p["temperature"]) and p["temperature"] >= 0):
            raise InputError(f"--temperature must be a number >= 0, got {p['temperature']}")
        if p["samples"] is not None and p["samples"] < 1:
            raise InputError(f"--samples must be at least 1, got {p['samples']}")
        from restitution.vibrating.ensemble import check_ensemble_memory

        check_ensemble_memory(p["samples"] or 1, n_modes, json=fmt != "text", name="--samples")
        if p["plot"] is not None:
            from restitution.cli._common import check_figure_file

            check_figure_file(p["plot"], "--plot")
    ms = get_modes(material, count=n_modes)
    from restitution.vibrating.vibration import kinetic_energy

    e0 = float(kinetic_energy(ms, v))
    inputs = {"nu": material.nu, "plane": plane, "v": v, "alpha": alpha, "method": method,
              "modes": n_modes, "select": select, "integrator": integrator,
              "energy_tol": energy_tol, "excite": excite,
              "step_check": step_check}  # fmt: skip
    start = time.perf_counter()
    if excite == "mode":
        from restitution.dynamics.collision import collide as run
        from restitution.vibrating.vibration import single_mode_state

        index = 0 if p["mode_index"] is None else p["mode_index"]
        phase = 0.0 if p["phase"] is None else p["phase"]
        Q, P = single_mode_state(ms, index, p["amplitude"] * e0, phase)
        _announce(ms, v, alpha, integrator, energy_tol)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = run(ms, v, alpha, integrator=integrator, energy_tol=energy_tol,
                         initial=(Q, P), step_judge=step_check)  # fmt: skip
        inputs.update(mode_index=index, amplitude=p["amplitude"], phase=phase)
        excited = {"index": index, "n": int(ms.n[index]), "l": int(ms.l[index]),
                   "omega": float(ms.omega[index])}  # fmt: skip
        payload = {**result.to_dict(), "excited_mode": excited,
                   "wall_time_s": time.perf_counter() - start}  # fmt: skip
        emit(Report("collide", inputs, payload, result.status, result.advice,
                    text=lambda: _summary(result), rows=lambda: _mode_rows(result, ms)),
             fmt)  # fmt: skip
        status = result.status
    else:
        from restitution.vibrating.ensemble import thermal_ensemble
        from restitution.vibrating.sequences import check_collisions_time

        samples = 1 if p["samples"] is None else p["samples"]
        seed = 0 if p["seed"] is None else p["seed"]
        check_collisions_time(ms, v, alpha, samples, force=force, name="--samples",
                              override="--force", item="sample", integrator=integrator,
                              energy_tol=energy_tol, step_judge=step_check)  # fmt: skip
        _announce(ms, v, alpha, integrator, energy_tol)
        with warnings.catch_warnings(), _progress_bar(samples) as advance:
            warnings.simplefilter("ignore")
            ens = thermal_ensemble(ms, v, alpha, p["temperature"] * e0, samples, seed,
                                   integrator=integrator, energy_tol=energy_tol,
                                   progress=advance, force=force,
                                   step_judge=step_check)  # fmt: skip
        inputs.update(temperature=p["temperature"], samples=samples, seed=seed)
        status = Status.OK if not ens.failures else Status.FAILED_SAMPLES
        advice = None if not ens.failures else (
            f"{len(ens.failures)} samples could not be integrated (see 'failures'); they are "
            "left out of the statistics")  # fmt: skip
        if p["plot"] is not None:
            from restitution.reproduction.figures.vibrating import plot_histogram

            plot_histogram(ens, p["plot"])
            note(f"wrote {p['plot']}")
        payload = {**ens.to_dict(), "wall_time_s": time.perf_counter() - start}
        emit(Report("collide", inputs, payload, status, advice,
                    text=lambda: "\n".join(_ensemble_text(ens)),
                    rows=lambda: payload["per_sample"]), fmt)  # fmt: skip
    if status != Status.OK:
        if fmt != "json":
            note(f"warning: status {status}")
        if status == Status.FAILED_SAMPLES:  # as epsilon and curve when collisions failed
            sys.exit(EXIT_FAILED_POINTS)
        if strict:
            sys.exit(EXIT_NOT_CONVERGED)


def _progress_bar(total: int):
    """A rich progress bar over the collisions of an ensemble on stderr (terminals only, not
    with --quiet); yields the callback that takes the number done."""
    import contextlib

    @contextlib.contextmanager
    def bar():
        if quiet() or not sys.stderr.isatty() or total < 2:
            yield None
            return
        from rich.console import Console
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeElapsedColumn,
            TimeRemainingColumn,
        )

        with Progress(TextColumn("collisions"), BarColumn(), MofNCompleteColumn(),
                      TimeElapsedColumn(), TextColumn("ETA"), TimeRemainingColumn(),
                      console=Console(stderr=True)) as prog:  # fmt: skip
            task = prog.add_task("collisions", total=total)
            yield lambda done: prog.update(task, completed=done)

    return bar()


def _ensemble_text(ens) -> list[str]:
    """The thermal ensemble for people: epsilon's statistics and the temperature."""
    s = ens.summary()
    if not s["samples"]:
        return ["no sample could be integrated"]
    return [
        f"epsilon over {s['samples']} thermal samples: mean {s['mean']:.6f} "
        f"(+- {s['mean_error'] or 0:.2g}), spread {s['spread']:.4g}, "
        f"min {s['min']:.4f}, max {s['max']:.4f}, fraction above 1: {s['fraction_above_1']:.3f}\n"
        f"temperature {ens.temperature:.4g} E R^2 per mode = {ens.temperature_fraction:.4g} "
        f"(m/2) v^2; v / v_thermal = {ens.v_over_v_thermal:.4g}; {ens.n_modes} modes, "
        f"v = {ens.v} c, alpha = {ens.alpha}, seed {ens.seed}"
    ]
