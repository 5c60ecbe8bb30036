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

A value allowed but outside the range of real grains and walls (:data:`PLAUSIBLE`: a 5 m grain,
a plate 600 radii thick, a yield stress above any metal's or above its material's theoretical
strength ``E/10``, a friction coefficient of 1e300) is not refused: the request warns once
(:func:`warn_implausible`, a :class:`~restitution.errors.PlausibilityWarning` naming the option,
the range and, where a unit brings the number into it, the number meant). Each range says where
it comes from next to its entry; the command line prints each warning as one ``warning:`` line
on stderr and lists them in its JSON (``warnings``).
"""

from __future__ import annotations

import difflib
import math
import os
import warnings
from collections.abc import Iterable, Mapping, Set
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from restitution.errors import InputError, PlausibilityWarning, describe, is_real

__all__ = ["KINDS", "PLAUSIBLE", "Plausible", "checked", "doubts", "option", "warn_implausible"]

KINDS = ("float", "floats", "choice", "file", "path", "dir", "flag", "extra")
"""A field's kind: one number, numbers (one or several after the flag), one of a few strings,
an existing file, a file to write, a directory, a flag; ``extra``: the options of registered
mechanisms that are not fields (:func:`restitution.laws.mechanisms.base.extra_options`), kept
as sorted ``(keyword, value)`` pairs."""

_PATH_EXAMPLES = {"file": "law.json", "path": "results.sqlite", "dir": "exports"}
"""A path of each path kind, for the advice of a refusal."""


def option(
    name: str, help: str, type: str = "float", *, unit: str = "", positive: bool = False, **extra
) -> dict:
    """Field metadata: the command-line option ``name`` of a field, its ``help``, its kind
    ``type`` (:data:`KINDS`) and, for a number, its ``unit`` (``""``: dimensionless) and whether
    it must be ``positive``; ``extra`` holds ``choices`` (a callable giving the allowed strings)
    and ``aliases``. ``help`` may be a callable giving it (from a registry read when the command
    line is built)."""
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


def _extra(value, meta, name: str) -> tuple[tuple[str, float], ...]:
    """The mechanisms' own options (a mapping, or ``(keyword, value)`` pairs), each checked by
    its option's kind and unit; ``None`` values are "not given" and dropped; an unknown keyword
    is refused with the ones there are."""
    from restitution.laws.mechanisms.base import extra_options

    known = {o.keyword: o for o in extra_options()}
    try:
        items = dict(value.items() if isinstance(value, Mapping) else value)
    except (TypeError, ValueError):
        raise InputError(
            f"{name} must map mechanism options to values, got {describe(value)}; give e.g. "
            f"{name}={{'work_of_adhesion': 0.1}}, or pass the option as a keyword"
        ) from None
    out = {}
    for key, item in items.items():
        if key not in known:
            close = difflib.get_close_matches(str(key), [*known, *(meta.get("fields") or ())],
                                              n=1)  # fmt: skip
            hint = f"; did you mean {close[0]}?" if close else ""
            raise InputError(
                f"no option {key!r} (the mechanisms' options: {', '.join(known) or 'none'}){hint}"
            )
        if item is not None:
            out[key] = _float(item, known[key].metadata(), key)
    return tuple(sorted(out.items()))


_CHECKS = {"float": _float, "choice": _choice, "file": _path, "path": _path, "dir": _path,
           "flag": _flag, "extra": _extra}  # fmt: skip


# -- plausibility --------------------------------------------------------------------------


@dataclass(frozen=True)
class Plausible:
    """Where one quantity of real grains and walls lies (:data:`PLAUSIBLE`).

    Attributes
    ----------
    low, high : float
        The range, in the option's unit (``0`` / ``inf``: no end).
    what : str
        The quantity in words ("a grain's radius").
    why : str
        Where the range comes from, for the warning.
    meant : tuple of (str, float)
        Units a number outside the range may have been written in, each with its size in the
        option's unit (``("mm", 1e-3)`` for a length in m): the first that brings the number into
        the range is offered ("did you mean 3 mm = 0.003?").
    """

    low: float
    high: float
    what: str
    why: str
    meant: tuple[tuple[str, float], ...] = ()


_LENGTHS = (("mm", 1e-3), ("um", 1e-6))
_STRESSES = (("GPa", 1e9), ("MPa", 1e6))

# Young moduli: soft elastomers and gels from about 1e5 Pa (silicone gels 1e4-1e5, rubber about
# 1e6); diamond, the stiffest bulk solid, 1.05-1.2e12 Pa (CRC Handbook; Ashby's charts).
_MODULUS = Plausible(1e5, 1.2e12, "a Young modulus",
                     "from soft rubber to diamond, the stiffest solid", _STRESSES)  # fmt: skip
# Densities: aerogels and foams from about 10 kg/m^3; osmium, the densest element, 22590 kg/m^3.
_DENSITY = Plausible(10.0, 3e4, "a density", "from foams and aerogels to osmium, the densest "
                     "element, 22590 kg/m^3", (("g/cm^3", 1e3),))  # fmt: skip
# Yield stresses: soft metals and wax from about 1 MPa (indium 1-2 MPa, lead 5-10 MPa); the
# strongest steel wires 5-6 GPa (drawn pearlitic wire); no metal's exceeds about 10 GPa, and
# ceramics, far harder, fracture before they flow.
_YIELD = Plausible(1e5, 1e10, "a yield stress", "from indium and lead to the strongest steel "
                   "wires, 5-6 GPa; no metal's is above about 10 GPa", _STRESSES)  # fmt: skip
_THEORETICAL = Plausible(0.0, 0.1, "a yield stress in its material's Young moduli",
                         "a solid's theoretical strength is about E/10; real ones yield far "
                         "below it, steels at E/1000-E/100")  # fmt: skip

PLAUSIBLE: dict[str, Plausible] = {
    "E": _MODULUS,
    "partner_E": _MODULUS,
    "wall_E": _MODULUS,
    "rho": _DENSITY,
    "partner_rho": _DENSITY,
    "wall_rho": _DENSITY,
    # Grains from fine powders (0.1 um; below, adhesion and surface forces rule the contact) to
    # boulders (1 m).
    "radius": Plausible(
        1e-7, 1.0, "a grain's radius", "from fine powders, 0.1 um, to boulders", _LENGTHS
    ),
    # A plate under a grain: sheets and panels up to centimetres; beyond 1 m it is a block.
    "wall_thickness": Plausible(
        0.0,
        1.0,
        "a plate's thickness under a grain",
        "thicker, it is a block: leave out --wall-thickness for the half-space",
        _LENGTHS,
    ),
    # The plate in the ball's radii: the longitudinal waves' round trip across 100 R (188 R/c
    # for steel on glass) outlasts the contact above about 1 mm/s (49 R/c at 1 m/s, growing as
    # w^(-1/5); the numbers of the thin-plate model's refusal): the waves reflected at the far
    # side come back after the ball left, and the plate is, to the ball, a block.
    "wall_thickness/radius": Plausible(
        0.0,
        100.0,
        "a plate's thickness in the ball's radii",
        "thicker, the waves reflected at its far side return "
        "after the contact (steel on glass above about 1 mm/s): "
        "to the ball it is a block; leave out --wall-thickness "
        "for the elastic half-space",
    ),
    "yield_stress": _YIELD,
    "partner_yield_stress": _YIELD,
    # A yield stress in the material's own modulus: the theoretical strength of a perfect
    # crystal is about E/10 (Frenkel's estimate of the ideal shear strength, G/2pi; Kelly and
    # Macmillan, Strong Solids), and real solids yield far below it (steels at E/1000-E/100,
    # the strongest wires near E/40). A stress the absolute range lets through (500 MPa) is
    # still no yield stress of a polymer with E = 3 GPa.
    "yield_stress/E": _THEORETICAL,
    "partner_yield_stress/partner_E": _THEORETICAL,
    # Thornton's limiting pressure is the pressure of first yield, 0.7-1.9 times the yield
    # stress (restitution.quasistatic.plastic.onset_pressure_ratio over nu in (-0.9, 0.5)).
    "limiting_pressure": Plausible(
        1e5,
        2e10,
        "a limiting contact pressure",
        "1.6 times a yield stress from indium's to the strongest steel's",
        _STRESSES,
    ),
    # Coulomb coefficients: granular materials 0.1-1 (glass beads 0.1-0.2, sand 0.5-0.8); clean
    # metals in vacuum a few (Bowden and Tabor), from cold welding.
    "friction": Plausible(
        0.0, 5.0, "a friction coefficient", "of order 0.1-1; clean metals in vacuum reach a few"
    ),
}
"""Plausible ranges of the request's numbers (field name, or ``"a/b"`` for the ratio of two
fields), each with where it comes from; :func:`doubts` checks a request against them."""


def _in_unit(value: float, unit: str) -> str:
    return f"{value:g} {unit}" if unit else f"{value:g}"


def doubts(request) -> list[str]:
    """One sentence for every number of ``request`` (a dataclass whose fields :func:`option`
    describes) outside its :data:`PLAUSIBLE` range, in the options' words and units; a ratio
    only where neither of its numbers is in doubt already."""
    meta = {f.name: f.metadata for f in fields(request)}
    out, doubted = [], set()
    for key, p in PLAUSIBLE.items():
        names = key.split("/")
        values = [getattr(request, name) for name in names]
        if any(v is None for v in values) or doubted.intersection(names):
            continue
        value = values[0] if len(values) == 1 else values[0] / values[1]
        if p.low <= value <= p.high:
            continue
        doubted.update(names)
        given = [f"{meta[n]['option']} {_in_unit(v, meta[n]['unit'])}"
                 for n, v in zip(names, values, strict=True)]  # fmt: skip
        unit = meta[names[0]]["unit"] if len(names) == 1 else ""
        head = given[0] if len(names) == 1 else f"{given[0]} is {value:.3g} times {given[1]}:"
        if p.low > 0 and p.high < math.inf:
            span = f"{p.low:.3g} ... {p.high:.3g}" + (f" {unit}" if unit else "")
        else:
            span = f"up to {_in_unit(p.high, unit)}" if p.low <= 0 else f"from {p.low:.3g}"
        side = "above" if value > p.high else "below"
        verb = "" if len(names) > 1 else " is"
        text = f"{head}{verb} {side} the range of {p.what}, {span} ({p.why})"
        for word, size in p.meant:
            if p.low <= value * size <= p.high:
                text += f"; did you mean {value:g} {word} = {value * size:g}?"
                break
        else:
            text += f"; check its units ({unit})" if unit else ""
        out.append(text)
    return out


def warn_implausible(request, stacklevel: int = 4) -> None:
    """A :class:`~restitution.errors.PlausibilityWarning` for each of :func:`doubts`; the
    default ``stacklevel`` points at the line that built ``request`` (its ``__post_init__``
    calls this)."""
    for text in doubts(request):
        warnings.warn(text, PlausibilityWarning, stacklevel=stacklevel)
