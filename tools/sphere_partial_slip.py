"""The quasistatic microslip ``beta`` of the finite sphere against law (b) and the half-space
(issue 63: the target the modal route should reach in partial slip).

Prints, per speed, annuli and ``tan(theta) / mu``, ``beta`` and ``epsilon_normal`` of
:mod:`restitution.quasistatic.sphere_partial_slip`'s solver on three contacts: the half-space
with Hertz's parabola (law (b)'s problem on annuli, a check), the sphere's flexibility with
Hertz's parabola, and the sphere itself (its flexibility and its own shape), beside law (b)
(:func:`~restitution.quasistatic.oblique.oblique_impact`). Units: ``E = rho = R = 1``, ``nu =
0.3``, ``mu = 0.5``; docs/oblique.md ("The finite sphere's own partial slip") quotes it.
With ``--one-state`` the same for the modal one-state route's contact
(:mod:`restitution.quasistatic.sphere_one_state`), beside its closed-form half-space law
instead of law (b) (docs/oblique.md, "The one-state route's own limit").

Usage (from the project's root, with its venv; about 10 s per speed at 40 annuli)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_partial_slip.py
"""

from __future__ import annotations

import argparse
import math

from restitution.quasistatic.oblique import oblique_impact
from restitution.quasistatic.sphere_one_state import one_state_half_space, one_state_run
from restitution.quasistatic.sphere_partial_slip import REACH, AnnularContact, hertz_peak, run

NU, MU = 0.3, 0.5


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speed", type=float, nargs="+", default=(0.005, 0.001, 2e-4, 4e-5))
    parser.add_argument("--tan-over-mu", type=float, nargs="+", default=(0.3, 1.0, 2.0))
    parser.add_argument("--annuli", type=int, nargs="+", default=(40, 80))
    parser.add_argument("--one-state", action="store_true",
                        help="the one-state route's contact instead of microslip")  # fmt: skip
    args = parser.parse_args()
    solve, law_name = (one_state_run, "one state") if args.one_state else (run, "law (b)")
    print(f"| v (c) | annuli | tan(theta)/mu | {law_name} | half-space | sphere, parabola | "
          "sphere |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    for v in args.speed:
        radius = REACH * math.sqrt(hertz_peak(v, NU))
        for n in args.annuli:
            half = AnnularContact.build(radius, NU, body="half-space", annuli=n)
            flat = AnnularContact.build(radius, NU, annuli=n, parabola=True)
            own = AnnularContact(flat.edges, flat.Hn, flat.Ht, False)
            for q in args.tan_over_mu:
                if args.one_state:
                    law = one_state_half_space(v, q * MU * v, MU, NU)[0]
                else:
                    law = oblique_impact(v, q * MU * v, MU, NU).beta
                row = [solve(c, v, q * MU * v, MU, NU, 100 * n) for c in (half, flat, own)]
                cells = " | ".join(f"{b:.4f} ({e:.6f})" for b, e in row)
                print(f"| {v:g} | {n} | {q:g} | {law:.4f} | {cells} |", flush=True)


if __name__ == "__main__":
    main()
