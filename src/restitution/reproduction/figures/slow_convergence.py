"""Convergence of the slowest points of a law in the number of modes and the wall hardness.

Units: speeds in ``c``; energy loss ``1 - epsilon^2`` (fraction of the initial kinetic energy);
``alpha`` in ``1/R``.

For every speed of the law below ``v_max`` (default ``2e-3 c``), the left panel shows the
energy loss against ``1/sqrt(N)`` at each wall hardness with the fitted line to ``N -> infinity``
(dashed), the right panel those limits against ``1/alpha`` with the line to ``alpha -> infinity``
and the point's final value with its error. Everything is read from the law's stored grids and
fits (the same numbers the law serves); nothing is recomputed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.reproduction.figures._style import add_notes

__all__ = ["SlowPoint", "compute", "plot"]


@dataclass(frozen=True)
class SlowPoint:
    """The grid and limits behind one point.

    Attributes
    ----------
    v : float
        Speed, ``c``.
    alpha : numpy.ndarray, shape (A,)
    n_modes : numpy.ndarray, shape (M,)
    loss : numpy.ndarray, shape (A, M)
        ``1 - epsilon^2`` at ``(alpha_i, N_j)``.
    n_limit, n_limit_err, n_slope : numpy.ndarray, shape (A,)
        ``N -> infinity`` at each ``alpha``: intercept, its error and the fitted slope in
        ``1/sqrt(N)``.
    limit, limit_err, alpha_slope : float
        Both limits, and the slope of the second fit in ``1/alpha``.
    ok : bool
        Whether the point passed its checks.
    """

    v: float
    alpha: np.ndarray
    n_modes: np.ndarray
    loss: np.ndarray
    n_limit: np.ndarray
    n_limit_err: np.ndarray
    n_slope: np.ndarray
    limit: float
    limit_err: float
    alpha_slope: float
    ok: bool


def compute(law, v_max: float = 2e-3, count: int | None = None) -> tuple[SlowPoint, ...]:
    """The slow modal points of ``law`` (an :class:`restitution.laws.law.EpsilonLaw`),
    ``v <= v_max`` (its low-speed points and the points of the residual route, which converge
    in ``N`` without an extrapolation in ``1/sqrt(N)``, have none to show); with ``count``, the
    ``count`` slowest of them."""
    out = []
    for p in law.metadata.get("points", []):
        if p["v"] > v_max * (1 + 1e-9) or p.get("route", "modal") != "modal":
            continue
        ex = p["extrapolation"]
        fits = ex["fits"]
        first = fits["first"]  # N -> infinity at every alpha (order "modes_first")
        out.append(
            SlowPoint(
                v=float(p["v"]),
                alpha=np.asarray(ex["alpha"], float),
                n_modes=np.asarray(ex["n_modes"], int),
                loss=np.asarray(ex["energy_loss_grid"], float),
                n_limit=np.array([f["limit"] for f in first], float),
                n_limit_err=np.array([f["limit_err"] for f in first], float),
                n_slope=np.array([f["slope"] for f in first], float),
                limit=float(p["energy_loss"]),
                limit_err=float(p["energy_loss_err"]),
                alpha_slope=float(fits["second"]["slope"]),
                ok=bool(p["asymptotic_ok"]),
            )
        )
    out.sort(key=lambda p: p.v)
    return tuple(out if count is None else out[:count])


def plot(points: tuple[SlowPoint, ...], nu: float, path=None, notes=()):
    """Two panels per speed; returns the matplotlib figure (saved to ``path`` if given)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = max(len(points), 1)
    fig, axes = plt.subplots(rows, 2, figsize=(9.0, 2.6 * rows + 0.6), squeeze=False)
    for row, p in zip(axes, points, strict=False):
        ax_n, ax_a = row
        x = 1.0 / np.sqrt(p.n_modes)
        for i, a in enumerate(p.alpha):
            (line,) = ax_n.plot(x, p.loss[i], "o-", ms=4, label=f"alpha = {a:.3g}")
            xs = np.array([0.0, x.max()])
            ax_n.plot(xs, p.n_limit[i] + p.n_slope[i] * xs, "--", color=line.get_color(), lw=1)
            ax_n.errorbar([0.0], [p.n_limit[i]], yerr=[p.n_limit_err[i]], fmt="s",
                          color=line.get_color(), ms=4, capsize=2)  # fmt: skip
        ax_n.set_xlabel("1/sqrt(N)")
        ax_n.set_ylabel("1 - epsilon^2")
        ax_n.set_title(f"v = {p.v:g} c: N -> infinity at each alpha", fontsize=9)
        ax_n.set_xlim(left=-0.0005)
        ax_n.legend(fontsize=7)
        ia = 1.0 / p.alpha
        ax_a.errorbar(ia, p.n_limit, yerr=p.n_limit_err, fmt="o", ms=4, capsize=2,
                      label="N -> infinity limits")  # fmt: skip
        xs = np.array([0.0, ia.max()])
        ax_a.plot(xs, p.limit + p.alpha_slope * xs, "k--", lw=1)
        verdict = "passes its checks" if p.ok else "flagged: not asymptotic"
        ax_a.errorbar([0.0], [p.limit], yerr=[p.limit_err], fmt="D", color="k", ms=5, capsize=3,
                      label=f"both limits ({verdict})")  # fmt: skip
        ax_a.set_xlabel("1/alpha [R]")
        ax_a.set_title(f"v = {p.v:g} c: alpha -> infinity", fontsize=9)
        ax_a.set_xlim(left=-0.05 * ia.max())
        ax_a.legend(fontsize=7)
    fig.suptitle(f"Slow collisions, nu = {nu:g}: convergence in N and alpha", fontsize=10)
    add_notes(
        fig, ["dashed: the fitted straight lines to the limits; squares/diamond: limits", *notes]
    )
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig
