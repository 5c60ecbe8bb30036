"""Plastic flow (Thornton's elastic-perfectly-plastic contact) with the viscous loss and the
elastic waves on one force pulse (:mod:`restitution.laws.plastic`).

Units: SI at the edge (yield stresses and pressures in Pa, speeds in m/s).

Asked by a yield stress (of the grain or of its partner), a limiting pressure, or a measured
epsilon that fixes the limiting pressure; it takes a relaxation time (given or fixed by the
measurement) onto its pulse.
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.laws.mechanisms.base import MechanismOption, register_mechanism

__all__ = ["PLASTIC_SECONDS_PER_SPEED", "PlasticFlow"]

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
        from restitution.laws.answer import LawAnswer
        from restitution.laws.plastic import (
            fit_two_measurements,
            infer_relaxation_time,
            plastic_law,
        )
        from restitution.laws.routes.base import check_speed_count

        r, s = request, si
        check_speed_count(len(r.speeds), PLASTIC_SECONDS_PER_SPEED, "plastic flow on one pulse")
        # The request refused what does not go together (request_checks._check_damping).
        tau = 0.0 if r.relaxation_time is None else r.relaxation_time * s.grain.c_m_s / r.radius
        if r.fixes_both:
            note("note: fitting the relaxation time and the limiting pressure to the two "
                 "measurements (nested root searches of the contact; half a minute)")  # fmt: skip
            law = fit_two_measurements(
                s,
                (r.measured_epsilon, r.measured_speed),
                (r.second_measured_epsilon, r.second_measured_speed),
            )
        elif r.fixes_limiting_pressure:
            note("note: inferring the limiting pressure from the measurement (root searches of "
                 "the contact; seconds)")  # fmt: skip
            law = plastic_law(s, tau=tau, measured_epsilon=r.measured_epsilon,
                              measured_speed_m_s=r.measured_speed)  # fmt: skip
        else:
            law = plastic_law(s, yield_stress_pa=r.yield_stress,
                              partner_yield_stress_pa=r.partner_yield_stress,
                              limiting_pressure_pa=r.limiting_pressure, tau=tau)  # fmt: skip
            if r.measured_epsilon is not None:
                note("note: inferring the relaxation time from the measurement with the plastic "
                     "flow on (root searches of the contact; seconds)")  # fmt: skip
                law = infer_relaxation_time(law, r.measured_epsilon, r.measured_speed)
        note("note: plastic flow: each speed is computed now on one force pulse (about a second "
             "a speed)")  # fmt: skip
        points = law.points(list(r.speeds))
        status, advice = no_rebound_status(points)
        return LawAnswer(r, s, points, status, advice, by=law)


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
