"""A law through the static residual (issue 46, item 3): :mod:`restitution.laws.making.residual_law`
and ``restitution law --compute --route residual``."""

import json

import pytest

from restitution.bodies.pair.partner import Partner
from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_load import law
from restitution.laws.making import residual_law as rl
from restitution.limits.run_options import Executor

GLASS_CYLINDER = ["--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--shape", "cylinder"]


def test_the_route_takes_the_production_speeds_and_refuses_what_it_cannot():
    """The speeds are the modal production's (the disk's 22; a pair's those of the pairs' plan,
    doubled); a pair of unequal radii and a body with no plan are refused in one line; the file
    name keeps the two routes' laws apart; the plan states speeds and time before anything
    runs."""
    assert len(rl.residual_speeds("disk")) == 22
    pair = Partner(modulus_ratio=0.3, density_ratio=0.32, nu=0.33)
    speeds = rl.residual_speeds("disk", pair)  # the pairs' groups: 1e-3 ... 0.3, doubled
    assert len(speeds) == 19 and speeds[0] == 2e-3 and speeds[-1] == pytest.approx(0.6)
    with pytest.raises(InputError, match="equal radii"):
        rl.check_route("disk", Partner(radius_ratio=1.4))
    with pytest.raises(InputError, match="no production plan for two spheres"):
        rl.check_route("sphere", Partner())
    assert rl.residual_filename(0.33) == "law_nu0.33_residual.json"
    p = rl.residual_plan(0.3, "sphere", out_dir="/nonexistent")
    assert not p.exists and p.speeds == 26 and p.seconds > 26 * 9.0
    assert "26 speeds" in p.words() and "residual route" in p.words()


@pytest.mark.slow  # 12-37 s (stop 70: the default run's budget)
def test_a_residual_law_says_its_route_and_resumes(tmp_path, monkeypatch):
    """Three speeds of the disk (``nu = 0.33``) through the route, no low-speed points: every
    point is ``route = "residual"`` with its three mode counts and walls, the model sentence
    names the route instead of the extrapolation in ``N``, and a second call finds the kept
    points (no collision runs: the point function is replaced by one that fails). The values
    agree with the shipped law (today's route) within 2 combined errors (measured: within
    0.6)."""
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path / "cache"))
    speeds = (0.1, 0.2, 0.3)
    path = rl.residual_law(0.33, out_dir=tmp_path / "out", speeds=speeds, low_speeds=(),
                           executor=Executor(workers=1))  # fmt: skip
    meta = json.loads(path.read_text())["metadata"]
    assert path.name == "law_nu0.33_residual.json"
    assert [p["route"] for p in meta["points"]] == ["residual"] * 3
    assert all(p["residual"]["n_modes"] == [200, 400, 800] for p in meta["points"])
    assert "static (residual flexibility)" in meta["model"] and "sqrt(N)" not in meta["model"]
    assert meta["residual"]["n_modes"] == [200, 400, 800]
    shipped = law(0.33)
    ours = EpsilonLaw.from_json(path)
    # The shipped law's slowest points are the residual route's too since 3 Dec 2026
    # (docs/numerics.md); the speeds compared here are modal points of it.
    assert ours.routes == ("residual",) and shipped.routes == ("modal", "quasistatic", "residual")
    assert {r["route"] for r in shipped._records() if r["v"] in speeds} == {"modal"}
    for v in speeds:
        err = (float(ours.epsilon_err(v)) ** 2 + float(shipped.epsilon_err(v)) ** 2) ** 0.5
        assert abs(float(ours.epsilon(v)) - float(shipped.epsilon(v))) < 2.0 * err, v

    def fail(task):
        raise AssertionError("a kept point was computed again")

    monkeypatch.setattr(rl, "_point", fail)
    path.unlink()
    again = rl.residual_law(0.33, out_dir=tmp_path / "out", speeds=speeds, low_speeds=(),
                            executor=Executor(workers=1))  # fmt: skip
    assert json.loads(again.read_text())["metadata"]["points"] == meta["points"]


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--route", "residual"], "belong to --compute"),
        (["--compute", "--route", "residual", "--store", "x.sqlite"], "leave out --store"),
        (["--compute", "--route", "residual", "--against", "grain", "--partner-radius-ratio",
          "1.4", "--partner-E", "210e9", "--partner-nu", "0.3", "--partner-rho", "7850"],
         "equal radii"),
    ],
)  # fmt: skip
def test_the_command_refuses_a_route_it_cannot_take(cli, extra, message):
    """One line, exit 2, before anything is computed."""
    args = ["law", *GLASS_CYLINDER, "--speed", "1"]
    if "--against" not in extra:
        args += ["--against", "wall"]
    code, out, err = cli(*args, *extra)
    assert code == 2, err
    assert message in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
