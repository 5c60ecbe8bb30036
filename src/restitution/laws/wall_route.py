"""The elastic wall's routes at one speed, and how fast they reach (issue 42).

Units: the ball's reduced units (``E = rho = R = 1`` of its 3D constants); ``v`` in ``c``.

:func:`route_at` is the half-space's route (the ball's Rayleigh estimate and Lamb's radiation of
Hertz's pulse, :func:`restitution.quasistatic.half_space.half_space_loss`) or the plate's
(Zener's coupled equation and the ball's modes driven by its force history,
:func:`plate_record`); :func:`route_top` is the fastest speed it serves. Both the law at the
asked speeds (:func:`restitution.laws.route_law.wall_law`) and the law on a grid
(:mod:`restitution.laws.wall_grid`) use them.
"""

from __future__ import annotations

import math

from restitution.errors import InputError
from restitution.laws.production import low_speed_record

__all__ = [
    "HALF_SPACE_ROUTE",
    "PLATE_ROUTE",
    "PLATE_TOP_SEARCH",
    "is_plate",
    "plate_record",
    "route_at",
    "route_top",
]

PLATE_TOP_SEARCH = 0.03
"""The fastest speed (``c``) a plate's top is looked for below (the sphere's low-speed points
end there)."""


PLATE_ROUTE = "Zener's thin plate, the coupled equation (restitution.quasistatic.plate)"
HALF_SPACE_ROUTE = (
    "the ball's modes driven by Hertz's pulse on the elastic half-space (Rayleigh's estimate) "
    "and the waves radiated into it (restitution.quasistatic.half_space)"
)


def is_plate(wall) -> bool:
    from restitution.bodies.wall import Plate

    return isinstance(wall, Plate)


def _plate_holds(nu: float, plate, v: float) -> bool:
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.plate import plate_impact, validity

    r = plate_impact(v, plate, nu=nu, mass=SPHERE_MASS)
    return bool(r.rebounds) and not validity(r, plate)


def _half_space_holds(nu: float, wall, v: float) -> bool:
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.quasistatic.half_space import LossBeyondEnergy, half_space_loss
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES

    try:
        half_space_loss(get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry), v, wall)
    except LossBeyondEnergy:
        return False
    return True


def route_top(nu: float, wall, slowest: float) -> float:
    """The fastest speed (``c``) the wall's route serves, by bisection in ``ln v`` to 0.1 % from
    ``slowest`` up: on a half-space up to its reach, below it where the losses would reach the
    kinetic energy (a very dense wall); on a plate up to :data:`PLATE_TOP_SEARCH` where Zener's
    model holds and the ball rebounds (:class:`InputError` when the route holds not even at
    ``slowest``)."""
    if not is_plate(wall):
        from restitution.quasistatic.half_space import half_space_reach

        top = float(half_space_reach(nu, wall))
        if _half_space_holds(nu, wall, top):  # the usual wall: one evaluation
            return top
        if not _half_space_holds(nu, wall, slowest):
            raise InputError(
                f"the half-space route has no value on this wall even at v = {slowest:g} c: the "
                "ball's vibrations and the waves radiated into it take all the kinetic energy "
                "(a very dense or soft wall)"
            )
        return _fastest(lambda v: _half_space_holds(nu, wall, v), slowest, top)
    if not _plate_holds(nu, wall, slowest):
        raise InputError(
            f"Zener's thin-plate model does not hold on this plate even at v = {slowest:g} c "
            "(or the ball does not rebound): no law at every speed; ask for single speeds"
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
    phase error of its order; it is below 1e-4 of the plate's loss here)."""
    from restitution.quasistatic.plate import ball_vibrations, model_error

    ball = ball_vibrations(impact, modes)
    loss = impact.plate_energy + ball
    eps = math.sqrt(max(impact.epsilon**2 - ball, 0.0))
    details = {"plate_energy": impact.plate_energy, "balance": impact.balance,
               "shares": [ball, impact.plate_energy]}  # fmt: skip
    return low_speed_record(v, eps, loss, model_error(impact, plate) + ball, details=details)


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
