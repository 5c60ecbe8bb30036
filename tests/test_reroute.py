"""Points of a computed law replaced by another route's (issue 65, item 2): the law says which
points changed, from what, and every collision point names its route."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.making.reroute import before_rerouting, rerouted, write_shipped

DATA = Path(str(resources.files("restitution.laws").joinpath("data")))


def _record(v: float) -> dict:
    return {
        "v": v,
        "epsilon": 0.99,
        "epsilon_err": 1e-5,
        "asymptotic_ok": True,
        "status": "ok",
        "route": "residual",
        "message": "",
    }


def test_a_shipped_law_written_again_is_unchanged_byte_for_byte(tmp_path):
    path = DATA / "law_nu0.25.json"
    out = write_shipped(EpsilonLaw.from_json(path), tmp_path / path.name)
    assert out.read_bytes() == path.read_bytes()


def test_a_rerouted_point_replaces_the_old_one_and_the_law_says_so(tmp_path):
    old = before_rerouting(EpsilonLaw.from_json(DATA / "law_nu0.25.json"))
    assert "rerouted" not in old.metadata
    v = float(old.v[~old.quasistatic][3])
    new = rerouted(old, [_record(v)], parameters={"reason": "a test"})
    assert new.v.size == old.v.size and new.epsilon(v) == pytest.approx(0.99, rel=1e-12)
    change = new.metadata["rerouted"]
    assert change["reason"] == "a test" and change["routes"] == ["residual"]
    (point,) = change["points"]
    assert point["v"] == v and point["to"]["route"] == "residual"
    assert point["from"]["epsilon"] == pytest.approx(float(old.epsilon(v)), rel=1e-12)
    routes = {r.get("route") for r in new._records()}
    assert routes == {"modal", "residual", "quasistatic"}
    assert np.array_equal(before_rerouting(new).epsilon_points, old.epsilon_points)
    assert new.routes == ("modal", "quasistatic", "residual")
    again = EpsilonLaw.from_json(write_shipped(new, tmp_path / "law.json"))
    assert np.array_equal(again.epsilon_points, new.epsilon_points)
    assert again.metadata["rerouted"] == change


def test_only_collision_points_are_rerouted():
    old = EpsilonLaw.from_json(DATA / "law_nu0.25.json")
    slow = float(old.v[old.quasistatic][0])
    with pytest.raises(InputError, match="not a collision point"):
        rerouted(old, [_record(slow)], parameters={})
    with pytest.raises(InputError, match="names no route"):
        rerouted(old, [{**_record(float(old.v[-1])), "route": None}], parameters={})


def test_a_point_of_the_residual_route_is_not_the_modal_route_s_to_calibrate():
    """The calibration's rows (restitution.fem.calibrate) served by a rerouted point, or by an
    interval with one at either end, say ``residual``; the others stay ``modal``."""
    from restitution.fem.calibrate import _modal_row

    old = EpsilonLaw.from_json(DATA / "law_nu0.25.json")
    modal = old.v[~old.quasistatic]
    # The shipped law's points 4 to 7 (v = 0.002 to 0.0064) are modal; its slower ones are the
    # residual route's already.
    assert {r.get("route") for r in old._records() if 0.0019 < r["v"] < 0.007} == {"modal"}
    new = rerouted(old, [_record(float(modal[5]))], parameters={})
    routes = [
        _modal_row("test", new, float(v), 0.99, 1e-5).route
        for v in (modal[5], np.sqrt(modal[4] * modal[5]), np.sqrt(modal[5] * modal[6]), modal[7])
    ]
    assert routes == ["residual", "residual", "residual", "modal"]
    assert _modal_row("test", old, float(modal[5]), 0.99, 1e-5).route == "modal"


def test_a_nu_law_over_grid_laws_of_mixed_routes_serves_the_bound_where_one_is_uncalibrated():
    """The residual route is not calibrated (its sd is its bound); PCHIP in nu through grid laws
    of which one has a residual point there must then serve the bound, not a mixture."""
    from restitution.laws.law_load import law
    from restitution.laws.law_nu import law_for

    nodes = [law(x) for x in (0.2, 0.33, 0.5, 0.7, 0.9)]
    modal = nodes[1].v[~nodes[1].quasistatic]
    nodes[1] = rerouted(nodes[1], [_record(float(modal[0]))], parameters={})
    served = law_for(0.3, laws=nodes)
    v = np.geomspace(modal[0] / 2, modal[-1], 400)
    sd, err, cal = served.epsilon_sd(v), served.epsilon_err(v), served.sd_calibrated(v)
    assert (~cal).any() and cal.any()
    assert np.array_equal(sd[~cal], err[~cal])
    assert np.all(sd[cal] < err[cal])


def test_the_shipped_disk_laws_before_rerouting_are_their_modal_points():
    """Each rerouted speed of the shipped disk laws gives back the modal point it replaced (the
    calibration judges the modal route on these, docs/errors.md), and rerouting them again with
    the shipped records gives the shipped law. A speed rerouted twice (the residual route on
    the laws' walls, then on walls 160-640: tools/residual_wall_ladder.py --apply) lists the
    second change from the first one's point. A modal point rerouted while ``ok`` is one the
    ladder serves from 160-640 (``--modal 0.001``, up to ``v = 1e-3``)."""
    for path in sorted(DATA.glob("law_nu*.json")):
        shipped = EpsilonLaw.from_json(path)
        changes = shipped.metadata["rerouted"]["points"]
        modal = before_rerouting(shipped)
        assert set(modal.routes) == {"modal", "quasistatic"}
        last = {}
        for change in changes:
            (j,) = np.flatnonzero(np.abs(modal.v - change["v"]) <= 1e-9 * change["v"])
            if j in last:
                assert change["from"] == last[j]
            else:
                assert change["from"]["route"] == "modal"
                assert modal.epsilon_points[j] == change["from"]["epsilon"]
                if change["from"]["status"] == "ok":
                    # A modal point served from the wall ladder's 160-640 (--modal 0.001).
                    assert change["v"] <= 1e-3 and modal.asymptotic_ok[j]
                    (now,) = [r for r in shipped._records() if r["v"] == change["v"]]
                    assert now["residual"]["walls"] == [160.0, 320.0, 640.0]
                else:
                    assert not modal.asymptotic_ok[j]
            last[j] = change["to"]
        records = [r for r in shipped._records() if r.get("route") == "residual"]
        again = rerouted(modal, records, parameters={})
        assert np.array_equal(again.epsilon_points, shipped.epsilon_points)
        assert np.array_equal(again.epsilon_err_points, shipped.epsilon_err_points)
