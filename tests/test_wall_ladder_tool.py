"""tools/residual_wall_ladder.py's bookkeeping (no point computed): which points it runs, and
that the file it writes holds every point it kept at every write, so an interrupted run loses
none (stop 76: a run that reordered its points wrote the file without those not yet reached)."""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path

import pytest

TOOLS = Path(__file__).resolve().parents[1] / "tools"
LADDER = Path(__file__).parent / "data" / "residual_wall_ladder.json"


@pytest.fixture
def tool(monkeypatch):
    monkeypatch.syspath_prepend(str(TOOLS))  # the tool imports its sibling residual_slow_points
    sys.modules.pop("residual_wall_ladder", None)
    return importlib.import_module("residual_wall_ladder")


def test_modal_points_are_the_laws_modal_points_up_to_the_speed(tool):
    """``--modal VMAX`` adds the shipped disk laws' modal points up to ``VMAX``, and only those;
    the laws serve none up to ``1e-3`` now (``--modal 0.001 --apply``, stop 76), but those
    above."""
    records = tool.law_records()
    assert tool.modal_points(1e-3) == []
    modal = tool.modal_points(3e-3)
    expected = {key for key, r in records.items() if r.get("route") == "modal" and key[1] <= 3e-3}
    assert modal and {(nu, v) for nu, v, _ in modal} == expected
    for nu, v, record in modal:
        assert 1e-3 < v <= 3e-3 and record == records[nu, v]


def test_an_interrupted_run_keeps_every_point_the_file_held(tool, tmp_path, monkeypatch):
    """A file with two kept points and one to compute between them (in the file's order): the
    run is interrupted in that point (``KeyboardInterrupt`` in its computation), after writing
    the first kept point; the file still holds both, as they were. The two points are the
    stored ladder's first two with today's code version: the tool keeps only points of its own
    version, and any edit of the disk's solver changes it (the stored file's may be older; stop
    80's edit of the wall nodes made it so)."""
    doc = json.loads(LADDER.read_text())
    version = tool._version("disk", False)
    kept = [{**p, "code_version": version} for p in doc["points"][:2]]
    out = tmp_path / "ladder.json"
    out.write_text(json.dumps({**doc, "points": kept}))
    assert [(p["nu"], p["v"]) for p in kept] == [(0.2, 1e-4), (0.2, 2e-4)]
    new = (0.2, 1.5e-4, {"route": "modal", "epsilon": 0.98, "epsilon_err": 1e-4, "status": "ok"})
    monkeypatch.setattr(tool, "residual_points", lambda: [new])
    monkeypatch.setattr(tool, "FIRST", ())
    monkeypatch.setattr(
        tool, "law_records", lambda: {(p["nu"], p["v"]): {"route": "residual"} for p in kept}
    )

    def interrupted(*args):
        raise KeyboardInterrupt

    monkeypatch.setattr(tool, "ladder_record", interrupted)
    with pytest.raises(KeyboardInterrupt):
        tool.main([str(out)])
    after = json.loads(out.read_text())["points"]
    assert after == sorted(kept, key=lambda p: (p["nu"], p["v"]))
