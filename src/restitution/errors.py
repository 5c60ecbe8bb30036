"""The package's exception hierarchy, and the checks of the Python API's arguments that raise it.

Every error a user can cause derives from :class:`RestitutionError`; the command line prints its
message on one line and exits with status 2, without a traceback. An argument of the wrong type
(``None``, a string, a list, a bool where a number belongs) is an :class:`InputError` too, from
the checks below: its message names the argument, what is allowed and what to pass instead.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

__all__ = [
    "RestitutionError",
    "CorruptFileError",
    "InputError",
    "OutputError",
    "PlausibilityWarning",
    "SchedulerError",
    "describe",
    "is_integer",
    "is_real",
    "is_real_array",
    "non_negative",
    "real",
    "real_array",
]


class RestitutionError(Exception):
    """Base class of all errors raised deliberately by this package."""


class InputError(RestitutionError, ValueError):
    """An input is outside its allowed range; the message names the range."""


class CorruptFileError(InputError):
    """A file the package wrote was changed after it was written (its content digest,
    :func:`restitution.jsonable.content_digest`, does not match), or carries no digest where one
    is required; the message names the file and what to do, ``reason`` says which in a few
    words (for a cache's warning)."""

    def __init__(self, message: str, reason: str = "it was changed after it was written") -> None:
        super().__init__(message)
        self.reason = reason


class SchedulerError(RestitutionError):
    """A Dask scheduler address is malformed, unreachable or not a Dask scheduler."""


class OutputError(RestitutionError):
    """An output file or directory cannot be written; the message names it and what to do."""


class PlausibilityWarning(UserWarning):
    """An input is allowed but outside the range of real grains and walls (a 5 m grain, a
    yield stress above any metal's): the run goes on, the message names the option, the range
    and, where a unit would bring the number into it, the number meant ("did you mean 3 mm =
    0.003?"). The ranges: :data:`restitution.laws.request_fields.PLAUSIBLE`."""


# -- argument checks -----------------------------------------------------------------------

_SHOWN = 60
"""Most characters of an argument's ``repr`` that a message shows."""


def describe(value) -> str:
    """``value`` for a one-line message: its ``repr`` on one line, cut to a few dozen
    characters, followed by its type where that is not a plain number.

    >>> describe("x")
    "'x' (str)"
    >>> describe(0.5)
    '0.5'
    """
    shown = " ".join(repr(value).split())
    if len(shown) > _SHOWN:
        shown = shown[: _SHOWN - 3] + "..."
    if is_real(value):
        return shown
    return f"{shown} ({type(value).__name__})"


def is_real(value) -> bool:
    """Whether ``value`` is one real number: a Python or NumPy integer or float (or a 0-d
    array of one), finite or not. A bool, a string, ``None``, a complex number or a sequence is
    not.

    >>> [is_real(x) for x in (1, 0.5, float("nan"), True, "1", None, [1.0])]
    [True, True, True, False, False, False, False]
    """
    if isinstance(value, bool | np.bool_):
        return False
    if isinstance(value, np.ndarray):
        return value.ndim == 0 and value.dtype.kind in "iuf"
    return isinstance(value, numbers.Real)


def is_integer(value) -> bool:
    """Whether ``value`` is a Python or NumPy integer (not a bool, not a float such as 10.0)."""
    return isinstance(value, int | np.integer) and not isinstance(value, bool | np.bool_)


def real(value, name: str, allowed: str = "", *, error: type[InputError] = InputError) -> float:
    """``float(value)`` if ``value`` is a finite real number (:func:`is_real`), else ``error``.

    Parameters
    ----------
    value
        The argument.
    name : str
        The argument's name, as the user wrote it (``"nu"``, ``"omega_max"``).
    allowed : str
        Its allowed range and unit, for the message, e.g. ``"in (-1, 1)"`` or ``"> 0 (Pa)"``.
        The caller checks the range itself; this checks type and finiteness only.
    error : type
        :class:`InputError` or one of its subclasses.

    Raises
    ------
    InputError
        ``"nu must be a number in (-1, 1), got 'x' (str); pass nu as a float"``.
    """
    where = f" {allowed}" if allowed else ""
    if not is_real(value):
        raise error(
            f"{name} must be a number{where}, got {describe(value)}; pass {name} as a float"
        )
    number = float(value)
    if not math.isfinite(number):
        raise error(f"{name} must be a finite number{where}, got {number!r}; pass a finite {name}")
    return number


def is_real_array(value) -> bool:
    """Whether ``value`` is a real number or an array (or nested list) of real numbers, finite
    or not: what ``numpy.asarray(value, dtype=float)`` reads without turning a bool into
    ``1.0``, parsing a string or turning ``None`` into ``nan``. A ragged list is not."""
    try:
        kind = np.asarray(value).dtype.kind
    except (TypeError, ValueError):  # ragged lists
        return False
    return kind in "iuf"


def real_array(value, name: str, allowed: str = "", *, error: type[InputError] = InputError):
    """``numpy.asarray(value, dtype=float)`` if :func:`is_real_array`, else ``error``;
    non-finite entries are left to the caller."""
    where = f" {allowed}" if allowed else ""
    if not is_real_array(value):
        raise error(
            f"{name} must be a number or an array of numbers{where}, got {describe(value)}; "
            f"pass {name} as a float or a list of floats"
        )
    return np.asarray(value, dtype=float)


def non_negative(value, name: str, unit: str, *, error: type[InputError] = InputError):
    """:func:`real_array` of ``value`` if every entry is finite and ``>= 0``, else ``error``
    (``unit`` names the unit in the message: ``"m/s"``, ``"c/R"``)."""
    arr = real_array(value, name, f"({unit})", error=error)
    if not np.all(np.isfinite(arr)) or np.any(arr < 0):
        raise error(
            f"{name} must be finite and non-negative ({unit}), got {describe(value)}; pass "
            f"{name} >= 0"
        )
    return arr
