"""The low-speed route of a body's law: points below the modal laws' slowest speed.

Units: the law's reduced units (speeds in ``c`` of the body's own material; a pair's relative
speed ``w``).

Each kind names its route (:attr:`~restitution.bodies.kinds.BodyKind.low_speed_route`, and
``pair_low_speed_route`` for two bodies of it): the sphere's is Rayleigh's estimate on Hertz's
force pulse (:mod:`restitution.quasistatic.low_speed`), the disk's the slow-impact model
(:mod:`restitution.quasistatic.slow_disk`). Both the shipped laws (:mod:`restitution.laws.making.
production`) and the serving of a request (a pair without a shipped law, an elastic wall's slow
speeds) call it; a new route is a function in :data:`_LOW_SPEED_ROUTES` and its modules in
:data:`restitution.provenance.ROUTE_MODULES`.
"""

from __future__ import annotations

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, kinds
from restitution.errors import InputError
from restitution.laws.law_point import QUASISTATIC_ROUTE, leave_one_out
from restitution.limits.run_options import Progress, progress_of
from restitution.status import Status

__all__ = [
    "low_speed_points",
    "low_speed_record",
    "low_speed_route",
    "low_speeds_of",
    "route_reach",
    "routed",
]


def low_speed_route(geometry: str, partner=None) -> str | None:
    """The name of the low-speed route of the body ``geometry`` on the wall (with a
    ``partner``: of two such bodies), ``None`` if it has none."""
    kind = body_kind(geometry)
    return kind.low_speed_route if partner is None else kind.pair_low_speed_route


def low_speeds_of(geometry: str, partner=None, nu: float | None = None) -> tuple[float, ...]:
    """The speeds of the low-speed points joined to the production law of a body on a wall
    (its kind's :attr:`~restitution.bodies.kinds.ProductionPlan.low_speeds`; the disk's are
    :data:`DISK_LOW_SPEEDS`) or of two bodies (:data:`PAIR_LOW_SPEEDS` for disks); none where
    the kind has no route or no plan. With ``nu``, only those within the route's reach
    (:func:`route_reach`; without it all, an upper bound for estimates)."""
    kind = body_kind(geometry)
    plan = kind.production if partner is None else kind.pair_production
    if plan is None or low_speed_route(geometry, partner) is None:
        return ()
    top = None if nu is None else route_reach(geometry, nu, partner)
    return tuple(v for v in plan.low_speeds if top is None or v <= top * (1.0 + 1e-12))


def route_reach(geometry: str, nu: float, partner=None) -> float | None:
    """The fastest speed (``c``; a pair's relative speed) the low-speed route of ``geometry``
    (with ``partner``) serves, or ``None`` where its plan's speeds are its reach: for two
    spheres :func:`restitution.quasistatic.low_speed.reach`, which depends on the partner."""
    if low_speed_route(geometry, partner) != "rayleigh" or partner is None:
        return None
    from restitution.quasistatic.low_speed import reach

    return reach(float(nu), partner)


def _track(speeds, nu: float, progress: Progress):
    """The speeds with a progress bar on stderr (stdout may carry a command's JSON)."""
    return progress.track(speeds, f"low speeds, nu = {nu:g}")


def _rayleigh_points(
    geometry: str, nu: float, speeds: list[float], progress: Progress, partner=None
):
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.low_speed import (
        CONTACT_TIME_SPREAD,
        LOW_SPEED_MODES,
        PAIR_LOW_SPEED_MODES,
        interpolation_error,
        low_speed_loss,
    )

    if partner is None:
        modes = get_modes(nu, LOW_SPEED_MODES, geometry=geometry)
        count = LOW_SPEED_MODES
    else:  # both spheres' modes below one frequency, each driven at its own pole
        count = PAIR_LOW_SPEED_MODES
        modes = partner.pair(nu, count, geometry)
    # What PCHIP between neighbouring points may miss joins each point's error.
    between = interpolation_error(modes, speeds) if len(speeds) > 1 else [0.0]
    out = []
    steps = _track(speeds, nu, progress)
    for v, gap in zip(steps, between, strict=True):
        r = low_speed_loss(modes, v)
        details = {"band": list(r.band)}
        if partner is not None:
            details["shares"] = list(r.shares)
        out.append((r, float(gap), details))
    parameters = {
        "route": "Rayleigh's estimate on Hertz's force pulse (restitution.quasistatic.low_speed)",
        "n_modes": count,
        "contact_time_spread": CONTACT_TIME_SPREAD,
    }
    return out, parameters


def _slow_modal_points(
    geometry: str, nu: float, speeds: list[float], progress: Progress, partner=None
):
    from restitution.quasistatic.slow_disk import MODEL_SPREAD, SLOW_CUTS, slow_loss, slow_modes

    modes = slow_modes(nu, partner)
    runs = [slow_loss(modes, v) for v in _track(speeds, nu, progress)]
    between = leave_one_out(speeds, [r.energy_loss for r in runs])
    out = [
        (r, float(gap), {"cuts": list(r.cuts), "losses": list(r.losses),
                         "convergence_err": r.convergence_err, "model_err": r.model_err})
        for r, gap in zip(runs, between, strict=True)
    ]  # fmt: skip
    parameters = {
        "route": "the disk's low modes in motion, its high modes static, closed by the 2D Hertz "
        "law (restitution.quasistatic.slow_disk)",
        "n_modes": len(modes),
        "cuts": list(SLOW_CUTS),
        "model_spread": MODEL_SPREAD,
    }
    return out, parameters


_LOW_SPEED_ROUTES = {"rayleigh": _rayleigh_points, "slow-modal": _slow_modal_points}
"""Each low-speed route by its name (a kind's ``low_speed_route``)."""


def low_speed_points(
    nu: float,
    speeds=None,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    partner=None,
    progress: Progress | bool = False,
) -> tuple[list[dict], dict]:
    """A body's low-speed law points, by its kind's route (:func:`low_speed_route`): the
    sphere's from Rayleigh's estimate (:mod:`restitution.quasistatic.low_speed`), the disk's
    and two disks' from the slow-impact model (:mod:`restitution.quasistatic.slow_disk`).

    Parameters
    ----------
    nu : float
        The body's Poisson number (the sphere's 3D one, the disk's 2D one).
    speeds : iterable of float, optional
        Speeds towards the wall, ``c``; default the kind's production speeds
        (:func:`low_speeds_of`).
    geometry : str
        The kind (the disk by default).
    partner : Partner, optional
        The second disk of a pair (then ``speeds`` are relative speeds ``w``).
    progress : Progress or bool
        The progress bar on stderr (:class:`restitution.limits.run_options.Progress`;
        ``True``/``False`` its shorthand).

    Returns
    -------
    records : list of dict
        One per speed, as a law's ``metadata["points"]`` holds them (``route``
        ``"quasistatic"``, ``status`` ``"quasistatic"``, ``asymptotic_ok`` false: there is no
        extrapolation to check), with the route's own details. The error is the estimate's
        (``estimate_err``) plus what PCHIP between this point and its neighbours may miss
        (``interpolation_err``).
    parameters : dict
        What they were computed with (the route, its settings, the code version), for
        :meth:`restitution.laws.law.EpsilonLaw.joined`.
    """
    from restitution.provenance import quasistatic_code_version

    name = low_speed_route(geometry, partner)
    if name is None:
        raise InputError(
            f"no low-speed route for the {geometry}{' pair' if partner else ''}; "
            f"{', '.join(routed())} have one"
        )
    route = _LOW_SPEED_ROUTES[name]
    speeds = [
        float(v) for v in (low_speeds_of(geometry, partner, nu) if speeds is None else speeds)
    ]
    results, parameters = route(geometry, float(nu), speeds, progress_of(progress), partner)
    records = [
        low_speed_record(v, r.epsilon, r.energy_loss, r.energy_loss_err, gap, details)
        for v, (r, gap, details) in zip(speeds, results, strict=True)
    ]
    parameters = {
        **parameters,
        "v_min": speeds[0],
        "v_max": speeds[-1],
        "code_version": quasistatic_code_version(geometry, name, pair=partner is not None),
    }
    return records, parameters


def low_speed_record(
    v: float, epsilon: float, loss: float, estimate_err: float, gap: float = 0.0, details=None
) -> dict:
    """One low-speed point as a law's ``metadata["points"]`` holds it: its error the route's
    estimate (``estimate_err``, of the loss) plus what PCHIP between its neighbours may miss
    (``gap``), flagged ``quasistatic`` (no extrapolation to check), with the route's own
    ``details``. ``epsilon`` is the route's (``sqrt(1 - loss)`` for an elastic loss)."""
    err = estimate_err + gap
    return {
        "v": v,
        "epsilon": epsilon,
        "epsilon_err": err / (2.0 * epsilon),
        "energy_loss": loss,
        "energy_loss_err": err,
        "estimate_err": estimate_err,
        "interpolation_err": gap,
        **(details or {}),
        "asymptotic_ok": False,
        "status": Status.QUASISTATIC,
        "route": QUASISTATIC_ROUTE,
        "message": "",
    }


def routed() -> list[str]:
    """Who has a low-speed route: each kind on the wall, and pairs of it."""
    out = []
    for kind in kinds().values():
        if kind.low_speed_route is not None:
            out.append(f"the {kind.geometry}")
        if kind.pair_low_speed_route is not None:
            out.append(f"two {kind.geometry}s")
    return out
