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
or a one-line refusal naming the option and the keyword), then the options together
(:mod:`restitution.laws.request_checks`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from pathlib import Path

from restitution.bodies.kinds import body_kind
from restitution.errors import InputError
from restitution.laws.partners.base import against_choices, owner, partner_for
from restitution.laws.request_checks import (
    OBLIQUE_OWN,
    check_options,
    check_partner_ratios,
    check_wall_numbers,
    paired_shapes,
    unequal_sizes_advice,
)
from restitution.laws.request_fields import checked, option, warn_implausible
from restitution.laws.units import BODIES, SHAPES, Grain

__all__ = ["DEFAULT_SPEEDS_M_S", "MEASURED_FIXES", "LawRequest", "option_fields", "request"]

DEFAULT_SPEEDS_M_S: tuple[float, ...] = (0.1, 0.5, 1.0, 5.0, 10.0)
"""Impact speeds (m/s) of a request that names none."""

MEASURED_FIXES = ("relaxation-time", "limiting-pressure", "both")
"""What one measured epsilon may fix (``--measured-fixes``)."""

ROUTES = ("modal", "residual")


def friction_models() -> tuple[str, ...]:
    """``--friction-model``'s choices, the default first: the registered friction routes'
    names (:mod:`restitution.dynamics.friction`)."""
    from restitution.dynamics.friction import friction_names

    return friction_names()


def _friction_help() -> str:
    """``--friction-model``'s help, from the registered routes' own sentences."""
    from restitution.dynamics.friction import routes_help

    return f"With --angle: {routes_help()}."


"""``--route`` of ``--compute``: the modal production or the static residual
(:mod:`restitution.laws.making.residual_law`)."""


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
            choices=lambda: list(against_choices()),
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
    angle: float | None = field(
        default=None,
        metadata=option(
            "--angle",
            "Oblique impact on the rigid wall: the angle of incidence from the wall's normal, "
            "degrees, in [0, 90), with --friction MU. Each speed w is the normal speed (the "
            "tangential one is w tan(angle), no spin before); the answer is epsilon_normal, "
            "beta, the spin after and the friction work, each with the change from half the "
            "modes as its error, computed by the modal oblique route (docs/oblique.md; "
            "cylinder, thin disk and sphere: 160 and 80 modes of the disk, 40 and 20 of the "
            "sphere, about a minute a speed). --radius adds the spin in rad/s. Several angles "
            "and the DEM codes' tangential parameters fitted to them: restitution oblique-fit.",
            unit="deg",
        ),
    )
    friction: float | None = field(
        default=None,
        metadata=option(
            "--friction",
            "Sliding friction coefficient mu: with --angle, Coulomb's coefficient of the "
            "oblique impact computed; otherwise the one the DEM snippets and the LAMMPS "
            "plugin's lines of --export set (LAMMPS: Mindlin's tangential spring; default "
            "none: they set mu = 0 and say so).",
        ),
    )
    friction_model: str | None = field(
        default=None,
        metadata=option(
            "--friction-model",
            _friction_help,
            "choice",
            choices=lambda: list(friction_models()),
        ),
    )
    kappa: float | None = field(
        default=None,
        metadata=option(
            "--kappa",
            "With --friction-model microslip: the tangential spring over the wall's normal "
            "stiffness at each node (Coulomb's law is kappa -> infinity); default 64.",
            positive=True,
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
            "state tau in seconds and export the DEM codes' viscoelastic contact, or with "
            "--export to set the DEM snippets' time step in seconds; for two sizes the smaller "
            "grain's). The elastic law needs no radius; the viscous loss depends on tau c / R.",
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
    extra: tuple = field(
        default=(),
        metadata=option(
            "--extra",
            "The options of the mechanisms registered beside these fields (each its own "
            "command-line option, e.g. --work-of-adhesion; restitution.laws.mechanisms): "
            "(keyword, value) pairs or a mapping; request(...) takes them as keywords.",
            "extra",
        ),
    )

    def __post_init__(self) -> None:
        # Each field alone first, by its option's kind, in the command's words and the Python
        # keyword's (issue 47: "speeds ... array([ 1., -1.])"; wall_E=True took 13 GiB), then
        # the options together (restitution.laws.request_checks).
        for f in fields(self):
            object.__setattr__(self, f.name, checked(f, getattr(self, f.name)))
        check_options(self)
        # Last, so that a refused request is refused in one line: numbers outside the range
        # of real grains and walls (a 5 m grain, a yield stress above any metal's) warn once.
        warn_implausible(self)

    # -- what the options amount to -------------------------------------------------------------

    def option_value(self, keyword: str):
        """The value of the option ``keyword``: a field's, or a mechanism's own option (its
        ``extra``); ``None`` when it is not given."""
        if keyword in _FIELD_NAMES:
            return getattr(self, keyword)
        return dict(self.extra).get(keyword)

    def head_on(self) -> LawRequest:
        """This request without the oblique impact's own fields (:data:`~restitution.laws.
        request_checks.OBLIQUE_OWN`): the head-on law of the same grain at the same speeds."""
        from dataclasses import replace

        return replace(self, **dict.fromkeys(OBLIQUE_OWN))

    @property
    def oblique_friction_model(self) -> str | None:
        """With ``angle``: ``friction_model`` or the law's default route for this grain's kind
        (:func:`restitution.dynamics.friction.law_default`: the residual route for the sphere,
        stick-slip for the disk); else ``None``."""
        if self.angle is None:
            return None
        if self.friction_model is not None:
            return self.friction_model
        from restitution.dynamics.friction import law_default

        return law_default(body_kind(BODIES[self.shape])).name

    @property
    def oblique_route(self):
        """With ``angle``: the friction route (:mod:`restitution.dynamics.friction`) of
        :attr:`oblique_friction_model`; else ``None``."""
        if self.angle is None:
            return None
        from restitution.dynamics.friction import friction_route

        return friction_route(self.oblique_friction_model)

    @property
    def oblique_kappa(self) -> float | None:
        """With ``angle`` and a route that takes ``kappa`` (microslip): ``kappa`` or its
        default; else ``None``."""
        route = self.oblique_route
        if route is None or not route.takes_kappa:
            return None
        from restitution.dynamics.oblique_microslip import MicroslipSettings

        return MicroslipSettings().kappa if self.kappa is None else self.kappa

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
        if self.against != owner("partner_E").against:
            raise InputError(
                "--partner-E, --partner-nu and --partner-rho describe a second grain: give them "
                "with --against grain"
            )
        kind = body_kind(BODIES[self.shape])
        if kind.pair_compression is None:
            raise InputError(
                f"laws of two {kind.geometry}s of different materials are not computed yet; use "
                f"--shape {paired_shapes()}, or leave out "
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
        check_partner_ratios(self, values)
        return other

    @property
    def partner_kind(self):
        """The partner kind this request asks for (:func:`restitution.laws.partners.base.
        partner_for`: the first whose ``matches`` holds)."""
        return partner_for(self)

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

        check_wall_numbers(self)
        ratios = (self.wall_E / self.E, self.wall_rho / self.rho, self.wall_nu)
        try:
            if self.wall_thickness is None:
                return HalfSpace(*ratios)
            return Plate(*ratios, thickness=self.wall_thickness / self.radius)
        except InputError as exc:
            raise InputError(f"the wall: {exc}") from None

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

    @property
    def oblique(self) -> bool:
        """Whether an oblique impact is asked (``--angle``; :mod:`restitution.laws.oblique`)."""
        return self.angle is not None

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
            **({} if self.angle is None else {"angle_deg": self.angle,
                                                 "friction_model": self.oblique_friction_model,
                                                 "kappa": self.oblique_kappa}),
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
            **{f"{k}_{_unit_key(k)}" if _unit_key(k) else k: v for k, v in self.extra},
        }  # fmt: skip

    def unequal_sizes(self) -> str:
        """What answers two grains too unequal in size for a pair (a sentence with the options
        that ask it): the smaller grain on an elastic wall of the larger one's material, which
        is to it a half-space (the larger grain's waves come back after the contact)."""
        return unequal_sizes_advice(self)


_FIELD_NAMES = frozenset(f.name for f in fields(LawRequest))


def _unit_key(keyword: str) -> str:
    """The unit of a mechanism's option as a JSON key's suffix (``J/m^2`` -> ``j_m2``)."""
    from restitution.laws.mechanisms.base import extra_options

    unit = next((o.unit for o in extra_options() if o.keyword == keyword), "")
    return unit.lower().replace("/", "_").replace("^", "")


def request(**options) -> LawRequest:
    """The :class:`LawRequest` of ``options``: its fields, and the options of the registered
    mechanisms (:func:`restitution.laws.mechanisms.base.extra_options`, e.g.
    ``work_of_adhesion=0.1``) as keywords too; an unknown keyword is refused in one line."""
    extra = dict(options.pop("extra", None) or ())
    extra.update({k: options.pop(k) for k in list(options) if k not in _FIELD_NAMES})
    return LawRequest(**options, extra=extra)


def option_fields():
    """The fields of :class:`LawRequest` in the order of their options."""
    return fields(LawRequest)
