"""Plastic flow (Thornton's elastic-perfectly-plastic contact) with the viscous loss and the
elastic waves on one force pulse (:mod:`restitution.laws.plastic`).

Units: SI at the edge (yield stresses and pressures in Pa, speeds in m/s).

Asked by a yield stress (of the grain or of its partner), a limiting pressure, or a measured
epsilon that fixes the limiting pressure; it takes a relaxation time (given or fixed by the
measurement) onto its pulse.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.laws.mechanisms.base import MechanismOption, register_mechanism

__all__ = ["PLASTIC_SECONDS_PER_SPEED", "PlasticFlow", "plastic_law_of"]

PLASTIC_SECONDS_PER_SPEED = 2.0
"""Wall time of one speed of a plastic answer (three force pulses and the spectra of the modes
they drive), seconds: 1-2 s measured on the project's 2-core machine (steel, 1 mm/s to 100 m/s;
slowest at the lowest speeds, whose pulses are longest)."""


@dataclass(frozen=True)
class PlasticFlow:
    """Thornton's plastic flow on one pulse (module docs)."""

    name: str = "plastic"
    words: str = "plastic flow (Thornton's elastic-perfectly-plastic contact)"
    rank: float = 20.0
    options: tuple = (
        MechanismOption("yield_stress", "--yield-stress", "", "Pa", True, field=True),
        MechanismOption(
            "partner_yield_stress", "--partner-yield-stress", "", "Pa", True, field=True
        ),  # fmt: skip
        MechanismOption("limiting_pressure", "--limiting-pressure", "", "Pa", True, field=True),
    )
    reads: tuple = ("radius", "relaxation_time", "measured_epsilon", "measured_speed")
    slow_form: str = "none below the yield speed (the contact is elastic there)"

    def asked(self, request) -> bool:
        return bool(request.plastic)

    def check(self, request) -> None:
        return None  # the request's own checks (restitution.laws.request_checks)

    def answer(self, request, si, note, progress: bool):
        from restitution.laws.answer import finish
        from restitution.laws.routes.base import check_speed_count

        r = request
        check_speed_count(len(r.speeds), PLASTIC_SECONDS_PER_SPEED, "plastic flow on one pulse")
        law = plastic_law_of(r, si, note)
        note("note: plastic flow: each speed is computed now on one force pulse (about a second "
             "a speed)")  # fmt: skip
        points = law.points(list(r.speeds))
        status, advice = no_rebound_status(points)
        table = walls = None
        if r.constants or r.export_dir is not None:
            # Constants, tables, snippets and the plugin of the plastic law: its table.
            table = _table_of(law, si, note, progress)
            if r.export_dir is not None:
                walls = _walls(law, si, note, progress)
        return finish(r, si, points, status, advice, note=note, by=law, table=table,
                      walls=walls)  # fmt: skip

    def table(self, request, si, note, progress: bool):
        """The plastic law at every speed of the elastic law, tabulated once
        (:func:`restitution.laws.tabulated.mechanism_table`): ``si_law(..., yield_stress=...)``
        and the exports."""
        return _table_of(plastic_law_of(request, si, note), si, note, progress)


def _table_of(law, si, note, progress: bool):
    """The table of the plastic law ``law`` on the elastic law ``si``."""
    from restitution.laws.tabulated import mechanism_table

    return mechanism_table(
        si,
        law.points,
        words="plastic flow",
        mechanisms=law.mechanisms,
        parameters={
            "limiting_pressure_pa": law.p_y,
            "limiting_pressure_err_pa": law.p_y_err,
            "limiting_pressure_source": law.source,
            "tau_c_over_R": law.tau,
            "tau_c_over_R_err": law.tau_err,
        },  # fmt: skip
        seconds_per_speed=PLASTIC_SECONDS_PER_SPEED,
        note=note,
        progress=progress,
        shape=_thornton_shape(law),
    )


def _thornton_shape(law):
    """Thornton's closed form ``epsilon_T(w / v_y)`` of the law's contact, a function of speeds
    in m/s: the shape its table interpolates the rest of (:mod:`restitution.laws.shaped_table`)."""
    from restitution.quasistatic.plastic import thornton_epsilon

    v_y = law.yield_speed_m_s()
    return lambda w: thornton_epsilon(np.asarray(w, dtype=float) / v_y)


def _walls(law, si, note, progress: bool):
    """The plastic law of the grain on the rigid wall for the plugin's wall table (the same
    limiting pressure and ``tau c / R``: identical grains are one grain of the law), ``{}`` for
    a law of the wall itself, and for a pair of two sizes or materials the sentence why there is
    none."""
    from dataclasses import replace

    from restitution.laws.partners.base import partner_of
    from restitution.laws.partners.rigid_wall import KIND as WALL
    from restitution.laws.si_law import si_law

    if not partner_of(si).is_grain:
        return {}
    if si.law.partner is not None:
        return {1: "a plastic pair of two sizes or materials: the wall tables of its grains are "
                "not made (give each grain's own export against the wall)"}  # fmt: skip
    wall = replace(law, si=si_law(grain=si.grain, against=WALL.against))
    note("note: the plastic law of the grain on the wall for the plugin")
    return {1: _table_of(wall, wall.si, note, progress)}


def plastic_law_of(request, si, note):
    """The :class:`~restitution.laws.plastic.PlasticLaw` of ``request`` on the elastic law
    ``si``: its limiting pressure given, from yield stresses, or inferred from one or two
    measurements (then with the relaxation time), each inference told first."""
    from restitution.laws.plastic import fit_two_measurements, infer_relaxation_time, plastic_law

    r, s = request, si
    # The request refused what does not go together (request_checks._check_damping).
    tau = 0.0 if r.relaxation_time is None else r.relaxation_time * s.grain.c_m_s / r.radius
    if r.fixes_both:
        note("note: fitting the relaxation time and the limiting pressure to the two "
             "measurements (nested root searches of the contact; half a minute)")  # fmt: skip
        return fit_two_measurements(
            s,
            (r.measured_epsilon, r.measured_speed),
            (r.second_measured_epsilon, r.second_measured_speed),
        )
    if r.fixes_limiting_pressure:
        note("note: inferring the limiting pressure from the measurement (root searches of "
             "the contact; seconds)")  # fmt: skip
        return plastic_law(s, tau=tau, measured_epsilon=r.measured_epsilon,
                           measured_speed_m_s=r.measured_speed)  # fmt: skip
    law = plastic_law(s, yield_stress_pa=r.yield_stress,
                      partner_yield_stress_pa=r.partner_yield_stress,
                      limiting_pressure_pa=r.limiting_pressure, tau=tau)  # fmt: skip
    if r.measured_epsilon is not None:
        note("note: inferring the relaxation time from the measurement with the plastic "
             "flow on (root searches of the contact; seconds)")  # fmt: skip
        law = infer_relaxation_time(law, r.measured_epsilon, r.measured_speed)
    return law


def no_rebound_status(points) -> tuple[str, str | None]:
    """:func:`~restitution.laws.si_point.overall_status`, whose advice for ``outside`` speaks of
    the law's range, saying instead where a speed has no value because the grain does not
    rebound (its contact computed, its losses above the impact energy)."""
    from restitution.laws.si_point import overall_status
    from restitution.status import Status

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


register_mechanism(PlasticFlow())
