"""Judge an epsilon(v) law against independent reference points (the FEM route).

Units: ``v`` in ``c`` (speed towards the wall); epsilon dimensionless.

For every reference point ``(nu, v, eps_ref +- err_ref)`` and the law of that ``nu`` the
difference ``eps_ref - law.epsilon(v)`` is expressed in units of the combined error
``sqrt(err_ref^2 + law.epsilon_err(v)^2)``; the coverage is the fraction of points within 1 and
2 combined errors (about 68 % and 95 % if both error bars are honest 1-sigma errors). Any
object with ``epsilon(v)`` and ``epsilon_err(v)`` serves as a law (e.g.
:class:`restitution.laws.law.EpsilonLaw`).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Protocol

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.errors import InputError
from restitution.estimate import Estimate, estimate_of, nan_for_none
from restitution.jsonable import finite_or_none
from restitution.laws.law_point import law_estimate
from restitution.status import Status

__all__ = ["JudgedPoint", "LawJudgement", "LawLike", "judge_law", "judge_shipped_law"]


class LawLike(Protocol):
    """What :func:`judge_law` needs of a law."""

    def epsilon(self, v: float) -> float: ...

    def epsilon_err(self, v: float) -> float: ...


@dataclass(frozen=True)
class JudgedPoint:
    """One reference point against the law.

    Attributes
    ----------
    nu, v : float
        Poisson number, speed towards the wall (``c``).
    reference_estimate : Estimate
        The reference point's epsilon, error and status; :attr:`reference` and
        :attr:`reference_err` read it.
    law_estimate : Estimate
        The law's at ``v`` (:func:`restitution.laws.law_point.law_estimate`; ``outside``
        when the law could not be evaluated); :attr:`law` and :attr:`law_err` read it.
    note : str
        Why the law gave no value, or the reference's own flag.
    """

    nu: float
    v: float
    reference_estimate: Estimate
    law_estimate: Estimate
    note: str = ""

    @property
    def reference(self) -> float:
        """Reference epsilon (``nan`` without one)."""
        return nan_for_none(self.reference_estimate.epsilon)

    @property
    def reference_err(self) -> float:
        """Its error."""
        return nan_for_none(self.reference_estimate.epsilon_err)

    @property
    def law(self) -> float:
        """The law's epsilon at ``v`` (``nan`` when the law could not be evaluated)."""
        return nan_for_none(self.law_estimate.epsilon)

    @property
    def law_err(self) -> float:
        """Its error."""
        return nan_for_none(self.law_estimate.epsilon_err)

    @property
    def difference(self) -> float:
        """``reference - law``."""
        return self.reference - self.law

    @property
    def combined_error(self) -> float:
        """``sqrt(reference_err^2 + law_err^2)``."""
        return math.hypot(self.reference_err, self.law_err)

    @property
    def sigma(self) -> float:
        """Difference in units of the combined error (signed; ``nan`` if not comparable)."""
        err = self.combined_error
        if not math.isfinite(self.difference) or not err > 0:
            return float("nan")
        return self.difference / err

    def to_dict(self) -> dict:
        """JSON-ready dictionary (``nan`` as ``None``)."""
        numbers = {
            "nu": self.nu,
            "v": self.v,
            "reference": self.reference,
            "reference_err": self.reference_err,
            "law": self.law,
            "law_err": self.law_err,
        }
        return {
            **{k: finite_or_none(x) for k, x in numbers.items()},
            "note": self.note,
            "difference": finite_or_none(self.difference),
            "combined_error": finite_or_none(self.combined_error),
            "sigma": finite_or_none(self.sigma),
        }


@dataclass(frozen=True)
class LawJudgement:
    """A table of reference points against a law, with the coverage.

    Attributes
    ----------
    points : tuple of JudgedPoint
    """

    points: tuple[JudgedPoint, ...]

    @property
    def compared(self) -> tuple[JudgedPoint, ...]:
        """The points with a finite ``sigma``."""
        return tuple(p for p in self.points if math.isfinite(p.sigma))

    def coverage(self, k: float) -> float:
        """Fraction of the compared points with ``|sigma| <= k`` (``nan`` without any)."""
        pts = self.compared
        if not pts:
            return float("nan")
        return sum(abs(p.sigma) <= k for p in pts) / len(pts)

    def to_dict(self) -> dict:
        """JSON-ready dictionary: the rows and the 1- and 2-sigma coverage."""
        return {
            "points": [p.to_dict() for p in self.points],
            "n_compared": len(self.compared),
            "coverage_1sigma": finite_or_none(self.coverage(1.0)),
            "coverage_2sigma": finite_or_none(self.coverage(2.0)),
        }

    def to_markdown(self) -> str:
        """The comparison table in Markdown."""
        rows = [
            "| nu | v (c) | FEM epsilon | law epsilon | difference | sigma |",
            "|---|---|---|---|---|---|",
        ]
        for p in self.points:
            sig = f"{p.sigma:+.2f}" if math.isfinite(p.sigma) else p.note or "n/a"
            rows.append(
                f"| {p.nu:g} | {p.v:g} | {p.reference:.5f} +- {p.reference_err:.5f} | "
                f"{p.law:.5f} +- {p.law_err:.5f} | {p.difference:+.5f} | {sig} |"
            )
        rows.append("")
        rows.append(
            f"Coverage: {self.coverage(1.0):.0%} within 1 sigma, {self.coverage(2.0):.0%} within "
            f"2 sigma ({len(self.compared)} points)."
        )
        return "\n".join(rows)


def judge_law(points: Iterable, laws: Mapping[float, LawLike] | LawLike) -> LawJudgement:
    """Compare reference points with a law (or one law per Poisson number).

    Parameters
    ----------
    points : iterable
        Objects with ``nu``, ``v``, ``epsilon`` and ``epsilon_err`` (e.g.
        :class:`restitution.fem.reference.ReferencePoint`).
    laws : LawLike or mapping of float to LawLike
        One law for all points, or laws keyed by ``nu`` (points of other ``nu`` are skipped).

    Returns
    -------
    LawJudgement
    """
    rows = []
    for p in points:
        if isinstance(laws, Mapping):
            law = next((lw for nu, lw in laws.items() if math.isclose(nu, p.nu)), None)
            if law is None:
                continue
        else:
            law = laws
        ref = getattr(p, "estimate", None) or estimate_of(
            p.epsilon, p.epsilon_err, getattr(p, "asymptotic_ok", True)
        )
        note = "" if ref.asymptotic else "reference flagged"
        try:
            at_law = law_estimate(law, p.v)
        except (InputError, ValueError) as exc:
            at_law = Estimate(None, None, Status.OUTSIDE, str(exc))
            note = f"no law value: {exc}"
        rows.append(JudgedPoint(float(p.nu), float(p.v), ref, at_law, note))
    return LawJudgement(points=tuple(rows))


def judge_shipped_law(reference_path=None, *, geometry: str = DEFAULT_GEOMETRY) -> LawJudgement:
    """The shipped FEM reference of the body ``geometry`` against its shipped modal laws
    (``restitution.law(nu, geometry=geometry)``)."""
    from restitution.fem.reference import load_reference
    from restitution.laws.law_load import law

    points = load_reference(reference_path, geometry=geometry)
    laws = {nu: law(nu, geometry=geometry) for nu in sorted({p.nu for p in points})}
    return judge_law(points, laws)


if __name__ == "__main__":
    import sys

    print(judge_shipped_law(sys.argv[1] if len(sys.argv) > 1 else None).to_markdown())
