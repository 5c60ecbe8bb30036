"""epsilon against the number of kept modes, with and without the static residual (issue 46).

Units: ``v`` in ``c``; walls ``alpha delta_max(v)``; ``N`` the lowest modes kept.

Nothing is computed here: the figure draws the stored measurement
(``restitution/reproduction/data/residual_study.json``, written by
:mod:`restitution.reproduction.residual_study`). One figure per body and Poisson number, one
panel per speed: ``|epsilon(N) - epsilon_ref|`` on log-log axes for the collision with the
residual (solid) and the plain modal collision (dashed), one colour per wall. The reference is
the plain modal collision's own limit ``N -> infinity`` (Richardson in ``1 / sqrt(N)`` from its
two largest sets, the laws' extrapolation), so the residual is judged by a route it does not
share; the grey band is that limit's uncertainty (the change from the next smaller pair).
:func:`summary` fits the orders of both routes from their successive differences
(``|eps(N_k+1) - eps(N_k)| ~ N^(-p)``).

Run as ``python -m restitution.reproduction.figures.residual_convergence --figures docs/figures``.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.reproduction.figures._style import add_notes

__all__ = ["DATA", "curves", "main", "plot", "summary"]

DATA = Path(__file__).resolve().parent.parent / "data" / "residual_study.json"
"""The stored measurement."""


def _load(path=DATA) -> list[dict]:
    return list(json.loads(Path(path).read_text())["points"].values())


def curves(points, geometry: str, nu: float) -> dict:
    """``{(v, wall): {"residual": (N, eps), "modal": (N, eps)}}`` of one body."""
    out: dict = {}
    for p in points:
        if p["geometry"] != geometry or p["nu"] != nu:
            continue
        out.setdefault((p["v"], p["wall"]), {}).setdefault(p["route"], []).append(
            (p["modes"], p["epsilon"])
        )
    return {
        key: {route: tuple(np.array(x) for x in zip(*sorted(pts), strict=True))
              for route, pts in routes.items()}
        for key, routes in out.items()
    }  # fmt: skip


def modal_limit(n, eps) -> tuple[float, float]:
    """Richardson in ``1 / sqrt(N)`` from the two largest sets, and the change from the pair
    below them (the limit's uncertainty)."""

    def limit(i, j):
        r = math.sqrt(n[j] / n[i])
        return eps[j] + (eps[j] - eps[i]) / (r - 1.0)

    best = limit(-2, -1)
    return best, abs(best - limit(-3, -2)) if len(n) > 2 else math.nan


def fitted_order(n, eps) -> float:
    """``p`` of ``|eps(N_k+1) - eps(N_k)| ~ N^(-p)`` by least squares in logs."""
    d = np.abs(np.diff(eps))
    ok = d > 0
    if np.count_nonzero(ok) < 2:
        return math.nan
    x = np.log(np.sqrt(n[1:] * n[:-1]))[ok]
    return float(-np.polyfit(x, np.log(d[ok]), 1)[0])


def summary(points, geometry: str, nu: float) -> list[dict]:
    """One row per ``(v, wall)``: the residual at its largest sets, the modal limit, both
    routes' fitted orders."""
    rows = []
    for (v, wall), routes in sorted(curves(points, geometry, nu).items()):
        row = {"v": v, "wall": wall}
        if "modal" in routes and routes["modal"][0].size >= 2:
            n, eps = routes["modal"]
            row["modal_limit"], row["modal_limit_err"] = modal_limit(n, eps)
            row["modal_order"] = fitted_order(n, eps)
            row["modal_largest"] = (int(n[-1]), float(eps[-1]))
        if "residual" in routes:
            n, eps = routes["residual"]
            row["residual"] = {int(k): float(e) for k, e in zip(n, eps, strict=True)}
            row["residual_order"] = fitted_order(n, eps)
        rows.append(row)
    return rows


def plot(points, geometry: str, nu: float, path=None):
    """The figure of one body (module docstring); returns it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = curves(points, geometry, nu)
    speeds = sorted({v for v, _ in data}, reverse=True)
    walls = sorted({w for _, w in data})
    colours = dict(zip(walls, ("tab:blue", "tab:orange", "tab:green", "tab:red"), strict=False))
    fig, axes = plt.subplots(1, len(speeds), figsize=(4.0 * len(speeds), 3.8), squeeze=False)
    for ax, v in zip(axes[0], speeds, strict=True):
        for wall in walls:
            routes = data.get((v, wall), {})
            if "modal" not in routes or routes["modal"][0].size < 3:
                continue
            ref, ref_err = modal_limit(*routes["modal"])
            c = colours[wall]
            for route, style in (("modal", "--"), ("residual", "-")):
                if route in routes:
                    n, eps = routes[route]
                    ax.loglog(n, np.maximum(np.abs(eps - ref), 1e-9), style, marker="o", ms=3,
                              color=c, label=f"{route}, alpha delta = {wall:g}")  # fmt: skip
            ax.axhspan(1e-9, max(ref_err, 1e-9), color=c, alpha=0.12, lw=0)
        ax.set_title(f"v = {v:g} c", fontsize=10)
        ax.set_xlabel("kept modes N")
        ax.set_ylabel("|epsilon(N) - modal limit|")
        ax.set_ylim(1e-8, 0.1)
    axes[0][0].legend(fontsize=6.5, loc="lower left")
    add_notes(fig, [f"{geometry}, nu = {nu:g}: solid with the static residual, dashed the "
                    "plain modal collision; shaded: the modal limit's own uncertainty (floor "
                    "1e-9)"])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110, format="png")
        plt.close(fig)
    return fig


BODIES = ((DISK.geometry, 0.33), (DISK.geometry, 0.9), (SPHERE.geometry, 0.3))
"""The bodies of the figures: issue 46's disk at 0.33 and 0.9 and sphere at 0.3."""


def main(argv=None) -> None:
    """``--figures DIR``: one PNG per body the stored measurement holds."""
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--figures", required=True, help="directory for the PNGs")
    args = parser.parse_args(argv)
    folder = Path(args.figures)
    folder.mkdir(parents=True, exist_ok=True)
    points = _load()
    for geometry, nu in BODIES:
        if curves(points, geometry, nu):
            path = folder / f"residual_convergence_{geometry}_nu{nu:g}.png"
            plot(points, geometry, nu, path)
            print(f"wrote {path}")


if __name__ == "__main__":
    main()
