"""Benchmark: the stiffness scan of the LAMMPS history-model fits, one array pass against one call
per stiffness (the baseline, before stop 78).

:func:`restitution.laws.oblique_fits.fit_history` scans ``scan`` stiffnesses ``chi`` before it
refines its best; :func:`restitution.laws.tangential_models.history_beta` now takes them all as
one array (one row per ``chi``, the normal motion stepped once). This script times, alternating,
the scan of 41 stiffnesses (``fit_history``'s default) at 8 angles and 4000 steps both ways for
``mindlin`` and ``linear_history``, checks the two agree, and prints the ratio baseline / array
as min / median / max over the repetitions, with the load average at the start and the end.
Run: python benchmarks/bench_history_scan.py [--repeats 5]
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution.laws.tangential_models import history_beta  # noqa: E402

ANGLES = np.radians([10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0])
MU = 0.3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--scan", type=int, default=41)
    parser.add_argument("--steps", type=int, default=4000)
    args = parser.parse_args()
    X = np.tan(ANGLES) / MU
    grid = np.geomspace(0.05, 5.0, args.scan)
    print(f"load average at start: {os.getloadavg()}")
    for model in ("mindlin", "linear_history"):
        ratios, base_t, new_t = [], [], []
        for _ in range(args.repeats):
            t = time.perf_counter()
            each = np.array([history_beta(X, c, model, steps=args.steps) for c in grid])
            base = time.perf_counter() - t
            t = time.perf_counter()
            rows = history_beta(X, grid, model, steps=args.steps)
            new = time.perf_counter() - t
            assert np.max(np.abs(rows - each)) <= 1e-15
            ratios.append(base / new)
            base_t.append(base)
            new_t.append(new)
        r = np.asarray(ratios)
        print(f"{model}: {args.scan} stiffnesses x {X.size} angles, {args.steps} steps: per-chi "
              f"calls {np.median(base_t):.3f} s, one array pass {np.median(new_t):.3f} s "
              f"(medians); ratio min / median / max {r.min():.1f} / {np.median(r):.1f} / "
              f"{r.max():.1f} over {args.repeats} alternating runs")  # fmt: skip
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
