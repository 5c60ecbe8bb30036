"""Reporters: one answer of a command, printed as text, JSON or CSV.

A command builds one :class:`Report` -- the library's answer as the JSON body, its text
rendering and, where the answer is a table, its rows -- and :func:`emit` prints it with the
reporter that ``--format`` names (:data:`REPORTERS`, check-jsonschema's ``REPORTER_BY_NAME`` in
spirit). ``--json`` is kept as an alias of ``--format json``. Every JSON document goes through
one writer (:func:`restitution.cli._common.dumps`: strict JSON, ``null`` for a missing number,
the envelope's keys first).

A new output format is one function decorated with :func:`reporter`.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Callable
from dataclasses import dataclass

import click

from restitution.cli._common import dumps, envelope
from restitution.errors import InputError
from restitution.status import Status

__all__ = ["REPORTERS", "Report", "emit", "format_options", "output_format", "reporter"]


@dataclass(frozen=True)
class Report:
    """What a command answers, before it is printed.

    Attributes
    ----------
    command : str
        The command's name (the envelope's ``command``).
    inputs : dict
        The options as given (the envelope's ``inputs``).
    payload : dict
        The answer's JSON body (after the envelope's keys).
    status, advice : str, str or None
        The answer's status and what to do about it.
    units : dict or None
        The units of its numbers (default: those of the body ``inputs["geometry"]``).
    text : callable or None
        ``text() -> str``: the answer for people.
    rows : callable or None
        ``rows() -> list of dict``: the answer as a table (one dict per row, the same keys);
        ``None`` when the answer is no table.
    """

    command: str
    inputs: dict
    payload: dict
    status: str = Status.OK
    advice: str | None = None
    units: dict | None = None
    text: Callable[[], str] | None = None
    rows: Callable[[], list[dict]] | None = None

    def document(self) -> dict:
        """The JSON document: the envelope, then the payload."""
        return envelope(self.command, self.inputs, self.payload, status=self.status,
                        advice=self.advice, units=self.units)  # fmt: skip


REPORTERS: dict[str, Callable[[Report], str]] = {}
"""Every output format by name (``--format``)."""


def reporter(name: str):
    """Register the decorated ``f(report) -> str`` as the output format ``name``."""

    def register(func: Callable[[Report], str]) -> Callable[[Report], str]:
        REPORTERS[name] = func
        return func

    return register


@reporter("text")
def _text(report: Report) -> str:
    if report.text is None:
        return dumps(report.document())
    return report.text().rstrip("\n")


@reporter("json")
def _json(report: Report) -> str:
    return dumps(report.document())


@reporter("csv")
def _csv(report: Report) -> str:
    if report.rows is None:
        raise InputError(f"`{report.command}` answers no table; use --format text or --format json")
    rows = report.rows()
    columns = list(dict.fromkeys(key for row in rows for key in row))
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: ("" if v is None else v) for k, v in row.items()})
    return buf.getvalue().rstrip("\n")


def output_format(fmt: str | None, as_json: bool) -> str:
    """The format of ``--format`` and its alias ``--json`` (one line when they disagree)."""
    if as_json and fmt not in (None, "json"):
        raise InputError(f"--json is --format json; it contradicts --format {fmt}: give one")
    return "json" if as_json else (fmt or "text")


def format_options(func):
    """``--format text|json|csv`` and its alias ``--json``; the command receives ``fmt``
    (resolved by :func:`output_format`)."""
    func = click.option(
        "--json", "as_json", is_flag=True, help="Print JSON (the same as --format json)."
    )(func)
    return click.option(
        "--format",
        "fmt",
        type=click.Choice(list(REPORTERS)),
        default=None,
        help="Print the answer as text (default), JSON or a CSV table.",
    )(func)


def emit(report: Report, fmt: str) -> None:
    """Print ``report`` in the format ``fmt`` (:data:`REPORTERS`) on stdout."""
    click.echo(REPORTERS[fmt](report))
