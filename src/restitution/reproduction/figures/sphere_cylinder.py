"""epsilon against impact speed for spheres beside cylinders of the same material (SI units).

Units: impact speed ``w`` in m/s against a rigid wall; epsilon dimensionless.

For a few real materials (3D constants in SI) the shipped laws are served at SI speeds by
:func:`restitution.laws.si_law.si_law`: the sphere's law for its 3D Poisson number
(``c = sqrt(E/rho)``) and the long cylinder's (the disk in plane strain, ``nu_2d = nu/(1-nu)``,
``c = sqrt(E/((1-nu^2) rho))``). Each curve covers only the speeds its law computed; points
whose extrapolation did not pass every asymptotic check are drawn hollow, and the sphere's slow
speeds served by the low-speed theory (status ``quasistatic``) dashed. Nothing is computed:
the figure shows the shipped numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.laws.si_law import si_law
from restitution.reproduction.figures._style import add_notes, figure_main
from restitution.status import Status

__all__ = ["MATERIALS", "SICurve", "compute", "main", "plot"]

MATERIALS: dict[str, tuple[float, float, float]] = {
    "steel": (210e9, 0.30, 7850.0),
    "aluminium": (70e9, 0.33, 2700.0),
    "glass": (63e9, 0.22, 2500.0),
}
"""Name -> (E in Pa, 3D nu, rho in kg/m^3), handbook values of common grains."""

_ASYMPTOTIC = (Status.COMPUTED, Status.INTERPOLATED)


@dataclass(frozen=True, eq=False)
class SICurve:
    """One body of one material: epsilon at SI speeds inside its law's computed range.

    Attributes
    ----------
    material, geometry : str
        Material name and ``"sphere"`` or ``"cylinder"``.
    speed_m_s, epsilon, epsilon_err : numpy.ndarray
        Impact speeds (m/s, against the wall) and the law's value and error there.
    asymptotic : numpy.ndarray of bool
        Whether the point's status is computed or interpolated between asymptotic points.
    quasistatic : numpy.ndarray of bool
        Whether the point comes from the low-speed theory (status ``quasistatic``).
    law_nu : float
        The Poisson number of the law served (the sphere's 3D nu, the cylinder's nu_2d).
    """

    material: str
    geometry: str
    speed_m_s: np.ndarray
    epsilon: np.ndarray
    epsilon_err: np.ndarray
    asymptotic: np.ndarray
    quasistatic: np.ndarray
    law_nu: float


def compute(materials=MATERIALS, points: int = 120) -> tuple[SICurve, ...]:
    """Sample every material's sphere and cylinder law at ``points`` speeds in its range."""
    out = []
    for name, (E, nu, rho) in materials.items():
        for geometry in (*SPHERE.shapes, "cylinder"):
            s = si_law(E=E, nu=nu, rho=rho, geometry=geometry, against=WALL.against)
            lo, hi = s.computed_range_m_s
            speeds = np.geomspace(lo, hi, points)
            pts = s.points(speeds)
            pts = [p for p in pts if p.epsilon is not None]
            out.append(
                SICurve(
                    material=name,
                    geometry=geometry,
                    speed_m_s=np.array([p.speed_m_s for p in pts]),
                    epsilon=np.array([p.epsilon for p in pts]),
                    epsilon_err=np.array([p.epsilon_err for p in pts]),
                    asymptotic=np.array([p.status in _ASYMPTOTIC for p in pts]),
                    quasistatic=np.array([p.status == Status.QUASISTATIC for p in pts]),
                    law_nu=float(s.grain.law_nu),
                )
            )
    return tuple(out)


def plot(curves: tuple[SICurve, ...], path=None, notes=()):
    """One panel per material: epsilon against the speed (log), sphere and cylinder."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(c.material for c in curves))
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 3.8), squeeze=False)
    colours = {SPHERE.geometry: "tab:red", "cylinder": "tab:blue"}
    for ax, name in zip(axes[0], names, strict=True):
        for c in (c for c in curves if c.material == name):
            col = colours[c.geometry]
            ax.fill_between(c.speed_m_s, c.epsilon - c.epsilon_err, c.epsilon + c.epsilon_err,
                            color=col, alpha=0.2, lw=0)  # fmt: skip
            q = c.quasistatic
            ax.plot(np.where(q, np.nan, c.speed_m_s), c.epsilon, "-", color=col, lw=1,
                    label=f"{c.geometry} (law nu = {c.law_nu:.3g})")  # fmt: skip
            if q.any():
                ax.plot(c.speed_m_s[q], c.epsilon[q], "--", color=col, lw=1,
                        label=f"{c.geometry}: low-speed theory")  # fmt: skip
            flagged = ~c.asymptotic & ~q
            ax.plot(c.speed_m_s[flagged], c.epsilon[flagged], "o", mfc="none", color=col, ms=3)
        ax.set_xscale("log")
        ax.set_xlabel("impact speed against the wall [m/s]")
        ax.set_ylabel("epsilon")
        ax.set_title(name, fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
    fig.suptitle("Vibrational epsilon: spheres beside long cylinders of the same material",
                 fontsize=10)  # fmt: skip
    add_notes(fig, ["bands: the laws' errors; hollow: not every asymptotic check passed; dashed: "
                    "the sphere's low-speed theory; each curve spans the speeds its law computed",
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.sphere_cylinder --figures DIR``."""
    figure_main(
        argv,
        "Draw spheres beside cylinders (shipped laws).",
        "sphere_cylinder.png",
        lambda args, path: plot(compute(), path),
    )


if __name__ == "__main__":
    main()
