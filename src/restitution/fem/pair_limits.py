"""epsilon of two disks (or spheres) from the FEM alone: mesh limit ``h -> 0`` and hard contact
``alpha -> inf``.

Units: the first body's, ``E1 = rho1 = R1 = 1``; ``w`` (relative normal speed of the centres)
in ``c1``, ``alpha`` in ``1/R1``, wall times in seconds.

The two limits of the disk on the wall (:mod:`restitution.fem.limits`), taken on the pair's
collisions (:func:`restitution.fem.pair_impact.fem_collide_pair`): at every ``alpha`` the energy
loss ``1 - eps^2`` of three mesh levels (both disks' meshes refined together) goes to ``h -> 0``
by Richardson, then ``alpha -> infinity`` linearly in ``1/alpha``; the other order is the check,
and the error combines both as for the wall (the same code,
:func:`restitution.fem.limits.fem_epsilon`'s assembly of the grid).

The walls are those the modal pair's sweeps use: ``alpha = P / delta(w)`` with the products
``P`` of the kind (:func:`restitution.limits.defaults.default_products`: the disk's
:data:`restitution.limits.defaults.ALPHA_PRODUCTS` 40, 80, 160; the sphere's 80, 160, 320, as
its modal pair judge :mod:`restitution.laws.making.pair_judge` and its FEM on the wall take them)
and ``delta`` the pair's quasistatic compression
:meth:`restitution.bodies.pair.partner.Partner.max_compression`. ``geometry`` names the kind of
both bodies (default the disk); a sphere's walls need the first sphere's ``nu``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from restitution.bodies.pair.partner import Partner
from restitution.errors import InputError
from restitution.fem.elasticity import as_material
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.impact import FemCollisionError, FemSettings
from restitution.fem.limits import FemEpsilon, FemGrid, FemRun, _assemble, grid_of
from restitution.fem.pair_impact import fem_collide_pair, pair_model_for
from restitution.fem.pair_model import PAIR_GEOMETRY
from restitution.limits.defaults import (
    ALPHA_SCALE,
    check_alpha_scale,
    check_alphas,
    check_distinct,
    default_products,
)

__all__ = ["FemPairEpsilon", "PairMesh", "fem_pair_epsilon", "pair_walls"]


def pair_walls(
    partner: Partner,
    w: float,
    alphas: Sequence[float] | None = None,
    alpha_scale: str | None = None,
    geometry: str = PAIR_GEOMETRY,
    nu: float | None = None,
) -> tuple[float, ...]:
    """Contact hardness values (``1/R1``) at relative speed ``w`` (``c1``), ascending.

    ``"compression"`` (default :data:`restitution.limits.defaults.ALPHA_SCALE`): ``alphas``
    (default the kind's :func:`restitution.limits.defaults.default_products`, the disk's
    :data:`restitution.limits.defaults.ALPHA_PRODUCTS`) are products ``alpha * delta(w)``
    with the pair's compression :meth:`Partner.max_compression` (of ``geometry``; a sphere's
    needs the first one's ``nu``); ``"absolute"``: ``alphas`` as given.
    """
    scale = alpha_scale or ALPHA_SCALE
    check_alpha_scale(scale)
    values = tuple(float(a) for a in (alphas or default_products(geometry)))
    check_distinct("alphas", values)
    check_alphas(values)
    if scale == "absolute":
        return tuple(sorted(values))
    delta = float(partner.max_compression(float(w), geometry, nu))
    return tuple(sorted(a / delta for a in values))


@dataclass(frozen=True)
class PairMesh:
    """Both meshes of one run of the grid.

    Attributes
    ----------
    alpha : float
        ``1/R1``.
    level : int
    n_dofs : tuple of int
        Kept dofs of each mesh (half disk or meridian section).
    contact_chords : tuple of float
        Each body's longest arc chord within the Hertz half-width, ``R1``.
    """

    alpha: float
    level: int
    n_dofs: tuple[int, int]
    contact_chords: tuple[float, float]

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "alpha": self.alpha,
            "level": self.level,
            "n_dofs": list(self.n_dofs),
            "contact_chords": list(self.contact_chords),
        }


@dataclass(frozen=True, eq=False)
class FemPairEpsilon:
    """epsilon of a pair at one relative speed from the FEM route, with its grid and fits.

    Attributes
    ----------
    partner : Partner
    nu2 : float
        The second body's Poisson number.
    limits : FemEpsilon
        Both limits of the grid (:class:`restitution.fem.limits.FemEpsilon`; its ``nu`` is the
        first body's, its ``v`` the relative speed ``w`` and its ``geometry`` the kind of both;
        its runs' ``n_dofs`` are both bodies' together and ``h_contact`` the larger of their
        contact chords).
    meshes : tuple of PairMesh
        Each run's two meshes, in the order of ``limits.runs``.
    products : tuple of float or None
        The walls as products ``alpha * delta(w)`` (``None`` for absolute walls).
    """

    partner: Partner
    nu2: float
    limits: FemEpsilon
    meshes: tuple[PairMesh, ...]
    products: tuple[float, ...] | None = None

    nu = property(lambda self: self.limits.nu, doc="The first body's Poisson number.")
    geometry = property(lambda self: self.limits.geometry, doc="The kind of both bodies.")
    w = property(lambda self: self.limits.v, doc="Relative normal speed, ``c1``.")
    v = w
    epsilon = property(lambda self: self.limits.epsilon, doc="epsilon of the relative speed.")
    epsilon_err = property(lambda self: self.limits.epsilon_err, doc="Its error.")
    energy_loss = property(lambda self: self.limits.energy_loss, doc="``1 - epsilon^2``.")
    energy_loss_err = property(lambda self: self.limits.energy_loss_err, doc="Its error.")
    asymptotic_ok = property(lambda self: self.limits.asymptotic_ok, doc="No flag raised.")
    message = property(lambda self: self.limits.message, doc="The flags, when raised.")
    estimate = property(lambda self: self.limits.estimate, doc="epsilon as an Estimate.")
    runs = property(lambda self: self.limits.runs, doc="The grid (:class:`FemRun`).")

    def summary(self) -> str:
        """Lines for the terminal: epsilon, energy loss, grid."""
        p, lim = self.partner, self.limits
        limits = "h -> 0" if lim.alpha is not None else "alpha -> inf and h -> 0"
        where = f" at alpha = {lim.alpha:g}" if lim.alpha is not None else ""
        dofs = sorted(r.n_dofs for r in lim.runs)
        lines = [
            f"epsilon = {self.epsilon:.6f} +- {self.epsilon_err:.6f}   (two {self.geometry}s, nu = "
            f"{self.nu:g} and {self.nu2:g}, R2/R1 = {p.radius_ratio:g}, E2/E1 = "
            f"{p.modulus_ratio:g}, rho2/rho1 = {p.density_ratio:g}; w = {self.w:g} c1 relative "
            f"speed; FEM, {limits}{where})",
            f"energy loss 1 - epsilon^2 = {self.energy_loss:.6f} +- {self.energy_loss_err:.6f}",
            f"grid: alpha = {', '.join(f'{a:g}' for a in lim.alphas)}; mesh levels "
            f"{', '.join(str(k) for k in lim.levels)} ({dofs[0]}-{dofs[-1]} dofs of both bodies, "
            f"{lim.wall_time_s:.0f} s)",
        ]
        if not self.asymptotic_ok:
            lines.append(f"warning: not asymptotic: {self.message}")
        return "\n".join(lines)

    def to_dict(self) -> dict:
        """JSON-ready dictionary: :meth:`FemEpsilon.to_dict` with the pair's keys (``geometry``
        the kind's name and ``"-pair"``: ``"disk-pair"``, ``"sphere-pair"``; ``partner``,
        ``nu2``, ``w``, the walls' products and both meshes of every run)."""
        d = self.limits.to_dict()
        d["geometry"] = f"{self.geometry}-pair"
        d["w"] = d["v"]
        d["v_units"] = "c1 = sqrt(E1/rho1) (relative normal speed of the centres)"
        d["nu2"] = self.nu2
        d["partner"] = self.partner.to_dict()
        d["grid"]["meshes"] = [m.to_dict() for m in self.meshes]
        d["settings"]["alpha_products"] = None if self.products is None else list(self.products)
        d["settings"]["walls"] = "alpha = product / Partner.max_compression(w)"
        return d


def _one_run(
    nu, partner, w, alpha, level, grading, base, geometry=PAIR_GEOMETRY
) -> tuple[FemRun, PairMesh]:
    start = time.perf_counter()
    n_gauss = (base or FemSettings()).n_gauss
    pair = pair_model_for(nu, partner, w, alpha, level, grading, n_gauss, geometry)
    mesh = PairMesh(alpha, level, pair.n_dofs, pair.contact_chords)
    dofs, chord = sum(pair.n_dofs), max(pair.contact_chords)
    try:
        r = fem_collide_pair(nu, partner, w, alpha, geometry=geometry, level=level,
                             grading=grading, settings=base)  # fmt: skip
    except FemCollisionError as exc:
        nan = float("nan")
        wall = time.perf_counter() - start
        run = FemRun(alpha, level, dofs, chord, nan, nan, 0, nan, wall, str(exc))
        return run, mesh
    run = FemRun(
        alpha=alpha,
        level=level,
        n_dofs=dofs,
        h_contact=chord,
        epsilon=r.epsilon,
        energy_drift=r.result.energy_drift,
        n_steps=r.result.n_steps,
        dt=r.result.dt,
        wall_time_s=time.perf_counter() - start,
    )
    return run, mesh


def fem_pair_epsilon(
    nu: float,
    partner: Partner,
    w: float,
    *,
    geometry: str = PAIR_GEOMETRY,
    alpha: float | None = None,
    grid: FemGrid | None = None,
    on_run: Callable[[FemRun], None] | None = None,
    alphas: Sequence[float] | None = None,
    alpha_scale: str | None = None,
    levels: Sequence[int] | None = None,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
) -> FemPairEpsilon:
    """epsilon of two disks (or spheres) at relative speed ``w``, extrapolated to ``h -> 0`` and
    ``alpha -> inf``.

    Parameters
    ----------
    nu : float
        The first body's Poisson number (a disk's 2D one, a sphere's 3D one).
    partner : Partner
        The second body (ratios to the first, its own ``nu``).
    w : float
        Relative normal speed of the centres before the collision, ``c1``.
    geometry : str
        The kind of both bodies (default the disk;
        :func:`restitution.fem.section.fem_geometries`).
    alpha : float, optional
        Only take ``h -> 0`` at this contact hardness (``1/R1``).
    alphas, alpha_scale
        The walls of ``alpha -> inf`` (:func:`pair_walls`; default the modal sweeps' products
        of the kind over the pair's compression: 40, 80, 160 for disks, 80, 160, 320 for
        spheres).
    levels : sequence of int
        Mesh levels, ascending and consecutive.
    grading : ContactGrading, optional
        How both meshes are graded (default the kind's).
    base : FemSettings, optional
        Integrator settings of every run.
    on_run : callable, optional
        Called with each finished :class:`FemRun`.

    Returns
    -------
    FemPairEpsilon
        Failed runs are kept (``epsilon = nan``) and flag the result.
    """
    if not isinstance(partner, Partner):
        raise InputError(f"the second body must be a Partner, got {partner!r}")
    grid = grid_of(grid, alphas=alphas, alpha_scale=alpha_scale, levels=levels,
                   grading=grading, base=base)  # fmt: skip
    material = as_material(float(nu), geometry)
    w = float(w)
    if not 0.0 < w < 1.0:
        raise InputError(f"the relative speed w must lie in (0, 1) in units of c1, got {w}")
    levels, alphas, alpha_scale, base = grid.levels, grid.alphas, grid.alpha_scale, grid.base
    grading = grid.grading
    if levels[0] < 0:
        raise InputError(f"mesh levels must be non-negative, got {levels}")
    grading = grading or default_grading(geometry)
    products = None
    if alpha is not None:
        if not (alpha > 0 and math.isfinite(alpha)):
            raise InputError(f"the contact hardness alpha must be positive (1/R1), got {alpha}")
        alpha_values = (float(alpha),)
    else:
        alpha_values = pair_walls(partner, w, alphas, alpha_scale, geometry, material.nu)
        if (alpha_scale or ALPHA_SCALE) == "compression":
            products = tuple(sorted(float(a) for a in (alphas or default_products(geometry))))
    start = time.perf_counter()
    runs, meshes = [], []
    for a in alpha_values:
        for k in levels:
            run, mesh = _one_run(material.nu, partner, w, a, k, grading, base, geometry)
            runs.append(run)
            meshes.append(mesh)
            if on_run is not None:
                on_run(run)
    wall = time.perf_counter() - start
    limits = _assemble(material, w, alpha, runs, levels, grading, wall, geometry)
    return FemPairEpsilon(
        partner=partner,
        nu2=float(partner.nu2(material.nu)),
        limits=limits,
        meshes=tuple(meshes),
        products=products,
    )
