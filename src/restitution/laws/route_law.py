"""A pair's law computed at the asked speeds by its low-speed route, in seconds, without a file.

Units: the first body's reduced units; ``v`` the relative speed of the centres in ``c1``.

Two spheres of any sizes and materials are never in a shipped grid, and their modal law would
take hours (docs/spheres.md). Up to the reach of their low-speed route (Rayleigh's estimate on
the pair's Hertz pulse, :func:`restitution.quasistatic.low_speed.reach`: about 15 m/s for two
steel spheres) each speed costs a fraction of a second. :func:`route_law` computes the speeds a
user asked for, each alone (so without an interpolation error: each point is served at its
own speed and nowhere between), and the reach itself, as a law that serves its points only
(:attr:`restitution.laws.law.EpsilonLaw.at_points_only`; a speed between them is ``outside``).
A law defined at every speed, for exports, constants and plots, is the route's whole grid
(``restitution law ... --compute``, :func:`restitution.laws.compute.computed_law`).

:func:`wall_law` does the same for a sphere on an elastic wall (issue 42): a half-space (the
ball's vibrations and the waves radiated into the block, up to the route's reach) or a thin
plate (Zener's model, speed by speed where it holds; docs/walls.md). Where neither route has a
value (above the half-space's reach, a plate where Zener's model fails), a point of the finite
elements' judge stored at the asked speed answers (:func:`restitution.laws.wall_points.
stored_wall_point`); other speeds there are ``outside``.
"""

from __future__ import annotations

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.production import low_speed_points, low_speed_record, route_reach
from restitution.laws.wall_points import compute_command, stored_wall_point

__all__ = ["route_law", "route_serves", "wall_law"]


def route_serves(geometry: str, nu: float, partner) -> bool:
    """Whether the pair of ``geometry`` with ``partner`` has a low-speed route with a reach
    (two spheres): then :func:`route_law` answers without a law file."""
    return partner is not None and route_reach(geometry, nu, partner) is not None


def route_law(nu: float, geometry: str, partner, speeds) -> EpsilonLaw:
    """The law of the pair at ``speeds`` (relative speeds, ``c1``) within the route's reach, and
    at the reach itself (half the reach too when no asked speed lies below it: a law has two
    points at least); speeds above the reach are left out (they are ``outside``).

    Raises
    ------
    InputError
        When the pair has no such route (:func:`route_serves`).
    """
    if not route_serves(geometry, nu, partner):
        raise InputError(
            f"two {geometry}s have no low-speed route with a reach; compute their law "
            "(restitution law ... --compute)"
        )
    top = float(route_reach(geometry, nu, partner))
    inside = sorted({float(v) for v in speeds if 0.0 < float(v) < top})
    points = [*(inside or [0.5 * top]), top]
    records, parameters = [], {}
    for v in points:
        (record,), parameters = low_speed_points(nu, [v], geometry=geometry, partner=partner)
        records.append(record)
    parameters = {**parameters, "reach": top, "v_min": points[0], "v_max": points[-1]}
    law = EpsilonLaw.from_records(
        nu,
        records,
        key="low_speed",
        parameters=parameters,
        geometry=geometry,
        partner=partner,
        at_points_only=True,
    )
    law.metadata["source"] = "computed now at the asked speeds by the pair's low-speed route"
    return law


def wall_law(nu: float, wall, speeds, *, progress=False) -> EpsilonLaw:
    """The law of a sphere on an elastic half-space ``wall``
    (:class:`restitution.bodies.wall.HalfSpace`) at ``speeds`` (``c``) within its route's reach
    (:func:`restitution.quasistatic.half_space.half_space_reach`) and at the reach: each speed
    alone (:func:`restitution.quasistatic.half_space.half_space_loss`, the ball's vibrations and
    the waves radiated into the wall, ``shares`` in that order), served at its points only
    (speeds above the reach are ``outside``). On a wall dense enough that the losses reach the
    kinetic energy below the reach, those speeds have no value and say why
    (``metadata["refused"]``, served as ``outside``), and the reach is where the route stops
    (:func:`restitution.laws.wall_route.route_top`)."""
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.bodies.wall import Plate
    from restitution.laws.wall_grid import SLOWEST
    from restitution.laws.wall_route import route_at, route_top
    from restitution.provenance import quasistatic_code_version
    from restitution.quasistatic.half_space import LossBeyondEnergy, half_space_reach
    from restitution.quasistatic.low_speed import CONTACT_TIME_SPREAD, LOW_SPEED_MODES

    if isinstance(wall, Plate):
        return _plate_law(nu, wall, speeds)
    reach = float(half_space_reach(nu, wall))
    inside = sorted({float(v) for v in speeds if 0.0 < float(v) < reach})
    route = route_at(nu, wall)  # the grid law's route, speed by speed

    def record(v):
        eps, loss, err, details = route(v)
        return low_speed_record(v, eps, loss, err, details=details)

    records, refused = [], {}
    for v in inside:
        try:
            records.append(record(v))
        except LossBeyondEnergy as exc:
            stored = stored_wall_point(nu, wall, v)
            if stored is None:
                refused[repr(v)] = str(exc)
            else:
                records.append({**stored, "model_refused": str(exc)})
    top = reach
    try:  # the reach itself, and a point below it where no speed was asked
        records += [record(v) for v in ([] if inside else [0.5 * reach])]
        records.append(record(reach))
    except LossBeyondEnergy:  # a wall so dense that the route stops below its reach
        try:
            top = route_top(nu, wall, SLOWEST)
        except InputError as exc:  # not even at the grid's slowest speed
            if not records:
                raise InputError(
                    f"{exc.args[0]}; a finite-element point answers instead (10-45 minutes of "
                    "one core): "
                    f"{compute_command(nu, wall.to_dict(), max(inside or [reach]))}"
                ) from None
            top = max((r["v"] for r in records if "v_stored" not in r), default=SLOWEST)
        if all(r["v"] != top for r in records):
            records.append(record(top))
    above = sorted({float(v) for v in speeds if float(v) > reach})
    records += [r for r in (stored_wall_point(nu, wall, v) for v in above) if r is not None]
    parameters = {
        "route": "the ball's modes driven by Hertz's pulse on the elastic half-space (Rayleigh's "
        "estimate) and the waves radiated into it (Lamb's point-force radiation; "
        "restitution.quasistatic.half_space)",
        "n_modes": LOW_SPEED_MODES,
        "contact_time_spread": CONTACT_TIME_SPREAD,
        "reach": top,
        "code_version": quasistatic_code_version(SPHERE.geometry, "rayleigh"),
    }
    law = EpsilonLaw.from_records(
        nu, records, key="low_speed", parameters=parameters, geometry=SPHERE.geometry,
        at_points_only=True,
    )  # fmt: skip
    law.metadata["wall"] = wall.to_dict()
    law.metadata["refused"] = refused
    law.metadata["source"] = "computed now at the asked speeds: a sphere on an elastic half-space"
    return law


def _plate_law(nu: float, plate, speeds) -> EpsilonLaw:
    """A sphere on a thin plate at ``speeds`` (``c``), each by Zener's model solved as the
    coupled equation (:mod:`restitution.quasistatic.plate`); the speeds where the model does
    not hold, or the ball does not rebound, are left out with the reason
    (``metadata["refused"]``), served as ``outside``."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.errors import InputError
    from restitution.laws.wall_grid import SLOWEST
    from restitution.laws.wall_route import plate_record, route_top
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES
    from restitution.quasistatic.plate import plate_impact, validity

    modes = get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry)

    records, refused = [], {}
    for v in sorted({float(x) for x in speeds if float(x) > 0}):
        r = plate_impact(v, plate, nu=nu, mass=SPHERE_MASS)
        reasons = validity(r, plate)
        if not r.rebounds:
            reasons.insert(0, "the ball does not rebound (it stays on the plate)")
        if reasons:
            stored = stored_wall_point(nu, plate, v)
            if stored is None:
                refused[repr(v)] = "; ".join(reasons)
            else:
                records.append({**stored, "model_refused": "; ".join(reasons)})
            continue
        records.append(plate_record(v, r, plate, modes))
    if not records:
        reasons = "; ".join(sorted(set(refused.values())))
        fastest = max(float(v) for v in refused)
        command = compute_command(nu, plate.to_dict(), fastest)
        advice = (
            ""
            if "does not rebound" in reasons
            else f"; a finite-element point answers instead (10-45 minutes of one core): "
            f"{command}; the next call serves it"
        )
        raise InputError(f"the thin-plate model serves none of the asked speeds: {reasons}{advice}")
    parameters = {
        "route": "Zener's thin plate, the coupled equation (restitution.quasistatic.plate)"
    }
    try:  # the fastest speed the model holds at (for the outside rows' note)
        parameters["reach"] = route_top(nu, plate, SLOWEST)
    except InputError:
        pass  # not even at the slowest grid speed: the asked speeds say why
    law = EpsilonLaw.from_records(
        nu, records, key="low_speed", parameters=parameters, geometry=SPHERE.geometry,
        at_points_only=True,
    )  # fmt: skip
    law.metadata["wall"] = plate.to_dict()
    law.metadata["refused"] = refused
    law.metadata["source"] = "computed now at the asked speeds: a sphere on a thin plate"
    return law
