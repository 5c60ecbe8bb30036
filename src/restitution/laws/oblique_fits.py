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
* :func:`fit_table`: all four at every speed of an oblique table (the rows of
  :func:`restitution.laws.making.oblique_table.compute_table`, ``law --angle``'s runs over
  angles), as :class:`ObliqueFits`, whose :meth:`~ObliqueFits.summary` adds LAMMPS's ``k_t``
  in Pa for the grain on the wall and for two grains of the material
  (:func:`lammps_mindlin_kt`).

The misfit is stated as the root mean square and the largest ``|beta_model - beta|`` over the
points fitted: how far each model is from the package's ``beta`` (the points' own error, the
change from half the modes, is stored beside them and is not a weight here).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares, minimize_scalar

from restitution.errors import InputError
from restitution.laws.exports.lammps_plugin import contact_modulus, contact_shear_modulus
from restitution.laws.tangential_models import history_beta, walton_beta

__all__ = [
    "FIT_NAMES",
    "HistoryFit",
    "ObliqueFits",
    "WaltonFit",
    "fit_history",
    "fit_microslip",
    "fit_table",
    "fit_walton",
    "lammps_mindlin_kt",
]

FIT_NAMES = ("walton", "mindlin", "linear_history", "microslip")
"""The fits of :func:`fit_table`, in the order they are reported."""


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


def _fit_chi(model_beta, beta, bounds, name, scan, grid_beta=None) -> HistoryFit:
    """The ``chi`` in ``bounds`` whose ``model_beta(chi)`` fits ``beta`` best; ``grid_beta``
    (optional): the model at an array of ``chi`` at once, one row each."""

    def cost(chi):
        return float(np.sum((model_beta(chi) - beta) ** 2))

    # beta(chi) oscillates (the tangential oscillation turns more during the contact as chi
    # grows), so the cost has several minima: scan a grid, then refine around its best.
    grid = np.geomspace(*bounds, scan)
    if grid_beta is None:
        costs = [cost(c) for c in grid]
    else:
        costs = np.sum((grid_beta(grid) - beta) ** 2, axis=1)
    k = int(np.argmin(costs))
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

    return _fit_chi(model_beta, beta, (0.05, 5.0), model, scan, grid_beta=model_beta)


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
    """LAMMPS's ``mindlin`` ``k_t`` (Pa) for the fitted ``chi = k_t a / k_n = k_t / (2 E*)``
    of grains of one material (``E* = E / (2 (1 - nu^2))``, the manual's mixing of
    ``hertz/material``), and its ratio to the ``NULL`` value ``8 G*``, ``1/G* = 4 (2 - nu)(1 +
    nu) / E`` (whose ``chi`` is Mindlin's ``2 (1 - nu) / (2 - nu)``); the same for the grain on
    the rigid wall (``wall_*``: ``E* = E / (1 - nu^2)``, ``1/G* = 2 (2 - nu)(1 + nu) / E``, the
    numbers of the exported wall line; :mod:`restitution.laws.exports.dem.lammps`). ``chi`` is
    one number for both contacts: Mindlin's ``4 G* / E*`` is the same for the wall and for two
    grains of one material, and the fit is made on the wall.

    >>> d = lammps_mindlin_kt(2 * 0.7 / 1.7, 210e9, 0.3)
    >>> round(d["ratio_to_null"], 12), round(d["wall_k_t_pa"] / d["wall_null_k_t_pa"], 12)
    (1.0, 1.0)
    """
    pair, wall = (E, nu), ()
    out = {}
    for prefix, partner in (("", pair), ("wall_", wall)):
        kt = 2.0 * chi * contact_modulus(E, nu, *partner)
        null = 8.0 * contact_shear_modulus(E, nu, *partner)
        out.update({f"{prefix}k_t_pa": kt, f"{prefix}null_k_t_pa": null,
                    f"{prefix}ratio_to_null": kt / null})  # fmt: skip
    return {**out, "mindlin_chi": 2.0 * (1.0 - nu) / (2.0 - nu)}


@dataclass(frozen=True, eq=False)
class ObliqueFits:
    """An oblique table's points per speed and the fits to them (arrays over the oblique
    angles).

    Attributes
    ----------
    speeds : tuple of float
        m/s.
    X, beta, beta_err, eps, eps_err, angle : dict of float to numpy.ndarray
        Per speed: ``tan(theta) / mu``, ``beta`` and its error, ``epsilon_normal`` and its
        error, the angle (degrees).
    head_on : dict of float to float
        ``epsilon_normal`` at angle 0 (the same modes and wall), where the table has it.
    walton, mindlin, linear_history, microslip : dict of float to fit
    friction : float
    material : dict
        The table's ``material`` (``E_pa``, ``nu``, ``rho_kg_m3``, ``shape``).
    inertia_factor : float
        ``K = 1 + m R^2 / I`` of the grain (3 for a disk, 7/2 for a solid sphere).
    """

    speeds: tuple
    X: dict
    beta: dict
    beta_err: dict
    eps: dict
    eps_err: dict
    angle: dict
    head_on: dict
    walton: dict
    mindlin: dict
    linear_history: dict
    microslip: dict
    friction: float
    material: dict
    inertia_factor: float

    def summary(self) -> dict:
        """Every fit per speed as JSON values (with LAMMPS's ``mindlin`` ``k_t``,
        :func:`lammps_mindlin_kt`), keyed by the speed's text."""
        m = self.material
        out = {}
        for w in self.speeds:
            out[str(w)] = {
                "walton": self.walton[w].to_dict(),
                "mindlin": {**self.mindlin[w].to_dict(),
                            **lammps_mindlin_kt(self.mindlin[w].chi, m["E_pa"], m["nu"])},
                "linear_history": self.linear_history[w].to_dict(),
                "microslip": self.microslip[w].to_dict(),
            }  # fmt: skip
        return out


def _speed_rows(rows, w):
    """The oblique rows of speed ``w`` by angle, and its angle-0 row (or ``None``)."""
    mine = sorted((r for r in rows if r["speed_m_s"] == w and r["angle_deg"] > 0),
                  key=lambda r: r["angle_deg"])  # fmt: skip
    zero = [r for r in rows if r["speed_m_s"] == w and r["angle_deg"] == 0]
    return mine, (zero[0] if zero else None)


def fit_table(table: dict, speeds=None, *, inertia_factor: float | None = None,
              steps: int = 4000, springs: int = 200, scan: int = 41) -> ObliqueFits:  # fmt: skip
    """Every fit (:data:`FIT_NAMES`) at every speed of the oblique ``table`` (as
    :func:`restitution.laws.making.oblique_table.compute_table` returns and stores it), or at
    ``speeds`` only. ``inertia_factor``: the table's own (stored since it was added), else give
    it. ``steps`` and ``springs`` are the resolutions of the DEM models and the microslip law,
    ``scan`` the stiffnesses scanned before a fit is refined. A speed needs two oblique
    angles whose ``beta`` was computed."""
    K = table.get("inertia_factor") if inertia_factor is None else inertia_factor
    if K is None:
        raise InputError(
            "this oblique table does not store its inertia_factor (K = 1 + m R^2 / I): give "
            "inertia_factor=3.0 for a disk or 3.5 for a sphere"
        )
    mu = float(table["friction"])
    speeds = tuple(table["speeds_m_s"] if speeds is None else speeds)
    per = {k: {} for k in ("X", "beta", "beta_err", "eps", "eps_err", "angle")}
    head_on, fits = {}, {k: {} for k in FIT_NAMES}
    for w in speeds:
        mine, zero = _speed_rows(table["rows"], w)
        mine = [r for r in mine if r["beta"] is not None]
        if len(mine) < 2:
            raise InputError(f"the table has {len(mine)} oblique angle(s) with a beta at "
                             f"{w:g} m/s: the fits need two or more (add angles)")  # fmt: skip
        if zero is not None:
            head_on[w] = zero["epsilon_normal"]
        angle = np.array([r["angle_deg"] for r in mine])
        X = np.tan(np.radians(angle)) / mu
        beta = np.array([r["beta"] for r in mine])
        eps = np.array([r["epsilon_normal"] for r in mine])
        per["X"][w], per["beta"][w], per["eps"][w], per["angle"][w] = X, beta, eps, angle
        per["beta_err"][w] = np.array([r["beta_error"] for r in mine])
        per["eps_err"][w] = np.array([r["epsilon_normal_error"] for r in mine])
        fits["walton"][w] = fit_walton(X, beta, eps, mu, K)
        fits["mindlin"][w] = fit_history(X, beta, "mindlin", K, steps, scan)
        fits["linear_history"][w] = fit_history(X, beta, "linear_history", K, steps, scan)
        fits["microslip"][w] = fit_microslip(X, beta, K, springs, scan)
    return ObliqueFits(speeds, **per, head_on=head_on, **fits, friction=mu,
                       material=table["material"], inertia_factor=float(K))  # fmt: skip
