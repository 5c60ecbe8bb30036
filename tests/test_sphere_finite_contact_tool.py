"""tools/sphere_finite_contact.py's two quasistatic models of the finite sphere's contact
(docs/oblique.md, "The sphere is not a half-space at this contact"): on the half-space both
are law (b), and in gross slip both give the impulse ratio's ``beta`` whatever the stiffness."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

from restitution.quasistatic.oblique import gross_slip_beta, oblique_impact

TOOLS = Path(__file__).resolve().parents[1] / "tools"
NU, MU, V = 0.3, 0.5, 0.005


@pytest.fixture(scope="module")
def tool():
    with pytest.MonkeyPatch.context() as patch:
        patch.syspath_prepend(str(TOOLS))
        yield importlib.import_module("sphere_finite_contact")


def test_both_models_on_the_half_space_are_law_b(tool):
    """Few springs and steps (200, 20000): within 3e-4 of ``oblique_impact``'s microslip
    ``beta`` (measured 1.2e-4 and 1.1e-4 at ``tan(theta)/mu = 0.3``, 2.7e-6 and 2.2e-6 at 2;
    the tool's defaults, 800 springs, reach 3e-5), ``epsilon_normal`` within 1e-10 of 1."""
    for q in (0.3, 2.0):
        law = oblique_impact(V, q * MU * V, MU, NU).beta
        for model in (tool.density_model, tool.series_model):
            beta, eps = model(None, V, q, springs=200, steps=20000)
            assert beta == pytest.approx(law, abs=3e-4), (model.__name__, q)
            assert eps == pytest.approx(1.0, abs=1e-6)


def test_gross_slip_does_not_see_the_stiffness(tool):
    """At ``tan(theta)/mu = 6`` (``psi = 4.9``, past the gross-slip ``psi`` 4.76) the contact
    slides throughout, the friction impulse is ``mu`` times the normal one, and ``beta =
    -1 + 2 K chi / psi`` for any stiffness: both finite-sphere models give it (measured 1.8e-8
    and 7.4e-7 from it at 200 springs)."""
    sphere = tool.Sphere(NU, (0.02, 0.04, 0.08, 0.12, 0.16, 0.2))
    psi = tool.stiffness_ratio(NU) * 6.0
    exact = float(gross_slip_beta(psi, NU))
    for model in (tool.density_model, tool.series_model):
        beta, _ = model(sphere, V, 6.0, springs=200, steps=20000)
        assert beta == pytest.approx(exact, abs=1e-5), model.__name__
