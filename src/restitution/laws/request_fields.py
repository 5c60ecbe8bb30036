"""The typed fields of a request: each option's kind, unit and bound, checked once at the API edge.

Units: those of :mod:`restitution.laws.request` (SI: Pa, kg/m^3, m/s, m, s, m^2/s^2); a field's
metadata names its own.

A field of :class:`~restitution.laws.request.LawRequest` carries in its metadata
(:func:`option`) the command-line option that sets it, its help, its kind and, for a number, its
unit and whether it must be positive. The command line converts its strings by the kind before
the request is built; :func:`checked` gives a value passed in Python the same form (a float, a
tuple of floats, one of the choices, a :class:`~pathlib.Path`, a bool) or refuses it in one line
that names the option, the Python keyword, the value's type and the unit. A string is not a
number in Python: ``wall_E='63e9'`` is refused with the number it seems to mean
(``give a number, e.g. wall_E=63e9``), not parsed.
"""

from __future__ import annotations

import difflib
import math
import os
from collections.abc import Iterable, Mapping, Set
from pathlib import Path

import numpy as np

from restitution.errors import InputError, describe, is_real

__all__ = ["KINDS", "checked", "option"]

KINDS = ("float", "floats", "choice", "file", "path", "dir", "flag")
"""A field's kind: one number, numbers (one or several after the flag), one of a few strings,
an existing file, a file to write, a directory, a flag."""

_PATH_EXAMPLES = {"file": "law.json", "path": "results.sqlite", "dir": "exports"}
"""A path of each path kind, for the advice of a refusal."""


def option(
    name: str, help: str, type: str = "float", *, unit: str = "", positive: bool = False, **extra
) -> dict:
    """Field metadata: the command-line option ``name`` of a field, its ``help``, its kind
    ``type`` (:data:`KINDS`) and, for a number, its ``unit`` (``""``: dimensionless) and whether
    it must be ``positive``; ``extra`` holds ``choices`` (a callable giving the allowed strings)
    and ``aliases``."""
    if type not in KINDS:
        raise ValueError(f"unknown option kind {type!r}; one of {KINDS}")
    return {"option": name, "help": help, "type": type, "unit": unit, "positive": positive,
            **extra}  # fmt: skip


def checked(f, value):
    """``value`` of the request field ``f`` (a :class:`dataclasses.Field` whose metadata
    :func:`option` made) in the command line's form, or :class:`InputError`. ``None`` is "not
    given" where the field's default is ``None``; numbers of kind ``floats`` without one (``None``
    or empty) are the field's default."""
    meta = f.metadata
    kind = meta["type"]
    if value is None and f.default is None:
        return None
    if kind == "floats":
        return f.default if value is None else (_floats(value, meta, f.name) or f.default)
    return _CHECKS[kind](value, meta, f.name)


def _unit(meta) -> str:
    return meta.get("unit") or "dimensionless"


def _typed(value) -> str:
    """:func:`describe` with the type always said (a number is the wrong type here)."""
    return f"{describe(value)} ({type(value).__name__})" if is_real(value) else describe(value)


def _meant(value) -> str | None:
    """The number a value of the wrong type seems to mean, as the user would write it: the text
    of a string that parses (``'63e9'``), the one entry of a list or array, a complex number's
    real part; ``None`` when it means none."""
    if isinstance(value, str):
        try:
            number = float(value)
        except ValueError:
            return None
        return value.strip() if math.isfinite(number) else None
    if isinstance(value, bool | np.bool_ | Mapping):
        return None
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        return None
    if arr.size != 1 or arr.dtype.kind not in "iufc":
        return None
    number = complex(arr.reshape(()).item())
    if number.imag != 0 or not math.isfinite(number.real):
        return None
    return f"{number.real:g}"


def _float(value, meta, name: str) -> float:
    opt, unit = meta["option"], _unit(meta)
    if not is_real(value):
        meant = _meant(value)
        advice = f"give a number, e.g. {name}={meant}" if meant else f"give {name} as a float"
        raise InputError(f"{opt} must be a number ({unit}), got {describe(value)}; {advice}")
    number = float(value)
    if not math.isfinite(number):
        bound = " > 0" if meta.get("positive") else ""
        raise InputError(
            f"{opt} must be a finite number{bound} ({unit}), got {number!r}; give a finite "
            f"{name}{bound}"
        )
    if meta.get("positive") and not number > 0:
        raise InputError(
            f"{opt} must be a positive number ({unit}), got {number!r}; give {name} > 0"
        )
    return number


def _floats(value, meta, name: str) -> tuple[float, ...]:
    """One number or a 1-D sequence or array of them (a 0-d array is one), each finite and
    positive (the one kind of several numbers: speeds)."""
    opt, unit = meta["option"], _unit(meta)
    if is_real(value):
        items = [value]
    elif (isinstance(value, np.ndarray) and value.ndim == 1) or (
        isinstance(value, Iterable)
        and not isinstance(value, str | bytes | Mapping | Set | np.ndarray)
    ):
        items = list(value)
    else:
        meant = _meant(value)
        raise InputError(
            f"{opt} must be a number or a 1-D list of numbers ({unit}), got {describe(value)}; "
            f"give e.g. {name}=[{meant or '1.0'}]"
        )
    numbers = []
    for w in items:
        if not is_real(w):
            meant = _meant(w)
            raise InputError(
                f"{opt} must be numbers ({unit}), got {describe(w)} among {describe(value)}; "
                f"give e.g. {name}=[{meant or '1.0'}]"
            )
        number = float(w)
        # > 0: at rest there is no collision (issue 47: 0 reached the routes, which refused it
        # in their own words, "need v > 0 and spread >= 0")
        if not (math.isfinite(number) and number > 0.0):
            raise InputError(
                f"{opt} must be a finite number > 0 ({unit}), got {number!r}; give {name} > 0"
            )
        numbers.append(number)
    return tuple(numbers)


def _choice(value, meta, name: str) -> str:
    choices = list(meta["choices"]())
    if isinstance(value, str) and value in choices:
        return str(value)
    close = difflib.get_close_matches(value, choices, n=1) if isinstance(value, str) else []
    advice = f"{name}={close[0]!r}" if close else f"one of them, e.g. {name}={choices[0]!r}"
    raise InputError(
        f"{meta['option']} must be one of {', '.join(map(repr, choices))}, got "
        f"{_typed(value)}; give {advice}"
    )


def _path(value, meta, name: str) -> Path:
    opt = meta["option"]
    if isinstance(value, str) and not value.strip():
        # issue 47: an empty path named the working directory and the files went there
        raise InputError(f"{opt} is empty; give {name} a path ('.' for the working directory)")
    if isinstance(value, str) or (
        isinstance(value, os.PathLike) and isinstance(os.fspath(value), str)
    ):
        return Path(value)
    raise InputError(
        f"{opt} must be a path (str or os.PathLike), got {_typed(value)}; give e.g. "
        f"{name}='{_PATH_EXAMPLES[meta['type']]}'"
    )


def _flag(value, meta, name: str) -> bool:
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise InputError(
        f"{meta['option']} is a flag: give {name}=True or {name}=False, got {_typed(value)}"
    )


_CHECKS = {"float": _float, "choice": _choice, "file": _path, "path": _path, "dir": _path,
           "flag": _flag}  # fmt: skip
