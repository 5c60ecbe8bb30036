"""One point of the SI law and what its status means: :class:`SIPoint`, the statuses' words,
the notes of the low-speed routes and stored finite-element points, and the loss's split
between the bodies (or the ball and an elastic wall) at a speed.

Units: SI at the edge (``speed_m_s`` in m/s); inside, the law's reduced speeds (``v`` in ``c``).

:class:`~restitution.laws.si_law.SILaw` evaluates a law; this module says, for each speed it
evaluates, where the number comes from (:func:`point_status`, :data:`STATUSES`) and what the
answer's worst point means (:func:`overall_status`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.kinds import body_kind
from restitution.estimate import Estimate
from restitution.laws.calibration import sd_words
from restitution.laws.law import EpsilonLaw
from restitution.laws.partners.base import partner_of
from restitution.status import Status

__all__ = [
    "BELOW_BUDGET_S",
    "DIRECT_WALL_SHARES",
    "SAME_SPEED",
    "SI_UNITS",
    "STATUSES",
    "SIPoint",
    "cut_at_one",
    "loss_shares_at",
    "low_speed_at",
    "not_informative",
    "overall_status",
    "point_status",
    "point_statuses",
    "quasistatic_note",
    "shares_at_all",
    "values_checked",
    "route_reach_of",
]

STATUSES: dict[Status, str] = {
    Status.COMPUTED: "at a computed speed; its extrapolation passed the asymptotic checks",
    Status.COMPUTED_NOT_ASYMPTOTIC: (
        "at a computed speed; its extrapolation did not pass every asymptotic check (the error "
        "bar is the fit's, read it as indicative)"
    ),
    Status.INTERPOLATED: "between two computed speeds whose extrapolations passed their checks",
    Status.INTERPOLATED_NOT_ASYMPTOTIC: (
        "between two computed speeds, at least one of which did not pass every asymptotic check"
    ),
    Status.QUASISTATIC: (
        "from the low-speed theory, not from collisions: Rayleigh's estimate of the energy left "
        "in the modes by Hertz's force pulse, with an error band for the uncertain contact time "
        "(the sphere below the modal laws' slowest speed; docs/spheres.md)"
    ),
    Status.OUTSIDE: "outside the computed range of the law; no value (the law never extrapolates)",
}
"""Status of a point -> what it means, in the words of the JSON output."""

DISK_QUASISTATIC_NOTE = (
    "from the slow-impact model, not from collisions: the modes below a cut frequency in "
    "motion, the others static, the contact closed by the 2D Hertz law; error: its convergence "
    "in the cut plus 1.2 % of the loss (disks below the modal laws' slowest speed; "
    "docs/quasistatic.md, section 7)"
)
"""What ``quasistatic`` means for a disk's law (:data:`STATUSES` says it for the sphere's)."""

SPHERE_PAIR_QUASISTATIC_NOTE = (
    "from the low-speed theory, not from collisions: Rayleigh's estimate of the energy left in "
    "both spheres' modes by the pair's Hertz force pulse, each sphere driven at its own pole, "
    "with an error band for the uncertain contact time (two spheres up to the route's reach; "
    "docs/spheres.md, section 'Two spheres')"
)
"""What ``quasistatic`` means for a law of two spheres."""

_ROUTE_NOTES: dict[str, str] = {"slow-modal": DISK_QUASISTATIC_NOTE}
"""What ``quasistatic`` means for the points of a low-speed route, by the route's name (a
kind's :attr:`~restitution.bodies.kinds.BodyKind.low_speed_route`, the routes of
:mod:`restitution.laws.making.production`): the disk's slow-impact model; for any other route (the
sphere's Rayleigh estimate) :data:`STATUSES` says it."""

SI_UNITS: dict[str, str] = {
    "system": "SI at the edge: the material's 3D constants and the speeds; reduced speeds v/c",
    "speed": "m/s (speed_m_s: the impact speed w against the partner)",
    "v_over_c": "c = the law's speed unit (c_m_s, m/s; c_formula says which)",
    "E": "Pa",
    "rho": "kg/m^3",
    "epsilon": "dimensionless: rebound speed / impact speed (relative speeds for two grains)",
    "temperature": "m^2/s^2 (granular temperature <v_x^2>)",
}
"""The units of ``restitution law``'s numbers (its JSON's ``units``)."""

_WORST_FIRST = (
    Status.OUTSIDE,
    Status.QUASISTATIC,
    Status.INTERPOLATED_NOT_ASYMPTOTIC,
    Status.COMPUTED_NOT_ASYMPTOTIC,
)

SAME_SPEED = 1e-9  # relative tolerance for "at a computed speed"


@dataclass(frozen=True)
class SIPoint:
    """epsilon at one SI speed.

    Attributes
    ----------
    speed_m_s : float
        Impact speed ``w``, m/s (towards the wall, or relative normal speed of two grains).
    v_over_c : float
        Reduced speed ``v`` towards the wall, units of ``c``.
    epsilon, epsilon_err : float or None
        Coefficient of restitution and its error; ``None`` when ``status == "outside"``.
    status : str
        One of :data:`STATUSES`.
    note : str
        Why, when the status is not ``"computed"``.
    loss_shares : tuple of float or None
        For two grains whose law holds the split (two spheres' low-speed route): the fractions
        of the lost energy left in the first and in the second grain (they add up to 1; of the
        central value, without an error of their own; between computed speeds linear in
        ``ln v``). ``None`` elsewhere.
    parts : tuple of (str, value)
        What the mechanism that answered adds (:mod:`restitution.laws.mechanisms`): the
        elastic law's epsilon beside the answer (``epsilon_elastic``), each loss (``loss_plastic``,
        ``loss_viscous``, ...), flags (``yielded``, ``stuck``, ``informative``); each reads as an
        attribute and is a key of :meth:`to_dict`. One point type for every answer: the elastic
        law's has none.
    epsilon_sd : float or None
        One standard deviation of epsilon (:mod:`restitution.laws.calibration`); ``None``: the
        route that answered states none, and :meth:`to_dict` gives the bound ``epsilon_err``.
    sd_calibrated : bool
        Whether ``epsilon_sd`` is calibrated on independent points (``False``: it is the bound).
    """

    speed_m_s: float
    v_over_c: float
    epsilon: float | None
    epsilon_err: float | None
    status: str
    note: str = ""
    loss_shares: tuple[float, float] | None = None
    parts: tuple[tuple[str, object], ...] = ()
    epsilon_sd: float | None = None
    sd_calibrated: bool = False

    def __getattr__(self, name: str):
        # A mechanism's part (``epsilon_elastic``, ``loss_plastic``, ...) reads as an attribute.
        if name != "parts":
            for key, value in self.parts:
                if key == name:
                    return value
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    @property
    def epsilon_range(self) -> tuple[float, float] | None:
        """``(epsilon - err, epsilon + err)`` cut to ``[0, 1]``: an elastic grain at rest before
        the impact only loses energy, so epsilon <= 1 whatever the error; ``None`` outside."""
        if self.epsilon is None or self.epsilon_err is None:
            return None
        return (
            max(0.0, self.epsilon - self.epsilon_err),
            min(1.0, self.epsilon + self.epsilon_err),
        )

    def to_dict(self) -> dict:
        rng = self.epsilon_range
        return {
            "speed_m_s": self.speed_m_s,
            "v_over_c": self.v_over_c,
            "epsilon": self.epsilon,
            "epsilon_err": self.epsilon_err,
            "epsilon_sd": self.sd,
            "epsilon_sd_kind": None if self.sd is None else sd_words(self.sd_calibrated),
            "epsilon_min": None if rng is None else rng[0],
            "epsilon_max": None if rng is None else rng[1],
            "status": self.status,
            "note": self.note,
            "loss_shares": None if self.loss_shares is None else list(self.loss_shares),
            **dict(self.parts),
        }

    @property
    def sd(self) -> float | None:
        """One standard deviation: :attr:`epsilon_sd`, or the bound ``epsilon_err`` where the
        answering route states none (then :attr:`sd_calibrated` is false)."""
        return self.epsilon_err if self.epsilon_sd is None else self.epsilon_sd

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return Estimate(self.epsilon, self.epsilon_err, self.status, self.note)


_CUT_AT_ONE = (
    "epsilon + error exceeds 1: an elastic grain at rest before the impact only loses energy, "
    "so epsilon <= 1 and epsilon_max is cut there"
)


BELOW_BUDGET_S = 300.0
"""Longest estimated time for the speeds below a law computed on demand by its low-speed
route; beyond it they stay ``outside`` (ask for fewer speeds)."""


@functools.lru_cache(maxsize=4096)
def low_speed_at(geometry: str, nu: float, partner, v: float):
    """epsilon, its error and the two bodies' shares of the loss (``None`` where the route does
    not split it) at ``v`` (``c``) by the low-speed route of ``geometry`` (with ``partner``),
    one speed alone (so without an interpolation term); remembered."""
    from restitution.laws.low_speed import low_speed_points

    (record,), _ = low_speed_points(nu, [v], geometry=geometry, partner=partner)
    first = _first_share(record)
    shares = None if first is None else (first, 1.0 - first)
    return float(record["epsilon"]), float(record["epsilon_err"]), shares


def cut_at_one(note: str, eps: float, err: float) -> str:
    """``note``, saying so when ``epsilon + err`` exceeds 1."""
    return note if eps + err <= 1.0 else (note + "; " if note else "") + _CUT_AT_ONE


def quasistatic_note(law) -> str:
    """What a low-speed point of ``law`` is, by the route of its body's kind (on the wall, or of
    its pair): the disk's slow-impact model or the sphere's Rayleigh estimate."""
    kind = body_kind(law.geometry)
    route = kind.low_speed_route if law.partner is None else kind.pair_low_speed_route
    note = partner_of(law).quasistatic_note  # an elastic wall's or a plate's
    if note is not None:
        return note
    if law.partner is not None and route == "rayleigh":
        return SPHERE_PAIR_QUASISTATIC_NOTE
    return _ROUTE_NOTES.get(route, STATUSES[Status.QUASISTATIC])


def _stored_note(record: dict) -> str:
    """What a stored finite-element point of an elastic wall is."""
    why = record.get("model_refused")
    return (
        "from the finite elements, not from a route: the wall's judge stored at this speed "
        f"(v = {float(record['v_stored']):.6g} c; ball and wall meshed, both limits; the "
        "ball's vibrations and the wall's waves together, not split; docs/walls.md)"
        + (f"; the wall's route does not hold here: {why}" if why else "")
    )


def _first_share(record: dict) -> float | None:
    """The first grain's fraction of the loss in a law point's record, if it holds the split."""
    shares = record.get("shares")
    if not shares or len(shares) != 2 or not sum(shares) > 0:
        return None
    return float(shares[0]) / float(sum(shares))


DIRECT_WALL_SHARES = 20
"""Most speeds of one answer whose ball/wall split is computed by the wall's route at the speed
itself when it is not a computed point of the law (:func:`loss_shares_at`; about half a second
each)."""


@functools.lru_cache(maxsize=1024)
def _wall_shares_at(nu: float, wall_items: tuple, v: float) -> tuple[float, float] | None:
    """The ball's and the wall's fractions of the loss at ``v`` (``c``) by the wall's route at
    that speed (:func:`restitution.laws.wall_route.route_at`); remembered."""
    from restitution.bodies.wall import wall_from_dict
    from restitution.laws.wall_route import route_at

    *_, details = route_at(nu, wall_from_dict(dict(wall_items)))(v)
    first = _first_share(details)
    return None if first is None else (first, 1.0 - first)


def loss_shares_at(law, v: float, direct: bool = True) -> tuple[float, float] | None:
    """Each grain's (or the ball's and the elastic wall's) fraction of the loss at ``v``: at a
    computed speed of ``law`` whose record holds the split (``shares``) that split; between two
    such speeds of an elastic wall's law the route's own split at ``v`` (``direct``; else
    ``None``): the ball's part oscillates with the speed (Rayleigh's phases) faster than a grid
    resolves, and an interpolated split differed from the route's at the same speed by a factor
    2 (issue 64: 0.0135 % without ``--export``, 0.0283 % with it, at 1 m/s on a glass block);
    between two speeds of a pair's law the fraction linear in ``ln v`` between theirs; ``None``
    elsewhere."""
    wall = partner_of(law).read(law)  # an elastic wall's record, else None
    if not isinstance(law, EpsilonLaw) or (law.partner is None and wall is None):
        return None
    pts = np.asarray(law.v, dtype=float)
    j = int(np.searchsorted(pts, v))
    records = law._records()
    if j < pts.size and abs(pts[j] - v) <= SAME_SPEED * pts[j]:
        first = _first_share(records[j])
    elif wall is not None:
        if not (direct and 0 < j < pts.size and not law.at_points_only):
            return None
        return _wall_shares_at(float(law.nu), tuple(sorted(wall.items())), float(v))
    elif 0 < j < pts.size and not law.at_points_only:
        a, b = _first_share(records[j - 1]), _first_share(records[j])
        if a is None or b is None:
            return None
        t = math.log(v / pts[j - 1]) / math.log(pts[j] / pts[j - 1])
        first = a + t * (b - a)
    else:
        first = None
    return None if first is None else (first, 1.0 - first)


def _is_stored(record: dict) -> bool:
    """Whether a law point is a stored finite-element point (not the route's)."""
    return str(record.get("route", "")).startswith("finite elements")


def _compute(law, v: float) -> str:
    """How to compute the missing finite-element point of an elastic wall's law at ``v``."""
    wall = partner_of(law).read(law) if isinstance(law, EpsilonLaw) else None
    if wall is None:
        return ""
    from restitution.laws.wall_points import compute_command

    return (
        f" (docs/walls.md; 10-45 minutes of one core: {compute_command(law.nu, wall, v)}; the "
        "next call serves it)"
    )


def route_reach_of(law) -> float:
    """The fastest speed (``c``) of a law served at its points only: its route's reach where
    the law states one, else its fastest point of the route (points of the finite elements
    stored beyond the route are not its reach)."""
    if not isinstance(law, EpsilonLaw):
        return float(law.v[-1])
    reach = law.metadata.get("low_speed", {}).get("reach")
    if reach is not None:
        return float(reach)
    routed = [float(r["v"]) for r in law._records() if not _is_stored(r)]
    return max(routed) if routed else float(law.v[-1])


def point_status(law, v: float) -> tuple[str, str]:
    pts = np.asarray(law.v, dtype=float)
    ok = np.asarray(law.asymptotic_ok, dtype=bool)
    quasi = np.asarray(law.quasistatic, dtype=bool)
    at = np.flatnonzero(np.abs(pts - v) <= SAME_SPEED * pts)
    if at.size:
        if quasi[at[0]]:
            return Status.QUASISTATIC, quasistatic_note(law)
        record = law._records()[at[0]] if isinstance(law, EpsilonLaw) else {}
        if _is_stored(record):
            status = Status.COMPUTED if ok[at[0]] else Status.COMPUTED_NOT_ASYMPTOTIC
            return status, _stored_note(record)
        if ok[at[0]]:
            return Status.COMPUTED, ""
        return Status.COMPUTED_NOT_ASYMPTOTIC, STATUSES[Status.COMPUTED_NOT_ASYMPTOTIC]
    if getattr(law, "at_points_only", False):
        kind = partner_of(law)
        what = kind.route_words  # "elastic wall", "pair"
        refused = next((why for at, why in law.metadata.get("refused", {}).items()
                        if abs(float(at) - v) <= SAME_SPEED * v), None)  # fmt: skip
        if refused:
            wall = kind.model_words  # plate, half-space
            if any(abs(float(at) - v) <= SAME_SPEED * v for at in law.metadata.get("no_judge", ())):
                # Beyond Hertz's contact: the finite elements are not offered either.
                return Status.OUTSIDE, f"v = {v:.3g} c: no value: {refused}"
            return Status.OUTSIDE, (
                f"v = {v:.3g} c: no value from the {wall}'s model: {refused}; no "
                f"finite-element point of this {wall} is stored at this speed{_compute(law, v)}"
                + (kind.served_further if "not informative" in refused else "")
            )
        if v > route_reach_of(law):
            return Status.OUTSIDE, (
                f"v = {v:.3g} c is above the reach {route_reach_of(law):.4g} c of the {what}'s "
                f"low-speed route, and no finite-element point of this {what} is stored at "
                f"this speed{_compute(law, v)}"
            )
        return Status.OUTSIDE, (
            f"v = {v:.3g} c: this law was computed at the asked speeds only (by the {what}'s "
            "low-speed route); ask for this speed"
        )
    if v < pts[0]:
        return Status.OUTSIDE, f"v = {v:.3g} c is below the lowest computed speed {pts[0]:g} c"
    j = int(np.searchsorted(pts, v))
    if j >= pts.size:
        return Status.OUTSIDE, f"v = {v:.3g} c is above the largest computed speed {pts[-1]:g} c"
    if quasi[j - 1] or quasi[j]:
        return Status.QUASISTATIC, quasistatic_note(law)
    good = bool(ok[j - 1] and ok[j])
    if good:
        return Status.INTERPOLATED, ""
    return Status.INTERPOLATED_NOT_ASYMPTOTIC, STATUSES[Status.INTERPOLATED_NOT_ASYMPTOTIC]


def point_statuses(law, vs) -> list[tuple[str, str]]:
    """:func:`point_status` at every speed of ``vs`` (``c``) in one pass: the speeds between
    two computed points of a law served between them classified as arrays (issue 62: 1e5
    speeds took 11 s one by one), those at a computed point given that point's status, the
    rest (outside, a law served at its points only) speed by speed."""
    arr = np.asarray(vs, dtype=float).ravel()
    out: list = [None] * arr.size
    pts = np.asarray(law.v, dtype=float)
    if arr.size == 0:
        return out
    j = np.clip(np.searchsorted(pts, arr), 0, pts.size - 1)
    k = np.clip(j - 1, 0, pts.size - 1)
    near = np.where(np.abs(pts[j] - arr) <= np.abs(pts[k] - arr), j, k)
    at = np.abs(pts[near] - arr) <= SAME_SPEED * pts[near]
    inside = (arr > pts[0]) & (arr < pts[-1]) & ~at
    if getattr(law, "at_points_only", False):
        inside[:] = False
    # At a computed point: that point's status (one evaluation a point, not a speed).
    memo: dict[int, tuple[str, str]] = {}
    for i in np.flatnonzero(at):
        n = int(near[i])
        if n not in memo:
            memo[n] = point_status(law, float(pts[n]))
        out[i] = memo[n]
    if inside.any():
        ok = np.asarray(law.asymptotic_ok, dtype=bool)
        quasi = np.asarray(law.quasistatic, dtype=bool)
        hi = np.searchsorted(pts, arr[inside])
        lo = hi - 1
        q = quasi[lo] | quasi[hi]
        good = ok[lo] & ok[hi]
        note = quasistatic_note(law) if q.any() else ""
        words = {
            Status.QUASISTATIC: note,
            Status.INTERPOLATED: "",
            Status.INTERPOLATED_NOT_ASYMPTOTIC: STATUSES[Status.INTERPOLATED_NOT_ASYMPTOTIC],
        }
        for i, qi, gi in zip(np.flatnonzero(inside), q, good, strict=True):
            st = (Status.QUASISTATIC if qi else Status.INTERPOLATED if gi
                  else Status.INTERPOLATED_NOT_ASYMPTOTIC)  # fmt: skip
            out[i] = (st, words[st])
    for i in range(arr.size):
        if out[i] is None:
            out[i] = point_status(law, float(arr[i]))
    return out


def shares_at_all(law, vs, direct: bool) -> list:
    """:func:`loss_shares_at` at every speed of ``vs`` (``c``); ``None`` for all at once for a
    law that holds no split (not a pair's, not an elastic wall's)."""
    if not isinstance(law, EpsilonLaw):
        return [None] * len(vs)
    if law.partner is None and partner_of(law).read(law) is None:
        return [None] * len(vs)
    return [loss_shares_at(law, float(v), direct) for v in vs]


def values_checked(law) -> bool:
    """Whether :func:`not_informative` can refuse a value of ``law`` (an elastic wall's law);
    for every other law it is ``None`` at every speed and need not be asked."""
    return isinstance(law, EpsilonLaw) and partner_of(law).read(law) is not None


def not_informative(law, v: float, eps: float, err: float) -> str | None:
    """For an elastic wall's law, why its value at ``v`` (``c``) is not served
    (:func:`restitution.laws.wall_route.uninformative`: the error exceeds the value, as
    between a grid law's points near its top), with what answers instead; ``None`` when it is
    served, and for every other law."""
    kind = partner_of(law)
    if not (isinstance(law, EpsilonLaw) and kind.read(law) is not None):
        return None
    from restitution.laws.wall_route import uninformative

    why = uninformative(eps, err)
    if why is None:
        return None
    return (
        f"v = {v:.3g} c: no value from the {kind.model_words}'s route: {why}{_compute(law, v)}"
        f"{kind.served_further}"
    )


def overall_status(points) -> tuple[str, str | None]:
    """``("ok", None)`` when every point is computed or interpolated between asymptotic points;
    otherwise the least trustworthy status among ``points`` (outside, quasistatic, not
    asymptotic) and what it means."""
    present = {p.status for p in points}
    for status in _WORST_FIRST:
        if status in present:
            these = [p for p in points if p.status == status]
            meaning = STATUSES[status] if status != Status.QUASISTATIC else these[0].note
            return status, f"{len(these)} of {len(points)} speeds: {meaning}"
    return Status.OK, None
