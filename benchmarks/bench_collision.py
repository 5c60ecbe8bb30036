"""Benchmark: one collision against scipy's DOP853 at equal accuracy in epsilon, and batching.

Setting of issue 3: nu = 0.33, v = 0.1, alpha = 500, 1600 lowest modes. Both solvers integrate
the same Hamiltonian with the same edge nodes; the baseline evaluates the wall terms the
straightforward way (dense g_k(phi_j) matrix, restitution.dynamics.reference). The reference epsilon
comes from split4 at a tiny energy tolerance. Each solver's tolerance (our energy_tol, DOP853's
rtol) is tightened tenfold from a loose start until its epsilon is within 1e-6 of the
reference, and the times of those runs are compared. Also printed: our default settings, and
the batched throughput for 32 speeds.

Run: python benchmarks/bench_collision.py [--modes 1600]
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution import collide, collide_batch, get_modes  # noqa: E402
from restitution.dynamics.reference import collide_dop853  # noqa: E402

NU, V, ALPHA, TARGET = 0.33, 0.1, 500.0, 1e-6


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--modes", type=int, default=1600)
    args = parser.parse_args()
    modes = get_modes(NU, count=args.modes)

    ref = collide(modes, V, ALPHA, energy_tol=1e-10).epsilon
    print(f"reference epsilon (split4, energy_tol 1e-10): {ref:.10f}")
    t = time.perf_counter()
    default = collide(modes, V, ALPHA)
    t_default = time.perf_counter() - t
    print(
        f"restitution defaults (split4, energy_tol 1e-6): |err| "
        f"{abs(default.epsilon - ref):.1e}  {default.n_steps} steps  {t_default:.2f} s"
    )
    tol = 1e-3
    while True:
        t = time.perf_counter()
        ours = collide(modes, V, ALPHA, energy_tol=tol)
        t_ours = time.perf_counter() - t
        err_ours = abs(ours.epsilon - ref)
        print(
            f"restitution energy_tol {tol:.0e}: eps {ours.epsilon:.10f}  |err| {err_ours:.1e}"
            f"  {ours.n_steps} steps  {t_ours:.2f} s",
            flush=True,
        )
        if err_ours <= TARGET or tol < 1e-9:
            break
        tol /= 10.0

    t_dop, err_dop, rtol = float("nan"), float("nan"), 1e-5
    while rtol >= 1e-12:
        t = time.perf_counter()
        d = collide_dop853(modes, V, ALPHA, rtol=rtol, atol=rtol * 1e-2)
        t_dop = time.perf_counter() - t
        err_dop = abs(d["epsilon"] - ref)
        print(
            f"DOP853 rtol {rtol:.0e}: eps {d['epsilon']:.10f}  |err| {err_dop:.1e}  "
            f"nfev {d['nfev']}  {t_dop:.2f} s",
            flush=True,
        )
        if err_dop <= TARGET:
            break
        rtol /= 10.0
    print(f"accuracy: ours {err_ours:.1e}, DOP853 {err_dop:.1e} (target {TARGET:.0e})")
    print(
        f"speed-up at equal accuracy: {t_dop / t_ours:.1f}x  (DOP853 {t_dop:.2f} s / "
        f"restitution {t_ours:.2f} s)"
    )

    vs = np.linspace(0.02, 0.3, 32)
    t = time.perf_counter()
    batch = collide_batch(modes, vs, ALPHA)
    t_batch = time.perf_counter() - t
    t = time.perf_counter()
    for v in vs[::8]:
        collide(modes, v, ALPHA)
    t_loop = (time.perf_counter() - t) * 8
    print(
        f"batch of 32 speeds: {t_batch:.1f} s = {32 / t_batch:.2f} collisions/s; "
        f"one at a time (4 of 32 timed, scaled): {t_loop:.1f} s = {32 / t_loop:.2f} "
        f"collisions/s; batching gains {t_loop / t_batch:.2f}x"
    )
    assert all(np.isfinite([r.epsilon for r in batch]))


if __name__ == "__main__":
    main()
