"""restitution.quasistatic.sphere_partial_slip: the finite sphere's quasistatic partial slip
on annuli (docs/oblique.md, "The finite sphere's own partial slip"). On the half-space with
Hertz's parabola the solver is law (b); in gross slip it is the impulse ratio for any
flexibility; on the sphere it converges in the annuli and tends to law (b) as the contact
shrinks."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.quasistatic.oblique import gross_slip_beta, oblique_impact, stiffness_ratio
from restitution.quasistatic.sphere_one_state import one_state_half_space
from restitution.quasistatic.sphere_partial_slip import (
    REACH,
    AnnularContact,
    hertz_peak,
    partial_slip_impact,
    run,
)

NU, MU = 0.3, 0.5


def _contact(v, body, annuli=40):
    return AnnularContact.build(REACH * math.sqrt(hertz_peak(v, NU)), NU, body=body, annuli=annuli)


def test_the_half_space_is_law_b():
    """40 annuli, 4000 steps: within 2e-4 of oblique_impact's microslip ``beta`` (measured
    3.2e-5 and 2.7e-5 at ``tan(theta)/mu = 0.3`` and 2; 1.1e-4 and 7e-6 at 80 annuli and
    8000 steps), and the normal contact gives back its energy (``epsilon_normal`` 1 within
    2.3e-8)."""
    v = 0.005
    contact = _contact(v, "half-space")
    for q in (0.3, 2.0):
        beta, eps = run(contact, v, q * MU * v, MU, NU, 4000)
        assert beta == pytest.approx(oblique_impact(v, q * MU * v, MU, NU).beta, abs=2e-4), q
        assert eps == pytest.approx(1.0, abs=1e-6)


def test_the_sphere_converges_and_slides_as_the_impulse_ratio_says():
    """At ``v = 0.005`` (Hertz's contact radius 0.155): 40 and 80 annuli (and 4000 and 8000
    steps) agree within 1e-3 (measured 9.7e-5; at 12 impacts, 4 speeds and 3 angles, at most
    7.2e-4; 160 annuli 2e-4 from 80 here), and the answer's ``beta_change`` (from 20 annuli
    and 2000 steps: 2.5e-3 here) is below 5e-3; at ``tan(theta)/mu = 6`` the contact slides
    throughout and ``beta = -1 + 2 K chi / psi`` (measured within 1e-9)."""
    v = 0.005
    b80, _ = run(_contact(v, "finite", 80), v, 0.3 * MU * v, MU, NU, 8000)
    out = partial_slip_impact(v, 0.3 * MU * v, MU, NU)
    assert out.beta == pytest.approx(b80, abs=1e-3) and out.beta_change < 5e-3
    assert out.epsilon_normal == pytest.approx(1.0, abs=1e-6)
    exact = float(gross_slip_beta(6.0 * stiffness_ratio(NU), NU))
    assert run(_contact(v, "finite"), v, 6.0 * MU * v, MU, NU, 4000)[0] == pytest.approx(
        exact, abs=1e-6
    )


def test_the_sphere_tends_to_law_b_as_the_contact_shrinks():
    """``beta`` of the sphere minus law (b) at ``tan(theta)/mu = 0.3`` falls with each step of
    the speed by 5 (the contact radius by 1.9): measured 0.306, 0.181, 0.104, 0.059 at ``v =
    0.005, 0.001, 2e-4, 4e-5`` (``a = 0.155`` to 0.022), order 0.82-0.88 in ``a``, as the
    sphere's ``chi`` approaches Mindlin's (like ``a ln(1/a)``). The sphere's ``beta`` is above
    law (b) at every speed."""
    gap = []
    for v in (0.005, 0.001, 2e-4, 4e-5):
        beta, _ = run(_contact(v, "finite"), v, 0.3 * MU * v, MU, NU, 4000)
        gap.append(beta - oblique_impact(v, 0.3 * MU * v, MU, NU).beta)
    gap = np.array(gap)
    order = np.log(gap[:-1] / gap[1:]) / math.log(5.0**0.4)
    assert np.all(gap > 0.0) and np.all((order > 0.7) & (order < 1.1)), (gap, order)


def test_spin_follows_from_beta():
    """No spin before: the tangential impulse ``J = m (v_c' - v_c) / K`` sets the centre's
    speed and the spin (``v_c = v_t - R omega``, ``I = 2 m R^2 / 5``): ``omega' = 5 J / (2 m
    R)``, so ``omega' = (5 / 7) (v_c' - v_c)`` with ``v_c' = -beta v_c``."""
    v, vt = 0.005, 0.3 * MU * 0.005
    out = partial_slip_impact(v, vt, MU, NU, annuli=20, steps=2000)
    assert out.spin_after == pytest.approx(-(5.0 / 7.0) * (-out.beta * vt - vt), rel=1e-12)


def test_bad_input_is_refused():
    with pytest.raises(InputError, match="v_tangential > 0"):
        partial_slip_impact(0.005, 0.0, MU, NU)
    with pytest.raises(InputError, match="pass v_normal <="):
        partial_slip_impact(0.5, 0.1, MU, NU)
    with pytest.raises(InputError, match="annuli >= 10"):
        partial_slip_impact(0.005, 0.001, MU, NU, annuli=4)
    with pytest.raises(InputError, match="body must be one of"):
        AnnularContact.build(0.1, NU, body="plate")


def test_the_tool_runs():
    """tools/sphere_partial_slip.py prints its table (one speed, one angle, 10 annuli)."""
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    out = subprocess.run(
        [sys.executable, str(root / "tools" / "sphere_partial_slip.py"), "--speed", "0.005",
         "--tan-over-mu", "0.3", "--annuli", "10"],  # fmt: skip
        capture_output=True, text=True, check=True, cwd=root,
        env={"PYTHONPATH": str(root / "src"), "OPENBLAS_NUM_THREADS": "1"},
    )  # fmt: skip
    assert "| 0.005 | 10 | 0.3 | -0.1672 |" in out.stdout


def test_the_figure_s_curves(tmp_path):
    """docs/figures/sphere_partial_slip.png on a small grid (20 annuli): laws (a) and (b) are
    oblique_impact's; in gross slip (``X = 8``, ``psi = 6.6``) all three give the impulse
    ratio; in partial slip the finite sphere is above law (b), more so at the faster speed,
    and its distance from law (b) falls with the contact radius; the same holds for the one-state
    contact against its closed-form half-space law (bottom row)."""
    from restitution.reproduction.figures import sphere_partial_slip as figure

    c = figure.compute([0.3, 8.0], (0.1, 10.0), (0.1, 10.0), annuli=20)
    v0 = 1.0 / figure.STEEL_C_M_S
    assert c.law_b[0] == oblique_impact(v0, 0.3 * 0.3 * v0, 0.3, NU).beta
    exact = float(gross_slip_beta(8.0 * stiffness_ratio(NU), NU))
    for beta in (c.law_a[1], c.law_b[1], *c.finite[:, 1]):
        assert beta == pytest.approx(exact, abs=1e-6)
    assert c.law_b[0] < c.finite[0, 0] < c.finite[1, 0]
    assert np.all(c.gap > 0.0) and np.all(np.diff(c.gap, axis=1) > 0.0)
    assert c.one_state[0] == one_state_half_space(v0, 0.3 * 0.3 * v0, 0.3, NU)[0]
    for beta in (c.one_state[1], *c.finite_one_state[:, 1]):
        assert beta == pytest.approx(exact, abs=1e-6)
    assert c.one_state[0] < c.finite_one_state[0, 0] < c.finite_one_state[1, 0]
    assert np.all(c.gap_one_state > 0.0) and np.all(np.diff(c.gap_one_state, axis=1) > 0.0)
    figure.plot(c, tmp_path / "f.png")
    assert (tmp_path / "f.png").stat().st_size > 10_000
