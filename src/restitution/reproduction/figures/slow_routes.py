"""Two routes to the energy loss of slow collisions: the dynamic law and Rayleigh's estimate.

Units: speeds in ``c`` (towards the wall); energy loss ``1 - epsilon^2`` (fraction of the
initial kinetic energy).

The dynamic route is a law's computed points (both limits ``alpha, N -> infinity``, with
errors; open symbols did not pass their checks). The quasistatic route is Rayleigh's estimate
(:func:`restitution.quasistatic.rayleigh.rayleigh_energy`, paper section 5): the lowest ``n_modes``
modes driven by the quasistatic contact force of eq. (57), once with the printed constant
(``"paper"``) and once with the constant the package derives (``"centre"``, docs/quasistatic.md).
:func:`compare` states, speed by speed, the ratio of the routes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.reproduction.figures import fig12_rayleigh
from restitution.reproduction.figures._style import add_notes

__all__ = ["RoutesData", "compare", "compute", "plot"]

LAWS = ("centre", "paper")


@dataclass(frozen=True)
class RoutesData:
    """Numbers of the figure.

    Attributes
    ----------
    nu : float
    v : numpy.ndarray, shape (K,)
        Speeds of the Rayleigh curves, ``c``.
    rayleigh : dict of str to numpy.ndarray, shape (K,)
        Rayleigh's energy loss for each contact law.
    law_v, law_loss, law_loss_err : numpy.ndarray, shape (J,)
        The dynamic law's points.
    law_ok : numpy.ndarray of bool, shape (J,)
    n_modes : int
        Modes of the Rayleigh sum.
    """

    nu: float
    v: np.ndarray
    rayleigh: dict
    law_v: np.ndarray
    law_loss: np.ndarray
    law_loss_err: np.ndarray
    law_ok: np.ndarray
    n_modes: int


def compute(law, *, n_modes: int = 1800, v_max: float = 0.02, n_v: int = 25) -> RoutesData:
    """Rayleigh's estimate on ``[v_min of the law's modal points / 2, v_max]`` and those points
    (the low-speed points: :mod:`restitution.reproduction.figures.disk_low_speed`)."""
    from restitution.laws.law_point import QUASISTATIC_ROUTE

    pts = [
        p
        for p in law.metadata["points"]
        if p["v"] <= v_max * (1 + 1e-9) and p.get("route") != QUASISTATIC_ROUTE
    ]
    v_lo = 0.5 * min(p["v"] for p in pts)
    curves = {
        name: fig12_rayleigh.compute(
            law.nu, n_modes=n_modes, law=name, v_min=v_lo, v_max=v_max, n_v=n_v
        )  # fmt: skip
        for name in LAWS
    }
    return RoutesData(
        nu=float(law.nu),
        v=curves[LAWS[0]].v,
        rayleigh={name: c.total for name, c in curves.items()},
        law_v=np.array([p["v"] for p in pts]),
        law_loss=np.array([p["energy_loss"] for p in pts]),
        law_loss_err=np.array([p["energy_loss_err"] for p in pts]),
        law_ok=np.array([p["asymptotic_ok"] for p in pts], bool),
        n_modes=int(n_modes),
    )


def compare(data: RoutesData) -> list[dict]:
    """At every law point: Rayleigh (each contact law, interpolated in log v) over dynamic."""
    rows = []
    for v, loss, err, ok in zip(
        data.law_v, data.law_loss, data.law_loss_err, data.law_ok, strict=True
    ):
        row = {"v": float(v), "dynamic": float(loss), "dynamic_err": float(err), "ok": bool(ok)}
        for name, curve in data.rayleigh.items():
            r = float(np.exp(np.interp(np.log(v), np.log(data.v), np.log(curve))))
            row[name] = r
            row[f"ratio_{name}"] = r / loss
        rows.append(row)
    return rows


def plot(data: RoutesData, path=None, notes=()):
    """Log-log figure of both routes; returns the figure (saved to ``path`` if given)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    styles = {"centre": ("k-", "derived constant of eq. (57)"),
              "paper": ("k:", "printed constant of eq. (57)")}  # fmt: skip
    for name, curve in data.rayleigh.items():
        style, text = styles[name]
        ax.loglog(data.v, curve, style, label=f"Rayleigh, {data.n_modes} modes, {text}")
    ok = data.law_ok
    for mask, face, text in ((ok, "C3", "passes its checks"), (~ok, "none", "flagged")):
        if np.any(mask):
            ax.errorbar(data.law_v[mask], data.law_loss[mask], yerr=data.law_loss_err[mask],
                        fmt="o", color="C3", mfc=face, capsize=2,
                        label=f"dynamic law, alpha, N -> infinity ({text})")  # fmt: skip
    ax.set_xlabel("v [c] (speed towards the wall)")
    ax.set_ylabel("1 - epsilon^2")
    ax.set_title(f"Slow collisions, nu = {data.nu:g}: dynamic and quasistatic routes", fontsize=10)
    ax.legend(fontsize=7, loc="best")
    add_notes(fig, list(notes))
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig
