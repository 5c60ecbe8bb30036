"""How the sphere's loss converges in the number of modes: the measured law behind its limit.

Units: speeds in ``c`` (of the sphere's 3D constants); energy loss ``1 - epsilon^2`` (fraction of
the initial kinetic energy); ``alpha`` in ``1/R``; ``N`` counts the lowest axisymmetric modes.

For a few speeds and walls (``alpha * delta_max(v)``, Hertz ``delta_max``) the sphere collides
with ``N`` from 100 to 12800 modes on two interleaved doubling ladders (``100 * 2^k`` and
``150 * 2^k``). The left panel shows the loss against ``1/sqrt(N)``; the right panel the local
exponents ``p`` of successive doublings (:func:`restitution.limits.order.local_exponents`): a
loss ``L_inf + A N^(-p)`` gives a flat line at ``p``. The collisions go through the result store
(:func:`restitution.limits.sweep.run_sweep`), so a second drawing computes nothing.

Run as ``python -m restitution.reproduction.figures.sphere_convergence --figures docs/figures``.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.limits.order import PowerLawFit, local_exponents, power_law_fit
from restitution.limits.store import Store
from restitution.limits.sweep import defaults_for, grid, load_grid, run_sweep
from restitution.reproduction.figures._style import add_notes

__all__ = ["LADDER", "SPEEDS", "SeriesN", "compute", "main", "plot"]

LADDER: tuple[int, ...] = tuple(
    sorted(b * 2**k for b in (100, 150) for k in range(8) if b * 2**k <= 12800)
)
"""Mode counts 100-12800: two doubling ladders, ``100 * 2^k`` and ``150 * 2^k``."""

SPEEDS: tuple[float, ...] = (0.1, 0.03, 0.01, 0.003)
"""Speeds of the figure, ``c``."""


@dataclass(frozen=True, eq=False)
class SeriesN:
    """The loss of one ``(v, alpha)`` against ``N``, with its measured convergence.

    Attributes
    ----------
    v, alpha, product : float
        Speed (``c``), wall hardness (``1/R``) and ``alpha * delta_max(v)``.
    n_modes : numpy.ndarray of int
    loss : numpy.ndarray
        ``1 - epsilon^2`` at each ``N``.
    n_mid, exponent : numpy.ndarray
        Local exponents of successive doublings, at their middle count.
    fit : PowerLawFit
        ``L_inf + A N^(-p)`` fitted to the upper half of the ladder (``N >= 1600``).
    """

    v: float
    alpha: float
    product: float
    n_modes: np.ndarray
    loss: np.ndarray
    n_mid: np.ndarray
    exponent: np.ndarray
    fit: PowerLawFit


def compute(
    nu: float = 0.3,
    speeds=SPEEDS,
    products=SPHERE.alpha_products,
    n_modes=LADDER,
    *,
    store=None,
    progress: bool | None = None,
    fit_from: int = 1600,
) -> tuple[SeriesN, ...]:
    """Run (or read from ``store``) the ladder at every speed and wall, and measure the order."""
    from dataclasses import replace

    settings = replace(
        defaults_for(SPHERE.geometry),
        velocities=tuple(speeds),
        alphas=tuple(products),
        n_modes=tuple(n_modes),
    )
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        run_sweep(grid([nu], settings), store=db, progress=progress, batch_size=1)
        out = []
        for v in settings.velocities:
            data = load_grid(db, nu, v, settings)
            for i, (alpha, product) in enumerate(zip(data.alpha, settings.alphas, strict=True)):
                loss = data.loss[i]
                mid, p = local_exponents(data.n_modes, loss)
                upper = data.n_modes >= fit_from
                fit = power_law_fit(data.n_modes[upper], loss[upper])
                out.append(SeriesN(v, float(alpha), product, data.n_modes, loss, mid, p, fit))
        return tuple(out)
    finally:
        if own:
            db.close()


def plot(series: tuple[SeriesN, ...], nu: float, path=None, notes=()):
    """Two panels: loss against ``1/sqrt(N)`` and local exponents against ``N``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_l, ax_p) = plt.subplots(1, 2, figsize=(11.0, 4.6))
    speeds = sorted({s.v for s in series}, reverse=True)
    colours = dict(zip(speeds, plt.cm.viridis(np.linspace(0.0, 0.85, len(speeds))), strict=True))
    styles = ["o-", "s--", "^:"]
    products = sorted({s.product for s in series})
    for s in series:
        style = styles[products.index(s.product) % len(styles)]
        first = s.product == products[0]
        label = f"v = {s.v:g}" if first else None
        # Each series relative to its own last point, so that all speeds share the axis.
        ax_l.plot(1 / np.sqrt(s.n_modes), s.loss / s.loss[-1], style, color=colours[s.v], ms=3,
                  lw=1, label=label)  # fmt: skip
        ax_p.plot(s.n_mid, s.exponent, style, color=colours[s.v], ms=3, lw=1)
    ax_l.set_xlabel("1/sqrt(N)")
    ax_l.set_ylabel("(1 - eps^2) / (1 - eps^2 at N = 12800)")
    ax_l.set_title("loss against 1/sqrt(N)", fontsize=9)
    ax_l.legend(fontsize=7, title="lines: walls " + ", ".join(f"{p:g}" for p in products),
                title_fontsize=7)  # fmt: skip
    ax_p.axhline(0.5, color="k", lw=0.8, ls="--")
    ax_p.set_xscale("log")
    ax_p.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax_p.set_ylim(-0.5, 2.0)
    ax_p.set_xlabel("N (middle of N, 2N, 4N)")
    ax_p.set_ylabel("local exponent p = log2(dL(N) / dL(2N))")
    ax_p.set_title("local order of convergence (dashed: 1/sqrt(N))", fontsize=9)
    fig.suptitle(
        f"Sphere, nu = {nu:g}: energy loss against the number of modes "
        "(walls alpha * delta_max, Hertz delta_max)",
        fontsize=10,
    )
    add_notes(fig, ["o-, s--, ^: the three walls; points outside -0.5..2 (sign changes) are "
                    "off the right panel", *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description="Draw the sphere's convergence in N.")
    parser.add_argument("--figures", required=True, help="directory for the figure")
    parser.add_argument("--nu", type=float, default=0.3, help="3D Poisson number [0.3]")
    parser.add_argument("--store", default=None, help="result store (default: the user cache)")
    args = parser.parse_args(argv)
    series = compute(args.nu, store=args.store, progress=True)
    out = Path(args.figures)
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"sphere_convergence_nu{args.nu:g}.png"
    plot(series, args.nu, path)
    print(f"wrote {path}")
    for s in series:
        f = s.fit
        print(
            f"v = {s.v:g}, alpha*delta = {s.product:g}: p = {f.exponent:.3f} +- "
            f"{f.exponent_err:.3f} (N {f.n_min}-{f.n_max}); local "
            + " ".join(f"{p:.2f}" for p in s.exponent)
        )


if __name__ == "__main__":
    main()
