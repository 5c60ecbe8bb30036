"""Plausibility warnings for production use (issue 61): a yield stress above its material's
theoretical strength E/10 warns even where the absolute range lets it through, and the command
line's warnings, one stderr line each, are in its JSON too (``warnings``)."""

import json
import warnings

import pytest

from restitution.errors import PlausibilityWarning
from restitution.laws.request import LawRequest

STEEL = dict(E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall")
POLYMER = dict(E=3e9, nu=0.35, rho=1200.0, shape="sphere", against="wall")
LAW = ("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere", "--against",
       "wall", "--speed", "1")  # fmt: skip


def _caught(**args) -> list[str]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlausibilityWarning)
        LawRequest(**args)
    return [str(w.message) for w in caught if issubclass(w.category, PlausibilityWarning)]


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (dict(POLYMER, yield_stress=5e8),
         ["--yield-stress 5e+08 Pa is 0.167 times --E 3e+09 Pa", "theoretical strength",
          "E/10"]),
        (dict(STEEL, against="grain", partner_E=3e9, partner_nu=0.35, partner_rho=1200.0,
              partner_yield_stress=4e8),
         ["--partner-yield-stress 4e+08 Pa is 0.133 times --partner-E 3e+09 Pa"]),
    ],
)  # fmt: skip
def test_a_yield_stress_above_a_tenth_of_its_modulus_warns_once(args, words):
    (text,) = _caught(**args)
    for w in words:
        assert w in text, (w, text)


@pytest.mark.parametrize(
    "args",
    [
        dict(POLYMER, yield_stress=5e7),  # a polymer's yield stress, E/60
        dict(STEEL, yield_stress=1.5e9),  # a hard steel, E/140
        dict(STEEL, yield_stress=30e9),  # above every metal's: that warning alone, not twice
    ],
)
def test_real_yield_stresses_do_not_warn_for_their_modulus(args):
    texts = _caught(**args)
    assert not [t for t in texts if "theoretical strength" in t], texts
    assert len(texts) == (1 if args["yield_stress"] > 1e10 else 0), texts


def test_the_json_lists_the_warnings_stderr_says(cli):
    code, out, err = cli(*LAW, "--radius", "5", "--relaxation-time", "1e-6", "--format", "json")
    assert code == 0, err
    lines = [x for x in err.splitlines() if x.startswith("warning: ")]
    assert len(lines) == 1
    assert json.loads(out)["warnings"] == [lines[0].removeprefix("warning: ")]
    code, out, err = cli(*LAW, "--format", "json")
    assert code == 0 and json.loads(out)["warnings"] == [] and "warning" not in err
