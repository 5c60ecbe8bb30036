"""What a user asks of the SI law: one frozen request, refused in one line when it is inconsistent.

Units: SI at this edge (Pa, kg/m^3, m/s, m, s, m^2/s^2); the law answers in them
(:mod:`restitution.laws.si_law`).

:class:`LawRequest` is the answer to "which options go together": its construction holds every
refusal that needs no law (two constants asked at once, a partner option against a wall,
damping of two materials, files that nothing would read, ``--store`` without ``--compute``, ...)
so the command line and a notebook get the same one-line :class:`~restitution.errors.InputError`
before anything is loaded or computed. :func:`restitution.laws.serve.serve` serves it. Each
field's metadata carries the option that sets it on the command line, its help, its kind and
unit (``restitution law`` builds its options from them), in the manner of check-jsonschema's
``ParseResult``; each field is checked alone by its kind first
(:mod:`restitution.laws.request_fields`: a value passed in Python gets the command line's type
or a one-line refusal naming the option and the keyword), then the options together.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from pathlib import Path

from restitution.bodies.kinds import body_kind
from restitution.errors import InputError
from restitution.laws.request_fields import checked, doubts, option, warn_implausible
from restitution.laws.units import BODIES, PARTNERS, SHAPES, Grain
from restitution.laws.wall_route import check_wall_request

__all__ = ["DEFAULT_SPEEDS_M_S", "MEASURED_FIXES", "LawRequest", "option_fields"]

DEFAULT_SPEEDS_M_S: tuple[float, ...] = (0.1, 0.5, 1.0, 5.0, 10.0)
"""Impact speeds (m/s) of a request that names none."""

MEASURED_FIXES = ("relaxation-time", "limiting-pressure", "both")
"""What one measured epsilon may fix (``--measured-fixes``)."""

ROUTES = ("modal", "residual")
"""``--route`` of ``--compute``: the modal production or the static residual
(:mod:`restitution.laws.making.residual_law`)."""

WALL_RATIOS = (1e-12, 1e12)
"""The wall's modulus and density over the grain's that an elastic wall takes (those of
:class:`restitution.bodies.wall.HalfSpace`, whose refusal speaks in ratios; the request says it
in Pa and kg/m^3 first)."""

PLATE_RADII = (1e-6, 1e6)
"""The plate thicknesses, in the ball's radii, that :class:`restitution.bodies.wall.Plate`
takes."""


@dataclass(frozen=True)
class LawRequest:
    """One question to the SI law (module docs); constructing it checks the options together.

    Every field is an option of ``restitution law`` (its metadata names it); ``None`` is
    "not given". The fields' help says what each means.
    """

    E: float = field(
        metadata=option("--E", "Young modulus of the 3D material, Pa.", unit="Pa", positive=True)
    )
    nu: float = field(metadata=option("--nu", "Poisson number of the 3D material."))
    rho: float = field(
        metadata=option(
            "--rho", "Density of the 3D material, kg/m^3.", unit="kg/m^3", positive=True
        )
    )
    shape: str = field(
        metadata=option(
            "--shape",
            "Long cylinder hit along a diameter (the disk in plane strain: nu_2d = nu/(1-nu), "
            "c = sqrt(E/((1-nu^2) rho))), thin disk (plane stress: nu_2d = nu, c = sqrt(E/rho)) "
            "or sphere (the sphere's law for nu itself, c = sqrt(E/rho)).",
            "choice",
            choices=lambda: list(SHAPES),
            aliases=("--geometry",),
        )
    )
    against: str = field(
        metadata=option(
            "--against",
            "A rigid flat wall hit at speed w (v = w/c), or an identical grain at relative normal "
            "speed w (v = w/(2c)); with --partner-radius-ratio a grain of the same material and "
            "another size (v = w/c, the pair's law).",
            "choice",
            choices=lambda: list(PARTNERS),
        )
    )
    speeds: tuple[float, ...] = field(
        default=DEFAULT_SPEEDS_M_S,
        metadata=option(
            "--speed",
            "Impact speed(s) w in m/s (several after one flag). Default: 0.1 0.5 1 5 10.",
            "floats",
            unit="m/s",
        ),
    )
    partner_radius_ratio: float | None = field(
        default=None,
        metadata=option(
            "--partner-radius-ratio",
            "With --against grain: radius of the partner grain over this grain's, R2/R1, same "
            "material (either way round; 1 = identical grains). Served by the law of the pair "
            "(law_pair_r<R>_nu<nu_2d>.json, or --law-file from `restitution curve --nu NU_2D "
            "--radius-ratio R`); w is the relative normal speed. With a constant, the exports "
            "give type pairs 1-1 and 2-2 (identical grains) and 1-2 (the pair). Two spheres: "
            "law_sphere_pair_r<R>_nu<nu>.json where shipped, else each speed computed now by "
            "their low-speed route (up to its reach, about 15 m/s for steel).",
        ),
    )
    partner_E: float | None = field(
        default=None,
        metadata=option(
            "--partner-E",
            "With --against grain: Young modulus of the partner grain's 3D material, Pa [this "
            "grain's]. A partner of another material (--partner-E, --partner-nu, "
            "--partner-rho): one pair is shipped (steel E = 210e9, nu = 0.3, rho = 7850 with "
            "glass 63e9, 0.2481, 2500, 1.4 times as large, cylinders; the same of one size, "
            "spheres); any other pair of cylinders is computed with --compute (the estimate is "
            "stated first) or read from --law-file, any other pair of spheres at the asked "
            "speeds by their low-speed route. The partner has this grain's geometry.",
            unit="Pa",  # its range: the partner's Grain ("the partner's material: ...")
        ),
    )
    partner_nu: float | None = field(
        default=None,
        metadata=option(
            "--partner-nu",
            "With --against grain: Poisson number of the partner grain's 3D material [this "
            "grain's].",
        ),
    )
    partner_rho: float | None = field(
        default=None,
        metadata=option(
            "--partner-rho",
            "With --against grain: density of the partner grain's 3D material, kg/m^3 [this "
            "grain's].",
            unit="kg/m^3",
        ),
    )
    wall_E: float | None = field(
        default=None,
        metadata=option(
            "--wall-E",
            "With --against wall: the wall is an elastic half-space (a thick block) of this "
            "Young modulus, Pa, instead of rigid; give --wall-nu and --wall-rho too. Spheres "
            "only; each speed computed by the low-speed route, the loss split into the ball's "
            "vibrations and the waves radiated into the block (docs/walls.md).",
            unit="Pa",
            positive=True,
        ),
    )
    wall_nu: float | None = field(
        default=None,
        metadata=option("--wall-nu", "With --wall-E: the wall's Poisson number."),
    )
    wall_rho: float | None = field(
        default=None,
        metadata=option(
            "--wall-rho", "With --wall-E: the wall's density, kg/m^3.", unit="kg/m^3", positive=True
        ),
    )
    wall_thickness: float | None = field(
        default=None,
        metadata=option(
            "--wall-thickness",
            "With --wall-E: the wall is an infinite plate of this thickness, m (Zener's "
            "thin-plate model, solved as the coupled equation); give the ball's --radius, m. "
            "Speeds where the model does not hold, or the ball does not rebound, get no value "
            "and say why.",
            unit="m",
            positive=True,
        ),
    )
    law_file: Path | None = field(
        default=None,
        metadata=option(
            "--law-file",
            "A law JSON from `restitution curve` for this material: the disk's law for its 2D "
            "Poisson number (cylinder, thin disk), the sphere's (`curve --geometry sphere`) for "
            "nu; with --partner-radius-ratio the pair's (`curve --radius-ratio R`).",
            "file",
        ),
    )
    identical_law_file: Path | None = field(
        default=None,
        metadata=option(
            "--identical-law-file",
            "With --partner-radius-ratio and --reference-speed or --maxwell-temperature: the "
            "law JSON of two identical grains of this material (`restitution curve --nu "
            "NU_2D`), for the 1-1 and 2-2 constants [default: the shipped laws]; with a partner "
            "material the 1-1 constant only.",
            "file",
        ),
    )
    partner_identical_law_file: Path | None = field(
        default=None,
        metadata=option(
            "--partner-identical-law-file",
            "With a partner material and --reference-speed or --maxwell-temperature: the law "
            "JSON of two identical grains of the partner's material, for the 2-2 constant "
            "[default: the shipped laws].",
            "file",
        ),
    )
    export_dir: Path | None = field(
        default=None,
        metadata=option(
            "--export",
            "Write the table (.txt, .csv), the closed form (.json, C header .h, Fortran .f90) "
            "and, with --reference-speed or --maxwell-temperature, a snippet for every DEM code "
            "(LAMMPS, LIGGGHTS, MercuryDPM, YADE) into this directory.",
            "dir",
        ),
    )
    reference_speed: float | None = field(
        default=None,
        metadata=option(
            "--reference-speed",
            "Constant for one-number codes: epsilon at this speed, m/s.",
            unit="m/s",
            positive=True,
        ),
    )
    friction: float | None = field(
        default=None,
        metadata=option(
            "--friction",
            "Sliding friction coefficient mu the DEM snippets of --export set (default none: "
            "they set mu = 0 and say so); restitution computes only the normal coefficient.",
        ),
    )
    maxwell_temperature: float | None = field(
        default=None,
        metadata=option(
            "--maxwell-temperature",
            "Constant for one-number codes: epsilon averaged (dissipation-weighted) over a "
            "Maxwell gas at this granular temperature <v_x^2>, m^2/s^2.",
            unit="m^2/s^2",
            positive=True,
        ),
    )
    measured_epsilon: float | None = field(
        default=None,
        metadata=option(
            "--measured-epsilon",
            "Material damping from one measurement: the coefficient of restitution measured at "
            "--measured-speed (same partner). The relaxation time is inferred from it and "
            "epsilon(w) given with its elastic and viscous parts (docs/damping.md).",
        ),
    )
    measured_speed: float | None = field(
        default=None,
        metadata=option(
            "--measured-speed",
            "Impact speed of --measured-epsilon, m/s.",
            unit="m/s",
            positive=True,
        ),
    )
    relaxation_time: float | None = field(
        default=None,
        metadata=option(
            "--relaxation-time",
            "Material damping given directly: the Kelvin-Voigt relaxation time (viscosities = "
            "tau x moduli), s; needs --radius.",
            unit="s",
            positive=True,
        ),
    )
    radius: float | None = field(
        default=None,
        metadata=option(
            "--radius",
            "Radius of the grain, m (with --relaxation-time, or with --measured-epsilon to "
            "state tau in seconds and export the DEM codes' viscoelastic contact; for two "
            "sizes the smaller grain's). The elastic law needs no radius; the viscous loss "
            "depends on tau c / R.",
            unit="m",
            positive=True,
        ),
    )
    yield_stress: float | None = field(
        default=None,
        metadata=option(
            "--yield-stress",
            "Plastic flow (spheres): the uniaxial yield stress of this grain's material, Pa. The "
            "contact's limiting pressure is the pressure of first yield (1.61 Y at nu = 0.3) of "
            "the softer body; epsilon then has its plastic, viscous and wave parts on one "
            "force pulse (Thornton's contact, docs/plasticity.md).",
            unit="Pa",
            positive=True,
        ),
    )
    partner_yield_stress: float | None = field(
        default=None,
        metadata=option(
            "--partner-yield-stress",
            "Plastic flow: the yield stress of a partner grain of another material, or of an "
            "elastic wall, Pa [the partner stays elastic].",
            unit="Pa",
            positive=True,
        ),
    )
    limiting_pressure: float | None = field(
        default=None,
        metadata=option(
            "--limiting-pressure",
            "Plastic flow: Thornton's limiting contact pressure p_y itself, Pa (instead of yield "
            "stresses).",
            unit="Pa",
            positive=True,
        ),
    )
    measured_fixes: str | None = field(
        default=None,
        metadata=option(
            "--measured-fixes",
            "Which parameter --measured-epsilon fixes: the relaxation time (default; damping) "
            "or the limiting pressure (plastic flow; the damping, if any, from "
            "--relaxation-time). One measurement fixes one parameter; 'both' (the default with "
            "a second measurement) fixes the two from two measurements.",
            "choice",
            choices=lambda: list(MEASURED_FIXES),
        ),
    )
    second_measured_epsilon: float | None = field(
        default=None,
        metadata=option(
            "--second-measured-epsilon",
            "A second measured coefficient of restitution, at --second-measured-speed: with "
            "the first, it fixes both the relaxation time and the limiting pressure (spheres).",
        ),
    )
    second_measured_speed: float | None = field(
        default=None,
        metadata=option(
            "--second-measured-speed",
            "Impact speed of --second-measured-epsilon, m/s.",
            unit="m/s",
            positive=True,
        ),
    )
    compute: bool = field(
        default=False,
        metadata=option(
            "--compute",
            "Compute the law of this material's exact Poisson number with the production "
            "settings when none is shipped for it (instead of interpolating in nu): minutes to "
            "hours, stated before it starts, with a progress bar; every collision goes to the "
            "result store (--store; an interrupted run resumes) and the law file to the cache, "
            "where the next call finds it.",
            "flag",
        ),
    )
    route: str | None = field(
        default=None,
        metadata=option(
            "--route",
            "With --compute: how the collisions reach many modes: 'modal' (default; windows of "
            "up to 10^5 modes extrapolated in N, as the shipped laws) or 'residual' (200-800 "
            "kept modes, the faster ones static: a few minutes on two cores; docs/numerics.md). "
            "The law says which route made it.",
            "choice",
            choices=lambda: list(ROUTES),
        ),
    )
    store: Path | None = field(
        default=None,
        metadata=option(
            "--store",
            "With --compute: the result store [results.sqlite in the user cache].",
            "path",
        ),
    )
    force: bool = field(
        default=False,
        metadata=option(
            "--force",
            "With --compute: compute even when the estimate exceeds the bound of one run (1 h).",
            "flag",
        ),
    )

    def __post_init__(self) -> None:
        # Each field alone first, by its option's kind, in the command's words and the Python
        # keyword's (issue 47: "speeds ... array([ 1., -1.])"; wall_E=True took 13 GiB), then
        # the options together.
        for f in fields(self):
            object.__setattr__(self, f.name, checked(f, getattr(self, f.name)))
        if self.reference_speed is not None and self.maxwell_temperature is not None:
            raise InputError("give --reference-speed or --maxwell-temperature, not both")
        if self.friction is not None:
            if self.friction < 0.0:
                raise InputError(f"--friction must be a number >= 0, got {self.friction!r}")
            if self.export_dir is None:
                raise InputError("--friction goes into the DEM snippets: add --export DIR")
        self._check_ratio()
        self._check_damping()
        other = self.partner_grain
        if other is not None and self.damped:
            raise InputError(
                "material damping of grains of two materials is not modelled (each material has "
                "its own relaxation time); leave out the damping options or the partner material"
            )
        if self.identical_law_file is not None or self.partner_identical_law_file is not None:
            self._check_identical_law_files()
        if self.elastic_wall is not None:
            self._check_elastic_wall()
        if self.plastic or self.measured_fixes is not None or self.fixes_both:
            self._check_plastic()
        if self.compute and self.law_file is not None:
            raise InputError("give --law-file or --compute, not both")
        if not self.compute and (self.store is not None or self.force or self.route):
            raise InputError(
                "--store, --force and --route belong to --compute; add --compute or leave them out"
            )
        if self.route == "residual" and self.store is not None:
            raise InputError(
                "--store holds the modal route's collisions; the residual route keeps its "
                "points in the cache: leave out --store or --route residual"
            )
        # Last, so that a refused request is refused in one line: numbers outside the range
        # of real grains and walls (a 5 m grain, a yield stress above any metal's) warn once.
        warn_implausible(self)

    # -- what the options amount to -------------------------------------------------------------

    @property
    def grain(self) -> Grain:
        """This grain (checks ``E``, ``nu``, ``rho`` and the geometry)."""
        return Grain(E=self.E, nu=self.nu, rho=self.rho, shape=self.shape)

    @property
    def radius_ratio(self) -> float | None:
        """The radius ratio the law takes: ``None`` for identical grains or a wall; ``1`` (or
        ``None``) for two materials of one size."""
        ratio = self.partner_radius_ratio
        if self.partner_grain is not None:
            return ratio
        return None if ratio is None or ratio == 1.0 else ratio

    @property
    def partner_grain(self) -> Grain | None:
        """The partner grain's material from the partner options (each defaulting to this
        grain's), or ``None`` without them or for the same material."""
        given = (self.partner_E, self.partner_nu, self.partner_rho)
        if given == (None, None, None):
            return None
        if self.against != "grain":
            raise InputError(
                "--partner-E, --partner-nu and --partner-rho describe a second grain: give them "
                "with --against grain"
            )
        kind = body_kind(BODIES[self.shape])
        if kind.pair_compression is None:
            raise InputError(
                f"laws of two {kind.geometry}s of different materials are not computed yet; use "
                f"--shape {_paired_shapes()}, or leave out "
                "--partner-E/--partner-nu/--partner-rho"
            )
        values = tuple(
            own if theirs is None else theirs
            for own, theirs in zip((self.E, self.nu, self.rho), given, strict=True)
        )
        if values == (self.E, self.nu, self.rho):
            return None
        try:
            other = Grain(E=values[0], nu=values[1], rho=values[2], shape=self.shape)
        except InputError as exc:
            raise InputError(
                f"the partner's material: {exc} (of --partner-E {values[0]:g} Pa, --partner-nu "
                f"{values[1]:g}, --partner-rho {values[2]:g} kg/m^3, each this grain's where not "
                "given)"
            ) from None
        self._check_partner_ratios(values)
        return other

    def _check_partner_ratios(self, values) -> None:
        """The partner's modulus and density within what a pair takes (:data:`restitution.
        bodies.pair.partner.RATIO_RANGE`), refused in Pa and kg/m^3 with the options given."""
        from restitution.bodies.pair.partner import RATIO_RANGE

        lo, hi = RATIO_RANGE
        for opt, own, value, mine, unit in (("--partner-E", "--E", values[0], self.E, "Pa"),
                                            ("--partner-rho", "--rho", values[2], self.rho,
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

    @property
    def elastic_wall(self):
        """The elastic half-space of the wall options (:class:`restitution.bodies.wall.
        HalfSpace`, in this grain's units), ``None`` without them (a rigid wall)."""
        given = (self.wall_E, self.wall_nu, self.wall_rho)
        if given == (None, None, None):
            if self.wall_thickness is not None:
                raise InputError(
                    "--wall-thickness describes a plate: give it with --wall-E, --wall-nu and "
                    "--wall-rho"
                )
            return None
        if None in given:
            raise InputError(
                "--wall-E, --wall-nu and --wall-rho describe an elastic wall together; give all "
                "three (or none for a rigid wall)"
            )
        from restitution.bodies.wall import HalfSpace, Plate

        self._check_wall_numbers()
        ratios = (self.wall_E / self.E, self.wall_rho / self.rho, self.wall_nu)
        try:
            if self.wall_thickness is None:
                return HalfSpace(*ratios)
            return Plate(*ratios, thickness=self.wall_thickness / self.radius)
        except InputError as exc:
            raise InputError(f"the wall: {exc}") from None

    def _check_wall_numbers(self) -> None:
        """The wall's numbers against what the wall's bodies take (:data:`WALL_RATIOS`,
        :data:`PLATE_RADII`), refused in the options' units and words: the wall's modulus and
        density against the grain's, a plate's thickness against the ball's radius (naming the
        one of the two outside the range of real grains and plates, :data:`restitution.laws.
        request_fields.PLAUSIBLE`)."""
        lo, hi = WALL_RATIOS
        for opt, own, value, mine, unit in (("--wall-E", "--E", self.wall_E, self.E, "Pa"),
                                            ("--wall-rho", "--rho", self.wall_rho, self.rho,
                                             "kg/m^3")):  # fmt: skip
            ratio = value / mine
            if not lo <= ratio <= hi:
                raise InputError(
                    f"{opt} {value:g} {unit} is {ratio:.3g} times {own} {mine:g} {unit}, beyond "
                    f"the {lo:g} ... {hi:g} times the grain's an elastic wall takes; check {opt} "
                    f"and its units ({unit}), or leave out the wall options for a rigid wall"
                )
        if not -1.0 < self.wall_nu < 0.5:
            raise InputError(
                f"the wall's Poisson number must lie in (-1, 0.5), got --wall-nu {self.wall_nu:g}"
            )
        if self.wall_thickness is None:
            return
        if self.radius is None:
            raise InputError("a plate (--wall-thickness) needs the ball's --radius, m")
        lo, hi = PLATE_RADII
        radii = self.wall_thickness / self.radius
        if not lo <= radii <= hi:
            culprit = "; ".join(
                text for text in doubts(self) if text.startswith(("--radius", "--wall-thickness"))
            )
            culprit = culprit or "check --wall-thickness and --radius (both in m)"
            raise InputError(
                f"--wall-thickness {self.wall_thickness:g} m is {radii:.3g} times --radius "
                f"{self.radius:g} m; a plate takes {lo:g} ... {hi:g} radii of the ball: {culprit}"
            )

    def _check_elastic_wall(self) -> None:
        if self.against != "wall":
            raise InputError(
                "--wall-E, --wall-nu and --wall-rho describe an elastic wall: give them with "
                "--against wall"
            )
        if body_kind(BODIES[self.shape]).planar:
            raise InputError(
                "an elastic wall is computed for spheres (a sphere on a half-space); use --shape "
                "sphere, or leave out the wall options (a rigid wall)"
            )
        if self.radius is not None and self.wall_thickness is None and not self.damped:
            raise InputError(
                "--radius goes with --wall-thickness (a plate) or --relaxation-time; a "
                "half-space needs no radius: leave it out"
            )
        needs = [what for what, asked in (("damping", self.damped),
                 ("--law-file", self.law_file is not None),
                 ("--compute", self.compute)) if asked]  # fmt: skip
        if needs:
            raise InputError(
                f"{' and '.join(needs)} with an elastic wall: not available yet (the wall's law "
                "comes from its routes, computed now); leave them out"
            )
        # A wall so soft that the slowest speed sinks the ball into it: refused in Pa and m/s
        # before any route runs (--wall-E 63, GPa typed as Pa, once took 6 GB).
        check_wall_request(self.grain, self.elastic_wall, self.speeds, self.wall_E)

    @property
    def damped(self) -> bool:
        """Whether damping is asked: a relaxation time, or a measurement that fixes it."""
        if self.fixes_both:
            return True
        if self.fixes_limiting_pressure:
            return self.relaxation_time is not None
        return (self.measured_epsilon, self.measured_speed, self.relaxation_time) != (None,) * 3

    @property
    def fixes_limiting_pressure(self) -> bool:
        """Whether the measurement fixes the limiting pressure (not the relaxation time)."""
        return self.measured_fixes == "limiting-pressure"

    @property
    def measured_speeds(self) -> tuple[float, ...]:
        """The measured speeds a plastic answer computes the elastic law at besides the asked
        ones (a law computed at the asked speeds only: a pair's route, an elastic wall)."""
        if not self.plastic:
            return ()
        given = (self.measured_speed, self.second_measured_speed)
        return tuple(w for w in given if w is not None)

    @property
    def fixes_both(self) -> bool:
        """Whether two measurements fix the relaxation time and the limiting pressure."""
        return (
            self.measured_fixes == "both"
            or self.second_measured_epsilon is not None
            or (self.second_measured_speed is not None)
        )

    @property
    def plastic(self) -> bool:
        """Whether plastic flow is asked: a yield stress, a limiting pressure, or a measurement
        that fixes it."""
        given = (self.yield_stress, self.partner_yield_stress, self.limiting_pressure)
        return given != (None,) * 3 or self.fixes_limiting_pressure or self.fixes_both

    def _check_damping(self) -> None:
        """The damping options together: a measurement is an epsilon and a speed; a relaxation
        time needs the radius (and a radius alone means nothing, but a plate's or an elastic
        wall's, whose checks say so); a measurement that fixes the relaxation time and the
        relaxation time given are one too many."""
        if (self.measured_epsilon is None) != (self.measured_speed is None):
            raise InputError("--measured-epsilon and --measured-speed go together; give both")
        if self.relaxation_time is not None and self.radius is None:
            raise InputError(
                "--relaxation-time needs --radius (m): the viscous loss depends on tau c / R"
            )
        if (
            self.radius is not None
            and self.relaxation_time is None
            and self.measured_epsilon is None
            and (self.wall_thickness is None and self.wall_E is None)
        ):
            raise InputError(
                "--radius goes with --relaxation-time or --measured-epsilon (damping); give "
                "damping or leave out --radius"
            )
        if (self.relaxation_time is not None and self.measured_epsilon is not None
                and self.measured_fixes not in ("limiting-pressure", "both")):  # fmt: skip
            raise InputError(
                "give --relaxation-time (with --radius) or --measured-epsilon with "
                "--measured-speed, not both (or let the measurement fix the limiting pressure: "
                "--measured-fixes limiting-pressure)"
            )

    def _check_plastic(self) -> None:
        asked = self.measured_fixes is not None or self.fixes_both
        if asked and None in (self.measured_epsilon, self.measured_speed):
            raise InputError(
                "--measured-fixes says what --measured-epsilon fixes: give it with "
                "--measured-epsilon and --measured-speed"
            )
        if self.fixes_both:
            second = (self.second_measured_epsilon, self.second_measured_speed)
            if None in second:
                raise InputError(
                    "two measurements fix both parameters: give --second-measured-epsilon and "
                    "--second-measured-speed with the first measurement"
                )
            if self.measured_fixes not in (None, "both"):
                raise InputError(
                    f"two measurements fix both parameters, not only the {self.measured_fixes}: "
                    "leave out --measured-fixes or the second measurement"
                )
            given = [name for name, value in (("--yield-stress", self.yield_stress),
                     ("--partner-yield-stress", self.partner_yield_stress),
                     ("--limiting-pressure", self.limiting_pressure),
                     ("--relaxation-time", self.relaxation_time)) if value is not None]  # fmt: skip
            if given:
                raise InputError(
                    f"two measurements fix the relaxation time and the limiting pressure: leave "
                    f"out {', '.join(given)}"
                )
        if not self.plastic:
            return
        if self.shape in BODIES and body_kind(BODIES[self.shape]).planar:
            raise InputError(
                "plastic flow is computed for spheres (Thornton's contact); no comparable law of "
                "cylinders or disks is derived (docs/plasticity.md): use --shape sphere, or "
                "leave out the plastic options"
            )
        if self.wall_thickness is not None:
            raise InputError(
                "plastic flow on a thin plate is not modelled (Zener's plate model is elastic); "
                "leave out --wall-thickness (a half-space) or the plastic options"
            )
        if self.fixes_limiting_pressure and (self.yield_stress, self.partner_yield_stress,
                                             self.limiting_pressure) != (None,) * 3:  # fmt: skip
            raise InputError(
                "one measurement fixes one parameter: give the yield stress (or limiting "
                "pressure), or let --measured-fixes limiting-pressure fix it, not both"
            )
        needs = [what for what, asked in (("--export", self.export_dir is not None),
                 ("--reference-speed/--maxwell-temperature", self.constants),
                 ("--compute", self.compute)) if asked]  # fmt: skip
        if needs:
            raise InputError(
                f"{' and '.join(needs)} with plastic flow: not available yet (the plastic law is "
                "computed at the asked speeds only); leave them out"
            )

    @property
    def constants(self) -> bool:
        """Whether a constant for one-number codes is asked for."""
        return (self.reference_speed, self.maxwell_temperature) != (None, None)

    def inputs(self) -> dict:
        """The request as given, with units in the keys (a command's JSON ``inputs``)."""
        path = lambda p: None if p is None else str(p)  # noqa: E731
        return {
            "E": self.E, "nu": self.nu, "rho": self.rho, "shape": self.shape,
            "against": self.against, "partner_radius_ratio": self.partner_radius_ratio,
            "partner_E": self.partner_E, "partner_nu": self.partner_nu,
            "partner_rho": self.partner_rho, "speeds_m_s": list(self.speeds),
            "law_file": path(self.law_file),
            "identical_law_file": path(self.identical_law_file),
            "partner_identical_law_file": path(self.partner_identical_law_file),
            "reference_speed": self.reference_speed,
            "maxwell_temperature": self.maxwell_temperature, "export": path(self.export_dir),
            "friction": self.friction,
            "measured_epsilon": self.measured_epsilon,
            "measured_speed_m_s": self.measured_speed,
            "relaxation_time_s": self.relaxation_time, "radius_m": self.radius,
            "wall_E": self.wall_E, "wall_nu": self.wall_nu, "wall_rho": self.wall_rho,
            "wall_thickness_m": self.wall_thickness,
            "yield_stress_pa": self.yield_stress,
            "partner_yield_stress_pa": self.partner_yield_stress,
            "limiting_pressure_pa": self.limiting_pressure,
            "measured_fixes": self.measured_fixes,
            "second_measured_epsilon": self.second_measured_epsilon,
            "second_measured_speed_m_s": self.second_measured_speed,
            "compute": self.compute,
            "route": self.route,
        }  # fmt: skip

    # -- refusals -------------------------------------------------------------------------------

    def _check_ratio(self) -> None:
        ratio = self.partner_radius_ratio
        if ratio is None:
            return
        if not (math.isfinite(ratio) and ratio > 0):
            raise InputError(
                "--partner-radius-ratio must be a positive number R2/R1 (1 = identical grains), "
                f"got {ratio:g}"
            )
        if self.against != "grain":
            raise InputError(
                "--partner-radius-ratio describes a second grain: give it with --against "
                "grain, or leave it out against a wall"
            )
        if ratio == 1.0 or self.shape not in BODIES:
            return
        from restitution.bodies.pair.partner import RATIO_RANGE

        lo, hi = RATIO_RANGE
        if not lo <= ratio <= hi:
            raise InputError(
                f"--partner-radius-ratio {ratio:g}: {self.unequal_sizes()}; a pair takes "
                f"{lo:g} ... {hi:g}"
            )
        kind = body_kind(BODIES[self.shape])
        if kind.pair_compression is None:
            raise InputError(
                f"--partner-radius-ratio {ratio:g}: laws of two {kind.geometry}s of different "
                f"sizes are not computed yet; use --shape {_paired_shapes()}, or leave it out "
                f"(identical {kind.geometry}s)"
            )

    def unequal_sizes(self) -> str:
        """What answers two grains too unequal in size for a pair (a sentence with the options
        that ask it): the smaller grain on an elastic wall of the larger one's material, which
        is to it a half-space (the larger grain's waves come back after the contact)."""
        ratio = self.partner_radius_ratio
        big = max(ratio, 1.0 / ratio)
        mine = (self.E, self.nu, self.rho)
        theirs = tuple(own if given is None else given for own, given in
                       zip(mine, (self.partner_E, self.partner_nu, self.partner_rho),
                           strict=True))  # fmt: skip
        head = f"the larger grain is {big:g} times the smaller's radius"
        if body_kind(BODIES[self.shape]).planar:
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
                f"--shape {self.shape} {wall.format(*mine)}"
            )
        return (
            f"{head}: to the smaller grain the larger one is an elastic half-space (the waves "
            f"reflected inside it return only after the contact), and w the smaller grain's "
            f"speed towards it; ask for {ask}"
        )

    def _check_identical_law_files(self) -> None:
        if self.partner_identical_law_file is not None and self.partner_grain is None:
            raise InputError(
                "--partner-identical-law-file serves the 2-2 constant of a partner of another "
                "material: give it with --partner-E/--partner-nu/--partner-rho"
            )
        if self.radius_ratio is None and self.partner_grain is None:
            raise InputError(
                "--identical-law-file serves the 1-1 and 2-2 constants of two grain sizes: give "
                "it with --partner-radius-ratio other than 1 (identical grains take --law-file)"
            )
        if not self.constants:
            raise InputError(
                "--identical-law-file and --partner-identical-law-file serve the constants per "
                "type pair: give them with --reference-speed or --maxwell-temperature"
            )


def _paired_shapes() -> str:
    """The shapes whose laws of two grains of different sizes or materials are computed."""
    names = [shape for shape, body in BODIES.items() if body_kind(body).pair_compression]
    return " or ".join(names)


def option_fields():
    """The fields of :class:`LawRequest` in the order of their options."""
    return fields(LawRequest)
