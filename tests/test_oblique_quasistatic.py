"""The quasistatic oblique impact (restitution.quasistatic.oblique), each check by a route of its
own: Mindlin's and Hertz's stiffnesses, the impulse ratio of gross slip, conservation laws, a
closed form of the rough limit (hypergeometric, docs/oblique.md), an independent solution of the
microslip law's rough limit, convergence orders, self-similarity and time reversal.
Units: E = rho = R = 1 of the grain, speeds in c, spins in c/R."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from restitution.errors import InputError
from restitution.quasistatic import oblique
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    sphere_contact_law,
    sphere_pair_contact_law,
    sphere_pair_mass,
    sphere_quasistatic_trajectory,
)
from restitution.quasistatic.oblique import (
    MODELS,
    beta_of_psi,
    gross_slip_beta,
    gross_slip_psi,
    no_slip_beta,
    oblique_impact,
    stiffness_ratio,
)

NO_MICROSLIP, MICROSLIP = MODELS
NU, V = 0.3, 0.01
CHI = stiffness_ratio(NU)


def impact(psi, *, mu=0.5, v=V, nu=NU, **kw):
    """The impact at ``psi`` (no spin): ``v_t = psi mu v / chi``."""
    return oblique_impact(v, psi * mu * v / stiffness_ratio(nu), mu, nu, **kw)


def test_doctests():
    assert doctest.testmod(oblique).failed == 0


@pytest.mark.parametrize("nu", [0.0, 0.25, 0.45])
def test_stiffness_ratio_is_mindlin_over_hertz(nu):
    """``k_t = 8 a / sum (2 - nu_i) / G_i`` (Mindlin) over ``dP/d delta`` of the package's
    Hertz laws, on the rigid wall and between two identical spheres: the same ``chi``."""
    G = 1.0 / (2.0 * (1.0 + nu))
    delta = 1e-3
    for law, compliances in ((sphere_contact_law(nu), 1), (sphere_pair_contact_law(nu), 2)):
        a = float(law.contact_radius(delta))
        k_t = 8.0 * a / (compliances * (2.0 - nu) / G)
        assert_allclose(k_t / float(law.stiffness(delta)), stiffness_ratio(nu), rtol=1e-13)


@pytest.mark.parametrize("model", MODELS)
def test_frictionless_contact_is_smooth(model):
    """mu = 0: no tangential force, so beta = -1 exactly, the spin is kept and the normal
    coefficient is 1."""
    out = oblique_impact(V, 0.02, 0.0, NU, spin=0.7, model=model)
    assert out.beta == -1.0
    assert out.spin == 0.7 and out.v_tangential == 0.02
    assert out.friction_work == 0.0
    assert_allclose(out.normal_coefficient, 1.0, atol=1e-10)
    assert abs(out.energy_balance) < 1e-10 * out.kinetic_energy_before


@pytest.mark.parametrize("model,tol", [(NO_MICROSLIP, 1e-10), (MICROSLIP, 1e-6)])
@pytest.mark.parametrize("factor", [1.02, 2.0, 6.0])
def test_gross_slip_is_the_impulse_ratio(model, tol, factor):
    """Sliding throughout, ``|J_t| = mu J_n = 2 mu m v_n``: ``beta = -1 + K mu (1 + e) /
    tan(theta) = -1 + 2 K chi / psi``, for a sphere (K = 7/2) and a disk-like K = 3."""
    for K in (3.5, 3.0):
        psi = factor * gross_slip_psi(NU, K, model)
        extra = {"springs": 400} if model == MICROSLIP else {}
        out = impact(psi, mu=0.3, inertia_factor=K, model=model, **extra)
        tan_theta = psi * 0.3 / CHI
        assert_allclose(out.beta, -1.0 + K * 0.3 * 2.0 / tan_theta, atol=tol)
        if model == NO_MICROSLIP:
            assert [name for name, _ in out.phases] == ["slip+"]


def test_gross_slip_begins_at_its_threshold():
    """No-microslip: the cap is reached at once above psi = 2/3, and slip lasts to the end above
    2 K chi - 2/3. Microslip: below 2 K chi - 1 some of the contact sticks and the friction
    impulse falls short of mu J_n, so beta lies below the gross-slip line."""
    first = [impact(p, model=NO_MICROSLIP).phases[0][0] for p in (0.66, 0.67)]
    assert first == ["stick", "slip+"]
    edge = gross_slip_psi(NU, model=NO_MICROSLIP)
    assert len(impact(edge * 0.99, model=NO_MICROSLIP).phases) == 3
    assert len(impact(edge * 1.001, model=NO_MICROSLIP).phases) == 1
    edge = gross_slip_psi(NU)
    assert_allclose(impact(1.001 * edge).beta, gross_slip_beta(1.001 * edge, NU), atol=1e-6)
    assert impact(0.95 * edge).beta < gross_slip_beta(0.95 * edge, NU) - 1e-3


@pytest.mark.parametrize("psi", [0.3, 1.0, 2.0, 3.0, 5.0, 1e3])
def test_energy_balance_no_microslip(psi):
    """Kinetic energy lost = friction work + stiffness loss (+ elastic energy left, 0), to the
    ODE tolerance; the kinetic energies recomputed here from the outputs."""
    out = impact(psi, model=NO_MICROSLIP)
    inertia = SPHERE_MASS / (out.inertia_factor - 1.0)
    vt0 = psi * 0.5 * V / CHI
    ke0 = 0.5 * SPHERE_MASS * (V**2 + vt0**2)
    ke1 = 0.5 * SPHERE_MASS * ((out.normal_coefficient * V) ** 2 + out.v_tangential**2)
    ke1 += 0.5 * inertia * out.spin**2
    lost = out.friction_work + out.stiffness_loss + out.elastic_energy_left
    assert abs(ke0 - ke1 - lost) < 1e-8 * ke0
    assert out.elastic_energy_left < 1e-12 * ke0 and out.friction_work >= 0.0


def test_energy_balance_microslip_converges_at_second_order():
    """The microslip law has no stiffness loss; its balance error falls like springs^-2."""
    errors = [abs(impact(3.0, model=MICROSLIP, springs=n).energy_balance) for n in (100, 200, 400)]
    slope = np.polyfit(np.log([100, 200, 400]), np.log(errors), 1)[0]
    assert -2.3 < slope < -1.7, (errors, slope)
    out = impact(3.0, model=MICROSLIP)
    assert out.stiffness_loss == 0.0
    assert abs(out.energy_balance) < 2e-7 * out.kinetic_energy_before


def test_microslip_beta_converges_at_second_order():
    """In gross slip, where only the quadrature of mu P errs, the error against the exact beta;
    in partial slip, the differences beta(n) - beta(2 n): both fall like springs^-2."""
    counts = np.array([100, 200, 400])
    exact = gross_slip_beta(7.0, NU)
    err = [abs(impact(7.0, model=MICROSLIP, springs=int(n)).beta - exact) for n in counts]
    slope = np.polyfit(np.log(counts), np.log(err), 1)[0]
    assert -2.3 < slope < -1.7, (err, slope)
    beta = [impact(0.3, model=MICROSLIP, springs=int(n)).beta for n in (*counts, 800)]
    slope = np.polyfit(np.log(counts), np.log(np.abs(np.diff(beta))), 1)[0]
    assert -2.3 < slope < -1.3, (beta, slope)


@pytest.mark.parametrize("nu,K", [(0.3, 3.5), (0.2, 3.5), (0.45, 3.0), (0.3, 1.0 / CHI)])
def test_rough_limit_closed_form(nu, K):
    """mu = inf: ``xi'' + K chi k_n(t) xi / m = 0`` solved by DOP853 against its hypergeometric
    closed form; K chi = 1 is the normal velocity's equation, beta = 1."""
    out = oblique_impact(V, 0.004, math.inf, nu, inertia_factor=K, model=NO_MICROSLIP)
    assert_allclose(out.beta, no_slip_beta(nu, K), atol=1e-9)
    assert out.phases == (("stick", 0.0),) and out.friction_work == 0.0
    if K == 1.0 / CHI:
        assert_allclose(out.beta, 1.0, atol=1e-9)


def test_no_microslip_reaches_its_rough_limit_like_psi_to_three_halves():
    """The final slip, which brings T to 0 with mu P, lasts a time ~ psi tau and changes v_c by
    ~ psi^(5/2): beta - beta_0 ~ psi^(3/2)."""
    psi = np.array([0.003, 0.01, 0.03])
    err = np.abs(beta_of_psi(psi, NU, model=NO_MICROSLIP) - no_slip_beta(NU))
    slope = np.polyfit(np.log(psi), np.log(err), 1)[0]
    assert 1.4 < slope < 1.65, (err, slope)


def _microslip_rough_limit(nu: float, K: float, v: float = V) -> float:
    """beta of the microslip law as psi -> 0, solved on its own: every spring sticks from when
    it touches (``u(t_x)``) until it leaves, so ``T = -2 chi E* (a u - J)``, ``J = int_0^a
    u(t_x) dx``; a spring leaves at ``tau - t_x``, so in unloading ``J(t) = J_load(tau - t)``.
    DOP853 in ``s`` (``dt = 2 sqrt(delta) ds``), loading half then unloading half."""
    law, chi, m = sphere_contact_law(nu), stiffness_ratio(nu), SPHERE_MASS
    kap = 2.0 * chi * law.E_star

    def load(_s, y):
        r, nd, u, vc, J = y
        return [nd, -2 * law.K * r**4 / m, 2 * r * vc, -2 * r * K / m * kap * (r * u - J), u * nd]

    def turn(_s, y):
        return y[1]

    turn.terminal, turn.direction = True, -1.0
    first = solve_ivp(
        load,
        (0, 1e3),
        [0, v, 0, 1, 0],
        "DOP853",
        rtol=1e-12,
        atol=1e-15,
        events=turn,
        dense_output=True,
    )
    s_mid = first.t_events[0][0]

    def unload(s, y):
        r, nd, u, vc = y
        J = first.sol(2 * s_mid - s)[4]
        return [nd, -2 * law.K * r**4 / m, 2 * r * vc, -2 * r * K / m * kap * (r * u - J)]

    second = solve_ivp(
        unload, (s_mid, 2 * s_mid), first.y_events[0][0][:4], "DOP853", rtol=1e-12, atol=1e-15
    )
    assert abs(second.y[0, -1]) < 1e-9 and abs(second.y[1, -1] + v) < 1e-9
    return -second.y[3, -1]


def test_microslip_rough_limit_by_an_independent_solution():
    """beta(psi) of the spring model is linear in psi near 0; its extrapolation 2 beta(psi) -
    beta(2 psi) meets the rough limit solved apart (-0.23167 for the sphere, nu = 0.3)."""
    limit = _microslip_rough_limit(NU, 3.5)
    assert_allclose(limit, -0.231670, atol=2e-6)
    b1, b2 = beta_of_psi([0.004, 0.008], NU)
    assert_allclose(2 * b1 - b2, limit, atol=1e-5)
    assert abs(b1 - limit) > 3e-4  # the extrapolation, not psi = 0.004 alone, meets it


def test_microslip_copies_the_normal_motion_when_k_chi_is_one():
    """K chi = 1 and psi < 1: ``u = (v_c / v_n) delta`` sticks every spring within its bound
    ``(mu / chi)(delta - x^2)`` and T = chi P v_c / v_n: the contact point's velocity follows
    the normal one and is reversed, beta = 1, with no slip."""
    out = impact(0.5, inertia_factor=1.0 / CHI, model=MICROSLIP)
    assert_allclose(out.beta, 1.0, atol=1e-9)
    assert out.friction_work < 1e-7 * out.kinetic_energy_before  # 5e-9 measured, 800 springs


@pytest.mark.parametrize("model,tol", [(NO_MICROSLIP, 1e-8), (MICROSLIP, 1e-9)])
def test_beta_depends_on_psi_only(model, tol):
    """Two (theta, mu) with one psi, two speeds (Hertz's self-similarity), and spin traded for
    tangential speed at one v_c: one beta (the spring model at any number of springs)."""
    kw = {"model": model} | ({"springs": 200} if model == MICROSLIP else {})
    ref = impact(2.5, mu=0.5, **kw)
    assert_allclose(impact(2.5, mu=0.1, **kw).beta, ref.beta, atol=tol)
    assert_allclose(impact(2.5, mu=0.5, v=0.001, **kw).beta, ref.beta, atol=tol)
    vt0 = 2.5 * 0.5 * V / CHI
    spun = oblique_impact(V, vt0 + 0.003, 0.5, NU, spin=0.003, **kw)
    assert_allclose(spun.beta, ref.beta, atol=tol)


@pytest.mark.parametrize("model", MODELS)
def test_beta_depends_on_chi_only_through_psi_and_k_chi(model):
    """Scaling the tangential spring's stiffness by ``chi`` and its slip bound by ``1 / chi``
    leaves ``beta`` a function of ``psi`` and ``K chi`` alone (docs/oblique.md uses it to read
    law (b) at another ``chi`` through ``inertia_factor``): ``nu = 0.3`` with ``K = 7/2`` and
    ``nu = 0`` (``chi = 1``) with ``K = 7/2 x 0.8235`` at one ``psi`` give one ``beta``
    (measured at most 1.2e-15 apart for the microslip law, 6.2e-14 for the no-microslip law's
    DOP853, at ``psi = 0.25`` and 2.5)."""
    kw = {"springs": 200} if model == MICROSLIP else {}
    chi0 = stiffness_ratio(0.0)
    for psi in (0.25, 2.5):
        ref = beta_of_psi([psi], NU, model=model, **kw)[0]
        other = beta_of_psi([psi], 0.0, inertia_factor=3.5 * CHI / chi0, model=model, **kw)[0]
        assert_allclose(other, ref, atol=1e-9)


@pytest.mark.parametrize("model", MODELS)
def test_angular_momentum_about_the_contact_point_is_kept(model):
    """The normal force acts through the centre and T at the contact point: ``I omega + m R v_t``
    is kept, ``I = m R^2 / (K - 1)``."""
    out = oblique_impact(V, 0.01, 0.4, NU, spin=-0.002, model=model)
    inertia = SPHERE_MASS / (out.inertia_factor - 1.0)
    assert_allclose(
        inertia * out.spin + SPHERE_MASS * out.v_tangential,
        inertia * -0.002 + SPHERE_MASS * 0.01,
        rtol=1e-13,
    )
    assert out.spin != -0.002


def test_two_identical_spheres_are_the_wall_in_reduced_quantities():
    """beta depends on psi, K and chi only: the pair's Hertz law and reduced mass give the
    wall's beta."""
    wall = impact(2.0, model=NO_MICROSLIP)
    pair = impact(2.0, model=NO_MICROSLIP, law=sphere_pair_contact_law(NU), mass=sphere_pair_mass())
    assert_allclose(pair.beta, wall.beta, atol=1e-8)
    assert pair.contact_time > wall.contact_time


@pytest.mark.parametrize("model", MODELS)
def test_time_reversal_of_the_frictionless_impact(model):
    """Run back from the end state with every velocity reversed: the start comes back. With
    friction it does not (the check can fail)."""
    kw = {"model": model} | ({"springs": 200} if model == MICROSLIP else {})
    for mu, returns in ((0.0, True), (0.5, False)):
        out = oblique_impact(V, 0.02, mu, NU, spin=0.5, **kw)
        back = oblique_impact(
            out.normal_coefficient * V, -out.v_tangential, mu, NU, spin=-out.spin, **kw
        )
        got = np.array(
            [back.normal_coefficient * out.normal_coefficient, back.v_tangential, back.spin]
        )
        assert np.allclose(got, [1.0, -0.02, -0.5], atol=1e-10) is returns


@pytest.mark.parametrize("model", MODELS)
def test_the_normal_pulse_is_hertz_closed_form(model):
    """The history's normal force against Hertz's closed-form pulse (incomplete beta function,
    restitution.quasistatic.hertz_sphere), which is symmetric in time; friction leaves it."""
    h = oblique_impact(V, 0.02, 0.5, NU, model=model, history=True).history
    exact = sphere_quasistatic_trajectory(sphere_contact_law(NU), V)
    assert_allclose(h.t[-1], exact.contact_time, rtol=1e-9)
    assert np.max(np.abs(h.normal_force - exact.force(h.t))) < 1e-8 * exact.max_force
    assert np.max(np.abs(exact.force(h.t[-1] - h.t) - h.normal_force)) < 1e-8 * exact.max_force


@pytest.mark.parametrize("model", MODELS)
def test_shape_of_beta_of_psi(model):
    """For the sphere at nu = 0.3: beta < 0 at small psi (the closed form -0.955, and -0.232 for
    microslip), beta > 0 between, largest below the gross-slip threshold, and always under the
    line -1 + 2 K chi / psi, since |T| <= mu P bounds the tangential impulse."""
    psi = np.array([0.3, 1.0, 2.0, 2.7, 3.0, 4.0, 5.0, 8.0])
    beta = (
        beta_of_psi(psi, NU, model=model, springs=200)
        if model == MICROSLIP
        else (beta_of_psi(psi, NU, model=model))
    )
    assert beta[0] < -0.1 and np.all(beta[2:6] > 0.2)
    assert 2.0 <= psi[np.argmax(beta)] <= 3.0
    assert np.all(beta <= gross_slip_beta(psi, NU) + 1e-6)
    assert np.all(beta >= -1.0 - gross_slip_beta(psi, NU) - 1.0)


@pytest.mark.parametrize(
    "kwargs",
    [
        {"nu": 0.5},
        {"v_normal": 0.0},
        {"v_normal": 5.0},
        {"mu": -0.1},
        {"mu": math.inf},
        {"mu": "0.3"},
        {"inertia_factor": 0.5},
        {"model": "rigid"},
        {"model": NO_MICROSLIP, "springs": 100},
        {"springs": 5},
        {"law": sphere_contact_law(0.2)},
        {"rtol": 0.1},
    ],
)
def test_refusals_say_what_to_pass(kwargs):
    args = {"v_normal": V, "v_tangential": 0.01, "mu": 0.3, "nu": NU} | kwargs
    with pytest.raises(InputError):
        oblique_impact(**args)


def test_beta_of_psi_refuses_psi_zero():
    with pytest.raises(InputError, match="no_slip_beta"):
        beta_of_psi([0.0, 1.0], NU)
