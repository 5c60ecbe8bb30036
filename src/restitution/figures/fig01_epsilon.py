"""Fig. 1: the coefficient of restitution epsilon versus the speed towards the wall.

Both limits (hard wall, infinitely many modes) are taken at every speed
(:func:`restitution.law.compute_curves`); error bars are the extrapolation errors. Points whose
extrapolation failed the asymptotic checks are drawn open. Speeds are the disk's speed towards
the wall in units of ``c = sqrt(E/rho)``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.law import Curve, compute_curves
from restitution.sweep import DEFAULTS, SweepSettings

__all__ = ["Fig01Data", "compute", "plot"]


@dataclass(frozen=True, eq=False)
class Fig01Data:
    """Numbers of Fig. 1.

    Attributes
    ----------
    nus : tuple of float
        Poisson numbers, one curve each.
    v : tuple of numpy.ndarray, shape (K,)
        Speeds towards the wall, units of ``c``.
    epsilon, epsilon_err : tuple of numpy.ndarray, shape (K,)
        Extrapolated epsilon and its error (``nan`` where the extrapolation failed).
    asymptotic_ok : tuple of numpy.ndarray of bool, shape (K,)
        Whether each point passed the asymptotic checks.
    """

    nus: tuple[float, ...]
    v: tuple[np.ndarray, ...]
    epsilon: tuple[np.ndarray, ...]
    epsilon_err: tuple[np.ndarray, ...]
    asymptotic_ok: tuple[np.ndarray, ...]


def compute(
    nus: Sequence[float] = (0.33, 0.9),
    settings: SweepSettings = DEFAULTS,
    *,
    curves: Mapping[float, Curve] | None = None,
    **sweep_kwargs,
) -> Fig01Data:
    """Numbers of Fig. 1 from computed ``curves``, or by running the sweep of ``settings``.

    ``sweep_kwargs`` go to :func:`restitution.law.compute_curves` (``store``, ``workers``, ...).
    """
    if curves is None:
        curves = compute_curves(nus, settings, **sweep_kwargs)
    chosen = [curves[float(nu)] for nu in nus]
    return Fig01Data(
        nus=tuple(float(nu) for nu in nus),
        v=tuple(np.asarray(c.velocities, dtype=float) for c in chosen),
        epsilon=tuple(c.epsilon for c in chosen),
        epsilon_err=tuple(c.epsilon_err for c in chosen),
        asymptotic_ok=tuple(np.array([x.asymptotic_ok for x in c.limits]) for c in chosen),
    )


def plot(data: Fig01Data, path: str | Path) -> Path:
    """Draw Fig. 1 to ``path`` (format from the suffix)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from scipy.interpolate import PchipInterpolator

    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    markers = "osD^v<>"
    for k, nu in enumerate(data.nus):
        v, eps, err, ok = data.v[k], data.epsilon[k], data.epsilon_err[k], data.asymptotic_ok[k]
        finite = np.isfinite(eps)
        color = f"C{k}"
        label = f"$\\nu = {nu:g}$"
        for sel, face in ((finite & ok, color), (finite & ~ok, "none")):
            if np.any(sel):
                ax.errorbar(
                    v[sel], eps[sel], yerr=err[sel], fmt=markers[k % len(markers)], ms=4,
                    mfc=face, mec=color, ecolor=color, capsize=2, ls="none",
                    label=label,
                )  # fmt: skip
                label = None
        if np.count_nonzero(finite) >= 1:
            xs = np.r_[0.0, v[finite]]
            curve = PchipInterpolator(xs, np.r_[1.0, eps[finite]])
            fine = np.linspace(0.0, xs[-1], 200)
            ax.plot(fine, curve(fine), color=color, lw=0.8)
    ax.set_xlabel(r"$v_i / c$ (speed towards the wall)")
    ax.set_ylabel(r"$\epsilon$")
    ax.set_xlim(left=0.0)
    ax.set_title("Coefficient of restitution (open: not asymptotic)", fontsize=9)
    if ax.get_legend_handles_labels()[0]:
        ax.legend()
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path
