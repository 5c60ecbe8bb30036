"""``restitution.si_law(**options)`` is the command line's equal (issue 62): for the five grains
of the issue it takes the options of ``restitution law`` as keywords and its law at every speed
agrees with ``restitution law --json`` at 0.01, 0.1, 1 and 10 m/s.

What "agrees" means, per law (each measured when written, the numbers in the tests):

* **the same numbers** where both come from one code path: the shipped elastic law, the glass
  beads' law interpolated in nu (0.01 m/s lies below it: both answer by its low-speed route),
  the damped law (the table is the damped law at the elastic law's speeds; at other speeds both
  interpolate the same elastic law and integrate the same viscous collisions: 1e-7 apart);
* **within a tenth of the table's stated error** where the table interpolates a mechanism the
  command line computes at the speed itself (plastic flow, an elastic wall): the miss is
  reported as a fraction of that error.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import restitution

SPEEDS = (0.01, 0.1, 1.0, 10.0)
STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere")
GLASS = dict(E=63e9, nu=0.2481, rho=2500.0, shape="sphere")


def _flags(**options) -> list[str]:
    out = []
    for k, v in options.items():
        flag = {"E": "--E", "wall_E": "--wall-E"}.get(k, "--" + k.replace("_", "-"))
        out += [flag, str(v)]
    return out


def _cli_points(cli, **options):
    code, out, err = cli("law", *_flags(**options), "--speed", *map(str, SPEEDS), "--json")
    assert code == 0, err
    return json.loads(out)["points"]


def _compare(cli, law, **options):
    """``(table epsilon, its error, command line's epsilon, its error)`` at :data:`SPEEDS`."""
    points = _cli_points(cli, **options)
    eps = law.epsilon(np.array(SPEEDS), outside="nan")
    err = law.epsilon_err(np.array(SPEEDS), outside="nan")
    return eps, err, np.array([p["epsilon"] for p in points], float), points


def test_an_elastic_steel_ball_on_a_wall_is_the_same_law(cli):
    law = restitution.si_law(**STEEL, against="wall")
    eps, err, want, _ = _compare(cli, law, **STEEL, against="wall")
    np.testing.assert_array_equal(eps, want)


def test_glass_beads_between_the_shipped_laws_answer_below_them_by_their_route(cli):
    law = restitution.si_law(**GLASS, against="grain")
    lo, _ = law.speed_range_m_s
    assert lo > SPEEDS[0]  # 0.01 m/s lies below the law: its low-speed route answers
    eps, err, want, points = _compare(cli, law, **GLASS, against="grain")
    assert points[0]["status"] == "quasistatic"
    np.testing.assert_allclose(eps, want, rtol=0, atol=1e-13)


@pytest.mark.slow  # 28 s of the default run (stop 76: the default run under 10 min)
def test_damped_glass_beads_are_the_damped_law(cli):
    opts = dict(measured_epsilon=0.9, measured_speed=1.0, radius=1e-3)
    law = restitution.si_law(**GLASS, against="grain", **opts)
    eps, err, want, _ = _compare(cli, law, **GLASS, against="grain", **opts)
    # Measured: 1.1e-8 at most (the table's interpolation of the elastic law against the
    # command line's, under the viscous loss); the stated errors are 1e-4 to 6e-3.
    assert np.all(np.abs(eps - want) <= 0.1 * err), (eps - want, err)
    assert np.all(np.abs(eps - want) <= 1e-6)
    # The split in one pass: at the table's own speeds the two losses are the command line's
    # parts of the same sum (1 - eps^2 = loss_waves + loss_viscous, docs/damping.md).
    w = np.asarray(law.law.v[::60], dtype=float) * law.speed_scale_m_s
    parts = law.losses(w)
    np.testing.assert_allclose(parts["loss_waves"] + parts["loss_viscous"], parts["loss_total"],
                               rtol=1e-12, atol=1e-15)  # fmt: skip
    assert np.all(parts["loss_viscous"] > 10 * parts["loss_waves"])  # 1 mm glass: viscous


@pytest.mark.slow
def test_plastic_steel_is_tabulated_within_its_stated_error(cli):
    """The table (the pulse computed at four speeds a decade, Thornton's closed form and the
    elastic law's own loss at every speed of the elastic law between them, the rest
    interpolated: restitution.laws.shaped_table) against the command line's pulse computed at
    the speed itself. Measured when written: the misses are 1.3e-4, 0.089, 0.073 and 0.013 of
    the stated errors (7.7e-8, 1.2e-5, 1.1e-4, 1.1e-3); with the computed speeds alone they were
    0.25, 0.11, 0.12 and 0.014."""
    opts = dict(yield_stress=1e9, radius=1e-3)
    law = restitution.si_law(**STEEL, against="wall", **opts)
    eps, err, want, _ = _compare(cli, law, **STEEL, against="wall", **opts)
    assert np.all(np.abs(eps - want) <= 0.1 * err), (eps - want, err)
    assert "plastic" in law.law.metadata["mechanisms"]


@pytest.mark.slow
def test_steel_on_a_glass_block_is_its_grid_law_within_its_stated_error(cli):
    """Measured when written: the misses are 0.0016, 8e-5, 0.0017 and 0.0021 of the stated
    errors: within a tenth of them."""
    opts = dict(wall_E=63e9, wall_nu=0.2481, wall_rho=2500.0)
    law = restitution.si_law(**STEEL, against="wall", **opts)
    eps, err, want, _ = _compare(cli, law, **STEEL, against="wall", **opts)
    print("wall misses / stated error:", np.abs(eps - want) / err)
    assert np.all(np.isfinite(eps))
    assert np.all(np.abs(eps - want) <= 0.1 * err), (eps - want, err)
