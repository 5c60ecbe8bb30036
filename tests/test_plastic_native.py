"""The DEM snippets of a plastic law say what each code's own elastic-plastic contact makes of
it (issue 61, item 2; :mod:`restitution.laws.exports.plastic_native`).

Checks: Luding's ``(1 + a w)^(-1/2)`` fitted to a law that is that curve returns its slope and
no miss (a closed form); against Thornton's closed form for steel the fit is the minimax one (a
nudge of ``a`` either way misses more) and its miss is what the snippet says; every registered
code says something for a plastic law and nothing for an elastic one.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from restitution.laws.exports.dem import DEM_TARGETS
from restitution.laws.exports.plastic_native import luding_fit
from restitution.quasistatic.plastic import thornton_epsilon


def _law(w, eps, mechanisms=("waves", "plastic")):
    """A stand-in for an SILaw: its speeds (m/s, unit scale), epsilon and mechanisms."""
    law = SimpleNamespace(v=np.asarray(w, float), epsilon_points=np.asarray(eps, float),
                          metadata={"mechanisms": list(mechanisms)})  # fmt: skip
    return SimpleNamespace(law=law, speed_scale_m_s=1.0)


W = np.geomspace(0.01, 100.0, 60)


def test_a_law_that_is_ludings_curve_gives_its_slope_and_no_miss():
    fit = luding_fit(_law(W, 1.0 / np.sqrt(1.0 + 0.37 * W)))
    assert fit.a_s_m == pytest.approx(0.37, rel=1e-6)
    assert fit.largest_miss < 1e-7
    assert fit.range_m_s == (W[0], W[-1])


def test_against_thorntons_contact_the_fit_is_the_minimax_one():
    # Thornton's closed form of steel with a yield speed of 0.03 m/s (about the package's for a
    # yield stress of 1 GPa, tests/test_plastic.py); epsilon = 1 below it.
    eps = thornton_epsilon(W / 0.03)
    law = _law(W, eps)
    fit = luding_fit(law)

    def worst(a):
        return np.max(np.abs(1.0 / np.sqrt(1.0 + a * W) - eps))

    assert worst(fit.a_s_m) == pytest.approx(fit.largest_miss, rel=1e-12)
    for nudge in (0.98, 1.02):
        assert worst(nudge * fit.a_s_m) > fit.largest_miss
    # The shapes differ (w^(-1/2) against w^(-1/4)): no slope follows over four decades.
    assert fit.largest_miss > 0.05
    lines = DEM_TARGETS["mercurydpm"].plastic(law)
    assert any(f"{fit.largest_miss:.3f}" in line for line in lines)
    assert all(line.startswith("//") for line in lines)


def test_every_code_says_something_of_a_plastic_law_and_nothing_of_an_elastic_one():
    eps = 1.0 / np.sqrt(1.0 + 0.1 * W)
    for target in DEM_TARGETS.values():
        assert target.plastic is not None, target.name
        assert target.plastic(_law(W, eps, ("waves",))) == []
        lines = target.plastic(_law(W, eps))
        assert lines and all(not line[:1].isalnum() for line in lines), target.name
        assert any("plastic flow" in line for line in lines)


def test_thorntons_closed_form_is_what_the_stand_in_uses():
    # The stand-in above rests on restitution.quasistatic.plastic.thornton_epsilon: at the yield
    # speed it is 1, and it falls as u^(-1/4) far above (Thornton 1997).
    assert thornton_epsilon(1.0) == pytest.approx(1.0, abs=1e-12)
    ratio = thornton_epsilon(1e6) / thornton_epsilon(1e5)
    assert ratio == pytest.approx(10.0 ** (-0.25), rel=1e-3)
    assert math.isfinite(thornton_epsilon(2.0))
