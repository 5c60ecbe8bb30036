"""One result type for "an epsilon with its error": the estimate every route answers with.

Units: epsilon is dimensionless (rebound speed over impact speed); its error too.

A collision sweep's extrapolated point, a finite-element limit, a low-speed theory's point, a
law's point, an answer in SI units, a damping grain's point and a constant for a DEM code each
keep their own details, but each says what it estimates in the same words:
:class:`Estimate`, from its ``estimate`` attribute. Its :class:`~restitution.status.Status`
says where the number comes from and whether it passed its route's checks; the status carries
its advice (:attr:`restitution.status.Status.advice`), as diffrax's ``RESULTS`` do.

Three types hold an epsilon with its error (issue 60; ``tests/test_record_types.py`` counts
them): :class:`Estimate` itself, a law's point in reduced units
(:class:`restitution.laws.law_point.LawPoint`, which holds an :class:`Estimate`) and an answer
in SI units (:class:`restitution.laws.si_point.SIPoint`). Any other record either holds an
:class:`Estimate` (a stored reference point, a constant for a DEM code; :class:`EstimateView`
gives it the names its readers know) or keeps what its route computes, the energy loss and its
error, and derives epsilon from it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.status import Status

__all__ = ["ERROR_MEANING", "Estimate", "EstimateView", "estimate_of", "nan_for_none"]

ERROR_MEANING = (
    "epsilon_err: the error of the estimate as its route states it (each route meant one "
    "standard deviation; on independent points it is an upper estimate, several times the "
    "actual miss, docs/errors.md): for a modal extrapolation "
    "the fits' error plus the spread between the two orders of the limits and between checks "
    "and the shift of a quadratic in 1/alpha (the wall's curvature, a bias estimate); "
    "for the FEM the Richardson and fit errors; for the low-speed theories their model band "
    "plus what PCHIP between neighbouring low-speed points strays; between a law's points the "
    "neighbouring errors (interpolated) joined in quadrature with the interpolation's "
    "estimate, the larger leave-one-out error of the interval's ends times 2 sqrt(s (1 - s)): "
    "an upper estimate (PCHIP at twice the spacing), not a standard deviation. epsilon_sd, "
    "where an answer gives it (restitution law; a law's epsilon_sd(v)): one standard "
    "deviation, the same parts scaled per route by factors fitted on independent points "
    "(67-78 % of the held-out between-speed and between-nu points and of the modal route's "
    "as a whole within one sd, docs/errors.md); where a route has too few such points it is "
    "the bound, and epsilon_sd_kind says 'bound'"
)
"""What an :class:`Estimate`'s error covers (the routes' own documents say how it is made)."""


@dataclass(frozen=True)
class Estimate:
    """epsilon, its error and its status.

    Attributes
    ----------
    epsilon : float or None
        The coefficient of restitution; ``None`` where there is none (outside a law's range).
    epsilon_err : float or None
        Its error (:data:`ERROR_MEANING`); ``None`` when it cannot be estimated.
    status : Status
        Where the number comes from and whether it passed its checks.
    message : str
        Why the status is not ``ok``, in the route's words.
    """

    epsilon: float | None
    epsilon_err: float | None
    status: Status
    message: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "status", Status(self.status))
        for name in ("epsilon", "epsilon_err"):
            value = getattr(self, name)
            if value is not None and not math.isfinite(value):
                object.__setattr__(self, name, None)

    @classmethod
    def from_record(cls, record) -> Estimate:
        """The estimate of a stored point (a mapping, e.g. a point of a reference file): its
        ``epsilon`` and ``epsilon_err`` (``None`` for none), ``ok`` or ``not-asymptotic`` from
        its ``asymptotic_ok``, and its ``message``."""
        eps, err = record["epsilon"], record["epsilon_err"]
        return cls(
            None if eps is None else float(eps),
            None if err is None else float(err),
            Status.OK if bool(record["asymptotic_ok"]) else Status.NOT_ASYMPTOTIC,
            str(record.get("message", "")),
        )

    @property
    def asymptotic(self) -> bool:
        """Whether it passed every check of its route (:attr:`Status.asymptotic`)."""
        return self.status.asymptotic

    @property
    def advice(self) -> str | None:
        """What to do about it (its status's advice)."""
        return self.status.advice

    def covers(self, value: float, k: float = 1.0) -> bool:
        """Whether ``value`` lies within ``k`` errors of ``epsilon``."""
        if self.epsilon is None or self.epsilon_err is None:
            return False
        return abs(value - self.epsilon) <= k * self.epsilon_err

    def to_dict(self) -> dict:
        """JSON-ready: ``epsilon``, ``epsilon_err``, ``status``, ``message``, ``advice``."""
        return {
            "epsilon": self.epsilon,
            "epsilon_err": self.epsilon_err,
            "status": str(self.status),
            "message": self.message,
            "advice": self.advice,
        }


def estimate_of(epsilon, epsilon_err, asymptotic_ok: bool, message: str = "") -> Estimate:
    """The estimate of a route that reports ``asymptotic_ok`` instead of a status: ``ok`` or
    ``not-asymptotic``."""
    status = Status.OK if asymptotic_ok else Status.NOT_ASYMPTOTIC
    return Estimate(epsilon, epsilon_err, status, "" if asymptotic_ok else message)


def nan_for_none(value: float | None) -> float:
    """An estimate's number as a float: ``value``, or ``nan`` for ``None`` (no value)."""
    return math.nan if value is None else value


class EstimateView:
    """What a record that holds an :class:`Estimate` (its field ``estimate``) answers under the
    names its readers know: ``epsilon`` and ``epsilon_err`` as floats (``nan`` where the
    estimate has none, as such records stored them before they held one), ``status``,
    ``asymptotic_ok`` and ``message``."""

    __slots__ = ()

    estimate: Estimate

    @property
    def epsilon(self) -> float:
        """The estimate's epsilon; ``nan`` where it has none."""
        return nan_for_none(self.estimate.epsilon)

    @property
    def epsilon_err(self) -> float:
        """Its error; ``nan`` where it has none."""
        return nan_for_none(self.estimate.epsilon_err)

    @property
    def status(self) -> Status:
        """The estimate's status."""
        return self.estimate.status

    @property
    def asymptotic_ok(self) -> bool:
        """Whether it passed every check of its route."""
        return self.estimate.asymptotic

    @property
    def message(self) -> str:
        """Why not, in the route's words."""
        return self.estimate.message
