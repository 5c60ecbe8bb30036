"""The measured order of convergence in the number of modes, without assuming it.

Units: the loss ``1 - epsilon^2`` is a fraction of the initial kinetic energy; ``N`` counts modes.

The extrapolation ``N -> infinity`` of :mod:`restitution.limits.extrapolation` is linear in
``1/sqrt(N)`` (the paper's Fig. 8, for the disk). Whether a body's loss converges like that is a
measurement: this module fits

    L(N) = L_inf + A N^(-p)

with ``p`` free (:func:`power_law_fit`, least squares by :func:`scipy.optimize.curve_fit`) and
gives the *local* exponents of successive doublings (:func:`local_exponents`): for three counts
``N, 2N, 4N``, ``p = log2((L(N) - L(2N)) / (L(2N) - L(4N)))``, exact for a pure power law and
independent of ``L_inf``. A window of ``N`` is in the asymptotic regime of a power law when the
local exponents are steady; their spread is the honest error of ``p``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import curve_fit

from restitution.errors import InputError
from restitution.jsonable import finite_or_none

__all__ = ["PowerLawFit", "local_exponents", "power_law_fit"]


@dataclass(frozen=True)
class PowerLawFit:
    """``L(N) = limit + amplitude N^(-exponent)`` fitted to a window of mode counts.

    Attributes
    ----------
    n_min, n_max : int
        The window.
    limit, amplitude, exponent : float
        Fitted parameters (``nan`` when the fit failed).
    exponent_err : float
        Standard error of ``exponent`` from the fit's covariance.
    rms : float
        Root-mean-square residual.
    """

    n_min: int
    n_max: int
    limit: float
    amplitude: float
    exponent: float
    exponent_err: float
    rms: float

    def to_dict(self) -> dict:
        """JSON-ready dictionary (non-finite numbers as ``None``)."""
        return {k: finite_or_none(v) if isinstance(v, float) else v for k, v in vars(self).items()}


def _checked(n_modes, loss) -> tuple[np.ndarray, np.ndarray]:
    n = np.asarray(n_modes, dtype=float)
    y = np.asarray(loss, dtype=float)
    if n.shape != y.shape or n.ndim != 1:
        raise InputError("n_modes and loss must be 1-D arrays of one length")
    if np.any(n < 1) or np.any(np.diff(n) <= 0):
        raise InputError("n_modes must be increasing counts >= 1")
    return n, y


def power_law_fit(n_modes, loss) -> PowerLawFit:
    """Least-squares fit of ``L_inf + A N^(-p)`` to at least four points, ``p`` free.

    The start is the local exponent of the first and last thirds; a fit that does not converge
    returns ``nan`` parameters rather than raising (a measurement, not a failure).
    """
    n, y = _checked(n_modes, loss)
    if n.size < 4:
        raise InputError("a power law with a free exponent needs at least 4 points")
    keep = np.isfinite(y)
    n, y = n[keep], y[keep]
    nan = float("nan")
    if n.size < 4:
        return PowerLawFit(int(n[0]) if n.size else 0, int(n[-1]) if n.size else 0,
                           nan, nan, nan, nan, nan)  # fmt: skip
    scale = n[0]

    def model(x, limit, amplitude, p):
        return limit + amplitude * (x / scale) ** (-p)

    start = (float(y[-1]), float(y[0] - y[-1]), 0.5)
    try:
        params, cov = curve_fit(model, n, y, p0=start, maxfev=20000)
    except (RuntimeError, ValueError):
        return PowerLawFit(int(n[0]), int(n[-1]), nan, nan, nan, nan, nan)
    err = math.sqrt(cov[2, 2]) if np.all(np.isfinite(cov)) and cov[2, 2] >= 0 else nan
    rms = float(np.sqrt(np.mean((model(n, *params) - y) ** 2)))
    limit, amplitude, p = (float(x) for x in params)
    return PowerLawFit(int(n[0]), int(n[-1]), limit, amplitude * scale**p, p, err, rms)


def local_exponents(n_modes, loss) -> tuple[np.ndarray, np.ndarray]:
    """Exponents of successive doublings: ``(N_mid, p)`` for every triple ``N, 2N, 4N``.

    ``n_modes`` must hold the doublings (other counts are ignored); ``p`` is ``nan`` where the
    two differences differ in sign (no power law there).
    """
    n, y = _checked(n_modes, loss)
    index = {int(round(x)): i for i, x in enumerate(n)}
    mids, ps = [], []
    for i, x in enumerate(n):
        j, k = index.get(int(round(2 * x))), index.get(int(round(4 * x)))
        if j is None or k is None:
            continue
        d1, d2 = y[i] - y[j], y[j] - y[k]
        mids.append(2 * x)
        ps.append(math.log2(d1 / d2) if d1 * d2 > 0 else float("nan"))
    return np.array(mids), np.array(ps)
