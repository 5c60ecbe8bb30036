"""``restitution law --angle DEG --friction MU`` (issue 63, item 4): the oblique impact of a real
grain in SI units (restitution.laws.oblique), its request's refusals and its report.

Checked against routes of their own: the SI conversion by hand (``c = sqrt(E / ((1 - nu^2)
rho))`` of the cylinder, ``v = w / c``, ``alpha = 40 / delta_max(v)`` with ``delta_max = v
sqrt(ln(4 / v))``, eq. 61) against the reduced-unit route called directly; frictionless
impacts (``beta = -1``, no spin, no friction work, at any angle); Coulomb's bound on ``beta``
(``beta <= -1 + K mu (1 + e) / tan(theta)`` within the lever's first-order correction); the
one-line refusals (the sphere is served since: tests/test_law_oblique_sphere.py). Measured
values: docs/oblique.md ("In SI units").
"""

from __future__ import annotations

import json
import math

import pytest
from _cli_checks import one_line_error

from restitution.bodies.cache import get_modes
from restitution.bodies.disk.rim import rim_modes
from restitution.dynamics.oblique import oblique_collision
from restitution.errors import InputError
from restitution.laws.oblique import oblique_answer
from restitution.laws.request import request
from restitution.status import Status

STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="cylinder", against="wall")
STEEL_ARGS = ("--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "cylinder",
              "--against", "wall")  # fmt: skip


def _fast(**kw):
    """A fast steel impact: 200 m/s (v = 0.037 c, alpha = 500), 8 modes; about 1 s."""
    return request(**{**STEEL, "speeds": (200.0,), **kw})


def test_si_point_is_the_reduced_route_at_the_speed_and_wall_converted_by_hand():
    r = _fast(angle=30.0, friction=0.3, radius=0.01)
    from dataclasses import replace

    from restitution.laws.serve import serve

    (law_point,) = serve(replace(r, angle=None, friction=None, radius=None)).points
    a = oblique_answer(r, modes=8, head_on=[law_point])
    p = a.points[0]
    c = math.sqrt(210e9 / ((1 - 0.09) * 7850.0))  # plane strain: E / (1 - nu^2)
    v = 200.0 / c
    alpha = 40.0 / (v * math.sqrt(math.log(4.0 / v)))
    assert p.v == pytest.approx(v, rel=1e-12) and p.alpha == pytest.approx(alpha, rel=1e-12)
    nu_2d = 0.3 / 0.7
    runs = {n: oblique_collision(rim_modes(get_modes(nu_2d, count=n)), v,
                                 v * math.tan(math.radians(30.0)), 0.3, alpha)
            for n in (4, 8)}  # fmt: skip
    assert p.epsilon_normal == runs[8].epsilon_normal
    assert p.beta == runs[8].beta
    assert p.beta_error == abs(runs[8].beta - runs[4].beta)
    assert p.spin_rad_s == pytest.approx(runs[8].spin * c / 0.01, rel=1e-12)
    assert p.spin_R_m_s == pytest.approx(runs[8].spin * c, rel=1e-12)
    assert p.status == Status.COMPUTED_NOT_ASYMPTOTIC and "half the modes" in p.advice
    assert p.epsilon_head_on_law == law_point.epsilon and p.head_on_law_status
    assert p.epsilon_head_on_law_error == law_point.epsilon_err
    # epsilon_normal's error: the change from half the modes, the distance from the head-on
    # law and that law's error, in quadrature.
    parts = (runs[8].epsilon_normal - runs[4].epsilon_normal,
             runs[8].epsilon_normal - law_point.epsilon, law_point.epsilon_err)  # fmt: skip
    assert p.epsilon_normal_error == pytest.approx(math.hypot(*parts), rel=1e-12)
    assert p.epsilon_normal_error >= abs(p.epsilon_normal - law_point.epsilon)
    assert a.status == Status.COMPUTED_NOT_ASYMPTOTIC


def test_frictionless_oblique_impact_keeps_its_tangential_motion():
    p = oblique_answer(_fast(angle=45.0, friction=0.0), modes=8).points[0]
    assert p.beta == pytest.approx(-1.0, abs=1e-12)
    assert abs(p.spin_R_m_s) < 1e-9 and p.friction_work == 0.0 and p.spin_rad_s is None
    assert p.epsilon_normal < 1.0 and abs(p.energy_balance) < 1e-9


def test_microslip_point_is_the_microslip_route_at_the_same_speed_and_wall():
    """--friction-model microslip: each number is microslip_collision's at the same reduced
    speed and wall (the same code path: equal), beta's error the change from half the modes
    (the cylinder has no quasistatic theory), one phase, the model and kappa in the inputs;
    the head-on law is still read beside epsilon_normal."""
    from restitution.dynamics.oblique_microslip import MicroslipSettings, microslip_collision

    r = _fast(angle=30.0, friction=0.3, friction_model="microslip", kappa=32.0)
    p = oblique_answer(r, modes=8).points[0]
    tan = math.tan(math.radians(30.0))
    runs = {n: microslip_collision(rim_modes(get_modes(0.3 / 0.7, count=n)), p.v, p.v * tan,
                                   0.3, p.alpha, settings=MicroslipSettings(kappa=32.0))
            for n in (4, 8)}  # fmt: skip
    assert p.beta == runs[8].beta and p.epsilon_normal == runs[8].epsilon_normal
    assert p.beta_error == abs(runs[8].beta - runs[4].beta) and p.phases == 1
    assert abs(p.energy_balance) < 1e-5
    inputs = r.inputs()
    assert inputs["friction_model"] == "microslip" and inputs["kappa"] == 32.0
    plain = _fast(angle=30.0, friction=0.3)
    assert plain.inputs()["friction_model"] == "stick-slip" and plain.inputs()["kappa"] is None


def test_refusals_before_anything_is_computed():
    cases = [
        (dict(angle=30.0), "needs --friction"),
        (dict(angle=90.0, friction=0.3), "[0, 90)"),
        (dict(angle=-1.0, friction=0.3), "[0, 90)"),
        (dict(angle=30.0, friction=-0.1), ">= 0"),
        (dict(angle=30.0, friction=0.3, against="grain"), "rigid wall"),
        (dict(angle=30.0, friction=0.3, reference_speed=1.0), "--reference-speed"),
        (dict(angle=30.0, friction=0.3, relaxation_time=1e-6), "--relaxation-time"),
        (dict(friction=0.3), "--angle"),
        (dict(angle=30.0, friction=0.3, kappa=16.0), "--friction-model microslip"),
        (dict(friction_model="microslip"), "goes with --angle"),
        (dict(kappa=16.0), "goes with --angle"),
    ]
    for kw, words in cases:
        with pytest.raises(InputError, match=None) as info:
            _fast(**kw)
        assert words in str(info.value), (kw, str(info.value))
        assert "\n" not in str(info.value)


def test_plot_is_refused_with_angle(cli, tmp_path):
    code, _out, err = cli("law", *STEEL_ARGS, "--speed", "200", "--angle", "30", "--friction",
                          "0.3", "--plot", str(tmp_path / "a.png"))  # fmt: skip
    one_line_error(code, err, "--plot")


@pytest.mark.slow
def test_steel_cylinder_at_1_m_s_30_degrees_mu_0_3_in_one_command(cli):
    """The issue's case: one command, beta, epsilon_normal, spin, with errors and statuses
    (160 and 80 modes; 16-18 s measured)."""
    code, out, err = cli("law", *STEEL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3", "--radius", "0.005", "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    assert d["status"] == "computed-not-asymptotic" and d["inputs"]["angle_deg"] == 30.0
    (p,) = d["points"]
    assert p["modes"] == 160 and p["status"] == "computed-not-asymptotic"
    tan = math.tan(math.radians(30.0))
    # Coulomb's bound: the friction impulse is at most mu times the normal one; the lever
    # l = R - delta and the normal forces' torque correct it at first order in v (2e-4 here).
    assert p["beta"] <= -1.0 + 3.0 * 0.3 * (1.0 + p["epsilon_normal"]) / tan + 1e-3
    assert 0.0 < p["epsilon_normal"] < 1.0 and p["friction_work"] > 0.0
    assert p["spin_rad_s"] > 0.0  # it rolls on in the sense of its tangential motion
    for key in ("epsilon_normal_error", "beta_error", "spin_rad_s_error", "friction_work_error"):
        assert p[key] >= 0.0
    assert abs(p["energy_balance"]) < 1e-9
    assert 0.0 < p["epsilon_head_on_law"] < 1.0 and p["head_on_law_status"]  # served beside it
    code, out, err = cli("law", *STEEL_ARGS, "--speed", "1", "--angle", "30", "--friction",
                         "0.3")  # fmt: skip
    assert code == 0 and "beta" in out and "m/s (omega R" in out and "+-" in out, err
    assert "head-on law at this speed" in out
