"""The package's exception hierarchy.

Every error a user can cause derives from :class:`RestitutionError`; the command line prints its
message on one line and exits with status 2, without a traceback.
"""

from __future__ import annotations

__all__ = ["RestitutionError", "InputError", "OutputError", "SchedulerError"]


class RestitutionError(Exception):
    """Base class of all errors raised deliberately by this package."""


class InputError(RestitutionError, ValueError):
    """An input is outside its allowed range; the message names the range."""


class SchedulerError(RestitutionError):
    """A Dask scheduler address is malformed, unreachable or not a Dask scheduler."""


class OutputError(RestitutionError):
    """An output file or directory cannot be written; the message names it and what to do."""
