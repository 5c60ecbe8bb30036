"""epsilon at one speed from the FEM alone: mesh limit ``h -> 0`` and hard wall ``alpha -> inf``.

Units: ``E = rho = R = 1``; ``v`` in ``c`` (speed towards the wall), ``alpha`` in ``1/R``, wall
times in seconds.

The FEM route has no modal truncation; its two limits are

1. ``h -> 0`` at every ``alpha``: three contact-graded meshes (:mod:`restitution.fem.graded`,
   levels ``0, 1, 2``, each halving all element sizes) and a Richardson extrapolation of the
   energy loss ``1 - eps^2`` (:func:`restitution.fem.richardson.richardson_limit`);
2. ``alpha -> infinity`` of those limits, linear in ``1/alpha``, with the package's
   extrapolation (:func:`restitution.limits.extrapolation.extrapolate_alpha`, errors propagated).

The ``alpha`` are those of the modal sweeps (:func:`restitution.limits.defaults.default_products`:
``alpha * delta_max(v) = 40, 80, 160`` with ``delta_max = v sqrt(ln(4/v))`` for the disk,
``80, 160, 320`` with Hertz's ``(15 m v^2 / (16 E*))^(2/5)`` for the sphere), so both routes
extrapolate from the same walls. As a check the other order is taken too (``alpha -> inf`` at
every level, then Richardson); the error is the larger of the two orders' errors combined in
quadrature with their difference, as in :func:`restitution.limits.extrapolation.combined_limit`.
``geometry="sphere"`` takes both limits for the sphere (:mod:`restitution.fem.section`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from restitution._version import __version__
from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.errors import InputError
from restitution.estimate import Estimate, estimate_of
from restitution.fem.elasticity import as_material
from restitution.fem.graded import (
    ContactGrading,
    default_grading,
    graded_settings,
    mesh_summary,
)
from restitution.fem.impact import FemCollisionError, FemSettings, fem_collide, model_for
from restitution.fem.richardson import MeshLimit, richardson_limit
from restitution.jsonable import finite_or_none
from restitution.limits.defaults import (
    ALPHA_SCALE,
    check_alpha_scale,
    check_alphas,
    check_distinct,
    default_products,
    walls_at,
)
from restitution.limits.extrapolation import (
    FromLoss,
    LinearLimit,
    epsilon_from_loss,
    extrapolate_alpha,
)

__all__ = ["LEVELS", "FemEpsilon", "FemGrid", "FemRun", "fem_epsilon", "grid_of"]

LEVELS = (0, 1, 2)
"""Mesh levels of the convergence study (each halves all element sizes)."""


@dataclass(frozen=True)
class FemGrid:
    """The grid of finite-element runs behind one epsilon: walls, mesh levels and run settings.

    Attributes
    ----------
    alphas : tuple of float or None
        Wall hardness values for ``alpha -> inf``, read by ``alpha_scale``; ``None``: the
        modal sweeps' products of the body
        (:func:`restitution.limits.defaults.default_products`).
    alpha_scale : {"absolute", "compression"} or None
        ``"compression"``: ``alphas`` are products ``alpha * delta_max(v)``; ``None``: the
        modal sweeps' default (:data:`restitution.limits.defaults.ALPHA_SCALE`).
    levels : tuple of int
        Mesh levels, ascending and consecutive (the Richardson ratio is 2 per level).
    grading : ContactGrading or None
        The mesh's grading towards the contact; ``None``: the body's default
        (:func:`restitution.fem.graded.default_grading`).
    base : FemSettings or None
        Integrator settings of every run.
    """

    alphas: tuple[float, ...] | None = None
    alpha_scale: str | None = None
    levels: tuple[int, ...] = LEVELS
    grading: object | None = None
    base: object | None = None

    def __post_init__(self) -> None:
        if self.alphas is not None:
            object.__setattr__(self, "alphas", tuple(float(a) for a in self.alphas))
        levels = tuple(int(k) for k in self.levels)
        if len(levels) < 2 or any(b - a != 1 for a, b in zip(levels, levels[1:], strict=False)):
            raise InputError(f"levels must be at least two consecutive integers, got {levels}")
        object.__setattr__(self, "levels", levels)


def grid_of(grid: FemGrid | None = None, **loose) -> FemGrid:
    """A :class:`FemGrid`, or one made of the loose keywords ``alphas``, ``alpha_scale``,
    ``levels``, ``grading``, ``base`` (the older spelling; not both)."""
    given = {k: v for k, v in loose.items() if v is not None}
    if grid is None:
        return FemGrid(**given)
    if not isinstance(grid, FemGrid):
        raise InputError(f"grid must be a FemGrid, got {type(grid).__name__}")
    if given:
        raise InputError(f"give grid= or {', '.join(sorted(given))}, not both")
    return grid


@dataclass(frozen=True)
class FemRun:
    """One FEM collision of the grid.

    Attributes
    ----------
    alpha : float
        Wall hardness, ``1/R``.
    level : int
        Mesh level.
    n_dofs : int
        Degrees of freedom of the half disk.
    h_contact : float
        Longest arc facet within the Hertz half-width of ``(R, 0)``, ``R``.
    epsilon : float
        ``nan`` when the run failed (``message`` says why).
    energy_drift : float
        Largest relative energy error of the run.
    n_steps : int
    dt : float
        Time step, ``R / c``.
    wall_time_s : float
        Seconds, mesh and matrices included.
    message : str
    """

    alpha: float
    level: int
    n_dofs: int
    h_contact: float
    epsilon: float
    energy_drift: float
    n_steps: int
    dt: float
    wall_time_s: float
    message: str = ""

    @property
    def energy_loss(self) -> float:
        """``1 - epsilon^2``."""
        return 1.0 - self.epsilon**2

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        d = dict(self.__dict__)
        d["epsilon"] = finite_or_none(self.epsilon)
        return d


@dataclass(frozen=True, eq=False)
class FemEpsilon(FromLoss):
    """epsilon at one speed from the FEM route, with the grid and fits behind it.

    Attributes
    ----------
    nu, v : float
        Poisson number (the body's own) and speed towards the wall (``c``).
    alpha : float or None
        The fixed wall hardness (``1/R``) when only ``h -> 0`` was taken; ``None`` for both.
    energy_loss, energy_loss_err : float
        The limit of ``1 - epsilon^2`` and its error; :attr:`epsilon`, :attr:`epsilon_err` and
        :attr:`estimate` derive from them.
    asymptotic_ok : bool
    message : str
    runs : tuple of FemRun
        The grid, ordered by ``alpha`` then level.
    mesh_limits : tuple of MeshLimit
        ``h -> 0`` at each ``alpha``.
    alpha_limit : LinearLimit or None
        ``alpha -> inf`` of the mesh limits (``None`` with a fixed ``alpha``).
    check_alpha_limits : tuple of LinearLimit
        The other order: ``alpha -> inf`` at each level.
    check_mesh_limit : MeshLimit or None
        ... then ``h -> 0``.
    order_difference : float
        Loss of the primary order minus the check order (``nan`` with a fixed ``alpha``).
    grading : ContactGrading
    levels : tuple of int
    wall_time_s : float
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
    """

    nu: float
    v: float
    alpha: float | None
    energy_loss: float
    energy_loss_err: float
    asymptotic_ok: bool
    message: str
    runs: tuple[FemRun, ...]
    mesh_limits: tuple[MeshLimit, ...]
    alpha_limit: LinearLimit | None
    check_alpha_limits: tuple[LinearLimit, ...]
    check_mesh_limit: MeshLimit | None
    order_difference: float
    grading: ContactGrading
    levels: tuple[int, ...]
    wall_time_s: float
    geometry: str = DEFAULT_GEOMETRY

    @property
    def alphas(self) -> tuple[float, ...]:
        """The wall hardness values of the grid, ``1/R``."""
        return tuple(sorted({r.alpha for r in self.runs}))

    def summary(self) -> str:
        """Three lines for the terminal: epsilon, energy loss, grid."""
        limits = "h -> 0" if self.alpha is not None else "alpha -> inf and h -> 0"
        where = f" at alpha = {self.alpha:g}" if self.alpha is not None else ""
        dofs = sorted({r.n_dofs for r in self.runs})
        lines = [
            f"epsilon = {self.epsilon:.6f} +- {self.epsilon_err:.6f}   ({self._body}nu = "
            f"{self.nu:g}, v = {self.v:g} c towards the wall; FEM, {limits}{where})",
            f"energy loss 1 - epsilon^2 = {self.energy_loss:.6f} +- {self.energy_loss_err:.6f}",
            f"grid: alpha = {', '.join(f'{a:g}' for a in self.alphas)}; mesh levels "
            f"{', '.join(str(k) for k in self.levels)} ({dofs[0]}-{dofs[-1]} dofs, "
            f"{self.wall_time_s:.0f} s)",
        ]
        if not self.asymptotic_ok:
            lines.append(f"warning: not asymptotic: {self.message}")
        return "\n".join(lines)

    @property
    def _body(self) -> str:
        """``"sphere, "`` for a sphere; nothing for the disk (the default body)."""
        return "" if self.geometry == DEFAULT_GEOMETRY else f"{self.geometry}, "

    def to_dict(self) -> dict:
        """JSON-ready dictionary with the keys of the modal route's
        :meth:`restitution.laws.law.PointEpsilon.to_dict` (``grid`` and ``fits`` hold the FEM's
        levels and fits in place of mode counts)."""
        alphas = self.alphas
        table = {(r.alpha, r.level): r for r in self.runs}

        def cell(a: float, k: int, name: str):
            r = table.get((a, k))
            value = None if r is None else getattr(r, name)
            return value if value is None or math.isfinite(value) else None

        return {
            "geometry": self.geometry,
            "nu": self.nu,
            "v": self.v,
            "v_units": f"c (speed of the {self.geometry} towards the wall)",
            "alpha": self.alpha,
            "limits": ["h"] if self.alpha is not None else ["alpha", "h"],
            "epsilon": finite_or_none(self.epsilon),
            "epsilon_err": finite_or_none(self.epsilon_err),
            "energy_loss": finite_or_none(self.energy_loss),
            "energy_loss_err": finite_or_none(self.energy_loss_err),
            "asymptotic_ok": bool(self.asymptotic_ok),
            "message": self.message,
            "grid": {
                "alpha": list(alphas),
                "levels": list(self.levels),
                "energy_loss": [[cell(a, k, "energy_loss") for k in self.levels] for a in alphas],
                "n_dofs": [[cell(a, k, "n_dofs") for k in self.levels] for a in alphas],
                "h_contact": [[cell(a, k, "h_contact") for k in self.levels] for a in alphas],
                "runs": [r.to_dict() for r in self.runs],
            },
            "fits": {
                "h": [m.to_dict() for m in self.mesh_limits],
                "alpha": self.alpha_limit.to_dict() if self.alpha_limit else None,
                "check_alpha": [f.to_dict() for f in self.check_alpha_limits],
                "check_h": self.check_mesh_limit.to_dict() if self.check_mesh_limit else None,
                "order_difference": finite_or_none(self.order_difference),
            },
            "failed_points": [
                {"alpha": r.alpha, "level": r.level, "message": r.message}
                for r in self.runs
                if not math.isfinite(r.epsilon)
            ],
            "settings": {
                "method": "fem",
                "levels": list(self.levels),
                "grading": self.grading.to_dict(),
                "alphas": list(alphas),
                "wall_time_s": self.wall_time_s,
            },
            "version": __version__,
        }

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return estimate_of(self.epsilon, self.epsilon_err, self.asymptotic_ok, self.message)


def _one_run(
    material: Material,
    v: float,
    alpha: float,
    level: int,
    settings: FemSettings,
    geometry: str = DEFAULT_GEOMETRY,
) -> FemRun:
    start = time.perf_counter()
    summary = mesh_summary(model_for(material, v, alpha, settings, geometry), v)
    try:
        r = fem_collide(material, v, alpha, geometry=geometry, settings=settings)
    except FemCollisionError as exc:
        return FemRun(
            alpha, level, summary.n_dofs, summary.h_contact, float("nan"), float("nan"), 0,
            float("nan"), time.perf_counter() - start, str(exc),
        )  # fmt: skip
    return FemRun(
        alpha=alpha,
        level=level,
        n_dofs=summary.n_dofs,
        h_contact=summary.h_contact,
        epsilon=r.epsilon,
        energy_drift=r.energy_drift,
        n_steps=r.n_steps,
        dt=r.dt,
        wall_time_s=time.perf_counter() - start,
    )


def fem_epsilon(
    material_or_nu: Material | float,
    v: float,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    alpha: float | None = None,
    grid: FemGrid | None = None,
    on_run: Callable[[FemRun], None] | None = None,
    alphas: Sequence[float] | None = None,
    alpha_scale: str | None = None,
    levels: Sequence[int] | None = None,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
) -> FemEpsilon:
    """epsilon at speed ``v`` from the FEM alone, extrapolated to ``h -> 0`` and ``alpha -> inf``.

    Parameters
    ----------
    material_or_nu : Material or float
        The body's material or its Poisson number (two-dimensional for the disk,
        three-dimensional for the sphere).
    v : float
        Speed towards the wall before the collision, ``c``.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body (:mod:`restitution.fem.section`).
    alpha : float, optional
        Only take ``h -> 0`` at this wall hardness (``1/R``).
    grid : FemGrid, optional
        The walls, mesh levels and run settings (:class:`FemGrid`); the five keywords below
        are its older spelling.
    alphas : sequence of float, optional
        Wall hardness values for ``alpha -> inf``, read by ``alpha_scale``; default the modal
        sweeps' products ``alpha * delta_max(v)`` of the body
        (:func:`restitution.limits.defaults.default_products`; ``delta_max`` its quasistatic
        compression, :func:`restitution.limits.defaults.walls_at`).
    alpha_scale : {"absolute", "compression"}, optional
        ``"compression"``: ``alphas`` are products ``alpha * delta_max(v)``; default as
        :data:`restitution.limits.defaults.ALPHA_SCALE` (the modal sweeps' default).
    levels : sequence of int
        Mesh levels, ascending and consecutive (the Richardson ratio is 2 per level; default
        :data:`LEVELS`).
    grading : ContactGrading, optional
        Default :func:`restitution.fem.graded.default_grading` of the ``geometry``.
    base : FemSettings, optional
        Integrator settings of every run.
    on_run : callable, optional
        Called with each finished :class:`FemRun` (progress reports).

    Returns
    -------
    FemEpsilon
        Failed runs are kept (``epsilon = nan``, with their message) and flag the result.
    """
    grid = grid_of(grid, alphas=alphas, alpha_scale=alpha_scale, levels=levels,
                   grading=grading, base=base)  # fmt: skip
    material = as_material(material_or_nu, geometry)
    v = float(v)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    levels, alphas, alpha_scale, base = grid.levels, grid.alphas, grid.alpha_scale, grid.base
    grading = grid.grading or default_grading(geometry)
    if alpha is not None:
        if not (alpha > 0 and math.isfinite(alpha)):
            raise InputError(f"the wall hardness alpha must be positive (1/R), got {alpha}")
        alpha_values = (float(alpha),)
    else:
        scale = alpha_scale or ALPHA_SCALE
        products = tuple(float(a) for a in (alphas or default_products(geometry)))
        check_distinct("alphas", products)
        check_alphas(products)
        check_alpha_scale(scale)
        alpha_values = tuple(
            sorted(walls_at(v, products, scale, geometry=geometry, nu=material.nu))
        )
    start = time.perf_counter()
    runs = []
    for a in alpha_values:
        for k in levels:
            settings = graded_settings(v, a, k, grading, base, geometry=geometry, nu=material.nu)
            run = _one_run(material, v, a, k, settings, geometry)
            runs.append(run)
            if on_run is not None:
                on_run(run)
    wall = time.perf_counter() - start
    return _assemble(material, v, alpha, runs, levels, grading, wall, geometry)


def _assemble(
    material, v, alpha, runs, levels, grading, wall, geometry=DEFAULT_GEOMETRY
) -> FemEpsilon:
    """Both limits from the grid of runs."""
    alpha_values = sorted({r.alpha for r in runs})
    loss = np.array(
        [[next(r for r in runs if r.alpha == a and r.level == k).energy_loss for k in levels]
         for a in alpha_values]
    )  # fmt: skip
    problems = []
    failed = [r for r in runs if not math.isfinite(r.epsilon)]
    if failed:
        problems.append(f"{len(failed)} run(s) failed: {failed[0].message}")
    mesh_limits = []
    for a, row in zip(alpha_values, loss, strict=True):
        # The finest consecutive finite levels: Richardson needs the ratio 2 between them.
        bad = np.nonzero(~np.isfinite(row))[0]
        good = row[bad[-1] + 1 :] if bad.size else row
        if good.size < 2:
            mesh_limits.append(None)
            continue
        fit = richardson_limit(good)
        mesh_limits.append(fit)
        if not fit.asymptotic_ok:
            problems.append(f"h -> 0 at alpha = {a:g}: {fit.message}")
    kept = [(a, m) for a, m in zip(alpha_values, mesh_limits, strict=True) if m is not None]
    nan = float("nan")
    alpha_limit, checks, check_mesh, difference = None, (), None, nan
    if not kept:
        loss_value, loss_err = nan, nan
    elif alpha is not None:
        loss_value, loss_err = kept[0][1].limit, kept[0][1].limit_err
    else:
        alpha_limit = extrapolate_alpha(
            [a for a, _ in kept],
            [m.limit for _, m in kept],
            loss_err=[m.limit_err for _, m in kept],
        )
        if not alpha_limit.asymptotic_ok:
            problems.append(f"alpha -> inf: {alpha_limit.message}")
        checks = tuple(extrapolate_alpha(alpha_values, col) for col in loss.T)
        check_values = [c.limit for c in checks]
        if len(check_values) >= 2 and all(math.isfinite(c) for c in check_values):
            check_mesh = richardson_limit(check_values)
            difference = alpha_limit.limit - check_mesh.limit
            # The check's own error: the finest level's alpha fit and the Richardson step.
            err_check = math.hypot(checks[-1].limit_err, check_mesh.limit_err)
            loss_err = math.sqrt(max(alpha_limit.limit_err, err_check) ** 2 + difference**2)
        else:
            loss_err = alpha_limit.limit_err
        loss_value = alpha_limit.limit
    if not math.isfinite(epsilon_from_loss(loss_value, loss_err)[0]):
        problems.append(f"energy loss {loss_value:.4g} is outside [0, 1)")
    return FemEpsilon(
        nu=material.nu,
        v=v,
        alpha=None if alpha is None else float(alpha),
        energy_loss=loss_value,
        energy_loss_err=loss_err,
        asymptotic_ok=not problems,
        message="; ".join(problems),
        runs=tuple(runs),
        mesh_limits=tuple(m for m in mesh_limits if m is not None),
        alpha_limit=alpha_limit,
        check_alpha_limits=checks,
        check_mesh_limit=check_mesh,
        order_difference=difference,
        grading=grading,
        levels=levels,
        wall_time_s=wall,
        geometry=geometry,
    )
