"""A library message in the words of the command that shows it.

The library names its inputs as Python does (``energy_tol``, ``max_steps``); a command line user
knows options (``--energy-tol``) and may have no way to set the rest. Every refusal and every
failure line a command prints passes through :func:`in_command_words` (issue 47: "CLI messages
that name Python arguments", advice that could not be followed from the command line):

* a name the command has an option for becomes that option;
* a collision setting the command has no option for (:class:`CollisionSettings
  <restitution.dynamics.settings.CollisionSettings>`) is marked as a setting of the Python
  API, where the advice can be followed;
* every other word is left as it is (names are matched whole, with an underscore, so prose such
  as "alpha" or a file name such as ``law_nu0.3.json`` is never touched).
"""

from __future__ import annotations

import dataclasses
import functools
import re

import click

__all__ = ["command_of", "current_command", "in_command_words"]

_NAME = re.compile(r"(?<![\w.\-/])[a-z][a-z0-9]*(?:_[a-z0-9]+)+(?![\w(/])")


@functools.cache
def _settings() -> frozenset[str]:
    from restitution.dynamics.settings import CollisionSettings

    return frozenset(f.name for f in dataclasses.fields(CollisionSettings) if "_" in f.name)


def command_of(group: click.Group, argv: list[str]) -> click.Command | None:
    """The subcommand of ``group`` that ``argv`` names (its first word that is not an option)."""
    for word in argv:
        if not word.startswith("-"):
            return group.commands.get(word)
    return None


def current_command() -> click.Command | None:
    """The command running now (inside a command's code), else ``None``."""
    ctx = click.get_current_context(silent=True)
    return None if ctx is None else ctx.command


def in_command_words(message: str, command: click.Command | None) -> str:
    """``message`` with the library's parameter names in ``command``'s words (module docs).

    >>> import click
    >>> @click.command()
    ... @click.option("--energy-tol", "energy_tol", type=float)
    ... def c(energy_tol): ...
    >>> in_command_words("raise energy_tol or max_steps", c)
    'raise --energy-tol or max_steps (a setting of the Python API only)'
    """
    if command is None:
        return message
    options = {
        p.name: p.opts[0]
        for p in command.params
        if isinstance(p, click.Option) and p.name and p.opts and p.opts[0].startswith("--")
    }

    def swap(match: re.Match) -> str:
        name = match.group(0)
        if name in options:
            return options[name]
        if name in _settings():
            return f"{name} (a setting of the Python API only)"
        return name

    return _NAME.sub(swap, message)
