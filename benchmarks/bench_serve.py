"""Benchmark: serving 10^6 speeds of an SI law, for every kind of law, against ``numpy.interp``.

Issue 62: 10^6 speeds of a law should take at most 50 times a bare ``numpy.interp`` on a
400-point table for the same speeds (what a simulation code does with a tabulated law). For
each law kind of :data:`KINDS` (a shipped law, a law interpolated in ``nu``, a damped law; add
one as one entry) the script builds the law, times its first call (it loads what the law
needs once: the grid laws' leave-one-out errors, any speed a low-speed route computes), then
``--repeats`` rounds, alternating in each: the baseline (``numpy.interp`` on the law's own
values at 400 speeds evenly spaced in ``log w`` over the asked ones), ``epsilon(w,
outside="nan")`` and ``epsilon_err(w, outside="nan")``. It prints min / median / max of each
time and of the ratio to the round's baseline, whether the median epsilon ratio meets the
issue's 50, and the load average at the start and the end (the machine has 2 cores and is
shared: read the ratios, not the times).

Run: python benchmarks/bench_serve.py [--speeds 1000000] [--repeats 5] [--low 0.01] [--high 10]
"""

from __future__ import annotations

import argparse
import os
import time
from collections.abc import Callable
from dataclasses import dataclass

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution.laws.api import si_law  # noqa: E402

TARGET = 50.0
"""Issue 62: 10^6 speeds in at most this many times a bare ``numpy.interp``."""

TABLE_POINTS = 400
"""Points of the baseline's table."""

GLASS = dict(E=63e9, nu=0.2481, rho=2500.0, shape="sphere", against="grain")
STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere")


@dataclass(frozen=True)
class LawKind:
    """One kind of law served: its name in the output and how to build it (an object with
    ``epsilon(w, outside=...)`` and ``epsilon_err(w, outside=...)`` at speeds ``w`` in m/s)."""

    name: str
    build: Callable[[], object]


KINDS: list[LawKind] = [
    LawKind(
        "elastic steel sphere on a wall (shipped law)",
        lambda: si_law(E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall"),
    ),
    LawKind("glass beads (law interpolated in nu)", lambda: si_law(**GLASS)),
    LawKind(
        "damped glass beads (epsilon 0.9 at 1 m/s, R = 1 mm)",
        lambda: si_law(**GLASS, measured_epsilon=0.9, measured_speed=1.0, radius=1e-3),
    ),
    LawKind(
        "plastic steel on a wall (yield stress 1 GPa, R = 1 mm; its table)",
        lambda: si_law(**STEEL, against="wall", yield_stress=1e9, radius=1e-3),
    ),
    LawKind(
        "steel on a glass block (an elastic half-space; its grid)",
        lambda: si_law(**STEEL, against="wall", wall_E=63e9, wall_nu=0.2481, wall_rho=2500.0),
    ),
]
"""The law kinds served; a further kind is one entry."""


def _timed(run) -> tuple[float, object]:
    start = time.perf_counter()
    out = run()
    return time.perf_counter() - start, out


def _stats(x) -> str:
    x = np.asarray(x)
    return " / ".join(f"{f(x):.3g}" for f in (np.min, np.median, np.max))


def bench(kind: LawKind, w: np.ndarray, repeats: int) -> dict:
    """Times (s) of the baseline, ``epsilon`` and ``epsilon_err`` at ``w`` over ``repeats``
    alternating rounds, their ratios to the round's baseline, and the first call's time."""
    built, law = _timed(kind.build)
    first, _ = _timed(lambda: law.epsilon_err(w, outside="nan"))
    table_w = np.geomspace(w.min(), w.max(), TABLE_POINTS)
    table = np.nan_to_num(law.epsilon(table_w, outside="nan"), nan=1.0)
    out = {"built": built, "first": first, "interp": [], "epsilon": [], "epsilon_err": []}
    for r in range(repeats):
        runs = {
            "interp": lambda: np.interp(w, table_w, table),
            "epsilon": lambda: law.epsilon(w, outside="nan"),
            "epsilon_err": lambda: law.epsilon_err(w, outside="nan"),
        }
        order = list(runs) if r % 2 == 0 else list(runs)[::-1]  # alternate who goes first
        for name in order:
            out[name].append(_timed(runs[name])[0])
    eps = law.epsilon(w, outside="nan")
    out["nan"] = int(np.isnan(eps).sum())
    for name in ("epsilon", "epsilon_err"):
        out[f"{name}_ratio"] = np.array(out[name]) / np.array(out["interp"])
    return out


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--speeds", type=int, default=10**6)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--low", type=float, default=0.01, help="slowest speed, m/s")
    parser.add_argument("--high", type=float, default=10.0, help="fastest speed, m/s")
    args = parser.parse_args(argv)
    w = np.geomspace(args.low, args.high, args.speeds)
    print(f"load average at the start {os.getloadavg()[0]:.2f} (2 cores); {args.speeds} speeds "
          f"{args.low:g}-{args.high:g} m/s, {args.repeats} alternating rounds; baseline: "
          f"numpy.interp on {TABLE_POINTS} points")  # fmt: skip
    for kind in KINDS:
        r = bench(kind, w, args.repeats)
        met = "met" if np.median(r["epsilon_ratio"]) <= TARGET else "NOT met"
        print(f"\n{kind.name}: built in {r['built']:.3g} s (target: under a minute); first "
              f"call (epsilon_err, one-time work) {r['first']:.3g} s; "
              f"{r['nan']} speeds outside the law (nan)")  # fmt: skip
        print(f"  numpy.interp  ms, min / median / max: {_stats(np.array(r['interp']) * 1e3)}")
        for name in ("epsilon", "epsilon_err"):
            print(f"  {name:12s}  ms, min / median / max: {_stats(np.array(r[name]) * 1e3)}"
                  f"   ratio to numpy.interp: {_stats(r[f'{name}_ratio'])}")  # fmt: skip
        print(f"  target epsilon <= {TARGET:g} x numpy.interp (median): {met}")
    print(f"\nload average at the end {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
