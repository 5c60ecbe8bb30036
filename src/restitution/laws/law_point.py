"""A law's computed points: one point with its status, the record a law's file keeps of it, and
the interpolation error of PCHIP through the points.

Units: ``v`` is the body's speed towards the wall in units of ``c = sqrt(E/rho)`` of its own
constants (a pair's: the relative speed of the centres, in the first body's ``c``); epsilon and
its errors are dimensionless. A law (:class:`restitution.laws.law.EpsilonLaw`) holds these
points; this module knows nothing of the law or its files.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.estimate import Estimate, EstimateView, estimate_of
from restitution.status import Status

__all__ = [
    "LOG_V",
    "QUASISTATIC_ROUTE",
    "LawPoint",
    "law_estimate",
    "leave_one_out",
    "point_record",
]

LOG_V = "ln v"
"""``metadata["interpolate_in"]`` of a law whose PCHIP takes its points at ``ln v`` (a
mechanism's table on a geometric grid, :mod:`restitution.laws.tabulated`); every other law
interpolates in ``v``."""

QUASISTATIC_ROUTE = "quasistatic"
"""``route`` of a law point from the low-speed theory (:mod:`restitution.quasistatic.low_speed`);
points without a ``route`` come from collisions (``"modal"``)."""


def leave_one_out(v, loss) -> np.ndarray:
    """How far PCHIP through the other points (in ``v``, as a law interpolates) strays from each
    interior point, shape (K,); the end points take their neighbour's. It is the error of twice
    the spacing, an upper estimate of the interpolation's between the points."""
    v, loss = np.asarray(v, dtype=float), np.asarray(loss, dtype=float)
    if v.size < 4:
        return np.zeros(v.size)
    out = np.empty(v.size)
    for j in range(1, v.size - 1):
        rest = np.delete(np.arange(v.size), j)
        out[j] = abs(float(PchipInterpolator(v[rest], loss[rest])(v[j])) - loss[j])
    out[0], out[-1] = out[1], out[-2]
    return out


def point_record(v: float, limit, settings) -> dict:
    """One computed point as a law's ``metadata["points"]`` holds it: the speed ``v`` (``c``),
    its extrapolation ``limit`` (a :class:`restitution.limits.extrapolate.CombinedLimit`) and
    the sweep ``settings`` it was computed with."""
    return {
        "v": float(v),
        "epsilon": limit.epsilon,
        "epsilon_err": limit.epsilon_err,
        "energy_loss": limit.limit,
        "energy_loss_err": limit.limit_err,
        "asymptotic_ok": bool(limit.asymptotic_ok),
        "status": Status.OK if limit.asymptotic_ok else Status.NOT_ASYMPTOTIC,
        "message": limit.message,
        "settings": settings.to_dict(),
        "extrapolation": limit.to_dict(),
    }


@dataclass(frozen=True)
class _Recorded:
    """Sweep settings as a point's record stores them (for :func:`point_record`)."""

    settings: dict

    def to_dict(self) -> dict:
        return dict(self.settings)


@dataclass(frozen=True)
class LawPoint(EstimateView):
    """One computed point of a law: a speed and what the law states there.

    Attributes
    ----------
    v : float
        Speed towards the wall, units of ``c``.
    estimate : Estimate
        Extrapolated coefficient of restitution, its error and status: ``ok`` when the
        point's extrapolations passed their checks, ``not-asymptotic`` when not (its
        ``message`` says why), ``quasistatic`` for a point of the low-speed theory
        (:mod:`restitution.quasistatic.low_speed`), which has no extrapolation. ``epsilon``,
        ``epsilon_err``, ``status`` and ``message`` read it (:class:`EstimateView`).
    """

    v: float
    estimate: Estimate


def law_estimate(law, v: float) -> Estimate:
    """``law``'s epsilon and error at ``v`` (``c``) as an :class:`Estimate`: ``ok`` where the
    computed points around ``v`` passed their checks (``law.checked(v)``, as
    :class:`~restitution.laws.law.EpsilonLaw` answers it), ``not-asymptotic`` where not; a law
    without ``checked`` (any object with ``epsilon(v)`` and ``epsilon_err(v)``) is taken at its
    word. Raises what the law raises at a speed it does not serve."""
    value, err = float(law.epsilon(v)), float(law.epsilon_err(v))
    checked = getattr(law, "checked", None)
    return estimate_of(value, err, True if checked is None else bool(checked(v)))
