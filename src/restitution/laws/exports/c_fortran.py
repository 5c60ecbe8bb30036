"""Source code that evaluates the law's PCHIP table: a C99 header and a Fortran include file.

Both take the impact speed ``w`` in m/s and give epsilon (dimensionless) at every speed a grain
meets, with a status (:class:`~restitution.laws.exports.pchip.TableStatus`): the table on its
range (0), the slow-impact continuation below it down to ``w = 0`` (1), and NaN, never a
coefficient, above it (2) or for a negative, infinite or NaN speed (3). C:
``double NAME_epsilon(double w_m_s, int *status)`` (``status`` may be ``NULL``); Fortran:
``pure subroutine NAME_epsilon(w_m_s, eps, status)``. Their comments state the range, the
table's deviation from the law, the continuation and its error bound, and, given a
:class:`~restitution.laws.exports.closed_form.ClosedForm`, its coefficients.
"""

from __future__ import annotations

import re

import numpy as np

from restitution.errors import InputError
from restitution.laws.exports._heading import _header
from restitution.laws.exports.closed_form import ClosedForm
from restitution.laws.exports.pchip import PchipTable, TableStatus, pchip_table
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
        f"{t.below.describe()} (status 1)",
        f"above {hi:.6g} m/s: no value (NaN, status 2), never an extrapolation; a negative, "
        "infinite or NaN speed: NaN, status 3; status 0: the table",
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


def _c_slow_loss(t: PchipTable, up: str, w: str) -> str:
    """The continuation's loss ``1 - epsilon^2`` at the C variable ``w`` (``w > 0``)."""
    if t.below.form == "power":
        return f"{up}_SLOW_LOSS0 * pow({w} / {up}_W_MIN_M_S, {up}_SLOW_EXPONENT)"
    return (
        f"{up}_SLOW_LOSS0 * pow(log({up}_SLOW_SCALE_M_S / {up}_W_MIN_M_S) / "
        f"log({up}_SLOW_SCALE_M_S / {w}), {up}_SLOW_EXPONENT)"
    )


def c_header(
    s: SILaw, f: ClosedForm | None = None, name: str = "restitution", *, table=None
) -> str:
    """A C99 header defining ``double NAME_epsilon(double w_m_s, int *status)``: the law's
    PCHIP table (:func:`pchip_table`) on ``[NAME_W_MIN_M_S, NAME_W_MAX_M_S]``, the slow-impact
    continuation below it, NaN above it; ``*status`` (unless ``NULL``) is one of
    ``NAME_INSIDE``, ``NAME_BELOW``, ``NAME_ABOVE``, ``NAME_BAD_SPEED``
    (:class:`TableStatus`). Needs ``-lm``. ``f`` (the closed form) only adds its coefficients
    to the comment."""
    t = table if table is not None else pchip_table(s)
    n = _c_ident(name)
    up = n.upper()
    lines = ["/*", *(f" * {line}" for line in _table_comment(s, t, f)), " */"]
    arrays = []
    for suffix, values in (("W", t.w_m_s), ("E", t.epsilon), ("D", t.slope_s_m)):
        rows = _rows(values, repr, 4, "    ", ",")
        rows[-1] = rows[-1][:-1]
        arrays += [f"static const double {n}_tab_{suffix.lower()}[{up}_N] = {{", *rows, "};"]
    slow = [
        f"#define {up}_SLOW_LOSS0 {t.below.loss0!r}",
        f"#define {up}_SLOW_EXPONENT {t.below.exponent!r}",
    ]
    if t.below.scale_m_s is not None:
        slow.append(f"#define {up}_SLOW_SCALE_M_S {t.below.scale_m_s!r}")
    codes = [f"#define {up}_{c.name} {int(c)}" for c in TableStatus]
    lines += [
        f"#ifndef {up}_EPSILON_H",
        f"#define {up}_EPSILON_H",
        "#include <math.h>",
        f"#define {up}_N {t.w_m_s.size}",
        f"#define {up}_W_MIN_M_S {t.range_m_s[0]!r}",
        f"#define {up}_W_MAX_M_S {t.range_m_s[1]!r}",
        "/* status codes: a coefficient comes with INSIDE (the table) or BELOW (the slow-impact",
        "   continuation); ABOVE (over the law's range) and BAD_SPEED come with NaN */",
        *codes,
        f"/* the continuation below {up}_W_MIN_M_S: {t.below.formula()} */",
        *slow,
        "/* knots (m/s), epsilon there, d epsilon / d w there (s/m) */",
        *arrays,
        "/* coefficient of restitution at impact speed w_m_s (m/s; see 'partner' above), for",
        f"   every 0 <= w_m_s <= {up}_W_MAX_M_S; NaN above it or for a negative, infinite or NaN",
        "   speed; *status (if status is not NULL) says which */",
        f"static inline double {n}_epsilon(double w_m_s, int *status)",
        "{",
        f"    int lo = 0, hi = {up}_N - 1;",
        "    double h, t;",
        f"    if (w_m_s >= 0.0 && w_m_s < {up}_W_MIN_M_S) {{",
        f"        if (status) *status = {up}_BELOW;",
        "        if (w_m_s == 0.0) return 1.0;",
        f"        return sqrt(1.0 - {_c_slow_loss(t, up, 'w_m_s')});",
        "    }",
        f"    if (!(w_m_s >= {up}_W_MIN_M_S && w_m_s <= {up}_W_MAX_M_S)) {{",
        f"        if (status) *status = (w_m_s > {up}_W_MAX_M_S && isfinite(w_m_s)) ? {up}_ABOVE"
        f" : {up}_BAD_SPEED;",
        "        return NAN;",
        "    }",
        f"    if (status) *status = {up}_INSIDE;",
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


def _fortran_slow_loss(t: PchipTable) -> str:
    """The continuation's loss ``1 - epsilon^2`` at ``w_m_s > 0``, in Fortran."""
    if t.below.form == "power":
        return "slow_loss0 * (w_m_s / tw(1))**slow_exponent"
    return "slow_loss0 * (log(slow_scale / tw(1)) / log(slow_scale / w_m_s))**slow_exponent"


def fortran_include(
    s: SILaw, f: ClosedForm | None = None, name: str = "restitution", *, table=None
) -> str:
    """A Fortran 2003 include file with ``pure subroutine NAME_epsilon(w_m_s, eps, status)``:
    the law's PCHIP table (:func:`pchip_table`) on its range, the slow-impact continuation
    below it, NaN (``ieee_quiet_nan``) above it; ``status`` as in C (:class:`TableStatus`).
    Include it after ``contains`` in a module or program (one with ``implicit none``). ``f``
    only adds its coefficients to the comment."""
    t = table if table is not None else pchip_table(s)
    n = _c_ident(name)
    lines = [f"! {part}" for line in _table_comment(s, t, f) for part in _fortran_comment(line)]
    lines += [
        f"pure subroutine {n}_epsilon(w_m_s, eps, status)",
        "  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite",
        "  implicit none",
        "  double precision, intent(in) :: w_m_s",
        "  double precision, intent(out) :: eps",
        "  integer, intent(out) :: status",
        "  double precision :: h, t",
        "  integer :: lo, hi, mid",
        f"  integer, parameter :: n = {t.w_m_s.size}",
        *(f"  integer, parameter :: {n}_{c.name.lower()} = {int(c)}" for c in TableStatus),
        f"  double precision, parameter :: slow_loss0 = {_fortran_real(t.below.loss0)}",
        f"  double precision, parameter :: slow_exponent = {_fortran_real(t.below.exponent)}",
    ]
    if t.below.scale_m_s is not None:
        lines.append(
            f"  double precision, parameter :: slow_scale = {_fortran_real(t.below.scale_m_s)}"
        )
    for arr, values in (("tw", t.w_m_s), ("te", t.epsilon), ("td", t.slope_s_m)):
        rows = _rows(values, _fortran_real, 4, "    ", ", &")
        rows[-1] = rows[-1][: -len(", &")] + " /)"
        lines += [f"  double precision, parameter :: {arr}(n) = (/ &", *rows]
    lines += [
        "  if (.not. ieee_is_finite(w_m_s) .or. .not. (w_m_s >= 0d0)) then",
        f"    status = {n}_bad_speed",
        "    eps = ieee_value(eps, ieee_quiet_nan)",
        "    return",
        "  end if",
        "  if (w_m_s > tw(n)) then",
        f"    status = {n}_above",
        "    eps = ieee_value(eps, ieee_quiet_nan)",
        "    return",
        "  end if",
        "  if (w_m_s < tw(1)) then",
        f"    status = {n}_below",
        "    eps = 1d0",
        f"    if (w_m_s > 0d0) eps = sqrt(1d0 - {_fortran_slow_loss(t)})",
        "    return",
        "  end if",
        f"  status = {n}_inside",
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
        f"end subroutine {n}_epsilon",
        "",
    ]
    return "\n".join(lines)
