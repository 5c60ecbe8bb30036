"""A steel ball's tangential restitution ``beta`` on the rigid wall against ``tan(theta) / mu``:
the finite sphere's own partial slip at three speeds beside Maw, Barber and Fawcett's laws on
the half-space, and the same for the modal route's one-state contact (issue 63; docs/oblique.md,
"The finite sphere's own partial slip", "The one-state route's own limit is not law (a)").

Units: dimensionless (``beta``, ``X = tan(theta) / mu``); speeds in m/s of a steel ball (``E =
210 GPa``, ``nu = 0.3``, ``rho = 7850 kg/m^3``, ``c = 5172 m/s``); ``beta`` does not depend on
the radius, nor on ``mu`` at a given ``X``.

Left: law (a) (one stick/slip state) and law (b) (microslip on the half-space), which do not
depend on the speed, and the finite sphere's microslip
(:mod:`restitution.quasistatic.sphere_partial_slip`) at 0.1, 1 and 10 m/s. Right: how far the
finite sphere is from law (b) against Hertz's contact radius, at ``X = 0.3`` and 2: it falls
at an order 0.7-0.9 in ``a``, slowly (0.02 at a steel ball's 1 cm/s). Below, the same for one
stick/slip state spread like the pressure (:mod:`restitution.quasistatic.sphere_one_state`:
its closed-form half-space law, not law (a), and the finite sphere). About two minutes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.quasistatic.oblique import oblique_impact
from restitution.quasistatic.sphere_one_state import one_state_half_space, one_state_run
from restitution.quasistatic.sphere_partial_slip import REACH, AnnularContact, hertz_peak, run
from restitution.reproduction.figures._style import add_notes, figure_main

__all__ = ["STEEL_C_M_S", "PartialSlipCurves", "compute", "main", "plot"]

NU, MU = 0.3, 0.3
STEEL_C_M_S = math.sqrt(210e9 / 7850.0)
"""``c = sqrt(E / rho)`` of the steel ball, m/s."""


@dataclass(frozen=True, eq=False)
class PartialSlipCurves:
    """``beta`` on the grid ``x = tan(theta) / mu``: ``law_a``, ``law_b`` (shape (X,)) and
    ``finite`` (shape (speeds, X)) at ``speed_m_s``; the gap ``finite - law (b)`` at
    ``gap_x`` (shape (2,)) for ``gap_speed_m_s`` with Hertz's contact radius ``gap_radius``
    (``R``), shape (2, gap speeds). The same for one stick/slip state spread like the
    pressure: ``one_state`` (the half-space's, shape (X,)), ``finite_one_state`` and
    ``gap_one_state`` (its finite sphere minus its half-space)."""

    x: np.ndarray
    law_a: np.ndarray
    law_b: np.ndarray
    speed_m_s: np.ndarray
    finite: np.ndarray
    gap_x: np.ndarray
    gap_speed_m_s: np.ndarray
    gap_radius: np.ndarray
    gap: np.ndarray
    one_state: np.ndarray
    finite_one_state: np.ndarray
    gap_one_state: np.ndarray


def _finite(w: float, xs, annuli: int) -> tuple[np.ndarray, np.ndarray]:
    """The finite sphere's ``beta`` at the steel speed ``w`` for each ``x`` (one set of
    annuli): with microslip and with one state."""
    v = w / STEEL_C_M_S
    contact = AnnularContact.build(REACH * math.sqrt(hertz_peak(v, NU)), NU, annuli=annuli)
    return tuple(
        np.array([solve(contact, v, x * MU * v, MU, NU, 100 * annuli)[0] for x in xs])
        for solve in (run, one_state_run)
    )


def compute(x=None, speeds_m_s=(0.1, 1.0, 10.0), gap_speeds_m_s=None, *,
            annuli: int = 40) -> PartialSlipCurves:  # fmt: skip
    """The curves of the module docs (``annuli`` across the contact's reach, 100 steps each
    per contact time: ``beta`` within 1e-3 of twice as many, tests/test_sphere_partial_slip.py)."""
    x = np.geomspace(0.1, 8.0, 15) if x is None else np.asarray(x, dtype=float)
    gaps = np.geomspace(0.01, 20.0, 7) if gap_speeds_m_s is None else np.asarray(gap_speeds_m_s)
    v0 = 1.0 / STEEL_C_M_S  # laws (a) and (b) do not depend on the speed

    def law(model, xs):
        return np.array([oblique_impact(v0, q * MU * v0, MU, NU, model=model).beta for q in xs])

    def one_state(xs):
        return np.array([one_state_half_space(v0, q * MU * v0, MU, NU)[0] for q in xs])

    gap_x = np.array([0.3, 2.0])
    at_gaps = np.array([_finite(w, gap_x, annuli) for w in gaps])  # (gaps, 2 frictions, 2)
    gap = at_gaps[:, 0].T - law("microslip", gap_x)[:, None]
    gap_one = at_gaps[:, 1].T - one_state(gap_x)[:, None]
    radius = np.array([math.sqrt(hertz_peak(w / STEEL_C_M_S, NU)) for w in gaps])
    curves = np.array([_finite(w, x, annuli) for w in speeds_m_s])  # (speeds, 2 frictions, X)
    return PartialSlipCurves(
        x, law("no-microslip", x), law("microslip", x), np.asarray(speeds_m_s, dtype=float),
        curves[:, 0], gap_x, np.asarray(gaps, float), radius, gap, one_state(x),
        curves[:, 1], gap_one,
    )  # fmt: skip


def _row(left, right, c: PartialSlipCurves, x_ref, ref_label, finite, gap, name) -> None:
    """One friction's panels: ``beta(x)`` beside law (a) and its half-space reference (left),
    the finite sphere's distance from that reference against ``a`` (right)."""
    left.plot(c.x, c.law_a, "k--", lw=1.0, label="law (a): Hertz-Mindlin, one state (DEM codes)")
    left.plot(c.x, x_ref, "k-", lw=1.4, label=ref_label)
    for w, beta, color in zip(c.speed_m_s, finite, ("tab:blue", "tab:orange", "tab:red"),
                              strict=False):  # fmt: skip
        a = math.sqrt(hertz_peak(w / STEEL_C_M_S, NU))
        left.plot(c.x, beta, "o-", ms=3, color=color,
                  label=f"finite sphere, {w:g} m/s (a = {a:.3f} R)")  # fmt: skip
    left.axhline(0.0, color="0.7", lw=0.6)
    left.set_xscale("log")
    left.set_xlabel("tan(theta) / mu")
    left.set_ylabel("beta (contact point)")
    left.set_title(f"{name}: steel ball on a rigid wall, nu = 0.3", fontsize=10)
    left.legend(fontsize=7, loc="upper left")
    for row, x, marker in zip(gap, c.gap_x, ("o", "s"), strict=True):
        right.plot(c.gap_radius, row, marker + "-", ms=4, label=f"tan(theta)/mu = {x:g}")
    a = c.gap_radius
    right.plot(a, gap[0, -1] * a / a[-1], "k:", lw=1.0, label="slope 1 (proportional to a)")
    top = right.secondary_xaxis(
        "top",
        functions=(lambda r: np.sqrt(16.0 * np.abs(r) ** 5 / (15.0 * 4.0 * math.pi / 3.0
                                                               * (1.0 - NU * NU))) * STEEL_C_M_S,
                   lambda w: np.sqrt(hertz_peak(np.abs(w) / STEEL_C_M_S, NU))),
    )  # fmt: skip
    top.set_xlabel("steel impact speed (m/s)", fontsize=8)
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel("Hertz's contact radius a (R)")
    right.set_ylabel("beta: finite sphere minus half-space")
    right.legend(fontsize=7, loc="upper left")


def plot(c: PartialSlipCurves, path=None, notes=()):
    """``beta(x)`` (left) and the finite sphere's distance from the half-space (right), with
    microslip (top) and with one stick/slip state spread like the pressure (bottom)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(10.0, 8.8))
    _row(*axes[0], c, c.law_b, "law (b): microslip on the half-space", c.finite, c.gap,
         "Microslip")  # fmt: skip
    _row(*axes[1], c, c.one_state, "one state spread like the pressure, half-space",
         c.finite_one_state, c.gap_one_state, "One state (the modal route's)")  # fmt: skip
    add_notes(fig, ["finite sphere: quasistatic, on annuli of its own flexibility (free sphere, "
                    "inertial relief); the half-space is its a -> 0 limit",
                    *notes])  # fmt: skip
    if path is not None:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=110)
    return fig


def main(argv=None) -> None:
    """``python -m restitution.reproduction.figures.sphere_partial_slip --figures DIR``."""
    figure_main(
        argv,
        "Draw the steel ball's beta on its own flexibility against the half-space's.",
        "sphere_partial_slip.png",
        lambda args, path: plot(compute(), path),
    )


if __name__ == "__main__":
    main()
