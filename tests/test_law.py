"""The epsilon(v) law, its exports, the epsilon/curve commands and Figs. 1, 7, 8.

Synthetic points test the interpolant and the exports; a stand-in solver with a known limit
tests the path store -> extrapolation -> law; a coarse real grid (10-20 modes, soft walls)
runs the figure modules and the commands end to end.
"""

import csv
import json
import math

import click
import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

from restitution import get_modes
from restitution.cli.epsilon import curve as curve_command
from restitution.cli.epsilon import epsilon as epsilon_command
from restitution.dynamics.collision import collide
from restitution.errors import InputError, RestitutionError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.making.build import law_from_store
from restitution.limits.curves import compute_curves, epsilon_at
from restitution.limits.sweep import SweepSettings
from restitution.reproduction.figures import fig01_epsilon, fig07_alpha, fig08_modes

V = np.array([0.01, 0.05, 0.1, 0.2, 0.3])
EPS = np.array([0.999, 0.99, 0.96, 0.88, 0.8])
ERR = np.array([1e-4, 5e-4, 1e-3, 2e-3, 4e-3])


@pytest.fixture
def synthetic():
    return EpsilonLaw.from_points(0.33, V, EPS, ERR, parameters={"source": "synthetic"})


def test_interpolant_passes_through_the_points_only(synthetic):
    assert_allclose(synthetic.epsilon(V), EPS, rtol=1e-14)
    assert_allclose(synthetic.epsilon_err(V), ERR, rtol=1e-14)
    assert isinstance(synthetic.epsilon(0.1), float)
    assert synthetic(np.full((2, 3), 0.1)).shape == (2, 3)
    # PCHIP keeps monotone data monotone.
    fine = synthetic.epsilon(np.linspace(0.01, 0.3, 1001))
    assert np.all(np.diff(fine) <= 0) and synthetic.monotone
    # The computed range, nothing more: no anchor at v = 0.
    assert synthetic.valid_range == (0.01, 0.3)


def test_outside_the_computed_range_is_never_a_number(synthetic):
    for v in (0.0, 0.005, 0.31, -0.01):
        with pytest.raises(InputError, match=r"outside the computed range 0.01 <= v <= 0.3"):
            synthetic.epsilon(v)
    with pytest.raises(InputError):
        synthetic.epsilon([0.005, 0.1])
    # "warn" warns and gives nan, never an extrapolated number (it used to return 236 at v = 5).
    with pytest.warns(UserWarning, match="returning nan"):
        assert math.isnan(synthetic.epsilon(5.0, outside="warn"))
    out = synthetic.epsilon([0.1, 0.4, 0.001], outside="nan")
    assert out[0] == pytest.approx(0.96) and np.isnan(out[1:]).all()
    assert np.isnan(synthetic.epsilon_err([0.4], outside="nan")).all()


def test_points_status_and_repr():
    law_ = EpsilonLaw.from_points(0.33, V, EPS, ERR, asymptotic_ok=[True, False, True, True, True])
    assert [p.status for p in law_.points] == ["ok", "not-asymptotic", "ok", "ok", "ok"]
    assert law_.points[2].v == 0.1 and law_.points[2].epsilon == 0.96
    text = repr(law_)
    assert "\n" not in text and "5 points" in text and "4 pass their checks" in text
    # Between a flagged point and its neighbours the interpolant is not "checked".
    assert law_.checked([0.02, 0.07, 0.15]).tolist() == [False, False, True]


def test_law_file_of_another_nu_is_refused(synthetic, tmp_path):
    path = synthetic.to_json(tmp_path / "law.json")  # nu = 0.33
    assert law(0.33, path=path).nu == 0.33 and law(path=path).nu == 0.33
    with pytest.raises(InputError) as info:
        law(0.9, path=path)
    message = str(info.value)
    assert "\n" not in message and "nu = 0.33" in message and "nu = 0.9" in message
    assert "restitution curve --nu 0.9" in message


def test_exports_round_trip(synthetic, tmp_path):
    back = EpsilonLaw.from_json(synthetic.to_json(tmp_path / "law.json"))
    grid = np.linspace(0.01, 0.3, 57)
    assert_allclose(back.epsilon(grid), synthetic.epsilon(grid), rtol=1e-15)
    meta = json.loads((tmp_path / "law.json").read_text())["metadata"]
    for key in ("model", "units", "parameters", "version", "date", "validity"):
        assert key in meta
    assert meta["parameters"]["source"] == "synthetic" and meta["parameters"]["nu"] == 0.33
    assert meta["validity"]["v_min"] == 0.01 and meta["validity"]["v_max"] == 0.3

    with open(synthetic.to_csv(tmp_path / "law.csv"), newline="") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    assert_allclose([float(r["epsilon"]) for r in rows], EPS, rtol=1e-15)
    assert_allclose([float(r["v"]) for r in rows], V, rtol=1e-15)
    assert {r["status"] for r in rows} == {"ok"}

    table = np.loadtxt(synthetic.to_table(tmp_path / "law.txt", points=61))
    assert table.shape[1] == 4 and 61 <= table.shape[0] <= 61 + V.size
    assert table[0, 0] == pytest.approx(0.01) and table[-1, 0] == pytest.approx(0.3)
    assert_allclose(table[:, 1], synthetic.epsilon(table[:, 0]), atol=1e-8)  # 8 decimals
    assert set(table[:, 3]) == {1.0}
    header = (tmp_path / "law.txt").read_text().splitlines()[0]
    assert header.startswith("# restitution law")


def test_law_without_data_says_how_to_compute_it():
    with pytest.raises(InputError, match="restitution curve --nu 0.123"):
        law(0.123)
    with pytest.raises(RestitutionError, match="not a restitution law"):
        EpsilonLaw._from_dict({"format": "something"}, "x.json")


# -- stand-in solver with a known answer -----------------------------------------------------


def known_limit(v):
    return 0.2 * v / (0.1 + v)  # energy loss at alpha, N -> infinity; increasing in v


def fake_batch(specs):
    """Energy loss with corrections in 1/alpha, 1/sqrt(N) and a cross term: exact limits."""
    out = []
    for s in specs:
        a, r = 1.0 / s.alpha, 1.0 / math.sqrt(s.n_modes)
        loss = known_limit(s.v) + 3.0 * a - 0.2 * r + 4.0 * a * r
        out.append(("ok", {"epsilon": math.sqrt(1.0 - loss), "energy_drift": 1e-9}))
    return out


@pytest.mark.parametrize("scale", ["absolute", "compression"])
def test_law_from_store_recovers_the_known_limit(tmp_path, client, scale):
    settings = SweepSettings(
        velocities=(0.02, 0.1, 0.3), alphas=(100.0, 200.0, 400.0), alpha_scale=scale
    )
    path = tmp_path / "fake.sqlite"
    curves = compute_curves([0.5], settings, store=path, client=client, batch_function=fake_batch)
    expected = np.sqrt(1.0 - known_limit(np.array(settings.velocities)))
    assert_allclose(curves[0.5].epsilon, expected, rtol=1e-12)
    assert all(c.asymptotic_ok for c in curves[0.5].limits)
    loaded = law_from_store(0.5, path, settings=settings)  # reads only
    assert_allclose(loaded.epsilon(0.1), expected[1], rtol=1e-12)
    assert loaded.metadata["parameters"]["alphas"] == [100.0, 200.0, 400.0]
    assert loaded.metadata["parameters"]["alpha_scale"] == scale
    alpha = settings.alphas_at(0.1)[1]  # 200, or 200 / delta_max(0.1)
    single = epsilon_at(0.5, 0.1, alpha=alpha, settings=settings, store=path, run=False)
    # Only N -> infinity at this alpha: the 1/alpha term stays.
    assert_allclose(single.energy_loss, known_limit(0.1) + 3.0 / alpha, rtol=1e-12)


def test_missing_points_are_flagged(tmp_path):
    settings = SweepSettings(
        velocities=(0.1,), alphas=(100.0, 200.0, 400.0), alpha_scale="absolute"
    )
    curves = compute_curves([0.5], settings, store=tmp_path / "empty.sqlite", run=False)
    limit = curves[0.5].limits[0]
    assert not limit.asymptotic_ok and "missing" in limit.message
    with pytest.raises(RestitutionError, match="fewer than two speeds"):
        EpsilonLaw.from_curve(curves[0.5])


# -- the real solver on a coarse grid --------------------------------------------------------

COARSE = SweepSettings(
    velocities=(0.1, 0.2),
    alphas=(20.0, 30.0, 40.0),
    alpha_scale="absolute",
    n_modes=(10, 14, 20),
    batch_size=3,
)


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    path = tmp_path_factory.mktemp("coarse") / "coarse.sqlite"
    curves = compute_curves([0.33], COARSE, store=path, progress=False)
    return path, curves


def test_figures_on_a_coarse_grid(coarse, tmp_path):
    path, curves = coarse
    f1 = fig01_epsilon.compute((0.33,), COARSE, curves=curves)
    f7 = fig07_alpha.compute(0.33, COARSE, curve=curves[0.33])
    f8 = fig08_modes.compute(0.33, COARSE, curve=curves[0.33])
    # Fig. 7's point (v = 0.2, alpha = 40, N = 20) against one independent in-process collision
    # (not batched, not stored, default solver settings): the two runs differ only in their
    # steps, each with an energy drift below the sweep's energy_tol = 1e-5 of E0, so their
    # losses agree to a few times that.
    direct = collide(get_modes(0.33, count=20), 0.2, 40.0)
    assert f7.n_modes == 20
    assert_allclose(f7.loss[1, 2], 1.0 - direct.epsilon**2, atol=5e-5)
    # Fig. 8 at the largest alpha shows the same point.
    assert np.all(f8.alpha == 40.0) and f8.loss[1, 2] == f7.loss[1, 2]
    # Fig. 1: inelastic, more so at the higher speed (paper, section 4).
    eps = f1.epsilon[0]
    assert np.all((eps > 0.5) & (eps < 1.0)) and eps[1] < eps[0]
    for module, data in ((fig01_epsilon, f1), (fig07_alpha, f7), (fig08_modes, f8)):
        out = module.plot(data, tmp_path / f"{module.__name__.rsplit('.', 1)[1]}.png")
        assert out.stat().st_size > 1000


def _run(command, args):
    group = click.Group()
    group.add_command(command)
    return CliRunner().invoke(group, [command.name, *args])


def _grid_args(path):
    return [
        "--alphas", "20", "30", "40", "--alpha-scale", "absolute",
        "--modes", "10", "14", "20", "--store", str(path),
    ]  # fmt: skip


def test_epsilon_command_json(coarse):
    path, curves = coarse
    result = _run(epsilon_command, ["--nu", "0.33", "--v", "0.2", "--json", *_grid_args(path)])
    assert result.exit_code == 0, result.output
    d = json.loads(result.output)
    assert d["epsilon"] == pytest.approx(curves[0.33].limits[1].epsilon, rel=1e-12)
    assert d["grid"]["alpha"] == [20.0, 30.0, 40.0] and d["grid"]["n_modes"] == [10, 14, 20]
    assert {"epsilon_err", "fits", "asymptotic_ok", "message"} <= d.keys()
    # --alpha takes the place of --alphas / --alpha-scale (giving both is refused).
    one_wall = ["--alpha", "40", "--modes", "10", "14", "20", "--store", str(path)]
    at = _run(epsilon_command, ["--nu", "0.33", "--v", "0.2", *one_wall])
    assert at.exit_code == 0 and "at alpha = 40" in at.output


def test_curve_command_writes_figures_and_exports(coarse, tmp_path):
    path, curves = coarse
    out = tmp_path / "out"
    args = ["--nu", "0.33", "--v", "0.1", "0.2", "--out", str(out), *_grid_args(path)]
    result = _run(curve_command, args)
    assert result.exit_code == 0, result.output
    for name in ("fig01_epsilon.png", "fig07_alpha_nu0.33.png", "fig08_modes_nu0.33.png"):
        assert (out / name).stat().st_size > 1000
    loaded = law(path=out / "law_nu0.33.json")
    assert_allclose(loaded.epsilon(0.2), curves[0.33].limits[1].epsilon, rtol=1e-12)
    assert np.loadtxt(out / "law_nu0.33.txt").shape[1] == 4  # v, epsilon, error, checked


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (["--nu", "0.33", "--v", "1.5"], "units of c"),
        (["--nu", "3", "--v", "0.1"], "nu"),
        (["--nu", "0.33", "--v", "0.1", "--alpha", "-5"], "alpha"),
    ],
)
def test_epsilon_command_bad_input(args, match, tmp_path):
    result = _run(epsilon_command, [*args, "--store", str(tmp_path / "s.sqlite")])
    assert isinstance(result.exception, InputError)
    assert match in str(result.exception)
