"""Plastic flow (issue 43): Thornton's contact in closed form and integrated, all mechanisms on one
pulse, the law with its parts, the inference from a measurement, and the flag of elastic answers.

Independent routes: the closed form against the integrated contact (orders of their difference in
the tolerance), Thornton's printed epsilon, the viscous collision of
:mod:`restitution.quasistatic.viscoelastic`, Rayleigh's estimate and the half-space's Hertz pulse
factor, the energy balance, and symmetry (two identical spheres as one on the wall at ``w/2``).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from _cli_checks import one_line_error

from restitution.errors import InputError
from restitution.quasistatic.half_space import HERTZ_PULSE_FACTOR
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    sphere_contact_law,
    sphere_pair_contact_law,
)
from restitution.quasistatic.plastic import (
    HIGH_SPEED_CONSTANT,
    YIELD_SPEED_CONSTANT,
    ThorntonContact,
    onset_pressure_ratio,
    thornton_epsilon,
)
from restitution.quasistatic.plastic_collision import pulse_collision
from restitution.quasistatic.viscoelastic import viscous_collision

LAW = sphere_contact_law(0.3)
P_Y = 3e-3  # limiting pressure in E (steel: 1.6 GPa / 210 GPa = 7.7e-3)
CONTACT = ThorntonContact(LAW.E_star, LAW.R, P_Y, SPHERE_MASS)


def _printed(u):
    """Thornton (1997), eq. for epsilon as it is usually quoted (Thornton and Ning 1998):
    ``(6 sqrt(3) / 5)^(1/2) [1 - (1/6)(v_y/v)^2]^(1/2) [(v_y/v) / ((v_y/v) + 2 sqrt(6/5 -
    (1/5)(v_y/v)^2))]^(1/4)``."""
    r = 1.0 / np.asarray(u)
    return (
        math.sqrt(6.0 * math.sqrt(3.0) / 5.0)
        * np.sqrt(1.0 - r * r / 6.0)
        * (r / (r + 2.0 * np.sqrt(1.2 - 0.2 * r * r))) ** 0.25
    )


# -- the closed form ---------------------------------------------------------------------------


def test_closed_form_is_thorntons_printed_one():
    u = np.geomspace(1.0, 1e5, 41)
    assert np.max(np.abs(thornton_epsilon(u) - _printed(u))) < 1e-12


def test_no_plastic_loss_below_the_yield_speed():
    assert np.all(thornton_epsilon([0.0, 0.3, 1.0]) == 1.0)


def test_high_speed_limit_and_its_order():
    # Johnson's 1.185; the relative correction falls like (v_y/v)^1 (x = sqrt(8s/15)(1 + ...)).
    assert HIGH_SPEED_CONSTANT == pytest.approx(1.185, abs=5e-4)
    u = np.array([1e3, 1e4, 1e5])
    miss = np.abs(thornton_epsilon(u) * u**0.25 / HIGH_SPEED_CONSTANT - 1.0)
    order = np.diff(np.log(miss)) / np.diff(np.log(u))
    assert np.allclose(order, -1.0, atol=0.02)


def test_yield_speed_constant_of_a_sphere_on_a_wall():
    # Thornton and Ning (1998) quote v_y = 1.56 (p_y^5 / (E*^4 rho))^(1/2).
    assert YIELD_SPEED_CONSTANT == pytest.approx(1.56, abs=0.001)
    E_star, p_y, rho, R = 230e9, 2e9, 7850.0, 0.004
    c = ThorntonContact(E_star, R, p_y, 4.0 / 3.0 * math.pi * rho * R**3)
    assert c.yield_speed == pytest.approx(
        YIELD_SPEED_CONSTANT * math.sqrt(p_y**5 / (E_star**4 * rho)), rel=1e-12
    )


def test_yield_speed_is_hertz_reaching_the_yield_compression():
    # Independent: Hertz's closed-form largest compression at v_y is delta_y.
    from restitution.quasistatic.hertz_sphere import sphere_quasistatic_collision

    q = sphere_quasistatic_collision(LAW, CONTACT.yield_speed, mass=SPHERE_MASS)
    assert q.max_compression[0] == pytest.approx(CONTACT.yield_compression, rel=1e-12)
    # And the largest Hertz pressure there is p_y.
    p0 = 2.0 * LAW.E_star / math.pi * math.sqrt(CONTACT.yield_compression)
    assert p0 == pytest.approx(P_Y, rel=1e-12)


def test_onset_of_yield_matches_johnson():
    # Johnson, Contact Mechanics, section 6.2: first yield at p0 = 1.60 Y (nu = 0.3), on the axis
    # at z = 0.48 a where the largest shear stress is 0.31 p0.
    assert onset_pressure_ratio(0.3) == pytest.approx(1.60, abs=0.015)
    assert 1.0 / (2.0 * onset_pressure_ratio(0.3)) == pytest.approx(0.31, abs=0.002)
    with pytest.raises(InputError):
        onset_pressure_ratio(0.7)


def test_identical_spheres_yield_as_one_on_the_wall_at_half_speed():
    pair = sphere_pair_contact_law(0.3)
    mass = 0.5 * SPHERE_MASS
    both = ThorntonContact(pair.E_star, pair.R, P_Y, mass)
    assert both.yield_speed == pytest.approx(2.0 * CONTACT.yield_speed, rel=1e-12)
    w = 7.0 * both.yield_speed
    got = pulse_collision(pair, w, p_y=P_Y, mass=mass).epsilon
    assert got == pytest.approx(float(CONTACT.epsilon(w / 2.0)), abs=1e-8)


# -- the integrated contact --------------------------------------------------------------------


@pytest.mark.parametrize("u", [1.5, 10.0, 1e3])
def test_integrated_contact_meets_the_closed_form_as_rtol_falls(u):
    v = u * CONTACT.yield_speed
    exact = float(CONTACT.epsilon(v))
    misses = [abs(pulse_collision(LAW, v, p_y=P_Y, rtol=r).epsilon - exact)
              for r in (1e-5, 1e-7, 1e-9)]  # fmt: skip
    assert misses[-1] < 1e-9
    # The difference falls with the tolerance, at least like rtol^(1/2) over each step of 100.
    assert misses[0] < 1e-4
    assert misses[2] < max(10.0 * misses[0] * 1e-2, 1e-11)


def test_without_plastic_flow_it_is_the_viscous_collision():
    for tau in (0.0, 0.02, 0.2):
        mine = pulse_collision(LAW, 1e-3, tau=tau)
        theirs = viscous_collision(LAW, [1e-3], tau)
        assert mine.epsilon == pytest.approx(theirs.epsilon[0], abs=1e-9)
        assert mine.viscous_work == pytest.approx(theirs.dissipated_work[0], abs=1e-9)
        assert mine.stored_energy == pytest.approx(theirs.stored_energy[0], abs=1e-9)
        assert not mine.yielded and mine.plastic_work == 0.0


@pytest.mark.parametrize("tau", [0.0, 0.05])
def test_energy_balance_with_every_mechanism(tau):
    c = pulse_collision(LAW, 30.0 * CONTACT.yield_speed, p_y=P_Y, tau=tau)
    assert c.yielded and c.plastic_work > 0.3
    total = c.epsilon**2 + c.plastic_work + c.viscous_work + c.stored_energy
    assert total == pytest.approx(1.0, abs=1e-9)
    assert c.energy_error < 1e-9


def test_damping_and_plastic_flow_lose_more_together():
    v = 5.0 * CONTACT.yield_speed
    both = pulse_collision(LAW, v, p_y=P_Y, tau=0.05).epsilon
    assert both < pulse_collision(LAW, v, p_y=P_Y).epsilon
    assert both < pulse_collision(LAW, v, tau=0.05).epsilon


def test_the_pulse_drives_the_modes_as_rayleigh_on_hertz():
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.rayleigh import rayleigh_energy

    modes = get_modes(0.3, 400, geometry="sphere")
    v = 1e-3
    mine = pulse_collision(LAW, v).mode_energy(modes)
    theirs = rayleigh_energy(modes, v, LAW)
    assert np.max(np.abs(mine - theirs.mode_energy)) < 1e-8 * theirs.energy_fraction


def test_force_rate_integral_of_hertz_pulse():
    v = 2e-3
    c = pulse_collision(LAW, v)
    expected = HERTZ_PULSE_FACTOR * LAW.K**2 * c.max_compression**2 * v
    assert c.force_rate_integral == pytest.approx(expected, rel=1e-8)


def test_plastic_pulse_is_longer_and_lower():
    v = 100.0 * CONTACT.yield_speed
    plastic, elastic = pulse_collision(LAW, v, p_y=P_Y), pulse_collision(LAW, v)
    assert plastic.contact_time > elastic.contact_time
    t = np.linspace(0.0, plastic.contact_time, 2001)
    assert plastic.force(t).max() < elastic.force(np.linspace(0, elastic.contact_time, 2001)).max()


def test_a_crushing_speed_is_refused():
    with pytest.raises(InputError, match="reaches the radius"):
        pulse_collision(LAW, 0.3, p_y=P_Y)


# -- the SI law --------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def steel():
    from restitution.laws.si_law import si_law

    return si_law(210e9, 0.3, 7850, "sphere", "wall")


def test_steel_ball_with_a_yield_stress(steel):
    from restitution.laws.plastic import plastic_law

    law = plastic_law(steel, yield_stress_pa=1e9)
    assert law.p_y == pytest.approx(onset_pressure_ratio(0.3) * 1e9)
    points = law.points([0.01, 1.0, 10.0])
    slow, one, ten = points
    assert not slow.yielded and slow.loss_plastic == 0.0
    # Below the yield speed only the waves lose: the contact returns all (to DOP853's rtol 1e-10).
    assert slow.epsilon == pytest.approx(slow.epsilon_elastic, abs=1e-10)
    # At 1 m/s plastic flow dominates by far; the parts add up to the total.
    assert one.yielded and one.loss_plastic > 1e3 * one.loss_waves
    assert one.epsilon**2 == pytest.approx(
        1 - one.loss_plastic - one.loss_stored - one.loss_viscous - one.loss_waves, abs=1e-9
    )
    # The closed form of the contact (ThorntonContact) and the served number agree within the
    # wave loss and the error.
    from restitution.quasistatic.plastic import ThorntonContact

    c = ThorntonContact(LAW.E_star, 1.0, law.reduced_p_y, SPHERE_MASS)
    for p in points:
        closed = float(c.epsilon(p.v_over_c))
        assert abs(math.sqrt(closed**2 - p.loss_waves) - p.epsilon) < 1e-8
    assert ten.epsilon < one.epsilon < slow.epsilon


def test_one_pulse_agrees_with_the_old_sum_where_losses_are_small(steel):
    # The old sum misses how the mechanisms act on one another: the viscous force takes energy
    # that the plastic flow would have taken, about L_v dL_p/dln(v^2), and the products of the
    # losses. Where all losses are small, the two answers differ by no more than that, and the
    # difference grows like the viscous loss.
    from restitution.laws.plastic import plastic_law

    vy = plastic_law(steel, yield_stress_pa=1e9).yield_speed_m_s()
    u, h = 1.1, 1e-4
    slope = (CONTACT.plastic_loss(u * (1 + h) * CONTACT.yield_speed)
             - CONTACT.plastic_loss(u * (1 - h) * CONTACT.yield_speed)) / (4.0 * h)  # fmt: skip
    gaps = []
    for tau in (1e-4, 2e-4):
        (p,) = plastic_law(steel, yield_stress_pa=1e9, tau=tau).points([u * vy])
        assert 1.0 - p.epsilon < 0.01  # every loss small
        interaction = p.loss_viscous * (abs(slope) + p.loss_plastic) / (2.0 * p.epsilon)
        gap = abs(p.epsilon - p.epsilon_sum_of_parts)
        assert gap < p.epsilon_err + interaction
        gaps.append(gap)
    assert gaps[1] / gaps[0] == pytest.approx(2.0, rel=0.1)
    # Where the losses are large they part by far more than the error (docs/plasticity.md).
    big = plastic_law(steel, yield_stress_pa=1e9, tau=0.3).points([3.0])[0]
    assert abs(big.epsilon - big.epsilon_sum_of_parts) > 5 * big.epsilon_err


def test_sum_of_parts_without_plastic_flow_is_the_damped_law(steel):
    from restitution.laws.damped import DampedLaw
    from restitution.laws.plastic import plastic_law

    tau = 0.01
    law = plastic_law(steel, limiting_pressure_pa=1e11, tau=tau)  # yields from ~1 km/s
    damped = DampedLaw(steel, tau)
    for mine, theirs in zip(law.points([0.1, 1.0]), damped.points([0.1, 1.0]), strict=True):
        assert not mine.yielded
        assert mine.epsilon_sum_of_parts == pytest.approx(theirs.epsilon, abs=1e-9)
        assert abs(mine.epsilon - theirs.epsilon) < mine.epsilon_err + theirs.epsilon_err


def test_limiting_pressure_inferred_from_a_measurement_round_trips(steel):
    from restitution.laws.plastic import plastic_law

    given = plastic_law(steel, limiting_pressure_pa=2.5e9)
    (p,) = given.points([2.0])
    inferred = plastic_law(steel, measured_epsilon=p.epsilon, measured_speed_m_s=2.0)
    assert inferred.p_y == pytest.approx(2.5e9, rel=1e-5)
    assert inferred.points([2.0])[0].epsilon == pytest.approx(p.epsilon, abs=1e-7)


def test_relaxation_time_inferred_with_plastic_flow_on(steel):
    from restitution.laws.plastic import infer_relaxation_time, plastic_law

    law = infer_relaxation_time(plastic_law(steel, yield_stress_pa=3e9), 0.8, 1.0)
    assert law.tau > 0
    (p,) = law.points([1.0])
    assert p.epsilon == pytest.approx(0.8, abs=1e-5)
    assert p.loss_viscous > 0 and p.loss_plastic > 0


def test_a_measurement_above_the_elastic_value_is_refused(steel):
    from restitution.laws.plastic import plastic_law

    with pytest.raises(InputError, match="no plastic flow explains it"):
        plastic_law(steel, measured_epsilon=0.9999999, measured_speed_m_s=1.0)


def test_elastic_answers_say_they_are_an_upper_bound(steel):
    from restitution.laws.mechanisms.bounds import elastic_bound
    from restitution.laws.si_law import si_law

    bound, text = elastic_bound(steel)
    # Steel, 250-1600 MPa: plastic flow from about 1 mm/s (mild steel) to 0.1 m/s.
    assert 5e-4 < bound < 3e-3
    assert "upper bound (no plastic flow)" in text and "steel" in text
    glass = si_law(63e9, 0.2481, 2500, "sphere", "wall")
    bound, text = elastic_bound(glass)
    assert bound is None and "brittle" in text


# -- the command -------------------------------------------------------------------------------


def _law(capsys, *args) -> tuple[int, str, str]:
    from restitution.cli import main

    try:
        main(["law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "sphere",
              *args])  # fmt: skip
        code = 0
    except SystemExit as exc:
        code = exc.code
    out = capsys.readouterr()
    return code, out.out, out.err


def test_law_command_with_a_yield_stress(capsys):
    code, out, err = _law(capsys, "--against", "wall", "--speed", "0.5", "--yield-stress", "1e9",
                          "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    assert any("plastic flow" in m for m in d["mechanisms"])
    assert d["plasticity"]["yield_speed_m_s"] == pytest.approx(0.0345, rel=0.01)
    (p,) = d["points"]
    assert p["yielded"] and p["loss_plastic"] > 0.3


def test_elastic_law_command_flags_plastic_speeds(capsys):
    code, out, err = _law(capsys, "--against", "wall", "--speed", "0.0005", "1", "--json")
    assert code == 0, err
    d = json.loads(out)
    slow, fast = d["points"]
    assert "upper bound (no plastic flow)" not in slow["note"]
    assert "upper bound (no plastic flow)" in fast["note"]
    assert d["plastic_flow_expected_from_m_s"] == pytest.approx(0.0011, rel=0.05)
    assert d["mechanisms_left_out"]


@pytest.mark.parametrize(
    "args, match",
    [
        (["--geometry", "cylinder", "--against", "wall", "--yield-stress", "1e9"], "spheres"),
        (["--against", "wall", "--wall-E", "63e9", "--wall-nu", "0.25", "--wall-rho", "2500",
          "--wall-thickness", "0.01", "--radius", "0.005", "--yield-stress", "1e9"], "plate"),
        (["--against", "wall", "--yield-stress", "1e9", "--compute"], "--law-file"),
        (["--against", "wall", "--measured-fixes", "limiting-pressure"], "--measured-epsilon"),
        (["--against", "wall", "--yield-stress", "1e9", "--limiting-pressure", "2e9"], "not both"),
        (["--against", "wall", "--partner-yield-stress", "1e9"], "rigid wall never yields"),
        (["--against", "wall", "--yield-stress", "1e9", "--measured-epsilon", "0.8",
          "--measured-speed", "1", "--measured-fixes", "limiting-pressure"], "one parameter"),
        (["--against", "wall", "--measured-epsilon", "0.8", "--measured-speed", "1",
          "--second-measured-epsilon", "0.7"], "--second-measured-speed"),
        (["--against", "wall", "--measured-epsilon", "0.8", "--measured-speed", "1",
          "--second-measured-epsilon", "0.7", "--second-measured-speed", "3",
          "--yield-stress", "1e9"], "leave out --yield-stress"),
        (["--against", "wall", "--measured-epsilon", "0.8", "--measured-speed", "1",
          "--second-measured-epsilon", "0.7", "--second-measured-speed", "3",
          "--measured-fixes", "relaxation-time"], "not only the relaxation-time"),
        (["--against", "wall", "--measured-epsilon", "0.8", "--measured-speed", "1",
          "--measured-fixes", "both"], "--second-measured-epsilon"),
        (["--against", "wall", "--limiting-pressure", "1e300"], "at or above the Young modulus"),
        (["--against", "wall", "--yield-stress", "nan"], "finite number > 0"),
    ],
)  # fmt: skip
def test_plastic_refusals_are_one_line(args, match, capsys):
    code, _, err = _law(capsys, *args)
    one_line_error(code, err, match)


def test_pair_contact_mass_is_the_pair_modes_mass():
    from restitution.bodies.pair.partner import Partner
    from restitution.laws.law import EpsilonLaw
    from restitution.laws.mechanisms.bounds import contact_scales
    from restitution.laws.si_law import SILaw
    from restitution.laws.units import Grain

    partner = Partner(radius_ratio=2.0, modulus_ratio=0.3, density_ratio=0.318471, nu=0.2481)
    law = EpsilonLaw.from_points(0.3, [1e-4, 1e-3], [0.99, 0.98], [1e-3, 1e-3],
                                 geometry="sphere", partner=partner)  # fmt: skip
    si = SILaw(Grain(210e9, 0.3, 7850, "sphere"), "grain", law,
               partner_grain=Grain(63e9, 0.2481, 2500, "sphere"))  # fmt: skip
    _, mass = contact_scales(si)
    assert mass == pytest.approx(partner.pair(0.3, 64, "sphere").mass, rel=1e-12)


@pytest.mark.slow  # 7 s of the default run (stop 76: the default run under 10 min)
def test_the_mechanisms_figure_is_drawn(tmp_path):
    """docs/figures/plastic_mechanisms_steel.png: below the yield speed only the waves and the
    viscosity lose; above it the plastic flow takes most, and epsilon falls."""
    from restitution.reproduction.figures import plastic_mechanisms

    c = plastic_mechanisms.compute([0.003, 0.3, 30.0])
    assert c.yield_speed_m_s == pytest.approx(0.0345, rel=0.01)
    assert c.plastic[0] == 0.0 and c.plastic[1] > 10 * c.viscous[1] > 0
    assert c.epsilon[0] > c.epsilon[1] > c.epsilon[2]
    assert np.all(c.waves > 0)
    plastic_mechanisms.plot(c, tmp_path / "f.png")
    assert (tmp_path / "f.png").stat().st_size > 10_000


def test_docstring_examples():
    import doctest
    import importlib

    for name in ("restitution.quasistatic.plastic_collision", "restitution.laws.plastic"):
        result = doctest.testmod(importlib.import_module(name))
        assert result.attempted > 0 and result.failed == 0


@pytest.mark.slow
def test_two_measurements_fix_both_parameters(steel, capsys):
    """Two measured epsilons at two speeds (from a known law) give back its relaxation time and
    limiting pressure (about half a minute of nested root searches)."""
    from restitution.laws.plastic import fit_two_measurements, plastic_law

    truth = plastic_law(steel, limiting_pressure_pa=2.5e9, tau=0.05)
    slow, fast = truth.points([0.01, 2.0])
    fit = fit_two_measurements(steel, (fast.epsilon, 2.0), (slow.epsilon, 0.01))
    assert fit.p_y == pytest.approx(2.5e9, rel=1e-5)
    assert fit.tau == pytest.approx(0.05, rel=1e-5)
    assert fit.p_y_err > 0 and fit.tau_err > 0
    # The command gives the same, with both parts in the rows.
    code, out, err = _law(capsys, "--against", "wall", "--speed", "1", "--json",
                          "--measured-epsilon", repr(slow.epsilon), "--measured-speed", "0.01",
                          "--second-measured-epsilon", repr(fast.epsilon),
                          "--second-measured-speed", "2")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    assert d["plasticity"]["limiting_pressure_pa"] == pytest.approx(2.5e9, rel=1e-5)
    (p,) = d["points"]
    assert p["loss_viscous"] > 0 and p["loss_plastic"] > 0


def test_two_measurements_that_no_pair_of_values_fits_are_refused(steel):
    from restitution.laws.plastic import fit_two_measurements

    # A slower impact that loses more than a faster one: no damping and plastic flow do that.
    with pytest.raises(InputError, match="no relaxation time and limiting pressure"):
        fit_two_measurements(steel, (0.5, 0.01), (0.9, 1.0))


def test_line_contact_onset_matches_johnson():
    from restitution.quasistatic.plastic import line_onset_pressure_ratio

    # Johnson, Contact Mechanics, section 6.2: plane strain, von Mises, p0 = 1.79 Y at z = 0.70 b;
    # a thin disk (plane stress) yields at its surface, where both stresses are -p0.
    assert line_onset_pressure_ratio(0.3, "strain") == pytest.approx(1.79, abs=0.01)
    assert line_onset_pressure_ratio(0.3, "stress") == pytest.approx(1.0, abs=1e-9)


def test_line_yield_speed_reaches_the_yield_force():
    # Independent route: the 2D quasistatic collision at that speed peaks at P = pi R p0^2 / E.
    from restitution.quasistatic.hertz import contact_law, quasistatic_collision
    from restitution.quasistatic.plastic import line_yield_speed

    law = contact_law(0.428571)
    p0 = 2e-3
    v = line_yield_speed(law, p0, math.pi)
    peak = quasistatic_collision(law, [v], mass=math.pi).max_force[0]
    assert peak == pytest.approx(math.pi * p0**2, rel=1e-9)


def test_cylinder_answers_are_flagged_too():
    from restitution.laws.mechanisms.bounds import elastic_bound
    from restitution.laws.si_law import si_law

    cylinder = si_law(210e9, 0.3, 7850, "cylinder", "wall")
    bound, text = elastic_bound(cylinder)
    assert 0.03 < bound < 0.15 and "plane strain" in text
    disks = si_law(210e9, 0.3, 7850, "thin-disk", "grain")
    bound2, text2 = elastic_bound(disks)
    assert bound2 is not None and "plane stress" in text2


def test_exports_name_their_mechanisms(steel):
    from restitution.laws.exports._heading import _header
    from restitution.laws.law import EpsilonLaw
    from restitution.laws.mechanisms.bounds import law_mechanisms

    lines = _header(steel)
    assert any(x.startswith("mechanisms: elastic waves") for x in lines)
    assert any(x.startswith("not in these numbers: viscous") for x in lines)
    assert any("upper bound (no plastic flow)" in x for x in lines)
    damped = EpsilonLaw.from_points(0.3, [1e-4, 1e-3], [0.99, 0.98], [1e-3, 1e-3],
                                    parameters={"relaxation_time_c_over_R": 0.1},
                                    geometry="sphere")  # fmt: skip
    assert law_mechanisms(damped) == ["waves", "viscous"]


def test_too_many_speeds_are_refused_before_any_work(capsys):
    # Plastic flow costs about 2 s a speed, a pair's route about 0.6 s: beyond the one-hour bound
    # of a run the command refuses at once, with the numbers and how many fit.
    speeds = [str(0.001 * (i + 1)) for i in range(2000)]
    code, _, err = _law(capsys, "--against", "wall", "--yield-stress", "1e9", "--speed", *speeds)
    one_line_error(code, err, "2000 speeds", "at most 1800 speeds")
    code, _, err = _law(capsys, "--against", "grain", "--partner-radius-ratio", "3",
                        "--speed", *(str(1e-4 * (i + 1)) for i in range(7000)))  # fmt: skip
    one_line_error(code, err, "7000 speeds", "low-speed route", "at most 6000 speeds")


def test_figure_main_parses_makes_the_folder_and_draws(tmp_path, capsys):
    # The shared command line of the figure modules (reproduction.figures._style.figure_main).
    from restitution.reproduction.figures._style import figure_main

    drawn = []
    figure_main(["--figures", str(tmp_path / "new"), "--nu", "0.2", "0.4"], "test",
                lambda args: f"f_{len(args.nu)}.png",
                lambda args, path: drawn.append((args.nu, path)), nu=([0.3], "nu"))  # fmt: skip
    assert drawn == [([0.2, 0.4], tmp_path / "new" / "f_2.png")]
    assert (tmp_path / "new").is_dir()
    assert capsys.readouterr().out.strip() == f"wrote {tmp_path / 'new' / 'f_2.png'}"
