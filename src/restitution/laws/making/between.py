"""Direct computations between a law's computed points: what its served values there miss.

A law serves PCHIP through its computed points, which cannot make an extremum between two of
them; where epsilon(v) turns (the contact time beating against the low modes) the served value
may miss. This module computes epsilon directly, with the production settings of the
neighbouring points (the same sweep, store and extrapolation as the law's own points), at
speeds between the computed ones, and compares: the served value and its stated error against
the direct value and its own.

``python -m restitution.laws.making.between --geometry <kind> --nu 0.3 --per-interval 2 --out F``
writes the comparison (JSON, whole or not at all); ``tests/test_between.py`` reads the stored
comparisons and checks the served errors' coverage, ``-m slow`` recomputes a sample.

Units: speeds in ``c`` (towards the wall), as the law's ``v``.
"""

from __future__ import annotations

import argparse
import datetime
import json
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.bodies.kinds import geometries
from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.making.refine import neighbour_settings
from restitution.limits.run_options import Progress, progress_of

__all__ = ["between_speeds", "compare", "coverage", "direct_points", "main"]


def between_speeds(law_: EpsilonLaw, per_interval: int, lo: float = 0.0, hi: float = 1.0):
    """``per_interval`` speeds evenly spaced in ``log v`` inside every interval of the law's
    modal points within ``[lo, hi]`` (the points themselves excluded)."""
    if not (isinstance(per_interval, int) and per_interval >= 1):
        raise InputError(f"per_interval must be an integer >= 1, got {per_interval!r}")
    v = law_.v[~law_.quasistatic]
    out = []
    for a, b in zip(v[:-1], v[1:], strict=True):
        if a >= lo and b <= hi:
            inner = np.geomspace(a, b, per_interval + 2)[1:-1]
            out.extend(float(f"{x:.6g}") for x in inner)
    return out


def direct_points(geometry, nu, speeds, *, store=None, progress: Progress | bool = False):
    """epsilon at each speed by the production route (both limits, the settings of the
    neighbouring point: :func:`restitution.laws.making.refine.neighbour_settings`), one
    :class:`~restitution.limits.curves.PointEpsilon` a speed."""
    from restitution.limits.curves import epsilon_at

    shipped = law(nu, geometry=geometry)
    meter = progress_of(progress)
    out = []
    for v in meter.track(list(speeds), f"direct points, {geometry} nu = {nu:g}"):
        settings = neighbour_settings(shipped, v)
        out.append(epsilon_at(nu, v, settings=settings, store=store))
    return out


def compare(law_: EpsilonLaw, points) -> list[dict]:
    """The served value and error against each direct point.

    ``z`` is ``|served - direct| / served_err`` (the promise: the served error covers the
    truth); ``z_joint`` divides by ``sqrt(served_err^2 + direct_err^2)`` (the direct value has
    an error of its own).
    """
    rows = []
    for p in points:
        served = float(law_.epsilon(p.v))
        err = float(law_.epsilon_err(p.v))
        diff = abs(served - p.epsilon)
        rows.append(
            {
                "v": p.v,
                "served": served,
                "served_err": err,
                "direct": p.epsilon,
                "direct_err": p.epsilon_err,
                "direct_asymptotic_ok": bool(p.asymptotic_ok),
                "z": diff / err,
                "z_joint": diff / float(np.hypot(err, p.epsilon_err)),
            }
        )
    return rows


def coverage(rows, key: str = "z") -> dict:
    """The fractions of rows within one and two stated errors, and the largest ``key``."""
    z = np.array([r[key] for r in rows], dtype=float)
    return {
        "n": int(z.size),
        "within_1": float(np.mean(z <= 1.0)) if z.size else float("nan"),
        "within_2": float(np.mean(z <= 2.0)) if z.size else float("nan"),
        "largest": float(z.max()) if z.size else float("nan"),
    }


def _write(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic.write_text(path, json.dumps(data, indent=1) + "\n")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m restitution.laws.making.between", description=__doc__.split("\n\n")[0]
    )
    parser.add_argument("--geometry", required=True, choices=geometries())
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--speeds", type=float, nargs="*", help="speeds (c); else --per-interval")
    parser.add_argument("--per-interval", type=int, default=1)
    parser.add_argument("--lo", type=float, default=0.0)
    parser.add_argument("--hi", type=float, default=1.0)
    parser.add_argument("--store", default=None)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args(argv)
    served = law(args.nu, geometry=args.geometry)
    speeds = args.speeds or between_speeds(served, args.per_interval, args.lo, args.hi)
    points = direct_points(args.geometry, args.nu, speeds, store=args.store, progress=True)
    rows = compare(served, points)
    _write(
        args.out,
        {
            "what": "epsilon computed directly (production route: sweep, store, both limits) "
            "at speeds between a shipped law's computed points, against the law's served value "
            "and error there",
            "source": "this package, python -m restitution.laws.making.between (the direct values "
            "are regression values of this package's production route, not of an independent code)",
            "geometry": args.geometry,
            "nu": args.nu,
            "law_code_version": served.metadata.get("code_version"),
            "date": datetime.date.today().isoformat(),
            "coverage": coverage(rows),
            "coverage_joint": coverage(rows, "z_joint"),
            "rows": rows,
        },
    )
    print(json.dumps({"coverage": coverage(rows), "coverage_joint": coverage(rows, "z_joint")}))


if __name__ == "__main__":
    main()
