"""Cached laws and points are served only as they were written (the hostile-input issue,
"silently wrong"): every law file the package writes carries a content digest; a law of the
cache (``<cache>/laws``) changed after it was written, or written without a digest, is computed
again instead of served; a kept residual point that was changed or holds an impossible value is
computed again instead of refining the law; a user's law file with a wrong digest is refused in
one line naming it; a file without a digest (the shipped laws, older files) still loads.

The computations are replaced by cheap stand-ins (the production's ``build``, the residual
route's ``_point``): what is checked is which numbers are served, not the physics.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import re
import warnings
from concurrent.futures import ThreadPoolExecutor
from importlib import resources

import numpy as np
import pytest
from _cli_checks import one_line_error

from restitution.errors import CorruptFileError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.law_load import law
from restitution.laws.making import compute
from restitution.laws.making import residual_law as rl

STEEL = ("--E", "200e9", "--nu", "0.27", "--rho", "7800", "--geometry", "cylinder", "--against",
         "wall")  # fmt: skip
"""A steel-like cylinder: nu_2d = 0.27 / 0.73, no shipped law (as in test_law_compute)."""

NU = float(f"{0.27 / 0.73:.6g}")  # the law's nu as the cache names it: 0.369863
V = (1e-3, 0.01, 0.1, 0.5)


def _constant(nu, eps, geometry="disk"):
    """A law of ``epsilon = eps`` at every speed of ``V`` (PCHIP serves ``eps`` between)."""
    return EpsilonLaw.from_points(nu, V, [eps] * len(V), [1e-4] * len(V), geometry=geometry)


def _change_one_digit(path, old="0.9932", new="0.5932", which=0):
    """``path`` with occurrence ``which`` of ``old`` in its text (one point's epsilon) turned
    into ``new``."""
    head, *tails = path.read_text().split(old)
    assert len(tails) > which
    parts = [head] + [(new if k == which else old) + tail for k, tail in enumerate(tails)]
    path.write_text("".join(parts))


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


# -- the digest of a law file -------------------------------------------------------------


def test_a_law_file_carries_the_digest_of_its_canonical_content(tmp_path):
    """The digest is SHA-256 of the document without it, dumped with sorted keys and no
    spaces (computed here with hashlib and json directly); reading and writing again keeps it
    valid and the numbers exact."""
    path = _constant(0.37, 0.9932).to_json(tmp_path / "law.json")
    doc = json.loads(path.read_text())
    rest = {k: v for k, v in doc.items() if k != "digest"}
    canonical = json.dumps(rest, sort_keys=True, separators=(",", ":"))
    assert doc["digest"] == "sha256:" + hashlib.sha256(canonical.encode()).hexdigest()
    again = EpsilonLaw.from_json(path)
    assert again.epsilon_points.tolist() == [0.9932] * 4 and again.v.tolist() == list(V)
    second = again.to_json(tmp_path / "again.json")
    assert EpsilonLaw.from_json(second).epsilon(0.05) == 0.9932
    assert re.fullmatch(r"sha256:[0-9a-f]{64}", json.loads(second.read_text())["digest"])


def test_a_user_file_changed_after_it_was_written_is_refused_in_one_line(tmp_path, cli):
    """One digit of one epsilon changed: refused by the Python API and by ``--law-file``, in
    one line naming the file and the command that writes it again; not served."""
    path = _constant(NU, 0.9932).to_json(tmp_path / "mine.json")
    _change_one_digit(path)
    with pytest.raises(CorruptFileError) as info:
        law(path=path)
    message = str(info.value)
    assert "\n" not in message and str(path) in message
    assert "changed after it was written" in message
    assert f"restitution curve --nu {NU:g}" in message
    code, out, err = cli("law", *STEEL, "--speed", "1000", "--law-file", str(path))
    one_line_error(code, err, str(path), "changed after it was written", "restitution curve")
    assert out == ""


def test_a_file_without_a_digest_still_loads(tmp_path):
    """The shipped laws carry none (their numbers are not rewritten); a file of an older
    version (here one written now with its digest removed) loads with its values, and one
    with an impossible epsilon is still refused by the value checks."""
    text = resources.files("restitution.laws").joinpath("data", law_filename(0.33)).read_text()
    assert "digest" not in json.loads(text)
    shipped = law(0.33)
    assert shipped.epsilon_points.tolist() == [
        p["epsilon"] for p in json.loads(text)["metadata"]["points"]
    ]
    path = _constant(0.37, 0.9932).to_json(tmp_path / "old.json")
    doc = json.loads(path.read_text())
    del doc["digest"]
    path.write_text(json.dumps(doc))
    assert EpsilonLaw.from_json(path).epsilon(0.05) == 0.9932
    doc["metadata"]["points"][1]["epsilon"] = 1.7
    path.write_text(json.dumps(doc))
    with pytest.raises(ValueError, match="0 < epsilon <= 1"):
        EpsilonLaw.from_json(path)


# -- the cache of computed laws -----------------------------------------------------------


def _fake_build(calls, eps):
    """A stand-in for :func:`restitution.laws.making.production.build`: writes the constant law
    ``eps`` where the production would write the law, and counts its calls."""

    def build(out_dir, nus, groups, **kw):
        calls.append(list(nus))
        (nu,) = nus
        return [_constant(nu, eps).to_json(out_dir / law_filename(nu))]

    return build


@pytest.mark.parametrize("damage", ["one digit", "no digest", "epsilon 1.7"])
def test_a_damaged_cached_law_is_computed_again_not_served(cli, cache, monkeypatch, damage):
    """A law in ``<cache>/laws`` of epsilon 0.9932 whose one point was changed to 0.5932 (or
    whose digest was removed, or whose epsilon is 1.7 with the digest removed): ``law
    --compute`` warns once, moves it to ``.corrupt``, computes the law again (here 0.97
    everywhere) and serves that, exit 0; the next call serves the new file without
    computing."""
    path = compute.law_dir() / law_filename(NU)
    path.parent.mkdir(parents=True)
    _constant(NU, 0.9932).to_json(path)
    if damage == "one digit":
        _change_one_digit(path, which=2)  # the point at v = 0.1, below the asked 0.19
    else:
        doc = json.loads(path.read_text())
        doc.pop("digest", None)
        if damage == "epsilon 1.7":
            doc["metadata"]["points"][2]["epsilon"] = 1.7
        path.write_text(json.dumps(doc))
    damaged = path.read_text()
    calls = []
    monkeypatch.setattr("restitution.laws.making.production.build", _fake_build(calls, 0.97))
    args = ("law", *STEEL, "--speed", "1000", "--compute", "--force", "--json")
    code, out, err = cli(*args)
    assert code == 0, err
    (point,) = json.loads(out)["points"]
    assert point["epsilon"] == pytest.approx(0.97, abs=1e-12)  # the law computed again
    assert calls == [[pytest.approx(NU, abs=1e-6)]]
    warned = [line for line in err.splitlines() if line.startswith("warning:")]
    assert len(warned) == 1 and str(path) in warned[0] and "computed again" in warned[0]
    why = {"one digit": "changed after it was written", "no digest": "no content digest",
           "epsilon 1.7": "no content digest"}[damage]  # fmt: skip
    assert why in warned[0]
    assert path.with_name(path.name + ".corrupt").read_text() == damaged
    # The law computed again is served from then on, nothing computed.
    code, out, err = cli(*args)
    assert code == 0 and len(calls) == 1 and "using the law computed before" in err
    assert "warning" not in err
    assert json.loads(out)["points"][0]["epsilon"] == pytest.approx(0.97, abs=1e-12)


def test_computed_law_returns_the_recomputed_file_with_one_warning(cache, monkeypatch):
    """The library call: a changed cached law gives one warning and the path of the law
    computed again, whose values are the new ones."""
    path = compute.law_dir() / law_filename(NU)
    path.parent.mkdir(parents=True)
    _constant(NU, 0.9932).to_json(path)
    _change_one_digit(path)
    assert not compute.plan(NU).exists
    monkeypatch.setattr("restitution.laws.making.production.build", _fake_build([], 0.97))
    with pytest.warns(UserWarning, match="changed after it was written") as record:
        served = compute.computed_law(NU, force=True)
    assert len(record) == 1
    assert served == path and EpsilonLaw.from_json(served).epsilon(0.05) == 0.97


# -- the residual route: its law and its kept points --------------------------------------


@contextlib.contextmanager
def _in_this_process(**_):
    """A stand-in for the executors' pool: the points run one after the other, in one thread
    of this process (so the replaced point function is the one that runs)."""
    with ThreadPoolExecutor(max_workers=1) as pool:
        yield pool, "this process"


def _fake_point(computed):
    """A stand-in for the residual route's point: epsilon = 0.9 - 0.1 v, recorded in
    ``computed``."""

    def point(task):
        geometry, nu, v, partner = task
        computed.append(v)
        return {"v": v, "epsilon": 0.9 - 0.1 * v, "epsilon_err": 1e-4, "energy_loss": 0.19,
                "energy_loss_err": 2e-4, "asymptotic_ok": True, "status": "ok",
                "route": rl.RESIDUAL_ROUTE, "message": ""}  # fmt: skip

    return point


def _residual(**kw):
    return rl.residual_law(0.33, speeds=(0.1, 0.2, 0.3), low_speeds=(), refine_rounds=0,
                           force=True, **kw)  # fmt: skip


@pytest.fixture
def route(cache, monkeypatch):
    """The residual route with the stand-in point, run in this process; its computed speeds."""
    computed = []
    monkeypatch.setattr(rl, "_point", _fake_point(computed))
    monkeypatch.setattr("restitution.limits.executors.executor", _in_this_process)
    return computed


def test_kept_points_changed_or_impossible_are_computed_again(route, cache):
    """Kept points of three speeds: one kept as written (0.95, not what the stand-in gives:
    it is used), one whose epsilon 0.9932 was changed to 0.5932 after writing (its digest no
    longer matches), one written with epsilon 1.7 (its digest matches; the value cannot be a
    collision's). The two are dropped with one warning and computed again; the law holds
    0.95, 0.88 and 0.87, never 0.5932 or 1.7."""
    version = rl._version("disk", False)
    file = cache / "residual_points" / rl.residual_filename(0.33)
    kept = rl._Kept(file, version)
    for v, eps in ((0.1, 0.95), (0.2, 0.9932), (0.3, 1.7)):
        kept.add({**_fake_point([])((None, None, v, None)), "epsilon": eps})
    _change_one_digit(file)
    with pytest.warns(UserWarning, match="2 kept point") as record:
        path = _residual()
    (warned,) = (str(w.message) for w in record)
    assert (
        "v = 0.2 (its digest does not match)" in warned and "0.3 (it holds epsilon = 1.7" in warned
    )
    assert route == [0.2, 0.3]
    served = EpsilonLaw.from_json(path)
    np.testing.assert_allclose(served.epsilon_points, [0.95, 0.88, 0.87], rtol=0, atol=1e-15)
    # The kept file now holds the points computed again, each with a matching digest.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        again = rl._Kept(file, version)
    assert sorted(again.points) == ["0.1", "0.2", "0.3"]
    assert again.points["0.2"]["epsilon"] == pytest.approx(0.88, abs=1e-15)


def test_kept_points_without_digests_are_computed_again(route, cache):
    """A kept file of the format before digests (points alone) cannot be verified: its
    points are computed again, not used."""
    file = cache / "residual_points" / rl.residual_filename(0.33)
    file.parent.mkdir(parents=True)
    old = {str(v): _fake_point([])((None, None, v, None)) | {"epsilon": 0.5932}
           for v in (0.1, 0.2, 0.3)}  # fmt: skip
    file.write_text(json.dumps({"code_version": rl._version("disk", False), "points": old}))
    with pytest.warns(UserWarning, match="3 kept point"):
        path = _residual()
    assert route == [0.1, 0.2, 0.3]
    np.testing.assert_allclose(EpsilonLaw.from_json(path).epsilon_points, [0.89, 0.88, 0.87])


def test_a_changed_residual_law_in_the_cache_is_computed_again(route, cache):
    """The route's output found in ``<cache>/laws`` with one digit changed is not returned as
    it is: it is moved aside with a warning and the law is computed again."""
    path = compute.law_dir() / rl.residual_filename(0.33)
    path.parent.mkdir(parents=True)
    _constant(0.33, 0.9932).to_json(path)
    _change_one_digit(path)
    assert not rl.residual_plan(0.33).exists
    with pytest.warns(UserWarning, match="changed after it was written"):
        served = _residual()
    assert served == path and route == [0.1, 0.2, 0.3]
    np.testing.assert_allclose(EpsilonLaw.from_json(served).epsilon_points, [0.89, 0.88, 0.87])
    assert path.with_name(path.name + ".corrupt").is_file()
    assert rl.residual_plan(0.33).exists  # the new file is served from now on


# -- the finite elements' stored wall points ----------------------------------------------


def test_stored_wall_points_changed_or_impossible_are_not_served(cache):
    """A user's FEM point file written by the package (here by ``--merge`` of a part holding
    one shipped point) carries a digest: served as written; with one digit changed, not
    served and one warning; a point with epsilon 1.7 (file without digest) is not served."""
    from restitution.bodies.wall import wall_from_dict
    from restitution.fem.wall_reference import merge_wall_references
    from restitution.laws.wall_points import stored_wall_point, user_points_dir

    shipped = json.loads(
        resources.files("restitution.laws").joinpath("data", "fem_reference_wall.json").read_text()
    )
    point = shipped["points"][0]
    args = (point["nu"], wall_from_dict(point["wall"]), point["v"])
    part = cache.parent / "part.json"
    part.write_text(json.dumps({**shipped, "points": [point]}))
    out = user_points_dir() / "mine.json"
    out.parent.mkdir(parents=True)
    merge_wall_references(out, [part])
    assert json.loads(out.read_text())["digest"].startswith("sha256:")
    eps = point["epsilon"]
    found = stored_wall_point(*args, points=None)
    assert found["epsilon"] == eps
    # Served from the shipped file too; move the user's point away from it in speed.
    moved = 0.8 * point["v"]
    part.write_text(json.dumps({**shipped, "points": [dict(point, v=moved)]}))
    merge_wall_references(out, [part])
    assert stored_wall_point(args[0], args[1], moved)["epsilon"] == eps
    digits = repr(eps)[:8]
    changed = digits[:-1] + ("1" if digits[-1] != "1" else "2")
    _change_one_digit(out, digits, changed)
    with pytest.warns(UserWarning, match="changed after it was written"):
        assert stored_wall_point(args[0], args[1], moved) is None
    impossible = {**shipped, "points": [dict(point, v=moved, epsilon=1.7)]}
    out.write_text(json.dumps(impossible))
    assert stored_wall_point(args[0], args[1], moved) is None
