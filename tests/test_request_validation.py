"""Hostile input at the API edge (the hostile-input issue: "tracebacks" and "silently wrong").

Every field of :class:`~restitution.laws.request.LawRequest` is checked alone by its option's
kind (:mod:`restitution.laws.request_fields`) before the options are checked together: a value
of the wrong type is one :class:`InputError` naming the command-line option and the Python
keyword, the value's type and the unit, where it was a TypeError, a MemoryError (``wall_E=True``
asked for 13 GiB), or silently taken (a misspelt ``measured_fixes`` fixed the relaxation time).
The collision settings' names, a law built from lists, a plate of radius 0 and a wall so dense
that its waves take more than the kinetic energy are here too.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

import numpy as np
import pytest
from _cli_checks import one_line_error

from restitution.dynamics.settings import CollisionSettings
from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.request import DEFAULT_SPEEDS_M_S, LawRequest

STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall", speeds=(1.0,))
GLASS_WALL = dict(wall_E=63e9, wall_nu=0.2481, wall_rho=2500.0)
PLATE = dict(GLASS_WALL, wall_thickness=0.001, radius=0.005)
MEASURED = dict(measured_epsilon=0.9, measured_speed=1.0)
PARTNER = dict(against="grain")
NAN, INF = float("nan"), float("inf")

# (keyword, option, extra options the field goes with, bad value, words of the refusal)
BAD = [
    # one number: a string is not parsed, a list or array of one is not unpacked, a bool or a
    # complex number is not a number, a non-finite one is refused as the command line does
    ("wall_E", "--wall-E", GLASS_WALL, "63e9", ["(str)", "(Pa)", "e.g. wall_E=63e9"]),
    ("wall_E", "--wall-E", GLASS_WALL, True, ["(bool)", "(Pa)"]),  # was 13 GiB of memory
    ("wall_E", "--wall-E", GLASS_WALL, np.array([63e9]), ["(ndarray)", "(Pa)"]),
    ("wall_E", "--wall-E", GLASS_WALL, [63e9], ["(list)", "(Pa)"]),
    ("wall_E", "--wall-E", GLASS_WALL, {"E": 63e9}, ["(dict)", "(Pa)"]),
    ("wall_E", "--wall-E", GLASS_WALL, 63e9 + 1j, ["(complex)", "(Pa)"]),
    ("wall_E", "--wall-E", GLASS_WALL, INF, ["finite", "(Pa)"]),
    ("wall_rho", "--wall-rho", GLASS_WALL, [2500], ["(list)", "(kg/m^3)"]),
    ("wall_nu", "--wall-nu", GLASS_WALL, "0.25", ["(str)", "(dimensionless)"]),
    ("wall_thickness", "--wall-thickness", PLATE, "0.001", ["(str)", "(m)"]),
    ("wall_thickness", "--wall-thickness", PLATE, NAN, ["finite", "(m)"]),
    ("E", "--E", {}, "210e9", ["(str)", "(Pa)", "e.g. E=210e9"]),
    ("E", "--E", {}, True, ["(bool)", "(Pa)"]),
    ("nu", "--nu", {}, None, ["(NoneType)", "(dimensionless)"]),
    ("rho", "--rho", {}, -7850.0, ["positive", "(kg/m^3)"]),
    ("partner_E", "--partner-E", PARTNER, "63e9", ["(str)", "(Pa)"]),
    ("partner_radius_ratio", "--partner-radius-ratio", PARTNER, "2", ["(str)"]),
    ("radius", "--radius", dict(relaxation_time=1e-6), "0.005", ["(str)", "(m)"]),
    ("relaxation_time", "--relaxation-time", dict(radius=0.005), [1e-6], ["(list)", "(s)"]),
    ("measured_speed", "--measured-speed", MEASURED, np.array([1.0]), ["(ndarray)", "(m/s)"]),
    ("measured_epsilon", "--measured-epsilon", MEASURED, "0.9", ["(str)"]),
    ("reference_speed", "--reference-speed", {}, "1", ["(str)", "(m/s)"]),
    ("maxwell_temperature", "--maxwell-temperature", {}, 1 + 1j, ["(complex)", "(m^2/s^2)"]),
    ("yield_stress", "--yield-stress", {}, [1e9], ["(list)", "(Pa)"]),
    ("limiting_pressure", "--limiting-pressure", {}, True, ["(bool)", "(Pa)"]),
    ("friction", "--friction", dict(reference_speed=1.0, export_dir="x"), "0.3", ["(str)"]),
    # speeds: a number or a 1-D list or array of numbers
    ("speeds", "--speed", {}, "1", ["(str)", "(m/s)"]),
    ("speeds", "--speed", {}, ["1", 2.0], ["(str)", "(m/s)"]),
    ("speeds", "--speed", {}, [1.0, True], ["(bool)", "(m/s)"]),
    ("speeds", "--speed", {}, True, ["(bool)", "(m/s)"]),
    ("speeds", "--speed", {}, np.array([[1.0, 2.0]]), ["1-D", "(m/s)"]),
    ("speeds", "--speed", {}, {1.0: 2.0}, ["(dict)", "(m/s)"]),  # took its keys
    ("speeds", "--speed", {}, [1 + 0j], ["(complex)", "(m/s)"]),
    ("speeds", "--speed", {}, np.array(["1"]), ["(str_)", "(m/s)"]),
    ("speeds", "--speed", {}, [INF], ["> 0", "(m/s)"]),
    # one of the listed strings
    ("shape", "--shape", {}, ["sphere"], ["(list)", "'sphere'"]),
    ("shape", "--shape", {}, "Sphere", ["'cylinder'", "shape='sphere'"]),
    ("against", "--against", {}, "walls", ["'wall', 'grain'", "against='wall'"]),
    ("against", "--against", {}, ["wall"], ["(list)"]),
    ("measured_fixes", "--measured-fixes", MEASURED, 1, ["(int)", "'relaxation-time'"]),
    ("route", "--route", dict(compute=True), ["modal"], ["(list)", "'modal', 'residual'"]),
    # paths: str or os.PathLike
    ("law_file", "--law-file", {}, 1, ["(int)", "os.PathLike"]),
    ("law_file", "--law-file", {}, b"law.json", ["(bytes)"]),
    ("export_dir", "--export", dict(reference_speed=1.0), 3.5, ["(float)"]),
    ("export_dir", "--export", dict(reference_speed=1.0), "", ["empty"]),  # wrote into cwd
    ("store", "--store", dict(compute=True), ["results.sqlite"], ["(list)"]),
    # flags: True or False
    ("compute", "--compute", {}, "no", ["(str)", "compute=True"]),
    ("compute", "--compute", {}, None, ["(NoneType)"]),
    ("force", "--force", dict(compute=True), 1, ["(int)"]),
    # quantities that must be positive: a plate of radius 0 divided by it
    ("radius", "--radius", PLATE, 0.0, ["positive", "(m)"]),
    ("radius", "--radius", dict(relaxation_time=1e-6), -1.0, ["positive", "(m)"]),
    ("wall_thickness", "--wall-thickness", PLATE, 0.0, ["positive", "(m)"]),
    ("maxwell_temperature", "--maxwell-temperature", {}, 0.0, ["positive", "(m^2/s^2)"]),
]


@pytest.mark.parametrize(
    ("keyword", "option", "extra", "value", "words"),
    BAD,
    ids=[f"{k}={v!r}"[:40] for k, _, _, v, _ in BAD],
)
def test_each_bad_field_is_one_input_error_naming_option_and_keyword(
    keyword, option, extra, value, words, tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)  # an empty export path named the working directory
    with pytest.raises(InputError) as info:
        LawRequest(**{**STEEL, **extra, keyword: value})
    message = str(info.value)
    assert "\n" not in message
    assert message.startswith(f"{option} "), message
    # the Python keyword itself, not only the option that spells it with dashes
    assert re.search(rf"(?<![-\w]){keyword}(?![-\w])", message), message
    for w in words:
        assert w in message, (w, message)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("typo", ["relaxation time", "limiting_pressure", "Both", "tau"])
def test_a_misspelt_measured_fixes_is_refused_with_the_choices(typo):
    """It was taken for the relaxation time (0.760 instead of the limiting pressure's 0.620)."""
    with pytest.raises(InputError) as info:
        LawRequest(**STEEL, **MEASURED, measured_fixes=typo)
    message = str(info.value)
    for choice in ("'relaxation-time'", "'limiting-pressure'", "'both'"):
        assert choice in message
    assert "--measured-fixes" in message and "measured_fixes=" in message


def test_what_the_command_line_accepts_python_gives_alike():
    """Python and NumPy numbers, a 0-d array of speeds, one speed alone, paths of any
    os.PathLike: accepted and given the command line's types."""

    class Where(os.PathLike):
        def __fspath__(self):
            return "law.json"

    r = LawRequest(E=np.float64(210e9), nu=np.float32(0.3), rho=7850,
                   shape=np.str_("sphere"), against="wall", speeds=np.array(1.0),
                   law_file=Where())  # fmt: skip
    assert r.speeds == (1.0,) and type(r.speeds[0]) is float
    assert (type(r.E), type(r.nu), type(r.rho)) == (float, float, float)
    assert r.rho == 7850.0 and r.nu == pytest.approx(0.3)
    assert r.law_file == Path("law.json")
    assert LawRequest(**{**STEEL, "speeds": 5}).speeds == (5.0,)
    assert LawRequest(**{**STEEL, "speeds": np.array([1, 2])}).speeds == (1.0, 2.0)
    assert LawRequest(**{**STEEL, "speeds": [np.float32(0.5), np.int64(2)]}).speeds == (0.5, 2.0)
    for not_given in (None, [], ()):
        assert LawRequest(**{**STEEL, "speeds": not_given}).speeds == DEFAULT_SPEEDS_M_S
    assert LawRequest(**STEEL, compute=np.bool_(True)).compute is True
    fixes = LawRequest(**STEEL, **MEASURED, measured_fixes="limiting-pressure", yield_stress=None)
    assert fixes.fixes_limiting_pressure


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("integrator", ["split4"]),
        ("integrator", {"split4": 1}),
        ("integrator", None),
        ("backend", np.array(["auto"])),  # compared elementwise: it was taken
        ("backend", ["numpy"]),
    ],
)
def test_collision_settings_names_are_checked(field, value):
    with pytest.raises(InputError) as info:
        CollisionSettings(**{field: value})
    message = str(info.value)
    assert f"unknown {field}" in message and type(value).__name__ in message
    allowed = ("'split4'", "'rk4'") if field == "integrator" else ("'auto'", "'numpy'")
    assert all(a in message for a in allowed), message


def test_a_law_built_from_lists_has_arrays_and_a_repr():
    """``repr`` of a law built from Python lists was an AttributeError (``list.size``)."""
    law = EpsilonLaw(0.33, [0.1, 0.2], [0.9, 0.8], [0.01, 0.01], [True, False])
    assert "2 points on 0.1 <= v/c <= 0.2, 1 pass their checks" in repr(law)
    assert isinstance(law.v, np.ndarray) and law.asymptotic_ok.dtype == bool
    assert float(law.epsilon(0.15)) == pytest.approx(0.85, abs=0.01)
    with pytest.raises(InputError, match="asymptotic_ok must be True or False"):
        EpsilonLaw(0.33, [0.1, 0.2], [0.9, 0.8], [0.01, 0.01], ["no", "yes"])


_STEEL_ARGS = ("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere",
               "--against", "wall", "--wall-E", "63e9", "--wall-nu", "0.2481")  # fmt: skip


def test_a_plate_of_radius_zero_is_one_line(cli):
    """It was a ZeroDivisionError (thickness / radius)."""
    code, _, err = cli(*_STEEL_ARGS, "--wall-rho", "2500", "--wall-thickness", "0.001",
                       "--radius", "0", "--speed", "1")  # fmt: skip
    one_line_error(code, err, "--radius must be a positive number (m), got 0.0")


def test_the_half_space_route_has_no_value_where_the_losses_pass_the_kinetic_energy():
    """Radiation on Hertz's pulse grows like sqrt(rho_w) v^(3/5): on a wall of 1e7 kg/m^3 a
    steel ball's waves take 0.57 of the energy at 1 m/s, 1.49 at 5 m/s (a math domain error in
    sqrt(1 - loss) before)."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.wall import HalfSpace
    from restitution.quasistatic.half_space import LossBeyondEnergy, half_space_loss
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    modes = get_modes(0.3, LOW_SPEED_MODES, geometry="sphere")
    wall = HalfSpace(63e9 / 210e9, 1e7 / 7850, 0.2481)
    c = math.sqrt(210e9 / 7850)
    assert half_space_loss(modes, 1.0 / c, wall).energy_loss < 1.0
    with pytest.raises(LossBeyondEnergy, match="take 1.49 times the kinetic energy"):
        half_space_loss(modes, 5.0 / c, wall)


@pytest.mark.slow  # 8 s of the default run (stop 76: the default run under 10 min)
def test_a_too_dense_wall_gives_no_value_at_that_speed(cli):
    """`--wall-rho 1e7` was a traceback (math domain error at the route's reach); now 1 m/s has
    its value, 5 m/s none (the losses pass the kinetic energy there) and says why, and the route
    reaches where the losses stay below it."""
    code, out, err = cli(*_STEEL_ARGS, "--wall-rho", "1e7", "--speed", "1", "5")
    assert "Traceback" not in err
    assert code == 1, err  # a requested speed got no value
    rows = {m[1]: m[0].split() for m in re.finditer(r"(?m)^\s+([15])\s+\d.*$", out)}
    # speed, v/c, epsilon, error, sd, status
    assert rows["1"][5] == "quasistatic" and 0.5 < float(rows["1"][2]) < 0.8
    assert rows["5"][2:6] == ["-", "-", "-", "outside"]
    assert "no value from the half-space's model" in out + err
    assert "times the kinetic energy" in out + err
    reach = re.search(r"the route reaches w = ([\d.]+) m/s", out + err)
    assert reach and 1.0 < float(reach.group(1)) < 5.0
