"""The command line: output formats and clean errors (one line on stderr, no traceback)."""

import json
import subprocess
import sys

import numpy as np
import pytest

from restitution import get_modes


def run(*args):
    return subprocess.run(
        [sys.executable, "-c", "from restitution.cli import main; main()", *args],
        capture_output=True,
        text=True,
        timeout=600,
    )


def test_modes_json_sorted_with_required_keys(tmp_path):
    out = tmp_path / "modes.json"
    r = run("modes", "--nu", "0.33", "--count", "50", "--format", "json", "--output", str(out))
    assert r.returncode == 0, r.stderr
    doc = json.loads(out.read_text())
    assert {"version", "command", "units", "inputs", "status", "advice"} <= doc.keys()
    assert doc["inputs"]["count"] == 50 and doc["status"] == "ok"
    records = doc["modes"]
    assert len(records) == 50
    assert {"n", "l", "omega", "C", "S"} <= records[0].keys()
    omega = [rec["omega"] for rec in records]
    assert omega == sorted(omega)
    np.testing.assert_allclose(omega, get_modes(0.33, count=50).omega, rtol=1e-15)


def test_modes_csv_and_figures(tmp_path):
    spec, shapes = tmp_path / "fig3.png", tmp_path / "fig2.png"
    r = run("modes", "--count", "20", "--format", "csv", "--plot-spectrum", str(spec),
            "--plot-shapes", str(shapes))  # fmt: skip
    assert r.returncode == 0, r.stderr
    lines = r.stdout.strip().splitlines()
    assert lines[0].startswith("order,n,l,omega") and len(lines) == 21
    import matplotlib.image as mpimg

    for path in (spec, shapes):
        img = mpimg.imread(path)
        assert img.shape[0] > 100 and img.std() > 0


def test_collide_json_keys():
    r = run("collide", "--v", "0.1", "--alpha", "500", "--modes", "30", "--json")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)
    for key in ("epsilon", "energy_drift", "contact_time", "max_compression",
                "mode_energies_after", "wall_time_s"):  # fmt: skip
        assert key in d
    assert 0.9 < d["epsilon"] < 1.0
    assert {"order", "n", "l", "energy"} == set(d["mode_energies_after"][0])
    loss = sum(m["energy"] for m in d["mode_energies_after"])
    assert loss == pytest.approx(1 - d["epsilon"] ** 2, abs=1e-5)


@pytest.mark.parametrize(
    "args, words",
    [
        (("modes", "--nu", "1.5"), "(-1, 1)"),
        (("modes", "--nu", "0.6", "--plane", "strain"), "(-1, 0.5]"),
        (("modes", "--count", "0"), "positive"),
        (("collide", "--v", "0"), "(0, 1)"),
        (("collide", "--v", "1.2"), "(0, 1)"),
        (("collide", "--v", "0.1", "--alpha", "-3"), "positive"),
        (("collide", "--v", "0.1", "--modes", "0"), "at least 1"),
        (("collide", "--v", "nan"), "(0, 1)"),
    ],
)
def test_bad_input_is_one_clear_line(args, words):
    r = run(*args)
    assert r.returncode == 2
    assert "Traceback" not in r.stderr
    lines = [x for x in r.stderr.strip().splitlines() if x]
    assert len(lines) == 1 and words in lines[0], r.stderr


def test_fast_speed_warns():
    """Beyond 0.3 c the text warns on stderr and the JSON says it in its status (issue 30: the
    warning once went to stderr only, where -q hid it)."""
    args = ("collide", "--v", "0.35", "--alpha", "100", "--modes", "10", "--energy-tol", "1e-4")
    r = run(*args)
    assert r.returncode == 0 and "linear elasticity" in r.stderr
    r = run(*args, "--json")
    d = json.loads(r.stdout)
    assert r.returncode == 0 and d["status"] == "large-deformation"
    assert "linear elasticity" in d["advice"]
