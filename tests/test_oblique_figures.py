"""The figures of docs/oblique.md (restitution.reproduction.figures.oblique_beta) and the shipped
oblique table they draw (restitution/laws/data/oblique/steel_cylinder_mu0.3.json).

The figure script runs on a coarse grid (one speed, coarse resolutions of the fitted models) and
one number is checked against an independent route: Walton's fitted ``mu_W`` against the
impulse ratio of the table's two gross-slip angles, ``beta = -1 + K mu_W (1 + e) / tan(theta)``
solved for ``mu_W`` (``K = 3``). The table is checked for its provenance and its own
consistency (the frictionless head-on rows have no ``beta``; every oblique row is under
Coulomb's gross-slip line within the lever's first-order correction).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from restitution.reproduction.figures import oblique_beta


@pytest.fixture(scope="module")
def table():
    return oblique_beta.load_table()


def test_table_has_its_provenance_and_every_point(table):
    assert table["code_version"] and table["computed"] and table["settings"]["modes"] == 160
    assert len(table["rows"]) == len(table["speeds_m_s"]) * len(table["angles_deg"])
    for r in table["rows"]:
        assert (r["beta"] is None) == (r["angle_deg"] == 0.0)
        assert abs(r["energy_balance"]) < 1e-9
        if r["beta"] is not None:
            tan = math.tan(math.radians(r["angle_deg"]))
            line = -1.0 + 3.0 * table["friction"] * (1.0 + r["epsilon_normal"]) / tan
            assert r["beta"] <= line + 2e-3, r


def test_figure_script_on_a_coarse_grid(table, tmp_path):
    w = table["speeds_m_s"][0]
    f = oblique_beta.compute(table, speeds=(w,), steps=500, springs=30, scan=7)
    # The two largest angles slide throughout (beta on the impulse ratio): mu_W from them.
    rows = sorted((r for r in table["rows"] if r["speed_m_s"] == w and r["angle_deg"] > 0),
                  key=lambda r: r["angle_deg"])[-2:]  # fmt: skip
    e = f.walton[w].e
    mu_w = [(1.0 + r["beta"]) * math.tan(math.radians(r["angle_deg"])) / (3.0 * (1.0 + e))
            for r in rows]  # fmt: skip
    assert f.walton[w].mu_w == pytest.approx(np.mean(mu_w), rel=2e-2)
    oblique_beta.plot_beta(f, tmp_path / "beta.png", speed=w, points=10, springs=30)
    oblique_beta.plot_normal(f, tmp_path / "eps.png")
    assert (tmp_path / "beta.png").stat().st_size > 10_000
    assert (tmp_path / "eps.png").stat().st_size > 10_000


@pytest.mark.slow
def test_a_stored_row_is_what_the_production_route_gives(table):
    """The cheapest stored row (5 m/s, 80 degrees: one slip; about 20 s), recomputed now by
    the table's own route, agrees with the file within a tenth of its stored error (a
    regression check of the shipped numbers)."""
    import dataclasses

    from restitution.laws.making.oblique_table import STEEL_TABLE, compute_table

    plan = dataclasses.replace(STEEL_TABLE, speeds=(5.0,), angles=(80.0,))
    (new,) = compute_table(plan, say=lambda _text: None)["rows"]
    (old,) = [r for r in table["rows"] if r["speed_m_s"] == 5.0 and r["angle_deg"] == 80.0]
    assert abs(new["beta"] - old["beta"]) <= 0.1 * old["beta_error"]
    assert abs(new["epsilon_normal"] - old["epsilon_normal"]) <= 0.1 * old["epsilon_normal_error"]
