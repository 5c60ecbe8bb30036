"""Issue 62, the Python API: a law interpolated in nu served fast and with its former numbers,
the notebook views (DataFrame, CSV) with each note once, the figure on the asked range naming
the mechanisms, and the notebook example of docs/materials.md run as it stands.

The interpolation in nu is checked against the former algorithm written out here: PCHIP in
``nu`` through every grid law (scipy's ``PchipInterpolator``) at each speed, the leave-one-out
prediction from all the other laws. The served law takes only the four laws PCHIP uses at its
``nu`` and its own arithmetic of scipy's formulas; the numbers agree to round-off (equal to the
last bit on this machine; the tests allow 1e-13 relative).
"""

from __future__ import annotations

import csv
import math
import re
import warnings
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.interpolate import PchipInterpolator

from restitution.errors import InputError
from restitution.laws import views
from restitution.laws.api import si_law
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_nu import NuInterpolatedLaw, law_for

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[1]
GLASS = dict(E=63e9, nu=0.2481, rho=2500, shape="sphere", against="grain")
DAMPED = dict(measured_epsilon=0.9, measured_speed=1.0, radius=1e-3)
ASKED = np.geomspace(0.02, 10.0, 12)  # m/s, inside every law's range here


# -- the former algorithm, every grid law at every speed ----------------------------------


def _pchip_all(x, y, at):
    """PCHIP through every node (every column of ``y``), nan where a column has one."""
    ok = np.all(np.isfinite(y), axis=0)
    out = np.full(y.shape[1:], np.nan)
    out[ok] = PchipInterpolator(x, y[:, ok], axis=0)(at)
    return out


def _former(law: NuInterpolatedLaw, v):
    """epsilon, its error and the interpolation error as the former code computed them, with
    the leave-one-out term's envelope over ``v/2, v, 2v`` (clipped to the laws' range) since
    3 Dec 2026 (``law_nu.SPEED_WINDOW``)."""
    x = np.array([n.nu for n in law.nodes])

    def leave_one_out(w):
        eps = np.array([n.epsilon(w, outside="nan") for n in law.nodes])
        loo = np.full(eps.shape, np.nan)
        for k in range(1, len(x) - 1):
            keep = np.arange(len(x)) != k
            loo[k] = np.abs(_pchip_all(x[keep], eps[keep], x[k]) - eps[k])
        return eps, loo

    eps, loo = leave_one_out(v)
    err = np.array([n.epsilon_err(v, outside="nan") for n in law.nodes])
    i = int(np.clip(np.searchsorted(x, law.nu) - 1, 0, len(x) - 2))
    t = (law.nu - x[i]) / (x[i + 1] - x[i])
    around = [k for k in (i, i + 1) if 0 < k < len(x) - 1]
    lo, hi = law.valid_range
    window = [loo[around]] + [leave_one_out(np.clip(v * f, lo, hi))[1][around] for f in (0.5, 2)]
    interp = np.max(np.concatenate(window), axis=0) * 4.0 * t * (1.0 - t)
    point = np.abs(_pchip_all(x, err, law.nu))
    return _pchip_all(x, eps, law.nu), np.hypot(point, interp), interp, loo


def _speeds(law, n: int = 3000) -> np.ndarray:
    """Speeds over and beyond the law's range, random ones and its own points."""
    lo, hi = law.valid_range
    rng = np.random.default_rng(62)
    return np.concatenate([np.geomspace(lo / 3, hi * 3, n), rng.uniform(lo, hi, n), law.v])


@pytest.mark.parametrize(
    "geometry, nu",
    # The glass sphere (first interval), the middle and last intervals of the sphere's grid,
    # and the disk's grid of nine laws at both ends and inside.
    [("sphere", 0.2481), ("sphere", 0.33), ("sphere", 0.44), ("disk", 0.21), ("disk", 0.55),
     ("disk", 0.89)],
)  # fmt: skip
def test_interpolated_law_serves_the_former_numbers(geometry, nu):
    law = law_for(nu, geometry=geometry)
    assert isinstance(law, NuInterpolatedLaw)
    v = _speeds(law)
    eps, err, interp, loo = _former(law, v)
    for got, want in (
        (law.epsilon(v, outside="nan"), eps),
        (law.epsilon_err(v, outside="nan"), err),
        (law.interpolation_err(v, outside="nan"), interp),
        (law.leave_one_out(v, outside="nan"), loo),
    ):
        assert np.array_equal(np.isnan(got), np.isnan(want))
        assert_allclose(got, want, rtol=1e-13, atol=1e-18)
    lo, hi = law.valid_range
    inside = (v >= lo) & (v <= hi)
    assert np.isfinite(eps[inside]).all() and np.isnan(eps[~inside]).all()


def test_synthetic_grid_with_a_turn_in_nu_serves_the_former_numbers():
    """Laws whose epsilon rises and falls with nu (PCHIP's zero slopes and one-sided end
    slopes at work), at every interval of a grid of four."""
    v = np.linspace(0.01, 0.3, 40)
    grid = [0.1, 0.3, 0.5, 0.7]
    laws = [
        EpsilonLaw.from_points(x, v, 0.9 - 0.1 * np.sin(9 * x + 20 * v), np.full(v.size, 1e-3))
        for x in grid
    ]
    w = np.linspace(0.005, 0.31, 2001)
    for nu in (0.12, 0.25, 0.3 + 1e-9, 0.42, 0.55, 0.69):
        law = NuInterpolatedLaw(nu, tuple(laws))
        eps, err, interp, _ = _former(law, w)
        assert_allclose(law.epsilon(w, outside="nan"), eps, rtol=1e-13, atol=1e-18)
        assert_allclose(law.epsilon_err(w, outside="nan"), err, rtol=1e-13, atol=1e-18)
        assert_allclose(law.interpolation_err(w, outside="nan"), interp, rtol=1e-13, atol=1e-18)


def test_outside_keeps_its_meaning_for_any_shape():
    law = law_for(0.2481, geometry="sphere")
    lo, hi = law.valid_range
    v = np.array([[lo / 2, lo], [hi, hi * 2]])
    got = law.epsilon(v, outside="nan")
    assert got.shape == (2, 2) and np.isnan(got[0, 0]) and np.isnan(got[1, 1])
    assert got[0, 1] == law.epsilon(lo) and got[1, 0] == law.epsilon(hi)
    assert isinstance(law.epsilon_err(float(np.sqrt(lo * hi))), float)
    with pytest.raises(InputError, match=r"outside the range .* every grid law .* covers"):
        law.epsilon(v)
    with pytest.warns(UserWarning, match="returning nan"):
        assert np.isnan(law.epsilon(hi * 2, outside="warn"))
    with pytest.raises(InputError, match="speeds must be numbers"):
        law.epsilon([lo, float("nan")], outside="nan")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing to say inside the range
        law.epsilon_err(np.geomspace(lo, hi, 50), outside="warn")


def test_points_behind_the_law_are_computed_once_and_read_only():
    law = law_for(0.2481, geometry="sphere")
    for name in ("v", "epsilon_points", "epsilon_err_points", "asymptotic_ok", "quasistatic"):
        first = getattr(law, name)
        assert getattr(law, name) is first and not first.flags.writeable
    assert_allclose(law.epsilon_points, law.epsilon(law.v), rtol=0)


def test_a_law_served_at_its_points_only_is_no_grid_law():
    v = np.array([0.01, 0.1])
    laws = [
        EpsilonLaw.from_records(
            x, [{"v": s, "epsilon": 0.9, "epsilon_err": 0.01, "asymptotic_ok": True} for s in v],
            key="low_speed", parameters={}, at_points_only=True,
        )
        for x in (0.2, 0.3, 0.4)
    ]  # fmt: skip
    with pytest.raises(InputError, match="interpolate between their points"):
        NuInterpolatedLaw(0.25, tuple(laws))


# -- the views: the same numbers as points(), each note once -------------------------------


class _Laws(dict):
    """The three laws, each built when first asked (the damped one's viscous table takes 25-40
    s: only the slow tests ask for it)."""

    MADE = {
        "shipped": lambda: si_law(E=210e9, nu=0.3, rho=7850, shape="sphere", against="wall"),
        "interpolated": lambda: si_law(**GLASS),
        "damped": lambda: si_law(**GLASS, **DAMPED),
    }

    def __missing__(self, kind):
        self[kind] = self.MADE[kind]()
        return self[kind]


@pytest.fixture(scope="module")
def laws():
    return _Laws()


@pytest.mark.parametrize(
    "kind",
    [
        "shipped",
        "interpolated",
        pytest.param("damped", marks=pytest.mark.slow),  # its table: 25-40 s (stop 76)
    ],
)
def test_frame_and_csv_hold_the_points_and_each_note_once(laws, kind, tmp_path):
    pd = pytest.importorskip("pandas")
    s = laws[kind]
    points = s.points(np.geomspace(*s.speed_range_m_s, views.DEFAULT_POINTS))
    frame = s.to_frame()
    assert tuple(frame.columns) == views.FRAME_COLUMNS and len(frame) == len(points)
    for name in ("speed_m_s", "v_over_c", "epsilon", "epsilon_err"):
        want = [math.nan if getattr(p, name) is None else getattr(p, name) for p in points]
        assert np.array_equal(frame[name].to_numpy(), np.array(want), equal_nan=True)
    assert list(frame["status"]) == [str(p.status) for p in points]
    notes = frame.attrs["notes"]
    assert [notes.get(k, "") for k in frame["note_id"]] == [p.note for p in points]
    assert sorted(notes.values()) == sorted({p.note for p in points} - {""})  # once each
    assert frame.attrs["mechanisms"] == (["waves", "viscous"] if kind == "damped" else ["waves"])
    # The CSV: the same table and the same notes, read back by pandas.
    path = s.to_csv(tmp_path / "law.csv")
    back = pd.read_csv(path, comment="#", keep_default_na=False, na_values=[""])
    assert tuple(back.columns) == views.FRAME_COLUMNS
    for name in ("speed_m_s", "epsilon", "epsilon_err", "epsilon_min", "epsilon_max"):
        assert np.array_equal(back[name].to_numpy(), frame[name].to_numpy(), equal_nan=True)
    assert list(back["note_id"].fillna("")) == list(frame["note_id"])
    head = [line for line in path.read_text().splitlines() if line.startswith("#")]
    assert [h for h in head if h.startswith("# note ")] == [
        f"# note {k}: {v}" for k, v in notes.items()
    ]
    assert len(path.read_text()) < 200 * len(points)  # no note repeated in the rows


def test_rows_keep_the_full_note(laws):
    s = laws["interpolated"]
    table = s.rows(ASKED)
    assert [tuple(r) for r in table] == [views.COLUMNS] * len(ASKED)
    assert [r["note"] for r in table] == [p.note for p in s.points(ASKED)]


def test_csv_reads_with_the_csv_module_after_its_comment_lines(laws, tmp_path):
    s = laws["shipped"]
    speeds = [1.0, 20.0, 5000.0]  # between the low-speed points, collisions, above the law
    path = s.to_csv(tmp_path / "law.csv", speeds)
    with open(path, newline="") as fh:
        lines = fh.read().splitlines()
    notes = dict(re.findall(r"^# note (n\d+): (.*)$", "\n".join(lines), re.M))
    read = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    points = s.points(speeds)
    assert [r["status"] for r in read] == [str(p.status) for p in points]
    assert [notes.get(r["note_id"], "") for r in read] == [p.note for p in points]
    assert (
        read[-1]["epsilon"] == ""
        and "above the largest computed speed" in notes[read[-1]["note_id"]]
    )


# -- the figure --------------------------------------------------------------------------


@pytest.mark.slow  # 25-40 s of the default run (stop 76: the default run under 10 min)
def test_plot_spans_the_asked_speeds_and_names_the_mechanisms(laws, tmp_path):
    s = laws["damped"]
    path = tmp_path / "damped.png"
    ax = s.plot(path, marks=s.points(ASKED))
    assert matplotlib.image.imread(path).shape[0] > 100
    left, right = ax.get_xlim()
    assert left <= ASKED[0] and right >= ASKED[-1]
    assert ASKED[0] / left < 1.5 and right / ASKED[-1] < 1.5  # not the law's 0.01-3000 m/s
    assert "waves + viscous" in ax.get_title()
    elastic = laws["interpolated"].plot(tmp_path / "elastic.png", marks=s.points(ASKED[:3]))
    assert "in the numbers: waves" in elastic.get_title() and "viscous" not in (elastic.get_title())


def test_plot_shows_the_band_in_epsilon_and_in_the_loss(laws, tmp_path):
    s = laws["interpolated"]
    w = np.geomspace(0.02, 1000.0, 40)
    ax = s.plot(tmp_path / "glass.png", w)
    assert ax.get_xlim() == pytest.approx((0.02, 1000.0))
    points = s.points(w)
    band = ax.collections[0].get_paths()[0].vertices[:, 1]
    assert min(band) == pytest.approx(min(p.epsilon_range[0] for p in points))
    assert max(band) == pytest.approx(max(p.epsilon_range[1] for p in points))
    loss_ax = ax.figure.axes[1]  # the loss panel below
    assert loss_ax.get_yscale() == "log" and loss_ax.get_xlim() == pytest.approx((0.02, 1000.0))
    loss_band = loss_ax.collections[0].get_paths()[0].vertices[:, 1]
    assert max(loss_band) == pytest.approx(max(1 - p.epsilon_range[0] for p in points))
    # An elastic sphere's band is thin on epsilon's axis, not on its loss's (log) axis.
    widths = np.array([p.epsilon_range[1] - p.epsilon_range[0] for p in points])
    losses = np.array([1 - p.epsilon for p in points])
    bottom, top = ax.get_ylim()
    assert np.median(widths) < 0.01 * (top - bottom)
    assert np.median(widths / losses) > 0.1


def test_plot_on_a_given_axes_draws_epsilon_only(laws):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    try:
        assert laws["shipped"].plot(ax=ax, speeds_m_s=[1.0, 10.0]) is ax
        assert fig.axes == [ax] and ax.get_xlabel().startswith("impact speed")
    finally:
        plt.close(fig)


# -- the notebook example of docs/materials.md ---------------------------------------------


def _notebook_blocks() -> list[str]:
    text = (ROOT / "docs" / "materials.md").read_text()
    start = text.index("\n## From a notebook")
    section = text[start : text.index("\n## ", start + 1)]
    return re.findall(r"```python\n(.*?)```", section, re.S)


@pytest.mark.slow  # 11-15 s (pandas, a 10^6-point evaluation and a figure)
def test_the_notebook_example_runs_as_it_stands(tmp_path, monkeypatch):
    pytest.importorskip("pandas")
    blocks = _notebook_blocks()
    assert blocks
    monkeypatch.chdir(tmp_path)
    ns: dict = {}
    for block in blocks:
        exec(compile(block, "docs/materials.md", "exec"), ns)  # noqa: S102
    assert ns["eps"].shape == (10**6,) and np.isfinite(ns["eps"]).all()
    assert_allclose(ns["eps"][[0, -1]], ns["glass"].epsilon([0.02, 10.0]), rtol=0)
    assert len(ns["frame"]) == views.DEFAULT_POINTS and ns["frame"].attrs["notes"]
    assert (tmp_path / "glass.csv").exists() and (tmp_path / "damped.png").exists()
    assert "viscous" in ns["ax"].get_title()
