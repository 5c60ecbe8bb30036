"""Commands ``restitution epsilon`` (one speed) and ``restitution curve`` (Figs. 1, 7, 8).

Thin layer over :mod:`restitution.laws.law`, :mod:`restitution.limits.sweep` and the figure
modules. List options accept several values after one flag (``--nu 0.33 0.9``) or a repeated flag.
"""

from __future__ import annotations

import math
import sys
from dataclasses import replace
from pathlib import Path

import click

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, kinds
from restitution.cli._common import (
    EXIT_FAILED_POINTS,
    EXIT_NOT_CONVERGED,
    LINEAR_SPEED,
    PathOption,
    body_nu,
    check_output_dir,
    force_option,
    geometry_option_no_plane,
    note,
    partner_from,
    partner_options,
    quiet,
    quiet_option,
    refuse_ignored,
    stretched,
    strict_option,
    writing,
)
from restitution.cli.report import (
    Report,
    emit,
    figure_format,
    figure_format_option,
    format_options,
    output_format,
)
from restitution.cli.words import current_command, in_command_words
from restitution.errors import InputError
from restitution.file_set import file_set
from restitution.limits.grid_check import check_grid
from restitution.limits.sweep import (
    DEFAULTS,
    SweepSettings,
    defaults_for,
    pair_settings,
)
from restitution.status import Status

_V_HELP = (
    "speed of the body towards the wall before the collision, in units of c = sqrt(E/rho) of "
    "its own constants (two identical bodies approaching at +-v, relative speed 2v, collide "
    "the same way)"
)


class _ListCommand(click.Command):
    """A command whose list options take several values after one flag.

    ``--nu 0.33 0.9`` is rewritten to ``--nu 0.33 --nu 0.9`` before Click parses it: every
    following token that reads as a number belongs to the flag.
    """

    list_options: tuple[str, ...] = ()

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        out: list[str] = []
        current = None
        for token in args:
            if token in self.list_options:
                current = token
                out.append(token)
                continue
            if current is not None and out[-1] != current and _is_number(token):
                out += [current, token]
                continue
            if current is not None and out[-1] == current:
                out.append(token)  # the flag's first value
                continue
            current = None
            out.append(token)
        return super().parse_args(ctx, out)


def _is_number(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


class _EpsilonCommand(_ListCommand):
    list_options = ("--alphas", "--modes")


class _CurveCommand(_ListCommand):
    list_options = ("--nu", "--v", "--alphas", "--modes")


def _settings(
    velocities=None,
    alphas=None,
    modes=None,
    alpha_scale=None,
    geometry=DEFAULT_GEOMETRY,
    partner=None,
) -> SweepSettings:
    """The body's default sweep (for a ``partner``: carried over to the pair by
    :func:`restitution.limits.sweep.pair_settings`) with the given sets in place of its own."""
    changes = {
        "velocities": tuple(velocities) if velocities else None,
        "alphas": tuple(alphas) if alphas else None,
        "n_modes": tuple(modes) if modes else None,
        "alpha_scale": alpha_scale,
    }
    base = defaults_for(geometry)
    if partner is not None:
        base = pair_settings(base, partner)
    return replace(base, **{k: v for k, v in changes.items() if v is not None})


def _executor_options(f):
    f = quiet_option(f)
    f = strict_option(f)
    f = click.option(
        "--retry-failed",
        is_flag=True,
        help="Recompute points stored as failed (points whose worker died are always retried).",
    )(f)
    f = click.option(
        "--progress/--no-progress",
        default=None,
        help="Progress bar with ETA on stderr (default: when stderr is a terminal).",
    )(f)
    f = click.option(
        "--store",
        type=PathOption(dir_okay=False, path_type=Path),
        default=None,
        help="Result store (SQLite); default: results.sqlite in the user cache directory.",
    )(f)
    f = click.option(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="Run on an existing Dask cluster, e.g. tcp://host:8786.",
    )(f)
    f = click.option(
        "--workers",
        type=click.IntRange(min=1),
        default=None,
        help="Run on a local Dask cluster with this many worker processes "
        "(default: local processes on all cores).",
    )(f)
    f = click.option(
        "--modes",
        "modes",
        type=click.IntRange(min=1),
        multiple=True,
        help="Mode counts N for the N -> infinity extrapolation (default "
        + ", ".join(f"{k.sweep_modes} for a {k.geometry}" for k in kinds().values())
        + ").",
    )(f)
    f = click.option(
        "--alpha-scale",
        type=click.Choice(["absolute", "compression"]),
        default=None,
        help="How --alphas are read: wall hardness in 1/R at every speed (absolute), or "
        "products alpha * delta_max(v) with the quasistatic compression delta_max (a disk: "
        "v sqrt(ln(4/v)); a sphere: Hertz) (compression). "
        f"Default {DEFAULTS.alpha_scale}.",
    )(f)
    f = click.option(
        "--alphas",
        type=float,
        multiple=True,
        help=f"Wall hardness values for alpha -> infinity (default {DEFAULTS.alphas}).",
    )(f)
    return f


@click.command(cls=_EpsilonCommand)
@click.option(
    "--nu",
    type=float,
    required=True,
    help="Poisson number: two-dimensional for a disk, three-dimensional for a sphere.",
)
@geometry_option_no_plane
@click.option("--v", "v", type=float, required=True, help=f"Speed v: {_V_HELP}.")
@click.option(
    "--alpha",
    type=float,
    default=None,
    help="Only extrapolate N -> infinity at this wall hardness (1/R); default: both limits.",
)
@format_options
@click.option(
    "--method",
    type=click.Choice(["modal", "fem"]),
    default="modal",
    show_default=True,
    help="modal: N modes, N -> infinity; fem: finite elements on contact-graded meshes, h -> 0.",
)
@force_option("--method fem: ")
@_executor_options
def epsilon(
    nu,
    geometry,
    v,
    alpha,
    fmt,
    as_json,
    method,
    force,
    alphas,
    alpha_scale,
    modes,
    workers,
    scheduler,
    store,
    progress,
    retry_failed,
    strict,
):
    """Coefficient of restitution at one speed v, extrapolated to a hard wall and N -> infinity.

    v is the body's speed towards the wall in units of c = sqrt(E/rho). The collisions of the
    grid are computed (or read from the store) first. Exit status 1 when grid points failed;
    with --strict, 3 when the extrapolation is not asymptotic. With --method fem the runs that
    would not fit in memory, or take more than the bound of one run (unless --force), are
    refused before any mesh is made.
    """
    from restitution.limits.curves import epsilon_at
    from restitution.limits.sweep import grid

    fmt = output_format(fmt, as_json)
    nu = body_nu(nu, None, geometry)
    if alpha is not None and (alphas or alpha_scale):
        raise InputError(
            "--alpha fixes one wall and extrapolates N -> infinity only; --alphas and "
            "--alpha-scale set the alpha -> infinity extrapolation: give one or the other"
        )
    if method == "fem":
        modal_only = {"--modes": modes, "--workers": workers, "--scheduler": scheduler}
        modal_only.update({"--store": store, "--retry-failed": retry_failed or None})
        _fem_epsilon(nu, geometry, v, alpha, alphas, alpha_scale, fmt, modal_only, progress,
                     strict, force)  # fmt: skip
        return
    if force:  # the modal sweep has no time bound to lift
        raise InputError("--force has no effect with --method modal")
    settings = _settings([v], alphas, modes, alpha_scale, geometry)
    swept = replace(settings, velocities=(float(v),))
    if alpha is not None:  # SweepSettings refuses a wall hardness that is not positive
        swept = replace(swept, alphas=(float(alpha),), alpha_scale="absolute")
    points = grid([nu], swept)
    work = check_grid(points, store)  # in seconds, not after a cluster has failed each point
    _announce(work, progress)
    report = _sweep(points, swept, store, workers, scheduler, progress, retry_failed)
    result = epsilon_at(nu, v, alpha=alpha, settings=settings, store=store, run=False)
    failed = len(result.failures) + len(report.lost)
    status, advice = _status(result.asymptotic_ok, result.message, failed)
    status, advice = stretched(status, advice, v, LINEAR_SPEED, None)
    inputs = {
        "geometry": geometry,
        "nu": nu,
        "v": v,
        "alpha": alpha,
        "settings": swept.to_dict(),
        "store": None if store is None else str(store),
    }
    body = _unknown_errors(result.to_dict(), swept)

    def text() -> str:
        limits = "N -> inf" if alpha is not None else "alpha -> inf and N -> inf"
        where = f" at alpha = {alpha:g}" if alpha is not None else ""
        grid_alphas = [alpha] if alpha is not None else list(settings.alphas_at(v, nu=nu))
        return (
            f"epsilon = {result.epsilon:.6f} +- {_err(result.epsilon_err, swept)}   "
            f"({geometry}, nu = {nu:g}, v = {v:g} c towards the wall; {limits}{where})\n"
            f"energy loss 1 - epsilon^2 = {result.energy_loss:.6f} +- "
            f"{_err(result.energy_loss_err, swept)}\n"
            f"grid: alpha = {', '.join(f'{a:g}' for a in grid_alphas)}; "
            f"N = {', '.join(str(n) for n in settings.n_modes)} "
            f"({settings.select} modes, {settings.integrator} integrator)"
        )

    emit(Report("epsilon", inputs, body, status, advice, text=text,
                rows=lambda: [_epsilon_row(body, status)]), fmt)  # fmt: skip
    _finish(status, advice, list(result.failures), report, strict, fmt)


_ROW_KEYS = ("geometry", "nu", "v", "alpha", "epsilon", "epsilon_err", "energy_loss",
             "energy_loss_err", "asymptotic_ok")  # fmt: skip


def _epsilon_row(body: dict, status: str) -> dict:
    """``epsilon --format csv``: the answer's numbers as one row, with its status."""
    return {**{k: body[k] for k in _ROW_KEYS}, "status": status}


def _two_point(settings: SweepSettings) -> bool:
    """Whether the fit cannot estimate an error: a line through two points (two N, or two alpha
    with both limits) has no residual, so its error is zero; one point has no fit at all."""
    return len(settings.n_modes) < 3 or 1 < len(settings.alphas) < 3


def _err(value: float, settings: SweepSettings) -> str:
    """An error bar, or ``unknown`` when the fit cannot estimate one (:func:`_two_point`)."""
    if _two_point(settings) or not (math.isfinite(value) and value > 0):
        return "unknown"
    return f"{value:.6f}"


def _unknown_errors(d: dict, settings: SweepSettings) -> dict:
    """The JSON of a result whose errors the fit cannot estimate (:func:`_two_point`): the
    error bars are ``null``, as the text says ``unknown``, and ``errors_unknown`` says why."""
    if not _two_point(settings):
        return d
    return {
        **d,
        "epsilon_err": None,
        "energy_loss_err": None,
        "errors_unknown": "fewer than 3 mode counts (or 2 walls) leave no residual to estimate "
        "an error from; give at least 3 --modes and 3 --alphas",
    }


def _announce(work, progress) -> None:
    """The grid's work (:class:`~restitution.limits.grid_check.GridWork`) on stderr where the
    progress bar shows (``--progress``, or stderr a terminal): a refusal stays one line."""
    shown = progress if progress is not None else sys.stderr.isatty()
    if work.collisions and shown and not quiet():
        note(f"note: {work.words()}")


def _sweep(points, settings, store, workers, scheduler, progress, retry_failed):
    from restitution.limits.sweep import run_sweep

    return run_sweep(
        points,
        store=store,
        workers=workers,
        scheduler=scheduler,
        batch_size=settings.batch_size,
        progress=False if quiet() else progress,
        retry_failed=retry_failed,
    )


def _fem_epsilon(
    nu, geometry, v, alpha, alphas, alpha_scale, fmt, modal_only, progress, strict, force
):
    """``epsilon --method fem``: both limits (or h -> 0 at one alpha) on the FEM route, printed
    like the modal route (JSON: the same envelope and keys, with levels in place of N)."""
    from restitution.fem.limits import fem_epsilon

    given = [name for name, value in modal_only.items() if value]
    if given:
        verb, it = ("belongs", "it") if len(given) == 1 else ("belong", "them")
        raise InputError(
            f"{', '.join(given)} {verb} to the modal route; leave {it} out with --method fem"
        )
    from restitution.fem.cost import check_epsilon

    options = {"alpha": alpha, "alphas": tuple(alphas) or None, "alpha_scale": alpha_scale}
    check_epsilon(nu, v, geometry=geometry, force=force, name="--v", override="--force",
                  **options)  # fmt: skip

    def report(run) -> None:
        note(
            f"alpha = {run.alpha:.6g}, level {run.level}: {run.n_dofs} dofs, "
            f"epsilon = {run.epsilon:.7f} ({run.wall_time_s:.1f} s)"
        )

    result = fem_epsilon(nu, v, on_run=report if progress else None, geometry=geometry, **options)
    status, advice = _status(result.asymptotic_ok, result.message, 0)
    if status != Status.OK:
        advice = f"{result.message}; refine the meshes or add harder walls (--alphas)"
    status, advice = stretched(status, advice, v, LINEAR_SPEED, None)
    inputs = {"geometry": geometry, "nu": nu, "v": v, "alpha": alpha, "method": "fem",
              "alphas": list(alphas) or None, "alpha_scale": alpha_scale}  # fmt: skip
    body = result.to_dict()
    emit(Report("epsilon", inputs, body, status, advice, text=result.summary,
                rows=lambda: [_epsilon_row(body, status)]), fmt)  # fmt: skip
    _finish(status, advice, (), None, strict, fmt)


def _status(asymptotic: bool, message: str, failed: int) -> tuple[str, str | None]:
    if failed:
        why = f" ({message})" if message else ""
        return Status.POINTS_FAILED, (
            f"{failed} collision(s) of the grid failed{why}; see the messages, change the "
            "settings, or rerun with --retry-failed"
        )
    if not asymptotic:
        return (
            Status.NOT_ASYMPTOTIC,
            f"{message}; use larger N (--modes) and harder walls (--alphas)",
        )
    return Status.OK, None


def _finish(status, advice, failures, report, strict, fmt="text") -> None:
    """Print what went wrong (JSON says it in 'status') and exit with the documented status."""
    if status == Status.OK:
        return
    if fmt != "json":
        note(f"warning: {status}: {advice}")
        for a, n, m in failures[:3]:
            note(f"  failed: alpha = {a:g}, N = {n}: {in_command_words(m, current_command())}")
        for spec, m in (report.lost if report is not None else ())[:3]:
            note(
                f"  lost (worker died; rerun to retry): v = {spec.v:g}, "
                f"alpha = {spec.alpha:g}, N = {spec.n_modes}: {m}"
            )
    if status == Status.POINTS_FAILED:
        sys.exit(EXIT_FAILED_POINTS)
    if strict:
        sys.exit(EXIT_NOT_CONVERGED)


_FIGURE_FORMATS = ("png", "pdf", "svg")
"""Figure formats of ``curve`` (``--figure-format``; ``--format`` before it named the reporter)."""


@click.command(cls=_CurveCommand)
@click.option(
    "--nu",
    "nus",
    type=float,
    multiple=True,
    help="Poisson number(s): two-dimensional for a disk (default 0.33 0.9), three-dimensional "
    "for a sphere (required).",
)
@geometry_option_no_plane
@click.option(
    "--v",
    "velocities",
    type=float,
    multiple=True,
    help=f"Speed(s) v: {_V_HELP}. Default: the paper's 0.005, 0.01, 0.02, 0.04, ..., 0.30.",
)
@click.option(
    "--out",
    type=PathOption(file_okay=False, path_type=Path),
    default=Path("restitution-curve"),
    show_default=True,
    help="Directory for figures and exports.",
)
@figure_format_option(_FIGURE_FORMATS, "png", "Figure format.")
@format_options(
    also=_FIGURE_FORMATS,
    also_help=" CSV: one row per (nu, v). png, pdf, svg: the old spelling of --figure-format "
    "(deprecated).",
)
@click.option(
    "--production",
    is_flag=True,
    help="Compute each law with the shipped laws' production settings (their speeds 1e-4-0.3, "
    "walls and mode windows; the low-speed points of a disk, a sphere or two disks too) "
    "instead of a grid: writes "
    "law_*.json / .csv / .txt only, no figures; the estimate is printed before it starts.",
)
@click.option(
    "--force",
    is_flag=True,
    help="With --production: compute even when the estimate exceeds the bound of one run (1 h).",
)
@partner_options(plane=False)
@_executor_options
@click.pass_context
def curve(
    ctx,
    nus,
    geometry,
    velocities,
    out,
    figure_fmt,
    fmt,
    as_json,
    production,
    force,
    alphas,
    alpha_scale,
    modes,
    workers,
    scheduler,
    store,
    progress,
    retry_failed,
    strict,
    radius_ratio,
    partner_nu,
    modulus_ratio,
    density_ratio,
):
    """epsilon(v) for one or more Poisson numbers: Fig. 1, Figs. 7 and 8, and exports.

    v is the body's speed towards the wall in units of c = sqrt(E/rho) of its own constants.
    Writes fig01_epsilon, fig07_alpha_nu*, fig08_modes_nu*, and law_nu*.json / .csv / .txt (the
    table: v, epsilon, epsilon_err for event-driven and DEM codes) into --out; for a sphere
    (--geometry sphere) the names carry the body: fig01_epsilon_sphere,
    fig07_alpha_sphere_nu*, fig08_modes_sphere_nu*, law_sphere_nu*.json / .csv / .txt (the
    file `restitution law --geometry sphere --law-file` reads). With --radius-ratio (or
    another partner option) the law of two bodies meeting head-on: v is their relative speed
    (default speeds twice the wall's, mode windows of both bodies at the wall's frequency cutoff;
    files law_pair_r<R2/R1>..._nu*.json). The figures are PNG unless --figure-format says
    otherwise; --format text|json|csv chooses how the table is printed. Exit status 1 when
    collisions failed; with --strict, 3 when a speed is not asymptotic.
    """
    from restitution.laws.law import EpsilonLaw
    from restitution.laws.law_file import law_filename
    from restitution.limits.curves import compute_curves
    from restitution.limits.store import Store
    from restitution.limits.sweep import grid
    from restitution.reproduction.figures import fig01_epsilon, fig07_alpha, fig08_modes

    if production and (figure_fmt is not None or fmt in _FIGURE_FORMATS):
        raise InputError(f"--figure-format has no effect {_PRODUCTION}")
    fmt, figure_fmt = figure_format(fmt, figure_fmt, _FIGURE_FORMATS, "png")
    fmt = output_format(fmt, as_json)
    kind = body_kind(geometry)
    if not nus and not kind.default_nus:
        defaults = "; ".join(
            f"the default {' '.join(f'{nu:g}' for nu in k.default_nus)} is the {k.geometry}'s"
            for k in kinds().values()
            if k.default_nus
        )
        raise InputError(
            f"give the {geometry}'s Poisson number(s) with --nu "
            f"({'two' if kind.dimension == 2 else 'three'}-dimensional, in "
            f"({kind.nu_low:g}, {kind.nu_high:g})); {defaults}"
        )
    nus = tuple(body_nu(nu, None, geometry) for nu in (nus or kind.default_nus))
    if partner_nu is not None and len(nus) > 1:
        raise InputError(
            "--partner-nu names the second body's material for one --nu; give one --nu with it"
        )
    partner = partner_from(ctx, nus[0], None, geometry)
    inputs = {"geometry": geometry, "nus": list(nus),
              "partner": None if partner is None else partner.to_dict(),
              "out": str(out), "store": None if store is None else str(store)}  # fmt: skip
    units = _curve_units(geometry, partner)
    if production:
        return _production(ctx, nus, geometry, partner, out, store, workers, progress, force,
                           fmt, inputs, units)  # fmt: skip
    refuse_ignored(ctx, {"force": "--force"}, "without --production")
    settings = _settings(velocities, alphas, modes, alpha_scale, geometry, partner)
    inputs.update(settings=settings.to_dict(), figure_format=figure_fmt)
    # The figures draw the curves' numbers whatever the body; a sphere's say so and are named
    # apart from the disk's, so one --out can hold both.
    tag, body_note = "", ""
    if kind.file_tag:
        tag = f"_{kind.file_tag}"
        body_note = (
            f"{geometry}: nu is its {kind.dimension}D Poisson number, v in c = sqrt(E/rho) of it"
        )
    if partner is not None:
        tag += "_pair"
        body_note = (
            f"two {geometry}s, R2/R1 = {partner.radius_ratio:g}: v is the relative speed, c of "
            "the first"
        )
    check_output_dir(out, "--out")  # before the sweep, not after it
    points = grid(nus, settings)
    _announce(check_grid(points, store), progress)
    report = _sweep(points, settings, store, workers, scheduler, progress, retry_failed)
    curves = compute_curves(nus, settings, store=store, run=False)
    with Store(store) as db:
        errors = db.errors(points)
    failed_specs = [s for s in points if s.key() in errors]
    failures = [(s.alpha, s.n_modes, errors[s.key()]) for s in failed_specs]
    lines, rows, laws = [], [], []
    # The run's figures and laws appear together or not at all (issue 47: a folder mixing two
    # runs' files after a full disk).
    with writing(out, "--out"), file_set(out, "curve", prune=False) as stage:
        written = [
            fig01_epsilon.plot(
                fig01_epsilon.compute(nus, curves=curves),
                stage / f"fig01_epsilon{tag}.{figure_fmt}",
                note=body_note,
            )
        ]
        for nu in nus:
            c = curves[nu]
            written.append(
                fig07_alpha.plot(
                    fig07_alpha.compute(nu, curve=c),
                    stage / f"fig07_alpha{tag}_nu{nu:g}.{figure_fmt}",
                    note=body_note,
                )
            )
            written.append(
                fig08_modes.plot(
                    fig08_modes.compute(nu, curve=c),
                    stage / f"fig08_modes{tag}_nu{nu:g}.{figure_fmt}",
                    note=body_note,
                )
            )
            lines += _curve_lines(c, geometry, settings)
            rows += _curve_rows(c, settings)
            try:
                law = EpsilonLaw.from_curve(c)
            except Exception as exc:  # noqa: BLE001 - report and go on with the other nu
                note(f"warning: no {geometry} law for nu = {nu:g}: {exc}")
                laws.append({"nu": nu, "files": [], "error": str(exc)})
                continue
            stem = Path(law_filename(nu, geometry, partner)).stem
            files = [
                law.to_json(stage / f"{stem}.json"),
                law.to_csv(stage / f"{stem}.csv"),
                law.to_table(stage / f"{stem}.txt"),
            ]
            written += files
            laws.append({"nu": nu, "files": [str(out / p.name) for p in files], "error": None})
    written = [out / Path(p).name for p in written]
    lines.append("wrote " + ", ".join(str(p) for p in written))
    asymptotic = all(row["asymptotic_ok"] for row in rows)
    failed = len(failures) + len(report.lost)
    message = "" if asymptotic else "some speeds are not asymptotic (see the table)"
    status, advice = _status(asymptotic, message, failed)
    payload = {
        "points": rows,
        "laws": laws,
        "written": [str(p) for p in written],
        "failed_points": [_point(s, errors[s.key()]) for s in failed_specs],
        "lost_points": [_point(s, m) for s, m in report.lost],
    }
    emit(Report("curve", inputs, payload, status, advice, units, lambda: "\n".join(lines),
                lambda: rows), fmt)  # fmt: skip
    _finish(status, advice, failures, report, strict, fmt)


def _point(spec, message: str) -> dict:
    """A collision of the grid that failed (or whose worker died), with its message."""
    return {"nu": spec.nu, "v": spec.v, "alpha": spec.alpha, "n_modes": spec.n_modes,
            "message": message}  # fmt: skip


def _curve_units(geometry: str, partner) -> dict:
    """The units of ``curve``'s numbers: the body's, ``v`` the relative speed of a pair."""
    units = dict(body_kind(geometry).units)
    if partner is not None:
        units["speed"] = "c1 = sqrt(E1/rho1) of the first body (v: the relative normal speed)"
    return units


def _curve_lines(c, geometry: str, settings: SweepSettings) -> list[str]:
    """The table of one Poisson number for people: v, epsilon, its error, asymptotic or why not."""
    body = "" if geometry == DEFAULT_GEOMETRY else f"{geometry}, "
    lines = [f"{body}nu = {c.nu:g}:   v/c    epsilon     error   asymptotic"]
    for v, lim in zip(c.velocities, c.limits, strict=True):
        eps = "nan" if not math.isfinite(lim.epsilon) else f"{lim.epsilon:.5f}"
        lines.append(
            f"          {v:5.3f}  {eps:>8}  {_err(lim.epsilon_err, settings)[:8]:>8}   "
            f"{'yes' if lim.asymptotic_ok else 'NO: ' + lim.message[:70]}"
        )
    return lines


def _curve_rows(c, settings: SweepSettings) -> list[dict]:
    """One row per speed of one Poisson number: epsilon, its error (``None`` when the fit
    cannot estimate one, as the text's ``unknown``), whether asymptotic, status and why."""
    rows = []
    for v, lim in zip(c.velocities, c.limits, strict=True):
        err = None if _err(lim.epsilon_err, settings) == "unknown" else float(lim.epsilon_err)
        rows.append({
            "nu": float(c.nu),
            "v": float(v),
            "epsilon": float(lim.epsilon) if math.isfinite(lim.epsilon) else None,
            "epsilon_err": err,
            "asymptotic_ok": bool(lim.asymptotic_ok),
            "status": Status.OK if lim.asymptotic_ok else Status.NOT_ASYMPTOTIC,
            "message": lim.message,
        })  # fmt: skip
    return rows


_PRODUCTION = (
    "with --production (its speeds, walls and mode windows are the shipped laws'; it draws no "
    "figures)"
)


def _production(ctx, nus, geometry, partner, out, store, workers, progress, force, fmt, inputs,
                units) -> None:  # fmt: skip
    """``curve --production``: each law with the production settings
    (:mod:`restitution.laws.making.compute`), written as JSON, CSV and table into ``out``."""
    from restitution.laws.law import EpsilonLaw
    from restitution.laws.low_speed import low_speeds_of
    from restitution.laws.making.compute import check_plan, plan, production_groups
    from restitution.laws.making.production import build

    refuse_ignored(
        ctx,
        {"velocities": "--v", "alphas": "--alphas", "alpha_scale": "--alpha-scale",
         "modes": "--modes", "scheduler": "--scheduler", "retry_failed": "--retry-failed"},
        _PRODUCTION,
    )  # fmt: skip
    groups = production_groups(geometry, partner)
    plans = [plan(nu, geometry, partner, out, reuse=False) for nu in nus]
    for p in plans:
        check_plan(p, force)
    check_output_dir(out, "--out")  # before the sweep, not after it
    written, lines, laws, rows = [], [], [], []
    for nu, p in zip(nus, plans, strict=True):
        note(f"note: nu = {nu:g}: {p.words()}")
        low = low_speeds_of(geometry, partner, nu)
        # The law's three files appear together or not at all (issue 47).
        with writing(out, "--out"), file_set(out, "curve", prune=False) as stage:
            (path,) = build(stage, [nu], groups, store=store, workers=workers,
                            progress=False if quiet() else progress, low_speeds=low,
                            geometry=geometry, partner=partner)  # fmt: skip
            law = EpsilonLaw.from_json(path)
            law.to_csv(path.with_suffix(".csv"))
            law.to_table(path.with_suffix(".txt"))
        files = [out / path.name, out / f"{path.stem}.csv", out / f"{path.stem}.txt"]
        written += files
        ok = [bool(x) for x in law.asymptotic_ok]
        lines.append(f"nu = {nu:g}: {sum(ok)} of {len(ok)} speeds pass every check; {path.name}")
        laws.append({"nu": nu, "files": [str(f) for f in files], "speeds": len(ok),
                     "passing": sum(ok)})  # fmt: skip
        rows += [
            {"nu": nu, "v": float(v), "epsilon": float(e), "epsilon_err": float(de),
             "asymptotic_ok": good,
             "status": Status.OK if good else Status.NOT_ASYMPTOTIC}
            for v, e, de, good in zip(law.v, law.epsilon_points, law.epsilon_err_points, ok,
                                      strict=True)
        ]  # fmt: skip
    lines.append("wrote " + ", ".join(str(p) for p in written))
    failing = sum(law["speeds"] - law["passing"] for law in laws)
    status, advice = Status.OK, None
    if failing:
        status = Status.NOT_ASYMPTOTIC
        advice = f"{failing} speed(s) fail a check (see 'points'); the laws mark them"
    inputs = {**inputs, "production": True}
    payload = {"laws": laws, "points": rows, "written": [str(p) for p in written]}
    emit(Report("curve", inputs, payload, status, advice, units, lambda: "\n".join(lines),
                lambda: rows), fmt)  # fmt: skip
