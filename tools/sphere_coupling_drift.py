"""The residual route's drift in the modes against Dundurs' coupling (issue 63; docs/oblique.md,
"Dundurs' coupling: the residual route's drift explained").

For a Poisson number, a speed and an angle (the steel ball's scale: ``v = 1.9334e-4 c`` per m/s,
``mu = 0.3``, one wall ``alpha = 80 / delta_max``), prints the one-state quasistatic twin on the
finite sphere without the coupling, with the continuum's (rigid wall and the route's wall), and
for each mode count the residual route's ``beta``
(:func:`restitution.dynamics.oblique_residual.residual_collision`, one wall) beside the twin
with the kept modes' share of the coupling alone
(:func:`restitution.bodies.sphere.contact_compliance.modal_annulus_tilt_flexibility`, what the
route holds, its residual having none), and the route corrected by the twin's missing share.

Usage (from the project's root, with its venv; 1-4 min on one core)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_coupling_drift.py \\
        --nu 0.3 --speed 1 --angle 30 20 40 80
"""

from __future__ import annotations

import argparse
import math
import time

from restitution.bodies.cache import get_modes
from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.contact_compliance import modal_annulus_tilt_flexibility
from restitution.dynamics.oblique_residual import residual_collision
from restitution.quasistatic import sphere_partial_slip as sps
from restitution.quasistatic.sphere_coupling import coupled_one_state_run
from restitution.quasistatic.sphere_one_state import one_state_run

C_PER_M_S = 1.9334154333963606e-4  # 1 m/s in c for steel (E 210 GPa, rho 7850 kg/m^3)
MU = 0.3
STEPS = 4000


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("modes", nargs="+", type=int)
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--speed", type=float, default=1.0, help="normal speed, m/s of steel")
    parser.add_argument("--angle", type=float, default=30.0, help="degrees from the normal")
    a = parser.parse_args()
    v = C_PER_M_S * a.speed
    vt = v * math.tan(math.radians(a.angle))
    alpha = 80.0 / sps.hertz_peak(v, a.nu)
    reach = sps.REACH * math.sqrt(sps.hertz_peak(v, a.nu))
    contact = sps.AnnularContact.build(reach, a.nu, annuli=40)
    free = one_state_run(contact, v, vt, MU, a.nu, STEPS)[0]
    rigid = coupled_one_state_run(contact, v, vt, MU, a.nu, STEPS)[0]
    wall = coupled_one_state_run(contact, v, vt, MU, a.nu, STEPS, alpha=alpha)[0]
    print(f"nu {a.nu}, {a.speed} m/s, {a.angle} deg, mu {MU}, alpha {alpha:.1f}: twin "
          f"{free:.5f} uncoupled, {rigid:.5f} coupled (rigid wall), "
          f"{wall:.5f} (this wall)")  # fmt: skip
    for n in a.modes:
        cap = cap_modes(get_modes(a.nu, count=n, geometry="sphere"), azimuthal=1)
        kept = coupled_one_state_run(
            contact, v, vt, MU, a.nu, STEPS, alpha=alpha,
            flexibility=lambda edges, cap=cap: modal_annulus_tilt_flexibility(cap, edges),
        )[0]  # fmt: skip
        start = time.perf_counter()
        out = residual_collision(cap, v, vt, MU, alpha)
        print(f"{n:4d} modes: route {out.beta:.5f}, twin with the kept share {kept:.5f}, "
              f"route corrected {out.beta + wall - kept:.5f}, epsilon_normal "
              f"{out.epsilon_normal:.7f} ({time.perf_counter() - start:.0f} s)",
              flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
