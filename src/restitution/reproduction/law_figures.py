"""Figures of the slow points of law files: convergence in ``N`` and ``alpha``, and two routes.

``make law`` runs it after :mod:`restitution.laws.making.production`::

    python -m restitution.reproduction.law_figures --figures docs/figures [LAW_FILE ...]

For every law file (default: the shipped ``restitution/laws/data/law_nu<nu>.json``) it draws
``slow_convergence_nu<nu>.png`` (:mod:`restitution.reproduction.figures.slow_convergence`) and
``slow_routes_nu<nu>.png`` (:mod:`restitution.reproduction.figures.slow_routes`) from the
grids and fits stored in the file; nothing is recomputed.
"""

from __future__ import annotations

import argparse
from importlib import resources
from pathlib import Path

from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.law_nu import shipped_nus

__all__ = ["draw_figures", "main", "shipped_law_files"]


def shipped_law_files() -> list[Path]:
    """The package's law files, by increasing ``nu``."""
    data = resources.files("restitution.laws").joinpath("data")
    return [Path(str(data.joinpath(law_filename(nu)))) for nu in shipped_nus()]


def draw_figures(law_files, out_dir) -> list[Path]:
    """Convergence and two-routes figures of the slow points of each law file."""
    from restitution.reproduction.figures import slow_convergence, slow_routes

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in law_files:
        law = EpsilonLaw.from_json(path)
        conv = out / f"slow_convergence_nu{law.nu:g}.png"
        # The four slowest modal points: since 4 Dec 2026 those up to v = 1e-3 are the residual
        # route's (docs/errors.md), which has no fit in 1/sqrt(N) to show.
        slow_convergence.plot(slow_convergence.compute(law, v_max=0.02, count=4), law.nu, conv)
        routes = out / f"slow_routes_nu{law.nu:g}.png"
        slow_routes.plot(slow_routes.compute(law, v_max=0.05), routes)
        written += [conv, routes]
    return written


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description="Draw the slow-point figures of law files.")
    parser.add_argument("--figures", required=True, help="directory for the figures")
    parser.add_argument(
        "laws", nargs="*", help="law JSON files (default: the shipped laws)", metavar="LAW_FILE"
    )
    args = parser.parse_args(argv)
    for path in draw_figures(args.laws or shipped_law_files(), args.figures):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
