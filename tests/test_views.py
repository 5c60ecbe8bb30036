"""An SI law for a notebook: rows, CSV, a pandas DataFrame, a figure, and `law --plot` (issue 45,
item 8)."""

from __future__ import annotations

import csv
import math

import matplotlib
import numpy as np
import pytest

from restitution import si_law
from restitution.laws import views

matplotlib.use("Agg")

SPEEDS = [0.001, 0.5, 20.0, 5000.0]  # below the collisions, between, and above the law


@pytest.fixture(scope="module")
def steel():
    return si_law(E=210e9, nu=0.3, rho=7850, shape="cylinder", against="wall")


def test_rows_are_the_points(steel):
    table = steel.rows(SPEEDS)
    assert [tuple(r) for r in table] == [views.COLUMNS] * len(SPEEDS)
    for r, p in zip(table, steel.points(SPEEDS), strict=True):
        assert r["speed_m_s"] == p.speed_m_s and r["epsilon"] == p.epsilon
        assert r["status"] == str(p.status) and isinstance(r["status"], str)
    assert table[-1]["status"] == "outside" and table[-1]["epsilon"] is None
    lo, hi = steel.speed_range_m_s
    default = steel.rows()
    assert len(default) == views.DEFAULT_POINTS
    assert default[0]["speed_m_s"] == pytest.approx(lo) and default[-1]["speed_m_s"] == (
        pytest.approx(hi)
    )


def test_csv_holds_every_point_and_an_empty_cell_for_no_value(steel, tmp_path):
    path = steel.to_csv(tmp_path / "law.csv", SPEEDS)
    with open(path, newline="") as fh:
        notes = [line for line in fh if line.startswith("#")]
        fh.seek(0)
        read = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    assert tuple(read[0]) == views.FRAME_COLUMNS and len(read) == len(SPEEDS)
    for r, p in zip(read, steel.points(SPEEDS), strict=True):
        # Issue 62: a row names its note, whose text is written once above the header.
        assert (r["note_id"] == "") == (p.note == "")
        if p.note:
            assert f"# note {r['note_id']}: {p.note}\n" in notes
        if p.epsilon is None:
            assert r["epsilon"] == "" and r["status"] == "outside"
        else:
            assert float(r["epsilon"]) == p.epsilon  # repr round-trips a float
            assert float(r["epsilon_err"]) == p.epsilon_err
    assert not list(tmp_path.glob(".*part*"))  # no temporary file left


def test_frame_is_the_rows_with_nan_for_no_value(steel):
    pd = pytest.importorskip("pandas")  # an optional dependency, in the test extra
    frame = steel.to_frame(SPEEDS)
    assert isinstance(frame, pd.DataFrame) and tuple(frame.columns) == views.FRAME_COLUMNS
    for (_, row), p in zip(frame.iterrows(), steel.points(SPEEDS), strict=True):
        assert frame.attrs["notes"].get(row["note_id"], "") == p.note  # issue 62: once
        if p.epsilon is None:
            assert math.isnan(row["epsilon"])
        else:
            assert row["epsilon"] == p.epsilon and row["epsilon_max"] <= 1.0
    assert frame["epsilon"].dtype == np.float64


def test_plot_draws_the_band_the_points_promise(steel, tmp_path):
    path = tmp_path / "law.png"
    ax = steel.plot(path, SPEEDS[:3], marks=steel.points(SPEEDS))
    image = matplotlib.image.imread(path)
    assert image.ndim == 3 and image.shape[0] > 100
    band = ax.collections[0].get_paths()[0].vertices[:, 1]
    points = steel.points(SPEEDS[:3])
    lows = [p.epsilon_range[0] for p in points]
    highs = [p.epsilon_range[1] for p in points]
    assert min(band) == pytest.approx(min(lows)) and max(band) == pytest.approx(max(highs))
    assert ax.get_xscale() == "log"


def test_law_plot_writes_the_figure(cli, tmp_path):
    path = tmp_path / "law.png"
    code, out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                         "cylinder", "--against", "wall", "--speed", "1", "10",
                         "--plot", str(path))  # fmt: skip
    assert code == 0, err
    assert f"wrote {path}" in err and matplotlib.image.imread(path).shape[0] > 100


def test_law_plot_refuses_before_computing(cli, tmp_path):
    base = ("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "cylinder",
            "--against", "wall", "--speed", "1")  # fmt: skip
    code, out, err = cli(*base, "--plot", str(tmp_path / "law.xyz"))
    assert code == 2 and "unknown figure format" in err and err.count("\n") == 1
    # A mechanism without a law at every speed: tests/test_api_si_law.py.


@pytest.mark.slow  # 30 s of the default run (stop 76: the default run under 10 min)
def test_law_plot_draws_a_damped_law_with_its_answer_on_it(cli, tmp_path):
    """A damping grain's plot is its damped law at every speed (the mechanism's table), the
    asked speeds marked on it, the mechanisms named in the title."""
    import matplotlib.pyplot as plt

    path = tmp_path / "damped.png"
    code, out, err = cli("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--shape",
                         "sphere", "--against", "grain", "--measured-epsilon", "0.9",
                         "--measured-speed", "1", "--radius", "1e-3", "--speed", "0.1", "1",
                         "--plot", str(path))  # fmt: skip
    assert code == 0, err
    assert f"wrote {path}" in err and matplotlib.image.imread(path).shape[0] > 100
    plt.close("all")
