"""FEM reference values of epsilon for a sphere on an elastic wall (a block or a plate), with
full provenance: the judge of the half-space and thin-plate routes (issue 42).

Units: the ball's, ``E = rho = R = 1`` of its three-dimensional constants; ``v`` in
``c = sqrt(E / rho)``; the wall's constants as ratios to the ball's
(:class:`restitution.bodies.wall.HalfSpace`, :class:`~restitution.bodies.wall.Plate`).

:func:`compute_wall_reference` runs :func:`restitution.fem.wall_limits.fem_wall_epsilon` at a
list of ``(nu, wall, v, first_level)`` and writes the JSON file after every point (a stopped
run keeps what it finished); with ``append=True`` it adds to an existing file. Every invocation
is one entry of ``"runs"`` (its time, code version, git commit, package versions) and every
point names its run. The code version digests the FEM route's sources and the wall's modules
(:data:`WALL_MODULES`). The shipped file is ``restitution/laws/data/fem_reference_wall.json``
(:data:`WALL_REFERENCE_POINTS`); :func:`restitution.laws.wall_points.load_wall_reference` reads
it. Every file written carries a content digest (:func:`restitution.jsonable.signed`): a file
changed after it was written is not served (:mod:`restitution.laws.wall_points`) and not
carried into a new one (``--append``, ``--merge``).

Command line (one process, one point after the other)::

    python -m restitution.fem.wall_reference OUT.json [NU:V[:THICKNESS[:FIRST_LEVEL]] ...]
        [--modulus-ratio E_W] [--density-ratio RHO_W] [--wall-nu NU_W] [--append]
    python -m restitution.fem.wall_reference OUT.json --merge PART.json [PART.json ...]

(``THICKNESS`` in ``R``, ``inf`` or nothing for the half-space; ``--merge`` joins files computed
by processes apart, :func:`merge_wall_references`.) Ctrl-C ends with one line and status 130:
what the file keeps, and the points still to add with ``--append``.
"""

from __future__ import annotations

import datetime
import json
import math
import sys
from collections.abc import Iterable
from pathlib import Path

from restitution import atomic
from restitution.bodies.wall import HalfSpace, Plate
from restitution.errors import CorruptFileError, InputError
from restitution.fem.limits import LEVELS, FemRun
from restitution.fem.reference import _environment
from restitution.fem.wall_limits import fem_wall_epsilon
from restitution.jsonable import DIGEST_KEY, digest_matches, signed
from restitution.laws.partners.base import WALL_KEY
from restitution.provenance import FEM_MODULES, source_digest

__all__ = [
    "STEEL_ON_GLASS",
    "WALL_MODULES",
    "WALL_REFERENCE_POINTS",
    "compute_wall_reference",
    "merge_wall_references",
]

WALL_MODULES: tuple[str, ...] = (
    *FEM_MODULES,
    "restitution.fem.pair_model",
    "restitution.fem.block",
    "restitution.fem.wall_impact",
    "restitution.fem.wall_limits",
    "restitution.bodies.wall",
    "restitution.quasistatic.plate",
)
"""Modules whose source determines a reference value of the wall."""

_GLASS_ON_STEEL = (63.0 / 210.0, 2500.0 / 7850.0, 0.2481)
"""Glass (``E = 63 GPa``, ``rho = 2500 kg/m^3``, ``nu = 0.2481``) in the units of steel
(``210 GPa``, ``7850 kg/m^3``): the materials of :mod:`restitution.laws.materials` and of
docs/walls.md's examples."""

STEEL_ON_GLASS = HalfSpace(*_GLASS_ON_STEEL)
"""A glass block under a steel ball (``nu = 0.3``)."""

_BALL_RADIUS_MM = 2.5
"""The 5 mm ball of issue 42: a plate ``h`` mm thick is ``h / 2.5`` radii."""

WALL_REFERENCE_POINTS = (
    (0.3, STEEL_ON_GLASS, 1e-3, 0),
    (0.3, STEEL_ON_GLASS, 5e-4, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=3.0 / _BALL_RADIUS_MM), 5e-4, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=10.0 / _BALL_RADIUS_MM), 5e-4, 0),
    (0.3, STEEL_ON_GLASS, 0.0019334, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=10.0 / _BALL_RADIUS_MM), 0.0019334, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=10.0 / _BALL_RADIUS_MM), 0.00019334, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=3.0 / _BALL_RADIUS_MM), 0.00019334, 0),
    (0.3, STEEL_ON_GLASS, 0.00019334, 0),
    (0.3, Plate(*_GLASS_ON_STEEL, thickness=30.0 / _BALL_RADIUS_MM), 0.00019334, 0),
)
"""``(nu, wall, v, first level)`` of the shipped reference: a steel ball on a glass block at
``v = 1e-3`` and ``5e-4`` (5.2 and 2.6 m/s) and a 5 mm steel ball on glass plates 3 mm and 10
mm thick at ``v = 5e-4`` (Zener's model holds on both there; at 5.2 m/s it fails on the 10 mm
plate); then the block and the 10 mm plate at 10 m/s (``v = 0.0019334``, ``c`` of steel
5172.2 m/s): the block judges the half-space route at its widest judged contact (``a / R =
0.14``), the plate is the answer where Zener's model fails; both plates at 1 m/s
(``v = 0.00019334``), the judge on the thickness figure's speed (the 3 mm plate took 79
minutes of one core), and the block at 1 m/s, the figure's thick end (29 minutes of one
core), and a 30 mm plate at 1 m/s, between the thin plates and the block where neither route
holds (21 minutes). Contact levels 0-2. A run at
``v = 5e-4`` costs about 1.7 times one at ``1e-3`` (steps go like ``v^(-3/5)``)."""


def fem_wall_code_version() -> str:
    """``__version__`` plus a digest of :data:`WALL_MODULES`."""
    return source_digest(WALL_MODULES, "fem-wall.")


def _key(point: dict) -> tuple:
    wall = point[WALL_KEY]
    return (float(point["nu"]), wall["kind"], float(wall.get("thickness", math.inf)),
            float(point["v"]))  # fmt: skip


def compute_wall_reference(
    path: str | Path,
    points: Iterable[tuple] | None = None,
    *,
    levels=LEVELS,
    on_run=None,
    provenance: dict | None = None,
    append: bool = False,
) -> dict:
    """Compute FEM epsilon of a sphere on walls at ``points`` (``(nu, wall, v[, first_level])``,
    default :data:`WALL_REFERENCE_POINTS`) and write them to ``path`` after every point;
    ``on_run(nu, wall, v, run)`` after every collision; ``append`` adds to the file (a point of
    the same ``nu``, wall kind, thickness and ``v`` is replaced)."""
    path = Path(path)
    if append and path.exists():
        doc = _read(path)
    else:
        doc = {
            "description": (
                "FEM epsilon of a sphere striking an elastic block or plate, both meshed, "
                "extrapolated to h -> 0 (Richardson, three levels of both meshes) and alpha -> "
                "infinity (linear in 1/alpha, alpha = (80, 160, 320) / delta_Hertz(v)), with the "
                "block's size checked by doubling it; "
                "restitution.fem.wall_reference.compute_wall_reference"
            ),
            "geometry": "sphere-on-wall",
            "units": (
                "E = rho = R = 1 of the ball's 3D constants; the wall's modulus and density as "
                "ratios to the ball's, a plate's thickness in R; v in c = sqrt(E/rho)"
            ),
            "code_version": None,
            "git_commit": "unknown",
            "runs": [],
            "points": [],
        }
    run = {
        "created": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "code_version": fem_wall_code_version(),
        "environment": _environment(),
        "levels": [int(k) for k in levels],
        **(provenance or {}),
    }
    doc["runs"].append(run)
    index = len(doc["runs"]) - 1
    versions = sorted({r["code_version"] for r in doc["runs"]})
    doc["code_version"] = versions[0] if len(versions) == 1 else versions
    doc["git_commit"] = run.get("git_commit", "unknown")
    for point in WALL_REFERENCE_POINTS if points is None else points:
        nu, wall, v = float(point[0]), point[1], float(point[2])
        first = int(point[3]) if len(point) > 3 else 0
        report = None
        if on_run is not None:
            report = lambda r, nu=nu, wall=wall, v=v: on_run(nu, wall, v, r)  # noqa: E731
        result = fem_wall_epsilon(nu, wall, v, levels=[first + int(k) for k in levels],
                                  on_run=report)  # fmt: skip
        new = {**result.to_dict(), "run": index}
        doc["points"] = [p for p in doc["points"] if _key(p) != _key(new)] + [new]
        doc["points"].sort(key=_key)
        atomic.write_text(path, json.dumps(signed(doc), indent=1) + "\n")
    return doc


def _read(path: str | Path) -> dict:
    """A reference file to add to: refused when it is not one, or was changed after it was
    written (its content digest does not match; one without a digest, older, is taken)."""
    doc = json.loads(Path(path).read_text())
    if not isinstance(doc, dict) or doc.get("geometry") != "sphere-on-wall":
        raise InputError(f"{path} is not an FEM reference of a sphere on a wall")
    if digest_matches(doc) is False:
        raise CorruptFileError(
            f"{path} was changed after it was written (its content no longer matches its "
            "digest); compute its points again into a new file instead of adding to it"
        )
    doc.pop(DIGEST_KEY, None)
    return doc


def merge_wall_references(path: str | Path, parts: Iterable[str | Path]) -> dict:
    """One file at ``path`` from files computed apart (two processes, one point each): their
    ``"runs"`` in order, each point naming its run anew; a point of the same key in a later
    part replaces an earlier one."""
    doc = None
    for part in parts:
        other = _read(part)
        if doc is None:
            doc = {**other, "runs": [], "points": []}
        offset = len(doc["runs"])
        doc["runs"].extend(other["runs"])
        new = [{**p, "run": p["run"] + offset} for p in other["points"]]
        keys = {_key(p) for p in new}
        doc["points"] = [p for p in doc["points"] if _key(p) not in keys] + new
    if doc is None:
        raise InputError("give at least one file to merge")
    doc["points"].sort(key=_key)
    versions = sorted({r["code_version"] for r in doc["runs"]})
    doc["code_version"] = versions[0] if len(versions) == 1 else versions
    commits = sorted({r.get("git_commit", "unknown") for r in doc["runs"]})
    doc["git_commit"] = commits[0] if len(commits) == 1 else commits
    atomic.write_text(Path(path), json.dumps(signed(doc), indent=1) + "\n")
    return doc


def _parse_point(text: str, constants: tuple[float, float, float]) -> tuple:
    parts = text.split(":")
    if not 2 <= len(parts) <= 4:
        raise InputError(f"a point is NU:V[:THICKNESS[:FIRST_LEVEL]], got {text!r}")
    try:
        nu, v = float(parts[0]), float(parts[1])
        h = float(parts[2]) if len(parts) > 2 and parts[2] else math.inf
        first = int(parts[3]) if len(parts) > 3 else 0
    except ValueError as exc:
        raise InputError(
            f"a point is NU:V[:THICKNESS[:FIRST_LEVEL]] of numbers, got {text!r}"
        ) from exc
    wall = HalfSpace(*constants) if math.isinf(h) else Plate(*constants, thickness=h)
    return nu, wall, v, first


def _point_words(point: tuple) -> str:
    """A point as the command line gives it: ``NU:V[:THICKNESS[:FIRST_LEVEL]]``."""
    nu, wall, v = point[0], point[1], point[2]
    first = int(point[3]) if len(point) > 3 else 0
    words = [repr(float(nu)), repr(float(v))]
    thickness = getattr(wall, "thickness", math.inf)
    if first or math.isfinite(thickness):
        words.append(repr(float(thickness)) if math.isfinite(thickness) else "")
    if first:
        words.append(str(first))
    return ":".join(words)


def _interrupted(out: str, todo: list[tuple], finished: int) -> str:
    """The line a Ctrl-C of :func:`main` ends with: what is kept in ``out`` and how to go on.
    The same command again would start ``out`` afresh (only ``--append`` adds to it), so the
    way on is ``--append`` with the points not finished."""
    finished = max(finished, 0)
    if finished == 0:
        return (
            f"interrupted before the first point finished; {out} was not written; run the "
            "same command again to start over"
        )
    rest = " ".join(_point_words(p) for p in todo[finished:])
    return (
        f"interrupted; the {finished} point(s) finished are kept in {out}; to compute the other "
        f"{len(todo) - finished}, run the same command with --append and only these points: "
        f"{rest}"
    )


def main(argv: list[str] | None = None) -> None:
    """``python -m restitution.fem.wall_reference OUT.json [NU:V[:THICKNESS[:FIRST]] ...]``."""
    import argparse
    import subprocess

    parser = argparse.ArgumentParser(description="Compute FEM reference values of walls.")
    parser.add_argument("out", help="JSON file to write")
    parser.add_argument(
        "points", nargs="*", help="NU:V[:THICKNESS[:FIRST_LEVEL]] (default: the shipped set)"
    )
    parser.add_argument("--modulus-ratio", type=float, default=_GLASS_ON_STEEL[0],
                        help="E_w / E (default glass on steel)")  # fmt: skip
    parser.add_argument("--density-ratio", type=float, default=_GLASS_ON_STEEL[1],
                        help="rho_w / rho (default glass on steel)")  # fmt: skip
    parser.add_argument("--wall-nu", type=float, default=_GLASS_ON_STEEL[2],
                        help="the wall's Poisson number (default glass's)")  # fmt: skip
    parser.add_argument("--append", action="store_true", help="add to an existing OUT.json")
    parser.add_argument(
        "--merge", nargs="+", metavar="PART",
        help="write OUT.json from files computed apart, and compute nothing",
    )  # fmt: skip
    args = parser.parse_intermixed_args(argv)
    if args.merge:
        doc = merge_wall_references(args.out, args.merge)
        print(f"wrote {args.out}: {len(doc['points'])} points from {len(doc['runs'])} runs")
        return
    constants = (args.modulus_ratio, args.density_ratio, args.wall_nu)
    points = [_parse_point(p, constants) for p in args.points] or None
    try:
        git = {"capture_output": True, "text": True, "check": True}
        commit = subprocess.run(["git", "rev-parse", "HEAD"], **git).stdout.strip()
        status = ["git", "status", "--porcelain", "--", "src"]
        changed = subprocess.run(status, **git).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit, changed = "unknown", ""

    def report(nu: float, wall: HalfSpace, v: float, run: FemRun) -> None:
        print(
            f"nu = {nu:g}, {wall.to_dict()}, v = {v:g}, alpha = {run.alpha:.6g}, level "
            f"{run.level}: {run.n_dofs} dofs, epsilon = {run.epsilon:.8f}, {run.n_steps} steps, "
            f"{run.wall_time_s:.1f} s {run.message}",
            flush=True,
        )

    todo = list(WALL_REFERENCE_POINTS if points is None else points)
    started: list[tuple] = []

    def feed():  # the next point is taken once the one before is written
        for point in todo:
            started.append(point)
            yield point

    try:
        doc = compute_wall_reference(
            args.out, feed(), on_run=report, append=args.append,
            provenance={"git_commit": commit, "git_uncommitted_sources": bool(changed)},
        )  # fmt: skip
    except KeyboardInterrupt:
        print(_interrupted(args.out, todo, len(started) - 1), file=sys.stderr)
        sys.exit(130)
    for p in doc["points"]:
        print(
            f"nu = {p['nu']:g}, {p[WALL_KEY]}, v = {p['v']:g}: epsilon = {p['epsilon']} +- "
            f"{p['epsilon_err']} ({p['settings']['wall_time_s']:.0f} s)"
        )


if __name__ == "__main__":
    main()
