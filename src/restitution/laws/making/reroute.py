"""Points of a computed law replaced by another route's (issue 65, item 2).

The shipped disk laws' slowest modal points fail their checks: their ``N``-extrapolation from
10^4-10^5 modes is curved (docs/numerics.md). The residual route
(:func:`restitution.limits.residual_point.residual_point`) converges there in ``N`` and agrees
with the finite elements. :func:`rerouted` puts such points into a law in place of the ones at
the same speeds and says so: every collision point carries its ``route`` (``"modal"`` for the
points kept, the replacing route's for the new ones; the low-speed points keep
``"quasistatic"``), the law's ``metadata["rerouted"]`` lists each replaced speed with the value,
error and status it had and has, why, and where the new points come from, and the model
sentence names both routes. Nothing is computed here: the points come in as records
(:func:`restitution.laws.making.residual_law.residual_record`).

Units: the law's (``v`` in ``c``; epsilon and its errors dimensionless).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from restitution import atomic
from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_point import QUASISTATIC_ROUTE

__all__ = ["MODAL_ROUTE", "before_rerouting", "rerouted", "write_shipped"]

MODAL_ROUTE = "modal"
"""``route`` of a point of collisions extrapolated in ``N`` and ``alpha``."""

_KEPT = ("epsilon", "epsilon_err", "status")


def _same(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * abs(b)


def _law_of(nu: float, merged: list[dict], metadata: dict) -> EpsilonLaw:
    """The law of the point records ``merged`` (as ``metadata["points"]`` holds them)."""
    return EpsilonLaw(
        nu=nu,
        v=np.array([float(r["v"]) for r in merged]),
        epsilon_points=np.array([float(r["epsilon"]) for r in merged]),
        epsilon_err_points=np.array([float(r["epsilon_err"]) for r in merged]),
        asymptotic_ok=np.array([bool(r["asymptotic_ok"]) for r in merged]),
        metadata=metadata,
    )


def rerouted(law_: EpsilonLaw, records: list[dict], *, parameters: Mapping) -> EpsilonLaw:
    """``law_`` with its collision points at the speeds of ``records`` replaced by them.

    Parameters
    ----------
    law_ : EpsilonLaw
        A law whose metadata hold its point records (every law this package computes).
    records : list of dict
        One per replaced point, as ``metadata["points"]`` holds them (``v``, ``epsilon``,
        ``epsilon_err``, ``asymptotic_ok``, ``status``, ``route``, ...); each ``v`` a speed of
        a collision point of ``law_`` (not a low-speed point), each ``route`` given.
    parameters : mapping
        Why and from where (``reason``, ``source``, the route's settings and code version):
        stored in ``metadata["rerouted"]`` with the list of replaced speeds.
    """
    own = law_._records() if law_.metadata.get("points") else []
    if not own:
        raise InputError("this law stores no point records; only computed laws can be rerouted")
    if not records:
        raise InputError("no points to put in; give at least one record")
    merged = [dict(r) for r in own]
    for r in merged:
        if r.get("route") != QUASISTATIC_ROUTE:
            r.setdefault("route", MODAL_ROUTE)
    changes = list((law_.metadata.get("rerouted") or {}).get("points", []))
    for new in records:
        if not new.get("route"):
            raise InputError(f"the point at v = {new.get('v')!r} names no route; give its route")
        at = [
            j
            for j, r in enumerate(merged)
            if _same(float(r["v"]), float(new["v"])) and r["route"] != QUASISTATIC_ROUTE
        ]
        if not at:
            raise InputError(
                f"v = {new['v']:g} is not a collision point of the {law_.body_name} law; "
                "give speeds of its modal points"
            )
        old = merged[at[0]]
        changes.append(
            {
                "v": float(old["v"]),
                "from": {"route": old["route"], **{k: old.get(k) for k in _KEPT}},
                "to": {"route": new["route"], **{k: new.get(k) for k in _KEPT}},
            }
        )
        merged[at[0]] = {**new, "v": float(old["v"])}
    routes = sorted({c["to"]["route"] for c in changes})
    metadata = dict(law_.metadata)
    metadata["points"] = merged
    metadata["rerouted"] = {**dict(parameters), "routes": routes, "points": changes}
    model = str(metadata.get("model", ""))
    note = (
        f" The collision points of route {', '.join(repr(r) for r in routes)} (listed under "
        "'rerouted') were computed by that route instead."
    )
    if note not in model:
        metadata["model"] = model + note
    return _law_of(law_.nu, merged, metadata)


def before_rerouting(law_: EpsilonLaw) -> EpsilonLaw:
    """``law_`` with the points it had before :func:`rerouted`: at every speed its
    ``metadata["rerouted"]`` lists, the value, error and status it replaced (the first, if a
    speed was replaced twice), a record of the route named there; ``law_`` itself if nothing
    was rerouted. What each route computed, for judging that route on its own values
    (:mod:`restitution.fem.calibrate`)."""
    changes = (law_.metadata.get("rerouted") or {}).get("points") or []
    if not changes:
        return law_
    first: dict[float, dict] = {}
    for change in changes:
        first.setdefault(float(change["v"]), change["from"])
    merged = [dict(r) for r in law_._records()]
    for j, r in enumerate(merged):
        old = next((o for v, o in first.items() if _same(float(r["v"]), v)), None)
        if old is not None and r.get("route") != QUASISTATIC_ROUTE:
            merged[j] = {
                "v": float(r["v"]),
                **{k: old.get(k) for k in _KEPT},
                "asymptotic_ok": old.get("status") == "ok",
                "route": old.get("route") or MODAL_ROUTE,
            }
    metadata = {k: v for k, v in law_.metadata.items() if k != "rerouted"}
    metadata["points"] = merged
    return _law_of(law_.nu, merged, metadata)


def write_shipped(law_: EpsilonLaw, path: str | os.PathLike) -> Path:
    """Write ``law_`` as the shipped laws are stored: its JSON export (:meth:`EpsilonLaw.to_dict
    <restitution.laws.law.EpsilonLaw.to_dict>`, one space of indent) without a content digest,
    so a shipped file read back and written again is unchanged byte for byte."""
    path = Path(path)
    atomic.write_text(path, json.dumps(law_.to_dict(), indent=1, allow_nan=False))
    return path
