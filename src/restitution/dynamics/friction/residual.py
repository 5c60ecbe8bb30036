"""The residual friction route: one stick/slip state with the dropped modes' static residual,
normal and tangential, Verlet steps (:func:`restitution.dynamics.oblique_residual.
residual_collision`), for the kinds that know their dropped modes' flexibility at the contact
(``BodyKind.oblique_residual``: the sphere); ``law --angle`` extrapolates it to the rigid wall
from ``alpha`` and ``2 alpha`` (:func:`wall_extrapolated`; issue 63).

Units: the dynamics' reduced units (module :mod:`restitution.dynamics.friction.base`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from restitution.dynamics.friction.base import register_friction_route
from restitution.dynamics.oblique_residual import RESIDUAL_CHOICE

__all__ = ["WALL_FIELDS", "Residual", "wall_extrapolated"]

WALL_FIELDS = ("beta", "v_tangential", "spin", "contact_velocity", "friction_work")
"""The results the residual route extrapolates to the rigid wall (:func:`wall_extrapolated`): the
tangential ones. ``epsilon_normal`` is the harder wall's: the route's hats couple the spin to
the normal motion by about 1e-5 (docs/oblique.md), which the extrapolation would triple, and
the normal coefficient's own approach to the rigid wall is the head-on law's, served beside it
and counted in its error."""


def wall_extrapolated(soft, hard):
    """The residual route's results on the walls ``alpha`` (``soft``) and ``2 alpha``
    (``hard``) extrapolated to the rigid wall, ``2 hard - soft`` in each of
    :data:`WALL_FIELDS` (the rest, ``epsilon_normal`` and the energies, are ``hard``'s; the
    energy balance the larger of the two).

    The one-state ``beta`` approaches the rigid wall at order 1 in ``1 / alpha``: the steel
    ball's rigid-sphere residual at 1 m/s, ``alpha delta_max`` = 80, 160, 320, stands 0.154,
    0.080, 0.041 below its quasistatic limit at ``tan(theta)/mu = 0.5`` and 0.035, 0.017, 0.008
    at 1.92 (ratios 0.47-0.52 per doubling), and the extrapolation from 80 and 160 lands 0.006
    and 0.001 from that limit (docs/oblique.md, "A static residual for the one-state
    route")."""
    values = {f: 2.0 * getattr(hard, f) - getattr(soft, f) for f in WALL_FIELDS}
    balance = max(abs(soft.energy_balance), abs(hard.energy_balance))
    return replace(hard, **values, energy_balance=math.copysign(balance, hard.energy_balance))


@dataclass(frozen=True)
class Residual:
    """One stick/slip state on the dropped modes' static residual
    (:func:`~restitution.dynamics.oblique_residual.residual_collision` at its default
    settings)."""

    name: str = RESIDUAL_CHOICE
    help: str = (
        "one stick/slip state with the dropped modes following the contact statically, "
        "normal, tangential and tilting (Dundurs' coupling), which law --angle extrapolates "
        "to the rigid wall; Verlet steps; beta within 2e-3 over 20-80 modes at 1 m/s, "
        "docs/oblique.md"
    )
    order: int = 2
    law_rank: int = 0
    integrator: str = "Verlet"
    every_node: bool = False
    takes_kappa: bool = False
    needs: str = "the dropped modes' static flexibility at the contact"
    law_walls: tuple[float, ...] = (1.0, 2.0)
    law_how: str = (
        "two walls (alpha and 2 alpha) each: planned Verlet steps times one timed force "
        "evaluation times 2.3 (measured 1.91-3.23)"
    )
    law_advice: str = (
        "one mode count with the dropped modes' static residual, extrapolated to the rigid "
        "wall from alpha and 2 alpha (order 1 in 1/alpha), not to N -> infinity: the error is "
        "the change from half the modes and, for beta, the distance from the route's "
        "quasistatic limit with Dundurs' coupling; twice the modes moved the steel ball's "
        "beta by 0.5-0.8 of this error and epsilon_normal by 0-1.2 of its (1 and 5 m/s, "
        "docs/oblique.md)"
    )

    def serves(self, kind) -> bool:
        return kind.oblique_body is not None and bool(kind.oblique_residual)

    def describe(self, kappa: float | None) -> str:
        return (
            "one stick/slip state for the contact, the dropped modes' static residual with "
            "Dundurs' coupling"
        )

    def contact(self, result) -> str:
        return "one state, its stick force carried by the residual's compliance"

    def work(self, body, v_normal, v_tangential, alpha, kappa):
        from restitution.dynamics.oblique_residual import residual_work

        return residual_work(body, v_normal, v_tangential, alpha)

    def plan(self, work) -> str:
        return f"Verlet steps with the dropped modes' residual on {work.nodes} wall nodes"

    def collision(self, body, v_normal, v_tangential, mu, alpha, kappa):
        from restitution.dynamics.oblique_residual import residual_collision

        return residual_collision(body, v_normal, v_tangential, mu, alpha)

    def law_work(self, body, v_normal, v_tangential, alpha, kappa):
        """Both walls' work as one (their seconds summed, the larger memory)."""
        soft, hard = (self.work(body, v_normal, v_tangential, f * alpha, kappa)
                      for f in self.law_walls)  # fmt: skip
        return replace(hard, seconds=float(soft.seconds + hard.seconds),
                       memory_bytes=max(soft.memory_bytes, hard.memory_bytes))  # fmt: skip

    def law_collision(self, body, v_normal, v_tangential, mu, alpha, kappa):
        soft, hard = (self.collision(body, v_normal, v_tangential, mu, f * alpha, kappa)
                      for f in self.law_walls)  # fmt: skip
        return wall_extrapolated(soft, hard)


register_friction_route(Residual())
