"""epsilon in the forms simulation codes read, in SI units.

Every export starts from an :class:`~restitution.laws.si_law.SILaw` (material, geometry, partner,
reduced-unit law) and carries, in its comments: the material, the geometry and the body of the
law (a cylinder or thin disk is served by the disk's law, a sphere by the sphere's), what the
speed means (wall or two grains), ``c``, the law's source and the package version.

* :func:`speed_table` / :func:`write_table` / :func:`write_csv`: ``speed_m_s epsilon
  [epsilon_err]`` on a uniform grid of the interpolant, for codes that interpolate linearly
  between ``[v, e]`` pairs (AcuTrace style); the CSV adds ``v_over_c`` and the status.
* :func:`fit_closed_form`: the form ``epsilon(w) = 1 - a x^p / (1 + b x^p)``, ``x = w / (k c)``,
  fitted to the computed points (weighted by their errors), with covariance, maximum deviation
  and the range where it follows every point within its error (and only there).
* :func:`pchip_table`: the law as a monotone piecewise-cubic table in m/s, which
  :func:`c_header` (C99) and :func:`fortran_include` (Fortran 2003) evaluate on the computed
  speeds, returning :data:`OUTSIDE` (``-1``) outside them; their headers state the range and
  the maximum deviation from the law in its error bars.
  Why this form: ``epsilon(0) = 1`` (the quasistatic limit), a power law ``1 - epsilon ~ a x^p``
  at small speeds (Rayleigh's estimate, paper section 5, gives a power of the speed), a
  saturation at large speeds through ``b``, three parameters, and one line of C.
* :func:`constant_at` (epsilon at a reference speed) and :func:`maxwell_constant` (averaged over
  the impact speeds of a gas at a granular temperature): one number for codes that take a
  constant per pair, with snippets for LAMMPS ``pair_style granular`` or, against a wall,
  ``fix wall/gran granular`` (:func:`lammps_snippet`),
  LIGGGHTS, MercuryDPM and YADE.
* :func:`type_pair_constants`: the constants of a bidisperse packing of one material (type 1 the
  small grain, type 2 the large): 1-1 and 2-2 from the law of identical grains, 1-2 from the
  pair's law, each at the same reference speed or temperature (:class:`TypePairs`); the same
  snippet functions write them per pair of particle types. Of two materials (type 1 this grain,
  type 2 the partner grain of its own material and size), 1-1 and 2-2 come from each
  material's law of identical grains, and the snippets give each type its own constants.

The speed ``w`` of a law of two grains of different sizes (``SILaw.law.partner``) is their
relative normal speed; every header says so (:attr:`SILaw.against_meaning`).
"""

from __future__ import annotations

import csv
import datetime
import math
import os
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.optimize import curve_fit

from restitution import atomic
from restitution._version import __version__
from restitution.errors import InputError, RestitutionError
from restitution.laws.si_law import SILaw
from restitution.status import Status

__all__ = [
    "SAME_SIZE_NOTE",
    "TWO_MATERIALS_NOTE",
    "OUTSIDE",
    "ClosedForm",
    "Constant",
    "PchipTable",
    "TypePairs",
    "c_header",
    "constant_at",
    "distribution_constant",
    "fit_closed_form",
    "fortran_include",
    "liggghts_snippet",
    "lammps_snippet",
    "maxwell_constant",
    "mercurydpm_snippet",
    "pchip_table",
    "speed_table",
    "type_pair_constants",
    "write_csv",
    "write_table",
    "yade_snippet",
]


_BODY_WORDS = {
    "cylinder": "long elastic cylinder hit along a diameter (the 2D disk in plane strain)",
    "thin-disk": "thin elastic disk hit on its rim (the 2D disk in plane stress)",
    "sphere": "elastic sphere (3D)",
}


def _law_line(s: SILaw) -> str:
    """``law: ...``: which law serves ``s`` (the body's, or the pair's) and where it is from."""
    g = s.grain
    pair = s.law.partner
    if pair is not None:
        which = (
            f"this {g.body} and one of the partner's material"
            if s.partner_grain is not None
            else f"a small and a large {g.body} of one material"
        )
        return (
            f"law: the pair's ({which}, R2/R1 = {pair.radius_ratio:g}; w their relative normal "
            f"speed), {g.law_nu_name} = {float(s.law.nu):g}, {s.law_source}"
        )
    if g.body == "disk":
        return f"law: nu_2d = {float(s.law.nu):g}, {s.law_source}"
    return f"law: the {g.body}'s, nu = {float(s.law.nu):g}, {s.law_source}"


def _header(s: SILaw) -> list[str]:
    g = s.grain
    lo, hi = s.computed_range_m_s
    return [
        f"restitution {__version__}, {datetime.datetime.now(datetime.UTC):%Y-%m-%dT%H:%M:%SZ}: "
        "coefficient of restitution of an elastic grain from its vibrational modes "
        "(Gerl & Zippelius model)",
        f"grain: {g.geometry}: {_BODY_WORDS[g.geometry]}",
        f"material: {g.describe()}",
        *([f"partner material: {s.partner_grain.describe()}"] if s.partner_grain else []),
        f"partner: {s.against}: {s.against_meaning}; speed unit k c = {s.speed_scale_m_s:.6g} m/s",
        _law_line(s),
        f"computed speeds: {lo:.6g} ... {hi:.6g} m/s; the law serves nothing outside them",
    ]


# -- tables --------------------------------------------------------------------------------


def _grid(s: SILaw, points: int) -> np.ndarray:
    if points < 2:
        raise InputError("a table needs at least 2 points")
    computed = np.asarray(s.law.v, dtype=float) * s.speed_scale_m_s
    lo, hi = s.speed_range_m_s
    try:
        s.epsilon(lo)
    except InputError:  # a law that serves only its computed speeds
        lo = float(computed[0])
    w = np.union1d(np.linspace(lo, hi, points), computed)
    return w[(w >= lo) & (w <= hi)]


def speed_table(s: SILaw, points: int = 61) -> np.ndarray:
    """``[speed_m_s, epsilon, epsilon_err]`` on a uniform grid of ``[0, w_max]`` joined with
    the computed speeds (from the lowest computed speed if the law refuses lower ones).

    Parameters
    ----------
    s : SILaw
        The law in SI units.
    points : int
        Rows, at least 2.

    Returns
    -------
    numpy.ndarray, shape (K, 3)
        ``K >= points`` rows.
    """
    w = _grid(s, points)
    return np.column_stack([w, s.epsilon(w), s.epsilon_err(w)])


def write_table(s: SILaw, path: str | os.PathLike, *, points: int = 61, columns: int = 3) -> Path:
    """Whitespace table ``speed_m_s epsilon [epsilon_err]`` with ``#`` comments.

    ``columns=2`` gives the two-column ``[v, e]`` form that AcuTrace-style codes interpolate
    linearly. Returns the path.
    """
    if columns not in (2, 3):
        raise InputError(f"a table has 2 or 3 columns, not {columns}")
    table = speed_table(s, points)[:, :columns]
    names = ["speed_m_s", "epsilon", "epsilon_err"][:columns]
    header = "\n".join([*_header(s), "columns: " + "  ".join(names) + " (piecewise linear)"])
    with atomic.replacing(path) as tmp:
        np.savetxt(tmp, table, fmt="%.8g", header=header, comments="# ")
    return Path(path)


def write_csv(s: SILaw, path: str | os.PathLike, *, points: int = 61) -> Path:
    """CSV ``speed_m_s,v_over_c,epsilon,epsilon_err,status`` with ``#`` comments."""
    w = _grid(s, points)
    path = Path(path)
    with atomic.replacing(path) as tmp, open(tmp, "w", newline="") as fh:
        for line in _header(s):
            fh.write(f"# {line}\n")
        writer = csv.writer(fh)
        writer.writerow(["speed_m_s", "v_over_c", "epsilon", "epsilon_err", "status"])
        for p in s.points(w):
            writer.writerow(
                [repr(p.speed_m_s), repr(p.v_over_c), repr(p.epsilon), repr(p.epsilon_err),
                 p.status]
            )  # fmt: skip
    return path


# -- closed form -----------------------------------------------------------------------------


def _form(x, a, b, p):
    xp = np.power(x, p)
    return 1.0 - a * xp / (1.0 + b * xp)


@dataclass(frozen=True)
class ClosedForm:
    """``epsilon(w) = 1 - a x^p / (1 + b x^p)`` with ``x = w / speed_scale_m_s``.

    Attributes
    ----------
    a, b, p : float
        Dimensionless coefficients (``x`` is the reduced speed ``v`` towards the wall).
    covariance : numpy.ndarray, shape (3, 3)
        Covariance of ``(a, b, p)``; scaled by ``chi2/dof`` when that exceeds 1 (the points
        scatter more than their error bars say).
    speed_scale_m_s : float
        ``k c``, m/s.
    max_deviation : float
        Largest ``|form - epsilon|`` over the points in :attr:`valid_m_s`.
    max_deviation_sigma : float
        Largest ``|form - epsilon| / epsilon_err`` over those points, at most 1.
    chi2_dof : float
        ``chi^2`` per degree of freedom of the weighted fit.
    valid_m_s : tuple of float
        ``(w_min, w_max)`` in m/s: the range of computed points the form follows within their
        errors (:func:`fit_closed_form`). Outside it the form is not valid: it misses the law
        by more than the errors, or the law has no points there.
    """

    a: float
    b: float
    p: float
    covariance: np.ndarray
    speed_scale_m_s: float
    max_deviation: float
    max_deviation_sigma: float
    chi2_dof: float
    valid_m_s: tuple[float, float]

    def epsilon(self, speed_m_s):
        """The form at speed(s) ``w`` in m/s."""
        return _form(np.asarray(speed_m_s, dtype=float) / self.speed_scale_m_s, *self.params)

    @property
    def params(self) -> tuple[float, float, float]:
        return self.a, self.b, self.p

    @property
    def errors(self) -> tuple[float, float, float]:
        """Standard errors of ``(a, b, p)``."""
        return tuple(float(x) for x in np.sqrt(np.diag(self.covariance)))

    def to_dict(self) -> dict:
        return {
            "form": "epsilon(w) = 1 - a x^p / (1 + b x^p), x = w / speed_scale_m_s",
            "valid": "only for valid_m_s[0] <= w <= valid_m_s[1] (m/s), where it follows every "
            "computed point within its error (max_deviation_sigma <= 1); elsewhere use the "
            "table (epsilon.h, epsilon.f90, epsilon_table.txt)",
            "a": self.a,
            "b": self.b,
            "p": self.p,
            "errors": list(self.errors),
            "covariance": self.covariance.tolist(),
            "speed_scale_m_s": self.speed_scale_m_s,
            "max_deviation": self.max_deviation,
            "max_deviation_sigma": self.max_deviation_sigma,
            "chi2_dof": self.chi2_dof,
            "valid_m_s": list(self.valid_m_s),
        }


def _decreasing_tail(eps: np.ndarray) -> int:
    """Index of the law's last maximum: from there on ``epsilon`` falls at every point."""
    k = eps.size - 1
    while k > 0 and eps[k - 1] > eps[k]:
        k -= 1
    return k


_SIGMA_FLOOR = 1e-12
"""Smallest error bar a point is weighted with (a zero error bar would divide by zero)."""


def _fit(v: np.ndarray, eps: np.ndarray, sigma: np.ndarray, p0) -> np.ndarray:
    popt, _ = curve_fit(_form, v, eps, p0=p0, sigma=sigma, absolute_sigma=True, maxfev=20000)
    return popt


def fit_closed_form(s: SILaw) -> ClosedForm:
    """Fit :class:`ClosedForm` to the law's computed points, weighted by their errors, on the
    widest range of speeds where it follows every point within its error bar.

    The form falls monotonically with the speed; the two-dimensional law does not (it has a
    maximum near ``v = 0.002 - 0.02 c``, docs/results.md), so the fit starts at the law's last
    maximum. Three parameters do not follow the shipped laws to their error bars over that
    whole tail: the range is then narrowed, one end at a time (the end point that misses more
    goes), and the form refitted, until every point left is within ``1 sigma``
    (:attr:`ClosedForm.max_deviation_sigma` ``<= 1``). ``valid_m_s`` is that range; outside it,
    use :func:`pchip_table` (what :func:`c_header` and :func:`fortran_include` evaluate).

    Raises
    ------
    InputError
        For a law with fewer than 4 points on its decreasing tail.
    RestitutionError
        When the form fits no range of 4 or more points within their errors, or has a pole
        inside the range it fits.
    """
    v_all = np.asarray(s.law.v, dtype=float)
    eps_all = np.asarray(s.law.epsilon_points, dtype=float)
    sig_all = np.maximum(np.asarray(s.law.epsilon_err_points, dtype=float), _SIGMA_FLOOR)
    lo, hi = _decreasing_tail(eps_all), v_all.size
    if hi - lo < 4:
        raise InputError(f"a three-parameter fit needs at least 4 points, the law has {hi - lo}")
    p0 = (1.0, 0.0, 0.8)
    while True:
        v, eps, sigma = v_all[lo:hi], eps_all[lo:hi], sig_all[lo:hi]
        try:
            popt = _fit(v, eps, sigma, p0)
        except (RuntimeError, ValueError) as exc:
            raise RestitutionError(f"the closed form did not fit the law's points: {exc}") from exc
        a, b, p = (float(x) for x in popt)
        if b < 0 and p > 0 and (-1.0 / b) ** (1.0 / p) <= v[-1]:
            raise RestitutionError(
                f"the closed form fitted to the law has a pole at v = {(-1.0 / b) ** (1.0 / p):.3g}"
                " c inside the computed range; use the table instead"
            )
        z = np.abs(_form(v, *popt) - eps) / sigma
        if np.all(np.isfinite(z)) and z.max() <= 1.0:
            break
        if hi - lo <= 4:
            raise RestitutionError(
                "the closed form follows no range of 4 or more computed points within their "
                "errors; use the table (pchip_table, epsilon.h)"
            )
        # Drop the end that misses more (a twentieth of the points at once on long laws).
        step = max(1, min((hi - lo - 4), (hi - lo) // 20))
        if z[:step].max() >= z[-step:].max():
            lo += step
        else:
            hi -= step
        p0 = tuple(popt) if np.all(np.isfinite(popt)) else p0
    popt, pcov = curve_fit(_form, v, eps, p0=popt, sigma=sigma, absolute_sigma=True, maxfev=20000)
    a, b, p = (float(x) for x in popt)
    resid = _form(v, *popt) - eps
    chi2_dof = float(np.sum((resid / sigma) ** 2) / max(v.size - 3, 1))
    return ClosedForm(
        a=a,
        b=b,
        p=p,
        covariance=pcov * max(1.0, chi2_dof),
        speed_scale_m_s=s.speed_scale_m_s,
        max_deviation=float(np.max(np.abs(resid))),
        max_deviation_sigma=float(np.max(np.abs(resid) / sigma)),
        chi2_dof=chi2_dof,
        valid_m_s=(float(v[0] * s.speed_scale_m_s), float(v[-1] * s.speed_scale_m_s)),
    )


# -- the table that C and Fortran evaluate -----------------------------------------------------


OUTSIDE = -1.0
"""What the C and Fortran functions return outside the table's range (and for a NaN speed):
epsilon is never negative, so ``-1`` cannot be mistaken for a value. No extrapolation."""


@dataclass(frozen=True)
class PchipTable:
    """The law as a monotone piecewise-cubic table in m/s: what :func:`c_header` and
    :func:`fortran_include` evaluate.

    Between knots ``w_i`` the value is the cubic Hermite polynomial through ``(w_i, e_i)`` and
    ``(w_{i+1}, e_{i+1})`` with slopes ``d_i``, ``d_{i+1}``: Fritsch-Carlson / PCHIP slopes
    (:class:`scipy.interpolate.PchipInterpolator`), monotone wherever the points are, the
    interpolant the law itself uses between its computed points.

    Attributes
    ----------
    w_m_s : numpy.ndarray
        Knots: the computed speeds, m/s.
    epsilon : numpy.ndarray
        The law's points at the knots.
    slope_s_m : numpy.ndarray
        ``d epsilon / d w`` at the knots, s/m.
    max_deviation : float
        Largest ``|table - law|`` on the knots and 16 speeds inside every interval.
    max_deviation_sigma : float
        The same in units of the law's error there (:meth:`SILaw.epsilon_err`).
    """

    w_m_s: np.ndarray
    epsilon: np.ndarray
    slope_s_m: np.ndarray
    max_deviation: float
    max_deviation_sigma: float

    @property
    def range_m_s(self) -> tuple[float, float]:
        """``(w_min, w_max)``, m/s: the table's range (the law's computed speeds)."""
        return float(self.w_m_s[0]), float(self.w_m_s[-1])

    def __call__(self, speed_m_s):
        """The table at speed(s) ``w`` (m/s) as C and Fortran evaluate it: :data:`OUTSIDE`
        outside :attr:`range_m_s`."""
        w = np.atleast_1d(np.asarray(speed_m_s, dtype=float))
        x, y, d = self.w_m_s, self.epsilon, self.slope_s_m
        inside = (w >= x[0]) & (w <= x[-1])
        i = np.clip(np.searchsorted(x, np.where(inside, w, x[0]), side="right") - 1, 0, x.size - 2)
        h = x[i + 1] - x[i]
        t = (np.where(inside, w, x[0]) - x[i]) / h
        val = (
            (1 + 2 * t) * (1 - t) ** 2 * y[i]
            + t * (1 - t) ** 2 * h * d[i]
            + t**2 * (3 - 2 * t) * y[i + 1]
            - t**2 * (1 - t) * h * d[i + 1]
        )
        out = np.where(inside, val, OUTSIDE)
        return float(out[0]) if np.ndim(speed_m_s) == 0 else out


def pchip_table(s: SILaw) -> PchipTable:
    """:class:`PchipTable` of the law over its computed speeds, with its measured deviation."""
    w = np.asarray(s.law.v, dtype=float) * s.speed_scale_m_s
    eps = np.asarray(s.law.epsilon_points, dtype=float)
    slope = PchipInterpolator(w, eps).derivative()(w)
    t = PchipTable(w, eps, slope, 0.0, 0.0)
    inner = np.linspace(0.0, 1.0, 18)[1:-1]
    probe = np.concatenate([w, (w[:-1, None] + np.diff(w)[:, None] * inner).ravel()])
    probe = probe[(probe >= w[0]) & (probe <= w[-1])]
    dev = np.abs(t(probe) - s.epsilon(probe))
    err = np.maximum(s.epsilon_err(probe), _SIGMA_FLOOR)
    return PchipTable(w, eps, slope, float(dev.max()), float((dev / err).max()))


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


# -- one constant per pair -------------------------------------------------------------------


@dataclass(frozen=True)
class Constant:
    """One coefficient of restitution for codes that take a constant per pair.

    Attributes
    ----------
    epsilon, epsilon_err : float
        The constant and its error.
    how : str
        What it is: the law at a reference speed, or an average over a named distribution.
    status : str
        Status of the law where the constant comes from (:data:`restitution.laws.si_law.STATUSES`);
        for an average, the worst status carrying more than 1 % of the weight.
    """

    epsilon: float
    epsilon_err: float
    how: str
    status: str

    def to_dict(self) -> dict:
        return {
            "epsilon": self.epsilon,
            "epsilon_err": self.epsilon_err,
            "how": self.how,
            "status": self.status,
        }


def constant_at(s: SILaw, speed_m_s: float) -> Constant:
    """epsilon at one reference speed ``w`` (m/s)."""
    (p,) = s.points([speed_m_s])
    if p.epsilon is None:
        raise InputError(f"no epsilon at {speed_m_s:g} m/s: {p.note}")
    return Constant(
        p.epsilon,
        p.epsilon_err,
        f"epsilon at w = {speed_m_s:g} m/s ({s.against}: {s.against_meaning})",
        p.status,
    )


_ORDER = (
    Status.COMPUTED,
    Status.INTERPOLATED,
    Status.COMPUTED_NOT_ASYMPTOTIC,
    Status.INTERPOLATED_NOT_ASYMPTOTIC,
    Status.QUASISTATIC,
)


def maxwell_constant(s: SILaw, temperature_m2_s2: float, *, nodes: int = 400) -> Constant:
    """epsilon averaged over the impacts of a Maxwell gas at granular temperature ``T``.

    ``T`` is the variance of one velocity component of a grain, ``<v_x^2>`` in m^2/s^2. The
    normal impact speed ``w`` is Gaussian with variance ``sigma^2 = 2 T`` (two grains,
    relative speed) or ``T`` (a grain against a wall), and impacts happen at a rate ``~ w``.
    For a pair's law (a small and a large grain) ``2 T`` assumes both sizes at the same
    ``<v_x^2> = T``; the constant's ``how`` says so.
    The constant returned conserves the mean energy dissipated per unit time::

        1 - eps_eff^2 = <w^3 (1 - epsilon(w)^2)> / <w^3>,  weight exp(-w^2 / (2 sigma^2))

    (the rate ``w`` times the impact energy ``w^2``). Its error is half the spread of
    ``eps_eff`` evaluated with ``epsilon +- epsilon_err`` (errors fully correlated).

    Raises
    ------
    InputError
        When more than 0.1 % of the weight lies above the law's range.
    """
    T = float(temperature_m2_s2)
    if not (math.isfinite(T) and T > 0):
        raise InputError(f"the granular temperature must be positive (m^2/s^2), got {T}")
    sigma2 = 2.0 * T if s.against == "grain" else T
    w_min, w_max = s.speed_range_m_s

    def above(w):  # int_w^inf u^3 exp(-u^2 / 2 sigma^2) du / int_0^inf (same)
        z = w**2 / (2.0 * sigma2)
        return (1.0 + z) * math.exp(-z)

    if above(w_max) > 1e-3:
        raise InputError(
            f"{above(w_max):.2%} of the dissipation at T = {T:g} m^2/s^2 comes from speeds above "
            f"the law's range {w_max:.6g} m/s; use a lower temperature"
        )
    if 1.0 - above(w_min) > 1e-3:
        raise InputError(
            f"{1.0 - above(w_min):.2%} of the dissipation at T = {T:g} m^2/s^2 comes from speeds "
            f"below the law's computed range (from {w_min:.6g} m/s); use a higher temperature"
        )
    x, wq = np.polynomial.legendre.leggauss(nodes)
    half = 0.5 * (w_max - w_min)
    w = w_min + half * (x + 1.0)
    rate = half * wq * w * np.exp(-(w**2) / (2.0 * sigma2))
    both = "" if s.law.partner is None else ", both grain sizes at <v_x^2> = T"
    return distribution_constant(
        s,
        w,
        rate,
        how=f"dissipation-weighted average over a Maxwell gas at T = {T:g} m^2/s^2 "
        f"({s.against}: normal speed variance {sigma2:g} m^2/s^2{both})",
    )


def distribution_constant(s: SILaw, speeds_m_s, rates, *, how: str = "") -> Constant:
    """Dissipation-weighted constant for impact speeds ``w_i`` (m/s) occurring at ``rates``.

    ``1 - eps_eff^2 = sum r_i w_i^2 (1 - epsilon(w_i)^2) / sum r_i w_i^2``: the constant that
    dissipates the same energy per unit time as the law over the named distribution (``rates``
    are impacts per unit time at each speed, or quadrature weights times that density). The
    error is half the spread of ``eps_eff`` with ``epsilon +- epsilon_err`` (fully correlated).
    """
    w = np.asarray(speeds_m_s, dtype=float)
    r = np.asarray(rates, dtype=float)
    if w.shape != r.shape or w.ndim != 1 or np.any(r < 0) or not np.sum(r * w**2) > 0:
        raise InputError("speeds and rates must be 1D of equal length, rates >= 0, not all 0")
    weight = r * w**2
    eps = s.epsilon(w)
    err = s.epsilon_err(w)

    def eff(e):
        return math.sqrt(max(0.0, 1.0 - np.sum(weight * (1.0 - e**2)) / np.sum(weight)))

    value = eff(eps)
    spread = 0.5 * abs(eff(np.minimum(eps + err, 1.0)) - eff(eps - err))
    statuses = np.array([p.status for p in s.points(w)])
    share = {st: float(np.sum(weight[statuses == st]) / np.sum(weight)) for st in set(statuses)}
    worst = max(
        (st for st, f in share.items() if f > 0.01), key=_ORDER.index, default=Status.COMPUTED
    )
    by_status = ", ".join(f"{k} {v:.0%}" for k, v in sorted(share.items()))
    return Constant(
        value,
        spread,
        f"{how or 'dissipation-weighted average over the given speeds'}; weight by status: "
        + by_status,
        worst,
    )


# -- constants per pair of particle types (bidisperse packings) ---------------------------------

SAME_SIZE_NOTE = (
    "identical grains of one material have the same epsilon(w) whatever their size: the law "
    "depends on w/c only (the model has no other length), so 1-1 and 2-2 share one constant"
)
"""Why the type pairs 1-1 and 2-2 of one material take the same constant."""

TWO_MATERIALS_NOTE = (
    "two materials: 1-1 and 2-2 are each material's law of identical grains (whatever their "
    "size), 1-2 the law of the two grains; the speeds of all three are relative normal speeds "
    "in m/s"
)
"""How the type pairs of two materials are served."""


def _check_type_pair_laws(pair: SILaw, identical: SILaw, identical2: SILaw | None = None) -> None:
    """One-line refusal unless ``pair`` is a pair's law and ``identical`` the law of two
    identical grains of its first material and geometry (and, for two materials,
    ``identical2`` that of the partner's)."""
    if pair.law.partner is None:
        raise InputError(
            "the 1-2 constant needs the law of two different grains (an SILaw with "
            "law.partner, si_law(..., against='grain', radius_ratio=R) with R != 1, or with "
            "partner_grain); give that as the pair's law"
        )
    for law, which in ((identical, "1-1"), (identical2, "2-2")):
        if law is not None and (law.law.partner is not None or law.against != "grain"):
            raise InputError(
                f"the {which} constant needs the law of two identical grains (si_law(..., "
                f"against='grain') without a radius ratio), got {law.against_meaning!r}"
            )
    if pair.grain != identical.grain:
        raise InputError(
            f"the pair's law is for {pair.grain.describe()}, the identical grains' for "
            f"{identical.grain.describe()}; give both laws for one material and geometry"
        )
    other = pair.partner_grain
    if other is None and identical2 is not None:
        raise InputError(
            "the pair is of one material: 1-1 and 2-2 share the law of identical grains; leave "
            "out the second one"
        )
    if other is not None and (identical2 is None or identical2.grain != other):
        raise InputError(
            f"the pair's second grain is {other.describe()}: give the law of two identical "
            "grains of that material for the 2-2 constant (identical2)"
        )


@dataclass(frozen=True, eq=False)
class TypePairs:
    """The constants of a bidisperse packing, per pair of particle types.

    One material: type 1 is the small grain (radius ``R1``), type 2 the large one (``R2 =
    radius_ratio R1``). Two identical grains of one material have the same ``epsilon(w)``
    whatever their size (the law depends on ``w / c`` only), so 1-1 and 2-2 share :attr:`same`,
    from the law of identical grains; 1-2 (:attr:`mixed`) comes from the pair's law.

    Two materials (``pair.partner_grain``): type 1 is this grain (material of ``pair.grain``,
    radius ``R1``), type 2 the partner (``pair.partner_grain``, ``R2 = radius_ratio R1``); 1-1
    comes from :attr:`identical`, 2-2 from :attr:`identical2` (:attr:`same2`).

    Built by :func:`type_pair_constants`; every snippet function takes it in place of a
    :class:`Constant` (with ``s`` its :attr:`pair`).

    Attributes
    ----------
    pair : SILaw
        The pair's law: ``w`` the relative normal speed of the two grains, m/s.
    identical : SILaw
        The law of two identical grains of type 1's material and geometry (``w`` their relative
        normal speed, m/s).
    mixed : Constant
        Type pair 1-2.
    same : Constant
        Type pair 1-1 (and 2-2 for one material).
    identical2 : SILaw or None
        Two materials: the law of two identical grains of type 2's material.
    same2 : Constant or None
        Two materials: type pair 2-2.
    """

    pair: SILaw
    identical: SILaw
    mixed: Constant
    same: Constant
    identical2: SILaw | None = None
    same2: Constant | None = None

    def __post_init__(self) -> None:
        _check_type_pair_laws(self.pair, self.identical, self.identical2)
        if (self.identical2 is None) != (self.same2 is None):
            raise InputError("give identical2 and same2 together (two materials) or neither")

    @property
    def radius_ratio(self) -> float:
        """``R2 / R1``: type 2's radius over type 1's (``> 1`` for one material)."""
        return self.pair.law.partner.radius_ratio

    @property
    def two_materials(self) -> bool:
        """Whether the types are of two materials."""
        return self.pair.partner_grain is not None

    @property
    def grains(self) -> dict[int, object]:
        """Type -> its :class:`~restitution.laws.units.Grain` (material and geometry)."""
        return {1: self.pair.grain, 2: self.pair.partner_grain or self.pair.grain}

    @property
    def constants(self) -> dict[tuple[int, int], Constant]:
        """``(i, j) -> Constant`` for the type pairs ``(1, 1)``, ``(2, 2)`` and ``(1, 2)``."""
        return {(1, 1): self.same, (2, 2): self.same2 or self.same, (1, 2): self.mixed}

    def matrix(self) -> np.ndarray:
        """epsilon per type pair, a symmetric 2 x 2 array (row, column: type - 1)."""
        c = self.constants
        return np.array([[c[1, 1].epsilon, c[1, 2].epsilon], [c[1, 2].epsilon, c[2, 2].epsilon]])

    def type_words(self) -> dict[str, str]:
        """What types 1 and 2 are, for comments and JSON."""
        r = self.radius_ratio
        if self.two_materials:
            g1, g2 = self.grains[1], self.grains[2]
            return {
                "1": f"this grain (radius R1): {g1.describe()}",
                "2": f"the partner grain (R2 = {r:g} R1): {g2.describe()}",
            }
        return {
            "1": "the small grain (radius R1)",
            "2": f"the large grain (R2 = {r:g} R1), same material",
        }

    def to_dict(self) -> dict:
        """JSON-ready: the types, the three constants and the laws they come from."""
        name = self.pair.grain.law_nu_name

        def source(s: SILaw) -> dict:
            return {name: float(s.law.nu), "source": s.law_source}

        if self.two_materials:
            laws = {"1-1": source(self.identical), "2-2": source(self.identical2)}
            note = TWO_MATERIALS_NOTE
        else:
            laws = {"1-1, 2-2": source(self.identical)}
            note = SAME_SIZE_NOTE
        return {
            "types": self.type_words(),
            "radius_ratio": self.radius_ratio,
            **{f"{i}-{j}": c.to_dict() for (i, j), c in self.constants.items()},
            "laws": {**laws, "1-2": source(self.pair)},
            "note": note,
        }


def type_pair_constants(
    pair: SILaw,
    identical: SILaw,
    *,
    speed_m_s: float | None = None,
    temperature_m2_s2: float | None = None,
    identical2: SILaw | None = None,
) -> TypePairs:
    """The constants of a bidisperse packing per pair of particle types, at one reference.

    Parameters
    ----------
    pair : SILaw
        The law of two different grains (``pair.law.partner`` set; from ``si_law(...,
        against="grain", radius_ratio=R[, partner_grain=...])``); gives type pair 1-2.
    identical : SILaw
        The law of two identical grains of the pair's first material and geometry
        (``si_law(..., against="grain")``); gives type pair 1-1 (and 2-2 for one material).
    speed_m_s : float, optional
        Reference relative normal speed ``w``, m/s: each constant is its law at ``w``
        (:func:`constant_at`).
    temperature_m2_s2 : float, optional
        Granular temperature ``<v_x^2>`` of both sizes, m^2/s^2: each constant is its law
        averaged over a Maxwell gas (:func:`maxwell_constant`). Give this or ``speed_m_s``.
    identical2 : SILaw, optional
        Two materials: the law of two identical grains of the partner's material; gives 2-2.

    Returns
    -------
    TypePairs

    Raises
    ------
    InputError
        For laws that do not fit together, neither or both references, or a reference outside
        a law (the message names the type pair).
    """
    if (speed_m_s is None) == (temperature_m2_s2 is None):
        raise InputError(
            "the type-pair constants need one reference: a speed (m/s) or a Maxwell "
            "temperature (m^2/s^2), not both and not neither"
        )
    _check_type_pair_laws(pair, identical, identical2)

    def one(s: SILaw, name: str) -> Constant:
        try:
            if speed_m_s is not None:
                return constant_at(s, speed_m_s)
            return maxwell_constant(s, temperature_m2_s2)
        except InputError as exc:
            raise InputError(f"type pair {name}: {exc}") from None

    if identical2 is None:
        return TypePairs(
            pair,
            identical,
            mixed=one(pair, "1-2 (small with large)"),
            same=one(identical, "1-1 and 2-2 (identical grains)"),
        )
    return TypePairs(
        pair,
        identical,
        mixed=one(pair, "1-2 (this grain with the partner)"),
        same=one(identical, "1-1 (two grains of this material)"),
        identical2=identical2,
        same2=one(identical2, "2-2 (two grains of the partner's material)"),
    )


# -- snippets ------------------------------------------------------------------------------------


def _constants(s: SILaw, c: Constant | TypePairs) -> dict[tuple[int, int], Constant]:
    """``(i, j) -> Constant`` per pair of particle types: ``{(1, 1): c}`` for one constant."""
    if isinstance(c, TypePairs):
        if c.pair is not s:
            raise InputError(
                "constants per type pair go with their pair's law: pass TypePairs.pair as the law"
            )
        return c.constants
    return {(1, 1): c}


def _constant_line(c: Constant) -> str:
    return f"epsilon = {c.epsilon:.6f} +- {c.epsilon_err:.2g}, {c.how}"


def _comment(s: SILaw, c: Constant | TypePairs, mark: str) -> str:
    lines = _header(s)
    if isinstance(c, TypePairs) and c.two_materials:
        words = c.type_words()
        lines += [
            f"type 1 = {words['1']}",
            f"type 2 = {words['2']}",
            f"1-2: {_constant_line(c.mixed)}; status: {c.mixed.status}",
            f"1-1: {_constant_line(c.same)}; status: {c.same.status}",
            f"2-2: {_constant_line(c.same2)}; status: {c.same2.status}",
            f"1-1 {_law_line(c.identical)}",
            f"2-2 {_law_line(c.identical2)}",
            TWO_MATERIALS_NOTE,
        ]
    elif isinstance(c, TypePairs):
        lines += [
            f"types: 1 = the small grain (radius R1), 2 = the large one (R2 = "
            f"{c.radius_ratio:g} R1), one material",
            f"1-2 (small with large): {_constant_line(c.mixed)}; status: {c.mixed.status}",
            f"1-1 and 2-2 (two grains of one size): {_constant_line(c.same)}; status: "
            f"{c.same.status}",
            f"1-1 and 2-2 {_law_line(c.identical)}",
            SAME_SIZE_NOTE,
        ]
    else:
        lines += [f"constant: {_constant_line(c)}", f"status: {c.status}"]
    lines.append(
        "only epsilon comes from restitution; stiffness and contact time come from the code's "
        "own contact model"
    )
    return "\n".join(f"{mark} {line}" for line in lines)


def _particles(s: SILaw) -> str:
    """What the DEM code's particles stand for, for the snippets' comments."""
    if s.grain.body == "sphere":
        return "this law is the sphere's: it applies to the code's spherical particles"
    return (
        f"this law is the {s.grain.geometry}'s (a 2D disk), not a sphere's: use it for "
        "disk-shaped grains (e.g. a 2D simulation)"
    )


def _lammps_model(g, eps: float) -> str:
    """The ``granular`` model arguments: Hertz with the 3D ``E`` and ``nu``, epsilon as the
    restitution coefficient, frictionless tangential model."""
    return (
        f"hertz/material {g.E:.8g} {eps:.8f} {g.nu:.8g} "
        "tangential linear_nohistory 1.0 0.0 damping coeff_restitution"
    )


def _grain_of(s: SILaw, c: Constant | TypePairs, i: int):
    """The grain of particle type ``i``: the partner's material for type 2 of two materials."""
    return c.grains[i] if isinstance(c, TypePairs) else s.grain


def _lammps_mixed(g1, g2) -> str:
    """``hertz/material`` arguments ``E`` and ``nu`` for an explicit 1-2 ``pair_coeff`` of two
    materials. LAMMPS reads an explicit ``pair_coeff i j`` as one material on both sides
    (stiffness ``4/3 E / (2 (1 - nu^2))``); ``nu = 0`` and ``E = 2 E*`` with
    ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`` give the two materials' Hertz stiffness."""
    e_star = 1.0 / ((1.0 - g1.nu**2) / g1.E + (1.0 - g2.nu**2) / g2.E)
    return f"{2.0 * e_star:.12g}", "0.0"


def lammps_snippet(s: SILaw, c: Constant | TypePairs) -> str:
    """Input lines for LAMMPS (GRANULAR package), SI units.

    Hertz contact with the material's 3D ``E`` and ``nu``; ``damping coeff_restitution`` makes
    LAMMPS take the second normal coefficient as the coefficient of restitution. Frictionless
    tangential model; replace it with yours.

    * Two grains: ``pair_style granular`` with ``pair_coeff * *`` for one constant, or
      ``pair_coeff 1 1``, ``2 2`` and ``1 2`` for a :class:`TypePairs` (type 1 the small
      grains).
    * A wall: ``fix wall/gran granular`` with the same model and a ``zplane`` wall at ``z = 0``
      (replace the wall geometry with yours). ``pair_coeff`` does not act on walls: a grain
      would pass through them. Grain-grain contacts need the law of two grains
      (``--against grain``), not this constant.
    """
    g = s.grain
    consts = _constants(s, c)
    head = [_comment(s, c, "#"), f"# {_particles(s)}"]
    if s.against == "wall":
        return "\n".join(
            [
                *head,
                "# needs: units si, atom_style sphere, comm_modify vel yes",
                "# the wall: a plane at z = 0 below the grains (change zplane 0.0 NULL to your "
                "wall); grain-grain contacts take the law of two grains (--against grain)",
                "fix restitution_wall all wall/gran granular "
                f"{_lammps_model(g, consts[1, 1].epsilon)} zplane 0.0 NULL",
                "",
            ]
        )
    if len(consts) == 1:
        pairs, needs = {("*", "*"): consts[1, 1]}, ""
    elif c.two_materials:
        pairs, needs = consts, ", create_box 2 (type 1 this grain, type 2 the partner grain)"
    else:
        pairs, needs = consts, ", create_box 2 (type 1 the small grains, type 2 the large)"
    lines = []
    for (i, j), k in pairs.items():
        if i == j or i == "*" or not c.two_materials:
            model = _lammps_model(_grain_of(s, c, 1 if i == "*" else i), k.epsilon)
        else:
            e12, nu12 = _lammps_mixed(c.grains[1], c.grains[2])
            lines.append(
                "# 1-2: E = 2 E* and nu = 0, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2: an explicit "
                "pair_coeff is read as one material on both sides"
            )
            model = (
                f"hertz/material {e12} {k.epsilon:.8f} {nu12} "
                "tangential linear_nohistory 1.0 0.0 damping coeff_restitution"
            )
        lines.append(f"pair_coeff {i} {j} {model}")
    return "\n".join(
        [
            *head,
            f"# needs: units si, atom_style sphere, comm_modify vel yes{needs}",
            "pair_style granular",
            *lines,
            "",
        ]
    )


def liggghts_snippet(s: SILaw, c: Constant | TypePairs) -> str:
    """Input lines for LIGGGHTS (``coefficientRestitution peratomtypepair``): one atom type for
    one constant, two for a :class:`TypePairs` (type 1 the small grains; the matrix row by
    row)."""
    consts = _constants(s, c)
    n = 2 if len(consts) > 1 else 1
    matrix = [
        consts[min(i, j), max(i, j)].epsilon for i in range(1, n + 1) for j in range(1, n + 1)
    ]
    grains = [_grain_of(s, c, i) for i in range(1, n + 1)]
    moduli = " ".join(f"{g.E:.8g}" for g in grains)
    poisson = " ".join(f"{g.nu:.8g}" for g in grains)
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            f"fix m1 all property/global youngsModulus peratomtype {moduli}",
            f"fix m2 all property/global poissonsRatio peratomtype {poisson}",
            f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
            + " ".join(f"{e:.8f}" for e in matrix),
            f"fix m4 all property/global coefficientFriction peratomtypepair {n} "
            + " ".join(["0.0"] * (n * n)),
            "pair_style gran model hertz tangential history",
            "pair_coeff * *",
            "",
        ]
    )


def _mass_ratio(s: SILaw, r: float) -> str:
    """``m2 = ... m1`` of two grains with radius ratio ``r`` (and, of two materials, density
    ratio ``rho2 / rho1``)."""
    if s.partner_grain is not None:
        q = s.partner_grain.rho / s.grain.rho
        return (
            f"m2 = r^2 (rho2/rho1) m1 = {r**2 * q:.6g} m1 for disks of one thickness (cylinders "
            "of one length)"
        )
    if s.grain.body == "sphere":
        return f"m2 = r^3 m1 = {r**3:.6g} m1 for spheres"
    return f"m2 = r^2 m1 = {r**2:.6g} m1 for disks of one thickness (cylinders of one length)"


def _mercury_mass(s: SILaw, c: Constant | TypePairs) -> str:
    """What MercuryDPM's ``mass`` argument must be for this partner and body.

    ``setCollisionTimeAndRestitutionCoefficient(tc, eps, mass)`` takes the effective mass
    ``2 m1 m2 / (m1 + m2)`` (MercuryDPM's ``LinearViscoelasticNormalSpecies``): the particle
    mass ``m`` for two identical grains, ``2 m`` for a grain against a wall (``m2`` infinite),
    ``2 m1 m2 / (m1 + m2)`` for a small and a large grain.
    """
    head = "mass: the effective mass 2 m1 m2 / (m1 + m2) (kg)"
    pair = s.law.partner
    if pair is not None:
        ratio = _mass_ratio(s, pair.radius_ratio)
        which = "type 1 and type 2" if s.partner_grain is not None else "a small and a large"
        both = f"m1, m2 the masses of {which} particle ({ratio})"
        if isinstance(c, TypePairs):
            each = "m1 for 1-1, m2 for 2-2, 2 m1 m2 / (m1 + m2) for 1-2"
            return f"{head} of each type pair: {each}; {both}"
        return f"{head} of the small and the large grain; {both}"
    m = "m = 4/3 pi rho R^3" if s.grain.body == "sphere" else "m the particle mass"
    which = "two identical grains: m" if s.against == "grain" else "a grain on a wall: 2 m"
    return f"{head}; for {which}, {m}"


def _mercury_species(name: str, rho: float, eps: float, mass: str) -> list[str]:
    return [
        f"auto {name} = speciesHandler.copyAndAddObject(LinearViscoelasticSpecies());",
        f"{name}->setDensity({rho:.8g});",
        f"{name}->setCollisionTimeAndRestitutionCoefficient(tc, {eps:.8f}, {mass});",
    ]


def mercurydpm_snippet(s: SILaw, c: Constant | TypePairs) -> str:
    """C++ lines for MercuryDPM (``LinearViscoelasticSpecies``; choose the collision time). A
    :class:`TypePairs` gives a species per type (``species1`` the small grains, ``species2`` the
    large) and their mixed species (``speciesHandler.getMixedObject``)."""
    g = s.grain
    consts = _constants(s, c)
    if len(consts) == 1:
        body = _mercury_species("species", g.rho, consts[1, 1].epsilon, "mass")
    else:
        two = c.two_materials
        body = [
            "// type 1: this grain's material" if two else "// type 1: the small grains",
            *_mercury_species("species1", c.grains[1].rho, consts[1, 1].epsilon, "m1"),
            "// type 2: the partner's material" if two else "// type 2: the large grains",
            *_mercury_species("species2", c.grains[2].rho, consts[2, 2].epsilon, "m2"),
            "// 1-2: type 1 with type 2" if two else "// 1-2: a small grain with a large one",
            "auto species12 = speciesHandler.getMixedObject(species1, species2);",
            "species12->setCollisionTimeAndRestitutionCoefficient(tc, "
            f"{consts[1, 2].epsilon:.8f}, 2 * m1 * m2 / (m1 + m2));",
        ]
    return "\n".join(
        [
            _comment(s, c, "//"),
            f"// {_particles(s)}",
            f"// tc: your collision time (s); {_mercury_mass(s, c)}",
            *body,
            "",
        ]
    )


def yade_snippet(s: SILaw, c: Constant | TypePairs) -> str:
    """Python lines for YADE (Hertz-Mindlin with ``en``). A :class:`TypePairs` gives two
    materials of the same constants (``mat1`` for the small grains, ``mat2`` for the large) and
    ``en`` as a ``MatchMaker`` over their ids."""
    consts = _constants(s, c)

    def mat(g) -> str:
        return (
            f"O.materials.append(FrictMat(young={g.E:.8g}, poisson={g.nu:.8g}, "
            f"density={g.rho:.8g}, frictionAngle=0.0))"
        )

    if len(consts) == 1:
        body = [
            mat(s.grain),
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en={consts[1, 1].epsilon:.8f})",
        ]
    else:
        matches = ", ".join(f"(mat{i}, mat{j}, {k.epsilon:.8f})" for (i, j), k in consts.items())
        two = c.two_materials
        body = [
            f"mat1 = {mat(c.grains[1])}  # type 1: "
            + ("this grain's material" if two else "the small grains"),
            f"mat2 = {mat(c.grains[2])}  # type 2: "
            + ("the partner's material" if two else "the large grains (same constants, own id)"),
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=({matches})))",
            "# give type 1 particles material=mat1, type 2 material=mat2"
            if two
            else "# give the small particles material=mat1, the large ones material=mat2",
        ]
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            *body,
            "# use ip2 in the InteractionLoop with Law2_ScGeom_MindlinPhys_Mindlin()",
            "",
        ]
    )
