"""The viscous loss of the material (Kelvin-Voigt): the damped law, the elastic law's loss and
the viscous one added (:mod:`restitution.laws.damped`).

Units: SI at the edge (the relaxation time in s, the radius in m, speeds in m/s).

Asked by a relaxation time (with the grain's radius) or by one measured epsilon that fixes it.
With plastic flow or adhesion asked too, those answer and take the relaxation time onto their
pulse (their rank is higher).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.laws.mechanisms.base import MechanismOption, register_mechanism

__all__ = ["Viscosity"]


@dataclass(frozen=True)
class Viscosity:
    """Kelvin-Voigt damping of the material (module docs)."""

    name: str = "viscous"
    words: str = "viscous loss of the material (Kelvin-Voigt)"
    rank: float = 10.0
    options: tuple = (
        MechanismOption("relaxation_time", "--relaxation-time", "", "s", True, field=True),
        MechanismOption("measured_epsilon", "--measured-epsilon", "", "", True, field=True),
        MechanismOption("measured_speed", "--measured-speed", "", "m/s", True, field=True),
    )
    reads: tuple = ("radius",)
    slow_form: str = (
        "1 - epsilon ~ v^(1/5) for a 3D contact (Kelvin-Voigt on Hertz's pulse), ~ "
        "1/sqrt(ln(1/v)) for a 2D one"
    )

    def asked(self, request) -> bool:
        return bool(request.damped)

    def check(self, request) -> None:
        return None  # the request's own checks (restitution.laws.request_checks)

    def table(self, request, si, note, progress: bool):
        """The damped law at every speed of the elastic law, as an SI law (``si_law(...,
        relaxation_time=..., radius=...)``)."""
        return _table(request, si, note, progress)

    def answer(self, request, si, note, progress: bool):
        from restitution.errors import InputError
        from restitution.laws.answer import finish
        from restitution.laws.damped import damped_law
        from restitution.laws.mechanisms.bounds import flag_points
        from restitution.laws.si_point import overall_status
        from restitution.limits.run_options import Progress

        r = request
        bars = Progress(None if progress else False)  # the damped law's: on a terminal only
        damped = damped_law(si, relaxation_time_s=r.relaxation_time, radius_m=r.radius,
                            measured_epsilon=r.measured_epsilon,
                            measured_speed_m_s=r.measured_speed, progress=bars)  # fmt: skip
        if si.law.partner is not None and r.constants:
            raise InputError(
                "constants per type pair of damping grains are not computed (tau c / R differs "
                "for the two sizes); drop --reference-speed/--maxwell-temperature, or the "
                "damping"
            )
        points, _ = flag_points(si, damped.points(list(r.speeds)))
        status, advice = overall_status(points)
        table = model = walls = None
        if r.constants or r.export_dir is not None:
            # Constants, tables and snippets of the damped law: the sum at every computed speed.
            what = "exports" if r.export_dir is not None else "constant"
            note(
                f"note: the damped law for the {what}: {damped.table_collisions()} viscous "
                "collisions at the elastic law's computed speeds"
            )
            table = damped.as_si_law(progress=bars)
            if r.export_dir is not None:
                model = _viscoelastic(r, damped, note)
                walls = _walls(si, damped, note, bars)
        return finish(r, si, points, status, advice, note=note, by=damped, table=table,
                      model=model, walls=walls)  # fmt: skip


def _table(r, si, note, progress: bool):
    """The damped law at every computed speed of the elastic law ``si``, as an SI law."""
    from restitution.laws.damped import damped_law
    from restitution.limits.run_options import Progress

    bars = Progress(None if progress else False)
    damped = damped_law(si, relaxation_time_s=r.relaxation_time, radius_m=r.radius,
                        measured_epsilon=r.measured_epsilon,
                        measured_speed_m_s=r.measured_speed, progress=bars)  # fmt: skip
    note(f"note: the damped law at every speed: {damped.table_collisions()} viscous collisions")
    return damped.as_si_law(progress=bars)


def _walls(si, damped, note, bars):
    """The damped law of the grain on the rigid wall for the plugin's wall table (the same
    material, the same ``tau c / R``: identical grains are one grain of the law), ``{}`` for a
    law of the wall itself, and for a pair of two sizes the sentence why there is none (the
    pair's ``tau c / R`` is the smaller grain's; the other grain's wall law is not made)."""
    from restitution.laws.damped import DampedLaw
    from restitution.laws.partners.base import partner_of
    from restitution.laws.partners.rigid_wall import KIND as WALL
    from restitution.laws.si_law import si_law

    if not partner_of(si).is_grain:
        return {}
    if si.law.partner is not None:
        return {1: "a damped pair of two sizes or materials: the wall tables of its grains are "
                "not made (give each grain's own export against the wall)"}  # fmt: skip
    wall = DampedLaw(si_law(grain=si.grain, against=WALL.against), damped.tau, damped.tau_err,
                     damped.radius_m, damped.measured)  # fmt: skip
    note(f"note: the damped law of the grain on the wall for the plugin: "
         f"{wall.table_collisions()} viscous collisions")  # fmt: skip
    return {1: wall.as_si_law(progress=bars)}


def _viscoelastic(r, damped, note):
    """The damped sphere law as the DEM codes' viscoelastic model for the exports
    (:func:`restitution.laws.exports.viscoelastic.viscoelastic_model`, the part it drops at the
    asked speeds), or ``None`` (a body or pair it does not describe: noted)."""
    from restitution.errors import InputError
    from restitution.laws.exports.viscoelastic import viscoelastic_model

    try:
        return viscoelastic_model(damped, r.speeds)
    except InputError as exc:
        note(f"note: no viscoelastic DEM snippets: {exc}")
        return None


register_mechanism(Viscosity())
