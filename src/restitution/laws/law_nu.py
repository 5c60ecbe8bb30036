"""epsilon(v) at any Poisson number of a body: shipped laws and their interpolation in nu.

The package ships laws ``epsilon(v)`` on a grid of Poisson numbers of each body: the disk's 2D
ones (``restitution/laws/data/law_nu<nu>.json``) and the sphere's 3D ones
(``law_sphere_nu<nu>.json``), :func:`restitution.laws.law_load.law`. :func:`law_for` serves,
for the body ``geometry`` and from its laws only,

* a shipped law when ``nu`` is within :data:`NU_MATCH` of a grid value (the 3D Poisson number is
  never known that well, and the JSON of every served point names the law's own ``nu``);
* otherwise, inside the grid and with at least three grid values, :class:`NuInterpolatedLaw`:
  at each speed the grid laws are interpolated in ``nu`` by a monotone cubic (PCHIP), and the
  error adds, in quadrature to the interpolated point errors, an estimate of the interpolation
  error from the leave-one-out errors: at every interior grid value the law is predicted from
  the others and compared with the computed one (at ``v``, ``v/2`` and ``2v``:
  :data:`SPEED_WINDOW`); ``nu`` between two grid values, at the fraction ``t`` of their
  interval, gets ``4 t (1 - t)`` times the larger of their two
  (:meth:`NuInterpolatedLaw.interpolation_err`): zero at a grid value, so the error is
  continuous in ``nu`` and serving a grid law within :data:`NU_MATCH` as it is changes
  nothing but round-off;
* else an :class:`~restitution.errors.InputError` that names the shipped values and the command
  that computes the law (``restitution curve [--geometry sphere] --nu NU --production --out
  DIR``), whose JSON is then served with ``path=``, or ``restitution law ... --compute``.
"""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass
from functools import cached_property
from importlib import resources

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.errors import InputError, describe, real
from restitution.laws.law import EpsilonLaw, _check_partner, _speeds
from restitution.laws.law_file import _curve_command, _file_nu, law_filename
from restitution.laws.law_load import NU_MATCH, _refuse_other_body, law

__all__ = [
    "NU_MATCH",
    "SPEED_WINDOW",
    "NuInterpolatedLaw",
    "law_for",
    "shipped_match",
    "shipped_nus",
]

SPEED_WINDOW = (0.5, 2.0)
"""The ``nu``-interpolation term at ``v`` is the largest leave-one-out error at ``v`` and at
these multiples of it (inside the grid laws' range): the leave-one-out prediction's miss is a
signed function of ``v`` that changes sign, and at a sign change its size says nothing of the
interpolation's (at ``nu_2d = 0.7`` the miss passes through zero near ``v = 1e-3``: 1.3e-5
there between 2.1e-3 at ``5e-4`` and 8e-4 at ``2e-3``, where PCHIP through the first grid
missed the direct law at ``nu_2d = 0.8`` by 3.3e-4). The window is the spacing of the production
speeds (1, 2, 5 per decade)."""


def shipped_nus(geometry: str = DEFAULT_GEOMETRY, partner=None) -> list[float]:
    """The Poisson numbers with a law of the body ``geometry`` (with a ``partner``: of that
    pair) in ``restitution/laws/data`` (2D for the disk, 3D for the sphere), increasing."""
    geometry = body_kind(geometry).geometry
    data = resources.files("restitution.laws").joinpath("data")
    try:
        found = [_file_nu(p.name, geometry, partner) for p in data.iterdir()]
    except (FileNotFoundError, NotADirectoryError, OSError):
        return []
    return sorted(x for x in found if x is not None)


def shipped_match(nu: float, geometry: str = DEFAULT_GEOMETRY, partner=None) -> float | None:
    """The Poisson number of the shipped law that serves ``nu`` as it is (within
    :data:`NU_MATCH`; the nearest), or ``None`` when none does: the one answer to "is a law of
    this body (and ``partner``) shipped for ``nu``?" (else it is interpolated, computed with
    ``--compute`` or read from a file)."""
    shipped = shipped_nus(geometry, partner)
    nearest = min(shipped, key=lambda x: abs(x - nu), default=None)
    return nearest if nearest is not None and abs(nearest - nu) <= NU_MATCH else None


def _interval(x: np.ndarray, at: float) -> int:
    """The interval ``x[i] <= at < x[i + 1]`` of ``at`` (the last one closed), as
    :class:`scipy.interpolate.PPoly` finds it."""
    return int(np.clip(np.searchsorted(x, at, side="right") - 1, 0, len(x) - 2))


def _window(x: np.ndarray, at: float) -> np.ndarray:
    """The nodes a PCHIP through ``x`` uses at ``at``: the two of its interval and one
    neighbour on each side (PCHIP's slope at a node is made of its two secants), at most 4."""
    i = _interval(x, at)
    return np.arange(max(i - 1, 0), min(i + 3, len(x)))


def _end_slope(h0: float, h1: float, m0: np.ndarray, m1: np.ndarray) -> np.ndarray:
    """PCHIP's one-sided slope at an end node, as scipy's ``PchipInterpolator._edge_case``:
    zero where it points against the end's secant, three times that secant where the two
    secants differ in sign and it is steeper."""
    d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
    s0 = np.sign(m0)
    flat = np.sign(d) != s0
    steep = (s0 != np.sign(m1)) & (np.abs(d) > 3.0 * np.abs(m0))
    steep &= ~flat
    d[flat] = 0.0
    d[steep] = 3.0 * m0[steep]
    return d


def _pchip_local(x: np.ndarray, y: np.ndarray, at: float, ends: tuple[bool, bool]):
    """PCHIP in ``x`` through every column of ``y`` at ``at``, from the nodes of its
    :func:`_window` only.

    ``x`` (shape (m,)) and ``y`` (shape (m, K)) hold the window's nodes, ``ends`` whether its
    first and last node end the whole grid (their slopes are then the one-sided ones). The
    arithmetic is scipy's, column by column (the slopes of ``PchipInterpolator``, the cubic of
    ``CubicHermiteSpline``, the sum of ``PPoly``), on ``K`` columns at once and on one interval
    (issue 62: scipy's cubics on every interval of 10^6 columns took 0.6 s). A column with a
    value that is not finite gives ``nan``.
    """
    y = np.asarray(y, dtype=float)
    j = _interval(x, at)
    h = np.diff(x)
    m = (y[1:] - y[:-1]) / h[:, None]
    if len(x) == 2:  # two nodes: a line
        d0 = d1 = m[0]
    else:
        d0, d1 = (_node_slope(h, m, k, len(x), ends) for k in (j, j + 1))
    s = at - x[j]
    # c1 s^2 + c0 s^3 of CubicHermiteSpline, summed as PPoly sums: y + d0 s + c1 s^2 + c0 s^3.
    t = d0 + d1
    t -= 2 * m[j]
    t /= h[j]
    c1 = m[j] - d0
    c1 /= h[j]
    c1 -= t
    t /= h[j]  # c0
    out = d0 * s
    out += y[j]
    c1 *= s * s
    out += c1
    t *= s * s * s
    out += t
    bad = ~np.isfinite(y).all(axis=0)
    if bad.any():
        out[bad] = np.nan
    return out


def _node_slope(h, m, k: int, n: int, ends: tuple[bool, bool]) -> np.ndarray:
    """PCHIP's slope at node ``k`` of ``n`` (spacings ``h``, secants ``m``): the weighted
    harmonic mean of its two secants (zero where they differ in sign or one is zero), the
    one-sided slope at an end of the grid."""
    if k == 0:
        if not ends[0]:
            raise ValueError("the slope of a window's first node is not the grid's")
        return _end_slope(h[0], h[1], m[0], m[1])
    if k == n - 1:
        if not ends[1]:
            raise ValueError("the slope of a window's last node is not the grid's")
        return _end_slope(h[-1], h[-2], m[-1], m[-2])
    w1, w2 = 2 * h[k] + h[k - 1], h[k] + 2 * h[k - 1]
    flat = np.sign(m[k]) != np.sign(m[k - 1])
    flat |= m[k] == 0
    flat |= m[k - 1] == 0
    with np.errstate(divide="ignore", invalid="ignore"):
        mean = w1 / m[k - 1]
        mean += w2 / m[k]
        mean /= w1 + w2
        mean = np.divide(1.0, mean, out=mean)
    mean[flat] = 0.0
    return mean


@dataclass(frozen=True, eq=False)
class NuInterpolatedLaw:
    """epsilon(v) at a Poisson number between grid laws, with a leave-one-out error.

    Attributes
    ----------
    nu : float
        The Poisson number served (2D for the disk, 3D for the sphere).
    nodes : tuple of EpsilonLaw
        Grid laws of one body, at least three, increasing in ``nu``, with ``nodes[0].nu < nu <
        nodes[-1].nu``, each interpolating between its points (none served at its points
        only).

    Notes
    -----
    Exposes the evaluation API of :class:`restitution.laws.law.EpsilonLaw` (``epsilon``,
    ``epsilon_err``, ``valid_range``, ``v``, ``epsilon_points``, ``epsilon_err_points``,
    ``asymptotic_ok``, ``quasistatic``) so that exports take either.

    The PCHIP in ``nu`` at one ``nu`` uses four grid laws at most (:func:`_window`), so only
    those are evaluated, and as one array per law (issue 62: 10^6 speeds took 2.6 s with every
    law evaluated twice and scipy's cubic built on every interval of every speed; the numbers
    are the same to round-off, ``tests/test_views_fast.py``). The points behind the law
    (:attr:`v`, :attr:`asymptotic_ok`, ...) are computed once.
    """

    nu: float
    nodes: tuple

    def __post_init__(self) -> None:
        nus = np.array([n.nu for n in self.nodes])
        if len(nus) < 3 or np.any(np.diff(nus) <= 0):
            raise InputError("interpolation in nu needs at least three laws, increasing in nu")
        bodies = {n.geometry for n in self.nodes}
        if len(bodies) != 1:
            raise InputError(
                f"interpolation in nu needs laws of one body, got {', '.join(sorted(bodies))}"
            )
        if len({n.partner for n in self.nodes}) != 1:
            raise InputError("interpolation in nu needs laws of one pair (or all on the wall)")
        if not nus[0] < self.nu < nus[-1]:
            raise InputError(
                f"nu = {self.nu:g} is outside the grid {nus[0]:g} ... {nus[-1]:g}; "
                "interpolation does not extrapolate"
            )
        if any(getattr(n, "at_points_only", False) for n in self.nodes):
            raise InputError(
                "interpolation in nu needs laws that interpolate between their points; a law "
                "served at its computed speeds only has no value between them"
            )

    @cached_property
    def geometry(self) -> str:
        """The body of the grid laws."""
        return self.nodes[0].geometry

    @cached_property
    def partner(self):
        """The grid laws' partner (``None``: the body on the wall; read for every speed of
        :meth:`SILaw.points`, so read once)."""
        return self.nodes[0].partner

    @property
    def routes(self) -> tuple[str, ...]:
        """The routes that made the grid laws' points (:attr:`EpsilonLaw.routes`)."""
        return tuple(sorted({r for law_ in self.nodes for r in law_.routes}))

    @cached_property
    def grid(self) -> np.ndarray:
        """The grid's Poisson numbers, shape (M,)."""
        return _frozen(np.array([n.nu for n in self.nodes]))

    @cached_property
    def valid_range(self) -> tuple[float, float]:
        """The speeds every grid law covers, units of ``c``."""
        return (
            max(n.valid_range[0] for n in self.nodes),
            min(n.valid_range[1] for n in self.nodes),
        )

    # -- evaluation ----------------------------------------------------------------------

    def _serve(self, v, outside: str, values) -> float | np.ndarray:
        """``values(w)`` (``w`` a 1-D array of speeds inside :attr:`valid_range`) at the speeds
        ``v`` of any shape, ``nan`` outside the range (raised or warned first, as ``outside``
        asks; :meth:`EpsilonLaw.epsilon`)."""
        arr = _speeds(v)
        flat = arr.ravel()
        bad = self._outside(flat, outside)
        if np.any(bad):
            out = np.full(flat.shape, np.nan)
            out[~bad] = _in_blocks(values, flat[~bad])
        else:
            out = _in_blocks(values, flat)
        return float(out[0]) if np.ndim(v) == 0 else out.reshape(arr.shape)

    def _outside(self, v: np.ndarray, outside: str) -> np.ndarray:
        """Where ``v`` is outside :attr:`valid_range` (where a grid law has no value), raised or
        warned as ``outside`` asks."""
        if not (isinstance(outside, str) and outside in ("raise", "warn", "nan")):
            raise InputError(f"outside must be 'raise', 'warn' or 'nan', not {describe(outside)}")
        lo, hi = self.valid_range
        bad = ~((v >= lo) & (v <= hi))
        if np.any(bad) and outside != "nan":
            meaning = "speed towards the wall" if self.partner is None else "relative speed"
            text = (
                f"speed(s) {np.unique(v[bad])[:5].tolist()} outside the range {lo:g} <= v <= "
                f"{hi:g} (units of c, {meaning}) every grid law of the {self.geometry} covers, "
                f"interpolated to {_what(self.nu, self.geometry)}"
            )
            if outside == "raise":
                raise InputError(
                    f"{text}; the law does not extrapolate (compute the law for this nu with "
                    f"`{_curve_command(self.geometry, self.nu, self.partner)}`, or pass "
                    "outside='nan')"
                )
            warnings.warn(text + "; returning nan", stacklevel=4)
        return bad

    def _pchip_in_nu(self, get, name: str, at: float, skip: int | None = None) -> np.ndarray:
        """PCHIP in ``nu`` at ``at`` through the grid laws' ``name`` (``"epsilon"`` or
        ``"epsilon_err"``; ``get(k, name)`` the law ``k``'s values), without the law ``skip``
        (a leave-one-out prediction); only the laws of its :func:`_window` are evaluated."""
        keep = np.array([k for k in range(len(self.nodes)) if k != skip])
        x = self.grid[keep]
        w = _window(x, at)
        y = np.array([get(k, name) for k in keep[w]])
        return _pchip_local(x[w], y, at, (w[0] == 0, w[-1] == len(x) - 1))

    def _node_values(self, v: np.ndarray):
        """``get(k, name)``: the grid law ``k``'s ``name`` at ``v`` (inside every law's range),
        each evaluated once."""
        memo = {}

        def get(k: int, name: str) -> np.ndarray:
            if (k, name) not in memo:
                memo[k, name] = getattr(self.nodes[k], name)(v, outside="nan")
            return memo[k, name]

        return get

    def _around(self) -> tuple[list[int], float]:
        """The grid laws whose leave-one-out errors make :meth:`interpolation_err` (those of
        ``nu``'s interval that are not end laws) and ``t``, the position of ``nu`` in the
        interval."""
        x = self.grid
        i = int(np.clip(np.searchsorted(x, self.nu) - 1, 0, len(x) - 2))
        t = (self.nu - x[i]) / (x[i + 1] - x[i])
        return [k for k in (i, i + 1) if 0 < k < len(x) - 1], t

    def _leave_one_out_at(self, get, k: int) -> np.ndarray:
        """``|prediction of law k from the others - law k|`` (``get``: :meth:`_node_values`)."""
        return np.abs(
            self._pchip_in_nu(get, "epsilon", float(self.grid[k]), skip=k) - get(k, "epsilon")
        )

    def _interpolation_err_at(self, get, w: np.ndarray) -> np.ndarray:
        """:meth:`interpolation_err` at the speeds ``w`` (``get``: :meth:`_node_values` of
        ``w``): the leave-one-out errors' envelope over :data:`SPEED_WINDOW`."""
        around, t = self._around()
        lo, hi = self.valid_range
        loo = [self._leave_one_out_at(get, k) for k in around]
        for factor in SPEED_WINDOW:
            near = self._node_values(np.clip(w * factor, lo, hi))
            loo += [self._leave_one_out_at(near, k) for k in around]
        return np.max(np.array(loo), axis=0) * 4.0 * t * (1.0 - t)

    def leave_one_out(self, v, *, outside: str = "raise") -> np.ndarray:
        """``|prediction without node k - node k|`` at speed(s) ``v``: the PCHIP of the other
        laws at ``nu_k``.

        Returns
        -------
        numpy.ndarray, shape (M, K)
            One row per grid law; ``nan`` for the two end laws (no extrapolation).
        """
        arr = np.atleast_1d(_speeds(v))
        flat = arr.ravel()
        bad = self._outside(flat, outside)
        get = self._node_values(flat[~bad])
        out = np.full((len(self.nodes), flat.size), np.nan)
        for k in range(1, len(self.nodes) - 1):
            out[k, ~bad] = self._leave_one_out_at(get, k)
        return out.reshape((len(self.nodes), *arr.shape))

    def interpolation_err(self, v, *, outside: str = "raise"):
        """Estimate of the interpolation error at ``self.nu``, speed(s) ``v``:
        ``4 t (1 - t)`` times the larger leave-one-out error of the two grid laws around ``nu``
        (of the one, next to an end law), the largest of it at ``v`` and at the multiples
        :data:`SPEED_WINDOW` of ``v``, ``t`` the position of ``nu`` between them (module
        docstring).

        An interpolation error vanishes at the nodes, so the estimate is continuous in ``nu``,
        zero at a grid law and the full leave-one-out error of the neighbours halfway between
        them (an end law has none; with its extrapolation from the others as one, the error at
        ``nu_2d = 0.25`` was 35 times the true one instead of 19).
        It is not reduced for the leave-one-out prediction's twice larger span: against direct
        laws at four Poisson numbers between the grid's (docs/materials.md) a quarter of it
        (second-order scaling) left the true error beyond one combined error at 55 % of the
        speeds of ``nu_2d = 0.6``; at full size 94 % of all 88 speeds were within one combined
        error and all within two, the stated error 3-19 times the true one (median over the
        speeds of each law). The earlier estimate, the grid's largest leave-one-out error at
        any ``nu``, was 4-38 times the true error and jumped at the grid values.
        """
        return self._serve(
            v, outside, lambda w: self._interpolation_err_at(self._node_values(w), w)
        )

    def epsilon(self, v, *, outside: str = "raise"):
        """Interpolated ``epsilon`` at speed(s) ``v`` towards the wall (units of ``c``);
        ``outside`` as :meth:`EpsilonLaw.epsilon`'s, for the range every grid law covers."""
        return self._serve(
            v, outside, lambda w: self._pchip_in_nu(self._node_values(w), "epsilon", self.nu)
        )

    def epsilon_err(self, v, *, outside: str = "raise"):
        """Error of :meth:`epsilon`: interpolated point error (+) leave-one-out error."""

        def err(w: np.ndarray) -> np.ndarray:
            get = self._node_values(w)
            point = np.abs(self._pchip_in_nu(get, "epsilon_err", self.nu))
            return np.hypot(point, self._interpolation_err_at(get, w))

        return self._serve(v, outside, err)

    def epsilon_sd(self, v, *, outside: str = "raise"):
        """One standard deviation of :meth:`epsilon`: the grid laws' standard deviations
        (:meth:`EpsilonLaw.epsilon_sd`) interpolated in ``nu``, joined in quadrature with the
        ``nu``-interpolation term scaled by its calibrated factor
        (:mod:`restitution.laws.calibration`, route ``nu``); where any grid law's is the bound
        (:meth:`sd_calibrated` false) it is the bound, :meth:`epsilon_err` (grid laws whose
        points come from routes calibrated and not, e.g. modal and residual, would otherwise
        give a value that is neither)."""
        from restitution.laws.calibration import CALIBRATIONS, NU

        c = CALIBRATIONS[NU].nu_factor

        def sd(w: np.ndarray) -> np.ndarray:
            get = self._node_values(w)
            cal = self._calibrated_at(w)
            point = np.where(
                cal,
                np.abs(self._pchip_in_nu(get, "epsilon_sd", self.nu)),
                np.abs(self._pchip_in_nu(get, "epsilon_err", self.nu)),
            )
            return np.hypot(point, np.where(cal, c, 1.0) * self._interpolation_err_at(get, w))

        return self._serve(v, outside, sd)

    def _calibrated_at(self, w: np.ndarray) -> np.ndarray:
        """Whether every grid law's standard deviation at the speeds ``w`` is calibrated."""
        ok = np.ones(np.shape(w), bool)
        for n in self.nodes:
            ok &= np.asarray(n.sd_calibrated(w, outside="nan"), bool)
        return ok

    def sd_calibrated(self, v, *, outside: str = "raise"):
        """Whether :meth:`epsilon_sd` at ``v`` is a calibrated standard deviation."""
        out = self._serve(v, outside, lambda w: self._calibrated_at(w).astype(float))
        return np.asarray(out) == 1.0 if np.ndim(v) else bool(out == 1.0)

    __call__ = epsilon

    # -- the points behind the law, as EpsilonLaw has them (computed once) ----------------

    @cached_property
    def v(self) -> np.ndarray:
        """Speeds computed for any grid law inside the range they all cover, increasing: each
        law's own points where epsilon(v) turns (:mod:`restitution.laws.making.refine`) are kept, so
        that what is tabulated from these points follows :meth:`epsilon` between them."""
        lo, hi = self.valid_range
        every = set()
        for n in self.nodes:
            every |= set(np.round(n.v, 12))
        return _frozen(np.array(sorted(x for x in every if lo <= x <= hi)))

    @cached_property
    def epsilon_points(self) -> np.ndarray:
        return _frozen(np.atleast_1d(self.epsilon(self.v)))

    @cached_property
    def epsilon_err_points(self) -> np.ndarray:
        return _frozen(np.atleast_1d(self.epsilon_err(self.v)))

    @cached_property
    def asymptotic_ok(self) -> np.ndarray:
        """A point is asymptotic when every grid law's points around it passed their checks
        (:meth:`EpsilonLaw.checked`: the point itself where a law computed it)."""
        ok = np.ones(self.v.size, bool)
        for n in self.nodes:
            ok &= np.atleast_1d(n.checked(self.v))
        return _frozen(ok)

    @cached_property
    def quasistatic(self) -> np.ndarray:
        """A point is from the low-speed theory when, in any grid law, it is such a point or
        lies between two of them."""
        out = np.zeros(self.v.size, bool)
        for n in self.nodes:
            q = np.asarray(n.quasistatic)
            hi = np.clip(np.searchsorted(n.v, self.v, side="left"), 0, n.v.size - 1)
            lo = np.clip(np.searchsorted(n.v, self.v, side="right") - 1, 0, n.v.size - 1)
            out |= q[lo] & q[hi]
        return _frozen(out)

    @property
    def source(self) -> str:
        return (
            f"PCHIP in nu between the laws for nu = {', '.join(f'{x:g}' for x in self.grid)} "
            "(error includes the interpolation error estimated from leave-one-out errors)"
        )


_BLOCK = 1 << 16
"""Speeds evaluated together: the some fifty array operations of a PCHIP in ``nu`` run on
blocks that stay in the processor's cache (twice as fast at 10^6 speeds as one pass each)."""


def _in_blocks(values, w: np.ndarray) -> np.ndarray:
    """``values(w)`` block by block (:data:`_BLOCK`); the same numbers (each speed alone)."""
    if w.size <= _BLOCK:
        return values(w)
    out = np.empty(w.size)
    for start in range(0, w.size, _BLOCK):
        out[start : start + _BLOCK] = values(w[start : start + _BLOCK])
    return out


def _frozen(a: np.ndarray) -> np.ndarray:
    """``a``, read-only: an array computed once and handed to every caller."""
    a.flags.writeable = False
    return a


def _what(nu: float, geometry: str) -> str:
    """``nu_2d = 0.33`` for the disk, ``sphere nu = 0.3`` else: the law's parameter (the kind's
    :attr:`~restitution.bodies.kinds.BodyKind.nu_name`), with the body unless it is the
    default one."""
    kind = body_kind(geometry)
    body = "" if kind.geometry == DEFAULT_GEOMETRY else f"{kind.geometry} "
    return f"{body}{kind.nu_name} = {nu:.6g}"


def _refusal(
    nu: float, shipped: list[float], why: str, geometry: str = DEFAULT_GEOMETRY, partner=None
) -> InputError:
    name = law_filename(nu, geometry, partner)
    pair = "" if partner is None else f" and the pair R2/R1 = {partner.radius_ratio:g}"
    cost = _cost(nu, geometry, partner)
    return InputError(
        f"no law for {_what(nu, geometry)}{pair}: {why} (grid: "
        f"{', '.join(f'{x:g}' for x in shipped) or 'none'}); compute it{cost}"
        f" with `{_curve_command(geometry, nu, partner)}` and pass the file DIR/{name} "
        "(--law-file, or path= from Python), or add --compute to `restitution law`"
    )


def _cost(nu: float, geometry: str, partner) -> str:
    """`` (N collisions, about T on one core)``: the plan of computing the law; empty when
    no plan can be made (the refusal's other words say why)."""
    from restitution import budget
    from restitution.laws.routes.base import computing_route

    try:
        p = computing_route("modal").plan(nu, geometry, partner, reuse=False)
    except InputError:
        return ""
    return f" ({p.collisions} collisions, about {budget.format_duration(p.seconds)} on one core)"


def law_for(
    nu: float,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    path: str | os.PathLike | None = None,
    laws: list[EpsilonLaw] | None = None,
    partner=None,
) -> EpsilonLaw | NuInterpolatedLaw:
    """The law ``epsilon(v)`` of the body ``geometry`` for its Poisson number ``nu``.

    Parameters
    ----------
    nu : float
        Poisson number: two-dimensional for the disk, three-dimensional for the sphere.
    geometry : str
        The body's kind (:func:`restitution.bodies.kinds.geometries`, default the disk); laws
        of another body are refused.
    path : path, optional
        A law JSON file (written by ``restitution curve``); its body must be ``geometry`` and
        its ``nu`` must match within :data:`NU_MATCH`.
    laws : list of EpsilonLaw, optional
        The grid to serve from instead of the shipped laws (for tests and for a user's own
        grid), all of the body ``geometry``.
    partner : Partner, optional
        Serve the laws of two bodies meeting head-on
        (:class:`restitution.bodies.pair.partner.Partner`; ``v`` the relative speed) instead of
        the body on the wall.

    Returns
    -------
    EpsilonLaw or NuInterpolatedLaw

    Raises
    ------
    InputError
        When ``nu`` is neither on nor inside a grid of at least three laws; the message names
        the grid and the command that computes the law.
    """
    nu = real(nu, "nu", "(the body's Poisson number)")
    geometry = body_kind(geometry).geometry
    _check_partner(partner)
    if path is not None:
        one = EpsilonLaw.from_json(path)
        _refuse_other_body(one, geometry, path, partner)
        if abs(one.nu - nu) > NU_MATCH:
            which = body_kind(geometry).nu_name
            raise InputError(
                f"the law file {path} is for {which} = {one.nu:g}, not {nu:.6g}; compute it "
                f"with `{_curve_command(geometry, nu, partner)}`"
            )
        return one
    body_kind(geometry).check_nu(nu)
    if laws is None:
        nearest = shipped_match(nu, geometry, partner)
        if nearest is not None:
            return law(nearest, geometry=geometry, partner=partner)
        shipped = shipped_nus(geometry, partner)
        _check_inside(nu, shipped, "shipped", geometry, partner)
        laws = [law(x, geometry=geometry, partner=partner) for x in shipped]
    if any(a.partner != partner for a in laws):
        raise InputError(
            "the given laws are not all laws of the asked pair (or all of the body on the wall)"
        )
    other = sorted({a.geometry for a in laws} - {geometry})
    if other:
        raise InputError(
            f"the given laws include laws of the {', '.join(other)}; a {geometry} is served "
            f"from {geometry} laws only"
        )
    grid = sorted(laws, key=lambda a: a.nu)
    nus = [a.nu for a in grid]
    nearest = min(range(len(grid)), key=lambda i: abs(nus[i] - nu))
    if abs(nus[nearest] - nu) <= NU_MATCH:
        return grid[nearest]
    _check_inside(nu, nus, "given", geometry, partner)
    return NuInterpolatedLaw(nu, tuple(grid))


def _check_inside(
    nu: float, nus: list[float], which: str, geometry: str = DEFAULT_GEOMETRY, partner=None
) -> None:
    if len(nus) < 3:
        raise _refusal(
            nu, nus, f"fewer than three {which} laws, so none is interpolated", geometry, partner
        )
    if not nus[0] < nu < nus[-1]:
        raise _refusal(nu, nus, f"outside the {which} grid", geometry, partner)
