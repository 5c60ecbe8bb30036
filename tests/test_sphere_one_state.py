"""restitution.quasistatic.sphere_one_state: the one-state contact (the modal route's friction:
one stick/slip state, traction spread like the pressure) at low speed, on the half-space and on
the finite sphere (docs/oblique.md, "The one-state route's own limit").

Two routes on the half-space: the closed-form law integrated phase by phase
(``one_state_half_space``, DOP853 with events) and the annuli with the half-space's
Hankel-transform flexibility and Hertz's parabola (``one_state_run``): no shared code but the
Hertz constants. The stick limit is a closed form derived by hand (module docs): ``-cos(pi
sqrt(K chi))`` at every speed.
"""

from __future__ import annotations

import math

import pytest

from restitution.errors import InputError
from restitution.quasistatic.oblique import gross_slip_beta, oblique_impact, stiffness_ratio
from restitution.quasistatic.sphere_one_state import (
    one_state_half_space,
    one_state_impact,
    one_state_run,
    stick_beta,
)
from restitution.quasistatic.sphere_partial_slip import REACH, AnnularContact, hertz_peak

NU, MU = 0.3, 0.5


def _contact(v, body, annuli=40):
    return AnnularContact.build(REACH * math.sqrt(hertz_peak(v, NU)), NU, body=body, annuli=annuli)


def test_the_annuli_on_the_half_space_are_the_closed_form_law():
    """``v = 0.005``, 40 annuli and 4000 steps: within 2e-4 of the phase-by-phase integration
    at ``tan(theta)/mu`` = 0.3, 1, 2, 3 (measured 1.1e-4, 6.1e-5, 1e-7, 1e-7; at 80 annuli
    and 8000 steps 2.5e-5, 2.6e-5); both give back the normal energy."""
    v = 0.005
    contact = _contact(v, "half-space")
    for q in (0.3, 1.0, 2.0, 3.0):
        beta, eps = one_state_run(contact, v, q * MU * v, MU, NU, 4000)
        exact, exact_eps = one_state_half_space(v, q * MU * v, MU, NU)
        assert beta == pytest.approx(exact, abs=2e-4), q
        assert eps == pytest.approx(1.0, abs=1e-6) and exact_eps == pytest.approx(1.0, abs=1e-9)


def test_a_contact_that_sticks_has_the_closed_form_beta_at_every_speed():
    """``beta_0 = -cos(pi sqrt(K chi))`` = -0.58205 (``nu = 0.3``, ``K = 7/2``), not law (a)'s
    -0.954. A contact must slip as it ends (its force ``F ~ delta^(1/4)`` outlasts ``mu P ~
    delta^(3/2)``), which moves ``beta`` by ``0.27 / mu`` at ``v_t = v_n`` (measured 2.7e-4,
    2.7e-5, 2.7e-6 at ``mu = 1e3, 1e4, 1e5``: order 1.0); at ``mu = 1e6`` the integration is
    within 1e-6 of the closed form at three speeds a decade apart, and the annuli agree with
    it at ``mu = 100``."""
    assert stick_beta(NU) == pytest.approx(-0.582050, abs=1e-6)
    assert oblique_impact(1e-3, 1e-3, 1e6, NU, model="no-microslip").beta < -0.95
    for v in (1e-4, 1e-3, 1e-2):
        assert one_state_half_space(v, v, 1e6, NU)[0] == pytest.approx(stick_beta(NU), abs=1e-6)
    shift = [one_state_half_space(1e-3, 1e-3, mu, NU)[0] - stick_beta(NU) for mu in (1e3, 1e4)]
    assert shift[0] > 0.0 and math.log10(shift[0] / shift[1]) == pytest.approx(1.0, abs=0.01)
    v = 0.005
    annuli = one_state_run(_contact(v, "half-space"), v, v, 100.0, NU, 4000)[0]
    assert annuli == pytest.approx(one_state_half_space(v, v, 100.0, NU)[0], abs=2e-4)


def test_gross_slip_is_the_impulse_ratio_on_both_bodies():
    """``tan(theta)/mu = 8``: the contact slides throughout, ``beta = -1 + 2 K chi / psi``
    (measured within 1.2e-12 by the integration, 2.8e-9 by the annuli on the sphere)."""
    v, q = 0.005, 8.0
    exact = float(gross_slip_beta(q * stiffness_ratio(NU), NU))
    assert one_state_half_space(v, q * MU * v, MU, NU)[0] == pytest.approx(exact, abs=1e-9)
    assert one_state_run(_contact(v, "finite"), v, q * MU * v, MU, NU, 4000)[0] == pytest.approx(
        exact, abs=1e-6
    )


def test_the_finite_sphere_converges_and_tends_to_the_half_space_as_the_contact_shrinks():
    """``tan(theta)/mu = 0.3``: the finite sphere reverses more than the half-space
    (-0.0483 at ``v = 0.005``, ``a = 0.155``, against -0.4882), and the gap falls as ``a``
    halves (0.440, 0.273, 0.164, 0.097 at ``v`` = 5e-3, 1e-3, 2e-4, 4e-5: ratios 0.62, 0.60,
    0.59 per halving of ``a``); ``beta_change`` (from 20 annuli and 2000 steps) is 4.8e-4
    at ``v = 0.005`` and 40 against 80 annuli differ by 9e-5."""
    v, vt = 0.005, 0.3 * MU * 0.005
    out = one_state_impact(v, vt, MU, NU)
    fine = one_state_run(_contact(v, "finite", 80), v, vt, MU, NU, 8000)[0]
    assert out.beta == pytest.approx(fine, abs=5e-4) and out.beta_change < 2e-3
    assert out.epsilon_normal == pytest.approx(1.0, abs=1e-6)
    half_space = one_state_half_space(v, vt, MU, NU)[0]
    gaps = [out.beta - half_space]
    gaps.append(one_state_impact(2e-4, 0.3 * MU * 2e-4, MU, NU).beta - half_space)
    assert gaps[0] > 0.4 and 0.1 < gaps[1] < 0.5 * gaps[0]
    # the impulse relation gives the spin: v_c = v_t - R omega after, K = 7/2
    vc = -out.beta * vt
    assert out.spin_after == pytest.approx((vt + (vc - vt) / 3.5) - vc, rel=1e-12)


def test_bad_input_is_refused_in_one_line():
    for args in ((0.0, 1e-3, MU, NU), (1e-3, -1e-3, MU, NU), (1e-3, 1e-3, 0.0, NU)):
        with pytest.raises(InputError) as caught:
            one_state_half_space(*args)
        assert "\n" not in str(caught.value)
    with pytest.raises(InputError, match="pass v_normal <="):
        one_state_impact(0.3, 0.01, MU, NU)
