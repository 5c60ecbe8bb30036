"""A law's file: its name, its metadata, the checks of what it stores, reading it and its exports.

Units: a law's ``v`` is the body's speed towards the wall in units of ``c = sqrt(E/rho)`` of its
own constants (a pair's: the relative speed of the centres in the first body's ``c``); epsilon
and its error are dimensionless (:func:`law_units` says it for each body, and every file says
it).

The file of a law (:class:`restitution.laws.law.EpsilonLaw`) is named by :func:`law_filename`
(``law_nu<nu>.json`` for the disk, ``law_sphere_nu<nu>.json`` for the sphere, ``law_pair_...``
for two bodies). Every law names its body in its metadata (``geometry``; files without it,
written before the sphere, are disks) and its ``code_version`` is that body's solver digest
(:func:`restitution.provenance.code_version`); :func:`_metadata` writes them with the body's
model (:data:`MODELS`) and units (:func:`law_units`).

Exports (all carry the body, the model, every parameter, the package version and the date):

* JSON (:meth:`EpsilonLaw.to_json <restitution.laws.law.EpsilonLaw.to_json>`,
  :func:`write_json`): metadata, the points and the fits behind every point;
* CSV (:func:`write_csv`): ``#`` metadata lines, then ``v,epsilon,epsilon_err,status``;
* a plain table (:func:`write_table`): ``#`` comments, then columns
  ``v epsilon epsilon_err checked`` of the interpolant on a uniform grid of the computed range,
  for event-driven and DEM codes (``checked`` is 1 where both neighbouring points passed their
  checks).

Reading (:func:`read_law`, :func:`law_from_dict`) refuses in one line what is not a law file, a
file changed after it was written and values that are not a law's, and says what writes the
file again. This module knows a law only by its attributes; the law's methods call it.
"""

from __future__ import annotations

import csv
import datetime
import json
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution._version import __version__
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, kinds
from restitution.errors import CorruptFileError, InputError, describe, is_integer, is_real, real
from restitution.jsonable import DIGEST_KEY, digest_matches, json_default, signed
from restitution.laws.law_point import QUASISTATIC_ROUTE
from restitution.provenance import code_version
from restitution.status import Status

__all__ = [
    "LAW_UNITS",
    "MAX_LAW_BYTES",
    "MODELS",
    "law_dict",
    "law_filename",
    "law_from_dict",
    "law_units",
    "plain_points",
    "read_law",
    "write_csv",
    "write_json",
    "write_table",
]

_FORMAT = "restitution-law"
_FORMAT_VERSION = 2  # 2: no anchor at v = 0; per-point settings and status

_DEFAULT = body_kind(DEFAULT_GEOMETRY)

MODEL = _DEFAULT.law_model
"""The model behind the laws of the default body, the paper's disk (its kind's
:attr:`~restitution.bodies.kinds.BodyKind.law_model`)."""

MODELS: dict[str, str] = {name: kind.law_model for name, kind in kinds().items()}
"""The model behind the laws of each of the package's bodies, by name (``model`` of a law's
metadata and exports): each kind's :attr:`~restitution.bodies.kinds.BodyKind.law_model`, which
:func:`law_units` and the laws read (also for a kind registered later)."""

LAW_UNITS = _DEFAULT.law_units
"""What a disk law's ``v`` and ``epsilon`` mean (the ``units`` of its metadata and exports, the
default kind's :attr:`~restitution.bodies.kinds.BodyKind.law_units`); :func:`law_units` gives
those of any body."""


PAIR_MODEL = (
    "Two free elastic {kind}s of radii R1 = 1 and R2 = radius_ratio (constants of the first, "
    "E1 = rho1 = 1; the second's in its units) meeting head-on, each expanded in its own free "
    "eigenmodes, the lowest N of both below one frequency; the potential V = (1/alpha) int "
    "exp(-alpha g) ds over the smaller body's surface, g the gap between surface points paired "
    "by their undeformed height (docs/two-disks.md); energy loss 1 - epsilon^2 of the relative "
    "motion extrapolated linearly in 1/alpha and in 1/sqrt(N)."
)
"""The model behind the laws of two bodies (``{kind}``: the bodies' kind)."""


def law_units(geometry: str = DEFAULT_GEOMETRY, partner=None) -> str:
    """What ``v`` and ``epsilon`` of a law of the body ``geometry`` mean (with a ``partner``:
    of the pair); the kind's :attr:`~restitution.bodies.kinds.BodyKind.law_units` on the
    wall."""
    found = body_kind(geometry)
    if partner is None:
        return found.law_units
    kind = found.geometry
    return (
        f"v is the relative normal speed of the two {kind}s' centres before the collision in "
        f"units of c1 = sqrt(E1/rho1) of the first {kind} (radius R1 = 1); the second has "
        f"R2/R1 = {partner.radius_ratio:g}, E2/E1 = {partner.modulus_ratio:g}, rho2/rho1 = "
        f"{partner.density_ratio:g}. epsilon = -w_after / w_before of the relative speed of the "
        "centres of mass."
    )


def _model(geometry: str, partner=None) -> str:
    """The ``model`` of a law of the body ``geometry`` (with a ``partner``: of the pair)."""
    kind = body_kind(geometry)
    return kind.law_model if partner is None else PAIR_MODEL.format(kind=kind.geometry)


MAX_LAW_BYTES = 64_000_000
"""The largest law file read (the shipped ones hold 0.2-0.9 MB): a device such as /dev/zero or
a runaway file is refused before it is read (issue 47: it grew without bound)."""


def _partner_fields(partner) -> list[tuple[str, str, str, float]]:
    """``(file tag, name, option, value)`` of each constant of ``partner`` that a law must name:
    the radius ratio always, the others where they are not the first body's."""
    fields = [("r", "R2/R1", "--radius-ratio", partner.radius_ratio)]
    if partner.modulus_ratio != 1.0:
        fields.append(("E", "E2/E1", "--modulus-ratio", partner.modulus_ratio))
    if partner.density_ratio != 1.0:
        fields.append(("rho", "rho2/rho1", "--density-ratio", partner.density_ratio))
    if partner.nu is not None:
        fields.append(("nu2", "nu2", "--partner-nu", partner.nu))
    return fields


def _file_prefix(geometry: str, partner=None) -> str:
    """``<head>_nu`` with ``<head>`` the kind's name of ``law``
    (:meth:`~restitution.bodies.kinds.BodyKind.file_name`): ``law_nu`` for the disk (the names
    of the first shipped files), ``law_<tag>_nu`` else; with a ``partner``
    ``<head>_pair_r<R2/R1>[_E<E2/E1>][_rho<rho2/rho1>][_nu2<nu2>]_nu`` (a sphere's
    ``law_sphere_pair_...``)."""
    head = body_kind(geometry).file_name("law")
    if partner is None:
        return f"{head}_nu"
    parts = [f"{tag}{value:g}" for tag, _, _, value in _partner_fields(partner)]
    return f"{head}_pair_{'_'.join(parts)}_nu"


def law_filename(nu: float, geometry: str = DEFAULT_GEOMETRY, partner=None) -> str:
    """File name of the law of the body ``geometry`` for ``nu`` (with a ``partner``, a
    :class:`~restitution.bodies.pair.partner.Partner`: of the pair).

    Examples
    --------
    >>> law_filename(0.33)
    'law_nu0.33.json'
    >>> law_filename(0.3, "sphere")
    'law_sphere_nu0.3.json'
    >>> from restitution.bodies.pair import Partner
    >>> law_filename(0.33, partner=Partner(radius_ratio=1.4))
    'law_pair_r1.4_nu0.33.json'
    """
    return f"{_file_prefix(geometry, partner)}{float(nu):g}.json"


def _file_nu(name: str, geometry: str, partner=None) -> float | None:
    """The ``nu`` of a law file name of the body ``geometry`` (and ``partner``); ``None`` for
    other names."""
    prefix = _file_prefix(geometry, partner)
    if not (name.startswith(prefix) and name.endswith(".json")):
        return None
    try:
        return float(name[len(prefix) : -len(".json")])
    except ValueError:
        return None


def _curve_command(geometry: str, nu: float | None = None, partner=None) -> str:
    """The command that computes a law file of ``geometry`` (and ``partner``) for ``nu``
    (``NU`` if none)."""
    kind = body_kind(geometry)
    flag = f" {kind.option}" if kind.option else ""
    value = "NU" if nu is None else f"{float(nu):.6g}"
    pair = ""
    if partner is not None:
        pair = "".join(f" {option} {value:g}" for _, _, option, value in _partner_fields(partner))
    # The shipped laws' settings where they exist (a body on the wall, two bodies of one
    # material of a kind with a pair production: two disks).
    same = partner is None or (kind.pair_production is not None and partner.same_material)
    production = " --production" if same else ""
    return f"restitution curve{flag} --nu {value}{pair}{production} --out DIR"


def _describe(partner) -> str:
    """``R2/R1 = 1.4`` (and the other ratios and ``nu2`` where they are not the first body's)."""
    return ", ".join(f"{name} = {value:g}" for _, name, _, value in _partner_fields(partner))


# -- what a file stores --------------------------------------------------------------------------


def _check_file_values(nu, points) -> None:
    """:class:`InputError` naming the first entry of a law file that is not what it must be:
    ``nu``, every point's ``v``, ``epsilon`` and ``epsilon_err`` numbers (a JSON bool, string
    or null is not), ``asymptotic_ok`` a bool."""
    if not is_real(nu):
        raise InputError(f"its nu is {describe(nu)}, not a number")
    if not isinstance(points, list):
        raise InputError(f"its points are {describe(points)}, not a list")
    for k, point in enumerate(points):
        if not isinstance(point, dict):
            raise InputError(f"its point {k} is {describe(point)}, not an object")
        for key in ("v", "epsilon", "epsilon_err"):
            if key in point and not is_real(point[key]):
                raise InputError(
                    f"its point {k} holds {key} = {describe(point[key])}, not a number"
                )
        if "asymptotic_ok" in point and not isinstance(point["asymptotic_ok"], bool):
            raise InputError(
                f"its point {k} holds asymptotic_ok = {describe(point['asymptotic_ok'])}, not "
                "true or false"
            )


def _check_file_partner(stored) -> None:
    """:class:`InputError` unless a law file's ``partner`` is absent or a partner's key."""
    from restitution.bodies.pair.partner import Partner

    if stored is None:
        return
    try:
        Partner.from_key(stored)
    except (TypeError, ValueError, AttributeError):  # InputError is a ValueError
        raise InputError(
            f"its partner is {describe(stored)}, not an object of radius_ratio, modulus_ratio, "
            "density_ratio and nu"
        ) from None


def _check_path(path) -> None:
    """One-line :class:`InputError` unless ``path`` is a file path (``str`` or path-like)."""
    if not isinstance(path, str | os.PathLike):
        raise InputError(
            f"path must be the path of a law JSON file (a str or pathlib.Path), got "
            f"{describe(path)}; pass e.g. path='DIR/law_nu0.33.json'"
        )


def _rewrite_advice(d) -> str:
    """What to do about a damaged law file ``d`` (its parsed JSON): the command that writes it
    again (of its body and ``nu`` where its metadata say them), or load another."""
    meta = d.get("metadata") if isinstance(d, dict) else None
    command = _curve_command(DEFAULT_GEOMETRY)
    if isinstance(meta, dict):
        try:
            partner = meta.get("partner")
            if partner is not None:
                from restitution.bodies.pair.partner import Partner

                partner = Partner.from_key(partner)
            geometry = body_kind(meta.get("geometry", DEFAULT_GEOMETRY)).geometry
            command = _curve_command(geometry, real(meta["nu"], "nu"), partner)
        except (KeyError, TypeError, ValueError, AttributeError):  # InputError is a ValueError
            pass
    return (
        f"write it again with the command that wrote it (`{command}`; `restitution law ... "
        "--compute` computes a damaged law of its cache again by itself), or load another"
    )


def _metadata(
    nu: float, parameters: Mapping, geometry: str = DEFAULT_GEOMETRY, partner=None
) -> dict:
    geometry = body_kind(geometry).geometry
    out = {
        "geometry": geometry,
        "nu": float(nu),
        "model": _model(geometry, partner),
        "units": law_units(geometry, partner),
        "parameters": {"nu": float(nu), "E": 1.0, "rho": 1.0, "R": 1.0, **parameters},
        "package": "restitution",
        "version": __version__,
        "code_version": code_version(geometry, pair=partner is not None),
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "interpolant": "scipy.interpolate.PchipInterpolator through the computed points only",
    }
    if partner is not None:
        out["partner"] = partner.to_dict()
    return out


# -- reading -------------------------------------------------------------------------------------


def read_law(cls, path: str | os.PathLike, *, require_digest: bool = False):
    """The law of the file at ``path`` (a :class:`~restitution.laws.law.EpsilonLaw` class
    ``cls``), as :meth:`EpsilonLaw.from_json <restitution.laws.law.EpsilonLaw.from_json>` reads
    it: a file with a content digest is checked against it; one without, unless
    ``require_digest``, loads when its values are those of a law."""
    _check_path(path)
    path = Path(path)
    try:
        if path.exists() and not path.is_file():
            raise ValueError("not a regular file")
        size = path.stat().st_size
        if size > MAX_LAW_BYTES:
            raise ValueError(
                f"{size / 1e6:.0f} MB, more than a law file's {MAX_LAW_BYTES / 1e6:.0f} MB"
            )
        d = json.loads(path.read_text())
    except (OSError, ValueError, RecursionError) as exc:
        why = "nested too deeply" if isinstance(exc, RecursionError) else exc
        raise InputError(
            f"cannot read law file {path}: {why}; give the path of a law JSON file"
        ) from None
    if require_digest and isinstance(d, dict) and DIGEST_KEY not in d:
        raise CorruptFileError(
            f"{path} carries no content digest (written by hand or by an older restitution), "
            f"so it cannot be verified; {_rewrite_advice(d)}",
            reason="it carries no content digest, so it cannot be verified",
        )
    return cls._from_dict(d, str(path))


def law_from_dict(cls, d: dict, source: str):
    """The law (``cls``) of a law file's parsed JSON ``d``; ``source`` names the file in the
    refusals, which say what writes it again."""
    if not isinstance(d, dict) or d.get("format") != _FORMAT:
        raise InputError(
            f"{source} is not a restitution law file (format {_FORMAT!r}); give a file "
            "written by restitution curve or EpsilonLaw.to_json"
        )
    again = _rewrite_advice(d)
    try:
        intact = digest_matches(d)
    except (ValueError, TypeError, RecursionError):  # not canonical JSON: not as written
        intact = False
    if intact is False:
        raise CorruptFileError(
            f"{source} was changed after it was written (its content no longer matches its "
            f"digest), so none of its numbers is served; {again}"
        )
    if d.get("format_version") not in (1, _FORMAT_VERSION):
        raise InputError(
            f"{source} has law format version {d.get('format_version')}; this code reads "
            f"1 and {_FORMAT_VERSION} ({again})"
        )
    # Version 1 files also described an anchor epsilon(0) = 1; it is not used any more.
    try:
        if not isinstance(d.get("metadata"), dict):
            raise InputError(f"its metadata are {describe(d.get('metadata'))}, not an object")
        points = d["metadata"]["points"]
        metadata = dict(d["metadata"])
        metadata["source"] = source
        # Files from before the sphere: disks, the default kind.
        geometry = metadata.get("geometry", DEFAULT_GEOMETRY)
        body_kind(geometry)
        _check_file_values(metadata["nu"], points)
        _check_file_partner(metadata.get("partner"))
        arrays = {
            "nu": float(d["metadata"]["nu"]),
            "v": np.array([p["v"] for p in points], dtype=float),
            "epsilon_points": np.array([p["epsilon"] for p in points], dtype=float),
            "epsilon_err_points": np.array([p["epsilon_err"] for p in points], dtype=float),
            "asymptotic_ok": np.array([p["asymptotic_ok"] for p in points], dtype=bool),
        }
    except KeyError as exc:
        raise InputError(
            f"{source} is not a valid law file: it lacks the key {exc} ({again})"
        ) from None
    except (TypeError, ValueError) as exc:  # InputError is a ValueError
        raise InputError(f"{source} is not a valid law file: {exc} ({again})") from None
    eps, err = arrays["epsilon_points"], arrays["epsilon_err_points"]
    bad = np.flatnonzero(~((eps > 0) & (eps <= 1) & np.isfinite(err) & (err >= 0)))
    if bad.size:
        k = int(bad[0])
        raise InputError(
            f"{source} is not a valid law file: at v = {arrays['v'][k]:g} it holds epsilon "
            f"= {float(eps[k])!r} +- {float(err[k])!r}; an elastic body's law has "
            f"0 < epsilon <= 1 and a finite error >= 0 ({again})"
        )
    try:
        return cls(**arrays, metadata=metadata)
    except InputError as exc:
        raise InputError(f"{source} is not a valid law file: {exc} ({again})") from None


# -- writing -------------------------------------------------------------------------------------


def law_dict(law) -> dict:
    """The JSON-ready dictionary of ``law`` (the JSON export's content; :meth:`EpsilonLaw.to_dict
    <restitution.laws.law.EpsilonLaw.to_dict>`)."""
    meta = dict(law.metadata)
    meta.pop("source", None)
    meta.setdefault("points", plain_points(law))
    meta["validity"] = _validity(law)
    return {"format": _FORMAT, "format_version": _FORMAT_VERSION, "metadata": meta}


def plain_points(law) -> list[dict]:
    """The records of ``law``'s points as its JSON writes them when its metadata hold none."""
    return [
        {
            "v": p.v,
            "epsilon": p.epsilon,
            "epsilon_err": p.epsilon_err,
            "asymptotic_ok": p.status == Status.OK,
            "status": p.status,
            "route": QUASISTATIC_ROUTE if p.status == Status.QUASISTATIC else "modal",
            "message": p.message,
        }
        for p in law.points
    ]


def _validity(law) -> dict:
    lo, hi = law.valid_range
    n_ok = int(np.sum(law.asymptotic_ok))
    quasi = law.quasistatic
    low = (
        f"{int(quasi.sum())} come from the low-speed theory ('quasistatic', "
        f"{law.v[quasi][0]:g} <= v <= {law.v[quasi][-1]:g}), "
        if quasi.any()
        else ""
    )
    return {
        "v_min": lo,
        "v_max": hi,
        "note": (
            f"computed for {lo:g} <= v <= {hi:g} c; nothing outside is served (no "
            f"extrapolation, no anchor at v = 0); {n_ok} of {law.v.size} points pass their "
            f"extrapolation checks, {low}the others are flagged 'not-asymptotic'"
        ),
        "monotone": law.monotone,
        "points_ok": n_ok,
        "points": int(law.v.size),
    }


def write_json(law, path: str | os.PathLike) -> Path:
    """Write the JSON export of ``law`` (:func:`law_dict`) with its content digest; returns the
    path (:meth:`EpsilonLaw.to_json <restitution.laws.law.EpsilonLaw.to_json>`).

    The document's top-level ``"digest"`` is ``"sha256:<hex>"``, the SHA-256 of the
    canonical JSON of the rest of the document as a reader parses it
    (:func:`restitution.jsonable.canonical_json`: ``json.dumps(doc, sort_keys=True,
    separators=(",", ":"), ensure_ascii=True)``); :func:`read_law` refuses a file whose
    content no longer matches it (:class:`~restitution.errors.CorruptFileError`).
    """
    path = Path(path)
    atomic.write_text(path, json.dumps(signed(law.to_dict()), indent=1, allow_nan=False))
    return path


def _header_lines(law) -> list[str]:
    meta = {k: v for k, v in law.metadata.items() if k not in ("points", "dropped")}
    lines = [
        f"restitution law epsilon(v) of the {law.body_name}, nu = {law.nu:g}",
        f"package: restitution {meta.get('version', __version__)} "
        f"(code {meta.get('code_version', '?')}); date: {meta.get('date')}",
        f"body: {law.body_name}",
        f"model: {_model(law.geometry, law.partner)}",
        f"units: {law_units(law.geometry, law.partner)}",
        f"validity: {_validity(law)['note']}",
        "parameters: " + json.dumps(meta.get("parameters", {}), default=json_default),
    ]
    return lines


def write_csv(law, path: str | os.PathLike) -> Path:
    """Write the points of ``law`` as CSV with ``#`` metadata lines; returns the path."""
    path = Path(path)
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        for line in _header_lines(law):
            fh.write(f"# {line}\n")
        writer = csv.writer(fh)
        writer.writerow(["v", "epsilon", "epsilon_err", "asymptotic_ok", "status"])
        for p in law.points:
            writer.writerow(
                [
                    repr(p.v),
                    repr(p.epsilon),
                    repr(p.epsilon_err),
                    int(p.status == Status.OK),
                    p.status,
                ]
            )
    return path


def write_table(law, path: str | os.PathLike, *, points: int = 301) -> Path:
    """Write ``v epsilon epsilon_err checked`` of the interpolant of ``law`` on a grid of its
    range.

    The grid is uniform in ``log v`` from ``v_min`` to ``v_max`` and contains every computed
    speed. ``checked`` is 1 where both neighbouring computed points passed their checks,
    else 0. A plain whitespace table with ``#`` comment lines, for event-driven and DEM
    codes that interpolate linearly; returns the path.
    """
    if not (is_integer(points) and points >= 2):
        raise InputError(
            f"points must be an integer >= 2 (rows of the table), got {describe(points)}; "
            "pass e.g. points=301"
        )
    lo, hi = law.valid_range
    v = np.unique(np.r_[np.geomspace(lo, hi, points), law.v])
    table = np.column_stack([v, law.epsilon(v), law.epsilon_err(v), law.checked(v).astype(float)])
    header = "\n".join(
        [
            *_header_lines(law),
            "columns: v [c]  epsilon  epsilon_err  checked (PCHIP interpolant of the points)",
        ]
    )
    with atomic.replacing(path) as tmp:
        np.savetxt(tmp, table, fmt=["%.8g", "%.8f", "%.8f", "%d"], header=header, comments="# ")
    return Path(path)
