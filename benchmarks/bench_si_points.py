"""Benchmark: serving many speeds of an SI law (``SILaw.points``), against the code before issue
47's fixes: every speed evaluated alone, building the law's PCHIP interpolants at every call.

Baseline: the same law with its two cached interpolants bypassed, so that every evaluation
builds ``scipy.interpolate.PchipInterpolator`` anew, as ``EpsilonLaw._interpolant`` did, and the
speeds served one at a time, as ``SILaw.points`` did. Project: one call, the interpolants cached
and the served speeds evaluated as one array. Both serve the same 2000 speeds of a steel sphere
against a wall; runs alternate (baseline, project, ...) and the script prints min / median / max
of the per-speed times and of their ratio, the served values' largest difference (they must
agree exactly), and the load average.

Run: python benchmarks/bench_si_points.py [--speeds N] [--repeats K]
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
from scipy.interpolate import PchipInterpolator  # noqa: E402

from restitution.laws.law import EpsilonLaw  # noqa: E402
from restitution.laws.si_law import si_law  # noqa: E402


def _uncached(self, values):
    """The interpolant as it was built before: anew at every call."""
    return PchipInterpolator(self.v, values, extrapolate=False)


def _serve(speeds, cached: bool):
    law = si_law(E=210e9, nu=0.3, rho=7850.0, geometry="sphere", against="wall")
    law.points(speeds[:1])  # the leave-one-out errors, built once either way
    original = EpsilonLaw._interpolant
    if not cached:
        EpsilonLaw._interpolant = _uncached
    try:
        start = time.perf_counter()
        if cached:
            points = law.points(speeds)
        else:
            points = [law.points([w])[0] for w in speeds]
        elapsed = time.perf_counter() - start
    finally:
        EpsilonLaw._interpolant = original
    return elapsed / len(speeds), np.array([p.epsilon for p in points], dtype=float)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--speeds", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    speeds = np.geomspace(0.01, 1000.0, args.speeds)
    base, ours, ratio, diff = [], [], [], 0.0
    for _ in range(args.repeats):
        t_base, e_base = _serve(speeds, cached=False)
        t_ours, e_ours = _serve(speeds, cached=True)
        base.append(t_base)
        ours.append(t_ours)
        ratio.append(t_base / t_ours)
        diff = max(diff, float(np.nanmax(np.abs(e_base - e_ours))))

    def stats(x):
        return " / ".join(f"{f(x):.3g}" for f in (np.min, np.median, np.max))

    print(f"load average {os.getloadavg()[0]:.2f}; {args.speeds} speeds, {args.repeats} runs each")
    print(f"baseline  ms a speed, min / median / max: {stats(np.array(base) * 1e3)}")
    print(f"project   ms a speed, min / median / max: {stats(np.array(ours) * 1e3)}")
    print(f"speed-up (baseline / project), min / median / max: {stats(np.array(ratio))}")
    print(f"largest difference of the served epsilon: {diff:.3g}")


if __name__ == "__main__":
    main()
