"""One collision of a sphere with an elastic wall, both meshed: the finite-element judge of the
half-space and plate routes (issue 42).

Units: the ball's, ``E = rho = R = 1`` of its three-dimensional constants; the wall's constants
in the ball's units (:class:`restitution.bodies.wall.HalfSpace`,
:class:`~restitution.bodies.wall.Plate`); ``v`` (the approach speed of the ball and the wall) in
``c = sqrt(E / rho)``, ``alpha`` in ``1 / R``, times in ``R / c``.

**The bodies.** The ball is the sphere's meridian section of the FEM route
(:func:`restitution.fem.model.fem_model`); the wall is a block of finite radius and depth
(:mod:`restitution.fem.block`): for a half-space, ``radius = depth = size * c_L t_c``; for a
plate of thickness ``h``, ``depth = h`` and ``radius = size * c_L t_c``, with ``c_L`` the wall's
compressional speed, ``t_c`` the contact time (:func:`contact_time`: Hertz's of the ball on the
wall, on a plate the longer of it and Zener's) and ``size = 0.75`` by default. A wave that
leaves the contact at the first touch and comes back from the bottom or the side has travelled
at least ``2 size c_L t_c = 1.5 t_c``; the judge checks that the block is large enough by
doubling ``size`` (:mod:`restitution.fem.wall_limits`). Both are the composite body of
:mod:`restitution.fem.pair_model` (:func:`~restitution.fem.pair_model.compose`: the ball's
contact quadrature carries the potential, the block's top is paired with it by the distance
from the axis, the block's tip at ``x = 0``) and the collision of :mod:`restitution.fem.impact`
(velocity Verlet, energy and stability monitors, start and stop tests) runs it unchanged.

**The observable.** The block is free, and the collision's own ``epsilon`` is that of the
relative speed of the centres of mass, ``-w'/w = J / (mu w) - 1`` (``J`` the impulse, ``mu``
the reduced mass). The block's recoil ``J / M`` is in it, a change of ``(1 + eps) m / M``
(``3.7e-4`` for the default block at ``v = 1e-3``, 2.7 % of the loss) that a wall anchored to
the ground, or a half-space, does not have; while no reflection has come back, the contact does
not feel the block's mass (the force histories of a block and of one twice as large agree to
``1e-6`` of the peak, their relative speeds differ by ``3.3e-4 v``). The judge's ``epsilon`` is
therefore the ball's: its speed after over before in the frame where the block was at rest,
``J / (m v) - 1 = (1 + eps_rel) M / (m + M) - 1`` by momentum, exactly. The two sizes then
agree to ``1e-6``.

**The meshes.** Hertz's contact of the ball on the wall (``1/E* = (1 - nu^2) + (1 -
nu_w^2)/E_w``, ``R_eff = R``, the ball's mass) gives the compression ``delta``, the contact
radius ``a = sqrt(delta)``, the peak pressure and ``t_c = 2.943 delta / v``. The ball is meshed
with the sphere's grading (:func:`restitution.fem.graded.default_grading`: contact size
``0.4 a``, growth 0.5 per unit distance, bulk ``0.17 R``) over the contact zone of the ball on a
rigid wall; the block's top to the same contact size and zone, its bulk to ``h_far =
c_T t_c / BLOCK_WAVELENGTHS`` (``c_T`` the wall's shear speed: the pulse's waves are at least
that long; a plate's at most ``h / PLATE_LAYERS``).

**Contact levels.** A level halves the contact size of both bodies and keeps their growth and
bulk sizes, so that a level adds a ring of elements around the contact instead of four times
the elements (on a rigid wall, levels halve every size): the block is many contact times of
waves wide, and a full refinement of it would cost 8 times more a level. The levels' limit
``h -> 0`` is thus that of the contact's resolution; what the bulk's fixed sizes leave is
measured by the bulk check (both bodies' bulk sizes and growth halved, ``bulk = 0.5``,
:mod:`restitution.fem.wall_limits`).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

from restitution.bodies.material import Material
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.bodies.wall import HalfSpace, Plate
from restitution.errors import InputError
from restitution.fem.block import block_model
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.impact import FemSettings, _stable_step, _start_position, run_accepted
from restitution.fem.model import FemModel, fem_model
from restitution.fem.pair_model import compose
from restitution.fem.section import fem_material
from restitution.quasistatic.plate import plate_impact

__all__ = [
    "BLOCK_SIZE",
    "BLOCK_WAVELENGTHS",
    "WallCollision",
    "WallScales",
    "fem_collide_wall",
    "wall_scales",
]

BLOCK_SIZE = 0.75
"""The block's radius (and a half-space's depth) in ``c_L t_c`` (module docs)."""

BLOCK_WAVELENGTHS = 16.0
"""The block's bulk elements at level 0: ``c_T t_c / BLOCK_WAVELENGTHS`` (module docs)."""

PLATE_RUN_CONTACTS = 12.0
"""A run on a plate may last this many contact times (on a block, as on a rigid wall, 4):
the plate rings near the contact long after the ball left, and the stop test waits until no
free vibration of that energy could close the gap (the 3 mm glass plate at ``v = 5e-4``:
184 R/c, 3.5 contact times, at ``alpha delta = 160``; beyond 4 at 80)."""

PLATE_LAYERS = 2
"""A plate's bulk elements at level 0 are at most its thickness over this (module docs)."""

_BALL_MASS = 4.0 * math.pi / 3.0


@dataclass(frozen=True)
class WallScales:
    """Hertz's contact of the ball on the wall at ``v`` (ball's units).

    Attributes
    ----------
    v : float
        Approach speed, ``c``.
    compression : float
        ``delta = (15 m v^2 / (16 E*))^(2/5)``, ``R``.
    force, half_width, pressure : float
        Peak force ``(4/3) E* delta^(3/2)`` (``E R^2``), contact radius ``sqrt(delta)``
        (``R``), peak pressure ``3 F / (2 pi a^2)`` (``E``).
    contact_time : float
        ``2.943 delta / v``, ``R / c``.
    """

    v: float
    compression: float
    force: float
    half_width: float
    pressure: float
    contact_time: float


def _check(nu: float, wall, v: float) -> tuple[float, HalfSpace, float]:
    if not isinstance(wall, HalfSpace):
        raise InputError(
            "the wall must be given as a restitution.bodies.wall.HalfSpace or Plate (its "
            f"modulus and density ratios, Poisson number and thickness), got {wall!r}"
        )
    v = float(v)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    return SPHERE.check_nu(float(nu)), wall, v


def wall_scales(nu: float, wall: HalfSpace, v: float) -> WallScales:
    """Hertz's contact of a sphere of Poisson number ``nu`` on ``wall`` at speed ``v``
    (``c``)."""
    nu, wall, v = _check(nu, wall, v)
    e_star = wall.effective_modulus(nu)
    delta = (15.0 * _BALL_MASS * v * v / (16.0 * e_star)) ** 0.4
    force = 4.0 / 3.0 * e_star * delta**1.5
    return WallScales(
        v=v,
        compression=delta,
        force=force,
        half_width=math.sqrt(delta),
        pressure=3.0 * force / (2.0 * math.pi * delta),
        contact_time=CONTACT_TIME_CONSTANT * delta / v,
    )


def contact_time(nu: float, wall: HalfSpace, v: float) -> float:
    """The contact's duration that sizes the block and bounds a run (``R / c``): Hertz's on
    the wall's ``E*``; on a plate the longer of it and Zener's thin-plate contact
    (:func:`restitution.quasistatic.plate.plate_impact`, which may not end: then
    :data:`~restitution.quasistatic.plate.MAX_CONTACT_TIMES` Hertz times)."""
    hertz = wall_scales(nu, wall, v).contact_time
    if not isinstance(wall, Plate):
        return hertz
    return max(hertz, plate_impact(v, wall, nu=nu, mass=_BALL_MASS).contact_time)


def _wall_material(wall: HalfSpace) -> Material:
    return fem_material(
        Material(nu=wall.nu, E=wall.modulus_ratio, rho=wall.density_ratio), SPHERE.geometry
    )


@dataclass(frozen=True, eq=False)
class WallModel:
    """The ball, the block and their composite (:func:`wall_model`); ``ball_mesh`` the ball's
    mesh as :class:`FemSettings` (for the same ball on a rigid wall)."""

    ball_mesh: FemSettings
    ball: FemModel
    block: FemModel
    composite: FemModel
    masses: tuple[float, float]
    block_radius: float
    block_depth: float


def wall_model(
    nu: float,
    wall: HalfSpace,
    v: float,
    alpha: float,
    level: int,
    *,
    size: float = BLOCK_SIZE,
    bulk: float = 1.0,
    grading: ContactGrading | None = None,
    n_gauss: int = FemSettings.n_gauss,
) -> WallModel:
    """The meshes of the ball and the block for ``v`` (``c``), ``alpha`` (``1/R``) and the
    contact ``level`` (module docs), and their composite; ``bulk`` scales both bodies' bulk
    sizes and growth (the bulk check takes 0.5)."""
    nu, wall, v = _check(nu, wall, v)
    if int(level) != level or level < 0:
        raise InputError(f"the mesh level must be a non-negative integer, got {level}")
    for name, value in (("size", size), ("bulk", bulk)):
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"the block's {name} must be a positive number, got {value!r}")
    grading = grading or default_grading(SPHERE.geometry)
    s = wall_scales(nu, wall, v)
    a = s.half_width
    zone = 1.2 * math.sqrt(a * a + 14.0 / alpha)
    h_contact = min(grading.contact_fraction * a, grading.h_far) * 2.0**-level
    ball_mesh = FemSettings(
        refine=0, contact_angle=float(min(zone, 0.5 * math.pi)), h_contact=h_contact,
        h_far=bulk * grading.h_far, grading=bulk * grading.grading, n_gauss=int(n_gauss),
    )  # fmt: skip
    ball = fem_model(
        fem_material(nu, SPHERE.geometry), 0, ball_mesh.contact_angle, h_contact,
        ball_mesh.h_far, ball_mesh.grading, int(n_gauss), SPHERE.geometry,
    )  # fmt: skip
    c_l, c_t = wall.compressional_speed, wall.shear_speed
    t_c = contact_time(nu, wall, v)
    radius = size * c_l * t_c
    h_far = bulk * c_t * t_c / BLOCK_WAVELENGTHS
    depth = radius
    if isinstance(wall, Plate):
        depth = wall.thickness
        h_far = min(h_far, bulk * depth / PLATE_LAYERS)
    block = block_model(
        _wall_material(wall), float(radius), float(depth), float(min(zone, radius)), 0,
        float(min(h_contact, h_far)), float(h_far), float(bulk * grading.grading), int(n_gauss),
    )  # fmt: skip
    models = (ball, block)
    composite, masses = compose(models, ((1.0, 1.0, 1.0), (1.0, 1.0, 1.0)), 0, 0.0, 3)
    return WallModel(ball_mesh, ball, block, composite, masses, float(radius), float(depth))


@dataclass(frozen=True)
class WallCollision:
    """One FEM collision of a sphere with a meshed wall.

    Attributes
    ----------
    epsilon : float
        The ball's speed after over before in the frame where the wall was at rest (module
        docs: the half-space's and the plate's ``epsilon``).
    relative_epsilon : float
        The relative speed of the centres of mass after over before (the free block's).
    block_mass : float
        The block's discrete mass, ``rho R^3``.
    energy_drift : float
        Largest relative energy error of the accepted run.
    n_dofs : tuple of int
        Kept dofs of the ball and the block.
    block_radius, block_depth : float
        ``R``.
    n_steps : int
    dt : float
    contact_time : float
        ``R / c``.
    wall_time_s : float
    """

    epsilon: float
    relative_epsilon: float
    block_mass: float
    energy_drift: float
    n_dofs: tuple[int, int]
    block_radius: float
    block_depth: float
    n_steps: int
    dt: float
    contact_time: float
    wall_time_s: float


def fem_collide_wall(
    nu: float,
    wall: HalfSpace,
    v: float,
    alpha: float,
    *,
    level: int = 0,
    size: float = BLOCK_SIZE,
    bulk: float = 1.0,
    grading: ContactGrading | None = None,
    settings: FemSettings | None = None,
) -> WallCollision:
    """A sphere of Poisson number ``nu`` striking ``wall`` at ``v`` (``c``) with the contact
    hardness ``alpha`` (``1/R``), both meshed (module docs)."""
    start = time.perf_counter()
    settings = settings or FemSettings()
    alpha = float(alpha)
    if not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the contact hardness alpha must be positive (1/R), got {alpha}")
    model = wall_model(nu, wall, v, alpha, level, size=size, bulk=bulk, grading=grading,
                       n_gauss=settings.n_gauss)  # fmt: skip
    s = wall_scales(nu, wall, v)
    comp = model.composite
    x_c = _start_position(comp, alpha, 0.5 * comp.disk.mass * v * v)
    if settings.max_time is None:
        spans = PLATE_RUN_CONTACTS if isinstance(wall, Plate) else 4.0
        t_c = contact_time(nu, wall, v)
        settings = replace(settings, max_time=(-1.0 - x_c) / v + spans * t_c + 10.0)
    dt = _stable_step(comp, alpha, 2.0 * s.pressure, settings.step_safety)
    run = run_accepted(comp, float(v), alpha, dt, settings, "the ball's run on the wall")
    m, block_mass = model.masses
    return WallCollision(
        epsilon=float((1.0 + run.epsilon) * block_mass / (m + block_mass) - 1.0),
        relative_epsilon=float(run.epsilon),
        block_mass=float(block_mass),
        energy_drift=float(run.drift),
        n_dofs=(int(model.ball.disk.n_dofs), int(model.block.disk.n_dofs)),
        block_radius=model.block_radius,
        block_depth=model.block_depth,
        n_steps=int(run.steps),
        dt=float(run.dt),
        contact_time=float(run.contact_time),
        wall_time_s=time.perf_counter() - start,
    )
