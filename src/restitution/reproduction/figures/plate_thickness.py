"""A steel ball on glass: epsilon against the plate's thickness, from the thin plate to the block.

Units: SI at the edge (a 5 mm steel ball, ``E = 210 GPa``, ``nu = 0.3``, ``rho = 7850 kg/m^3``,
on glass, ``63 GPa``, ``0.2481``, ``2500 kg/m^3``; thickness in mm, speed 1 m/s); the routes
work in the ball's reduced units.

The curve is Zener's thin-plate model solved as the coupled equation
(:mod:`restitution.quasistatic.plate`), drawn solid where its validity holds and dotted where
it does not, with its error band; the horizontal line is the half-space
(:mod:`restitution.quasistatic.half_space`: the ball's vibrations and the block's radiated
waves) with its error. The finite-element judge's stored points of this ball on glass
(:mod:`restitution.fem.wall_reference`: plates and the block, both limits and both checks)
are drawn where their speed is the figure's (within :data:`restitution.laws.wall_points.
SPEED_MATCH`): at 1 m/s the two plates; the second figure, at :data:`FEM_SPEED_M_S`, holds both
plates and the block.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.wall import HalfSpace, Plate
from restitution.estimate import Estimate
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["ThicknessCurve", "compute", "main", "plot"]

STEEL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
GLASS = {"E": 63e9, "nu": 0.2481, "rho": 2500.0}
RADIUS_M = 2.5e-3
SPEED_M_S = 1.0
FEM_SPEED_M_S = 5e-4 * float(np.sqrt(STEEL["E"] / STEEL["rho"]))
"""The speed of the judge's stored plate points, ``v = 5e-4 c`` (2.59 m/s)."""


@dataclass(frozen=True, eq=False)
class ThicknessCurve:
    """epsilon against the plate's thickness, and the half-space's.

    Attributes
    ----------
    thickness_mm, epsilon, epsilon_err : numpy.ndarray, shape (K,)
        Zener's model (``nan`` where the ball does not rebound).
    valid : numpy.ndarray of bool, shape (K,)
        Whether the thin-plate model holds there.
    block : Estimate
        The half-space's epsilon and error (:attr:`half_space`, :attr:`half_space_err`).
    """

    thickness_mm: np.ndarray
    epsilon: np.ndarray
    epsilon_err: np.ndarray
    valid: np.ndarray
    block: Estimate
    speed_m_s: float = SPEED_M_S
    fem: tuple = ()
    """``(thickness_mm, epsilon, epsilon_err)`` of the stored FEM points at this speed
    (``inf`` for the block)."""

    half_space = property(lambda self: self.block.epsilon, doc="The block's epsilon.")
    half_space_err = property(lambda self: self.block.epsilon_err, doc="Its error.")


def _fem_points(v: float, ratios) -> tuple:
    """The judge's stored points of a steel ball on this glass at ``v`` (``c``)."""
    import math

    from restitution.laws.wall_points import SPEED_MATCH, load_wall_reference

    out = []
    for p in load_wall_reference():
        w = p.wall
        same = (w.modulus_ratio, w.density_ratio, w.nu) == tuple(ratios)
        if same and p.nu == STEEL["nu"] and abs(math.log(p.v / v)) <= SPEED_MATCH:
            mm = getattr(w, "thickness", np.inf) * RADIUS_M * 1e3
            out.append((float(mm), p.epsilon, p.epsilon_err))
    return tuple(sorted(out))


def compute(thickness_mm=None, speed_m_s: float = SPEED_M_S) -> ThicknessCurve:
    """Zener's model at each thickness and the half-space, at ``speed_m_s`` (module docs)."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.half_space import half_space_loss
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES
    from restitution.quasistatic.plate import model_error, plate_impact, validity

    h = np.geomspace(0.5, 100.0, 61) if thickness_mm is None else np.asarray(thickness_mm)
    ratios = (GLASS["E"] / STEEL["E"], GLASS["rho"] / STEEL["rho"], GLASS["nu"])
    v = speed_m_s / np.sqrt(STEEL["E"] / STEEL["rho"])
    eps, err, ok = [], [], []
    for mm in h:
        plate = Plate(*ratios, thickness=mm * 1e-3 / RADIUS_M)
        r = plate_impact(v, plate, nu=STEEL["nu"], mass=SPHERE_MASS)
        if r.epsilon is None:
            eps.append(np.nan), err.append(np.nan), ok.append(False)
            continue
        eps.append(r.epsilon)
        err.append(model_error(r, plate) / (2.0 * r.epsilon))
        ok.append(not validity(r, plate))
    modes = get_modes(STEEL["nu"], LOW_SPEED_MODES, geometry=SPHERE.geometry)
    block = half_space_loss(modes, v, HalfSpace(*ratios))
    return ThicknessCurve(np.asarray(h, dtype=float), np.array(eps), np.array(err),
                          np.array(ok), block.estimate, float(speed_m_s),
                          _fem_points(v, ratios))  # fmt: skip


def plot(c: ThicknessCurve, path=None, notes=()):
    """epsilon against the thickness (log), Zener's band, the half-space's line."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 4.4))
    lines = ((c.valid, "-", "thin plate (Zener, coupled equation)"),
             (~c.valid, ":", "thin plate where its model does not hold"))  # fmt: skip
    for sel, style, label in lines:
        y = np.where(sel, c.epsilon, np.nan)
        ax.plot(c.thickness_mm, y, style, color="tab:blue", lw=1.2, label=label)
    # epsilon lies in [0, 1] whatever the error (an elastic ball at rest only loses energy)
    low = np.clip(c.epsilon - c.epsilon_err, 0.0, 1.0)
    high = np.clip(c.epsilon + c.epsilon_err, 0.0, 1.0)
    ax.fill_between(c.thickness_mm, low, high, where=c.valid, color="tab:blue", alpha=0.2,
                    lw=0)  # fmt: skip
    ax.axhspan(c.half_space - c.half_space_err, c.half_space + c.half_space_err,
               color="tab:red", alpha=0.2, lw=0)  # fmt: skip
    ax.axhline(c.half_space, color="tab:red", lw=1.0,
               label="half-space (ball's vibrations + radiated waves)")  # fmt: skip
    plates = [p for p in c.fem if np.isfinite(p[0])]
    if plates:
        x, y, e = zip(*plates, strict=True)
        ax.errorbar(x, y, e, fmt="o", color="k", ms=4, capsize=3, label="finite elements (plate)")
    for _, eps, err in (p for p in c.fem if not np.isfinite(p[0])):
        ax.errorbar([c.thickness_mm[-1]], [eps], [err], fmt="s", color="k", ms=4, capsize=3,
                    label="finite elements (block)")  # fmt: skip
    ax.set_xscale("log")
    ax.set_ylim(0.0, 1.02)
    ax.set_xlabel("glass plate thickness h (mm)")
    ax.set_ylabel("epsilon")
    ax.set_title(f"A 5 mm steel ball on glass at {c.speed_m_s:.3g} m/s", fontsize=10)
    ax.legend(fontsize=7, loc="lower right")
    add_notes(fig, ["bands: error estimates, cut to [0, 1]; Zener's plate has no radiation "
                    "into its depth: it tends to 1, not to the block (dotted: its model fails)",
                    *([] if c.fem else [f"no finite-element point is stored at "
                                        f"{c.speed_m_s:.3g} m/s (they are at "
                                        f"{FEM_SPEED_M_S:.3g} m/s: the second figure)"]),
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.plate_thickness --figures DIR``."""
    figure_main(
        argv,
        "Draw epsilon against plate thickness.",
        "plate_thickness_steel_glass.png",
        _draw_both,
    )


def _draw_both(args, path) -> None:
    """The 1 m/s figure at ``path`` and the judge's speed beside it (``..._2.6ms.png``)."""
    plot(compute(), path)
    second = path.with_name(f"{path.stem}_{FEM_SPEED_M_S:.2g}ms.png")
    plot(compute(speed_m_s=FEM_SPEED_M_S), second)
    print(f"wrote {second}")


if __name__ == "__main__":
    main()
