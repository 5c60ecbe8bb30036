"""The elastic wall's routes at one speed, how fast they reach, what they cost, and when their
value is not served (issue 42; issue 64's hostile walls).

Units: the ball's reduced units (``E = rho = R = 1`` of its 3D constants); ``v`` in ``c``.

:func:`route_at` is the half-space's route (the ball's Rayleigh estimate and Lamb's radiation of
Hertz's pulse, :func:`restitution.quasistatic.half_space.half_space_loss`) or the plate's
(Zener's coupled equation and the ball's modes driven by its force history,
:func:`plate_record`); :func:`route_top` is the fastest speed it serves. Both the law at the
asked speeds (:func:`restitution.laws.route_law.wall_law`) and the law on a grid
(:mod:`restitution.laws.wall_grid`) use them.

Three rules keep a hostile wall from hanging a run or serving a number that says nothing:

* **The contact** (:func:`contact_refusal`): Hertz's contact, every route here and the finite
  elements' judge hold while the compression is small against the ball's radius. A speed whose
  Hertz compression on the wall reaches :data:`HERTZ_COMPRESSION_LIMIT` has no model; a request
  with no other speed is refused in one line (:func:`check_wall_request` in SI units: a wall
  modulus in GPa typed as Pa sinks the ball by radii).
* **The cost** (:func:`route_cost`, :func:`check_route_cost`): every speed's time and memory is
  estimated from its contact time before any is computed, and a set beyond
  :data:`restitution.budget.TIME_BOUND_S` is refused with the number of speeds that fit.
* **Informative** (:func:`uninformative`): a value whose error exceeds it, or at a speed beyond
  the route's reach, is not served: the speed gets no value (status ``outside``) and the note
  says why and what answers instead. One function for every route of the walls.
"""

from __future__ import annotations

import math

import numpy as np

from restitution.errors import InputError
from restitution.laws.low_speed import low_speed_record
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.quasistatic.half_space import BALL_QUADRATURE_PHASE

__all__ = [
    "HALF_SPACE_ROUTE",
    "HERTZ_COMPRESSION_LIMIT",
    "PLATE_ROUTE",
    "PLATE_TOP_SEARCH",
    "check_contact",
    "check_route_cost",
    "check_wall_request",
    "contact_refusal",
    "hertz_compression",
    "is_plate",
    "plate_record",
    "route_at",
    "route_cost",
    "route_top",
    "uninformative",
]

PLATE_TOP_SEARCH = 0.03
"""The fastest speed (``c``) a plate's top is looked for below (the sphere's low-speed points
end there)."""

HERTZ_COMPRESSION_LIMIT = 0.25
"""Hertz's compression (``R``) at and beyond which no route of the package holds: the contact
radius ``a = sqrt(R delta)`` is then half the ball's radius, three times the widest contact the
half-space route reaches (``a / R = 0.155``) and the finite-element judge met (``0.14``).
Hertz's theory takes ``a << R``, and the judge is linear elasticity. A speed beyond it gets no
value and no offer of a finite-element point."""


PLATE_ROUTE = "Zener's thin plate, the coupled equation (restitution.quasistatic.plate)"
HALF_SPACE_ROUTE = (
    "the ball's modes driven by Hertz's pulse on the elastic half-space (Rayleigh's estimate) "
    "and the waves radiated into it (restitution.quasistatic.half_space)"
)


def uninformative(epsilon: float, epsilon_err: float, v: float | None = None,
                  reach: float | None = None) -> str | None:  # fmt: skip
    """Why a route's value is not served, or ``None`` when it is: its error exceeds the value
    (the interval ``epsilon +- err`` reaches below 0: it says nothing of the rebound), or the
    speed ``v`` lies beyond the route's stated ``reach`` (``c``). The one rule of every route
    that serves an elastic wall (the half-space, the plate, their grids and the SI answer,
    :meth:`restitution.laws.si_law.SILaw.points`).

    >>> uninformative(0.207, 1.0)
    'its value 0.207 +- 1 is not informative: the error exceeds the value'
    >>> uninformative(0.9, 0.01) is None
    True
    """
    reasons = []
    if not (math.isfinite(epsilon_err) and epsilon_err <= epsilon):
        reasons.append(
            f"its value {epsilon:.3g} +- {epsilon_err:.2g} is not informative: the error "
            "exceeds the value"
        )
    if reach is not None and v is not None and v > reach * (1.0 + 1e-9):
        reasons.append(f"v = {v:.4g} c lies beyond the route's reach {reach:.4g} c")
    return "; ".join(reasons) or None


def _contact_law(nu: float, wall):
    """Hertz's law of the ball (``nu``) on ``wall`` (``E*`` of both)."""
    from dataclasses import replace

    from restitution.quasistatic.hertz_sphere import sphere_contact_law

    return replace(sphere_contact_law(nu), effective_modulus=wall.effective_modulus(nu))


def hertz_compression(nu: float, wall, v: float) -> float:
    """Hertz's largest compression (``R``) of the ball (``nu``) hitting ``wall`` at ``v``
    (``c``): ``(5 m v^2 / (4 K))^(2/5)``, ``K = (4/3) E*``; not capped at ``R``."""
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS

    k = _contact_law(nu, wall).K
    return (1.25 * SPHERE_MASS * v * v / k) ** 0.4


def contact_refusal(nu: float, wall, v: float) -> str | None:
    """Why no route holds at ``v`` on ``wall`` (Hertz's compression at or beyond
    :data:`HERTZ_COMPRESSION_LIMIT`), or ``None``."""
    delta = hertz_compression(nu, wall, v)
    if delta < HERTZ_COMPRESSION_LIMIT:
        return None
    return (
        f"the ball would sink {delta:.3g} R into the wall (Hertz's compression with E* of ball "
        f"and wall, E_w/E = {wall.modulus_ratio:.3g}), and every route here needs it small "
        f"against the radius (below {HERTZ_COMPRESSION_LIMIT:g} R)"
    )


def check_contact(nu: float, wall, speeds) -> None:
    """Refuse, in one line, speeds (``c``) of which none has a model on ``wall``
    (:func:`contact_refusal`): the slowest one's compression is named."""
    speeds = [float(v) for v in speeds if float(v) > 0]
    if not speeds:
        return
    slowest = min(speeds)
    why = contact_refusal(nu, wall, slowest)
    if why is not None:
        hint = " (is the wall's modulus in Pa?)" if wall.modulus_ratio < 1e-6 else ""
        raise InputError(f"the wall: at v = {slowest:.3g} c {why}; no speed asked has a "
                         f"value{hint}")  # fmt: skip


def check_wall_request(grain, wall, speeds_m_s, wall_E: float) -> None:
    """The same refusal in the user's units, for the request (``--wall-E``, m/s): when the
    slowest asked speed already compresses the ball beyond :data:`HERTZ_COMPRESSION_LIMIT`
    into ``wall`` (``grain``'s units), one line with the compression and, for a modulus that
    looks like GPa typed as Pa, the number meant.

    >>> from restitution.bodies.wall import HalfSpace
    >>> from restitution.laws.units import Grain
    >>> steel = Grain(210e9, 0.3, 7850, "sphere")
    >>> soft = HalfSpace(63 / 210e9, 2500 / 7850, 0.2481)
    >>> check_wall_request(steel, soft, [1.0], 63.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    restitution.errors.InputError: --wall-E 63 Pa: at 1 m/s the ball would sink 11.6 radii ...
    """
    speeds = [float(w) for w in speeds_m_s if float(w) > 0]
    if not speeds or wall is None:
        return
    w = min(speeds)
    delta = hertz_compression(grain.law_nu, wall, float(grain.v_over_c(w, WALL.against)))
    if delta < HERTZ_COMPRESSION_LIMIT:
        return
    meant = 1e9 * wall_E
    hint = f" (did you mean {wall_E:g}e9?)" if 1e8 <= meant <= 2e12 else ""
    raise InputError(
        f"--wall-E {wall_E:g} Pa: at {w:g} m/s the ball would sink {delta:.3g} radii into "
        f"this wall (Hertz's compression; every route here needs it below "
        f"{HERTZ_COMPRESSION_LIMIT:g} of the radius); no speed asked has a value{hint}"
    )


def is_plate(wall) -> bool:
    from restitution.bodies.wall import Plate

    return isinstance(wall, Plate)


def _plate_holds(nu: float, plate, v: float) -> bool:
    """Whether Zener's model serves ``v``: the ball rebounds, the model holds (``validity``) and
    its value is informative (:func:`uninformative`; the ball's own part, below 1e-4 of the
    loss, left out)."""
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.plate import model_error, plate_impact, validity

    if contact_refusal(nu, plate, v) is not None:
        return False
    r = plate_impact(v, plate, nu=nu, mass=SPHERE_MASS)
    if not r.rebounds or validity(r, plate):
        return False
    return uninformative(r.epsilon, model_error(r, plate) / (2.0 * r.epsilon)) is None


def _half_space_holds(nu: float, wall, v: float) -> bool:
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.half_space import LossBeyondEnergy, half_space_loss
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    if contact_refusal(nu, wall, v) is not None:
        return False
    try:
        r = half_space_loss(get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry), v, wall)
    except LossBeyondEnergy:
        return False
    return uninformative(r.epsilon, r.epsilon_err) is None


def route_top(nu: float, wall, slowest: float) -> float:
    """The fastest speed (``c``) the wall's route serves, by bisection in ``ln v`` to 0.1 % from
    ``slowest`` up: on a half-space up to its reach, below it where the losses would reach the
    kinetic energy or the value stops being informative (a very dense wall); on a plate up to
    :data:`PLATE_TOP_SEARCH` where Zener's model holds, the ball rebounds and the value is
    informative (:class:`InputError` when the route holds not even at ``slowest``)."""
    if not is_plate(wall):
        from restitution.quasistatic.half_space import half_space_reach

        top = float(half_space_reach(nu, wall))
        if _half_space_holds(nu, wall, top):  # the usual wall: one evaluation
            return top
        if not _half_space_holds(nu, wall, slowest):
            raise InputError(
                f"the half-space route has no informative value on this wall even at v = "
                f"{slowest:g} c: the ball's vibrations and the waves radiated into it take all "
                "or nearly all the kinetic energy (a very dense or soft wall)"
            )
        return _fastest(lambda v: _half_space_holds(nu, wall, v), slowest, top)
    if not _plate_holds(nu, wall, slowest):
        raise InputError(
            f"Zener's thin-plate model has no informative value on this plate even at v = "
            f"{slowest:g} c (it does not hold, the ball does not rebound, or the error exceeds "
            "the value): no law at every speed; ask for single speeds"
        )
    if _plate_holds(nu, wall, PLATE_TOP_SEARCH):
        return PLATE_TOP_SEARCH
    return _fastest(lambda v: _plate_holds(nu, wall, v), slowest, PLATE_TOP_SEARCH)


def _fastest(holds, slowest: float, top: float) -> float:
    """The fastest speed between ``slowest`` (where ``holds``) and ``top`` (where not) at which
    ``holds``, by bisection in ``ln v`` to 0.1 %."""
    lo, hi = math.log(slowest), math.log(top)
    while hi - lo > 1e-3:  # the top to 0.1 %
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if holds(math.exp(mid)) else (lo, mid)
    return math.exp(lo)


def plate_record(v: float, impact, plate, modes) -> dict:
    """A plate's law point at ``v``: Zener's loss (the plate's flexural waves) and the ball's
    vibrations driven by the same force history
    (:func:`restitution.quasistatic.plate.ball_vibrations`), ``shares`` (ball, plate). Its
    error is Zener's model error plus the ball's part itself (Rayleigh's estimate carries a
    phase error of its order; it is below 1e-4 of the plate's loss here). Where the ball's
    slowest mode is slow against the contact (:data:`restitution.quasistatic.half_space.
    BALL_QUADRATURE_PHASE`: a thin or soft plate, whose contact lasts up to 200 Hertz times)
    the ball's part is half its envelope (:func:`restitution.quasistatic.half_space.
    ball_envelope`, which bounds Zener's pulse too), not integrated."""
    from restitution.quasistatic.half_space import ball_envelope, ball_integrated
    from restitution.quasistatic.plate import ball_vibrations, model_error

    if ball_integrated(modes, impact.contact_time):
        ball = ball_vibrations(impact, modes)
    else:
        ball = 0.5 * ball_envelope(modes, v, plate)
    loss = impact.plate_energy + ball
    eps = math.sqrt(max(impact.epsilon**2 - ball, 0.0))
    details = {"plate_energy": impact.plate_energy, "balance": impact.balance,
               "shares": [ball, impact.plate_energy]}  # fmt: skip
    with np.errstate(divide="ignore"):  # no epsilon left beside the ball's bound: error inf
        err = model_error(impact, plate) + ball
        return low_speed_record(v, np.float64(eps), loss, err, details=details)


def route_at(nu: float, wall):
    """``v -> (epsilon, loss, loss_err, details)`` of the wall's route (``c``; ``loss_err`` the
    route's own error of the loss)."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.half_space import ball_envelope, half_space_loss
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    modes = get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry)
    if is_plate(wall):
        from restitution.quasistatic.hertz_sphere import SPHERE_MASS
        from restitution.quasistatic.plate import plate_impact

        def plate(v):
            r = plate_record(v, plate_impact(v, wall, nu=nu, mass=SPHERE_MASS), wall, modes)
            details = {k: r[k] for k in ("plate_energy", "balance", "shares")}
            return r["epsilon"], r["energy_loss"], r["estimate_err"], details

        return plate

    def half_space(v):
        r = half_space_loss(modes, v, wall)
        details = {"shares": list(map(float, r.shares)), "band": list(map(float, r.band)),
                   "ball_envelope": ball_envelope(modes, v, wall)}  # fmt: skip
        return r.epsilon, r.energy_loss, r.energy_loss_err, details

    return half_space


# Wall time of the ball's quadrature: 2.3e-8 s a mode and node (0.5 s at 1.3e4 nodes, 1.26 s
# at 3.35e4, 1600 modes: steel on glass at v = 1e-4 and 1e-6 on the project's 2-core machine;
# a plate's spectrum, cos and sin on 6-node panels, 0.87 s at 2.6e4 nodes); about 0.05 s
# besides. Zener's equation: 0.01 s plus 0.008 s a Hertz contact time it lasts (0.38 s at 50).
_SECONDS_PER_MODE_NODE = 2.5e-8
_SECONDS_FIXED = 0.05
_ODE_SECONDS_PER_CONTACT = 0.008
# Bytes of the quadrature: the nodes, weights, forces and panel arrays (about 20 doubles a
# node) and the blocks of the cosine table (32 MiB, twice).
_BYTES_PER_NODE = 160.0
_BYTES_FIXED = 64.0 * 2**20


def route_cost(nu: float, wall, v, *, ball: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Estimated ``(seconds, bytes)`` of the wall's route at speeds ``v`` (``c``, shape (K,))
    on one core, before it runs: the ball's quadrature has a node every 1/48 period of its
    fastest mode over the contact (none beyond :data:`restitution.quasistatic.half_space.
    BALL_QUADRATURE_PHASE`: the envelope then; on a plate 6-node panels over the whole contact,
    cosine and sine), Zener's equation as many steps as its contact lasts Hertz contact times
    (up to :data:`restitution.quasistatic.plate.MAX_CONTACT_TIMES`; ``1 + 0.3 lambda^2`` of
    them, measured at Zener's ``lambda`` 0.8-13). Speeds refused by their contact
    (:func:`contact_refusal`) cost nothing but the check; ``ball=False``: Zener's equation
    alone (a plate's speed beyond its route's top, refused with its reason)."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES
    from restitution.quasistatic.plate import MAX_CONTACT_TIMES

    v = np.atleast_1d(np.asarray(v, dtype=float))
    k = _contact_law(nu, wall).K
    delta = (1.25 * SPHERE_MASS * v * v / k) ** 0.4
    tau = 2.9432752 * delta / v  # Hertz's contact time (hertz_sphere's kappa)
    modes = get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry)
    seconds = np.full(v.shape, _SECONDS_FIXED)
    per_phase = 16.0 * 0.75  # nodes per omega tau / pi: 16-node panels over half the pulse
    if is_plate(wall):
        lam = k**0.4 * SPHERE_MASS**0.6 * v**0.2 / wall.impedance  # plate.zener_parameter
        times = np.minimum(1.0 + 0.3 * lam * lam, MAX_CONTACT_TIMES)
        seconds += 0.01 + _ODE_SECONDS_PER_CONTACT * times
        tau = tau * times
        per_phase = 2.0 * 6.0 * 1.5  # 6-node panels over the whole pulse, cosine and sine
    omega_max = float(np.max(modes.omega))
    nodes = per_phase * omega_max * tau / math.pi + 16.0 * 24.0
    integrated = (float(np.min(modes.omega)) * tau < BALL_QUADRATURE_PHASE) & ball
    nodes = np.where(integrated & (delta < HERTZ_COMPRESSION_LIMIT), nodes, 0.0)
    seconds = np.where(delta < HERTZ_COMPRESSION_LIMIT, seconds, 0.0)
    seconds = seconds + _SECONDS_PER_MODE_NODE * len(modes) * nodes
    return seconds, _BYTES_FIXED + _BYTES_PER_NODE * nodes


def check_route_cost(
    nu: float, wall, speeds, what: str = "speeds of the wall's route", *, zener_only=()
) -> float:
    """Refuse, before any is computed, the route at ``speeds`` (``c``; and Zener's equation
    alone at ``zener_only``) beyond the time bound of one run
    (:data:`restitution.budget.TIME_BOUND_S`) or the memory of one speed beyond this machine's
    budget, in one line with the numbers and the count that fits; returns the estimated
    seconds (:func:`route_cost`)."""
    from restitution import budget

    speeds = np.unique(np.asarray([float(v) for v in speeds], dtype=float))
    alone = np.unique(np.asarray([float(v) for v in zener_only], dtype=float))
    if speeds.size + alone.size == 0:
        return 0.0
    seconds, memory = route_cost(nu, wall, np.concatenate([speeds, alone]))
    if alone.size:
        seconds[speeds.size :] = route_cost(nu, wall, alone, ball=False)[0]
    speeds = np.concatenate([speeds, alone])
    need = float(seconds.sum())
    worst = int(np.argmax(memory))
    budget.check_memory_total(
        "v", f"{speeds[worst]:.3g} c", float(memory[worst]), "the quadrature of the ball's modes "
        "over its contact", lambda room: "faster speeds or a harder wall (a shorter contact) fit",
    )  # fmt: skip
    if need > budget.TIME_BOUND_S:
        each = need / speeds.size
        most = int(budget.TIME_BOUND_S // each)
        raise InputError(
            f"{speeds.size} {what} would take about {budget.format_duration(need)} (about "
            f"{budget.format_duration(each)} a speed: the ball's modes over contacts of this "
            f"wall), more than the {budget.format_duration(budget.TIME_BOUND_S)} bound of one "
            f"run; ask for at most {most} speeds at a time"
        )
    return need
