"""Benchmark: FEM against the modal solver at equal accuracy in epsilon.

Both methods refine until their own error estimate of epsilon is below ``--tol``:

* FEM: mesh levels 0, 1, 2, ...; error = last Cauchy difference |eps_K - eps_(K-1)|.
* modal: N = 100, 200, 400, ... lowest modes; 1 - eps^2 extrapolated linearly in 1/sqrt(N)
  through the last three N (:func:`restitution.limits.extrapolation.extrapolate_modes`); error = the
  extrapolation's error estimate, accepted only when the fit looks asymptotic.

The time of a method is the sum over its sequence (a user needs the whole sequence for the
error estimate), including the FEM's mesh and matrix set-up and the computation of the modes
(done cold, from the frequency equation, not from the cache). Prints both sequences, both
times and their ratio, and how far apart the two answers are in combined errors.

    python benchmarks/bench_fem_vs_modal.py [--nu 0.33] [--v 0.1] [--alpha 500] [--tol 3e-4]
"""

from __future__ import annotations

import argparse
import math
import time
import warnings

import numpy as np

from restitution.bodies.disk.modes import compute_modes
from restitution.bodies.material import Material
from restitution.dynamics.collision import collide
from restitution.fem import fem_collide
from restitution.limits.extrapolation import epsilon_from_loss, extrapolate_modes


def fem_until(material: Material, v: float, alpha: float, tol: float, max_level: int):
    """FEM levels until the last change of epsilon is below ``tol``."""
    rows, total = [], 0.0
    for level in range(max_level + 1):
        r = fem_collide(material, v, alpha, refine=level)
        total += r.wall_time_s
        err = abs(r.epsilon - rows[-1][1]) if rows else math.inf
        rows.append((level, r.epsilon, err, r.wall_time_s))
        print(
            f"  FEM   refine {level}: eps = {r.epsilon:.7f}  change {err:.1e}  "
            f"{r.wall_time_s:7.1f} s",
            flush=True,
        )
        if err < tol:
            break
    return rows[-1][1], rows[-1][2], total


def modal_until(material: Material, v: float, alpha: float, tol: float, max_modes: int):
    """Double N until the extrapolated epsilon's error is below ``tol``."""
    counts = [100]
    while counts[-1] * 2 <= max_modes:
        counts.append(counts[-1] * 2)
    start = time.perf_counter()
    pool = compute_modes(material, count=counts[-1])
    total = time.perf_counter() - start
    print(f"  modal modes: {counts[-1]} computed in {total:.1f} s", flush=True)
    losses, eps, err = [], math.nan, math.inf
    for i, n in enumerate(counts):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = collide(pool.lowest(n), v, alpha)
        total += r.wall_time_s
        losses.append(r.energy_loss)
        note = ""
        if i >= 2:
            fit = extrapolate_modes(np.array(counts[i - 2 : i + 1]), np.array(losses[-3:]))
            eps, err = epsilon_from_loss(fit.limit, fit.limit_err)
            note = f"  -> N=inf: {eps:.7f} +- {err:.1e}" + ("" if fit.asymptotic_ok else " (?)")
            if not fit.asymptotic_ok:
                err = math.inf
        print(
            f"  modal N = {n:5d}: eps = {r.epsilon:.7f}  {r.wall_time_s:7.1f} s{note}", flush=True
        )
        if err < tol:
            break
    return eps, err, total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nu", type=float, default=0.33)
    parser.add_argument("--v", type=float, default=0.1)
    parser.add_argument("--alpha", type=float, default=500.0)
    parser.add_argument("--tol", type=float, default=3e-4, help="target error of epsilon")
    parser.add_argument("--max-level", type=int, default=3)
    parser.add_argument("--max-modes", type=int, default=3200)
    args = parser.parse_args()
    material = Material(args.nu)
    print(f"nu = {args.nu}, v = {args.v} c, alpha = {args.alpha}, target error {args.tol:.1e}")
    fem_eps, fem_err, fem_time = fem_until(material, args.v, args.alpha, args.tol, args.max_level)
    modal_eps, modal_err, modal_time = modal_until(
        material, args.v, args.alpha, args.tol, args.max_modes
    )
    print(f"FEM:   eps = {fem_eps:.7f} +- {fem_err:.1e}   total {fem_time:8.1f} s")
    print(f"modal: eps = {modal_eps:.7f} +- {modal_err:.1e}   total {modal_time:8.1f} s")
    print(f"time ratio FEM / modal = {fem_time / modal_time:.2f}")
    sigma = math.hypot(fem_err, modal_err)
    print(
        f"FEM - modal = {fem_eps - modal_eps:+.2e} ({abs(fem_eps - modal_eps) / sigma:.2f} "
        "combined errors)"
    )
    for name, err in (("FEM", fem_err), ("modal", modal_err)):
        if not err < args.tol:
            print(f"warning: {name} did not reach the target error; raise its limit")


if __name__ == "__main__":
    main()
