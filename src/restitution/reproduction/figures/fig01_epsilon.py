"""Fig. 1: the coefficient of restitution epsilon versus the speed towards the wall.

Both limits (hard wall, infinitely many modes) are taken at every speed
(:func:`restitution.limits.curves.compute_curves`); error bars are the extrapolation errors. Points
whose extrapolation failed the asymptotic checks are drawn open. Speeds are the disk's speed towards
the wall in units of ``c = sqrt(E/rho)``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.limits.curves import Curve, compute_curves
from restitution.limits.sweep import DEFAULTS, SweepSettings
from restitution.reproduction.figures._style import add_notes

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
    speed_unit : str
        Unit of ``v``: ``"c"`` (``sqrt(E/rho)``) or ``"c_L"`` (``c / sqrt(1 - nu^2)``, the
        dilatational wave speed; the collisions then ran at ``v / sqrt(1 - nu^2)`` in ``c``).
    """

    nus: tuple[float, ...]
    v: tuple[np.ndarray, ...]
    epsilon: tuple[np.ndarray, ...]
    epsilon_err: tuple[np.ndarray, ...]
    asymptotic_ok: tuple[np.ndarray, ...]
    speed_unit: str = "c"


def compute(
    nus: Sequence[float] = (0.33, 0.9),
    settings: SweepSettings = DEFAULTS,
    *,
    curves: Mapping[float, Curve] | None = None,
    speed_unit: str = "c",
    scale: Mapping[float, float] | None = None,
    **sweep_kwargs,
) -> Fig01Data:
    """Numbers of Fig. 1 from computed ``curves``, or by running the sweep of ``settings``.

    ``scale[nu]`` is ``speed_unit`` in units of ``c``: the curves' speeds (in ``c``) are divided
    by it. ``sweep_kwargs`` go to :func:`restitution.limits.curves.compute_curves` (``store``, ...).
    """
    if curves is None:
        curves = compute_curves(nus, settings, **sweep_kwargs)
    chosen = [curves[float(nu)] for nu in nus]
    factor = [1.0 if scale is None else float(scale[float(nu)]) for nu in nus]
    return Fig01Data(
        nus=tuple(float(nu) for nu in nus),
        speed_unit=speed_unit,
        v=tuple(
            np.asarray(c.velocities, dtype=float) / f for c, f in zip(chosen, factor, strict=True)
        ),
        epsilon=tuple(c.epsilon for c in chosen),
        epsilon_err=tuple(c.epsilon_err for c in chosen),
        asymptotic_ok=tuple(np.array([x.asymptotic_ok for x in c.limits]) for c in chosen),
    )


def plot(data: Fig01Data, path: str | Path, note: str = "") -> Path:
    """Draw Fig. 1 to ``path`` (format from the suffix); ``note`` is printed under the axes.

    Filled markers passed the asymptotic checks, open ones did not. An error bar is cut at
    ``epsilon = 1`` (energy conservation: the loss ``1 - epsilon^2`` cannot be negative) and the
    cut is drawn as a caret; the note under the axes says so when it happens.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from scipy.interpolate import PchipInterpolator

    fig, ax = plt.subplots(figsize=(6.0, 4.6))
    markers = "osD^v<>"
    clipped = False
    for k, nu in enumerate(data.nus):
        v, eps, err, ok = data.v[k], data.epsilon[k], data.epsilon_err[k], data.asymptotic_ok[k]
        finite = np.isfinite(eps)
        color = f"C{k}"
        upper = np.minimum(err, np.maximum(1.0 - eps, 0.0))
        cut = finite & (eps + err > 1.0)
        clipped |= bool(np.any(cut))
        for sel, face, what in (
            (finite & ok, color, "checks passed"),
            (finite & ~ok, "none", "not asymptotic"),
        ):
            if np.any(sel):
                ax.errorbar(
                    v[sel], eps[sel], yerr=[err[sel], upper[sel]],
                    fmt=markers[k % len(markers)], ms=4.5, mfc=face, mec=color, ecolor=color,
                    capsize=2, ls="none", label=f"$\\nu = {nu:g}$, {what}",
                )  # fmt: skip
        if np.any(cut):
            ax.plot(v[cut], np.ones(np.count_nonzero(cut)), "^", color=color, ms=5)
        if np.count_nonzero(finite) >= 2:
            # The computed points only, as the law serves them: no curve to an assumed
            # epsilon(0) = 1 (docs/results.md, slow collisions).
            xs = v[finite]
            curve = PchipInterpolator(xs, eps[finite])
            fine = np.linspace(xs[0], xs[-1], 200)
            ax.plot(fine, curve(fine), color=color, lw=0.8)
    ax.axhline(1.0, color="0.6", lw=0.6, ls=":")
    unit = r"c_L" if data.speed_unit == "c_L" else "c"
    ax.set_xlabel(rf"$v_i / {unit}$ (speed towards the wall)")
    ax.set_ylabel(r"$\epsilon$")
    ax.set_xlim(left=0.0)
    title = "Coefficient of restitution"
    if data.speed_unit == "c_L":
        title += r": speeds in $c_L = c/\sqrt{1-\nu^2}$"
    ax.set_title(title, fontsize=10)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, loc="lower left")
    notes = []
    if clipped:
        notes.append("^: error bar cut at epsilon = 1 (the energy loss cannot be negative)")
    add_notes(fig, [*notes, note])
    path = Path(path)
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
    return path
