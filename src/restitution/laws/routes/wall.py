"""The route of a grain on an elastic wall: a half-space (the ball's vibrations and Lamb's waves
radiated into the wall) or a plate (Zener's thin-plate model).

Units: SI at the edge; the wall's law in the grain's reduced units (``c``).

At the asked speeds each speed is computed now (:func:`restitution.laws.route_law.wall_law`,
seconds); for exports or constants, which need the law at every speed, on a grid of speeds
(:func:`restitution.laws.wall_grid.wall_grid_law`), whose time is stated first.
"""

from __future__ import annotations

from dataclasses import dataclass

from restitution import budget
from restitution.atomic import check_output_dir
from restitution.errors import InputError
from restitution.laws.route_law import wall_law
from restitution.laws.routes.base import register_route
from restitution.laws.si_law import SILaw
from restitution.laws.wall_grid import grid_seconds, wall_grid_law

__all__ = ["ElasticWallRoute"]


@dataclass(frozen=True)
class ElasticWallRoute:
    """A grain on an elastic wall (module docs)."""

    name: str = "elastic-wall"
    order: float = 10

    def serves(self, request) -> bool:
        return request.elastic_wall is not None

    def law(self, request, note, progress: bool) -> SILaw:
        r = request
        grain, wall = r.grain, r.elastic_wall
        if r.export_dir is not None or r.constants:
            return self._grid(r, note, progress)
        what = ("Zener's thin-plate model" if r.wall_thickness is not None
                else "the ball's vibrations and the waves radiated into the wall")  # fmt: skip
        note(f"note: an elastic wall: each speed is computed now ({what}; seconds)")
        vs = [float(grain.v_over_c(w, r.against)) for w in (*r.speeds, *r.measured_speeds)]
        return SILaw(grain, r.against, wall_law(grain.law_nu, wall, vs))

    def table(self, request, note, progress: bool) -> SILaw:
        """The law at every speed of its range (``si_law(..., wall_E=...)``, exports): on a
        grid of speeds (:func:`restitution.laws.wall_grid.wall_grid_law`)."""
        return self._grid(request, note, progress)

    @staticmethod
    def _grid(r, note, progress: bool) -> SILaw:
        """The law on a grid of speeds, served at every speed of its range."""
        if r.plastic:
            raise InputError(
                "plastic flow with an elastic wall is answered at the asked speeds only; leave "
                "out --export and --reference-speed/--maxwell-temperature"
            )
        grain, wall = r.grain, r.elastic_wall
        seconds = grid_seconds(grain.law_nu, wall)  # refuses a plate without a range first
        if r.export_dir is not None:
            check_output_dir(r.export_dir, "--export")  # before anything is computed
        what = ("exports" if r.export_dir is not None
                else "constant" if r.constants else "law at every speed")  # fmt: skip
        note(f"note: an elastic wall: its law on a grid of speeds for the {what} is computed now "
             f"(about {budget.format_duration(seconds)})")  # fmt: skip
        return SILaw(grain, r.against, wall_grid_law(grain.law_nu, wall, progress=progress))


register_route(ElasticWallRoute())
