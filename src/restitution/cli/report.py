"""Reporters: one answer of a command, printed as text, JSON or CSV.

A command builds one :class:`Report` -- the library's answer as the JSON body, its text
rendering and, where the answer is a table, its rows -- and :func:`emit` prints it with the
reporter that ``--format`` names (:data:`REPORTERS`, check-jsonschema's ``REPORTER_BY_NAME`` in
spirit). ``--json`` is kept as an alias of ``--format json``. Every JSON document goes through
one writer (:func:`restitution.cli._common.dumps`: strict JSON, ``null`` for a missing number,
the envelope's keys first).

A new output format is one function decorated with :func:`reporter`.

Two commands used ``--format`` for something else before it named the reporter: ``modes``
printed ``--format table`` (now ``text``; ``table`` is kept as its deprecated alias) and
``curve`` and ``paper`` took the figure format (now ``--figure-format``; a figure format given
to ``--format`` is still taken as one, with a note: :func:`figure_format`).
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import click

from restitution.cli._common import dumps, envelope, note, write_text
from restitution.errors import InputError
from restitution.status import Status

__all__ = [
    "REPORTERS",
    "Report",
    "emit",
    "figure_format",
    "figure_format_option",
    "format_options",
    "no_table",
    "output_format",
    "reporter",
    "rich_text",
]


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
    no_table : str or None
        Why the answer is no table (``rows`` is ``None``), for the CSV reporter's refusal.
    """

    command: str
    inputs: dict
    payload: dict
    status: str = Status.OK
    advice: str | None = None
    units: dict | None = None
    text: Callable[[], str] | None = None
    rows: Callable[[], list[dict]] | None = None
    no_table: str | None = None

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


def _cell(value):
    """A CSV cell: empty for a missing number (``None``, NaN, an infinity: JSON's ``null``)."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return ""
    return value


@reporter("csv")
def _csv(report: Report) -> str:
    if report.rows is None:
        raise no_table(report.command, report.no_table)
    rows = report.rows()
    columns = list(dict.fromkeys(key for row in rows for key in row))
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: _cell(v) for k, v in row.items()})
    return buf.getvalue().rstrip("\n")


def no_table(command: str, why: str | None = None) -> InputError:
    """The refusal of ``--format csv`` by a command whose answer is no table (raised by the CSV
    reporter, or by the command before it computes anything)."""
    why = f" ({why})" if why else ""
    return InputError(f"`{command}` answers no table{why}; use --format text or --format json")


def output_format(fmt: str | None, as_json: bool, aliases: dict[str, str] | None = None) -> str:
    """The format of ``--format`` and its alias ``--json`` (one line when they disagree).

    ``aliases`` maps a deprecated value of ``--format`` to the reporter it names (``modes``:
    ``table`` -> ``text``); the note saying so goes to stderr.
    """
    if as_json and fmt not in (None, "json"):
        raise InputError(f"--json is --format json; it contradicts --format {fmt}: give one")
    if fmt in (aliases or {}):
        note(f"note: --format {fmt} is deprecated; it is --format {aliases[fmt]}")
        fmt = aliases[fmt]
    return "json" if as_json else (fmt or "text")


class _Formats(click.Choice):
    """The choice of ``--format``: every registered reporter, read when the option is parsed
    (a reporter registered after the command was built counts), and a command's ``also``."""

    def __init__(self, also: tuple[str, ...] = ()) -> None:
        self.also = tuple(also)
        super().__init__([*REPORTERS, *self.also])

    def convert(self, value, param, ctx):
        self.choices = [*REPORTERS, *self.also]
        return super().convert(value, param, ctx)


def format_options(func=None, *, also: tuple[str, ...] = (), also_help: str = ""):
    """``--format text|json|csv`` and its alias ``--json``; the command receives ``fmt`` and
    ``as_json`` (resolved by :func:`output_format`).

    ``also``: further values ``--format`` accepts for the command's own reasons (an old
    meaning kept as a deprecated alias), explained by ``also_help``. Used bare
    (``@format_options``) or called (``@format_options(also=...)``).
    """

    def decorate(func):
        func = click.option(
            "--json", "as_json", is_flag=True, help="Print JSON (the same as --format json)."
        )(func)
        return click.option(
            "--format",
            "fmt",
            type=_Formats(also),
            default=None,
            help="Print the answer as text (default), JSON or a CSV table." + also_help,
        )(func)

    return decorate if func is None else decorate(func)


def figure_format_option(choices: tuple[str, ...], default: str, help: str):
    """``--figure-format``: the format of the figures a command draws (``choices``); left out,
    :func:`figure_format` gives ``default`` (or the old spelling ``--format``'s value)."""
    return click.option(
        "--figure-format",
        "figure_fmt",
        type=click.Choice(choices),
        default=None,
        help=f"{help} [default: {default}]",
    )


def figure_format(
    fmt: str | None, figure_fmt: str | None, choices: tuple[str, ...], default: str
) -> tuple[str | None, str]:
    """``(reporter format, figure format)`` of ``--format`` and ``--figure-format``.

    ``--format`` named the figure format before it named the reporter: a figure format given
    to it is still taken as one, with a note to use ``--figure-format`` (one line when the two
    disagree).
    """
    if fmt not in choices:
        return fmt, figure_fmt or default
    if figure_fmt is not None and figure_fmt != fmt:
        raise InputError(
            f"--format {fmt} is the old spelling of --figure-format {fmt}; it contradicts "
            f"--figure-format {figure_fmt}: give one"
        )
    note(f"note: --format {fmt} for the figures is deprecated; use --figure-format {fmt}")
    return None, fmt


def rich_text(draw: Callable) -> str:
    """What ``draw(console)`` prints with a rich console on stdout, as a string (with the
    console's styles when stdout is a terminal, as it would have printed them)."""
    from rich.console import Console

    console = Console()
    with console.capture() as captured:
        draw(console)
    return captured.get()


def emit(report: Report, fmt: str, output: Path | None = None) -> None:
    """Print ``report`` in the format ``fmt`` (:data:`REPORTERS`) on stdout, or write it to
    ``output`` (with a note on stderr)."""
    text = REPORTERS[fmt](report)
    if output is None:
        click.echo(text)
    else:
        write_text(text, output)
