"""``restitution paper``: compute, judge and write a reproduction of Gerl and Zippelius.

:func:`build_paper` is thin orchestration:
:func:`restitution.reproduction.paper.compute.compute_paper` computes,
:func:`restitution.reproduction.claims.compare` judges every claim,
:mod:`restitution.reproduction.paper.files` writes the figures, Table 1, the law exports and the
record, :mod:`restitution.reproduction.paper.report` lays out the report and
:mod:`restitution.reproduction.report` renders ``report.html`` (self-contained) and
``report.md``.
"""

from __future__ import annotations

import datetime
import os
import shutil
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

from restitution import atomic
from restitution._version import __version__
from restitution.errors import InputError
from restitution.reproduction.claims import Comparison
from restitution.reproduction.paper.compute import PaperData, StageEvent, _Stages, compute_paper
from restitution.reproduction.paper.files import (
    FigureFile,
    LawExport,
    to_json,
    write_figures,
    write_law_exports,
    write_sphere_figure,
    write_table1,
)
from restitution.reproduction.paper.settings import FULL, PaperSettings

__all__ = ["PaperRun", "build_paper"]


def _docs_dir() -> Path | None:
    """The project's ``docs`` folder when running from a source tree (src layout), else None."""
    candidate = Path(__file__).resolve().parents[4] / "docs"  # src/restitution/reproduction/paper
    return candidate if (candidate / "equations.md").is_file() else None


@dataclass(frozen=True, eq=False)
class PaperRun:
    """What :func:`build_paper` did.

    Attributes
    ----------
    out : Path
        Output folder.
    data : PaperData
        Every number behind the figures.
    comparisons : tuple of Comparison
    figures : tuple of FigureFile
    table1 : (Path, Path)
        ``table1.md`` and ``table1.csv``.
    report_html, report_md, record : Path
        ``report.html``, ``report.md`` and ``paper.json``.
    docs : tuple of Path
        Copies of the project's documentation linked from the report.
    laws : tuple of LawExport
        The epsilon(v) law of this run per Poisson number (JSON, CSV, plain table).
    spheres : Path or None
        ``sphere_cylinder.png`` (the shipped sphere laws beside cylinders), if drawn.
    started : str
        UTC start time, ISO 8601.
    run_time_s : float
        Wall-clock time of the whole run, seconds.
    timings : tuple of (str, float)
        ``(stage label, seconds)`` of every stage.
    """

    out: Path
    data: PaperData
    comparisons: tuple[Comparison, ...]
    figures: tuple[FigureFile, ...]
    table1: tuple[Path, Path]
    report_html: Path
    report_md: Path
    record: Path
    docs: tuple[Path, ...]
    laws: tuple[LawExport, ...]
    started: str
    run_time_s: float
    timings: tuple[tuple[str, float], ...] = field(default_factory=tuple)
    spheres: Path | None = None


def build_paper(
    out: str | os.PathLike = "paper-output",
    settings: PaperSettings = FULL,
    *,
    store=None,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
    fmt: str = "svg",
    progress: bool | None = None,
    on_stage: Callable[[StageEvent], None] | None = None,
) -> PaperRun:
    """Compute and write every figure, Table 1 and the report into ``out``.

    Parameters
    ----------
    out : path
        Output folder (created).
    settings : PaperSettings
        :data:`FULL` (default) or :data:`QUICK`.
    store : restitution.limits.store.Store or path, optional
        Result store of the sweep (default: the same as ``restitution curve``).
    workers, scheduler, client
        Executor of the sweep (:func:`restitution.limits.sweep.run_sweep`).
    fmt : {"svg", "pdf"}
        Vector format written beside every PNG.
    progress : bool, optional
        The sweep's progress bar (default: when stderr is a terminal).
    on_stage : callable, optional
        Called with a :class:`StageEvent` at the start and end of every stage.

    Returns
    -------
    PaperRun
    """
    from restitution.reproduction import report as rp
    from restitution.reproduction.claims import compare
    from restitution.reproduction.paper.report import paper_blocks

    if fmt not in ("svg", "pdf"):
        raise InputError(f"vector format must be 'svg' or 'pdf', not {fmt!r}")
    t0 = time.perf_counter()
    started = datetime.datetime.now(datetime.UTC).replace(microsecond=0).isoformat()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    data = compute_paper(
        settings,
        store=store,
        workers=workers,
        scheduler=scheduler,
        client=client,
        progress=progress,
        on_stage=on_stage,
    )
    stages = _Stages(on_stage)
    stages.timings.extend(data.timings)
    comparisons = compare(data)
    figures = stages.run("figures", lambda: write_figures(data, out, fmt))

    def report_stage():
        t1 = write_table1(data.table1, out)
        docs = _copy_docs(out)
        laws = write_law_exports(data.curves, out)
        spheres = write_sphere_figure(out)
        record = out / "paper.json"
        run = PaperRun(
            out=out,
            data=data,
            comparisons=comparisons,
            figures=figures,
            table1=t1,
            report_html=out / "report.html",
            report_md=out / "report.md",
            record=record,
            docs=docs,
            laws=laws,
            started=started,
            run_time_s=time.perf_counter() - t0,
            timings=tuple(stages.timings),
            spheres=spheres,
        )
        blocks = paper_blocks(run, store_path=_store_label(store))
        title = "Coefficient of restitution for elastic disks: reproduction report"
        atomic.write_text(run.report_md, rp.to_markdown(blocks))
        atomic.write_text(run.report_html, rp.to_html(blocks, title, base=out))
        atomic.write_text(record, to_json(_record(run, _store_label(store))))
        return run

    run = stages.run("report", report_stage)
    return replace(run, run_time_s=time.perf_counter() - t0, timings=tuple(stages.timings))


def _store_label(store) -> str:
    from restitution.limits.store import Store, default_store_path

    if store is None:
        return f"{default_store_path()} (default)"
    if isinstance(store, Store):
        return str(getattr(store, "path", store))
    return str(store)


def _copy_docs(out: Path) -> tuple[Path, ...]:
    src = _docs_dir()
    if src is None:
        return ()
    dst = out / "docs"
    dst.mkdir(exist_ok=True)
    copied = []
    for name in ("equations.md", "quasistatic.md", "spheres.md"):
        if (src / name).is_file():
            shutil.copyfile(src / name, dst / name)
            copied.append(dst / name)
    return tuple(copied)


def _record(run: PaperRun, store_label: str) -> dict:
    d = run.data
    sr = d.sweep_report
    from restitution.reproduction.claims import counts

    return {
        "format": "restitution-paper",
        "version": __version__,
        "code_version": _code_version(),
        "started": run.started,
        "run_time_s": run.run_time_s,
        "settings": d.settings.to_dict(),
        "store": store_label,
        "sweep": _sweep_record(sr),
        "sweeps_by_speed_unit": {u: _sweep_record(r) for u, r in d.sweep_reports.items()},
        "verdicts": counts(run.comparisons),
        "comparisons": [asdict(c) for c in run.comparisons],
        "epsilon": {
            unit: {
                "v_units": unit,
                **{
                    f"{nu:g}": {
                        "v": f.v[k],
                        "epsilon": f.epsilon[k],
                        "epsilon_err": f.epsilon_err[k],
                        "asymptotic_ok": f.asymptotic_ok[k],
                    }
                    for k, nu in enumerate(f.nus)
                },
            }
            for unit, f in d.fig01_units.items()
        },
        "timings": [{"stage": s, "seconds": t} for s, t in run.timings],
        "files": [p.name for f in run.figures for p in (f.png, f.vector)]
        + [p.name for p in run.table1]
        + [p.name for law in run.laws for p in (law.json, law.csv, law.table)],
    }


def _sweep_record(sr) -> dict:
    return {
        "total": sr.total,
        "skipped": sr.skipped,
        "computed": sr.computed,
        "failed": [{"point": asdict(p), "message": m} for p, m in sr.failed],
        "wall_time_s": sr.wall_time_s,
        "executor": sr.executor,
    }


def _code_version() -> str:
    from restitution.bodies.kinds import DEFAULT_GEOMETRY
    from restitution.provenance import code_version

    return code_version(DEFAULT_GEOMETRY)
