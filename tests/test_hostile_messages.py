"""Refusals and warnings of ``restitution law`` that say what happened, in the user's units and
words (the hostile-input issue, classes "misleading" and "plausibility"): each test is a case
that once spoke in reduced units, blamed the wrong option, named options ``law`` does not have,
or let an implausible number pass in silence.

``S`` is a steel sphere, ``W`` a glass half-space under it; every command hits the wall at
1 m/s unless it says otherwise.
"""

from __future__ import annotations

import ast
import copy
import json
import re
import warnings
from pathlib import Path

import click
import pytest
from _cli_checks import one_line_error

import restitution
from restitution.cli import cli as _group
from restitution.errors import InputError, PlausibilityWarning
from restitution.laws.request import LawRequest

S = ("--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere")
W = ("--wall-E", "63e9", "--wall-nu", "0.2481", "--wall-rho", "2500")
STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere")
GLASS_WALL = dict(wall_E=63e9, wall_nu=0.2481, wall_rho=2500.0)

REDUCED = ("reduced units", "(the ball's units)", "c1/R1", " R/c", "p_y = 0.")
"""Words of a message in the package's reduced units, not the user's."""


def _law(cli, *args, against="wall", speed=("--speed", "1")):
    return cli("law", *S, "--against", against, *args, *speed)


def _in_user_units(line: str) -> None:
    for word in REDUCED:
        assert word not in line, (word, line)


def _warnings(err: str) -> list[str]:
    return [x for x in err.splitlines() if x.startswith("warning: ")]


# -- 1. refusals in the user's units, naming the options given ---------------------------------


def test_a_soft_wall_without_yield_options_is_not_refused_in_reduced_units():
    """`--wall-E 1e6` without any yield option ended in "a limiting pressure p_y = 0.00192 at or
    above E* = 5.23e-06": the note on where plastic flow starts computed the yield speed of
    steel's typical yield stresses on a contact whose E* (1e6 Pa) no yield pressure reaches.
    That contact never yields: the note says so in Pa, and the elastic answer is given. (The law
    here is the shipped rigid wall's with the soft wall in its metadata: the note reads only
    that; the wall's own route takes minutes at 1e6 Pa.)"""
    from restitution.bodies.wall import HalfSpace
    from restitution.laws.mechanisms.bounds import elastic_bound
    from restitution.laws.si_law import SILaw, si_law

    steel = si_law(210e9, 0.3, 7850, "sphere", "wall")
    law = copy.deepcopy(steel.law)
    law.metadata["wall"] = HalfSpace(1e6 / 210e9, 2500 / 7850, 0.25).to_dict()
    bound, text = elastic_bound(SILaw(steel.grain, "wall", law))
    assert bound is None
    assert "not reached on this contact" in text and "E* = 1.07e+06 Pa" in text
    _in_user_units(text)


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        (("--partner-yield-stress", "63e9"),
         ["9.78e+10 Pa", "--partner-yield-stress",
          "Young modulus 6.3e+10 Pa of the wall (--wall-E)"]),
        (("--yield-stress", "63e9"),
         ["1.02e+11 Pa", "--yield-stress", "E* = 5.2e+10 Pa (of --E and --wall-E)",
          "never yields"]),
    ],
)  # fmt: skip
def test_a_yield_stress_beyond_the_contact_is_refused_in_pascal(cli, extra, words):
    """`--partner-yield-stress 63e9` on a glass wall said "a limiting pressure p_y = 0.466 at or
    above E* = 0.248" (reduced units, no option): the limiting pressure was checked against the
    grain's modulus only, and the contact's refused it in its own units."""
    code, _, err = _law(cli, *W, *extra)
    line = err.strip().splitlines()[-1]
    assert code == 2 and line.startswith("error: ") and "Traceback" not in err
    for w in words:
        assert w in line, (w, line)
    _in_user_units(line)


def test_a_given_limiting_pressure_is_refused_at_the_softer_body_with_its_option(cli):
    code, _, err = _law(cli, "--limiting-pressure", "1e300")
    line = one_line_error(code, err, "at or above the Young modulus 2.1e+11 Pa of the grain (--E)")
    assert "--limiting-pressure" in line


# -- 2. an unequal pair: a half-space, in law's options ------------------------------------------


@pytest.mark.parametrize("ratio", ["1e-13", "1e13"])
def test_a_partner_beyond_the_pair_range_is_a_half_space_with_law_options(cli, ratio):
    """`--partner-radius-ratio 1e-13` said "the partner's radius ratio 1e+13 ... to one body
    the other is then a rigid wall; collide with the wall instead": the ratio inverted, a large
    partner called rigid (to the small grain it is an elastic half-space, `--wall-E`), and a
    command, not an option of `law`."""
    code, _, err = _law(cli, "--partner-radius-ratio", ratio, against="grain")
    line = one_line_error(
        code,
        err,
        f"--partner-radius-ratio {float(ratio):g}",
        "elastic half-space",
        "--against wall --wall-E 2.1e+11 --wall-nu 0.3 --wall-rho 7850",
    )
    assert "rigid" not in line and "collide" not in line


def test_a_pair_too_unequal_for_the_route_is_a_half_space_not_more_modes(cli):
    """`--partner-radius-ratio 0.001` reached the pair's modes and said "R2/R1 = 1000 ... to the
    other body it is a rigid wall; collide with the wall instead"; at 60, "use about 4615 modes
    or more" (no option of `law` sets modes)."""
    code, _, err = _law(cli, "--partner-radius-ratio", "0.001", against="grain")
    line = err.strip().splitlines()[-1]
    assert code == 2 and line.startswith("error: --partner-radius-ratio 0.001: ")
    assert "elastic half-space" in line and "--against wall --wall-E 2.1e+11" in line
    for wrong in ("rigid", "collide", "modes or more", "R2/R1 = 1000"):
        assert wrong not in line, (wrong, line)


def test_the_half_space_advice_is_a_request_law_takes():
    """The options the unequal pair's advice names make a request `law` accepts (the advice
    works when followed): a partner of another material, smaller than this grain, gets the
    partner's command on a wall of this grain's material."""
    r = LawRequest(**STEEL, against="grain", partner_radius_ratio=1e-3, partner_E=63e9,
                   partner_nu=0.2481, partner_rho=2500.0)  # fmt: skip
    advice = r.unequal_sizes()
    command = advice[advice.index("restitution law ") + len("restitution law ") :].split()
    ctx = _group.commands["law"].make_context("law", command)
    asked = LawRequest(**{k: v for k, v in ctx.params.items() if k in _fields()})
    assert asked.elastic_wall is not None and asked.E == 63e9 and asked.wall_E == 210e9


def _fields() -> set[str]:
    from restitution.laws.request import option_fields

    return {f.name for f in option_fields()}


_MESSAGE_MODULES = [
    "laws/request.py",
    "laws/request_checks.py",
    "laws/request_fields.py",
    "laws/serve.py",
    "laws/plastic.py",
    "laws/mechanisms/bounds.py",
    "laws/mechanisms/base.py",
    "laws/mechanisms/adhesion.py",
    "laws/units.py",
    "laws/si_law.py",
    "laws/damped.py",
    "laws/route_law.py",
    "laws/wall_route.py",
    "laws/wall_grid.py",
    "laws/making/compute.py",
    "laws/law_nu.py",
    "cli/law.py",
    "cli/law_text.py",
    "bodies/material.py",
    "bodies/wall.py",
]
"""Modules whose messages (refusals, notes, advice) ``restitution law`` prints."""

_OPTION = re.compile(r"(?<![\w-])--[A-Za-z][\w-]*[A-Za-z0-9]")
_COMMAND = re.compile(r"restitution ([a-z][a-z-]*)|python -m [\w.]+")


def _message_strings(path: Path):
    """``(line, text)`` of every string a module's code builds (f-strings joined, a ``{}`` per
    field), leaving out docstrings, the help of option metadata (:func:`restitution.laws.
    request_fields.option`) and argparse's own definitions."""
    tree = ast.parse(path.read_text())
    skip = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant | ast.JoinedStr):
            skip.update(id(n) for n in ast.walk(node))
        if isinstance(node, ast.Call):
            name = getattr(node.func, "id", getattr(node.func, "attr", None))
            if name in ("option", "add_argument", "ArgumentParser"):
                skip.update(id(n) for n in ast.walk(node))
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.JoinedStr):
            skip.update(id(n) for n in ast.walk(node))
            text = "".join(v.value if isinstance(v, ast.Constant) else "{}" for v in node.values)
            yield node.lineno, text
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            yield node.lineno, node.value


def _options_of(command_name: str) -> set[str]:
    command = _group.commands[command_name]
    params = command.get_params(click.Context(command))  # law's mechanisms' options too
    return {o for p in params if isinstance(p, click.Option) for o in p.opts}


@pytest.mark.parametrize("module", _MESSAGE_MODULES)
def test_every_option_a_message_names_is_an_option_of_its_command(module):
    """Every `--option` in a message of these modules is an option of `law`, or of the command a
    message names before it (`restitution curve --nu NU_2D`; a `python -m` tool's own options
    are its business): advice that names `--modes` or a `collide` option cannot be followed from
    `law` (the issue's unequal pair said "collide with the wall instead")."""
    src = Path(restitution.__file__).parent
    law_options = _options_of("law")
    wrong = []
    for line, text in _message_strings(src / module):
        spans = [(m.start(), m.group(1) or "") for m in _COMMAND.finditer(text)]
        for m in _OPTION.finditer(text):
            before = [name for start, name in spans if start < m.start()]
            if before and not before[-1]:
                continue  # after `python -m tool`
            owner = before[-1] if before else "law"
            known = law_options if owner == "law" else _options_of(owner)
            if m.group(0) not in known:
                wrong.append(f"{module}:{line}: {m.group(0)} (of {owner}) in {text[:80]!r}")
    assert not wrong, "\n".join(wrong)


def test_the_options_check_finds_an_option_law_does_not_have(tmp_path):
    """The check above is not empty: a message naming `--modes` is caught."""
    bad = tmp_path / "m.py"
    bad.write_text('def f(n):\n    raise ValueError(f"use {n} modes: --modes {n}")\n')
    texts = [t for _, t in _message_strings(bad)]
    assert texts == ["use {} modes: --modes {}"]
    assert "--modes" not in _options_of("law")


# -- 3. the right cause ---------------------------------------------------------------------------


@pytest.mark.parametrize("radius", ["1e-300", "1e-12"])
def test_a_bad_radius_is_not_blamed_on_the_plate(cli, radius):
    """`--wall-thickness 0.001 --radius 1e-300` said "the wall: the plate's thickness must lie in
    1e-6 ... 1e6 R, got 1e+297": the radius is the implausible one."""
    code, _, err = _law(cli, *W, "--wall-thickness", "0.001", "--radius", radius)
    line = one_line_error(code, err, f"--radius {radius} m is below the range of a grain's radius",
                          "--wall-thickness 0.001 m")  # fmt: skip
    assert "the plate's thickness must lie" not in line
    _in_user_units(line)


def test_a_wall_modulus_beyond_the_wall_range_is_refused_in_pascal(cli):
    """`--wall-E 1e-3` said "the wall's modulus ratio must lie in 1e-12 ... 1e12 (the ball's
    units)"."""
    code, _, err = _law(cli, "--wall-E", "1e-3", "--wall-nu", "0.2", "--wall-rho", "2500")
    line = err.strip().splitlines()[-1]
    assert code == 2 and "--wall-E 0.001 Pa is 4.76e-15 times --E 2.1e+11 Pa" in line
    _in_user_units(line)


def test_a_measured_relaxation_time_blames_the_yield_stress_that_loses_too_much(cli):
    """`--measured-epsilon 0.9 --measured-speed 1 --yield-stress 1e9` said "the measured epsilon
    0.9 ... is not below 0.508803, the value there without damping: no damping explains it;
    check the measurement": 0.5088 is the value with the plastic flow of the yield stress given,
    which loses too much for the measurement; the measurement is below the elastic value."""
    code, _, err = _law(cli, "--measured-epsilon", "0.9", "--measured-speed", "1",
                        "--yield-stress", "1e9")  # fmt: skip
    line = err.strip().splitlines()[-1]
    assert code == 2 and line.startswith("error: ")
    assert "--yield-stress" in line and "plastic flow given loses too much" in line
    assert "--measured-fixes limiting-pressure" in line
    assert "no damping explains it" not in line


def test_a_measured_limiting_pressure_blames_the_damping_that_loses_too_much(cli):
    """`--measured-fixes limiting-pressure` with a long `--relaxation-time`: the damping given
    takes all the energy, and "no plastic flow explains it; check the measurement" blamed the
    measurement."""
    code, _, err = _law(cli, "--measured-epsilon", "0.5", "--measured-speed", "1",
                        "--measured-fixes", "limiting-pressure", "--relaxation-time", "1e-3",
                        "--radius", "0.001")  # fmt: skip
    line = err.strip().splitlines()[-1]
    assert code == 2 and "--relaxation-time" in line and "damping given loses too much" in line
    assert "no rebound there" in line


def test_a_measurement_above_the_elastic_value_still_blames_the_measurement():
    from restitution.laws.plastic import infer_relaxation_time, plastic_law
    from restitution.laws.si_law import si_law

    steel = si_law(210e9, 0.3, 7850, "sphere", "wall")
    with pytest.raises(InputError, match="no damping explains it; check the measurement"):
        infer_relaxation_time(plastic_law(steel, yield_stress_pa=1e9), 0.9999999, 1.0)


NO_REBOUND = ("--yield-stress", "1e9", "--relaxation-time", "1e-3", "--radius", "0.001")
"""A grain whose damping takes all the kinetic energy at 1 m/s."""


def test_no_rebound_is_not_called_outside_the_range(cli):
    """A speed whose losses exceed the impact energy was "outside: outside the computed range
    of the law; no value ...; the law serves 0.005172 m/s <= w <= 1552 m/s" (1 m/s is inside);
    in JSON, "outside the law's range". It is no rebound, with the losses."""
    code, out, err = _law(cli, *NO_REBOUND)
    assert code == 1 and "the law serves" not in err
    (line,) = [x for x in err.splitlines() if x.startswith("note: at 1 m/s: no value: no rebound")]
    # The contact alone: viscosity takes all but 2e-10 of the energy (its waves' estimate is
    # beyond the one-pulse model there: tests/test_hostile_bounds.py).
    assert "the contact alone returns epsilon = 1.5e-05 (viscosity 100 %" in line
    code, out, err = _law(cli, *NO_REBOUND, "--format", "json")
    d = json.loads(out)
    assert d["status"] == "outside" and "no rebound" in d["advice"]
    assert "law's range" not in err and "no rebound" in err


def test_a_thick_plate_points_to_the_half_space(cli):
    """A 0.1 m plate under a 0.5 mm ball was refused with a 10-45 minute finite-element command
    alone: to the ball such a plate is a block, answered by the half-space in seconds."""
    code, _, err = _law(cli, *W, "--wall-thickness", "0.1", "--radius", "0.0005")
    (warning,) = _warnings(err)
    assert "--wall-thickness 0.1 m is 200 times --radius 0.0005 m" in warning
    assert "leave out --wall-thickness" in warning
    assert err.index("warning: ") < err.index("note: ")  # before the work starts


def test_a_plate_metres_thick_asks_about_the_units(cli):
    """`--wall-thickness 3` (m) was answered with the finite-element command only."""
    code, _, err = _law(cli, *W, "--wall-thickness", "3", "--radius", "0.001")
    (warning,) = _warnings(err)
    assert "did you mean 3 mm = 0.003?" in warning


# -- 4. plausibility ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("extra", "words"),
    [
        (dict(radius=5.0, relaxation_time=1e-6), ["--radius 5 m", "did you mean 5 mm = 0.005?"]),
        (dict(GLASS_WALL, wall_thickness=0.3, radius=0.5e-3),
         ["--wall-thickness 0.3 m is 600 times --radius 0.0005 m", "block"]),
        (dict(yield_stress=30e9), ["--yield-stress 3e+10 Pa is above the range of a yield stress",
                                   "no metal's"]),
        (dict(friction=1e300, reference_speed=1.0, export_dir="x"),
         ["--friction 1e+300 is above the range of a friction coefficient"]),
        (dict(E=1e4), ["--E 10000 Pa is below the range of a Young modulus"]),
        (dict(E=2e12), ["--E 2e+12 Pa is above"]),
        (dict(E=210.0), ["did you mean 210 GPa = 2.1e+11?"]),
        (dict(rho=7.85), ["did you mean 7.85 g/cm^3 = 7850?"]),
        (dict(rho=4e4), ["--rho 40000 kg/m^3 is above the range of a density"]),
        (dict(GLASS_WALL, wall_rho=1.0), ["--wall-rho 1 kg/m^3 is below"]),
        (dict(against="grain", partner_E=1e13), ["--partner-E 1e+13 Pa is above"]),
        (dict(GLASS_WALL, wall_thickness=2.0, radius=0.01), ["--wall-thickness 2 m is above",
                                                            "did you mean 2 mm = 0.002?"]),
    ],
)  # fmt: skip
def test_an_implausible_number_warns_once_and_goes_on(extra, words):
    args = {**STEEL, "against": "wall", **extra}
    with pytest.warns(PlausibilityWarning) as caught:
        LawRequest(**args)
    texts = [str(w.message) for w in caught if issubclass(w.category, PlausibilityWarning)]
    assert len(texts) == 1, texts
    for w in words:
        assert w in texts[0], (w, texts[0])


@pytest.mark.parametrize(
    "extra",
    [
        dict(),
        dict(GLASS_WALL),
        dict(GLASS_WALL, wall_thickness=0.003, radius=0.0025),
        dict(yield_stress=1e9),
        dict(radius=0.001, relaxation_time=1e-6),
        dict(friction=0.5, reference_speed=1.0, export_dir="x"),
        dict(against="grain", partner_E=63e9, partner_nu=0.2481, partner_rho=2500.0),
    ],
)
def test_real_grains_and_walls_do_not_warn(extra):
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        LawRequest(**{**STEEL, "against": "wall", **extra})


def test_the_command_line_warns_in_one_line_and_goes_on(cli, tmp_path):
    code, out, err = _law(cli, "--radius", "5", "--relaxation-time", "1e-6")
    assert code == 0 and out
    (warning,) = _warnings(err)
    assert warning.startswith("warning: --radius 5 m is above the range of a grain's radius")


def test_a_refusal_carries_the_warning_in_its_one_line(cli):
    code, _, err = _law(cli, "--limiting-pressure", "1e300")
    one_line_error(code, err, "(warning: --limiting-pressure 1e+300 Pa is above the range")


def test_a_refused_request_does_not_warn():
    """The request's own refusals come first: a refused request says one thing."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlausibilityWarning)
        with pytest.raises(InputError, match="--relaxation-time needs --radius"):
            LawRequest(**STEEL, against="wall", relaxation_time=1e-6, yield_stress=30e9)


def test_the_plausible_ranges_are_one_table_of_request_fields():
    """Each entry of the table names fields of the request (or a ratio of two), an ordered range
    and where it comes from."""
    from restitution.laws.request_fields import PLAUSIBLE

    for key, p in PLAUSIBLE.items():
        assert set(key.split("/")) <= _fields(), key
        assert 0.0 <= p.low < p.high and p.what and p.why, key


def test_the_wall_ranges_the_request_checks_are_the_walls():
    """The request refuses in Pa what the wall's bodies would refuse in ratios: the same ends."""
    from restitution.bodies.wall import HalfSpace, Plate
    from restitution.laws.request_checks import PLATE_RADII, WALL_RATIOS

    lo, hi = WALL_RATIOS
    HalfSpace(lo, hi, 0.25)
    for beyond in (lo / 2, hi * 2):
        with pytest.raises(InputError):
            HalfSpace(beyond, 1.0, 0.25)
    lo, hi = PLATE_RADII
    Plate(1.0, 1.0, 0.25, thickness=lo)
    Plate(1.0, 1.0, 0.25, thickness=hi)
    for beyond in (lo / 2, hi * 2):
        with pytest.raises(InputError):
            Plate(1.0, 1.0, 0.25, thickness=beyond)
