"""A steel ball on a rigid wall from 1 mm/s to 100 m/s: plastic flow, viscous loss and elastic waves
on one force pulse, stacked (issue 43; docs/plasticity.md).

Units: SI at the edge: a steel sphere (``E = 210 GPa``, ``nu = 0.3``, ``rho = 7850 kg/m^3``) of
radius 2.5 mm with the yield stress 1 GPa (the limiting pressure of first yield, 1.61 GPa) and a
Kelvin-Voigt relaxation time of 1 ns (``tau c / R = 2.1e-3``): illustrative values, not a
measured ball. The losses are fractions of the kinetic energy.

Top: the losses stacked, ``1 - epsilon^2`` of the one-pulse answer
(:class:`restitution.laws.plastic.PlasticLaw`), with epsilon itself, the elastic law alone and
the old sum of parts. Bottom: each loss on a logarithmic scale, where the elastic waves (a
millionth to a thousandth) can be seen.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["MechanismCurves", "compute", "main", "plot"]

STEEL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
RADIUS_M = 2.5e-3
YIELD_STRESS_PA = 1e9
RELAXATION_TIME_S = 1e-9


@dataclass(frozen=True, eq=False)
class MechanismCurves:
    """The one-pulse answer and its parts at each speed.

    Attributes
    ----------
    speed_m_s, epsilon, epsilon_err, epsilon_elastic, epsilon_sum : numpy.ndarray, shape (K,)
    plastic, viscous, waves, stored : numpy.ndarray, shape (K,)
        Fractions of the kinetic energy.
    yield_speed_m_s, tau : float
        The contact's yield speed and ``tau c / R``.
    """

    speed_m_s: np.ndarray
    epsilon: np.ndarray
    epsilon_err: np.ndarray
    epsilon_elastic: np.ndarray
    epsilon_sum: np.ndarray
    plastic: np.ndarray
    viscous: np.ndarray
    waves: np.ndarray
    stored: np.ndarray
    yield_speed_m_s: float
    tau: float


def compute(speeds_m_s=None) -> MechanismCurves:
    """The steel ball's law at each speed (module docs): about a second a speed."""
    from restitution.laws.plastic import plastic_law
    from restitution.laws.si_law import si_law

    w = np.geomspace(1e-3, 100.0, 41) if speeds_m_s is None else np.asarray(speeds_m_s)
    si = si_law(STEEL["E"], STEEL["nu"], STEEL["rho"], SPHERE.geometry, WALL.against)
    tau = RELAXATION_TIME_S * si.grain.c_m_s / RADIUS_M
    law = plastic_law(si, yield_stress_pa=YIELD_STRESS_PA, tau=tau)
    points = law.points(list(w))

    def column(name):
        return np.array([np.nan if getattr(p, name) is None else getattr(p, name)
                         for p in points], dtype=float)  # fmt: skip

    return MechanismCurves(
        np.asarray(w, dtype=float), column("epsilon"), column("epsilon_err"),
        column("epsilon_elastic"), column("epsilon_sum_of_parts"), column("loss_plastic"),
        column("loss_viscous"), column("loss_waves"), column("loss_stored"),
        law.yield_speed_m_s(), tau,
    )  # fmt: skip


def plot(c: MechanismCurves, path=None, notes=()):
    """The stacked losses with epsilon (top), each loss on a log scale (bottom)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 7.2), sharex=True)
    parts = ((c.plastic, "plastic flow (Thornton)", "tab:red"),
             (c.viscous, "viscous (Kelvin-Voigt)", "tab:green"),
             (c.waves, "elastic waves (the elastic law, on this pulse)", "tab:blue"))  # fmt: skip
    top.stackplot(c.speed_m_s, *(p[0] for p in parts), labels=[p[1] for p in parts],
                  colors=[p[2] for p in parts], alpha=0.45)  # fmt: skip
    top.plot(c.speed_m_s, c.epsilon, "k-", lw=1.4, label="epsilon (one pulse)")
    top.fill_between(
        c.speed_m_s,
        np.clip(c.epsilon - c.epsilon_err, 0, 1),
        np.clip(c.epsilon + c.epsilon_err, 0, 1),
        color="k",
        alpha=0.2,
        lw=0,
    )
    top.plot(c.speed_m_s, c.epsilon_sum, "k--", lw=1.0, label="epsilon, old sum of parts")
    top.plot(c.speed_m_s, c.epsilon_elastic, "k:", lw=1.0, label="epsilon, elastic law alone")
    top.axvline(c.yield_speed_m_s, color="0.5", lw=0.8)
    top.set_ylim(0.0, 1.02)
    top.set_ylabel("epsilon; losses (fraction of the kinetic energy)")
    top.set_title("A 2.5 mm steel ball on a rigid wall (Y = 1 GPa, relaxation time 1 ns)",
                  fontsize=10)  # fmt: skip
    top.legend(fontsize=7, loc="center left")
    for values, label, color in parts:
        bottom.plot(c.speed_m_s, np.where(values > 0, values, np.nan), color=color, label=label)
    bottom.axvline(c.yield_speed_m_s, color="0.5", lw=0.8, label="yield speed")
    bottom.set_xscale("log")
    bottom.set_yscale("log")
    bottom.set_xlabel("impact speed w (m/s)")
    bottom.set_ylabel("loss (fraction of the kinetic energy)")
    bottom.legend(fontsize=7, loc="lower right")
    add_notes(fig, ["band: the one-pulse error (not Thornton's idealisation); illustrative "
                    "material values", *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.plastic_mechanisms --figures DIR``."""
    figure_main(
        argv,
        "Draw a steel ball's loss mechanisms.",
        "plastic_mechanisms_steel.png",
        lambda args, path: plot(compute(), path),
    )


if __name__ == "__main__":
    main()
