"""Benchmark: a law through the static residual against today's production (issue 46).

Two parts, one run:

1. **Values and the residual route's full time.** Every modal speed of the shipped law
   (``law_<body>_nu<nu>.json``: its points from the modal production, not the low-speed route)
   is computed again by the residual route (:func:`restitution.limits.residual_point.
   residual_point`: 400 and 800 kept modes, the law's three walls, the hard-wall limit) on
   ``--workers`` processes. Prints each point beside the shipped one, the difference in combined
   errors (``sigma``), the largest ``|sigma|`` and the ratio of the two routes' errors, and the
   wall-clock time of the whole set.
2. **Times side by side, alternating.** For ``--pairs`` pairs of the production's speeds, today's
   production of those two speeds (:func:`restitution.limits.curves.compute_curves` on the
   law's own sweep settings, a fresh store, ``--workers`` Dask workers) and the residual route
   of the same two speeds (``--workers`` processes) run one after the other, baseline first in
   even pairs, residual first in odd ones. Prints min, median and max of the per-pair ratio,
   and today's full time estimated from the pairs' mean per speed (an estimate: say so).

The load average is printed at the start and the end; the machine should be otherwise idle.

    python benchmarks/bench_residual_law.py [--geometry sphere] [--nu 0.3] [--workers 2]
        [--pairs 2] [--skip-values]
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import statistics
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor

from restitution.laws.law import law
from restitution.laws.production import production_groups
from restitution.limits.curves import compute_curves
from restitution.limits.residual_point import residual_point
from restitution.limits.run_options import Executor


def _point(args):
    geometry, nu, v = args
    return residual_point(geometry, nu, v)


def _residual(geometry, nu, speeds, workers):
    start = time.perf_counter()
    with ProcessPoolExecutor(workers) as pool:
        points = list(pool.map(_point, [(geometry, nu, v) for v in speeds]))
    return points, time.perf_counter() - start


def _baseline(geometry, nu, speeds, workers):
    groups = production_groups(geometry)
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        for v in speeds:
            group = next(g for g in groups if v in g.velocities)
            compute_curves([nu], dataclasses.replace(group, velocities=(v,)),
                           store=os.path.join(folder, "store.sqlite"),
                           executor=Executor(workers=workers))  # fmt: skip
    return time.perf_counter() - start


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--geometry", default="sphere")
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--pairs", type=int, default=2)
    parser.add_argument("--skip-values", action="store_true")
    args = parser.parse_args(argv)
    print(f"load average at start: {os.getloadavg()}", flush=True)
    shipped = law(args.nu, geometry=args.geometry)
    meta = shipped.metadata
    modal = [p for p in meta["points"] if p.get("route", "modal") != "quasistatic"
             and p.get("status") != "quasistatic"]  # fmt: skip
    print(f"{args.geometry}, nu = {args.nu}: {len(modal)} modal speeds in the shipped law")
    if not args.skip_values:
        points, seconds = _residual(args.geometry, args.nu, [p["v"] for p in modal], args.workers)
        worst, ratios = 0.0, []
        print("       v   shipped eps +- err          residual eps +- err       sigma")
        for old, new in zip(modal, points, strict=True):
            comb = math.hypot(old["epsilon_err"], new.epsilon_err)
            sigma = (new.epsilon - old["epsilon"]) / comb
            worst = max(worst, abs(sigma))
            ratios.append(new.epsilon_err / old["epsilon_err"])
            print(f"{old['v']:8.5f}  {old['epsilon']:.7f} +- {old['epsilon_err']:.1e} "
                  f"({old['status']:>14s})  {new.epsilon:.7f} +- {new.epsilon_err:.1e}  "
                  f"{sigma:+.2f}", flush=True)  # fmt: skip
        print(f"residual route: {len(points)} speeds in {seconds:.1f} s on {args.workers} "
              f"processes; largest |sigma| {worst:.2f}; error ratio residual / shipped: min "
              f"{min(ratios):.2f}, median {statistics.median(ratios):.2f}, max "
              f"{max(ratios):.2f}")  # fmt: skip
    planned = [v for g in production_groups(args.geometry) for v in g.velocities]
    step = max(1, len(planned) // (2 * max(args.pairs, 1)))
    sample = planned[::step][: 2 * args.pairs]
    ratios, per_speed = [], []
    for k in range(0, len(sample) - 1, 2):
        speeds = sample[k : k + 2]
        order = ("baseline", "residual") if (k // 2) % 2 == 0 else ("residual", "baseline")
        times = {}
        for name in order:
            if name == "baseline":
                times[name] = _baseline(args.geometry, args.nu, speeds, args.workers)
            else:
                times[name] = _residual(args.geometry, args.nu, speeds, args.workers)[1]
        ratios.append(times["baseline"] / times["residual"])
        per_speed.append(times["baseline"] / len(speeds))
        print(f"speeds {speeds}: today's production {times['baseline']:.1f} s, residual "
              f"{times['residual']:.1f} s, ratio {ratios[-1]:.1f}", flush=True)  # fmt: skip
    if ratios:
        print(f"ratio today / residual over {len(ratios)} pairs: min {min(ratios):.1f}, median "
              f"{statistics.median(ratios):.1f}, max {max(ratios):.1f}; today's full set "
              f"estimated at {statistics.mean(per_speed) * len(planned) / 60:.0f} min for "
              f"{len(planned)} speeds (estimate from the pairs, not measured)")  # fmt: skip
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
