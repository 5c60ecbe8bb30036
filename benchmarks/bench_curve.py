"""Benchmark: the full Fig. 1 grid from a cold (temporary) result store.

Both Poisson numbers (0.33, 0.9) x the paper's velocities x the default alpha and N sets of
:data:`restitution.sweep.DEFAULTS`, on local processes (all cores) unless ``--workers`` or
``--scheduler`` says otherwise. Prints the total time, collisions per second, and epsilon at
every speed. The budget of the issue is 10 minutes on a 2-core machine.

    python benchmarks/bench_curve.py [--quick] [--workers N | --scheduler ADDRESS]
"""

from __future__ import annotations

import argparse
import math
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from restitution.curves import compute_curves
from restitution.store import Store
from restitution.sweep import DEFAULTS

BUDGET_S = 600.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a small grid (smoke test)")
    parser.add_argument("--workers", type=int, default=None, help="Dask LocalCluster workers")
    parser.add_argument("--scheduler", default=None, help="Dask scheduler address")
    args = parser.parse_args()
    settings = DEFAULTS
    if args.quick:
        settings = replace(
            DEFAULTS, velocities=(0.05, 0.2), alphas=(20.0, 30.0, 40.0), n_modes=(10, 14, 20)
        )
    nus = (0.33, 0.9)
    n = len(nus) * len(settings.velocities) * len(settings.alphas) * len(settings.n_modes)
    print(
        f"grid: nu {nus} x {len(settings.velocities)} v x alpha {settings.alphas} "
        f"x N {settings.n_modes} = {n} collisions ({settings.integrator}, "
        f"batch {settings.batch_size})"
    )
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.sqlite"
        t0 = time.perf_counter()
        curves = compute_curves(
            nus, settings, store=path, workers=args.workers, scheduler=args.scheduler
        )
        total = time.perf_counter() - t0
        with Store(path) as db:
            rows = list(db)
    failed = sum(not r.ok for r in rows)
    cpu = sum(r.wall_time_s for r in rows if r.ok and math.isfinite(r.wall_time_s))
    print(f"total time {total:.1f} s for {len(rows)} collisions ({failed} failed)")
    print(f"collisions per second: {len(rows) / total:.3f}")
    print(f"solver time summed over workers: {cpu:.1f} s")
    verdict = "within" if total <= BUDGET_S else "OVER"
    print(f"{verdict} the {BUDGET_S:.0f} s budget of the full grid" if not args.quick else "")
    for nu, curve in curves.items():
        print(f"nu = {nu:g}:   v/c   epsilon +- error   asymptotic")
        for v, c in zip(curve.velocities, curve.limits, strict=True):
            flag = "yes" if c.asymptotic_ok else "no: " + c.message[:80]
            print(f"        {v:6.3f}  {c.epsilon:.5f} +- {c.epsilon_err:.5f}   {flag}")


if __name__ == "__main__":
    main()
