"""epsilon of two disks of one material against their relative speed, for several radius ratios,
and how the lost energy is shared between the two disks.

Units: ``w`` is the relative normal speed of the two centres in units of ``c = sqrt(E/rho)``
(2D constants of both disks); epsilon and the shares are dimensionless.

Left: the shipped laws (:func:`restitution.laws.law_load.law` with a
:class:`~restitution.bodies.pair.partner.Partner`), ``R2/R1 = 1`` being the disk on the wall at
``v = w/2`` (the identity of two identical disks). Points whose extrapolation did not pass
every check are drawn hollow. Right: the share of the energy lost to vibrations that sits in the
small disk, ``E1 / (E1 + E2)``, from one collision per speed at the hardest wall of the laws
(``alpha delta_pair(w) = 160``) and a mode window of the laws (``N (1 + r^2)`` modes of both):
a finite-``N``, finite-``alpha`` number, which :func:`compute` says.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["RATIOS", "PairCurve", "compute", "main", "plot"]

RATIOS = (1.0, 1.2, 1.4, 2.0)
"""Radius ratios ``R2 / R1`` drawn (1: the disk's own law at half the speed)."""

SHARE_PRODUCT = 160.0
"""The wall of the share collisions, ``alpha delta_pair(w)`` (the laws' hardest)."""


@dataclass(frozen=True, eq=False)
class PairCurve:
    """One radius ratio: the law's points and the energy shares.

    Attributes
    ----------
    radius_ratio : float
        ``R2 / R1``.
    w, epsilon, epsilon_err : numpy.ndarray
        The law's computed relative speeds (``c``), epsilon and its error.
    asymptotic : numpy.ndarray of bool
        Whether each point passed its extrapolation checks.
    share_w, share_small : numpy.ndarray
        Relative speeds of the share collisions and the small disk's share of the lost energy.
    share_modes : int
        Modes of both disks in each share collision.
    """

    radius_ratio: float
    w: np.ndarray
    epsilon: np.ndarray
    epsilon_err: np.ndarray
    asymptotic: np.ndarray
    share_w: np.ndarray
    share_small: np.ndarray
    share_modes: int


def compute(
    nu: float = 0.33,
    ratios=RATIOS,
    *,
    share_speeds=(0.01, 0.04, 0.1, 0.2, 0.4, 0.6),
    share_window: int = 1880,
) -> tuple[PairCurve, ...]:
    """The curves of :data:`RATIOS` at the 2D Poisson number ``nu`` (a shipped pair grid value).

    ``share_window`` is the wall's mode count whose frequency cutoff the share collisions use
    (``share_window (1 + r^2)`` modes of both disks; 1880 is the laws' smallest window at the
    paper's speeds).
    """
    from restitution.bodies.pair.partner import Partner
    from restitution.dynamics.collision import collide
    from restitution.laws.law_load import law

    out = []
    for r in ratios:
        partner = Partner(radius_ratio=float(r))
        if r == 1.0:
            wall = law(nu)
            w, eps, err, ok = (
                2 * wall.v,
                wall.epsilon_points,
                wall.epsilon_err_points,
                wall.asymptotic_ok,
            )
        else:
            pair_law = law(nu, partner=partner)
            w = pair_law.v
            eps, err, ok = (
                pair_law.epsilon_points,
                pair_law.epsilon_err_points,
                pair_law.asymptotic_ok,
            )
        n = int(round(share_window * (1.0 + r * r)))
        pair = partner.pair(nu, n)
        shares = []
        for x in share_speeds:
            result = collide(pair, x, SHARE_PRODUCT / partner.max_compression(x))
            first, second = pair.member_energies(result.mode_energy_after)
            shares.append(first / (first + second))
        out.append(
            PairCurve(
                float(r),
                np.asarray(w, float),
                np.asarray(eps, float),
                np.asarray(err, float),
                np.asarray(ok, bool),
                np.asarray(share_speeds, float),
                np.array(shares),
                n,
            )
        )
    return tuple(out)


def plot(curves: tuple[PairCurve, ...], path=None, nu: float = 0.33, notes=()):
    """epsilon(w) per ratio (left) and the small disk's share of the lost energy (right)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(9.6, 3.9))
    colours = plt.get_cmap("viridis")(np.linspace(0.0, 0.85, len(curves)))
    for c, col in zip(curves, colours, strict=True):
        label = "R2/R1 = 1 (the wall at w/2)" if c.radius_ratio == 1.0 else (
            f"R2/R1 = {c.radius_ratio:g}")  # fmt: skip
        left.fill_between(c.w, c.epsilon - c.epsilon_err, c.epsilon + c.epsilon_err,
                          color=col, alpha=0.2, lw=0)  # fmt: skip
        left.plot(c.w, c.epsilon, "-", color=col, lw=1, label=label)
        left.plot(c.w[c.asymptotic], c.epsilon[c.asymptotic], "o", color=col, ms=3)
        left.plot(c.w[~c.asymptotic], c.epsilon[~c.asymptotic], "o", mfc="none", color=col, ms=3)
        right.plot(c.share_w, c.share_small, "o-", color=col, ms=3, lw=1,
                   label=f"{label}, N = {c.share_modes}")  # fmt: skip
    left.set_xscale("log")
    left.set_xlabel("relative speed w [c]")
    left.set_ylabel("epsilon")
    left.set_title(f"two disks of one material, nu_2d = {nu:g}", fontsize=10)
    left.legend(fontsize=7, loc="lower left")
    right.set_xscale("log")
    right.set_ylim(0, 1)
    right.axhline(0.5, color="0.6", lw=0.5)
    right.set_xlabel("relative speed w [c]")
    right.set_ylabel("share of the lost energy in the small disk")
    right.set_title(f"one collision per speed, alpha delta = {SHARE_PRODUCT:g}", fontsize=10)
    right.legend(fontsize=7, loc="upper left")
    add_notes(fig, ["left: the shipped laws (bands: their errors; hollow: not every "
                    "extrapolation check passed); right: finite N and alpha, not extrapolated",
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.pair_epsilon --figures DIR``."""
    figure_main(
        argv,
        "Draw the laws of two disks (shipped laws).",
        lambda args: f"pair_epsilon_nu{args.nu:g}.png",
        lambda args, path: plot(compute(args.nu), path, nu=args.nu),
        nu=(0.33, "2D Poisson number (0.33)"),
    )


if __name__ == "__main__":
    main()
