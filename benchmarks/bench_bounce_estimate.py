"""Benchmark: the time of a ``bounce`` sequence against its estimate, before and after issue 47.

``restitution bounce`` refuses, before any work, a sequence estimated to take longer than the
one-hour bound (:func:`restitution.vibrating.sequences.check_bounce_time`). The audit found
that estimate 3.5-7.5 times optimistic: it counted every collision as the first one from rest,
while the later ones start vibrating and refine their steps. This script runs sequences of 8
collisions on a grid (N = 10, 40, 160, 640; v = 0.01, 0.1; alpha = 500, 2000; under gravity
1e-4 and between walls 2.5 apart; nu = 0.33), counts every step the integrator takes (every
run of every refinement), and prints, per sequence and as min / median / max:

* counted steps over the first collision's estimated steps times the collisions (what
  :data:`restitution.vibrating.sequences.SEQUENCE_STEPS` covers);
* measured seconds over the old estimate (``work = 1``, the baseline) and over the new one;
* measured seconds per counted step against :func:`restitution.budget.collision_seconds`.

The load average is printed at the start and the end. Run: python
benchmarks/bench_bounce_estimate.py [--collisions 8]
"""

from __future__ import annotations

import argparse
import itertools
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

import restitution.dynamics.collision as collision  # noqa: E402
import restitution.vibrating.sequences as sequences  # noqa: E402
from restitution.bodies.cache import get_modes  # noqa: E402
from restitution.bodies.material import Material  # noqa: E402
from restitution.budget import collision_seconds  # noqa: E402
from restitution.dynamics.collision import CollisionSettings  # noqa: E402
from restitution.dynamics.steps import estimate_work  # noqa: E402


def counting_runs() -> list[int]:
    """Wrap the integrator's two runners so that every step they take is counted."""
    counted = [0]
    for name in ("run_kernel", "run_numpy"):
        original = getattr(collision, name)

        def run(*args, _original=original, **kwargs):
            got = _original(*args, **kwargs)
            counted[0] += sum(getattr(member, "steps", 0) for member in got)
            return got

        setattr(collision, name, run)
    return counted


def _summary(values) -> str:
    a = np.asarray(values)
    return f"{a.min():.2f} / {np.median(a):.2f} / {a.max():.2f}"


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--collisions", type=int, default=8)
    args = parser.parse_args()
    counted = counting_runs()
    print(f"load average at start: {os.getloadavg()}")
    sequences.bounce(get_modes(Material(nu=0.33), count=40), 0.1, 500, 2, gravity=1e-4)  # warm
    rows = []
    grid = itertools.product([10, 40, 160, 640], [0.01, 0.1], [500.0, 2000.0],
                             [{"gravity": 1e-4}, {"walls_distance": 2.5}])  # fmt: skip
    for n, v, alpha, flight in grid:
        modes = get_modes(Material(nu=0.33), count=n)
        first = estimate_work(modes, np.array([v]), np.array([alpha]), CollisionSettings()).steps
        k = args.collisions
        new = sequences.check_bounce_time(modes, v, alpha, k, force=True)
        old = collision_seconds(first, n) * k
        counted[0] = 0
        t = time.perf_counter()
        sequences.bounce(modes, v, alpha, k, force=True, **flight)
        t = time.perf_counter() - t
        row = (counted[0] / (first * k), t / old, t / new, t / counted[0] / collision_seconds(1, n))
        rows.append(row)
        print(f"N={n:4d} v={v:<5} alpha={alpha:<6g} {next(iter(flight)):14s} steps/estimate "
              f"{row[0]:5.2f}  time/old {row[1]:5.2f}  time/new {row[2]:5.2f}  "
              f"s per step/model {row[3]:4.2f}", flush=True)  # fmt: skip
    a = np.array(rows)
    print(f"counted steps / first collision's estimate (min / median / max): {_summary(a[:, 0])}"
          f" (SEQUENCE_STEPS = {sequences.SEQUENCE_STEPS})")  # fmt: skip
    print(f"measured / old estimate: {_summary(a[:, 1])}")
    print(f"measured / new estimate: {_summary(a[:, 2])}")
    print(f"seconds per counted step / collision_seconds model: {_summary(a[:, 3])}")
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
