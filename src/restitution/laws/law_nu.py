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
  the others and compared with the computed one; ``nu`` between two grid values, at the
  fraction ``t`` of their interval, gets ``4 t (1 - t)`` times the larger of their two
  (:meth:`NuInterpolatedLaw.interpolation_err`): zero at a grid value, so the error is
  continuous in ``nu`` and serving a grid law within :data:`NU_MATCH` as it is changes
  nothing but round-off;
* else an :class:`~restitution.errors.InputError` that names the shipped values and the command
  that computes the law (``restitution curve [--geometry sphere] --nu NU --production --out
  DIR``), whose JSON is then served with ``path=``, or ``restitution law ... --compute``.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from importlib import resources

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.errors import InputError, real
from restitution.laws.law import EpsilonLaw, _check_partner
from restitution.laws.law_file import _curve_command, _file_nu, law_filename
from restitution.laws.law_load import NU_MATCH, _refuse_other_body, law

__all__ = ["NU_MATCH", "NuInterpolatedLaw", "law_for", "shipped_match", "shipped_nus"]


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


def _pchip(x: np.ndarray, y: np.ndarray, at: float) -> np.ndarray:
    """PCHIP through ``(x, y[:, j])`` for every column ``j``, at ``at``; linear for 2 nodes. A
    column with a value missing (``nan``: a speed outside a grid law's range, asked with
    ``outside="nan"``) is ``nan`` (issue 62: one such speed raised scipy's "`y` must contain
    only finite values" for every speed)."""
    y = np.asarray(y, dtype=float)
    ok = np.all(np.isfinite(y), axis=0)
    if np.all(ok):
        return PchipInterpolator(x, y, axis=0, extrapolate=True)(at)
    out = np.full(y.shape[1:], np.nan)
    if np.any(ok):
        out[ok] = PchipInterpolator(x, y[:, ok], axis=0, extrapolate=True)(at)
    return out


@dataclass(frozen=True, eq=False)
class NuInterpolatedLaw:
    """epsilon(v) at a Poisson number between grid laws, with a leave-one-out error.

    Attributes
    ----------
    nu : float
        The Poisson number served (2D for the disk, 3D for the sphere).
    nodes : tuple of EpsilonLaw
        Grid laws of one body, at least three, increasing in ``nu``, with ``nodes[0].nu < nu <
        nodes[-1].nu``.

    Notes
    -----
    Exposes the evaluation API of :class:`restitution.laws.law.EpsilonLaw` (``epsilon``,
    ``epsilon_err``, ``valid_range``, ``v``, ``epsilon_points``, ``epsilon_err_points``,
    ``asymptotic_ok``, ``quasistatic``) so that exports take either.
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

    @property
    def geometry(self) -> str:
        """The body of the grid laws."""
        return self.nodes[0].geometry

    @property
    def partner(self):
        """The grid laws' partner (``None``: the body on the wall)."""
        return self.nodes[0].partner

    @property
    def routes(self) -> tuple[str, ...]:
        """The routes that made the grid laws' points (:attr:`EpsilonLaw.routes`)."""
        return tuple(sorted({r for law_ in self.nodes for r in law_.routes}))

    @property
    def grid(self) -> np.ndarray:
        """The grid's Poisson numbers, shape (M,)."""
        return np.array([n.nu for n in self.nodes])

    @property
    def valid_range(self) -> tuple[float, float]:
        """The speeds every grid law covers, units of ``c``."""
        return (
            max(n.valid_range[0] for n in self.nodes),
            min(n.valid_range[1] for n in self.nodes),
        )

    def _node_values(self, v: np.ndarray, outside: str) -> tuple[np.ndarray, np.ndarray]:
        eps = np.array([np.atleast_1d(n.epsilon(v, outside=outside)) for n in self.nodes])
        err = np.array([np.atleast_1d(n.epsilon_err(v, outside=outside)) for n in self.nodes])
        return eps, err

    def leave_one_out(self, v, *, outside: str = "raise") -> np.ndarray:
        """``|prediction without node k - node k|`` at speed(s) ``v``: the PCHIP of the other
        laws at ``nu_k``.

        Returns
        -------
        numpy.ndarray, shape (M, K)
            One row per grid law; ``nan`` for the two end laws (no extrapolation).
        """
        v = np.atleast_1d(np.asarray(v, dtype=float))
        eps, _ = self._node_values(v, outside)
        x = self.grid
        out = np.full(eps.shape, np.nan)
        for k in range(1, len(x) - 1):
            keep = np.arange(len(x)) != k
            out[k] = np.abs(_pchip(x[keep], eps[keep], x[k]) - eps[k])
        return out

    def interpolation_err(self, v, *, outside: str = "raise"):
        """Estimate of the interpolation error at ``self.nu``, speed(s) ``v``:
        ``4 t (1 - t)`` times the larger leave-one-out error of the two grid laws around ``nu``
        (of the one, next to an end law), ``t`` the position of ``nu`` between them (module
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
        loo = self.leave_one_out(v, outside=outside)
        x = self.grid
        i = int(np.clip(np.searchsorted(x, self.nu) - 1, 0, len(x) - 2))
        t = (self.nu - x[i]) / (x[i + 1] - x[i])
        around = [k for k in (i, i + 1) if 0 < k < len(x) - 1]  # the end laws have none
        out = np.max(loo[around], axis=0) * 4.0 * t * (1.0 - t)
        return float(out[0]) if np.ndim(v) == 0 else out

    def epsilon(self, v, *, outside: str = "raise"):
        """Interpolated ``epsilon`` at speed(s) ``v`` towards the wall (units of ``c``)."""
        arr = np.atleast_1d(np.asarray(v, dtype=float))
        eps, _ = self._node_values(arr, outside)
        out = _pchip(self.grid, eps, self.nu)
        return float(out[0]) if np.ndim(v) == 0 else out

    def epsilon_err(self, v, *, outside: str = "raise"):
        """Error of :meth:`epsilon`: interpolated point error (+) leave-one-out error."""
        arr = np.atleast_1d(np.asarray(v, dtype=float))
        _, err = self._node_values(arr, outside)
        point = np.abs(_pchip(self.grid, err, self.nu))
        out = np.hypot(point, self.interpolation_err(arr, outside=outside))
        return float(out[0]) if np.ndim(v) == 0 else out

    __call__ = epsilon

    # -- the points behind the law, as EpsilonLaw has them --------------------------------

    @property
    def v(self) -> np.ndarray:
        """Speeds computed for any grid law inside the range they all cover, increasing: each
        law's own points where epsilon(v) turns (:mod:`restitution.laws.making.refine`) are kept, so
        that what is tabulated from these points follows :meth:`epsilon` between them."""
        lo, hi = self.valid_range
        every = set()
        for n in self.nodes:
            every |= set(np.round(n.v, 12))
        return np.array(sorted(x for x in every if lo <= x <= hi))

    @property
    def epsilon_points(self) -> np.ndarray:
        return np.atleast_1d(self.epsilon(self.v))

    @property
    def epsilon_err_points(self) -> np.ndarray:
        return np.atleast_1d(self.epsilon_err(self.v))

    @property
    def asymptotic_ok(self) -> np.ndarray:
        """A point is asymptotic when every grid law's points around it passed their checks
        (:meth:`EpsilonLaw.checked`: the point itself where a law computed it)."""
        ok = np.ones(self.v.size, bool)
        for n in self.nodes:
            ok &= np.atleast_1d(n.checked(self.v))
        return ok

    @property
    def quasistatic(self) -> np.ndarray:
        """A point is from the low-speed theory when, in any grid law, it is such a point or
        lies between two of them."""
        out = np.zeros(self.v.size, bool)
        for n in self.nodes:
            q = np.asarray(n.quasistatic)
            hi = np.clip(np.searchsorted(n.v, self.v, side="left"), 0, n.v.size - 1)
            lo = np.clip(np.searchsorted(n.v, self.v, side="right") - 1, 0, n.v.size - 1)
            out |= q[lo] & q[hi]
        return out

    @property
    def source(self) -> str:
        return (
            f"PCHIP in nu between the laws for nu = {', '.join(f'{x:g}' for x in self.grid)} "
            "(error includes the interpolation error estimated from leave-one-out errors)"
        )


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
