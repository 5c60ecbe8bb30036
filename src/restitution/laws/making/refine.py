"""Speeds added where epsilon(v) turns between a law's computed points.

A law serves PCHIP through its computed points, which makes no extremum between two of them;
epsilon(v) turns where the contact time beats against the low modes, and a grid spaced
evenly in ``ln v`` puts no point there. A not-a-knot cubic spline in ``ln v`` through the same
points does turn between them. Where the two differ somewhere inside an interval by more than
the points' errors, the interval holds an unresolved turn: at the 62 direct points computed
between the speeds of the sphere's (``nu = 0.3``) and the disk's (``0.33``) laws
(``tests/data/between_*.json``) PCHIP missed by up to 1.1e-3, and ``|PCHIP - spline|``
came within a factor 0.3-2.3 of each miss where the miss exceeded the point errors.

The scan (:func:`turning_speeds`) evaluates both at ``per_interval`` speeds evenly spaced in
``ln v`` inside every interval of the modal points and flags each interval whose largest
difference exceeds ``factor`` times the larger point error of its two ends; the new speed is
where the difference is largest. :func:`refine` computes a point there by the production
route, with the settings of the neighbouring point that has the larger mode window (the same
sweep, store and both limits as the law's own points), and joins it to the law; each further
round scans the law with the points of the round before. The law's ``metadata["refined"]``
records the rule and each round's speeds.

``python -m restitution.laws.making.refine FILE... [--rounds N]`` refines law files in place (each
written whole or not at all); ``make law`` (``law-sphere``, ``law-pair``) runs it after
production.

Units: speeds in ``c`` (towards the wall; for a pair the relative speed), as the law's ``v``.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline, PchipInterpolator

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_point import point_record
from restitution.limits.run_options import Executor, Progress, progress_of
from restitution.limits.sweep import SweepSettings
from restitution.provenance import code_version

__all__ = ["FACTOR", "PER_INTERVAL", "neighbour_settings", "refine", "turning_speeds", "main"]

FACTOR = 1.0
"""An interval is flagged when PCHIP and the spline differ inside it by more than this many
times the larger point error of its ends."""

PER_INTERVAL = 10
"""Speeds inside each interval at which the scan compares PCHIP and the spline."""

RULE = (
    "a point where PCHIP and a not-a-knot cubic spline in ln v through the modal points differ "
    "most inside an interval, when that difference exceeds factor times the larger point error "
    "of the interval's ends (restitution.laws.making.refine)"
)


def _modal(law_: EpsilonLaw):
    keep = ~law_.quasistatic
    return law_.v[keep], law_.epsilon_points[keep], law_.epsilon_err_points[keep]


def turning_speeds(
    law_: EpsilonLaw, *, factor: float = FACTOR, per_interval: int = PER_INTERVAL
) -> list[tuple[float, float]]:
    """``(v, ratio)`` for every interval of the law's modal points where PCHIP and the cubic
    spline in ``ln v`` differ by more than ``factor`` point errors: ``v`` the speed of the
    largest difference (4 significant digits), ``ratio`` that difference over the larger point
    error of the interval's ends. Empty for fewer than four modal points."""
    if not (isinstance(per_interval, int) and per_interval >= 1):
        raise InputError(f"per_interval must be an integer >= 1, got {per_interval!r}")
    if not (isinstance(factor, int | float) and factor > 0):
        raise InputError(f"factor must be a positive number, got {factor!r}")
    v, eps, err = _modal(law_)
    if v.size < 4:
        return []
    pchip, spline = PchipInterpolator(v, eps), CubicSpline(np.log(v), eps)
    out = []
    for j in range(v.size - 1):
        inside = np.geomspace(v[j], v[j + 1], per_interval + 2)[1:-1]
        gap = np.abs(pchip(inside) - spline(np.log(inside)))
        k = int(np.argmax(gap))
        ratio = float(gap[k] / max(err[j], err[j + 1]))
        speed = float(f"{inside[k]:.4g}")
        if ratio > factor and v[j] < speed < v[j + 1]:
            out.append((speed, ratio))
    return out


def neighbour_settings(law_: EpsilonLaw, v: float) -> SweepSettings:
    """The sweep settings for a new point at ``v``: those recorded with the neighbouring modal
    point of the larger mode window (windows grow towards slow speeds, where fewer modes are
    not yet asymptotic), at the single speed ``v``."""
    modal = [r for r, q in zip(law_._records(), law_.quasistatic, strict=True) if not q]
    speeds = np.array([float(r["v"]) for r in modal])
    j = int(np.searchsorted(speeds, v))
    if not (0 < j < speeds.size) or v in speeds:
        raise InputError(
            f"v = {v:g} is not strictly between two computed speeds of the {law_.body_name} law "
            f"({speeds[0]:g} ... {speeds[-1]:g}); choose a speed between two of them"
        )
    records = [r for r in (modal[j - 1], modal[j]) if "settings" in r]
    if not records:
        raise InputError(f"the points around v = {v:g} record no sweep settings to reuse")
    chosen = max(records, key=lambda r: max(r["settings"]["n_modes"]))
    return replace(SweepSettings(**chosen["settings"]), velocities=(float(v),))


def _compute(law_: EpsilonLaw, speeds, store, executor, progress) -> tuple[list, list]:
    """The new points' records (and the speeds whose extrapolation gave no number)."""
    from restitution.limits.curves import compute_curves

    by_settings: dict[SweepSettings, list[float]] = {}
    for v in speeds:
        base = replace(neighbour_settings(law_, v), velocities=(0.5,))
        by_settings.setdefault(base, []).append(v)
    records, dropped = [], []
    for base, group in by_settings.items():
        settings = replace(base, velocities=tuple(group))
        curve = compute_curves(
            [law_.nu], settings, store=store, executor=executor, progress=progress
        )[float(law_.nu)]
        for v, limit in zip(curve.velocities, curve.limits, strict=True):
            if np.isfinite(limit.epsilon):
                records.append(point_record(float(v), limit, settings))
            else:
                dropped.append({"v": float(v), "message": limit.message})
    return records, dropped


def refine(
    law_: EpsilonLaw,
    *,
    rounds: int = 1,
    factor: float = FACTOR,
    per_interval: int = PER_INTERVAL,
    store=None,
    executor: Executor | None = None,
    progress: Progress | bool = False,
) -> EpsilonLaw:
    """The law with a point added in every interval where the scan (:func:`turning_speeds`)
    finds an unresolved turn, for up to ``rounds`` rounds (fewer when a scan flags nothing).

    Parameters
    ----------
    law_ : EpsilonLaw
        A law whose modal points record their sweep settings (every law this package computes).
    rounds : int
        Scans and computations, each on the law with the points of the round before.
    factor, per_interval
        The scan's threshold (:data:`FACTOR`) and its speeds per interval (:data:`PER_INTERVAL`).
    store, executor, progress
        Passed to :func:`restitution.limits.curves.compute_curves`.
    """
    if not (isinstance(rounds, int) and rounds >= 0):
        raise InputError(f"rounds must be an integer >= 0, got {rounds!r}")
    meter = progress_of(progress)
    previous = dict(law_.metadata.get("refined") or {})
    done = list(previous.get("rounds", []))
    for _ in range(rounds):
        flagged = turning_speeds(law_, factor=factor, per_interval=per_interval)
        if not flagged:
            break
        records, dropped = _compute(law_, [v for v, _ in flagged], store, executor, meter)
        done.append(
            {
                "speeds": [v for v, _ in flagged],
                "ratios": [round(r, 3) for _, r in flagged],
                "dropped": dropped,
            }
        )
        parameters = {
            "rule": RULE,
            "factor": factor,
            "per_interval": per_interval,
            "rounds": done,
            "code_version": code_version(law_.geometry, pair=law_.partner is not None),
        }
        law_ = law_.joined(records, key="refined", parameters=parameters)
    return law_


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(
        prog="python -m restitution.laws.making.refine", description=__doc__.split("\n\n")[0]
    )
    parser.add_argument("files", nargs="+", type=Path, help="law JSON files, refined in place")
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--factor", type=float, default=FACTOR)
    parser.add_argument("--workers", type=int, default=None, help="local processes")
    parser.add_argument("--store", default=None, help="result store (default: user cache)")
    parser.add_argument(
        "--dry-run", action="store_true", help="print the flagged speeds, compute nothing"
    )
    args = parser.parse_args(argv)
    executor = Executor(workers=args.workers)
    for path in args.files:
        start = time.perf_counter()
        law_ = EpsilonLaw.from_json(path)
        if args.dry_run:
            flagged = turning_speeds(law_, factor=args.factor)
            print(f"{path.name}: {len(flagged)} interval(s) flagged: {flagged}", flush=True)
            continue
        before = law_.v.size
        law_ = refine(
            law_, rounds=args.rounds, factor=args.factor, store=args.store, executor=executor,
            progress=True,
        )  # fmt: skip
        law_.to_json(path)
        print(
            f"{path.name}: {law_.v.size - before} point(s) added in "
            f"{time.perf_counter() - start:.0f} s",
            flush=True,
        )


if __name__ == "__main__":
    main()
