"""FEM reference values of epsilon for two disks or two spheres, with full provenance (the judge
of the modal pair).

Units: the first body's, ``E1 = rho1 = R1 = 1`` (a disk's 2D plane-stress constants, a sphere's
3D ones); ``w`` (relative normal speed of the centres) in ``c1``; ``alpha`` in ``1/R1``; the
second body's constants as ratios to the first's (:class:`restitution.bodies.pair.partner.Partner`).

:func:`compute_pair_reference` runs :func:`restitution.fem.pair_limits.fem_pair_epsilon` at a
list of ``(nu, partner, w)`` and writes a JSON file after every point (a stopped run keeps what
it finished). With ``append=True`` it adds to an existing file: every invocation is one entry of
``"runs"`` (its creation time, code version, git commit and package versions) and every point
names its run (``"run"``), as :func:`restitution.fem.reference.merge_reference` does for the
disk on the wall. A point stores the inputs, both meshes and every run's epsilon, drift, step and
time, both fits and both orders of the limits. The code version is :func:`fem_pair_code_version`:
a digest of the FEM route's sources, the pair's FEM modules and :mod:`restitution.bodies.pair`.
The shipped files are ``restitution/laws/data/fem_reference_disk_pair.json``
(:data:`PAIR_REFERENCE_POINTS`) and ``fem_reference_sphere_pair.json`` (two spheres,
:data:`SPHERE_PAIR_REFERENCE_POINTS`; :func:`pair_reference_filename` of the kind);
:func:`load_pair_reference` reads them (``geometry=`` the kind, default the disk). Every
function takes the kind of both bodies as ``geometry``; a file holds one kind (its
``"geometry"`` is ``"disk-pair"`` or ``"sphere-pair"``).

Command line (one process, one point after the other)::

    python -m restitution.fem.pair_reference OUT.json [NU:W:R2[:FIRST_LEVEL] ...]
        [--geometry KIND] [--modulus-ratio E2] [--density-ratio RHO2] [--partner-nu NU2]
        [--append]
"""

from __future__ import annotations

import datetime
import json
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from restitution import atomic
from restitution.bodies.kinds import body_kind
from restitution.bodies.pair.partner import Partner
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.estimate import Estimate, EstimateView
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.limits import LEVELS, FemRun
from restitution.fem.pair_limits import fem_pair_epsilon
from restitution.fem.pair_model import PAIR_GEOMETRY
from restitution.fem.reference import _environment
from restitution.fem.section import _kind as fem_kind
from restitution.fem.section import fem_geometries
from restitution.limits.defaults import default_products
from restitution.provenance import FEM_MODULES, package_modules, source_digest

__all__ = [
    "PAIR_MODULES",
    "PAIR_REFERENCE_FILENAME",
    "PAIR_REFERENCE_POINTS",
    "SPHERE_PAIR_REFERENCE_POINTS",
    "PairReferencePoint",
    "compute_pair_reference",
    "fem_pair_code_version",
    "load_pair_reference",
    "pair_reference_filename",
]

PAIR_MODULES: tuple[str, ...] = (
    *FEM_MODULES,
    "restitution.fem.pair_model",
    "restitution.fem.pair_impact",
    "restitution.fem.pair_limits",
    *package_modules("restitution.bodies.pair"),
)
"""Modules whose source determines an FEM reference value of a pair: the FEM route's
(:data:`restitution.provenance.FEM_MODULES`), the pair's FEM modules and the pair's bodies."""


def pair_reference_filename(geometry: str = PAIR_GEOMETRY) -> str:
    """The shipped reference file of pairs of the kind ``geometry``, in ``restitution/laws/data``:
    ``fem_reference_<kind>_pair.json``."""
    return f"fem_reference_{geometry}_pair.json"


def _pair_tag(geometry: str) -> str:
    """A file's ``"geometry"``: the kind's name and ``-pair``."""
    return f"{geometry}-pair"


PAIR_REFERENCE_FILENAME = pair_reference_filename()
"""The shipped file of disk pairs, in ``restitution/laws/data``."""

PAIR_REFERENCE_POINTS = (
    (0.33, Partner(1.4), 0.2, 1),
    (0.33, Partner(1.4), 0.6, 1),
    (0.33, Partner(2.0), 0.2, 1),
    (0.9, Partner(1.4), 0.2, 1),
    (0.33, Partner(1.4), 0.01, 1),
)
"""``(nu, partner, w, first level)`` of the shipped reference: one material (the partner's
``nu`` is the first disk's), radius ratio 1.4 (the bidisperse packings' ratio) at ``w = 0.2`` and
``0.6``, ratio 2 at ``w = 0.2``, ``nu = 0.9`` at ratio 1.4, ``w = 0.2``, and a slow point, ratio
1.4 at ``w = 0.01`` (535 s). Levels 1-3, as for the disk on the wall at ``v >= 0.01`` (level 0 is
not asymptotic at ``w = 0.2``)."""

STEEL_GLASS = Partner(1.0, 0.3, 0.318471, nu=0.2481)
"""A glass sphere against a steel one of the same size (the steel sphere first, ``nu = 0.3``):
the partner of the shipped law ``law_sphere_pair_r1_E0.3_rho0.318471_nu20.2481_nu0.3.json``
and of ``tests/data/sphere_pair_judge_steel_glass.json``."""

SPHERE_PAIR_REFERENCE_POINTS = (
    (0.3, Partner(2.0), 0.024, 0),
    (0.3, STEEL_GLASS, 0.024, 0),
    (0.3, Partner(2.0), 0.002, 0),
    (0.3, STEEL_GLASS, 0.002, 0),
    (0.3, Partner(1.5), 0.002, 0),
)
"""``(nu, partner, w, first level)`` of the shipped reference of two spheres (3D ``nu = 0.3``):
radius ratios 2 and 1.5 of one material and steel on glass of one size (:data:`STEEL_GLASS`).
At ``w = 0.002``, inside the reach of the shipped pair laws' low-speed route (their ``v_max``
0.0033, 0.0040 and 0.0057), and at ``w = 0.024``, a speed of the modal pair judge
(:mod:`restitution.laws.making.pair_judge`, ``tests/data/sphere_pair_judge_*.json``). Levels 0-2
with the sphere's grading, as for the sphere on the wall. The shipped file holds the first four
(1220-1400 s a point at ``w = 0.002``, 360-440 s at ``0.024``, one core); the fifth, ratio 1.5
at ``w = 0.002``, is asked for but not yet computed (docs/spheres.md)."""

_DEFAULT_POINTS = {
    PAIR_GEOMETRY: PAIR_REFERENCE_POINTS,
    SPHERE.geometry: SPHERE_PAIR_REFERENCE_POINTS,
}
"""The shipped points of each kind's reference file."""


def fem_pair_code_version() -> str:
    """``__version__`` plus a digest of :data:`PAIR_MODULES`, e.g. ``0.1.0+fem-pair.3fa2...``."""
    return source_digest(PAIR_MODULES, "fem-pair.")


@dataclass(frozen=True)
class PairReferencePoint(EstimateView):
    """One FEM reference value of a pair.

    Attributes
    ----------
    nu : float
        The first body's Poisson number.
    partner : Partner
    w : float
        Relative normal speed of the centres, ``c1``.
    estimate : Estimate
        epsilon of the relative speed, its error, ``ok`` or ``not-asymptotic`` and the message,
        as stored; ``epsilon``, ``epsilon_err``, ``asymptotic_ok`` and ``message`` read it
        (:class:`~restitution.estimate.EstimateView`).
    """

    nu: float
    partner: Partner
    w: float
    estimate: Estimate

    @property
    def v(self) -> float:
        """The speed a law is evaluated at (``w``): so :func:`restitution.fem.judge.judge_law`
        takes these points with the law of their pair."""
        return self.w


def _key(point: dict) -> tuple:
    """``(nu, partner, w)`` of a stored point, orderable (a partner's ``nu`` of ``None`` first)."""
    partner = tuple(
        (name, value is not None, 0.0 if value is None else float(value))
        for name, value in sorted(point["partner"].items())
    )
    return float(point["nu"]), partner, float(point["w"])


def _new_document(grading: ContactGrading, levels, geometry: str = PAIR_GEOMETRY) -> dict:
    kind = body_kind(geometry)
    products = ", ".join(f"{a:g}" for a in default_products(geometry))
    constants = "2D" if kind.planar else "3D"
    return {
        "description": (
            f"FEM epsilon of two {geometry}s meeting head-on, extrapolated to h -> 0 "
            "(Richardson, three levels of both contact-graded meshes) and alpha -> infinity "
            f"(linear in 1/alpha, walls alpha = ({products}) / Partner.max_compression(w)); "
            "restitution.fem.pair_reference.compute_pair_reference"
        ),
        "geometry": _pair_tag(geometry),
        "units": (
            f"E1 = rho1 = R1 = 1 of the first {geometry}'s {constants} constants; the "
            "partner's radius, modulus and density as ratios to the first's; w in "
            "c1 = sqrt(E1/rho1) (relative normal speed of the centres); alpha in 1/R1; epsilon "
            "of the relative speed"
        ),
        "levels": [int(k) for k in levels],
        "levels_note": "per point: first_level + levels (settings.levels of each point)",
        "grading": grading.to_dict(),
        "code_version": None,
        "git_commit": "unknown",
        "runs": [],
        "points": [],
    }


def compute_pair_reference(
    path: str | Path,
    points: Iterable[tuple] | None = None,
    *,
    geometry: str = PAIR_GEOMETRY,
    levels=LEVELS,
    grading: ContactGrading | None = None,
    on_run: Callable[[float, Partner, float, FemRun], None] | None = None,
    provenance: dict | None = None,
    append: bool = False,
) -> dict:
    """Compute FEM epsilon of pairs with errors at ``points`` and write them to ``path``.

    Parameters
    ----------
    path : str or Path
        JSON file, rewritten after every point.
    points : iterable of tuple, optional
        ``(nu, partner, w)`` or ``(nu, partner, w, first_level)``: the first body's Poisson
        number, the :class:`Partner`, the relative speed (``c1``); the levels are
        ``first_level + levels`` (``first_level`` defaults to 0). Default: the shipped points
        of the kind (:data:`PAIR_REFERENCE_POINTS`, :data:`SPHERE_PAIR_REFERENCE_POINTS`).
    geometry : str
        The kind of both bodies (default the disk).
    levels : sequence of int
    grading : ContactGrading, optional
        Both meshes' grading (default the kind's).
    on_run : callable, optional
        Called with ``(nu, partner, w, run)`` after every collision.
    provenance : dict, optional
        Further provenance of this invocation (e.g. ``{"git_commit": ...}``).
    append : bool
        Add to the file at ``path`` if it exists (a point of the same ``nu``, partner and ``w``
        is replaced) instead of starting a new one.

    Returns
    -------
    dict
        What was written.
    """
    geometry = fem_kind(geometry).geometry
    if points is None:
        points = _DEFAULT_POINTS[geometry]
    grading = grading or default_grading(geometry)
    path = Path(path)
    if append and path.exists():
        doc = json.loads(path.read_text())
        if doc.get("geometry") != _pair_tag(geometry):
            raise InputError(f"{path} is not an FEM reference of {geometry} pairs; cannot append")
    else:
        doc = _new_document(grading, levels, geometry)
    run = {
        "created": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "code_version": fem_pair_code_version(),
        "environment": _environment(),
        "levels": [int(k) for k in levels],
        "grading": grading.to_dict(),
        **(provenance or {}),
    }
    doc["runs"].append(run)
    index = len(doc["runs"]) - 1
    versions = sorted({r["code_version"] for r in doc["runs"]})
    doc["code_version"] = versions[0] if len(versions) == 1 else versions
    doc["git_commit"] = run.get("git_commit", "unknown")
    for point in points:
        nu, partner, w = float(point[0]), point[1], float(point[2])
        if not isinstance(partner, Partner):
            raise InputError(f"a reference point's partner must be a Partner, got {partner!r}")
        first = int(point[3]) if len(point) > 3 else 0
        report = None
        if on_run is not None:
            report = lambda r, nu=nu, p=partner, w=w: on_run(nu, p, w, r)  # noqa: E731
        shifted = [first + int(k) for k in levels]
        result = fem_pair_epsilon(nu, partner, w, levels=shifted, grading=grading,
                                  on_run=report, geometry=geometry)  # fmt: skip
        new = {**result.to_dict(), "run": index}
        doc["points"] = [p for p in doc["points"] if _key(p) != _key(new)] + [new]
        doc["points"].sort(key=_key)
        atomic.write_text(path, json.dumps(doc, indent=1) + "\n")
    return doc


def load_pair_reference(
    path: str | Path | None = None,
    *,
    partner: Partner | None = None,
    geometry: str = PAIR_GEOMETRY,
) -> tuple[PairReferencePoint, ...]:
    """The FEM reference points of pairs of the kind ``geometry`` (default the disk) from
    ``path`` (default: the kind's shipped file, :func:`pair_reference_filename`), all or only
    those of ``partner``."""
    geometry = fem_kind(geometry).geometry
    filename = pair_reference_filename(geometry)
    if path is None:
        text = resources.files("restitution.laws").joinpath("data", filename).read_text()
    else:
        text = Path(path).read_text()
    name = path or filename
    try:
        doc = json.loads(text)
        if doc.get("geometry") != _pair_tag(geometry):
            raise InputError(f"{name} is not an FEM reference of {geometry} pairs")
        points = tuple(
            PairReferencePoint(
                nu=float(p["nu"]),
                partner=Partner.from_key(p["partner"]),
                w=float(p["w"]),
                estimate=Estimate.from_record(p),
            )
            for p in doc["points"]
        )
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise InputError(f"{name} is not an FEM reference file of pairs: {exc}") from exc
    if partner is not None:
        points = tuple(p for p in points if p.partner == partner)
    return points


def _parse_point(text: str, partner_args: dict) -> tuple:
    parts = text.split(":")
    if len(parts) not in (3, 4):
        raise InputError(f"a point is NU:W:R2[:FIRST_LEVEL], got {text!r}")
    try:
        nu, w, r2 = (float(x) for x in parts[:3])
        first = int(parts[3]) if len(parts) == 4 else 1
    except ValueError as exc:
        raise InputError(f"a point is NU:W:R2[:FIRST_LEVEL] of numbers, got {text!r}") from exc
    return nu, Partner(radius_ratio=r2, **partner_args), w, first


def main(argv: list[str] | None = None) -> None:
    """``python -m restitution.fem.pair_reference OUT.json [NU:W:R2[:FIRST_LEVEL] ...]``."""
    import argparse
    import subprocess

    parser = argparse.ArgumentParser(description="Compute FEM reference values of pairs.")
    parser.add_argument("out", help="JSON file to write")
    parser.add_argument(
        "points", nargs="*",
        help="NU:W:R2[:FIRST_LEVEL] (first level 1; default: the shipped set of the kind)",
    )  # fmt: skip
    parser.add_argument(
        "--geometry", default=PAIR_GEOMETRY, choices=fem_geometries(),
        help=f"the kind of both bodies (default {PAIR_GEOMETRY})",
    )  # fmt: skip
    parser.add_argument("--modulus-ratio", type=float, default=1.0, help="E2/E1 (default 1)")
    parser.add_argument("--density-ratio", type=float, default=1.0, help="rho2/rho1 (default 1)")
    parser.add_argument("--partner-nu", type=float, default=None, help="nu2 (default: nu)")
    parser.add_argument("--append", action="store_true", help="add to an existing OUT.json")
    args = parser.parse_intermixed_args(argv)
    partner_args = {
        "modulus_ratio": args.modulus_ratio,
        "density_ratio": args.density_ratio,
        "nu": args.partner_nu,
    }
    points = [_parse_point(p, partner_args) for p in args.points] or None
    try:
        commit = subprocess.run(
            ["git", "rev-parse", "HEAD"], capture_output=True, text=True, check=True
        ).stdout.strip()
        changed = subprocess.run(
            ["git", "status", "--porcelain", "--", "src"], capture_output=True, text=True,
            check=True,
        ).stdout.strip()  # fmt: skip
    except (OSError, subprocess.CalledProcessError):
        commit, changed = "unknown", ""

    def report(nu: float, partner: Partner, w: float, run: FemRun) -> None:
        print(
            f"nu = {nu:g}, R2/R1 = {partner.radius_ratio:g}, w = {w:g}, alpha = {run.alpha:.6g}, "
            f"level {run.level}: {run.n_dofs} dofs, h_contact = {run.h_contact:.3g}, "
            f"epsilon = {run.epsilon:.8f}, {run.n_steps} steps, {run.wall_time_s:.1f} s "
            f"{run.message}",
            flush=True,
        )

    doc = compute_pair_reference(
        args.out,
        points,
        geometry=args.geometry,
        on_run=report,
        provenance={"git_commit": commit, "git_uncommitted_sources": bool(changed)},
        append=args.append,
    )
    for p in doc["points"]:
        print(
            f"nu = {p['nu']:g}, partner {p['partner']}, w = {p['w']:g}: epsilon = "
            f"{p['epsilon']} +- {p['epsilon_err']} ({p['settings']['wall_time_s']:.0f} s)"
        )


if __name__ == "__main__":
    main()
