"""epsilon(w) of a damping grain: the loss to vibrations, the viscous loss, and both.

Units: impact speeds in m/s; epsilon dimensionless.

One material, steel (E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3), as a sphere and as a long
cylinder against a wall, with the relaxation time inferred from one coefficient of restitution,
0.9 at 1 m/s (an illustrative datum, not a measurement): :func:`restitution.laws.damped.
damped_law`. Three curves per body: the elastic law (the loss to vibrations only), the viscous
loss alone (the quasistatic Kelvin-Voigt contact, :mod:`restitution.quasistatic.viscoelastic`)
and both together. The cylinder's elastic law (and so the sum) starts at its lowest computed
speed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["MATERIAL", "MEASURED", "DampedCurve", "compute", "main", "plot"]

MATERIAL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
"""Steel, SI."""

MEASURED = (0.9, 1.0)
"""The illustrative datum: epsilon = 0.9 at 1 m/s against a wall."""


@dataclass(frozen=True, eq=False)
class DampedCurve:
    """One body: speeds (m/s), the three epsilons (``nan`` where a part has no value) and
    the inferred ``tau c / R``."""

    geometry: str
    speeds_m_s: np.ndarray
    epsilon: np.ndarray
    epsilon_err: np.ndarray
    elastic: np.ndarray
    viscous: np.ndarray
    tau: float


def compute(geometries=(*SPHERE.shapes, "cylinder"), speeds_m_s=None) -> tuple[DampedCurve, ...]:
    """The curves of steel for each body in ``geometries``."""
    from restitution.laws.damped import damped_law
    from restitution.laws.si_law import si_law

    speeds = np.geomspace(0.01, 10.0, 31) if speeds_m_s is None else np.asarray(speeds_m_s)
    out = []
    for geometry in geometries:
        d = damped_law(
            si_law(**MATERIAL, geometry=geometry, against=WALL.against),
            measured_epsilon=MEASURED[0],
            measured_speed_m_s=MEASURED[1],
        )
        pts = d.points(speeds)

        def col(name, pts=pts):
            return np.array([np.nan if getattr(p, name) is None else getattr(p, name) for p in pts])

        out.append(
            DampedCurve(
                geometry,
                np.asarray(speeds, float),
                col("epsilon"),
                col("epsilon_err"),
                col("epsilon_elastic"),
                col("epsilon_viscous"),
                d.tau,
            )
        )
    return tuple(out)


def plot(curves: tuple[DampedCurve, ...], path=None):
    """One panel per body: elastic only, viscous only, both."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(curves), figsize=(4.8 * len(curves), 3.9), squeeze=False)
    for ax, c in zip(axes[0], curves, strict=True):
        ax.plot(c.speeds_m_s, c.elastic, "-", color="tab:blue", label="vibrations only (elastic)")
        ax.plot(c.speeds_m_s, c.viscous, "--", color="tab:orange",
                label="viscous only (quasistatic)")  # fmt: skip
        ax.fill_between(c.speeds_m_s, c.epsilon - c.epsilon_err, c.epsilon + c.epsilon_err,
                        color="k", alpha=0.2, lw=0)  # fmt: skip
        ax.plot(c.speeds_m_s, c.epsilon, "-", color="k", lw=1.5, label="both")
        ax.plot([MEASURED[1]], [MEASURED[0]], "s", color="tab:red", ms=5,
                label=f"datum: {MEASURED[0]:g} at {MEASURED[1]:g} m/s")  # fmt: skip
        ax.set_xscale("log")
        ax.set_xlabel("impact speed w [m/s]")
        ax.set_ylabel("epsilon")
        ax.set_title(f"steel {c.geometry} on a wall, tau c/R = {c.tau:.3g}", fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
    add_notes(fig, ["tau inferred from the datum (illustrative); the sum adds the two losses of "
                    "kinetic energy; the cylinder's elastic law starts at its lowest computed "
                    "speed (docs/damping.md)"])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.damping --figures DIR``."""
    figure_main(
        argv,
        "Draw epsilon(w) of damping steel grains.",
        "damping_steel.png",
        lambda args, path: plot(compute(), path),
    )


if __name__ == "__main__":
    main()
