"""Every command prints its answer through one reporter chosen by ``--format text|json|csv``,
``--json`` its alias (issue 40, STYLE.md item 17): the JSON is the same document either way,
the CSV a table with a header, the text not empty; ``--json --format csv`` is one line; the
figure formats ``curve`` and ``paper`` took from ``--format`` before are still taken, with a
note (``--figure-format`` now). Small modes, fake sweeps and a stand-in paper run keep it to
seconds."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import pytest
from _cli_checks import one_line_error

from restitution.limits.store import Store
from restitution.limits.sweep import DEFAULTS, grid

TIMING = ("wall_time_s", "run_time_s")
GRID = ("--alphas", "20", "30", "40", "--alpha-scale", "absolute", "--modes", "10", "14", "20")
LAW = ("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500", "--geometry", "cylinder",
       "--against", "wall", "--speed", "0.5", "1")  # fmt: skip


def _untimed(obj):
    """The document without its wall-clock times (they differ from run to run)."""
    if isinstance(obj, dict):
        return {k: _untimed(v) for k, v in obj.items() if k not in TIMING}
    if isinstance(obj, list):
        return [_untimed(x) for x in obj]
    return obj


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """A store holding a stand-in sweep of nu = 0.33 at v = 0.1 and 0.2 (energy loss with
    known corrections in 1/alpha and 1/sqrt(N)): epsilon and curve read it, nothing runs."""
    path = tmp_path_factory.mktemp("reporters") / "s.sqlite"
    settings = replace(DEFAULTS, velocities=(0.1, 0.2), alphas=(20.0, 30.0, 40.0),
                       n_modes=(10, 14, 20), alpha_scale="absolute")  # fmt: skip
    with Store(path) as db:
        for spec in grid([0.33], settings):
            a, r = 1.0 / spec.alpha, 1.0 / math.sqrt(spec.n_modes)
            loss = 0.2 * spec.v / (0.1 + spec.v) + 3.0 * a - 0.2 * r + 4.0 * a * r
            db.put(spec, {"epsilon": math.sqrt(1.0 - loss), "energy_drift": 1e-9})
    return path


@pytest.fixture
def stand_in_paper(monkeypatch, tmp_path):
    """``restitution paper`` without its two minutes: build_paper answers a run with three
    verdicts at once (the arguments it was called with in ``calls``)."""
    import restitution.reproduction.paper as paper_module
    from restitution.reproduction.claims import Comparison

    calls = []

    def build_paper(out, settings, **kwargs):
        calls.append(kwargs)
        out = Path(out)
        return SimpleNamespace(
            data=SimpleNamespace(
                settings=settings,
                sweep_report=SimpleNamespace(total=4, computed=1, skipped=3, failed=()),
            ),
            comparisons=(
                Comparison("Fig. 1", "epsilon at v = 0.1", "0.94", "0.941", "agrees (1%)", True),
                Comparison("Table 1", "omega of (2, 0)", "1.44", "1.50", "differs by 4%", False),
                Comparison("Fig. 7", "trend", "falls", "-", "inconclusive: too few", None),
            ),
            run_time_s=1.0,
            report_html=out / "report.html",
            report_md=out / "report.md",
            record=out / "paper.json",
        )

    monkeypatch.setattr(paper_module, "build_paper", build_paper)
    return ("paper", "--quick", "--out", str(tmp_path / "paper"), "--no-progress"), calls


def _cases(store, tmp_path, paper_args):
    sweep, out = ("--store", str(store), "--no-progress"), str(tmp_path / "curve")
    cases = {
        "collide": "collide --v 0.1 --modes 8",
        "collide-pair": "collide --v 0.05 --radius-ratio 1.4 --modes 6",
        "collide-oblique": "collide --v 0.05 --alpha 100 --modes 6 --angle 45 --friction 0.5",
        "collide-mode": "collide --v 0.1 --modes 8 --excite mode --amplitude 0.01",
        "collide-thermal": "collide --v 0.1 --modes 8 --excite thermal --temperature 0.25 "
        "--samples 2",
        "bounce": "bounce --v 0.1 --modes 8 --collisions 2 --gravity 1e-5 --energy-tol 1e-5",
        "quasistatic": "quasistatic --v 0.01 --modes 10",
        "quasistatic-sphere": "quasistatic --geometry sphere --nu 0.3 --v 0.01 --modes 10",
        "quasistatic-pair": "quasistatic --v 0.02 --radius-ratio 1.4",
        "modes": "modes --count 5",
    }
    return {
        **{name: tuple(words.split()) for name, words in cases.items()},
        "epsilon": ("epsilon", "--nu", "0.33", "--v", "0.2", *GRID, *sweep),
        "curve": ("curve", "--nu", "0.33", "--v", "0.1", "0.2", *GRID, *sweep, "--out", out),
        "paper": paper_args,
        "law": LAW,
    }


ROWS = {  # rows of each case's CSV, and columns it must have
    "collide": (8, {"index", "n", "l", "omega", "energy_after"}),
    "collide-pair": (6, {"index", "body", "omega", "energy_after"}),
    "collide-oblique": (11, {"index", "family", "n", "l", "omega", "energy_after"}),
    "collide-mode": (8, {"index", "omega", "energy_before", "energy_after"}),
    "collide-thermal": (2, {"epsilon", "mode_energy_before", "mode_energy_after"}),
    "bounce": (2, {"k", "v", "epsilon", "v_constant_epsilon"}),
    "quasistatic": (1, {"nu", "v", "max_compression", "contact_time", "rayleigh_dominant_n"}),
    "quasistatic-sphere": (1, {"nu", "v", "max_compression", "contact_radius"}),
    "quasistatic-pair": (1, {"nu", "partner_nu", "partner_radius_ratio", "contact_time"}),
    "modes": (5, {"n", "l", "omega", "C", "S"}),
    "epsilon": (1, {"nu", "v", "epsilon", "epsilon_err", "status"}),
    "curve": (2, {"nu", "v", "epsilon", "epsilon_err", "asymptotic_ok", "status"}),
    "paper": (3, {"figure", "claim", "verdict", "agrees", "outcome"}),
    "law": (2, {"speed_m_s", "epsilon", "status"}),
}


@pytest.mark.parametrize("name", list(ROWS))
def test_every_command_prints_text_json_and_csv(cli, store, tmp_path, stand_in_paper, name):
    args = _cases(store, tmp_path, stand_in_paper[0])[name]
    code, out, err = cli(*args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["command"] == args[0] and {"version", "units", "inputs", "status"} <= set(doc)
    code, out, err = cli(*args, "--format", "json")
    assert code == 0, err
    assert _untimed(json.loads(out)) == _untimed(doc)
    code, out, err = cli(*args, "--format", "csv")
    assert code == 0, err
    header = next(csv.reader(io.StringIO(out)))
    rows = list(csv.DictReader(io.StringIO(out)))
    count, columns = ROWS[name]
    assert len(rows) == count and columns <= set(header), (header, len(rows))
    assert all(list(row) == header and None not in row.values() for row in rows)
    code, text, err = cli(*args)
    assert code == 0 and text.strip(), err
    assert not text.lstrip().startswith("{")  # the people's answer, not the JSON


COMMANDS = {
    "collide": ("collide", "--v", "0.1"),
    "bounce": ("bounce", "--v", "0.1", "--gravity", "1e-5"),
    "quasistatic": ("quasistatic", "--v", "0.01"),
    "epsilon": ("epsilon", "--nu", "0.33", "--v", "0.1"),
    "curve": ("curve",),
    "compare-fem": ("compare-fem",),
    "modes": ("modes",),
    "paper": ("paper",),
    "law": LAW,
}


@pytest.mark.parametrize("name", list(COMMANDS))
def test_json_and_csv_at_once_is_one_line(cli, name):
    code, out, err = cli(*COMMANDS[name], "--json", "--format", "csv")
    one_line_error(code, err, "--json is --format json", "--format csv")
    assert out == ""


def test_fem_collision_refuses_csv_before_it_runs(cli, monkeypatch):
    import restitution.fem

    monkeypatch.setattr(restitution.fem, "fem_collide", pytest.fail)
    code, out, err = cli("collide", "--method", "fem", "--v", "0.1", "--format", "csv")
    one_line_error(code, err, "`collide` answers no table", "no modes", "--format json")


def test_compare_fem_in_every_format(cli, monkeypatch):
    """One real comparison (the coarsest mesh, three small N), printed in every format."""
    import restitution.fem.compare as compare

    run, kept = compare.compare_fem_modal, []

    def once(*args, **kwargs):  # the finite elements once; the formats print the same answer
        if not kept:
            kept.append(run(*args, **kwargs))
        return kept[0]

    monkeypatch.setattr(compare, "compare_fem_modal", once)
    args = ("compare-fem", "--refine", "0", "--modes", "20,30,40")
    code, out, err = cli(*args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    code, out, err = cli(*args, "--format", "json")
    assert json.loads(out) == doc
    code, out, err = cli(*args, "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [r["method"] for r in rows] == ["fem", "modal", "modal", "modal", "fem finest",
                                           "modal N -> inf"]  # fmt: skip
    assert [r["n_modes"] for r in rows[1:4]] == ["20", "30", "40"]
    assert float(rows[0]["epsilon"]) == doc["fem"][0]["epsilon"]
    assert rows[4]["epsilon_err"] == ""  # one level: no error estimate (JSON: null)
    code, text, err = cli(*args)
    assert "FEM - modal" in text


def test_curve_takes_the_old_figure_format_with_a_note(cli, store, tmp_path):
    base = ("curve", "--nu", "0.33", "--v", "0.1", "0.2", *GRID, "--store", str(store),
            "--no-progress")  # fmt: skip
    code, out, err = cli(*base, "--out", str(tmp_path / "a"), "--format", "pdf")
    assert code == 0, err
    assert "use --figure-format pdf" in err and "fig01_epsilon.pdf" in out
    assert (tmp_path / "a" / "fig01_epsilon.pdf").is_file()
    code, out, err = cli(*base, "--out", str(tmp_path / "b"), "--figure-format", "svg", "--json")
    assert code == 0 and "figure-format" not in err, err
    doc = json.loads(out)
    assert doc["inputs"]["figure_format"] == "svg"
    assert (tmp_path / "b" / "fig01_epsilon.svg").is_file()
    assert [law["error"] for law in doc["laws"]] == [None]
    code, out, err = cli(*base, "--out", str(tmp_path / "c"), "--format", "pdf", "--figure-format",
                         "svg")  # fmt: skip
    one_line_error(code, err, "--format pdf is the old spelling of --figure-format pdf")


def test_paper_takes_the_old_figure_format_with_a_note(cli, stand_in_paper):
    args, calls = stand_in_paper
    code, out, err = cli(*args, "--format", "pdf")
    assert code == 0, err
    assert "use --figure-format pdf" in err and calls[-1]["fmt"] == "pdf"
    assert "claims of the paper: 1 agree, 1 differ, 1 inconclusive" in out
    code, out, err = cli(*args, "--figure-format", "pdf", "--format", "csv")
    assert code == 0 and "figure-format" not in err and calls[-1]["fmt"] == "pdf"
    code, out, err = cli(*args)
    assert calls[-1]["fmt"] == "svg"


def test_modes_table_is_text_with_a_note(cli, tmp_path):
    code, text, err = cli("modes", "--count", "4")
    code, same, err = cli("modes", "--count", "4", "--format", "text")
    assert code == 0 and same == text and err == ""
    code, table, err = cli("modes", "--count", "4", "--format", "table")
    assert code == 0 and table == text and "--format table is deprecated" in err
    code, out, err = cli("modes", "--count", "4", "--format", "csv", "--output",
                         str(tmp_path / "m.csv"))  # fmt: skip
    assert code == 0 and out == "" and "wrote" in err
    assert len(list(csv.DictReader(open(tmp_path / "m.csv")))) == 4


def test_a_new_output_format_is_one_registered_function(cli, monkeypatch):
    """Issue 40: an output format is one function registered with ``@reporter``; every
    command offers it at once."""
    from restitution.cli import report

    monkeypatch.setitem(report.REPORTERS, "keys", lambda r: " ".join(sorted(r.document())))
    code, out, err = cli("modes", "--nu", "0.33", "--count", "3", "--format", "keys")
    assert code == 0, err
    assert out.split() == sorted(["version", "command", "units", "error_meaning", "inputs",
                                  "status", "advice", "modes"])  # fmt: skip
