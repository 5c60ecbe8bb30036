"""Command line of vibrating disks: ``collide --excite`` and ``bounce`` (issue 17).

Runs in this process (as tests/test_hostile.py does) on small mode sets; every number checked
against the library computed here independently.
"""

import json

import numpy as np
import pytest

import restitution
from restitution import get_modes
from restitution.dynamics.collision import collide
from restitution.vibrating.vibration import kinetic_energy, single_mode_state


def test_thermal_ensemble_json(cli, tmp_path):
    fig = tmp_path / "hist.png"
    code, out, err = cli("collide", "--v", "0.1", "--modes", "10", "--excite",
                         "thermal", "--temperature", "0.25", "--samples", "6", "--seed", "2",
                         "--energy-tol", "1e-5", "--plot", str(fig), "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    assert d["units"] == restitution.UNITS and d["status"] == "ok"
    assert d["inputs"]["temperature"] == 0.25 and d["inputs"]["seed"] == 2
    t = d["temperature"]
    assert t["per_mode_fraction_of_E0"] == pytest.approx(0.25)
    assert t["per_mode_reduced"] == pytest.approx(0.25 * 0.5 * np.pi * 0.01)
    assert t["v_over_v_thermal"] == pytest.approx(2.0)
    rows = d["per_sample"]
    assert len(rows) == 6 and d["samples"] == 6
    keys = {"epsilon", "mode_energy_before", "mode_energy_after", "kinetic_energy_before",
            "kinetic_energy_after"}  # fmt: skip
    assert keys <= rows[0].keys()
    eps = np.array([r["epsilon"] for r in rows])
    assert d["mean"] == pytest.approx(eps.mean()) and d["spread"] == pytest.approx(eps.std(ddof=1))
    assert d["fraction_above_1"] == pytest.approx(np.mean(eps > 1))
    for r in rows:  # energy balance, fractions of (m/2) v^2
        before = r["kinetic_energy_before"] + r["mode_energy_before"]
        after = r["kinetic_energy_after"] + r["mode_energy_after"]
        assert after == pytest.approx(before, rel=3e-5)
    assert fig.stat().st_size > 5000


def test_single_mode_matches_the_library(cli):
    args = ("--excite", "mode", "--mode-index", "2", "--amplitude", "0.05", "--phase", "1.0")
    code, out, err = cli("collide", "--v", "0.1", "--modes", "12", *args, "--json")
    assert code == 0, err
    d = json.loads(out)
    ms = get_modes(0.33, count=12)
    Q, P = single_mode_state(ms, 2, 0.05 * kinetic_energy(ms, 0.1), 1.0)
    # The command judges the step by epsilon (--step-check, default epsilon): the same call.
    assert d["inputs"]["step_check"] == "epsilon"
    assert d["epsilon"] == collide(ms, 0.1, 500.0, initial=(Q, P), step_judge="epsilon").epsilon
    assert d["vibration_energy_before"] == pytest.approx(0.05, rel=1e-12)
    assert d["excited_mode"]["n"] == int(ms.n[2])


def test_bounce_json(cli):
    code, out, err = cli("bounce", "--v", "0.1", "--alpha", "400", "--modes", "10",
                         "--collisions", "3", "--gravity", "1e-5", "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    rows = d["collisions"]
    assert d["command"] == "bounce" and len(rows) == 3
    # bounce judges every step by epsilon, as collide does (vibration.STEP_JUDGE).
    first = collide(get_modes(0.33, count=10), 0.1, 400.0, step_judge="epsilon")
    assert rows[0]["epsilon"] == first.epsilon
    assert rows[1]["vibration_before"] > 0
    assert d["constant_epsilon"]["impact_speeds"][1] == pytest.approx(0.1 * rows[0]["epsilon"])


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("--excite", "sideways"), "unknown --excite"),
        (("--excite", "thermal", "--temperature", "-1"), "--temperature"),
        (("--excite", "thermal", "--temperature", "1", "--samples", "0"), "--samples"),
        (("--excite", "thermal"), "needs --temperature"),
        (("--excite", "mode"), "needs --amplitude"),
        (("--excite", "mode", "--amplitude", "0.1", "--mode-index", "99"), "mode index"),
        (("--excite", "mode", "--amplitude", "0.1", "--temperature", "1"), "no effect"),
        (("--temperature", "1"), "no effect"),
        (("--excite", "thermal", "--temperature", "1", "--method", "fem"), "--method modal"),
    ],
)
def test_bad_excitations_are_one_line(cli, args, words):
    code, _, err = cli("collide", "--v", "0.1", "--modes", "10", *args)
    lines = [x for x in err.splitlines() if x.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("error: "), err
    assert words in lines[0]


@pytest.mark.parametrize(
    ("args", "words"),
    [
        ((), "exactly one"),
        (("--gravity", "1e-5", "--walls-distance", "5"), "exactly one"),
        (("--gravity", "-1"), "--gravity"),
        (("--walls-distance", "1"), "--walls-distance"),
        (("--gravity", "1e-5", "--collisions", "0"), "--collisions"),
    ],
)
def test_bad_bounces_are_one_line(cli, args, words):
    code, _, err = cli("bounce", "--v", "0.1", "--modes", "10", *args)
    lines = [x for x in err.splitlines() if x.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("error: "), err
    assert words in lines[0]
