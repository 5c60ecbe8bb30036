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
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.laws.making.oblique_table import STEEL_TABLE, table_path
from restitution.laws.oblique_fits import (
    fit_history,
    fit_microslip,
    fit_walton,
    lammps_mindlin_kt,
)
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["ObliqueFits", "compute", "load_table", "main", "plot_beta", "plot_normal"]

K_DISK = 3.0
"""``K = 1 + m R^2 / I`` of a cylinder."""


def load_table(name: str = STEEL_TABLE.name) -> dict:
    """The shipped oblique table ``name``."""
    return json.loads(table_path(name).read_text())


@dataclass(frozen=True, eq=False)
class ObliqueFits:
    """The table's points per speed and the fits to them (arrays over the oblique angles).

    Attributes
    ----------
    speeds : tuple of float
        m/s.
    X, beta, beta_err, eps, eps_err, angle : dict of float to numpy.ndarray
        Per speed: ``tan(theta) / mu``, ``beta`` and its error, ``epsilon_normal`` and its
        error, the angle (degrees).
    head_on : dict of float to float
        ``epsilon_normal`` at angle 0 (the same modes and wall), where the table has it.
    walton, mindlin, linear_history, microslip : dict of float to fit
    friction : float
    material : dict
    """

    speeds: tuple
    X: dict
    beta: dict
    beta_err: dict
    eps: dict
    eps_err: dict
    angle: dict
    head_on: dict
    walton: dict
    mindlin: dict
    linear_history: dict
    microslip: dict
    friction: float
    material: dict

    def summary(self) -> dict:
        """Every fit per speed as JSON values (with LAMMPS's ``mindlin`` ``k_t``)."""
        m = self.material
        out = {}
        for w in self.speeds:
            out[str(w)] = {
                "walton": self.walton[w].to_dict(),
                "mindlin": {**self.mindlin[w].to_dict(),
                            **lammps_mindlin_kt(self.mindlin[w].chi, m["E_pa"], m["nu"])},
                "linear_history": self.linear_history[w].to_dict(),
                "microslip": self.microslip[w].to_dict(),
            }  # fmt: skip
        return out


def compute(table: dict | None = None, speeds=None, *, steps: int = 4000,
            springs: int = 200, scan: int = 41) -> ObliqueFits:  # fmt: skip
    """The fits of every speed of ``table`` (default: the shipped steel table), or of
    ``speeds`` only; ``steps`` and ``springs`` are the resolutions of the DEM models and the
    microslip law, ``scan`` the stiffnesses scanned before a fit is refined."""
    table = load_table() if table is None else table
    mu = float(table["friction"])
    rows = table["rows"]
    speeds = tuple(table["speeds_m_s"] if speeds is None else speeds)
    per = {k: {} for k in ("X", "beta", "beta_err", "eps", "eps_err", "angle")}
    head_on, fits = {}, {k: {} for k in ("walton", "mindlin", "linear_history", "microslip")}
    for w in speeds:
        mine = sorted((r for r in rows if r["speed_m_s"] == w and r["angle_deg"] > 0),
                      key=lambda r: r["angle_deg"])  # fmt: skip
        zero = [r for r in rows if r["speed_m_s"] == w and r["angle_deg"] == 0]
        if zero:
            head_on[w] = zero[0]["epsilon_normal"]
        angle = np.array([r["angle_deg"] for r in mine])
        X = np.tan(np.radians(angle)) / mu
        beta = np.array([r["beta"] for r in mine])
        eps = np.array([r["epsilon_normal"] for r in mine])
        for key, value in (
            ("X", X),
            ("beta", beta),
            ("eps", eps),
            ("angle", angle),
            ("beta_err", np.array([r["beta_error"] for r in mine])),
            ("eps_err", np.array([r["epsilon_normal_error"] for r in mine])),
        ):
            per[key][w] = value  # fmt: skip
        fits["walton"][w] = fit_walton(X, beta, eps, mu, K_DISK)
        fits["mindlin"][w] = fit_history(X, beta, "mindlin", K_DISK, steps, scan)
        fits["linear_history"][w] = fit_history(X, beta, "linear_history", K_DISK, steps, scan)
        fits["microslip"][w] = fit_microslip(X, beta, K_DISK, springs, scan)
    return ObliqueFits(speeds, **per, head_on=head_on, **fits, friction=mu,
                       material=table["material"])  # fmt: skip


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
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for w in f.speeds:
        ax.errorbar(f.X[w], f.beta[w], yerr=f.beta_err[w], fmt="o", ms=4, capsize=2,
                    label=f"modal, {w:g} m/s")  # fmt: skip
    x = np.geomspace(min(float(v.min()) for v in f.X.values()) * 0.8,
                     max(float(v.max()) for v in f.X.values()) * 1.1, points)  # fmt: skip
    ms = f.microslip[w0]
    nu = (2.0 - 2.0 * ms.chi) / (2.0 - ms.chi)
    ax.plot(x, beta_of_psi(ms.chi * x, nu, inertia_factor=K_DISK, springs=springs), "k-",
            label=f"Maw-Barber-Fawcett (microslip), chi = {ms.chi:.3f}")  # fmt: skip
    mi = f.mindlin[w0]
    ax.plot(x, history_beta(x, mi.chi, "mindlin", steps=4000), "k--",
            label=f"LAMMPS mindlin, chi = {mi.chi:.3f}")  # fmt: skip
    wa = f.walton[w0]
    ax.plot(x, walton_beta(x, wa.e, wa.mu_ratio, wa.beta_0, K_DISK), "k:",
            label=f"Walton e={wa.e:.3f}, mu_W={wa.mu_w:.3f}, beta_0={wa.beta_0:.3f}")  # fmt: skip
    ax.set_xscale("log")
    ax.axhline(0.0, color="0.8", lw=0.8)
    ax.set_xlabel("tan(theta) / mu   (Maw et al.'s psi = chi tan(theta) / mu)")
    ax.set_ylabel("beta = -v_c(after) / v_c(before)")
    ax.legend(fontsize=7, loc="lower left")
    m = f.material
    add_notes(fig, [f"steel {m['shape']} (E = {m['E_pa']:.3g} Pa, nu = {m['nu']:g}) on the "
                    f"rigid wall, mu = {f.friction:g}; fits at {w0:g} m/s"])  # fmt: skip
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
