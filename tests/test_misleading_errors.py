"""Errors and statuses that say what happened (issue 30, "misleading errors" and "answers that
depend on how they were asked"): each test is a case of the hostile-input audit that once gave a
wrong cause, a wrong exit status or an answer that changed when its own inputs were fed back.
"""

from __future__ import annotations

import json

import pytest
from _cli_checks import one_line_error
from _sampling import representatives

from restitution import get_modes
from restitution.cli import _common
from restitution.dynamics.collision import CollisionError, collide
from restitution.status import Status


@pytest.fixture(scope="module")
def small():
    return get_modes(0.33, count=40)


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_a_tolerance_too_tight_is_blamed_on_itself_not_on_alpha(small):
    """A tolerance the step bound cannot meet once said "lower alpha" up front, or "reduce dt or
    energy_tol" after the run: both must name energy_tol and advise raising it."""
    from restitution.errors import InputError

    with pytest.raises(InputError) as info:  # refused up front: the estimate
        collide(small, 0.1, 500.0, energy_tol=1e-14, max_steps=20_000)
    msg = str(info.value)
    assert "energy_tol = 1e-14 asks for that step" in msg and "raise energy_tol" in msg
    assert "lower alpha" not in msg
    # The estimate lets it start; the step refinements then break the bound during the run.
    with pytest.raises(CollisionError) as info:
        collide(small, 0.1, 500.0, energy_tol=1e-14)
    msg = str(info.value)
    assert "energy_tol = 1e-14" in msg and "max_steps = 2000000" in msg
    assert "raise energy_tol" in msg and "reduce dt or energy_tol" not in msg


def test_a_fixed_step_beyond_the_step_bound_advises_a_larger_step(small):
    from restitution.errors import InputError

    with pytest.raises(InputError, match="the step is the given dt: raise dt or max_steps"):
        collide(small, 0.1, 500.0, dt=1e-4, max_steps=1000)


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_thermal_samples_that_all_failed_exit_non_zero(cli):
    code, out, err = cli(
        "collide", "--v", "0.1", "--modes", "40", "--excite", "thermal", "--temperature", "1e3",
        "--samples", "3", "--seed", "1", "--json",
    )  # fmt: skip
    assert code == _common.EXIT_FAILED_POINTS, err
    d = json.loads(out)
    assert d["status"] == Status.FAILED_SAMPLES
    assert len(d["failures"]) == 3


def test_gravity_that_throws_the_disk_back_too_fast_names_gravity(cli):
    """--gravity 1e6 once reported "v must lie in (0, 1) ..., got [450.8]", a speed the user
    never gave; the refusal names the gravity, the speed it would bring and the bound."""
    code, out, err = cli(
        "bounce", "--v", "0.1", "--alpha", "416", "--modes", "40", "--collisions", "3",
        "--gravity", "1e6",
    )  # fmt: skip
    line = one_line_error(code, err, "gravity = 1e+06", "lower --gravity", "keeps this return")
    assert "got [" not in line


def test_export_onto_a_device_says_it_is_no_folder(cli):
    code, out, err = cli(
        "law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder",
        "--against", "wall", "--speed", "1", "--export", "/dev/full",
    )  # fmt: skip
    line = one_line_error(code, err, "--export /dev/full", "not a directory")
    assert "File exists" not in line


def test_one_mode_count_gives_no_error_bar_in_text_or_json(cli, tmp_path):
    """The text said "+- unknown" while the JSON gave a number; both now say unknown."""
    args = ("epsilon", "--nu", "0.33", "--v", "0.2", "--modes", "40", "--alphas", "20", "30",
            "40", "--alpha-scale", "absolute", "--store", str(tmp_path / "s.sqlite"),
            "--no-progress")  # fmt: skip
    code, out, err = cli(*args)
    assert "+- unknown" in out
    code, out, err = cli(*args, "--json")
    d = json.loads(out)
    assert d["epsilon_err"] is None and d["energy_loss_err"] is None
    assert "fewer than 3 mode counts" in d["errors_unknown"]
    assert d["epsilon"] is not None and d["status"] == Status.NOT_ASYMPTOTIC


@pytest.mark.slow  # 12 s of the default run (stop 76: the default run under 10 min)
@pytest.mark.parametrize("quiet", representatives([(), ("-q",)], {()}))  # -q: with -m slow
def test_beyond_the_model_range_is_a_status_not_only_a_warning(cli, quiet):
    """v = 0.99 once reported status ok with a compression of 0.9 R, the warning on stderr
    only (and -q hid it): the JSON's status says it."""
    code, out, err = cli(
        *quiet, "collide", "--nu", "0.33", "--v", "0.99", "--alpha", "500", "--modes", "40",
        "--json",
    )  # fmt: skip
    d = json.loads(out)
    assert d["status"] == Status.LARGE_DEFORMATION
    assert "beyond 0.3 c" in d["advice"] and f"{d['max_compression']:.2g} R" in d["advice"]
    code, out, err = cli(
        *quiet, "collide", "--nu", "0.33", "--v", "0.99", "--alpha", "500", "--modes", "40",
        "--json", "--strict",
    )  # fmt: skip
    assert code == _common.EXIT_NOT_CONVERGED


def test_a_pair_is_judged_by_its_relative_speed(cli):
    """Two disks at relative speed w: each moves at about w/2, so 0.5 is inside the range."""
    base = ("collide", "--nu", "0.33", "--radius-ratio", "1.4", "--alpha", "500", "--modes",
            "60", "--json")  # fmt: skip
    inside = json.loads(cli(*base, "--v", "0.5")[1])
    beyond = json.loads(cli(*base, "--v", "0.7")[1])
    assert inside["status"] == Status.OK
    assert beyond["status"] == Status.LARGE_DEFORMATION and "beyond 0.6 c" in beyond["advice"]


@pytest.mark.parametrize(
    "command",
    [
        ("collide", "--v", "0.1", "--alpha", "500", "--modes", "40", "--json"),
        ("quasistatic", "--v", "0.01", "--json"),
        ("modes", "--count", "5", "--format", "json"),
    ],
    ids=["collide", "quasistatic", "modes"],
)
def test_plane_strain_inputs_fed_back_give_the_same_answer(cli, command):
    """``--plane strain --nu 0.3`` was recorded as nu = 0.4286 beside plane = strain, so the
    recorded inputs, fed back, converted twice. Now ``nu`` is as given and ``nu_2d`` beside it."""
    code, out, err = cli(*command, "--nu", "0.3", "--plane", "strain")
    first = json.loads(out)
    inputs = first["inputs"]
    assert inputs["nu"] == 0.3 and inputs["plane"] == "strain"
    assert inputs["nu_2d"] == pytest.approx(0.3 / 0.7, rel=1e-15)
    code, out, err = cli(*command, "--nu", repr(inputs["nu"]), "--plane", inputs["plane"])
    again = json.loads(out)
    assert again["inputs"] == inputs
    drop = ("wall_time_s", "timing")
    assert {k: v for k, v in again.items() if k not in drop} == {
        k: v for k, v in first.items() if k not in drop
    }
