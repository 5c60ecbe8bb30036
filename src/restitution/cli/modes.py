"""``restitution modes``: the eigenmode table, Fig. 2 and Fig. 3."""

from __future__ import annotations

import io
from pathlib import Path

import click

from restitution.bodies.cache import check_mode_request, get_modes
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.cli._common import (
    PathOption,
    body_nu,
    check_figure_file,
    check_output_file,
    geometry_option,
    note,
    nu_inputs,
    nu_option,
    plane_option,
    quiet_option,
    refuse_ignored,
    writing,
)
from restitution.cli.report import Report, emit, format_options, output_format
from restitution.errors import InputError


def _table(records: list[dict], geometry: str) -> str:
    from rich.console import Console
    from rich.table import Table

    table = Table(title=body_kind(geometry).modes_title)
    columns = list(records[0]) if records else []
    for col in columns:
        table.add_column(col, justify="right")
    for r in records:
        table.add_row(*(str(r[c]) if isinstance(r[c], int) else f"{r[c]:.8g}" for c in columns))
    buf = io.StringIO()
    Console(file=buf, width=140, force_terminal=False).print(table)
    return buf.getvalue()


@click.command()
@nu_option
@plane_option
@geometry_option
@click.option("--count", type=int, default=None, help="Number of lowest modes [default: 1600].")
@click.option("--omega-max", type=float, default=None, help="All modes below this omega (c/R).")
@format_options(also=("table",), also_help=" CSV: one row per mode. table: the old name of text.")
@click.option(
    "--output",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Write the listing to FILE instead of standard output.",
)
@click.option(
    "--plot-spectrum",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Draw Fig. 3 (omega against n, radial and tangential type apart) to FILE.",
)
@click.option(
    "--plot-shapes",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Draw Fig. 2 (deformed polar grid of low modes) to FILE.",
)
@quiet_option
def modes(nu, plane, geometry, count, omega_max, fmt, as_json, output, plot_spectrum,
          plot_shapes):  # fmt: skip
    """Eigenmodes of the free elastic body that couple to a head-on impact, by frequency.

    Units: E = rho = R = 1 of the body's own constants, omega in c/R. Disk: the symmetric
    family; for n = 0 only the breathing modes (eq. 20); C = U_r(1) > 0 and S = U_phi(1) are
    the edge amplitudes. Sphere: Lamb's axisymmetric spheroidal modes of order l (u_r = U(r)
    P_l, u_theta = V(r) dP_l/dtheta), C = U(1) and S = V(1). The rigid translation is excluded.
    The JSON format is one object: version, units, inputs, status and the list "modes"; the
    CSV one row per mode.
    """
    fmt = output_format(fmt, as_json, aliases={"table": "text"})
    if count is not None and omega_max is not None:
        raise InputError("give either --count or --omega-max, not both")
    if count is None and omega_max is None:
        count = 1600
    given, nu = nu, body_nu(nu, plane, geometry)
    check_mode_request(nu, count, omega_max, geometry)
    if geometry != DEFAULT_GEOMETRY:
        refuse_ignored(
            click.get_current_context(),
            {"plot_spectrum": "--plot-spectrum", "plot_shapes": "--plot-shapes"},
            "they draw the disk's Figs. 2 and 3",
        )
    if output is not None:
        check_output_file(output, "--output")
    for path, option in ((plot_spectrum, "--plot-spectrum"), (plot_shapes, "--plot-shapes")):
        if path is not None:
            check_figure_file(path, option)
    ms = get_modes(nu, count=count, omega_max=omega_max, geometry=geometry)
    records = ms.as_records()
    inputs = {
        "geometry": geometry,
        **nu_inputs(given, plane, geometry),
        "count": count,
        "omega_max": omega_max,
    }
    emit(Report("modes", inputs, {"modes": records}, text=lambda: _table(records, geometry),
                rows=lambda: records), fmt, output)  # fmt: skip
    if plot_spectrum is not None:
        from restitution.reproduction.figures import fig03_spectrum

        top = float(omega_max) if omega_max is not None else float(min(ms.omega.max(), 20.0))
        data = fig03_spectrum.compute(nu, omega_max=top)
        with writing(plot_spectrum, "--plot-spectrum"):
            fig03_spectrum.plot(data, plot_spectrum)
        note(f"wrote {plot_spectrum}")
    if plot_shapes is not None:
        from restitution.reproduction.figures import fig02_shapes

        data = fig02_shapes.compute(nu)
        with writing(plot_shapes, "--plot-shapes"):
            fig02_shapes.plot(data, plot_shapes)
        note(f"wrote {plot_shapes}")
