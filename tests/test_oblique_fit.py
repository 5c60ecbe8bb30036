"""``restitution oblique-fit`` and its Python edge (restitution.laws.making.oblique_fit): a
material's oblique table over angles and the DEM parameters fitted to it (issue 63, delivery).

The fits are checked against independent routes on tables whose law is known:
Maw-Barber-Fawcett's law (a) (quasistatic DOP853 in restitution.quasistatic.oblique), which
LAMMPS's ``mindlin`` with Mindlin's ``k_t = 8 G*`` reproduces to 1.2e-7
(tests/test_lammps_friction.py), must give back Mindlin's ``chi = 2 (1 - nu) / (2 - nu)`` and
the ``k_t`` of the exported lines; Walton's law must give back its parameters. The command runs
the modal route on a coarse grid (10 modes: the plumbing, not converged numbers): Coulomb's
impulse ratio at the gross-slip angle, the refusals before any run, and (slow: the fits at
their full resolution take about 15 s a run) the same numbers through the command line and
Python.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.making.oblique_fit import oblique_fit
from restitution.laws.oblique_fits import fit_table
from restitution.laws.tangential_models import walton_beta
from restitution.quasistatic.oblique import beta_of_psi

STEEL = dict(E=210e9, nu=0.3, rho=7850.0)
MU = 0.3
COARSE = dict(shape="cylinder", friction=MU, angles=(20.0, 50.0, 80.0), speeds=(5.0,), modes=10)
"""A coarse run (3 angles of the cylinder at 5 m/s, 10 and 5 modes: about 6 s)."""
COARSE_FITS = dict(steps=500, springs=30, scan=7)
"""The fits' coarse resolutions (tests/test_oblique_figures.py's)."""


def _table(angles, beta, eps, K=None, speed=1.0):
    """A table in compute_table's layout with the given beta and epsilon_normal per angle."""
    rows = [{"angle_deg": a, "speed_m_s": speed, "beta": b, "beta_error": 0.0,
             "epsilon_normal": e, "epsilon_normal_error": 0.0, "status": "ok", "advice": None}
            for a, b, e in zip(angles, beta, eps, strict=True)]  # fmt: skip
    table = {"friction": MU, "speeds_m_s": [speed], "angles_deg": list(angles), "rows": rows,
             "material": {"E_pa": STEEL["E"], "nu": STEEL["nu"], "rho_kg_m3": STEEL["rho"],
                          "shape": "sphere"}}  # fmt: skip
    if K is not None:
        table["inertia_factor"] = K
    return table


ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)


def test_law_a_gives_back_mindlins_stiffness_and_the_exported_k_t():
    """A sphere table made by Maw-Barber-Fawcett's law (a) (nu = 0.3, K = 7/2): the fitted
    ``mindlin`` chi is Mindlin's 0.8235 within the refinement's tolerance (``xatol`` 1e-6) and
    the DEM model's step error (first order: measured 1.8e-6 at 1000 steps, 7e-8 at 4000), and
    its ``k_t`` on the rigid wall is the exported line's ``8 G*``, ``G* = G / (2 - nu)``,
    between grains ``8 G*`` with ``1/G* = 2 (2 - nu) / G``."""
    nu, K = STEEL["nu"], 3.5
    chi = 2 * (1 - nu) / (2 - nu)
    X = np.tan(np.radians(ANGLES)) / MU
    beta = beta_of_psi(chi * X, nu, inertia_factor=K, model="no-microslip")
    fits = fit_table(_table(ANGLES, beta, [1.0] * len(ANGLES), K=K), steps=4000, scan=21,
                     springs=20)  # fmt: skip
    m = fits.summary()["1.0"]["mindlin"]
    assert m["chi"] == pytest.approx(chi, rel=1e-5)
    assert m["rms"] < 1e-5  # measured 2e-7
    G = STEEL["E"] / (2 * (1 + nu))
    assert m["wall_k_t_pa"] == pytest.approx(8 * G / (2 - nu), rel=1e-5)
    assert m["k_t_pa"] == pytest.approx(8 * G / (2 * (2 - nu)), rel=1e-5)
    assert m["wall_ratio_to_null"] == pytest.approx(m["ratio_to_null"], rel=1e-12)
    assert fits.inertia_factor == K


def test_walton_gives_back_its_parameters_at_the_sphere_lever():
    X = np.tan(np.radians(ANGLES)) / MU
    beta = walton_beta(X, 0.95, 1.1, 0.4, inertia_factor=3.5)
    fits = fit_table(_table(ANGLES, beta, [0.95] * len(ANGLES), K=3.5), steps=200, scan=5,
                     springs=20)  # fmt: skip
    w = fits.walton[1.0]
    assert (w.e, w.mu_w, w.beta_0) == pytest.approx((0.95, 1.1 * MU, 0.4), rel=1e-6)
    assert w.rms < 1e-9


def test_a_table_without_its_lever_or_with_one_angle_is_refused():
    with pytest.raises(InputError, match="give inertia_factor=3.0 for a disk or 3.5"):
        fit_table(_table((10.0, 20.0), (0.1, 0.2), (1.0, 1.0)))
    with pytest.raises(InputError, match="the fits need two or more"):
        fit_table(_table((0.0, 20.0), (None, 0.2), (1.0, 1.0), K=3.0))


@pytest.fixture(scope="module")
def coarse():
    return oblique_fit(**STEEL, **COARSE, **COARSE_FITS)


def test_history_models_scan_every_stiffness_at_once():
    """A row of the array call is the single call (the same arithmetic, one row per chi)."""
    from restitution.laws.tangential_models import history_beta

    X = np.tan(np.radians((10.0, 40.0, 80.0))) / MU
    grid = np.geomspace(0.05, 5.0, 7)
    for model in ("mindlin", "linear_history"):
        rows = history_beta(X, grid, model, inertia_factor=3.5, steps=800)
        each = [history_beta(X, c, model, inertia_factor=3.5, steps=800) for c in grid]
        assert rows.shape == (7, 3)
        assert np.max(np.abs(rows - np.array(each))) <= 1e-15


def test_the_text_answer_names_every_fit_and_the_lammps_words(coarse):
    from restitution.cli.oblique_fit import _draw
    from restitution.cli.report import rich_text

    text = rich_text(lambda console: _draw(console, coarse))
    for words in ("Walton: e ", "LAMMPS mindlin: chi", "linear_history: chi", "microslip: chi",
                  coarse.lammps_lines(5.0)["wall_fix"], "status: ",
                  "normal coefficient for the DEM code: law's "):  # fmt: skip
        assert words in text
    assert len(coarse.rows()) == 4 and {r["fit"] for r in coarse.rows()} == {
        "walton", "mindlin", "linear_history", "microslip"}  # fmt: skip


@pytest.mark.slow
def test_the_command_and_python_give_the_same_numbers(cli, tmp_path):
    """The command (its fits at full resolution) and :func:`oblique_fit` with the same
    arguments: the same points, fits and LAMMPS words (one code path, one machine)."""
    coarse = oblique_fit(**STEEL, **COARSE)
    args = ["oblique-fit", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
            "cylinder", "--friction", str(MU), "--angle", "20", "50", "80", "--speed", "5",
            "--modes", "10"]  # fmt: skip
    code, out, err = cli(*args, "--format", "json", "--plot", str(tmp_path / "beta.png"))
    assert code == 0, err
    doc = json.loads(out)
    assert doc["command"] == "oblique-fit" and doc["status"] == str(coarse.status)
    assert doc["inputs"]["angles_deg"] == [20.0, 50.0, 80.0]
    assert "about" in err and "expected" in err  # the estimate, before the runs
    rows = {(r["angle_deg"], r["speed_m_s"]): r for r in doc["table"]["rows"]}
    for r in coarse.table["rows"]:
        mine = rows[r["angle_deg"], r["speed_m_s"]]
        assert (mine["beta"], mine["epsilon_normal"]) == (r["beta"], r["epsilon_normal"])
    assert doc["fits"] == json.loads(json.dumps(coarse.fits.summary()))
    assert doc["lammps"]["5.0"] == coarse.lammps_lines(5.0)
    assert (tmp_path / "beta.png").stat().st_size > 10_000
    code, out, err = cli(*args, "--format", "csv", "--output", str(tmp_path / "fits.csv"))
    assert code == 0, err
    import csv

    with open(tmp_path / "fits.csv") as fh:
        table = list(csv.DictReader(fh))
    assert [r["fit"] for r in table] == ["walton", "mindlin", "linear_history", "microslip"]
    code, out, err = cli(*args)
    assert code == 0 and "LAMMPS mindlin: chi" in out and "tangential mindlin " in out


def test_every_row_carries_the_head_on_law_the_dem_code_needs(coarse):
    """The rows' ``epsilon_head_on_law`` is what ``law`` serves at the speed (without
    ``--angle``), and ``epsilon_normal``'s error covers the distance to it."""
    from restitution.laws.request import request
    from restitution.laws.serve import serve

    (point,) = serve(request(**STEEL, shape="cylinder", against="wall", speeds=(5.0,))).points
    for r in coarse.table["rows"]:
        assert r["epsilon_head_on_law"] == point.epsilon
        assert r["epsilon_normal_error"] >= abs(r["epsilon_normal"] - point.epsilon)


def test_the_gross_slip_angle_is_coulombs_impulse_ratio(coarse):
    """At 80 degrees the contact slides throughout: ``beta = -1 + K mu (1 + e) / tan(theta)``
    (K = 3, the cylinder), with the row's own epsilon_normal, within the lever's first-order
    correction (the shipped table's bound, tests/test_oblique_figures.py)."""
    assert coarse.fits.inertia_factor == pytest.approx(3.0, rel=1e-12)
    (row,) = [r for r in coarse.table["rows"] if r["angle_deg"] == 80.0]
    ratio = -1.0 + 3.0 * MU * (1.0 + row["epsilon_normal"]) / math.tan(math.radians(80.0))
    assert abs(row["beta"] - ratio) < 2e-3
    assert abs(row["energy_balance"]) < 1e-9
    lines = coarse.lammps_lines(5.0)
    wall = lines["wall_fix"]
    assert wall.startswith("tangential mindlin ") and wall.endswith(" 0.0 0.3")


def test_refusals_come_before_any_run(cli):
    code, out, err = cli("oblique-fit", "--E", "210e9", "--nu", "0.3", "--rho", "7850",
                         "--shape", "sphere", "--friction", "0.3", "--angle", "30")  # fmt: skip
    assert code == 2 and "two or more angles above 0" in err and len(err.splitlines()) == 1
    with pytest.raises(InputError, match="two or more angles above 0"):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, angles=(0.0, 30.0))
    with pytest.raises(InputError, match="each angle once"):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, angles=(30.0, 30.0, 40.0))
    with pytest.raises(InputError, match="--angle"):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, angles=(30.0, 95.0))
    with pytest.raises(InputError, match="--modes must be an integer >= 2"):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, angles=(30.0, 60.0), modes=1)
    # 1e9 m/s is 1.9e5 c: refused in one line (it was a math domain error deep in the contact)
    with pytest.raises(InputError, match="needs a normal speed below c = 5"):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, angles=(30.0, 60.0), speeds=(1e9,))
    # The steel cylinder at 0.01 m/s: about 2 h estimated for the 9 default angles
    with pytest.raises(
        InputError, match=r"more than the 1 h .*angles of these speeds fit.*--force"
    ):
        oblique_fit(**STEEL, shape="cylinder", friction=MU, speeds=(0.01,))


def test_more_modes_than_the_memory_holds_are_refused_before_the_nodes(cli, monkeypatch):
    """``--modes 2000`` of the sphere needs about 209 GiB for its wall nodes' rows (109446
    modes of both symmetries on 125536 nodes; measured, stop 81): refused in one line before
    any node is made, where it died of a NumPy MemoryError; here with the memory made 1 MiB
    and 20 modes, which the nodes' estimate also exceeds."""
    import restitution.budget as budget
    from restitution.bodies.sphere.cap import SphereCap

    def never(*_args, **_kwargs):
        raise AssertionError("the nodes were made")

    monkeypatch.setattr(SphereCap, "wall_nodes", never)
    monkeypatch.setattr(budget, "available_memory", lambda: 2.0**20)
    code, _, err = cli("oblique-fit", "--E", "210e9", "--nu", "0.3", "--rho", "7850",
                       "--shape", "sphere", "--friction", "0.3", "--angle", "30", "60",
                       "--modes", "20")  # fmt: skip
    assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert "--modes 20 needs about" in err and "ask for fewer modes" in err
