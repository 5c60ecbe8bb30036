"""Plastic flow exported (issue 61): ``law --yield-stress ... --export DIR`` writes the tables,
C and Fortran and the LAMMPS plugin's tables of the plastic law (its table,
restitution.laws.tabulated), the plugin's wall table the plastic law of the grain on the wall,
each knot the mechanism's own number at that speed (the command line's ``law`` there)."""

from __future__ import annotations

import numpy as np
import pytest

import restitution
from restitution.laws.exports.pchip import LOG_KNOTS_INSIDE
from restitution.laws.request import request
from restitution.laws.serve import serve

STEEL = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere"]
STEEL_KW = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere")


def _knots(path):
    """The table's knots ``(w, epsilon, slope)``: the ``knots N`` rows after its header (the
    map beta(epsilon) follows them)."""
    lines = [x for x in path.read_text().splitlines() if x.strip() and not x.startswith("#")]
    at = next(i for i, x in enumerate(lines) if x.split()[0] == "knots")
    count = int(lines[at].split()[1])
    return np.array([[float(y) for y in x.split()] for x in lines[at + 1 : at + 1 + count]])


@pytest.mark.slow
def test_a_plastic_steel_export_has_every_file_and_the_walls_plastic_law(cli, tmp_path):
    out = tmp_path / "export"
    code, _, err = cli("law", *STEEL, "--against", "grain", "--yield-stress", "1e9",
                       "--radius", "1e-3", "--speed", "1", "--export", str(out))  # fmt: skip
    assert code == 0, err
    for name in ("epsilon.csv", "epsilon.h", "epsilon.f90", "epsilon_lammps_plugin_11.table",
                 "epsilon_lammps_plugin_wall1.table", "epsilon_lammps_plugin.in"):  # fmt: skip
        assert (out / name).is_file(), name
    wall = out / "epsilon_lammps_plugin_wall1.table"
    head = wall.read_text()
    assert "plastic flow (Thornton" in head and "upper bound (no plastic flow)" not in head
    knots = _knots(wall)
    # The table's speeds, with LOG_KNOTS_INSIDE knots of its interpolant between each two (the
    # plastic table interpolates in ln v; the plugin's cubic is in w). Its speeds are the elastic
    # law's; the pulse was computed at some of them (restitution.laws.shaped_table): those are
    # the package's direct answers.
    table = restitution.si_law(**STEEL_KW, against="wall", yield_stress=1e9, radius=1e-3)
    records = table.law.metadata["points"]
    assert (knots.shape[0] - 1) % (LOG_KNOTS_INSIDE + 1) == 0
    at_records = knots[:: LOG_KNOTS_INSIDE + 1]
    assert at_records.shape[0] == len(records)
    np.testing.assert_allclose(at_records[:, 1], [r["epsilon"] for r in records], rtol=0,
                               atol=1e-12)  # fmt: skip
    computed = at_records[[r["computed"] for r in records]]
    assert computed.shape[0] >= 10
    # Three computed speeds above the yield speed: the plastic law of the grain on the wall.
    pick = computed[(computed[:, 0] > 0.1) & (computed[:, 0] < 50.0)][::3][:3]
    assert len(pick) == 3
    direct = serve(request(**STEEL_KW, against="wall", yield_stress=1e9, radius=1e-3,
                           speeds=list(pick[:, 0]))).points  # fmt: skip
    for (w, eps, _), p in zip(pick, direct, strict=True):
        assert eps < 0.9  # plastic, far below the elastic law's 0.9999
        assert abs(eps - p.epsilon) <= 1e-9, (w, eps, p.epsilon)
