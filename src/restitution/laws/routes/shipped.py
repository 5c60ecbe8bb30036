"""The route of the shipped laws: the law of the grain's Poisson number, interpolated between
the shipped ones (:mod:`restitution.laws.law_nu`). Asked last: it serves every request no other
route took, or refuses it with what would serve it.

Units: SI at the edge.

Two grains of two materials have a shipped law only for the shipped pair; for any other the
refusal states the plan of ``--compute`` (or names the law computed before).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution import budget
from restitution.atomic import check_output_dir
from restitution.errors import InputError
from restitution.laws.law_nu import shipped_match
from restitution.laws.routes.base import computing_route, register_route
from restitution.laws.routes.given import served_from, target
from restitution.laws.si_law import SILaw

__all__ = ["ShippedRoute"]


@dataclass(frozen=True)
class ShippedRoute:
    """The shipped laws (module docs)."""

    name: str = "shipped"
    order: float = 100

    def serves(self, request) -> bool:
        return True

    def law(self, request, note, progress: bool) -> SILaw:
        if request.partner_grain is not None:
            if request.export_dir is not None:
                check_output_dir(request.export_dir, "--export")  # as every route: first
            _refuse_uncomputed(request)
        return served_from(request, None)


def _refuse_uncomputed(r) -> None:
    """Two materials without a shipped law: refuse, with the estimate of ``--compute``."""
    law_nu, body, partner = target(r)
    if shipped_match(law_nu, body, partner) is not None:
        return  # a shipped law of these two materials serves it
    p = computing_route("modal").plan(law_nu, body, partner)
    if p.exists:
        how = f"--compute finds the law computed before ({p.path})"
    else:
        how = (
            f"add --compute ({p.collisions} collisions, about "
            f"{budget.format_duration(p.seconds)} on one core)"
        )
    raise InputError(
        f"no law of these two materials is shipped: {how}, or give its file with --law-file"
    )


register_route(ShippedRoute())
