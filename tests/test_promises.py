"""What an answer promises about its errors, and advice that works when followed (issue 45,
items 5 and 6)."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

from restitution import si_law
from restitution.errors import InputError
from restitution.estimate import ERROR_MEANING

STEEL = dict(E=210e9, nu=0.3, rho=7850)


@pytest.fixture(scope="module")
def steel_sphere():
    return si_law(**STEEL, shape="sphere", against="grain")


def test_no_served_range_reaches_above_one(steel_sphere):
    """An elastic grain at rest before the impact only loses energy: epsilon_max is cut at 1,
    and a point whose epsilon + error exceeds 1 says so."""
    lo, hi = steel_sphere.speed_range_m_s
    points = steel_sphere.points(np.geomspace(lo, hi, 400))
    above = 0
    for p in points:
        d = p.to_dict()
        assert d["epsilon_max"] <= 1.0
        assert d["epsilon_min"] == pytest.approx(max(0.0, p.epsilon - p.epsilon_err), abs=0)
        if p.epsilon + p.epsilon_err > 1.0:
            above += 1
            assert d["epsilon_max"] == 1.0
            assert "epsilon + error exceeds 1" in p.note
    assert above > 0  # the steel sphere has such speeds (the low-speed points near epsilon = 1)


def test_every_json_says_what_its_errors_cover(cli):
    for args in (
        ["modes", "--nu", "0.33", "--count", "3"],
        ["law", *"--E 210e9 --nu 0.3 --rho 7850 --shape sphere --against wall".split(),
         "--speed", "1"],
        ["quasistatic", "--nu", "0.33", "--v", "0.01"],
    ):  # fmt: skip
        code, out, err = cli(*args, "--format", "json")
        assert code == 0, err
        assert json.loads(out)["error_meaning"] == ERROR_MEANING
    assert "standard deviation" in ERROR_MEANING and "upper estimate" in ERROR_MEANING


def test_the_advice_outside_a_laws_range_works_when_followed(steel_sphere):
    """``si_law(...).epsilon`` above the law's range says "pass outside='nan'"; doing so gives
    nan there and the law's value inside (issue 45: it used to be a TypeError). Below the
    range its low-speed route answers, as the command line does (issue 62: it raised there)."""
    _, hi = steel_sphere.speed_range_m_s
    with pytest.raises(InputError) as info:
        steel_sphere.epsilon(2.0 * hi)
    advice = re.search(r"pass (outside='nan')", str(info.value))
    assert advice is not None, str(info.value)
    assert math.isnan(steel_sphere.epsilon(2.0 * hi, outside="nan"))
    assert math.isnan(steel_sphere.epsilon_err(2.0 * hi, outside="nan"))
    both = steel_sphere.epsilon([0.5 * hi, 2.0 * hi], outside="nan")
    assert both[0] == steel_sphere.epsilon(0.5 * hi) and math.isnan(both[1])
    lo, _ = steel_sphere.speed_range_m_s
    (slow,) = steel_sphere.points([0.5 * lo])
    assert steel_sphere.epsilon(0.5 * lo) == slow.epsilon
    assert steel_sphere.epsilon_err(0.5 * lo) == slow.epsilon_err


def test_below_the_slowest_point_the_low_speed_route_answers(steel_sphere):
    """Issue 45: two steel spheres at 1 mm/s were ``outside``; the law's slowest points come
    from Rayleigh's estimate, which holds the slower the better, so it answers there, computed
    at that speed (no interpolation), and agrees with the law's own slowest point where they
    meet."""
    from restitution.laws.low_speed import low_speed_points

    lo, _ = steel_sphere.speed_range_m_s
    slow, at = steel_sphere.points([0.1 * lo, lo])
    assert slow.status == at.status == "quasistatic"
    assert "computed at this speed" in slow.note
    (record,), _ = low_speed_points(0.3, [slow.v_over_c], geometry="sphere")
    assert slow.epsilon == record["epsilon"]
    assert 1.0 - slow.epsilon < 1.0 - at.epsilon  # slower: less loss
    (again,), _ = low_speed_points(0.3, [at.v_over_c], geometry="sphere")
    assert abs(again["epsilon"] - at.epsilon) <= at.epsilon_err


def test_the_advice_below_a_law_works_when_followed():
    """The law in units of c, asked below its slowest point, names the call of its low-speed
    route (issue 45: it named `restitution epsilon --geometry sphere --v 9.67e-7`, which runs
    collisions for minutes where the route answers in a second); the call, made as written,
    answers at that speed."""
    from restitution.laws.law_load import law

    served = law(0.3, geometry="sphere")
    with pytest.raises(InputError) as info:
        served.epsilon(1e-7)
    call = re.search(r"(restitution\.laws\.low_speed\.low_speed_points\(.*?\))(?=, or)",
                     str(info.value))  # fmt: skip
    assert call is not None, str(info.value)
    import restitution.laws.low_speed  # noqa: F401 (the call's module)

    records, _ = eval(call.group(1), {"restitution": restitution, "v": 1e-7})  # noqa: S307
    assert records[0]["v"] == 1e-7 and 1.0 - records[0]["epsilon"] < 1e-7


@pytest.mark.parametrize(
    ("shape", "nu"), [("sphere", 0.49), ("sphere", 0.17), ("cylinder", 0.49)]
)  # a rubber-like sphere, fused silica, a rubber-like cylinder (nu_2d = 0.96)
def test_a_law_refused_off_the_grid_states_the_time_to_compute_it(cli, shape, nu):
    """Issue 45: the refusal names the collisions and the time of the computation it
    advises (the estimate of `law --compute`, laws.compute.plan)."""
    from restitution.laws.making.compute import plan
    from restitution.laws.si_law import Grain

    code, out, err = cli("law", "--E", "1e9", "--nu", str(nu), "--rho", "1000", "--shape",
                         shape, "--against", "wall", "--speed", "1")  # fmt: skip
    assert code == 2 and err.count("\n") == 1, err
    grain = Grain(E=1e9, nu=nu, rho=1000.0, shape=shape)
    p = plan(grain.law_nu, grain.kind.geometry, reuse=False)
    assert f"({p.collisions} collisions, about " in err and "on one core)" in err
    assert p.collisions > 0 and p.seconds > 0
