"""The time step of the DEM exports (issue 61): Hertz's contact time against an integration of
Hertz's force law by scipy, the rule dt = t_c / 50 against velocity Verlet on the contact the
codes integrate, and the step of every contact type in every snippet of an export folder."""

import doctest
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from restitution.laws import exports
from restitution.laws.exports import lammps_plugin as lp
from restitution.laws.exports import time_step as time_step_module
from restitution.laws.exports.dem import DEM_TARGETS
from restitution.laws.exports.time_step import (
    REFERENCE_RADIUS_M,
    STEPS_PER_CONTACT,
    hertz_contact_time,
    time_steps,
)
from restitution.laws.si_law import si_law
from restitution.laws.units import Grain

STEEL = (210e9, 0.3, 7850.0)
GLASS = Grain(63e9, 0.2481, 2500.0, "sphere")


def integrated_contact_time(estar, rstar, mstar, w):
    """The time from touch to separation of ``m* x'' = -(4/3) E* sqrt(R*) x^(3/2)``, ``x(0) =
    0``, ``x'(0) = w``, by DOP853 in SI variables (s): no scaling, no closed form."""
    k = 4.0 / 3.0 * estar * math.sqrt(rstar)

    def rhs(_t, y):
        return [y[1], -k * max(y[0], 0.0) ** 1.5 / mstar]

    def apart(_t, y):
        return y[0]

    apart.terminal, apart.direction = True, -1
    guess = (mstar**2 / (estar**2 * rstar * w)) ** 0.2  # only sets the horizon and the tolerance
    sol = solve_ivp(rhs, (0.0, 10 * guess), [0.0, w], method="DOP853", rtol=1e-12,
                    atol=[1e-14 * w * guess, 1e-14 * w], events=apart)  # fmt: skip
    return float(sol.t_events[0][0])


@pytest.mark.parametrize(
    ("estar", "rstar", "mstar", "w"),
    [
        (1.154e11, 5e-3, 1.64e-2, 0.01),  # two steel spheres of 1 cm, slowly
        (2.308e11, 1e-2, 3.29e-2, 10.0),  # a steel sphere on a rigid wall
        (3.357e10, 5e-4, 5.24e-6, 3012.0),  # glass beads of 1 mm at their law's fastest
        (2.0e6, 2e-2, 0.05, 1.0),  # a rubber ball
    ],
)
def test_contact_time_is_the_integrated_hertz_contact(estar, rstar, mstar, w):
    assert_allclose(hertz_contact_time(estar, rstar, mstar, w),
                    integrated_contact_time(estar, rstar, mstar, w), rtol=1e-9)  # fmt: skip


def test_doctests():
    assert doctest.testmod(time_step_module).failed == 0


def test_contact_time_is_johnsons_closed_form_and_scales():
    # 2.868 (m*^2 / (E*^2 R* w))^(1/5): Johnson's 2.87; the prefactor is the sphere's
    # kappa = 2.9433 times (15/16)^(2/5).
    t = hertz_contact_time(1.0, 1.0, 1.0, 1.0)
    assert_allclose(t, 2.9432752 * (15 / 16) ** 0.4, rtol=1e-7)
    assert round(t, 2) == 2.87
    base = hertz_contact_time(1e11, 1e-3, 1e-5, 1.0)
    assert_allclose(hertz_contact_time(1e11, 1e-3, 1e-5, 32.0), base / 2.0, rtol=1e-14)
    assert_allclose(hertz_contact_time(1e11, 2e-3, 8e-5, 1.0), 2.0 * base, rtol=1e-14)  # ~ R


def verlet_error(eps, steps_per_contact, phase, estar=1.15e11, rstar=5e-3, mstar=1.64e-2):
    """``epsilon(Verlet) - epsilon`` of one Hertz + Tsuji contact at 1 m/s, integrated as
    LAMMPS's fix nve/sphere does (half kick, drift, force with the half-step velocity, half
    kick) at ``dt = t_c / steps_per_contact``; the contact opens ``phase`` of a step after
    the start."""
    beta = float(lp.lammps_coeff_restitution_beta(eps)) if eps < 1.0 else 0.0
    dt = hertz_contact_time(estar, rstar, mstar, 1.0) / steps_per_contact

    def force(x, v):
        if x <= 0.0:
            return 0.0
        k = 2.0 * estar * math.sqrt(rstar * x)
        return 2.0 / 3.0 * k * x + beta * math.sqrt(mstar * k) * v

    x, v = -phase * dt, 1.0
    f = force(x, v)
    for _ in range(20 * steps_per_contact):
        v -= 0.5 * dt * f / mstar
        x += dt * v
        f = force(x, v)
        v -= 0.5 * dt * f / mstar
        if x < 0.0 and v < 0.0:
            return -v - eps
    raise AssertionError("the contact did not end")


@pytest.mark.parametrize("eps", [1.0, 0.99, 0.9, 0.7, 0.5])
def test_fifty_steps_per_contact_keep_one_percent_of_the_loss(eps):
    # The module's rule and its table: worst over 20 opening phases.
    phases = np.linspace(0.025, 0.975, 20)
    worst = max(abs(verlet_error(eps, STEPS_PER_CONTACT, p)) for p in phases)
    assert worst <= 0.01 * (1.0 - eps) + 5e-5, worst
    coarse = max(abs(verlet_error(eps, 20, p)) for p in phases)
    assert coarse > worst  # and the step matters: 20 steps per contact are worse


def cases():
    """(law, constant, contact types) of a wall, identical grains, two sizes and two
    materials."""
    wall = si_law(*STEEL, "sphere", "wall")
    grain = si_law(*STEEL, "sphere", "grain")
    pair = si_law(*STEEL, "sphere", "grain", radius_ratio=2)
    mixed = si_law(*STEEL, "sphere", "grain", radius_ratio=1, partner_grain=GLASS)
    glass = si_law(63e9, 0.2481, 2500.0, "sphere", "grain")
    two = ["types 1-1", "types 1-2", "types 2-2", "type 1 on the wall", "type 2 on the wall"]
    return [
        (wall, exports.constant_at(wall, 1.0), ["type 1 on the wall"]),
        (grain, exports.constant_at(grain, 1.0), ["types 1-1", "type 1 on the wall"]),
        (pair, exports.type_pair_constants(pair, grain, speed_m_s=1.0), two),
        (mixed, exports.type_pair_constants(mixed, grain, speed_m_s=1.0, identical2=glass), two),
    ]


def test_every_contact_type_has_its_time_by_hand():
    r1 = 2e-3
    for s, c, names in cases():
        steps = time_steps(s, c, r1)
        assert [x.contact for x in steps.contacts] == names
        for x in steps.contacts:
            i, j = (int(x.contact.split()[1]), 0) if "wall" in x.contact else map(
                int, x.contact.split()[1].split("-"))  # fmt: skip
            grains = {1: s.grain, 2: s.partner_grain or s.grain}
            ratio = 1.0 if s.law.partner is None else s.law.partner.radius_ratio
            radius = {1: r1, 2: ratio * r1}
            mass = {k: 4 / 3 * math.pi * radius[k] ** 3 * grains[k].rho for k in (1, 2)}
            a = grains[i]
            if j == 0:
                want = (lp.contact_modulus(a.E, a.nu), radius[i], mass[i])
            else:
                b = grains[j]
                want = (lp.contact_modulus(a.E, a.nu, b.E, b.nu),
                        radius[i] * radius[j] / (radius[i] + radius[j]),
                        mass[i] * mass[j] / (mass[i] + mass[j]))  # fmt: skip
            assert_allclose((x.E_star_pa, x.R_eff_m, x.m_eff_kg), want, rtol=1e-14)
            assert x.speed_m_s > 1.0 and x.whose == "its law"
            assert_allclose(x.time_step_s, x.contact_time_s / STEPS_PER_CONTACT, rtol=1e-15)
        shortest = min(x.time_step_s for x in steps.contacts)
        assert 0.99 * shortest < steps.time_step_s <= shortest  # rounded down to 3 digits
        # without a radius: the same times for R1 = 1 mm, which scale with R1
        unsized = time_steps(s, c)
        assert not unsized.sized and steps.sized
        for a, b in zip(unsized.contacts, steps.contacts, strict=True):
            assert_allclose(b.contact_time_s, a.contact_time_s * r1 / REFERENCE_RADIUS_M,
                            rtol=1e-12)  # fmt: skip


def test_the_fastest_impact_sets_the_step():
    s, c, _ = cases()[1]
    (grains, wall) = time_steps(s, c, 1e-3).contacts
    assert grains.speed_m_s == s.speed_range_m_s[1]
    assert wall.speed_m_s == si_law(*STEEL, "sphere", "wall").speed_range_m_s[1]
    # a one-constant pair exports the 1-2 law only: 1-1 and 2-2 take its fastest speed
    pair = si_law(*STEEL, "sphere", "grain", radius_ratio=2)
    by = {x.contact: x for x in time_steps(pair, exports.constant_at(pair, 1.0)).contacts}
    assert by["types 1-2"].whose == "its law"
    assert by["types 1-1"].speed_m_s == pair.speed_range_m_s[1]
    assert "no law of this contact" in by["types 1-1"].whose


_COMMANDS = {"lammps": "timestep ", "liggghts": "timestep ", "yade": "O.dt = ",
             "mercurydpm": "setTimeStep(tc / 50.0);"}  # fmt: skip


@pytest.mark.parametrize("radius", [None, 5e-4])
def test_every_snippet_of_the_folder_carries_the_step(tmp_path, radius):
    s, c, names = cases()[2]
    folder = exports.write_folder(s, c, tmp_path, radius_m=radius)
    dt = folder.time_steps.time_step_s
    files = {
        t.name: (tmp_path / f"epsilon_{t.file_name}").read_text() for t in DEM_TARGETS.values()
    }
    files["plugin"] = (tmp_path / "epsilon_lammps_plugin.in").read_text()
    for target, text in files.items():
        for name in names:
            assert f"  {name}: w = " in text, (target, name)
        assert "Johnson, Contact Mechanics" in text or "tc/50" in text
        command = _COMMANDS.get(target, "timestep ")
        lines = [ln for ln in text.splitlines() if ln.startswith(command)]
        if target == "mercurydpm":  # a linear species: the user's collision time tc
            assert lines == [command]
        elif radius is None:
            assert lines == [] and "no step set: give --radius" in text, target
        else:
            assert len(lines) == 1, target
            assert_allclose(float(lines[0][len(command) :].split()[0]), dt, rtol=0)
    compile(files["yade"], "yade.py", "exec")


def test_the_command_line_takes_a_radius_for_the_export(tmp_path, cli):
    code, _, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "sphere", "--against", "wall", "--speed", "1", "--reference-speed", "1",
                       "--radius", "0.002", "--export", str(tmp_path / "x"))  # fmt: skip
    assert code == 0, err
    text = (tmp_path / "x" / "epsilon_lammps.in").read_text()
    want = time_steps(si_law(*STEEL, "sphere", "wall"), None, 0.002).time_step_s
    assert f"\ntimestep {want:.3g}\n" in text
    code, _, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "sphere", "--against", "wall", "--speed", "1", "--radius",
                       "0.002")  # fmt: skip
    assert code != 0 and "--export DIR (the DEM snippets' time step)" in err
