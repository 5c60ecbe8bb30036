"""The three-parameter closed form ``epsilon(w) = 1 - a x^p / (1 + b x^p)``, fitted to a law.

``x = w / (k c)`` is the reduced speed (``w`` in m/s, ``k c`` the law's speed unit in m/s);
``a``, ``b`` and ``p`` are dimensionless. The fit weights the computed points by their errors and
keeps the widest range of speeds where the form follows every point within its error, and only
that range (:attr:`ClosedForm.valid_m_s`, m/s).

Why this form: ``epsilon(0) = 1`` (the quasistatic limit), a power law ``1 - epsilon ~ a x^p``
at small speeds (Rayleigh's estimate, paper section 5, gives a power of the speed), a
saturation at large speeds through ``b``, three parameters, and one line of C.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import curve_fit

from restitution.errors import InputError, RestitutionError
from restitution.laws.si_law import SILaw

__all__ = ["ClosedForm", "fit_closed_form"]


def _form(x, a, b, p):
    xp = np.power(x, p)
    return 1.0 - a * xp / (1.0 + b * xp)


@dataclass(frozen=True)
class ClosedForm:
    """``epsilon(w) = 1 - a x^p / (1 + b x^p)`` with ``x = w / speed_scale_m_s``.

    Attributes
    ----------
    a, b, p : float
        Dimensionless coefficients (``x`` is the reduced speed ``v`` towards the wall).
    covariance : numpy.ndarray, shape (3, 3)
        Covariance of ``(a, b, p)``; scaled by ``chi2/dof`` when that exceeds 1 (the points
        scatter more than their error bars say).
    speed_scale_m_s : float
        ``k c``, m/s.
    max_deviation : float
        Largest ``|form - epsilon|`` over the points in :attr:`valid_m_s`.
    max_deviation_sigma : float
        Largest ``|form - epsilon| / epsilon_err`` over those points, at most 1.
    chi2_dof : float
        ``chi^2`` per degree of freedom of the weighted fit.
    valid_m_s : tuple of float
        ``(w_min, w_max)`` in m/s: the range of computed points the form follows within their
        errors (:func:`fit_closed_form`). Outside it the form is not valid: it misses the law
        by more than the errors, or the law has no points there.
    """

    a: float
    b: float
    p: float
    covariance: np.ndarray
    speed_scale_m_s: float
    max_deviation: float
    max_deviation_sigma: float
    chi2_dof: float
    valid_m_s: tuple[float, float]

    def epsilon(self, speed_m_s):
        """The form at speed(s) ``w`` in m/s."""
        return _form(np.asarray(speed_m_s, dtype=float) / self.speed_scale_m_s, *self.params)

    @property
    def params(self) -> tuple[float, float, float]:
        return self.a, self.b, self.p

    @property
    def errors(self) -> tuple[float, float, float]:
        """Standard errors of ``(a, b, p)``."""
        return tuple(float(x) for x in np.sqrt(np.diag(self.covariance)))

    def to_dict(self) -> dict:
        return {
            "form": "epsilon(w) = 1 - a x^p / (1 + b x^p), x = w / speed_scale_m_s",
            "valid": "only for valid_m_s[0] <= w <= valid_m_s[1] (m/s), where it follows every "
            "computed point within its error (max_deviation_sigma <= 1); elsewhere use the "
            "table (epsilon.h, epsilon.f90, epsilon_table.txt)",
            "a": self.a,
            "b": self.b,
            "p": self.p,
            "errors": list(self.errors),
            "covariance": self.covariance.tolist(),
            "speed_scale_m_s": self.speed_scale_m_s,
            "max_deviation": self.max_deviation,
            "max_deviation_sigma": self.max_deviation_sigma,
            "chi2_dof": self.chi2_dof,
            "valid_m_s": list(self.valid_m_s),
        }


def _decreasing_tail(eps: np.ndarray) -> int:
    """Index of the law's last maximum: from there on ``epsilon`` falls at every point."""
    k = eps.size - 1
    while k > 0 and eps[k - 1] > eps[k]:
        k -= 1
    return k


_SIGMA_FLOOR = 1e-12
"""Smallest error bar a point is weighted with (a zero error bar would divide by zero)."""


def _fit(v: np.ndarray, eps: np.ndarray, sigma: np.ndarray, p0) -> np.ndarray:
    # The optimiser tries parameters where the form overflows; those trials lose, and the fit
    # found is judged against every point afterwards (no warning for the user to act on).
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        popt, _ = curve_fit(_form, v, eps, p0=p0, sigma=sigma, absolute_sigma=True, maxfev=20000)
    return popt


def fit_closed_form(s: SILaw) -> ClosedForm:
    """Fit :class:`ClosedForm` to the law's computed points, weighted by their errors, on the
    widest range of speeds where it follows every point within its error bar.

    The form falls monotonically with the speed; the two-dimensional law does not (it has a
    maximum near ``v = 0.002 - 0.02 c``, docs/results.md), so the fit starts at the law's last
    maximum. Three parameters do not follow the shipped laws to their error bars over that
    whole tail: the range is then narrowed, one end at a time (the end point that misses more
    goes), and the form refitted, until every point left is within ``1 sigma``
    (:attr:`ClosedForm.max_deviation_sigma` ``<= 1``). ``valid_m_s`` is that range; outside it,
    use :func:`pchip_table` (what :func:`c_header` and :func:`fortran_include` evaluate).

    Raises
    ------
    InputError
        For a law with fewer than 4 points on its decreasing tail.
    RestitutionError
        When the form fits no range of 4 or more points within their errors, or has a pole
        inside the range it fits.
    """
    v_all = np.asarray(s.law.v, dtype=float)
    eps_all = np.asarray(s.law.epsilon_points, dtype=float)
    sig_all = np.maximum(np.asarray(s.law.epsilon_err_points, dtype=float), _SIGMA_FLOOR)
    lo, hi = _decreasing_tail(eps_all), v_all.size
    if hi - lo < 4:
        raise InputError(f"a three-parameter fit needs at least 4 points, the law has {hi - lo}")
    p0 = (1.0, 0.0, 0.8)
    while True:
        v, eps, sigma = v_all[lo:hi], eps_all[lo:hi], sig_all[lo:hi]
        try:
            popt = _fit(v, eps, sigma, p0)
        except (RuntimeError, ValueError) as exc:
            raise RestitutionError(f"the closed form did not fit the law's points: {exc}") from exc
        a, b, p = (float(x) for x in popt)
        if b < 0 and p > 0 and (-1.0 / b) ** (1.0 / p) <= v[-1]:
            raise RestitutionError(
                f"the closed form fitted to the law has a pole at v = {(-1.0 / b) ** (1.0 / p):.3g}"
                " c inside the computed range; use the table instead"
            )
        z = np.abs(_form(v, *popt) - eps) / sigma
        if np.all(np.isfinite(z)) and z.max() <= 1.0:
            break
        if hi - lo <= 4:
            raise RestitutionError(
                "the closed form follows no range of 4 or more computed points within their "
                "errors; use the table (pchip_table, epsilon.h)"
            )
        # Drop the end that misses more (a twentieth of the points at once on long laws).
        step = max(1, min((hi - lo - 4), (hi - lo) // 20))
        if z[:step].max() >= z[-step:].max():
            lo += step
        else:
            hi -= step
        p0 = tuple(popt) if np.all(np.isfinite(popt)) else p0
    popt, pcov = curve_fit(_form, v, eps, p0=popt, sigma=sigma, absolute_sigma=True, maxfev=20000)
    a, b, p = (float(x) for x in popt)
    resid = _form(v, *popt) - eps
    chi2_dof = float(np.sum((resid / sigma) ** 2) / max(v.size - 3, 1))
    return ClosedForm(
        a=a,
        b=b,
        p=p,
        covariance=pcov * max(1.0, chi2_dof),
        speed_scale_m_s=s.speed_scale_m_s,
        max_deviation=float(np.max(np.abs(resid))),
        max_deviation_sigma=float(np.max(np.abs(resid) / sigma)),
        chi2_dof=chi2_dof,
        valid_m_s=(float(v[0] * s.speed_scale_m_s), float(v[-1] * s.speed_scale_m_s)),
    )
