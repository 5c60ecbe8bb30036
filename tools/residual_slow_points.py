"""The residual route at the shipped disk laws' points that fail their checks (issue 65, item 2).

Every modal point of the shipped disk laws (``law_nu*.json``, the points without a ``route`` or
with ``route: "modal"``) whose status is not ``ok`` is computed again by the residual route
(:func:`restitution.limits.residual_point.residual_point` with its defaults: the law's three
walls, 200, 400 and 800 kept modes, 80 nodes across the contact), one point at a time on one
process, the finite-element points first (``nu = 0.2, 0.33, 0.9`` at ``v = 1e-4, 2e-4``).
Each point is written to ``OUT`` as soon as it is done (the whole file, atomically), with the
shipped point beside it and, where one exists, the finite-element reference at its speed
(``laws/data/fem_reference.json``, ``tests/data/fem_slow_points.json``); a rerun keeps the points
already in ``OUT`` of the same code version.

A point that stays curved in ``1/alpha`` on the law's walls is computed again on harder walls
(:data:`HARDER_WALLS`). With ``--apply`` the shipped laws then take the points that pass their
checks and, where a
finite-element reference exists, lie within one combined error of it
(:func:`restitution.laws.making.reroute.rerouted`, written by
:func:`~restitution.laws.making.reroute.write_shipped`); the others stay as they are.

Usage (from the project's root, with its venv)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/residual_slow_points.py \
        tests/data/residual_slow_points.json [--only-fem] [--apply]
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import scipy

from restitution import atomic
from restitution.laws.law import EpsilonLaw
from restitution.laws.making.reroute import rerouted, write_shipped
from restitution.laws.making.residual_law import _version, residual_record
from restitution.limits.residual_point import NODES_PER_CONTACT, RESIDUAL_MODES, residual_point

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "src" / "restitution" / "laws" / "data"
FEM_FILES = (DATA / "fem_reference.json", ROOT / "tests" / "data" / "fem_slow_points.json")
FEM_POINTS = ((0.2, 1e-4), (0.2, 2e-4), (0.33, 1e-4), (0.33, 2e-4), (0.9, 1e-4), (0.9, 2e-4))


def failing_points() -> list[tuple[float, float, dict]]:
    """``(nu, v, shipped record)`` of every modal point of a shipped disk law not ``ok``, and of
    every such point replaced before (``metadata["rerouted"]``: the record it replaced)."""
    out = []
    for path in sorted(DATA.glob("law_nu*.json")):
        meta = json.loads(path.read_text())["metadata"]
        for p in meta["points"]:
            if p.get("route") in (None, "modal") and p["status"] != "ok":
                out.append((float(meta["nu"]), float(p["v"]), p))
        for change in (meta.get("rerouted") or {}).get("points", []):
            # The failing modal point replaced; not a later change of the residual point's
            # walls, nor a modal point that passed and is served from harder walls
            # (tools/residual_wall_ladder.py --modal).
            was = change["from"]
            if was.get("route") in (None, "modal") and was["status"] != "ok":
                out.append((float(meta["nu"]), float(change["v"]), change["from"]))
    first = {(nu, v) for nu, v in FEM_POINTS}
    return sorted(out, key=lambda t: ((t[0], t[1]) not in first, t[0], t[1]))


def fem_points() -> dict[tuple[float, float], dict]:
    """``(nu, v) -> {epsilon, epsilon_err, asymptotic_ok, file}`` of the disk's stored
    finite-element references."""
    out = {}
    for path in FEM_FILES:
        for p in json.loads(path.read_text())["points"]:
            if p.get("alpha") is None:
                out[(float(p["nu"]), float(p["v"]))] = {
                    "epsilon": p["epsilon"],
                    "epsilon_err": p["epsilon_err"],
                    "asymptotic_ok": p["asymptotic_ok"],
                    "file": str(path.relative_to(ROOT)),
                }
    return out


HARDER_WALLS = ((80.0, 160.0, 320.0), (160.0, 320.0, 640.0))
"""Where the law's walls (``alpha delta_max = 40, 80, 160``) leave a point curved in
``1/alpha``, the point again on walls two and four times as hard (the check's own advice: more
asymptotic points), in that order until one passes its checks; every try is stored under
``harder_walls`` (issue 65, item 2)."""


def _sigma(a: float, a_err: float, b: float, b_err: float) -> float:
    """``(a - b)`` in combined errors."""
    return (a - b) / float(np.hypot(a_err, b_err))


def _compared(record: dict, fem: dict | None) -> dict:
    """``record`` with the finite-element point at its speed (``None``: none) and both routes'
    distances from it in combined errors."""
    if fem is None:
        return {**record, "fem": None}
    shipped = record["shipped"]
    return {
        **record,
        "fem": {
            **fem,
            "sigma_residual": _sigma(
                record["epsilon"], record["epsilon_err"], fem["epsilon"], fem["epsilon_err"]
            ),
            "sigma_shipped": _sigma(
                shipped["epsilon"], shipped["epsilon_err"], fem["epsilon"], fem["epsilon_err"]
            ),
        },
    }


def accepted(record: dict) -> bool:
    """Whether a computed point may replace the shipped one: it passes its checks and lies
    within one combined error of the finite elements where they were computed."""
    fem = record.get("fem")
    return record["status"] == "ok" and (fem is None or abs(fem["sigma_residual"]) <= 1.0)


def chosen(record: dict) -> dict | None:
    """The record that replaces the shipped point: the point on the law's walls if
    :func:`accepted`, else the first accepted try on harder walls, else none."""
    for r in (record, *record.get("harder_walls", [])):
        if accepted(r):
            return r
    return None


def apply(doc: dict, source: str) -> list[str]:
    """Put the accepted points of ``doc`` into the shipped laws; one line per law."""
    lines = []
    for path in sorted(DATA.glob("law_nu*.json")):
        law_ = EpsilonLaw.from_json(path)
        mine = [c for p in doc["points"] if p["nu"] == law_.nu and (c := chosen(p)) is not None]
        if not mine:
            continue
        keys = (
            "nu",
            "wall_time_s",
            "load_average_1min",
            "date",
            "code_version",
            "shipped",
            "fem",
            "harder_walls",
        )
        records = [{k: v for k, v in p.items() if k not in keys} for p in mine]
        parameters = {
            "reason": (
                "issue 65, item 2: these collision points failed their checks by the modal "
                "route (its N-extrapolation curved or its drop-one test failed; at three speeds "
                "its wall limit 50-53 % curved against the 50 % tolerance); the residual route "
                "passes them and lies within one combined error of the finite elements where "
                "they were computed (docs/numerics.md)"
            ),
            "source": source,
            "function": doc["function"],
            "settings": doc["settings"],
            "code_version": doc["code_version"],
            "date": max(p["date"] for p in mine),
        }
        lines.append(reroute_and_write(law_, records, parameters, path, "replaced"))
    return lines


def reroute_and_write(law_, records, parameters, path, what: str) -> str:
    """Write ``law_`` with ``records`` put in (:func:`rerouted`) to ``path``; one line: how many
    points were ``what`` and how many collision points pass their checks."""
    new = rerouted(law_, records, parameters=parameters)
    write_shipped(new, path)
    ok = int(np.sum(new.asymptotic_ok & ~new.quasistatic))
    return (
        f"{path.name}: {len(records)} point(s) {what}; {ok} of "
        f"{int(np.sum(~new.quasistatic))} collision points pass"
    )


def _computed(nu, v, shipped, version, walls, fem) -> dict:
    """One residual point (``walls``: ``None`` for the law's) as stored, with its provenance
    and its distance from the finite elements; one line printed."""
    load = os.getloadavg()[0]
    start = time.perf_counter()
    record = residual_record(residual_point("disk", nu, v, walls=walls))
    record = {
        "nu": nu,
        **record,
        "wall_time_s": round(time.perf_counter() - start, 2),
        "load_average_1min": round(load, 2),
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "code_version": version,
        "shipped": {k: shipped.get(k) for k in ("epsilon", "epsilon_err", "status")},
    }
    print(
        f"nu={nu:<9g} v={v:<9g} walls {record['residual']['walls']} residual "
        f"{record['epsilon']:.7f} +- {record['epsilon_err']:.1e} ({record['status']}), shipped "
        f"{shipped['epsilon']:.7f} +- {shipped['epsilon_err']:.1e}; "
        f"{record['wall_time_s']:.1f} s",
        flush=True,
    )
    return _compared(record, fem)


def _command() -> str:
    return "tools/residual_slow_points.py " + " ".join(a for a in sys.argv[1:] if a != "--apply")


def environment() -> dict:
    """The versions and machine a tool's points are computed with, as its files store them."""
    return {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "machine": platform.machine(),
    }


def _git_commit() -> str:
    try:
        out = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True)
        return out.stdout.strip()
    except OSError:
        return ""


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--only-fem", action="store_true", help="only the six FE points")
    parser.add_argument("--apply", action="store_true", help="then put them into the laws")
    args = parser.parse_args(argv)
    version = _version("disk", False)
    kept = json.loads(args.out.read_text()) if args.out.exists() else {"points": []}
    done = {(p["nu"], p["v"]): p for p in kept["points"] if p.get("code_version") == version}
    todo = failing_points()
    if args.only_fem:
        todo = [t for t in todo if (t[0], t[1]) in set(FEM_POINTS)]
    doc = {
        "description": (
            "epsilon of the disk on the rigid wall by the residual route at the shipped disk "
            "laws' modal points that fail their checks (issue 65, item 2); beside each, the "
            "shipped point it would replace"
        ),
        "geometry": "disk",
        "units": "E = rho = R = 1 of the disk's constants; v in c (speed towards the wall)",
        "function": "restitution.limits.residual_point.residual_point(geometry, nu, v)",
        "command": kept.get("command") if len(done) >= len(todo) else _command(),
        "settings": {
            "modes": list(RESIDUAL_MODES),
            "nodes_per_contact": NODES_PER_CONTACT,
            "walls": "the disk's alpha_products (alpha delta_max = 40, 80, 160)",
            "harder_walls": [list(w) for w in HARDER_WALLS],
            "processes": 1,
            "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS"),
        },
        "code_version": version,
        # The commit the points were computed at: a rerun that computes none keeps it.
        "git_commit": kept.get("git_commit") if len(done) >= len(todo) else _git_commit(),
        "environment": environment(),
        "points": [],
    }
    fem = fem_points()
    points = []
    for nu, v, shipped in todo:
        if (nu, v) in done:
            points.append(_compared(done[(nu, v)], fem.get((nu, v))))
            continue
        record = _computed(nu, v, shipped, version, None, fem.get((nu, v)))
        if record["status"] != "ok":
            record["harder_walls"] = []
            for walls in HARDER_WALLS:
                again = _computed(nu, v, shipped, version, walls, fem.get((nu, v)))
                record["harder_walls"].append(again)
                if again["status"] == "ok":
                    break
        points.append(record)
        doc["points"] = points
        atomic.write_text(args.out, json.dumps(doc, indent=1) + "\n")
    doc["points"] = points
    atomic.write_text(args.out, json.dumps(doc, indent=1) + "\n")
    if args.apply:
        for line in apply(doc, str(args.out.resolve().relative_to(ROOT))):
            print(line, flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
