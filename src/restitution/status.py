"""The one vocabulary of statuses: of collisions, stored points, law points, SI answers and JSON.

:class:`Status` is a string enum: a member equals, hashes, prints, formats and serialises to JSON
(keys included) as its plain value (``Status.OK == "ok"``, ``json.dumps(Status.OK) == '"ok"'``),
so files and JSON documents carry the same text as before the enum existed.

Where each status occurs:

* a collision (:attr:`restitution.dynamics.results.CollisionResult.status`): ``OK``,
  ``DRIFT_EXCEEDED``, ``NOT_FINITE``;
* a point of a sweep and a row of the result store (:mod:`restitution.limits.store`): ``OK``,
  ``FAILED``;
* a point of a law (:class:`restitution.laws.law_point.LawPoint`): ``OK``, ``NOT_ASYMPTOTIC``,
  ``QUASISTATIC``;
* an answer in SI units (:mod:`restitution.laws.si_law`): ``COMPUTED``,
  ``COMPUTED_NOT_ASYMPTOTIC``, ``INTERPOLATED``, ``INTERPOLATED_NOT_ASYMPTOTIC``,
  ``QUASISTATIC``, ``OUTSIDE``;
* the envelope of a command's JSON (:func:`restitution.cli._common.envelope`): ``OK``,
  ``NOT_ASYMPTOTIC``, ``POINTS_FAILED``, ``FAILED_SAMPLES``, ``LARGE_DEFORMATION`` (``collide``
  beyond ``v = 0.3 c``), or a collision's status;
* an oblique impact (``collide --angle``, ``law --angle``): ``OK``, ``COMPUTED_NOT_ASYMPTOTIC``
  (one mode count, not extrapolated), ``LARGE_DEFORMATION``, ``SUSPECT``.
"""

from __future__ import annotations

import enum

__all__ = ["ASYMPTOTIC", "Status"]


class Status(enum.StrEnum):
    """Every status string the package produces (see the module docstring for where)."""

    OK = "ok"
    """Nothing is wrong: the collision met its tolerance, the point is stored, the
    extrapolation passed its checks, the command's result is trustworthy."""

    FAILED = "failed"
    """A collision of a sweep raised; its error message is stored instead of results."""

    DRIFT_EXCEEDED = "drift-exceeded"
    """A collision run at a fixed step whose relative energy drift exceeds ``energy_tol``."""

    NOT_FINITE = "not-finite"
    """A collision run that produced no finite epsilon or energy drift."""

    NOT_ASYMPTOTIC = "not-asymptotic"
    """An extrapolation (law point, command result) that did not pass every asymptotic check."""

    POINTS_FAILED = "points-failed"
    """Some collisions of a command's grid failed or were lost; the result lacks them."""

    FAILED_SAMPLES = "failed-samples"
    """Some collisions of a thermal ensemble could not be integrated; they are left out."""

    COMPUTED = "computed"
    """At a computed speed of a law whose extrapolation passed its checks."""

    COMPUTED_NOT_ASYMPTOTIC = "computed-not-asymptotic"
    """At a computed speed of a law whose extrapolation did not pass every check."""

    INTERPOLATED = "interpolated"
    """Between two computed speeds of a law that both passed their checks."""

    INTERPOLATED_NOT_ASYMPTOTIC = "interpolated-not-asymptotic"
    """Between two computed speeds of a law, at least one of which did not pass every check."""

    QUASISTATIC = "quasistatic"
    """From the low-speed theory, not from a collision: the sphere's Rayleigh estimate on Hertz's
    force pulse with its error band (:mod:`restitution.quasistatic.low_speed`), or the disk's
    slow-impact model (:mod:`restitution.quasistatic.slow_disk`); a law point of that route or
    an answer next to one."""

    LARGE_DEFORMATION = "large-deformation"
    """A collision faster than the model's range (``v > 0.3 c`` against a wall): it met its
    tolerance, but linear elasticity is stretched (the body's largest compression is a sizeable
    fraction of its radius); the number is the linear model's, not a real body's."""
    OUTSIDE = "outside"
    """Outside the computed range of a law: no value (a law never extrapolates)."""

    SUSPECT = "suspect"
    """An oblique impact in the regime where the modal route is not trusted (more than 320
    modes on a wall of ``alpha >= 4000`` with friction above 0.1: the contact can break into
    dozens of stick/slip phases with an erratic force; docs/oblique.md, "Caution");
    :func:`restitution.dynamics.oblique_cost.suspect_advice` says what to compare it with."""

    @property
    def advice(self) -> str | None:
        """What to do about a result of this status (``None``: nothing); one line that works
        when followed. A result may say more (its own ``advice``)."""
        return _ADVICE.get(self)

    @property
    def asymptotic(self) -> bool:
        """Whether a result of this status passed every check of its route (an error bar that
        means what it says)."""
        return self in ASYMPTOTIC


ASYMPTOTIC = frozenset({Status.OK, Status.COMPUTED, Status.INTERPOLATED})
"""The statuses of results that passed every check of their route."""

_ADVICE: dict[Status, str] = {
    Status.FAILED: "read the stored message; recompute with --retry-failed once it is fixed",
    Status.DRIFT_EXCEEDED: "leave out dt (the step is then refined to energy_tol) or lower it",
    Status.NOT_FINITE: "lower dt or energy_tol; check v in (0, 1) and alpha > 0",
    Status.NOT_ASYMPTOTIC: (
        "read the error bar as indicative: the fits were not yet linear in 1/alpha and "
        "1/sqrt(N); harder walls and more modes (--alphas, --modes) make them so"
    ),
    Status.POINTS_FAILED: (
        "run the same command again (stored points are reused, lost ones recomputed) or add "
        "--retry-failed for points that failed in the solver"
    ),
    Status.FAILED_SAMPLES: "the statistics leave the failed samples out; see 'failures'",
    Status.COMPUTED_NOT_ASYMPTOTIC: (
        "read the error bar as indicative; compute the law with larger windows to confirm it"
    ),
    Status.INTERPOLATED_NOT_ASYMPTOTIC: (
        "read the error bar as indicative; compute the law with larger windows to confirm it"
    ),
    Status.QUASISTATIC: (
        "the error is the low-speed theory's band (its model and convergence), not a "
        "collision's extrapolation"
    ),
    Status.LARGE_DEFORMATION: "use v <= 0.3 c (0.6 c relative for a pair): linear elasticity",
    Status.OUTSIDE: "give speeds inside the law's computed range; a law never extrapolates",
    Status.SUSPECT: (
        "compare with the same impact at 320 modes or on a softer wall before using the number"
    ),
}
