"""``restitution oblique-fit``: a material's tangential coefficient ``beta`` over angles and the
DEM codes' tangential parameters fitted to it.

A thin layer over :func:`restitution.laws.making.oblique_fit.oblique_fit`: the options are its
arguments (the material in SI, as ``law``), the runs are ``law --angle``'s at every angle, the
answer one :class:`~restitution.cli.report.Report` printed as text, JSON or CSV (one row per
speed and fit, ``pandas.read_csv``-ready), and ``--plot`` draws ``beta`` against
``tan(angle)/mu`` with the fitted models (the figure of docs/oblique.md).

Units: SI (Pa, kg/m^3, m/s, degrees; ``k_t`` in Pa).
"""

from __future__ import annotations

from pathlib import Path

import click

from restitution.cli._common import (
    LiveChoice,
    PathOption,
    check_figure_file,
    note,
    quiet,
    quiet_option,
)
from restitution.cli.epsilon import _ListCommand
from restitution.cli.report import Report, emit, format_options, output_format, rich_text
from restitution.dynamics.friction import friction_names
from restitution.laws.units import SHAPES

__all__ = ["oblique_fit"]


class _Lists(_ListCommand):
    list_options = ("--angle", "--speed")


@click.command(name="oblique-fit", cls=_Lists)
@click.option("--E", "E", type=float, required=True, help="Young modulus of the 3D material, Pa.")
@click.option("--nu", type=float, required=True, help="Poisson number of the 3D material.")
@click.option("--rho", type=float, required=True, help="Density of the 3D material, kg/m^3.")
@click.option("--shape", "--geometry", "shape", type=click.Choice(list(SHAPES)),
              required=True, help="As `law --shape`.")  # fmt: skip
@click.option("--friction", type=float, required=True,
              help="Coulomb's friction coefficient mu between grain and wall.")  # fmt: skip
@click.option("--angle", "angles", type=float, multiple=True,
              help="Angles of incidence from the wall's normal, degrees (several after one flag;"
              " two or more above 0). Default: 0 10 20 ... 80 (0: the head-on baseline of "
              "epsilon_normal).")  # fmt: skip
@click.option(
    "--speed",
    "speeds",
    type=float,
    multiple=True,
    help="Normal impact speeds, m/s (several after one flag). Default: 1.",
)
@click.option("--modes", type=int, default=None,
              help="Modes of each run (the error is the change from half as many). Default: "
              "law --angle's (160 for a cylinder or thin disk, 40 for a sphere).")  # fmt: skip
@click.option("--friction-model", type=LiveChoice(friction_names), default=None,
              help="As `law --friction-model` (default: law's for the shape: stick-slip for a "
              "cylinder or thin disk, residual for a sphere).")  # fmt: skip
@click.option(
    "--kappa",
    type=float,
    default=None,
    help="With --friction-model microslip: as `law --kappa` (default 64).",
)
@click.option("--plot", type=PathOption(dir_okay=False, path_type=Path), default=None,
              help="Also draw beta against tan(angle)/mu with the fitted models to this file "
              "(the first speed's fits, or the second's where there are several).")  # fmt: skip
@click.option(
    "--output",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Write the answer (in --format) to this file instead of stdout.",
)
@format_options
@click.option(
    "--force",
    is_flag=True,
    help="Run even when the estimated time exceeds the bound of one run (1 h).",
)
@quiet_option
def oblique_fit(E, nu, rho, shape, friction, angles, speeds, modes, friction_model, kappa, plot,
                output, fmt, as_json, force) -> None:  # fmt: skip
    """Tangential restitution of a real material over angles, and the DEM parameters that
    reproduce it: Walton's e, mu_W, beta_0 and LAMMPS's mindlin k_t (Pa) per speed.

    Every angle is `law --angle`'s oblique impact on the rigid wall (the modal route, about a
    minute per angle and speed for a cylinder, docs/oblique.md); the fits are least squares on
    beta with their rms and largest misfit. Example (a steel ball, mu = 0.3, 1 m/s):

    restitution oblique-fit --E 210e9 --nu 0.3 --rho 7850 --shape sphere --friction 0.3
    """
    from restitution.laws.making.oblique_fit import DEFAULT_ANGLES, DEFAULT_SPEEDS
    from restitution.laws.making.oblique_fit import oblique_fit as run

    fmt = output_format(fmt, as_json)
    if plot is not None:
        check_figure_file(plot, "--plot")
    inputs = {"E": E, "nu": nu, "rho": rho, "shape": shape, "friction": friction,
              "angles_deg": list(angles or DEFAULT_ANGLES),
              "speeds_m_s": list(speeds or DEFAULT_SPEEDS), "modes": modes,
              "friction_model": friction_model, "kappa": kappa}  # fmt: skip
    say = (lambda _text: None) if quiet() else note
    fit = run(E, nu, rho, shape, friction, angles=angles or DEFAULT_ANGLES,
              speeds=speeds or DEFAULT_SPEEDS, modes=modes, friction_model=friction_model,
              kappa=kappa, force=force, say=say)  # fmt: skip
    if plot is not None:
        from restitution.reproduction.figures.oblique_beta import plot_beta

        plot_beta(fit.fits, plot)
        note(f"wrote {plot}")
    payload = fit.to_dict()
    emit(Report("oblique-fit", inputs, payload, status=str(fit.status), advice=fit.advice,
                units=payload.pop("units"), text=lambda: rich_text(lambda c: _draw(c, fit)),
                rows=fit.rows), fmt, output)  # fmt: skip


def _draw(console, fit) -> None:
    """The points by angle and speed, then the fits of each speed and the LAMMPS words."""
    from rich.table import Table

    points = Table(title="modal oblique impacts (+-: the change from half the modes)")
    for head in ("angle (deg)", "speed (m/s)", "epsilon_normal", "+-", "beta", "+-"):
        points.add_column(head, justify="right")
    for r in fit.table["rows"]:
        beta = ("-", "") if r["beta"] is None else (f"{r['beta']:.4f}", f"{r['beta_error']:.2g}")
        points.add_row(f"{r['angle_deg']:g}", f"{r['speed_m_s']:g}",
                       f"{r['epsilon_normal']:.6f}", f"{r['epsilon_normal_error']:.2g}",
                       *beta)  # fmt: skip
    console.print(points)
    f = fit.fits
    for speed, per in f.summary().items():
        w, m, h, ms = (per[k] for k in ("walton", "mindlin", "linear_history", "microslip"))
        console.print(
            f"fits at {speed} m/s, mu = {f.friction:g}, K = {f.inertia_factor:g} (rms and "
            f"largest |beta_model - beta| over {w['points']} angles):\n"
            f"  Walton: e {w['e']:.5f}, mu_W {w['mu_w']:.4f}, beta_0 {w['beta_0']:.4f} "
            f"({w['rms']:.3g}, {w['largest']:.3g})\n"
            f"  LAMMPS mindlin: chi {m['chi']:.4f}, k_t {m['wall_k_t_pa']:.4g} Pa on the wall, "
            f"{m['k_t_pa']:.4g} Pa between grains: {m['ratio_to_null']:.3f} x 8 G* "
            f"({m['rms']:.3g}, {m['largest']:.3g})\n"
            f"  LAMMPS linear_history: chi {h['chi']:.4f} ({h['rms']:.3g}, {h['largest']:.3g})\n"
            f"  Maw-Barber-Fawcett microslip: chi {ms['chi']:.4f} ({ms['rms']:.3g}, "
            f"{ms['largest']:.3g})",
            soft_wrap=True,
        )
        law = next(r for r in fit.table["rows"] if str(r["speed_m_s"]) == speed)
        eps, err = law["epsilon_head_on_law"], law["epsilon_head_on_law_error"]
        if eps is not None:
            console.print(f"  normal coefficient for the DEM code: law's {eps:.6f} +- {err:.2g} "
                          f"({law['head_on_law_status']}; Walton's e above is the runs' own)",
                          soft_wrap=True)  # fmt: skip
        words = fit.lammps_lines(float(speed))
        console.print(f"  LAMMPS lines, in place of the exported 'tangential mindlin ...': the "
                      f"wall fix '{words['wall_fix']}', pair_coeff of two grains "
                      f"'{words['pair_coeff']}'", soft_wrap=True)  # fmt: skip
    console.print(f"status: {fit.status}" + (f" ({fit.advice})" if fit.advice else ""),
                  soft_wrap=True)  # fmt: skip
    others = [f"{r['status']} at {r['angle_deg']:g} deg, {r['speed_m_s']:g} m/s"
              for r in fit.table["rows"] if r["status"] != fit.status]  # fmt: skip
    if others:
        console.print("  other points: " + "; ".join(others), soft_wrap=True)
