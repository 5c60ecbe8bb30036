"""The served standard deviation (issue 65, item 1): calibrated per route on independent points.

The factors of :mod:`restitution.laws.calibration` come from the rule of
:mod:`restitution.fem.calibrate` (maximum likelihood on one half of the independent points,
rows sorted by source, Poisson number and speed, the even ones fitted); the held-out half is
checked here against the issue's targets: within one standard deviation at 60-80 % of the
points, within two at 95 % or more. Where the measured coverage misses a target the test says
so (``xfail(strict=True)``, the numbers in its reason and in docs/errors.md): it is a finding,
not a tolerance. All from stored data: the finite-element references
(``laws/data/fem_reference*.json``), the direct points between computed speeds
(``tests/data/between_*.json``) and the shipped laws; a few seconds.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from restitution.fem.calibrate import (
    LADDER_FILE,
    coverage,
    fit,
    halves,
    rows_between,
    rows_fem,
    rows_residual,
    z_scores,
)
from restitution.laws.calibration import CALIBRATIONS, MODAL, NU, QUASISTATIC, RESIDUAL_HARD
from restitution.laws.law_load import law
from restitution.laws.law_nu import law_for
from restitution.laws.si_law import si_law

DATA = Path(__file__).parent / "data"


@pytest.fixture(scope="module")
def fitted():
    return fit(DATA)


def test_the_shipped_factors_are_the_rule_s_fit_rounded_to_two_digits(fitted):
    """The factors in calibration.py are what the stated rule gives on the stored data (a
    check of their provenance: a changed law or data file changes them)."""
    got = fitted["fitted_factors"]
    assert round(got["a"], 2) == CALIBRATIONS[MODAL].point_factor
    assert round(got["b"], 2) == CALIBRATIONS[MODAL].interpolation_factor
    assert round(got["d"], 2) == CALIBRATIONS[MODAL].gap_factor
    assert round(got["c"], 2) == CALIBRATIONS[NU].nu_factor
    assert CALIBRATIONS[MODAL].calibrated and CALIBRATIONS[NU].calibrated
    assert not CALIBRATIONS[QUASISTATIC].calibrated


def _held(fitted, kind):
    return fitted["coverage"][kind]["held_out"]


def test_the_nu_route_covers_its_held_out_points(fitted):
    """51 held-out speeds of the direct laws at nu_2d = 0.25, 3/7, 0.6, 0.8 (measured: 78 %
    within one, 96 % within two)."""
    c = _held(fitted, "nu")
    assert c["points"] == 51
    assert 0.60 <= c["within_1"] <= 0.80 and c["within_2"] >= 0.95, c


def test_the_interpolation_terms_cover_the_held_out_between_points(fitted):
    """46 held-out direct points between computed speeds, with the leave-one-out term and the
    spline's gap (measured: 31 within one, 67.4 %, and all 46 within two; with the
    leave-one-out term alone, the rule before, 76 % and 93.5 %)."""
    c = _held(fitted, "between")
    assert c["points"] == 46
    assert 0.60 <= c["within_1"] <= 0.80 and c["within_2"] >= 0.95, c


def test_the_two_interpolation_factors_fitted_on_the_other_half_cover_the_first(fitted):
    """The halves swapped: ``b`` and ``d`` fitted on the held-out 46 and checked on the 47
    the shipped factors were fitted on (measured: b = 0.024, d = 0.86; 68.1 % within one, 97.9
    % within two). The gap's term carries the fit either way (d 0.77 and 0.86)."""
    s = fitted["coverage"]["between"]["swapped"]
    assert s["checked"]["points"] == 47
    assert 0.60 <= s["checked"]["within_1"] <= 0.80 and s["checked"]["within_2"] >= 0.95, s
    assert 0.5 <= s["factors"]["d"] <= 1.0


def test_the_spline_gap_is_pchip_s_own_miss_where_epsilon_is_a_cubic():
    """A not-a-knot cubic spline reproduces a cubic exactly (SciPy's CubicSpline), so on points
    of a cubic in ``v`` the gap equals PCHIP's actual miss, computed here against the cubic
    itself; it is zero at the points."""
    from restitution.laws.law import EpsilonLaw

    v = np.linspace(0.01, 0.1, 7)

    def cubic(x):
        return 0.99 - 0.4 * x + 3.0 * x**2 - 20.0 * x**3

    given = EpsilonLaw.from_points(0.33, v, cubic(v), [1e-5] * v.size)
    w = np.linspace(0.0101, 0.0999, 301)
    miss = np.abs(given.epsilon(w) - cubic(w))
    assert np.max(miss) > 1e-7  # PCHIP does miss the cubic
    np.testing.assert_allclose(given.spline_gap(w), miss, rtol=1e-8, atol=1e-15)
    assert np.all(given.spline_gap(v) <= 1e-15)


def test_the_modal_point_error_covers_the_held_out_fem_points_within_two(fitted):
    """13 held-out finite-element points at computed speeds: all within two."""
    c = _held(fitted, "fem")
    assert c["points"] == 13
    assert c["within_2"] >= 0.95, c


@pytest.mark.xfail(
    strict=True,
    reason="measured 12 of 13 (92 %) within one: the finite "
    "elements' own stated errors alone cover 21 of the 26 points (81 %), so with "
    "any point factor at least 81 % of them lie within one (docs/errors.md)",
)
def test_the_modal_point_error_covers_at_most_80_percent_of_the_fem_points(fitted):
    assert _held(fitted, "fem")["within_1"] <= 0.80


def test_the_fem_errors_alone_cover_most_of_their_points():
    """Why the test above fails: with no modal error at all, 21 of the 26 finite-element points
    at modal speeds are within one of their own errors."""
    rows = [r for r in rows_fem() if r.route == MODAL]
    z = z_scores(rows, "fem", 0.0, 0.0, 0.0, 0.0)
    assert len(rows) == 26 and int(np.sum(z <= 1.0)) == 21


def test_the_modal_route_as_a_whole_covers_two_thirds_of_its_held_out_points(fitted):
    """Finite-element and between-speed points together, 59 held out (measured: 43, 72.9 %,
    within one)."""
    c = _held(fitted, "modal")
    assert c["points"] == 59
    assert 0.60 <= c["within_1"] <= 0.80, c


def test_the_modal_route_as_a_whole_covers_95_percent_within_two(fitted):
    """Measured: 59 of 59 (it was 56 of 59 with the leave-one-out term alone)."""
    assert _held(fitted, "modal")["within_2"] >= 0.95


def test_the_halves_split_every_comparison_evenly():
    rows = rows_between(DATA)
    fit_rows, held = halves(rows)
    assert len(fit_rows) - len(held) in (0, 1)
    assert not {id(r) for r in fit_rows} & {id(r) for r in held}
    assert coverage(np.array([0.5, 1.5, 2.5]))["within_1"] == pytest.approx(1 / 3)


# -- the steel cylinder of the issue ----------------------------------------------------------


def _fem_steel():
    """The finite-element point of the steel cylinder (E = 210 GPa, nu = 0.3, plane strain:
    nu_2d = 3/7) at 1 m/s on the wall (v = 1.844e-4 c), computed for this issue by
    ``python -m restitution.fem.reference OUT 0.42857142857142855:0.00018443607745413223``
    (levels 0-2, three walls; its provenance in the file). It is flagged: curved in 1/alpha
    (55 % against the 50 % tolerance)."""
    doc = json.loads((DATA / "fem_steel_cylinder_1ms.json").read_text())
    (p,) = doc["points"]
    return p


def test_the_steel_cylinder_at_1_m_s_finite_elements_are_the_soft_walls_value():
    """The finite elements at 1 m/s extrapolate from the laws' walls (alpha delta_max = 40, 80,
    160). The residual route at the same speed on the ladder of walls
    (tests/data/residual_ladder_steel_cylinder_1ms.json, ``tools/residual_wall_ladder.py
    --point``) gives their value on those walls (measured: 0.9938302 +- 2.6e-4 against the
    FEM's 0.9938320 +- 1.5e-4) and converges on harder ones to 0.993651 +- 1.1e-5 (640-2560);
    the issue's reference 0.99383 is the soft walls' value, 1.8e-4 above the limit."""
    fem = _fem_steel()
    (p,) = json.loads((DATA / "residual_ladder_steel_cylinder_1ms.json").read_text())["points"]
    assert (p["nu"], p["v"]) == pytest.approx((fem["nu"], fem["v"]), rel=1e-12)
    soft, hard = p["triples"][0], p["triples"][-1]
    near = abs(fem["epsilon"] - soft["epsilon"]) / np.hypot(fem["epsilon_err"], soft["epsilon_err"])
    far = (fem["epsilon"] - hard["epsilon"]) / np.hypot(fem["epsilon_err"], hard["epsilon_err"])
    assert near <= 0.1 and far > 1.0  # measured 0.007 and 1.17
    limits = [t["epsilon"] for t in p["triples"][2:]]
    assert max(limits) - min(limits) <= hard["epsilon_err"]  # settled from 160-640 on


def test_the_steel_cylinder_at_1_m_s_finite_elements_on_the_served_walls():
    """The finite elements at 1 m/s on the walls the law is served from (alpha delta_max = 160,
    320, 640: ``python -m restitution.fem.reference OUT
    0.42857142857142855:0.00018443607745413223 --walls 160 320 640``, 4 Dec 2026, 11 minutes
    on one core, tests/data/fem_steel_cylinder_1ms_walls160.json; its wall 160 repeats the soft
    file's to 1e-12). Measured: 0.9936524 +- 4.3e-6, not flagged (curvature 5 %): 1.8e-4 below
    their own value on 40-160 (0.9938320, the issue's reference), as the residual route falls
    (0.9938302 -> 0.9936494 on the same walls, 3.0e-6 from the finite elements); the served
    0.9936274 +- 1.5e-4 lies 0.16 bounds below it (the issue's target: within one error, an
    error of at most 6e-4) and 1.0 sd (PCHIP's miss between 1e-4 and 2e-4)."""
    doc = json.loads((DATA / "fem_steel_cylinder_1ms_walls160.json").read_text())
    (hard,) = doc["points"]
    soft = _fem_steel()
    assert (hard["nu"], hard["v"]) == pytest.approx((soft["nu"], soft["v"]), rel=1e-12)
    assert hard["asymptotic_ok"] and "[160.0, 320.0, 640.0]" in doc["description"]
    runs = {(r["alpha"], r["level"]): r["epsilon"] for r in soft["grid"]["runs"]}
    shared = [r for r in hard["grid"]["runs"] if (r["alpha"], r["level"]) in runs]
    assert len(shared) == 3  # the wall 160 at levels 0-2: the same runs
    for r in shared:
        assert r["epsilon"] == pytest.approx(runs[r["alpha"], r["level"]], rel=1e-12)
    # The wall bias, seen by the finite elements themselves and by the residual route.
    (ladder,) = json.loads((DATA / "residual_ladder_steel_cylinder_1ms.json").read_text())["points"]
    route = ladder["triples"][2]  # 160-640, the walls of this run
    fall = soft["epsilon"] - hard["epsilon"]  # measured 1.80e-4
    assert fall > np.hypot(soft["epsilon_err"], hard["epsilon_err"])
    assert abs(hard["epsilon"] - route["epsilon"]) <= np.hypot(
        hard["epsilon_err"], route["epsilon_err"]
    )
    s = si_law(E=210e9, nu=0.3, rho=7850, shape="cylinder", against="wall")
    (q,) = s.points([1.0])
    miss = abs(q.epsilon - hard["epsilon"])
    assert miss <= q.epsilon_err <= 6e-4  # the target, against the unbiased reference
    assert miss <= 2 * np.hypot(q.epsilon_sd, hard["epsilon_err"])


def test_the_steel_cylinder_at_1_m_s_is_served_within_its_sd_of_the_hard_walls():
    """Served from the residual route on walls 160-640 at 1e-4 and 2e-4 (both ends of its
    interval): its bound 1.8e-4 (the issue's limit: 6e-4), its calibrated sd (measured 2.7e-5)
    and the value within two sds of the route's limit on 640-2560 at that very speed
    (measured: 1.0 sd; the miss, 2.7e-5, is PCHIP's between the points 1e-4 and 2e-4)."""
    (p,) = json.loads((DATA / "residual_ladder_steel_cylinder_1ms.json").read_text())["points"]
    hard = p["triples"][-1]
    s = si_law(E=210e9, nu=0.3, rho=7850, shape="cylinder", against="wall")
    (q,) = s.points([1.0])
    assert q.v_over_c == pytest.approx(p["v"], rel=1e-9)
    assert q.sd_calibrated and q.epsilon_sd < q.epsilon_err <= 6e-4
    f = CALIBRATIONS[RESIDUAL_HARD].point_factor
    z = abs(q.epsilon - hard["epsilon"]) / np.hypot(q.epsilon_sd, f * hard["epsilon_err"])
    assert z <= 2.0
    d = q.to_dict()
    assert d["epsilon_sd"] == q.epsilon_sd and d["epsilon_sd_kind"] == "standard deviation"


# -- serving ---------------------------------------------------------------------------------


def test_a_route_without_calibration_serves_its_bound_and_says_so():
    # 0.1 m/s for the steel cylinder is v = 1.8e-5 c: between the disk law's low-speed points.
    s = si_law(E=210e9, nu=0.3, rho=7850, shape="cylinder", against="wall")
    (p,) = s.points([0.1])
    assert p.status == "quasistatic"
    assert not p.sd_calibrated and p.epsilon_sd == p.epsilon_err
    assert p.to_dict()["epsilon_sd_kind"] == "bound"


def test_a_law_of_given_points_serves_their_error_as_its_sd():
    """The factors belong to this package's modal route; another program's points keep their
    own error."""
    from restitution.laws.law import EpsilonLaw

    given = EpsilonLaw.from_points(0.33, [0.01, 0.02, 0.03], [0.99, 0.98, 0.97], [1e-3] * 3)
    v = np.array([0.01, 0.015, 0.03])
    assert not given.sd_calibrated(v).any()
    assert np.array_equal(given.epsilon_sd(v), given.epsilon_err(v))


def test_the_calibrated_sd_is_below_the_bound_and_zero_nowhere():
    for served in (law(0.33), law(0.3, geometry="sphere"), law_for(0.3)):
        lo, hi = served.valid_range
        v = np.geomspace(lo, hi, 400)
        sd, err = served.epsilon_sd(v), served.epsilon_err(v)
        cal = served.sd_calibrated(v)
        assert np.all(sd <= err + 1e-18) and np.all(sd > 0)
        assert np.all(sd[~cal] == err[~cal]) and cal.any()


def _law_command(capsys, *extra) -> tuple[str, str]:
    from restitution.cli import main

    args = [
        "law",
        "--E",
        "210e9",
        "--nu",
        "0.3",
        "--rho",
        "7850",
        "--shape",
        "cylinder",
        "--against",
        "wall",
        "--speed",
        "0.1",
        "10",
        *extra,
    ]
    try:
        main(args)
    except SystemExit as exc:
        assert exc.code == 0
    return capsys.readouterr()


def test_the_law_command_shows_the_sd_and_what_it_means(capsys):
    out, _ = _law_command(capsys)
    lines = out.splitlines()
    head = next(line for line in lines if "speed [m/s]" in line)
    assert head.split()[-3:] == ["error", "sd", "status"]
    slow, fast = (line.split() for line in lines[lines.index(head) + 1 :][:2])
    assert slow[4].endswith("*") and not fast[4].endswith("*")  # the bound; calibrated
    meaning = lines[lines.index(head) - 1]
    assert "'sd' one standard deviation" in meaning and "sd* is the bound" in meaning
    doc = json.loads(_law_command(capsys, "--json")[0])
    assert "epsilon_sd" in doc["error_meaning"] and "upper estimate" in doc["error_meaning"]
    assert "one standard deviation" in doc["epsilon_sd_meaning"]
    kinds = [p["epsilon_sd_kind"] for p in doc["points"]]
    assert kinds == ["bound", "standard deviation"]


@pytest.mark.slow  # 11 s of the default run (stop 79: the default run under 10 min)
def test_each_route_is_judged_on_its_own_values(fitted):
    """The shipped disk laws serve the residual route at their slowest points (docs/numerics.md);
    the modal factors are fitted on the modal values there (kept in the laws' ``rerouted``
    entries), so the 26 modal rows are those of the laws before rerouting, and the 27
    finite-element points at the residual route's speeds (nu = 0.33 and 0.9 at v = 1e-4 and,
    since the modal points up to 1e-3 are served from the wall ladder, 1e-3: the shipped
    reference file; four more in tests/data/fem_slow_points.json and 19 at its faster points
    in tests/data/fem_residual_points.json) are rows of that route."""
    own = [r for r in rows_fem() if r.route == MODAL]
    served = rows_fem(served=True)
    assert len(own) == 26 and sum(r.route == MODAL for r in served) == 22
    residual = [r for r in served if r.route == "residual"]
    assert sorted((r.nu, r.v) for r in residual) == [
        (0.33, 1e-4),
        (0.33, 1e-3),
        (0.9, 1e-4),
        (0.9, 1e-3),
    ]
    every = rows_residual(DATA)
    assert len(every) == 27 and all(r.route == "residual" for r in every)
    assert fitted["coverage"]["residual"]["bound"]["points"] == 27


def _ladder():
    return {(p["nu"], p["v"]): p for p in json.loads((DATA / LADDER_FILE).read_text())["points"]}


def test_the_finite_elements_agree_with_the_residual_route_on_their_own_walls():
    """The finite elements extrapolate from the laws' walls (alpha delta_max = 40, 80, 160), so
    they judge the residual route on those walls, not its wall limit: against the route there
    (the wall ladder's first triple), all 26 with a ladder record lie within one combined bound
    (measured 4 Dec 2026: largest 0.36; against the point the law served before, on 80-320 at
    11 speeds and the modal value at the two modal speeds, largest 1.03, nu = 0.9 at 1e-3,
    modal). The values now served, from 160-640, lie further from them (13 of 26 within one, 24
    within two; largest 2.4, nu = 0.9 at 1e-4): the soft walls' bias, shared by both
    methods."""
    ladder = _ladder()
    near, far = [], []
    for r in rows_residual(DATA):
        p = ladder.get((r.nu, r.v))
        if p is None:  # nu = 0.8 at 0.001: the ladder failed there
            continue
        soft = p["triples"][0]
        assert soft["walls"] == [40.0, 80.0, 160.0]
        near.append(
            abs(r.reference - soft["epsilon"]) / np.hypot(r.reference_err, soft["epsilon_err"])
        )
        far.append(abs(r.reference - r.served) / np.hypot(r.reference_err, r.point_err))
    assert len(near) == 26 and max(near) <= 1.0
    assert np.median(far) > 2 * np.median(near)
    assert coverage(np.array(far))["within_2"] >= 0.9


def test_the_ladder_s_served_triple_is_the_shipped_point():
    """The wall ladder (tools/residual_wall_ladder.py) refits the walls a point was served from
    when it was computed to that point (the same route, walls and modes, so the harder walls
    judge what was served; the same code path on one machine: 1e-9), and the shipped laws now
    serve its triple 160-640 (``--apply``): the 36 residual points, and the 13 modal points up
    to ``v = 1e-3`` that ``--modal 0.001`` added (stop 76; their modal value is the rerouting's
    ``from``)."""
    doc = json.loads((DATA / LADDER_FILE).read_text())
    residual = [p for p in doc["points"] if p["served_triple"] is not None]
    modal = [p for p in doc["points"] if p["served_triple"] is None]
    assert len(residual) == 36 and len(modal) == 13
    for p in residual:
        own = p["triples"][p["served_triple"]]
        assert own["walls"] == p["shipped"]["walls"]
        assert own["epsilon"] == pytest.approx(p["shipped"]["epsilon"], rel=1e-9)
        assert own["epsilon_err"] == pytest.approx(p["shipped"]["epsilon_err"], rel=1e-6)
    for p in modal:
        assert p["shipped"]["route"] == "modal" and p["v"] <= 1e-3
        (change,) = [c for c in law(p["nu"]).metadata["rerouted"]["points"] if c["v"] == p["v"]]
        assert change["from"]["route"] == "modal"
        assert change["from"]["epsilon"] == p["shipped"]["epsilon"]
    for p in doc["points"]:
        (now,) = [r for r in law(p["nu"])._records() if r["v"] == p["v"]]
        assert now["route"] == "residual" and now["residual"]["walls"] == [160.0, 320.0, 640.0]
        assert now["epsilon"] == p["triples"][2]["epsilon"]
        assert now["epsilon_err"] == p["triples"][2]["epsilon_err"]


def test_the_modal_points_ladder_is_the_same_computation_as_the_laws_ladder():
    """tests/data/residual_ladder_modal_points.json (``--point``, 3 Dec 2026) and the laws'
    ladder's ``--modal`` points (4 Dec 2026) computed the same four points with the same code
    version: equal to 1e-12 (the same code path on one machine)."""
    ladder = _ladder()
    other = json.loads((DATA / "residual_ladder_modal_points.json").read_text())["points"]
    assert len(other) == 4
    for p in other:
        q = ladder[(p["nu"], p["v"])]
        assert q["code_version"] == p["code_version"]
        np.testing.assert_allclose(q["energy_loss_grid"], p["energy_loss_grid"], rtol=1e-12, atol=0)


def test_the_top_walls_repeat_the_ladder_s_hardest_two():
    """``--top`` runs the route on 1280, 2560, 5120: its first two walls are the ladder's last two,
    the same computation (the same code path on one machine: equal to 1e-12)."""
    tops = [p for p in _ladder().values() if "top" in p]
    assert len(tops) >= 20
    for p in tops:
        grid, top = np.array(p["energy_loss_grid"]), np.array(p["top"]["energy_loss_grid"])
        np.testing.assert_allclose(top[:2], grid[-2:], rtol=1e-12, atol=0)


def test_the_residual_route_s_bound_covers_harder_walls(fitted):
    """Served from 160-640, the route's bound covers its own limit on harder walls: 1280-5120
    where computed (no wall in common), else 640-2560, and the ladder at speeds between its
    points (tests/data/residual_ladder_between.json, the steel cylinder at 1 m/s); 62 rows since
    the 13 modal points up to ``v = 1e-3`` joined, 38 of them on 1280-5120 since stop 77
    (measured: 96.8 % within one, all within two)."""
    c = fitted["coverage"]["residual"]["harder_walls"]["bound"]
    assert c["points"] == 62
    assert c["within_1"] >= 0.95 and c["within_2"] == 1.0


def test_the_residual_route_s_judges_share_no_wall_with_it_up_to_1e_3():
    """Every ladder point up to ``v = 1e-3`` (the 25 residual points and, since stop 77, the 13
    former modal points) has its ``--top`` limit on 1280-5120, which shares no wall with the
    served 160-640; the faster ones are judged on 640-2560."""
    ladder = _ladder()
    slow = [p for p in ladder.values() if p["v"] <= 1e-3 * (1 + 1e-9)]
    assert len(slow) == 38 and all("top" in p for p in slow)
    assert all(p["top"]["walls"] == [1280.0, 2560.0, 5120.0] for p in slow)


def test_the_residual_route_s_sd_covers_its_held_out_points(fitted):
    """The factor of the hard-wall residual route by the module's rule (given the modal route's
    ``b`` and ``d``): fitted 0.4988 on 31 of the 62 rows (0.4390 at stop 76, when the 13 former
    modal points were judged on 640-2560, which shares a wall with the served 160-640; 0.4502 on
    25 of 49 before they joined), checked on the held-out half: 22 of 31 within one (71.0 %), 30
    within two (96.8 %; the one beyond, nu = 0.8 at 2e-4, at 2.21)."""
    h = fitted["coverage"]["residual"]["harder_walls"]
    assert round(h["factor_by_the_rule"], 2) == CALIBRATIONS[RESIDUAL_HARD].point_factor
    held = h["held_out"]
    assert held["points"] == 31
    assert 0.6 <= held["within_1"] <= 0.8 and held["within_2"] >= 0.95, held


def test_residual_points_on_the_laws_walls_keep_their_bound():
    """A residual point on the laws' own walls (a law of ``--route residual``, the one point the
    ladder failed at) is not the hard-wall route: its sd is its bound."""
    served = law(0.8)
    (j,) = np.flatnonzero(np.isclose(served.v, 0.001, rtol=1e-9))
    assert served._records()[j]["residual"]["walls"][0] == 40.0
    assert not served.sd_calibrated(0.001) and served.epsilon_sd(0.001) == served.epsilon_err(0.001)
    (k,) = np.flatnonzero(np.isclose(served.v, 2e-4, rtol=1e-9))
    assert served.sd_calibrated(2e-4) and served.epsilon_sd(2e-4) < served.epsilon_err(2e-4)
