"""The table of docs/oblique.md's "A static residual for the one-state route": ``beta`` of the
modal one-state route with the dropped modes' static residual
(:func:`restitution.dynamics.oblique_residual.residual_collision`) against the mode count and the
wall, beside the route without it (:func:`restitution.dynamics.oblique.oblique_collision`,
``--bare``), issue 63.

The sphere's cap of azimuthal orders 0 and 1 (``--azimuthal``) on ``N`` axisymmetric modes; 0
is the rigid sphere, whose residual is the continuum's whole flexibility. Units: ``E = rho = R
= 1``, ``nu = 0.3``, ``mu = 0.5``; ``--v`` the normal speed in ``c``.

Usage (from the project's root, with its venv)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_modal_residual.py \\
        --modes 0 20 40 --alpha 2000 8000
"""

from __future__ import annotations

import argparse
import time

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.dynamics.oblique import oblique_collision
from restitution.dynamics.oblique_residual import residual_collision

NU, MU = 0.3, 0.5


def cap(count: int, azimuthal: int | None):
    """The cap of ``count`` axisymmetric modes (0: none, the rigid sphere's nodes)."""
    full = cap_modes(compute_sphere_modes(NU, count=max(count, 1)), azimuthal=azimuthal)
    return full if count else full.take(slice(0, 0))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--modes", type=int, nargs="+", default=(0, 20))
    parser.add_argument("--alpha", type=float, nargs="+", default=(2000.0, 8000.0))
    parser.add_argument("--v", type=float, default=0.005)
    parser.add_argument("--tan-over-mu", type=float, default=0.3)
    parser.add_argument("--azimuthal", type=int, default=1, help="-1: every order")
    parser.add_argument("--bare", action="store_true", help="also the route without residual")
    args = parser.parse_args()
    vt = args.tan_over_mu * MU * args.v
    print(
        "| modes | cap | alpha | beta | epsilon_normal | energy balance | steps | s | bare beta |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    for n in args.modes:
        body = cap(n, None if args.azimuthal < 0 else args.azimuthal)
        for alpha in args.alpha:
            start = time.perf_counter()
            out = residual_collision(body, args.v, vt, MU, alpha)
            took = time.perf_counter() - start
            bare = oblique_collision(body, args.v, vt, MU, alpha).beta if args.bare and n else None
            print(
                f"| {n} | {len(body)} | {alpha:g} | {out.beta:.4f} | {out.epsilon_normal:.6f} | "
                f"{out.energy_balance:.1e} | {out.steps} | {took:.0f} | "
                f"{'' if bare is None else f'{bare:.4f}'} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
