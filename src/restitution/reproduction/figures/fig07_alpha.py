"""Fig. 7: energy left in the vibrations, ``1 - epsilon^2``, versus ``1/alpha``.

For every speed: the data at the largest ``N`` of the grid (the paper used ``N = 940``) with
their regression line to ``alpha -> infinity`` (filled markers, solid lines), and the
``N -> infinity`` limits at every ``alpha`` with the second-stage line of the combined limit
(open markers, dashed), whose intercept is the final answer.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.limits.curves import Curve, compute_curves
from restitution.limits.extrapolation import extrapolate_alpha, extrapolate_modes
from restitution.limits.sweep import DEFAULTS, SweepSettings
from restitution.reproduction.figures._style import add_notes, limits_and_legends

__all__ = ["Fig07Data", "compute", "plot"]


@dataclass(frozen=True, eq=False)
class Fig07Data:
    """Numbers of Fig. 7 for one Poisson number.

    Attributes
    ----------
    nu : float
        Poisson number.
    n_modes : int
        The fixed ``N`` of the filled series (the largest of the grid).
    v : numpy.ndarray, shape (K,)
        Speeds towards the wall, units of ``c``.
    alpha : numpy.ndarray, shape (K, A)
        Wall hardness values at each speed, ``1/R`` (the same in every row unless the sweep
        scales ``alpha`` with the compression).
    loss : numpy.ndarray, shape (K, A)
        ``1 - epsilon^2`` at ``N = n_modes``.
    limit, slope : numpy.ndarray, shape (K,)
        Regression line of ``loss`` in ``1/alpha`` (intercept = ``alpha -> infinity``).
    loss_inf : numpy.ndarray, shape (K, A)
        ``N -> infinity`` limit at every ``alpha``.
    limit_inf, slope_inf : numpy.ndarray, shape (K,)
        Regression line of ``loss_inf`` (intercept = both limits).
    asymptotic_ok : numpy.ndarray of bool, shape (K,)
        Whether the fixed-``N`` fit passed the asymptotic checks.
    """

    nu: float
    n_modes: int
    v: np.ndarray
    alpha: np.ndarray
    loss: np.ndarray
    limit: np.ndarray
    slope: np.ndarray
    loss_inf: np.ndarray
    limit_inf: np.ndarray
    slope_inf: np.ndarray
    asymptotic_ok: np.ndarray


def compute(
    nu: float = 0.33,
    settings: SweepSettings = DEFAULTS,
    *,
    curve: Curve | None = None,
    **sweep_kwargs,
) -> Fig07Data:
    """Numbers of Fig. 7 from a computed ``curve`` or by running the sweep of ``settings``."""
    if curve is None:
        curve = compute_curves([nu], settings, **sweep_kwargs)[float(nu)]
    first = curve.limits[0]
    alpha = np.array([c.alpha for c in curve.limits])
    j = int(np.argmax(first.n_modes))
    loss, limit, slope, ok, loss_inf, limit_inf, slope_inf = [], [], [], [], [], [], []
    for c in curve.limits:
        fit = extrapolate_alpha(c.alpha, c.loss[:, j])
        loss.append(c.loss[:, j])
        limit.append(fit.limit)
        slope.append(fit.slope)
        ok.append(fit.asymptotic_ok)
        at_alpha = np.array([extrapolate_modes(c.n_modes, row).limit for row in c.loss])
        second = extrapolate_alpha(c.alpha, at_alpha)
        loss_inf.append(at_alpha)
        limit_inf.append(second.limit)
        slope_inf.append(second.slope)
    return Fig07Data(
        nu=float(curve.nu),
        n_modes=int(first.n_modes[j]),
        v=np.asarray(curve.velocities, dtype=float),
        alpha=alpha,
        loss=np.array(loss),
        limit=np.array(limit),
        slope=np.array(slope),
        loss_inf=np.array(loss_inf),
        limit_inf=np.array(limit_inf),
        slope_inf=np.array(slope_inf),
        asymptotic_ok=np.array(ok),
    )


def plot(data: Fig07Data, path: str | Path, note: str = "") -> Path:
    """Draw Fig. 7 to ``path``. ``note`` is printed under the axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 5.6))
    cmap = plt.get_cmap("viridis")
    for k, v in enumerate(data.v):
        x = 1.0 / data.alpha[k]
        line_x = np.linspace(0.0, 1.05 * x.max(), 50)
        color = cmap(k / max(len(data.v) - 1, 1))
        ax.plot(x, data.loss[k], "o", ms=3.5, color=color, label=f"{v:g}")
        ax.plot(line_x, data.limit[k] + data.slope[k] * line_x, "-", lw=0.8, color=color)
        ax.plot(x, data.loss_inf[k], "o", ms=3.5, mfc="none", color=color)
        ax.plot(line_x, data.limit_inf[k] + data.slope_inf[k] * line_x, "--", lw=0.6, color=color)
    ax.set_xlabel(r"$1/\alpha$")
    ax.set_ylabel(r"$1 - \epsilon^2$")
    ax.set_xlim(left=0.0)
    ax.set_title(
        f"$\\nu = {data.nu:g}$: filled N = {data.n_modes}, open N $\\to\\infty$", fontsize=9
    )
    # Intercepts at x = 0 (a negative one marked), and both legends outside the axes.
    limits_and_legends(
        ax,
        data.limit_inf,
        f"filled, solid: N = {data.n_modes}, line in $1/\\alpha$",
        r"open, dashed: N $\to\infty$ at each $\alpha$, line",
        len(data.v),
    )
    add_notes(fig, [note])
    path = Path(path)
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
    return path
