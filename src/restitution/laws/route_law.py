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
"""

from __future__ import annotations

from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.production import low_speed_points, route_reach

__all__ = ["route_law", "route_serves"]


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
