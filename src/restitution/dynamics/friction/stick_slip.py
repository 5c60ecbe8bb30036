"""The default friction route: one stick/slip state for the whole contact, the exact switch,
DOP853 phase by phase (:func:`restitution.dynamics.oblique.oblique_collision`; issue 63).

Units: the dynamics' reduced units (module :mod:`restitution.dynamics.friction.base`).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.dynamics.friction.base import OneWallLaw, register_friction_route
from restitution.dynamics.oblique import FRICTION_MODELS

__all__ = ["STICK_SLIP", "StickSlip"]

STICK_SLIP = FRICTION_MODELS[0]
"""The route's name (``"stick-slip"``)."""


@dataclass(frozen=True)
class StickSlip(OneWallLaw):
    """One stick/slip state for the contact (:func:`~restitution.dynamics.oblique.
    oblique_collision` at its defaults, ``rtol = 1e-10``)."""

    name: str = STICK_SLIP
    help: str = "one stick/slip state for the whole contact, DOP853 phase by phase"
    order: int = 0
    law_rank: int = 1
    integrator: str = "DOP853"
    every_node: bool = False
    takes_kappa: bool = False
    needs: str = ""
    law_how: str = (
        "measured on softer walls, alpha <= 1000-4000; on the harder walls of slow impacts "
        "it overestimates: steel at 1 m/s took a fifth to a half of it, docs/oblique.md"
    )

    def serves(self, kind) -> bool:
        return kind.oblique_body is not None

    def describe(self, kappa: float | None) -> str:
        return "one stick/slip state for the contact"

    def contact(self, result) -> str:
        phases = ", ".join(f"{name} at {t:.4g}" for name, t in result.phases[:6])
        more = f" and {len(result.phases) - 6} more" if len(result.phases) > 6 else ""
        return f"{len(result.phases)} phases ({phases}{more}; R/c)"

    def work(self, body, v_normal, v_tangential, alpha, kappa):
        from restitution.dynamics.oblique_cost import oblique_work

        return oblique_work(body, v_normal, alpha)

    def plan(self, work) -> str:
        return f"DOP853 phase by phase on {work.nodes} nodes"

    def collision(self, body, v_normal, v_tangential, mu, alpha, kappa):
        from restitution.dynamics.oblique import oblique_collision

        return oblique_collision(body, v_normal, v_tangential, mu, alpha)


register_friction_route(StickSlip())
