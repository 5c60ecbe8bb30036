"""Issue 30: every public function refuses an argument of the wrong type or range with a one-line
:class:`~restitution.errors.InputError` (or a subclass) that names the argument, never a
TypeError, AttributeError or ValueError from deep inside; valid arguments give what they gave.

Each case is ``(call, words, error)``: ``words`` is a regular expression the message must match
(the argument's name), ``error`` the class it must be an instance of.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
import re
from importlib import resources

import numpy as np
import pytest
from numpy.testing import assert_array_equal

import restitution
from restitution import (
    EpsilonLaw,
    Grain,
    InputError,
    Material,
    MaterialError,
    SILaw,
    compute_modes,
    get_modes,
    law,
    si_law,
    weyl_count,
)
from restitution.bodies.cache import check_mode_request
from restitution.bodies.kinds import body_kind
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.bodies.sphere.modes import weyl_count as sphere_weyl_count
from restitution.dynamics.collision import collide, collide_batch
from restitution.errors import describe, is_real
from restitution.limits.curves import compute_curves, epsilon_at
from restitution.limits.sweep import SweepSettings

NAN, INF = math.nan, math.inf

NOT_NUMBERS = {"None": None, "str": "x", "list": [0.3], "bool": True, "complex": 1j}
"""Values that are not one real number; a bool is refused, not read as 1.0."""
NOT_FINITE = {"nan": NAN, "inf": INF}
SOME = {k: v for k, v in NOT_NUMBERS.items() if v is not None}
"""For optional arguments, whose ``None`` means their default (``law(nu=None)``: 0.33)."""

SHIPPED = resources.files("restitution.laws").joinpath("data", "law_nu0.33.json")
GLASS = {"E": 63e9, "nu": 0.2481, "rho": 2500.0, "geometry": "cylinder", "against": "wall"}


@pytest.fixture(autouse=True)
def _own_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))


def _case(id_, call, words, error=InputError):
    return pytest.param(call, words, error, id=id_)


def _numbers(name, make, words=None, error=InputError, values=None):
    """One case per wrong value of the numeric argument ``name`` (``make(value)`` calls)."""
    values = {**NOT_NUMBERS, **NOT_FINITE} if values is None else values
    return [
        _case(f"{name}={key}", lambda v=value: make(v), words or rf"\b{name}\b", error)
        for key, value in values.items()
    ]


def _law():
    return law(0.33)


def _glass():
    return si_law(**GLASS)


def _steel():
    return Grain(E=210e9, nu=0.3, rho=7850.0, geometry="sphere")


@functools.cache
def _disk():
    """Ten modes of the disk at nu = 0.33 (no cache: the collision cases only need a body)."""
    return compute_modes(0.33, count=10)


def _point(**kw):
    """epsilon_at at (0.33, 0.1) reading the store only: the arguments are refused before it."""
    return epsilon_at(**{"nu": 0.33, "v": 0.1, "run": False, **kw})


CASES = [
    # Material and its constructors: MaterialError, naming the constant.
    *_numbers("nu", lambda x: Material(x), error=MaterialError),
    *_numbers("E", lambda x: Material(0.3, E=x), error=MaterialError),
    *_numbers("rho", lambda x: Material(0.3, rho=x), error=MaterialError),
    *_numbers("nu", lambda x: Material.from_3d(1.0, x), error=MaterialError),
    *_numbers("E", lambda x: Material.from_3d(x, 0.3), error=MaterialError),
    *_numbers("rho", lambda x: Material.from_3d(1.0, 0.3, rho=x), error=MaterialError),
    *_numbers("mu", lambda x: Material.from_moduli(x, 1.0), error=MaterialError),
    *_numbers("K", lambda x: Material.from_moduli(1.0, x), error=MaterialError),
    *[
        _case(f"plane={v!r}", lambda v=v: Material.from_3d(1.0, 0.3, plane=v), "plane",
              MaterialError)
        for v in (None, 5, "plain", np.array(["stress", "strain"]))
    ],  # fmt: skip
    # compute_modes and get_modes (disk and sphere): material, count, omega_max.
    *_numbers("material", lambda x: compute_modes(x, count=10), error=MaterialError,
              values={**NOT_NUMBERS, "array": np.array([0.3, 0.4])}),
    *_numbers("material", lambda x: get_modes(x, count=10), error=MaterialError,
              values={**NOT_NUMBERS, "array": np.array([0.3, 0.4])}),
    *_numbers("nu", lambda x: compute_modes(x, count=10), error=MaterialError, values=NOT_FINITE),
    *_numbers("count", lambda x: compute_modes(0.33, count=x),
              values={"str": "x", "list": [10], "bool": True, "float": 10.5, "float10": 10.0,
                      "nan": NAN, "zero": 0, "negative": -3, "array": np.array([10])}),
    *_numbers("count", lambda x: get_modes(0.33, count=x),
              values={"str": "x", "list": [10], "bool": True, "float": 10.5, "zero": 0,
                      "array": np.array([10]), "0d-array": np.array(10)}),
    *_numbers("count", lambda x: get_modes(0.3, count=x, geometry="sphere"),
              values={"str": "x", "bool": True, "float": 10.5}),
    *_numbers("count", lambda x: compute_sphere_modes(0.3, count=x),
              values={"bool": True, "float": 10.5, "list": [10]}),
    *_numbers("omega_max", lambda x: compute_modes(0.33, omega_max=x),
              values={**NOT_NUMBERS, **NOT_FINITE, "zero": 0.0, "negative": -1.0}),
    *_numbers("omega_max", lambda x: compute_sphere_modes(0.3, omega_max=x),
              values={"str": "x", "bool": True, "nan": NAN, "negative": -1.0}),
    *_numbers("omega_max", lambda x: get_modes(0.33, omega_max=x),
              values={"bool": True, "nan": NAN, "zero": 0.0, "str": "x", "list": [5.0],
                      "complex": 1j}),
    *_numbers("use_cache", lambda x: get_modes(0.33, count=5, use_cache=x),
              values={"str": "no", "None": None, "int": 0, "list": []}),
    # check_mode_request (the command line's early check): count, omega_max and nu.
    *_numbers("count", lambda x: check_mode_request(0.33, x),
              values={"str": "x", "bool": True, "float": 10.0, "array": np.array([10])}),
    *_numbers("omega_max", lambda x: check_mode_request(0.33, None, x),
              values={"str": "x", "list": [5.0], "bool": True}),
    *_numbers("nu", lambda x: check_mode_request(x, None, 5.0),
              values={**NOT_NUMBERS, **NOT_FINITE, "str-number": "0.3", "outside": 1.5}),
    # BodyKind.check_nu, behind every Poisson number of a body: never float() of anything.
    *_numbers("nu", lambda x: body_kind("disk").check_nu(x),
              values={**NOT_NUMBERS, **NOT_FINITE, "str-number": "0.3", "minus-one": -1,
                      "one": 1.0}),
    *_numbers("nu", lambda x: body_kind("sphere").check_nu(x),
              values={"bool": True, "str-number": "0.3", "half": 0.5, "inf": INF}),
    _case("count-and-omega_max", lambda: compute_modes(0.33), r"count.*omega_max"),
    _case("sphere-nu-str", lambda: compute_sphere_modes("x", count=5), r"\bnu\b"),
    # weyl_count (disk and sphere): omega and nu.
    *_numbers("omega", lambda x: weyl_count(x, 0.33),
              values={"None": None, "str": "x", "bool": True, "nan": NAN, "inf": INF,
                      "negative": -1.0, "array": np.array([1.0, -1.0])}),
    *_numbers("nu", lambda x: weyl_count(10.0, x),
              values={**NOT_NUMBERS, **NOT_FINITE, "outside": 10.5, "minus-one": -1.0}),
    *_numbers("omega", lambda x: sphere_weyl_count(x, 0.3), values={"str": "x", "negative": -1}),
    *_numbers("nu", lambda x: sphere_weyl_count(1.0, x), values={"bool": True, "outside": 0.7}),
    # law: nu, nu_2d, path, partner, geometry; and the evaluation of a law.
    *_numbers("nu", lambda x: law(nu=x), words=r"\bnu\b|Poisson number",
              values={**SOME, **NOT_FINITE, "array": np.array([0.33]), "outside": 1.5}),
    *_numbers("nu_2d", lambda x: law(nu_2d=x), values={**SOME, **NOT_FINITE}),
    *_numbers("nu", lambda x: law(x, path=str(SHIPPED)), words=r"\bnu\b|Poisson number",
              values={"str": "x", "nan": NAN, "bool": True}),
    *_numbers("path", lambda x: law(path=x),
              values={"float": 1.0, "list": ["a.json"], "bool": True}),
    *_numbers("partner", lambda x: law(partner=x), values={"str": "x", "float": 1.4, "dict": {}}),
    *_numbers("geometry", lambda x: law(geometry=x), values={"None": None, "int": 5, "list": [1]}),
    *_numbers("speeds", lambda x: _law().epsilon(x), words=r"speeds",
              values={"None": None, "str": "x", "bool": True, "nan": NAN, "complex": 1j,
                      "ragged": [[0.1], [0.1, 0.2]]}),
    *_numbers("speeds", lambda x: _law().checked(x), words=r"speeds",
              values={"str": "x", "bool": True}),
    *_numbers("outside", lambda x: _law().epsilon(0.01, outside=x),
              values={"None": None, "bool": True, "array": np.array(["raise", "nan"])}),
    *_numbers("points", lambda x: _law().to_table("unused.txt", points=x),
              values={"str": "x", "float": 2.5, "one": 1, "bool": True}),
    # EpsilonLaw built by hand.
    *_numbers("nu", lambda x: EpsilonLaw.from_points(x, [0.1, 0.2], [0.9, 0.8], [0.01, 0.01])),
    *_numbers("v", lambda x: EpsilonLaw.from_points(0.33, x, [0.9, 0.8], [0.01, 0.01]),
              values={"None": None, "str": "x", "bool": True}),
    *_numbers("epsilon", lambda x: EpsilonLaw.from_points(0.33, [0.1, 0.2], x, [0.01, 0.01]),
              values={"None": None, "str": ["x", "y"], "short": [0.9]}),
    *_numbers("epsilon_err", lambda x: EpsilonLaw.from_points(0.33, [0.1, 0.2], [0.9, 0.8], x),
              values={"None": None, "long": [0.01, 0.01, 0.01]}),
    _case("from_points-partner",
          lambda: EpsilonLaw.from_points(0.33, [0.1, 0.2], [0.9, 0.8], [0.0, 0.0], partner="x"),
          r"\bpartner\b"),
    _case("from_points-parameters",
          lambda: EpsilonLaw.from_points(0.33, [0.1, 0.2], [0.9, 0.8], [0.0, 0.0], parameters="x"),
          r"\bparameters\b"),
    *_numbers("nu", lambda x: EpsilonLaw(x, np.array([0.1, 0.2]), np.array([0.9, 0.8]),
                                         np.zeros(2), np.ones(2, bool)),
              values={"str": "0.33", "bool": True, "None": None}),
    _case("EpsilonLaw-short-err",
          lambda: EpsilonLaw(0.33, np.array([0.1, 0.2]), np.array([0.9, 0.8]), np.zeros(1),
                             np.ones(2, bool)),
          r"epsilon_err_points"),
    _case("EpsilonLaw-nan-speed",
          lambda: EpsilonLaw(0.33, np.array([0.1, NAN]), np.array([0.9, 0.8]), np.zeros(2),
                             np.ones(2, bool)),
          r"speeds v"),
    # si_law, SILaw and Grain: the SI edge.
    *_numbers("E", lambda x: si_law(**{**GLASS, "E": x})),
    *_numbers("nu", lambda x: si_law(**{**GLASS, "nu": x})),
    *_numbers("rho", lambda x: si_law(**{**GLASS, "rho": x})),
    *_numbers("geometry", lambda x: si_law(**{**GLASS, "geometry": x}),
              values={"None": None, "list": ["cylinder"], "array": np.array(["a", "b"])}),
    *_numbers("against", lambda x: si_law(**{**GLASS, "against": x}),
              values={"None": None, "int": 1, "array": np.array(["wall", "grain"])}),
    *_numbers("path", lambda x: si_law(**GLASS, path=x), values={"float": 1.0, "bool": True}),
    *_numbers("radius ratio", lambda x: si_law(**{**GLASS, "against": "grain"}, radius_ratio=x),
              values={**SOME, **NOT_FINITE, "negative": -2.0}),
    *_numbers("speeds", lambda x: _glass().epsilon(x),
              values={"None": None, "str": "x", "bool": True, "nan": NAN, "negative": -1.0}),
    *_numbers("speeds_m_s", lambda x: _glass().points(x),
              values={"None": None, "str": "x", "bool": True}),
    _case("SILaw-grain", lambda: SILaw("steel", "wall", _law()), r"\bgrain\b"),
    _case("SILaw-law", lambda: SILaw(_glass().grain, "wall", "law_nu0.33.json"), r"\blaw\b"),
    *_numbers("E", lambda x: Grain(E=x, nu=0.3, rho=1.0, geometry="sphere")),
    *_numbers("nu", lambda x: Grain(E=1.0, nu=x, rho=1.0, geometry="thin-disk")),
    *_numbers("rho", lambda x: Grain(E=1.0, nu=0.3, rho=x, geometry="cylinder")),
    *_numbers("geometry", lambda x: Grain(E=1.0, nu=0.3, rho=1.0, geometry=x),
              values={"None": None, "list": ["sphere"], "int": 3}),
    *_numbers("speeds", lambda x: _steel().v_over_c(x, "wall"),
              values={"None": None, "str": "x", "bool": True, "inf": INF, "negative": -1.0}),
    *_numbers("speeds", lambda x: _steel().speed_m_s(x, "grain"),
              values={"None": None, "str": "x", "nan": NAN, "negative": -1.0}),
    *_numbers("against", lambda x: _steel().v_over_c(1.0, x),
              values={"None": None, "array": np.array(["wall"])}),
    # epsilon_at and compute_curves: refused before a store is read, with run=False too (a nu
    # no body has once read a grid of missing points and answered nan).
    *_numbers("nu", lambda x: _point(nu=x),
              values={**NOT_NUMBERS, **NOT_FINITE, "minus-one": -1, "outside": 10.5}),
    *_numbers("nu", lambda x: _point(nu=x, settings=SweepSettings(geometry="sphere")),
              values={"str": "0.3", "half": 0.5}),
    *_numbers("v", lambda x: _point(v=x),
              values={**NOT_NUMBERS, **NOT_FINITE, "zero": 0.0, "one": 1.0, "negative": -0.1}),
    *_numbers("alpha", lambda x: _point(alpha=x),
              values={**SOME, **NOT_FINITE, "zero": 0.0, "negative": -500.0}),
    *_numbers("settings", lambda x: _point(settings=x),
              values={"None": None, "str": "x", "dict": {"n_modes": (300,)}}),
    *_numbers("run", lambda x: _point(run=x), values={"str": "no", "None": None, "int": 1}),
    *_numbers("nus", lambda x: compute_curves(x, run=False),
              values={"float": 0.33, "str": "0.33", "None": None}),
    *_numbers("nu", lambda x: compute_curves([0.33, x], run=False),
              values={"str": "x", "bool": True, "nan": NAN, "outside": 1.5}),
    *_numbers("settings", lambda x: compute_curves([0.33], x, run=False), values={"str": "x"}),
    *_numbers("run", lambda x: compute_curves([0.33], run=x), values={"str": "no"}),
    # collide and collide_batch: None is not nan, a bool is not 1.0.
    *_numbers("v", lambda x: collide(_disk(), x, 100.0),
              values={**NOT_NUMBERS, **NOT_FINITE, "np-bool": np.bool_(True)}),
    *_numbers("alpha", lambda x: collide(_disk(), 0.1, x),
              values={**NOT_NUMBERS, **NOT_FINITE, "zero": 0}),
    *_numbers("v", lambda x: collide_batch(_disk(), x, 100.0),
              values={"None": None, "with-None": [0.1, None], "with-bool": [0.1, True],
                      "strs": np.array(["0.1"])}),
    *_numbers("alpha", lambda x: collide_batch(_disk(), [0.1, 0.2], x),
              values={"None": None, "with-bool": (100.0, False), "ragged": [[1.0], [1.0, 2.0]]}),
]  # fmt: skip


@pytest.mark.parametrize("call,words,error", CASES)
def test_a_wrong_argument_is_one_line_that_names_it(call, words, error):
    with pytest.raises(error) as info:
        call()
    message = str(info.value)
    assert isinstance(info.value, InputError)
    assert "\n" not in message, message
    assert re.search(words, message), message


def test_nan_is_never_recommended_as_a_computation():
    # The shipped file for 0.33 with nu = nan once answered "compute `restitution curve --nu
    # nan`"; a non-finite nu is refused as such, with and without a file.
    for call in (lambda: law(nu=NAN), lambda: law(NAN, path=str(SHIPPED))):
        with pytest.raises(InputError, match=r"finite") as info:
            call()
        assert "curve --nu" not in str(info.value)


@pytest.mark.parametrize(
    "key,value",
    [("v", "x"), ("v", None), ("v", True), ("v", "0.1"), ("epsilon", "x"), ("epsilon", True),
     ("epsilon", [0.9]), ("epsilon_err", None), ("epsilon_err", "0.01"), ("asymptotic_ok", "yes"),
     ("asymptotic_ok", None), ("v", NAN)],
)  # fmt: skip
def test_a_law_file_with_a_non_number_is_refused_in_one_line(tmp_path, key, value):
    doc = json.loads(SHIPPED.read_text())
    doc["metadata"]["points"][3][key] = value
    path = tmp_path / "damaged.json"
    path.write_text(json.dumps(doc))
    for call in (lambda: law(path=path), lambda: si_law(**GLASS, path=path)):
        with pytest.raises(InputError, match="not a valid law file") as info:
            call()
        message = str(info.value)
        assert "\n" not in message and str(path) in message
        assert key in message or "speeds v" in message, message


@pytest.mark.parametrize(
    "where,value,words",
    [("nu", "0.33", "nu"), ("nu", None, "nu"), ("points", 5, "points"), ("partner", "x", "partner"),
     ("geometry", 5, "geometry")],
)  # fmt: skip
def test_a_law_file_with_wrong_metadata_is_refused_in_one_line(tmp_path, where, value, words):
    doc = json.loads(SHIPPED.read_text())
    doc["metadata"][where] = value
    path = tmp_path / "damaged.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(InputError, match=rf"not a valid law file.*{words}"):
        law(path=path)


def test_a_missing_law_file_is_an_input_error(tmp_path):
    with pytest.raises(InputError, match="cannot read law file"):
        law(path=tmp_path / "none.json")


# -- valid arguments give what they gave ---------------------------------------------------


def test_numpy_scalars_and_ints_are_numbers():
    assert Material(np.float32(0.25)).nu == float(np.float32(0.25))
    assert Material(np.array(0.3)).nu == 0.3
    assert Material(0, E=2, rho=np.int64(3)) == Material(0.0, E=2.0, rho=3.0)
    assert Material.from_3d(np.float64(210e9), 0.3, plane="strain", rho=7850) == Material.from_3d(
        210e9, 0.3, plane="strain", rho=7850.0
    )
    g = Grain(E=np.float64(210e9), nu=np.float32(0.3), rho=7850, geometry="thin-disk")
    assert g.nu == float(np.float32(0.3)) and g.rho == 7850.0


def test_weyl_count_is_its_formula_for_numbers_arrays_and_lists():
    # Leading Weyl term of the symmetric disk modes (weyl_count's docstring).
    w, nu = 37.5, 0.33
    assert weyl_count(w, nu) == w**2 / 8.0 * ((1.0 - nu**2) + 2.0 * (1.0 + nu))
    grid = np.array([0.0, 1.0, 20.0])
    assert_array_equal(weyl_count(grid, nu), grid**2 / 8.0 * ((1.0 - nu**2) + 2.0 * (1.0 + nu)))
    assert_array_equal(weyl_count(list(grid), nu), weyl_count(grid, nu))
    assert sphere_weyl_count(2, 0.3) == sphere_weyl_count(2.0, 0.3)


def test_a_numpy_count_computes_the_same_modes():
    a = compute_modes(0.33, count=12)
    b = compute_modes(np.float64(0.33), count=np.int64(12))
    for name in ("n", "l", "omega", "A", "B", "C", "S"):
        assert_array_equal(getattr(a, name), getattr(b, name))


def test_laws_serve_the_same_numbers_for_numpy_and_list_arguments():
    a, b = law(0.33), law(np.float64(0.33), path=str(SHIPPED))
    v = [1e-3, 0.01, 0.1]
    assert_array_equal(a.epsilon(v), b.epsilon(np.array(v)))
    assert a.epsilon(np.float32(0.01)) == a.epsilon(float(np.float32(0.01)))
    s = _glass()
    assert_array_equal(s.epsilon([1.0, 2]), s.epsilon(np.array([1.0, 2.0])))


def test_the_helpers_read_numbers_as_numbers():
    assert [is_real(x) for x in (1, 0.5, NAN, np.int8(3), np.array(2.0))] == [True] * 5
    assert not any(is_real(x) for x in (True, np.bool_(False), "1", None, [1.0], 1j))
    assert describe(np.arange(1000.0)).count("\n") == 0 and len(describe(np.arange(1000.0))) < 80
    assert restitution.errors.real(np.float32(0.5), "x") == 0.5


def test_a_wrong_argument_is_shown_as_given():
    # The message says what was passed: None, not the nan it became; a bool, not 1.0.
    for call, shown in [
        (lambda: collide(_disk(), None, 100.0), "got None"),
        (lambda: collide_batch(_disk(), [0.1], None), "got None"),
        (lambda: collide(_disk(), True, 100.0), "got True (bool)"),
        (lambda: collide(_disk(), 0.1, True), "got True (bool)"),
        (lambda: _point(v=2.0), "got 2.0"),
        (lambda: _point(nu=10.5), "got 10.5"),
        (lambda: body_kind("disk").check_nu("0.3"), "got '0.3' (str)"),
    ]:
        with pytest.raises(InputError) as info:
            call()
        assert shown in str(info.value), str(info.value)


def test_a_numpy_count_reads_the_same_cache_entry(tmp_path):
    # np.int64(10) once crashed in the cache key ("int64 is not JSON serializable").
    a = get_modes(0.33, count=10)
    b = get_modes(np.float64(0.33), count=np.int64(10))
    c = get_modes(0.33, count=np.int32(10), use_cache=np.bool_(False))
    for name in ("n", "l", "omega", "A", "B", "C", "S"):
        assert_array_equal(getattr(a, name), getattr(b, name))
        assert_array_equal(getattr(a, name), getattr(c, name))
    assert len(list((tmp_path / "cache").glob("modes-*.npz"))) == 1
    assert check_mode_request(0.33, np.int64(10)) == 10
    assert type(check_mode_request(0.33, np.int64(10))) is int


def test_check_nu_reads_numbers_as_before():
    disk = body_kind("disk")
    for nu in (0.33, np.float32(0.3), np.float64(-0.5), np.array(0.25), 0, np.int64(0)):
        assert disk.check_nu(nu) == float(nu) and type(disk.check_nu(nu)) is float
    assert body_kind("sphere").check_nu(np.float32(0.49)) == float(np.float32(0.49))


def test_epsilon_at_reads_numpy_scalars_as_floats(tmp_path):
    # Nothing stored and run=False: a point of nan, flagged, with the arguments as floats.
    store = tmp_path / "s.sqlite"
    a = epsilon_at(0.33, 0.1, alpha=500.0, store=store, run=False)
    b = epsilon_at(np.float64(0.33), np.float64(0.1), alpha=np.int64(500), store=store, run=False)
    assert (b.nu, b.v, b.alpha) == (0.33, 0.1, 500.0)
    assert all(type(x) is float for x in (b.nu, b.v, b.alpha))
    assert a.settings == b.settings and not b.asymptotic_ok
    assert json.dumps(b.to_dict()) == json.dumps(a.to_dict())


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_collide_reads_numbers_lists_and_arrays_alike():
    # The same collision from a float, a NumPy scalar, an int alpha, a list and an array.
    modes = _disk()
    ref = collide(modes, 0.1, 100.0)
    same = [
        collide(modes, np.float64(0.1), np.int64(100)),
        collide(modes, np.array(0.1), 100),
        collide_batch(modes, [0.1], [100.0])[0],
        collide_batch(modes, np.array([0.1, 0.1]), 100.0)[1],
        collide_batch(modes, (0.1,), np.array([100.0]))[0],
    ]
    for r in same:
        for field in dataclasses.fields(ref):
            if field.name != "wall_time_s":
                assert_array_equal(getattr(r, field.name), getattr(ref, field.name), field.name)
