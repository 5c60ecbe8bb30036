"""The sphere's loss per unit speed from granular speeds to fast impacts: three routes.

Units: ``E = rho = R = 1`` of the sphere's 3D constants; ``v`` in ``c = sqrt(E/rho)``; the loss
``1 - epsilon^2`` divided by ``v`` (dimensionless).

For one shipped sphere law (``law_sphere_nu<nu>.json``) the figure shows its low-speed points
(Rayleigh's estimate on Hertz's pulse, :mod:`restitution.quasistatic.low_speed`, with its error
band), its modal points (collisions extrapolated in ``alpha`` and ``N``; hollow where a check
failed) and the finite-element reference points at that ``nu``
(``laws/data/fem_reference_sphere.json``; hollow where flagged). Dividing by ``v`` makes the
slow losses visible: they are proportional to ``v`` times a factor that oscillates with the
contact time. Nothing is computed: the figure shows the shipped numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.fem.reference import load_reference
from restitution.laws.law_load import law
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["SlowSphere", "compute", "main", "plot"]


@dataclass(frozen=True, eq=False)
class SlowSphere:
    """The shipped numbers of one sphere law, as loss per unit speed.

    Attributes
    ----------
    nu : float
        The sphere's 3D Poisson number.
    v, loss, loss_err : numpy.ndarray, shape (K,)
        Speeds (``c``) of the law's points, ``(1 - epsilon^2) / v`` and its error.
    quasistatic, asymptotic_ok : numpy.ndarray of bool, shape (K,)
        The point's route (low-speed theory or collisions) and, for collisions, its checks.
    fem_v, fem_loss, fem_loss_err : numpy.ndarray, shape (F,)
        The finite-element reference at this ``nu``, the same quantities.
    fem_ok : numpy.ndarray of bool, shape (F,)
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
    fem_ok: np.ndarray


def _per_speed(v, eps, eps_err):
    """``(1 - eps^2) / v`` and its error ``2 eps eps_err / v``."""
    v, eps, eps_err = (np.asarray(x, dtype=float) for x in (v, eps, eps_err))
    return (1.0 - eps**2) / v, 2.0 * eps * eps_err / v


def compute(nu: float = 0.3) -> SlowSphere:
    """Read the shipped sphere law of ``nu`` and the FEM reference points at that ``nu``."""
    served = law(nu, geometry=SPHERE.geometry)
    loss, err = _per_speed(served.v, served.epsilon_points, served.epsilon_err_points)
    fem = [p for p in load_reference(geometry=SPHERE.geometry) if abs(p.nu - nu) < 1e-9]
    fv = np.array([p.v for p in fem])
    floss, ferr = _per_speed(fv, [p.epsilon for p in fem], [p.epsilon_err for p in fem])
    return SlowSphere(
        nu=float(nu),
        v=np.asarray(served.v, dtype=float),
        loss=loss,
        loss_err=err,
        quasistatic=np.asarray(served.quasistatic, dtype=bool),
        asymptotic_ok=np.asarray(served.asymptotic_ok, dtype=bool),
        fem_v=fv,
        fem_loss=floss,
        fem_loss_err=ferr,
        fem_ok=np.array([p.asymptotic_ok for p in fem], dtype=bool),
    )


def plot(s: SlowSphere, path=None, notes=()):
    """Loss per unit speed against ``v`` (log): the low-speed band, modal and FEM points."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    q = s.quasistatic
    ax.fill_between(s.v[q], s.loss[q] - s.loss_err[q], s.loss[q] + s.loss_err[q],
                    color="tab:green", alpha=0.25, lw=0)  # fmt: skip
    ax.plot(s.v[q], s.loss[q], "-", color="tab:green", lw=1,
            label="low-speed theory (Rayleigh on Hertz's pulse) and its error")  # fmt: skip
    modal = ~q
    for ok, face in ((True, "tab:red"), (False, "none")):
        sel = modal & (s.asymptotic_ok == ok)
        label = "modal collisions, extrapolated" + ("" if ok else " (flagged)")
        ax.errorbar(s.v[sel], s.loss[sel], s.loss_err[sel], fmt="o", ms=3.5, color="tab:red",
                    mfc=face, lw=0.8, capsize=2, label=label)  # fmt: skip
    for ok, face in ((True, "k"), (False, "none")):
        sel = s.fem_ok == ok
        if sel.any():
            ax.errorbar(s.fem_v[sel], s.fem_loss[sel], s.fem_loss_err[sel], fmt="s", ms=5,
                        color="k", mfc=face, lw=0.8, capsize=2,
                        label="finite elements" + ("" if ok else " (flagged)"))  # fmt: skip
    ax.set_xscale("log")
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("v / c  (speed towards the wall; steel: c = 5172 m/s)")
    ax.set_ylabel("(1 - epsilon^2) / v")
    ax.set_title(f"Elastic sphere on a wall, nu = {s.nu:g}: energy lost to vibrations per unit "
                 "speed", fontsize=10)  # fmt: skip
    ax.legend(fontsize=7, loc="upper left")
    add_notes(fig, ["hollow: a check of the extrapolation failed; the loss oscillates with v "
                    "through the phase omega tau / 2 of the modes (tau ~ v^(-1/5))",
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.sphere_low_speed --figures DIR [--nu NU]``."""
    figure_main(
        argv,
        "Draw the sphere's slow losses (shipped laws).",
        lambda args: f"sphere_low_speed_nu{args.nu:g}.png",
        lambda args, path: plot(compute(args.nu), path),
        nu=(0.3, "shipped sphere law (3D nu)"),
    )


if __name__ == "__main__":
    main()
