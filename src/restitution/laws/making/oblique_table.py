"""The oblique table of one material: ``beta(angle, speed)`` and ``epsilon_normal(angle,
speed)`` of the modal oblique route, stored with its provenance.

Units: SI at the edge (m/s, degrees, Pa, kg/m^3); the stored ``v`` and ``alpha`` in the grain's
reduced units (``c``, ``1 / R``).

Each entry is one speed and one angle of :func:`restitution.laws.oblique.oblique_answer` (the
same runs as ``law --angle``: the kind's modes, :func:`restitution.laws.oblique.law_modes`, and
half as many, the kind's softest wall), so the table and the command cannot disagree. The table
holds the settings, the grain's ``inertia_factor``, the code version of the modal solver
(:func:`restitution.provenance.code_version`), the date and the wall time, and is read by
:func:`restitution.laws.oblique_fits.fit_table` (Walton's parameters, the DEM codes' tangential
models) and by the figure of docs/oblique.md. Any material's table is made by ``restitution
oblique-fit`` (:mod:`restitution.laws.making.oblique_fit`); the shipped steel cylinder's
(``restitution/laws/data/oblique/<name>.json``) by ``python -m
restitution.laws.making.oblique_table`` (about 10 min on the project's machine).
"""

from __future__ import annotations

import datetime
import json
import time
from dataclasses import dataclass
from pathlib import Path

from restitution.atomic import write_text
from restitution.laws.oblique import oblique_answer, oblique_seconds
from restitution.laws.partners.base import owner
from restitution.laws.request import request
from restitution.laws.serve import head_on_points
from restitution.laws.units import BODIES
from restitution.provenance import code_version

__all__ = [
    "STEEL_TABLE",
    "TablePlan",
    "compute_table",
    "plan_requests",
    "table_path",
    "table_seconds",
]

_MODEL_WORDS = {
    "stick-slip": "stick-slip (exact switch), rtol 1e-10",
    "microslip": "microslip (Coulomb's law at every wall node, regularised by kappa)",
}
"""How the table's settings name its friction model."""


@dataclass(frozen=True)
class TablePlan:
    """What a table computes: a material (SI), a shape, a friction coefficient, the normal
    speeds (m/s), the angles (degrees from the normal), the modes (``None``: the kind's,
    :func:`~restitution.laws.oblique.law_modes`), the friction model and microslip's
    ``kappa`` (``None``: ``law --angle``'s defaults)."""

    name: str
    E: float
    nu: float
    rho: float
    shape: str
    friction: float
    speeds: tuple[float, ...]
    angles: tuple[float, ...]
    modes: int | None = None
    friction_model: str | None = None
    kappa: float | None = None


STEEL_TABLE = TablePlan(
    name="steel_cylinder_mu0.3",
    E=210e9,
    nu=0.3,
    rho=7850.0,
    shape="cylinder",
    friction=0.3,
    speeds=(0.5, 1.0, 2.0, 5.0),
    angles=(0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0),
)
"""The shipped table: a steel cylinder (E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3) on the rigid
wall, mu = 0.3, tan(angle) / mu from 0.59 to 18.9; angle 0 is the head-on impact of the same modes
and wall (no tangential force), the baseline of ``epsilon_normal``."""


def table_path(name: str) -> Path:
    """Where the table ``name`` is shipped."""
    return Path(__file__).resolve().parents[1] / "data" / "oblique" / f"{name}.json"


def plan_requests(plan: TablePlan) -> list:
    """One :class:`~restitution.laws.request.LawRequest` per angle of ``plan`` (each checked
    where it is built: a bad material, angle or friction is refused before any run)."""
    wall = owner("wall_E").against  # the rigid wall's partner kind
    return [request(E=plan.E, nu=plan.nu, rho=plan.rho, shape=plan.shape, against=wall,
                    speeds=plan.speeds, angle=angle, friction=plan.friction,
                    friction_model=plan.friction_model, kappa=plan.kappa)
            for angle in plan.angles]  # fmt: skip


def table_seconds(plan: TablePlan) -> tuple[float, str]:
    """The estimated seconds of :func:`compute_table` (the modes computed or read from the
    cache, nothing run) and how they were estimated."""
    total, how = 0.0, ""
    for asked in plan_requests(plan):
        seconds, how = oblique_seconds(asked, plan.modes)
        total += seconds
    return total, how


def compute_table(plan: TablePlan, say=print) -> dict:
    """Compute ``plan`` (every angle at every speed) and return the table as stored; ``say``
    is told each point as it is done. Each row also holds the head-on law at its speed
    (``epsilon_head_on_law``: the normal coefficient ``law`` serves, :func:`~restitution.laws.
    serve.head_on_points`), which ``epsilon_normal``'s error then includes."""
    rows, start = [], time.perf_counter()
    modes = factor = model = None
    asks = plan_requests(plan)
    head_on = head_on_points(asks[0], say)  # the same at every angle
    for angle, asked in zip(plan.angles, asks, strict=True):
        answer = oblique_answer(asked, modes=plan.modes, head_on=head_on)
        modes, factor = answer.points[0].modes, answer.inertia_factor
        model = asked.oblique_friction_model
        for p in answer.points:
            rows.append({"angle_deg": angle, **p.to_dict()})
            beta = "-" if p.beta is None else f"{p.beta:.5f} +- {p.beta_error:.2g}"
            say(f"{angle:g} deg, {p.speed_m_s:g} m/s: eps_n {p.epsilon_normal:.6f}, beta "
                f"{beta}, {p.wall_time_s:.1f} s")  # fmt: skip
    return {
        "description": "beta(angle, speed) and epsilon_normal(angle, speed) of the modal "
        "oblique route (restitution.laws.oblique, the runs of `law --angle`): "
        f"{modes} modes, errors the change from {modes // 2}",
        "material": {"E_pa": plan.E, "nu": plan.nu, "rho_kg_m3": plan.rho, "shape": plan.shape},
        "friction": plan.friction,
        "inertia_factor": factor,
        "speeds_m_s": list(plan.speeds),
        "angles_deg": list(plan.angles),
        "settings": {
            "modes": modes,
            "error_modes": modes // 2,
            "wall_hardness": "exponential wall, alpha * delta_max(v) = the kind's softest "
            "alpha product",
            "friction_model": _MODEL_WORDS.get(model, model),
        },
        "code_version": code_version(BODIES[plan.shape]),
        "computed": datetime.date.today().isoformat(),
        "wall_time_s": round(time.perf_counter() - start, 1),
        "rows": rows,
    }


def main() -> None:  # pragma: no cover - the production run
    table = compute_table(STEEL_TABLE)
    path = table_path(STEEL_TABLE.name)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, json.dumps(table, indent=1) + "\n")
    print(f"wrote {path}")


if __name__ == "__main__":  # pragma: no cover
    main()
