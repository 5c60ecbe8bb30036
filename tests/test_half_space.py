"""The energy a slow impact radiates into an elastic half-space (restitution.quasistatic.half_space,
issue 42's low-speed route, served by `law --wall-E ...`).

Independent checks: Rayleigh's wave speed against the closed-form root of Rayleigh's equation at
nu = 1/4; the Rayleigh waves' share of a point force's radiation against Miller and Pursey's
67.4 % (Proc. R. Soc. A 233, 55 (1955), the partition quoted throughout the literature); the
closed form of Hertz's pulse integral against the trajectory differentiated numerically; the
time-domain formula (Parseval) against the frequency integral of the sampled pulse's spectrum;
the exact v^(3/5) scaling.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from restitution.quasistatic.half_space import (
    HERTZ_PULSE_FACTOR,
    radiated_fraction,
    radiation_integrals,
)
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    sphere_contact_law,
    sphere_quasistatic_trajectory,
)

NU = 0.3
STEEL_ON_STEEL = {
    "mass": SPHERE_MASS,
    "radius": 1.0,
    "e_star": 1.0 / (2.0 * (1.0 - NU**2)),
    "wall_density": 1.0,
    "wall_shear_speed": math.sqrt(1.0 / (2.0 * (1.0 + NU))),
    "wall_nu": NU,
}


def test_rayleigh_speed_and_share_at_a_quarter():
    """At nu = 1/4, c_R / c_T = sqrt(2 - 2/sqrt(3)) exactly, and Miller and Pursey's Rayleigh
    share of a vertical point force is 67.4 % (measured 67.36 %)."""
    r = radiation_integrals(0.25)
    assert r.rayleigh_speed == pytest.approx(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), rel=1e-10)
    assert r.rayleigh_share == pytest.approx(0.674, abs=0.001)
    # the compressional and shear part holds the P waves' 6.9 %, the rest is shear alone
    assert r.body_both / r.total > 0.069


def test_hertz_pulse_integral_matches_the_trajectory():
    """(9/5) B(4/5, 3/2) K^2 delta^2 v against int (dP/dt)^2 dt of the closed-form trajectory,
    differentiated by central differences and integrated by quadrature (measured 3e-11)."""
    law = sphere_contact_law(NU)
    v = 1e-3
    tr = sphere_quasistatic_trajectory(law, v)
    tau = tr.contact_time
    h = 1e-6 * tau

    def rate2(t):
        return ((tr.force(t + h) - tr.force(t - h)) / (2 * h)) ** 2

    numeric = 2 * quad(lambda t: float(rate2(t)), h, 0.5 * tau, limit=400, epsrel=1e-10)[0]
    closed = HERTZ_PULSE_FACTOR * law.K**2 * tr.max_compression**2 * v
    assert numeric == pytest.approx(closed, rel=1e-8)


def test_the_time_formula_is_the_frequency_integral_of_the_pulse():
    """E_rad = I / (2 pi rho c_T^3) int (dP/dt)^2 dt against (1/pi) int |P(w)|^2 w Im G dw with
    the spectrum of the sampled pulse (Parseval; measured 6e-11)."""
    law = sphere_contact_law(NU)
    v = 1e-3
    tr = sphere_quasistatic_trajectory(law, v)
    n = 1 << 16
    t = np.linspace(0.0, tr.contact_time, n)
    dt = t[1] - t[0]
    spectrum = np.fft.rfft(tr.force(t), n=8 * n) * dt
    omega = 2 * math.pi * np.fft.rfftfreq(8 * n, dt)
    rho, c_t = STEEL_ON_STEEL["wall_density"], STEEL_ON_STEEL["wall_shear_speed"]
    integral = radiation_integrals(NU).total
    conductance = integral / (2.0 * math.pi * rho * c_t**3)
    # omega Im G(omega) = conductance * omega^2 (module docs)
    freq = np.trapezoid(np.abs(spectrum) ** 2 * omega**2, omega) / math.pi * conductance
    time = conductance * HERTZ_PULSE_FACTOR * law.K**2 * tr.max_compression**2 * v
    assert freq == pytest.approx(time, rel=1e-8)


def test_the_fraction_grows_like_the_three_fifths_power_of_the_speed():
    """E_rad / E_kin = C (v/c)^(3/5) exactly; for a steel ball on a steel half-space C = 1.132
    (the (v/c)^(3/5) law of Hunter 1957 and Reed 1985, c = sqrt(E/rho))."""
    a = radiated_fraction(1e-5, **STEEL_ON_STEEL)
    b = radiated_fraction(1e-3, **STEEL_ON_STEEL)
    assert b / a == pytest.approx(100**0.6, rel=1e-12)
    assert a / 1e-5**0.6 == pytest.approx(1.1318, rel=1e-4)
    # a 5 mm steel ball at 1 m/s: about a hundred times its own vibrations' 5e-5
    assert 100 < radiated_fraction(1.0 / 5172.19, **STEEL_ON_STEEL) / 5e-5 < 150


# -- a sphere on an elastic half-space: the ball's vibrations and the wall's waves ----------------


def test_a_rigid_heavy_wall_is_the_rigid_wall():
    """E_w, rho_w -> infinity (c_T fixed): the waves vanish and the ball's part is its loss on
    the rigid wall (E* -> E / (1 - nu^2); measured 4e-10 relative at 1e12)."""
    from restitution import get_modes
    from restitution.bodies.wall import HalfSpace
    from restitution.quasistatic.half_space import half_space_loss
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES, low_speed_loss

    modes = get_modes(NU, LOW_SPEED_MODES, geometry="sphere")
    rigid = low_speed_loss(modes, 1e-4)
    hard = half_space_loss(modes, 1e-4, HalfSpace(1e12, 1e12, 0.3))
    assert hard.shares[1] < 1e-12  # 1 / (rho_w c_T^3): 1e-12 times the steel block's
    assert hard.energy_loss == pytest.approx(rigid.energy_loss, rel=1e-9)
    soft = half_space_loss(modes, 1e-4, HalfSpace(0.3, 0.32, 0.25))
    assert sum(soft.shares) == pytest.approx(soft.energy_loss, rel=1e-12)
    assert soft.shares[1] > 100 * soft.shares[0]  # the block takes far more than the ball


def test_a_steel_ball_on_a_glass_block(cli):
    """Issue 42's question at 0.1, 1 and 10 m/s: one command, a value, its error, a status and
    the split each (the route reaches 12.3 m/s, :data:`HALF_SPACE_REACH_SPEED`); 15 m/s lies
    above the reach and is outside, saying so and how to compute it."""
    import json

    code, out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                         "sphere", "--against", "wall", "--wall-E", "63e9", "--wall-nu",
                         "0.2481", "--wall-rho", "2500", "--speed", "0.1", "1", "10", "15",
                         "--json")  # fmt: skip
    points = json.loads(out)["points"]
    for p in points[:3]:
        assert p["status"] == "quasistatic" and 0.97 < p["epsilon"] < 1.0
        ball, wall = p["loss_shares"]
        assert wall > 0.99 and ball + wall == pytest.approx(1.0)
    # the loss grows with the speed
    assert points[2]["epsilon"] < points[1]["epsilon"] < points[0]["epsilon"]
    assert points[3]["status"] == "outside" and "elastic wall" in points[3]["note"]
    assert "restitution.fem.wall_reference" in points[3]["note"]


def test_the_reach_is_the_contact_width_of_the_rigid_wall_at_its_speed():
    """The route serves contacts as wide as the sphere's on the rigid wall at
    HALF_SPACE_REACH_SPEED: a wall of the ball's own material and a stiffer, heavier one reach
    further than glass; the reach scales with that speed as the width goes like v^(2/5) at a
    fixed E* (reach ~ speed)."""
    from restitution.bodies.wall import HalfSpace
    from restitution.quasistatic.half_space import HALF_SPACE_REACH_SPEED, half_space_reach
    from restitution.quasistatic.low_speed import REACH_WALL_SPEED

    glass = HalfSpace(0.3, 2500.0 / 7850.0, 0.2481)
    steel = HalfSpace(1.0, 1.0, 0.3)
    assert half_space_reach(NU, glass) < half_space_reach(NU, steel)
    c = math.sqrt(210e9 / 7850.0)
    assert half_space_reach(NU, glass) * c == pytest.approx(12.28, abs=0.01)
    # the sphere's own route's width (0.003) gave 7.37 m/s: the reach is linear in the speed
    ratio = HALF_SPACE_REACH_SPEED / REACH_WALL_SPEED
    assert half_space_reach(NU, glass) * c / ratio == pytest.approx(7.37, abs=0.01)


@pytest.mark.parametrize(
    "extra, message",
    [
        (("--against", "grain", "--wall-E", "63e9", "--wall-nu", "0.25", "--wall-rho", "2500"),
         "with --against wall"),
        (("--against", "wall", "--wall-E", "63e9"), "give all three"),
        (("--against", "wall", "--wall-E", "-1", "--wall-nu", "0.25", "--wall-rho", "2500"),
         "--wall-E must be a positive number"),
        (("--against", "wall", "--wall-E", "63e9", "--wall-nu", "0.6", "--wall-rho", "2500"),
         "Poisson number must lie in (-1, 0.5)"),
        (("--against", "wall", "--wall-E", "63e9", "--wall-nu", "0.25", "--wall-rho", "2500",
          "--compute"), "not available yet"),
    ],
)  # fmt: skip
def test_elastic_wall_options_are_refused_in_one_line(cli, extra, message):
    from _cli_checks import one_line_error

    code, _, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "sphere", *extra)  # fmt: skip
    one_line_error(code, err, message)


def test_a_cylinder_on_an_elastic_wall_is_refused(cli):
    from _cli_checks import one_line_error

    code, _, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "cylinder", "--against", "wall", "--wall-E", "63e9", "--wall-nu", "0.25",
                       "--wall-rho", "2500")  # fmt: skip
    one_line_error(code, err, "computed for spheres")
