"""The sphere through the layers above the collision: the mode cache, the store keys, the walls
of the extrapolation, the work estimate, and ``restitution epsilon/modes/collide --geometry
sphere``."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad

from restitution.bodies.cache import check_mode_request, get_modes
from restitution.bodies.kinds import body_kind
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.bodies.sphere.surface import depth_transform, max_compression_estimate
from restitution.cli import main
from restitution.dynamics.collision import CollisionSettings, estimate_work
from restitution.errors import InputError
from restitution.limits.curves import epsilon_at
from restitution.limits.defaults import walls_at
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import DEFAULTS, SweepSettings, defaults_for


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path))
    return tmp_path


def test_the_mode_cache_serves_spheres_and_disks_apart(cache):
    sphere = get_modes(0.3, count=60, geometry="sphere")
    again = get_modes(0.3, count=60, geometry="sphere")  # from the file
    direct = compute_sphere_modes(0.3, count=60)
    for field in ("l", "n", "omega", "A", "B", "C", "S"):
        np.testing.assert_array_equal(getattr(again, field), getattr(direct, field))
    assert again.geometry == "sphere" and len(list(cache.glob("modes-*.npz"))) == 1
    disk = get_modes(0.3, count=60)
    assert disk.geometry == "disk" and len(list(cache.glob("modes-*.npz"))) == 2
    assert not np.array_equal(disk.omega, sphere.omega)


def test_the_sphere_refuses_what_it_cannot_do(cache):
    with pytest.raises(InputError, match=r"\(-1, 0.5\)"):
        get_modes(0.6, count=10, geometry="sphere")  # a valid disk nu, not a sphere's
    with pytest.raises(InputError, match="not feasible"):
        check_mode_request(0.3, body_kind("sphere").max_modes + 1, geometry="sphere")
    with pytest.raises(InputError, match="Weyl"):
        check_mode_request(0.3, None, 1e4, geometry="sphere")
    with pytest.raises(InputError, match="unknown geometry 'cube'"):
        get_modes(0.3, count=10, geometry="cube")


def test_weyl_estimate_inverts():
    kind = body_kind("sphere")
    omega = kind.omega_for(5000, 0.3)
    assert kind.weyl_count(omega, 0.3) == pytest.approx(5000, rel=1e-12)


def test_the_store_keys_the_body():
    disk = PointSpec(0.3, 0.1, 500.0, 40)
    sphere = PointSpec(0.3, 0.1, 500.0, 40, geometry="sphere")
    assert disk.key() != sphere.key()
    assert sphere.inputs()["code_version"] != disk.inputs()["code_version"]
    with pytest.raises(InputError, match="unknown geometry"):
        PointSpec(0.3, 0.1, 500.0, 40, geometry="cube")


def test_a_stored_sphere_point_reads_back_as_a_sphere(tmp_path):
    spec = PointSpec(0.3, 0.1, 500.0, 40, geometry="sphere")
    with Store(tmp_path / "r.sqlite") as db:
        db.put(spec, {"epsilon": 0.99, "energy_drift": 1e-7})
        assert db.get(spec).spec == spec
        assert [p.spec for p in db.points(geometry="sphere")] == [spec]
        assert db.points() == []  # the disk's code version holds no row


def test_sphere_walls_follow_the_hertz_compression():
    # The closed form of max_compression_estimate, written out: (15 m v^2 / (16 E*))^(2/5).
    v, nu = 0.02, 0.25
    delta = (15 * (4 * math.pi / 3) * v**2 * (1 - nu**2) / 16) ** 0.4
    assert max_compression_estimate(v, nu) == pytest.approx(delta, rel=1e-14)
    assert walls_at(v, (40.0, 80.0), "compression", geometry="sphere", nu=nu) == pytest.approx(
        (40 / delta, 80 / delta), rel=1e-14
    )
    with pytest.raises(InputError, match="need its nu"):
        walls_at(v, (40.0,), "compression", geometry="sphere")
    settings = SweepSettings(velocities=(v,), geometry="sphere")
    assert settings.alphas_at(v, nu=nu) == walls_at(
        v, settings.alphas, "compression", geometry="sphere", nu=nu
    )


@pytest.mark.parametrize("alpha", [0.5, 3.0, 40.0, 900.0])
def test_the_sphere_depth_transform_against_quadrature(alpha):
    # 2 pi int_0^{pi/2} exp(alpha (cos t - 1)) sin t dt, by scipy's adaptive quadrature.
    ref, _ = quad(
        lambda t: 2 * math.pi * math.exp(alpha * (math.cos(t) - 1)) * math.sin(t),
        0,
        math.pi / 2,
        epsabs=0,
        epsrel=1e-12,
        points=[min(1.0, 5 / math.sqrt(alpha))],
    )
    assert float(depth_transform(alpha)) == pytest.approx(ref, rel=1e-10)


def test_the_work_estimate_of_a_sphere_brackets_the_run():
    from restitution import collide

    modes = compute_sphere_modes(0.3, count=200)
    settings = CollisionSettings()
    est = estimate_work(modes, np.array([0.05]), np.array([600.0]), settings)
    run = collide(modes, v=0.05, alpha=600.0)
    # The estimate (first step, Hertz contact time, flight from the start position) is within
    # a factor 3 of the steps the run took, either way.
    assert run.n_steps / 3 < est.steps < 3 * run.n_steps


def test_sphere_defaults_differ_in_the_body_the_walls_and_the_mode_counts():
    sphere = defaults_for("sphere")
    assert sphere.geometry == "sphere"
    disk = defaults_for("disk")
    assert disk == DEFAULTS
    assert sphere.velocities == disk.velocities
    assert sphere.alphas == body_kind("sphere").alpha_products == (80.0, 160.0, 320.0)
    assert sphere.n_modes == (1600, 3200, 6400, 12800)


@pytest.mark.slow  # 5 s of the default run (stop 79: the default run under 10 min)
def test_epsilon_at_extrapolates_a_sphere(tmp_path):
    settings = SweepSettings(velocities=(0.1,), n_modes=(100, 200, 400), geometry="sphere")
    r = epsilon_at(0.3, 0.1, settings=settings, store=tmp_path / "s.sqlite", progress=False)
    d = r.to_dict()
    assert d["geometry"] == "sphere" and "sphere" in d["v_units"]
    assert 0.98 < r.epsilon < 1.0 and math.isfinite(r.epsilon_err)
    # The grid's walls are the sphere's (Hertz compression at nu = 0.3).
    assert d["grid"]["alpha"] == pytest.approx(
        [a / max_compression_estimate(0.1, 0.3) for a in settings.alphas]
    )


def _run(capsys, *args) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of ``restitution ARGS`` (the console entry point)."""
    try:
        main(list(args))
        code = 0
    except SystemExit as exc:
        code = exc.code or 0
    out = capsys.readouterr()
    return code, out.out, out.err


def _json(capsys, *args):
    code, out, err = _run(capsys, *args)
    assert code == 0, err
    return json.loads(out)


def test_cli_modes_of_a_sphere(cache, capsys):
    args = ("--geometry", "sphere", "--nu", "0.25", "--count", "30", "--format", "json")
    d = _json(capsys, "modes", *args)
    assert d["inputs"]["geometry"] == "sphere" and "sphere" in d["units"]["system"]
    assert len(d["modes"]) == 30 and {"l", "omega", "C", "S"} <= set(d["modes"][0])
    # Lamb's gravest mode: l = 2 at omega R / c_T = 0.842 pi (nu = 1/4, c_T = sqrt(0.4)).
    assert d["modes"][0]["l"] == 2
    assert d["modes"][0]["omega"] / math.sqrt(0.4) == pytest.approx(0.842 * math.pi, rel=3e-3)


def test_cli_collide_with_a_sphere_has_the_disk_keys(cache, capsys):
    args = ("--nu", "0.3", "--v", "0.05", "--alpha", "500", "--modes", "60", "--json")
    sphere = _json(capsys, "collide", "--geometry", "sphere", *args)
    disk = _json(capsys, "collide", *args)
    assert set(sphere) == set(disk)
    assert sphere["units"]["energy"].endswith("m = 4 pi / 3")
    assert 0.99 < sphere["epsilon"] < 1.0


@pytest.mark.slow  # 8-18 s of the default run (issue 45: the default run under 10 min)
def test_cli_collide_a_sphere_by_finite_elements(cache, capsys):
    args = ("--nu", "0.3", "--v", "0.1", "--alpha", "300", "--json")
    fem = _json(capsys, "collide", "--geometry", "sphere", "--method", "fem", *args)
    modal = _json(capsys, "collide", "--geometry", "sphere", "--modes", "400", *args)
    assert fem["inputs"]["geometry"] == "sphere" and fem["inputs"]["method"] == "fem"
    assert "sphere" in fem["units"]["system"]
    # The coarse mesh against 400 modes: the modal loss converges from above like 1/sqrt(N)
    # (docs/spheres.md: 0.0149 at N = 400, 0.0137 extrapolated; the FEM's 0.0137).
    assert fem["energy_loss"] < modal["energy_loss"] < 1.15 * fem["energy_loss"]


@pytest.mark.parametrize(
    "args, message",
    [
        (("modes", "--nu", "0.3", "--plane", "strain"), "--plane applies to disks only"),
        (("modes", "--nu", "0.3", "--plot-shapes", "x.png"), "--plot-shapes"),
        (("collide", "--nu", "0.3", "--v", "0.1", "--excite", "thermal"), "disks only"),
    ],
)
def test_cli_refuses_disk_only_options_for_a_sphere(cache, capsys, args, message):
    code, out, err = _run(capsys, args[0], "--geometry", "sphere", *args[1:])
    assert code == 2 and out == ""
    assert err.startswith("error: ") and message in err and err.count("\n") == 1


@pytest.mark.slow  # 4 s of the default run (stop 79: the default run under 10 min)
def test_the_convergence_figure_measures_what_it_draws(tmp_path):
    from restitution.limits.order import local_exponents, power_law_fit
    from restitution.reproduction.figures import sphere_convergence

    ladder = (100, 150, 200, 300, 400, 600, 800)
    series = sphere_convergence.compute(
        0.3, (0.1,), (80.0,), ladder, store=tmp_path / "s.sqlite", progress=False, fit_from=100
    )
    (s,) = series
    assert s.alpha == pytest.approx(80 / max_compression_estimate(0.1, 0.3))
    assert np.all(np.isfinite(s.loss)) and np.all((s.loss > 0) & (s.loss < 0.05))
    # The drawn exponents and fit are those of the stored losses.
    mid, p = local_exponents(ladder, s.loss)
    np.testing.assert_array_equal(s.n_mid, mid)
    np.testing.assert_array_equal(s.exponent, p)
    assert s.fit == power_law_fit(ladder, s.loss)
    path = tmp_path / "conv.png"
    sphere_convergence.plot(series, 0.3, path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
