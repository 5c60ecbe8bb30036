"""The route of two grains without a shipped law whose pair has a low-speed route with a reach
(two spheres): the law at the asked speeds, each computed now.

Units: SI at the edge; the pair's law in the first grain's reduced units (relative speeds
``w``, ``c1``).

Where a law at every speed is needed (exports, constants, damping) the route is refused with
the plan of ``--compute``.
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.bodies.pair.partner import UnequalPairError
from restitution.errors import InputError
from restitution.laws.law_nu import shipped_match
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.laws.route_law import route_law, route_serves
from restitution.laws.routes.base import check_speed_count, computing_route, register_route
from restitution.laws.routes.given import target
from restitution.laws.si_law import SILaw
from restitution.laws.units import Grain

__all__ = ["ROUTE_SECONDS_PER_SPEED", "PairRoute"]

ROUTE_SECONDS_PER_SPEED = 0.6
"""Wall time of one speed of a pair's low-speed route, seconds (0.57 s measured for the shipped
sphere pairs' production points)."""


@dataclass(frozen=True)
class PairRoute:
    """Two grains by their pair's low-speed route (module docs)."""

    name: str = "pair-low-speed"
    order: float = 40

    def serves(self, request) -> bool:
        r = request
        if r.compute or r.law_file is not None or r.elastic_wall is not None:
            return False
        law_nu, body, partner = target(r)
        try:
            return route_serves(body, law_nu, partner) and not shipped_match(law_nu, body, partner)
        except UnequalPairError as exc:
            raise InputError(_unequal(r, exc)) from None

    def law(self, request, note, progress: bool) -> SILaw:
        r = request
        law_nu, body, partner = target(r)
        needs = [
            what
            for what, asked in (
                ("--export", r.export_dir is not None),
                ("--reference-speed/--maxwell-temperature", r.constants),
                ("damping", r.damped and not r.plastic),
            )
            if asked
        ]
        if needs:
            p = computing_route("modal").plan(law_nu, body, partner)
            verb = "needs" if len(needs) == 1 else "need"
            raise InputError(
                f"{' and '.join(needs)} {verb} the pair's law at every speed, which is not "
                f"shipped: add --compute ({p.words()})"
            )
        grain = Grain(r.E, r.nu, r.rho, r.shape)
        # The pair's law takes the relative speed: v = w / c (the rigid wall's scale, k = 1).
        vs = [float(grain.v_over_c(w, WALL.against)) for w in (*r.speeds, *r.measured_speeds)]
        check_speed_count(len(set(vs)), ROUTE_SECONDS_PER_SPEED,
                          f"the {body} pair's low-speed route")  # fmt: skip
        note(
            f"note: two {body}s of this pair have no shipped law: each speed is computed now by "
            "their low-speed route (about a second a speed)"
        )
        try:
            law = route_law(law_nu, body, partner, vs)
        except UnequalPairError as exc:
            raise InputError(_unequal(r, exc)) from None
        return SILaw(Grain(r.E, r.nu, r.rho, r.shape), r.against, law,
                     partner_grain=r.partner_grain)  # fmt: skip

    def table(self, request, note, progress: bool) -> SILaw:
        """The pair's law at every speed of its route's reach (``si_law(..., radius_ratio=...)``
        of two spheres): the route on a grid of speeds with the PCHIP gap measured inside every
        interval (:func:`restitution.laws.wall_grid.route_grid_law`), its time told first."""
        from restitution import budget
        from restitution.laws.low_speed import low_speed_points, route_reach
        from restitution.laws.wall_grid import SLOWEST, grid_evaluations, route_grid_law

        r = request
        law_nu, body, partner = target(r)
        top = float(route_reach(body, law_nu, partner))
        count = len(grid_evaluations(SLOWEST, top))
        check_speed_count(count, ROUTE_SECONDS_PER_SPEED,
                          f"the grid of the {body} pair's low-speed route")  # fmt: skip
        note(f"note: two {body}s of this pair have no shipped law: their law at every speed is "
             f"computed now by their low-speed route on a grid of speeds (about "
             f"{budget.format_duration(count * ROUTE_SECONDS_PER_SPEED)})")  # fmt: skip

        def route(v: float):
            (rec,), _ = low_speed_points(law_nu, [v], geometry=body, partner=partner)
            shares = {"shares": rec["shares"]} if "shares" in rec else {}
            return rec["epsilon"], rec["energy_loss"], rec["estimate_err"], shares

        try:
            law = route_grid_law(route, law_nu, top, geometry=body, partner=partner,
                                 name="the pair's low-speed route",
                                 what=f"speeds of the {body} pair's route",
                                 progress=progress)  # fmt: skip
        except UnequalPairError as exc:
            raise InputError(_unequal(r, exc)) from None
        law.metadata["source"] = (
            f"computed now on a grid of {law.v.size} speeds by the pair's low-speed route (the "
            "PCHIP error measured inside every interval)"
        )
        return SILaw(Grain(r.E, r.nu, r.rho, r.shape), r.against, law,
                     partner_grain=r.partner_grain)  # fmt: skip


def _unequal(r, exc) -> str:
    """The refusal of a pair whose route's modes all belong to one grain, in ``law``'s words
    (the body layer's names ``collide``'s way out and mode counts, which ``law`` has no option
    for)."""
    ratio = r.partner_radius_ratio
    if ratio is not None and ratio != 1.0:
        return (
            f"--partner-radius-ratio {ratio:g}: the pair's low-speed route keeps a few thousand "
            "modes of the two grains, all of the larger one here (the smaller one's would take "
            f"about {exc.need:.2g}); {r.unequal_sizes()}"
        )
    still = "the partner" if exc.still == 1 else "this grain"
    return (
        f"the pair's low-speed route keeps a few thousand modes of the two grains, none of "
        f"{still} (its sound speed over its radius is far above the other's: it would take "
        f"about {exc.need:.2g} modes): no law of so unequal a pair is computed; check "
        "--partner-E and --partner-rho"
    )


register_route(PairRoute())
