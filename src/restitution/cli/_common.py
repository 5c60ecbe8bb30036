"""Options and output helpers shared by the commands."""

from __future__ import annotations

import json
import math
from pathlib import Path

import click

from restitution.errors import InputError
from restitution.material import Material

PLANE_HELP = (
    "Interpret --nu as the three-dimensional Poisson number of a thin plate (stress) or of a "
    "long cylinder (strain, eq. 2). Without it, --nu is the two-dimensional Poisson number of "
    "eq. (6), as in the paper (e.g. 0.9 is only reachable that way or by plane strain)."
)


nu_option = click.option(
    "--nu", type=float, default=0.33, show_default=True, help="Poisson number."
)
plane_option = click.option(
    "--plane", type=click.Choice(["stress", "strain"]), default=None, help=PLANE_HELP
)


def material_from(nu: float, plane: str | None) -> Material:
    """Material for a command's ``--nu`` and ``--plane`` options."""
    if plane is None:
        return Material(nu=nu)
    return Material.from_3d(E=1.0, nu=nu, plane=plane).reduced()  # the modal path is reduced


def positive_finite(name: str, value: float) -> float:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be a positive number, got {value}")
    return value


def write_text(text: str, output: Path | None) -> None:
    """Print ``text`` or write it to ``output``."""
    if output is None:
        click.echo(text, nl=not text.endswith("\n"))
    else:
        output.write_text(text if text.endswith("\n") else text + "\n")
        click.echo(f"wrote {output}", err=True)


def dumps(obj) -> str:
    return json.dumps(obj, indent=2, allow_nan=True)
