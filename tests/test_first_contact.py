"""What a new user meets first: the README, ``--help`` and the first outputs of ``law``.

The README's list of statuses is the code's :class:`restitution.status.Status`, it links every
page of docs/, every ``--option`` a command's help names is one it has (or is named with the
command that has it), the text of ``law`` ends its table before the notes start, the refusal of
a too cold Maxwell gas gives advice that works, and the damped law's long tabulation is
announced on stderr with the number of collisions it integrates.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import click
import pytest
from _cli_checks import one_line_error
from click.testing import CliRunner
from numpy.testing import assert_array_equal

from restitution.cli import cli as cli_group
from restitution.status import Status

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
RESTITUTION = str(Path(sys.executable).with_name("restitution"))
STEEL = ["--E", "210e9", "--nu", "0.3", "--rho", "7850"]


# -- the damped law's tabulation ---------------------------------------------------------------


def test_a_viscous_collision_advances_a_meter_once_per_speed():
    from restitution.quasistatic.hertz import contact_law
    from restitution.quasistatic.viscoelastic import viscous_collision

    law = contact_law(0.33)
    v = [1e-4, 1e-3, 1e-2]
    done = []
    metered = viscous_collision(law, v, 0.01, advance=done.append)
    assert done == [1, 1, 1]
    assert_array_equal(metered.epsilon, viscous_collision(law, v, 0.01).epsilon)


def test_a_damped_constant_announces_the_collisions_it_integrates(cli, monkeypatch):
    """The note on stderr says how many viscous collisions the damped law's table takes, that
    is how many it integrates, and stdout stays one JSON document."""
    from restitution.laws.damped import DampedLaw
    from restitution.quasistatic import viscoelastic

    calls = []
    collide_one = viscoelastic._collide_one
    monkeypatch.setattr(viscoelastic, "_collide_one", lambda *a: calls.append(1) or collide_one(*a))
    integrated = []
    as_si_law = DampedLaw.as_si_law

    def counted(self, progress=False):
        before = len(calls)
        out = as_si_law(self, progress)
        integrated.append(len(calls) - before)
        return out

    monkeypatch.setattr(DampedLaw, "as_si_law", counted)
    code, out, err = cli("law", *STEEL, "--shape", "cylinder", "--against", "wall",
                         "--relaxation-time", "2e-8", "--radius", "0.005", "--speed", "1",
                         "--reference-speed", "1", "--json")  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["constant"]["epsilon"] < 1.0
    announced = [int(m.group(1)) for m in re.finditer(r"note: .*?(\d+) viscous collisions", err)]
    assert announced == integrated
    assert integrated[0] > 100  # one per computed speed of the disk's law


# -- a too cold Maxwell gas: the advice works --------------------------------------------------


@pytest.mark.parametrize(
    "grain",
    [
        ["--shape", "cylinder", "--against", "wall"],  # 0.98 % below the law: the mean speed
        ["--shape", "sphere", "--against", "wall"],  # all below: the slowest served speed
        ["--shape", "cylinder", "--against", "grain", "--partner-radius-ratio", "1.4",
         "--partner-E", "63e9", "--partner-nu", "0.2481", "--partner-rho", "2500"],
    ],
)  # fmt: skip
def test_the_refusal_of_a_cold_maxwell_gas_gives_advice_that_works(cli, grain):
    """``--maxwell-temperature 1e-6`` (sigma = 1 mm/s) is below what the laws average; the
    refusal names the temperatures they do average and a --reference-speed, and both work."""

    base = ["law", *STEEL, *grain, "--speed", "1"]
    code, _, err = cli(*base, "--maxwell-temperature", "1e-6")
    line = one_line_error(code, err, "slower than", "--reference-speed")
    assert "higher temperature" not in line
    lowest = re.search(r"average only (\S+) <= T <= (\S+) m\^2/s\^2", line).group(1)
    speed = re.search(r"--reference-speed (\S+) \(", line).group(1)
    assert float(lowest) > 1e-6
    for advice in (["--maxwell-temperature", lowest], ["--reference-speed", speed]):
        code, out, err = cli(*base, *advice, "--json")
        assert code == 0, err
        d = json.loads(out)
        constant = d["type_pairs"]["1-2"] if "type_pairs" in d else d["constant"]
        assert 0.9 < constant["epsilon"] < 1.0


# -- every --option a help text names ----------------------------------------------------------

_OPTION = re.compile(r"(?<![\w-])--[A-Za-z][\w-]*")
_QUOTED = re.compile(r"`([^`]*)`")


def _options(command: click.Command) -> set[str]:
    """Every option ``command`` takes (its parameters as it parses: ``law`` adds the registered
    mechanisms' own options when it runs)."""
    params = command.get_params(click.Context(command))
    return {o for p in params for o in (*p.opts, *p.secondary_opts)} | {"--help"}


def _help(args: list[str]) -> str:
    """``--help`` of ``args`` as the group prints it, on one line per paragraph (no wrapping
    that could split an option at its hyphens)."""
    result = CliRunner().invoke(
        cli_group, [*args, "--help"], terminal_width=10**6, max_content_width=10**6
    )
    assert result.exit_code == 0, result.output
    return result.output


def _foreign_options(text: str, command: click.Command) -> list[str]:
    """The ``--options`` in ``text`` (the help of ``command``) that the command they are written
    with does not have. The rule: an option is ``command``'s own, or it sits in a quoted command
    line that starts with the name of the command that has it (`` `curve --radius-ratio R` ``,
    `` `restitution law --law-file` ``)."""
    bad = []
    outside = text
    for quoted in _QUOTED.findall(text):
        outside = outside.replace(f"`{quoted}`", " ", 1)
        words = quoted.split()
        if words[:1] == ["restitution"]:
            words = words[1:]
        other = cli_group.commands.get(words[0]) if words else None
        allowed = _options(other if other is not None else command)
        bad += [t for t in _OPTION.findall(quoted) if t not in allowed]
    own = _options(command)
    return bad + [t for t in _OPTION.findall(outside) if t not in own]


def test_the_rule_catches_an_option_the_command_does_not_have():
    epsilon = cli_group.commands["epsilon"]
    assert _foreign_options("give --nu and --plane", epsilon) == ["--plane"]
    assert _foreign_options("as `restitution law --law-file` reads it", epsilon) == []
    assert _foreign_options("as `law --plane` reads it", epsilon) == ["--plane"]
    assert _foreign_options("as `--law-file` says", epsilon) == ["--law-file"]


@pytest.mark.parametrize("name", [None, *sorted(cli_group.commands)])
def test_every_option_a_help_names_is_one_the_command_has(name):
    command = cli_group if name is None else cli_group.commands[name]
    text = _help([] if name is None else [name])
    assert _foreign_options(text, command) == []


# -- law's text: the table, then the notes -----------------------------------------------------


def test_law_text_ends_its_last_row_before_the_first_note_in_merged_output():
    """stdout (the table) ends with a newline, so with stderr (the notes) merged into it, as
    a terminal shows them, the last row and the first note are two lines."""
    argv = [RESTITUTION, "law", *STEEL, "--shape", "cylinder", "--against", "wall",
            "--speed", "1e-3", "0.01", "1"]  # fmt: skip
    merged = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert merged.returncode == 0, merged.stdout
    lines = merged.stdout.splitlines()
    first_note = next(i for i, line in enumerate(lines) if line.startswith("note: "))
    assert first_note > 0
    last_row = lines[first_note - 1].split()
    assert [float(x) for x in last_row[:2]] == [1.0, pytest.approx(1 / 5421.93, rel=5e-3)]
    assert last_row[-1] in set(Status)
    assert all("note: " not in line for line in lines[:first_note])  # no note inside a row
    # 1 m/s lies between the law's points at 1e-4 and 2e-4 c, the residual route's since the
    # slowest points were rerouted (they were modal and not asymptotic): no note of its own.
    assert {line.split(":")[1].strip() for line in lines[first_note:]} == {Status.QUASISTATIC}
    alone = subprocess.run(argv, capture_output=True, text=True)
    assert alone.stdout.endswith(" interpolated\n")
    assert alone.stderr.startswith("note: quasistatic: ")


# -- docs/materials.md: where a steel sphere's law starts --------------------------------------


def test_materials_page_states_the_sphere_law_s_served_range():
    """The page once said the sphere's laws start at 15.5 m/s (their first collision); the
    low-speed points serve down to v = 1e-6 c."""
    from restitution import si_law

    text = (ROOT / "docs" / "materials.md").read_text()
    stated = re.search(
        r"\"sphere\", \"wall\"\)\.speed_range_m_s` = \(([\d.]+), ([\d.]+)\) m/s", text
    )
    lo, hi = si_law(210e9, 0.3, 7850, "sphere", "wall").speed_range_m_s
    assert float(stated.group(1)) == pytest.approx(lo, rel=1e-4)
    assert float(stated.group(2)) == pytest.approx(hi, rel=1e-4)
    assert "from 5.2 mm/s for steel against a wall" in text and lo == pytest.approx(
        5.2e-3, rel=0.01
    )


# -- the README --------------------------------------------------------------------------------


def _section(text: str, title: str) -> str:
    """The README's section ``## title``, up to the next ``## ``."""
    start = text.index(f"\n## {title}\n")
    end = text.find("\n## ", start + 1)
    return text[start : end if end > 0 else None]


def test_readme_opens_with_its_title_and_the_two_commands():
    lines = README.read_text().splitlines()
    assert lines[0] == "# restitution"
    block = lines[lines.index("```sh") + 1 : lines.index("```")]
    assert [line.split()[:2] for line in block] == [["make", "paper"], ["make", "test"]]


def test_readme_lists_every_status_of_the_code_with_its_meaning():
    rows = re.findall(r"^\| `([a-z-]+)` \| ([^|]+) \| ([^|]+) \|$", _section(README.read_text(),
                      "Statuses"), re.M)  # fmt: skip
    listed = [status for status, _, _ in rows]
    assert sorted(listed) == sorted(s.value for s in Status)  # every member, once
    assert listed == [s.value for s in Status]  # in the enum's order
    for _, where, meaning in rows:
        assert where.strip() and len(meaning.split()) >= 8, meaning


def test_readme_links_every_page_of_the_docs_from_its_documentation_list():
    text = README.read_text()
    pages = {p.name for p in (ROOT / "docs").glob("*.md")}
    documentation = text[text.index("\nDocumentation: ") :].split("\n\n")[0]
    listed = set(re.findall(r"\]\(docs/([\w.-]+\.md)\)", documentation))
    assert listed == pages
    linked = set(re.findall(r"\]\(docs/([\w.-]+\.md)\)", text))
    assert linked <= pages  # and no link to a page that is not there


def test_readme_python_example_uses_the_current_spelling():
    """The first Python block calls ``restitution.law(nu)`` (``nu_2d=`` is its former keyword,
    kept as a deprecated alias) and what it serves is the same law."""
    import restitution

    block = re.search(r"```python\n(.*?)```", README.read_text(), re.S).group(1)
    assert "nu_2d=" not in block
    call = re.search(r"restitution\.law\(([^)]*)\)", block).group(1)
    assert call == "0.33"
    assert restitution.law(0.33).nu == restitution.law(nu_2d=0.33).nu == 0.33
