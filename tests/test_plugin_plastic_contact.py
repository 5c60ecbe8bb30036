"""The LAMMPS plugin's law per contact with plastic flow (issue 61, item 1), its Python side,
against direct answers of the package's plastic law (:mod:`restitution.laws.plastic`).

* The wave ratio ``r(x, u)`` (plastic_waves.py) between its knots against the spectra of the two
  pulses computed directly at the modes' frequencies (what the package's plastic law does).
* Thornton's part: the contact's yield speed is the package's ``yield_speed_m_s`` of that
  contact, ``epsilon_T`` its closed form.
* epsilon per contact against ``plastic_law(...).points`` of the package: a grain on the wall
  (two radii: the wall law has no scale), the shipped pairs ``R2/R1 = 1, 1.5, 2`` and the pair
  ``R2/R1 = 1.3`` computed now by the pair's route; within a small part of each point's error.
* Below the yield speed the law is the elastic law per contact; the file's version 2, version 1
  kept for laws without plastic flow; the refusals.

The plastic table is built once per machine (three to six minutes, then the disk cache): on a
fresh machine (CI) that would be most of the default run's budget, so the module is ``slow``.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest

import restitution
from restitution.errors import InputError
from restitution.laws.exports import plastic_waves as pw
from restitution.laws.exports.contact_file import (
    CONTACT_FORMAT,
    PLASTIC_CONTACT_FORMAT,
    contact_law_file,
)
from restitution.laws.exports.contact_law import pair_contact_law, wall_contact_law
from restitution.laws.exports.lammps_plugin import contact_modulus
from restitution.laws.plastic import plastic_law
from restitution.laws.request import request
from restitution.laws.routes.pair import PairRoute
from restitution.laws.units import Grain
from restitution.quasistatic.plastic import thornton_epsilon

pytestmark = pytest.mark.slow  # the table's first build: minutes (module docs)

STEEL = Grain(210e9, 0.3, 7850.0, "sphere")
GLASS = Grain(63e9, 0.2481, 2500.0, "sphere")
YIELD = 1e9
"""The steel's yield stress, Pa (the issue's)."""

E_PAIR = contact_modulus(STEEL.E, STEEL.nu, STEEL.E, STEEL.nu)
E_WALL = contact_modulus(STEEL.E, STEEL.nu)

SHARE = 0.05
"""How far the law per contact may lie from the package's answer, in units of that answer's
error: the table's interpolation (measured at most 0.02 of it, docs/lammps-plugin.md) and the
law per contact's elastic part (at most 8e-3 of the elastic laws' errors)."""


def mass(r):
    return 4.0 / 3.0 * math.pi * r**3 * STEEL.rho


@pytest.fixture(scope="module")
def pair():
    return pair_contact_law(STEEL, yield_stress_pa=YIELD)


@pytest.fixture(scope="module")
def wall():
    return wall_contact_law(STEEL, yield_stress_pa=YIELD)


def _si(ratio):
    if ratio == 1.0:
        return restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain")
    if ratio in (1.5, 2.0):
        return restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain",
                                  radius_ratio=ratio)  # fmt: skip
    return None


def _route(ratio, speeds):
    """The package's pair law of a ratio not shipped: the pair's route at the speeds (what
    `restitution law --partner-radius-ratio r --speed ...` answers)."""
    rq = request(E=STEEL.E, nu=STEEL.nu, rho=STEEL.rho, shape="sphere", against="grain",
                 partner_radius_ratio=ratio, speeds=list(speeds))  # fmt: skip
    return PairRoute().law(rq, lambda _: None, False)


def test_the_ratio_between_knots_is_the_direct_spectra():
    # Points between the knots in x and in eta = arccosh(u), where steel of 1 GPa goes (u x^5
    # about 4e8 on the wall, 9e8 for radii 1 and 2 mm), against the two pulses' spectra at the
    # sphere's 1600 modes. The package's error of a plastic point counts the waves' change by
    # the pulse, L_el |r - 1|, and their coupling to the contact's loss, L_el r (1 - eps_T^2):
    # the table's miss times L_el is a small part of those.
    waves = pw.plastic_waves(STEEL.nu)
    rng = np.random.default_rng(611)
    for _ in range(2):
        u = math.cosh(rng.uniform(0.05, 6.0))
        x = rng.uniform(waves.x[0], min(waves.x[-1], (1e9 / u) ** 0.2))
        got, want = waves(x, u), pw.exact_ratio(STEEL.nu, x, u)
        counted = math.hypot(want - 1.0, want * (1.0 - float(thornton_epsilon(u)) ** 2))
        miss = abs(got - want)
        print(f"x = {x:.3f}, u = {u:.3f}: table {got:.8f}, direct {want:.8f}, miss {miss:.2e} "
              f"= {miss / counted:.2e} of the counted terms")  # fmt: skip
        assert miss < SHARE * counted


def test_thorntons_part_is_the_packages(pair, wall):
    # v_y of the contact's own constants: the package's yield speed of that law; epsilon_T its
    # closed form (quasistatic.plastic) at w / v_y.
    law = plastic_law(_si(2.0), yield_stress_pa=YIELD)
    assert pair.plastic.limiting_pressure_pa == law.p_y  # the onset pressure, 1.6128 Y
    w = 1.0
    got = pair(w, 1e-3, mass(1e-3), 2e-3, mass(2e-3), E_PAIR)
    assert math.isclose(got.speed_over_yield, w / law.yield_speed_m_s(), rel_tol=1e-14)
    assert math.isclose(got.epsilon_contact, float(thornton_epsilon(got.speed_over_yield)),
                        rel_tol=1e-14)  # fmt: skip
    on_wall = plastic_law(restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "wall"),
                          yield_stress_pa=YIELD)  # fmt: skip
    for r in (0.5e-3, 3e-3):  # the wall's v_y has no radius
        got = wall(w, r, mass(r), E_WALL)
        assert math.isclose(got.speed_over_yield, w / on_wall.yield_speed_m_s(), rel_tol=1e-14)


def test_a_plastic_grain_on_the_wall_is_the_packages_law(wall):
    # any radius: the wall law, v_y and x have no scale
    law = plastic_law(restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "wall"),
                      yield_stress_pa=YIELD)  # fmt: skip
    for p, radius in zip(law.points([0.06, 2.0]), (1e-3, 1.7e-3), strict=True):
        got = wall(p.speed_m_s, radius, mass(radius), E_WALL)
        print(f"wall, {p.speed_m_s} m/s: {got.epsilon:.10f}, package {p.epsilon:.10f} "
              f"+- {p.epsilon_err:.2e}")  # fmt: skip
        assert abs(got.epsilon - p.epsilon) < SHARE * p.epsilon_err


@pytest.mark.parametrize("ratio, w", [(1.0, 0.7), (1.5, 5.0), (2.0, 0.1)])
def test_plastic_pairs_are_the_packages_laws(pair, ratio, w):
    law = plastic_law(_si(ratio), yield_stress_pa=YIELD)
    for p in law.points([w]):
        got = pair(p.speed_m_s, 1e-3, mass(1e-3), ratio * 1e-3, mass(ratio * 1e-3), E_PAIR)
        print(f"R2/R1 = {ratio}, {p.speed_m_s} m/s: {got.epsilon:.10f}, package "
              f"{p.epsilon:.10f} +- {p.epsilon_err:.2e}")  # fmt: skip
        assert abs(got.epsilon - p.epsilon) < SHARE * p.epsilon_err


def test_a_plastic_pair_not_shipped(pair):
    # 1 mm and 1.3 mm: the package's plastic law on the pair's route computed now.
    speeds = [1.0]
    law = plastic_law(_route(1.3, speeds), yield_stress_pa=YIELD)
    for p in law.points(speeds):
        got = pair(p.speed_m_s, 1e-3, mass(1e-3), 1.3e-3, mass(1.3e-3), E_PAIR)
        print(f"R2/R1 = 1.3, {p.speed_m_s} m/s: {got.epsilon:.10f}, package {p.epsilon:.10f} "
              f"+- {p.epsilon_err:.2e}")  # fmt: skip
        assert abs(got.epsilon - p.epsilon) < SHARE * p.epsilon_err


def test_below_the_yield_speed_the_law_is_the_elastic_one(pair, wall):
    elastic_pair, elastic_wall = pair_contact_law(STEEL), wall_contact_law(STEEL)
    for w in (1e-3, 0.03):
        a = pair(w, 1e-3, mass(1e-3), 2e-3, mass(2e-3), E_PAIR)
        assert a.speed_over_yield < 1.0 and a.epsilon_contact == 1.0
        assert a.epsilon == elastic_pair.epsilon(w, 1e-3, mass(1e-3), 2e-3, mass(2e-3), E_PAIR)
        assert wall(w, 1e-3, mass(1e-3), E_WALL).epsilon == elastic_wall.epsilon(
            w, 1e-3, mass(1e-3), E_WALL
        )


def test_the_file_says_its_version(pair, wall):
    text = contact_law_file(pair, ["plastic steel"])
    lines = [ln for ln in text.splitlines() if not ln.startswith("#")]
    assert lines[0] == PLASTIC_CONTACT_FORMAT
    flow = next(ln for ln in lines if ln.startswith("plastic-flow"))
    assert float(flow.split()[1]) == pair.plastic.limiting_pressure_pa
    k, step = next(ln for ln in lines if ln.startswith("wave-ratio")).split()[1:]
    assert int(k) == pw.U_KNOTS and float(step) == pw.ETA_STEP
    wall_lines = [ln for ln in contact_law_file(wall, []).splitlines() if ln[:1] != "#"]
    flow = next(i for i, ln in enumerate(wall_lines) if ln.startswith("plastic-flow"))
    assert wall_lines[0] == PLASTIC_CONTACT_FORMAT
    word, *numbers = wall_lines[flow + 1].split()
    assert word == "material" and list(map(float, numbers)) == [STEEL.E, STEEL.nu, STEEL.rho]
    # a law without plastic flow keeps version 1, which every plugin reads
    assert CONTACT_FORMAT in contact_law_file(pair_contact_law(STEEL), []).splitlines()


def test_what_the_plastic_law_refuses():
    with pytest.raises(InputError, match="plastic flow with damping is not in the law per"):
        pair_contact_law(STEEL, relaxation_time_s=1e-7, yield_stress_pa=YIELD)
    with pytest.raises(InputError, match="one material"):
        pair_contact_law(STEEL, GLASS, yield_stress_pa=YIELD)
    with pytest.raises(InputError, match="not both"):
        wall_contact_law(STEEL, yield_stress_pa=YIELD, limiting_pressure_pa=2e9)
    with pytest.raises(InputError, match="at or above the Young modulus"):
        wall_contact_law(STEEL, limiting_pressure_pa=300e9)
    # a limiting pressure of 0.2 GPa: v_y = 1.9e-4 m/s on the wall; at 1 mm/s the contact lasts
    # 108 transit times (beyond X_TOP = 80), at 1 m/s w / v_y = 5300 (beyond U_TOP = 1105)
    soft = wall_contact_law(STEEL, limiting_pressure_pa=2e8)
    for w, what in ((1e-3, "transit times"), (1.0, "times the contact's yield speed")):
        got = soft(w, 1e-3, mass(1e-3), E_WALL)
        assert got.epsilon is None and "no epsilon is extrapolated" in got.note
        assert what in got.note and "plastic pulse's waves" in got.note
    # a limiting pressure of 20 GPa: v_y = 18.7 m/s on the wall; at 1000 m/s (u = 53, inside the
    # wall law's modal range) the contact lasts 6.8 transit times, below the route's x_lo = 7.0
    hard = wall_contact_law(STEEL, limiting_pressure_pa=2e10)
    got = hard(1000.0, 1e-3, mass(1e-3), E_WALL)
    assert got.epsilon is None and "below the 7.007" in got.note
    assert "low-speed route's reach" in got.note


def test_doctests():
    assert doctest.testmod(pw, raise_on_error=True).failed == 0
