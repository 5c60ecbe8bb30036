"""Source code that evaluates the law's PCHIP table: a C99 header and a Fortran include file.

``NAME_epsilon(w_m_s)`` takes the impact speed ``w`` in m/s and returns epsilon
(dimensionless) on the table's range, :data:`~restitution.laws.exports.pchip.OUTSIDE` (``-1``)
outside it or for a NaN speed. Their comments state the range and the table's deviation from the
law, and, given a :class:`~restitution.laws.exports.closed_form.ClosedForm`, its coefficients.
"""

from __future__ import annotations

import re

import numpy as np

from restitution.errors import InputError
from restitution.laws.exports._heading import _header
from restitution.laws.exports.closed_form import ClosedForm
from restitution.laws.exports.pchip import OUTSIDE, PchipTable, pchip_table
from restitution.laws.si_law import SILaw

__all__ = ["c_header", "fortran_include"]


def _table_comment(s: SILaw, t: PchipTable, f: ClosedForm | None) -> list[str]:
    lo, hi = t.range_m_s
    lines = [
        *_header(s),
        f"epsilon(w): monotone piecewise-cubic (PCHIP) table of the law's {t.w_m_s.size} "
        f"computed points, w in m/s, valid for {lo:.6g} <= w <= {hi:.6g} m/s only",
        f"max deviation from the law over that range: {t.max_deviation:.2g} "
        f"({t.max_deviation_sigma:.2g} sigma; sigma the law's error there)",
        f"outside that range (and for a NaN speed) it returns {OUTSIDE:g}: no extrapolation",
    ]
    if f is not None:
        da, db, dp = f.errors
        lines += [
            "three-parameter closed form (epsilon_closed_form.json): epsilon(w) = 1 - a x^p / "
            f"(1 + b x^p), x = w / {f.speed_scale_m_s:.6g} m/s, a = {f.a:.6g} +- {da:.2g}, "
            f"b = {f.b:.6g} +- {db:.2g}, p = {f.p:.6g} +- {dp:.2g}",
            f"  within the points' errors only on {f.valid_m_s[0]:.6g} ... {f.valid_m_s[1]:.6g} "
            f"m/s (max deviation {f.max_deviation_sigma:.2g} sigma there); not valid elsewhere",
        ]
    return lines


def _c_ident(name: str) -> str:
    out = "".join(ch if ch.isalnum() else "_" for ch in name)
    if not out or out[0].isdigit():
        raise InputError(f"{name!r} is not a usable identifier")
    return out


def _rows(values: np.ndarray, fmt, per_line: int, indent: str, sep: str) -> list[str]:
    items = [fmt(float(x)) for x in values]
    return [
        indent + ", ".join(items[i : i + per_line]) + sep for i in range(0, len(items), per_line)
    ]


def c_header(
    s: SILaw, f: ClosedForm | None = None, name: str = "restitution", *, table=None
) -> str:
    """A C99 header defining ``double NAME_epsilon(double w_m_s)``: the law's PCHIP table
    (:func:`pchip_table`), ``NAME_OUTSIDE`` (``-1``) outside ``[NAME_W_MIN_M_S,
    NAME_W_MAX_M_S]``. ``f`` (the closed form) only adds its coefficients to the comment."""
    t = table if table is not None else pchip_table(s)
    n = _c_ident(name)
    up = n.upper()
    lines = ["/*", *(f" * {line}" for line in _table_comment(s, t, f)), " */"]
    arrays = []
    for suffix, values in (("W", t.w_m_s), ("E", t.epsilon), ("D", t.slope_s_m)):
        rows = _rows(values, repr, 4, "    ", ",")
        rows[-1] = rows[-1][:-1]
        arrays += [f"static const double {n}_tab_{suffix.lower()}[{up}_N] = {{", *rows, "};"]
    lines += [
        f"#ifndef {up}_EPSILON_H",
        f"#define {up}_EPSILON_H",
        f"#define {up}_N {t.w_m_s.size}",
        f"#define {up}_W_MIN_M_S {t.range_m_s[0]!r}",
        f"#define {up}_W_MAX_M_S {t.range_m_s[1]!r}",
        f"#define {up}_OUTSIDE ({OUTSIDE!r})",
        "/* knots (m/s), epsilon there, d epsilon / d w there (s/m) */",
        *arrays,
        "/* coefficient of restitution at impact speed w_m_s (m/s; see 'partner' above);",
        f"   {up}_OUTSIDE outside [{up}_W_MIN_M_S, {up}_W_MAX_M_S] or for NaN */",
        f"static inline double {n}_epsilon(double w_m_s)",
        "{",
        f"    int lo = 0, hi = {up}_N - 1;",
        "    double h, t;",
        f"    if (!(w_m_s >= {up}_W_MIN_M_S && w_m_s <= {up}_W_MAX_M_S)) return {up}_OUTSIDE;",
        "    while (hi - lo > 1) {",
        "        const int mid = (lo + hi) / 2;",
        f"        if ({n}_tab_w[mid] <= w_m_s) lo = mid; else hi = mid;",
        "    }",
        f"    h = {n}_tab_w[hi] - {n}_tab_w[lo];",
        f"    t = (w_m_s - {n}_tab_w[lo]) / h;",
        f"    return (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t) * {n}_tab_e[lo]",
        f"        + t * (1.0 - t) * (1.0 - t) * h * {n}_tab_d[lo]",
        f"        + t * t * (3.0 - 2.0 * t) * {n}_tab_e[hi]",
        f"        - t * t * (1.0 - t) * h * {n}_tab_d[hi];",
        "}",
        f"#endif /* {up}_EPSILON_H */",
        "",
    ]
    return "\n".join(lines)


def _fortran_comment(line: str, width: int = 128) -> list[str]:
    """``line`` in pieces of at most ``width`` characters, cut after ``, `` or ``; `` (free-form
    Fortran allows 132 characters per line, comments included), then at spaces if need be."""
    parts, cur = [], ""
    for chunk in re.split(r"(?<=[,;] )", line):
        if cur and len(cur) + len(chunk) > width:
            parts.append(cur.rstrip())
            cur = "  "
        cur += chunk
    parts.append(cur.rstrip())
    out = []
    for part in parts:
        while len(part) > width:
            cut = part.rfind(" ", 0, width)
            cut = cut if cut > 2 else width
            out.append(part[:cut])
            part = "  " + part[cut:].lstrip()
        out.append(part)
    return out


def _fortran_real(x: float) -> str:
    return f"{x:.17e}".replace("e", "d")


def fortran_include(
    s: SILaw, f: ClosedForm | None = None, name: str = "restitution", *, table=None
) -> str:
    """A Fortran 90 include file with ``pure function NAME_epsilon(w_m_s)``: the law's PCHIP
    table (:func:`pchip_table`), ``-1d0`` outside its range. Include it after ``contains`` in a
    module or program (one with ``implicit none``). ``f`` only adds its coefficients to the
    comment."""
    t = table if table is not None else pchip_table(s)
    n = _c_ident(name)
    lines = [f"! {part}" for line in _table_comment(s, t, f) for part in _fortran_comment(line)]
    lines += [
        f"pure function {n}_epsilon(w_m_s) result(eps)",
        "  implicit none",
        "  double precision, intent(in) :: w_m_s",
        "  double precision :: eps, h, t",
        "  integer :: lo, hi, mid",
        f"  integer, parameter :: n = {t.w_m_s.size}",
    ]
    for arr, values in (("tw", t.w_m_s), ("te", t.epsilon), ("td", t.slope_s_m)):
        rows = _rows(values, _fortran_real, 4, "    ", ", &")
        rows[-1] = rows[-1][: -len(", &")] + " /)"
        lines += [f"  double precision, parameter :: {arr}(n) = (/ &", *rows]
    lines += [
        f"  eps = {_fortran_real(OUTSIDE)}",
        "  if (.not. (w_m_s >= tw(1) .and. w_m_s <= tw(n))) return",
        "  lo = 1",
        "  hi = n",
        "  do while (hi - lo > 1)",
        "    mid = (lo + hi) / 2",
        "    if (tw(mid) <= w_m_s) then",
        "      lo = mid",
        "    else",
        "      hi = mid",
        "    end if",
        "  end do",
        "  h = tw(hi) - tw(lo)",
        "  t = (w_m_s - tw(lo)) / h",
        "  eps = (1d0 + 2d0 * t) * (1d0 - t)**2 * te(lo) + t * (1d0 - t)**2 * h * td(lo) &",
        "    + t**2 * (3d0 - 2d0 * t) * te(hi) - t**2 * (1d0 - t) * h * td(hi)",
        f"end function {n}_epsilon",
        "",
    ]
    return "\n".join(lines)
