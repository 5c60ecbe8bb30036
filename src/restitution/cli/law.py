"""Command ``restitution law``: epsilon of a real material at speeds in m/s, and exports.

Options -> one :class:`~restitution.laws.request.LawRequest` (its construction refuses what
does not go together) -> :func:`restitution.laws.serve.serve` -> one reporter (``--format``).
The options are the request's fields (their metadata holds names and help).
"""

from __future__ import annotations

import contextlib
import sys
import warnings
from dataclasses import MISSING, fields
from pathlib import Path

import click

from restitution.atomic import writing
from restitution.cli._common import (
    EXIT_FAILED_POINTS,
    LiveChoice,
    PathOption,
    check_figure_file,
    note,
    quiet,
    quiet_option,
)
from restitution.cli.epsilon import _ListCommand
from restitution.cli.law_text import oblique_lines, status_notes, text_lines
from restitution.cli.report import Report, emit, format_options, output_format
from restitution.errors import InputError, PlausibilityWarning, RestitutionError
from restitution.laws.mechanisms.base import extra_options
from restitution.laws.request import LawRequest, request

_TYPES = {
    "float": dict(type=float, default=None),
    "floats": dict(type=float, multiple=True),
    "file": dict(type=PathOption(dir_okay=False, exists=True, path_type=Path), default=None),
    "path": dict(type=PathOption(dir_okay=False, path_type=Path), default=None),
    "dir": dict(type=PathOption(file_okay=False, path_type=Path), default=None),
    "flag": dict(is_flag=True),
}


def _help(text) -> str:
    """A field's help: its text, or the text its callable gives (a registry's sentences)."""
    return text() if callable(text) else text


def _request_options(func):
    """One option per field of :class:`LawRequest`, in the fields' order (the mechanisms' own
    options, its ``extra``, are added when the command runs: :class:`_LawCommand`)."""
    for f in reversed(fields(LawRequest)):
        meta = f.metadata
        if meta["type"] == "extra":
            continue
        kwargs = dict(_TYPES.get(meta["type"], {}))
        if meta["type"] == "choice":
            kwargs = dict(type=LiveChoice(meta["choices"]))
        required = f.default is MISSING and f.default_factory is MISSING
        names = (meta["option"], *meta.get("aliases", ()))
        func = click.option(*names, f.name, required=required, help=_help(meta["help"]),
                            **kwargs)(func)  # fmt: skip
    return func


class _LawCommand(_ListCommand):
    """``law``'s options: the request's fields, and the options of every mechanism registered
    when the command runs (:func:`restitution.laws.mechanisms.base.extra_options`: a mechanism
    added in its own module brings its options)."""

    list_options = ("--speed",)

    def get_params(self, ctx: click.Context) -> list[click.Parameter]:
        params = super().get_params(ctx)
        have = {name for p in params for name in getattr(p, "opts", ())}
        extra = [click.Option([o.option], o.keyword, type=float, default=None,
                              help=f"{o.help} [{o.unit}]" if o.unit else o.help)
                 for o in extra_options() if o.option not in have]  # fmt: skip
        return [*params[:-1], *extra, params[-1]] if params else extra


class _Doubts:
    """The request's plausibility warnings (:class:`~restitution.errors.PlausibilityWarning`),
    each one ``warning:`` line on stderr before the first note of the work (so before anything
    long starts) or after the answer; a refusal that comes first carries them in its one line
    instead (a refused command says one line). :attr:`texts` keeps them all for the JSON's
    ``warnings``."""

    def __init__(self, texts: list[str]) -> None:
        self.texts = tuple(texts)
        self.pending = list(texts)

    def flush(self) -> None:
        for text in self.pending:
            note(f"warning: {text}")
        self.pending.clear()

    def note(self, text: str) -> None:
        self.flush()
        note(text)

    @contextlib.contextmanager
    def refusals(self):
        """Add the pending warnings to a refusal's line."""
        try:
            yield
        except RestitutionError as exc:
            if self.pending:
                exc.args = (f"{exc} (warning: {'; '.join(self.pending)})",)
            raise


def _request(options) -> tuple[LawRequest, _Doubts]:
    """The request of the options, and its plausibility warnings held back (:class:`_Doubts`);
    any other warning is shown as it comes."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlausibilityWarning)
        asked = request(**options)
    texts = []
    for w in caught:
        if issubclass(w.category, PlausibilityWarning):
            texts.append(str(w.message))
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    return asked, _Doubts(texts)


@click.command(cls=_LawCommand)
@_request_options
@click.option(
    "--plot",
    "plot_file",
    type=PathOption(dir_okay=False, path_type=Path),
    default=None,
    help="Also draw epsilon(w) over the law's range with its error band, the speeds computed "
    "by collisions and the asked speeds, to this file (format from its suffix: .png, .pdf, "
    ".svg, ...).",
)
@format_options
@quiet_option
def law(fmt, as_json, plot_file, **options):
    """Coefficient of restitution of a real material at impact speeds in m/s.

    Every speed comes with v/c, epsilon, its error and a status saying where the number comes
    from. A cylinder or thin disk is served by the disk's laws (2D Poisson number), a sphere by
    the sphere's (its own nu); a Poisson number without a law is refused with the command that
    computes it. Example (a glass cylinder against a wall):

    \b
    restitution law --E 63e9 --nu 0.2481 --rho 2500 --shape cylinder \\
        --against wall --speed 0.5 1 5

    Two grains of one material and different sizes: --against grain --partner-radius-ratio R
    (docs/materials.md). A partner of another material: add --partner-E, --partner-nu and
    --partner-rho. The law of a steel cylinder with a glass one 1.4 times as large is shipped:

    \b
    restitution law --E 210e9 --nu 0.3 --rho 7850 --shape cylinder \\
        --against grain --partner-radius-ratio 1.4 --partner-E 63e9 \\
        --partner-nu 0.2481 --partner-rho 2500 --speed 0.1 1 10

    Any other pair of materials is computed on demand with --compute (minutes, estimated before
    it starts; --route residual for equal radii: about half). Two spheres of any sizes and
    materials are answered at the asked speeds by their low-speed route (up to about 15 m/s for
    steel), in seconds:

    \b
    restitution law --E 210e9 --nu 0.3 --rho 7850 --shape sphere \\
        --against grain --partner-radius-ratio 2 --speed 0.01 0.1 1 10

    Material damping (a Kelvin-Voigt relaxation time) adds the viscous loss to the loss to
    vibrations, from one measured coefficient of restitution or from the relaxation time:

    \b
    restitution law --E 210e9 --nu 0.3 --rho 7850 --shape sphere \\
        --against wall --measured-epsilon 0.9 --measured-speed 1 --speed 0.1 1 10
    """
    fmt = output_format(fmt, as_json)
    request, doubts = _request(options)
    with doubts.refusals():
        answer = _answer(request, plot_file, doubts.note)
    doubts.flush()
    r = answer.request
    # The warnings in the JSON too: a script reading it sees what stderr said.
    payload = {**answer.to_dict(), "warnings": list(doubts.texts)}
    lines = oblique_lines if r.oblique else text_lines
    emit(Report("law", r.inputs(), payload, answer.status, answer.advice,
                answer.units, lambda: "\n".join(lines(answer)),
                lambda: [p.to_dict() for p in answer.points]), fmt)  # fmt: skip
    if fmt == "text" and not r.oblique:
        for line in status_notes(answer):
            note(line)
    missing = [p for p in answer.points if p.epsilon is None]
    if missing and options.get("speeds"):  # speeds the user asked (not the default ones)
        if fmt != "text":  # the text says it in its notes
            first = missing[0]
            note(f"no value at {len(missing)} of the requested speeds; at {first.speed_m_s:g} "
                 f"m/s: {first.note or first.status}")  # fmt: skip
        sys.exit(EXIT_FAILED_POINTS)


def _answer(request: LawRequest, plot_file, say):
    """The served answer, and its plot when asked (refused before anything is computed)."""
    from restitution.laws.mechanisms.base import answering
    from restitution.laws.serve import serve

    mechanism = answering(request)
    table = None if mechanism is None else getattr(mechanism, "table", None)
    if plot_file is not None:
        if request.oblique:
            raise InputError(
                "--plot draws a law at every speed; an oblique impact (--angle) is computed at "
                "the asked speeds only: leave out --plot and read the rows (--format csv)"
            )
        if mechanism is not None and table is None:
            raise InputError(
                f"--plot draws a law at every speed, which {mechanism.words} does not make "
                "yet; leave out --plot and read the rows (--format csv)"
            )
        check_figure_file(plot_file, "--plot")  # before anything is computed
    answer = serve(request, note=say, progress=not quiet())
    if plot_file is not None:
        drawn = answer.law
        if table is not None:  # the mechanism's law at every speed, the answer's points on it
            elastic = drawn
            if getattr(elastic.law, "at_points_only", False):
                from restitution.laws.routes.base import law_at_every_speed

                elastic = law_at_every_speed(request, say, not quiet())
            drawn = table(request, elastic, say, not quiet())
        with writing(plot_file, "--plot"):  # a full disk names the option and the file
            drawn.plot(plot_file, marks=answer.points)
        say(f"wrote {plot_file}")
    return answer
