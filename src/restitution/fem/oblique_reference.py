"""Stored finite-element oblique impacts of the disk, beside the modal route's (issue 63).

Units: ``E = rho = R = 1`` (the disk's two-dimensional constants); speeds in ``c``.

Command line (writes the JSON with its provenance: settings, the FEM code version, the modal
solver's code version, the date and the wall times; ``--add-kappa`` adds the low-speed
convergence in ``kappa`` to an existing file):

    python -m restitution.fem.oblique_reference OUT.json
    python -m restitution.fem.oblique_reference OUT.json --add-kappa

The study: one speed and wall (``v = 0.05``, ``alpha = 40 / delta_max(v)``, the softest wall of
the head-on judge), ``nu = 0.33``, ``mu = 0.5`` at ``tan(theta) / mu = 0.5, 1, 2, 3, 6`` (the
last in gross slip) and ``mu = 0.1`` at 80 degrees; the finite elements on mesh levels 0, 1, 2
at ``kappa = 16, 64`` (and the convergence in ``kappa`` and in the step at level 0, 45
degrees, ``mu = 0.5``), the modal route (:func:`restitution.dynamics.oblique.oblique_collision`,
the exact switch) at 40, 80 and 160 modes. The same at low speed, ``v = 0.005``: gross sliding
(``mu = 0.1``, 80 degrees) on ``alpha = 500``, and ``mu = 0.5`` at ``tan(theta) / mu = 0.3, 0.6,
2, 3, 6`` on ``alpha = 2000`` (the wall of docs/oblique.md's table against Maw, Barber and
Fawcett).
"""

from __future__ import annotations

import datetime
import json
import math
import sys
import time

from restitution.bodies.disk.contact import max_compression_estimate
from restitution.fem.oblique_impact import fem_oblique_collide
from restitution.fem.whole_disk import PLANAR_GEOMETRY
from restitution.provenance import FEM_MODULES, code_version, source_digest

__all__ = [
    "CASES",
    "LOW_SPEED",
    "LOW_SPEED_CASES",
    "add_low_speed_kappa_study",
    "compute",
    "fem_oblique_code_version",
]

NU = 0.33
V = 0.05
ALPHA_PRODUCT = 40.0
CASES: tuple[tuple[float, float], ...] = (
    (0.5, 0.5),
    (0.5, 1.0),
    (0.5, 2.0),
    (0.5, 3.0),
    (0.5, 6.0),
    (0.1, math.tan(math.radians(80.0)) / 0.1),
)
"""``(mu, tan(theta) / mu)`` of the study at ``V``."""
LOW_SPEED = (0.005, 2000.0)
"""``(v, alpha)`` of the low-speed study: the wall of docs/oblique.md's table against Maw,
Barber and Fawcett (its rows ``tan(theta) / mu = 0.3, 0.6, 2, 3, 6`` at ``mu = 0.5``)."""
LOW_SPEED_CASES: tuple[tuple[float, float], ...] = (
    (0.5, 0.3),
    (0.5, 0.6),
    (0.5, 2.0),
    (0.5, 3.0),
    (0.5, 6.0),
)
GROSS_SLIDING_LOW = (0.005, 500.0, 0.1, math.tan(math.radians(80.0)) / 0.1)
"""``(v, alpha, mu, tan(theta) / mu)``: the modal route's gross-sliding check."""
LEVELS = (0, 1, 2)
KAPPAS = (16.0, 64.0)
KAPPA_STUDY = (1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0)
MODES = (40, 80, 160)


def fem_oblique_code_version() -> str:
    """The FEM code version of the oblique judge: the head-on FEM modules and the two oblique
    ones."""
    modules = FEM_MODULES + ("restitution.fem.whole_disk", "restitution.fem.oblique_impact")
    return source_digest(modules, "fem-oblique.")


def _modal(v: float, mu: float, tan: float, alpha: float, modes: int) -> dict:
    from restitution.bodies.cache import get_modes
    from restitution.bodies.kinds import body_kind
    from restitution.dynamics.oblique import oblique_collision

    body = body_kind(PLANAR_GEOMETRY).oblique_body(get_modes(NU, count=modes, use_cache=False))
    start = time.perf_counter()
    out = oblique_collision(body, v, v * tan, mu, alpha)
    return {
        "modes": modes,
        "epsilon_normal": out.epsilon_normal,
        "beta": out.beta,
        "spin": out.spin,
        "friction_work": out.friction_work,
        "vibration_energy": out.vibration_energy,
        "energy_balance": out.energy_balance,
        "phases": len(out.phases),
        "wall_time_s": time.perf_counter() - start,
    }


def _fem(v: float, mu: float, tan: float, alpha: float, **settings) -> dict:
    out = fem_oblique_collide(NU, v, v * tan, mu, alpha, **settings).to_dict()
    out["step_safety"] = settings.get("step_safety", 0.9)
    return out


def _study(v: float, alpha: float, cases, on_case) -> list[dict]:
    """FEM (every level and ``kappa``) and modal runs (every mode count) of ``cases``."""
    rows = []
    for mu, tan in cases:
        case = {
            "v_normal": v,
            "alpha": alpha,
            "mu": mu,
            "tan_over_mu": tan,
            "angle_deg": math.degrees(math.atan(mu * tan)),
        }
        case["fem"] = [
            _fem(v, mu, mu * tan, alpha, level=lv, kappa=k) for lv in LEVELS for k in KAPPAS
        ]
        case["modal"] = [_modal(v, mu, mu * tan, alpha, n) for n in MODES]
        rows.append(case)
        on_case(rows)
    return rows


def compute(path: str) -> dict:
    """Run the studies and write them to ``path`` (JSON, after every case); returns them."""
    start = time.perf_counter()
    alpha = ALPHA_PRODUCT / max_compression_estimate(V)
    data = {
        "what": "oblique impact of the disk on the exponential wall with Coulomb friction: "
        "finite elements (whole disk, point-wise friction) against the modal route",
        "units": "E = rho = R = 1 (2D constants); speeds c; energies in E0",
        "nu": NU,
        "v_normal": V,
        "alpha": alpha,
        "alpha_product": ALPHA_PRODUCT,
        "fem_code_version": fem_oblique_code_version(),
        "modal_code_version": code_version(PLANAR_GEOMETRY),
        "fem_settings": FEM_SETTINGS,
        "modal_settings": "oblique_collision, exact stick/slip switch, rtol 1e-10, the N "
        "lowest symmetric modes and their rim partners (rim_modes)",
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "command": "python -m restitution.fem.oblique_reference " + path,
        "frictionless_45": _fem(V, 0.0, 1.0, alpha),
        "kappa_study": [_fem(V, 0.5, 1.0, alpha, kappa=k) for k in KAPPA_STUDY],
        "step_study": [
            _fem(V, 0.5, 1.0, alpha, kappa=4.0, step_safety=s) for s in (0.9, 0.45, 0.225)
        ],
    }

    def save(key):
        def on_case(rows):
            data[key] = rows
            data["wall_time_s"] = time.perf_counter() - start
            _write(path, data)

        return on_case

    _study(V, alpha, CASES, save("cases"))
    v, alpha_low, mu, tan = GROSS_SLIDING_LOW
    _study(v, alpha_low, ((mu, tan),), save("gross_sliding_low_speed"))
    _study(*LOW_SPEED, LOW_SPEED_CASES, save("low_speed_cases"))
    return data


FEM_SETTINGS = (
    "FemObliqueSettings defaults but level and kappa: the head-on judge's graded_settings(v, "
    "alpha, level) (ContactGrading defaults: contact_fraction 0.4, grading 0.5, h_far 0.4) "
    "mirrored, the fine arc widened by min(v_t, 4 mu v) times the contact time (at most 0.5 "
    "rad), 8 Gauss points per rim facet, rim |phi| <= pi/2, step_safety 0.9 (unless stated), "
    "energy_tol 1e-5, nu = 0.33 (2D constants)"
)
LOW_SPEED_KAPPAS = (16.0, 64.0, 256.0, 1024.0)
"""``kappa`` of the low-speed convergence study (level 0, ``tan(theta) / mu = 0.3`` and 2)."""


def add_low_speed_kappa_study(path: str) -> dict:
    """Add ``low_speed_kappa_study`` (level 0, :data:`LOW_SPEED_KAPPAS`, ``mu = 0.5``,
    ``tan(theta) / mu = 0.3`` and 2 at :data:`LOW_SPEED`) to the study in ``path``, with its own
    date, code version and wall time."""
    with open(path) as fh:
        data = json.load(fh)
    start = time.perf_counter()
    v, alpha = LOW_SPEED
    rows = [_fem(v, 0.5, 0.5 * tan, alpha, kappa=k) for tan in (0.3, 2.0) for k in LOW_SPEED_KAPPAS]
    data["low_speed_kappa_study"] = {
        "runs": rows,
        "fem_code_version": fem_oblique_code_version(),
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "command": f"python -m restitution.fem.oblique_reference {path} --add-kappa",
        "wall_time_s": time.perf_counter() - start,
    }
    _write(path, data)
    return data


def _write(path: str, data: dict) -> None:
    with open(path, "w") as fh:
        json.dump(data, fh, indent=1)
        fh.write("\n")


if __name__ == "__main__":  # pragma: no cover
    if len(sys.argv) == 3 and sys.argv[2] == "--add-kappa":
        add_low_speed_kappa_study(sys.argv[1])
    elif len(sys.argv) == 2:
        compute(sys.argv[1])
    else:
        raise SystemExit(
            "usage: python -m restitution.fem.oblique_reference OUT.json [--add-kappa]"
        )
