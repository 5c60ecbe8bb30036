"""Benchmark: a law through the static residual against today's production (issue 46).

Three parts, one run; the load average is printed at the start and the end (the machine should
be otherwise idle).

1. **Values against the shipped law** (a body on the wall; skipped with ``--skip-values`` and
   for a pair, which has no shipped law of equal radii and two materials). Every modal speed of
   the shipped law is computed again by the residual route
   (:func:`restitution.limits.residual_point.residual_point`: 200, 400 and 800 kept modes, the
   law's walls, the hard-wall limit) on ``--workers`` processes. Prints each point beside the
   shipped one, the difference in combined errors (``sigma``), the largest ``|sigma|``, the
   ratio of the two routes' errors and the time of the set.
2. **Times side by side, alternating, and values at those speeds.** For ``--pairs`` pairs of
   the production's speeds, today's production of the two speeds
   (:func:`restitution.limits.curves.compute_curves` on the production's own sweep settings, a
   fresh store, ``--workers`` Dask workers) and the residual route of the same two speeds
   (``--workers`` processes) run one after the other, baseline first in even pairs, residual
   first in odd ones. Prints each speed's two values and their difference in combined errors,
   the min, median and max of the per-pair time ratio, and today's full time estimated from the
   pairs' mean per speed (an estimate: said so).
3. **Both productions, whole** (``--full``): today's
   (:func:`restitution.laws.making.production.build` with the production's groups and its
   refining round, a fresh store) and the residual one
   (:func:`restitution.laws.making.residual_law.residual_law` of every production speed with its
   refining round, from nothing kept), one after the other on ``--workers`` workers, timed;
   then the largest difference in combined errors at the speeds both computed. The low-speed
   points are left out of both: both join the same ones (their cost, from the kind's plan, is
   printed beside).

``--pair`` takes the pair of two disks of two materials of the issue's target: a steel
cylinder with a glass one of its size (the shipped two-material pair's constants at
``R2/R1 = 1``).

    python benchmarks/bench_residual_law.py [--geometry sphere] [--nu 0.3] [--pair]
        [--workers 2] [--pairs 2] [--skip-values] [--full]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import statistics
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from restitution._paths import cache_root
from restitution.laws.law_load import law
from restitution.laws.low_speed import low_speeds_of
from restitution.laws.making.compute import production_groups, seconds_per_low_point
from restitution.laws.making.production import _steel_glass
from restitution.laws.making.residual_law import residual_filename, residual_law, residual_speeds
from restitution.limits.curves import compute_curves
from restitution.limits.residual_point import residual_point
from restitution.limits.run_options import Executor


def _point(args):
    geometry, nu, v, partner = args
    return residual_point(geometry, nu, v, partner=partner)


def _residual(geometry, nu, speeds, workers, partner):
    start = time.perf_counter()
    with ProcessPoolExecutor(workers) as pool:
        points = list(pool.map(_point, [(geometry, nu, v, partner) for v in speeds]))
    return points, time.perf_counter() - start


def _baseline(geometry, nu, speeds, workers, partner):
    groups = production_groups(geometry, partner)
    values = []
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        for v in speeds:
            group = next(g for g in groups if v in g.velocities)
            curves = compute_curves([nu], dataclasses.replace(group, velocities=(v,)),
                                    store=os.path.join(folder, "store.sqlite"),
                                    executor=Executor(workers=workers))  # fmt: skip
            curve = curves[float(nu)]
            values.append((float(curve.epsilon[0]), float(curve.epsilon_err[0])))
    return values, time.perf_counter() - start


def _sigma(a, a_err, b, b_err) -> float:
    return (b - a) / math.hypot(a_err, b_err)


def _values(args, partner) -> None:
    shipped = law(args.nu, geometry=args.geometry)
    modal = [p for p in shipped.metadata["points"]
             if p.get("route") in (None, "modal")]  # fmt: skip
    print(f"{args.geometry}, nu = {args.nu}: {len(modal)} modal speeds in the shipped law")
    points, seconds = _residual(args.geometry, args.nu, [p["v"] for p in modal], args.workers,
                                partner)  # fmt: skip
    worst, ratios = 0.0, []
    print("       v   shipped eps +- err          residual eps +- err       sigma")
    for old, new in zip(modal, points, strict=True):
        sigma = _sigma(old["epsilon"], old["epsilon_err"], new.epsilon, new.epsilon_err)
        worst = max(worst, abs(sigma))
        ratios.append(new.epsilon_err / old["epsilon_err"])
        print(f"{old['v']:8.5f}  {old['epsilon']:.7f} +- {old['epsilon_err']:.1e} "
              f"({old['status']:>14s})  {new.epsilon:.7f} +- {new.epsilon_err:.1e}  "
              f"{sigma:+.2f}", flush=True)  # fmt: skip
    print(f"residual route: {len(points)} speeds in {seconds:.1f} s on {args.workers} "
          f"processes; largest |sigma| {worst:.2f}; error ratio residual / shipped: min "
          f"{min(ratios):.2f}, median {statistics.median(ratios):.2f}, max "
          f"{max(ratios):.2f}")  # fmt: skip


def _alternating(args, partner) -> None:
    planned = residual_speeds(args.geometry, partner)
    step = max(1, len(planned) // (2 * max(args.pairs, 1)))
    sample = planned[::step][: 2 * args.pairs]
    ratios, per_speed, worst = [], [], 0.0
    for k in range(0, len(sample) - 1, 2):
        speeds = sample[k : k + 2]
        order = ("baseline", "residual") if (k // 2) % 2 == 0 else ("residual", "baseline")
        times, values = {}, {}
        for name in order:
            run = _baseline if name == "baseline" else _residual
            values[name], times[name] = run(args.geometry, args.nu, speeds, args.workers,
                                            partner)  # fmt: skip
        for v, (eps, err), new in zip(speeds, values["baseline"], values["residual"],
                                      strict=True):  # fmt: skip
            sigma = _sigma(eps, err, new.epsilon, new.epsilon_err)
            worst = max(worst, abs(sigma))
            print(f"  v = {v:g}: today {eps:.7f} +- {err:.1e}, residual {new.epsilon:.7f} +- "
                  f"{new.epsilon_err:.1e}, {sigma:+.2f} combined errors")  # fmt: skip
        ratios.append(times["baseline"] / times["residual"])
        per_speed.append(times["baseline"] / len(speeds))
        print(f"speeds {speeds}: today's production {times['baseline']:.1f} s, residual "
              f"{times['residual']:.1f} s, ratio {ratios[-1]:.2f}", flush=True)  # fmt: skip
    if ratios:
        print(f"ratio today / residual over {len(ratios)} pairs: min {min(ratios):.2f}, median "
              f"{statistics.median(ratios):.2f}, max {max(ratios):.2f}; largest |sigma| at "
              f"these speeds {worst:.2f}; today's {len(planned)} speeds estimated at "
              f"{statistics.mean(per_speed) * len(planned) / 60:.1f} min on {args.workers} "
              f"workers (from the pairs' mean per speed: an estimate, not measured; no "
              f"refining points)")  # fmt: skip


def _whole_residual(args, partner, folder):
    name = residual_filename(args.nu, args.geometry, partner)
    (cache_root() / "residual_points" / name).unlink(missing_ok=True)  # from nothing kept
    return residual_law(args.nu, args.geometry, partner, out_dir=folder, low_speeds=(),
                        executor=Executor(workers=args.workers), force=True)  # fmt: skip


def _whole_baseline(args, partner, folder):
    from restitution.laws.making.production import build

    (path,) = build(folder, [args.nu], production_groups(args.geometry, partner),
                    store=os.path.join(folder, "store.sqlite"), low_speeds=(),
                    executor=Executor(workers=args.workers))  # fmt: skip
    return path


def _full(args, partner) -> None:
    """Both productions whole (no low-speed points), today's first; each law's points against
    the other's at the speeds both computed."""
    laws, seconds = {}, {}
    for name, run in (("today", _whole_baseline), ("residual", _whole_residual)):
        with tempfile.TemporaryDirectory() as folder:
            start = time.perf_counter()
            path = run(args, partner, folder)
            seconds[name] = time.perf_counter() - start
            laws[name] = json.loads(Path(path).read_text())["metadata"]["points"]
        print(f"{name}'s production, whole: {len(laws[name])} speeds in "
              f"{seconds[name] / 60:.2f} min on {args.workers} workers", flush=True)  # fmt: skip
    today = {p["v"]: p for p in laws["today"]}
    sigmas = [_sigma(today[p["v"]]["epsilon"], today[p["v"]]["epsilon_err"], p["epsilon"],
                     p["epsilon_err"]) for p in laws["residual"] if p["v"] in today]  # fmt: skip
    low = low_speeds_of(args.geometry, partner, args.nu)
    low_s = len(low) * seconds_per_low_point(args.geometry, partner)
    print(f"whole productions: today {seconds['today'] / 60:.2f} min, residual "
          f"{seconds['residual'] / 60:.2f} min, ratio {seconds['today'] / seconds['residual']:.2f}"
          f"; at the {len(sigmas)} speeds both computed the largest |sigma| is "
          f"{max(map(abs, sigmas)):.2f}; the {len(low)} low-speed points both join: about "
          f"{low_s / 60:.1f} min on one core (the kind's plan), in neither time")  # fmt: skip


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--geometry", default="sphere")
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--pair", action="store_true", help="steel and glass disks, R2 = R1")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--pairs", type=int, default=2)
    parser.add_argument("--skip-values", action="store_true")
    parser.add_argument("--full", action="store_true")
    args = parser.parse_args(argv)
    partner = None
    if args.pair:
        args.geometry = "disk"
        args.nu, partner = _steel_glass("cylinder", 1.0)  # the shipped pair's materials
    print(f"load average at start: {os.getloadavg()}", flush=True)
    if not args.skip_values and partner is None:
        _values(args, partner)
    _alternating(args, partner)
    if args.full:
        _full(args, partner)
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
