"""A new partner is one object and its registration (issue 60): a toy partner kind defined here,
in the test, is served through the command line (``law --against mirror-grain``), Python
(``si_law(..., against="mirror-grain")``), the tables of ``--export`` and the LAMMPS plugin's
tables, without a module of the package edited for it.

The toy, a "mirror grain", is an identical grain under another name: speed scale 2 (each grain
moves at ``w / 2`` towards the contact plane, the rigid wall's problem at ``v = w / (2 c)``), a
grain-grain contact, the law on the wall. Every check compares with the package's own identical
grain (``against="grain"``), which it must equal number for number.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.laws.partners.base import (
    PartnerKind,
    against_choices,
    partner_for,
    partner_kind,
    partner_of,
    register_partner,
    unregister_partner,
)
from restitution.laws.partners.grain import KIND as GRAIN
from restitution.laws.partners.rigid_wall import rigid_contact
from restitution.laws.request import request
from restitution.laws.serve import serve
from restitution.laws.si_law import si_law

NAME = "mirror-grain"
GLASS = dict(E=63e9, nu=0.2481, rho=2500.0, shape="cylinder")
CLI_GLASS = ["--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--shape", "cylinder"]
SPEEDS = (0.1, 1.0, 10.0)


@dataclass(frozen=True)
class MirrorGrain:
    """An identical grain under another name (module docs)."""

    name: str = NAME
    against: str = NAME
    order: float = 50
    options: tuple[str, ...] = ()
    speed_factor: float = 2.0
    speed_meaning: str = "a mirror grain, relative normal speed w (v = w / (2 c))"
    body: type | None = None
    is_grain: bool = True
    loss: str | None = None
    quasistatic_note: str | None = None
    route_words: str = "mirror pair"
    model_words: str = "mirror grain"
    served_further: str = ""
    split_head: str = "        loss in grain 1 / 2"
    dem_mass: str = "two identical grains: m"
    dem_mass_line: str = "m;  // kg, effective mass of two identical grains"
    variance_factor: float = 2.0

    def matches(self, r) -> bool:
        return r.against == self.against

    def meaning(self, si) -> str:
        return self.speed_meaning

    def contact(self, si):
        return rigid_contact(si)  # two identical spheres: the wall's contact at w / 2

    def half_space(self, law):
        return None

    def slow_form(self, planar: bool):
        return None

    def read(self, law):
        return None

    def write(self, law, wall) -> None:
        """Nothing: the law on the wall serves it."""


@pytest.fixture
def mirror():
    kind = register_partner(MirrorGrain())
    yield kind
    unregister_partner(NAME)


def _numbers(points):
    return [(p.speed_m_s, p.v_over_c, p.epsilon, p.epsilon_err, p.status, p.note) for p in points]


def test_the_toy_is_a_partner_kind_and_is_offered_while_registered(mirror):
    assert isinstance(mirror, PartnerKind)
    assert partner_kind(NAME) is mirror
    assert against_choices() == ("wall", "grain", NAME)
    assert partner_for(request(**GLASS, against=NAME, speeds=SPEEDS)) is mirror


def test_without_the_toy_it_is_refused_in_one_line(cli):
    assert NAME not in against_choices()
    with pytest.raises(InputError, match=r"must be 'wall' or 'grain', got 'mirror-grain'"):
        si_law(**GLASS, against=NAME)
    code, _, err = cli("law", *CLI_GLASS, "--against", NAME, "--speed", "1")
    assert code != 0 and NAME in err


def test_si_law_serves_the_toy_as_the_identical_grain(mirror):
    toy = si_law(**GLASS, against=NAME)
    grain = si_law(**GLASS, against="grain")
    assert partner_of(toy) is mirror
    assert toy.k == grain.k == 2.0
    assert toy.speed_range_m_s == grain.speed_range_m_s
    assert _numbers(toy.points(SPEEDS)) == _numbers(grain.points(SPEEDS))
    assert toy.against_meaning == mirror.speed_meaning
    # The request in Python, as a notebook asks it.
    asked = {a: serve(request(**GLASS, against=a, speeds=SPEEDS)) for a in (NAME, "grain")}
    assert _numbers(asked[NAME].points) == _numbers(asked["grain"].points)
    assert _numbers(asked[NAME].points) == _numbers(grain.points(SPEEDS))


def test_the_command_line_serves_the_toy_as_the_identical_grain(mirror, cli):
    answers = {}
    for against in (NAME, "grain"):
        code, out, err = cli("law", *CLI_GLASS, "--against", against, "--speed", "0.1", "1",
                             "10", "--json")  # fmt: skip
        assert code == 0, err
        answers[against] = json.loads(out)
    toy, grain = answers[NAME], answers["grain"]
    assert toy["against"] == NAME and grain["against"] == "grain"
    assert toy["points"] == grain["points"]
    assert toy["status"] == grain["status"]


def _data(path) -> list[str]:
    """A file's lines without its comments."""
    return [x for x in path.read_text().splitlines() if not x.startswith(("#", "//", "!"))]


def _as_grain(text: str) -> str:
    """The toy's file with its partner named as the identical grain is (a file's head names the
    partner and what its speed means; a Maxwell constant names the partner of its variance)."""
    text = text.replace(f"{NAME}: {MirrorGrain.speed_meaning}", f"grain: {GRAIN.speed_meaning}")
    return _undated(text.replace(f"({NAME}: ", "(grain: "))


def _undated(text: str) -> str:
    """A file without the time it was written (the two folders are a second apart or not)."""
    return re.sub(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", "<time>", text)


@pytest.mark.parametrize("constant", [("--reference-speed", "1"),
                                      ("--maxwell-temperature", "0.01")])  # fmt: skip
def test_the_tables_and_the_plugin_tables_are_the_identical_grains(mirror, cli, tmp_path,
                                                                   constant):  # fmt: skip
    """The export folder with a constant (so with the DEM snippets, whose contact words and
    Maxwell gas's speed variance are the kind's)."""
    folders = {}
    for against in (NAME, "grain"):
        out = tmp_path / against
        code, _, err = cli("law", *CLI_GLASS, "--against", against, "--speed", "1",
                           *constant, "--export", str(out))  # fmt: skip
        assert code == 0, err
        folders[against] = out
    toy, grain = folders[NAME], folders["grain"]
    # The grains' contact (1-1) and the grain on the rigid wall: the exports of grains carry
    # both, from the partner kind's is_grain.
    for name in ("epsilon.csv", "epsilon_lammps_plugin_11.table",
                 "epsilon_lammps_plugin_wall1.table", "epsilon_lammps_plugin.in"):  # fmt: skip
        assert (toy / name).exists(), name
    # Every file of the folder (the DEM snippets too: their contact words are the kind's).
    names = sorted(p.name for p in grain.iterdir() if not p.name.startswith("."))
    assert sorted(p.name for p in toy.iterdir() if not p.name.startswith(".")) == names
    for name in names:
        assert _as_grain((toy / name).read_text()) == _undated((grain / name).read_text()), name
    rows = [x for x in _data(toy / "epsilon.csv") if x and not x.startswith("speed")]
    assert len(rows) > 10
    eps = np.array([float(r.split(",")[2]) for r in rows])
    assert np.all((eps > 0) & (eps <= 1))
    # Its head names the toy and what its speed means.
    head = [x for x in (toy / "epsilon.csv").read_text().splitlines() if x.startswith("#")]
    assert any(f"partner: {NAME}: {mirror.speed_meaning}" in x for x in head), head


def test_the_shipped_kinds_are_found_from_requests_and_law_files():
    """Which kind a request asks for (``matches``, in ``order``) and which one a law's file
    holds (``read``): the one place ``metadata["wall"]`` is read."""
    from restitution.bodies.pair.partner import Partner
    from restitution.bodies.wall import HalfSpace, Plate
    from restitution.laws.law import EpsilonLaw

    steel = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere", speeds=(1.0,))
    wall = dict(wall_E=63e9, wall_nu=0.25, wall_rho=2500.0)
    asked = {
        "wall": request(**steel, against="wall"),
        "grain": request(**steel, against="grain"),
        "half-space": request(**steel, against="wall", **wall),
        "plate": request(**steel, against="wall", **wall, wall_thickness=0.01, radius=0.005),
    }
    for name, r in asked.items():
        assert partner_for(r) is partner_kind(name) is r.partner_kind, name
    assert against_choices() == ("wall", "grain")
    law = EpsilonLaw.from_points(0.3, np.array([1e-3, 1e-2]), np.array([0.99, 0.98]),
                                 np.array([1e-3, 1e-3]), geometry="sphere")  # fmt: skip
    assert partner_of(law) is partner_kind("wall")
    for body in (HalfSpace(0.3, 0.3, 0.25), Plate(0.3, 0.3, 0.25, thickness=2.0)):
        held = EpsilonLaw.from_points(0.3, law.v, law.epsilon(law.v), law.epsilon_err(law.v),
                                      geometry="sphere")  # fmt: skip
        name = body.to_dict()["kind"]
        partner_kind(name).write(held, body)
        assert partner_of(held) is partner_kind(name)
        assert partner_of(held).read(held) == body.to_dict()
    pair = EpsilonLaw.from_points(0.3, law.v, law.epsilon(law.v), law.epsilon_err(law.v),
                                  geometry="sphere", partner=Partner(radius_ratio=2.0))  # fmt: skip
    assert partner_of(pair) is partner_kind("grain")
