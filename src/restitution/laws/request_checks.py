"""The refusals of a :class:`~restitution.laws.request.LawRequest`: its options checked together.

Units: SI, those of the request's options (Pa, kg/m^3, m/s, m, s); the refusals say them in the
options' words.

Each field of a request is checked alone first, by its option's kind
(:mod:`restitution.laws.request_fields`); :func:`check_options` then refuses what does not go
together (two constants asked at once, a partner option against a wall, damping of two
materials, files that nothing would read, ``--store`` without ``--compute``, ...), each in one
line naming the options and what to do, before any law is loaded or computed. The request's
properties that build the partner and the wall call :func:`check_partner_ratios` and
:func:`check_wall_numbers`. This module knows the request only by its attributes.
"""

from __future__ import annotations

import math

from restitution.bodies.kinds import body_kind
from restitution.errors import InputError
from restitution.laws.mechanisms.base import mechanisms, used_fields
from restitution.laws.partners.base import owner
from restitution.laws.request_fields import doubts
from restitution.laws.units import BODIES
from restitution.laws.wall_route import check_wall_request

__all__ = [
    "PLATE_RADII",
    "WALL_RATIOS",
    "check_options",
    "check_partner_ratios",
    "check_wall_numbers",
    "paired_shapes",
    "unequal_sizes_advice",
]

WALL_RATIOS = (1e-12, 1e12)
"""The wall's modulus and density over the grain's that an elastic wall takes (those of
:class:`restitution.bodies.wall.HalfSpace`, whose refusal speaks in ratios; the request says it
in Pa and kg/m^3 first)."""

PLATE_RADII = (1e-6, 1e6)
"""The plate thicknesses, in the ball's radii, that :class:`restitution.bodies.wall.Plate`
takes."""


def check_options(r) -> None:
    """Refuse in one line what the options of the request ``r`` ask together and does not go
    together (each field was checked alone before)."""
    if r.reference_speed is not None and r.maxwell_temperature is not None:
        raise InputError("give --reference-speed or --maxwell-temperature, not both")
    if r.friction is not None:
        if r.friction < 0.0:
            raise InputError(f"--friction must be a number >= 0, got {r.friction!r}")
        if r.export_dir is None and r.angle is None:
            raise InputError(
                "--friction goes into the DEM snippets: add --export DIR (or --angle DEG for "
                "an oblique impact)"
            )
    if r.angle is None and (r.friction_model is not None or r.kappa is not None):
        flag = "--friction-model" if r.friction_model is not None else "--kappa"
        raise InputError(
            f"{flag} goes with --angle DEG and --friction MU (an oblique impact); leave it out "
            "for a head-on law"
        )
    if r.angle is not None:
        _check_oblique(r)
        return
    _check_ratio(r)
    _check_damping(r)
    other = r.partner_grain
    if other is not None and r.damped:
        raise InputError(
            "material damping of grains of two materials is not modelled (each material has "
            "its own relaxation time); leave out the damping options or the partner material"
        )
    if r.identical_law_file is not None or r.partner_identical_law_file is not None:
        _check_identical_law_files(r)
    if r.elastic_wall is not None:
        _check_elastic_wall(r)
    if r.plastic or r.measured_fixes is not None or r.fixes_both:
        _check_plastic(r)
    if r.compute and r.law_file is not None:
        raise InputError("give --law-file or --compute, not both")
    if not r.compute and (r.store is not None or r.force or r.route):
        raise InputError(
            "--store, --force and --route belong to --compute; add --compute or leave them out"
        )
    if r.route == "residual" and r.store is not None:
        raise InputError(
            "--store holds the modal route's collisions; the residual route keeps its "
            "points in the cache: leave out --store or --route residual"
        )


OBLIQUE_OWN = frozenset({"angle", "friction", "friction_model", "kappa", "radius"})
"""The request fields of the oblique impact itself: without them (all ``None``) the same request
is the head-on law of the grain (:meth:`restitution.laws.request.LawRequest.head_on`)."""

OBLIQUE_FIELDS = frozenset({"E", "nu", "rho", "shape", "against", "speeds"}) | OBLIQUE_OWN
"""The request fields an oblique impact (``--angle``) reads; any other given is refused."""


def _check_oblique(r) -> None:
    """``--angle``: its range, its friction, and no option that it would not read (it is a
    grain of one material on the rigid wall, elastic, computed at the asked speeds)."""
    from dataclasses import fields

    if not (math.isfinite(r.angle) and 0.0 <= r.angle < 90.0):
        raise InputError(
            f"--angle must lie in [0, 90) degrees from the wall's normal, got {r.angle}"
        )
    if r.friction is None:
        raise InputError(
            "--angle needs --friction MU (Coulomb's coefficient, 0 frictionless): an oblique "
            "impact is both"
        )
    from restitution.dynamics.friction import friction_route, friction_routes, refuse_kappa

    route = friction_route(r.friction_model) if r.friction_model else None
    if route is not None:
        refuse_kappa(route, r.kappa)
    for f in fields(r):
        if f.name in OBLIQUE_FIELDS or f.name == "extra":
            continue
        if getattr(r, f.name) != f.default:
            raise InputError(
                f"{f.metadata['option']} does not go with --angle (an oblique impact of an "
                "elastic grain on the rigid wall, computed at the asked speeds); leave it out"
            )
    given = [k for k, v in dict(r.extra).items() if v is not None]
    if given:
        raise InputError(
            f"--{given[0].replace('_', '-')} does not go with --angle (an oblique impact of an "
            "elastic grain on the rigid wall); leave it out"
        )
    wall = owner("wall_E").against
    if r.against != wall:
        raise InputError(
            f"oblique impacts are computed against the rigid wall so far; use --against {wall}"
        )
    kind = body_kind(BODIES[r.shape])
    if kind.oblique_body is None or kind.oblique_law is not None:
        shapes = [s for s, name in BODIES.items()
                  if body_kind(name).oblique_body is not None
                  and body_kind(name).oblique_law is None]  # fmt: skip
        why = (f"the {kind.geometry}'s oblique route is not built" if kind.oblique_body is None
               else kind.oblique_law)  # fmt: skip
        raise InputError(
            f"oblique impacts (--angle) of the {r.shape} are not served by law yet ({why}); "
            f"--shape {' or '.join(shapes)} have one, or leave out --angle and --friction for "
            f"the {r.shape}'s head-on law"
        )
    if route is None:
        from restitution.dynamics.friction import law_default

        route = law_default(kind)
        refuse_kappa(route, r.kappa)
    if not route.serves(kind):
        shapes = [s for s, name in BODIES.items() if route.serves(body_kind(name))]
        raise InputError(
            f"--friction-model {route.name} needs {route.needs}, which the {r.shape}'s route "
            f"has not yet (--shape {' or '.join(shapes)} has it); use --friction-model "
            f"{' or '.join(o.name for o in friction_routes() if o.serves(kind))}"
        )


def _check_ratio(r) -> None:
    ratio = r.partner_radius_ratio
    if ratio is None:
        return
    if not (math.isfinite(ratio) and ratio > 0):
        raise InputError(
            "--partner-radius-ratio must be a positive number R2/R1 (1 = identical grains), "
            f"got {ratio:g}"
        )
    if r.against != owner("partner_radius_ratio").against:
        raise InputError(
            "--partner-radius-ratio describes a second grain: give it with --against "
            "grain, or leave it out against a wall"
        )
    if ratio == 1.0 or r.shape not in BODIES:
        return
    from restitution.bodies.pair.partner import RATIO_RANGE

    lo, hi = RATIO_RANGE
    if not lo <= ratio <= hi:
        raise InputError(
            f"--partner-radius-ratio {ratio:g}: {unequal_sizes_advice(r)}; a pair takes "
            f"{lo:g} ... {hi:g}"
        )
    kind = body_kind(BODIES[r.shape])
    if kind.pair_compression is None:
        raise InputError(
            f"--partner-radius-ratio {ratio:g}: laws of two {kind.geometry}s of different "
            f"sizes are not computed yet; use --shape {paired_shapes()}, or leave it out "
            f"(identical {kind.geometry}s)"
        )


def unequal_sizes_advice(r) -> str:
    """What answers two grains too unequal in size for a pair (a sentence with the options
    that ask it): the smaller grain on an elastic wall of the larger one's material, which
    is to it a half-space (the larger grain's waves come back after the contact)."""
    ratio = r.partner_radius_ratio
    big = max(ratio, 1.0 / ratio)
    mine = (r.E, r.nu, r.rho)
    theirs = tuple(own if given is None else given for own, given in
                   zip(mine, (r.partner_E, r.partner_nu, r.partner_rho),
                       strict=True))  # fmt: skip
    head = f"the larger grain is {big:g} times the smaller's radius"
    if body_kind(BODIES[r.shape]).planar:
        return (
            f"{head}: to the smaller grain it is a flat wall, and an elastic wall is "
            "computed for spheres only (--against wall, a rigid wall, is its limit when it "
            "is also far stiffer)"
        )
    wall = "--against wall --wall-E {:g} --wall-nu {:g} --wall-rho {:g}"
    if ratio > 1.0 or theirs == mine:
        ask = (
            f"this grain with {wall.format(*theirs)} in place of --against grain and "
            "--partner-radius-ratio"
        )
        if theirs != mine:
            ask += " and the partner options"
    else:
        ask = (
            f"the partner, the smaller grain, on a wall of this grain's material: "
            f"restitution law --E {theirs[0]:g} --nu {theirs[1]:g} --rho {theirs[2]:g} "
            f"--shape {r.shape} {wall.format(*mine)}"
        )
    return (
        f"{head}: to the smaller grain the larger one is an elastic half-space (the waves "
        f"reflected inside it return only after the contact), and w the smaller grain's "
        f"speed towards it; ask for {ask}"
    )


def _check_identical_law_files(r) -> None:
    if r.partner_identical_law_file is not None and r.partner_grain is None:
        raise InputError(
            "--partner-identical-law-file serves the 2-2 constant of a partner of another "
            "material: give it with --partner-E/--partner-nu/--partner-rho"
        )
    if r.radius_ratio is None and r.partner_grain is None:
        raise InputError(
            "--identical-law-file serves the 1-1 and 2-2 constants of two grain sizes: give "
            "it with --partner-radius-ratio other than 1 (identical grains take --law-file)"
        )
    if not r.constants:
        raise InputError(
            "--identical-law-file and --partner-identical-law-file serve the constants per "
            "type pair: give them with --reference-speed or --maxwell-temperature"
        )


def _check_damping(r) -> None:
    """The damping options together: a measurement is an epsilon and a speed; a relaxation
    time needs the radius (and a radius alone means nothing, but a plate's or an elastic
    wall's, whose checks say so, or an export's, whose snippets take their time step from
    it); a measurement that fixes the relaxation time and the relaxation time given are one
    too many."""
    if (r.measured_epsilon is None) != (r.measured_speed is None):
        raise InputError("--measured-epsilon and --measured-speed go together; give both")
    if r.relaxation_time is not None and r.radius is None:
        raise InputError(
            "--relaxation-time needs --radius (m): the viscous loss depends on tau c / R"
        )
    if (
        r.radius is not None
        and r.relaxation_time is None
        and r.measured_epsilon is None
        and (r.wall_thickness is None and r.wall_E is None)
        and r.export_dir is None
        and "radius" not in used_fields(r)
    ):
        raise InputError(
            f"--radius goes with --relaxation-time or --measured-epsilon (damping){_sized()}, "
            "or --export DIR (the DEM snippets' time step); give one of them or leave out "
            "--radius"
        )
    if (r.relaxation_time is not None and r.measured_epsilon is not None
            and r.measured_fixes not in ("limiting-pressure", "both")):  # fmt: skip
        raise InputError(
            "give --relaxation-time (with --radius) or --measured-epsilon with "
            "--measured-speed, not both (or let the measurement fix the limiting pressure: "
            "--measured-fixes limiting-pressure)"
        )


def _check_plastic(r) -> None:
    asked = r.measured_fixes is not None or r.fixes_both
    if asked and None in (r.measured_epsilon, r.measured_speed):
        raise InputError(
            "--measured-fixes says what --measured-epsilon fixes: give it with "
            "--measured-epsilon and --measured-speed"
        )
    if r.fixes_both:
        second = (r.second_measured_epsilon, r.second_measured_speed)
        if None in second:
            raise InputError(
                "two measurements fix both parameters: give --second-measured-epsilon and "
                "--second-measured-speed with the first measurement"
            )
        if r.measured_fixes not in (None, "both"):
            raise InputError(
                f"two measurements fix both parameters, not only the {r.measured_fixes}: "
                "leave out --measured-fixes or the second measurement"
            )
        given = [name for name, value in (("--yield-stress", r.yield_stress),
                 ("--partner-yield-stress", r.partner_yield_stress),
                 ("--limiting-pressure", r.limiting_pressure),
                 ("--relaxation-time", r.relaxation_time)) if value is not None]  # fmt: skip
        if given:
            raise InputError(
                f"two measurements fix the relaxation time and the limiting pressure: leave "
                f"out {', '.join(given)}"
            )
    if not r.plastic:
        return
    if r.shape in BODIES and body_kind(BODIES[r.shape]).planar:
        raise InputError(
            "plastic flow is computed for spheres (Thornton's contact); no comparable law of "
            "cylinders or disks is derived (docs/plasticity.md): use --shape sphere, or "
            "leave out the plastic options"
        )
    if r.wall_thickness is not None:
        raise InputError(
            "plastic flow on a thin plate is not modelled (Zener's plate model is elastic); "
            "leave out --wall-thickness (a half-space) or the plastic options"
        )
    if r.fixes_limiting_pressure and (r.yield_stress, r.partner_yield_stress,
                                      r.limiting_pressure) != (None,) * 3:  # fmt: skip
        raise InputError(
            "one measurement fixes one parameter: give the yield stress (or limiting "
            "pressure), or let --measured-fixes limiting-pressure fix it, not both"
        )
    if r.compute:
        raise InputError(
            "--compute with plastic flow: not available yet (plastic flow is computed on a "
            "shipped or given elastic law); compute the elastic law first (law ... --compute, "
            "without the plastic options), then give it with --law-file"
        )


def _check_elastic_wall(r) -> None:
    if r.against != owner("wall_E").against:
        raise InputError(
            "--wall-E, --wall-nu and --wall-rho describe an elastic wall: give them with "
            "--against wall"
        )
    if body_kind(BODIES[r.shape]).planar:
        raise InputError(
            "an elastic wall is computed for spheres (a sphere on a half-space); use --shape "
            "sphere, or leave out the wall options (a rigid wall)"
        )
    if (r.radius is not None and r.wall_thickness is None and not r.damped
            and r.export_dir is None and "radius" not in used_fields(r)):  # fmt: skip
        raise InputError(
            "--radius goes with --wall-thickness (a plate), --relaxation-time or --export DIR "
            "(the DEM snippets' time step); a half-space needs no radius: leave it out"
        )
    needs = [what for what, asked in (("damping", r.damped),
             ("--law-file", r.law_file is not None),
             ("--compute", r.compute)) if asked]  # fmt: skip
    if needs:
        raise InputError(
            f"{' and '.join(needs)} with an elastic wall: not available yet (the wall's law "
            "comes from its routes, computed now); leave them out"
        )
    # A wall so soft that the slowest speed sinks the ball into it: refused in Pa and m/s
    # before any route runs (--wall-E 63, GPa typed as Pa, once took 6 GB).
    check_wall_request(r.grain, r.elastic_wall, r.speeds, r.wall_E)


def check_wall_numbers(r) -> None:
    """The wall's numbers against what the wall's bodies take (:data:`WALL_RATIOS`,
    :data:`PLATE_RADII`), refused in the options' units and words: the wall's modulus and
    density against the grain's, a plate's thickness against the ball's radius (naming the
    one of the two outside the range of real grains and plates, :data:`restitution.laws.
    request_fields.PLAUSIBLE`)."""
    lo, hi = WALL_RATIOS
    for opt, own, value, mine, unit in (("--wall-E", "--E", r.wall_E, r.E, "Pa"),
                                        ("--wall-rho", "--rho", r.wall_rho, r.rho,
                                         "kg/m^3")):  # fmt: skip
        ratio = value / mine
        if not lo <= ratio <= hi:
            raise InputError(
                f"{opt} {value:g} {unit} is {ratio:.3g} times {own} {mine:g} {unit}, beyond "
                f"the {lo:g} ... {hi:g} times the grain's an elastic wall takes; check {opt} "
                f"and its units ({unit}), or leave out the wall options for a rigid wall"
            )
    if not -1.0 < r.wall_nu < 0.5:
        raise InputError(
            f"the wall's Poisson number must lie in (-1, 0.5), got --wall-nu {r.wall_nu:g}"
        )
    if r.wall_thickness is None:
        return
    if r.radius is None:
        raise InputError("a plate (--wall-thickness) needs the ball's --radius, m")
    lo, hi = PLATE_RADII
    radii = r.wall_thickness / r.radius
    if not lo <= radii <= hi:
        culprit = "; ".join(
            text for text in doubts(r) if text.startswith(("--radius", "--wall-thickness"))
        )
        culprit = culprit or "check --wall-thickness and --radius (both in m)"
        raise InputError(
            f"--wall-thickness {r.wall_thickness:g} m is {radii:.3g} times --radius "
            f"{r.radius:g} m; a plate takes {lo:g} ... {hi:g} radii of the ball: {culprit}"
        )


def check_partner_ratios(r, values) -> None:
    """The partner's modulus and density within what a pair takes (:data:`restitution.
    bodies.pair.partner.RATIO_RANGE`), refused in Pa and kg/m^3 with the options given."""
    from restitution.bodies.pair.partner import RATIO_RANGE

    lo, hi = RATIO_RANGE
    for opt, own, value, mine, unit in (("--partner-E", "--E", values[0], r.E, "Pa"),
                                        ("--partner-rho", "--rho", values[2], r.rho,
                                         "kg/m^3")):  # fmt: skip
        ratio = value / mine
        if lo <= ratio <= hi:
            continue
        if ratio > hi and opt == "--partner-E":
            way = (
                "to this grain such a partner is a rigid wall: --against wall without the "
                "partner options"
            )
        else:
            way = f"check {opt} and its units ({unit})"
        raise InputError(
            f"{opt} {value:g} {unit} is {ratio:.3g} times {own} {mine:g} {unit}, beyond the "
            f"{lo:g} ... {hi:g} times this grain's a pair of grains takes; {way}"
        )


def paired_shapes() -> str:
    """The shapes whose laws of two grains of different sizes or materials are computed."""
    names = [shape for shape, body in BODIES.items() if body_kind(body).pair_compression]
    return " or ".join(names)


def _sized() -> str:
    """``, or --work-of-adhesion (adhesion)``: the mechanisms' own options that need the grain's
    radius, for the refusal of a radius nothing reads."""
    named = [f"{o.option} ({m.name})" for m in mechanisms() if "radius" in m.reads
             for o in m.options if not o.field]  # fmt: skip
    return "".join(f", or {n}" for n in named)
