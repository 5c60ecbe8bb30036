"""Command ``restitution law``: epsilon of a real material at speeds in m/s, and exports.

Thin layer over :mod:`restitution.laws.si_law` and :mod:`restitution.laws.exports`.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import click

from restitution.bodies.kinds import body_kind
from restitution.cli._common import note, quiet_option
from restitution.cli.epsilon import _ListCommand
from restitution.jsonable import json_default
from restitution.laws.units import BODIES, GEOMETRIES
from restitution.status import Status


class _LawCommand(_ListCommand):
    list_options = ("--speed",)


def _paired_shapes() -> str:
    """The shapes whose laws of two grains of different sizes or materials are computed."""
    names = [shape for shape, body in BODIES.items() if body_kind(body).pair_compression]
    return " or ".join(names)


@click.command(cls=_LawCommand)
@click.option("--E", "E", type=float, required=True, help="Young modulus of the 3D material, Pa.")
@click.option("--nu", type=float, required=True, help="Poisson number of the 3D material.")
@click.option("--rho", type=float, required=True, help="Density of the 3D material, kg/m^3.")
@click.option(
    "--geometry",
    type=click.Choice(list(GEOMETRIES)),
    required=True,
    help="Long cylinder hit along a diameter (the disk in plane strain: nu_2d = nu/(1-nu), "
    "c = sqrt(E/((1-nu^2) rho))), thin disk (plane stress: nu_2d = nu, c = sqrt(E/rho)) or "
    "sphere (the sphere's law for nu itself, c = sqrt(E/rho)).",
)
@click.option(
    "--against",
    type=click.Choice(["wall", "grain"]),
    required=True,
    help="A rigid flat wall hit at speed w (v = w/c), or an identical grain at relative normal "
    "speed w (v = w/(2c)); with --partner-radius-ratio a grain of the same material and another "
    "size (v = w/c, the pair's law).",
)
@click.option(
    "--partner-radius-ratio",
    type=float,
    default=None,
    help="With --against grain: radius of the partner grain over this grain's, R2/R1, same "
    "material (either way round; 1 = identical grains). Served by the law of the pair "
    "(law_pair_r<R>_nu<nu_2d>.json, or --law-file from `restitution curve --nu NU_2D "
    "--radius-ratio R`); w is the relative normal speed. With a constant, the exports give "
    "type pairs 1-1 and 2-2 (identical grains) and 1-2 (the pair). Cylinders and thin disks only.",
)
@click.option(
    "--partner-E",
    "partner_E",
    type=float,
    default=None,
    help="With --against grain: Young modulus of the partner grain's 3D material, Pa [this "
    "grain's]. A partner of another material (--partner-E, --partner-nu, --partner-rho): one "
    "pair is shipped (steel E = 210e9, nu = 0.3, rho = 7850 with glass 63e9, 0.2481, 2500, "
    "1.4 times as large, cylinders); any other is computed with --compute (the estimate is "
    "stated first) or read from --law-file. Cylinders and thin disks only; the partner has "
    "this grain's geometry.",
)
@click.option(
    "--partner-nu",
    type=float,
    default=None,
    help="With --against grain: Poisson number of the partner grain's 3D material [this grain's].",
)
@click.option(
    "--partner-rho",
    type=float,
    default=None,
    help="With --against grain: density of the partner grain's 3D material, kg/m^3 [this grain's].",
)
@click.option(
    "--speed",
    "speeds",
    type=float,
    multiple=True,
    help="Impact speed(s) w in m/s (several after one flag). Default: 0.1 0.5 1 5 10.",
)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@click.option(
    "--law-file",
    type=click.Path(dir_okay=False, exists=True, path_type=Path),
    default=None,
    help="A law JSON from `restitution curve` for this material: the disk's law for its 2D "
    "Poisson number (cylinder, thin disk), the sphere's (`curve --geometry sphere`) for nu; with "
    "--partner-radius-ratio the pair's (`curve --radius-ratio R`).",
)
@click.option(
    "--identical-law-file",
    type=click.Path(dir_okay=False, exists=True, path_type=Path),
    default=None,
    help="With --partner-radius-ratio and --reference-speed or --maxwell-temperature: the law "
    "JSON of two identical grains of this material (`restitution curve --nu NU_2D`), for the "
    "1-1 and 2-2 constants [default: the shipped laws]; with a partner material the 1-1 "
    "constant only.",
)
@click.option(
    "--partner-identical-law-file",
    type=click.Path(dir_okay=False, exists=True, path_type=Path),
    default=None,
    help="With a partner material and --reference-speed or --maxwell-temperature: the law JSON "
    "of two identical grains of the partner's material, for the 2-2 constant [default: the "
    "shipped laws].",
)
@click.option(
    "--export",
    "export_dir",
    type=click.Path(file_okay=False, path_type=Path),
    default=None,
    help="Write the table (.txt, .csv), the closed form (.json, C header .h, Fortran .f90) "
    "and, with --reference-speed or --maxwell-temperature, snippets for LAMMPS, LIGGGHTS, "
    "MercuryDPM and YADE into this directory.",
)
@click.option(
    "--reference-speed",
    type=float,
    default=None,
    help="Constant for one-number codes: epsilon at this speed, m/s.",
)
@click.option(
    "--maxwell-temperature",
    type=float,
    default=None,
    help="Constant for one-number codes: epsilon averaged (dissipation-weighted) over a Maxwell "
    "gas at this granular temperature <v_x^2>, m^2/s^2.",
)
@click.option(
    "--measured-epsilon",
    type=float,
    default=None,
    help="Material damping from one measurement: the coefficient of restitution measured at "
    "--measured-speed (same partner). The relaxation time is inferred from it and epsilon(w) "
    "given with its elastic and viscous parts (docs/damping.md).",
)
@click.option(
    "--measured-speed",
    type=float,
    default=None,
    help="Impact speed of --measured-epsilon, m/s.",
)
@click.option(
    "--relaxation-time",
    type=float,
    default=None,
    help="Material damping given directly: the Kelvin-Voigt relaxation time (viscosities = "
    "tau x moduli), s; needs --radius.",
)
@click.option(
    "--radius",
    type=float,
    default=None,
    help="Radius of the grain, m (with --relaxation-time; for two sizes the smaller grain's). "
    "The elastic law needs no radius; the viscous loss depends on tau c / R.",
)
@click.option(
    "--compute",
    is_flag=True,
    help="Compute the law of this material's exact Poisson number with the production settings "
    "when none is shipped for it (instead of interpolating in nu): minutes to hours, stated "
    "before it starts, with a progress bar; every collision goes to the result store (--store; "
    "an interrupted run resumes) and the law file to the cache, where the next call finds it.",
)
@click.option(
    "--store",
    type=click.Path(dir_okay=False, path_type=Path),
    default=None,
    help="With --compute: the result store [results.sqlite in the user cache].",
)
@click.option(
    "--force",
    is_flag=True,
    help="With --compute: compute even when the estimate exceeds the bound of one run (1 h).",
)
@quiet_option
def law(
    E,
    nu,
    rho,
    geometry,
    against,
    partner_radius_ratio,
    partner_E,
    partner_nu,
    partner_rho,
    speeds,
    as_json,
    law_file,
    identical_law_file,
    partner_identical_law_file,
    export_dir,
    reference_speed,
    maxwell_temperature,
    measured_epsilon,
    measured_speed,
    relaxation_time,
    radius,
    compute,
    store,
    force,
):
    """Coefficient of restitution of a real material at impact speeds in m/s.

    Every speed comes with v/c, epsilon, its error and a status saying where the number comes
    from. A cylinder or thin disk is served by the disk's laws (2D Poisson number), a sphere by
    the sphere's (its own nu); a Poisson number without a law is refused with the command that
    computes it. Example (a glass cylinder against a wall):

    \b
    restitution law --E 63e9 --nu 0.2481 --rho 2500 --geometry cylinder \\
        --against wall --speed 0.5 1 5

    Two grains of one material and different sizes: --against grain --partner-radius-ratio R
    (docs/materials.md). A partner of another material: add --partner-E, --partner-nu and
    --partner-rho. The law of a steel cylinder with a glass one 1.4 times as large is shipped:

    \b
    restitution law --E 210e9 --nu 0.3 --rho 7850 --geometry cylinder \\
        --against grain --partner-radius-ratio 1.4 --partner-E 63e9 \\
        --partner-nu 0.2481 --partner-rho 2500 --speed 0.1 1 10

    Any other pair of materials is computed on demand with --compute (10-30 minutes on two
    cores, estimated before it starts).

    Material damping (a Kelvin-Voigt relaxation time) adds the viscous loss to the loss to
    vibrations, from one measured coefficient of restitution or from the relaxation time:

    \b
    restitution law --E 210e9 --nu 0.3 --rho 7850 --geometry sphere \\
        --against wall --measured-epsilon 0.9 --measured-speed 1 --speed 0.1 1 10
    """
    from restitution.cli._common import envelope
    from restitution.errors import InputError
    from restitution.laws import exports
    from restitution.laws.si_law import SI_UNITS, overall_status, si_law

    if reference_speed is not None and maxwell_temperature is not None:
        raise InputError("give --reference-speed or --maxwell-temperature, not both")
    if export_dir is not None:
        from restitution.cli._common import check_output_dir

        check_output_dir(Path(export_dir), "--export")  # before anything is computed
    ratio = _check_ratio(partner_radius_ratio, against, geometry)
    other = _partner_grain(E, nu, rho, geometry, against, partner_E, partner_nu, partner_rho)
    if other is not None and ratio is None:
        ratio = partner_radius_ratio  # None or 1: two materials of one size
    if other is not None and (measured_epsilon, measured_speed, relaxation_time) != (None,) * 3:
        raise InputError(
            "material damping of grains of two materials is not modelled (each material has "
            "its own relaxation time); leave out the damping options or the partner material"
        )
    if identical_law_file is not None or partner_identical_law_file is not None:
        _check_identical_law_file(
            ratio, other, reference_speed, maxwell_temperature, partner_identical_law_file
        )
    served = law_file
    if compute:
        served = _computed(E, nu, rho, geometry, against, ratio, law_file, store, force, other)
    elif store is not None or force:
        raise InputError("--store and --force belong to --compute; add --compute or leave them out")
    elif other is not None and law_file is None:
        _refuse_uncomputed(E, nu, rho, geometry, against, ratio, other)
    s = si_law(E, nu, rho, geometry, against, path=served, radius_ratio=ratio,
               partner_grain=other)  # fmt: skip
    speeds = list(speeds) or [0.1, 0.5, 1.0, 5.0, 10.0]
    damped = _damped(s, measured_epsilon, measured_speed, relaxation_time, radius)
    if (
        damped is not None
        and s.law.partner is not None
        and ratio_constants(reference_speed, maxwell_temperature)
    ):
        raise InputError(
            "constants per type pair of damping grains are not computed (tau c / R differs for "
            "the two sizes); drop --reference-speed/--maxwell-temperature, or the damping"
        )
    if damped is None:
        result = s.to_dict(speeds)
        status, advice = overall_status(s.points(speeds))
    else:
        result = damped.to_dict(speeds)
        status, advice = overall_status(damped.points(speeds))
        if (reference_speed, maxwell_temperature, export_dir) != (None, None, None):
            # Constants, tables and snippets of the damped law: the sum at every computed speed.
            s = damped.as_si_law()
    constant = pairs = None
    if s.law.partner is not None and (reference_speed, maxwell_temperature) != (None, None):
        # Two sizes: a constant per pair of particle types; the pair's own is 1-2.
        identical = _identical(E, nu, rho, geometry, identical_law_file, "--identical-law-file")
        identical2 = None
        if other is not None:
            identical2 = _identical(other.E, other.nu, other.rho, geometry,
                                    partner_identical_law_file,
                                    "--partner-identical-law-file")  # fmt: skip
        pairs = exports.type_pair_constants(
            s,
            identical,
            speed_m_s=reference_speed,
            temperature_m2_s2=maxwell_temperature,
            identical2=identical2,
        )
        constant = pairs.mixed
    elif reference_speed is not None:
        constant = exports.constant_at(s, reference_speed)
    elif maxwell_temperature is not None:
        constant = exports.maxwell_constant(s, maxwell_temperature)
    if constant is not None:
        result["constant"] = constant.to_dict()
    if pairs is not None:
        result["type_pairs"] = pairs.to_dict()
    if export_dir is not None:
        result["exports"] = [str(p) for p in _export(s, pairs or constant, export_dir)]
    if as_json:
        inputs = {"E": E, "nu": nu, "rho": rho, "geometry": geometry, "against": against,
                  "partner_radius_ratio": partner_radius_ratio,
                  "partner_E": partner_E, "partner_nu": partner_nu, "partner_rho": partner_rho,
                  "speeds_m_s": speeds, "law_file": None if law_file is None else str(law_file),
                  "identical_law_file": (None if identical_law_file is None
                                         else str(identical_law_file)),
                  "partner_identical_law_file": (None if partner_identical_law_file is None
                                                 else str(partner_identical_law_file)),
                  "reference_speed": reference_speed,
                  "maxwell_temperature": maxwell_temperature,
                  "export": None if export_dir is None else str(export_dir),
                  "measured_epsilon": measured_epsilon, "measured_speed_m_s": measured_speed,
                  "relaxation_time_s": relaxation_time, "radius_m": radius,
                  "compute": compute}  # fmt: skip
        d = envelope("law", inputs, result, status=status, advice=advice, units=SI_UNITS)
        click.echo(json.dumps(d, indent=1, default=json_default))
        return
    g = s.grain
    click.echo(g.describe())
    if other is not None:
        click.echo(f"partner: {other.describe()}")
    pair = s.law.partner
    body = g.body if pair is None else f"{g.body} pair (R2/R1 = {pair.radius_ratio:g})"
    click.echo(
        f"against {against}: {result['against_meaning']}; {body} law "
        f"{g.law_nu_name} = {float(s.law.nu):g} ({result['law']['source']})"
    )
    if pair is not None and pair.same_material and partner_radius_ratio < 1.0:
        click.echo(
            f"the radius ratio {partner_radius_ratio:g} is the pair R2/R1 = "
            f"{pair.radius_ratio:g} seen from the large grain: the same collision"
        )
    if damped is not None:
        _damped_table(damped, speeds, result)
    else:
        _table(s, speeds, result)
    if pairs is not None and pairs.two_materials:
        click.echo(
            f"type 1 = this grain, type 2 = the partner (R2 = {pairs.radius_ratio:g} R1); "
            "constants per type pair:"
        )
        for name, c in (("1-2", pairs.mixed), ("1-1", pairs.same), ("2-2", pairs.same2)):
            click.echo(f"  {name:>8}: {_constant_text(c)}")
    elif pairs is not None:
        click.echo(
            f"type 1 = the small grain, type 2 = the large one (R2 = {pairs.radius_ratio:g} R1); "
            f"constants per type pair:"
        )
        for name, c in (("1-2", pairs.mixed), ("1-1, 2-2", pairs.same)):
            click.echo(f"  {name:>8}: {_constant_text(c)}")
        click.echo(f"  ({exports.SAME_SIZE_NOTE})")
    elif constant is not None:
        click.echo(f"constant: {_constant_text(constant)}")
    if export_dir is not None:
        click.echo("wrote " + ", ".join(result["exports"]))


def _constant_text(c) -> str:
    return f"epsilon = {c.epsilon:.6f} +- {c.epsilon_err:.2g} ({c.how}; {c.status})"


def _check_ratio(ratio: float | None, against: str, geometry: str) -> float | None:
    """The ``radius_ratio`` to pass to :func:`si_law`: ``None`` without one (and for ``1``, the
    identical grain); one-line refusals naming --partner-radius-ratio."""
    from restitution.errors import InputError

    if ratio is None:
        return None
    if not (math.isfinite(ratio) and ratio > 0):
        raise InputError(
            f"--partner-radius-ratio must be a positive number R2/R1 (1 = identical grains), got "
            f"{ratio:g}"
        )
    if against != "grain":
        raise InputError(
            "--partner-radius-ratio describes a second grain: give it with --against grain, or "
            "leave it out against a wall"
        )
    if ratio == 1.0:
        return None
    kind = body_kind(BODIES[geometry])
    if kind.pair_compression is None:
        raise InputError(
            f"--partner-radius-ratio {ratio:g}: laws of two {kind.geometry}s of different sizes "
            f"are not computed yet; use --geometry {_paired_shapes()}, or leave it out "
            f"(identical {kind.geometry}s)"
        )
    return ratio


def _partner_grain(E, nu, rho, geometry, against, partner_E, partner_nu, partner_rho):
    """The partner grain's material (a ``Grain``) from --partner-E/--partner-nu/--partner-rho
    (each defaulting to this grain's), or ``None`` without them or for the same material."""
    from restitution.errors import InputError
    from restitution.laws.units import Grain

    if (partner_E, partner_nu, partner_rho) == (None, None, None):
        return None
    if against != "grain":
        raise InputError(
            "--partner-E, --partner-nu and --partner-rho describe a second grain: give them "
            "with --against grain"
        )
    kind = body_kind(BODIES[geometry])
    if kind.pair_compression is None:
        raise InputError(
            f"laws of two {kind.geometry}s of different materials are not computed yet; use "
            f"--geometry {_paired_shapes()}, or leave out --partner-E/--partner-nu/--partner-rho"
        )
    values = (
        E if partner_E is None else partner_E,
        nu if partner_nu is None else partner_nu,
        rho if partner_rho is None else partner_rho,
    )
    if values == (E, nu, rho):
        return None
    try:
        return Grain(E=values[0], nu=values[1], rho=values[2], geometry=geometry)
    except InputError as exc:
        raise InputError(f"the partner's material: {exc}") from None


def _check_identical_law_file(ratio, other, reference_speed, maxwell_temperature, second):
    """Refuse --identical-law-file / --partner-identical-law-file where nothing would read
    them."""
    from restitution.errors import InputError

    if second is not None and other is None:
        raise InputError(
            "--partner-identical-law-file serves the 2-2 constant of a partner of another "
            "material: give it with --partner-E/--partner-nu/--partner-rho"
        )
    if ratio is None and other is None:
        raise InputError(
            "--identical-law-file serves the 1-1 and 2-2 constants of two grain sizes: give it "
            "with --partner-radius-ratio other than 1 (identical grains take --law-file)"
        )
    if reference_speed is None and maxwell_temperature is None:
        raise InputError(
            "--identical-law-file and --partner-identical-law-file serve the constants per type "
            "pair: give them with --reference-speed or --maxwell-temperature"
        )


def _identical(E, nu, rho, geometry, path, option):
    """The law of two identical grains of a material, for a type pair i-i."""
    from restitution.errors import InputError
    from restitution.laws.si_law import si_law

    try:
        return si_law(E, nu, rho, geometry, "grain", path=path)
    except InputError as exc:
        raise InputError(
            f"the constants per type pair need the law of identical grains of each material: "
            f"{exc}; give that file with {option}"
        ) from None


def _refuse_uncomputed(E, nu, rho, geometry, against, ratio, other):
    """Two materials without --compute or --law-file: refuse, with the estimate of
    --compute, unless a shipped law serves them."""
    from restitution import budget
    from restitution.errors import InputError
    from restitution.laws.compute import plan
    from restitution.laws.law_nu import shipped_match
    from restitution.laws.si_law import law_target

    law_nu, body, partner = law_target(E, nu, rho, geometry, against, ratio, other)
    if shipped_match(law_nu, body, partner) is not None:
        return  # a shipped law of these two materials serves it
    p = plan(law_nu, body, partner)
    if p.exists:
        how = f"--compute finds the law computed before ({p.path})"
    else:
        how = (
            f"add --compute ({p.collisions} collisions, about "
            f"{budget.format_duration(p.seconds)} on one core)"
        )
    raise InputError(
        f"no law of these two materials is shipped: {how}, or give its file with --law-file"
    )


def _computed(E, nu, rho, geometry, against, ratio, law_file, store, force, other=None):
    """``law --compute``: the law file of the material's exact Poisson number (computed with the
    production settings, or found in the cache), or ``None`` when a shipped law serves it."""
    from restitution.cli._common import check_output_file, quiet
    from restitution.errors import InputError
    from restitution.laws.compute import check_plan, computed_law, plan
    from restitution.laws.law_nu import shipped_match
    from restitution.laws.si_law import law_target

    if law_file is not None:
        raise InputError("give --law-file or --compute, not both")
    law_nu, body, partner = law_target(E, nu, rho, geometry, against, ratio, other)
    if shipped_match(law_nu, body, partner) is not None:
        note(f"note: a shipped law serves nu = {law_nu:.6g}; nothing to compute")
        return None
    if store is not None:
        check_output_file(store, "--store")
    p = plan(law_nu, body, partner)
    check_plan(p, force)
    note(f"note: {p.words()}")
    return computed_law(law_nu, body, partner, store=store, progress=not quiet(), force=force)


def _export(s, constant, out: Path) -> list[Path]:
    """Write the tables and closed form of ``s`` and, with ``constant`` (a ``Constant`` or the
    ``TypePairs`` of ``s``), the snippets into ``out``."""
    from restitution.laws import exports

    written = exports.write_folder(s, constant, out)
    if written.no_closed_form is not None:
        note(f"note: no closed form written: {written.no_closed_form}")
    return list(written.paths)


def ratio_constants(reference_speed, maxwell_temperature) -> bool:
    """Whether a constant for one-number codes is asked for."""
    return (reference_speed, maxwell_temperature) != (None, None)


def _places(err) -> int:
    """Decimals for two significant digits of the error (slow impacts: 1 - 1e-8)."""
    return 6 if not err else max(6, 1 - math.floor(math.log10(err)))


def _outside_notes(s, notes: dict) -> None:
    for status, text in notes.items():
        if status == Status.OUTSIDE:
            lo, hi = s.computed_range_m_s
            text += f"; the law serves {lo:.4g} m/s <= w <= {hi:.4g} m/s"
        note(f"note: {status}: {text}")


def _table(s, speeds, result) -> None:
    """The elastic law's rows."""
    click.echo("  speed [m/s]        v/c       epsilon      error   status")
    notes = {}
    for p in s.points(speeds):
        places = _places(p.epsilon_err)
        eps = "-" if p.epsilon is None else f"{p.epsilon:.{places}f}"
        err = "-" if p.epsilon_err is None else f"{p.epsilon_err:.2g}"
        click.echo(f"  {p.speed_m_s:11.4g}  {p.v_over_c:9.3g}  {eps:>12}  {err:>9}   {p.status}")
        if p.status not in (Status.COMPUTED, Status.INTERPOLATED):
            notes[p.status] = result["statuses"][p.status]
    _outside_notes(s, notes)


def _damped_table(d, speeds, result) -> None:
    """Rows of a damping grain: both losses, and each alone."""
    line = f"damping: tau c/R = {d.tau:.6g} +- {d.tau_err:.2g}"
    if d.relaxation_time_s is not None:
        line += f" (tau = {d.relaxation_time_s:.4g} s for R = {d.radius_m:g} m)"
    if d.measured is not None:
        line += f", from epsilon = {d.measured[0]:g} measured at {d.measured[1]:g} m/s"
    click.echo(line)
    click.echo("  speed [m/s]        v/c       epsilon      error    elastic    viscous   status")
    notes = {}
    for p in d.points(speeds):
        places = _places(p.epsilon_err)
        eps = "-" if p.epsilon is None else f"{p.epsilon:.{places}f}"
        err = "-" if p.epsilon_err is None else f"{p.epsilon_err:.2g}"
        el = "-" if p.epsilon_elastic is None else f"{p.epsilon_elastic:.6f}"
        vi = "-" if p.epsilon_viscous is None else f"{p.epsilon_viscous:.6f}"
        click.echo(
            f"  {p.speed_m_s:11.4g}  {p.v_over_c:9.3g}  {eps:>12}  {err:>9}  {el:>9}  {vi:>9}   "
            f"{p.status}"
        )
        if p.status not in (Status.COMPUTED, Status.INTERPOLATED):
            notes[p.status] = result["statuses"].get(p.status) or p.note
    _outside_notes(d.si, notes)


def _damped(s, measured_epsilon, measured_speed, relaxation_time, radius):
    """The damped law the options ask for, or ``None`` without damping options."""
    from restitution.errors import InputError
    from restitution.laws.damped import damped_law

    if (measured_epsilon, measured_speed, relaxation_time) == (None, None, None):
        if radius is not None:
            raise InputError("--radius goes with --relaxation-time; give both or neither")
        return None
    if relaxation_time is not None and (measured_epsilon, measured_speed) != (None, None):
        raise InputError(
            "give --relaxation-time (with --radius) or --measured-epsilon with --measured-speed, "
            "not both"
        )
    if relaxation_time is None and None in (measured_epsilon, measured_speed):
        raise InputError("--measured-epsilon and --measured-speed go together; give both")
    if relaxation_time is not None and radius is None:
        raise InputError(
            "--relaxation-time needs --radius (m): the viscous loss depends on tau c / R"
        )
    return damped_law(
        s,
        relaxation_time_s=relaxation_time,
        radius_m=radius,
        measured_epsilon=measured_epsilon,
        measured_speed_m_s=measured_speed,
    )
