"""``restitution law --shape sphere --angle DEG --friction MU`` (issue 63, its last item): the
oblique impact of a real ball on the rigid wall in SI units (restitution.laws.oblique with the
sphere's cap of every azimuthal order, restitution.bodies.sphere.cap).

Checked against routes of their own: frictionless impacts keep their tangential motion (``beta =
-1``, no spin, no friction work) and their normal coefficient is the same route's head-on one
(angle 0); in gross sliding ``beta`` is the impulse ratio ``-1 + K mu (1 + e) / tan(theta)``
with the sphere's ``K = 1 + m R^2 / I = 7/2``, within the point's own error. The issue's case
(steel ball, 1 m/s, 30 degrees, ``mu = 0.3``, 40 and 20 axisymmetric modes) runs through the
command (slow: 62-75 s measured). Measured values: docs/oblique.md ("In SI units", "The issue's
case for the sphere").

Units: SI at the command (m/s, rad/s, degrees); ``v = w / c`` with the sphere's ``c =
sqrt(E / rho)`` of its three-dimensional constants (5172 m/s for steel).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import math

import pytest
from _cli_checks import one_line_error

from restitution.bodies import kinds
from restitution.errors import InputError
from restitution.laws import oblique
from restitution.laws.oblique import law_modes, oblique_answer
from restitution.laws.request import request
from restitution.quasistatic.sphere_partial_slip import partial_slip_impact
from restitution.status import Status

STEEL_BALL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall")
BALL_ARGS = ("--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere",
             "--against", "wall")  # fmt: skip
K_SPHERE = 3.5
"""``1 + m R^2 / I`` of the solid sphere (``I = (2/5) m R^2``)."""


def _ball(angle, friction, modes):
    """The steel ball at 1 m/s (``v = 1.93e-4``, ``alpha = 80 / delta_max = 4.50e4``) at
    ``modes`` axisymmetric modes (and half as many), by the law's default route for the sphere
    (the residual route on ``alpha`` and ``2 alpha`` since stop 86)."""
    r = request(**STEEL_BALL, speeds=(1.0,), angle=angle, friction=friction, radius=0.005)
    return oblique_answer(r, modes=modes).points[0]


def test_the_sphere_kind_sets_its_own_mode_counts():
    """The sphere's law runs 40 modes and 20 (its collide default stays 20); the disk's 160 and
    80 are unchanged. No laws/ code names a kind: the counts are the kinds' attributes."""
    assert law_modes(kinds.body_kind("sphere")) == 40
    assert kinds.body_kind("sphere").oblique_modes == 20
    assert law_modes(kinds.body_kind("disk")) == oblique.MODES == 160


def test_the_sphere_request_is_served_and_its_kind_can_still_refuse(monkeypatch):
    """The sphere's refusal is gone; a kind that says why ``law`` does not serve it
    (``BodyKind.oblique_law``) is still refused in one line, naming the shapes that are."""
    r = request(**STEEL_BALL, speeds=(1.0,), angle=30.0, friction=0.3)
    assert r.oblique and r.shape == "sphere"
    sphere = kinds.body_kind("sphere")
    monkeypatch.setitem(kinds.kinds(), "sphere", dataclasses.replace(sphere, oblique_law="slow"))
    with pytest.raises(InputError) as info:
        request(**STEEL_BALL, speeds=(1.0,), angle=30.0, friction=0.3)
    words = str(info.value)
    assert "not served by law yet (slow)" in words and "--shape cylinder or thin-disk" in words
    assert "\n" not in words


@pytest.mark.slow  # 15 s (stop 76); 93 s on the residual route, the law's default since stop 86
def test_frictionless_ball_keeps_its_tangential_motion_and_its_head_on_epsilon():
    """``mu = 0`` at 30 degrees: ``beta = -1``, no spin, no friction work, and ``epsilon_normal``
    the route's own head-on value (angle 0, same modes and wall). 4 and 2 modes: 0.98840287
    both, apart by 4.1e-12, about 3 s each; at 8 modes 0.97700259 (2.8e-12), at 40 modes
    0.99736007 (5.0e-13, 62 s each; 2 Dec 2026)."""
    oblique_point = _ball(30.0, 0.0, modes=4)
    head_on = _ball(0.0, 0.0, modes=4)
    assert oblique_point.beta == pytest.approx(-1.0, abs=1e-12)
    assert abs(oblique_point.spin_rad_s) < 1e-9 and oblique_point.friction_work == 0.0
    assert head_on.beta is None and head_on.alpha == oblique_point.alpha
    assert oblique_point.epsilon_normal == pytest.approx(head_on.epsilon_normal, abs=1e-6)
    assert abs(oblique_point.energy_balance) < 1e-9 and abs(head_on.energy_balance) < 1e-9


@pytest.mark.slow  # 12-13 s (stop 70); 57 s on the residual route (stop 86)
def test_gross_sliding_ball_beta_is_the_impulse_ratio():
    """80 degrees, ``mu = 0.1``: the ball slides throughout (one phase) and ``beta`` is the
    impulse ratio ``-1 + (7/2) mu (1 + e) / tan(theta)`` with its own ``e``, within the point's
    error (the change from 4 modes). 8 modes: -0.8780148 against -0.8779904 (2.4e-5; the
    contact's lever and the pressure's torque, first order in the compression 1.8e-3), error
    7.2e-4; about 4 s. (At 40 modes, the law's count: -0.8768296 against -0.8767340, 9.6e-5,
    beyond that point's error 6.3e-5, the change from 20 modes, which does not hold the lever;
    hence also the lever's bound 1e-3 of the cylinder's test; 59 s, 2 Dec 2026.)"""
    p = _ball(80.0, 0.1, modes=8)
    ratio = -1.0 + K_SPHERE * 0.1 * (1.0 + p.epsilon_normal) / math.tan(math.radians(80.0))
    assert p.phases == 1 and p.beta_error > 0.0
    assert abs(p.beta - ratio) <= p.beta_error and abs(p.beta - ratio) < 1e-3
    assert p.spin_rad_s > 0.0 and p.friction_work > 0.0


@pytest.mark.slow
def test_steel_ball_at_1_m_s_30_degrees_mu_0_3_with_stick_slip(cli):
    """The issue's case by the stick-slip route (the sphere's law default until stop 86, now
    named): one command, beta, epsilon_normal, spin, with errors and statuses, and
    no warnings of the hard wall's trial steps (40 and 20 modes; 62-75 s measured, 2 Dec 2026:
    epsilon_normal 0.99738 +- 0.0031, beta 0.179 +- 0.054, spin 97.2 +- 4.4 rad/s, energy
    balance 3.6e-12, 17 phases; with the quasistatic limit's distance in beta's error, 0.17855 +-
    0.088 against Hertz-Mindlin's 0.10838, 58 s, the same day)."""
    code, out, err = cli("law", *BALL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3", "--radius", "0.005", "--friction-model", "stick-slip",
                         "--format", "json")  # fmt: skip
    assert code == 0, err
    assert "warning" not in err.lower() and err.startswith("note: 1 oblique impacts at 40 and 20")
    d = json.loads(out)
    assert d["status"] == str(Status.COMPUTED_NOT_ASYMPTOTIC) and d["shape"] == "sphere"
    (p,) = d["points"]
    assert p["modes"] == 40 and p["status"] == "computed-not-asymptotic"
    for key in ("epsilon_normal", "beta", "spin_rad_s", "friction_work", "energy_balance"):
        assert math.isfinite(p[key]), key
    for key in ("epsilon_normal_error", "beta_error", "spin_rad_s_error", "friction_work_error"):
        assert p[key] > 0.0 and math.isfinite(p[key]), key
    assert abs(p["energy_balance"]) < 1e-6
    tan = math.tan(math.radians(30.0))
    # Coulomb's bound with the sphere's K = 7/2 (+1e-3 for the lever at first order in v).
    assert p["beta"] <= -1.0 + K_SPHERE * 0.3 * (1.0 + p["epsilon_normal"]) / tan + 1e-3
    assert 0.0 < p["epsilon_normal"] < 1.0 and p["friction_work"] > 0.0 and p["spin_rad_s"] > 0.0
    # The head-on sphere law (quasistatic at 1 m/s: 0.999975) is served beside it and counted
    # in epsilon_normal's error.
    assert p["head_on_law_status"] and 0.999 < p["epsilon_head_on_law"] < 1.0
    assert p["epsilon_normal_error"] >= abs(p["epsilon_normal"] - p["epsilon_head_on_law"])
    # This route's low-speed limit (one state spread like the pressure, on the finite sphere)
    # in beta's error; Hertz-Mindlin's laws (a) and (b) on the half-space beside it.
    assert p["beta_error"] >= abs(p["beta"] - p["beta_one_state_finite"])
    assert p["beta_microslip"] > p["beta_quasistatic"] and p["beta_microslip_finite"] is None


@pytest.mark.slow  # 18 s of the default run (stop 76: the default run under 10 min)
def test_the_ball_with_microslip_measures_beta_from_the_finite_sphere(cli, monkeypatch):
    """--friction-model microslip: beta's error holds the distance from the finite sphere's own
    quasistatic partial slip (that route's low-speed limit,
    restitution.quasistatic.sphere_partial_slip), reported beside Hertz-Mindlin with microslip
    on the half-space (law (b), 0.31605, this package's quasistatic route, a regression value),
    and the text says which limit is in the error (4 and 2 modes for speed). At this contact
    (``a = 0.042 R``) the finite sphere reverses more than the half-space (0.388: measured
    0.072 above law (b))."""
    monkeypatch.setattr(oblique, "law_modes", lambda kind: 4)
    args = (*BALL_ARGS, "--speed", "1", "--angle", "30", "--friction", "0.3",
            "--friction-model", "microslip")  # fmt: skip
    code, out, err = cli("law", *args, "--format", "json")
    assert code == 0, err
    (p,) = json.loads(out)["points"]
    assert p["phases"] == 1 and p["beta_microslip"] == pytest.approx(0.31605, abs=1e-5)
    finite = partial_slip_impact(p["v"], p["v_tangential"], 0.3, 0.3).beta
    assert p["beta_microslip_finite"] == finite and finite > p["beta_microslip"] + 0.05
    assert p["beta_error"] >= abs(p["beta"] - finite)
    code, out, err = cli("law", *args)
    assert code == 0, err
    assert "0.31605 with microslip (law (b))" in out and p["beta_one_state_finite"] is None
    assert (f"this route's low-speed limit (in beta's error): beta = {finite:.5f}, microslip "
            "on the finite sphere's own flexibility (0.31605 on a half-space)") in out  # fmt: skip


@pytest.mark.slow  # 13 s (stop 76); 98 s on the residual route (stop 86)
def test_text_and_csv_reports_of_the_ball(cli, monkeypatch):
    """Text and CSV of the ball's answer, as for the cylinder (the kind's count lowered to 4
    and 2 modes for speed: about 3 s each)."""
    monkeypatch.setattr(oblique, "law_modes", lambda kind: 4)
    code, out, err = cli("law", *BALL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3", "--radius", "0.005")  # fmt: skip
    assert code == 0 and "beta" in out and "+-" in out and "rad/s" in out, err
    assert (
        "quasistatic Hertz-Mindlin at this impact (on a half-space): beta = 0.10838 with one "
        "stick/slip state (law (a), the DEM codes'), 0.31605 with microslip"
    ) in out
    assert ("this route's low-speed limit (in beta's error): beta = 0.32366, one stick/slip state "
            "spread like the pressure on the finite sphere's own flexibility with Dundurs' "
            "coupling (0.26640 on a half-space)") in out  # fmt: skip
    assert "and 2 alpha each, extrapolated to the rigid wall" in out  # the law's default route
    assert "warning" not in err.lower()
    code, out, err = cli("law", *BALL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3", "--format", "csv")  # fmt: skip
    assert code == 0, err
    (row,) = csv.DictReader(io.StringIO(out))
    assert row["modes"] == "4" and float(row["beta_error"]) > 0.0
    assert row["status"] == "computed-not-asymptotic" and math.isfinite(float(row["beta"]))
    assert float(row["beta_quasistatic"]) == pytest.approx(0.1083827, abs=1e-7)


@pytest.mark.slow  # 26 s (stop 76); 197 s on the residual route (stop 86)
def test_the_ball_carries_its_quasistatic_limits_and_beta_s_error_holds_its_own():
    """The sphere's kind names Hertz-Mindlin (``BodyKind.oblique_quasistatic``): each point
    carries on the half-space its ``beta`` without microslip (law (a), the DEM codes'), with it
    (law (b)) and with the one-state route's own contact (one stick/slip state spread like the
    pressure), and that contact on the finite sphere (``beta_one_state_finite``, this route's
    low-speed limit); ``beta_error`` is the change from half the modes and the distance from
    that limit in quadrature. Checked against closed forms: frictionless, all are the smooth
    ``-1``; in gross sliding (80 degrees, ``mu = 0.1``) all are the rigid impulse ratio with
    ``e = 1``, ``-1 + (7/2) mu 2 / tan(theta)`` = -0.8765711 (law (a) to 8e-15, law (b) 5.5e-9:
    its spring discretisation). At 30 degrees, ``mu = 0.3`` (``psi = 1.585``): law (a)
    0.10838, law (b) 0.31605, one state 0.26640 on the half-space and 0.32366 on the sphere
    with Dundurs' coupling (0.34347 without; since stop 87) (this package's quasistatic routes,
    regression values; the one-state ones are checked by tests/test_sphere_one_state.py and
    tests/test_sphere_coupling.py); 4 and 2 modes about 3 s each. The disk has no such
    theory: its points carry ``None`` and its error is the change alone."""
    smooth = _ball(30.0, 0.0, modes=4)
    assert smooth.beta_quasistatic == -1.0 and smooth.beta_microslip == -1.0
    assert smooth.beta_one_state == -1.0 and smooth.beta_one_state_finite == -1.0
    tan80 = math.tan(math.radians(80.0))
    ratio = -1.0 + K_SPHERE * 0.1 * 2.0 / tan80
    sliding = _ball(80.0, 0.1, modes=4)
    assert sliding.beta_quasistatic == pytest.approx(ratio, abs=1e-12)
    assert sliding.beta_microslip == pytest.approx(ratio, abs=1e-7)
    assert sliding.beta_one_state == pytest.approx(ratio, abs=1e-9)
    assert sliding.beta_one_state_finite == pytest.approx(ratio, abs=1e-6)
    p = _ball(30.0, 0.3, modes=4)
    assert p.beta_microslip - p.beta_quasistatic > 0.1  # microslip reverses more (docs table)
    assert p.beta_one_state == pytest.approx(0.26640, abs=1e-5)
    assert p.beta_one_state_finite == pytest.approx(0.32366, abs=1e-5)
    assert p.beta_microslip_finite is None  # the microslip route's limit
    coarse = _ball(30.0, 0.3, modes=2)
    change = abs(p.beta - coarse.beta)
    assert p.beta_error == pytest.approx(math.hypot(change, p.beta - p.beta_one_state_finite))
    assert p.beta_error >= abs(p.beta - p.beta_one_state_finite) and p.beta_error >= change
    disk = dict(STEEL_BALL, shape="cylinder")
    r = request(**disk, speeds=(1.0,), angle=30.0, friction=0.3, radius=0.005)
    (q,) = oblique_answer(r, modes=8).points
    assert q.beta_quasistatic is None and q.beta_microslip is None and q.beta_one_state is None
    assert q.beta_microslip_finite is None and q.beta_one_state_finite is None
    assert q.beta_error == pytest.approx(
        abs(q.beta - oblique_answer(r, modes=4).points[0].beta), abs=1e-15
    )


def test_beyond_hertz_s_reach_the_ball_has_no_quasistatic_limit():
    """``law`` accepts normal speeds up to the route's reach (steel: 3000 m/s is ``v = 0.58``,
    status ``large-deformation``), but Hertz's quasistatic theory refuses ``v > 0.529``: there
    the point carries no quasistatic ``beta`` (and its error is the mode change alone) instead of
    failing after the modal runs. Below it, the half-space's are served (``v = 0.5``: 0.1079
    without microslip) and, beyond the finite sphere's annuli (``v > 0.233 c``), each route
    measures from its friction on the half-space (law (b); one state spread like the
    pressure, not law (a))."""
    sphere = kinds.body_kind("sphere")
    for microslip in (False, True):
        beyond = oblique._quasistatic_betas(sphere, 0.58, 0.58 * 0.577, 0.3, 0.3, microslip)
        assert beyond == oblique._Limits() and beyond.route(microslip) is None
    below = oblique._quasistatic_betas(sphere, 0.5, 0.5 * 0.577, 0.3, 0.3)
    assert below.law_a is not None and below.law_b > below.law_a and below.finite is None
    assert below.law_b > below.one_state > below.law_a
    assert below.route(False) == below.one_state and below.route(True) == below.law_b
    assert oblique._quasistatic_betas(sphere, 0.5, 0.5 * 0.577, 0.3, 0.3, True) == below
    slow = oblique._quasistatic_betas(sphere, 0.005, 0.005 * 0.577, 0.3, 0.3, True)
    assert None not in dataclasses.astuple(slow) and slow.route(True) == slow.finite
    one = oblique._quasistatic_betas(sphere, 0.005, 0.005 * 0.577, 0.3, 0.3, False)
    assert one.route(False) == one.finite and one.finite != slow.finite


@pytest.mark.slow
def test_steel_ball_at_1_m_s_30_degrees_mu_0_3_in_one_command(cli):
    """The issue's case in one command, by the sphere's law default since stop 86, the residual
    route (the dropped modes' static residual, one stick/slip state, extrapolated to the rigid
    wall from alpha and 2 alpha): the ball at 40 and 20 modes (106-119 s of runs measured)
    lies within 0.02 of the route's own limit (the finite sphere's one state on the rigid wall
    with Dundurs' coupling, 0.32366, another code: annuli, quasistatic; measured 0.33856,
    0.0153 off; 0.0049 from the uncoupled 0.34347 before stop 87), where the
    stick-slip route on one wall lies 0.165 away (0.17855, test above); beta's error holds that
    distance; one phase, energy balance within 1e-6; errors and statuses for beta,
    epsilon_normal and the spin (docs/oblique.md, "A static residual for the one-state
    route", "The residual route over the speeds")."""
    code, out, err = cli("law", *BALL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3", "--radius", "0.005", "--format", "json")  # fmt: skip
    assert code == 0, err
    assert "residual friction" in err and "two walls" in err
    d = json.loads(out)
    assert d["inputs"]["friction_model"] == "residual"
    (p,) = d["points"]
    for key in ("epsilon_normal_error", "beta_error", "spin_rad_s_error", "friction_work_error"):
        assert p[key] > 0.0 and math.isfinite(p[key]), key
    assert p["status"] == "computed-not-asymptotic" and p["spin_rad_s"] > 0.0
    assert p["modes"] == 40 and p["phases"] == 1 and abs(p["energy_balance"]) < 1e-6
    assert abs(p["beta"] - p["beta_one_state_finite"]) < 0.02
    assert p["beta_error"] >= abs(p["beta"] - p["beta_one_state_finite"])
    assert "extrapolated to the rigid wall" in p["advice"]


def test_the_wall_extrapolation_is_linear_in_the_tangential_results():
    """``wall_extrapolated``: ``2 hard - soft`` in beta, the spin, the tangential speeds and the
    friction work; ``epsilon_normal`` and the rest the harder wall's; the larger energy miss."""
    from restitution.dynamics.friction.residual import WALL_FIELDS, wall_extrapolated
    from restitution.dynamics.oblique import ObliqueCollision

    base = dict.fromkeys(f.name for f in dataclasses.fields(ObliqueCollision))
    soft = ObliqueCollision(
        **{
            **base,
            **dict.fromkeys(WALL_FIELDS, 1.0),
            "epsilon_normal": 0.9,
            "energy_balance": -3e-9,
        }
    )
    hard = ObliqueCollision(**{**base, **dict.fromkeys(WALL_FIELDS, 1.5),
                                       "epsilon_normal": 0.95, "energy_balance": 1e-9})  # fmt: skip
    out = wall_extrapolated(soft, hard)
    assert all(getattr(out, f) == 2.0 for f in WALL_FIELDS)
    assert out.epsilon_normal == 0.95 and out.energy_balance == 3e-9


def test_residual_is_refused_for_a_kind_without_it(cli):
    """--friction-model residual needs the kind's contact residual: the cylinder (the disk's
    route) is refused in one line naming the sphere."""
    code, _out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                          "cylinder", "--against", "wall", "--speed", "1", "--angle", "30",
                          "--friction", "0.3", "--friction-model", "residual")  # fmt: skip
    one_line_error(code, err, "--friction-model residual", "--shape sphere")


def test_the_ball_without_friction_is_refused_in_one_line(cli):
    """Other refusals still hold for the sphere: ``--angle`` without ``--friction``."""
    code, _out, err = cli("law", *BALL_ARGS, "--speed", "1", "--angle", "30")
    one_line_error(code, err, "--friction")
