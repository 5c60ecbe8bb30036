"""Laws of the sphere, end to end: file names and metadata, the refusal of the other body's
laws, provenance, the SI edge (``c = sqrt(E/rho)`` with the 3D constants, ``v = w / (k c)``),
``restitution law --geometry sphere``, ``restitution curve --geometry sphere`` and the exports.

A small real law (three speeds, N = 100, 200, 400, the walls alpha delta_max = 40, 80, 160) is
computed once into a temporary store; its numbers are not converged and are never compared with
stored values, only with the same law read back through another route. Synthetic laws (a closed
form in v) test what needs many points (the closed-form fit) or several Poisson numbers.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from importlib import resources
from types import SimpleNamespace

import numpy as np
import pytest
from _sampling import representatives
from numpy.testing import assert_allclose
from scipy.interpolate import PchipInterpolator

from restitution.bodies.kinds import body_kind
from restitution.cli import main
from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.law_load import law
from restitution.laws.law_nu import NuInterpolatedLaw, law_for, shipped_nus
from restitution.laws.making import production
from restitution.laws.making.build import law_from_store
from restitution.laws.si_law import SILaw, si_law
from restitution.laws.units import Grain
from restitution.limits.curves import compute_curves
from restitution.limits.extrapolation import combined_limit
from restitution.limits.sweep import defaults_for
from restitution.provenance import code_version

NU = 0.3
V = (0.05, 0.1, 0.2)
# The CLI builds its settings from defaults_for("sphere"); so do we, with every grid value
# given, so that both read the same points of the store.
SETTINGS = replace(
    defaults_for("sphere"),
    velocities=V,
    alphas=(40.0, 80.0, 160.0),
    alpha_scale="compression",
    n_modes=(100, 200, 400),
    batch_size=3,
)
GRID_ARGS = [
    "--v", *map(str, V), "--alphas", "40", "80", "160", "--alpha-scale", "compression",
    "--modes", "100", "200", "400",
]  # fmt: skip

# Steel: E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3.
E, RHO = 210e9, 7850.0
STEEL = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "sphere"]
C_STEEL = math.sqrt(E / RHO)  # the sphere's velocity unit, written out: sqrt(E/rho), 3D E


@pytest.fixture(autouse=True)
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))


@pytest.fixture(scope="module")
def computed(tmp_path_factory):
    """The small real sphere law at nu = 0.3, its store and its file."""
    root = tmp_path_factory.mktemp("sphere_law")
    store = root / "store.sqlite"
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("RESTITUTION_CACHE_DIR", str(root / "cache"))
        curve = compute_curves([NU], SETTINGS, store=store, progress=False)[NU]
    law_ = EpsilonLaw.from_curve(curve)
    path = law_.to_json(root / law_filename(NU, "sphere"))
    return SimpleNamespace(root=root, store=store, curve=curve, law=law_, path=path)


def closed(v, a=0.6, b=1.5, p=0.85):
    """A smooth synthetic epsilon(v), decreasing, with epsilon(0) = 1."""
    return 1 - a * v**p / (1 + b * v**p)


VV = np.linspace(0.005, 0.3, 40)


def synthetic(nu=NU, geometry="sphere", scale=1.0):
    eps = 1 - scale * (1 - closed(VV))
    return EpsilonLaw.from_points(nu, VV, eps, np.full(VV.size, 1e-5), geometry=geometry)


def run_cli(capsys, *args):
    """Exit code, stdout and stderr of ``restitution ARGS``."""
    try:
        main([str(a) for a in args])
        code = 0
    except SystemExit as exc:
        code = exc.code or 0
    out = capsys.readouterr()
    return code, out.out, out.err


# -- files, metadata, provenance --------------------------------------------------------------


def test_file_names_carry_the_body():
    assert law_filename(0.33) == "law_nu0.33.json"  # the disk's names are unchanged
    assert law_filename(0.33, "disk") == "law_nu0.33.json"
    assert law_filename(0.3, "sphere") == "law_sphere_nu0.3.json"
    with pytest.raises(InputError, match="unknown geometry 'cube'"):
        law_filename(0.3, "cube")
    # The disk's shipped grid does not pick up sphere files, nor the sphere's disk files.
    assert 0.33 in shipped_nus() and 0.33 not in shipped_nus("sphere")
    names = {p.name for p in resources.files("restitution.laws").joinpath("data").iterdir()}
    assert {law_filename(nu, "sphere") for nu in shipped_nus("sphere")} <= names


def test_a_sphere_law_names_its_body_and_round_trips(computed):
    law_ = computed.law
    assert law_.geometry == "sphere" and law_.nu == NU
    assert_allclose(law_.v, V, rtol=1e-15)
    assert "EpsilonLaw(sphere, nu=0.3" in repr(law_)
    meta = json.loads(computed.path.read_text())["metadata"]
    assert meta["geometry"] == "sphere"
    assert meta["model"].startswith("Elastic sphere (3D linear elasticity")
    assert "sphere's speed towards the wall" in meta["units"]
    assert all(p["settings"]["geometry"] == "sphere" for p in meta["points"])
    back = law(NU, geometry="sphere", path=computed.path)
    assert back.geometry == "sphere"
    assert_allclose(back.epsilon_points, law_.epsilon_points, rtol=1e-15)
    assert_allclose(back.epsilon(0.15), law_.epsilon(0.15), rtol=1e-15)
    # The plain table and the CSV say which body.
    header = law_.to_table(computed.root / "t.txt").read_text().splitlines()[:4]
    assert header[0] == "# restitution law epsilon(v) of the sphere, nu = 0.3"
    assert "# body: sphere" in header
    # Every point's extrapolation, redone from the grid stored in the file, is the point.
    for p in meta["points"]:
        ex = p["extrapolation"]
        redo = combined_limit(ex["alpha"], ex["n_modes"], np.array(ex["energy_loss_grid"]))
        assert redo.epsilon == pytest.approx(p["epsilon"], rel=0, abs=1e-12)


def test_the_law_records_the_sphere_solver(computed):
    assert computed.law.metadata["code_version"] == code_version("sphere")
    assert code_version("sphere") != code_version("disk")
    disk = EpsilonLaw.from_points(0.33, VV, closed(VV), np.full(VV.size, 1e-5))
    assert disk.geometry == "disk" and disk.metadata["code_version"] == code_version("disk")


def test_law_from_store_builds_the_same_sphere_law(computed):
    again = law_from_store(NU, computed.store, settings=SETTINGS)
    assert again.geometry == "sphere"
    assert_allclose(again.epsilon_points, computed.law.epsilon_points, rtol=1e-15)


def test_files_without_a_body_are_disks(tmp_path):
    """Law files written before the sphere carry no ``geometry``: they are disks."""
    path = synthetic(0.33, "disk").to_json(tmp_path / "old.json")
    d = json.loads(path.read_text())
    del d["metadata"]["geometry"], d["digest"]  # nor a digest, which came later still
    path.write_text(json.dumps(d))
    old = law(0.33, path=path)
    assert old.geometry == "disk"
    with pytest.raises(InputError, match="holds a law of the disk, not of the sphere"):
        law(0.33, geometry="sphere", path=path)
    # The shipped files load as disks, under both keywords of the disk's Poisson number.
    assert law(0.33).geometry == "disk" and law(nu_2d=0.33).nu == 0.33
    with pytest.raises(InputError, match="nu_2d is the disk's"):
        law(nu_2d=0.3, geometry="sphere")
    with pytest.raises(InputError, match="give the Poisson number once"):
        law(0.33, nu_2d=0.33)


def test_a_law_of_the_other_body_is_refused(computed, tmp_path, capsys):
    disk_file = synthetic(NU, "disk").to_json(tmp_path / "law_nu0.3.json")
    refusals = [
        lambda: law(NU, path=computed.path),  # the default body is the disk
        lambda: law(NU, geometry="sphere", path=disk_file),
        lambda: law_for(NU, path=computed.path),
        lambda: law_for(NU, geometry="sphere", path=disk_file),
        lambda: si_law(E, NU, RHO, "thin-disk", "wall", path=computed.path),
        lambda: si_law(E, NU, RHO, "sphere", "wall", path=disk_file),
        lambda: SILaw(Grain(E, NU, RHO, "sphere"), "wall", synthetic(NU, "disk")),
    ]
    for refuse in refusals:
        with pytest.raises(InputError, match=r"law of the (disk|sphere)") as info:
            refuse()
        assert "\n" not in str(info.value)
    with pytest.raises(InputError, match="holds a law of the sphere, not of the disk") as info:
        law(NU, path=computed.path)
    assert "geometry='sphere'" in str(info.value)
    # Grids of laws: one body only.
    mixed = [synthetic(0.2), synthetic(0.3, "disk"), synthetic(0.4)]
    with pytest.raises(InputError, match="laws of the disk"):
        law_for(0.25, geometry="sphere", laws=mixed)
    with pytest.raises(InputError, match="laws of one body"):
        NuInterpolatedLaw(0.25, tuple(mixed))
    # The command line: a cylinder with a sphere's file, in one line.
    args = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder"]
    code, out, err = run_cli(
        capsys, "law", *args, "--against", "wall", "--speed", "1000", "--law-file", computed.path
    )
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "holds a law of the sphere, not of the disk" in err


def test_a_sphere_law_is_refused_for_a_disk_nu_only_a_disk_has():
    with pytest.raises(InputError, match=r"\(-1, 0.5\)"):
        law(0.9, geometry="sphere")
    with pytest.raises(InputError, match=r"\(-1, 0.5\)"):
        EpsilonLaw.from_points(0.7, VV, closed(VV), np.full(VV.size, 1e-5), geometry="sphere")


# -- the SI edge ------------------------------------------------------------------------------


def test_grain_sphere_conversions():
    g = Grain(E=E, nu=NU, rho=RHO, geometry="sphere")
    assert g.body == "sphere" and g.law_nu == NU and g.law_nu_name == "nu" and g.plane is None
    assert_allclose(g.c_m_s, C_STEEL, rtol=1e-15)
    # A thin disk has the same c (plane stress keeps E); a long cylinder the plate speed.
    assert_allclose(Grain(E, NU, RHO, "thin-disk").c_m_s, C_STEEL, rtol=1e-15)
    assert_allclose(
        Grain(E, NU, RHO, "cylinder").c_m_s, math.sqrt(E / ((1 - NU**2) * RHO)), rtol=1e-15
    )
    w = np.array([0.0, 1.0, 250.0, 4000.0])
    assert_allclose(g.v_over_c(w, "wall"), w / C_STEEL, rtol=1e-15)
    assert_allclose(g.v_over_c(w, "grain"), w / (2 * C_STEEL), rtol=1e-15)
    assert_allclose(g.speed_m_s(g.v_over_c(w, "grain"), "grain"), w, rtol=1e-15)
    d = g.to_dict()
    assert d["body"] == "sphere" and d["law_nu"] == NU and d["c_m_s"] == g.c_m_s
    assert "sqrt(E / rho)" in d["c_formula"]
    assert not {"E_2d_Pa", "nu_2d", "plane"} & d.keys()  # a sphere has no 2D constants
    assert "sphere" in g.describe() and "nu_2d" not in g.describe()
    for attribute in ("nu_2d", "E_2d", "material"):
        with pytest.raises(InputError, match="a sphere has no"):
            getattr(g, attribute)
    # The disk's keys stay, with the law's parameter under the common name too.
    cyl = Grain(E, 0.25, RHO, "cylinder").to_dict()
    assert cyl["nu_2d"] == cyl["law_nu"] == pytest.approx(0.25 / 0.75, rel=1e-15)
    assert cyl["body"] == "disk" and "E_2d_Pa" in cyl


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(nu=0.5), r"\(-1, 0.5\)"),  # incompressible: no modes
        (dict(nu=-1.0), r"\(-1, 0.5\]"),
        (dict(E=-1.0), "positive"),
        (dict(rho=0.0), "density"),
    ],
)
def test_bad_spheres_are_refused(kwargs, match):
    with pytest.raises(InputError, match=match):
        Grain(**{"E": E, "nu": NU, "rho": RHO, "geometry": "sphere", **kwargs})


@pytest.mark.parametrize("against, k", [("wall", 1.0), ("grain", 2.0)])
def test_si_law_serves_the_sphere_law_at_w_over_k_c(computed, against, k):
    s = si_law(E=E, nu=NU, rho=RHO, geometry="sphere", against=against, path=computed.path)
    law_ = computed.law
    assert s.speed_scale_m_s == pytest.approx(k * C_STEEL, rel=1e-15)
    # At the computed speeds, w = k c v: the computed points themselves.
    for p, v, eps, ok in zip(
        s.points(k * C_STEEL * np.array(V)),
        law_.v,
        law_.epsilon_points,
        law_.asymptotic_ok,
        strict=True,
    ):
        assert p.v_over_c == pytest.approx(v, rel=1e-14)
        assert p.epsilon == pytest.approx(eps, rel=1e-14)
        assert p.status == ("computed" if ok else "computed-not-asymptotic")
    # Between them, the interpolant at w / (k c); outside, no number.
    inside, below, above = s.points([0.15 * k * C_STEEL, 0.01 * k * C_STEEL, 0.5 * k * C_STEEL])
    assert inside.epsilon == pytest.approx(law_.epsilon(0.15), rel=1e-14)
    assert inside.status.startswith("interpolated")
    assert below.status == above.status == "outside" and below.epsilon is None
    lo, hi = s.computed_range_m_s
    assert_allclose([lo, hi], [0.05 * k * C_STEEL, 0.2 * k * C_STEEL], rtol=1e-14)


def test_two_spheres_at_w_are_one_sphere_on_the_wall_at_half_w(computed):
    wall = si_law(E, NU, RHO, "sphere", "wall", path=computed.path)
    grain = si_law(E, NU, RHO, "sphere", "grain", path=computed.path)
    w = np.array([300.0, 500.0, 900.0])
    assert_allclose(grain.epsilon(2 * w), wall.epsilon(w), rtol=1e-14)
    assert_allclose(grain.epsilon_err(2 * w), wall.epsilon_err(w), rtol=1e-14)


def test_no_shipped_sphere_law_names_the_command(capsys):
    # An auxetic sphere (nu = -0.5) lies outside any grid the package ships.
    with pytest.raises(InputError) as info:
        si_law(E, -0.5, RHO, "sphere", "wall")
    message = str(info.value)
    assert "\n" not in message and message.startswith("no law for sphere nu = -0.5")
    assert "`restitution curve --geometry sphere --nu -0.5 --production --out DIR`" in message
    assert "DIR/law_sphere_nu-0.5.json" in message
    args = ["--E", "210e9", "--nu", "-0.5", "--rho", "7850", "--geometry", "sphere"]
    code, out, err = run_cli(capsys, "law", *args, "--against", "wall", "--speed", "1")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "restitution curve --geometry sphere --nu -0.5 --production --out DIR" in err
    with pytest.raises(InputError, match="give the sphere's Poisson number"):
        law(geometry="sphere")
    with pytest.raises(InputError, match=r"restitution curve --geometry sphere --nu -0\.5"):
        law(-0.5, geometry="sphere")


def test_sphere_laws_interpolate_in_nu():
    grid = [synthetic(nu, scale=1 + nu) for nu in (0.2, 0.3, 0.4)]
    served = law_for(0.25, geometry="sphere", laws=grid)
    assert isinstance(served, NuInterpolatedLaw) and served.geometry == "sphere"
    v = np.array([0.01, 0.1, 0.25])
    # PCHIP through the three laws' values at each speed, written out with scipy.
    nodes = np.array([g.epsilon(v) for g in grid])
    expected = PchipInterpolator([0.2, 0.3, 0.4], nodes, axis=0)(0.25)
    assert_allclose(served.epsilon(v), expected, rtol=1e-14)
    s = SILaw(Grain(E, 0.25, RHO, "sphere"), "grain", served)
    assert_allclose(s.epsilon(2 * C_STEEL * v), expected, rtol=1e-14)
    assert law_for(0.3, geometry="sphere", laws=grid) is grid[1]


# -- the command line -------------------------------------------------------------------------


def test_cli_law_sphere_json(computed, capsys):
    reduced = [0.05, 700.0 / C_STEEL, 0.2]  # the lowest and highest computed speeds, and one
    speeds = [v * C_STEEL for v in reduced]  # between: wall speeds w = c v
    for against, k in (("wall", 1.0), ("grain", 2.0)):
        code, out, err = run_cli(
            capsys, "law", *STEEL, "--against", against, "--speed", *(k * w for w in speeds),
            "--json", "--law-file", computed.path,
        )  # fmt: skip
        assert code == 0, err
        d = json.loads(out)
        assert d["geometry"] == d["body"] == d["law"]["geometry"] == "sphere"
        assert d["law_nu"] == d["law"]["nu"] == NU
        assert "nu_2d" not in out and "E_2d" not in out  # no 2D constants for a sphere
        assert d["c_m_s"] == pytest.approx(C_STEEL, rel=1e-15)
        for p, w, v in zip(d["points"], speeds, reduced, strict=True):
            assert p["speed_m_s"] == pytest.approx(k * w, rel=1e-15)
            assert p["v_over_c"] == pytest.approx(v, rel=1e-14)
            assert p["epsilon"] == pytest.approx(computed.law.epsilon(v), rel=1e-12)
            assert p["epsilon_err"] == pytest.approx(computed.law.epsilon_err(v), rel=1e-12)
            assert p["status"] in d["statuses"] and p["status"] != "outside"
    code, out, err = run_cli(
        capsys, "law", *STEEL, "--against", "wall", "--speed", 700, "--law-file", computed.path
    )
    assert code == 0 and "sphere (3D constants as they are)" in out
    assert "sphere law nu = 0.3" in out


def test_cli_curve_writes_the_sphere_law(computed, tmp_path, capsys):
    out_dir = tmp_path / "out"
    code, out, err = run_cli(
        capsys, "curve", "--geometry", "sphere", "--nu", NU, *GRID_ARGS,
        "--store", computed.store, "--out", out_dir, "--no-progress",
    )  # fmt: skip
    assert code == 0, err  # every point was in the store: read, not computed
    assert "sphere, nu = 0.3:" in out
    names = {p.name for p in out_dir.iterdir()}
    assert {f"law_sphere_nu0.3.{ext}" for ext in ("json", "csv", "txt")} <= names
    assert {
        "fig01_epsilon_sphere.png",
        "fig07_alpha_sphere_nu0.3.png",
        "fig08_modes_sphere_nu0.3.png",
    } <= names
    assert not any(n.startswith("law_nu") for n in names)
    written = law(NU, geometry="sphere", path=out_dir / "law_sphere_nu0.3.json")
    assert_allclose(written.epsilon_points, computed.law.epsilon_points, rtol=1e-15)
    assert_allclose(written.epsilon_err_points, computed.law.epsilon_err_points, rtol=1e-15)


@pytest.mark.parametrize(
    "args, message",
    [
        (["--geometry", "sphere"], "give the sphere's Poisson number(s) with --nu"),
        (["--geometry", "sphere", "--nu", "0.6"], "(-1, 0.5)"),
    ],
)
def test_cli_curve_refuses_for_a_sphere(capsys, tmp_path, args, message):
    code, out, err = run_cli(capsys, "curve", *args, "--out", tmp_path / "o")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert message in err


# -- exports ------------------------------------------------------------------------------------


@pytest.mark.parametrize("against", ["wall", "grain"])
def test_exports_name_the_sphere(tmp_path, against):
    s = SILaw(Grain(E, NU, RHO, "sphere"), against, synthetic())
    k = 1.0 if against == "wall" else 2.0
    f = exports.fit_closed_form(s)
    assert_allclose(f.params, (0.6, 1.5, 0.85), rtol=1e-5)  # the synthetic law's own form
    assert f.speed_scale_m_s == pytest.approx(k * C_STEEL, rel=1e-15)
    v0 = VV[13]  # a computed speed of the synthetic law
    c = exports.constant_at(s, v0 * k * C_STEEL)
    assert c.epsilon == pytest.approx(closed(v0), rel=1e-12) and c.status == "computed"
    texts = {
        "table": exports.write_table(s, tmp_path / "t.txt").read_text(),
        "csv": exports.write_csv(s, tmp_path / "t.csv").read_text(),
        "c": exports.c_header(s, f),
        "fortran": exports.fortran_include(s, f),
        "lammps": exports.lammps_snippet(s, c),
        "liggghts": exports.liggghts_snippet(s, c),
        "mercurydpm": exports.mercurydpm_snippet(s, c),
        "yade": exports.yade_snippet(s, c),
    }
    for name, text in texts.items():
        assert "grain: sphere: elastic sphere (3D)" in text, name
        assert "law: the sphere's, nu = 0.3" in text, name
        assert "nu_2d" not in text and "cylinder" not in text and "disk" not in text, name
        assert f"c = sqrt(E/rho) = {C_STEEL:.6g} m/s" in text, name
    # The table holds every computed speed, at w = k c v (8 significant digits).
    table = np.loadtxt(tmp_path / "t.txt")
    rows = np.abs(table[:, :1] - VV * k * C_STEEL).argmin(axis=0)
    assert_allclose(table[rows, 0], VV * k * C_STEEL, rtol=1e-7)
    assert_allclose(table[rows, 1], closed(VV), atol=1e-7)
    # MercuryDPM's mass argument is the effective mass 2 m1 m2 / (m1 + m2)
    # (LinearViscoelasticNormalSpecies::setCollisionTimeAndRestitutionCoefficient): m for two
    # identical spheres, 2 m against a wall, with the sphere's m = 4/3 pi rho R^3.
    mercury = texts["mercurydpm"]
    assert "m = 4/3 pi rho R^3" in mercury
    assert ("two identical grains: m" if against == "grain" else "a grain on a wall: 2 m") in (
        mercury
    )
    for name in ("lammps", "liggghts", "mercurydpm", "yade"):
        assert "this law is the sphere's" in texts[name]


def test_exports_of_a_cylinder_say_it_is_not_a_sphere():
    g = Grain(63e9, 0.25, 2500.0, "cylinder")
    s = SILaw(g, "wall", synthetic(0.25 / 0.75, "disk"))
    c = exports.constant_at(s, 500.0)
    for snippet in (exports.lammps_snippet, exports.mercurydpm_snippet, exports.yade_snippet):
        text = snippet(s, c)
        assert "grain: cylinder: long elastic cylinder" in text
        assert "this law is the cylinder's (a 2D disk), not a sphere's" in text
    assert "a grain on a wall: 2 m" in exports.mercurydpm_snippet(s, c)


def test_cli_law_exports_a_sphere_law_file(tmp_path, capsys):
    path = synthetic().to_json(tmp_path / law_filename(NU, "sphere"))
    out_dir = tmp_path / "exports"
    code, out, err = run_cli(
        capsys, "law", *STEEL, "--against", "grain", "--law-file", path,
        "--export", out_dir, "--reference-speed", 0.1 * 2 * C_STEEL,
    )  # fmt: skip
    assert code == 0, err
    manifest = out_dir / ".restitution-export.json"
    files = sorted(p for p in out_dir.iterdir() if p != manifest)
    # 5 tables and codes, 4 snippets, the plugin's tables (the grains', the grain on the wall)
    # and its input lines; the manifest (restitution.file_set) names exactly them. No law per
    # contact: it would be the package's own, not the given file's (the input lines say so).
    assert len(files) == 12
    assert "--law-file" in (out_dir / "epsilon_lammps_plugin.in").read_text()
    assert sorted(json.loads(manifest.read_text())["files"]) == [p.name for p in files]
    for p in files:
        if p.suffix != ".json":
            assert "grain: sphere: elastic sphere (3D)" in p.read_text(), p.name
    closed_form = json.loads((out_dir / "epsilon_closed_form.json").read_text())
    assert closed_form["speed_scale_m_s"] == pytest.approx(2 * C_STEEL, rel=1e-15)


# -- production -------------------------------------------------------------------------------


@pytest.mark.slow  # 7 s of the default run (stop 76: the default run under 10 min)
def test_production_builds_sphere_files(computed, tmp_path, monkeypatch, capsys):
    nus, groups = production.production("sphere")
    plan = body_kind("sphere").production
    assert nus == plan.nus == (0.2, 0.25, 0.3, 0.35, 0.4, 0.45)
    assert [g.n_modes for g in groups] == [(2400, 4800, 9600, 19200)]
    assert [len(g.velocities) for g in groups] == [26]
    assert all(g.geometry == "sphere" for g in groups)
    assert all(-1 < nu < 0.5 for nu in nus)
    assert production.production("disk") == (production.SHIPPED_NUS, production.SETTINGS_GROUPS)
    # build() with the small grid, every point already stored: it writes the sphere's file.
    # Two low-speed points join the collisions' (production: the kind's low speeds).
    (path,) = production.build(
        tmp_path, (NU,), (SETTINGS,), store=computed.store, progress=False, low_speeds=(1e-4, 1e-3)
    )
    assert path.name == "law_sphere_nu0.3.json"
    built = law(NU, geometry="sphere", path=path)
    assert built.quasistatic.tolist() == [True, True, False, False, False]
    assert_allclose(built.epsilon_points[2:], computed.law.epsilon_points, rtol=1e-15)
    assert built.v[:2].tolist() == [1e-4, 1e-3]
    assert [p.status for p in built.points[:2]] == ["quasistatic", "quasistatic"]
    with pytest.raises(InputError, match="one body"):
        production.build(tmp_path, (NU,), (SETTINGS, production.PAPER))
    # The switch picks the sphere's settings (build itself is replaced: no production run).
    seen = {}

    def fake_build(out, nus, groups, **kwargs):
        seen.update(out=out, nus=nus, groups=groups)
        return []

    monkeypatch.setattr(production, "build", fake_build)
    production.main(["--geometry", "sphere", "--out", str(tmp_path / "data")])
    assert seen["nus"] == plan.nus and seen["groups"] == groups
    capsys.readouterr()


# -- shipped sphere laws (`make law-sphere`) ---------------------------------------------------

_DATA = resources.files("restitution.laws").joinpath("data")
SPHERE_FILES = [law_filename(nu, "sphere") for nu in shipped_nus("sphere")]


@pytest.mark.parametrize("name", representatives(SPHERE_FILES, {"law_sphere_nu0.3.json"}))
def test_shipped_sphere_low_speed_points_have_not_moved(name):
    """The stale-data test of the laws' low-speed points: every point below the modal speeds is
    one of the sphere kind's production low speeds, flagged 'quasistatic'; three of them (both
    ends and the middle) recomputed by the current code give the stored loss and estimate error,
    and the interpolation errors of the whole grid are the current code's; each point's error is
    their sum."""
    import warnings

    from restitution import get_modes
    from restitution.laws.low_speed import low_speed_points
    from restitution.provenance import quasistatic_code_version
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES, interpolation_error

    meta = json.loads(_DATA.joinpath(name).read_text())["metadata"]
    low = [p for p in meta["points"] if p.get("route") == "quasistatic"]
    speeds = body_kind("sphere").production.low_speeds
    assert [p["v"] for p in low] == list(speeds)
    assert all(p["status"] == "quasistatic" and not p["asymptotic_ok"] for p in low)
    assert max(p["v"] for p in low) < min(
        p["v"] for p in meta["points"] if p.get("route") != "quasistatic"
    )
    sample = [low[0], low[len(low) // 2], low[-1]]
    redo, parameters = low_speed_points(meta["nu"], [p["v"] for p in sample], geometry="sphere")
    assert parameters["n_modes"] == meta["low_speed"]["n_modes"]
    for p, q in zip(sample, redo, strict=True):
        assert q["energy_loss"] == pytest.approx(p["energy_loss"], rel=1e-9), (
            f"{name}: the low-speed point v = {p['v']} moved; regenerate with `make law-sphere`"
        )
        assert q["estimate_err"] == pytest.approx(p["estimate_err"], rel=1e-9)
    modes = get_modes(meta["nu"], LOW_SPEED_MODES, geometry="sphere")
    between = interpolation_error(modes, speeds)
    assert_allclose([p["interpolation_err"] for p in low], between, rtol=1e-9)
    assert_allclose(
        [p["energy_loss_err"] for p in low],
        [p["estimate_err"] + p["interpolation_err"] for p in low],
        rtol=1e-12,
    )
    now = quasistatic_code_version("sphere", "rayleigh")
    if meta["low_speed"]["code_version"] != now:
        warnings.warn(
            f"{name}'s low-speed points were computed with code "
            f"{meta['low_speed']['code_version']}, this is {now}; "
            "the sampled points have not moved",
            stacklevel=1,
        )


@pytest.mark.slow
def test_computed_sphere_laws_are_smooth_in_nu(tmp_path):
    """Real small laws at nu = 0.2, 0.25, 0.35, 0.4 interpolated to 0.3 agree with the law
    computed at 0.3 within the two error bars (the interpolated one includes the leave-one-out
    estimate of the interpolation error)."""
    settings = replace(SETTINGS, velocities=(0.1, 0.2))
    nus = (0.2, 0.25, 0.3, 0.35, 0.4)
    curves = compute_curves(nus, settings, store=tmp_path / "s.sqlite", progress=False)
    laws = {nu: EpsilonLaw.from_curve(curves[nu]) for nu in nus}
    grid = [laws[nu] for nu in nus if nu != 0.3]
    served = law_for(0.3, geometry="sphere", laws=grid)
    assert isinstance(served, NuInterpolatedLaw)
    v = np.array([0.1, 0.2])
    gap = np.abs(served.epsilon(v) - laws[0.3].epsilon(v))
    print("interpolated - computed at nu = 0.3:", gap, "bars:", served.epsilon_err(v))
    assert np.all(gap <= served.epsilon_err(v) + laws[0.3].epsilon_err(v))


def test_the_sphere_cylinder_figure_shows_the_shipped_numbers(tmp_path):
    """The figure's sphere curve is the shipped law read at v = w / c, c = sqrt(E / rho) by
    hand; the cylinder's at c = sqrt(E / ((1 - nu^2) rho)), nu_2d = nu / (1 - nu)."""
    from restitution.reproduction.figures import sphere_cylinder

    steel = {"steel": sphere_cylinder.MATERIALS["steel"]}
    curves = {c.geometry: c for c in sphere_cylinder.compute(steel, points=25)}
    E, nu, rho = steel["steel"]
    sphere, cylinder = curves["sphere"], curves["cylinder"]
    v = sphere.speed_m_s / np.sqrt(E / rho)
    assert_allclose(sphere.epsilon, law(nu, geometry="sphere").epsilon(v), rtol=1e-12)
    c_cyl = np.sqrt(E / ((1 - nu**2) * rho))
    served = law_for(nu / (1 - nu))  # steel's nu_2d = 0.4286, interpolated between disk laws
    assert_allclose(cylinder.epsilon, served.epsilon(cylinder.speed_m_s / c_cyl), rtol=1e-12)
    assert sphere.speed_m_s.size == 25 and cylinder.speed_m_s.size == 25
    path = tmp_path / "sc.png"
    sphere_cylinder.plot(tuple(curves.values()), path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
