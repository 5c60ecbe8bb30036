"""One coefficient of restitution for codes that take a constant per pair.

epsilon (dimensionless) at a reference speed ``w`` in m/s (:func:`constant_at`), averaged over
the impacts of a Maxwell gas at a granular temperature ``<v_x^2>`` in m^2/s^2
(:func:`maxwell_constant`), or over any distribution of impact speeds (m/s) and rates
(:func:`distribution_constant`); the averages keep the dissipated energy per unit time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError
from restitution.estimate import Estimate
from restitution.laws.si_law import SILaw
from restitution.status import Status

__all__ = ["Constant", "constant_at", "distribution_constant", "maxwell_constant"]


@dataclass(frozen=True)
class Constant:
    """One coefficient of restitution for codes that take a constant per pair.

    Attributes
    ----------
    epsilon, epsilon_err : float
        The constant and its error.
    how : str
        What it is: the law at a reference speed, or an average over a named distribution.
    status : str
        Status of the law where the constant comes from (:data:`restitution.laws.si_law.STATUSES`);
        for an average, the worst status carrying more than 1 % of the weight.
    """

    epsilon: float
    epsilon_err: float
    how: str
    status: str

    @property
    def estimate(self) -> Estimate:
        """The constant as one :class:`~restitution.estimate.Estimate` (its status the law's)."""
        return Estimate(self.epsilon, self.epsilon_err, self.status, self.how)

    def to_dict(self) -> dict:
        return {
            "epsilon": self.epsilon,
            "epsilon_err": self.epsilon_err,
            "how": self.how,
            "status": self.status,
        }


def constant_at(s: SILaw, speed_m_s: float) -> Constant:
    """epsilon at one reference speed ``w`` (m/s)."""
    (p,) = s.points([speed_m_s])
    if p.epsilon is None:
        raise InputError(f"no epsilon at {speed_m_s:g} m/s: {p.note}")
    return Constant(
        p.epsilon,
        p.epsilon_err,
        f"epsilon at w = {speed_m_s:g} m/s ({s.against}: {s.against_meaning})",
        p.status,
    )


_ORDER = (
    Status.COMPUTED,
    Status.INTERPOLATED,
    Status.COMPUTED_NOT_ASYMPTOTIC,
    Status.INTERPOLATED_NOT_ASYMPTOTIC,
    Status.QUASISTATIC,
)


def maxwell_constant(s: SILaw, temperature_m2_s2: float, *, nodes: int = 400) -> Constant:
    """epsilon averaged over the impacts of a Maxwell gas at granular temperature ``T``.

    ``T`` is the variance of one velocity component of a grain, ``<v_x^2>`` in m^2/s^2. The
    normal impact speed ``w`` is Gaussian with variance ``sigma^2 = 2 T`` (two grains,
    relative speed) or ``T`` (a grain against a wall), and impacts happen at a rate ``~ w``.
    For a pair's law (a small and a large grain) ``2 T`` assumes both sizes at the same
    ``<v_x^2> = T``; the constant's ``how`` says so.
    The constant returned conserves the mean energy dissipated per unit time::

        1 - eps_eff^2 = <w^3 (1 - epsilon(w)^2)> / <w^3>,  weight exp(-w^2 / (2 sigma^2))

    (the rate ``w`` times the impact energy ``w^2``). Its error is half the spread of
    ``eps_eff`` evaluated with ``epsilon +- epsilon_err`` (errors fully correlated).

    Raises
    ------
    InputError
        When more than 0.1 % of the weight lies above the law's range.
    """
    T = float(temperature_m2_s2)
    if not (math.isfinite(T) and T > 0):
        raise InputError(f"the granular temperature must be positive (m^2/s^2), got {T}")
    sigma2 = 2.0 * T if s.against == "grain" else T
    w_min, w_max = s.speed_range_m_s

    def above(w):  # int_w^inf u^3 exp(-u^2 / 2 sigma^2) du / int_0^inf (same)
        z = w**2 / (2.0 * sigma2)
        return (1.0 + z) * math.exp(-z)

    if above(w_max) > 1e-3:
        raise InputError(
            f"{above(w_max):.2%} of the dissipation at T = {T:g} m^2/s^2 comes from speeds above "
            f"the law's range {w_max:.6g} m/s; use a lower temperature"
        )
    if 1.0 - above(w_min) > 1e-3:
        raise InputError(
            f"{1.0 - above(w_min):.2%} of the dissipation at T = {T:g} m^2/s^2 comes from speeds "
            f"below the law's computed range (from {w_min:.6g} m/s); use a higher temperature"
        )
    x, wq = np.polynomial.legendre.leggauss(nodes)
    half = 0.5 * (w_max - w_min)
    w = w_min + half * (x + 1.0)
    rate = half * wq * w * np.exp(-(w**2) / (2.0 * sigma2))
    both = "" if s.law.partner is None else ", both grain sizes at <v_x^2> = T"
    return distribution_constant(
        s,
        w,
        rate,
        how=f"dissipation-weighted average over a Maxwell gas at T = {T:g} m^2/s^2 "
        f"({s.against}: normal speed variance {sigma2:g} m^2/s^2{both})",
    )


def distribution_constant(s: SILaw, speeds_m_s, rates, *, how: str = "") -> Constant:
    """Dissipation-weighted constant for impact speeds ``w_i`` (m/s) occurring at ``rates``.

    ``1 - eps_eff^2 = sum r_i w_i^2 (1 - epsilon(w_i)^2) / sum r_i w_i^2``: the constant that
    dissipates the same energy per unit time as the law over the named distribution (``rates``
    are impacts per unit time at each speed, or quadrature weights times that density). The
    error is half the spread of ``eps_eff`` with ``epsilon +- epsilon_err`` (fully correlated).
    """
    w = np.asarray(speeds_m_s, dtype=float)
    r = np.asarray(rates, dtype=float)
    if w.shape != r.shape or w.ndim != 1 or np.any(r < 0) or not np.sum(r * w**2) > 0:
        raise InputError("speeds and rates must be 1D of equal length, rates >= 0, not all 0")
    weight = r * w**2
    eps = s.epsilon(w)
    err = s.epsilon_err(w)

    def eff(e):
        return math.sqrt(max(0.0, 1.0 - np.sum(weight * (1.0 - e**2)) / np.sum(weight)))

    value = eff(eps)
    spread = 0.5 * abs(eff(np.minimum(eps + err, 1.0)) - eff(eps - err))
    statuses = np.array([p.status for p in s.points(w)])
    share = {st: float(np.sum(weight[statuses == st]) / np.sum(weight)) for st in set(statuses)}
    worst = max(
        (st for st, f in share.items() if f > 0.01), key=_ORDER.index, default=Status.COMPUTED
    )
    by_status = ", ".join(f"{k} {v:.0%}" for k, v in sorted(share.items()))
    return Constant(
        value,
        spread,
        f"{how or 'dissipation-weighted average over the given speeds'}; weight by status: "
        + by_status,
        worst,
    )
