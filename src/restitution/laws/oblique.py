"""The oblique impact of a real grain on the rigid wall with Coulomb friction, in SI units.

Units: SI at this edge (m/s, rad/s, Pa, kg/m^3, m, degrees); inside, the grain's reduced units
(``E = rho = R = 1`` of its body kind's constants, speeds in ``c``, spins in ``c / R``).

``law --angle DEG --friction MU`` (:class:`~restitution.laws.request.LawRequest` with ``angle``)
is answered here: each asked speed ``w`` is the grain's normal speed towards the wall, ``v = w /
c`` (:meth:`~restitution.laws.units.Grain.v_over_c`), the tangential speed ``v tan(angle)``, no
spin before. The body kind's oblique body (:attr:`restitution.bodies.kinds.BodyKind.
oblique_body`: the disk's rim in both mode families, the sphere's cap of every azimuthal
order) hits the exponential wall of hardness ``alpha = p / delta_max(v)``, ``p`` the softest of
the kind's walls (:attr:`~restitution.bodies.kinds.BodyKind.alpha_products`, 40 for the disk, 80
for the sphere: the wall the head-on law's sweeps start from), in
:func:`restitution.dynamics.oblique.oblique_collision`, at the kind's mode count
(:func:`law_modes`: 160 for the disk, 40 for the sphere) and at half as many. The numbers are
those of the full count; the error of each is its change from half the modes: a measure of how
far one mode count is from converged, **not** an extrapolation to ``N, alpha -> infinity`` (the
head-on laws' route, which the oblique route cannot yet afford; docs/oblique.md). Hence every
point's status is at best
:attr:`~restitution.status.Status.COMPUTED_NOT_ASYMPTOTIC`. ``epsilon_normal``'s error also
holds its distance from the head-on law at the speed (:func:`_normal_error`): one mode count on
one wall is ten times further from the head-on limit than from half its modes.

Where the kind names its quasistatic oblique theory
(:attr:`~restitution.bodies.kinds.BodyKind.oblique_quasistatic`, the sphere's Hertz-Mindlin,
:data:`QUASISTATIC`), each point also carries that theory's ``beta`` at its speeds, on the
half-space: ``beta_quasistatic`` without microslip (Maw, Barber and Fawcett's law (a), the DEM
codes' Hertz-Mindlin), ``beta_microslip`` with Mindlin's microslip (law (b), what a continuum's
local friction gives) and ``beta_one_state`` with the modal one-state route's own contact (one
stick/slip state whose traction is spread like the pressure:
:mod:`restitution.quasistatic.sphere_one_state`; not law (a), whose traction is Mindlin's:
-0.488 against -0.954 at ``tan(theta)/mu = 0.3``). Beside them, the route's own friction on the
finite body's flexibility (:data:`FINITE_BODY`): ``beta_one_state_finite`` for one stick/slip
state, ``beta_microslip_finite`` for ``--friction-model microslip`` (friction at every wall node
by :func:`restitution.dynamics.oblique_microslip.microslip_collision`). Both depart from their
half-space values at order 0.7-0.9 in the contact radius ``a``: for a steel ball at 1 m/s and 30
degrees, ``mu = 0.3``, 0.343 against 0.266 (one state) and 0.388 against 0.316 (microslip). The
one-state limit on the finite sphere holds Dundurs' coupling (the in-line traction tilts the
contact, the wall holds it flat: :mod:`restitution.quasistatic.sphere_coupling`), which every
converged route has and the half-space theories leave out: 0.323 for that ball, 0.020 below the
uncoupled 0.343 (docs/oblique.md, "Dundurs' coupling"); the microslip limit is still uncoupled.
``beta``'s error then also holds, in quadrature, the distance from the route's own low-speed
limit (:meth:`_Limits.route`: the finite body's, or beyond its reach the half-space's), as
``epsilon_normal``'s holds the head-on law's: one doubling of the modes understates how far 40
modes are from that limit (docs/oblique.md, "The one-state route's own limit": at ``v = 0.005
c``, ``tan(theta)/mu = 0.3``, the wall ``alpha = 80 / delta_max`` alone keeps the continuum's
one-state ``beta`` 0.17 below the rigid wall's, and 20-80 modes keep their quasistatic twin
0.33-0.51 below the continuum's). Above the quasistatic regime the distance also holds the
impact's dynamics: an upper estimate there.

``--friction-model residual`` (the kinds whose ``oblique_residual`` is set: the sphere) runs
:func:`restitution.dynamics.oblique_residual.residual_collision` instead: the same one-state
contact with the dropped modes' static residual, normal, tangential and (since stop 87) the
tilt of Dundurs' coupling; the sphere's default (the steel ball above at 1 m/s: 0.32609 +-
0.0025 against the coupled limit 0.32366; the stick-slip route on one wall 0.17855;
docs/oblique.md, "A static residual for the one-state route", "Dundurs' coupling"); its
limit is the one-state one with the coupling.

A kind without an oblique route, or one whose kind says why ``law`` does not serve it
(:attr:`~restitution.bodies.kinds.BodyKind.oblique_law`), is refused where the request is built
(:mod:`restitution.laws.request_checks`); nothing here names a kind.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass

from restitution import budget
from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import body_kind
from restitution.dynamics.oblique_cost import check_reach, suspect_advice
from restitution.errors import InputError
from restitution.laws.units import BODIES
from restitution.quasistatic.oblique import MODELS as QUASISTATIC_MODELS
from restitution.quasistatic.oblique import oblique_impact as quasistatic_impact
from restitution.quasistatic.sphere_coupling import (
    coupled_one_state_impact,
    coupled_one_state_seconds,
)
from restitution.quasistatic.sphere_one_state import one_state_half_space
from restitution.quasistatic.sphere_partial_slip import partial_slip_impact, partial_slip_seconds
from restitution.status import Status

__all__ = [
    "LARGE_SPEED",
    "MODES",
    "QUASISTATIC",
    "ObliqueAnswer",
    "ObliquePoint",
    "law_modes",
    "oblique_answer",
    "oblique_seconds",
    "worst_status",
]

MODES = 160
"""The disk's symmetric modes of each oblique point (the rim holds about twice as many), as
``collide --angle``'s default; the error is the change from ``MODES // 2``. Another kind's count
is its :attr:`~restitution.bodies.kinds.BodyKind.oblique_law_modes` (:func:`law_modes`)."""

LARGE_SPEED = 0.3
"""Above this normal speed (``c``) linear elasticity is stretched: status ``large-deformation``
(as ``collide``)."""


@dataclass(frozen=True)
class ObliquePoint:
    """One speed of an oblique answer. Speeds m/s, spins rad/s (``spin_rad_s``; ``None``
    without a radius) and m/s (``spin_R_m_s = omega R``), energies fractions of the kinetic
    energy before; each ``*_error`` is the change from half the modes.

    Attributes
    ----------
    speed_m_s, v : float
        Normal speed towards the wall, m/s and ``c``.
    v_tangential : float
        Tangential speed before, ``c``.
    alpha, modes : float, int
        The wall (``1 / R``) and the symmetric modes.
    epsilon_normal, beta : float
        ``-v_n(after) / v_n``; ``-v_c(after) / v_c(before)`` of the contact point (``None`` at
        angle 0).
    spin_R_m_s, spin_rad_s : float
        Spin after (rolling sense) times ``R``, m/s; and in rad/s with the radius.
    friction_work, energy_balance : float
        Friction work and the integration's energy balance, fractions of ``E0``.
    phases : int
        Stick/slip phases of the contact (1 for the microslip route: every node on its own).
    epsilon_head_on_law, epsilon_head_on_law_error, head_on_law_status : float, float, str
        The head-on law of the material at this speed (``N, alpha -> infinity``, what ``law``
        without ``--angle`` answers), to read ``epsilon_normal`` against: the gap is the
        distance of one mode count on one wall from the limit (docs/oblique.md); ``None`` where
        no law serves this material.
    status, advice : Status, str
    wall_time_s : float
        Both runs, s.
    beta_quasistatic, beta_microslip : float or None
        The kind's quasistatic oblique theory at this impact on the half-space (module docs):
        without microslip (law (a), the DEM codes' Hertz-Mindlin) and with it (law (b));
        ``None`` where the kind has none, or at angle 0.
    beta_one_state : float or None
        The same with one stick/slip state whose traction is spread like the pressure, the
        modal one-state route's own contact, on the half-space
        (:func:`restitution.quasistatic.sphere_one_state.one_state_half_space`).
    beta_microslip_finite, beta_one_state_finite : float or None
        The route's friction (microslip, or one state) on the finite body's own flexibility
        (:data:`FINITE_BODY`; one state with Dundurs' coupling, microslip without): that
        route's low-speed limit, in its ``beta_error``; ``None``
        for the other route, or where the kind has none. Beyond the finite body's reach the
        error takes the half-space's (``beta_microslip``, ``beta_one_state``).
    """

    speed_m_s: float
    v: float
    v_tangential: float
    alpha: float
    modes: int
    epsilon_normal: float
    epsilon_normal_error: float
    beta: float | None
    beta_error: float | None
    spin_R_m_s: float
    spin_R_m_s_error: float
    spin_rad_s: float | None
    spin_rad_s_error: float | None
    friction_work: float
    friction_work_error: float
    energy_balance: float
    phases: int
    epsilon_head_on_law: float | None
    epsilon_head_on_law_error: float | None
    head_on_law_status: str | None
    status: Status
    advice: str
    wall_time_s: float
    beta_quasistatic: float | None = None
    beta_microslip: float | None = None
    beta_microslip_finite: float | None = None
    beta_one_state: float | None = None
    beta_one_state_finite: float | None = None

    @property
    def epsilon(self) -> float:
        """The normal coefficient (what ``law`` checks every point has)."""
        return self.epsilon_normal

    @property
    def note(self) -> str:
        """The advice (what ``law`` says of a point)."""
        return self.advice

    def to_dict(self) -> dict:
        """The point as JSON values."""
        return {k: (str(v) if isinstance(v, Status) else v) for k, v in asdict(self).items()}


def worst_status(statuses) -> Status:
    """The worst of oblique points' ``statuses`` (``suspect``, ``large-deformation``,
    ``computed-not-asymptotic``, else ``ok``); strings are read as :class:`Status`."""
    order = (Status.SUSPECT, Status.LARGE_DEFORMATION, Status.COMPUTED_NOT_ASYMPTOTIC)
    got = {Status(s) for s in statuses}
    return next((s for s in order if s in got), Status.OK)


@dataclass(frozen=True)
class ObliqueAnswer:
    """What :func:`oblique_answer` returns (the same object for a notebook and ``law``)."""

    request: object
    shape: str
    nu_body: float
    c_m_s: float
    points: tuple[ObliquePoint, ...]
    inertia_factor: float
    """``K = 1 + m R^2 / I`` of the grain's body (3 for the disk, 7/2 for the sphere): the
    lever of Coulomb's impulse ratio ``beta = -1 + K mu (1 + epsilon_normal) / tan(theta)``."""

    @property
    def status(self) -> Status:
        """The worst of the points' statuses (:func:`worst_status`)."""
        return worst_status(p.status for p in self.points)

    @property
    def advice(self) -> str | None:
        """The advice of the first point of the answer's status."""
        return next((p.advice for p in self.points if p.status == self.status), None)

    @property
    def units(self) -> dict:
        """The units of every number of :meth:`to_dict`."""
        return {
            "speed": "m/s (speed_m_s: normal speed towards the wall; v, v_tangential: units of "
            f"c = {self.c_m_s:.6g} m/s)",
            "angle": "degrees from the wall's normal",
            "spin": "spin_rad_s: rad/s (positive in the rolling sense); spin_R_m_s: spin times "
            "the radius, m/s",
            "energy": "fraction of the kinetic energy before",
            "alpha": "1/R",
            "wall_time": "s",
        }

    def to_dict(self) -> dict:
        """The command's JSON payload."""
        r = self.request
        return {
            "route": "modal oblique (restitution.dynamics.oblique), "
            f"{self.points[0].modes if self.points else MODES} modes, error from half",
            "shape": self.shape,
            "nu_body": self.nu_body,
            "c_m_s": self.c_m_s,
            "angle_deg": r.angle,
            "friction": r.friction,
            "inertia_factor": self.inertia_factor,
            "beta_meaning": "-v_c(after)/v_c(before), v_c = v_t - R omega the contact point's "
            "tangential velocity: -1 smooth, +1 reversed",
            "points": [p.to_dict() for p in self.points],
        }


def _silent(text: str) -> None:
    """The default ``note``: say nothing."""


def law_modes(kind) -> int:
    """The modes of ``law --angle``'s answer for body kind ``kind`` (the error from half as
    many): its ``oblique_law_modes``, else its ``oblique_modes`` (``collide --angle``'s)."""
    return kind.oblique_law_modes or kind.oblique_modes


@dataclass(frozen=True, eq=False)
class _Plan:
    """What :func:`oblique_answer` runs: the kind, the body's ``nu``, ``tan(angle)``, the
    modes, the speeds ``(w, v, alpha)``, the bodies of both mode counts, the friction route
    (:mod:`restitution.dynamics.friction`), and the estimated seconds (:attr:`how` they were
    estimated: the route's words)."""

    kind: object
    nu: float
    tan: float
    modes: int
    speeds: list
    bodies: dict
    route: object
    seconds: float

    @property
    def how(self) -> str:
        """How :attr:`seconds` were estimated: the route's words."""
        return self.route.law_how

    def run(self, body, v: float, alpha: float, request):
        """The route's law run of ``body`` at ``(v, alpha)`` (its walls, extrapolated where it
        has two)."""
        return self.route.law_collision(body, v, v * self.tan, request.friction, alpha,
                                        request.oblique_kappa)  # fmt: skip


def _plan(r, modes: int | None) -> _Plan:
    """The plan of ``r``'s runs (its modes computed or read from the cache, nothing run)."""
    grain = r.grain
    kind = body_kind(BODIES[r.shape])
    modes = law_modes(kind) if modes is None else modes
    nu = grain.law_nu
    tan = math.tan(math.radians(r.angle))
    plans = []
    for w in r.speeds:
        v = float(grain.v_over_c(w, r.against))
        if not v < 1.0:  # the contact's closed forms (and linear elasticity) end well before
            raise InputError(
                f"--speed {w:g} m/s is {v:.3g} c: an oblique impact needs a normal speed below "
                f"c = {grain.c_m_s:.6g} m/s (above 0.3 c its status is large-deformation); "
                "give a slower speed"
            )
        alpha = kind.alpha_products[0] / kind.max_compression(v, nu)
        check_reach(v, alpha, ("the normal speed (c)", "alpha"))
        plans.append((w, v, alpha))
    bodies = {n: kind.oblique_body(get_modes(nu, count=n, geometry=kind.geometry))
              for n in (modes // 2, modes)}  # fmt: skip
    top = bodies[modes]
    for _, _, alpha in plans:  # before the estimates below, which make the nodes
        budget.check_memory_total(
            "--modes",
            modes,
            top.wall_node_memory(alpha),
            f"the {len(top)} modes of both symmetries on the wall's "
            f"{top.wall_node_count(alpha)} nodes",
            lambda _limit: "ask for fewer modes",
        )
    route = r.oblique_route
    seconds = sum(route.law_work(b, v, v * tan, a, r.oblique_kappa).seconds
                  for b in bodies.values() for _, v, a in plans)  # fmt: skip
    if kind.oblique_quasistatic in FINITE_BODY_SECONDS and tan != 0.0 and r.friction:
        estimate = FINITE_BODY_SECONDS[kind.oblique_quasistatic]
        seconds += sum(estimate(v, nu, route.every_node) for _, v, _ in plans)
    return _Plan(kind, nu, tan, modes, plans, bodies, route, seconds)


def oblique_seconds(request, modes: int | None = None) -> tuple[float, str]:
    """The estimated seconds of :func:`oblique_answer` for ``request`` at ``modes`` (its
    modes computed or read from the cache, nothing run), and how they were estimated."""
    plan = _plan(request, modes)
    return plan.seconds, plan.how


def oblique_answer(
    request, note: Callable[[str], None] = _silent, *, modes: int | None = None, head_on=None
) -> ObliqueAnswer:
    """The oblique impact of ``request`` (a :class:`~restitution.laws.request.LawRequest` with
    ``angle`` and ``friction``) at each of its speeds (module docs).

    Parameters
    ----------
    request : LawRequest
        Checked where it was built (the kind has an oblique route, the partner is the wall).
    note : callable
        Told the estimated time before the runs.
    modes : int or None
        Symmetric (for the sphere axisymmetric) modes; the error from ``modes // 2``. ``None``:
        the kind's own count (:func:`law_modes`: 160 for the disk, 40 for the sphere).
    head_on : sequence of SIPoint or None, optional
        The head-on law's points at the request's speeds (:func:`restitution.laws.serve.serve`
        passes them), reported beside ``epsilon_normal``; ``None``: none.
    """
    r, grain = request, request.grain
    plan = _plan(r, modes)
    kind, nu, tan, bodies, modes = plan.kind, plan.nu, plan.tan, plan.bodies, plan.modes
    note(
        f"note: {len(plan.speeds)} oblique impacts at {modes} and {modes // 2} modes, "
        f"{r.oblique_friction_model} friction: about {plan.seconds:.0f} s expected ({plan.how})"
    )
    head_on = [None] * len(r.speeds) if head_on is None else list(head_on)
    points = []
    for (w, v, alpha), law_point in zip(plan.speeds, head_on, strict=True):
        start = time.perf_counter()
        # The overflowing trial steps of these hard walls are handled (and silenced) by
        # oblique_collision; the accepted run balances its energy to ~1e-11 (energy_balance).
        runs = {n: plan.run(b, v, alpha, r) for n, b in bodies.items()}
        wall = time.perf_counter() - start
        limits = _quasistatic_betas(kind, v, v * tan, r.friction, nu, plan.route.every_node)
        points.append(_point(r, grain, w, v, alpha, runs, modes, wall, law_point, limits,
                             plan.route))  # fmt: skip
    body = bodies[modes]
    return ObliqueAnswer(r, r.shape, nu, grain.c_m_s, tuple(points),
                         1.0 + body.mass / body.inertia)  # fmt: skip


def _hertz_mindlin(v: float, v_tangential: float, mu: float, nu: float):
    """``beta`` of Hertz-Mindlin's quasistatic oblique impact of the solid sphere on the rigid
    wall (:func:`restitution.quasistatic.oblique.oblique_impact`, ``K = 7/2``), without and with
    microslip (about 0.01 s and 0.13 s), and of the one-state contact spread like the pressure
    on the half-space (:func:`restitution.quasistatic.sphere_one_state.one_state_half_space`,
    about 0.01 s)."""
    laws = tuple(
        float(quasistatic_impact(v, v_tangential, mu, nu, model=model).beta)
        for model in QUASISTATIC_MODELS
    )
    one_state = -1.0 if mu == 0.0 else one_state_half_space(v, v_tangential, mu, nu)[0]
    return (*laws, one_state)


def _finite_sphere(v: float, v_tangential: float, mu: float, nu: float, microslip: bool) -> float:
    """``beta`` of the finite sphere's own quasistatic impact with the route's friction: with
    microslip (:func:`restitution.quasistatic.sphere_partial_slip.partial_slip_impact`, about
    1-5 s, without Dundurs' coupling) or with one state spread like the pressure and Dundurs'
    coupling (:func:`restitution.quasistatic.sphere_coupling.coupled_one_state_impact`, about
    1-9 s)."""
    if mu == 0.0:
        return -1.0  # no tangential force: the contact point keeps its velocity
    impact = partial_slip_impact if microslip else coupled_one_state_impact
    return float(impact(v, v_tangential, mu, nu).beta)


def _finite_sphere_seconds(v: float, nu: float, microslip: bool) -> float:
    """The estimated seconds of :func:`_finite_sphere`."""
    return partial_slip_seconds(v, nu) if microslip else coupled_one_state_seconds(v, nu)


QUASISTATIC: dict[str, Callable[[float, float, float, float], tuple[float, float, float]]] = {
    "hertz-mindlin": _hertz_mindlin,
}
"""A kind's quasistatic oblique theory by its name (:attr:`~restitution.bodies.kinds.BodyKind.
oblique_quasistatic`): ``(v, v_tangential, mu, nu) -> (beta without microslip (law (a)),
with microslip (law (b)), with one state spread like the pressure)``, all on the half-space,
speeds in the kind's ``c``."""

FINITE_BODY: dict[str, Callable[[float, float, float, float, bool], float]] = {
    "hertz-mindlin": _finite_sphere,
}
"""Beside a kind's quasistatic theory, the same impact on the finite body's own surface
flexibility instead of the half-space's, with the route's friction (``(v, v_tangential, mu, nu,
microslip) -> beta``): the route's low-speed limit, where the half-space's is only its limit as
the contact shrinks (docs/oblique.md, "The finite sphere's own partial slip", "The one-state
route's own limit")."""

FINITE_BODY_SECONDS: dict[str, Callable[[float, float, bool], float]] = {
    "hertz-mindlin": _finite_sphere_seconds,
}
"""The estimated seconds of :data:`FINITE_BODY`'s answer at ``(v, nu, microslip)``."""


@dataclass(frozen=True)
class _Limits:
    """The quasistatic ``beta`` of one impact (:func:`_quasistatic_betas`); ``None`` where
    none applies."""

    law_a: float | None = None
    law_b: float | None = None
    one_state: float | None = None
    finite: float | None = None

    def route(self, microslip: bool) -> float | None:
        """The route's own low-speed limit: its friction on the finite body or, beyond that
        body's reach, on the half-space (law (b) for microslip; the one-state contact spread
        like the pressure, not law (a), for one stick/slip state)."""
        if self.finite is not None:
            return self.finite
        return self.law_b if microslip else self.one_state


def _quasistatic_betas(kind, v: float, v_tangential: float, mu: float, nu: float,
                       microslip: bool = False) -> _Limits:  # fmt: skip
    """The kind's quasistatic ``beta`` at this impact (:class:`_Limits`): on the half-space,
    without and with microslip and with one state spread like the pressure, and on the finite
    body with the route's friction (:data:`FINITE_BODY`); ``None`` for each that does not
    apply: no theory, no tangential motion (angle 0), or a speed beyond the theory's reach
    (Hertz's ``delta << R``: the sphere's refuses ``v > 0.529 c``, far inside
    ``large-deformation``; the finite sphere's annuli refuse ``v > 0.233 c`` at ``nu =
    0.3``). ``beta``'s error is then the change from half the modes alone."""
    if kind.oblique_quasistatic is None or v_tangential == 0.0:
        return _Limits()
    try:
        law_a, law_b, one_state = QUASISTATIC[kind.oblique_quasistatic](v, v_tangential, mu, nu)
    except InputError:
        return _Limits()
    limits = _Limits(law_a, law_b, one_state)
    finite = FINITE_BODY.get(kind.oblique_quasistatic)
    try:
        return (
            limits
            if finite is None
            else _Limits(law_a, law_b, one_state, finite(v, v_tangential, mu, nu, microslip))
        )
    except InputError:
        return limits


def _beta_error(fine, coarse, quasistatic: float | None) -> float | None:
    """The change of ``beta`` from half the modes and, where the kind has a quasistatic limit,
    the distance from it, in quadrature (module docs)."""
    if math.isnan(fine.beta):
        return None
    change = abs(fine.beta - coarse.beta)
    return change if quasistatic is None else math.hypot(change, fine.beta - quasistatic)


def _normal_error(fine, coarse, law_point) -> float:
    """The error of ``epsilon_normal``: its change from half the modes and, where the head-on
    law serves the speed, its distance from that law (with the law's own error) in quadrature.

    Friction moves ``epsilon_normal`` from the head-on value of the same modes and wall by
    1.5e-4 at most in the steel table (docs/oblique.md), while one mode count on the softest
    wall stays far from the head-on limit ``N, alpha -> infinity``: 0.97842 against the law's
    0.99364 for the steel cylinder at 1 m/s, ten times the change from half the modes. The
    distance from the law counts that (and the friction's small shift with it: an upper
    estimate)."""
    change = abs(fine.epsilon_normal - coarse.epsilon_normal)
    if law_point is None or law_point.epsilon is None:
        return change
    gap = abs(fine.epsilon_normal - law_point.epsilon)
    return math.sqrt(change**2 + gap**2 + float(law_point.epsilon_err or 0.0) ** 2)


def _point(r, grain, w, v, alpha, runs, modes, wall, law_point, limits,
           route) -> ObliquePoint:  # fmt: skip
    """One speed's answer; ``beta``'s error holds the distance from the friction ``route``'s
    own quasistatic limit (:meth:`_Limits.route`)."""
    microslip = route.every_node
    fine, coarse = runs[modes], runs[modes // 2]
    c = grain.c_m_s
    spin, spin_err = fine.spin * c, abs(fine.spin - coarse.spin) * c
    rad = None if r.radius is None else 1.0 / r.radius
    beta = None if math.isnan(fine.beta) else fine.beta
    status, advice = Status.COMPUTED_NOT_ASYMPTOTIC, route.law_advice
    suspect = suspect_advice(modes, alpha, r.friction)
    if v > LARGE_SPEED:
        status, advice = Status.LARGE_DEFORMATION, Status.LARGE_DEFORMATION.advice
    if suspect is not None:
        status, advice = Status.SUSPECT, suspect
    return ObliquePoint(
        speed_m_s=float(w),
        v=v,
        v_tangential=fine.v_tangential_before,
        alpha=alpha,
        modes=modes,
        epsilon_normal=fine.epsilon_normal,
        epsilon_normal_error=_normal_error(fine, coarse, law_point),
        beta=beta,
        beta_error=_beta_error(fine, coarse, limits.route(microslip)),
        spin_R_m_s=spin,
        spin_R_m_s_error=spin_err,
        spin_rad_s=None if rad is None else spin * rad,
        spin_rad_s_error=None if rad is None else spin_err * rad,
        friction_work=fine.friction_work,
        friction_work_error=abs(fine.friction_work - coarse.friction_work),
        energy_balance=fine.energy_balance,
        phases=len(fine.phases),
        epsilon_head_on_law=None if law_point is None else law_point.epsilon,
        epsilon_head_on_law_error=None if law_point is None else law_point.epsilon_err,
        head_on_law_status=None if law_point is None else str(law_point.status),
        status=status,
        advice=advice,
        wall_time_s=wall,
        beta_quasistatic=limits.law_a,
        beta_microslip=limits.law_b,
        beta_one_state=limits.one_state,
        beta_microslip_finite=limits.finite if microslip else None,
        beta_one_state_finite=None if microslip else limits.finite,
    )
