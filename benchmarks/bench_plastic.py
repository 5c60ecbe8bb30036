"""Benchmark: the time of one speed of a plastic answer against its estimate and the elastic law.

``restitution law --yield-stress`` refuses, before any work, a request whose speeds would take
longer than the one-hour bound of a run, at
:data:`restitution.laws.serve.PLASTIC_SECONDS_PER_SPEED` a speed (issue 47: estimates checked
against measurement). This script measures what one speed costs (steel on a rigid wall, Y = 1
GPa, with and without damping, speeds from 1 mm/s to 100 m/s), in alternating rounds with the
elastic law's points at the same speeds (the baseline: what the answer costs without plastic
flow), and prints min / median / max per speed, the ratio to the estimate, and the load.

Run: python benchmarks/bench_plastic.py [--rounds 3] [--speeds 8]
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution.laws.plastic import plastic_law  # noqa: E402
from restitution.laws.serve import PLASTIC_SECONDS_PER_SPEED  # noqa: E402
from restitution.laws.si_law import si_law  # noqa: E402


def _per_speed(run, speeds) -> float:
    t = time.perf_counter()
    run(speeds)
    return (time.perf_counter() - t) / len(speeds)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--speeds", type=int, default=8)
    args = parser.parse_args()
    steel = si_law(210e9, 0.3, 7850, "sphere", "wall")
    elastic = steel.points
    plastic = plastic_law(steel, yield_stress_pa=1e9).points
    damped = plastic_law(steel, yield_stress_pa=1e9, tau=0.01).points
    # Fresh speeds every round, so no cached low-speed point is reused.
    rng = np.random.default_rng(1)
    rows = {"elastic law (baseline)": [], "plastic": [], "plastic + damping": []}
    for _ in range(args.rounds):
        speeds = list(np.sort(10.0 ** rng.uniform(-3.0, 2.0, args.speeds)))
        for name, run in zip(rows, (elastic, plastic, damped), strict=True):
            rows[name].append(_per_speed(run, speeds))
    load = os.getloadavg()[0]
    print(f"load average at the end: {load:.2f} (2 cores)")
    print(f"estimate of a plastic speed: {PLASTIC_SECONDS_PER_SPEED:g} s")
    for name, times in rows.items():
        t = np.array(times)
        ratio = t / PLASTIC_SECONDS_PER_SPEED
        print(
            f"{name:24s} s/speed min {t.min():.3f}  median {np.median(t):.3f}  max {t.max():.3f}"
            f"   measured / estimate: {ratio.min():.2f} / {np.median(ratio):.2f} /"
            f" {ratio.max():.2f}"
        )


if __name__ == "__main__":
    main()
