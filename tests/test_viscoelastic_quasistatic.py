"""Material damping in the quasistatic collision (restitution.quasistatic.viscoelastic).

Independent references: Brilliantov et al.'s formula for A as printed (eq. 4 of Ramirez et al.,
PRE 60, 4465 (1999)) typed here; the printed C1 = 1.15344 and C2 = 0.79826 of the same paper and
a quadrature for C1; scipy's Radau (implicit, unscaled variables, the laws' array methods) for
the equation of motion; adaptive quadrature of the dissipated work along the elastic trajectory
for the first order in tau; convergence orders fitted with np.polyfit; the pair of identical
disks against the disk on a wall at half the speed.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad, solve_ivp

from restitution.errors import InputError
from restitution.quasistatic import viscoelastic as ve
from restitution.quasistatic.hertz import contact_law, quasistatic_collision
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    sphere_contact_law,
    sphere_quasistatic_collision,
)
from restitution.quasistatic.viscoelastic import (
    C1,
    C2,
    DELAYED_RECOVERY,
    SEPARATIONS,
    dissipative_constant,
    loss_slope,
    loss_slope_estimate,
    pair_viscous_collision,
    proportional_viscosities,
    sphere_damping_parameter,
    sphere_viscous_expansion,
    tau_from_epsilon,
    viscous_collision,
)

NU = 0.3
SPHERE = sphere_contact_law(NU)
DISK = contact_law(NU)
LAWS = {"sphere": (SPHERE, SPHERE_MASS), "disk": (DISK, math.pi)}


def printed_A(eta1, eta2, E, nu):
    """Eq. (4) of Ramirez et al. 1999 (Brilliantov et al. 1996), in their eta1, eta2."""
    return (
        (3 * eta2 - eta1) ** 2
        / (3 * (3 * eta2 + 2 * eta1))
        * (1 - nu**2)
        * (1 - 2 * nu)
        / (E * nu**2)
    )


# ---- the dissipative constant ----------------------------------------------------------------


@pytest.mark.parametrize("nu", [-0.9, -0.3, 0.01, 0.2, 0.3, 0.45, 0.499])
def test_A_is_tau_for_proportional_viscosities(nu):
    for E, tau in ((1.0, 0.02), (63e9, 2.5e-6)):
        # Brilliantov's eta1 = tau E/(1+nu) = 2 tau mu and eta2 = tau E/(3(1-2nu)) = tau K.
        assert_allclose(
            printed_A(tau * E / (1 + nu), tau * E / (3 * (1 - 2 * nu)), E, nu), tau, rtol=1e-12
        )
        eta, zeta = proportional_viscosities(tau, E, nu)
        assert_allclose(dissipative_constant(eta, zeta, E, nu), tau, rtol=1e-12)


def test_A_maps_newtonian_viscosities_onto_brilliantovs():
    # Non-proportional viscosities: eta1 = 2 eta, eta2 = zeta, and A is linear in them.
    for eta, zeta, nu in ((0.3, 1.7, 0.3), (2.0, 0.1, -0.2), (0.0, 1.0, 0.25)):
        a = dissipative_constant(eta, zeta, 2.0, nu)
        assert_allclose(a, printed_A(2 * eta, zeta, 2.0, nu), rtol=1e-14)
        assert_allclose(dissipative_constant(5 * eta, 5 * zeta, 2.0, nu), 5 * a, rtol=1e-14)
    assert dissipative_constant(1.0, 2.0 / 3.0, 1.0, 0.3) == pytest.approx(0.0, abs=1e-16)


def test_A_refusals():
    with pytest.raises(InputError, match="0/0"):
        dissipative_constant(1.0, 1.0, 1.0, 0.0)
    with pytest.raises(InputError, match="Poisson"):
        dissipative_constant(1.0, 1.0, 1.0, 0.5)
    with pytest.raises(InputError, match="shear_viscosity"):
        dissipative_constant(-1.0, 1.0, 1.0, 0.3)
    with pytest.raises(InputError, match="Poisson"):
        proportional_viscosities(0.1, 1.0, 0.5)


# ---- the sphere's low-speed series -----------------------------------------------------------


def test_series_coefficients():
    # 1 - epsilon = 2 (5/4)^(3/5) q int_0^1 x^(1/2) sqrt(1 - x^(5/2)) dx to first order (the
    # dissipated work on Hertz's trajectory), the end weights x^(1/2) (1 - x)^(1/2) taken out.
    def smooth(x):
        return math.sqrt((1 - x**2.5) / (1 - x)) if x < 1 else math.sqrt(2.5)

    ref, _ = quad(smooth, 0, 1, weight="alg", wvar=(0.5, 0.5), epsabs=0, epsrel=1e-13)
    assert_allclose(C1, 2 * 1.25**0.6 * ref, rtol=1e-12)
    # The printed values (Ramirez et al. 1999) are these, cut after five decimals.
    assert 0 <= C1 - 1.15344 < 1e-5
    assert 0 <= C2 - 0.79826 < 1e-5


def test_sphere_collision_depends_on_q_alone():
    # Same q = (3/2) tau alpha^(2/5) v^(1/5) from speeds 100 times apart.
    v1, v2, tau1 = 1e-4, 1e-2, 0.03
    tau2 = tau1 * (v1 / v2) ** 0.2
    q1 = sphere_damping_parameter(SPHERE, v1, tau1)
    assert_allclose(sphere_damping_parameter(SPHERE, v2, tau2), q1, rtol=1e-14)
    for sep in SEPARATIONS:
        a = viscous_collision(SPHERE, v1, tau1, separation=sep)
        b = viscous_collision(SPHERE, v2, tau2, separation=sep)
        assert_allclose(b.epsilon, a.epsilon, rtol=1e-9)
        # Lengths scale with xi_max ~ v^(4/5), times with xi_max / v ~ v^(-1/5).
        assert_allclose(
            b.max_compression / b.elastic_max_compression,
            a.max_compression / a.elastic_max_compression,
            rtol=1e-8,
        )
        assert_allclose(
            b.contact_time / b.elastic_contact_time,
            a.contact_time / a.elastic_contact_time,
            rtol=1e-8,
        )


@pytest.fixture(scope="module")
def series_runs():
    """epsilon from the equation of motion at q = 0.002 ... 0.064, both criteria."""
    v = 1e-3
    q = 0.002 * 2.0 ** np.arange(6)
    tau = q / (1.5 * (SPHERE.K / SPHERE_MASS) ** 0.4 * v**0.2)
    eps = {
        sep: np.array([viscous_collision(SPHERE, v, t, separation=sep).epsilon[0] for t in tau])
        for sep in SEPARATIONS
    }
    return v, q, tau, eps


def _order(q, residual):
    return np.polyfit(np.log(q), np.log(np.abs(residual)), 1)[0]


def test_sphere_series_error_shrinks_like_the_next_order(series_runs):
    v, q, tau, eps = series_runs
    for sep in SEPARATIONS:
        e = eps[sep]
        by_terms = [
            np.array(
                [sphere_viscous_expansion(SPHERE, v, t, separation=sep, terms=n)[0] for t in tau]
            )
            for n in (1, 2, 3)
        ]
        assert_allclose(by_terms[0], 1 - C1 * q, rtol=1e-13)
        # One term: the error is C2 q^2.
        assert abs(_order(q, e - by_terms[0]) - 2.0) < 0.03
        # Three terms: O(q^3) under both criteria.
        assert abs(_order(q, e - by_terms[2]) - 3.0) < 0.06
    # Without a pulling contact the C2 term leaves q^(5/2) (next test); with it, q^3.
    assert abs(_order(q, eps["compression"] - (1 - C1 * q + C2 * q**2)) - 3.0) < 0.03
    # C2 refitted from the equation of motion: epsilon - 1 + C1 q = C2 q^2 + c3 q^3 + c4 q^4.
    fit = np.linalg.lstsq(
        np.array([q**2, q**3, q**4]).T, eps["compression"] - 1 + C1 * q, rcond=None
    )[0]
    assert_allclose(fit[0], C2, rtol=1e-4)
    assert -0.53 < fit[1] < -0.51  # the q^3 coefficient of the "compression" series
    fit = np.linalg.lstsq(
        np.array([q**2, q**2.5, q**3, q**3.5]).T, eps["force"] - 1 + C1 * q, rcond=None
    )[0]
    assert_allclose(fit[0], C2, rtol=1e-3)


def test_criteria_differ_by_the_delayed_recovery_term(series_runs):
    # epsilon_force - epsilon_compression = (4/15) q^(5/2) (1 + O(q)): the impulse the pulling
    # contact takes in the layer xi < (3/2) tau |xi'| (module notes).
    _, q, _, eps = series_runs
    ratio = (eps["force"] - eps["compression"]) / q**2.5
    assert np.all(ratio < DELAYED_RECOVERY)
    assert_allclose(ratio[0], 4 / 15, rtol=4e-3)
    assert abs(_order(q, ratio - 4 / 15) - 1.0) < 0.05


# ---- first order in tau, for sphere and disk ---------------------------------------------------


def slope_on_elastic_path(law, v, mass):
    """(2/(m v^2)) int_0^xi_max F'(xi) sqrt(v^2 - 2 V(xi)/m) d xi, quadrature in xi with the
    square root's end weight taken out, from the laws' array methods."""
    collide = sphere_quasistatic_collision if law is SPHERE else quasistatic_collision
    dmax = float(collide(law, v, mass=mass).max_compression[0])
    vm = float(law.potential(dmax))

    def f(xi):
        left = (
            max(1.0 - float(law.potential(xi)) / vm, 0.0) / (dmax - xi)
            if xi < dmax
            else (float(law.force(dmax)) / vm)
        )
        return float(law.stiffness(xi)) * math.sqrt(left)

    value, _ = quad(f, 0, dmax, weight="alg", wvar=(0, 0.5), epsabs=0, epsrel=1e-10, limit=200)
    return 2.0 * value * math.sqrt(vm) / (math.sqrt(0.5 * mass) * mass * v**2)


@pytest.mark.parametrize("name", ["sphere", "disk"])
def test_first_order_in_tau_is_the_work_on_the_elastic_path(name):
    law, mass = LAWS[name]
    for v in (1e-3, 0.03):
        s_ref = slope_on_elastic_path(law, v, mass)
        assert_allclose(loss_slope(law, v)[0], s_ref, rtol=1e-8)
        for sep in SEPARATIONS:
            # (1 - epsilon) / tau = S + O(tau): Richardson's extrapolation from tau, 2 tau.
            r = [
                (1 - viscous_collision(law, v, t, separation=sep).epsilon[0]) / t
                for t in (1e-3, 2e-3)
            ]
            assert_allclose(r[0], s_ref, rtol=2e-3)
            assert_allclose(2 * r[0] - r[1], s_ref, rtol=2e-5)
    if name == "sphere":
        v = np.array([1e-6, 1e-3, 0.1])
        exact = C1 * 1.5 * (law.K / mass) ** 0.4 * v**0.2
        assert_allclose(loss_slope(law, v), exact, rtol=1e-9)
        assert_allclose(loss_slope_estimate(law, v), exact, rtol=1e-13)


def test_disk_slope_closed_form_is_off_by_the_square_of_the_local_exponent():
    # The local power law at xi_max misses the quadrature by O(e^2), e = 1/(Lambda - 1) ~
    # 1/ln(4R/xi_max); the linear oscillator's (pi/2) sqrt(k/m) by O(e).
    v = 10.0 ** -np.arange(4.0, 13.0, 2.0)
    exact = loss_slope(DISK, v)
    qs = quasistatic_collision(DISK, v)
    e = DISK.local_exponent(qs.max_compression)
    power = loss_slope_estimate(DISK, v)
    linear = 0.5 * math.pi * np.sqrt(qs.max_force / (math.pi * qs.max_compression))
    assert np.all(np.abs(power / exact - 1) < 0.15 * e**2)
    assert abs(_order(e, power / exact - 1) - 2.0) < 0.1
    assert abs(_order(e, linear / exact - 1) - 1.0) < 0.1
    # 1 - epsilon ~ tau / sqrt(ln(1/v)) -> 0 as v -> 0, slowly.
    assert np.all(np.diff(exact) < 0)


# ---- conservation, an independent integrator, limits --------------------------------------------


@pytest.mark.parametrize("name", ["sphere", "disk"])
def test_energy_balance(name):
    law, _ = LAWS[name]
    for sep in SEPARATIONS:
        c = viscous_collision(law, [1e-3, 0.05], 0.2, separation=sep)
        assert np.all(c.energy_error < 1e-9)
        assert np.all((c.epsilon > 0.5) & (c.epsilon < 0.99))
        if sep == "force":
            assert np.all((c.stored_energy > 0) & (c.separation_compression > 0))
        else:
            assert np.all((c.stored_energy == 0) & (c.separation_compression == 0))


def radau_collision(law, v, tau, mass, separation):
    """m xi'' = -F - tau xi' F' in unscaled variables with Radau; the dissipated work by
    quadrature of tau F'(xi) xi'^2 over the dense output."""

    def forces(xi):
        xi = min(max(xi, 0.0), law.max_compression)
        return float(law.force(xi)), float(law.stiffness(xi))

    def rhs(t, y):
        F, S = forces(y[0])
        return [y[1], -(F + tau * y[1] * S) / mass]

    def end(t, y):
        if separation == "compression":
            return y[0]
        F, S = forces(y[0])
        return F + tau * y[1] * S if y[0] > 0 else y[0]

    end.terminal, end.direction = True, -1
    sol = solve_ivp(
        rhs,
        (0, 1e4),
        [0.0, v],
        method="Radau",
        rtol=1e-11,
        atol=1e-15 * v,
        events=end,
        dense_output=True,
        first_step=1e-6,
    )
    t_end = sol.t_events[0][0]
    xi_end, u_end = sol.y_events[0][0]

    def power(t):
        xi, u = sol.sol(t)
        return tau * forces(xi)[1] * u * u

    work, _ = quad(power, 0, t_end, epsabs=0, epsrel=1e-10, limit=400)
    return -u_end / v, t_end, max(xi_end, 0.0), work / (0.5 * mass * v * v)


@pytest.mark.parametrize("name", ["sphere", "disk"])
def test_against_an_independent_integration(name):
    law, mass = LAWS[name]
    v, tau = 0.02, 0.3
    for sep in SEPARATIONS:
        eps, t_end, xi_end, work = radau_collision(law, v, tau, mass, sep)
        c = viscous_collision(law, v, tau, separation=sep)
        assert_allclose(c.epsilon[0], eps, rtol=1e-9)
        assert_allclose(c.contact_time[0], t_end, rtol=1e-9)
        assert_allclose(c.separation_compression[0], xi_end, rtol=1e-9, atol=1e-14)
        assert_allclose(c.dissipated_work[0], work, rtol=2e-9)
        stored = float(law.potential(xi_end)) / (0.5 * mass * v * v)
        assert_allclose(eps**2 + work + stored, 1.0, atol=1e-8)


@pytest.mark.parametrize("name", ["sphere", "disk"])
def test_no_damping_is_the_elastic_collision(name):
    law, _ = LAWS[name]
    for sep in SEPARATIONS:
        c = viscous_collision(law, [1e-4, 0.01, 0.1], 0.0, separation=sep)
        assert_allclose(c.epsilon, 1.0, atol=1e-9)
        assert_allclose(c.contact_time, c.elastic_contact_time, rtol=1e-8)
        assert_allclose(c.max_compression, c.elastic_max_compression, rtol=1e-9)
        assert np.all(c.dissipated_work == 0)


def test_pair_of_identical_disks_is_the_wall_at_half_the_speed():
    # delta = 2 xi_wall(P), reduced mass pi/2: u = delta/2 obeys the wall's equation at w/2.
    w = np.array([0.002, 0.06])
    for sep in SEPARATIONS:
        pair = pair_viscous_collision(w, 0.15, NU, separation=sep)
        wall = viscous_collision(DISK, w / 2, 0.15, separation=sep)
        assert pair.mass == pytest.approx(math.pi / 2)
        assert_allclose(pair.epsilon, wall.epsilon, rtol=1e-9)
        assert_allclose(pair.contact_time, wall.contact_time, rtol=1e-8)
        assert_allclose(pair.max_compression, 2 * wall.max_compression, rtol=1e-9)


@pytest.mark.parametrize("name", ["sphere", "disk"])
def test_tau_from_epsilon_round_trips(name):
    law, _ = LAWS[name]
    for v, tau, sep in ((1e-3, 0.02, "force"), (0.05, 0.4, "compression")):
        eps = viscous_collision(law, v, tau, separation=sep).epsilon[0]
        assert_allclose(tau_from_epsilon(law, v, eps, separation=sep), tau, rtol=1e-9)


def test_scalar_force_path_matches_the_laws():
    d = np.array([1e-12, 1e-6, 1e-3, 0.05])
    for law in (SPHERE, DISK, contact_law(0.2, "paper"), contact_law(0.4, "diameter")):
        got = np.array([ve._force_stiffness(law, x) for x in d])
        assert_allclose(got[:, 0], law.force(d), rtol=1e-14)
        assert_allclose(got[:, 1], law.stiffness(d), rtol=1e-14)


def test_refusals():
    with pytest.raises(InputError, match="tau"):
        viscous_collision(SPHERE, 0.01, -0.1)
    with pytest.raises(InputError, match="separation"):
        viscous_collision(SPHERE, 0.01, 0.1, separation="distance")
    with pytest.raises(InputError, match="exceeds"):
        viscous_collision(DISK, 10.0, 0.1)
    with pytest.raises(InputError, match="law"):
        viscous_collision("sphere", 0.01, 0.1)
    with pytest.raises(InputError, match="epsilon"):
        tau_from_epsilon(SPHERE, 0.01, 1.0)
    with pytest.raises(InputError, match="terms"):
        sphere_viscous_expansion(SPHERE, 0.01, 0.1, terms=4)
    with pytest.raises(InputError, match="sphere"):
        sphere_damping_parameter(DISK, 0.01, 0.1)


def test_docstring_examples():
    result = doctest.testmod(ve)
    assert result.attempted > 0 and result.failed == 0
