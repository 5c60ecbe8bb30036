"""The computing routes, registered with the serving side (:mod:`restitution.laws.routes.base`):
``--compute`` by the modal production settings (:mod:`restitution.laws.making.compute`) and
``--route residual`` by the static residual (:mod:`restitution.laws.making.residual_law`).

Units: the body's reduced units (``nu`` its law's Poisson number); plans in seconds of wall time
on one core.

Importing this module registers both (:mod:`restitution` does, so every call of
:func:`restitution.laws.serve.serve` finds them).
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.laws.making import compute, residual_law
from restitution.laws.routes.base import register_computing_route

__all__ = ["ModalCompute", "ResidualCompute"]


@dataclass(frozen=True)
class ModalCompute:
    """The law by the shipped laws' production settings, collisions of the modal body."""

    name: str = "modal"

    def plan(self, nu, geometry, partner=None, *, reuse=True) -> compute.ComputePlan:
        return compute.plan(nu, geometry, partner, reuse=reuse)

    def check(self, plan, force=False) -> None:
        compute.check_plan(plan, force)

    def compute(self, nu, geometry, partner=None, *, store=None, progress=False, force=False):
        return compute.computed_law(nu, geometry, partner, store=store, progress=progress,
                                    force=force)  # fmt: skip


@dataclass(frozen=True)
class ResidualCompute:
    """The law by the static residual (fewer modes, the rest static)."""

    name: str = "residual"

    def plan(self, nu, geometry, partner=None, *, reuse=True) -> residual_law.ResidualPlan:
        return residual_law.residual_plan(nu, geometry, partner, reuse=reuse)

    def check(self, plan, force=False) -> None:
        residual_law.check_residual_plan(plan, force)

    def compute(self, nu, geometry, partner=None, *, store=None, progress=False, force=False):
        return residual_law.residual_law(nu, geometry, partner, progress=progress, force=force)


register_computing_route(ModalCompute())
register_computing_route(ResidualCompute())
