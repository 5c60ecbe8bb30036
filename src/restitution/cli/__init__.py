"""Command line interface: a thin layer over the library.

Every command lives in its own module of this package; this file only assembles the group and
turns the package's own errors into one line on stderr with exit status 2.

Exit status: 0 success; 1 some collisions of a sweep failed (``epsilon``, ``curve``) or some
requested speeds got no value (``law``); 2 an
error (one line on stderr); 3 with ``--strict``, a result that is not asymptotic or not
converged; 130 interrupted.
"""

from __future__ import annotations

import sys

import click

from restitution._version import __version__
from restitution.cli._common import quiet_option
from restitution.errors import RestitutionError


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="restitution")
@quiet_option
def cli() -> None:
    """Coefficient of restitution of elastic grains from their vibrational modes.

    Bodies: a disk (2D: a long cylinder in plane strain or a thin disk in plane stress) or a
    sphere (3D), e.g. `collide --geometry sphere`. Partners: a rigid wall, or a second grain:
    a disk of another size and/or material (`collide --radius-ratio R`), an identical sphere.
    Material damping: a Kelvin-Voigt relaxation time (`collide --relaxation-time`).
    `law` answers for a real material in SI units (m/s), damping included, and exports tables,
    closed forms and constants for DEM codes (LAMMPS, LIGGGHTS, MercuryDPM, YADE); every point
    says its status.

    Units of the other commands: E = rho = R = 1 of the body's own constants, so speeds are in
    c = sqrt(E/rho) and times in R/c. A disk: its two-dimensional (plane-stress) E and nu, mass
    pi (`modes --plane strain|stress` reads the 3D nu of a cylinder|thin disk). A sphere: its
    three-dimensional E and nu, mass 4 pi/3. v is the body's speed towards the wall (two
    identical bodies approaching at +-v collide the same way, at relative speed 2v); with a
    second body v is the relative speed, in c of the first.

    Exit status: 0 success; 1 some collisions of a sweep failed, or some speeds of `law` got
    no value; 2 an error; 3 a result that is
    not asymptotic or not converged, with `epsilon --strict` (likewise curve, collide,
    compare-fem).
    """


def _register() -> None:
    from restitution.cli import bounce as _bounce
    from restitution.cli import collide as _collide
    from restitution.cli import epsilon as _epsilon
    from restitution.cli import fem_compare as _fem_compare
    from restitution.cli import lammps_plugin as _lammps_plugin
    from restitution.cli import law as _law
    from restitution.cli import modes as _modes
    from restitution.cli import oblique_fit as _oblique_fit
    from restitution.cli import paper as _paper
    from restitution.cli import quasistatic as _quasistatic

    cli.add_command(_modes.modes)
    cli.add_command(_collide.collide)
    cli.add_command(_bounce.bounce)
    cli.add_command(_quasistatic.quasistatic)
    cli.add_command(_epsilon.epsilon)
    cli.add_command(_epsilon.curve)
    cli.add_command(_fem_compare.compare_fem)
    cli.add_command(_paper.paper)
    cli.add_command(_law.law)
    cli.add_command(_oblique_fit.oblique_fit)
    cli.add_command(_lammps_plugin.lammps_plugin)


_register()


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """Warnings as one line on stderr (none with ``--quiet``)."""
    from restitution.cli._common import note

    note(f"warning: {message}")


def main(argv: list[str] | None = None) -> None:
    """Console-script entry point."""
    import warnings

    warnings.showwarning = _show_warning
    try:
        cli.main(args=argv, prog_name="restitution", standalone_mode=False)
    except click.exceptions.Abort:
        click.echo("aborted", err=True)
        sys.exit(130)
    except click.UsageError as exc:  # one line, like every other refusal (issue 47)
        where = exc.ctx.command_path if exc.ctx is not None else "restitution"
        click.echo(f"error: {exc.format_message()} (see '{where} --help')", err=True)
        sys.exit(exc.exit_code)
    except click.ClickException as exc:
        exc.show()
        sys.exit(exc.exit_code)
    except RestitutionError as exc:
        from restitution.cli.words import command_of, in_command_words

        words = sys.argv[1:] if argv is None else list(argv)
        click.echo(f"error: {in_command_words(str(exc), command_of(cli, words))}", err=True)
        sys.exit(2)
    except OSError as exc:  # a file the command reads or writes, named by the system
        where = f" ({exc.filename})" if exc.filename else ""
        click.echo(f"error: {exc.strerror or exc}{where}", err=True)
        sys.exit(2)
    except KeyboardInterrupt:
        click.echo("interrupted", err=True)
        sys.exit(130)
