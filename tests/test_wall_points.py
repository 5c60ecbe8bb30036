"""The finite elements' stored points of a wall, served where the routes have no value
(restitution.laws.wall_points, issue 42)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from restitution.bodies.wall import HalfSpace, Plate
from restitution.estimate import Estimate
from restitution.laws.wall_points import (
    SPEED_MATCH,
    WallReferencePoint,
    load_wall_reference,
    stored_wall_point,
)

GLASS = (0.3, 2500.0 / 7850.0, 0.2481)


def _point(wall, v=2e-3, eps=0.9, err=1e-5, ok=True):
    loss = 1.0 - eps * eps
    estimate = Estimate(eps, err, "ok" if ok else "not-asymptotic")
    return WallReferencePoint(0.3, wall, v, estimate, loss, 2.0 * eps * err)


def test_a_stored_point_answers_its_ball_wall_and_speed():
    plate = Plate(*GLASS, thickness=4.0)
    points = [_point(HalfSpace(*GLASS), eps=0.98), _point(plate)]
    found = stored_wall_point(0.3, Plate(*GLASS, thickness=4.0), 2e-3, points)
    assert found["epsilon"] == 0.9 and found["epsilon_err"] == pytest.approx(1e-5, rel=1e-12)
    assert found["route"].startswith("finite elements") and found["status"] == "ok"
    # the block is another wall; a thicker plate, another ball or speed: nothing stored
    assert stored_wall_point(0.3, HalfSpace(*GLASS), 2e-3, points)["epsilon"] == 0.98
    assert stored_wall_point(0.3, Plate(*GLASS, thickness=4.4), 2e-3, points) is None
    assert stored_wall_point(0.25, plate, 2e-3, points) is None
    assert stored_wall_point(0.3, plate, 2e-3 * (1.0 + 2.0 * SPEED_MATCH), points) is None
    flagged = stored_wall_point(0.3, plate, 2e-3, [_point(plate, ok=False)])
    assert flagged["status"] == "not-asymptotic"


def test_a_nearby_speed_widens_the_error_by_the_bound_on_the_change():
    """A loss L ~ v^p with p <= 1 moves epsilon by at most eps - sqrt(eps^2 - L (v/v_s - 1))
    (to first order L / (2 eps) ln(v / v_s)); a loss that follows v^1 exactly (the bound's
    edge) stays inside the widened error, one that follows v^(3/5) well inside."""
    plate = Plate(*GLASS, thickness=4.0)
    v_s, eps = 2e-3, 0.9
    loss = 1.0 - eps * eps
    v = v_s * math.exp(0.5 * SPEED_MATCH)
    found = stored_wall_point(0.3, plate, v, [_point(plate, v=v_s, eps=eps, err=0.0)])
    eps_at_v = math.sqrt(1.0 - loss * v / v_s)  # the steepest loss the bound allows
    assert abs(eps_at_v - found["epsilon"]) <= found["epsilon_err"] * (1.0 + 1e-9)
    half_space_like = math.sqrt(1.0 - loss * (v / v_s) ** 0.6)
    assert abs(half_space_like - found["epsilon"]) < 0.7 * found["epsilon_err"]
    assert found["epsilon_err"] == pytest.approx(loss / (2.0 * eps) * 0.5 * SPEED_MATCH, rel=1e-3)


def test_the_shipped_points_load():
    points = load_wall_reference()
    assert len(points) >= 4
    assert all(isinstance(p.wall, HalfSpace) and 0 < p.epsilon < 1 for p in points)


def test_the_advice_s_command_computes_the_point_the_next_call_serves(tmp_path, monkeypatch):
    """The advice of an outside plate speed (`compute_command`) names a file in the user's
    point folder and a point the FEM command line parses back into the same ball, wall and
    speed; a file of that form placed there (here a shipped plate point, moved to 9
    m/s: plumbing only, not a physical value) is served by the next call."""
    import json
    import shlex
    from importlib import resources

    from restitution.fem.wall_reference import _parse_point
    from restitution.laws.wall_points import compute_command, user_points_dir

    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path))
    plate = Plate(*GLASS, thickness=4.0)
    v = 9.0 / math.sqrt(210e9 / 7850.0)
    assert stored_wall_point(0.3, plate, v) is None
    words = shlex.split(compute_command(0.3, plate.to_dict(), v))
    out, point = Path(words[3]), words[4]
    assert out.parent == user_points_dir() == tmp_path / "fem_wall"
    ratios = tuple(float(words[i + 1]) for i in (5, 7, 9))
    nu, wall, v_parsed = _parse_point(point, ratios)[:3]
    assert (nu, wall) == (0.3, plate) and v_parsed == pytest.approx(v, rel=1e-12)
    shipped = json.loads(
        resources.files("restitution.laws").joinpath("data", "fem_reference_wall.json").read_text()
    )
    doc = {**shipped, "points": [dict(shipped["points"][-1], v=v_parsed, wall=plate.to_dict())]}
    out.parent.mkdir(parents=True)
    out.write_text(json.dumps(doc))
    found = stored_wall_point(0.3, plate, v)
    assert found is not None and found["epsilon"] == doc["points"][0]["epsilon"]
