"""Command ``restitution paper``: regenerate every computed figure, Table 1 and the report.

Thin layer over :func:`restitution.reproduction.paper.build_paper`; progress is shown with rich on
stderr.
"""

from __future__ import annotations

from pathlib import Path

import click

from restitution.cli._common import PathOption
from restitution.cli.report import (
    Report,
    emit,
    figure_format,
    figure_format_option,
    format_options,
    output_format,
)
from restitution.status import Status

_VECTOR_FORMATS = ("svg", "pdf")
"""Vector formats written beside every PNG (``--figure-format``; ``--format`` before it named
the reporter)."""


class _StageProgress:
    """Shows the stages of a paper run with rich: a bar over the stages and one line each.

    The sweep draws its own progress bar; a second live display at the same time is not
    allowed, so the stage bar pauses while a stage with its own progress runs.
    """

    def __init__(self, enabled: bool | None, total: int) -> None:
        import sys

        from rich.console import Console
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            SpinnerColumn,
            TextColumn,
            TimeElapsedColumn,
        )

        self.console = Console(stderr=True)
        self.enabled = sys.stderr.isatty() if enabled is None else enabled
        self.progress = Progress(
            SpinnerColumn(),
            TextColumn("{task.description}"),
            BarColumn(),
            MofNCompleteColumn(),
            TimeElapsedColumn(),
            console=self.console,
            disable=not self.enabled,
            transient=True,
        )
        self.task = self.progress.add_task("paper", total=total)
        self.total = total

    def __enter__(self) -> _StageProgress:
        self.progress.start()
        return self

    def __exit__(self, *exc) -> None:
        self.progress.stop()

    def __call__(self, event) -> None:
        if event.kind == "start":
            self.progress.update(self.task, description=event.label)
            if event.own_progress:
                self.progress.stop()
            self.console.print(f"[{event.index + 1}/{self.total}] {event.label} ...")
            return
        if event.own_progress:
            self.progress.start()
        self.progress.advance(self.task)
        self.console.print(f"[{event.index + 1}/{self.total}] done in {event.seconds:.1f} s")


@click.command()
@click.option(
    "--quick",
    is_flag=True,
    help="Coarse grids through the same code (4 speeds, N = 20, 30, 40, small collisions): "
    "a check that everything runs; the numbers are not converged and every figure and the "
    "report say so.",
)
@click.option(
    "--out",
    type=PathOption(file_okay=False, path_type=Path),
    default=Path("paper-output"),
    show_default=True,
    help="Folder for the figures, Table 1 and report.html / report.md.",
)
@click.option(
    "--store",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Result store of the sweep (SQLite), shared with `restitution curve`; default: "
    "results.sqlite in the user cache directory. A second run reuses every stored collision.",
)
@click.option(
    "--workers",
    type=click.IntRange(min=1),
    default=None,
    help="Run the sweep on a local Dask cluster with this many worker processes "
    "(default: local processes on all cores).",
)
@click.option(
    "--scheduler",
    default=None,
    metavar="ADDRESS",
    help="Run the sweep on an existing Dask cluster, e.g. tcp://host:8786.",
)
@figure_format_option(_VECTOR_FORMATS, "svg", "Vector format written beside every PNG.")
@format_options(
    also=_VECTOR_FORMATS,
    also_help=" CSV: one row per claim of the paper judged. svg, pdf: the old spelling of "
    "--figure-format (deprecated).",
)
@click.option(
    "--c-only",
    is_flag=True,
    help="Read the paper's speeds in c only: skip the second Fig. 1 (speeds read in "
    "c_L = c/sqrt(1 - nu^2)) and its sweep, which doubles the collisions.",
)
@click.option(
    "--progress/--no-progress",
    default=None,
    help="Progress bars on stderr (default: when stderr is a terminal).",
)
def paper(quick, out, store, workers, scheduler, figure_fmt, fmt, as_json, c_only, progress):
    """Regenerate the paper: Figs. 1-3, 5-8, 10-12, Table 1 and a report comparing with it.

    Writes PNG and SVG (or PDF) figures, table1.md / table1.csv, report.html and report.md
    (the paper's stated values beside ours, "agrees" or "differs by ...", the errata, every
    parameter) and paper.json into --out. Speeds are the disk's speed towards the wall in
    units of c = sqrt(E/rho). The collisions of the sweep go through the result store, so a
    second run only redraws. --format json|csv prints the verdicts (the record of the run is
    paper.json either way).
    """
    from dataclasses import replace

    from restitution.reproduction.paper import FULL, QUICK, STAGES, build_paper

    fmt, figure_fmt = figure_format(fmt, figure_fmt, _VECTOR_FORMATS, "svg")
    fmt = output_format(fmt, as_json)
    settings = QUICK if quick else FULL
    if c_only:
        settings = replace(settings, speed_units=("c",))
    with _StageProgress(progress, len(STAGES)) as reporter:
        run = build_paper(
            out,
            settings,
            store=store,
            workers=workers,
            scheduler=scheduler,
            fmt=figure_fmt,
            progress=progress,
            on_stage=reporter,
        )
    inputs = {"quick": quick, "c_only": c_only, "out": str(out),
              "store": None if store is None else str(store),
              "figure_format": figure_fmt}  # fmt: skip
    emit(paper_report(run, inputs), fmt)
    return run


def paper_report(run, inputs: dict) -> Report:
    """The answer of ``restitution paper`` from its run (:class:`PaperRun`): the sweep, the
    verdicts on the paper's claims (the CSV: one row per claim) and the files."""
    from dataclasses import asdict

    from restitution.reproduction.claims import counts

    n = counts(run.comparisons)
    sr = run.data.sweep_report
    name = run.data.settings.name
    status, advice = Status.OK, None
    if sr.failed:
        status = Status.POINTS_FAILED
        advice = (
            f"{len(sr.failed)} collision(s) of the sweep failed (see {run.record.name}); rerun "
            "to retry them, or change the settings"
        )
    payload = {
        "settings": name,
        "run_time_s": run.run_time_s,
        "sweep": {"total": sr.total, "computed": sr.computed, "skipped": sr.skipped,
                  "failed": len(sr.failed)},
        "verdicts": n,
        "comparisons": [{**asdict(c), "outcome": c.outcome} for c in run.comparisons],
        "report_html": str(run.report_html),
        "report_md": str(run.report_md),
        "record": str(run.record),
    }  # fmt: skip

    def text() -> str:
        lines = [
            f"{name} run in {run.run_time_s:.0f} s: sweep {sr.computed} computed, "
            f"{sr.skipped} from the store, {len(sr.failed)} failed; claims of the paper: "
            f"{n['agrees']} agree, {n['differs']} differ, {n['inconclusive']} inconclusive"
        ]
        if name == "quick":
            lines.append("QUICK RUN: coarse grids, numbers not converged")
        for c in run.comparisons:
            if c.agrees is False and not c.detail:
                lines.append(f"  differs: {c.figure}: {c.claim}: {c.verdict}")
        lines.append(f"report: {run.report_html}  (and {run.report_md.name})")
        return "\n".join(lines)

    return Report("paper", inputs, payload, status, advice, text=text,
                  rows=lambda: payload["comparisons"])  # fmt: skip
