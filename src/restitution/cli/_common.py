"""Options and output helpers shared by the commands.

Every JSON document a command prints carries the same envelope keys (:func:`envelope`):
``version``, ``command``, ``units``, ``inputs``, ``status`` and ``advice``.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import click

from restitution import atomic, budget
from restitution._version import __version__
from restitution.atomic import check_output_dir, check_output_file, writing  # noqa: F401 (re-exported)
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, geometries, kinds
from restitution.bodies.material import Material
from restitution.errors import InputError, OutputError
from restitution.estimate import ERROR_MEANING
from restitution.jsonable import finite_tree, json_default
from restitution.status import Status

EXIT_FAILED_POINTS = 1
"""Exit status when collisions of a sweep failed (their messages are printed)."""

EXIT_NOT_CONVERGED = 3
"""Exit status with ``--strict`` when a result is not asymptotic or not converged."""

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


class LiveChoice(click.Choice):
    """A choice whose allowed values are read when the command runs, from a callable (the
    kinds, partners or routes registered then: one registered in its own module is
    offered)."""

    def __init__(self, choices_of) -> None:
        self._choices_of = choices_of
        super().__init__(list(choices_of()))

    @property
    def choices(self):
        return tuple(self._choices_of())

    @choices.setter
    def choices(self, value) -> None:
        """Ignored: the callable gives them."""


class PathOption(click.Path):
    """``click.Path`` that refuses an empty path (issue 47: ``--out ''`` wrote into the working
    directory); ``.`` names the working directory."""

    def convert(self, value, param, ctx):
        if isinstance(value, str) and not value.strip():
            self.fail("is empty; give a path (. for the working directory)", param, ctx)
        return super().convert(value, param, ctx)


def _geometry_help(plane: bool = True) -> str:
    """Each kind in one clause: what --nu is for it (``plane``: the command has --plane)."""
    clauses = []
    for kind in kinds().values():
        nu = (
            (
                "--nu is two-dimensional unless --plane is given"
                if plane
                else "--nu is two-dimensional"
            )
            if kind.planar
            else f"--nu is its three-dimensional Poisson number, in ({kind.nu_low:g}, "
            f"{kind.nu_high:g}); units E = rho = R = 1 of the {kind.geometry}"
        )
        clauses.append(f"'{kind.geometry}' ({kind.description.split(';')[0]}; {nu})")
    return "The body: " + ", ".join(clauses) + "."


geometry_option = click.option(
    "--geometry",
    type=click.Choice(geometries()),
    default=DEFAULT_GEOMETRY,
    show_default=True,
    help=_geometry_help(),
)
"""``--geometry`` of a command that has ``--plane``."""

geometry_option_no_plane = click.option(
    "--geometry",
    type=click.Choice(geometries()),
    default=DEFAULT_GEOMETRY,
    show_default=True,
    help=_geometry_help(plane=False),
)
"""``--geometry`` of a command without ``--plane`` (a disk's --nu is two-dimensional)."""

_state = {"quiet": False}


def _set_quiet(ctx: click.Context, param: click.Parameter, value: bool) -> None:
    if value:
        _state["quiet"] = True


quiet_option = click.option(
    "-q",
    "--quiet",
    is_flag=True,
    expose_value=False,
    is_eager=True,
    callback=_set_quiet,
    help="Print only results and errors: no notes, warnings or progress on stderr.",
)

strict_option = click.option(
    "--strict",
    is_flag=True,
    help=f"Exit with status {EXIT_NOT_CONVERGED} when the result is not asymptotic or not "
    "converged (the JSON 'status' says so either way).",
)


def force_option(scope: str = ""):
    """``--force``: run beyond the time bound of one run (:data:`restitution.budget.TIME_BOUND_S`),
    never beyond the memory bound; ``scope`` opens the help (``"--method fem: "``)."""
    bound = budget.format_duration(budget.TIME_BOUND_S)
    text = (
        f"run even when the estimated time exceeds the bound of one run ({bound}); the memory "
        "bound is never lifted."
    )
    return click.option(
        "--force", is_flag=True, help=f"{scope}{text}" if scope else text[:1].upper() + text[1:]
    )


def quiet() -> bool:
    """Whether ``--quiet`` was given."""
    return _state["quiet"]


def note(message: str) -> None:
    """A note or warning on stderr, unless ``--quiet``."""
    if not _state["quiet"]:
        click.echo(message, err=True)


def material_from(nu: float, plane: str | None) -> Material:
    """Material for a command's ``--nu`` and ``--plane`` options."""
    if plane is None:
        return Material(nu=nu)
    return Material.from_3d(E=1.0, nu=nu, plane=plane).reduced()  # the modal path is reduced


def body_nu(nu: float, plane: str | None, geometry: str) -> float:
    """The Poisson number the modal path of ``geometry`` works with, from ``--nu``/``--plane``.

    For a disk, :func:`material_from`'s two-dimensional number; a sphere takes ``--nu`` as its
    three-dimensional number and refuses ``--plane`` (it would be accepted and ignored).
    """
    if body_kind(geometry).planar:
        return material_from(nu, plane).nu
    if plane is not None:
        raise InputError(
            f"--plane applies to disks only; the {geometry}'s --nu is already its "
            "three-dimensional Poisson number: leave out --plane"
        )
    return body_kind(geometry).check_nu(nu)


def nu_inputs(nu: float, plane: str | None, geometry: str) -> dict:
    """The ``inputs`` entries of ``--nu``/``--plane`` for a command's JSON: ``nu`` and
    ``plane`` as the user gave them, so that the inputs fed back give the same answer (a
    converted number recorded as ``nu`` beside ``plane`` would be converted twice), and, for a
    disk, ``nu_2d``: the two-dimensional Poisson number the computation used."""
    d = {"nu": nu, "plane": plane}
    if body_kind(geometry).planar:
        d["nu_2d"] = body_nu(nu, plane, geometry)
    return d


PARTNER_OPTIONS = {
    "radius_ratio": "--radius-ratio",
    "partner_nu": "--partner-nu",
    "modulus_ratio": "--modulus-ratio",
    "density_ratio": "--density-ratio",
}
"""The options that describe a second body (parameter name -> flag)."""


def partner_options(f=None, *, plane: bool = True):
    """``--radius-ratio``, ``--partner-nu``, ``--modulus-ratio``, ``--density-ratio``: a second
    body instead of the wall (read with :func:`partner_from`). ``plane``: the command has
    ``--plane`` (which reads ``--partner-nu`` too). Used bare (``@partner_options``) or called
    (``@partner_options(plane=False)``)."""
    if f is None:
        return lambda func: partner_options(func, plane=plane)
    read = "read like --nu (with --plane)" if plane else "read like --nu"
    for option in reversed(
        (
            click.option(
                "--radius-ratio",
                type=float,
                default=None,
                help="Meet a second body of radius R2 = this * R1 instead of the wall (two "
                "disks; two spheres need 1). --v is then the relative normal speed of the two, "
                "in c of the first body; --modes counts both bodies' modes below one frequency "
                "(docs/two-disks.md).",
            ),
            click.option(
                "--partner-nu",
                type=float,
                default=None,
                help=f"Poisson number of the second body, {read} [default: --nu].",
            ),
            click.option(
                "--modulus-ratio",
                type=float,
                default=None,
                help="Young modulus of the second body / the first's (E2/E1) [default: 1].",
            ),
            click.option(
                "--density-ratio",
                type=float,
                default=None,
                help="Density of the second body / the first's (rho2/rho1) [default: 1].",
            ),
        )
    ):
        f = option(f)
    return f


def partner_from(ctx: click.Context, nu: float, plane: str | None, geometry: str):
    """The :class:`~restitution.bodies.pair.partner.Partner` of the options of
    :func:`partner_options` (``None`` when none was given: the wall). ``--partner-nu`` is read
    like ``--nu`` (:func:`body_nu`); equal to ``--nu`` it is the same material's."""
    from restitution.bodies.pair.partner import Partner

    p = ctx.params
    if not any(given(ctx, name) for name in PARTNER_OPTIONS):
        return None
    ratios = {}
    for name in ("radius_ratio", "modulus_ratio", "density_ratio"):
        value = 1.0 if p[name] is None else p[name]
        ratios[name] = positive_finite(PARTNER_OPTIONS[name], value)
    second = None
    if p["partner_nu"] is not None:
        second = body_nu(p["partner_nu"], plane, geometry)
        if second == body_nu(nu, plane, geometry):
            second = None
    return Partner(nu=second, **ratios)


def pair_units(geometry: str) -> dict:
    """The units of a command's numbers for two bodies of ``geometry``: the first body's
    reduced units, ``v`` the relative speed of the centres, energies fractions of the kinetic
    energy in the centre-of-mass frame (the envelope's ``units`` of a pair)."""
    return {
        **body_kind(geometry).units,
        "system": f"E1 = rho1 = R1 = 1: the first {geometry}'s constants",
        "speed": "c1 = sqrt(E1/rho1) (v: the relative normal speed of the two centres)",
        "energy": "fraction of the kinetic energy in the centre-of-mass frame (mu/2) v^2, "
        "mu the reduced mass",
    }


def positive_finite(name: str, value: float) -> float:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be a positive number, got {value}")
    return value


def given(ctx: click.Context, name: str) -> bool:
    """Whether the option ``name`` (parameter name) was given on the command line."""
    source = ctx.get_parameter_source(name)
    return source is not None and source.name not in ("DEFAULT", "DEFAULT_MAP")


def refuse_ignored(ctx: click.Context, names: dict[str, str], reason: str) -> None:
    """Refuse options that would be accepted and then ignored (``names``: param -> flag)."""
    bad = [flag for name, flag in names.items() if given(ctx, name)]
    if bad:
        raise InputError(
            f"{', '.join(bad)} {'has' if len(bad) == 1 else 'have'} no effect {reason}"
        )


def check_figure_file(path: Path, option: str) -> None:
    """Refuse a figure name whose suffix Matplotlib cannot write, then check the path."""
    from matplotlib.backend_bases import FigureCanvasBase

    formats = FigureCanvasBase.get_supported_filetypes()
    suffix = path.suffix.lower().lstrip(".")
    if suffix not in formats:
        raise OutputError(
            f"{option} {path}: unknown figure format {path.suffix or '(none)'!r}; use one of "
            f"{', '.join('.' + f for f in sorted(formats))}"
        )
    check_output_file(path, option)


def write_text(text: str, output: Path | None) -> None:
    """Print ``text`` or write it to ``output``."""
    if output is None:
        click.echo(text, nl=not text.endswith("\n"))
    else:
        with writing(output, "--output"):
            with atomic.replacing(output) as tmp, open(tmp, "w") as fh:
                fh.write(text if text.endswith("\n") else text + "\n")
        note(f"wrote {output}")


def envelope(
    command: str,
    inputs: dict,
    payload: dict | None = None,
    *,
    status: str = Status.OK,
    advice: str | None = None,
    units: dict | None = None,
) -> dict:
    """The keys every JSON output starts with, then ``payload``.

    ``version`` (package version), ``command``, ``units`` (given, or those of the body named by
    ``inputs["geometry"]``, the disk's :data:`restitution.dynamics.results.UNITS` if none:
    :attr:`restitution.bodies.kinds.BodyKind.units`), ``inputs`` (every option that determines the
    result), ``status`` (``"ok"`` or what is wrong, :class:`restitution.status.Status`) and
    ``advice`` (what to do when the status is not ``"ok"``). ``error_meaning`` says what every
    error of an epsilon (``epsilon_err``) covers (:data:`restitution.estimate.ERROR_MEANING`).
    """
    head = {
        "version": __version__,
        "command": command,
        "units": dict(units or body_kind(inputs.get("geometry", DEFAULT_GEOMETRY)).units),
        "error_meaning": ERROR_MEANING,
        "inputs": inputs,
        "status": status,
        "advice": advice,
    }
    return {**head, **{k: v for k, v in (payload or {}).items() if k not in head}}


def dumps(obj) -> str:
    """Strict JSON (``NaN`` and infinities become ``null``), numpy values included."""
    plain = json.loads(json.dumps(obj, default=json_default, allow_nan=True))
    return json.dumps(finite_tree(plain), indent=2, allow_nan=False)


LINEAR_SPEED = 0.3
"""Fastest impact on a wall (``c``) within the model's range: beyond it a collision's status is
``large-deformation`` (linear elasticity stretched; the laws stop there too)."""


def stretched(status, advice, v: float, fastest: float, result):
    """``(status, advice)`` of a collision, ``large-deformation`` when ``v`` exceeds
    ``fastest`` and the collision is otherwise ``ok`` (a worse status is kept)."""
    if v <= fastest or status != Status.OK:
        return status, advice
    compression = getattr(result, "max_compression", None)
    shown = "" if compression is None else f" (largest compression {compression:.2g} R)"
    return Status.LARGE_DEFORMATION, (
        f"v = {v:g} c is beyond {fastest:g} c, where the model's linear elasticity is "
        f"stretched{shown}: the number is the linear model's, not a real body's; use v <= "
        f"{fastest:g}"
    )
