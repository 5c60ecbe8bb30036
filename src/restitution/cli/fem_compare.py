"""``restitution compare-fem``: finite elements against the modal solver for one collision."""

from __future__ import annotations

import math
import sys

import click

from restitution.bodies.cache import check_mode_request
from restitution.cli._common import (
    EXIT_NOT_CONVERGED,
    force_option,
    material_from,
    note,
    nu_option,
    plane_option,
    quiet_option,
    strict_option,
)
from restitution.cli.report import Report, emit, format_options, output_format, rich_text
from restitution.errors import InputError
from restitution.status import Status


def _int_list(text: str, name: str) -> list[int]:
    try:
        values = [int(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise InputError(f"{name} must be comma-separated integers, got {text!r}") from None
    if not values:
        raise InputError(f"{name} must list at least one integer")
    return values


def _text(comparison, nu, v, alpha) -> str:
    """Both methods' runs and limits for people (rich tables)."""
    return rich_text(lambda console: _print(console, comparison, nu, v, alpha))


_COLUMNS = ("method", "refine", "dofs", "n_modes", "epsilon", "epsilon_err", "energy_loss",
            "energy_drift", "n_steps", "dt", "wall_time_s")  # fmt: skip
"""The columns of ``compare-fem --format csv``."""


def _rows(d: dict) -> list[dict]:
    """One row per run (each FEM level, each modal N), then the two limits compared: the FEM's
    finest mesh and the modal N -> infinity, with their errors."""

    def row(values: dict) -> dict:
        return {k: values.get(k) for k in _COLUMNS}

    finest = d["fem"][-1]
    return [
        *(row({**run, "method": "fem", "n_modes": None}) for run in d["fem"]),
        *(row({**run, "method": "modal"}) for run in d["modal"]),
        row({"method": "fem finest", "refine": finest["refine"], "dofs": finest["dofs"],
             "epsilon": d["fem_epsilon"], "epsilon_err": d["fem_error"]}),
        row({"method": "modal N -> inf", "epsilon": d["modal_epsilon"],
             "epsilon_err": d["modal_error"]}),
    ]  # fmt: skip


def _print(console, comparison, nu, v, alpha) -> None:
    from rich.table import Table

    fem = Table(title=f"FEM, nu = {nu}, v = {v} c, alpha = {alpha}")
    for col in ("refine", "dofs", "epsilon", "change", "drift", "steps", "time/s"):
        fem.add_column(col, justify="right")
    prev = None
    for k, n, r in zip(comparison.fem_levels, comparison.fem_dofs, comparison.fem, strict=True):
        diff = "" if prev is None else f"{r.epsilon - prev:+.1e}"
        fem.add_row(
            str(k),
            str(n),
            f"{r.epsilon:.7f}",
            diff,
            f"{r.energy_drift:.0e}",
            str(r.n_steps),
            f"{r.wall_time_s:.1f}",
        )
        prev = r.epsilon
    console.print(fem)
    modal = Table(title="modal, N lowest modes")
    for col in ("N", "epsilon", "1 - eps^2", "drift", "steps", "time/s"):
        modal.add_column(col, justify="right")
    for r in comparison.modal:
        modal.add_row(
            str(r.n_modes),
            f"{r.epsilon:.7f}",
            f"{r.energy_loss:.6f}",
            f"{r.energy_drift:.0e}",
            str(r.n_steps),
            f"{r.wall_time_s:.1f}",
        )
    console.print(modal)
    lim = comparison.modal_limit
    flag = ""
    if lim is not None and not lim.asymptotic_ok:
        flag = f"  [yellow]not asymptotic: {lim.message}[/yellow]"
    console.print(
        f"FEM, finest mesh:  epsilon = {comparison.fem_epsilon:.7f} "
        f"+- {comparison.fem_error:.1e} (last change)\n"
        f"modal, N -> inf:   epsilon = {comparison.modal_epsilon:.7f} "
        f"+- {comparison.modal_error:.1e} (1 - eps^2 linear in 1/sqrt(N)){flag}"
    )
    sigma = comparison.combined_error
    ratio = abs(comparison.difference) / sigma if sigma > 0 and math.isfinite(sigma) else math.nan
    console.print(f"FEM - modal:       {comparison.difference:+.2e} = {ratio:.2f} combined errors")


@click.command("compare-fem")
@nu_option
@plane_option
@click.option(
    "--v",
    "v",
    type=float,
    default=0.1,
    show_default=True,
    help="Speed of the disk towards the wall in units of c, in (0, 1).",
)
@click.option(
    "--alpha",
    type=float,
    default=500.0,
    show_default=True,
    help="Wall hardness alpha of V = exp(alpha x)/alpha, in 1/R (same for both).",
)
@click.option(
    "--refine",
    type=int,
    default=2,
    show_default=True,
    help="Finest FEM mesh level; the FEM runs at every level from --refine-min up.",
)
@click.option(
    "--refine-min", type=int, default=0, show_default=True, help="Coarsest FEM mesh level."
)
@click.option(
    "--modes",
    "modes",
    default="200,400,800,1600",
    show_default=True,
    help="Comma-separated numbers of lowest modes for the modal runs.",
)
@format_options
@force_option()
@strict_option
@quiet_option
def compare_fem(nu, plane, v, alpha, refine, refine_min, modes, fmt, as_json, force, strict):
    """Compare the FEM impact solver with the modal solver extrapolated to N -> infinity.

    The FEM runs at mesh levels refine-min..refine (error: last Cauchy difference); the modal
    solver runs with the N lowest modes and 1 - eps^2 is extrapolated linearly in 1/sqrt(N)
    at the same alpha. Units: E = rho = R = 1, v in c, alpha in 1/R. The finest level costs
    about 8 times the one below it (refine 2: tens of seconds; refine 3: estimated 8 min); FEM
    levels that would not fit in memory, or take more than the bound of one run (unless
    --force), are refused before any mesh is made.
    """
    from restitution.fem.compare import compare_fem_modal

    fmt = output_format(fmt, as_json)
    material = material_from(nu, plane)
    if refine_min < 0 or refine < refine_min:
        raise InputError(f"need 0 <= --refine-min <= --refine, got {refine_min} and {refine}")
    counts = _int_list(modes, "--modes")
    if min(counts) < 1:
        raise InputError(f"--modes must be positive, got {modes}")
    if len(set(counts)) != len(counts):
        raise InputError(f"--modes has repeated values ({modes}); give distinct counts")
    check_mode_request(material.nu, max(counts))
    from restitution.fem.cost import check_compare

    check_compare(material, v, alpha, refine, refine_min, force=force, name="--refine",
                  override="--force")  # fmt: skip
    comparison = compare_fem_modal(
        material, v, alpha, levels=range(refine_min, refine + 1), counts=counts
    )
    lim = comparison.modal_limit
    status, advice = Status.OK, None
    if lim is None or not lim.asymptotic_ok:
        status = Status.NOT_ASYMPTOTIC
        advice = (lim.message if lim is not None else "no modal extrapolation") + (
            "; use more and larger --modes"
        )
    inputs = {
        "nu": material.nu,
        "plane": plane,
        "v": v,
        "alpha": alpha,
        "refine": refine,
        "refine_min": refine_min,
        "modes": counts,
    }
    d = comparison.to_dict()
    emit(Report("compare-fem", inputs, d, status, advice,
                text=lambda: _text(comparison, material.nu, v, alpha),
                rows=lambda: _rows(d)), fmt)  # fmt: skip
    if status != Status.OK:
        if fmt != "json":  # the JSON says it in "status"
            note(f"warning: {status}: {advice}")
        if strict:
            sys.exit(EXIT_NOT_CONVERGED)
