"""The oblique impact of a steel cylinder on the rigid wall: ``beta`` against ``tan(theta) /
mu`` (modal route, Maw-Barber-Fawcett, LAMMPS's ``mindlin``, Walton) and ``epsilon_normal``
against the angle.

Units: dimensionless (``beta``, ``epsilon_normal``, ``X = tan(theta) / mu``); angles in
degrees, speeds in m/s.

Nothing modal is computed here: the modal points are the shipped table
(``laws/data/oblique/steel_cylinder_mu0.3.json``, :mod:`restitution.laws.making.oblique_table`).
:func:`compute` fits to them, per speed, Walton's three parameters, the stiffness of LAMMPS's
``mindlin`` and ``linear_history`` models and of Maw, Barber and Fawcett's microslip law
(:mod:`restitution.laws.oblique_fits`); :func:`plot_beta` and :func:`plot_normal` draw the two
figures of docs/oblique.md.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.laws.making.oblique_table import STEEL_TABLE, table_path
from restitution.laws.oblique_fits import ObliqueFits, fit_table
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["compute", "load_table", "main", "plot_beta", "plot_normal"]

K_DISK = 3.0
"""``K = 1 + m R^2 / I`` of a cylinder (the shipped steel table predates the tables' own
``inertia_factor``)."""


def load_table(name: str = STEEL_TABLE.name) -> dict:
    """The shipped oblique table ``name``."""
    return json.loads(table_path(name).read_text())


def compute(table: dict | None = None, speeds=None, *, steps: int = 4000,
            springs: int = 200, scan: int = 41) -> ObliqueFits:  # fmt: skip
    """The fits (:func:`restitution.laws.oblique_fits.fit_table`) of every speed of ``table``
    (default: the shipped steel table), or of ``speeds`` only."""
    table = load_table() if table is None else table
    K = table.get("inertia_factor", K_DISK)
    return fit_table(table, speeds, inertia_factor=K, steps=steps, springs=springs, scan=scan)


def plot_beta(f: ObliqueFits, path, speed: float | None = None, *, points: int = 80,
              springs: int = 200) -> None:  # fmt: skip
    """``beta`` against ``tan(theta) / mu``: the modal points of every speed (error bars: the
    change from half the modes) and, at ``speed`` (default the table's second), the fitted
    microslip law (``springs``), LAMMPS's ``mindlin`` and Walton's law, each on ``points``
    values of ``X``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from restitution.laws.tangential_models import history_beta, walton_beta
    from restitution.quasistatic.oblique import beta_of_psi

    w0 = f.speeds[min(1, len(f.speeds) - 1)] if speed is None else speed
    K = f.inertia_factor
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for w in f.speeds:
        ax.errorbar(f.X[w], f.beta[w], yerr=f.beta_err[w], fmt="o", ms=4, capsize=2,
                    label=f"modal, {w:g} m/s")  # fmt: skip
    x = np.geomspace(min(float(v.min()) for v in f.X.values()) * 0.8,
                     max(float(v.max()) for v in f.X.values()) * 1.1, points)  # fmt: skip
    ms = f.microslip[w0]
    nu = (2.0 - 2.0 * ms.chi) / (2.0 - ms.chi)
    ax.plot(x, beta_of_psi(ms.chi * x, nu, inertia_factor=K, springs=springs), "k-",
            label=f"Maw-Barber-Fawcett (microslip), chi = {ms.chi:.3f}")  # fmt: skip
    mi = f.mindlin[w0]
    ax.plot(x, history_beta(x, mi.chi, "mindlin", inertia_factor=K, steps=4000), "k--",
            label=f"LAMMPS mindlin, chi = {mi.chi:.3f}")  # fmt: skip
    wa = f.walton[w0]
    ax.plot(x, walton_beta(x, wa.e, wa.mu_ratio, wa.beta_0, K), "k:",
            label=f"Walton e={wa.e:.3f}, mu_W={wa.mu_w:.3f}, beta_0={wa.beta_0:.3f}")  # fmt: skip
    ax.set_xscale("log")
    ax.axhline(0.0, color="0.8", lw=0.8)
    ax.set_xlabel("tan(theta) / mu   (Maw et al.'s psi = chi tan(theta) / mu)")
    ax.set_ylabel("beta = -v_c(after) / v_c(before)")
    ax.legend(fontsize=7, loc="lower left")
    m = f.material
    add_notes(fig, [f"{m['shape']} (E = {m['E_pa']:.3g} Pa, nu = {m['nu']:g}, rho = "
                    f"{m['rho_kg_m3']:g} kg/m^3) on the rigid wall, mu = {f.friction:g}; fits "
                    f"at {w0:g} m/s"])  # fmt: skip
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=130, format=Path(path).suffix.lstrip(".") or "png")
    plt.close(fig)


def plot_normal(f: ObliqueFits, path) -> None:
    """``epsilon_normal`` against the angle, every speed (top), and its change from the head-on
    value (angle 0) of the same modes and wall (bottom, where the table has angle 0)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True)
    for w in f.speeds:
        angle, eps = f.angle[w], f.eps[w]
        if w in f.head_on:
            angle, eps = np.r_[0.0, angle], np.r_[f.head_on[w], eps]
            bottom.plot(angle, (eps - f.head_on[w]) * 1e5, "o-", ms=4, label=f"{w:g} m/s")
        top.plot(angle, eps, "o-", ms=4, label=f"{w:g} m/s")
    top.axhline(1.0, color="0.6", lw=0.8, ls="--")
    top.set_ylabel("epsilon_normal")
    top.legend(fontsize=7)
    bottom.axhline(0.0, color="0.6", lw=0.8)
    bottom.set_ylabel("epsilon_normal - head-on (1e-5)")
    bottom.set_xlabel("angle of incidence from the normal (degrees)")
    add_notes(fig, [f"modal route, mu = {f.friction:g}; head-on: angle 0, the same modes and "
                    "wall; every value below 1"])  # fmt: skip
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=130, format=Path(path).suffix.lstrip(".") or "png")
    plt.close(fig)


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.oblique_beta --figures DIR``: both figures
    (``oblique_beta.png``, ``oblique_epsilon_normal.png``) and the fits on stdout."""

    def draw(_args, path) -> None:
        f = compute()
        plot_beta(f, path)
        plot_normal(f, path.with_name("oblique_epsilon_normal.png"))
        print(json.dumps(f.summary(), indent=1))

    figure_main(argv, "Draw the oblique figures of docs/oblique.md (shipped table).",
                "oblique_beta.png", draw)  # fmt: skip


if __name__ == "__main__":
    main()
