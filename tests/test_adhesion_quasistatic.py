"""JKR adhesion (issue 60, item 6): the contact, its hysteresis and sticking speed in closed form,
against independent routes.

Routes: the JKR numbers found on the curve itself by root finding and minimisation; the branch's
inversion against its parametrisation; the potential and the hysteresis by quadrature of the
force; the collision integrated with DOP853 against the closed-form epsilon (orders of their
difference in ``rtol``), the energy along the integrated trajectory, the sticking speed's exponents
fitted from integrations; two spheres as one on the wall at half speed; the limits of the damped
contact (first order in ``A`` by quadrature along the elastic path; ``w -> 0`` the viscous
collision of :mod:`restitution.quasistatic.viscoelastic`); the pulse's spectrum against direct
quadrature, its jumps, its force-rate divergence and its Hertz limit
(:class:`~restitution.quasistatic.plastic_collision.PulseCollision`); the pulse without its jumps
against the full one less the steps (integration by parts) and its ``omega^(-3/2)`` tail; the
full pulse's mode energy as the jump-free part, the jumps' and their interference.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from restitution.errors import InputError
from restitution.quasistatic.adhesion import (
    HYSTERESIS_CONSTANT,
    STICKING_SPEED_PAIR,
    STICKING_SPEED_WALL,
    JKRContact,
    adhesive_collision,
    adhesive_epsilon,
    reduced_work_of_adhesion,
    sticking_speed,
    work_of_adhesion,
)
from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law
from restitution.quasistatic.plastic_collision import pulse_collision
from restitution.quasistatic.viscoelastic import viscous_collision

LAW = sphere_contact_law(0.3)
W = 1e-6  # work of adhesion in E R (glass: 0.4 J/m^2 / (63 GPa * 10 um) = 6.3e-7)
CONTACT = JKRContact(LAW.E_star, LAW.R, W, mass=SPHERE_MASS)
V_S = CONTACT.sticking_speed
# Non-round constants in SI-like units for the curve's own numbers.
ODD = JKRContact(3.7e10, 2.3e-5, 0.173)


def approx(expected, *, rel=1e-6, abs=0.0):
    """``pytest.approx`` without its default absolute tolerance (1e-12), which would pass the
    small SI numbers here (lengths of 1e-7 m, forces of 1e-5 N) at any relative error."""
    return pytest.approx(expected, rel=rel, abs=abs)


# -- definitions -------------------------------------------------------------------------------


def test_work_of_adhesion_is_dupres():
    assert work_of_adhesion(0.1) == approx(0.2, rel=1e-15)  # 2 gamma, identical, vacuum
    assert work_of_adhesion(0.1, 0.3, 0.05) == approx(0.35, rel=1e-15)
    with pytest.raises(InputError, match="gamma12 <="):
        work_of_adhesion(0.1, 0.1, 0.3)


def test_reduced_work_of_adhesion_is_w_over_E_R():
    # The pull-off force (3/2) pi w R in E R^2 is the SI one over E R^2.
    E, R, w = 63e9, 10e-6, 0.4
    reduced = JKRContact(1.0, 1.0, reduced_work_of_adhesion(w, E, R))
    si = JKRContact(E, R, w)
    assert reduced.load_control_pull_off_force * E * R**2 == approx(
        si.load_control_pull_off_force, rel=1e-14
    )


# -- the JKR curve -----------------------------------------------------------------------------


def test_jkr_numbers_are_the_curves_zeros_and_extrema():
    c, l = ODD, ODD.length_scale
    a0 = brentq(lambda a: float(c.force(a)), 0.5 * l, 5.0 * l, xtol=1e-20, rtol=1e-15)
    assert a0 == approx(c.zero_load_radius, rel=1e-12)
    snap = brentq(lambda a: float(c.compression(a)), 0.5 * l, 5.0 * l, xtol=1e-20, rtol=1e-15)
    assert snap == approx(c.snap_in_radius, rel=1e-12)
    assert float(c.force(snap)) == approx(c.snap_in_force, rel=1e-12)
    opts = {"bounds": (0.1 * l, 3.0 * l), "method": "bounded", "options": {"xatol": 1e-13 * l}}
    load = minimize_scalar(lambda a: float(c.force(a)), **opts)
    assert load.fun == approx(c.load_control_pull_off_force, rel=1e-12)
    assert load.fun == approx(-1.5 * math.pi * c.w * c.R, rel=1e-12)
    neck = minimize_scalar(lambda a: float(c.compression(a)), **opts)
    # A minimum's position is good to the square root of the rounding: 1.5e-8 here; F moves
    # 1.2 times as much (d ln F / d ln a = 6/5 at a_c).
    assert neck.x == approx(c.pull_off_radius, rel=1e-7)
    assert neck.fun == approx(c.pull_off_compression, rel=1e-12)
    assert float(c.force(neck.x)) == approx(c.pull_off_force, rel=1.2e-7)
    # Johnson's forms: a0^3 = 9 pi w R^2 / (2 E*), a_c = a0 / 6^(2/3).
    assert c.zero_load_radius**3 == approx(4.5 * math.pi * c.w * c.R**2 / c.E_star, rel=1e-14)
    assert c.pull_off_radius == approx(c.zero_load_radius / 6.0 ** (2.0 / 3.0), rel=1e-14)


def test_branch_inversion_undoes_the_parametrisation():
    a = ODD.pull_off_radius * np.concatenate(
        [[1.0, 1.0 + 1e-9, 1.001], np.geomspace(1.1, 1e6, 200)]
    )
    back = ODD.contact_radius(ODD.compression(a))
    # Near the double root (the pull-off) a rounding of delta moves a by its square root.
    assert np.max(np.abs(back[:3] / a[:3] - 1.0)) < 1e-7
    assert np.max(np.abs(back[3:] / a[3:] - 1.0)) < 1e-12
    with pytest.raises(InputError, match="neck broke"):
        ODD.contact_radius(1.01 * ODD.pull_off_compression)


def test_potential_is_the_work_of_the_force():
    c = ODD
    for a1, a2 in ((c.pull_off_radius, c.snap_in_radius), (c.snap_in_radius, 40 * c.length_scale)):
        work, _ = quad(lambda a: float(c.force(a)) * (2 * a / c.R - math.sqrt(
            math.pi * c.w / (2 * c.E_star * a))), a1, a2, epsabs=0, epsrel=1e-13)  # fmt: skip
        du = float(c.potential(c.compression(a2)) - c.potential(c.compression(a1)))
        assert du == approx(work, rel=1e-11)


def test_hysteresis_constant_by_quadrature_and_published():
    # Delta W = -int_{delta_c}^{0} F d delta along the branch, by quadrature in a.
    c = ODD
    work, _ = quad(lambda a: -float(c.force(a)) * (2 * a / c.R - math.sqrt(
        math.pi * c.w / (2 * c.E_star * a))), c.pull_off_radius, c.snap_in_radius, epsabs=0,
        epsrel=1e-13)  # fmt: skip
    assert c.hysteresis == approx(work, rel=1e-11)
    assert float(c.potential(c.pull_off_compression)) == approx(work, rel=1e-11)
    # Thornton and Ning (1998) as cited by a public DEM script: 7.09; their v_s constant 1.84.
    assert HYSTERESIS_CONSTANT == approx(7.09, abs=0.005)
    assert STICKING_SPEED_WALL == approx(1.84, abs=0.005)


def test_sticking_speed_forms_of_a_sphere_and_a_pair():
    E_star, rho, R, w = 66.85e9, 2500.0, 10e-6, 0.4
    m = 4.0 / 3.0 * math.pi * rho * R**3
    base = (w**5 / (rho**3 * E_star**2 * R**5)) ** (1.0 / 6.0)
    assert sticking_speed(E_star, R, w, m) == approx(STICKING_SPEED_WALL * base, rel=1e-14)
    # Two identical spheres: R_eff = R/2, m/2, E* of the pair (half the wall's for equal bodies).
    pair = sticking_speed(E_star / 2, R / 2, w, m / 2)
    base2 = (w**5 / (rho**3 * (E_star / 2) ** 2 * R**5)) ** (1.0 / 6.0)
    assert pair == approx(STICKING_SPEED_PAIR * base2, rel=1e-14)


def test_closed_form_epsilon_and_its_limits():
    u = np.array([0.0, 0.5, 1.0, 1.0 + 1e-8, 2.0, 1e3])
    eps = adhesive_epsilon(u, 1.0)
    assert np.all(eps[:3] == 0.0)
    assert eps[3] == approx(math.sqrt(2e-8), rel=1e-6)  # sqrt(2 (v - v_s) / v_s)
    np.testing.assert_allclose(1.0 - eps[4:] ** 2, 1.0 / u[4:] ** 2, rtol=1e-9)  # rounding
    assert 1.0 - eps[-1] == approx(0.5e-6, rel=1e-6)  # (v_s/v)^2 / 2 far above


# -- the integrated collision ------------------------------------------------------------------


@pytest.mark.parametrize("u", [1.001, 1.1, 3.0, 100.0])
def test_integration_meets_the_closed_form_as_rtol_falls(u):
    v = u * V_S
    exact = float(CONTACT.epsilon(v))
    runs = [adhesive_collision(CONTACT, v, rtol=r) for r in (1e-6, 1e-8, 1e-10)]
    misses = [abs(r.epsilon**2 - exact**2) for r in runs]  # the energy lost, ((m/2) v^2)
    assert all(not r.stuck for r in runs)
    assert misses[-1] < 1e-9
    assert misses[2] < 1e-2 * misses[0]  # falls at least like rtol^(1/2)
    assert runs[-1].energy_error < 1e-9
    assert runs[-1].hysteresis == approx((V_S / v) ** 2, rel=1e-12)


@pytest.mark.parametrize("u", [0.5, 0.999])
def test_below_the_sticking_speed_the_grain_stays(u):
    v = u * V_S
    r = adhesive_collision(CONTACT, v, bounces=4)
    assert r.stuck and r.epsilon == 0.0
    assert r.min_compression > CONTACT.pull_off_compression
    # It turns where the branch has taken all its kinetic energy (the closed-form potential).
    assert float(CONTACT.potential(r.min_compression)) == approx(
        0.5 * SPHERE_MASS * v * v, rel=1e-8
    )
    assert r.energy_error < 1e-9
    with pytest.raises(InputError, match="stuck"):
        r.spectrum([1.0])
    assert not adhesive_collision(CONTACT, 1.001 * V_S).stuck


def test_energy_is_conserved_on_the_branch():
    v = 3.0 * V_S
    r = adhesive_collision(CONTACT, v)
    d, dd = r.trajectory(np.linspace(0.0, r.contact_time, 401))
    energy = 0.5 * SPHERE_MASS * dd**2 + CONTACT.potential(np.maximum(d, r.min_compression))
    assert np.max(np.abs(energy / (0.5 * SPHERE_MASS * v * v) - 1.0)) < 1e-9
    assert d[0] == approx(0.0, abs=1e-12 * r.max_compression)
    assert d[-1] == approx(CONTACT.pull_off_compression, rel=1e-9)


def test_force_of_the_state_meets_the_force_of_the_inverted_branch():
    # The integration carries the contact radius; Ferrari's root gives it from delta.
    r = adhesive_collision(CONTACT, 3.0 * V_S)
    t = np.linspace(0.0, r.contact_time, 101)
    d, _ = r.trajectory(t)
    by_root = CONTACT.force(CONTACT.contact_radius(np.maximum(d, CONTACT.pull_off_compression)))
    assert np.max(np.abs(r.force(t) - by_root)) < 1e-7 * CONTACT.force_scale
    assert r.force(np.array([0.0]))[0] == approx(CONTACT.snap_in_force, rel=1e-12)
    assert r.force(np.array([r.contact_time]))[0] == approx(CONTACT.pull_off_force,
                                                                   rel=1e-6)  # fmt: skip


def _measured_sticking_speed(contact: JKRContact, v: float) -> float:
    """``v_s`` from the energy an integrated collision at ``v`` loses."""
    r = adhesive_collision(contact, v)
    assert not r.stuck
    return v * math.sqrt(1.0 - r.epsilon**2)


def test_sticking_speed_exponents_from_integrations():
    # Fixed density: the mass grows like R^3, like rho.
    v = 10.0 * V_S
    factors = np.array([1.0, 2.0, 4.0])
    cases = {
        "w": (5.0 / 6.0, lambda f: JKRContact(LAW.E_star, 1.0, W * f, mass=SPHERE_MASS)),
        "R": (-5.0 / 6.0, lambda f: JKRContact(LAW.E_star, f, W, mass=SPHERE_MASS * f**3)),
        "E*": (-1.0 / 3.0, lambda f: JKRContact(LAW.E_star * f, 1.0, W, mass=SPHERE_MASS)),
        "rho": (-0.5, lambda f: JKRContact(LAW.E_star, 1.0, W, mass=SPHERE_MASS * f)),
    }
    for name, (exponent, build) in cases.items():
        measured = [_measured_sticking_speed(build(f), v) for f in factors]
        slope = np.polyfit(np.log(factors), np.log(measured), 1)[0]
        assert slope == approx(exponent, abs=1e-7), name
        assert measured[0] == approx(V_S, rel=1e-8)


def test_two_spheres_are_one_on_the_wall_at_half_speed():
    # Identical spheres: the mid-plane is a rigid frictionless wall taking half of w.
    wall = JKRContact(LAW.E_star, 1.0, W / 2, mass=SPHERE_MASS)
    pair = JKRContact(LAW.E_star / 2, 0.5, W, mass=SPHERE_MASS / 2)
    u = 3.0 * pair.sticking_speed
    assert adhesive_collision(pair, u).epsilon == approx(
        adhesive_collision(wall, u / 2).epsilon, abs=1e-9
    )
    assert _measured_sticking_speed(pair, u) == approx(2 * wall.sticking_speed, rel=1e-8)
    # The pair's constant, in the sphere's radius and the pair's E* (rho = 1 here).
    base = (W**5 / (pair.E_star**2 * 1.0**5)) ** (1.0 / 6.0)
    assert _measured_sticking_speed(pair, u) == approx(STICKING_SPEED_PAIR * base, rel=1e-8)


def test_glass_bead_through_the_reduced_units():
    # docs/adhesion.md: E = 63 GPa, nu = 0.24, rho = 2500 kg/m^3, R = 10 um, w = 0.4 J/m^2.
    E, nu, rho, R, w = 63e9, 0.24, 2500.0, 10e-6, 0.4
    c_sound = math.sqrt(E / rho)
    reduced = JKRContact(1.0 / (1.0 - nu**2), 1.0, reduced_work_of_adhesion(w, E, R),
                         mass=SPHERE_MASS)  # fmt: skip
    v_si = _measured_sticking_speed(reduced, 5.0 * reduced.sticking_speed) * c_sound
    E_star = E / (1.0 - nu**2)
    closed = STICKING_SPEED_WALL * (w**5 / (rho**3 * E_star**2 * R**5)) ** (1.0 / 6.0)
    assert v_si == approx(closed, rel=1e-8)
    assert closed == approx(0.0620, abs=5e-5)  # the number docs/adhesion.md quotes


def test_a_crushing_speed_is_refused():
    with pytest.raises(InputError, match="reaches R"):
        adhesive_collision(CONTACT, 1.0)


# -- Kelvin-Voigt damping on the same pulse ----------------------------------------------------


def _loss_slope(contact: JKRContact, v: float) -> float:
    """``lim (epsilon_el^2 - epsilon^2) / A``: the viscous work ``int 2 E* a delta'^2 dt`` along
    the elastic path, by quadrature in the contact radius (speed from the closed-form
    potential): twice the compression branch, once the tension down to ``a_c``."""
    c, m = contact, contact.mass
    l, e0 = c.length_scale, 0.5 * m * v * v

    def speed(a):
        return math.sqrt(max(v * v - 2.0 * float(c.potential(c.compression(a))) / m, 0.0))

    def integrand(a):
        slope = 2 * a / c.R - math.sqrt(math.pi * c.w / (2 * c.E_star * a))
        return 2.0 * c.E_star * a * speed(a) * slope

    a_max = brentq(lambda a: float(c.potential(c.compression(a))) - e0, c.snap_in_radius, 1e6 * l)
    comp, _ = quad(integrand, c.snap_in_radius, a_max, epsabs=0, epsrel=1e-12, limit=200)
    tension, _ = quad(integrand, c.pull_off_radius, c.snap_in_radius, epsabs=0, epsrel=1e-12)
    return (2.0 * comp + tension) / e0


@pytest.mark.parametrize("u", [1.5, 5.0])
def test_damping_to_first_order_is_the_work_on_the_elastic_path(u):
    v = u * V_S
    elastic = adhesive_collision(CONTACT, v).epsilon ** 2
    slopes = {A: (elastic - adhesive_collision(CONTACT, v, tau=A).epsilon ** 2) / A
              for A in (1e-3, 1e-4)}  # fmt: skip
    # The slope is linear in A near 0: Richardson's extrapolation removes the first order.
    extrapolated = (10.0 * slopes[1e-4] - slopes[1e-3]) / 9.0
    assert extrapolated == approx(_loss_slope(CONTACT, v), rel=1e-6)
    assert abs(slopes[1e-3] / extrapolated - 1.0) > 1e-5  # the first order was there


def test_without_adhesion_it_is_the_viscous_collision():
    # delta_c -> 0: the end at delta = 0 of the "compression" criterion. The contact radius
    # differs from Hertz's by O(w^(1/2)), hence the viscous work and epsilon.
    v, tau = 1e-3, 0.05
    ref = viscous_collision(LAW, [v], tau, separation="compression")
    ws = np.array([1e-8, 1e-10, 1e-12])
    miss = []
    for w in ws:
        r = adhesive_collision(JKRContact(LAW.E_star, LAW.R, w, mass=SPHERE_MASS), v, tau=tau)
        assert r.energy_error < 1e-9
        miss.append(abs(r.epsilon - ref.epsilon[0]))
    order = np.diff(np.log(miss)) / np.diff(np.log(ws))
    assert order == approx([0.5, 0.5], abs=0.02)
    assert miss[-1] < 1e-5


def test_damping_raises_the_sticking_speed_and_keeps_the_energy():
    v = 1.05 * V_S
    damped = adhesive_collision(CONTACT, v, tau=0.3)
    assert damped.stuck and not adhesive_collision(CONTACT, v).stuck
    r = adhesive_collision(CONTACT, 3.0 * V_S, tau=0.05)
    assert r.viscous_work > 0.01
    assert r.epsilon**2 + r.hysteresis + r.viscous_work == approx(1.0, abs=1e-9)


# -- the pulse for the waves -------------------------------------------------------------------


@pytest.fixture(scope="module")
def rebound():
    return adhesive_collision(CONTACT, 3.0 * V_S)


@pytest.mark.slow  # 7 s of the default run (stop 76: the default run under 10 min)
def test_spectrum_meets_direct_quadrature(rebound):
    T = rebound.contact_time
    for omega in (1.0 / T, 10.0 / T):
        got = rebound.spectrum([omega])[0]

        def force(t):
            return float(rebound.force(np.array([t]))[0])

        re, _ = quad(force, 0, T, weight="cos", wvar=omega, epsabs=0, epsrel=1e-10, limit=200)
        im, _ = quad(force, 0, T, weight="sin", wvar=omega, epsabs=0, epsrel=1e-10, limit=200)
        assert abs(got - (re - 1j * im)) < 1e-9 * abs(got)


def test_the_jumps_set_the_high_frequency_spectrum(rebound):
    # i omega F(omega) -> F(0+) - F(T-) e^{-i omega T}: the two jumps. The rise F_c + K sqrt(T - t)
    # before the neck breaks adds -(K/2) sqrt(pi/omega) e^{i pi/4} e^{-i omega T}, with
    # K = -2 pi w R sqrt(2 u / (3 delta_s)) (u the rebound speed; module docs), and the smooth
    # rest O(1/omega).
    T = rebound.contact_time
    omega = np.array([1e3, 1e4, 1e5]) / T
    jumps = CONTACT.snap_in_force - CONTACT.pull_off_force * np.exp(-1j * omega * T)
    rest = 1j * omega * rebound.spectrum(omega) - jumps
    u = rebound.epsilon * rebound.v
    K = -2.0 * CONTACT.force_scale * math.sqrt(2.0 * u / (3.0 * CONTACT.compression_scale))
    rise = -0.5 * K * np.sqrt(math.pi / omega) * np.exp(1j * (math.pi / 4 - omega * T))
    miss = np.abs(rest / rise - 1.0)  # O(omega^(-1/2))
    assert np.all(np.diff(miss) < 0) and miss[-1] < 1e-2
    assert np.diff(np.log(np.abs(rest))) / np.diff(np.log(omega)) == approx([-0.5, -0.5], abs=0.01)
    assert math.isinf(rebound.force_rate_integral)


@pytest.mark.parametrize("tau", [0.0, 0.05])
def test_the_spectrum_without_the_jumps_is_the_full_one_less_the_steps(tau):
    # Integration by parts: F(omega) = F_jump_free(omega) + (F(0+) - F(T-) e^{-i omega T}) /
    # (i omega). The full spectrum (the force at the nodes, met by quad above) less the steps,
    # which are taken from force() at the pulse's ends, against the direct integral of dF/dsigma.
    # Where omega T = 1 and 10 the steps and the jump-free part are of one size (no cancellation):
    # the full spectrum's 1e-9 of quad above is the tolerance. Measured 4.8e-12, 2.7e-11 (tau 0)
    # and 4.7e-12, 2.1e-12 (tau 0.05) of |F|.
    r = adhesive_collision(CONTACT, 3.0 * V_S, tau=tau)
    T = r.contact_time
    omega = np.array([1.0, 10.0]) / T
    start, end = (float(f) for f in r.force(np.array([0.0, T])))
    assert r.jump_free_terms() == approx((start, end), rel=1e-12)
    if tau == 0.0:
        assert (start, end) == approx((CONTACT.snap_in_force, CONTACT.pull_off_force), rel=1e-9)
    full = r.spectrum(omega)
    steps = (start - end * np.exp(-1j * omega * T)) / (1j * omega)
    got = r.spectrum(omega, jumps=False)
    assert np.all(np.abs(got - (full - steps)) < 1e-9 * np.abs(full))
    assert np.all(np.abs(got) > 0.5 * np.abs(full))  # of one size: measured 1.30, 0.75
    both = r.mode_energy(SimpleNamespace(omega=omega, C=np.ones(2), mass=SPHERE_MASS),
                         viscous="both", jumps=False)  # fmt: skip
    assert both.shape == (2, 2) and (tau > 0) == bool(np.all(both[:, 0] != both[:, 1]))


@pytest.mark.parametrize("tau", [0.0, 0.05])
def test_the_full_pulses_mode_energy_is_the_parts_and_their_interference(tau):
    # |F_smooth + F_jumps|^2 = |F_smooth|^2 + |F_jumps|^2 + 2 Re(F_smooth conj(F_jumps)): the full
    # pulse's energy (the force at the nodes, met by quad above) against mode_energy_parts (the
    # jump-free quadrature, the jumps' closed spectrum, their interference), with and without
    # the viscous force, from omega T = 1 to 1e4. The jumps alone are the steps of force() at the
    # pulse's ends. Per mode, of the parts' largest: up to omega T = 10 measured 8.0e-12 (tau 0)
    # and 7.8e-12 (tau 0.05); above, the integration's floor at rtol = 1e-10 (either spectrum
    # good to about 1e-6 there, docs/adhesion.md), measured 3.5e-7 and 1.0e-7 (at rtol = 1e-12:
    # 3.4e-9 and 9.1e-9).
    r = adhesive_collision(CONTACT, 3.0 * V_S, tau=tau)
    T = r.contact_time
    modes = SimpleNamespace(omega=np.geomspace(1.0, 1e4, 9) / T, C=np.linspace(0.5, 1.5, 9),
                            mass=SPHERE_MASS)  # fmt: skip
    start, end = (float(f) for f in r.force(np.array([0.0, T])))
    steps = (start - end * np.exp(-1j * modes.omega * T)) / (1j * modes.omega)
    assert np.all(np.abs(r.spectrum(modes.omega, jumps="only") - steps) < 1e-12 * np.abs(steps))
    full = r.mode_energy(modes, viscous="both")
    smooth, jumps, cross = r.mode_energy_parts(modes, viscous="both")
    assert smooth.shape == jumps.shape == cross.shape == full.shape == (9, 2)
    assert np.array_equal(smooth, r.mode_energy(modes, viscous="both", jumps=False))
    assert np.array_equal(jumps, r.mode_energy(modes, viscous="both", jumps="only"))
    scale = np.maximum(np.maximum(smooth, jumps), np.abs(cross))
    residual = np.abs(full - (smooth + jumps + cross)) / scale
    assert np.max(residual[:3]) < 1e-10 and np.max(residual) < 1e-6, residual
    # the interference is of the parts' size at low frequency: it is not a rounding
    assert np.max(np.abs(cross[:3]) / scale[:3]) > 0.1
    with pytest.raises(InputError, match="jumps must be"):
        r.spectrum(modes.omega, jumps="none")


def test_without_the_jumps_the_spectrum_falls_like_omega_to_minus_3_2(rebound):
    # What is left at high frequency is the rise F_c + K sqrt(T - t) before the neck break (the
    # previous test's "rest", here computed directly, without subtracting the jumps).
    T = rebound.contact_time
    omega = np.array([1e3, 1e4, 1e5]) / T
    got = 1j * omega * rebound.spectrum(omega, jumps=False)
    u = rebound.epsilon * rebound.v
    K = -2.0 * CONTACT.force_scale * math.sqrt(2.0 * u / (3.0 * CONTACT.compression_scale))
    rise = -0.5 * K * np.sqrt(math.pi / omega) * np.exp(1j * (math.pi / 4 - omega * T))
    miss = np.abs(got / rise - 1.0)  # O(omega^(-1/2)): measured 0.078, 0.016, 0.0053
    assert np.all(np.diff(miss) < 0) and miss[-1] < 1e-2
    assert np.diff(np.log(np.abs(got))) / np.diff(np.log(omega)) == approx([-0.5, -0.5], abs=0.01)
    # B = K^2 / 4: the log coefficient of the force-rate integral is this tail's
    assert rebound.force_rate_log_coefficient == approx(K * K / 4.0, rel=1e-12)
    with pytest.raises(InputError, match="omega > 0"):
        rebound.spectrum([0.0], jumps=False)


def test_force_rate_integral_grows_with_the_log_of_the_cutoff(rebound):
    cut = rebound.contact_time * 10.0 ** -np.arange(5.0, 9.0)
    I = np.array([rebound.smooth_force_rate_integral(c) for c in cut])
    miss = np.abs(np.diff(I) / math.log(10.0) / rebound.force_rate_log_coefficient - 1.0)
    # The next term of the expansion is ~ cutoff^(1/2).
    order = np.log10(miss[:-1] / miss[1:])
    assert order == approx([0.5, 0.5], abs=0.1)
    assert miss[-1] < 1e-3


def test_mode_energy_tends_to_the_hertz_pulse_as_w_vanishes():
    # Modes of period about the contact time (Rayleigh's range) and below; at rtol = 1e-10
    # either pulse's spectrum is good to about 1e-6 there, hence rtol = 1e-12 here.
    modes = SimpleNamespace(omega=np.array([0.5, 2.0, 8.0]), C=np.ones(3), mass=SPHERE_MASS)
    v, rtol = 1e-3, 1e-12
    hertz = pulse_collision(LAW, v, rtol=rtol).mode_energy(modes)
    miss = [np.abs(adhesive_collision(JKRContact(LAW.E_star, LAW.R, w, mass=SPHERE_MASS), v,
                                      rtol=rtol).mode_energy(modes) / hertz - 1.0)
            for w in (1e-9, 1e-11, 1e-13)]  # fmt: skip
    assert np.all(miss[1] < 0.1 * miss[0]) and np.all(miss[2] < 0.1 * miss[1])
    assert np.max(miss[2]) < 1e-6
    # The pulse without its jumps too (the jumps are first order in w): measured misses
    # (1.1e-5, 1.6e-6, 1.6e-3), (1.1e-7, 4.4e-8, 1.5e-5), (1.1e-9, 4.8e-10, 1.5e-7).
    miss = [np.abs(adhesive_collision(JKRContact(LAW.E_star, LAW.R, w, mass=SPHERE_MASS), v,
                                      rtol=rtol).mode_energy(modes, jumps=False) / hertz - 1.0)
            for w in (1e-9, 1e-11, 1e-13)]  # fmt: skip
    assert np.all(miss[1] < 0.1 * miss[0]) and np.all(miss[2] < 0.1 * miss[1])
    assert np.max(miss[2]) < 1e-6
    modes = SimpleNamespace(omega=np.geomspace(0.1, 100.0, 5), C=np.ones(5), mass=SPHERE_MASS)
    both = adhesive_collision(CONTACT, 3.0 * V_S, tau=0.05).mode_energy(modes, viscous="both")
    assert both.shape == (5, 2) and np.all(both > 0)


# -- refusals ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (lambda: JKRContact(1.0, 1.0, -0.1), "w must be >= 0"),
        (lambda: JKRContact(1.0, 1.0, float("nan")), "finite"),
        (lambda: JKRContact(0.0, 1.0, 0.1), "E_star must be > 0"),
        (lambda: JKRContact(1.0, 1.0, "0.1"), "pass w as a float"),
        (lambda: JKRContact(1.0, 1.0, 0.1).sticking_speed, "mass=m"),
        (
            lambda: adhesive_collision(JKRContact(1.0, 1.0, 0.0, mass=1.0), 1e-3),
            "viscous_collision",
        ),
        (lambda: adhesive_collision(CONTACT, 1e-3, bounces=0), "bounces"),
        (lambda: adhesive_collision(CONTACT, -1e-3), "v must be > 0"),
        (lambda: adhesive_collision(LAW, 1e-3), "JKRContact"),
        (lambda: reduced_work_of_adhesion(-1.0, 63e9, 1e-5), "w_si"),
    ],
)
def test_bad_input_is_refused_in_one_line(call, words):
    with pytest.raises(InputError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message and words in message
