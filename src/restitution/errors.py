"""The package's exception hierarchy.

Every error a user can cause derives from :class:`RestitutionError`; the command line prints its
message on one line and exits with status 2, without a traceback.
"""

from __future__ import annotations

__all__ = ["RestitutionError", "InputError"]


class RestitutionError(Exception):
    """Base class of all errors raised deliberately by this package."""


class InputError(RestitutionError, ValueError):
    """An input is outside its allowed range; the message names the range."""
