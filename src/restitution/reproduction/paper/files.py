"""Files of a paper run: the figures (PNG and SVG or PDF), Table 1, the law exports, the record.

Each writer takes the data of :func:`restitution.reproduction.paper.compute.compute_paper` and a
folder.
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from restitution import atomic
from restitution.errors import InputError
from restitution.jsonable import finite_tree, json_default

__all__ = [
    "FIGURE_STEMS",
    "FigureFile",
    "LawExport",
    "write_figures",
    "write_law_exports",
    "to_json",
    "write_table1",
]

FIGURE_STEMS = (
    "fig01_epsilon",
    "fig02_shapes",
    "fig03_spectrum",
    "fig05_snapshots",
    "fig06_mode_energy",
    "fig07_alpha",
    "fig08_modes",
    "fig10_force",
    "fig11_contact",
    "fig12_rayleigh",
)


@dataclass(frozen=True)
class FigureFile:
    """One figure written by :func:`write_figures`.

    Attributes
    ----------
    stem : str
        File name without suffix, e.g. ``"fig07_alpha_nu0.9"``.
    title : str
        E.g. ``"Fig. 7 (nu = 0.9)"``.
    png, vector : Path
        The raster and the vector (SVG or PDF) file.
    nu : float or None
        The Poisson number of a figure drawn once per ``nu`` (Figs. 7 and 8).
    """

    stem: str
    title: str
    png: Path
    vector: Path
    nu: float | None = None


def _figure_jobs(data) -> list[tuple[str, str, Any, Callable, float | None]]:
    """``(stem, title, data, plot, nu)`` of every figure file."""
    from restitution.reproduction.figures import (
        fig01_epsilon,
        fig02_shapes,
        fig03_spectrum,
        fig05_snapshots,
        fig06_mode_energy,
        fig07_alpha,
        fig08_modes,
        fig10_force,
        fig11_contact,
        fig12_rayleigh,
    )

    jobs = [
        ("fig01_epsilon", "Fig. 1", data.fig01, fig01_epsilon.plot, None),
    ]
    for unit, f01 in data.fig01_units.items():
        if unit != "c":
            title = f"Fig. 1, speeds read in {unit}"
            jobs.append((f"fig01_epsilon_{unit}", title, f01, fig01_epsilon.plot, None))
    jobs += [
        ("fig02_shapes", "Fig. 2", data.fig02, fig02_shapes.plot, None),
        ("fig03_spectrum", "Fig. 3", data.fig03, fig03_spectrum.plot, None),
        ("fig05_snapshots", "Fig. 5", data.fig05, fig05_snapshots.plot, None),
        ("fig06_mode_energy", "Fig. 6", data.fig06, fig06_mode_energy.plot, None),
    ]
    for f7 in data.fig07:
        title = f"Fig. 7 (nu = {f7.nu:g})"
        jobs.append((f"fig07_alpha_nu{f7.nu:g}", title, f7, fig07_alpha.plot, f7.nu))
    for f8 in data.fig08:
        title = f"Fig. 8 (nu = {f8.nu:g})"
        jobs.append((f"fig08_modes_nu{f8.nu:g}", title, f8, fig08_modes.plot, f8.nu))
    jobs += [
        ("fig10_force", "Fig. 10", data.fig10, fig10_force.plot, None),
        ("fig11_contact", "Fig. 11", data.fig11, fig11_contact.plot, None),
        ("fig12_rayleigh", "Fig. 12", data.fig12, fig12_rayleigh.plot, None),
    ]
    return jobs


def write_figures(data, out: Path, fmt: str = "svg") -> tuple[FigureFile, ...]:
    """Draw every figure as PNG and as ``fmt`` (``"svg"`` or ``"pdf"``) into ``out``."""
    if fmt not in ("svg", "pdf"):
        raise InputError(f"vector format must be 'svg' or 'pdf', not {fmt!r}")
    import matplotlib

    matplotlib.use("Agg")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    from restitution.reproduction.figures._style import QUICK_NOTE

    note = QUICK_NOTE if data.settings.name == "quick" else ""
    files = []
    for stem, title, fig_data, plot, nu in _figure_jobs(data):
        png, vec = out / f"{stem}.png", out / f"{stem}.{fmt}"
        plot(fig_data, png, note=note)
        plot(fig_data, vec, note=note)
        files.append(FigureFile(stem, title, png, vec, nu))
    return tuple(files)


def write_table1(table, out: Path) -> tuple[Path, Path]:
    """Table 1 as ``table1.md`` and ``table1.csv`` in ``out``; ours beside the paper's."""
    from restitution.reproduction.figures.table1 import to_markdown

    out = Path(out)
    md = out / "table1.md"
    atomic.write_text(
        md,
        "# Table 1: the ten modes with the most average energy\n\n"
        "Energies are fractions of the initial kinetic energy. 'mean energy (contact)' averages "
        "over the contact (x0 > -1), 'mean over run' over the whole integrated run; 'paper' "
        "columns are the paper's values for the same (n, l), 'not listed' where the paper's "
        f"top ten lacks that mode. epsilon = {table.epsilon:.6f}, contact time = "
        f"{table.contact_time:.4f} R/c.\n\n" + to_markdown(table),
    )
    path = out / "table1.csv"
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(
            ["rank", "n", "l", "mean_energy_contact", "paper_mean_energy", "mean_energy_run",
             "energy_after", "paper_energy_after"]
        )  # fmt: skip
        for i in range(table.n.size):
            w.writerow(
                [i + 1, int(table.n[i]), int(table.l[i]), _num(table.mean_contact[i]),
                 _num(table.paper_mean[i]), _num(table.mean_window[i]), _num(table.after[i]),
                 _num(table.paper_after[i])]
            )  # fmt: skip
    return md, path


def _num(x: float) -> str:
    return "" if not math.isfinite(float(x)) else f"{float(x):.9g}"


@dataclass(frozen=True)
class LawExport:
    """The epsilon(v) law of one Poisson number as written by :func:`write_law_exports`.

    Attributes
    ----------
    nu : float
    json, csv, table : Path
        :meth:`restitution.laws.law.EpsilonLaw.to_json`, ``to_csv`` and ``to_table`` files.
    """

    nu: float
    json: Path
    csv: Path
    table: Path


def write_law_exports(curves: dict, out: Path) -> tuple[LawExport, ...]:
    """The epsilon(v) law of every curve of this run as JSON, CSV and a plain table.

    The laws come from this run's sweep (:meth:`restitution.laws.law.EpsilonLaw.from_curve`), so a
    quick run exports a quick (unconverged) law; the files say their grid.
    """
    from restitution.laws.law import EpsilonLaw

    out = Path(out)
    written = []
    for nu, curve in curves.items():
        law = EpsilonLaw.from_curve(curve)
        stem = f"law_nu{float(nu):g}"
        written.append(
            LawExport(
                float(nu),
                law.to_json(out / f"{stem}.json"),
                law.to_csv(out / f"{stem}.csv"),
                law.to_table(out / f"{stem}.txt"),
            )
        )
    return tuple(written)


def write_sphere_figure(out: Path) -> Path | None:
    """``sphere_cylinder.png``: the shipped sphere laws beside the cylinders' of the same
    materials (:mod:`restitution.reproduction.figures.sphere_cylinder`); ``None`` when fewer than
    three sphere laws are shipped (no material could be served)."""
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.laws.law_nu import shipped_nus
    from restitution.reproduction.figures import sphere_cylinder

    if len(shipped_nus(SPHERE.geometry)) < 3:
        return None
    path = Path(out) / "sphere_cylinder.png"
    sphere_cylinder.plot(sphere_cylinder.compute(), path)
    return path


def to_json(obj: Any) -> str:
    """``obj`` as JSON through the package's one numpy encoder, NaN as null."""
    plain = json.loads(json.dumps(obj, default=json_default))
    return json.dumps(finite_tree(plain), indent=1, allow_nan=False)
