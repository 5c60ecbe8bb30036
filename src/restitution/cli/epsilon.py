"""Commands ``restitution epsilon`` (one speed) and ``restitution curve`` (Figs. 1, 7, 8).

Thin layer over :mod:`restitution.law`, :mod:`restitution.sweep` and the figure modules. List
options accept several values after one flag (``--nu 0.33 0.9``) or a repeated flag.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import click

from restitution.material import Material
from restitution.sweep import DEFAULTS, SweepSettings

_V_HELP = (
    "speed of the disk towards the wall before the collision, in units of the 2D sound speed "
    "c = sqrt(E/rho) (two identical disks approaching at +-v, relative speed 2v, collide the "
    "same way)"
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


def _settings(velocities=None, alphas=None, modes=None, alpha_scale=None) -> SweepSettings:
    changes = {
        "velocities": tuple(velocities) if velocities else None,
        "alphas": tuple(alphas) if alphas else None,
        "n_modes": tuple(modes) if modes else None,
        "alpha_scale": alpha_scale,
    }
    return replace(DEFAULTS, **{k: v for k, v in changes.items() if v is not None})


def _check_nu(nu: float) -> float:
    return Material(nu=nu).nu  # raises InputError naming the allowed range


def _executor_options(f):
    f = click.option(
        "--progress/--no-progress",
        default=None,
        help="Progress bar with ETA on stderr (default: when stderr is a terminal).",
    )(f)
    f = click.option(
        "--store",
        type=click.Path(dir_okay=False, path_type=Path),
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
        help=f"Mode counts N for the N -> infinity extrapolation (default {DEFAULTS.n_modes}).",
    )(f)
    f = click.option(
        "--alpha-scale",
        type=click.Choice(["absolute", "compression"]),
        default=None,
        help="How --alphas are read: wall hardness in 1/R at every speed (absolute), or "
        "products alpha * delta_max(v) with delta_max = v sqrt(ln(4/v)) (compression). "
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
@click.option("--nu", type=float, required=True, help="Two-dimensional Poisson number.")
@click.option("--v", "v", type=float, required=True, help=f"Speed v: {_V_HELP}.")
@click.option(
    "--alpha",
    type=float,
    default=None,
    help="Only extrapolate N -> infinity at this wall hardness (1/R); default: both limits.",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON with the grid and fits.")
@click.option(
    "--method",
    type=click.Choice(["modal", "fem"]),
    default="modal",
    show_default=True,
    help="modal: N modes, N -> infinity; fem: finite elements on contact-graded meshes, h -> 0.",
)
@_executor_options
def epsilon(
    nu, v, alpha, as_json, method, alphas, alpha_scale, modes, workers, scheduler, store, progress
):
    """Coefficient of restitution at one speed v, extrapolated to a hard wall and N -> infinity.

    v is the disk's speed towards the wall in units of c = sqrt(E/rho). The collisions of the
    grid are computed (or read from the store) first.
    """
    from restitution.law import epsilon_at

    nu = _check_nu(nu)
    if method == "fem":
        from restitution.fem.limits import fem_epsilon_command

        modal_only = {"--modes": modes, "--workers": workers, "--scheduler": scheduler}
        modal_only["--store"] = store
        return fem_epsilon_command(nu, v, alpha, alphas, alpha_scale, as_json, modal_only, progress)
    settings = _settings(velocities=[v], alphas=alphas, modes=modes, alpha_scale=alpha_scale)
    result = epsilon_at(
        nu,
        v,
        alpha=alpha,
        settings=settings,
        store=store,
        workers=workers,
        scheduler=scheduler,
        progress=progress,
    )
    if as_json:
        click.echo(json.dumps(result.to_dict(), indent=1))
        return
    limits = "N -> inf" if alpha is not None else "alpha -> inf and N -> inf"
    where = f" at alpha = {alpha:g}" if alpha is not None else ""
    click.echo(
        f"epsilon = {result.epsilon:.6f} +- {result.epsilon_err:.6f}   "
        f"(nu = {nu:g}, v = {v:g} c towards the wall; {limits}{where})"
    )
    click.echo(
        f"energy loss 1 - epsilon^2 = {result.energy_loss:.6f} +- {result.energy_loss_err:.6f}"
    )
    grid_alphas = [alpha] if alpha is not None else list(settings.alphas_at(v))
    click.echo(
        f"grid: alpha = {', '.join(f'{a:g}' for a in grid_alphas)}; "
        f"N = {', '.join(str(n) for n in settings.n_modes)} "
        f"({settings.select} modes, {settings.integrator} integrator)"
    )
    if not result.asymptotic_ok:
        click.echo(f"warning: not asymptotic: {result.message}", err=True)


@click.command(cls=_CurveCommand)
@click.option(
    "--nu",
    "nus",
    type=float,
    multiple=True,
    help="Two-dimensional Poisson number(s) (default 0.33 0.9).",
)
@click.option(
    "--v",
    "velocities",
    type=float,
    multiple=True,
    help=f"Speed(s) v: {_V_HELP}. Default: the paper's 0.005, 0.01, 0.02, 0.04, ..., 0.30.",
)
@click.option(
    "--out",
    type=click.Path(file_okay=False, path_type=Path),
    default=Path("restitution-curve"),
    show_default=True,
    help="Directory for figures and exports.",
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["png", "pdf", "svg"]),
    default="png",
    show_default=True,
    help="Figure format.",
)
@_executor_options
def curve(
    nus, velocities, out, fmt, alphas, alpha_scale, modes, workers, scheduler, store, progress
):
    """epsilon(v) for one or more Poisson numbers: Fig. 1, Figs. 7 and 8, and exports.

    v is the disk's speed towards the wall in units of c = sqrt(E/rho). Writes
    fig01_epsilon, fig07_alpha_nu*, fig08_modes_nu*, and law_nu*.json / .csv / .txt (the
    table: v, epsilon, epsilon_err for event-driven and DEM codes) into --out.
    """
    from restitution.figures import fig01_epsilon, fig07_alpha, fig08_modes
    from restitution.law import EpsilonLaw, compute_curves, law_filename

    nus = tuple(_check_nu(nu) for nu in (nus or (0.33, 0.9)))
    settings = _settings(velocities=velocities, alphas=alphas, modes=modes, alpha_scale=alpha_scale)
    out.mkdir(parents=True, exist_ok=True)
    curves = compute_curves(
        nus, settings, store=store, workers=workers, scheduler=scheduler, progress=progress
    )
    written = [
        fig01_epsilon.plot(fig01_epsilon.compute(nus, curves=curves), out / f"fig01_epsilon.{fmt}")
    ]
    for nu in nus:
        c = curves[nu]
        written.append(
            fig07_alpha.plot(fig07_alpha.compute(nu, curve=c), out / f"fig07_alpha_nu{nu:g}.{fmt}")
        )
        written.append(
            fig08_modes.plot(fig08_modes.compute(nu, curve=c), out / f"fig08_modes_nu{nu:g}.{fmt}")
        )
        click.echo(f"nu = {nu:g}:   v/c    epsilon     error   asymptotic")
        for v, lim in zip(c.velocities, c.limits, strict=True):
            eps = "nan" if not math.isfinite(lim.epsilon) else f"{lim.epsilon:.5f}"
            click.echo(
                f"          {v:5.3f}  {eps:>8}  {lim.epsilon_err:8.5f}   "
                f"{'yes' if lim.asymptotic_ok else 'NO: ' + lim.message[:70]}"
            )
        try:
            law = EpsilonLaw.from_curve(c)
        except Exception as exc:  # noqa: BLE001 - report and go on with the other nu
            click.echo(f"warning: no law for nu = {nu:g}: {exc}", err=True)
            continue
        stem = Path(law_filename(nu)).stem
        written += [
            law.to_json(out / f"{stem}.json"),
            law.to_csv(out / f"{stem}.csv"),
            law.to_table(out / f"{stem}.txt"),
        ]
    click.echo("wrote " + ", ".join(str(p) for p in written))
