"""epsilon of a sphere on an elastic wall from the finite elements alone: the mesh limit
``h -> 0``, the hard contact ``alpha -> inf`` and the block's size.

Units: the ball's, ``E = rho = R = 1`` of its three-dimensional constants; ``v`` in
``c = sqrt(E / rho)``, ``alpha`` in ``1/R``, wall times in seconds.

The two limits are those of the ball on a rigid wall and of two balls (the same code,
:func:`restitution.fem.limits._assemble` of the grid): at every ``alpha`` the loss ``1 - eps^2``
of three mesh levels (ball and block refined together) goes to ``h -> 0`` by Richardson, then
``alpha -> inf`` linearly in ``1/alpha``; the other order is the check. The walls are
``alpha = P / delta(v)`` with the sphere's products ``P`` (80, 160, 320,
:func:`restitution.limits.defaults.default_products`) and Hertz's compression of the ball on the
wall (:func:`restitution.fem.wall_impact.wall_scales`).

The levels are contact levels (:mod:`restitution.fem.wall_impact`): they halve the contact
size of both bodies and keep the bulk. Two more runs on the coarsest level at the hardest wall
measure what the fixed parts leave, and each difference from the same run of the grid is added
in quadrature to the limits' error:

* **size**: the block twice as large (:data:`restitution.fem.wall_impact.BLOCK_SIZE` doubled);
  a reflection that reached the ball before it left would show here;
* **bulk**: both bodies' bulk sizes and growth halved (``bulk = 0.5``).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.wall import HalfSpace
from restitution.estimate import Estimate, estimate_of
from restitution.fem.elasticity import as_material
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.impact import FemCollisionError, FemSettings
from restitution.fem.limits import LEVELS, FemEpsilon, FemRun, _assemble
from restitution.fem.wall_impact import BLOCK_SIZE, fem_collide_wall, wall_scales
from restitution.jsonable import finite_or_none
from restitution.laws.partners.base import WALL_KEY
from restitution.limits.defaults import default_products

__all__ = ["FemWallEpsilon", "WallCheck", "fem_wall_epsilon"]


@dataclass(frozen=True)
class WallCheck:
    """One check of the fixed parts of the grid: its run and its loss minus the same grid
    run's.

    Attributes
    ----------
    name : str
        ``"size"`` (the block doubled) or ``"bulk"`` (the bulk sizes halved).
    run : FemRun
    difference : float
    """

    name: str
    run: FemRun
    difference: float

    def to_dict(self) -> dict:
        return {"name": self.name, "run": self.run.to_dict(),
                "difference": finite_or_none(self.difference)}  # fmt: skip


@dataclass(frozen=True, eq=False)
class FemWallEpsilon:
    """epsilon of a sphere on a meshed wall at one speed, with its grid, fits and checks.

    Attributes
    ----------
    wall : HalfSpace
        The wall (a :class:`~restitution.bodies.wall.Plate` for a plate).
    limits : FemEpsilon
        Both limits of the grid (contact levels, walls); its error holds neither check.
    size : float
        The block's radius (and a half-space's depth) in ``c_L t_c``.
    checks : tuple of WallCheck
        The block's size and the bulk (module docs).
    """

    wall: HalfSpace
    limits: FemEpsilon
    size: float
    checks: tuple[WallCheck, ...]

    nu = property(lambda self: self.limits.nu, doc="The ball's Poisson number.")
    v = property(lambda self: self.limits.v, doc="Approach speed, ``c``.")

    @property
    def energy_loss(self) -> float:
        """``1 - epsilon^2`` of both limits."""
        return self.limits.energy_loss

    @property
    def energy_loss_err(self) -> float:
        """The limits' error and the checks' differences, in quadrature."""
        return math.hypot(self.limits.energy_loss_err, *(c.difference for c in self.checks))

    @property
    def epsilon(self) -> float:
        return math.sqrt(1.0 - self.energy_loss)

    @property
    def epsilon_err(self) -> float:
        return self.energy_loss_err / (2.0 * self.epsilon)

    @property
    def asymptotic_ok(self) -> bool:
        return self.limits.asymptotic_ok and all(math.isfinite(c.difference) for c in self.checks)

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`
        (a check that did not run flags it)."""
        failed = [f"the {c.name} check did not run" for c in self.checks
                  if not math.isfinite(c.difference)]  # fmt: skip
        why = "; ".join(filter(None, [self.limits.message, *failed]))
        return estimate_of(self.epsilon, self.epsilon_err, self.asymptotic_ok, why)

    def to_dict(self) -> dict:
        """JSON-ready: the limits' dictionary with the wall, the block and the checks."""
        d = self.limits.to_dict()
        d["geometry"] = f"{self.limits.geometry}-on-{self.wall.to_dict()['kind']}"
        d[WALL_KEY] = self.wall.to_dict()
        d["limits_energy_loss_err"] = d["energy_loss_err"]
        d["energy_loss_err"] = finite_or_none(self.energy_loss_err)
        d["epsilon"] = finite_or_none(self.epsilon)
        d["epsilon_err"] = finite_or_none(self.epsilon_err)
        d["epsilon_meaning"] = (
            "the ball's speed after over before in the frame where the wall was at rest"
        )
        d["asymptotic_ok"] = bool(self.asymptotic_ok)
        d["block"] = {
            "size": self.size,
            "size_units": "c_L t_c (the wall's compressional speed, the contact time)",
        }
        d["levels_meaning"] = "contact levels: each halves both bodies' contact size only"
        d["checks"] = [c.to_dict() for c in self.checks]
        return d


def _one_run(nu, wall, v, alpha, level, grading, base, **mesh) -> FemRun:
    """One run as a :class:`FemRun` (``n_dofs`` of ball and block together, ``h_contact`` the
    contact size); ``mesh`` the block's ``size`` and ``bulk``."""
    start = time.perf_counter()
    try:
        r = fem_collide_wall(nu, wall, v, alpha, level=level, grading=grading, settings=base,
                             **mesh)  # fmt: skip
    except FemCollisionError as exc:
        nan = float("nan")
        return FemRun(alpha, level, 0, nan, nan, nan, 0, nan, time.perf_counter() - start,
                      str(exc))  # fmt: skip
    return FemRun(
        alpha=alpha,
        level=level,
        n_dofs=sum(r.n_dofs),
        h_contact=grading.contact_fraction * wall_scales(nu, wall, v).half_width / 2**level,
        epsilon=r.epsilon,
        energy_drift=r.energy_drift,
        n_steps=r.n_steps,
        dt=r.dt,
        wall_time_s=time.perf_counter() - start,
    )


def fem_wall_epsilon(
    nu: float,
    wall: HalfSpace,
    v: float,
    *,
    products: Sequence[float] | None = None,
    levels: Sequence[int] = LEVELS,
    size: float = BLOCK_SIZE,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
    on_run: Callable[[FemRun], None] | None = None,
) -> FemWallEpsilon:
    """epsilon of a sphere of Poisson number ``nu`` striking ``wall`` at ``v`` (``c``), from
    the FEM's limits and checks (module docs).

    Parameters
    ----------
    products : sequence of float, optional
        ``alpha * delta(v)`` of the walls (default the sphere's 80, 160, 320).
    levels : sequence of int
        Contact levels, ascending and consecutive.
    size : float
        The block's radius (a half-space's depth too) in ``c_L t_c``.
    on_run : callable, optional
        Called with each finished :class:`FemRun`.
    """
    material = as_material(float(nu), SPHERE.geometry)
    grading = grading or default_grading(SPHERE.geometry)
    levels = tuple(int(k) for k in levels)
    v = float(v)
    delta = wall_scales(material.nu, wall, v).compression
    products = tuple(sorted(float(p) for p in (products or default_products(SPHERE.geometry))))
    alphas = tuple(p / delta for p in products)
    start = time.perf_counter()
    runs = []

    def one(alpha, level, **mesh) -> FemRun:
        run = _one_run(material.nu, wall, v, alpha, level, grading, base, **{"size": size, **mesh})
        if on_run is not None:
            on_run(run)
        return run

    for a in alphas:
        for k in levels:
            runs.append(one(a, k))
    same = next(r for r in runs if r.alpha == alphas[-1] and r.level == levels[0])
    checks = []
    for name, mesh in (("size", {"size": 2.0 * size}), ("bulk", {"bulk": 0.5})):
        run = one(alphas[-1], levels[0], **mesh)
        checks.append(WallCheck(name, run, run.energy_loss - same.energy_loss))
    limits = _assemble(material, v, None, runs, levels, grading, time.perf_counter() - start,
                       SPHERE.geometry)  # fmt: skip
    return FemWallEpsilon(wall=wall, limits=limits, size=float(size), checks=tuple(checks))
