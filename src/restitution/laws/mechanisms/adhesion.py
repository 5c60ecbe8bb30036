"""Adhesion: JKR's adhesive contact, with the viscous loss and the elastic waves on one force
pulse (:mod:`restitution.laws.adhesive`; the physics and its checks in
:mod:`restitution.quasistatic.adhesion` and docs/adhesion.md).

Units: SI at the edge: the work of adhesion in J/m^2, the grain's radius in m, speeds in m/s.

Asked by ``--work-of-adhesion`` (``work_of_adhesion=`` in Python): Dupre's work of adhesion
``w = gamma1 + gamma2 - gamma12`` of the two surfaces, ``2 gamma`` for two identical surfaces in
vacuum (JKR's pull-off force is ``(3/2) pi w R``). Adhesion breaks the scale invariance of the
elastic law (the sticking speed goes as ``R^(-5/6)``), so it needs the grain's radius; it takes
a relaxation time onto its pulse. Below the sticking speed the grain does not rebound
(``epsilon = 0``).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.errors import InputError
from restitution.laws.mechanisms.base import MechanismOption, register_mechanism

__all__ = ["ADHESION_SECONDS_PER_SPEED", "Adhesion"]

ADHESION_SECONDS_PER_SPEED = 2.0
"""Wall time of one speed of an adhesive answer (two force pulses and the spectra of the modes
they drive), seconds: the order of a plastic one's (the same modes, the same pulses' panels)."""

WORK_OF_ADHESION = MechanismOption(
    "work_of_adhesion",
    "--work-of-adhesion",
    "Dupre's work of adhesion w = gamma1 + gamma2 - gamma12 of the two surfaces, J/m^2 (2 gamma "
    "for identical surfaces in vacuum; JKR's pull-off force is 1.5 pi w R): JKR adhesion, "
    "which makes a slow grain stick (docs/adhesion.md). Needs --radius; spheres on a rigid "
    "wall or on a grain.",
    "J/m^2",
    True,
)


@dataclass(frozen=True)
class Adhesion:
    """JKR adhesion on one pulse (module docs)."""

    name: str = "adhesion"
    words: str = "adhesion (JKR's adhesive contact)"
    rank: float = 30.0
    options: tuple = (WORK_OF_ADHESION,)
    reads: tuple = ("radius", "relaxation_time")
    slow_form: str = "epsilon = 0 below the sticking speed: the grain does not rebound"

    def asked(self, request) -> bool:
        return request.option_value(WORK_OF_ADHESION.keyword) is not None

    def check(self, request) -> None:
        r = request
        if r.plastic:
            raise InputError(
                "adhesion with plastic flow: not derived here (JKR's contact on Thornton's "
                "plastic one is another model); leave out --work-of-adhesion or the plastic "
                "options"
            )
        if r.grain.kind.planar:
            raise InputError(
                "adhesion is computed for spheres (JKR's contact is three-dimensional); use "
                "--shape sphere, or leave out --work-of-adhesion"
            )
        if r.elastic_wall is not None:
            raise InputError(
                "adhesion on an elastic wall: not derived (the JKR pulse's radiation into a "
                "point-force wall grows with the log of its cutoff, and its jumps' energy is "
                "not split between ball and wall); use a rigid wall, or leave out "
                "--work-of-adhesion"
            )
        if r.radius is None:
            raise InputError(
                "--work-of-adhesion needs --radius (m): the sticking speed depends on the "
                "grain's size (as R^(-5/6))"
            )
        if r.measured_epsilon is not None:
            raise InputError(
                "a measured epsilon with adhesion: not available yet (it would fix one "
                "parameter); give --relaxation-time, or leave out --measured-epsilon"
            )
        if r.export_dir is not None or r.constants:
            raise InputError(
                "--export and --reference-speed/--maxwell-temperature with adhesion: not "
                "available yet (the exports' slow continuation assumes a rebound at every "
                "speed); leave them out"
            )

    def answer(self, request, si, note, progress: bool):
        from restitution.laws.adhesive import adhesive_law
        from restitution.laws.answer import LawAnswer
        from restitution.laws.mechanisms.bounds import flag_points
        from restitution.laws.routes.base import check_speed_count
        from restitution.laws.si_point import overall_status

        r = request
        check_speed_count(len(r.speeds), ADHESION_SECONDS_PER_SPEED, "adhesion on one pulse")
        tau = 0.0 if r.relaxation_time is None else r.relaxation_time * si.grain.c_m_s / r.radius
        law = adhesive_law(si, work_of_adhesion=r.option_value(WORK_OF_ADHESION.keyword),
                           radius_m=r.radius, tau=tau)  # fmt: skip
        note(
            f"note: adhesion: each speed is computed now on one force pulse (the sticking speed "
            f"is {law.sticking_speed_m_s():.3g} m/s)"
        )
        points, _ = flag_points(si, law.points(list(r.speeds)))
        status, advice = overall_status(points)
        return LawAnswer(r, si, points, status, advice, by=law)

    def table(self, request, si, note, progress: bool):
        """The adhesive law at every speed (``si_law(..., work_of_adhesion=...)``): tabulated
        once from the first speed with a rebound (:func:`restitution.laws.tabulated.
        mechanism_table`), ``epsilon = 0`` below the sticking speed."""
        from restitution.laws.adhesive import adhesive_law
        from restitution.laws.tabulated import mechanism_table

        r = request
        tau = 0.0 if r.relaxation_time is None else r.relaxation_time * si.grain.c_m_s / r.radius
        law = adhesive_law(si, work_of_adhesion=r.option_value(WORK_OF_ADHESION.keyword),
                           radius_m=r.radius, tau=tau)  # fmt: skip
        stick = law.sticking_speed_m_s()
        return mechanism_table(
            si,
            law.points,
            words="adhesion",
            mechanisms=law.mechanisms,
            parameters={
                "work_of_adhesion_j_m2": law.work_of_adhesion,
                "radius_m": r.radius,
                "tau_c_over_R": tau,
                "sticking_speed_m_s": stick,
            },  # fmt: skip
            seconds_per_speed=ADHESION_SECONDS_PER_SPEED,
            note=note,
            progress=progress,
            zero_below=stick,
        )


register_mechanism(Adhesion())
