"""How the collision converges in the number of kept modes, with and without the static
residual (issue 46, item 2): the measurement behind docs/numerics.md's "Fewer modes: a static
residual" and its figure.

Units: the disk's ``E = rho = R = 1``; ``v`` in ``c``; walls ``alpha delta_max(v)`` as the laws
use them (:func:`restitution.limits.defaults.walls_at`, compression scale).

For every ``(nu, v, wall)``: epsilon of the collision with the static residual
(:func:`restitution.dynamics.residual.collide_residual`, its Richardson step error beside it)
for ``N = 25 ... 1600`` kept modes, and epsilon of the plain modal collision
(:func:`restitution.dynamics.collision.collide`, held to an energy drift of 1e-9) for
``N = 100 ... 25600``. Every point is appended to the JSON file as it is done (written whole,
:mod:`restitution.atomic`); a rerun skips what the file holds.

Command line::

    python -m restitution.reproduction.residual_study OUT.json [--nu 0.33 0.9]
        [--v 0.001 0.01 0.1] [--walls 40 80 160]
"""

from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path

from restitution import atomic
from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.dynamics.collision import collide
from restitution.dynamics.residual import collide_residual

__all__ = ["MODAL_MODES", "RESIDUAL_MODES", "compute"]

RESIDUAL_MODES = (25, 50, 100, 200, 400, 800, 1600)
"""Kept modes of the residual collisions."""

MODAL_MODES = (100, 400, 1600, 6400, 25600)
"""Modes of the plain modal collisions (the laws' production reaches 102400)."""

STEP_FACTOR = 0.2
"""The residual collisions' step factor (:data:`restitution.dynamics.residual.STEP_FACTOR`);
each runs at it and at half of it (Richardson's estimate of the step error is stored)."""

MODAL_DRIFT = 1e-9
"""Energy tolerance of the plain modal collisions: their step error far below the N error."""


def _key(geometry: str, route: str, nu: float, v: float, wall: float, n: int) -> str:
    return f"{geometry}:{route}:{nu:g}:{v:g}:{wall:g}:{n}"


def _load(path: Path) -> dict:
    if path.exists():
        return json.loads(path.read_text())
    return {"description": __doc__.split("\n\n")[0], "units": "disk E = rho = R = 1; v in c",
            "points": {}}  # fmt: skip


def compute(
    path,
    nus,
    speeds,
    walls,
    residual_modes=RESIDUAL_MODES,
    modal_modes=MODAL_MODES,
    geometry: str = DEFAULT_GEOMETRY,
    step_factor: float = STEP_FACTOR,
):
    """Run every missing point and append it to ``path`` (JSON), printing one line each."""
    path = Path(path)
    kind = body_kind(geometry)
    data = _load(path)
    points = data["points"]
    for nu in nus:
        for v in speeds:
            for wall in walls:
                alpha = wall / float(kind.max_compression(v, nu))
                jobs = [("residual", n) for n in residual_modes]
                jobs += [("modal", n) for n in modal_modes]
                for route, n in jobs:
                    key = _key(geometry, route, nu, v, wall, n)
                    if key in points:
                        continue
                    body = get_modes(nu, count=n, geometry=geometry)
                    start = time.perf_counter()
                    if route == "residual":
                        r = collide_residual(body, v, alpha, richardson=True,
                                             step_factor=step_factor)  # fmt: skip
                        point = {"epsilon": r.epsilon, "step_error": r.step_error,
                                 "drift": r.drift, "nodes": r.nodes,
                                 "active": r.active, "step_factor": step_factor}  # fmt: skip
                    else:
                        r = collide(body, v, alpha, energy_tol=MODAL_DRIFT)
                        point = {"epsilon": r.epsilon, "drift": r.energy_drift}
                    point.update(geometry=geometry, route=route, nu=nu, v=v, wall=wall,
                                 alpha=alpha, modes=n,
                                 seconds=time.perf_counter() - start)  # fmt: skip
                    points[key] = point
                    atomic.write_text(path, json.dumps(data, indent=1))
                    line = f"{route:8s} nu={nu:g} v={v:g} wall={wall:g} N={n}: "
                    print(
                        line + f"eps={point['epsilon']:.9f} ({point['seconds']:.1f} s)", flush=True
                    )
    return data


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--nu", type=float, nargs="+", default=[0.33, 0.9])
    parser.add_argument("--v", type=float, nargs="+", default=[0.1, 0.01, 0.001])
    parser.add_argument("--walls", type=float, nargs="+", default=[40.0, 80.0, 160.0])
    parser.add_argument("--geometry", default=DEFAULT_GEOMETRY)
    parser.add_argument("--step-factor", type=float, default=STEP_FACTOR)
    parser.add_argument("--residual-modes", type=int, nargs="*", default=list(RESIDUAL_MODES))
    parser.add_argument("--modal-modes", type=int, nargs="*", default=list(MODAL_MODES))
    args = parser.parse_args(argv)
    if not all(math.isfinite(x) and x > 0 for x in [*args.nu, *args.v, *args.walls]):
        parser.error("every nu, v and wall must be a positive number")
    compute(args.out, args.nu, args.v, args.walls, args.residual_modes, args.modal_modes,
            args.geometry, args.step_factor)  # fmt: skip


if __name__ == "__main__":
    main()
