"""The oblique table of one material: ``beta(angle, speed)`` and ``epsilon_normal(angle,
speed)`` of the modal oblique route, stored with its provenance.

Units: SI at the edge (m/s, degrees, Pa, kg/m^3); the stored ``v`` and ``alpha`` in the grain's
reduced units (``c``, ``1 / R``).

Each entry is one speed and one angle of :func:`restitution.laws.oblique.oblique_answer` (the
same runs as ``law --angle``: :data:`~restitution.laws.oblique.MODES` modes and half as many,
the wall ``alpha delta_max = 40``), so the table and the command cannot disagree. The file
(``restitution/laws/data/oblique/<name>.json``) holds the settings, the code version of the
modal solver (:func:`restitution.provenance.code_version`), the date and the wall time, and is
read by :mod:`restitution.laws.oblique_fits` (Walton's parameters, the DEM codes' tangential
models) and by the figure of docs/oblique.md. Run as ``python -m
restitution.laws.making.oblique_table`` (about 10 min on the project's machine).
"""

from __future__ import annotations

import datetime
import json
import time
from dataclasses import dataclass
from pathlib import Path

from restitution.atomic import write_text
from restitution.laws.oblique import MODES, oblique_answer
from restitution.laws.partners.base import owner
from restitution.laws.request import request
from restitution.laws.units import BODIES
from restitution.provenance import code_version

__all__ = ["STEEL_TABLE", "TablePlan", "compute_table", "table_path"]


@dataclass(frozen=True)
class TablePlan:
    """What a table computes: a material (SI), a shape, a friction coefficient, the normal
    speeds (m/s) and the angles (degrees from the normal)."""

    name: str
    E: float
    nu: float
    rho: float
    shape: str
    friction: float
    speeds: tuple[float, ...]
    angles: tuple[float, ...]
    modes: int = MODES


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


def compute_table(plan: TablePlan, say=print) -> dict:
    """Compute ``plan`` (every angle at every speed) and return the table as stored."""
    rows, start = [], time.perf_counter()
    wall = owner("wall_E").against  # the rigid wall's partner kind
    for angle in plan.angles:
        asked = request(E=plan.E, nu=plan.nu, rho=plan.rho, shape=plan.shape, against=wall,
                        speeds=plan.speeds, angle=angle, friction=plan.friction)  # fmt: skip
        answer = oblique_answer(asked, modes=plan.modes)
        for p in answer.points:
            rows.append({"angle_deg": angle, **p.to_dict()})
            beta = "-" if p.beta is None else f"{p.beta:.5f} +- {p.beta_error:.2g}"
            say(f"{angle:g} deg, {p.speed_m_s:g} m/s: eps_n {p.epsilon_normal:.6f}, beta "
                f"{beta}, {p.wall_time_s:.1f} s")  # fmt: skip
    return {
        "description": "beta(angle, speed) and epsilon_normal(angle, speed) of the modal "
        "oblique route (restitution.laws.oblique, the runs of `law --angle`): "
        f"{plan.modes} modes, errors the change from {plan.modes // 2}",
        "material": {"E_pa": plan.E, "nu": plan.nu, "rho_kg_m3": plan.rho, "shape": plan.shape},
        "friction": plan.friction,
        "speeds_m_s": list(plan.speeds),
        "angles_deg": list(plan.angles),
        "settings": {
            "modes": plan.modes,
            "error_modes": plan.modes // 2,
            "wall_hardness": "exponential wall, alpha * delta_max(v) = the kind's softest "
            "alpha product",
            "friction_model": "stick-slip (exact switch), rtol 1e-10",
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
