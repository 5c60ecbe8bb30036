"""Extrapolation of the vibrational energy to a hard wall and to infinitely many modes.

Paper section 4. The fraction of the initial kinetic energy left in the vibrations after the
collision, ``L = 1 - epsilon^2`` (dimensionless), is computed for finite wall hardness ``alpha``
(units ``1/R``) and a finite number ``N`` of modes. Two limits are needed:

* ``alpha -> infinity``: ``L`` is linear in ``1/alpha`` (Fig. 7), because the energy held by the
  wall potential at closest approach is ``~ 1/alpha``.
* ``N -> infinity``: ``L`` is linear in ``1/sqrt(N)`` (Fig. 8).

Each limit is the intercept of a straight-line least-squares fit. Its uncertainty is the
fit's standard error combined in quadrature with the *drop-one spread*: the change of the
intercept when the least asymptotic point (smallest ``alpha`` or smallest ``N``) is left out.
On data that are linear up to independent noise this gives close to the nominal 68 % coverage
(checked by a test on synthetic data).

A fit is flagged (``asymptotic_ok = False`` with a message), never silently trusted, when

* it has fewer than 3 points (linearity cannot be judged);
* the drop-one spread exceeds ``drop_tol`` times the extrapolated step ``|limit - y_near|``
  (``y_near`` is the data point closest to the limit): leaving out one point changes the
  extrapolated part of the answer by too much;
* the data are curved: the slope of a quadratic through them changes by more than
  ``curvature_tol`` (relative to the straight line's slope) between ``x = 0`` and the least
  asymptotic point, and the quadratic term is significant at two standard errors where that can
  be estimated (>= 4 points, or known point errors).

Scale-free tests (spread divided by the standard error, chi-square with an estimated noise) are
useless here: the collision data are deterministic, their residuals *are* the curvature, and
for 3 points the ratio spread / standard error is a constant of the design. Hence the relative
tests above.

The combined limit (both ``alpha`` and ``N`` to infinity) from a grid ``L[i, j]`` at
``(alpha_i, N_j)`` is taken in a documented order, by default ``N -> infinity`` at every
``alpha`` first, then ``alpha -> infinity`` of those limits; the other order is computed as a
check. The errors of the first stage are propagated through the second stage's intercept
weights as independent errors. With unweighted fits on a complete grid the two orders give the
*same* limit exactly (the two intercept functionals are linear and commute); they differ in
their error estimates and, when points are missing or the drop-one fits are taken, in the limit.
The combined error is the larger of the two orders' errors combined in quadrature with their
difference and with the wall's curvature: how far a quadratic in ``1/alpha`` through the
``alpha -> infinity`` fit's points moves its limit (:func:`alpha_curvature_shift`; the
verdicts above are taken before it joins). ``epsilon = sqrt(1 - L)`` with
``epsilon_err = L_err / (2 epsilon)``.

**Negligible first stages.** The relative tests above measure a fit's instability against its
own extrapolated step; where the data are flat (the loss at one ``alpha`` changes by 1e-5 over
a factor 8 in ``N`` while the ``alpha`` extrapolation is uncertain by 1e-4) the step is close to
zero and the ratio means nothing. A failing first-stage fit is therefore not held against the
combined limit when everything it can do to the answer -- the largest of its extrapolated step,
its drop-one spread and the shift of its limit to a quadratic fit -- is below ``drop_tol``
times the second stage's *own* error (its standard error and drop-one spread, without the
errors propagated from the first stage, so the rule is not circular). The waiver is recorded
in ``CombinedLimit.notes``; the fit's error is still propagated into the combined error.

**Flat first stages: window stability.** Both relative tests divide by something that can be
zero within its own error: the drop-one test by the extrapolated step, the curvature test by
the slope. Where a first-stage fit's slope is zero within two standard errors (the loss does
not resolve a direction of convergence in ``N``; it only wiggles, as at ``nu = 0.9``,
``v = 5e-4``, where it moves by 7e-5 over ``N = 12800-102400``), the two ratios mean nothing.
Such a fit (with at least 4 points, so that a window without one member can still be judged)
is not held against the combined limit if the *whole answer* is stable within its stated
error against the window: the combined limit recomputed without the window's least
asymptotic member, and without its most asymptotic member (the answer before that member was
added), must both lie within ``limit_err`` of the full window's limit. Fits whose slope is
resolved keep the relative tests; a stable window does not rescue them. The outcome is
recorded in ``CombinedLimit.notes`` (passed) or ``message`` (failed) with the numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from restitution.errors import InputError
from restitution.estimate import Estimate, estimate_of
from restitution.jsonable import finite_or_none

__all__ = [
    "CombinedLimit",
    "FromLoss",
    "LinearLimit",
    "alpha_curvature_shift",
    "combined_limit",
    "epsilon_from_loss",
    "extrapolate_alpha",
    "extrapolate_modes",
    "linear_limit",
]

DROP_TOL = 0.3
"""Largest accepted drop-one spread relative to the extrapolated step ``|limit - y_near|``."""
CURVATURE_TOL = 0.5
"""Largest accepted relative change of the slope between ``x = 0`` and the largest ``x``."""
MIN_POINTS = 3
"""Fewest points with which linearity can be judged."""


@dataclass(frozen=True, eq=False)
class LinearLimit:
    """Intercept at ``x = 0`` of a straight line through ``(x, y)``.

    Attributes
    ----------
    variable : str
        Name of the abscissa, e.g. ``"1/alpha"`` or ``"1/sqrt(N)"``.
    parameter : numpy.ndarray, shape (n,)
        The parameter behind each point (``alpha`` in ``1/R``, or ``N``), as given.
    x, y : numpy.ndarray, shape (n,)
        Abscissa and data of the points used (non-finite points removed).
    limit : float
        Intercept ``y(x = 0)``: the extrapolated value.
    limit_err : float
        ``sqrt(stat_err^2 + drop_spread^2 + propagated_err^2)``.
    stat_err : float
        Standard error of the intercept from the fit residuals (and known point errors).
    drop_spread : float
        ``|limit - limit without the least asymptotic point|`` (0 with fewer than 3 points).
    propagated_err : float
        Error of the intercept from known point errors ``y_err`` taken as independent.
    slope, slope_err : float
        Slope ``dy/dx`` and its standard error.
    residuals : numpy.ndarray, shape (n,)
        ``y - fit``.
    curvature : float
        Relative change of the slope of a quadratic through the points between ``x = 0`` and
        the least asymptotic point (``nan`` with fewer than 3 points).
    asymptotic_ok : bool
        False when the points do not look asymptotic; ``message`` says why.
    message : str
        Empty when ``asymptotic_ok``.
    """

    variable: str
    parameter: np.ndarray
    x: np.ndarray
    y: np.ndarray
    limit: float
    limit_err: float
    stat_err: float
    drop_spread: float
    propagated_err: float
    slope: float
    slope_err: float
    residuals: np.ndarray
    curvature: float
    asymptotic_ok: bool
    message: str = ""

    def line(self, x: np.ndarray) -> np.ndarray:
        """The fitted line at ``x``."""
        return self.limit + self.slope * np.asarray(x, dtype=float)

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "variable": self.variable,
            "parameter": _floats(self.parameter),
            "x": _floats(self.x),
            "y": _floats(self.y),
            "limit": finite_or_none(self.limit),
            "limit_err": finite_or_none(self.limit_err),
            "stat_err": finite_or_none(self.stat_err),
            "drop_spread": finite_or_none(self.drop_spread),
            "propagated_err": finite_or_none(self.propagated_err),
            "slope": finite_or_none(self.slope),
            "slope_err": finite_or_none(self.slope_err),
            "residuals": _floats(self.residuals),
            "curvature": finite_or_none(self.curvature),
            "asymptotic_ok": bool(self.asymptotic_ok),
            "message": self.message,
        }


def _floats(values: np.ndarray) -> list:
    return [finite_or_none(v) for v in np.asarray(values, dtype=float).ravel()]


def _line_fit(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float, float, np.ndarray]:
    """Unweighted straight line: intercept, slope, their standard errors, intercept weights.

    The intercept is ``sum(w * y)``; the weights let errors of ``y`` be propagated.
    """
    n = x.size
    design = np.column_stack([np.ones(n), x])
    pinv = np.linalg.pinv(design)  # rows: intercept and slope weights
    intercept, slope = pinv @ y
    resid = y - design @ np.array([intercept, slope])
    if n > 2:
        s2 = float(resid @ resid) / (n - 2)
        cov = s2 * (pinv @ pinv.T)
        se_b, se_a = math.sqrt(max(cov[0, 0], 0.0)), math.sqrt(max(cov[1, 1], 0.0))
    else:
        se_b = se_a = 0.0
    return float(intercept), float(slope), se_b, se_a, pinv[0]


def linear_limit(
    x: np.ndarray,
    y: np.ndarray,
    *,
    y_err: np.ndarray | None = None,
    variable: str = "x",
    parameter: np.ndarray | None = None,
    drop_tol: float = DROP_TOL,
    curvature_tol: float = CURVATURE_TOL,
) -> LinearLimit:
    """Extrapolate ``y`` linearly in ``x`` to ``x = 0``.

    Parameters
    ----------
    x : array_like, shape (n,)
        Abscissa, positive; the point with the largest ``x`` is the least asymptotic one.
    y : array_like, shape (n,)
        Data. Points where ``x`` or ``y`` is not finite are ignored (failed collisions).
    y_err : array_like, shape (n,), optional
        Known independent errors of ``y``; they are propagated into ``propagated_err`` and
        used as the noise scale of the curvature significance test.
    variable : str
        Name of ``x`` for messages and exports.
    parameter : array_like, shape (n,), optional
        The parameter behind ``x`` (stored for exports); defaults to ``x``.
    drop_tol, curvature_tol : float
        Thresholds of the asymptotic checks (module docstring).

    Returns
    -------
    LinearLimit

    Examples
    --------
    >>> fit = linear_limit([0.1, 0.2, 0.3], [1.1, 1.2, 1.3])
    >>> round(fit.limit, 12), fit.asymptotic_ok
    (1.0, True)
    """
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    par = x if parameter is None else np.asarray(parameter, dtype=float).ravel()
    err = None if y_err is None else np.asarray(y_err, dtype=float).ravel()
    if x.shape != y.shape or par.shape != x.shape or (err is not None and err.shape != x.shape):
        raise InputError(
            f"x, y (and parameter, y_err) must have the same length; got {x.size} and {y.size}"
        )
    keep = np.isfinite(x) & np.isfinite(y)
    if err is not None:
        keep &= np.isfinite(err)
    order = np.argsort(x[keep])  # most asymptotic first
    x, y, par = x[keep][order], y[keep][order], par[keep][order]
    err = None if err is None else np.abs(err[keep][order])
    n = x.size
    if n < 2 or np.ptp(x) == 0.0:
        nan = float("nan")
        limit = float(y[0]) if n == 1 else nan
        return LinearLimit(
            variable, par, x, y, limit, nan, nan, nan, nan, nan, nan, np.zeros(n), nan,
            False, f"{n} distinct point(s) in {variable}: cannot extrapolate; need >= {MIN_POINTS}",
        )  # fmt: skip
    if np.any(x <= 0):
        raise InputError(f"{variable} must be positive for an extrapolation to {variable} = 0")

    limit, slope, se_b, se_a, weights = _line_fit(x, y)
    residuals = y - (limit + slope * x)
    propagated = 0.0 if err is None else float(math.sqrt(np.sum((weights * err) ** 2)))
    drop_spread = 0.0
    if n >= MIN_POINTS:
        drop_limit = _line_fit(x[:-1], y[:-1])[0]
        drop_spread = abs(limit - drop_limit)
    # Model error: with four or more points, the shift of the limit when a quadratic term is
    # allowed. Deterministic data that are still curved would otherwise get error bars that
    # only measure how well a straight line fits a curve (measured: a 4-sigma shift at
    # nu = 0.9, v = 0.3 over N = 300-940).
    # Only where the curvature is significant against the noise, so noisy straight lines keep
    # their nominal coverage.
    model_err = 0.0
    if n >= MIN_POINTS + 1 and _curvature(x, y, slope, err)[1]:
        model_err = abs(float(np.polyfit(x, y, 2)[2]) - limit)
    limit_err = math.sqrt(se_b**2 + drop_spread**2 + propagated**2 + model_err**2)

    problems = []
    curvature = float("nan")
    if n < MIN_POINTS:
        problems.append(f"only {n} points in {variable}; need >= {MIN_POINTS} to judge linearity")
    else:
        step = abs(limit - y[0])
        if drop_spread > drop_tol * step and drop_spread > 2.0 * propagated:
            problems.append(
                f"dropping the least asymptotic point ({variable} = {x[-1]:.4g}) moves the limit "
                f"by {drop_spread:.3g}, more than {drop_tol:g} x the extrapolated step {step:.3g}"
            )
        curvature, significant = _curvature(x, y, slope, err)
        if curvature > curvature_tol and significant:
            problems.append(
                f"curved in {variable}: the slope changes by {100 * curvature:.0f}% between "
                f"{variable} = 0 and {x[-1]:.4g} (tolerance {100 * curvature_tol:.0f}%); "
                "add more asymptotic points"
            )
    return LinearLimit(
        variable=variable,
        parameter=par,
        x=x,
        y=y,
        limit=limit,
        limit_err=limit_err,
        stat_err=se_b,
        drop_spread=drop_spread,
        propagated_err=propagated,
        slope=slope,
        slope_err=se_a,
        residuals=residuals,
        curvature=curvature,
        asymptotic_ok=not problems,
        message="; ".join(problems),
    )


def _curvature(
    x: np.ndarray, y: np.ndarray, slope: float, err: np.ndarray | None
) -> tuple[float, bool]:
    """Relative slope change ``|2 c x_max / slope|`` of a quadratic fit, and its significance.

    The quadratic term counts as significant when it exceeds two standard errors; with 3 points
    and no known errors its error cannot be estimated and it counts as significant.
    """
    n = x.size
    scale = np.ptp(x)
    t = (x - x.mean()) / scale
    design = np.column_stack([np.ones(n), t, t**2])
    pinv = np.linalg.pinv(design)
    coef = pinv @ y
    c = coef[2] / scale**2
    curvature = abs(2.0 * c * x[-1] / slope) if slope != 0.0 else float("inf")
    variance = 0.0
    if n > 3:
        resid = y - design @ coef
        variance = float(resid @ resid) / (n - 3) * float(pinv[2] @ pinv[2])
    if err is not None:
        variance = max(variance, float(np.sum((pinv[2] * err) ** 2)))
    if n == 3 and err is None:
        return curvature, True
    return curvature, abs(coef[2]) > 2.0 * math.sqrt(variance)


def extrapolate_alpha(
    alpha: np.ndarray, loss: np.ndarray, *, loss_err: np.ndarray | None = None, **kwargs
) -> LinearLimit:
    """Limit ``alpha -> infinity`` of the energy loss, linear in ``1/alpha`` (Fig. 7).

    Parameters
    ----------
    alpha : array_like, shape (n,)
        Wall hardness, ``1/R``.
    loss : array_like, shape (n,)
        ``1 - epsilon^2`` at each ``alpha`` (fraction of the initial kinetic energy).
    loss_err : array_like, shape (n,), optional
        Known errors of ``loss``.
    **kwargs
        Passed to :func:`linear_limit` (``drop_tol``, ``curvature_tol``).
    """
    alpha = np.asarray(alpha, dtype=float)
    if np.any(alpha <= 0):
        raise InputError("alpha (wall hardness, 1/R) must be positive")
    return linear_limit(
        1.0 / alpha, loss, y_err=loss_err, variable="1/alpha", parameter=alpha, **kwargs
    )


def extrapolate_modes(
    n_modes: np.ndarray, loss: np.ndarray, *, loss_err: np.ndarray | None = None, **kwargs
) -> LinearLimit:
    """Limit ``N -> infinity`` of the energy loss, linear in ``1/sqrt(N)`` (Fig. 8).

    Parameters
    ----------
    n_modes : array_like of int, shape (n,)
        Number of modes ``N`` of each run.
    loss : array_like, shape (n,)
        ``1 - epsilon^2`` at each ``N``.
    loss_err : array_like, shape (n,), optional
        Known errors of ``loss``.
    **kwargs
        Passed to :func:`linear_limit`.
    """
    n_modes = np.asarray(n_modes, dtype=float)
    if np.any(n_modes < 1):
        raise InputError("numbers of modes must be >= 1")
    return linear_limit(
        1.0 / np.sqrt(n_modes),
        loss,
        y_err=loss_err,
        variable="1/sqrt(N)",
        parameter=n_modes,
        **kwargs,
    )


def epsilon_from_loss(loss: float, loss_err: float) -> tuple[float, float]:
    """``epsilon = sqrt(1 - loss)`` and its first-order error ``loss_err / (2 epsilon)``.

    A loss outside ``[0, 1)`` gives ``nan`` for epsilon above 1 or imaginary; the caller flags it.
    """
    if not (0.0 <= loss < 1.0) or not math.isfinite(loss):
        return float("nan"), float("nan")
    eps = math.sqrt(1.0 - loss)
    return eps, loss_err / (2.0 * eps)


class FromLoss:
    """``epsilon`` and ``epsilon_err`` of a record that holds an energy loss and its error
    (fields ``energy_loss``, ``energy_loss_err``): :func:`epsilon_from_loss` of them, ``nan``
    for a loss outside ``[0, 1)``."""

    __slots__ = ()

    energy_loss: float
    energy_loss_err: float
    estimate: Estimate  # each record's own (its status and message), as every such record has

    @property
    def epsilon(self) -> float:
        """``sqrt(1 - energy_loss)`` (``nan`` for a loss outside ``[0, 1)``)."""
        return epsilon_from_loss(self.energy_loss, self.energy_loss_err)[0]

    @property
    def epsilon_err(self) -> float:
        """Its error, ``energy_loss_err / (2 epsilon)``."""
        return epsilon_from_loss(self.energy_loss, self.energy_loss_err)[1]


@dataclass(frozen=True, eq=False)
class CombinedLimit:
    """Energy loss and epsilon extrapolated to ``alpha -> infinity`` and ``N -> infinity``.

    Attributes
    ----------
    alpha : numpy.ndarray, shape (A,)
        Wall hardness values, ``1/R``.
    n_modes : numpy.ndarray of int, shape (M,)
        Mode counts.
    loss : numpy.ndarray, shape (A, M)
        ``1 - epsilon^2`` on the grid (``nan`` where a collision failed).
    order : str
        ``"modes_first"`` (``N -> inf`` at each ``alpha``, then ``alpha -> inf``) or
        ``"alpha_first"``; the primary order.
    limit, limit_err : float
        Extrapolated loss and its error (module docstring); :attr:`epsilon`,
        :attr:`epsilon_err` and :attr:`estimate` derive from them.
    first : tuple of LinearLimit
        First-stage fits of the primary order (one per ``alpha`` for ``modes_first``).
    second : LinearLimit
        Second-stage fit of the primary order.
    check_first, check_second : tuple of LinearLimit, LinearLimit
        The same for the other order.
    order_difference : float
        ``limit(primary) - limit(other order)``.
    asymptotic_ok : bool
        All fits of the primary order are asymptotic (or negligible, see ``notes``), the orders
        agree within the error and the limit is a physical loss.
    message : str
        Why not, when not.
    settings : dict
        Tolerances passed to the fits.
    notes : str
        First-stage fits whose relative tests were waived because their whole extrapolation is
        negligible (module docstring), with the numbers.
    alpha_curvature : float
        :func:`alpha_curvature_shift` of the ``alpha -> infinity`` fit of the ``modes_first``
        order; joined in quadrature into ``limit_err``.
    """

    alpha: np.ndarray
    n_modes: np.ndarray
    loss: np.ndarray
    order: str
    limit: float
    limit_err: float
    first: tuple[LinearLimit, ...]
    second: LinearLimit
    check_first: tuple[LinearLimit, ...]
    check_second: LinearLimit
    order_difference: float
    asymptotic_ok: bool
    message: str = ""
    settings: dict = field(default_factory=dict)
    notes: str = ""
    alpha_curvature: float = 0.0

    @property
    def epsilon(self) -> float:
        """``sqrt(1 - limit)`` (``nan`` if the limit is outside ``[0, 1)``)."""
        return epsilon_from_loss(self.limit, self.limit_err)[0]

    @property
    def epsilon_err(self) -> float:
        """Its error, ``limit_err / (2 epsilon)``."""
        return epsilon_from_loss(self.limit, self.limit_err)[1]

    def to_dict(self, *, fits: bool = True) -> dict:
        """JSON-ready dictionary; ``fits=False`` leaves out the individual fits."""
        d = {
            "order": self.order,
            "alpha": _floats(self.alpha),
            "n_modes": [int(n) for n in self.n_modes],
            "energy_loss_grid": [_floats(row) for row in self.loss],
            "energy_loss": finite_or_none(self.limit),
            "energy_loss_err": finite_or_none(self.limit_err),
            "epsilon": finite_or_none(self.epsilon),
            "epsilon_err": finite_or_none(self.epsilon_err),
            "order_difference": finite_or_none(self.order_difference),
            "alpha_curvature": finite_or_none(self.alpha_curvature),
            "asymptotic_ok": bool(self.asymptotic_ok),
            "message": self.message,
            "notes": self.notes,
            "settings": dict(self.settings),
        }
        if fits:
            d["fits"] = {
                "first": [f.to_dict() for f in self.first],
                "second": self.second.to_dict(),
                "check_first": [f.to_dict() for f in self.check_first],
                "check_second": self.check_second.to_dict(),
            }
        return d

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return estimate_of(self.epsilon, self.epsilon_err, self.asymptotic_ok, self.message)


def _two_stage(
    alpha: np.ndarray, n_modes: np.ndarray, loss: np.ndarray, modes_first: bool, kwargs: dict
) -> tuple[tuple[LinearLimit, ...], LinearLimit]:
    if modes_first:
        first = tuple(extrapolate_modes(n_modes, row, **kwargs) for row in loss)
        lim = np.array([f.limit for f in first])
        err = np.array([f.limit_err for f in first])
        second = extrapolate_alpha(alpha, lim, loss_err=_err_or_none(err), **kwargs)
    else:
        first = tuple(extrapolate_alpha(alpha, col, **kwargs) for col in loss.T)
        lim = np.array([f.limit for f in first])
        err = np.array([f.limit_err for f in first])
        second = extrapolate_modes(n_modes, lim, loss_err=_err_or_none(err), **kwargs)
    return first, second


def _err_or_none(err: np.ndarray) -> np.ndarray:
    # Fits that could not give an error (too few points) keep their value with zero error; the
    # flag of that fit carries the warning.
    return np.where(np.isfinite(err), err, 0.0)


def combined_limit(
    alpha: np.ndarray,
    n_modes: np.ndarray,
    loss: np.ndarray,
    *,
    order: str = "modes_first",
    stability: bool = True,
    **kwargs,
) -> CombinedLimit:
    """Extrapolate a grid of energy losses to ``alpha -> infinity`` and ``N -> infinity``.

    Parameters
    ----------
    alpha : array_like, shape (A,)
        Wall hardness values, ``1/R``.
    n_modes : array_like of int, shape (M,)
        Mode counts.
    loss : array_like, shape (A, M)
        ``1 - epsilon^2`` at ``(alpha_i, N_j)``; ``nan`` marks a missing point.
    order : {"modes_first", "alpha_first"}
        Primary order of the two limits; the other is computed as a check.
    stability : bool
        Judge flat first-stage fits by window stability (module docstring). ``False`` flags
        them like any other failing fit (used for the reduced windows of that very test).
    **kwargs
        Passed to :func:`linear_limit` (``drop_tol``, ``curvature_tol``).

    Returns
    -------
    CombinedLimit
    """
    if order not in ("modes_first", "alpha_first"):
        raise InputError(f"order must be 'modes_first' or 'alpha_first', not {order!r}")
    alpha = np.asarray(alpha, dtype=float).ravel()
    n_modes = np.asarray(n_modes).ravel().astype(int)
    loss = np.asarray(loss, dtype=float)
    if loss.shape != (alpha.size, n_modes.size):
        raise InputError(
            f"loss grid must have shape (len(alpha), len(n_modes)) = "
            f"({alpha.size}, {n_modes.size}); got {loss.shape}"
        )
    primary = order == "modes_first"
    first, second = _two_stage(alpha, n_modes, loss, primary, kwargs)
    check_first, check_second = _two_stage(alpha, n_modes, loss, not primary, kwargs)
    difference = second.limit - check_second.limit
    err = math.sqrt(max(second.limit_err, check_second.limit_err) ** 2 + difference**2)

    problems = []
    notes = []
    stage1 = "N" if primary else "alpha"
    own = math.hypot(second.stat_err, second.drop_spread)
    drop_tol = kwargs.get("drop_tol", DROP_TOL)
    flat = []
    for fit, value in zip(first, alpha if primary else n_modes, strict=True):
        if fit.asymptotic_ok:
            continue
        name = "alpha" if primary else "N"
        reach = _consequence(fit)
        if reach < drop_tol * own:
            notes.append(
                f"{stage1} -> inf at {name} = {value:g}: relative tests waived, the whole "
                f"extrapolation moves the loss by at most {reach:.2g} < {drop_tol:g} x the "
                f"second stage's own error {own:.2g} ({fit.message})"
            )
        elif _flat(fit):
            flat.append(
                f"{stage1} -> inf at {name} = {value:g}: slope {fit.slope:.2g} +- "
                f"{fit.slope_err:.2g} is zero within 2 standard errors ({fit.message})"
            )
        else:
            problems.append(f"{stage1} -> inf at {name} = {value:g}: {fit.message}")
    if flat and stability:
        shifts = _window_shifts(alpha, n_modes, loss, order, second.limit, kwargs)
        verdict = (
            f"the combined limit moves by {shifts[0]:.2g} without the window's least "
            f"asymptotic member and by {shifts[1]:.2g} without its most asymptotic member"
        )
        if max(shifts) <= err:
            notes.extend(
                f"{text}; relative tests ill-posed, window stable: {verdict}, within the "
                f"error {err:.2g}"
                for text in flat
            )
        else:
            problems.extend(
                f"{text}; window not stable: {verdict}, more than the error {err:.2g}"
                for text in flat
            )
    elif flat:
        problems.extend(flat)
    if not second.asymptotic_ok:
        problems.append(f"{'alpha' if primary else 'N'} -> inf: {second.message}")
    # Round-off floor: on a complete grid the two orders agree to machine precision.
    floor = 1e-12 * max(1.0, abs(second.limit))
    if math.isfinite(difference) and abs(difference) > max(
        second.limit_err, check_second.limit_err, floor
    ):
        problems.append(f"the two orders of the limits differ by {difference:.3g}")
    # The stated error also holds what the wall's curvature in 1/alpha can move the limit
    # (after every verdict above, which keeps its own rules).
    bend = alpha_curvature_shift(second if primary else check_second)
    err = math.hypot(err, bend)
    if not math.isfinite(epsilon_from_loss(second.limit, err)[0]):
        problems.append(f"extrapolated energy loss {second.limit:.4g} is outside [0, 1)")
    return CombinedLimit(
        alpha=alpha,
        n_modes=n_modes,
        loss=loss,
        order=order,
        limit=second.limit,
        limit_err=err,
        first=first,
        second=second,
        check_first=check_first,
        check_second=check_second,
        order_difference=difference,
        asymptotic_ok=not problems,
        message="; ".join(problems),
        settings={k: float(v) for k, v in kwargs.items()},
        notes="; ".join(notes),
        alpha_curvature=bend,
    )


def alpha_curvature_shift(fit: LinearLimit) -> float:
    """How far a quadratic through the ``alpha -> infinity`` fit's points (in ``1/alpha``)
    moves its limit from the straight line's: the bias of the line when the loss bends in
    ``1/alpha``; 0 with fewer than three points.

    Measured on the sphere (``nu = 0.3``, ``v = 0.0993``): its production walls (``alpha
    delta_max = 80, 160, 320``) gave epsilon = 0.9914089 with an error of 5.0e-5 before this
    term; the walls ``160-640`` and ``320-1280`` gave 0.9913508 and 0.9913394, 5.8e-5 and
    7.0e-5 away; this shift is 6.3e-5 of epsilon there (docs/numerics.md)."""
    if fit.y.size < MIN_POINTS or not math.isfinite(fit.limit):
        return 0.0
    return abs(float(np.polyfit(fit.x, fit.y, 2)[2]) - fit.limit)


def _consequence(fit: LinearLimit) -> float:
    """The most a first-stage fit's extrapolation can move the loss: the largest of its
    extrapolated step, its drop-one spread and the shift of its limit to a quadratic fit."""
    if fit.y.size < MIN_POINTS or not math.isfinite(fit.limit):
        return math.inf
    quadratic = float(np.polyfit(fit.x, fit.y, 2)[2])
    return max(abs(fit.limit - fit.y[0]), fit.drop_spread, abs(quadratic - fit.limit))


def _flat(fit: LinearLimit) -> bool:
    """A fit of at least 4 points whose slope is zero within two standard errors."""
    return (
        fit.y.size >= MIN_POINTS + 1
        and math.isfinite(fit.slope_err)
        and abs(fit.slope) <= 2.0 * fit.slope_err
    )


def _window_shifts(
    alpha: np.ndarray,
    n_modes: np.ndarray,
    loss: np.ndarray,
    order: str,
    limit: float,
    kwargs: dict,
) -> tuple[float, float]:
    """How far the combined limit moves when the first stage's window loses its least
    asymptotic member and when it loses its most asymptotic one."""
    # The first stage's axis: N (more modes = more asymptotic) or alpha (harder = more).
    axis = 1 if order == "modes_first" else 0
    members = n_modes if axis == 1 else alpha
    by_order = np.argsort(members)

    def shift(j: int) -> float:
        grid = dict(alpha=alpha, n_modes=n_modes)
        grid["n_modes" if axis == 1 else "alpha"] = np.delete(members, j)
        reduced = combined_limit(
            **grid, loss=np.delete(loss, j, axis=axis), order=order, stability=False, **kwargs
        )
        return abs(reduced.limit - limit)

    return shift(by_order[0]), shift(by_order[-1])
