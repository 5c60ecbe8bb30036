"""FEM reference values of epsilon with full provenance (the judge of the modal law).

Units: ``E = rho = R = 1``; ``v`` in ``c`` (speed towards the wall), ``alpha`` in ``1/R``.

:func:`compute_reference` runs :func:`restitution.fem.limits.fem_epsilon` at a list of
``(nu, v)`` and writes a JSON file after every point (a long run that is stopped keeps what it
finished): the inputs, the mesh sizes, every level's epsilon, drift, step and time, both fits,
the code version (:func:`restitution.provenance.fem_code_version`: a digest of the FEM sources
and what they import) and the package versions.
The shipped files are ``restitution/laws/data/fem_reference.json`` (the disk) and
``fem_reference_sphere.json`` (the sphere, :data:`SPHERE_REFERENCE_POINTS`);
:func:`load_reference` reads them.
"""

from __future__ import annotations

import datetime
import json
import platform
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from restitution import atomic
from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.estimate import Estimate, EstimateView
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.limits import LEVELS, FemRun, fem_epsilon
from restitution.fem.section import fem_geometries
from restitution.provenance import fem_code_version

__all__ = [
    "REFERENCE_POINTS",
    "SHIPPED_POINTS",
    "SPHERE_REFERENCE_POINTS",
    "ReferencePoint",
    "reference_filename",
    "compute_reference",
    "load_reference",
    "merge_reference",
]

REFERENCE_POINTS = (
    (0.33, 0.1, 1),
    (0.9, 0.1, 1),
    (0.9, 0.3, 1),
    (0.33, 0.01, 1),
    (0.9, 0.01, 1),
    (0.33, 0.001, 0),
    (0.9, 0.001, 0),
    (0.33, 0.0001, 0),
    (0.9, 0.0001, 0),
    (0.33, 1e-5, 0),
)
"""``(nu, v, first level)`` of the shipped reference: v = 1e-4, 1e-3, 1e-2, 0.1 at both nu and
0.3 at nu = 0.9; and v = 1e-5 at nu = 0.33, where the laws serve the slow-impact model
(:mod:`restitution.quasistatic.slow_disk`; 28 minutes of one core beside other work, 0.76 of
the estimate of :mod:`restitution.fem.cost`). Three levels from the
first; the finer levels 1-3 where they are affordable."""


SPHERE_REFERENCE_POINTS = tuple(
    (nu, v, 0) for nu in (0.2, 0.3, 0.45) for v in (0.00521, 0.0189, 0.0993)
) + ((0.3, 0.001, 0), (0.3, 0.0005, 0), (0.3, 0.0002, 0), (0.2, 0.0002, 0), (0.45, 0.0002, 0))
"""``(nu, v, first level)`` of the sphere's reference: three 3D Poisson numbers of the shipped
sphere laws (the ends and steel), each at three of the laws' computed speeds (the law's own
points, so that the judge tests the extrapolation, not the interpolation between speeds); and
five points below the modal speeds, where the laws serve the low-speed theory
(:mod:`restitution.quasistatic.low_speed`): ``nu = 0.3`` at ``v = 1e-3, 5e-4, 2e-4`` (steel at
5.2, 2.6 and 1.03 m/s) and the grid's ends at ``v = 2e-4``. The shipped file merges the runs
(:func:`merge_reference`)."""


SHIPPED_POINTS: dict[str, tuple[tuple[float, float, int], ...]] = {
    DISK.geometry: REFERENCE_POINTS,
    SPHERE.geometry: SPHERE_REFERENCE_POINTS,
}
"""The points of each body's shipped reference, by the kind's name (the default points of
``python -m restitution.fem.reference``)."""


def reference_filename(geometry: str = DEFAULT_GEOMETRY) -> str:
    """``fem_reference.json`` for the disk, ``fem_reference_<file tag>.json`` otherwise (the
    kind's :meth:`~restitution.bodies.kinds.BodyKind.file_name`)."""
    return body_kind(geometry).file_name("fem_reference") + ".json"


def _environment() -> dict:
    import numpy
    import scipy
    import skfem

    return {
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "scipy": scipy.__version__,
        "scikit-fem": getattr(skfem, "__version__", "unknown"),
        "machine": platform.machine(),
    }


@dataclass(frozen=True)
class ReferencePoint(EstimateView):
    """One FEM reference value.

    Attributes
    ----------
    nu, v : float
        Poisson number and speed towards the wall (``c``).
    estimate : Estimate
        epsilon, its error, ``ok`` or ``not-asymptotic`` and the message, as stored;
        ``epsilon``, ``epsilon_err``, ``asymptotic_ok`` and ``message`` read it
        (:class:`~restitution.estimate.EstimateView`).
    """

    nu: float
    v: float
    estimate: Estimate


def compute_reference(
    path: str | Path,
    points: Iterable[tuple[float, float]] = REFERENCE_POINTS,
    *,
    levels=LEVELS,
    grading: ContactGrading | None = None,
    on_run: Callable[[float, float, FemRun], None] | None = None,
    provenance: dict | None = None,
    geometry: str = DEFAULT_GEOMETRY,
    walls: Sequence[float] | None = None,
) -> dict:
    """Compute FEM epsilon with errors at ``points`` and write them with provenance to ``path``.

    Parameters
    ----------
    path : str or Path
        JSON file, rewritten after every point.
    points : iterable of tuple
        ``(nu, v)`` or ``(nu, v, first_level)``, ``v`` in ``c``; the levels are
        ``first_level + levels`` (``first_level`` defaults to 0).
    levels : sequence of int
    grading : ContactGrading, optional
    on_run : callable, optional
        Called with ``(nu, v, run)`` after every collision.
    provenance : dict, optional
        Further provenance to store (e.g. the commit of the sources).
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body (:mod:`restitution.fem.section`); its default grading when ``grading`` is not
        given (:func:`restitution.fem.graded.default_grading`).
    walls : sequence of float, optional
        The walls as products ``alpha * delta_max(v)`` (the modal sweeps' scale); default the
        body's own (:func:`restitution.limits.defaults.default_products`: 40, 80, 160 for the
        disk). Harder walls judge a route served from them (docs/errors.md).

    Returns
    -------
    dict
        What was written.
    """
    grading = grading or default_grading(geometry)
    path = Path(path)
    doc = {
        "description": (
            f"FEM epsilon of the {geometry}-wall collision, extrapolated to h -> 0 (Richardson, "
            "three contact-graded meshes) and alpha -> infinity (linear in 1/alpha); "
            "restitution.fem.reference.compute_reference"
            + ("" if walls is None else f", walls alpha delta_max = {list(walls)}")
        ),
        "geometry": geometry,
        "units": f"E = rho = R = 1 of the {geometry}'s constants; v in c = sqrt(E/rho) (speed "
        "towards the wall); alpha in 1/R",
        "created": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "code_version": fem_code_version(),
        "environment": _environment(),
        **(provenance or {}),
        "levels": [int(k) for k in levels],
        "levels_note": "per point: first_level + levels (settings.levels of each point)",
        "grading": grading.to_dict(),
        "points": [],
    }
    for point in points:
        nu, v = point[0], point[1]
        first = int(point[2]) if len(point) > 2 else 0
        report = None if on_run is None else (lambda run, nu=nu, v=v: on_run(nu, v, run))
        shifted = [first + int(k) for k in levels]
        result = fem_epsilon(
            nu, v, levels=shifted, grading=grading, on_run=report, geometry=geometry,
            alphas=walls, alpha_scale=None if walls is None else "compression",
        )  # fmt: skip
        doc["points"].append(result.to_dict())
        atomic.write_text(path, json.dumps(doc, indent=1) + "\n")
    return doc


def merge_reference(docs: list[dict]) -> dict:
    """One reference document from several runs: per ``(nu, v)`` the point with the finest
    levels (the later run on a tie); each run's provenance is kept under ``"runs"`` and every
    point names its run (``"run"``: index into ``"runs"``)."""
    if not docs:
        raise InputError("nothing to merge")
    chosen: dict[tuple[float, float], dict] = {}
    for i, doc in enumerate(docs):
        for point in doc["points"]:
            key = (float(point["nu"]), float(point["v"]))
            old = chosen.get(key)
            if old is None or max(point["settings"]["levels"]) >= max(old["settings"]["levels"]):
                chosen[key] = {**point, "run": i}
    runs = [{k: v for k, v in doc.items() if k != "points"} for doc in docs]
    versions = {r["code_version"] for r in runs}
    bodies = {doc.get("geometry", DEFAULT_GEOMETRY) for doc in docs}
    if len(bodies) != 1:
        raise InputError(f"cannot merge references of different bodies: {', '.join(bodies)}")
    return {
        "description": docs[-1]["description"],
        "geometry": bodies.pop(),
        "units": docs[-1]["units"],
        "code_version": versions.pop() if len(versions) == 1 else sorted(versions),
        "git_commit": runs[-1].get("git_commit", "unknown"),
        "runs": runs,
        "points": [chosen[k] for k in sorted(chosen)],
    }


def load_reference(
    path: str | Path | None = None, *, geometry: str = DEFAULT_GEOMETRY
) -> tuple[ReferencePoint, ...]:
    """The FEM reference points from ``path`` (default: the shipped file of ``geometry``).

    A file of another body is refused (files without ``"geometry"`` are the disk's).
    """
    if path is None:
        name = reference_filename(geometry)
        text = resources.files("restitution.laws").joinpath("data", name).read_text()
    else:
        text = Path(path).read_text()
    try:
        doc = json.loads(text)
        if doc.get("geometry", DEFAULT_GEOMETRY) != geometry:
            raise InputError(
                f"{path} is the FEM reference of the {doc['geometry']}, not of the {geometry}"
            )
        points = tuple(
            ReferencePoint(nu=float(p["nu"]), v=float(p["v"]), estimate=Estimate.from_record(p))
            for p in doc["points"]
        )
    except (ValueError, KeyError, TypeError) as exc:
        name = path or "fem_reference.json"
        raise InputError(f"{name} is not an FEM reference file: {exc}") from exc
    return points


def main(argv: list[str] | None = None) -> None:
    """``python -m restitution.fem.reference OUT.json [--geometry sphere] [nu:v[:level] ...]``."""
    import argparse
    import subprocess

    parser = argparse.ArgumentParser(description="Compute FEM reference values of epsilon.")
    parser.add_argument("out", help="JSON file to write")
    parser.add_argument("points", nargs="*", help="nu:v[:first_level] (default: the shipped set)")
    parser.add_argument("--geometry", choices=fem_geometries(), default=DEFAULT_GEOMETRY)
    parser.add_argument(
        "--walls",
        type=float,
        nargs="+",
        default=None,
        help="walls as products alpha * delta_max(v) (default the body's own: 40 80 160 for "
        "the disk)",
    )
    args = parser.parse_intermixed_args(argv)
    points = [tuple(float(x) for x in a.split(":")) for a in args.points]
    points = points or SHIPPED_POINTS.get(args.geometry, ())
    if not points:
        parser.error(f"the {args.geometry} has no shipped reference points; give nu:v points")
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "HEAD"], capture_output=True, text=True, check=True
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"

    def report(nu: float, v: float, run: FemRun) -> None:
        print(
            f"nu = {nu:g}, v = {v:g}, alpha = {run.alpha:.6g}, level {run.level}: "
            f"{run.n_dofs} dofs, h_contact = {run.h_contact:.3g}, epsilon = {run.epsilon:.8f}, "
            f"{run.n_steps} steps, {run.wall_time_s:.1f} s {run.message}",
            flush=True,
        )

    compute_reference(
        args.out, points, on_run=report, provenance={"git_commit": commit}, geometry=args.geometry,
        walls=args.walls,
    )  # fmt: skip


if __name__ == "__main__":
    main()
