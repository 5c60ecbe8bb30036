"""The shipped epsilon(v) laws cannot go stale silently.

Every law file in ``restitution/laws/data`` is loaded and checked against the current code:

* no epsilon above 1, every error finite and positive;
* every point's extrapolation, redone by the current :mod:`restitution.limits.extrapolation`
  from the energy-loss grid stored in the file, gives the stored epsilon and the stored verdict,
  so a point that fails its checks cannot be served unflagged;
* a sample of the cheapest stored collisions (the smallest mode count, softest wall, at three
  speeds), recomputed with the current solver and the file's own settings, has moved by less
  than a tenth of its point's error. A changed solver hash with unmoved numbers is only
  reported.

The laws of two disks (``law_pair_*.json``, issue 27) are checked the same way, their sample
collisions recomputed on the pair of the file's partner.

Regenerate the files with ``make law`` (``make law-pair`` for the pairs) when this test fails.
"""

from __future__ import annotations

import json
import warnings
from importlib import resources

import numpy as np
import pytest

from restitution import get_modes
from restitution.bodies.pair import Partner
from restitution.dynamics.collision import CollisionSettings, collide
from restitution.limits.extrapolation import combined_limit
from restitution.provenance import code_version

_DATA = resources.files("restitution.laws").joinpath("data")
LAW_FILES = sorted(p.name for p in _DATA.iterdir() if p.name.startswith(("law_nu", "law_pair_r")))


def _load(name: str) -> dict:
    return json.loads(_DATA.joinpath(name).read_text())["metadata"]


def _settings(meta: dict, point: dict) -> dict:
    """The sweep settings behind ``point`` (per point since several groups make one law)."""
    return point.get("settings") or meta["parameters"]


def _modal(points: list[dict]) -> list[dict]:
    """The points from collisions (the low-speed points: tests/test_slow_disk.py)."""
    return [p for p in points if p.get("route") != "quasistatic"]


def test_there_are_shipped_laws():
    assert {"law_nu0.33.json", "law_nu0.9.json"} <= set(LAW_FILES)
    assert {"law_pair_r1.4_nu0.33.json", "law_pair_r2_nu0.9.json"} <= set(LAW_FILES)


@pytest.mark.parametrize("name", LAW_FILES)
def test_points_are_physical_and_their_flags_truthful(name):
    meta = _load(name)
    for p in meta["points"]:
        assert p["epsilon"] <= 1.0, (p["v"], p["epsilon"])
        assert np.isfinite(p["epsilon_err"]) and p["epsilon_err"] > 0
    for p in _modal(meta["points"]):
        order = _settings(meta, p)["order"]
        ex = p["extrapolation"]
        redo = combined_limit(
            ex["alpha"],
            ex["n_modes"],
            np.array(ex["energy_loss_grid"], dtype=float),
            order=order,
        )
        assert redo.epsilon == pytest.approx(p["epsilon"], rel=0, abs=1e-12), p["v"]
        assert redo.epsilon_err == pytest.approx(p["epsilon_err"], rel=1e-9), p["v"]
        # The stored verdict is the current code's verdict: a failing point is flagged.
        assert bool(redo.asymptotic_ok) == bool(p["asymptotic_ok"]), (p["v"], redo.message)


@pytest.mark.parametrize("name", LAW_FILES)
def test_cheap_collisions_have_not_moved(name):
    meta = _load(name)
    points = _modal(meta["points"])
    # The cheapest collisions: the points whose smallest mode set is the smallest of the law
    # (the slow points need 1e4-1e5 modes and are checked through their stored grids above).
    smallest = min(min(p["extrapolation"]["n_modes"]) for p in points)
    cheap = [p for p in points if min(p["extrapolation"]["n_modes"]) == smallest]
    sample = [cheap[0], cheap[len(cheap) // 2], cheap[-1]]
    moved = []
    for p in sample:
        params = _settings(meta, p)
        if params.get("select", "lowest") != "lowest":
            pytest.fail(f"{name}: the sample recomputation knows only the 'lowest' selection")
        settings = CollisionSettings(integrator=params["integrator"], **params["options"])
        ex = p["extrapolation"]
        j = int(np.argmin(ex["n_modes"]))
        i = int(np.argmin(ex["alpha"]))
        stored = ex["energy_loss_grid"][i][j]
        partner = meta.get("partner")
        if partner is None:
            modes = get_modes(meta["nu"], count=int(ex["n_modes"][j]))
        else:
            modes = Partner.from_key(partner).pair(meta["nu"], int(ex["n_modes"][j]))
        r = collide(modes, p["v"], ex["alpha"][i], settings)
        now = 1.0 - r.epsilon**2
        moved.append(abs(now - stored) / p["energy_loss_err"])
        assert abs(now - stored) <= 0.1 * p["energy_loss_err"], (
            f"{name}: the collision at v = {p['v']}, alpha = {ex['alpha'][i]:.4g}, "
            f"N = {ex['n_modes'][j]} moved from {stored:.8f} to {now:.8f}, more than a tenth "
            f"of the point's error {p['energy_loss_err']:.2e}; regenerate with `make law`"
        )
    now = code_version("disk", pair="partner" in meta)
    if meta["code_version"] != now:
        warnings.warn(
            f"{name} was computed with code {meta['code_version']}, this is {now}; "
            f"its sampled collisions moved by at most {max(moved):.1e} of their point errors",
            stacklevel=1,
        )
