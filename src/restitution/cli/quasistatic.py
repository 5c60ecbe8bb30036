"""``restitution quasistatic``: the quasistatic limit of paper section 5 at one speed, for the disk
(2D Hertz) or the sphere (3D Hertz)."""

from __future__ import annotations

import math

import click

from restitution.bodies.cache import check_mode_request
from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.cli._common import (
    body_nu,
    geometry_option,
    given,
    note,
    nu_inputs,
    nu_option,
    pair_units,
    partner_from,
    partner_options,
    plane_option,
    quiet_option,
    refuse_ignored,
)
from restitution.cli.report import Report, emit, format_options, output_format
from restitution.dynamics.results import UNITS
from restitution.errors import InputError
from restitution.quasistatic.hertz import (
    LAWS,
    contact_law,
    contact_time_rate,
    quasistatic_collision,
)
from restitution.quasistatic.hertz_pair import (
    pair_contact_law,
    pair_mass,
    pair_quasistatic_collision,
)
from restitution.quasistatic.hertz_sphere import (
    CONTACT_TIME_CONSTANT,
    sphere_contact_law,
    sphere_pair_contact_law,
    sphere_quasistatic_collision,
)


def quasistatic_summary(nu: float, v: float, law: str = "paper", n_modes: int = 400) -> dict:
    """Everything the command reports, as a JSON-ready dict (units in the key names' docs)."""
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.rayleigh import rayleigh_energy

    hl = contact_law(nu, law)
    q = quasistatic_collision(hl, v)
    modes = get_modes(nu, count=n_modes)
    ray = rayleigh_energy(modes, v, hl)
    n, l, share = ray.dominant
    return {
        "nu": nu,
        "v": v,
        "law": law,
        "law_constant": hl.constant,
        "max_compression": float(q.max_compression[0]),
        "max_force": float(q.max_force[0]),
        "contact_time": float(q.contact_time[0]),
        "harmonic_ratio": float(q.harmonic_ratio[0]),
        "harmonic_ratio_leading_order": float(1.0 + contact_time_rate(hl, q.max_compression)[0]),
        "eq61_max_compression": float(q.estimate_max_compression[0]),
        "eq61_contact_time": float(q.estimate_contact_time[0]),
        "law_max_force": hl.max_force,
        "law_max_compression": hl.max_compression,
        "law_max_speed": hl.max_speed(),
        "rayleigh_energy_fraction": ray.energy_fraction,
        "rayleigh_quadrupole_fraction": ray.fraction_of(2, 0),
        "rayleigh_dominant_mode": [n, l],
        "rayleigh_dominant_share": share,
        "rayleigh_n_modes": len(modes),
        "units": dict(UNITS),
    }


def sphere_quasistatic_summary(nu: float, v: float, n_modes: int = 400) -> dict:
    """What the command reports for a sphere (3D Hertz, Rayleigh's estimate with its modes)."""
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.rayleigh import rayleigh_energy

    _check_rayleigh_speed(v)
    law = sphere_contact_law(nu)
    q = sphere_quasistatic_collision(law, v)
    modes = get_modes(nu, count=n_modes, geometry=SPHERE.geometry)
    ray = rayleigh_energy(modes, v, law)
    n, l, share = ray.dominant
    return {
        "geometry": SPHERE.geometry,
        "nu": nu,
        "v": v,
        "law": law.name,
        "E_star": law.E_star,
        "max_compression": float(q.max_compression[0]),
        "max_force": float(q.max_force[0]),
        "contact_time": float(q.contact_time[0]),
        "contact_radius": float(q.contact_radius[0]),
        "contact_time_constant": CONTACT_TIME_CONSTANT,
        "law_max_speed": law.max_speed(),
        "rayleigh_energy_fraction": ray.energy_fraction,
        "rayleigh_quadrupole_fraction": ray.quadrupole,
        "rayleigh_dominant_mode": [n, l],
        "rayleigh_dominant_share": share,
        "rayleigh_n_modes": len(modes),
        "units": dict(SPHERE.units),
    }


_DISK_ONLY = {"law": "--law", "plane": "--plane"}


@click.command()
@nu_option
@plane_option
@geometry_option
@click.option(
    "--v",
    "v",
    type=float,
    required=True,
    help="Speed of the body towards the wall in units of c = sqrt(E/rho). Two identical bodies "
    "approaching each other at +-v collide like this (relative speed 2v).",
)
@click.option(
    "--law",
    type=click.Choice(LAWS),
    default="paper",
    show_default=True,
    help="2D Hertz law of the disk: paper = eq. (57) as printed (c = -1-nu); diameter = eq. "
    "(56) integrated correctly (c = -1); centre = approach of the centre of mass "
    "(c = -1-2/pi-nu/4), see docs/quasistatic.md. A sphere has Hertz's 3D law only.",
)
@click.option(
    "--modes",
    "n_modes",
    type=int,
    default=400,
    show_default=True,
    help="Lowest modes driven in Rayleigh's approach (the paper's Fig. 12 uses 1800).",
)
@partner_options
@format_options
@quiet_option
@click.pass_context
def quasistatic(
    ctx,
    nu,
    plane,
    geometry,
    v,
    law,
    n_modes,
    radius_ratio,
    partner_nu,
    modulus_ratio,
    density_ratio,
    fmt,
    as_json,
):
    """Quasistatic collision (2D Hertz law for the disk, 3D Hertz for the sphere) and
    Rayleigh's energy estimate at speed V.

    Reports the maximal compression, the contact time (and for the disk the eq. (61)
    estimates), and the fraction of the kinetic energy left in the modes when the quasistatic
    force drives them at the contact point (paper section 5). With --radius-ratio (or another
    partner option) two bodies meet at relative speed V: two disks by their 2D Hertz law with a
    common contact width (docs/two-disks.md), without Rayleigh's estimate; two spheres by the
    pair's 3D Hertz law, with Rayleigh's estimate of each sphere's loss (docs/spheres.md).
    """
    fmt = output_format(fmt, as_json)
    if geometry != DISK.geometry:
        refuse_ignored(
            ctx,
            _DISK_ONLY,
            f"for a {geometry}: --law and --plane apply to disks only (a {geometry} has "
            "Hertz's 3D law, and its --nu is already three-dimensional); leave them out",
        )
    if n_modes < 1:
        raise InputError(f"--modes must be at least 1, got {n_modes}")
    body = body_nu(nu, plane, geometry)
    partner = partner_from(ctx, nu, plane, geometry)
    if partner is not None and geometry == SPHERE.geometry:
        _sphere_pair(ctx, body, partner, v, n_modes, fmt)
        return
    if partner is not None:
        _pair(ctx, body, partner, geometry, v, law, fmt)
        return
    check_mode_request(body, n_modes, geometry=geometry)
    if geometry == SPHERE.geometry:
        _sphere(body, v, n_modes, fmt)
        return
    if geometry != DISK.geometry:
        raise InputError(
            f"no quasistatic theory for a {geometry} yet; use a {DISK.geometry} or a "
            f"{SPHERE.geometry}"
        )
    out = quasistatic_summary(body, v, law, n_modes)
    if not math.isfinite(out["contact_time"]):
        raise InputError("contact time is not finite; use a smaller --v")
    inputs = {
        "geometry": geometry, **nu_inputs(nu, plane, geometry), "v": v, "law": law,
        "modes": n_modes,
    }  # fmt: skip
    _emit(inputs, out, _disk_text(out, v, law), fmt)


def _emit(inputs: dict, out: dict, text: str, fmt: str, units: dict | None = None) -> None:
    """The answer of one quasistatic collision (the CSV: one row), and the note on Rayleigh's
    validity with the text; ``units`` the envelope's (default: the body's on the wall)."""
    emit(Report("quasistatic", inputs, out, units=units, text=lambda: text,
                rows=lambda: [_row(out)]), fmt)  # fmt: skip
    if fmt == "text" and "rayleigh_energy_fraction" in out:
        _note_validity(out)


def _row(out: dict) -> dict:
    """The summary as one CSV row: nested entries flattened (``partner_radius_ratio``,
    ``rayleigh_dominant_n``), the units left to the JSON."""
    row = {}
    for key, value in out.items():
        if key == "units":
            continue
        if key == "rayleigh_dominant_mode":
            row["rayleigh_dominant_n"], row["rayleigh_dominant_l"] = value
        elif isinstance(value, dict):  # a top-level key of the same name wins (partner_nu)
            row.update({f"{key}_{k}": v for k, v in value.items() if f"{key}_{k}" not in out})
        else:
            row[key] = value
    return row


def _disk_text(out: dict, v: float, law: str) -> str:
    return (
        f"quasistatic collision, nu = {out['nu']:g}, v = {v:g} c towards the wall, "
        f"law '{law}' (c = {out['law_constant']:.6g})\n"
        f"  max compression  {out['max_compression']:.6g} R   (eq. 61: "
        f"{out['eq61_max_compression']:.6g})\n"
        f"  contact time     {out['contact_time']:.6g} R/c (eq. 61: "
        f"{out['eq61_contact_time']:.6g}); v tau / (pi delta_max) = "
        f"{out['harmonic_ratio']:.6f}\n"
        f"  max force        {out['max_force']:.6g} E R\n"
        f"  Rayleigh: energy left in {out['rayleigh_n_modes']} modes = "
        f"{out['rayleigh_energy_fraction']:.6g} of (m/2) v^2, "
        f"{100 * out['rayleigh_dominant_share']:.1f}% in mode "
        f"(n={out['rayleigh_dominant_mode'][0]}, l={out['rayleigh_dominant_mode'][1]})"
    )


def pair_quasistatic_summary(nu: float, partner, w: float, law: str = "centre") -> dict:
    """What the command reports for two disks at relative speed ``w`` (``c1``): their Hertz
    law (:func:`restitution.quasistatic.hertz_pair.pair_contact_law`), the quasistatic collision
    with the reduced mass, and the eq. (61)-type compression that scales the pair's walls."""
    nu2 = partner.nu2(nu)
    kwargs = {
        "radius_ratio": partner.radius_ratio,
        "modulus_ratio": partner.modulus_ratio,
    }
    hl = pair_contact_law(nu, nu2, law=law, **kwargs)
    q = pair_quasistatic_collision(w, nu, nu2, density_ratio=partner.density_ratio, law=law,
                                   **kwargs)  # fmt: skip
    return {
        "geometry": "disk-pair",
        "nu": nu,
        "partner": partner.to_dict(),
        "partner_nu": nu2,
        "v": w,
        "law": law,
        "E_eff": hl.E,
        "R_K": hl.R,
        "law_constant": hl.constant,
        "reduced_mass": pair_mass(partner.radius_ratio, partner.density_ratio),
        "max_compression": float(q.max_compression[0]),
        "max_force": float(q.max_force[0]),
        "contact_time": float(q.contact_time[0]),
        "wall_scale_compression": float(partner.max_compression(w)),
        "units": {
            "system": "E1 = rho1 = R1 = 1: the first disk's 2D constants",
            "speed": "c1 = sqrt(E1/rho1) (v: the relative normal speed of the two centres)",
            "length": "R1 (compressions: approach of the two centres)",
            "time": "R1/c1",
            "force": "E1 R1 (per unit thickness)",
            "mass": "rho1 R1^2 (per unit thickness)",
        },
    }


def _pair(ctx, nu: float, partner, geometry: str, w: float, law: str, fmt: str) -> None:
    """``quasistatic --radius-ratio ...``: two disks (:mod:`restitution.quasistatic.hertz_pair`)."""
    if geometry != DISK.geometry:
        raise InputError(
            f"the quasistatic theory of two bodies is derived for disks; leave out the partner "
            f"options for a {geometry}"
        )
    refuse_ignored(ctx, {"n_modes": "--modes"}, "for two disks (no Rayleigh estimate for pairs)")
    # The paper's eq. (57) as printed is the default of one disk; the pair's compression is the
    # approach of the centres, so a pair takes the centre law unless --law is given.
    if not given(ctx, "law"):
        law = "centre"
    out = pair_quasistatic_summary(nu, partner, w, law)
    if not math.isfinite(out["contact_time"]):
        raise InputError("contact time is not finite; use a smaller --v")
    inputs = {"geometry": geometry, "nu": nu, "partner_nu": out["partner_nu"], "v": w,
              "law": law, "radius_ratio": partner.radius_ratio,
              "modulus_ratio": partner.modulus_ratio,
              "density_ratio": partner.density_ratio}  # fmt: skip
    text = (
        f"quasistatic collision of two disks, nu = {nu:g} and {out['partner_nu']:g}, R2/R1 = "
        f"{partner.radius_ratio:g}, E2/E1 = {partner.modulus_ratio:g}, rho2/rho1 = "
        f"{partner.density_ratio:g}; relative speed v = {w:g} c1, law '{law}'\n"
        f"  E_eff = {out['E_eff']:.6g} E1, R_K = {out['R_K']:.6g} R1, reduced mass "
        f"{out['reduced_mass']:.6g} rho1 R1^2\n"
        f"  max approach of the centres  {out['max_compression']:.6g} R1 (the walls' scale: "
        f"{out['wall_scale_compression']:.6g})\n"
        f"  contact time     {out['contact_time']:.6g} R1/c1\n"
        f"  max force        {out['max_force']:.6g} E1 R1"
    )
    _emit(inputs, out, text, fmt, pair_units(geometry))


def _check_rayleigh_speed(v: float) -> None:
    """Refuse a speed below :data:`restitution.laws.units.SLOWEST_V`, where Rayleigh's estimate
    for a sphere vanishes in double precision and its pulse quadrature, sized by the contact
    time (``~ v^(-1/5)``), is not (``quasistatic --geometry sphere --v 1e-300`` ended in a
    ZeroDivisionError, ``--v 1e-50`` in a 2.6 TiB allocation), as ``law`` refuses it."""
    from restitution.laws.units import SLOWEST_V

    if 0.0 < v < SLOWEST_V:  # other speeds are the theories' to refuse
        raise InputError(
            f"--v {v:g}: below {SLOWEST_V:g} c a sphere's vibrational loss (Rayleigh's estimate, "
            f"under 1e-17 of the energy) vanishes in double precision and epsilon is 1; ask for "
            f"--v >= {SLOWEST_V:g}"
        )


def sphere_pair_summary(nu: float, partner, w: float, n_modes: int) -> dict:
    """What the command reports for two spheres at relative speed ``w`` (``c1``): their Hertz
    law, the quasistatic collision with the reduced mass, and the route's estimate of the loss
    (:func:`restitution.quasistatic.low_speed.low_speed_loss` of the pair: both spheres' modes
    below one frequency, each driven at its own pole) with its error and each sphere's share."""
    from restitution.quasistatic.low_speed import low_speed_loss, reach

    _check_rayleigh_speed(w)
    pair = partner.pair(nu, n_modes, SPHERE.geometry)
    r = low_speed_loss(pair, w)
    law = sphere_pair_contact_law(
        nu, partner.nu2(nu), radius_ratio=partner.radius_ratio,
        modulus_ratio=partner.modulus_ratio,
    )  # fmt: skip
    q = sphere_quasistatic_collision(law, w, mass=pair.mass)
    return {
        "geometry": "sphere-pair",
        "nu": nu,
        "partner": partner.to_dict(),
        "partner_nu": partner.nu2(nu),
        "v": w,
        "E_star": law.E_star,
        "R_eff": law.R,
        "reduced_mass": pair.mass,
        "max_compression": float(q.max_compression[0]),
        "contact_radius": float(q.contact_radius[0]),
        "max_force": float(q.max_force[0]),
        "contact_time": float(q.contact_time[0]),
        "energy_loss": r.energy_loss,
        "energy_loss_err": r.energy_loss_err,
        "epsilon": r.epsilon,
        "epsilon_err": r.epsilon_err,
        "shares": list(r.shares),
        "n_modes": len(pair),
        "reach": reach(nu, partner),
        "units": {
            "system": "E1 = rho1 = R1 = 1: the first sphere's 3D constants",
            "speed": "c1 = sqrt(E1/rho1) (v: the relative normal speed of the two centres)",
            "length": "R1 (compressions: approach of the two centres)",
            "time": "R1/c1",
            "force": "E1 R1^2",
            "mass": "rho1 R1^3",
            "energy": "fraction of (mu/2) v^2, mu the reduced mass",
        },
    }


def _sphere_pair(ctx, nu: float, partner, w: float, n_modes: int, fmt: str) -> None:
    """``quasistatic --geometry sphere --radius-ratio ...``: two spheres (docs/spheres.md)."""
    from restitution.quasistatic.low_speed import PAIR_LOW_SPEED_MODES

    if not given(ctx, "n_modes"):
        n_modes = PAIR_LOW_SPEED_MODES
    out = sphere_pair_summary(nu, partner, w, n_modes)
    inputs = {"geometry": SPHERE.geometry, "nu": nu, "partner_nu": out["partner_nu"], "v": w,
              "modes": n_modes, "radius_ratio": partner.radius_ratio,
              "modulus_ratio": partner.modulus_ratio,
              "density_ratio": partner.density_ratio}  # fmt: skip
    first, second = out["shares"]
    beyond = "" if w <= out["reach"] else " (above the route's reach: not served by `law`)"
    text = (
        f"quasistatic collision of two spheres, nu = {nu:g} and {out['partner_nu']:g}, R2/R1 = "
        f"{partner.radius_ratio:g}, E2/E1 = {partner.modulus_ratio:g}, rho2/rho1 = "
        f"{partner.density_ratio:g}; relative speed v = {w:g} c1\n"
        f"  E* = {out['E_star']:.6g} E1, R_eff = {out['R_eff']:.6g} R1, reduced mass "
        f"{out['reduced_mass']:.6g} rho1 R1^3\n"
        f"  max approach of the centres  {out['max_compression']:.6g} R1 (contact radius "
        f"{out['contact_radius']:.6g} R1)\n"
        f"  contact time     {out['contact_time']:.6g} R1/c1\n"
        f"  max force        {out['max_force']:.6g} E1 R1^2\n"
        f"  Rayleigh: energy left in {out['n_modes']} modes of both = "
        f"{out['energy_loss']:.6g} +- {out['energy_loss_err']:.2g} of (mu/2) v^2 "
        f"({first:.4g} in the first sphere, {second:.4g} in the second); epsilon = "
        f"{out['epsilon']:.9g} +- {out['epsilon_err']:.2g}\n"
        f"  the route's reach: v = {out['reach']:.4g} c1{beyond}"
    )
    _emit(inputs, out, text, fmt, pair_units(SPHERE.geometry))


def _sphere(nu: float, v: float, n_modes: int, fmt: str) -> None:
    out = sphere_quasistatic_summary(nu, v, n_modes)
    inputs = {"geometry": SPHERE.geometry, "nu": nu, "v": v, "modes": n_modes}
    n, l = out["rayleigh_dominant_mode"]
    text = (
        f"quasistatic collision of a sphere, nu = {nu:g}, v = {v:g} c towards the wall, "
        f"3D Hertz law (E* = {out['E_star']:.6g} E)\n"
        f"  max compression  {out['max_compression']:.6g} R   (contact radius "
        f"{out['contact_radius']:.6g} R)\n"
        f"  contact time     {out['contact_time']:.6g} R/c (= "
        f"{out['contact_time_constant']:.6f} delta_max / v)\n"
        f"  max force        {out['max_force']:.6g} E R^2\n"
        f"  Rayleigh: energy left in {out['rayleigh_n_modes']} modes = "
        f"{out['rayleigh_energy_fraction']:.6g} of (m/2) v^2, "
        f"{100 * out['rayleigh_dominant_share']:.1f}% in mode (l={l}, n={n})"
    )
    _emit(inputs, out, text, fmt)


def _note_validity(out: dict) -> None:
    if out["rayleigh_energy_fraction"] > 0.1:
        note(
            "  note: a fraction this large is outside the first-order validity of Rayleigh's "
            "approach"
        )
