"""Benchmark: the full Fig. 1 grid from a cold (temporary) result store.

Both Poisson numbers (0.33, 0.9) x the paper's velocities x the default alpha and N sets of
:data:`restitution.limits.sweep.DEFAULTS`, on local processes (all cores) unless ``--workers`` or
``--scheduler`` says otherwise. Prints the total time, collisions per second, and epsilon at
every speed. The budget of the issue is 10 minutes on a 2-core machine.

With ``--backends R`` it instead times the same grid R times with the NumPy reference path
and with the compiled kernel, alternating, each from its own cold store, and prints the
ratio per round and its min/median/max (the production time before and after the kernel).

    python benchmarks/bench_curve.py [--quick] [--workers N | --scheduler ADDRESS]
    python benchmarks/bench_curve.py --backends 3
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from restitution.limits.curves import compute_curves
from restitution.limits.store import Store
from restitution.limits.sweep import DEFAULTS

BUDGET_S = 600.0


def numpy_points(specs):
    """Sweep task on the NumPy reference path (the production path before the kernel)."""
    from restitution.bodies.cache import get_modes
    from restitution.dynamics.collision import CollisionSettings, collide_batch

    first = specs[0]
    settings = CollisionSettings(
        integrator=first.integrator, backend="numpy", **dict(first.options)
    )
    modes = get_modes(first.nu, count=first.n_modes)
    results = collide_batch(modes, [s.v for s in specs], [s.alpha for s in specs], settings)
    return [("ok", r.to_dict()) for r in results]


def _timed_grid(nus, settings, batch_function=None) -> float:
    kwargs = {} if batch_function is None else {"batch_function": batch_function}
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        compute_curves(nus, settings, store=Path(tmp) / "b.sqlite", progress=False, **kwargs)
        return time.perf_counter() - t0


def compare_backends(nus, settings, rounds: int) -> None:
    """Alternating rounds: NumPy path, then compiled kernel, each from a cold store."""
    ratios = []
    for i in range(rounds):
        t_numpy = _timed_grid(nus, settings, numpy_points)
        t_kernel = _timed_grid(nus, settings)
        ratios.append(t_numpy / t_kernel)
        one, five, _ = os.getloadavg()
        print(
            f"round {i + 1}: numpy path {t_numpy:.1f} s, compiled kernel {t_kernel:.1f} s, "
            f"ratio {ratios[-1]:.2f}x (load {one:.2f} / {five:.2f})",
            flush=True,
        )
    print(
        f"numpy / compiled: min {min(ratios):.2f}x median {statistics.median(ratios):.2f}x "
        f"max {max(ratios):.2f}x over {rounds} rounds"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a small grid (smoke test)")
    parser.add_argument("--workers", type=int, default=None, help="Dask LocalCluster workers")
    parser.add_argument("--scheduler", default=None, help="Dask scheduler address")
    parser.add_argument("--backends", type=int, default=0, help="rounds of numpy vs compiled")
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
    if args.backends:
        compare_backends(nus, settings, args.backends)
        return
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
