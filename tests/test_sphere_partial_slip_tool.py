"""tools/sphere_partial_slip.py: the quasistatic partial slip of the finite sphere on annuli
(docs/oblique.md, "The finite sphere's own partial slip"). On the half-space with Hertz's
parabola it is law (b); in gross slip it is the impulse ratio for any flexibility; on the
sphere it converges in the annuli and tends to law (b) as the contact shrinks."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import numpy as np
import pytest

from restitution.quasistatic.oblique import gross_slip_beta, oblique_impact, stiffness_ratio

TOOLS = Path(__file__).resolve().parents[1] / "tools"
NU, MU = 0.3, 0.5


@pytest.fixture(scope="module")
def tool():
    with pytest.MonkeyPatch.context() as patch:
        patch.syspath_prepend(str(TOOLS))
        yield importlib.import_module("sphere_partial_slip")


def _contact(tool, v, body, annuli=40):
    return tool.Contact.build(tool.REACH * math.sqrt(tool.hertz_peak(v)), body=body, annuli=annuli)


def test_the_half_space_is_law_b(tool):
    """40 annuli, 4000 steps: within 2e-4 of oblique_impact's microslip ``beta`` (measured
    3.2e-5 and 2.7e-5 at ``tan(theta)/mu = 0.3`` and 2; 1.1e-4 and 7e-6 at 80 annuli and
    8000 steps), and the normal contact gives back its energy (``epsilon_normal`` 1 within
    2.3e-8)."""
    v = 0.005
    contact = _contact(tool, v, "half-space")
    for q in (0.3, 2.0):
        beta, eps = tool.oblique(contact, v, q, steps=4000)
        assert beta == pytest.approx(oblique_impact(v, q * MU * v, MU, NU).beta, abs=2e-4), q
        assert eps == pytest.approx(1.0, abs=1e-6)


def test_the_sphere_converges_in_the_annuli_and_slides_as_the_impulse_ratio_says(tool):
    """At ``v = 0.005`` (contact radius 0.155): 40 and 80 annuli agree within 3e-4 (measured
    7e-5; 160 annuli 2e-4 from 80); at ``tan(theta)/mu = 6`` the contact slides throughout and
    ``beta = -1 + 2 K chi / psi`` (measured within 1e-9)."""
    v = 0.005
    coarse, fine = _contact(tool, v, "sphere", 40), _contact(tool, v, "sphere", 80)
    b40, eps = tool.oblique(coarse, v, 0.3, steps=4000)
    b80, _ = tool.oblique(fine, v, 0.3, steps=8000)
    assert b40 == pytest.approx(b80, abs=3e-4)
    assert eps == pytest.approx(1.0, abs=1e-6)
    exact = float(gross_slip_beta(6.0 * stiffness_ratio(NU), NU))
    assert tool.oblique(coarse, v, 6.0, steps=4000)[0] == pytest.approx(exact, abs=1e-6)


def test_the_sphere_tends_to_law_b_as_the_contact_shrinks(tool):
    """``beta`` of the sphere minus law (b) at ``tan(theta)/mu = 0.3`` falls with each step of
    the speed by 5 (the contact radius by 1.9): measured 0.306, 0.181, 0.104, 0.059 at ``v =
    0.005, 0.001, 2e-4, 4e-5`` (``a = 0.155`` to 0.022), order 0.82-0.88 in ``a``, as the
    sphere's ``chi`` approaches Mindlin's (like ``a ln(1/a)``). The sphere's ``beta`` is above
    law (b) at every speed."""
    speeds = (0.005, 0.001, 2e-4, 4e-5)
    gap = []
    for v in speeds:
        beta, _ = tool.oblique(_contact(tool, v, "sphere"), v, 0.3, steps=4000)
        gap.append(beta - oblique_impact(v, 0.3 * MU * v, MU, NU).beta)
    gap = np.array(gap)
    order = np.log(gap[:-1] / gap[1:]) / math.log(5.0**0.4)
    assert np.all(gap > 0.0) and np.all((order > 0.7) & (order < 1.1)), (gap, order)
