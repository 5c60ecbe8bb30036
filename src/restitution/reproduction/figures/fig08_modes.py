"""Fig. 8: energy left in the vibrations versus ``1/sqrt(N)``, extrapolated to ``N -> infinity``.

For every speed: the data at the largest ``alpha`` of the grid with their regression line
(filled markers, solid lines; the paper's regression used ``N = 300, 400, 600, 940``), and the
``alpha -> infinity`` limits at every ``N`` with their line (open markers, dashed).
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

__all__ = ["Fig08Data", "compute", "plot"]


@dataclass(frozen=True, eq=False)
class Fig08Data:
    """Numbers of Fig. 8 for one Poisson number.

    Attributes
    ----------
    nu : float
        Poisson number.
    alpha : numpy.ndarray, shape (K,)
        The fixed wall hardness of the filled series at each speed (the largest of the grid),
        ``1/R``.
    v : numpy.ndarray, shape (K,)
        Speeds towards the wall, units of ``c``.
    n_modes : numpy.ndarray of int, shape (M,)
        Mode counts.
    loss : numpy.ndarray, shape (K, M)
        ``1 - epsilon^2`` at ``alpha``.
    limit, slope : numpy.ndarray, shape (K,)
        Regression line of ``loss`` in ``1/sqrt(N)``.
    loss_inf : numpy.ndarray, shape (K, M)
        ``alpha -> infinity`` limit at every ``N``.
    limit_inf, slope_inf : numpy.ndarray, shape (K,)
        Regression line of ``loss_inf``.
    asymptotic_ok : numpy.ndarray of bool, shape (K,)
        Whether the fixed-``alpha`` fit passed the asymptotic checks.
    """

    nu: float
    alpha: np.ndarray
    v: np.ndarray
    n_modes: np.ndarray
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
) -> Fig08Data:
    """Numbers of Fig. 8 from a computed ``curve`` or by running the sweep of ``settings``."""
    if curve is None:
        curve = compute_curves([nu], settings, **sweep_kwargs)[float(nu)]
    first = curve.limits[0]
    i = int(np.argmax(first.alpha))
    loss, limit, slope, ok, loss_inf, limit_inf, slope_inf = [], [], [], [], [], [], []
    for c in curve.limits:
        fit = extrapolate_modes(c.n_modes, c.loss[i])
        loss.append(c.loss[i])
        limit.append(fit.limit)
        slope.append(fit.slope)
        ok.append(fit.asymptotic_ok)
        at_n = np.array([extrapolate_alpha(c.alpha, col).limit for col in c.loss.T])
        second = extrapolate_modes(c.n_modes, at_n)
        loss_inf.append(at_n)
        limit_inf.append(second.limit)
        slope_inf.append(second.slope)
    return Fig08Data(
        nu=float(curve.nu),
        alpha=np.array([c.alpha[i] for c in curve.limits]),
        v=np.asarray(curve.velocities, dtype=float),
        n_modes=np.asarray(first.n_modes, dtype=int),
        loss=np.array(loss),
        limit=np.array(limit),
        slope=np.array(slope),
        loss_inf=np.array(loss_inf),
        limit_inf=np.array(limit_inf),
        slope_inf=np.array(slope_inf),
        asymptotic_ok=np.array(ok),
    )


def plot(data: Fig08Data, path: str | Path, note: str = "") -> Path:
    """Draw Fig. 8 to ``path``. ``note`` is printed under the axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 5.6))
    x = 1.0 / np.sqrt(data.n_modes)
    line_x = np.linspace(0.0, 1.05 * x.max(), 50)
    cmap = plt.get_cmap("viridis")
    for k, v in enumerate(data.v):
        color = cmap(k / max(len(data.v) - 1, 1))
        ax.plot(x, data.loss[k], "o", ms=3.5, color=color, label=f"{v:g}")
        ax.plot(line_x, data.limit[k] + data.slope[k] * line_x, "-", lw=0.8, color=color)
        ax.plot(x, data.loss_inf[k], "o", ms=3.5, mfc="none", color=color)
        ax.plot(line_x, data.limit_inf[k] + data.slope_inf[k] * line_x, "--", lw=0.6, color=color)
    ax.set_xlabel(r"$1/\sqrt{N}$")
    ax.set_ylabel(r"$1 - \epsilon^2$")
    ax.set_xlim(left=0.0)
    ax.set_title(
        f"$\\nu = {data.nu:g}$: filled largest $\\alpha$, open $\\alpha \\to\\infty$",
        fontsize=9,
    )
    # Intercepts at x = 0 (a negative one marked), and both legends outside the axes.
    limits_and_legends(
        ax,
        data.limit_inf,
        r"filled, solid: largest $\alpha$, line in $1/\sqrt{N}$",
        r"open, dashed: $\alpha \to\infty$ at each N, line",
        len(data.v),
    )
    add_notes(fig, [note])
    path = Path(path)
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
    return path
