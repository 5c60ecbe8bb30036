"""``restitution law --compute``: the law of the user's exact Poisson number (issue 28).

The production settings take minutes (disk) to a quarter of an hour (a pair) per law; here the
sweeps are replaced by one tiny group (few modes, soft walls) so that the whole path runs in
seconds: the estimate stated before the work, the law file written into the cache and served, the
next call served from that file without computing, and the refusals.
"""

from __future__ import annotations

import csv
import io
import json
from dataclasses import replace

import pytest
from _cli_checks import one_line_error

from restitution.bodies.kinds import KINDS, SweepPlan
from restitution.laws.making import compute, production
from restitution.limits.sweep import SweepSettings

STEEL = ("--E", "200e9", "--nu", "0.27", "--rho", "7800", "--geometry", "cylinder", "--against",
         "wall")  # fmt: skip
"""A steel-like cylinder: nu_2d = 0.27 / 0.73 = 0.369863, between the shipped 0.33 and 3/7."""

TINY_LOW = (2e-6, 2e-5)

TINY = SweepSettings(velocities=(0.1, 0.2, 0.3), alphas=(40.0, 80.0, 160.0), n_modes=(40, 60, 80),
                     batch_size=3)  # fmt: skip


@pytest.fixture
def tiny(monkeypatch, tmp_path):
    """One tiny sweep and two low-speed points instead of the production groups and speeds, the
    cache in ``tmp_path``."""
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    disk = KINDS["disk"]
    tiny_plan = SweepPlan(TINY.velocities, TINY.n_modes, TINY.batch_size)
    plan = replace(disk.production, groups=(tiny_plan,), low_speeds=TINY_LOW)
    monkeypatch.setitem(KINDS, "disk", replace(disk, production=plan))
    assert production.production_groups("disk") == (TINY,)
    return tmp_path


@pytest.mark.slow  # 8-18 s of the default run (issue 45: the default run under 10 min)
def test_computes_the_exact_nu_once_then_serves_the_file(cli, tiny, monkeypatch):
    args = ("law", *STEEL, "--speed", "1000", "--compute", "--store", str(tiny / "s.sqlite"))
    code, out, err = cli(*args, "--json")
    assert code == 0, err
    # The estimate, before the work: 27 collisions and at most one refining point in each of
    # the 2 intervals (3 x 3 grids; restitution.laws.making.refine).
    assert "45 collisions" in err and "into" in err
    d = json.loads(out)
    path = tiny / "cache" / "laws" / "law_nu0.369863.json"
    assert path.is_file()
    assert d["inputs"]["compute"] is True and d["inputs"]["law_file"] is None
    assert d["law"]["nu"] == pytest.approx(0.27 / 0.73, abs=1e-6)
    (point,) = d["points"]
    assert point["status"] in ("computed", "computed-not-asymptotic", "interpolated",
                               "interpolated-not-asymptotic")  # fmt: skip
    # Served from the law file: the same numbers as the file gives through --law-file.
    code, out2, err = cli("law", *STEEL, "--speed", "1000", "--law-file", str(path), "--json")
    assert json.loads(out2)["points"] == d["points"]

    # The next call finds the file and computes nothing.
    def refuse(*a, **k):
        raise AssertionError("computed again")

    monkeypatch.setattr("restitution.laws.making.production.build", refuse)
    code, out3, err = cli(*args, "--json")
    assert code == 0 and "using the law computed before" in err
    assert json.loads(out3)["points"] == d["points"]


def test_a_shipped_nu_is_not_computed(cli, tiny, monkeypatch):
    monkeypatch.setattr("restitution.laws.making.production.build", pytest.fail)
    code, out, err = cli("law", "--E", "1e9", "--nu", "0.33", "--rho", "1000", "--geometry",
                         "thin-disk", "--against", "wall", "--speed", "1", "--compute")  # fmt: skip
    assert code == 0 and "a shipped law serves nu = 0.33; nothing to compute" in err


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_a_computation_beyond_the_time_bound_is_refused_unless_forced(cli, tiny, monkeypatch):
    disk = KINDS["disk"]
    slow = replace(disk.production, seconds_per_collision=1e4)
    monkeypatch.setitem(KINDS, "disk", replace(disk, production=slow))
    args = ("law", *STEEL, "--speed", "1000", "--compute")
    code, out, err = cli(*args)
    # 27 + 2 x 9 collisions (refinement bound) of 1e4 s and two low-speed points of 2.05 s
    one_line_error(code, err, "45 collisions", "5.21 days", "1 h bound", "--force")
    assert not (tiny / "cache" / "laws").exists()
    code, out, err = cli(*args, "--force", "--store", str(tiny / "s.sqlite"))
    assert code == 0, err


@pytest.mark.parametrize(
    "extra, words",
    [
        (("--store", "x.sqlite"), "--store, --force and --route belong to --compute"),
        (("--force",), "--store, --force and --route belong to --compute"),
    ],
)
def test_compute_options_without_compute_are_refused(cli, extra, words):
    code, out, err = cli("law", *STEEL, "--speed", "1", *extra)
    one_line_error(code, err, words)


def test_compute_with_a_law_file_is_refused(cli, tiny):
    path = tiny / "law.json"
    path.write_text("{}")
    code, out, err = cli("law", *STEEL, "--speed", "1", "--compute", "--law-file", str(path))
    one_line_error(code, err, "give --law-file or --compute, not both")


def test_plan_counts_the_production_collisions():
    """Without the tiny group: the production sweeps' collisions (disk 22 speeds, sphere 26, a
    pair 19, each on 3 walls x 4 windows), as counted from the shipped laws' groups, and at
    most one refining point in each interval between their speeds (21, 25, 18 x 12)."""
    from restitution.bodies.pair.partner import Partner

    assert compute.plan(0.4, "disk").collisions == 264 + 252
    assert compute.plan(0.27, "sphere").collisions == 312 + 300
    assert compute.plan(0.4, "disk", Partner(radius_ratio=1.4)).collisions == 228 + 216
    # Two materials take the same sweeps (issue 27), their windows scaled with the partner's.
    two = Partner(radius_ratio=1.4, modulus_ratio=2.0)
    assert compute.plan(0.4, "disk", two).collisions == 228 + 216
    # Two spheres: their low-speed route up to its reach, no collisions (issue 41).
    spheres = compute.plan(0.27, "sphere", Partner(radius_ratio=1.4))
    assert spheres.collisions == 0 and 300 < spheres.low_points < 487
    assert "low-speed route" in spheres.words()


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_curve_production_writes_the_law_with_the_production_groups(cli, tiny, monkeypatch):
    """``curve --production`` (the command a refusal names) runs the production groups (here the
    tiny stand-in) through the store and writes the law as JSON, CSV and table; a second run
    computes the file again from the store (no collision twice)."""
    from restitution.laws.law import EpsilonLaw

    out = tiny / "out"
    args = ("curve", "--nu", "0.41", "--production", "--out", str(out), "--store",
            str(tiny / "s.sqlite"), "--no-progress")  # fmt: skip
    code, stdout, err = cli(*args)
    assert code == 0, err
    assert "45 collisions" in err  # 27 and the refinement's bound (3 speeds: none refined)
    law = EpsilonLaw.from_json(out / "law_nu0.41.json")
    assert list(law.v) == [*TINY_LOW, 0.1, 0.2, 0.3]
    assert law.quasistatic.tolist() == [True, True, False, False, False]
    assert (out / "law_nu0.41.csv").is_file() and (out / "law_nu0.41.txt").is_file()
    import restitution.dynamics.collision as collision

    monkeypatch.setattr(collision, "_attempt", pytest.fail)  # everything from the store now
    code, stdout, err = cli(*args)
    assert code == 0, err
    assert EpsilonLaw.from_json(out / "law_nu0.41.json").epsilon_points.tolist() == (
        law.epsilon_points.tolist()
    )
    # The same answer as JSON (the law per nu, a point per speed) and as a CSV of the points.
    code, stdout, err = cli(*args, "--json")
    assert code == 0, err
    doc = json.loads(stdout)
    assert doc["command"] == "curve" and doc["inputs"]["production"] is True
    assert [p["v"] for p in doc["points"]] == list(law.v)
    assert doc["laws"][0]["files"][0] == str(out / "law_nu0.41.json")
    code, stdout, err = cli(*args, "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(stdout)))
    assert [float(r["epsilon"]) for r in rows] == law.epsilon_points.tolist()
    # Figures are not drawn there: a figure format is refused, by either spelling.
    code, stdout, err = cli(*args, "--format", "svg")
    one_line_error(code, err, "--figure-format has no effect with --production")


@pytest.mark.parametrize(
    "extra, words",
    [
        (("--v", "0.1"), "--v has no effect with --production"),
        (("--modes", "40", "60", "80"), "--modes has no effect with --production"),
    ],
)
def test_curve_production_refuses_grid_options(cli, tiny, extra, words):
    code, out, err = cli("curve", "--nu", "0.41", "--production", *extra)
    one_line_error(code, err, words)


def test_curve_force_needs_production(cli):
    code, out, err = cli("curve", "--nu", "0.41", "--force")
    one_line_error(code, err, "--force has no effect without --production")
