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
(``restitution law ... --compute``, :func:`restitution.laws.making.compute.computed_law`).

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
from restitution.laws.low_speed import low_speed_points, low_speed_record, route_reach
from restitution.laws.partners.base import partner_of_body
from restitution.laws.wall_points import compute_command, stored_wall_point
from restitution.laws.wall_route import uninformative

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


def _keep(nu: float, wall, v: float, rec, why, records: list, refused: dict) -> None:
    """The route's record ``rec`` at ``v`` into ``records`` where it is served (``why`` is
    ``None``); else the stored finite-element point of ``wall`` there (with the route's reason),
    or, without one, the reason into ``refused``."""
    if why is None:
        records.append(rec)
        return
    stored = stored_wall_point(nu, wall, v)
    if stored is None:
        refused[repr(v)] = why
    else:
        records.append({**stored, "model_refused": why})


def wall_law(nu: float, wall, speeds, *, progress=False) -> EpsilonLaw:
    """The law of a sphere on an elastic half-space ``wall``
    (:class:`restitution.bodies.wall.HalfSpace`) at ``speeds`` (``c``) within its route's reach
    (:func:`restitution.quasistatic.half_space.half_space_reach`) and at the reach: each speed
    alone (:func:`restitution.quasistatic.half_space.half_space_loss`, the ball's vibrations and
    the waves radiated into the wall, ``shares`` in that order), or, for more speeds than a grid
    spanning them computes, interpolated from that grid with its measured gap
    (:func:`restitution.laws.wall_grid.tabulated_records`); served at its points only (speeds
    above the reach are ``outside``). A value that is not informative
    (:func:`restitution.laws.wall_route.uninformative`), and on a wall dense enough that the
    losses reach the kinetic energy below the reach, has no value and says why
    (``metadata["refused"]``, served as ``outside``), and the reach is where the route stops
    (:func:`restitution.laws.wall_route.route_top`). Before anything is computed: speeds whose
    Hertz compression leaves every model (:func:`restitution.laws.wall_route.check_contact`:
    all of them refused in one line) and the estimated time
    (:func:`restitution.laws.wall_route.check_route_cost`)."""
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.bodies.wall import Plate
    from restitution.laws.wall_grid import SLOWEST
    from restitution.laws.wall_route import check_contact, check_route_cost, route_at, route_top
    from restitution.provenance import quasistatic_code_version
    from restitution.quasistatic.half_space import LossBeyondEnergy, half_space_reach
    from restitution.quasistatic.low_speed import CONTACT_TIME_SPREAD, LOW_SPEED_MODES

    if isinstance(wall, Plate):
        return _plate_law(nu, wall, speeds)
    asked = sorted({float(v) for v in speeds if float(v) > 0})
    check_contact(nu, wall, asked)
    reach = float(half_space_reach(nu, wall))
    inside = [v for v in asked if v < reach]
    anchors = [*([] if inside else [0.5 * reach]), reach]
    tabulate = _tabulates(inside)
    check_route_cost(nu, wall, [*(_grid_of(inside) if tabulate else inside), *anchors])
    route = route_at(nu, wall)  # the grid law's route, speed by speed

    def record(v):
        eps, loss, err, details = route(v)
        return low_speed_record(v, eps, loss, err, details=details)

    records, refused = [], {}

    def keep(v, rec, why):
        why = why or uninformative(rec["epsilon"], rec["epsilon_err"])
        _keep(nu, wall, v, rec, why, records, refused)

    computed = None
    if tabulate:
        from restitution.laws.wall_grid import tabulated_records

        try:
            computed = tabulated_records(route, inside)
        except LossBeyondEnergy:  # the route stops inside the asked range: speed by speed
            check_route_cost(nu, wall, inside)
    if computed is not None:
        for rec in computed:
            keep(rec["v"], rec, None)
    else:
        for v in inside:
            try:
                keep(v, record(v), None)
            except LossBeyondEnergy as exc:
                keep(v, None, str(exc))
    top = reach
    try:  # the reach itself, and a point below it where no speed was asked
        anchor = [record(v) for v in anchors]
        if any(uninformative(r["epsilon"], r["epsilon_err"]) for r in anchor):
            raise LossBeyondEnergy("not informative at the reach")
        records += anchor
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
    above = [v for v in asked if v > reach]
    no_judge = _beyond_models(nu, wall, above, refused)
    records += [
        r
        for r in (stored_wall_point(nu, wall, v) for v in above if repr(v) not in no_judge)
        if r is not None
    ]
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
        nu, _unique(records), key="low_speed", parameters=parameters, geometry=SPHERE.geometry,
        at_points_only=True,
    )  # fmt: skip
    partner_of_body(wall).write(law, wall)
    law.metadata["refused"] = refused
    law.metadata["no_judge"] = sorted(no_judge)
    law.metadata["source"] = (
        "computed now at the asked speeds: a sphere on an elastic half-space"
        + _tabulated_words(inside, computed)
    )
    return law


def _tabulates(inside) -> bool:
    """Whether the asked speeds ``inside`` the route (``c``) are more than a grid spanning them
    computes (:func:`restitution.laws.wall_grid.grid_evaluations`): then they are interpolated
    from that grid."""
    from restitution.laws.wall_grid import grid_evaluations

    return len(inside) > 2 and len(inside) > len(grid_evaluations(min(inside), max(inside)))


def _grid_of(inside) -> list[float]:
    """The speeds (``c``) a grid spanning ``inside`` computes the route at."""
    from restitution.laws.wall_grid import grid_evaluations

    return grid_evaluations(min(inside), max(inside))


def _tabulated_words(inside, computed) -> str:
    if computed is None:
        return ""
    from restitution.laws.wall_grid import grid_evaluations

    n = len(grid_evaluations(min(inside), max(inside)))
    return (
        f"; its {len(inside)} speeds interpolated from the route computed at {n} speeds "
        "spanning them (restitution.laws.wall_grid.tabulated_records: the measured PCHIP gap "
        "in each error)"
    )


def _beyond_models(nu: float, wall, speeds, refused: dict) -> set[str]:
    """The speeds (``c``) among ``speeds`` whose Hertz compression leaves every model
    (:func:`restitution.laws.wall_route.contact_refusal`): their reason into ``refused``, their
    keys returned (no finite-element point is offered for them)."""
    from restitution.laws.wall_route import contact_refusal

    out = set()
    for v in speeds:
        why = contact_refusal(nu, wall, v)
        if why is not None:
            refused[repr(v)] = why
            out.add(repr(v))
    return out


def _unique(records: list[dict]) -> list[dict]:
    """``records`` with one record a speed (the first)."""
    seen, out = set(), []
    for r in records:
        if float(r["v"]) not in seen:
            seen.add(float(r["v"]))
            out.append(r)
    return out


def _plate_law(nu: float, plate, speeds) -> EpsilonLaw:
    """A sphere on a thin plate at ``speeds`` (``c``), each by Zener's model solved as the
    coupled equation (:mod:`restitution.quasistatic.plate`; interpolated from a grid for many
    speeds, as :func:`wall_law`); the speeds where the model does not hold, the ball does not
    rebound, the value is not informative or the speed lies beyond the route's top
    (:func:`restitution.laws.wall_route.route_top`, :func:`restitution.laws.wall_route.
    uninformative`) are left out with the reason (``metadata["refused"]``), served as
    ``outside``. Where none is served the law holds the top alone."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.laws.wall_grid import SLOWEST
    from restitution.laws.wall_route import (
        check_contact,
        check_route_cost,
        plate_record,
        route_top,
    )
    from restitution.quasistatic.hertz_sphere import SPHERE_MASS
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES
    from restitution.quasistatic.plate import echo_ratio, model_error, plate_impact, validity

    asked = sorted({float(x) for x in speeds if float(x) > 0})
    check_contact(nu, plate, asked)
    refused: dict = {}
    no_judge = _beyond_models(nu, plate, asked, refused)
    modelled = [v for v in asked if repr(v) not in no_judge]
    slowest = min([SLOWEST, *modelled])
    # The top first: a bisection of about 16 of Zener's equations alone (no ball's modes),
    # each bounded (at most MAX_CONTACT_TIMES contact times, under 2 s).
    try:  # the fastest speed the model serves (the rule's reach, and the outside rows' note)
        top = route_top(nu, plate, slowest)
    except InputError:
        top = None  # not even at the slowest speed: the asked speeds say why
    inside = [v for v in modelled if top is not None and v <= top * (1.0 + 1e-9)]
    tabulate = _tabulates(inside)
    per_speed = [v for v in inside if not tabulate]
    beyond = [v for v in modelled if v not in set(inside)]  # Zener's equation: the reason
    check_route_cost(nu, plate, _grid_of(inside) if tabulate else per_speed, zener_only=beyond)
    modes = get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry)
    records = []

    def keep(v, rec, reasons):
        why = "; ".join(reasons) if reasons else uninformative(
            rec["epsilon"], rec["epsilon_err"], v, top)  # fmt: skip
        _keep(nu, plate, v, rec, why, records, refused)

    computed = None
    if tabulate:
        from restitution.laws.wall_grid import tabulated_records

        def held(v):  # route_at's plate route, where the model holds
            r = plate_impact(v, plate, nu=nu, mass=SPHERE_MASS)
            if not r.rebounds or validity(r, plate):
                raise _NotHeld
            rec = plate_record(v, r, plate, modes)
            details = {k: rec[k] for k in ("plate_energy", "balance", "shares")}
            return rec["epsilon"], rec["energy_loss"], rec["estimate_err"], details

        try:
            computed = tabulated_records(held, inside)
        except _NotHeld:  # the model fails inside the asked range: speed by speed
            check_route_cost(nu, plate, inside)
    for v in [x for x in modelled if computed is None or x not in inside]:
        r = plate_impact(v, plate, nu=nu, mass=SPHERE_MASS)
        reasons = validity(r, plate)
        if not r.rebounds:
            reasons.insert(0, "the ball does not rebound (it stays on the plate)")
        if not reasons and top is not None and v > top * (1.0 + 1e-9):
            # Beyond the top: why (the reach, and the value), without the ball's modes.
            err = model_error(r, plate) / (2.0 * r.epsilon)
            reasons.append(uninformative(r.epsilon, err, v, top))
        keep(v, None if reasons else plate_record(v, r, plate, modes), reasons)
    for rec in computed or []:
        keep(rec["v"], rec, None)
    if not records and top is not None:  # nothing served: the law holds its top alone
        records.append(plate_record(top, plate_impact(top, plate, nu=nu, mass=SPHERE_MASS),
                                    plate, modes))  # fmt: skip
    if not records:
        reasons = "; ".join(sorted(set(refused.values())))
        fastest = max(float(v) for v in refused)
        command = compute_command(nu, plate.to_dict(), fastest)
        advice = (
            ""
            if "does not rebound" in reasons or no_judge
            else f"; a finite-element point answers instead (10-45 minutes of one core): "
            f"{command}; the next call serves it"
        )
        slowest = min(float(v) for v in refused)
        echo = echo_ratio(plate_impact(slowest, plate, nu=nu, mass=SPHERE_MASS), plate)
        if echo > 1.0:  # the far side's echo returns after the contact: a block, in seconds
            advice = (
                f"; to the ball a plate of {plate.thickness:g} of its radii is a block (the "
                f"echo of its far side returns {echo:.3g} contact times later, after the ball "
                "has left): leave out --wall-thickness for the elastic half-space (seconds)"
            )
        raise InputError(f"the thin-plate model serves none of the asked speeds: {reasons}{advice}")
    parameters = {
        "route": "Zener's thin plate, the coupled equation (restitution.quasistatic.plate)"
    }
    if top is not None:
        parameters["reach"] = top
    law = EpsilonLaw.from_records(
        nu, _unique(records), key="low_speed", parameters=parameters, geometry=SPHERE.geometry,
        at_points_only=True,
    )  # fmt: skip
    partner_of_body(plate).write(law, plate)
    law.metadata["refused"] = refused
    law.metadata["no_judge"] = sorted(no_judge)
    law.metadata["source"] = "computed now at the asked speeds: a sphere on a thin plate" + (
        _tabulated_words(inside, computed)
    )
    return law


class _NotHeld(InputError):
    """Zener's model fails at a grid speed inside the asked range."""
