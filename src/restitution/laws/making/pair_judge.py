"""Two spheres: their modal collisions against their low-speed route, where both hold.

Units: the first sphere's reduced units; ``w`` the relative speed of the centres in ``c1``.

The low-speed route of two spheres (Rayleigh's estimate on the pair's Hertz pulse,
:mod:`restitution.quasistatic.low_speed`) serves up to its reach; the modal pair
(:class:`restitution.bodies.pair.BodyPair` of two spheres, every collision extrapolated in
``alpha`` and ``N`` as a law's points are) is the independent route. :func:`judge` runs the
modal sweep (through a result store, so a second run reads it) and sets each point beside the
route's estimate at that speed: ``z = (modal - route) / sqrt(err_modal^2 + err_route^2)``.

``python -m restitution.laws.making.pair_judge --radius-ratio 2 --out F [--store S]`` writes the
comparison (JSON, whole or not at all; the settings and the code version inside);
``tests/test_sphere_pair.py`` reads the stored comparisons.
"""

from __future__ import annotations

import argparse
import datetime
import json
from pathlib import Path

from restitution import atomic
from restitution.bodies.pair import Partner
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.limits.run_options import Executor
from restitution.limits.sweep import SweepSettings
from restitution.provenance import code_version

__all__ = ["SPEEDS", "WINDOW", "judge", "main"]

SPEEDS = (0.003, 0.006, 0.012, 0.024, 0.05)
"""Relative speeds of the comparison, ``c1``: from the reach of two identical spheres' route
(0.006) down by two and up by eight."""

WINDOW = (2250, 4500, 9000, 18000)
"""Modes of both spheres together: the most a pair of radius ratio 2 affords (its larger sphere
takes 8/9 of them, up to the 20000 a sphere's mode scan computes)."""

WALLS = (80.0, 160.0, 320.0)
"""``alpha delta_pair(w)``: the sphere's walls (its kind's ``alpha_products``)."""


def settings_for(partner: Partner, speeds=SPEEDS, window=WINDOW) -> SweepSettings:
    """The modal sweep of the comparison."""
    return SweepSettings(
        velocities=tuple(speeds), alphas=WALLS, alpha_scale="compression",
        n_modes=tuple(window), geometry=SPHERE.geometry, partner=partner, batch_size=3,
    )  # fmt: skip


def judge(partner: Partner, nu: float = 0.3, speeds=SPEEDS, *, store=None, workers=1) -> dict:
    """The modal points and the route's estimates at ``speeds`` (module docs)."""
    from restitution.limits.curves import compute_curves
    from restitution.quasistatic.low_speed import PAIR_LOW_SPEED_MODES, low_speed_loss, reach

    settings = settings_for(partner, speeds)
    curve = compute_curves([nu], settings, store=store, executor=Executor(workers=workers),
                           progress=False)[nu]  # fmt: skip
    modes = partner.pair(nu, PAIR_LOW_SPEED_MODES, SPHERE.geometry)
    rows = []
    for w, limit in zip(curve.velocities, curve.limits, strict=True):
        route = low_speed_loss(modes, float(w))
        err = (limit.epsilon_err**2 + route.epsilon_err**2) ** 0.5
        rows.append(
            {
                "w": float(w),
                "modal": {**limit.to_dict(), "settings": None},
                "route": {"epsilon": route.epsilon, "epsilon_err": route.epsilon_err,
                          "shares": list(route.shares)},
                "z": (limit.epsilon - route.epsilon) / err,
            }
        )  # fmt: skip
    return {
        "source": (
            "this package's own routes (regression values): python -m "
            "restitution.laws.making.pair_judge; the modal points are extrapolated collisions of "
            "the pair, the route's are Rayleigh's estimate on the pair's Hertz pulse"
        ),
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "code_version": code_version(SPHERE.geometry, pair=True),
        "nu": float(nu),
        "partner": partner.to_dict(),
        "reach": reach(nu, partner),
        "settings": {
            "walls_alpha_delta": list(WALLS),
            "n_modes": list(settings.n_modes),
            "energy_tol": dict(settings.options).get("energy_tol"),
        },  # fmt: skip
        "rows": rows,
    }


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description="Two spheres: modal collisions against the route.")
    parser.add_argument("--radius-ratio", type=float, default=2.0)
    parser.add_argument("--modulus-ratio", type=float, default=1.0)
    parser.add_argument("--density-ratio", type=float, default=1.0)
    parser.add_argument("--nu2", type=float, default=None)
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--speeds", type=float, nargs="+", default=list(SPEEDS))
    parser.add_argument("--store", default=None)
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    partner = Partner(args.radius_ratio, args.modulus_ratio, args.density_ratio, args.nu2)
    data = judge(partner, args.nu, args.speeds, store=args.store, workers=args.workers)
    atomic.write_text(Path(args.out), json.dumps(data, indent=1, allow_nan=False) + "\n")
    for row in data["rows"]:
        print(f"w = {row['w']:g}: z = {row['z']:+.2f}")


if __name__ == "__main__":
    main()
