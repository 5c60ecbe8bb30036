"""The law as a monotone piecewise-cubic (PCHIP) table in m/s, the one C and Fortran evaluate.

Knots at the law's computed speeds ``w`` (m/s), epsilon there (dimensionless) and the PCHIP
slopes ``d epsilon / d w`` (s/m). Below the slowest knot the table continues to ``w = 0`` with
the slow-impact asymptote (:mod:`~restitution.laws.exports.below`); above the fastest it has no
value (NaN, status :attr:`TableStatus.ABOVE`), never an extrapolation. Its deviation from the law
is measured, in absolute terms and in units of the law's error there.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.laws.exports.below import SlowContinuation, slow_continuation
from restitution.laws.exports.closed_form import _SIGMA_FLOOR
from restitution.laws.si_law import SILaw

__all__ = ["PchipTable", "TableStatus", "pchip_table"]


class TableStatus(IntEnum):
    """What the table's value at a speed is; the C and Fortran functions set the same codes.

    ``INSIDE`` (0) and ``BELOW`` (1) come with a coefficient; ``ABOVE`` (2) and ``BAD_SPEED`` (3)
    with NaN, which no code can take for a coefficient by mistake."""

    INSIDE = 0
    """On the computed speeds: the law's table."""
    BELOW = 1
    """Below the slowest computed speed (``w = 0`` included): the slow-impact continuation."""
    ABOVE = 2
    """Above the fastest computed speed: no value (NaN)."""
    BAD_SPEED = 3
    """A negative, infinite or NaN speed: no value (NaN)."""


@dataclass(frozen=True)
class PchipTable:
    """The law as a monotone piecewise-cubic table in m/s: what :func:`c_header` and
    :func:`fortran_include` evaluate.

    Between knots ``w_i`` the value is the cubic Hermite polynomial through ``(w_i, e_i)`` and
    ``(w_{i+1}, e_{i+1})`` with slopes ``d_i``, ``d_{i+1}``: Fritsch-Carlson / PCHIP slopes
    (:class:`scipy.interpolate.PchipInterpolator`), monotone wherever the points are, the
    interpolant the law itself uses between its computed points.

    Attributes
    ----------
    w_m_s : numpy.ndarray
        Knots: the computed speeds, m/s.
    epsilon : numpy.ndarray
        The law's points at the knots.
    slope_s_m : numpy.ndarray
        ``d epsilon / d w`` at the knots, s/m.
    max_deviation : float
        Largest ``|table - law|`` on the knots and 16 speeds inside every interval.
    max_deviation_sigma : float
        The same in units of the law's error there (:meth:`SILaw.epsilon_err`).
    below : SlowContinuation
        The slow-impact continuation below the slowest knot, to ``w = 0``.
    """

    w_m_s: np.ndarray
    epsilon: np.ndarray
    slope_s_m: np.ndarray
    max_deviation: float
    max_deviation_sigma: float
    below: SlowContinuation

    @property
    def range_m_s(self) -> tuple[float, float]:
        """``(w_min, w_max)``, m/s: the table's range (the law's computed speeds)."""
        return float(self.w_m_s[0]), float(self.w_m_s[-1])

    def status(self, speed_m_s):
        """:class:`TableStatus` code(s) of speed(s) ``w`` (m/s), as C and Fortran set them."""
        w = np.atleast_1d(np.asarray(speed_m_s, dtype=float))
        code = np.full(w.shape, int(TableStatus.BAD_SPEED))
        code[(w >= 0.0) & (w < self.w_m_s[0])] = TableStatus.BELOW
        code[(w >= self.w_m_s[0]) & (w <= self.w_m_s[-1])] = TableStatus.INSIDE
        code[(w > self.w_m_s[-1]) & np.isfinite(w)] = TableStatus.ABOVE
        return int(code[0]) if np.ndim(speed_m_s) == 0 else code

    def __call__(self, speed_m_s):
        """The table at speed(s) ``w`` (m/s) as C and Fortran evaluate it: the knots' cubic on
        :attr:`range_m_s`, the continuation :attr:`below` it, NaN above it or for a negative,
        infinite or NaN speed (:meth:`status` says which)."""
        w = np.atleast_1d(np.asarray(speed_m_s, dtype=float))
        x, y, d = self.w_m_s, self.epsilon, self.slope_s_m
        code = np.atleast_1d(self.status(w))
        inside = code == TableStatus.INSIDE
        i = np.clip(np.searchsorted(x, np.where(inside, w, x[0]), side="right") - 1, 0, x.size - 2)
        h = x[i + 1] - x[i]
        t = (np.where(inside, w, x[0]) - x[i]) / h
        val = (
            (1 + 2 * t) * (1 - t) ** 2 * y[i]
            + t * (1 - t) ** 2 * h * d[i]
            + t**2 * (3 - 2 * t) * y[i + 1]
            - t**2 * (1 - t) * h * d[i + 1]
        )
        slow = code == TableStatus.BELOW
        out = np.where(inside, val, np.nan)
        out[slow] = self.below(w[slow])
        return float(out[0]) if np.ndim(speed_m_s) == 0 else out


LOG_KNOTS_INSIDE = 7
"""Knots added inside every interval of a law that interpolates in ``ln v`` (a mechanism's
table, :data:`restitution.laws.law_point.LOG_V`): the C, Fortran and plugin tables are cubic in
``w``, and through the law's own knots alone they missed its interpolant by 3.1e-4 at 1 m/s in
plastic steel's table, three times its stated error there (the plugin's rebound in LAMMPS
showed it). With the law's values and slopes at seven more speeds an interval (geometric) the
cubic in ``w`` follows the law's cubic in ``ln v``: the deviation is measured below."""


def _knots(s: SILaw) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(w, epsilon, d epsilon / d w)`` at the knots of the law's table: its computed speeds,
    with PCHIP's slopes in ``w``; for a law that interpolates in ``ln v``, its own interpolant's
    values and slopes at the computed speeds and :data:`LOG_KNOTS_INSIDE` speeds inside every
    interval."""
    from restitution.laws.law_point import LOG_V

    scale = s.speed_scale_m_s
    v = np.asarray(s.law.v, dtype=float)
    eps = np.asarray(s.law.epsilon_points, dtype=float)
    if (getattr(s.law, "metadata", None) or {}).get("interpolate_in") != LOG_V:
        w = v * scale
        return w, eps, PchipInterpolator(w, eps).derivative()(w)
    frac = np.arange(1, LOG_KNOTS_INSIDE + 1) / (LOG_KNOTS_INSIDE + 1)
    inside = (v[:-1, None] * (v[1:, None] / v[:-1, None]) ** frac[None, :]).ravel()
    at = np.sort(np.concatenate([v, inside]))
    through = PchipInterpolator(np.log(v), eps)  # the law's own (EpsilonLaw._interpolant)
    values = through(np.log(at))
    values[np.searchsorted(at, v)] = eps  # the computed points as they are
    w = at * scale
    return w, values, through.derivative()(np.log(at)) / w


def pchip_table(s: SILaw) -> PchipTable:
    """:class:`PchipTable` of the law over its computed speeds, with its measured deviation."""
    w, eps, slope = _knots(s)
    below = slow_continuation(s, float(w[0]), float(eps[0]))
    t = PchipTable(w, eps, slope, 0.0, 0.0, below)
    inner = np.linspace(0.0, 1.0, 18)[1:-1]
    probe = np.concatenate([w, (w[:-1, None] + np.diff(w)[:, None] * inner).ravel()])
    probe = probe[(probe >= w[0]) & (probe <= w[-1])]
    dev = np.abs(t(probe) - s.epsilon(probe))
    err = np.maximum(s.epsilon_err(probe), _SIGMA_FLOOR)
    return PchipTable(w, eps, slope, float(dev.max()), float((dev / err).max()), below)
