"""Benchmark: building 1600 modes at nu = 0.33, against a naive root finder.

Baseline: the textbook approach, the raw boundary determinant (scipy's jv/jvp), a scan with the
same grid step, and scipy.optimize.brentq on every sign change; no column normalisation, no
search for near-degenerate pairs. Both runs search the same frequency window; the script prints
times, their ratio, and how many roots each finds (the baseline's misses show why the project
does more than that).

Run: python benchmarks/bench_modes.py
"""

from __future__ import annotations

import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import jv, jvp  # noqa: E402

from restitution import compute_modes  # noqa: E402

NU, COUNT, STEP = 0.33, 1600, 0.04


def _raw_det(n: int, w: float | np.ndarray) -> np.ndarray:
    k, q = w * np.sqrt(1 - NU**2), w * np.sqrt(2 * (1 + NU))
    if n == 0:
        return k * jvp(1, k) + NU * jv(1, k)
    a11 = -((1 - NU) * k * jvp(n, k) + (k**2 - (1 - NU) * n**2) * jv(n, k))
    a12 = n * (1 - NU) * (q * jvp(n, q) - jv(n, q))
    a21 = -2 * n * (k * jvp(n, k) - jv(n, k))
    a22 = 2 * q * jvp(n, q) + (q**2 - 2 * n**2) * jv(n, q)
    return a11 * a22 - a12 * a21


def baseline(omega_max: float) -> list[float]:
    roots = []
    n = 0
    while True:
        grid = np.arange(0.05, omega_max, STEP)
        f = _raw_det(n, grid)
        idx = np.nonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)[0]
        found = [brentq(lambda x, n=n: _raw_det(n, x), grid[i], grid[i + 1]) for i in idx]
        roots += found
        if not found and n > 5:
            break
        n += 1
    return sorted(roots)


def main() -> None:
    t = time.perf_counter()
    modes = compute_modes(NU, count=COUNT)
    t_ours = time.perf_counter() - t
    w_max = float(modes.omega.max()) + 1e-9
    t = time.perf_counter()
    base = baseline(w_max)
    t_base = time.perf_counter() - t
    base = np.array(base)
    base = base[base <= w_max]
    print(
        f"restitution: {len(modes)} modes below omega = {w_max:.4f} in {t_ours:.2f} s "
        f"(target < 3 s)"
    )
    print(f"baseline (raw determinant, jvp, brentq): {base.size} roots in {t_base:.2f} s")
    print(
        f"speed ratio baseline / restitution: {t_base / t_ours:.2f}x; roots missed by the "
        f"baseline: {len(modes) - base.size}"
    )


if __name__ == "__main__":
    main()
