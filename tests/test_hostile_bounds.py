"""Inputs that ran without end now end in seconds with one line (issue 64, "hangs")."""

from __future__ import annotations

import pytest
from _cli_checks import one_line_error

from restitution.quasistatic.hertz_sphere import sphere_contact_law
from restitution.quasistatic.viscoelastic import QuasistaticError, viscous_collision


def test_a_relaxation_time_that_overflows_the_damping_is_refused():
    """tau = 1e300 R/c: the damping term overflows and DOP853 never reached the separation
    (no answer in 60 s). Below the bound the grain hardly rebounds: at tau v / xi_max = 1.1e7
    epsilon is about 1e-12 (measured 1.07e-12 here)."""
    law = sphere_contact_law(0.3)
    for tau in (1e300, 1e150, 1e20):
        with pytest.raises(QuasistaticError, match="overflow"):
            viscous_collision(law, [2e-4], tau)
    assert 0.0 < viscous_collision(law, [2e-4], 1e8).epsilon[0] < 1e-11


def test_the_command_line_names_the_relaxation_time(cli):
    code, _, err = cli("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--shape",
                       "sphere", "--against", "wall", "--relaxation-time", "1e300", "--radius",
                       "0.001", "--speed", "1")  # fmt: skip
    one_line_error(code, err, "tau", "overflow", "relaxation time")


def test_waves_beyond_the_one_pulse_model_are_not_served(cli):
    """A relaxation time of 1 ms on a 1 mm steel ball (tau c/R = 5e3) with plastic flow: the
    waves' estimate, scaled from Hertz's pulse, was served as 3.85e5 % of the impact energy in
    the no-rebound note. Above the impact energy it is the model's limit, said as such, and no
    wave loss is served."""
    import json

    code, out, _ = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "sphere", "--against", "wall", "--yield-stress", "1e9",
                       "--relaxation-time", "1e-3", "--radius", "0.001", "--speed", "1",
                       "--json")  # fmt: skip
    (point,) = json.loads(out)["points"]
    assert code == 1 and point["epsilon"] is None and point["loss_waves"] is None
    assert point["status"] == "outside" and "beyond the one-pulse model" in point["note"]
    assert point["loss_viscous"] == pytest.approx(1.0, abs=1e-3)  # the contact itself stops it
