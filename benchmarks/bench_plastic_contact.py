"""How far the plugin's plastic law per contact lies from the package's direct answers, at random
contacts between the knots (docs/lammps-plugin.md, "The interpolation error").

Two measurements, seeds fixed:

1. the wave ratio ``r(x, u)`` of :mod:`restitution.laws.exports.plastic_waves` at random points
   between its knots (``u`` log-uniform up to the table's top, ``x`` uniform where ``u x^5 <=
   1e9``, the region of steel of yield stress 1 GPa and about five times softer) against
   :func:`~restitution.laws.exports.plastic_waves.exact_ratio` (the two pulses' spectra at the
   sphere's modes, as the package's plastic law computes them);
2. epsilon per contact of steel (yield stress 1 GPa) against ``plastic_law(...).points`` of the
   package: random speeds log-uniform in 0.04 ... 30 m/s, a grain of random radius on the wall
   and pairs of the shipped ratios 1, 1.5, 2 of random radii; the miss in units of the
   package's error of that point.

Run: ``PYTHONPATH=src .venv/bin/python benchmarks/bench_plastic_contact.py [N]`` (N contacts of
each kind, default 12; a few minutes, the package's plastic points computing their pulses).
"""

from __future__ import annotations

import math
import sys

import numpy as np

import restitution
from restitution.laws.exports import plastic_waves as pw
from restitution.laws.exports.contact_law import pair_contact_law, wall_contact_law
from restitution.laws.exports.lammps_plugin import contact_modulus
from restitution.laws.plastic import plastic_law
from restitution.laws.units import Grain

STEEL = Grain(210e9, 0.3, 7850.0, "sphere")
YIELD = 1e9


def mass(r):
    return 4.0 / 3.0 * math.pi * r**3 * STEEL.rho


def ratio_misses(n: int, rng) -> None:
    waves = pw.plastic_waves(STEEL.nu)
    worst = (0.0, None)
    for _ in range(n):
        u = math.cosh(rng.uniform(0.0, waves.eta[-1]))
        top = min(waves.x[-1], (1e9 / u) ** 0.2)
        if top <= waves.x[0]:
            continue
        x = rng.uniform(waves.x[0], top)
        got, want = waves(x, u), pw.exact_ratio(STEEL.nu, x, u)
        miss = abs(got - want)
        print(f"r: x = {x:7.3f}, u = {u:9.3f}: table {got:.8f}, direct {want:.8f}, miss {miss:.2e}"
              f" ({miss / max(abs(want - 1.0), 1e-300):.2e} of |r - 1|)")  # fmt: skip
        if miss > worst[0]:
            worst = (miss, (x, u, want))
    print(f"largest miss of r: {worst[0]:.3e} at (x, u, r) = {worst[1]}")


def epsilon_misses(n: int, rng) -> None:
    pair = pair_contact_law(STEEL, yield_stress_pa=YIELD)
    wall = wall_contact_law(STEEL, yield_stress_pa=YIELD)
    e_pair = contact_modulus(STEEL.E, STEEL.nu, STEEL.E, STEEL.nu)
    e_wall = contact_modulus(STEEL.E, STEEL.nu)
    laws = {
        "wall": restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "wall"),
        1.0: restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain"),
        1.5: restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain", radius_ratio=1.5),
        2.0: restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain", radius_ratio=2.0),
    }
    worst = (0.0, None)
    for kind, si in laws.items():
        speeds = 10 ** rng.uniform(math.log10(0.04), math.log10(30.0), n)
        radii = 10 ** rng.uniform(-3.3, -2.7, n)
        law = plastic_law(si, yield_stress_pa=YIELD)
        for w, r, p in zip(speeds, radii, law.points(speeds), strict=True):
            if kind == "wall":
                got = wall(w, r, mass(r), e_wall)
            else:
                got = pair(w, r, mass(r), kind * r, mass(kind * r), e_pair)
            if got.epsilon is None or p.epsilon is None:
                print(f"{kind}, {w:.4g} m/s, R1 = {r:.3g} m: no answer ({got.note or p.note})")
                continue
            share = abs(got.epsilon - p.epsilon) / p.epsilon_err
            print(f"{kind}, {w:.4g} m/s, R1 = {r:.3g} m, u = {got.speed_over_yield:.4g}: "
                  f"{got.epsilon:.10f}, package {p.epsilon:.10f} +- {p.epsilon_err:.2e}: "
                  f"{share:.2e} of its error")  # fmt: skip
            if share > worst[0]:
                worst = (share, (kind, w, r))
    print(f"largest miss of epsilon: {worst[0]:.3e} of the package's error at {worst[1]}")


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 12
    rng = np.random.default_rng(2026)
    ratio_misses(2 * count, rng)
    epsilon_misses(count, rng)
