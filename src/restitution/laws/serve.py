"""Serve a :class:`~restitution.laws.request.LawRequest`: the one library call behind ``law``.

Units: SI (m/s; the law's own answer carries its units, :data:`restitution.laws.si_point.SI_UNITS`).

:func:`serve` decides which law answers (a shipped one, one computed on demand with
``compute=True``, a given file), adds material damping, the constants for one-number DEM codes
(per pair of particle types for two grains) and writes the exports; it returns a
:class:`LawAnswer`, the same object for a notebook as for the command line, whose
:meth:`LawAnswer.to_dict` is the command's JSON. Notes (what was computed, what was left out)
go to the ``note`` callable instead of a terminal.

Example
-------
>>> from restitution.laws.request import LawRequest
>>> a = serve(LawRequest(E=63e9, nu=0.2481, rho=2500, geometry="cylinder", against="wall",
...                      speeds=(1.0,)))
>>> 0.99 < a.points[0].epsilon < 1.0
True
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from restitution.atomic import writing
from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws import routes as _routes  # noqa: F401  (registers the routes)
from restitution.laws.damped import DampedLaw, damped_law
from restitution.laws.mechanisms import flag_points
from restitution.laws.plastic import PlasticLaw
from restitution.laws.request import LawRequest
from restitution.laws.routes.base import check_speed_count, route_for
from restitution.laws.si_law import SILaw, si_law
from restitution.laws.si_point import SI_UNITS, overall_status
from restitution.limits.run_options import Progress
from restitution.status import Status

__all__ = ["LawAnswer", "serve"]


def _silent(text: str) -> None:
    """The default ``note``: say nothing."""


@dataclass(frozen=True, eq=False)
class LawAnswer:
    """What :func:`serve` gives: the law, its points at the asked speeds and what was made of it.

    Attributes
    ----------
    request : LawRequest
    law : SILaw
        The elastic law that served (for a damping grain: the law the damping was added to).
    damped : DampedLaw or None
        The damping grain's law (elastic and viscous parts), when damping was asked for.
    points : tuple
        One point per asked speed (:class:`~restitution.laws.si_point.SIPoint`, or
        :class:`~restitution.laws.damped.DampedPoint` for a damping grain).
    status, advice : str, str or None
        The answer's status (the worst of its points') and what to do about it.
    constant : Constant or None
        The constant for one-number codes (for two grains: the 1-2 pair's).
    pairs : TypePairs or None
        The constants per pair of particle types (two grain sizes or materials).
    exports : tuple of Path
        The files written (``export_dir``).
    units : dict
        The units of every number.
    """

    request: LawRequest
    law: SILaw
    damped: DampedLaw | None
    points: tuple
    status: str
    advice: str | None
    constant: object | None = None
    pairs: object | None = None
    exports: tuple = ()
    units: dict = field(default_factory=lambda: dict(SI_UNITS))
    plastic: PlasticLaw | None = None

    def to_dict(self) -> dict:
        """The answer as the ``law`` command's JSON gives it (without the envelope): the law's
        own (the mechanisms it contains among them), with the answer's points."""
        speeds = list(self.request.speeds)
        if self.plastic is not None:
            out = self.plastic.to_dict(speeds, self.points)
        elif self.damped is not None:
            out = self.damped.to_dict(speeds, self.points)
        else:
            out = self.law.to_dict(speeds)
            out["points"] = [p.to_dict() for p in self.points]
        if self.constant is not None:
            out["constant"] = self.constant.to_dict()
        if self.pairs is not None:
            out["type_pairs"] = self.pairs.to_dict()
        if self.request.export_dir is not None:
            out["exports"] = [str(p) for p in self.exports]
        return out


def serve(
    request: LawRequest, *, note: Callable[[str], None] = _silent, progress: bool = False
) -> LawAnswer:
    """The answer to ``request`` (module docs).

    Parameters
    ----------
    request : LawRequest
        The question; its construction refused inconsistent options already.
    note : callable, optional
        Called with one line for each note (the estimate of a computation, a closed form that
        could not be fitted); default: none.
    progress : bool
        Show a progress bar of a computation on stderr (``compute``), and, on a terminal, of
        a damped law's viscous collisions (inferring its relaxation time; tabulating it for
        the exports or constants, which a note announces with their number).

    Raises
    ------
    InputError
        When no law can serve (a Poisson number off the grid, two materials without a law),
        with the command or option that makes one.
    """
    r = request
    s = route_for(r).law(r, note, progress)
    if r.plastic:
        return _plastic_answer(r, s, note)
    bars = Progress(None if progress else False)  # the damped law's: on a terminal only
    damped = _damped(r, s, bars)
    if damped is not None and s.law.partner is not None and r.constants:
        raise InputError(
            "constants per type pair of damping grains are not computed (tau c / R differs for "
            "the two sizes); drop --reference-speed/--maxwell-temperature, or the damping"
        )
    points = damped.points(list(r.speeds)) if damped else s.points(list(r.speeds), note=note)
    points, _ = flag_points(s, points)
    status, advice = overall_status(points)
    if damped is not None and (r.constants or r.export_dir is not None):
        # Constants, tables and snippets of the damped law: the sum at every computed speed.
        what = "exports" if r.export_dir is not None else "constant"
        note(
            f"note: the damped law for the {what}: {damped.table_collisions()} viscous "
            "collisions at the elastic law's computed speeds"
        )
        s = damped.as_si_law(progress=bars)
    constant, pairs = _constants(r, s)
    model = None if r.export_dir is None else _viscoelastic(r, damped, note)
    written = _write_exports(r, s, pairs or constant, model, note)
    return LawAnswer(r, s, damped, points, status, advice, constant, pairs, written)


def _write_exports(r: LawRequest, s: SILaw, constant, model, note) -> tuple:
    """The export folder of ``s`` when ``--export`` is asked (its paths), else ``()``."""
    if r.export_dir is None:
        return ()
    with writing(r.export_dir, "--export"):  # a full disk names the option and the folder
        folder = exports.write_folder(s, constant, r.export_dir, model, r.friction)
    if folder.no_closed_form is not None:
        note(f"note: no closed form written: {folder.no_closed_form}")
    if folder.no_plugin is not None:
        note(f"note: no LAMMPS plugin tables written: {folder.no_plugin}")
    return tuple(folder.paths)


def _viscoelastic(r: LawRequest, damped: DampedLaw | None, note):
    """The damped sphere law as the DEM codes' viscoelastic model for the exports
    (:func:`restitution.laws.exports.viscoelastic.viscoelastic_model`, the part it drops at the
    asked speeds), or ``None`` (no damping, or a body or pair it does not describe: noted)."""
    if damped is None:
        return None
    from restitution.laws.exports.viscoelastic import viscoelastic_model

    try:
        return viscoelastic_model(damped, r.speeds)
    except InputError as exc:
        note(f"note: no viscoelastic DEM snippets: {exc}")
        return None


PLASTIC_SECONDS_PER_SPEED = 2.0
"""Wall time of one speed of a plastic answer (three force pulses and the spectra of the modes
they drive), seconds: 1-2 s measured on the project's 2-core machine (steel, 1 mm/s to 100 m/s;
slowest at the lowest speeds, whose pulses are longest)."""


def _plastic_answer(r: LawRequest, s: SILaw, note) -> LawAnswer:
    """The answer with plastic flow: the limiting pressure given or inferred, the relaxation
    time given or inferred with the plastic flow on (one measurement fixes one of them)."""
    from restitution.laws.plastic import (
        fit_two_measurements,
        infer_relaxation_time,
        plastic_law,
    )

    check_speed_count(len(r.speeds), PLASTIC_SECONDS_PER_SPEED, "plastic flow on one pulse")
    # The request refused what does not go together (request_checks._check_damping).
    tau = 0.0 if r.relaxation_time is None else r.relaxation_time * s.grain.c_m_s / r.radius
    measured = r.measured_epsilon is not None
    if r.fixes_both:
        note("note: fitting the relaxation time and the limiting pressure to the two "
             "measurements (nested root searches of the contact; half a minute)")  # fmt: skip
        law = fit_two_measurements(
            s,
            (r.measured_epsilon, r.measured_speed),
            (r.second_measured_epsilon, r.second_measured_speed),
        )
    elif r.fixes_limiting_pressure:
        note("note: inferring the limiting pressure from the measurement (root searches of the "
             "contact; seconds)")  # fmt: skip
        law = plastic_law(s, tau=tau, measured_epsilon=r.measured_epsilon,
                          measured_speed_m_s=r.measured_speed)  # fmt: skip
    else:
        law = plastic_law(s, yield_stress_pa=r.yield_stress,
                          partner_yield_stress_pa=r.partner_yield_stress,
                          limiting_pressure_pa=r.limiting_pressure, tau=tau)  # fmt: skip
        if measured:
            note("note: inferring the relaxation time from the measurement with the plastic "
                 "flow on (root searches of the contact; seconds)")  # fmt: skip
            law = infer_relaxation_time(law, r.measured_epsilon, r.measured_speed)
    note("note: plastic flow: each speed is computed now on one force pulse (about a second a "
         "speed)")  # fmt: skip
    points = law.points(list(r.speeds))
    status, advice = _plastic_status(points)
    return LawAnswer(r, s, None, points, status, advice, plastic=law)


def _plastic_status(points) -> tuple[str, str | None]:
    """:func:`~restitution.laws.si_point.overall_status`, whose advice for ``outside`` speaks of
    the law's range, saying instead where a speed has no value because the grain does not
    rebound (its contact computed, its losses above the impact energy)."""
    status, advice = overall_status(points)
    stuck = [p for p in points if p.epsilon is None and p.epsilon_contact is not None]
    if status != Status.OUTSIDE or not stuck:
        return status, advice
    advice = (
        f"{len(stuck)} of {len(points)} speeds: no rebound, the losses exceed the impact energy "
        "(each point's note has them)"
    )
    beyond = sum(p.status == Status.OUTSIDE for p in points) - len(stuck)
    if beyond:
        advice += f"; {beyond}: outside the computed range of the law"
    return status, advice


def _constants(r: LawRequest, s: SILaw):
    """``(constant, pairs)``: the constant for one-number codes and, for two grains, the
    constants per pair of particle types (the pair's own is the 1-2 one)."""
    if not r.constants:
        return None, None
    if s.law.partner is not None:
        identical = _identical(r.E, r.nu, r.rho, r.shape, r.identical_law_file,
                               "--identical-law-file")  # fmt: skip
        other = r.partner_grain
        identical2 = None
        if other is not None:
            identical2 = _identical(other.E, other.nu, other.rho, r.shape,
                                    r.partner_identical_law_file,
                                    "--partner-identical-law-file")  # fmt: skip
        pairs = exports.type_pair_constants(
            s,
            identical,
            speed_m_s=r.reference_speed,
            temperature_m2_s2=r.maxwell_temperature,
            identical2=identical2,
        )
        return pairs.mixed, pairs
    if r.reference_speed is not None:
        return exports.constant_at(s, r.reference_speed), None
    return exports.maxwell_constant(s, r.maxwell_temperature), None


def _identical(E, nu, rho, geometry, path, option) -> SILaw:
    """The law of two identical grains of a material, for a type pair i-i."""
    try:
        return si_law(E, nu, rho, geometry, "grain", path=path)
    except InputError as exc:
        raise InputError(
            f"the constants per type pair need the law of identical grains of each material: "
            f"{exc}; give that file with {option}"
        ) from None


def _damped(r: LawRequest, s: SILaw, progress: Progress) -> DampedLaw | None:
    """The damped law the request asks for, or ``None`` without damping options."""
    if not r.damped:
        return None  # the request refused damping options that do not go together
    return damped_law(
        s,
        relaxation_time_s=r.relaxation_time,
        radius_m=r.radius,
        measured_epsilon=r.measured_epsilon,
        measured_speed_m_s=r.measured_speed,
        progress=progress,
    )
