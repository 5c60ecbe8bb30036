"""The routes of a law file: one the user gives (``--law-file``) and one computed on demand
(``--compute``, by the computing route ``--route`` names), each served as a shipped law is.

Units: SI at the edge.

A computed law's file is made by a computing route (:mod:`restitution.laws.routes.base`,
registered by :mod:`restitution.laws.making.routes`): its plan is stated before it runs. Where a
shipped law serves the material's Poisson number, nothing is computed and the shipped law
answers.
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution.atomic import check_output_dir, check_output_file
from restitution.laws.law_nu import shipped_match
from restitution.laws.routes.base import computing_route, register_route
from restitution.laws.si_law import SILaw, law_target, si_law

__all__ = ["ComputedRoute", "LawFileRoute", "served_from", "target"]


def target(request) -> tuple:
    """``(law nu, kind's geometry, Partner or None)`` of the law ``request`` asks for
    (:func:`restitution.laws.si_law.law_target`)."""
    r = request
    return law_target(r.E, r.nu, r.rho, r.shape, r.against, r.radius_ratio, r.partner_grain)


def served_from(r, path) -> SILaw:
    """The SI law of request ``r`` from the law file ``path`` (``None``: the shipped laws),
    after the export folder is checked (before anything is computed)."""
    if r.export_dir is not None:
        check_output_dir(r.export_dir, "--export")
    return si_law(r.E, r.nu, r.rho, r.shape, r.against, path=path,
                  radius_ratio=r.radius_ratio, partner_grain=r.partner_grain)  # fmt: skip


@dataclass(frozen=True)
class LawFileRoute:
    """The law file the user gives (``--law-file``)."""

    name: str = "law-file"
    order: float = 20

    def serves(self, request) -> bool:
        return request.law_file is not None and not request.compute

    def law(self, request, note, progress: bool) -> SILaw:
        return served_from(request, request.law_file)


@dataclass(frozen=True)
class ComputedRoute:
    """The law of the material's exact Poisson number, computed now or found in the cache
    (``--compute``; the modal production settings or ``--route residual``)."""

    name: str = "computed"
    order: float = 30

    def serves(self, request) -> bool:
        return bool(request.compute)

    def law(self, request, note, progress: bool) -> SILaw:
        r = request
        if r.export_dir is not None:
            check_output_dir(r.export_dir, "--export")  # before anything is computed
        law_nu, body, partner = target(r)
        if shipped_match(law_nu, body, partner) is not None:
            note(f"note: a shipped law serves nu = {law_nu:.6g}; nothing to compute")
            return served_from(r, None)
        route = computing_route(r.route or "modal")
        if r.store is not None and route.name == "modal":
            check_output_file(r.store, "--store")
        plan = route.plan(law_nu, body, partner)
        route.check(plan, r.force)
        note(f"note: {plan.words()}")
        path = route.compute(law_nu, body, partner, store=r.store, progress=progress,
                             force=r.force)  # fmt: skip
        return served_from(r, path)


register_route(LawFileRoute())
register_route(ComputedRoute())
