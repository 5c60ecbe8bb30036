"""The disk's loss at slow impacts: the shipped law's two routes, the finite elements, and the
quasistatic theory.

Units: two-dimensional ``E = rho = R = 1``; ``v`` in ``c = sqrt(E/rho)`` (speed towards the
wall); the loss ``1 - epsilon^2`` (dimensionless).

For one shipped disk law (``law_nu<nu>.json``) the figure shows its low-speed points (the disk's
slow-impact model, :mod:`restitution.quasistatic.slow_disk`, with their error band), its modal
points (hollow where a check failed), the finite-element reference points at that ``nu``
(``laws/data/fem_reference.json``), Rayleigh's estimate on the quasistatic pulse (the
``v -> 0`` limit, reached only logarithmically) and the closed-form leading behaviour
(:func:`restitution.quasistatic.slow_disk.asymptotic_loss`). The law's points are the shipped
numbers; the two quasistatic curves are computed (a few seconds).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.fem.reference import load_reference
from restitution.laws.law_load import law
from restitution.quasistatic.hertz import contact_law
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.quasistatic.slow_disk import asymptotic_loss
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["SlowDisk", "compute", "main", "plot"]

_RAYLEIGH_MODES = 400  # the Duhamel sum's tail beyond them is below 1e-3 of the loss


@dataclass(frozen=True, eq=False)
class SlowDisk:
    """The numbers of one disk law's slow end.

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number.
    v, loss, loss_err : numpy.ndarray, shape (K,)
        The law's speeds (``c``, up to ``v_max``), ``1 - epsilon^2`` and its error.
    quasistatic, asymptotic_ok : numpy.ndarray of bool, shape (K,)
        The point's route (slow-impact model or collisions) and, for collisions, its checks.
    fem_v, fem_loss, fem_loss_err : numpy.ndarray, shape (F,)
        The finite-element reference at this ``nu``.
    theory_v, rayleigh, leading : numpy.ndarray, shape (T,)
        Speeds of the quasistatic curves, Rayleigh's Duhamel estimate there (``nan`` where not
        computed) and the leading behaviour.
    """

    nu: float
    v: np.ndarray
    loss: np.ndarray
    loss_err: np.ndarray
    quasistatic: np.ndarray
    asymptotic_ok: np.ndarray
    fem_v: np.ndarray
    fem_loss: np.ndarray
    fem_loss_err: np.ndarray
    theory_v: np.ndarray
    rayleigh: np.ndarray
    leading: np.ndarray


def compute(nu: float = 0.33, *, v_max: float = 0.02, n_rayleigh: int = 40) -> SlowDisk:
    """Read the shipped disk law of ``nu`` (its points up to ``v_max``) and the FEM points at
    that ``nu``; compute Rayleigh's estimate at ``n_rayleigh`` speeds (0: none) and the leading
    behaviour at 200."""
    served = law(nu)
    sel = served.v <= v_max
    eps, err = served.epsilon_points[sel], served.epsilon_err_points[sel]
    fem = [p for p in load_reference() if abs(p.nu - nu) < 1e-9 and p.v <= v_max]
    feps = np.array([p.epsilon for p in fem])
    # The quasistatic curves only where the contact is slow (above, Rayleigh's estimate exceeds
    # the loss many times, docs/quasistatic.md section 4).
    theory_v = np.geomspace(float(served.v[0]), min(v_max, 3e-3), 200)
    modes = get_modes(nu, _RAYLEIGH_MODES, geometry=DEFAULT_GEOMETRY)
    rayleigh = np.full(theory_v.size, np.nan)
    centre = contact_law(nu, "centre")
    if n_rayleigh:
        pick = np.unique(np.linspace(0, theory_v.size - 1, n_rayleigh).round().astype(int))
        for i in pick:
            rayleigh[i] = rayleigh_energy(modes, float(theory_v[i]), centre).energy_fraction
    return SlowDisk(
        nu=float(nu),
        v=np.asarray(served.v[sel], dtype=float),
        loss=1.0 - eps**2,
        loss_err=2.0 * eps * err,
        quasistatic=np.asarray(served.quasistatic[sel], dtype=bool),
        asymptotic_ok=np.asarray(served.asymptotic_ok[sel], dtype=bool),
        fem_v=np.array([p.v for p in fem]),
        fem_loss=1.0 - feps**2,
        fem_loss_err=2.0 * feps * np.array([p.epsilon_err for p in fem]),
        theory_v=theory_v,
        rayleigh=rayleigh,
        leading=asymptotic_loss(modes, theory_v),
    )


def plot(slow: list[SlowDisk], path=None, notes=()):
    """One panel per law: ``1 - epsilon^2`` against ``v`` (log)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(slow), figsize=(6.2 * len(slow), 4.4), squeeze=False)
    for ax, s in zip(axes[0], slow, strict=True):
        q = s.quasistatic
        ax.fill_between(s.v[q], s.loss[q] - s.loss_err[q], s.loss[q] + s.loss_err[q],
                        color="tab:green", alpha=0.3, lw=0)  # fmt: skip
        ax.plot(s.v[q], s.loss[q], "-", color="tab:green", lw=1.2,
                label="slow-impact model (low modes moving) and its error")  # fmt: skip
        for ok, face in ((True, "tab:red"), (False, "none")):
            sel = ~q & (s.asymptotic_ok == ok)
            ax.errorbar(s.v[sel], s.loss[sel], s.loss_err[sel], fmt="o", ms=3.5,
                        color="tab:red", mfc=face, lw=0.8, capsize=2,
                        label="modal collisions" + ("" if ok else " (flagged)"))  # fmt: skip
        if s.fem_v.size:
            ax.errorbar(s.fem_v, s.fem_loss, s.fem_loss_err, fmt="s", ms=5, color="k",
                        mfc="none", lw=0.8, capsize=2, label="finite elements")  # fmt: skip
        r = np.isfinite(s.rayleigh)
        ax.plot(s.theory_v[r], s.rayleigh[r], "--", color="tab:blue", lw=1,
                label="Rayleigh on the quasistatic pulse (the v -> 0 limit)")  # fmt: skip
        ax.plot(s.theory_v, s.leading, ":", color="tab:gray", lw=1,
                label="leading behaviour ~ 1/ln^2(1/v)")  # fmt: skip
        ax.set_xscale("log")
        top = max(np.max(s.loss + s.loss_err), np.max(s.fem_loss, initial=0.0))
        ax.set_ylim(0.0, 1.3 * top)
        ax.set_xlabel("v / c  (towards the wall; steel cylinder: c = 5420 m/s)")
        ax.set_ylabel("1 - epsilon^2")
        ax.set_title(f"Elastic disk on a wall, nu_2d = {s.nu:g}", fontsize=10)
        ax.legend(fontsize=7, loc="upper left")
    add_notes(fig, ["hollow: a check of the modal extrapolation failed; the loss falls only "
                    "like 1/ln^2(1/v) as v -> 0, with oscillations", *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.disk_low_speed --figures DIR``."""
    figure_main(
        argv,
        "Draw the disk's slow losses (shipped laws).",
        "disk_low_speed.png",
        lambda args, path: plot([compute(nu) for nu in args.nu], path),
        nu=([0.33, 0.9], "2D nu"),
    )


if __name__ == "__main__":
    main()
