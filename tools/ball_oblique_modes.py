"""The steel ball's oblique impact at its real wall, against Maw, Barber and Fawcett (issue 63).

The modal sphere (:func:`restitution.dynamics.oblique.oblique_collision` on the cap of every
azimuthal order, ``BodyKind.oblique_body``) of steel (``nu = 0.3``) at 1 m/s (``v = w / c``,
``c = sqrt(E / rho)`` = 5172 m/s: ``v = 1.9334e-4``) on the wall ``law --angle`` uses (``alpha =
80 / delta_max(v)``), ``mu = 0.3``, at angles whose ``tan(theta) / mu`` spans partial slip to
gross slip, at 10, 20 and 40 axisymmetric modes; beside it the quasistatic theory
(:func:`restitution.quasistatic.oblique.beta_of_psi`) with one stick/slip state for the contact
(law (a), ``"no-microslip"``: the modal model's own counterpart) and with Mindlin's microslip
(law (b)), at ``psi = chi tan(theta) / mu``, ``chi = 2 (1 - nu) / (2 - nu)``.

Writes ``OUT`` (JSON: settings, per angle and mode count ``epsilon_normal``, ``beta``, spin,
energy balance, wall time; the two laws' ``beta``; the code version, date and machine) whole or
not at all, and prints the table of docs/oblique.md.

Usage (from the project's root, with its venv; about 5 min on one core)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/ball_oblique_modes.py \
        tests/data/ball_oblique_modes.json
"""

from __future__ import annotations

import argparse
import datetime
import json
import math
import platform
import time

from restitution import atomic
from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import body_kind
from restitution.dynamics.oblique import oblique_collision
from restitution.provenance import code_version
from restitution.quasistatic.oblique import MODELS, beta_of_psi, stiffness_ratio

NU = 0.3
SPEED_M_S = 1.0
C_M_S = math.sqrt(210e9 / 7850.0)
MU = 0.3
TAN_OVER_MU = (0.5, 1.0, 2.0, 3.0, 6.0)
MODES = (10, 20, 40)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="JSON file to write")
    out = parser.parse_args().out
    kind = body_kind("sphere")
    v = SPEED_M_S / C_M_S
    alpha = kind.alpha_products[0] / kind.max_compression(v, NU)
    chi = stiffness_ratio(NU)
    bodies = {n: kind.oblique_body(get_modes(NU, count=n, geometry="sphere")) for n in MODES}
    rows = []
    for ratio in TAN_OVER_MU:
        tan = ratio * MU
        psi = chi * ratio
        row = {
            "tan_over_mu": ratio,
            "angle_deg": math.degrees(math.atan(tan)),
            "psi": psi,
            "law_a": float(beta_of_psi([psi], NU, model=MODELS[0])[0]),
            "law_b": float(beta_of_psi([psi], NU, model=MODELS[1])[0]),
            "modal": {},
        }
        for n, body in bodies.items():
            start = time.perf_counter()
            r = oblique_collision(body, v, v * tan, MU, alpha)
            row["modal"][str(n)] = {
                "epsilon_normal": r.epsilon_normal,
                "beta": r.beta,
                "spin_after": r.spin,
                "energy_balance": r.energy_balance,
                "phases": len(r.phases),
                "wall_time_s": time.perf_counter() - start,
            }
            print(f"tan/mu {ratio}: {n} modes beta {r.beta:.4f} "
                  f"e_n {r.epsilon_normal:.6f} ({time.perf_counter() - start:.0f} s)",
                  flush=True)  # fmt: skip
        rows.append(row)
    data = {
        "what": __doc__.splitlines()[0],
        "settings": {
            "nu": NU,
            "speed_m_s": SPEED_M_S,
            "c_m_s": C_M_S,
            "v": v,
            "alpha": alpha,
            "mu": MU,
            "chi": chi,
            "modes": list(MODES),
            "rtol": 1e-10,
        },  # fmt: skip
        "rows": rows,
        "code_version": code_version("sphere"),
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "machine": f"{platform.machine()}, {platform.python_version()}",
        "command": "tools/ball_oblique_modes.py",
    }
    atomic.write_text(out, json.dumps(data, indent=1) + "\n")
    print("| tan/mu | angle | psi | " + " | ".join(f"{n} modes" for n in MODES)
          + " | law (a) | law (b) |")  # fmt: skip
    for row in rows:
        modal = " | ".join(f"{row['modal'][str(n)]['beta']:+.3f}" for n in MODES)
        print(f"| {row['tan_over_mu']} | {row['angle_deg']:.1f} | {row['psi']:.3f} | {modal} | "
              f"{row['law_a']:+.3f} | {row['law_b']:+.3f} |")  # fmt: skip


if __name__ == "__main__":
    main()
