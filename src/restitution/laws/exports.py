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
  and validity range; :func:`c_header` and :func:`fortran_include` evaluate it.
  Why this form: ``epsilon(0) = 1`` (the quasistatic limit), a power law ``1 - epsilon ~ a x^p``
  at small speeds (Rayleigh's estimate, paper section 5, gives a power of the speed), a
  saturation at large speeds through ``b``, three parameters, and one line of C.
* :func:`constant_at` (epsilon at a reference speed) and :func:`maxwell_constant` (averaged over
  the impact speeds of a gas at a granular temperature): one number for codes that take a
  constant per pair, with snippets for LAMMPS ``pair_style granular`` (:func:`lammps_snippet`),
  LIGGGHTS, MercuryDPM and YADE.
"""

from __future__ import annotations

import csv
import datetime
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import curve_fit

from restitution import atomic
from restitution._version import __version__
from restitution.errors import InputError, RestitutionError
from restitution.laws.si_law import SILaw
from restitution.laws.units import PARTNERS
from restitution.status import Status

__all__ = [
    "ClosedForm",
    "Constant",
    "c_header",
    "constant_at",
    "distribution_constant",
    "fit_closed_form",
    "fortran_include",
    "liggghts_snippet",
    "lammps_snippet",
    "maxwell_constant",
    "mercurydpm_snippet",
    "speed_table",
    "write_csv",
    "write_table",
    "yade_snippet",
]


_BODY_WORDS = {
    "cylinder": "long elastic cylinder hit along a diameter (the 2D disk in plane strain)",
    "thin-disk": "thin elastic disk hit on its rim (the 2D disk in plane stress)",
    "sphere": "elastic sphere (3D)",
}


def _header(s: SILaw) -> list[str]:
    g = s.grain
    lo, hi = s.computed_range_m_s
    if g.body == "disk":
        law_line = f"law: nu_2d = {float(s.law.nu):g}, {s.law_source}"
    else:
        law_line = f"law: the {g.body}'s, nu = {float(s.law.nu):g}, {s.law_source}"
    return [
        f"restitution {__version__}, {datetime.datetime.now(datetime.UTC):%Y-%m-%dT%H:%M:%SZ}: "
        "coefficient of restitution of an elastic grain from its vibrational modes "
        "(Gerl & Zippelius model)",
        f"grain: {g.geometry}: {_BODY_WORDS[g.geometry]}",
        f"material: {g.describe()}",
        f"partner: {s.against}: {PARTNERS[s.against]}; speed unit k c = "
        f"{s.speed_scale_m_s:.6g} m/s",
        law_line,
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
        Largest ``|form - epsilon|`` over the fitted points.
    max_deviation_sigma : float
        Largest ``|form - epsilon| / epsilon_err`` over the fitted points.
    chi2_dof : float
        ``chi^2`` per degree of freedom of the weighted fit.
    valid_m_s : tuple of float
        Fitted speeds ``(w_min, w_max)`` in m/s. The form has ``epsilon(0) = 1`` built in, but
        it is validated only on ``[w_min, w_max]``; outside, it is a guess.
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


def fit_closed_form(s: SILaw) -> ClosedForm:
    """Fit :class:`ClosedForm` to the law's computed points, weighted by their errors.

    The form falls monotonically with the speed; the two-dimensional law does not (it has a
    maximum near ``v = 0.002 - 0.02 c``, docs/results.md). The fit therefore takes the points
    from the law's last maximum up, and its validity range says so: below it, use the table.
    """
    v = np.asarray(s.law.v, dtype=float)
    eps = np.asarray(s.law.epsilon_points, dtype=float)
    err = np.asarray(s.law.epsilon_err_points, dtype=float)
    start = _decreasing_tail(eps)
    v, eps, err = v[start:], eps[start:], err[start:]
    if v.size < 4:
        raise InputError(f"a three-parameter fit needs at least 4 points, the law has {v.size}")
    sigma = np.maximum(err, 1e-6)
    try:
        popt, pcov = curve_fit(
            _form, v, eps, p0=(1.0, 0.0, 0.8), sigma=sigma, absolute_sigma=True, maxfev=20000
        )
    except (RuntimeError, ValueError) as exc:
        raise RestitutionError(f"the closed form did not fit the law's points: {exc}") from exc
    a, b, p = (float(x) for x in popt)
    if b < 0 and p > 0 and (-1.0 / b) ** (1.0 / p) <= v[-1]:
        raise RestitutionError(
            f"the closed form fitted to the law has a pole at v = {(-1.0 / b) ** (1.0 / p):.3g} c "
            "inside the computed range; use the table instead"
        )
    resid = _form(v, *popt) - eps
    chi2_dof = float(np.sum((resid / sigma) ** 2) / (v.size - 3))
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


def _fit_comment(s: SILaw, f: ClosedForm) -> list[str]:
    da, db, dp = f.errors
    return [
        *_header(s),
        "closed form: epsilon(w) = 1 - a x^p / (1 + b x^p), x = w / SPEED_SCALE (w in m/s)",
        f"a = {f.a:.6g} +- {da:.2g}, b = {f.b:.6g} +- {db:.2g}, p = {f.p:.6g} +- {dp:.2g} "
        f"(covariance in the JSON export)",
        f"max deviation from the computed points: {f.max_deviation:.3g} "
        f"({f.max_deviation_sigma:.3g} of their error bars); chi2/dof = {f.chi2_dof:.3g}",
        f"valid for 0 <= w <= {f.valid_m_s[1]:.6g} m/s (fitted {f.valid_m_s[0]:.6g} ... "
        f"{f.valid_m_s[1]:.6g} m/s)",
    ]


def _c_ident(name: str) -> str:
    out = "".join(ch if ch.isalnum() else "_" for ch in name)
    if not out or out[0].isdigit():
        raise InputError(f"{name!r} is not a usable identifier")
    return out


def c_header(s: SILaw, f: ClosedForm, name: str = "restitution") -> str:
    """A C99 header defining ``double NAME_epsilon(double w_m_s)`` (the closed form)."""
    n = _c_ident(name)
    guard = n.upper() + "_EPSILON_H"
    lines = ["/*", *(f" * {line}" for line in _fit_comment(s, f)), " */"]
    lines += [
        f"#ifndef {guard}",
        f"#define {guard}",
        "#include <math.h>",
        f"#define {n.upper()}_SPEED_SCALE_M_S {f.speed_scale_m_s!r}",
        f"#define {n.upper()}_W_MAX_M_S {f.valid_m_s[1]!r}",
        "/* coefficient of restitution at impact speed w_m_s (m/s; see 'partner' above) */",
        f"static inline double {n}_epsilon(double w_m_s)",
        "{",
        f"    const double xp = pow(w_m_s / {n.upper()}_SPEED_SCALE_M_S, {f.p!r});",
        f"    return 1.0 - {f.a!r} * xp / (1.0 + {f.b!r} * xp);",
        "}",
        f"#endif /* {guard} */",
        "",
    ]
    return "\n".join(lines)


def _fortran_real(x: float) -> str:
    return f"{x:.17e}".replace("e", "d")


def fortran_include(s: SILaw, f: ClosedForm, name: str = "restitution") -> str:
    """A Fortran include file with ``pure function NAME_epsilon(w_m_s)`` (the closed form).

    Include it after ``contains`` in a module or program.
    """
    n = _c_ident(name)
    lines = [f"! {line}" for line in _fit_comment(s, f)]
    lines += [
        f"pure function {n}_epsilon(w_m_s) result(eps)",
        "  double precision, intent(in) :: w_m_s",
        "  double precision :: eps, xp",
        f"  xp = (w_m_s / {_fortran_real(f.speed_scale_m_s)})**{_fortran_real(f.p)}",
        f"  eps = 1d0 - {_fortran_real(f.a)} * xp / (1d0 + {_fortran_real(f.b)} * xp)",
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
        f"epsilon at w = {speed_m_s:g} m/s ({s.against}: {PARTNERS[s.against]})",
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
    return distribution_constant(
        s,
        w,
        rate,
        how=f"dissipation-weighted average over a Maxwell gas at T = {T:g} m^2/s^2 "
        f"({s.against}: normal speed variance {sigma2:g} m^2/s^2)",
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


def _comment(s: SILaw, c: Constant, mark: str) -> str:
    lines = [
        *_header(s),
        f"constant: epsilon = {c.epsilon:.6f} +- {c.epsilon_err:.2g}, {c.how}",
        f"status: {c.status}",
        "only epsilon comes from restitution; stiffness and contact time come from the code's "
        "own contact model",
    ]
    return "\n".join(f"{mark} {line}" for line in lines)


def _particles(s: SILaw) -> str:
    """What the DEM code's particles stand for, for the snippets' comments."""
    if s.grain.body == "sphere":
        return "this law is the sphere's: it applies to the code's spherical particles"
    return (
        f"this law is the {s.grain.geometry}'s (a 2D disk), not a sphere's: use it for "
        "disk-shaped grains (e.g. a 2D simulation)"
    )


def lammps_snippet(s: SILaw, c: Constant) -> str:
    """Input lines for LAMMPS ``pair_style granular`` (GRANULAR package), SI units.

    Hertz contact with the material's 3D ``E`` and ``nu``; ``damping coeff_restitution`` makes
    LAMMPS take the second normal coefficient as the coefficient of restitution. Frictionless
    tangential model; replace it with yours.
    """
    g = s.grain
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            "# needs: units si, atom_style sphere, comm_modify vel yes",
            "pair_style granular",
            f"pair_coeff * * hertz/material {g.E:.8g} {c.epsilon:.8f} {g.nu:.8g} "
            "tangential linear_nohistory 1.0 0.0 damping coeff_restitution",
            "",
        ]
    )


def liggghts_snippet(s: SILaw, c: Constant) -> str:
    """Input lines for LIGGGHTS (one atom type; ``coefficientRestitution peratomtypepair``)."""
    g = s.grain
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            f"fix m1 all property/global youngsModulus peratomtype {g.E:.8g}",
            f"fix m2 all property/global poissonsRatio peratomtype {g.nu:.8g}",
            f"fix m3 all property/global coefficientRestitution peratomtypepair 1 {c.epsilon:.8f}",
            "fix m4 all property/global coefficientFriction peratomtypepair 1 0.0",
            "pair_style gran model hertz tangential history",
            "pair_coeff * *",
            "",
        ]
    )


def _mercury_mass(s: SILaw) -> str:
    """What MercuryDPM's ``mass`` argument must be for this partner and body.

    ``setCollisionTimeAndRestitutionCoefficient(tc, eps, mass)`` takes the effective mass
    ``2 m1 m2 / (m1 + m2)`` (MercuryDPM's ``LinearViscoelasticNormalSpecies``): the particle
    mass ``m`` for two identical grains, ``2 m`` for a grain against a wall (``m2`` infinite).
    """
    m = "m = 4/3 pi rho R^3" if s.grain.body == "sphere" else "m the particle mass"
    which = "two identical grains: m" if s.against == "grain" else "a grain on a wall: 2 m"
    return f"mass: the effective mass 2 m1 m2 / (m1 + m2) (kg); for {which}, {m}"


def mercurydpm_snippet(s: SILaw, c: Constant) -> str:
    """C++ lines for MercuryDPM (``LinearViscoelasticSpecies``; choose the collision time)."""
    g = s.grain
    return "\n".join(
        [
            _comment(s, c, "//"),
            f"// {_particles(s)}",
            f"// tc: your collision time (s); {_mercury_mass(s)}",
            "auto species = speciesHandler.copyAndAddObject(LinearViscoelasticSpecies());",
            f"species->setDensity({g.rho:.8g});",
            f"species->setCollisionTimeAndRestitutionCoefficient(tc, {c.epsilon:.8f}, mass);",
            "",
        ]
    )


def yade_snippet(s: SILaw, c: Constant) -> str:
    """Python lines for YADE (Hertz-Mindlin with ``en``)."""
    g = s.grain
    return "\n".join(
        [
            _comment(s, c, "#"),
            f"# {_particles(s)}",
            f"O.materials.append(FrictMat(young={g.E:.8g}, poisson={g.nu:.8g}, "
            f"density={g.rho:.8g}, frictionAngle=0.0))",
            f"ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en={c.epsilon:.8f})",
            "# use ip2 in the InteractionLoop with Law2_ScGeom_MindlinPhys_Mindlin()",
            "",
        ]
    )
