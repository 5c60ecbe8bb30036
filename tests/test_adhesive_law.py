"""The adhesive law (restitution.laws.adhesive): JKR adhesion, damping and the elastic waves on
one pulse, in SI units.

Independent routes: the closed forms of restitution.quasistatic.adhesion (v_s, epsilon of the
contact alone, Thornton and Ning's constants), JKR contacts built here in SI from the pair's
E*, R and mass (not through contact_scales), the symmetry of two identical spheres and one on
the wall with w/2 at half the speed, convergence orders (in w, in tau, in the mode set's top
frequency) fitted from the law's own numbers, and the growth of the waves on the pulse without
its jumps against a half-space's point-force radiation (restitution.quasistatic.half_space) of
the force rate's log coefficient; the full pulse's mode energy as the jump-free part, the jumps'
and their interference (which the error holds). Stored numbers: the glass bead's v_s = 62.0
mm/s and Tabor parameters 2.4 (wall) and 3.0 (two beads) are docs/adhesion.md's table.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest
from numpy.testing import assert_allclose

from restitution.errors import InputError
from restitution.estimate import Estimate
from restitution.laws.adhesive import adhesive_law
from restitution.laws.damped import UNINFORMATIVE
from restitution.laws.si_law import SILaw, si_law
from restitution.quasistatic.adhesion import (
    STICKING_SPEED_PAIR,
    STICKING_SPEED_WALL,
    JKRContact,
    adhesive_collision,
    adhesive_epsilon,
)
from restitution.status import Status

# Soda-lime glass (docs/adhesion.md): nu = 0.24 lies between the shipped sphere laws (nu = 0.2
# to 0.45), served by PCHIP in nu.
E, NU, RHO = 63e9, 0.24, 2500.0
RADIUS, W = 10e-6, 0.4  # m, J/m^2 (dry glass)
E_WALL = E / (1.0 - NU**2)  # E* of a sphere on a rigid wall
MASS = 4.0 / 3.0 * math.pi * RHO * RADIUS**3
RTOL = 1e-10  # adhesive_collision's default rtol; the energy's errors stay below it


@pytest.fixture(scope="module")
def glass() -> SILaw:
    return si_law(E, NU, RHO, "sphere", "wall")


@pytest.fixture(scope="module")
def bead(glass):
    return adhesive_law(glass, work_of_adhesion=W, radius_m=RADIUS)


SPEEDS = (0.03, 0.1, 1.0, 10.0)  # m/s: stuck, just above v_s, 16 v_s, 161 v_s


@pytest.fixture(scope="module")
def bead_points(bead):
    return dict(zip(SPEEDS, bead.points(list(SPEEDS)), strict=True))


def _closed_wall_v_s(w: float, radius: float) -> float:
    """Thornton and Ning's form with this package's constant (docs/adhesion.md), SI."""
    return STICKING_SPEED_WALL * (w**5 / (RHO**3 * E_WALL**2 * radius**5)) ** (1.0 / 6.0)


# -- 3. the glass bead -----------------------------------------------------------------------


def test_glass_bead_sticking_speed_against_the_closed_form(glass, bead):
    assert float(glass.law.nu) == NU
    v_s = bead.sticking_speed_m_s()
    assert_allclose(v_s, _closed_wall_v_s(W, RADIUS), rtol=1e-13)
    assert round(v_s * 1e3, 1) == 62.0  # docs/adhesion.md's table
    # The integrated collision: v_s = v sqrt(1 - epsilon^2) exactly in the model.
    c = bead.collision(2.0 * v_s)
    assert_allclose(2.0 * v_s * math.sqrt(1.0 - c.epsilon**2), v_s, rtol=10 * RTOL)
    assert round(bead.tabor_parameter, 1) == 2.4


def test_glass_bead_sticks_below_v_s_and_is_elastic_far_above(bead, bead_points):
    stuck = bead_points[0.03]
    assert (stuck.epsilon, stuck.epsilon_err, stuck.stuck) == (0.0, 0.0, True)
    assert stuck.status != Status.OUTSIDE and "0.06203 m/s" in stuck.note
    fast = bead_points[10.0]
    assert not fast.stuck
    # 161 v_s: the adhesion's loss and the waves' change are below the elastic law's error.
    assert abs(fast.epsilon - fast.epsilon_elastic) <= fast.epsilon_elastic_err
    assert abs(fast.epsilon - fast.epsilon_elastic) <= fast.epsilon_err
    est = fast.estimate
    assert isinstance(est, Estimate) and est.epsilon == fast.epsilon
    assert est.epsilon_err == fast.epsilon_err and est.status == fast.status


def test_a_speed_the_elastic_law_does_not_serve_has_no_value(bead, glass):
    (p,) = bead.points([1e4])
    (q,) = glass.points([1e4])
    assert p.epsilon is None and p.status == Status.OUTSIDE and p.note == q.note


# -- 2. the contact part is the closed form --------------------------------------------------


@pytest.mark.parametrize("factor", [1.001, 1.1, 3.0, 100.0])
def test_epsilon_contact_is_the_closed_form(bead, factor):
    v_s = bead.sticking_speed_m_s()
    eps = bead.collision(factor * v_s).epsilon
    closed = float(adhesive_epsilon(factor * v_s, v_s))
    assert_allclose(eps**2, closed**2, rtol=0, atol=10 * RTOL)


def test_the_points_contact_parts_add_up(bead, bead_points):
    v_s = bead.sticking_speed_m_s()
    for speed in (1.0, 10.0):
        p = bead_points[speed]
        assert_allclose(p.epsilon_contact**2, float(adhesive_epsilon(speed, v_s)) ** 2,
                        rtol=0, atol=10 * RTOL)  # fmt: skip
        assert p.loss_viscous == 0.0
        assert_allclose(p.loss_adhesion, (v_s / speed) ** 2, rtol=1e-12)
        # epsilon^2 = epsilon_contact^2 - waves
        assert_allclose(p.epsilon**2, p.epsilon_contact**2 - p.loss_waves, rtol=1e-12)


# -- the waves on the JKR pulse without its jumps ---------------------------------------------


@pytest.fixture(scope="module")
def bead_pulses(bead_points):
    """At 0.1 m/s (1.6 v_s): the modes, the adhesive pulse and Hertz's modes' energies, built
    here from the sphere's contact law and the JKR contact in the grain's E R (not through the
    law)."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES
    from restitution.quasistatic.plastic_collision import pulse_collision

    v = bead_points[0.1].v_over_c
    modes = get_modes(NU, LOW_SPEED_MODES, geometry=SPHERE.geometry)
    law = sphere_contact_law(NU)
    jkr = JKRContact(law.E_star, 1.0, W / (E * RADIUS), mass=SPHERE_MASS)
    return modes, adhesive_collision(jkr, v), pulse_collision(law, v).mode_energy(modes)


def _sums(energy, modes, doublings: int):
    """Sums of ``energy`` over the lowest N/2^k modes (k = doublings, ..., 0), and the top
    frequency of each set."""
    order = np.argsort(modes.omega, kind="stable")
    counts = [len(modes) >> k for k in range(doublings, -1, -1)]
    return (np.array([energy[order[:n]].sum() for n in counts]),
            np.array([modes.omega[order[n - 1]] for n in counts]))  # fmt: skip


def test_the_jumps_waves_grow_like_the_top_frequency(bead_pulses):
    """With the jumps |F(omega)| ~ 1/omega, and the modes' squared amplitudes per frequency grow
    like omega^2 (a half-space's point-force admittance): the Rayleigh sum over the lowest modes
    grows like their top frequency, about x sqrt(2) per doubling of the set (whose top frequency
    grows by 1.42). The estimate the law no longer takes (module docs)."""
    modes, pulse, hertz = bead_pulses
    sums, tops = _sums(pulse.mode_energy(modes), modes, 2)
    slope = np.polyfit(np.log(tops), np.log(sums), 1)[0]
    assert abs(slope - 1.0) < 0.1, slope  # measured 0.991
    ratios = sums / _sums(hertz, modes, 2)[0]
    assert ratios[-1] > 1e4 and ratios[-1] / ratios[-2] > 1.3  # 4.43e4, x 1.37 per doubling


def test_without_the_jumps_the_waves_grow_like_the_log_of_the_top_frequency(
    bead_pulses, bead_points
):
    """The pulse without its jumps falls like omega^(-3/2) (the (T - t)^(-1/2) rate before the
    neck break): the sum over the modes grows like the log of the top frequency, by 2 kappa B /
    (m v^2) per e-fold, a half-space's point-force radiation (kappa: radiation_conductance of
    the grain's own material) of the force rate's log coefficient B. Then the law's ratio, its
    error's mode-set term, and its growth per doubling of the set (measured x 1.092 at 0.1 m/s,
    1.6 v_s, and x 1.091 at 1.01 v_s; with the jumps x 1.37 and x 1.43)."""
    from restitution.quasistatic.half_space import radiation_conductance

    modes, pulse, hertz = bead_pulses
    sums, tops = _sums(pulse.mode_energy(modes, jumps=False), modes, 3)
    rate = np.diff(sums) / np.diff(np.log(tops))
    kappa = radiation_conductance(1.0, math.sqrt(0.5 / (1.0 + NU)), NU)
    predicted = 2.0 * kappa * pulse.force_rate_log_coefficient / (pulse.mass * pulse.v**2)
    # The modes' discreteness spreads single doublings by about 5 % (measured from 50 to 1600
    # modes at 1.01, 1.6 and 10 v_s); here -2.1 %, +0.8 %, -0.9 %.
    assert_allclose(rate, predicted, rtol=0.1)
    ratios = sums / _sums(hertz, modes, 3)[0]
    assert ratios[-1] / ratios[-2] < 1.15  # measured 1.092
    p = bead_points[0.1]
    base = 1.0 - p.epsilon_elastic**2
    assert_allclose(p.loss_waves, base * ratios[-1], rtol=1e-9)  # ratio 241 (4.43e4 with jumps)
    assert p.epsilon_err >= base * abs(ratios[-1] - ratios[-2]) / (2.0 * p.epsilon)
    assert "halved" not in p.note  # the upper half adds 8.4 %, below the note's 10 %


def test_the_interference_of_the_jumps_waves_is_in_the_error(bead_pulses, bead_points):
    """The full pulse's energy in the modes is |F_smooth + F_jumps|^2: the jump-free part the law
    keeps, the jumps' own (Delta W, module docs) and their interference 2 Re(F_smooth
    conj(F_jumps)), which the model cannot place. Over the 1600 modes at 0.1 m/s the full
    pulse's sum (its own quadrature, the jumps included) against the three parts: measured
    1.5e-8 of it (the integration's floor at high frequency; docs/adhesion.md). The
    interference as that difference, full - jump-free - jumps alone, against the one computed
    from the two spectra: 2.9e-7. It is 2.35e3 times Hertz's estimate, 9.8 times the ratio kept
    (241; it swings with the speed, 2.7e3 at 1.6 v_s, 1.6e3 at 1.65 v_s); the point carries base
    times it and its error holds it whole (a bound; here it is the error, 0.994 of it)."""
    modes, pulse, hertz = bead_pulses
    full = pulse.mode_energy(modes)
    smooth, jumps, cross = pulse.mode_energy_parts(modes)
    assert np.array_equal(smooth, pulse.mode_energy(modes, jumps=False))
    residual = abs(full.sum() - (smooth.sum() + jumps.sum() + cross.sum())) / full.sum()
    assert residual < 1e-7, residual
    difference = full.sum() - smooth.sum() - pulse.mode_energy(modes, jumps="only").sum()
    assert_allclose(difference, cross.sum(), rtol=1e-6)
    ratio_cross = cross.sum() / hertz.sum()
    assert ratio_cross > 5.0 * smooth.sum() / hertz.sum()  # 2.35e3 against 241
    p = bead_points[0.1]
    base = 1.0 - p.epsilon_elastic**2
    assert_allclose(p.loss_waves_interference, base * ratio_cross, rtol=1e-9)
    assert 2.0 * p.epsilon * p.epsilon_err >= abs(p.loss_waves_interference)
    # epsilon itself does not hold it: epsilon^2 = epsilon_contact^2 - loss_waves
    assert_allclose(p.epsilon**2, p.epsilon_contact**2 - p.loss_waves, rtol=1e-12)


@pytest.fixture(scope="module")
def near_points(bead):
    factors = (1.01, 1.1, 1.5, 2.0)
    v_s = bead.sticking_speed_m_s()
    return dict(zip(factors, bead.points([f * v_s for f in factors]), strict=True))


def test_just_above_v_s_the_bead_rebounds_below_the_contacts_epsilon(bead, near_points):
    """With the jumps' waves (5e5 times Hertz's at 1.01 v_s) the law had no value up to 1.16
    v_s. Without them the waves take 3.4e-4, 7.6e-4, 8.8e-4, 6.4e-4 of the impact energy at 1.01,
    1.1, 1.5, 2 v_s: epsilon = 0.139 +- 0.030, 0.416 +- 0.012, 0.7448 +- 0.0049, 0.8657 +- 0.0029,
    errors 21 %, 3.0 %, 0.66 %, 0.34 % of epsilon. Most of it is the interference of the jumps'
    waves with the smooth pulse's (8.3e-3, 1.03e-2, 7.2e-3, 5.0e-3 of the impact energy), which
    the model cannot place; the rest of the budget, the error before that term was counted, is
    2.2 %, 0.29 %, 0.10 %, 0.047 % of epsilon (at 1.01 v_s mostly the elastic law's error,
    larger than its loss there, scaled by the ratio 322). The check on the error's size is
    recomputed for the new budget: that rest below 5 % of epsilon, as the whole error was
    before, and the whole below the quarter of epsilon above which a point says it is not
    informative."""
    v_s = bead.sticking_speed_m_s()
    for factor, p in near_points.items():
        assert p.epsilon is not None and p.status != Status.OUTSIDE and not p.stuck
        assert_allclose(p.epsilon_contact**2, float(adhesive_epsilon(factor * v_s, v_s)) ** 2,
                        rtol=0, atol=10 * RTOL)  # fmt: skip
        assert 0.0 < p.epsilon < p.epsilon_contact
        in_eps2, cross = 2.0 * p.epsilon * p.epsilon_err, abs(p.loss_waves_interference)
        rest = math.sqrt(in_eps2**2 - cross**2) / (2.0 * p.epsilon)
        assert rest < 0.05 * p.epsilon, (factor, rest / p.epsilon)
        assert cross > rest * 2.0 * p.epsilon  # the interference leads the budget
        assert p.epsilon_err < UNINFORMATIVE * p.epsilon, (factor, p.epsilon_err / p.epsilon)
        assert "not informative" not in p.note and "halved" not in p.note
    assert np.all(np.diff([p.epsilon for p in near_points.values()]) > 0)


# -- 1. far above v_s: the law tends to the elastic law ----------------------------------------


def test_far_above_v_s_the_law_tends_to_the_elastic_law(glass):
    """At 5 m/s with w from 0.04 to 4e-5 J/m^2 (v/v_s = 550 to 1.7e5). The contact's loss is
    (v_s/v)^2, of order w^(5/3); the waves' change by the pulse without its jumps, base (ratio -
    1), is below it down to w = 4e-4 (a fifth to two fifths of it: measured 0.26, 0.38, 0.22)
    and changes sign below (the next test), so the difference to the elastic law is mostly the
    contact's own loss, within the law's error."""
    speed = 5.0
    works = np.array([0.04, 0.004, 0.0004, 0.00004])
    hyst, vss, change = [], [], []
    for w in works:
        law = adhesive_law(glass, work_of_adhesion=float(w), radius_m=RADIUS)
        (p,) = law.points([speed])
        vss.append(law.sticking_speed_m_s())
        assert abs(p.epsilon - p.epsilon_elastic) <= p.epsilon_err
        hyst.append(1.0 - p.epsilon_contact**2)
        base = 1.0 - p.epsilon_elastic**2
        change.append(p.loss_waves - base)  # base (ratio - 1)
    assert_allclose(hyst, (np.array(vss) / speed) ** 2, rtol=0, atol=10 * RTOL)
    change = np.abs(change)
    assert np.all(np.diff(change) < 0), change  # 8.5e-7, 2.7e-8, 3.4e-10, 5.8e-11
    assert np.all(change[:3] < 0.5 * np.array(hyst[:3])), change / hyst


def test_as_w_vanishes_the_ratio_tends_to_one_at_first_order(glass):
    """The jump-free ratio -> 1 (Hertz's pulse) continuously as w -> 0: at 5 m/s, w = 4e-5 to
    4e-8 J/m^2, integrated at rtol = 1e-12 (at the law's 1e-10 the ratio is good to about 1e-9,
    the size of ratio - 1 at 4e-7). ratio - 1 is negative there, of first order in w (the branch's
    force differs from Hertz's by O(w)), with a correction shrinking about like w^(2/3) (delta_s
    over Hertz's compression): local orders per decade measured 0.805, 0.950, 0.990 (0.805,
    0.949, 0.982 with OpenBLAS's AVX-512 kernels). The last decade is at the integration's noise:
    its excess, 4.1e-10, moved by 8.2e-12 (2 %) between the two BLAS kernels (the spectra at the
    modes' high frequencies are sums that cancel), its order by 0.008; so the last miss is held
    below 0.03 (the first two decades' trend, x 0.26 per decade, gives 0.013) rather than to a
    third of the one before."""
    from restitution.quasistatic.plastic_collision import pulse_collision

    speed, rtol = 5.0, 1e-12
    works = np.array([4e-5, 4e-6, 4e-7, 4e-8])
    laws = [adhesive_law(glass, work_of_adhesion=float(w), radius_m=RADIUS) for w in works]
    c = laws[0]._contact
    v = speed / glass.speed_scale_m_s
    hertz = pulse_collision(c.law, v, mass=c.mass, rtol=rtol).mode_energy(c.modes).sum()
    excess = np.array([adhesive_collision(law.jkr, v, rtol=rtol).mode_energy(c.modes, jumps=False)
                       .sum() / hertz - 1.0 for law in laws])  # fmt: skip
    assert np.all(excess < 0), excess  # -2.3e-7, -3.6e-8, -4.0e-9, -4.1e-10
    order = np.diff(np.log(-excess)) / np.diff(np.log(works))
    miss = np.abs(order - 1.0)
    assert miss[1] < miss[0] / 3.0 and miss[2] < 0.03, order


# -- 4. two identical spheres ------------------------------------------------------------------


@pytest.fixture(scope="module")
def two_beads():
    return adhesive_law(si_law(E, NU, RHO, "sphere", "grain"), work_of_adhesion=W,
                        radius_m=RADIUS)  # fmt: skip


def test_two_identical_spheres_against_the_pairs_own_contact(bead, two_beads):
    """The pair's JKR contact built here in SI (E* = E / (2 (1 - nu^2)), R/2, m/2) at the
    relative speed, and Thornton and Ning's pair constant."""
    pair = JKRContact(E_WALL / 2.0, RADIUS / 2.0, W, mass=MASS / 2.0)
    v_s = two_beads.sticking_speed_m_s()
    closed = STICKING_SPEED_PAIR * (W**5 / (RHO**3 * (E_WALL / 2.0) ** 2 * RADIUS**5)) ** (1 / 6)
    assert_allclose([v_s, pair.sticking_speed], closed, rtol=1e-13)
    assert round(v_s * 1e3, 1) == 69.6  # docs/adhesion.md's table
    for speed in (0.08, 0.3, 3.0):
        eps = adhesive_collision(pair, speed).epsilon
        assert_allclose(two_beads.collision(speed).epsilon, eps, rtol=0, atol=10 * RTOL)
    # Tabor's mu of the physical pair: (R/2) w^2 / (E*/2)^2 = 2 R w^2 / E*^2
    assert_allclose(two_beads.tabor_parameter, 2 ** (1 / 3) * bead.tabor_parameter, rtol=1e-13)
    assert round(two_beads.tabor_parameter, 1) == 3.0


def test_two_identical_spheres_are_one_on_the_wall_with_half_w_at_half_speed(glass, two_beads):
    half = adhesive_law(glass, work_of_adhesion=W / 2.0, radius_m=RADIUS)
    for speed in (0.08, 0.3, 3.0):
        assert two_beads.collision(speed).epsilon == half.collision(speed / 2.0).epsilon
    (p,) = two_beads.points([1.0])
    (q,) = half.points([0.5])
    assert (p.epsilon, p.epsilon_err, p.loss_waves) == (q.epsilon, q.epsilon_err, q.loss_waves)


def test_two_spheres_of_two_sizes_against_their_contact():
    """A pair's law (radius ratio 2, nu = 0.3): E*, R_eff = 2R/3 and the reduced mass 8 m1/9
    of the two spheres built here; one point through both spheres' modes."""
    nu = 0.3
    law = adhesive_law(si_law(E, nu, RHO, "sphere", "grain", radius_ratio=2),
                       work_of_adhesion=W, radius_m=RADIUS)  # fmt: skip
    pair = JKRContact(E / (2.0 * (1.0 - nu**2)), 2.0 * RADIUS / 3.0, W, mass=8.0 * MASS / 9.0)
    assert_allclose(law.sticking_speed_m_s(), pair.sticking_speed, rtol=1e-13)
    assert_allclose(law.collision(0.3).epsilon, adhesive_collision(pair, 0.3).epsilon,
                    rtol=0, atol=10 * RTOL)  # fmt: skip
    (p,) = law.points([2.0])
    assert p.epsilon is not None and p.epsilon < p.epsilon_contact < p.epsilon_elastic


# -- 5. the scaling of v_s -----------------------------------------------------------------


def test_sticking_speed_scales_as_w_5_6_and_r_minus_5_6(glass):
    """Exponents fitted to v_s = v sqrt(1 - epsilon_contact^2) of integrated collisions."""

    def measured(w, radius):
        law = adhesive_law(glass, work_of_adhesion=w, radius_m=radius)
        v = 3.0 * law.sticking_speed_m_s()
        return v * math.sqrt(1.0 - law.collision(v).epsilon ** 2)

    factors = np.array([1.0, 2.0, 4.0])
    by_w = [measured(0.1 * f, RADIUS) for f in factors]
    by_r = [measured(W, 5e-6 * f) for f in factors]
    assert_allclose(np.polyfit(np.log(factors), np.log(by_w), 1)[0], 5 / 6, atol=1e-7)
    assert_allclose(np.polyfit(np.log(factors), np.log(by_r), 1)[0], -5 / 6, atol=1e-7)


# -- 6. damping --------------------------------------------------------------------------------


def test_damping_lowers_epsilon_and_raises_v_s_to_first_order(glass, bead):
    """tau = 1e-4, 1e-3, 1e-2 (R/c): the contact's epsilon at 1 m/s falls and the sticking
    speed rises, both to first order in tau."""
    taus = np.array([1e-4, 1e-3, 1e-2])
    speed, v_s0 = 1.0, bead.sticking_speed_m_s()
    e0 = bead.collision(speed).epsilon
    drop, rise = [], []
    for tau in taus:
        law = adhesive_law(glass, work_of_adhesion=W, radius_m=RADIUS, tau=float(tau))
        v_s = law.sticking_speed_m_s()
        assert law.collision(v_s * (1 - 1e-7)).stuck and not law.collision(v_s * (1 + 1e-7)).stuck
        drop.append(e0 - law.collision(speed).epsilon)
        rise.append(v_s - v_s0)
    assert np.all(np.diff(drop) > 0) and np.all(np.diff(rise) > 0) and min(drop + rise) > 0
    for change in (drop, rise):
        order = np.diff(np.log(change)) / np.diff(np.log(taus))
        assert abs(order[0] - 1.0) < 1e-3, order  # 0.99995 and 1.0000015 measured


def test_vanishing_damping_gives_the_undamped_law(glass, bead):
    law = adhesive_law(glass, work_of_adhesion=W, radius_m=RADIUS, tau=1e-9)
    # the root search of the damped law, against the closed form
    assert_allclose(law.sticking_speed_m_s(), bead.sticking_speed_m_s(), rtol=1e-8)
    assert law.mechanisms == ["waves", "adhesion", "viscous"]
    assert bead.mechanisms == ["waves", "adhesion"]


def test_a_damped_point(glass, bead, bead_points):
    law = adhesive_law(glass, work_of_adhesion=W, radius_m=RADIUS, tau=1e-2)
    (p,) = law.points([1.0])
    q = bead_points[1.0]
    assert p.loss_viscous > 0 and p.epsilon_contact < q.epsilon_contact and p.epsilon < q.epsilon
    assert_allclose(p.epsilon_contact**2, 1.0 - p.loss_adhesion - p.loss_viscous, atol=10 * RTOL)
    # between the two sticking speeds the damped grain sticks
    between = 0.5 * (law.sticking_speed_m_s() + bead.sticking_speed_m_s())
    (s,) = law.points([between])
    assert s.stuck and s.epsilon == 0.0


# -- 7. refusals -------------------------------------------------------------------------------


def _wall(si: SILaw, kind: str) -> SILaw:
    """``si`` as if its law were of an elastic wall: the metadata a wall's law carries
    (:func:`restitution.laws.mechanisms.bounds.wall_of`), no wall's numbers."""
    wall = {"kind": kind, "modulus_ratio": 0.3, "density_ratio": 0.32, "nu": 0.25,
            "thickness": 2.0}  # fmt: skip
    return SILaw(si.grain, "wall", replace(si.law, metadata={**si.law.metadata, "wall": wall}))


STEEL = si_law(210e9, 0.3, 7850, "sphere", "wall")


@pytest.mark.parametrize(
    "si,kw,words",
    [
        (si_law(63e9, 0.2481, 2500, "cylinder", "wall"), {}, "spheres"),
        (_wall(STEEL, "half-space"), {}, "not derived"),
        (_wall(STEEL, "plate"), {}, "not derived"),
        (STEEL, {"work_of_adhesion": 0.0}, "> 0"),
        (STEEL, {"work_of_adhesion": -0.1}, "> 0"),
        (STEEL, {"work_of_adhesion": math.nan}, "finite"),
        (STEEL, {"work_of_adhesion": math.inf}, "finite"),
        (STEEL, {"radius_m": 0.0}, "radius"),
        (STEEL, {"radius_m": math.nan}, "finite"),
        (STEEL, {"tau": -1.0}, "tau"),
        ("steel", {}, "SILaw"),
    ],
)
def test_refusals_in_one_line(si, kw, words):
    with pytest.raises(InputError) as info:
        adhesive_law(si, **{"work_of_adhesion": W, "radius_m": RADIUS, **kw})
    message = str(info.value)
    assert words in message and "\n" not in message


# -- the JSON ----------------------------------------------------------------------------------


def test_to_dict(bead, bead_points):
    speeds = [0.03, 1.0]
    d = bead.to_dict(speeds, points=[bead_points[s] for s in speeds])
    json.dumps(d, allow_nan=False)
    a = d["adhesion"]
    assert a["work_of_adhesion_j_m2"] == W and a["radius_m"] == RADIUS
    assert a["sticking_speed_m_s"] == bead.sticking_speed_m_s() and a["tau_c_over_R"] == 0.0
    assert "Johnson, K. Kendall and A. D. Roberts" in a["references"][0]
    assert "Thornton and Z. Ning" in a["references"][1]
    assert a["tabor_parameter"] < 3 and "marginal" in a["tabor_note"]
    assert "JKR idealisation" in a["error_does_not_cover"]
    assert "interference of the" in a["error_covers"]
    assert "interference of the" not in a["error_does_not_cover"]  # only its growth with the set
    assert any("adhesion" in m for m in d["mechanisms"])
    assert [p["epsilon"] for p in d["points"]] == [0.0, bead_points[1.0].epsilon]
    assert set(d["points"][0]) >= {
        "epsilon",
        "epsilon_err",
        "epsilon_contact",
        "loss_adhesion",
        "loss_waves_interference",
        "stuck",
        "status",
        "note",
    }
