"""tools/sphere_modal_partial_slip.py: the modal microslip route's quasistatic twin (docs/
oblique.md, "The finite sphere's own partial slip"). Its machinery against closed forms: the
exponential wall's normal contact gives the energy back, and in gross slip ``beta`` is the
impulse ratio's whatever the flexibility, wall and springs."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.quasistatic.oblique import gross_slip_beta, stiffness_ratio

TOOLS = Path(__file__).resolve().parents[1] / "tools"


@pytest.fixture(scope="module")
def tool():
    with pytest.MonkeyPatch.context() as patch:
        patch.syspath_prepend(str(TOOLS))
        yield importlib.import_module("sphere_modal_partial_slip")


def test_the_twin_slides_as_the_impulse_ratio_says_and_keeps_the_energy(tool):
    """20 modes, the wall ``alpha = 500``, 20 annuli, 1500 steps: at ``tan(theta)/mu = 12``
    (gross slip) ``beta = -1 + 2 K chi / psi`` (measured within 1.1e-12; at 6, gross slip on
    the half-space and on the continuous sphere, these 20 modes still stick at times: 0.1475
    against 0.1667), and ``epsilon_normal`` is 1 (the quasistatic contact on the exponential
    wall is elastic; measured within 4e-12). The same with the one-state route's friction
    (``one_state``: one stick/slip state spread like the pressure)."""
    cap = cap_modes(compute_sphere_modes(tool.NU, count=20), azimuthal=1)
    exact = float(gross_slip_beta(12.0 * stiffness_ratio(tool.NU), tool.NU))
    for one_state in (False, True):
        beta, eps = tool.impact(cap, 500.0, 64.0, 12.0, annuli=20, steps=1500, one_state=one_state)
        assert beta == pytest.approx(exact, abs=1e-6) and eps == pytest.approx(1.0, abs=1e-8)
