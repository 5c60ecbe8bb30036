"""SI units at the API edge: geometry (eq. 2), collision partner, and the `restitution law`
command against the reduced-unit law at the matching v/c."""

import json
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import restitution
from restitution.cli import main
from restitution.errors import InputError
from restitution.laws.law_nu import law_for, shipped_nus
from restitution.laws.si_law import si_law
from restitution.laws.si_point import STATUSES
from restitution.laws.units import Grain, partner_factor

# A glass whose Poisson number, 0.2481 (commercial glasses: about 0.20-0.25), maps in a long
# cylinder onto the shipped law nu_2d = 0.33: 0.2481 / 0.7519 = 0.32996.
GLASS = ["--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--geometry", "cylinder"]
# A rubber-like cylinder (elastic, nu = 0.47368 -> nu_2d = 0.89998, the shipped 0.9).
RUBBER = ["--E", "5e6", "--nu", "0.47368", "--rho", "1100", "--geometry", "cylinder"]


def c_plane_strain(E, nu, rho):
    """c = sqrt(E_2d / rho) with E_2d = E / (1 - nu^2), written out independently."""
    return math.sqrt(E / ((1.0 - nu * nu) * rho))


def run_json(capsys, args):
    main(["law", *args, "--json"])
    return json.loads(capsys.readouterr().out)


def test_geometry_maps_by_eq_2():
    cyl = Grain(E=2.0, nu=0.25, rho=3.0, geometry="cylinder")
    disk = Grain(E=2.0, nu=0.25, rho=3.0, geometry="thin-disk")
    assert_allclose([cyl.nu_2d, cyl.E_2d], [0.25 / 0.75, 2.0 / (1 - 0.0625)])
    assert_allclose([disk.nu_2d, disk.E_2d], [0.25, 2.0])
    assert_allclose(cyl.c_m_s, c_plane_strain(2.0, 0.25, 3.0))
    assert_allclose(disk.c_m_s, math.sqrt(2.0 / 3.0))


def test_partner_sets_the_speed_scale():
    g = Grain(E=210e9, nu=0.3, rho=7850, geometry="thin-disk")
    w = np.array([0.0, 1.0, 7.5])
    assert_allclose(g.v_over_c(w, "wall"), w / g.c_m_s)
    assert_allclose(g.v_over_c(w, "grain"), w / (2 * g.c_m_s))
    assert_allclose(g.speed_m_s(g.v_over_c(w, "grain"), "grain"), w)
    assert partner_factor("wall") == 1 and partner_factor("grain") == 2


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(E=1.0, nu=0.3, rho=1.0, geometry="cube"), "cylinder"),
        (dict(E=1.0, nu=0.5, rho=1.0, geometry="sphere"), r"\(-1, 0.5\)"),
        (dict(E=-1.0, nu=0.3, rho=1.0, geometry="cylinder"), "positive"),
        (dict(E=1.0, nu=0.5, rho=1.0, geometry="cylinder"), "nu < 0.5"),
        (dict(E=1.0, nu=0.3, rho=0.0, geometry="thin-disk"), "density"),
    ],
)
def test_bad_grains_are_refused(kwargs, match):
    with pytest.raises(InputError, match=match):
        Grain(**kwargs)


def test_negative_speed_and_unknown_partner_are_refused():
    g = Grain(E=1.0, nu=0.3, rho=1.0, geometry="thin-disk")
    with pytest.raises(InputError, match="non-negative"):
        g.v_over_c(-1.0, "wall")
    with pytest.raises(InputError, match="'wall' or 'grain'"):
        g.v_over_c(1.0, "floor")


@pytest.mark.parametrize("against, k", [("wall", 1.0), ("grain", 2.0)])
def test_glass_at_1_m_s_agrees_with_the_reduced_law(capsys, against, k):
    out = run_json(capsys, [*GLASS, "--against", against, "--speed", "1"])
    c = c_plane_strain(63e9, 0.2481, 2500.0)
    assert {"c_m_s", "nu_2d", "geometry", "against", "points"} <= out.keys()
    assert out["geometry"] == "cylinder" and out["against"] == against
    assert_allclose(out["c_m_s"], c, rtol=1e-12)
    assert_allclose(out["nu_2d"], 0.2481 / 0.7519, rtol=1e-12)
    (p,) = out["points"]
    assert set(p) >= {"speed_m_s", "v_over_c", "epsilon", "epsilon_err", "status"}
    v = 1.0 / (k * c)
    assert_allclose(p["v_over_c"], v, rtol=1e-12)
    reduced = restitution.law(0.33)
    lo, hi = reduced.valid_range
    if lo <= v <= hi:
        # Against a wall 1 m/s is v = 1.9e-4 c, between the law's collisions; two grains at
        # relative speed 1 m/s are v = 9.6e-5 c, among its low-speed points (quasistatic).
        assert abs(p["epsilon"] - reduced.epsilon(v)) <= reduced.epsilon_err(v) + 1e-15
        want = ("interpolated", "computed") if v >= 1e-4 else ("quasistatic",)
        assert p["status"].startswith(want)
    else:
        # Two grains at relative speed 1 m/s: v = 9.6e-5 c, below it. No number, the range said.
        assert p["epsilon"] is None and p["status"] == "outside"
        assert "below the lowest computed speed" in p["note"]
    if against == "wall":
        assert lo <= v <= hi  # the README's first example must be served


def test_rubber_like_cylinder_in_the_computed_range(capsys):
    out = run_json(capsys, [*RUBBER, "--against", "grain", "--speed", "1", "5", "10"])
    c = c_plane_strain(5e6, 0.47368, 1100.0)
    reduced = restitution.law(0.9)
    for p, w in zip(out["points"], [1.0, 5.0, 10.0], strict=True):
        v = w / (2 * c)
        assert_allclose(p["v_over_c"], v, rtol=1e-12)
        assert abs(p["epsilon"] - reduced.epsilon(v)) <= reduced.epsilon_err(v) + 1e-15
        assert p["status"] in STATUSES and p["status"] != "outside"


def test_speed_above_the_range_has_no_value(capsys):
    # Issue 45: the exit status says that a requested speed got no value (1, as for failed
    # collisions of a sweep); the JSON is written whole before it.
    with pytest.raises(SystemExit) as info:
        main(["law", *RUBBER, "--against", "wall", "--speed", "100", "--json"])
    assert info.value.code == 1
    out = capsys.readouterr()
    (p,) = json.loads(out.out)["points"]
    assert p["status"] == "outside" and p["epsilon"] is None
    assert "no value at 1 of the requested speeds" in out.err


def test_steel_cylinder_is_interpolated_between_its_grid_neighbours(capsys):
    """Steel as a long cylinder has nu_2d = 0.3 / 0.7 = 0.4286, between shipped laws: served by
    PCHIP in nu, which never leaves the interval of its two neighbours' values."""
    nus = shipped_nus()
    nu2 = 0.3 / 0.7
    lo = max(n for n in nus if n < nu2)
    hi = min(n for n in nus if n > nu2)
    args = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--geometry", "cylinder"]
    out = run_json(capsys, [*args, "--against", "wall", "--speed", "1", "50", "1000"])
    assert_allclose(out["nu_2d"], nu2, rtol=1e-12)
    c = c_plane_strain(210e9, 0.3, 7850.0)
    for p, w in zip(out["points"], [1.0, 50.0, 1000.0], strict=True):
        v = w / c
        a, b = restitution.law(lo).epsilon(v), restitution.law(hi).epsilon(v)
        assert p["status"].startswith("interpolated")
        assert_allclose(p["epsilon"], law_for(nu2).epsilon(v), rtol=1e-12)
        assert min(a, b) - 1e-12 <= p["epsilon"] <= max(a, b) + 1e-12
        # The error covers at least the interpolated point errors of the two neighbours.
        floor = min(restitution.law(lo).epsilon_err(v), restitution.law(hi).epsilon_err(v))
        assert p["epsilon_err"] >= floor


def test_nu_beyond_the_grid_is_refused_with_the_command_that_computes_it(capsys):
    """A nearly incompressible cylinder (3D nu = 0.49, nu_2d = 0.96) lies beyond the grid."""
    args = ["law", "--E", "5e6", "--nu", "0.49", "--rho", "1100", "--geometry", "cylinder"]
    with pytest.raises(SystemExit) as info:
        main([*args, "--against", "wall", "--speed", "1"])
    assert info.value.code == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Traceback" not in err
    assert "restitution curve --nu 0.960784" in err


def test_python_api_matches_the_command(capsys):
    s = si_law(E=63e9, nu=0.2481, rho=2500, geometry="cylinder", against="grain")
    out = run_json(capsys, [*GLASS, "--against", "grain", "--speed", "2", "26", "300"])
    # The command's JSON is the envelope (version, command, units, error_meaning, inputs, status,
    # advice) and then exactly what the Python API gives.
    payload = json.loads(json.dumps(s.to_dict([2, 26, 300])))
    head = ("version", "command", "units", "error_meaning", "inputs", "status", "advice")
    assert list(out)[: len(head)] == list(head)
    # The command's plausibility warnings about its inputs (none for glass) close it.
    assert out["warnings"] == []
    assert {k: v for k, v in out.items() if k not in (*head, "warnings")} == payload
    assert_allclose([p["epsilon"] for p in out["points"]], s.epsilon([2, 26, 300]))


def test_si_law_refuses_a_law_for_another_nu():
    from restitution.laws.si_law import SILaw

    grain = Grain(E=1.0, nu=0.3, rho=1.0, geometry="thin-disk")
    with pytest.raises(InputError, match="nu_2d"):
        SILaw(grain, "wall", restitution.law(0.33))


def test_docstring_examples():
    import doctest
    import importlib

    # restitution.laws.si_law is also the function's name in the package namespace (as law is).
    for module in map(
        importlib.import_module, ("restitution.laws.units", "restitution.laws.si_law")
    ):
        result = doctest.testmod(module)
        assert result.attempted > 0 and result.failed == 0


def test_text_output_names_partner_and_status(capsys):
    with pytest.raises(SystemExit) as info:
        main(["law", *RUBBER, "--against", "wall", "--speed", "0.000001", "5", "100"])
    assert info.value.code == 1  # a requested speed got no value
    captured = capsys.readouterr()
    assert "against wall: a rigid flat wall" in captured.out
    assert "c = 76.55" in captured.out
    # 1 um/s is v = 1.3e-8 c, below the law's lowest speed 1e-7 c (a low-speed point): the
    # low-speed route answers there (issue 45); 100 m/s is v = 1.3 c, above it: said, with no
    # number.
    rows = {line.split()[0]: line for line in captured.out.splitlines() if line[:2] == "  "}
    assert rows["1e-06"].split()[-1] == "quasistatic"
    assert rows["100"].split()[-1] == "outside"
    assert "note: outside:" in captured.err


def test_one_vocabulary_with_the_old_names_kept():
    """Issue 40: a *shape* is the real grain (cylinder, thin disk, sphere), a *kind* the modal
    body whose law serves it; ``geometry`` is kept as the old name of the shape."""
    from restitution.laws.si_law import si_law

    new = Grain(E=210e9, nu=0.3, rho=7850, shape="cylinder")
    old = Grain(E=210e9, nu=0.3, rho=7850, geometry="cylinder")
    assert new == old and new.geometry == new.shape == "cylinder" and new.kind.geometry == "disk"
    d = new.to_dict()
    assert (d["shape"], d["kind"], d["geometry"], d["body"]) == ("cylinder", "disk") * 2
    with pytest.raises(InputError, match="give one"):
        Grain(E=210e9, nu=0.3, rho=7850, shape="cylinder", geometry="sphere")
    # Both grains alike: the first as a Grain too.
    a = si_law(grain=new, against="wall")
    b = si_law(210e9, 0.3, 7850, "cylinder", "wall")
    assert a.points([1.0])[0].epsilon == b.points([1.0])[0].epsilon
    with pytest.raises(InputError, match="not both"):
        si_law(210e9, grain=new, against="wall")


def test_epsilon_at_takes_the_kind_by_name(tmp_path):
    """``epsilon_at(..., geometry="sphere")`` was a TypeError (issue 40)."""
    from dataclasses import replace

    from restitution.limits.curves import epsilon_at
    from restitution.limits.sweep import DEFAULTS

    point = epsilon_at(0.3, 0.02, geometry="sphere", run=False, store=tmp_path / "s.sqlite")
    assert point.settings.geometry == "sphere" and point.settings.n_modes[0] == 1600
    assert not point.asymptotic_ok  # nothing stored, nothing computed
    with pytest.raises(InputError, match="give one"):
        disk = replace(DEFAULTS, batch_size=3)  # a disk's settings, not the default object
        epsilon_at(0.3, 0.02, geometry="sphere", settings=disk, run=False)
