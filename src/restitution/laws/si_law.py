"""The coefficient of restitution at impact speeds in m/s, for a named material and partner.

:func:`si_law` joins a :class:`~restitution.laws.units.Grain` (3D constants in SI units and a
geometry), a collision partner (``"wall"`` or ``"grain"``) and the reduced-unit law of the
grain's body for its law Poisson number (:attr:`~restitution.laws.units.Grain.law_nu`: the 2D
``nu_2d`` of a cylinder or thin disk, the 3D ``nu`` of a sphere;
:func:`restitution.laws.law_nu.law_for`). :meth:`SILaw.points` evaluates it at SI speeds and
says, for every point, where its number comes from (:data:`STATUSES`).

Example (a glass cylinder with nu = 0.2481, which maps onto the shipped law nu_2d = 0.33)::

    >>> from restitution.laws.si_law import si_law
    >>> s = si_law(E=63e9, nu=0.2481, rho=2500, shape="cylinder", against="wall")
    >>> round(s.grain.c_m_s)
    5182
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.errors import InputError, describe, is_real, real_array
from restitution.laws.calibration import SD_MEANING
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_nu import NU_MATCH, NuInterpolatedLaw, law_for, shipped_match
from restitution.laws.mechanisms.base import mechanism_fields
from restitution.laws.mechanisms.bounds import elastic_bound, flag_points, law_mechanisms
from restitution.laws.partners.base import partner_of
from restitution.laws.partners.grain import KIND as GRAIN
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.laws.si_point import (
    BELOW_BUDGET_S,
    DIRECT_WALL_SHARES,
    SAME_SPEED,
    STATUSES,
    SIPoint,
    cut_at_one,
    not_informative,
    point_statuses,
    quasistatic_note,
    route_reach_of,
    shares_at_all,
    values_checked,
)
from restitution.laws.units import Grain, partner_factor
from restitution.status import Status

__all__ = ["SILaw", "law_target", "pair_partner", "si_law"]


@dataclass(frozen=True, eq=False)
class SILaw:
    """epsilon(w) for a grain in SI units against a named partner.

    Attributes
    ----------
    grain : Grain
        Material (3D constants, SI) and geometry.
    against : {"wall", "grain"}
        Collision partner: ``w`` is the speed towards a rigid wall, or the relative normal speed
        of two grains: identical ones, or, when the law is a pair's (``law.partner``), a grain
        of the same material with the radius ratio ``law.partner.radius_ratio``.
    law : EpsilonLaw or NuInterpolatedLaw
        The reduced-unit law of ``grain.body`` for ``grain.law_nu`` (of the body on the wall, or
        of the pair).
    below : Below, optional
        Who answers below the law's slowest point instead of its low-speed route: the
        mechanism of a table (:class:`restitution.laws.below_route.Below`, its points at asked
        speeds), as the command line answers there.
    """

    grain: Grain
    against: str
    law: EpsilonLaw | NuInterpolatedLaw
    partner_grain: Grain | None = None
    below: object = field(default=None, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.grain, Grain):
            raise InputError(
                f"grain must be a Grain, got {describe(self.grain)}; pass e.g. Grain(E=63e9, "
                "nu=0.25, rho=2500, shape='cylinder'), or call si_law(...)"
            )
        if not isinstance(self.law, EpsilonLaw | NuInterpolatedLaw):
            raise InputError(
                f"law must be an EpsilonLaw (restitution.law) or a law interpolated in nu, got "
                f"{describe(self.law)}; pass restitution.law(...), or call si_law(...)"
            )
        partner_factor(self.against)  # validates
        pair = self.law.partner
        if pair is not None:
            if self.against != GRAIN.against:
                raise InputError(
                    "a law of two grains serves collisions of two grains (against='grain'), "
                    f"not against a {self.against}"
                )
            if not pair.same_material:
                _check_partner_grain(self.grain, self.partner_grain, pair)
        if self.partner_grain is not None and (pair is None or pair.same_material):
            raise InputError(
                "partner_grain names the second grain's material, and the law is of one "
                "material; pass the law of the two materials (si_law(..., partner_grain=...)) or "
                "leave partner_grain out"
            )
        body = getattr(self.law, "geometry", DEFAULT_GEOMETRY)
        if body != self.grain.body:
            raise InputError(
                f"the law is a law of the {body}, the grain ({self.grain.geometry}) needs a law "
                f"of the {self.grain.body}"
            )
        name = self.grain.law_nu_name
        if abs(float(self.law.nu) - self.grain.law_nu) > NU_MATCH:
            raise InputError(
                f"the law is for {name} = {float(self.law.nu):g}, the grain has {name} = "
                f"{self.grain.law_nu:.6g}"
            )

    @property
    def against_meaning(self) -> str:
        """What the SI speed ``w`` is: towards the wall, or the relative speed of two grains
        (identical ones, or of the same material and the law's radius ratio)."""
        return partner_of(self).meaning(self)

    @property
    def k(self) -> float:
        """``k`` in ``v = w / (k c)``: 1 against a wall and for a pair's law (whose ``v`` is the
        relative speed), 2 for two identical grains (served by the law on the wall)."""
        return 1.0 if self.law.partner is not None else partner_factor(self.against)

    @property
    def speed_scale_m_s(self) -> float:
        """``k c``: ``w = k c v`` (:attr:`k`), m/s."""
        return self.k * self.grain.c_m_s

    def _reduced(self, speed_m_s):
        """``v = w / (k c)`` of SI speed(s) ``w``, checked by :meth:`Grain.v_over_c`."""
        return self.grain.v_over_c(speed_m_s, WALL.against) / self.k

    @property
    def speed_range_m_s(self) -> tuple[float, float]:
        """Speeds in m/s the law covers: its computed range times ``k c``."""
        lo, hi = self.law.valid_range
        return lo * self.speed_scale_m_s, hi * self.speed_scale_m_s

    @property
    def computed_range_m_s(self) -> tuple[float, float]:
        """Lowest and highest computed speeds in m/s (the law serves nothing outside)."""
        return (
            float(self.law.v[0]) * self.speed_scale_m_s,
            float(self.law.v[-1]) * self.speed_scale_m_s,
        )

    @property
    def law_source(self) -> str:
        if isinstance(self.law, NuInterpolatedLaw):
            return self.law.source
        return str(self.law.metadata.get("source", "law"))

    def _served_v(self, v):
        """``v`` with the ends of the law's range snapped to them within :data:`SAME_SPEED`: the
        conversion ``w / (k c)`` of a speed at the lowest or highest computed speed may land a
        rounding error outside, where the law serves nothing."""
        lo, hi = self.law.valid_range
        arr = np.asarray(v, dtype=float)
        arr = np.where(np.abs(arr - lo) <= SAME_SPEED * lo, lo, arr)
        arr = np.where(np.abs(arr - hi) <= SAME_SPEED * hi, hi, arr)
        return float(arr) if np.ndim(v) == 0 else arr

    def epsilon(self, speed_m_s, *, outside: str = "raise"):
        """epsilon at SI speed(s) ``w`` (m/s), one array in one pass.

        Below the law's slowest point, when that point is its low-speed route's, the route
        answers, as :meth:`points` and the command line do (seconds:
        :func:`restitution.laws.below_route.below_values`). Elsewhere outside the law's range
        ``outside`` is the law's (:meth:`EpsilonLaw.epsilon`): raise ``InputError``
        (``"raise"``), or return ``nan`` (``"nan"``; ``"warn"`` warns too).
        """
        return self._evaluate(speed_m_s, outside, 0)

    def epsilon_err(self, speed_m_s, *, outside: str = "raise"):
        """Error of :meth:`epsilon` at ``w`` (m/s); ``outside`` as there."""
        return self._evaluate(speed_m_s, outside, 1)

    def epsilon_sd(self, speed_m_s, *, outside: str = "raise"):
        """One standard deviation of :meth:`epsilon` at ``w`` (m/s; :meth:`EpsilonLaw.
        epsilon_sd`, docs/errors.md); below the law, where its low-speed route answers, the
        route's bound. ``outside`` as :meth:`epsilon`'s."""
        return self._evaluate(speed_m_s, outside, 2)

    def _evaluate(self, speed_m_s, outside: str, which: int):
        """:meth:`epsilon` (``which`` 0), its error (1) or its standard deviation (2; below the
        law the route's error, the bound)."""
        v = self._served_v(self._reduced(speed_m_s))
        flat = np.atleast_1d(np.asarray(v, dtype=float)).ravel()
        below = self._route_answers(flat)
        f = (self.law.epsilon, self.law.epsilon_err, self.law.epsilon_sd)[which]
        which = min(which, 1)
        if not below.any():
            return f(self._inside(speed_m_s, outside), outside=outside)
        try:
            values = self._below_answers(flat[below])[which]
        except InputError:
            if outside == "raise":
                raise
            values = np.full(int(below.sum()), np.nan)
        rest = self._inside(speed_m_s, outside, exempt=below)
        out = np.atleast_1d(np.asarray(f(rest, outside=outside), dtype=float)).ravel().copy()
        out[below] = values
        return float(out[0]) if np.ndim(v) == 0 else out.reshape(np.shape(v))

    def statuses(self, speeds_m_s) -> np.ndarray:
        """The status of every speed (m/s) as :meth:`points` gives it, as one array of strings
        (the same rules, without the points' numbers and notes)."""
        return np.array([str(p.status) for p in self.points(speeds_m_s)], dtype=object)

    def losses(self, speeds_m_s) -> dict[str, np.ndarray]:
        """The losses at every speed (m/s) in one pass: fractions of the impact energy, one
        array a name. ``loss_total`` is ``1 - epsilon^2``; a law whose computed speeds keep
        their mechanisms' parts (a damped or plastic table: ``loss_waves``, ``loss_viscous``,
        ``loss_plastic``, ...) gives each, linear in ``ln w`` between those speeds; a law of one
        mechanism gives it under its name (``loss_waves``). ``nan`` where no value is served
        (and for the parts below a table's slowest speed, which its mechanism answers whole)."""
        w = np.atleast_1d(np.asarray(speeds_m_s, dtype=float))
        eps = np.asarray(self.epsilon(w, outside="nan"), dtype=float)
        out = {"loss_total": 1.0 - eps**2}
        records = self.law._records() if isinstance(self.law, EpsilonLaw) else []
        names = sorted(set.intersection(*(
            {k for k, x in r.items() if k.startswith("loss_") and isinstance(x, float)}
            for r in records
        ))) if records else []  # fmt: skip
        if not names:
            mechanisms = law_mechanisms(self.law)
            if len(mechanisms) == 1:
                out[f"loss_{mechanisms[0]}"] = out["loss_total"].copy()
            return out
        v = np.log(np.asarray(self.law.v, dtype=float))
        at = np.log(np.maximum(self._reduced(w), 1e-300))
        inside = (at >= v[0]) & (at <= v[-1]) & np.isfinite(eps)
        for name in names:
            part = np.interp(at, v, [r[name] for r in records])
            out[name] = np.where(inside, part, np.nan)
        return out

    def _route_answers(self, flat: np.ndarray) -> np.ndarray:
        """Which of the reduced speeds ``flat`` lie below the law's slowest point where its
        low-speed route continues it (:meth:`_route`; the slowest point is the route's own)."""
        lowest = float(self.law.v[0])
        below = (flat > 0) & (flat < lowest * (1.0 - SAME_SPEED))
        if not below.any() or self.below is not None:
            return below
        if not bool(self.law.quasistatic[0]) or self._route() is None:
            return np.zeros(flat.shape, bool)
        return below

    def _below_answers(self, v: np.ndarray):
        """``(epsilon, error, shares)`` at the reduced speeds ``v`` (below the law), by
        :func:`restitution.laws.below_route.below_values` for their unique values, the last
        few answers kept (``epsilon`` and ``epsilon_err`` of one array compute once)."""
        from restitution.laws.below_route import below_values

        key = np.unique(v)
        memo = self.__dict__.setdefault("_below_memo", {})
        k = key.tobytes()
        if k not in memo:
            if len(memo) >= 4:
                memo.pop(next(iter(memo)))
            memo[k] = (
                below_values(self.law, self._route(), key)
                if self.below is None
                else self.below.values(key, self.speed_scale_m_s, float(self.law.v[0]))
            )
        eps, err, shares = memo[k]
        pos = np.searchsorted(key, v)
        return eps[pos], err[pos], [shares[i] for i in pos]

    def _inside(self, speed_m_s, outside: str, exempt=None):
        """The reduced speeds of ``speed_m_s``; with ``outside="raise"`` a speed outside the
        law's range is refused here, in m/s (the law would say it in units of ``c``).
        ``exempt`` (a mask of the flattened speeds, answered elsewhere) are set to the law's
        slowest speed."""
        v = self._served_v(self._reduced(speed_m_s))
        lo, hi = self.law.valid_range
        if exempt is not None:
            v = np.atleast_1d(np.asarray(v, dtype=float)).ravel().copy()
            v[exempt] = lo
        if outside == "raise":
            arr = np.atleast_1d(v)
            bad = ~((arr >= lo) & (arr <= hi))
            if np.any(bad):
                w = np.atleast_1d(np.asarray(speed_m_s, dtype=float)).ravel()
                w = np.broadcast_to(w, arr.shape)[bad]
                slo, shi = self.speed_range_m_s
                raise InputError(
                    f"speed(s) {[float(f'{x:.4g}') for x in np.unique(w)[:5]]} m/s outside the "
                    f"{slo:.4g} m/s <= w <= {shi:.4g} m/s this law serves; it does not "
                    "extrapolate (pass outside='nan' for nan there, or see each speed's status "
                    "with .points(speeds))"
                )
        return v

    def _route(self):
        """``(name, nu, partner)`` of the low-speed route that continues this law below its
        slowest point (the law's own, at the grain's exact Poisson number), or ``None``."""
        from restitution.laws.low_speed import low_speed_route

        # The route is the elastic waves' alone: a law with more in its numbers (an elastic
        # wall's radiation, a damped or plastic table) is not continued by it (it gave the ball
        # on a rigid wall below an elastic wall's grid).
        if law_mechanisms(self.law) != ["waves"]:
            return None
        partner = self.law.partner
        name = low_speed_route(self.law.geometry, partner)
        if name is None:
            return None
        nu = float(self.law.nu) if partner is not None else float(self.grain.law_nu)
        return name, nu, partner

    def _below(self, speeds: list[float], note) -> dict[float, tuple]:
        """epsilon, its error and the shares at speeds (``c``) below the law's slowest point,
        by the law's low-speed route (the model the law's slowest points come from), as
        :meth:`epsilon` answers them (:func:`restitution.laws.below_route.below_values`: each
        alone while few, else from a grid spanning them). Skipped (``{}``) beyond
        :data:`BELOW_BUDGET_S`."""
        from restitution.laws.below_route import below_seconds

        if not speeds:
            return {}
        v = np.asarray(speeds, dtype=float)
        if not self._route_answers(v).all():
            return {}
        if self.below is not None:
            estimate = self.below.seconds(np.unique(v), float(self.law.v[0]), self.speed_scale_m_s)
        else:
            estimate = below_seconds(self.law, np.unique(v))
        if estimate > BELOW_BUDGET_S:
            return {}
        if estimate > 5.0 and note is not None:
            by = self.below.words if self.below is not None else self._route()[0]
            note(f"computing {len(speeds)} speed(s) below the law's slowest point by its "
                 f"low-speed route ({by}; about {estimate:.0f} s)")  # fmt: skip
        eps, err, shares = self._below_answers(v)
        return {
            float(x): (float(e), float(d), s)
            for x, e, d, s in zip(speeds, eps, err, shares, strict=True)
        }

    def points(self, speeds_m_s, *, note=None) -> tuple[SIPoint, ...]:
        """epsilon, its error and its status at every speed (m/s); never raises for range.

        Below the law's slowest point, when that point is from the law's low-speed route, a
        speed is computed now by that route (status ``quasistatic``; a few seconds a speed,
        ``note(text)`` told first when it takes longer); above the fastest point, and below a
        law of collisions alone, it is ``outside``.
        """
        ws = np.atleast_1d(real_array(speeds_m_s, "speeds_m_s", "(m/s)"))
        vs = [float(v) for v in np.atleast_1d(self._reduced(ws))]
        lowest = float(self.law.v[0])
        below = self._below(sorted({v for v in vs if v < lowest * (1.0 - SAME_SPEED)}), note)
        statuses = point_statuses(self.law, vs)
        served = self._served_all(vs, statuses, below)
        direct = len(set(vs)) <= DIRECT_WALL_SHARES  # a wall's split at the speed itself
        shares = shares_at_all(self.law, vs, direct)
        checked = values_checked(self.law)
        out = []
        for w, v, (status, text), share in zip(ws, vs, statuses, shares, strict=True):
            eps = err = sd = None
            calibrated = False
            if v in below:
                eps, err, split = below[v]
                status = Status.QUASISTATIC
                text = (
                    quasistatic_note(self.law) + "; computed at this speed by the route of "
                    "the law's slowest points (below them)"
                    if self.below is None
                    else f"computed at this speed by {self.below.words} (below its table)"
                )
                out.append(
                    SIPoint(
                        float(w),
                        v,
                        eps,
                        err,
                        status,
                        cut_at_one(text, eps, err),
                        split,
                        epsilon_sd=err,  # the route's bound: not calibrated
                    )
                )
                continue
            if status != Status.OUTSIDE:
                found = served.get(v)
                if isinstance(found, InputError):  # a nu-interpolated law's narrower range
                    status, text = Status.OUTSIDE, str(found)
                else:
                    eps, err, sd, calibrated = found
                    why = not_informative(self.law, v, eps, err) if checked else None
                    if why is not None:  # an elastic wall's value that says nothing
                        status, text, eps, err, sd = Status.OUTSIDE, why, None, None, None
            if status == Status.OUTSIDE:
                lo, hi = self.speed_range_m_s
                if getattr(self.law, "at_points_only", False):
                    top = route_reach_of(self.law) * self.speed_scale_m_s
                    text += f"; the route reaches w = {top:.4g} m/s"
                else:
                    text += f"; the law serves {lo:.4g} m/s <= w <= {hi:.4g} m/s"
            else:
                text = cut_at_one(text, eps, err)
            share = None if status == Status.OUTSIDE else share
            out.append(
                SIPoint(
                    float(w),
                    v,
                    eps,
                    err,
                    status,
                    text,
                    share,
                    epsilon_sd=sd,
                    sd_calibrated=calibrated,
                )
            )
        return tuple(out)

    def _served_all(self, vs, statuses, below) -> dict:
        """epsilon and its error at every speed of ``vs`` the law serves (not outside, not
        computed below it), evaluated as one array (issue 47: 1e5 speeds took minutes one at a
        time); where the array call is refused (a nu-interpolated law's narrower range), speed
        by speed, the refusal kept for the speeds it concerns."""
        inside = sorted({v for v, (st, _) in zip(vs, statuses, strict=True)
                         if st != Status.OUTSIDE and v not in below})  # fmt: skip
        if not inside:
            return {}
        at = self._served_v(np.array(inside))
        try:
            eps = np.atleast_1d(self.law.epsilon(at))
            err = np.atleast_1d(self.law.epsilon_err(at))
            sd, cal = self._sd(at)
            return {
                v: (float(e), float(d), float(s), bool(c))
                for v, e, d, s, c in zip(inside, eps, err, sd, cal, strict=True)
            }
        except InputError:
            out = {}
            for v in inside:
                try:
                    sv = self._served_v(v)
                    (s,), (c,) = self._sd(np.array([sv]))
                    out[v] = (
                        float(self.law.epsilon(sv)),
                        float(self.law.epsilon_err(sv)),
                        float(s),
                        bool(c),
                    )
                except InputError as exc:
                    out[v] = exc
            return out

    def _sd(self, at: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The law's standard deviation at the reduced speeds ``at`` and whether it is
        calibrated; a law without one (any object with ``epsilon_err`` only) gives its
        error, uncalibrated."""
        if not hasattr(self.law, "epsilon_sd"):
            return np.atleast_1d(self.law.epsilon_err(at)), np.zeros(np.size(at), bool)
        return (
            np.atleast_1d(self.law.epsilon_sd(at)),
            np.atleast_1d(self.law.sd_calibrated(at)),
        )

    # -- views for a notebook (restitution.laws.views) ------------------------------------

    def rows(self, speeds_m_s=None) -> list[dict]:
        """The points as one dict a speed (default: 301 speeds over the law's range)."""
        from restitution.laws import views

        return views.rows(self, speeds_m_s)

    def to_csv(self, path, speeds_m_s=None):
        """The points as a CSV file, written whole or not at all; returns its path."""
        from restitution.laws import views

        return views.to_csv(self, path, speeds_m_s)

    def to_frame(self, speeds_m_s=None):
        """The points as a pandas DataFrame (pandas is optional: only this needs it)."""
        from restitution.laws import views

        return views.to_frame(self, speeds_m_s)

    def plot(self, path=None, speeds_m_s=None, *, ax=None, marks=()):
        """epsilon(w) with its error band, the speeds computed by collisions and ``marks``
        (points to show with their error bars); saved to ``path`` when given; returns the
        Matplotlib Axes."""
        from restitution.laws import views

        return views.plot(self, path, speeds_m_s, ax=ax, marks=marks)

    def to_dict(self, speeds_m_s, points=None) -> dict:
        """The JSON of ``restitution law``: constants, partner, the mechanisms in the numbers,
        and the points (each above the speed where plastic flow is expected saying so,
        :func:`restitution.laws.mechanisms.bounds.flag_points`).

        ``body`` names the law's body and ``law_nu`` its Poisson number; a disk also reports
        ``nu_2d`` (the same number), a sphere has no two-dimensional constants. ``law`` gives
        the served law's body, ``nu`` and source.
        """
        lo, hi = self.computed_range_m_s
        g = self.grain
        if points is None:
            points, bound = flag_points(self, self.points(speeds_m_s))
        else:  # the answer's own, flagged already (not computed twice: issue 62)
            bound = elastic_bound(self)[0]
        head = {"c_m_s": g.c_m_s}
        if g.kind.planar:
            head["nu_2d"] = g.nu_2d
        law = {"geometry": self.law.geometry, "nu": float(self.law.nu)}
        if g.kind.planar:
            law["nu_2d"] = float(self.law.nu)
        pair = self.law.partner
        if pair is not None:
            law["partner"] = pair.to_dict()
        extra = {}
        if self.partner_grain is not None:
            extra["partner_material"] = self.partner_grain.to_dict()
        return {
            **head,
            "law_nu": g.law_nu,
            "shape": g.shape,
            "kind": g.body,
            "geometry": g.shape,
            "body": g.body,
            "against": self.against,
            "against_meaning": self.against_meaning,
            "material": g.to_dict(),
            **extra,
            "law": {
                **law,
                "source": self.law_source,
                "routes": list(getattr(self.law, "routes", ())),
                "computed_speeds_m_s": [lo, hi],
                "v_units": (
                    "v = w / c, the relative speed of the two grains in units of c of "
                    f"{'this grain' if self.partner_grain is not None else 'both'} (the pair's "
                    f"law); {g.c_formula}"
                    if pair is not None
                    else "v = w / (k c), speed towards the wall in units of c; k = "
                    f"{partner_factor(self.against):g} ({self.against}); {g.c_formula}"
                ),
            },
            "statuses": {**STATUSES, Status.QUASISTATIC: quasistatic_note(self.law)},
            "epsilon_sd_meaning": SD_MEANING,
            **mechanism_fields(law_mechanisms(self.law)),
            "plastic_flow_expected_from_m_s": bound,
            "points": [p.to_dict() for p in points],
        }


def si_law(
    E: float | None = None,
    nu: float | None = None,
    rho: float | None = None,
    shape: str | None = None,
    against: str | None = None,
    *,
    grain: Grain | None = None,
    path: str | os.PathLike | None = None,
    radius_ratio: float | None = None,
    partner_grain: Grain | None = None,
    geometry: str | None = None,
) -> SILaw:
    """epsilon at SI speeds for a material given by its 3D constants (or as a ``grain``).

    Both grains can be given alike: ``si_law(grain=Grain(...), against="grain",
    partner_grain=Grain(...))``, or this one by its four numbers.

    Parameters
    ----------
    E : float
        Three-dimensional Young modulus, Pa.
    nu : float
        Three-dimensional Poisson number.
    rho : float
        Density, kg/m^3.
    shape : {"cylinder", "thin-disk", "sphere"}
        Long cylinder (the disk in plane strain), thin disk (plane stress) or sphere (the law
        of the sphere for ``nu`` itself, ``c = sqrt(E / rho)``); ``geometry=`` is its
        deprecated alias.
    against : {"wall", "grain"}
        Rigid wall at speed ``w``, or two identical grains at relative normal speed ``w``.
    grain : Grain, optional
        This grain, instead of ``E``, ``nu``, ``rho`` and ``shape``.
    path : path, optional
        A law file of the grain's body for its ``law_nu`` (from ``restitution curve
        [--geometry sphere]``; for a pair ``restitution curve --radius-ratio R``, or
        :func:`restitution.laws.making.compute.computed_law`).
    radius_ratio : float, optional
        Against a grain of another size: the ratio of the two radii ``R2 / R1``, this grain's
        ``R1``. For one material either way round (``1`` is the identical grain), served by the
        laws of two disks (``law_pair_r<R>_nu<nu_2d>.json``,
        :func:`restitution.laws.law_nu.law_for` with a
        :class:`~restitution.bodies.pair.partner.Partner`); ``w`` is the relative speed.
    partner_grain : Grain, optional
        Against a grain of another material (its 3D constants, the same geometry; ``None``: this
        grain's material). One such law is shipped (steel cylinders, ``E = 210e9``, ``nu =
        0.3``, ``rho = 7850``, with glass ones 1.4 times as large, ``63e9``, ``0.2481``,
        ``2500``; :data:`restitution.laws.making.production.PAIR_TWO_MATERIALS`); for any other
        give ``path``, computed by :func:`restitution.laws.making.compute.computed_law` for the
        partner of :func:`law_target` (``restitution law ... --compute`` does both). Its
        constants enter
        the law in this grain's 2D units, rounded to six significant digits
        (:func:`pair_partner`); ``v = w / c`` with this grain's ``c``.

    Returns
    -------
    SILaw

    Raises
    ------
    InputError
        For constants out of range, or when no law serves the grain's body and ``law_nu`` (the
        message names the command that computes it).
    """
    grain = _grain_of(E, nu, rho, shape, geometry, grain)
    partner_factor(against)
    partner = _partner(radius_ratio, against, grain, partner_grain)
    other = _other_material(grain, partner_grain)
    if other is not None and path is None and not _shipped(grain, partner):
        raise InputError(
            "no law of these two materials is shipped: compute it with `restitution law ... "
            "--compute` (or restitution.laws.making.compute.computed_law), or give its law file "
            "(path)"
        )
    return SILaw(
        grain,
        against,
        law_for(grain.law_nu, geometry=grain.body, path=path, partner=partner),
        partner_grain=other,
    )


def _shipped(grain: Grain, partner) -> bool:
    """Whether a shipped law of two bodies of ``grain``'s kind (disks) serves its ``law_nu``
    with ``partner`` exactly (laws of two materials are not interpolated in ``nu``)."""
    return shipped_match(grain.law_nu, grain.body, partner) is not None


def _grain_of(E, nu, rho, shape, geometry, grain) -> Grain:
    """The grain of :func:`si_law`'s arguments: ``grain``, or its four numbers."""
    if grain is None:
        return Grain(E, nu, rho, shape, geometry=geometry)
    if not isinstance(grain, Grain):
        raise InputError(f"grain must be a Grain, got {type(grain).__name__}; see Grain(...)")
    if (E, nu, rho, shape, geometry) != (None,) * 5:
        raise InputError("give the grain as grain=Grain(...) or as E, nu, rho and shape, not both")
    return grain


def law_target(E, nu, rho, geometry: str, against: str, radius_ratio=None, partner_grain=None):
    """``(law_nu, body, partner)``: the law :func:`si_law` serves for these arguments (the
    Poisson number of the law, 2D for cylinders and thin disks; the body, ``"disk"`` or
    ``"sphere"``; the :class:`~restitution.bodies.pair.partner.Partner` or ``None``), e.g. for
    :func:`restitution.laws.making.compute.computed_law`."""
    grain = Grain(E=E, nu=nu, rho=rho, shape=geometry)
    partner_factor(against)
    return grain.law_nu, grain.body, _partner(radius_ratio, against, grain, partner_grain)


def _six(x: float) -> float:
    """``x`` rounded to six significant digits: a partner's ratios as law files name them."""
    return float(f"{x:.6g}")


def pair_partner(grain: Grain, other: Grain, radius_ratio: float = 1.0):
    """The :class:`~restitution.bodies.pair.partner.Partner` of a grain of the material
    ``other`` (same geometry), ``radius_ratio`` times as large as ``grain``, in the units of
    ``grain``'s law (2D constants for disks, 3D for spheres): ``E2 / E1``, ``rho2 / rho1`` and
    the partner's law Poisson number (``None`` when it is this grain's), each rounded to six
    significant digits, so that law files computed for the same two materials carry the same
    name and key."""
    from restitution.bodies.pair.partner import Partner

    nu2 = _six(other.law_nu)
    return Partner(
        radius_ratio=_six(radius_ratio),
        modulus_ratio=_six(other.law_E / grain.law_E),
        density_ratio=_six(other.rho / grain.rho),
        nu=None if nu2 == _six(grain.law_nu) else nu2,
    )


def _check_partner_grain(grain: Grain, other: Grain | None, pair) -> None:
    """One-line refusal unless ``other`` is the material of the pair law ``pair``."""
    if other is None:
        raise InputError(
            "the law is of grains of two materials: give the second grain's material "
            "(partner_grain=Grain(...), si_law(..., partner_grain=...))"
        )
    want = pair_partner(grain, other, pair.radius_ratio)
    if want.key() != pair.key():
        raise InputError(
            f"the law is of the pair {pair.to_dict()}, the two materials make "
            f"{want.to_dict()}; give the law of these two materials"
        )


def _other_material(grain: Grain, partner_grain) -> Grain | None:
    """The partner grain when it is of another material than ``grain``; ``None`` for none or
    the same material (checked: a Grain of the same geometry)."""
    if partner_grain is None:
        return None
    if not isinstance(partner_grain, Grain):
        raise InputError(
            f"partner_grain must be a Grain, got {describe(partner_grain)}; pass e.g. "
            "Grain(E=63e9, nu=0.25, rho=2500, shape='cylinder')"
        )
    if partner_grain.geometry != grain.geometry:
        raise InputError(
            f"the two grains must share one geometry: this is a {grain.geometry}, the partner a "
            f"{partner_grain.geometry}"
        )
    if (partner_grain.E, partner_grain.nu, partner_grain.rho) == (grain.E, grain.nu, grain.rho):
        return None
    return partner_grain


def _partner(radius_ratio, against: str, grain: Grain, partner_grain=None):
    """The :class:`Partner` of a second grain ``radius_ratio`` times as large: of the same
    material the larger of the ratio and its inverse (the pair is the same either way round,
    its speeds in ``c`` of both; ``None`` for the identical grain or no ratio), of another
    material (``partner_grain``) this grain's ``R2 / R1`` as given (:func:`pair_partner`)."""
    other = _other_material(grain, partner_grain)
    if radius_ratio is None and other is None:
        return None
    r = 1.0 if radius_ratio is None else radius_ratio
    if not is_real(r):
        raise InputError(
            f"the radius ratio must be a positive number, got {describe(radius_ratio)}; pass "
            "radius_ratio as a float > 0"
        )
    r = float(r)
    if not (np.isfinite(r) and r > 0):
        raise InputError(
            f"the radius ratio must be a positive number, got {radius_ratio!r}; pass "
            "radius_ratio as a finite float > 0"
        )
    if against != GRAIN.against:
        what = "a radius ratio" if other is None else "a partner material"
        raise InputError(
            f"{what} describes a second grain; it needs against='grain', not {against!r}"
        )
    # Pairs of different bodies are sized (and computed) for the kinds with a pair compression.
    if grain.kind.pair_compression is None and (r != 1.0 or other is not None):
        raise InputError(
            f"laws of two {grain.body}s of different sizes or materials are not computed yet; "
            "give radius_ratio=None and no partner material (identical grains)"
        )
    if other is not None:
        return pair_partner(grain, other, r)
    # Six significant digits, as law files name the ratio and as a partner's materials are
    # rounded (issue 47: 1.4000001 found the file of 1.4 and then refused it as another pair).
    r = _six(max(r, 1.0 / r))
    if r == 1.0:
        return None
    from restitution.bodies.pair.partner import Partner

    return Partner(radius_ratio=r)
