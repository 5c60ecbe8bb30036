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
from restitution.estimate import Estimate, EstimateView
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw
from restitution.status import Status

__all__ = [
    "Constant",
    "constant_at",
    "distribution_constant",
    "maxwell_constant",
    "maxwell_temperatures",
]


@dataclass(frozen=True)
class Constant(EstimateView):
    """One coefficient of restitution for codes that take a constant per pair.

    Attributes
    ----------
    estimate : Estimate
        The constant, its error, the status of the law where it comes from
        (:data:`restitution.laws.si_point.STATUSES`; for an average, the worst status carrying
        more than 1 % of the weight) and, as its message, what it is (:attr:`how`).
        ``epsilon``, ``epsilon_err`` and ``status`` read it
        (:class:`~restitution.estimate.EstimateView`).
    """

    estimate: Estimate

    @property
    def how(self) -> str:
        """What it is: the law at a reference speed, or an average over a named distribution."""
        return self.estimate.message

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
    how = f"epsilon at w = {speed_m_s:g} m/s ({s.against}: {s.against_meaning})"
    return Constant(Estimate(p.epsilon, p.epsilon_err, p.status, how))


_ORDER = (
    Status.COMPUTED,
    Status.INTERPOLATED,
    Status.COMPUTED_NOT_ASYMPTOTIC,
    Status.INTERPOLATED_NOT_ASYMPTOTIC,
    Status.QUASISTATIC,
)


_OUTSIDE_SHARE = 1e-3
"""The largest share of a Maxwell gas's dissipation that may come from speeds outside a law's
range (where the law has no value) for :func:`maxwell_constant` to average it."""


def _share_above(z: float) -> float:
    """The share of ``<w^3>`` (weight ``exp(-w^2 / (2 sigma^2))``) from ``w^2 / (2 sigma^2) > z``:
    ``int_w^inf u^3 exp(-u^2 / 2 sigma^2) du / int_0^inf (same) = (1 + z) exp(-z)``."""
    return (1.0 + z) * math.exp(-z)


def _z_where(share: float) -> float:
    """``z`` at which :func:`_share_above` is ``share``."""
    from scipy.optimize import brentq

    return brentq(lambda z: _share_above(z) - share, 0.0, 100.0, xtol=1e-14, rtol=1e-14)


def _variance_factor(s: SILaw) -> float:
    """``sigma^2 / T`` of the normal impact speed: 2 for two grains, 1 against a wall."""
    return partner_of(s).variance_factor


def maxwell_temperatures(*laws: SILaw) -> tuple[float, float]:
    """The granular temperatures ``T_min <= T <= T_max`` (m^2/s^2) at which
    :func:`maxwell_constant` averages every one of ``laws``: those at which at most 0.1 % of the
    dissipation comes from speeds below or above a law's range. ``T_min > T_max`` when there is
    none (a law too narrow, or laws that do not overlap)."""
    z_low, z_high = _z_where(1.0 - _OUTSIDE_SHARE), _z_where(_OUTSIDE_SHARE)
    lo, hi = 0.0, math.inf
    for s in laws:
        w_min, w_max = s.speed_range_m_s
        lo = max(lo, w_min**2 / (2.0 * z_low * _variance_factor(s)))
        hi = min(hi, w_max**2 / (2.0 * z_high * _variance_factor(s)))
    return lo, hi


def _inward(x: float, up: bool) -> str:
    """``x`` to three significant digits, rounded up (``up``) or down, so that the number
    printed lies on the inner side of the bound ``x``."""
    e = math.floor(math.log10(x)) - 2
    q = math.ceil(x / 10.0**e - 1e-9) if up else math.floor(x / 10.0**e + 1e-9)
    return f"{q * 10.0**e:.3g}"


def _maxwell_refusal(s: SILaw, T: float, share: float, below: bool, laws) -> str:
    """Why a Maxwell gas at ``T`` is not averaged over ``s``, and what answers instead: the
    temperatures that are averaged, and one speed to take a constant at (the gas's
    dissipation-weighted mean impact speed, or the served speed nearest to it), over every law
    of ``laws`` served together."""
    w_min, w_max = s.speed_range_m_s
    w = w_min if below else w_max
    T_lo, T_hi = maxwell_temperatures(*laws)
    which = "the law" if len(laws) == 1 else "the type pairs' laws"
    averaged = f"so {which} average no temperature"
    T_in = _inward(T_lo, True), _inward(T_hi, False)
    if T_lo < T_hi and float(T_in[0]) <= float(T_in[1]):
        averaged = f"so {which} average only {T_in[0]} <= T <= {T_in[1]} m^2/s^2"
    head = (
        f"{share:.2%} of the dissipation of a Maxwell gas at T = {T:g} m^2/s^2 comes from "
        f"impacts {'slower' if below else 'faster'} than {w:.6g} m/s (v/c = "
        f"{w / s.speed_scale_m_s:.3g}), the {'slowest' if below else 'fastest'} speed the law "
        f"serves (it has no value beyond, never an extrapolated one); an average may leave out "
        f"{_OUTSIDE_SHARE:.1%} at most, {averaged}"
    )
    w_lo = max(x.speed_range_m_s[0] for x in laws)
    w_hi = min(x.speed_range_m_s[1] for x in laws)
    lo, hi = _inward(w_lo, True), _inward(w_hi, False)
    if float(lo) > float(hi):
        return head
    # <w^4> / <w^3> = sqrt(2) sigma Gamma(5/2) / Gamma(2): the speed that carries the dissipation
    mean = math.sqrt(2.0 * _variance_factor(s) * T) * 0.75 * math.sqrt(math.pi)
    at = f"{mean:.3g}"
    why = "the gas's dissipation-weighted mean impact speed <w^4>/<w^3>"
    if not float(lo) <= float(at) <= float(hi):
        at = lo if float(at) < float(lo) else hi
        why = f"the served speed nearest to the gas's dissipation-weighted mean {mean:.3g} m/s"
    return (
        f"{head}. For one constant of this gas, take epsilon at one impact speed: "
        f"--reference-speed {at} ({why}; any speed from {lo} to {hi} m/s is served; "
        "constant_at in Python)"
    )


def maxwell_constant(
    s: SILaw, temperature_m2_s2: float, *, nodes: int = 400, together: tuple = ()
) -> Constant:
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

    ``together``: further laws averaged at the same ``T`` (the type pairs of
    :func:`~restitution.laws.exports.type_pairs.type_pair_constants`), so that a refusal names
    the temperatures and speeds that every one of them serves.

    Raises
    ------
    InputError
        When more than 0.1 % of the dissipation comes from speeds below or above the law's
        range, with the temperatures it averages (:func:`maxwell_temperatures`) and the
        speeds at which :func:`constant_at` (``--reference-speed``) answers instead.
    """
    T = float(temperature_m2_s2)
    if not (math.isfinite(T) and T > 0):
        raise InputError(f"the granular temperature must be positive (m^2/s^2), got {T}")
    sigma2 = _variance_factor(s) * T
    w_min, w_max = s.speed_range_m_s

    laws = (s, *together)

    def above(w):
        return _share_above(w**2 / (2.0 * sigma2))

    if above(w_max) > _OUTSIDE_SHARE:
        raise InputError(_maxwell_refusal(s, T, above(w_max), False, laws))
    if 1.0 - above(w_min) > _OUTSIDE_SHARE:
        raise InputError(_maxwell_refusal(s, T, 1.0 - above(w_min), True, laws))
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
    what = how or "dissipation-weighted average over the given speeds"
    return Constant(Estimate(value, spread, worst, f"{what}; weight by status: {by_status}"))
