"""Two spheres of one material and radius ratios 1-4: the loss per unit speed, and who keeps it.

Units: the first (smaller) sphere's ``E = rho = R1 = 1``; ``w`` the relative speed in ``c``;
the loss ``1 - epsilon^2`` (a fraction of ``(mu/2) w^2``) divided by ``w``.

For every shipped law of two spheres of one material (``law_sphere_pair_r<R>_nu<nu>.json``,
their low-speed route) and for two identical spheres (the shipped law of the sphere on the
wall at ``v = w/2``, whose loss is the pair's) the upper panel shows ``(1 - epsilon^2) / w``
with its error band, the lower panel the fraction of the loss left in the smaller sphere (the
route's split, of its central value). Nothing is computed: the figure shows shipped numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.pair import Partner
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.laws.law_load import law
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["PairCurve", "compute", "main", "plot"]


@dataclass(frozen=True, eq=False)
class PairCurve:
    """One pair's shipped low-speed points.

    Attributes
    ----------
    radius_ratio : float
        ``R2 / R1`` (1: two identical spheres).
    w, loss, loss_err : numpy.ndarray, shape (K,)
        Relative speeds (``c``), ``(1 - epsilon^2) / w`` and its error.
    small_share : numpy.ndarray, shape (K,)
        Fraction of the loss in the smaller sphere.
    """

    radius_ratio: float
    w: np.ndarray
    loss: np.ndarray
    loss_err: np.ndarray
    small_share: np.ndarray


def _curve(r: float, served, w, shares) -> PairCurve:
    eps, err = served.epsilon_points, served.epsilon_err_points
    q = np.asarray(served.quasistatic, dtype=bool)
    w = np.asarray(w, dtype=float)[q]
    return PairCurve(
        radius_ratio=r,
        w=w,
        loss=(1.0 - eps[q] ** 2) / w,
        loss_err=2.0 * eps[q] * err[q] / w,
        small_share=np.asarray(shares, dtype=float)[q],
    )


def compute(nu: float = 0.3, ratios=(1.5, 2.0, 4.0)) -> list[PairCurve]:
    """Read the shipped laws: the sphere on the wall (two identical spheres) and the pairs."""
    wall = law(nu, geometry=SPHERE.geometry)
    out = [_curve(1.0, wall, 2.0 * np.asarray(wall.v), np.full(wall.v.size, 0.5))]
    for r in ratios:
        pair = law(nu, geometry=SPHERE.geometry, partner=Partner(radius_ratio=r))
        shares = []
        for record in pair.metadata["points"]:
            first, second = record.get("shares") or (np.nan, np.nan)
            shares.append(first / (first + second))
        out.append(_curve(r, pair, pair.v, shares))
    return out


def plot(curves: list[PairCurve], path=None, nu: float = 0.3, notes=()):
    """The two panels (module docs)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, low) = plt.subplots(2, 1, figsize=(7.5, 6.4), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 2]})  # fmt: skip
    for c, colour in zip(curves, ("k", "tab:blue", "tab:green", "tab:red", "tab:purple"),
                         strict=False):  # fmt: skip
        label = "R2/R1 = 1 (the sphere on a wall at w/2)" if c.radius_ratio == 1 else (
            f"R2/R1 = {c.radius_ratio:g}")  # fmt: skip
        top.fill_between(c.w, c.loss - c.loss_err, c.loss + c.loss_err, color=colour,
                         alpha=0.15, lw=0)  # fmt: skip
        top.plot(c.w, c.loss, "-", color=colour, lw=1, label=label)
        low.plot(c.w, c.small_share, "-", color=colour, lw=1)
    top.set_xscale("log")
    top.set_ylim(bottom=0.0)
    top.set_ylabel("(1 - epsilon^2) / w")
    top.set_title(f"Two elastic spheres of one material, nu = {nu:g}: the loss to vibrations "
                  "per unit speed (low-speed route)", fontsize=10)  # fmt: skip
    top.legend(fontsize=7, loc="upper left")
    low.set_ylim(0.0, 1.0)
    low.set_ylabel("share of the smaller sphere")
    low.set_xlabel("w / c  (relative speed; steel: c = 5172 m/s); each law up to its reach")
    add_notes(fig, ["bands: the route's error (its contact-time band, its mode tail and the "
                    "interpolation between its speeds); the shares are of the central value",
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.sphere_pairs --figures DIR [--nu NU]``."""
    figure_main(
        argv,
        "Draw two spheres' losses (shipped laws).",
        lambda args: f"sphere_pairs_nu{args.nu:g}.png",
        lambda args, path: plot(compute(args.nu), path, args.nu),
        nu=(0.3, "shipped laws' 3D nu"),
    )


if __name__ == "__main__":
    main()
