"""Fits of simpler oblique-impact models to the package's ``beta``: Walton's three parameters
and the stiffness of the DEM codes' tangential models, each with the misfit that remains.

Units: dimensionless (``X = tan(theta) / mu``, ``beta``, ``chi``); the LAMMPS parameters in Pa
where they have one.

* :func:`fit_walton`: Walton's ``e``, ``mu_W`` and ``beta_0``
  (:func:`~restitution.laws.tangential_models.walton_beta`): ``e`` is the mean of the measured
  ``epsilon_normal`` (Walton's normal coefficient, which the points give directly), ``mu_W`` and
  ``beta_0`` least squares on ``beta``.
* :func:`fit_history`: the one stiffness ``chi`` of LAMMPS's ``mindlin`` (``k_t a / k_n``,
  speed-free) or ``linear_history`` (``k_t / k_n(delta_max)``, a ``k_t`` per speed) that fits
  ``beta`` best (:func:`~restitution.laws.tangential_models.history_beta`); friction is the
  given ``mu`` and the tangential damping ``x_gamma,t = 0`` (elastic grains).
* :func:`fit_microslip`: the same for Maw, Barber and Fawcett's microslip law (law (b) of
  :mod:`restitution.quasistatic.oblique`), ``chi = 2 (1 - nu) / (2 - nu)`` in its range
  ``(2/3, 4/3)``.

The misfit is stated as the root mean square and the largest ``|beta_model - beta|`` over the
points fitted: how far each model is from the package's ``beta`` (the points' own error, the
change from half the modes, is stored beside them and is not a weight here).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares, minimize_scalar

from restitution.errors import InputError
from restitution.laws.tangential_models import history_beta, walton_beta

__all__ = [
    "HistoryFit",
    "WaltonFit",
    "fit_history",
    "fit_microslip",
    "fit_walton",
    "lammps_mindlin_kt",
]


@dataclass(frozen=True)
class WaltonFit:
    """Walton's parameters and the misfit: ``e``, ``mu_W`` (``mu_ratio`` times the ``mu`` of
    the points), ``beta_0``; ``rms`` and ``largest`` of ``beta_model - beta``; ``points``."""

    e: float
    mu_w: float
    mu_ratio: float
    beta_0: float
    rms: float
    largest: float
    points: int

    def to_dict(self) -> dict:
        return dict(self.__dict__)


@dataclass(frozen=True)
class HistoryFit:
    """One tangential model's fitted stiffness ``chi`` and its misfit (``rms``, ``largest``)."""

    model: str
    chi: float
    rms: float
    largest: float
    points: int

    def to_dict(self) -> dict:
        return dict(self.__dict__)


def _arrays(X, beta):
    X, beta = np.asarray(X, dtype=float), np.asarray(beta, dtype=float)
    if X.shape != beta.shape or X.ndim != 1 or X.size < 2:
        raise InputError("give X and beta as two 1-D arrays of one length, at least 2 points")
    if not (np.all(np.isfinite(X) & (X > 0)) and np.all(np.isfinite(beta))):
        raise InputError("X = tan(theta)/mu must be positive and beta finite")
    return X, beta


def fit_walton(X, beta, epsilon_normal, mu: float, inertia_factor: float = 3.0) -> WaltonFit:
    """Walton's ``e, mu_W, beta_0`` fitted to ``beta(X)`` and ``epsilon_normal`` (module docs).

    >>> X = np.array([0.5, 1.0, 2.0, 5.0, 10.0])
    >>> from restitution.laws.tangential_models import walton_beta
    >>> f = fit_walton(X, walton_beta(X, 0.98, 1.1, 0.35), [0.98] * 5, 0.3)
    >>> round(f.mu_w, 6), round(f.beta_0, 6), f.rms < 1e-9
    (0.33, 0.35, True)
    """
    X, beta = _arrays(X, beta)
    e = float(np.mean(np.asarray(epsilon_normal, dtype=float)))

    def residual(p):
        return walton_beta(X, e, p[0], p[1], inertia_factor) - beta

    best = None
    for b0 in np.linspace(-0.9, 0.9, 7):  # the model is piecewise: several starts
        sol = least_squares(residual, [1.0, b0], bounds=([1e-3, -1.0], [1e3, 1.0]))
        if best is None or sol.cost < best.cost:
            best = sol
    r = residual(best.x)
    return WaltonFit(e, float(best.x[0] * mu), float(best.x[0]), float(best.x[1]),
                     float(np.sqrt(np.mean(r**2))), float(np.max(np.abs(r))), X.size)  # fmt: skip


def _fit_chi(model_beta, beta, bounds, name, scan) -> HistoryFit:
    def cost(chi):
        return float(np.sum((model_beta(chi) - beta) ** 2))

    # beta(chi) oscillates (the tangential oscillation turns more during the contact as chi
    # grows), so the cost has several minima: scan a grid, then refine around its best.
    grid = np.geomspace(*bounds, scan)
    k = int(np.argmin([cost(c) for c in grid]))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    sol = minimize_scalar(cost, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6})
    r = model_beta(sol.x) - beta
    return HistoryFit(name, float(sol.x), float(np.sqrt(np.mean(r**2))),
                      float(np.max(np.abs(r))), beta.size)  # fmt: skip


def fit_history(X, beta, model: str = "mindlin", inertia_factor: float = 3.0,
                steps: int = 4000, scan: int = 41) -> HistoryFit:  # fmt: skip
    """The stiffness ``chi`` of LAMMPS's ``model`` that fits ``beta(X)`` best (module docs):
    the best of ``scan`` values on ``[0.05, 5]`` (geometric), refined between its neighbours.

    >>> X = np.array([0.5, 1.0, 2.0, 3.0, 8.0])
    >>> from restitution.laws.tangential_models import history_beta
    >>> f = fit_history(X, history_beta(X, 0.8, steps=4000))
    >>> round(f.chi, 3), f.rms < 1e-4
    (0.8, True)
    """
    X, beta = _arrays(X, beta)

    def model_beta(chi):
        return history_beta(X, chi, model, inertia_factor=inertia_factor, steps=steps)

    return _fit_chi(model_beta, beta, (0.05, 5.0), model, scan)


def fit_microslip(
    X, beta, inertia_factor: float = 3.0, springs: int = 200, scan: int = 41
) -> HistoryFit:
    """The ``chi`` of Maw, Barber and Fawcett's microslip law that fits ``beta(X)`` best,
    ``chi`` in ``(2/3, 4/3)`` (Poisson numbers ``(-1, 0.5)``); ``springs`` of its method of
    dimensionality reduction (error about ``springs^-2``)."""
    from restitution.quasistatic.oblique import beta_of_psi

    X, beta = _arrays(X, beta)

    def model(chi):
        nu = (2.0 - 2.0 * chi) / (2.0 - chi)
        return beta_of_psi(chi * X, nu, inertia_factor=inertia_factor, model="microslip",
                           springs=springs)  # fmt: skip

    return _fit_chi(model, beta, (0.67, 1.33), "microslip", scan)


def lammps_mindlin_kt(chi: float, E: float, nu: float) -> dict:
    """LAMMPS's ``mindlin`` ``k_t`` (Pa) for the fitted ``chi = k_t / (2 E_eff)`` of grains of
    one material (``E_eff = E / (2 (1 - nu^2))``, the manual's mixing of ``hertz/material``), and
    its ratio to the ``NULL`` value ``8 G``, ``1/G = 4 (2 - nu)(1 + nu) / E`` (whose ``chi`` is
    Mindlin's ``2 (1 - nu) / (2 - nu)``).

    >>> d = lammps_mindlin_kt(2 * 0.7 / 1.7, 210e9, 0.3)
    >>> round(d["ratio_to_null"], 12)
    1.0
    """
    e_eff = E / (2.0 * (1.0 - nu * nu))
    null = 8.0 * E / (4.0 * (2.0 - nu) * (1.0 + nu))
    kt = 2.0 * chi * e_eff
    return {"k_t_pa": kt, "null_k_t_pa": null, "ratio_to_null": kt / null,
            "mindlin_chi": 2.0 * (1.0 - nu) / (2.0 - nu)}  # fmt: skip
