"""The sphere's modal oblique impact (restitution.dynamics.oblique with
restitution.bodies.sphere.cap), each check by a route of its own: the head-on collision of the
axisymmetric modes (the package's integrator and the DOP853 reference), the rigid-body impulse
ratio with K = 7/2, the energy balance, the invariance of the complete mode set under the
rolling rotation (and the failure of the m <= 1 set), the rigid-sphere limit, the mirror
symmetry, convergence in the wall nodes, and the quasistatic theory of Maw, Barber and Fawcett
at low speed. Units: E = rho = R = 1 (three-dimensional constants), speeds in c, spins in c/R,
energies fractions of the initial kinetic energy. Measured values are in docs/oblique.md
("The sphere")."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.dynamics.collision import collide
from restitution.dynamics.oblique import impulse_ratio_beta, oblique_collision
from restitution.dynamics.reference import collide_dop853
from restitution.quasistatic.oblique import beta_of_psi, stiffness_ratio

NU = 0.3
K = 3.5  # 1 + m R^2 / I of the solid sphere
TAN80 = math.tan(math.radians(80.0))


@pytest.fixture(scope="module")
def modes20():
    return compute_sphere_modes(NU, count=20)


@pytest.fixture(scope="module")
def cap20(modes20):
    """Every azimuthal order of the 20 axisymmetric modes: 146 modes."""
    return cap_modes(modes20)


@pytest.fixture(scope="module")
def cap20_m1(modes20):
    """Azimuthal orders 0 and 1 only: 53 modes (cheaper; not closed under rotations)."""
    return cap_modes(modes20, azimuthal=1)


# -- the acceptance checks of issue 63 ---------------------------------------------------------


@pytest.mark.slow  # 20 s of the default run (stop 76: the default run under 10 min)
def test_frictionless_impact_is_the_head_on_collision(modes20, cap20):
    """mu = 0 at 45 degrees, also with the sphere turned by 0.3 rad before (the contact off the
    modes' pole): epsilon_normal is the head-on epsilon of the package's collision (split4,
    energy_tol 1e-6: measured 4.8e-8 apart; the issue asks 1e-6) and of the DOP853 reference
    (1.7e-13; turned 1.8e-13); beta = -1, no spin, the non-axisymmetric modes stay at rest
    (unturned: 5e-34 of E0) and the energy left in the modes is 1 - epsilon^2 (fractions of
    E0 = 2 x the normal energy)."""
    v, alpha = 0.05, 100.0
    head_on = collide(modes20, v, alpha).epsilon
    reference = collide_dop853(modes20, v, alpha)["epsilon"]
    out = oblique_collision(cap20, v, v, 0.0, alpha)
    assert abs(out.epsilon_normal - head_on) < 1e-6
    assert abs(out.epsilon_normal - reference) < 1e-9
    assert abs(out.beta + 1.0) < 1e-14 and abs(out.spin) < 1e-15
    assert out.friction_work == 0.0 and out.phases == (("slip+", 0.0),)
    assert np.all(out.mode_energy[len(modes20) :] < 1e-25)
    assert_allclose(out.vibration_energy, (1.0 - out.epsilon_normal**2) / 2.0, atol=1e-10)
    assert abs(out.energy_balance) < 1e-10
    turned = oblique_collision(cap20, v, v, 0.0, alpha, rotation=0.3)
    assert abs(turned.epsilon_normal - reference) < 1e-9
    assert abs(turned.beta + 1.0) < 1e-9 and abs(turned.spin) < 1e-9


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_gross_sliding_is_the_impulse_ratio(cap20):
    """mu = 0.1 at 80 degrees slides throughout: beta = -1 + K mu (1 + e) / tan(theta),
    K = 7/2, within 1e-3 at v = 0.002 (measured 5.2e-4; the difference is exactly the lever and
    the normal torque of the deformed contact: 5e-16 from their sum); at v = 0.005 the lever,
    first order in the compression, is larger (1.26e-3)."""
    diffs = []
    for v in (0.002, 0.005):
        out = oblique_collision(cap20, v, v * TAN80, 0.1, 500.0)
        assert [name for name, _ in out.phases] == ["slip+"]
        rigid = impulse_ratio_beta(0.1, TAN80, out.epsilon_normal, inertia_factor=K)
        split = out.lever_correction + out.normal_torque_correction
        assert abs(out.beta - rigid - split) < 1e-12
        assert abs(out.energy_balance) < 1e-5
        diffs.append(abs(out.beta - rigid))
    assert diffs[0] < 1e-3 < diffs[1]


@pytest.mark.parametrize("mu,degrees", [(0.5, 45.0), (2.0, 30.0), (0.3, 10.0)])
def test_energy_balance(cap20_m1, mu, degrees):
    """Translation, rotation, vibrations, friction work and the wall's energy add up to the
    initial kinetic energy within 1e-5 (measured <= 3.9e-13), through stick and slip (the
    m <= 1 set: the balance holds for any set of modes)."""
    v = 0.05
    out = oblique_collision(cap20_m1, v, v * math.tan(math.radians(degrees)), mu, 100.0)
    assert abs(out.energy_balance) < 1e-5
    assert out.friction_work > 0.0 and out.wall_energy < 1e-11
    parts = out.translation_energy + out.rotation_energy + out.vibration_energy
    assert_allclose(parts + out.friction_work + out.wall_energy, 1.0, atol=1e-5)


# -- the rolling contact: every azimuthal order ------------------------------------------------


@pytest.mark.slow  # 12-37 s (stop 70: the default run's budget)
def test_the_complete_set_does_not_care_where_the_contact_is(cap20, cap20_m1):
    """With every azimuthal order the modes of each root span a space closed under the
    rotation, so an impact with the sphere turned by 0.2 rad before is the same impact
    (v = 0.05, alpha = 100, mu = 0.5, 45 degrees: stick and slip; measured 4.5e-14 in
    epsilon_normal, 1.1e-12 in beta); with m <= 1 about the fixed pole it is not (0.015 in
    epsilon_normal, and its beta 0.038 from the complete set's: the check can fail). The
    complete set's energy balance: -6.5e-13 (the issue asks 1e-5)."""
    v, alpha = 0.05, 100.0
    a = oblique_collision(cap20, v, v, 0.5, alpha)
    b = oblique_collision(cap20, v, v, 0.5, alpha, rotation=0.2)
    assert abs(b.epsilon_normal - a.epsilon_normal) < 1e-10
    assert abs(b.beta - a.beta) < 1e-8 and abs(b.spin - a.spin) < 1e-9
    assert abs(a.energy_balance) < 1e-5 and abs(b.energy_balance) < 1e-5
    c = oblique_collision(cap20_m1, v, v, 0.5, alpha)
    d = oblique_collision(cap20_m1, v, v, 0.5, alpha, rotation=0.2)
    assert abs(d.epsilon_normal - c.epsilon_normal) > 1e-2
    assert abs(c.beta - a.beta) > 1e-2


@pytest.mark.slow
def test_the_azimuthal_orders_converge(modes20, cap20):
    """beta and epsilon_normal of m <= 1, 2, 3 against every order (v = 0.05, alpha = 100,
    mu = 0.5, 45 degrees): beta is off by 0.038, 1.7e-3, 7.9e-5 (measured), each order at
    least ten times closer than the one before, and m <= 1 gives epsilon_normal > 1 (1.0065;
    every order 0.99847)."""
    v, alpha = 0.05, 100.0
    full = oblique_collision(cap20, v, v, 0.5, alpha)
    runs = [oblique_collision(cap_modes(modes20, azimuthal=m), v, v, 0.5, alpha) for m in (1, 2, 3)]
    off = np.array([abs(r.beta - full.beta) for r in runs])
    assert np.all(off[1:] < off[:-1] / 10.0) and off[2] < 1e-4, off
    assert runs[0].epsilon_normal > 1.0 > full.epsilon_normal


# -- limits and symmetries -----------------------------------------------------------------


def test_rigid_sphere_limit(cap20):
    """Without modes the exponential wall is elastic (e = 1: 5e-11), gross slip is the impulse
    ratio with e = 1 up to the lever's correction ~ 1/alpha (-8.8e-4, -8.8e-5), and a rough
    contact ends rolling (beta ~ 1/alpha: 7.2e-3, 7.1e-4)."""
    rigid = cap20.take(np.arange(0))
    slips, rolls = [], []
    for alpha in (100.0, 1000.0):
        out = oblique_collision(rigid, 0.01, 0.01 * TAN80, 0.1, alpha)
        assert abs(out.epsilon_normal - 1.0) < 1e-9
        rigid_beta = impulse_ratio_beta(0.1, TAN80, out.epsilon_normal, inertia_factor=K)
        assert abs(out.beta - rigid_beta - out.lever_correction) < 1e-12
        slips.append(out.lever_correction)
        rolls.append(oblique_collision(rigid, 0.01, 0.01, 10.0, alpha).beta)
    assert_allclose(np.array(slips) * [100, 1000], slips[0] * 100, rtol=0.1)
    assert_allclose(np.array(rolls) * [100, 1000], rolls[0] * 100, rtol=0.1)
    assert 0.0 < rolls[1] < 1e-3


@pytest.mark.slow  # 5 s of the default run (stop 79: the default run under 10 min)
def test_mirror_image(cap20_m1):
    """v_t -> -v_t: the same beta and normal coefficient, the opposite spin (the rings' nodes
    are symmetric about the plane phi = +-pi/2; measured 5e-15)."""
    a = oblique_collision(cap20_m1, 0.05, 0.04, 0.5, 100.0)
    b = oblique_collision(cap20_m1, 0.05, -0.04, 0.5, 100.0)
    assert_allclose(b.beta, a.beta, atol=1e-10)
    assert_allclose(b.spin, -a.spin, atol=1e-10)
    assert_allclose(b.epsilon_normal, a.epsilon_normal, atol=1e-12)
    assert len(a.phases) > 2  # stick and slip, not only sliding


@pytest.mark.slow  # 12-37 s (stop 70: the default run's budget)
def test_converges_in_the_wall_nodes(cap20):
    """Twice the nodes per ring and 1.5 times the rings change beta through stick and slip,
    with the contact off the pole (turned 0.2 rad), by 9e-16 and 4e-14 (measured)."""
    v, alpha = 0.05, 100.0
    ref = oblique_collision(cap20, v, v, 0.5, alpha, rotation=0.2)
    fine = oblique_collision(cap20.with_azimuths(64), v, v, 0.5, alpha, rotation=0.2)
    rings = len(cap20.wall_nodes(alpha).theta)
    more = oblique_collision(cap20, v, v, 0.5, alpha, rotation=0.2, n_nodes=(3 * rings) // 2)
    assert abs(fine.beta - ref.beta) < 1e-6 and abs(more.beta - ref.beta) < 1e-6


# -- low speed: the quasistatic theory ---------------------------------------------------------


@pytest.mark.slow
def test_low_speed_against_maw_barber_fawcett_and_the_route_s_own_twin(cap20, cap20_m1):
    """At v = 0.005, alpha = 500, beta(tan(theta) / mu) of the modal sphere (one stick/slip
    state) against its own quasistatic twin: the same contact (traction spread like the
    pressure) on the same 20 modes' flexibility and wall, without the modes' inertia
    (tools/sphere_modal_partial_slip.py --one-state, 60 annuli: -0.832 and +0.063 at
    tan(theta)/mu = 0.3 and 2, measured 0.020 and 0.047 from the modal route); in gross slip
    (8) the impulse ratio's line, 0.009 off (measured; the lever at mu = 0.5). Maw, Barber and
    Fawcett's law (a) (-0.954, +0.138, -0.125) is not this route's limit
    (docs/oblique.md, "The one-state route's own limit is not law (a)": the one-state contact
    on the rigid wall's finite sphere is -0.048 at 0.3); on this soft wall the modal values sit
    near it by the wall's and the truncation's effects, which the twin holds."""
    import importlib
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
    try:
        twin = importlib.import_module("sphere_modal_partial_slip")
    finally:
        sys.path.pop(0)
    v, mu = 0.005, 0.5
    assert (twin.V, twin.MU, twin.NU) == (v, mu, NU)
    chi = stiffness_ratio(NU)
    ratio = np.array([0.3, 2.0, 8.0])  # tan(theta) / mu
    modal = np.array([oblique_collision(cap20, v, r * mu * v, mu, 500.0).beta for r in ratio])
    statics = [twin.impact(cap20_m1, 500.0, 64.0, r, one_state=True)[0] for r in ratio[:2]]
    assert np.all(np.abs(modal[:2] - statics) <= [0.04, 0.07]), modal[:2] - statics
    gross = beta_of_psi(ratio[2:] * chi, NU, inertia_factor=K, model="no-microslip")
    assert abs(modal[2] - gross[0]) <= 0.01 and modal[0] < -0.8 and modal[1] > 0.05
