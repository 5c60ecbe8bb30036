"""Benchmark: which route is cheaper where -- graded FEM against modes at equal accuracy.

At a low, a middle and a high speed (default v = 1e-3, 0.03, 0.3 in units of c) and one wall per
speed, ``alpha = 80 / delta_max(v)`` (the middle wall of the sweeps), both routes refine until
their own error estimate of epsilon is below ``--tol``:

* FEM (contact-graded meshes, :mod:`restitution.fem.graded`): levels 0, 1, 2, ...; from the
  third level on, the Richardson limit of ``1 - eps^2`` through the last three
  (:func:`restitution.fem.richardson.richardson_limit`), error = its estimate;
* modal: N = 100, 200, 400, ... lowest modes, ``1 - eps^2`` extrapolated in ``1/sqrt(N)``
  through the last three N (``bench_fem_vs_modal.modal_until``; modes computed cold).

Times are the sums over each sequence (a user needs the whole sequence for the error), set-up
included. One process. Prints both answers, both times and which route is cheaper at each speed.

    python benchmarks/bench_fem_route.py [--nu 0.33] [--v 1e-3 0.03 0.3] [--tol 1e-4]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

from restitution.bodies.disk.contact import max_compression_estimate
from restitution.bodies.material import Material
from restitution.fem.graded import graded_settings, mesh_summary
from restitution.fem.impact import fem_collide, model_for
from restitution.fem.richardson import richardson_limit
from restitution.limits.extrapolation import epsilon_from_loss

sys.path.insert(0, str(Path(__file__).parent))
from bench_fem_vs_modal import modal_until  # noqa: E402


def graded_until(material: Material, v: float, alpha: float, tol: float, max_level: int):
    """Graded FEM levels until the Richardson error of epsilon is below ``tol``."""
    losses, total, eps, err = [], 0.0, math.nan, math.inf
    for level in range(max_level + 1):
        start = time.perf_counter()
        s = graded_settings(v, alpha, level)
        r = fem_collide(material, v, alpha, settings=s)
        dofs = mesh_summary(model_for(material, v, alpha, s), v).n_dofs
        total += time.perf_counter() - start
        losses.append(r.energy_loss)
        note = ""
        if level >= 2:
            fit = richardson_limit(losses[-3:])
            eps, err = epsilon_from_loss(fit.limit, fit.limit_err)
            note = f"  -> h=0: {eps:.7f} +- {err:.1e} ({fit.kind})"
            if not fit.asymptotic_ok:
                err = math.inf
        print(
            f"  FEM   level {level}: {dofs:6d} dofs, eps = {r.epsilon:.7f}  "
            f"{time.perf_counter() - start:7.1f} s{note}",
            flush=True,
        )
        if err < tol:
            break
    return eps, err, total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nu", type=float, default=0.33)
    parser.add_argument("--v", type=float, nargs="+", default=[1e-3, 0.03, 0.3])
    parser.add_argument("--tol", type=float, default=1e-4, help="target error of epsilon")
    parser.add_argument("--max-level", type=int, default=3)
    parser.add_argument("--max-modes", type=int, default=3200)
    args = parser.parse_args()
    material = Material(args.nu)
    rows = []
    for v in args.v:
        alpha = 80.0 / max_compression_estimate(v)
        print(f"nu = {args.nu}, v = {v:g} c, alpha = {alpha:.5g} /R, target error {args.tol:.0e}")
        fem = graded_until(material, v, alpha, args.tol, args.max_level)
        modal = modal_until(material, v, alpha, args.tol, args.max_modes)
        rows.append((v, alpha, fem, modal))
    print()
    print("   v/c     alpha   FEM eps +- err (time)            modal eps +- err (time)     cheaper")
    for v, alpha, (fe, ferr, ft), (me, merr, mt) in rows:
        reached = [name for name, e in (("FEM", ferr), ("modal", merr)) if e < args.tol]
        if len(reached) == 2:
            cheaper = "FEM" if ft < mt else "modal"
            verdict = f"{cheaper} ({max(ft, mt) / min(ft, mt):.1f}x)"
        elif reached:
            verdict = f"{reached[0]} (only one reached the target)"
        else:
            verdict = "neither reached the target"
        print(
            f"{v:7.3g} {alpha:9.4g}   {fe:.6f} +- {ferr:.1e} ({ft:6.1f} s)   "
            f"{me:.6f} +- {merr:.1e} ({mt:6.1f} s)   {verdict}"
        )


if __name__ == "__main__":
    main()
