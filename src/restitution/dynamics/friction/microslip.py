"""The microslip friction route: Coulomb's law at every wall node, regularised by ``kappa``,
Verlet steps (:func:`restitution.dynamics.oblique_microslip.microslip_collision`; issue 63).

Units: the dynamics' reduced units (module :mod:`restitution.dynamics.friction.base`).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.dynamics.friction.base import OneWallLaw, register_friction_route
from restitution.dynamics.oblique_microslip import MICROSLIP, MicroslipSettings

__all__ = ["Microslip"]


@dataclass(frozen=True)
class Microslip(OneWallLaw):
    """Friction at every wall node (:func:`~restitution.dynamics.oblique_microslip.
    microslip_collision` with :class:`~restitution.dynamics.oblique_microslip.
    MicroslipSettings` of the given ``kappa``)."""

    name: str = MICROSLIP
    help: str = (
        "Coulomb's law at every wall node, Mindlin's annulus of microslip, regularised by "
        "--kappa; Verlet steps; closer to the finite elements in partial slip"
    )
    order: int = 1
    law_rank: int = 2
    integrator: str = "Verlet"
    every_node: bool = True
    takes_kappa: bool = True
    needs: str = ""
    law_how: str = "planned Verlet steps times one timed step; measured runs took 0.88-4.8 times it"

    def serves(self, kind) -> bool:
        return kind.oblique_body is not None

    def describe(self, kappa: float | None) -> str:
        return f"microslip at every wall node, kappa = {_kappa(kappa):g}"

    def contact(self, result) -> str:
        return "each wall node sticks or slips on its own"

    def work(self, body, v_normal, v_tangential, alpha, kappa):
        from restitution.dynamics.oblique_microslip import microslip_work

        return microslip_work(body, v_normal, v_tangential, alpha, settings=_settings(kappa))

    def plan(self, work) -> str:
        return f"Verlet steps with friction at each of {work.nodes} wall nodes"

    def collision(self, body, v_normal, v_tangential, mu, alpha, kappa):
        from restitution.dynamics.oblique_microslip import microslip_collision

        return microslip_collision(body, v_normal, v_tangential, mu, alpha,
                                   settings=_settings(kappa))  # fmt: skip


def _kappa(kappa: float | None) -> float:
    return MicroslipSettings().kappa if kappa is None else kappa


def _settings(kappa: float | None) -> MicroslipSettings:
    return MicroslipSettings(kappa=_kappa(kappa))


register_friction_route(Microslip())
