"""The plugin's wall table of a damped grain is the damped law on the wall (issue 60: it was the
elastic law, 0.99997 at 1 m/s for a glass bead whose damped wall law and native snippet give
0.886; issue 61 item 3). One export of identical damped grains writes, from the one answer, the
pair's table and the grain's damped law on the wall; the wall table's knots are compared with
``restitution law --against wall`` of the same relaxation time, an independent request through
the same damped law."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline

pytestmark = pytest.mark.slow  # the damped export's fixture: 42-61 s of the default run (stop 76)

GLASS = ["--E", "63e9", "--nu", "0.24", "--rho", "2500", "--shape", "sphere"]
DAMPING = ["--measured-epsilon", "0.9", "--measured-speed", "1", "--radius", "1e-3"]


def _knots(path) -> np.ndarray:
    lines = [x for x in path.read_text().splitlines() if not x.startswith("#")]
    start = next(i for i, x in enumerate(lines) if x.startswith("knots "))
    count = int(lines[start].split()[1])
    return np.array(
        [[float(y) for y in x.split()[:3]] for x in lines[start + 1 : start + 1 + count]]
    )


@pytest.fixture(scope="module")
def export(tmp_path_factory):
    from restitution.cli import main

    out = tmp_path_factory.mktemp("damped") / "export"
    try:
        main(["law", *GLASS, "--against", "grain", "--speed", "1", *DAMPING, "--json", "-q",
              "--export", str(out)])  # fmt: skip
    except SystemExit as exc:  # the command line's exit
        assert exc.code in (0, None)
    return out


def test_the_wall_table_says_it_is_damped(export):
    head = (export / "epsilon_lammps_plugin_wall1.table").read_text()
    (line,) = [x for x in head.splitlines() if x.startswith("# mechanisms:")]
    assert "viscous loss of the material" in line


def test_the_wall_table_is_the_damped_wall_law(export, cli):
    code, out, err = cli("law", *GLASS, "--against", "grain", "--speed", "1", *DAMPING, "--json")
    assert code == 0, err
    tau_s = json.loads(out)["damping"]["relaxation_time_s"]
    knots = _knots(export / "epsilon_lammps_plugin_wall1.table")
    some = knots[:: max(len(knots) // 12, 1)]
    speeds = [repr(float(w)) for w in some[:, 0]] + ["1"]
    code, out, err = cli("law", *GLASS, "--against", "wall", "--relaxation-time", repr(tau_s),
                         "--radius", "1e-3", "--speed", *speeds, "--json")  # fmt: skip
    assert code == 0, err
    points = json.loads(out)["points"]
    # At the knots (the damped wall law's computed speeds) the same numbers: one code path.
    for (w, eps, _), p in zip(some, points[:-1], strict=True):
        assert p["epsilon"] == pytest.approx(eps, rel=1e-12), w
    # Between the knots the plugin's cubic Hermite interpolant, within the law's error.
    table = CubicHermiteSpline(knots[:, 0], knots[:, 1], knots[:, 2])
    at_1 = points[-1]
    assert abs(float(table(1.0)) - at_1["epsilon"]) <= at_1["epsilon_err"]
    assert at_1["epsilon"] < 0.95  # damped: the elastic law there is 0.99997
