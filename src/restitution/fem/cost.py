"""What a finite-element run will cost, estimated from its inputs before any mesh is made.

Units: ``E = rho = R = 1``; speeds in ``c``, ``alpha`` in ``1/R``, lengths in ``R``; the costs in
seconds of wall time on this project's 2-core machine and in bytes.

Issue 30: every entry point refuses, before it starts, work that cannot finish here. A run of
:func:`restitution.fem.impact.fem_collide` costs

* the set-up of its :class:`restitution.fem.model.FemModel`: mesh, matrices, two eigenvalue
  solves, a sparse LU factorisation of ``K`` and one solve per arc node. Its time and peak
  memory grow much faster than the degrees of freedom ``n`` (the factorisation's fill), so
  both are read off the measured table :data:`_SETUP` by log-log interpolation and continued
  beyond its ends with the slope of the last segment;
* its time steps: velocity Verlet at the step of the stability limit ``2 / omega_max``, each
  a sparse product with ``K`` (:data:`_STEP_S`, :data:`_DOF_STEP_S`).

Nothing is meshed: ``n`` comes from the size function of
:func:`restitution.fem.mesh.graded_half_disk` (:func:`estimate_mesh`), the number of steps
from the quasistatic contact time, the start gap and the step rule of
:mod:`restitution.fem.impact` (:func:`run_cost`). The models stay in
:func:`restitution.fem.model.fem_model`'s cache, so a study of several runs holds the earlier
ones while it builds the next (:func:`plan`). The checks (:func:`check_collide`,
:func:`check_compare`, :func:`check_epsilon`) refuse through
:func:`restitution.budget.check_memory_total` (never overridden) and
:func:`restitution.budget.check_time_total` (unless ``force``), naming the finest level or
the slowest speed that fits. The measurements behind the constants are beside them;
docs/fem.md compares the estimates with later runs (measured / estimated wall time 0.71-1.26).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import numpy as np
from scipy.special import i0e

from restitution import budget
from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.errors import InputError
from restitution.fem.elasticity import as_material
from restitution.fem.graded import ContactGrading, default_grading, graded_settings
from restitution.fem.impact import (
    CONTACT_TOL,
    FemSettings,
    contact_angle_estimate,
    pressure_estimate,
)
from restitution.fem.limits import LEVELS
from restitution.fem.model import fem_model
from restitution.fem.section import contact_time, section
from restitution.limits.defaults import (
    ALPHA_SCALE,
    check_alpha_scale,
    check_alphas,
    check_distinct,
    default_products,
    walls_at,
)

__all__ = [
    "FemPlan",
    "MeshEstimate",
    "RunCost",
    "check_collide",
    "check_compare",
    "check_epsilon",
    "collide_plan",
    "compare_plan",
    "epsilon_plan",
    "estimate_mesh",
    "plan",
    "run_cost",
]

# -- the mesh --------------------------------------------------------------------------------
# Triangles = _ELEMENTS * integral over the half disk of dA / q(h)^2, with h the size function
# of graded_half_disk, its growth capped at _BISECTION_GRADING (bisection with conforming
# closure grades no faster) and q(h) the largest sqrt(2)^-j not above h (the edge lengths the
# bisection of the initial right triangles makes). Fitted (geometric mean) to 72 meshes of
# graded_half_disk: levels 0-2 of collide's settings (v = 0.01-0.3, alpha = 50, 500) and of the
# convergence studies' grading (disk nu = 0.33 and sphere nu = 0.3, v = 1e-6 to 0.1, the
# softest and hardest default walls), 112 to 12281 triangles: every count within -12 % and
# +17 % of the fit (the cap 0.42 minimises the spread; without it -14 % to +34 %).
_ELEMENTS = 5.13
_BISECTION_GRADING = 0.42
# Arc facets = _ARC_FACETS * integral along the arc of ds / q(h): the same 72 meshes, within
# -11 % and +33 %.
_ARC_FACETS = 1.34
# Points of the integration grid per direction (0.3 % from a 1200-point grid).
_GRID = 160

# -- the time step ----------------------------------------------------------------------------
# omega_K = _OMEGA_K c_L / h and lambda_B = _LAMBDA_B / h, with h the target edge on the
# contact arc (h_contact 2^-refine) and c_L = sqrt((lambda + 2 mu) / rho) the section's
# longitudinal wave speed: geometric means over 44 models (disk nu = 0.33 and 0.9, sphere
# nu = 0.3, levels 0 and 1, v = 1e-6 to 0.1); measured 14.3-28.1 and 17.0-29.7 (the shortest
# edge is 0.30-0.52 h, by where h falls between the bisection's sizes).
_OMEGA_K = 20.3
_LAMBDA_B = 23.3
# Simulated time = _SIMULATED_TIME * (quasistatic contact time + 2 * start gap / v): measured
# 0.93-1.30 times that in 15 runs (disk nu = 0.33, 0.9, sphere nu = 0.3; v = 1e-5 to 0.1).
_SIMULATED_TIME = 1.1

# -- wall time and memory ---------------------------------------------------------------------
# One Verlet step: 25 us + 24 ns per degree of freedom, within -25 % and +30 % of 13 runs of
# 745-44763 dofs (the machine shared with a long computation, load average 2-3).
_STEP_S = 25e-6
_DOF_STEP_S = 24e-9
# Set-up of one FemModel (fem_model: mesh, assembly, eigsh, splu, arc compliances): dofs,
# seconds, peak RSS above the imported process (bytes). Collide's meshes of levels 0-3 at
# nu = 0.33, v = 0.1, alpha = 500, and level 2 with the sizes scaled by 0.6 (97991 dofs), each
# in a fresh process on the project's machine. The growth steepens (time: slopes 1.3, 1.7,
# 2.2, 4.0 in log-log; memory: 1.1, 1.1, 1.5, 2.5): SuperLU's fill, not the mesh.
_SETUP = np.array(
    [
        (3563, 0.139, 19.7e6),
        (12301, 0.705, 72.9e6),
        (44763, 6.40, 293.0e6),
        (97991, 35.4, 979.1e6),
        (169801, 322.0, 3906.8e6),
    ]
)
# What a built model keeps (the cache holds it): 1.89 kB per dof, measured with tracemalloc at
# 3563-44763 dofs (1882-1891 B).
_MODEL_BYTES_PER_DOF = 1890.0
# Checked later against 7 single runs and 2 epsilon studies of 745-69627 dofs, disk and sphere
# (docs/fem.md): measured / estimated wall time 0.71-1.26, peak memory 0.82-1.05, dofs 0.94-1.17.


@dataclass(frozen=True)
class MeshEstimate:
    """Sizes of a graded half-disk mesh, estimated without making it.

    Attributes
    ----------
    n_elements : float
        Triangles.
    n_arc_facets : float
        Facets on the arc.
    n_dofs : float
        Kept degrees of freedom of the P2 + bubble discretisation,
        ``6 n_elements + 2 n_arc_facets + 1`` (exact for the meshes: Euler's formula with the
        roller on the diameter).
    """

    n_elements: float
    n_arc_facets: float
    n_dofs: float


def _quantized(h: np.ndarray) -> np.ndarray:
    """Largest ``sqrt(2)^-j`` not above ``h``: the edge lengths of bisected right triangles."""
    return 2.0 ** (-np.ceil(-2.0 * np.log2(h) - 1e-9) / 2.0)


def _sizes(x, y, angle, scale, h_contact, h_far, grading) -> np.ndarray:
    """Target longest edge of :func:`restitution.fem.mesh.graded_half_disk` at ``(x, y)``.

    The mesh measures the distance ``d`` to the contact arc from an element's nearest point,
    ``d - h/2``; ``h = scale (h_contact + g (d - h/2))`` solved for ``h``.
    """
    r = np.hypot(x, y)
    theta = np.arctan2(y, x)
    end = np.hypot(x - math.cos(angle), y - math.sin(angle))
    d = np.where(theta <= angle, np.abs(1.0 - r), end)
    g = min(grading, _BISECTION_GRADING)
    h = scale * (h_contact + g * d) / (1.0 + 0.5 * scale * g)
    return np.minimum(scale * h_far, np.maximum(h, scale * h_contact))


def estimate_mesh(
    refine: int, contact_angle: float, h_contact: float, h_far: float, grading: float
) -> MeshEstimate:
    """Triangles, arc facets and degrees of freedom of
    ``graded_half_disk(refine, contact_angle, h_contact=..., h_far=..., grading=...)``.

    Integrates the mesh's size function over the half disk (no mesh is made; a few ms). Within
    -12 % and +17 % of the meshes it was fitted to (module source). Each level multiplies
    the count by about 4 once the level's sizes are below the coarse mesh's.

    Examples
    --------
    >>> round(estimate_mesh(1, 0.58, 0.04, 0.25, 0.3).n_dofs, -3)  # the mesh: 12301
    13000.0
    """
    scale = 2.0**-refine
    finest = scale * min(h_contact, h_far)
    u = np.concatenate([[0.0], np.geomspace(finest / 20.0, 1.0, _GRID)])  # 1 - r
    r = np.sort(1.0 - u)
    inside = np.linspace(0.0, contact_angle, max(_GRID // 3, 20))
    outside = contact_angle + np.concatenate(
        [[0.0], np.geomspace(finest / 20.0, max(math.pi - contact_angle, finest), _GRID)]
    )
    theta = np.unique(np.concatenate([inside, np.minimum(outside, math.pi)]))
    rm, tm = 0.5 * (r[1:] + r[:-1]), 0.5 * (theta[1:] + theta[:-1])
    R, T = np.meshgrid(rm, tm, indexing="ij")
    area = np.outer(np.diff(r) * rm, np.diff(theta))
    args = (contact_angle, scale, h_contact, h_far, grading)
    h = _quantized(_sizes(R * np.cos(T), R * np.sin(T), *args))
    elements = _ELEMENTS * float((area / h**2).sum())
    h_arc = _quantized(_sizes(np.cos(tm), np.sin(tm), *args))
    arc = _ARC_FACETS * float((np.diff(theta) / h_arc).sum())
    return MeshEstimate(elements, arc, 6.0 * elements + 2.0 * arc + 1.0)


# -- one run ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class RunCost:
    """Estimated cost of one :func:`restitution.fem.impact.fem_collide`.

    Attributes
    ----------
    n_dofs : float
        Degrees of freedom (:func:`estimate_mesh`).
    steps : float
        Time steps of one run at the planned step (a repeated run after a step reduction,
        rare, is not counted).
    dt : float
        Planned step, ``R / c``.
    setup_s, step_s : float
        Seconds of the model's set-up and of one time step.
    peak_bytes : float
        Peak memory of building the model (its factorisation included), bytes.
    model_bytes : float
        Memory the built model keeps while it is cached, bytes.
    """

    n_dofs: float
    steps: float
    dt: float
    setup_s: float
    step_s: float
    peak_bytes: float
    model_bytes: float

    @property
    def seconds(self) -> float:
        """Set-up and time steps, seconds."""
        return self.setup_s + self.steps * self.step_s


def _loglog(n: float, column: int) -> float:
    """Column ``column`` of :data:`_SETUP` at ``n`` dofs, interpolated in log-log and
    continued beyond the table with the slope of its end segments."""
    x = np.log(_SETUP[:, 0])
    y = np.log(_SETUP[:, column])
    ln = math.log(max(n, 1.0))
    i = int(np.clip(np.searchsorted(x, ln), 1, x.size - 1))
    slope = (y[i] - y[i - 1]) / (x[i] - x[i - 1])
    return math.exp(y[i - 1] + slope * (ln - x[i - 1]))


def _start_gap(material: Material, v: float, alpha: float, geometry: str) -> float:
    """Gap (``R``) between the undeformed body and the wall where the run starts: the wall
    energy ``CONTACT_TOL`` times the kinetic one (:mod:`restitution.fem.impact`), with the arc
    integral of ``exp(alpha (x - 1))`` in closed form (the disk's half arc: ``pi i0e(alpha)``;
    the sphere's surface: ``2 pi (1 - exp(-2 alpha)) / alpha``)."""
    if section(geometry).axisymmetric:
        mass = 4.0 * math.pi / 3.0 * material.rho
        integral = 2.0 * math.pi * -math.expm1(-2.0 * alpha) / alpha
    else:
        mass = 0.5 * math.pi * material.rho
        integral = math.pi * float(i0e(alpha))
    # In logarithms: at v = 1e-300 the energy underflows to 0 (issue 47: a math domain error).
    ln_ratio = math.log(CONTACT_TOL * 0.5 * mass * alpha / integral) + 2.0 * math.log(v)
    return max(-ln_ratio / alpha, 0.0)


def run_cost(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    settings: FemSettings | None = None,
    geometry: str = DEFAULT_GEOMETRY,
) -> RunCost:
    """Estimated cost of ``fem_collide(material_or_nu, v, alpha, geometry=geometry,
    settings=settings)``, without making its mesh.

    Parameters
    ----------
    material_or_nu : Material or float
    v : float
        Speed towards the wall, ``c``, in (0, 1).
    alpha : float
        Wall hardness, ``1/R``.
    settings : FemSettings, optional
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).

    Returns
    -------
    RunCost
    """
    settings = settings or FemSettings()
    material = as_material(material_or_nu, geometry)
    v, alpha = float(v), float(alpha)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    if not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the wall hardness alpha must be positive, got {alpha}")
    angle = settings.contact_angle
    if angle is None:
        angle = contact_angle_estimate(v, alpha, geometry, material.nu)
    mesh = estimate_mesh(
        int(settings.refine), angle, settings.h_contact, settings.h_far, settings.grading
    )
    n = mesh.n_dofs
    lam, mu = section(geometry).lame(material)
    h = 2.0 ** -int(settings.refine) * min(settings.h_contact, settings.h_far)
    omega_k = _OMEGA_K * math.sqrt((lam + 2.0 * mu) / material.rho) / h
    pressure = pressure_estimate(v, geometry, material.nu)
    dt = settings.step_safety * 2.0 / math.sqrt(omega_k**2 + alpha * pressure * _LAMBDA_B / h)
    simulated = _SIMULATED_TIME * (
        contact_time(v, geometry, material.nu) + 2.0 * _start_gap(material, v, alpha, geometry) / v
    )
    if settings.max_time is not None:
        simulated = min(simulated, settings.max_time)
    return RunCost(
        n_dofs=n,
        steps=simulated / dt,
        dt=dt,
        setup_s=_loglog(n, 1),
        step_s=_STEP_S + _DOF_STEP_S * n,
        peak_bytes=_loglog(n, 2),
        model_bytes=_MODEL_BYTES_PER_DOF * n,
    )


# -- several runs -----------------------------------------------------------------------------


def _count(x: float) -> str:
    """``12000`` as ``1.2e4``: two significant digits, a short exponent."""
    mantissa, _, exponent = f"{x:.2g}".partition("e")
    return f"{mantissa}e{int(exponent)}" if exponent else mantissa


@dataclass(frozen=True)
class FemPlan:
    """Estimated cost of FEM runs made one after the other in one process.

    Attributes
    ----------
    runs : tuple of RunCost
    seconds : float
        All set-ups and time steps.
    peak_bytes : float
        Largest memory at any time: a model's set-up plus the earlier models still in
        :func:`restitution.fem.model.fem_model`'s cache.
    """

    runs: tuple[RunCost, ...]
    seconds: float
    peak_bytes: float

    def _largest(self) -> RunCost:
        return max(self.runs, key=lambda r: r.seconds)

    def time_words(self) -> str:
        """How the time was estimated, for a refusal."""
        r = self._largest()
        runs = "the FEM run" if len(self.runs) == 1 else f"{len(self.runs)} FEM runs, the longest"
        return (
            f"{runs}: a model of about {_count(r.n_dofs)} degrees of freedom, set-up "
            f"{budget.format_duration(r.setup_s)}, then {_count(r.steps)} time steps of "
            f"{budget.format_duration(r.step_s)}"
        )

    def memory_words(self) -> str:
        """What the memory holds, for a refusal."""
        n = max(r.n_dofs for r in self.runs)
        kept = "" if len(self.runs) == 1 else ", with the earlier models kept in the cache"
        return (
            f"the FEM model of about {_count(n)} degrees of freedom and its sparse "
            f"factorisation{kept}"
        )


def plan(runs: Sequence[RunCost]) -> FemPlan:
    """The cost of ``runs`` made in this order in one process (each with its own model)."""
    runs = tuple(runs)
    if not runs:
        raise InputError("an FEM plan needs at least one run")
    keep = fem_model.cache_parameters()["maxsize"] or 0
    peak = 0.0
    for i, r in enumerate(runs):
        held = sum(x.model_bytes for x in runs[max(0, i - keep) : i])
        peak = max(peak, held + r.peak_bytes)
    return FemPlan(runs, sum(r.seconds for r in runs), peak)


def collide_plan(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    refine: int,
    geometry: str = DEFAULT_GEOMETRY,
    settings: FemSettings | None = None,
) -> FemPlan:
    """The cost of ``fem_collide(..., refine=refine)`` (``settings``: the other fields)."""
    level = replace(settings or FemSettings(), refine=refine)  # FemSettings checks refine
    return plan([run_cost(material_or_nu, v, alpha, level, geometry)])


def compare_plan(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    levels: Sequence[int],
    geometry: str = DEFAULT_GEOMETRY,
    settings: FemSettings | None = None,
) -> FemPlan:
    """The cost of the FEM side of :func:`restitution.fem.compare.compare_fem_modal` (the modal
    side's mode count is bounded by :func:`restitution.bodies.cache.check_mode_request`)."""
    base = settings or FemSettings()
    return plan(
        [run_cost(material_or_nu, v, alpha, replace(base, refine=int(k)), geometry) for k in levels]
    )


def epsilon_plan(
    material_or_nu: Material | float,
    v: float,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    alpha: float | None = None,
    alphas: Sequence[float] | None = None,
    alpha_scale: str | None = None,
    levels: Sequence[int] = LEVELS,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
) -> FemPlan:
    """The cost of :func:`restitution.fem.limits.fem_epsilon` with the same arguments: every
    wall of the grid at every level, on the meshes of
    :func:`restitution.fem.graded.graded_settings`."""
    material = as_material(material_or_nu, geometry)
    v = float(v)
    if not 0.0 < v < 1.0:
        raise InputError(f"the speed v must lie in (0, 1) in units of c, got {v}")
    grading = grading or default_grading(geometry)
    if alpha is not None:
        if not (alpha > 0 and math.isfinite(alpha)):  # as fem_epsilon refuses it
            raise InputError(f"the wall hardness alpha must be positive (1/R), got {alpha}")
        walls = (float(alpha),)
    else:
        products = tuple(float(a) for a in (alphas or default_products(geometry)))
        check_distinct("alphas", products)
        check_alphas(products)
        scale = alpha_scale or ALPHA_SCALE
        check_alpha_scale(scale)
        walls = tuple(sorted(walls_at(v, products, scale, geometry=geometry, nu=material.nu)))
    runs = []
    for a in walls:
        for k in levels:
            s = graded_settings(v, a, k, grading, base, geometry=geometry, nu=material.nu)
            runs.append(run_cost(material, v, a, s, geometry))
    return plan(runs)


# -- refusals ---------------------------------------------------------------------------------


def _check(
    plan_of: Callable, name: str, value, fits_phrase: Callable, force: bool, override: str
) -> FemPlan:
    """Refuse ``plan_of(value)`` beyond the memory budget, or beyond the time bound unless
    ``force``; ``fits_phrase(ok)`` names the value that fits, ``ok(plan)`` saying whether a
    plan does. The value a memory refusal names also fits the time bound (unless ``force``),
    so that taking it is not refused next."""
    p = plan_of(value)

    def in_time(q: FemPlan) -> bool:
        return force or q.seconds <= budget.TIME_BOUND_S

    budget.check_memory_total(
        name, value, p.peak_bytes, p.memory_words(),
        lambda limit: fits_phrase(lambda q: q.peak_bytes <= limit and in_time(q)),
    )  # fmt: skip
    budget.check_time_total(
        name, value, p.seconds, p.time_words(),
        lambda bound: fits_phrase(lambda q: q.seconds <= bound),
        force=force, override=override,
    )  # fmt: skip
    return p


def _finest(plan_of: Callable, name: str, value: int, lowest: int) -> Callable:
    """``fits_phrase`` of a mesh level: the finest level from ``lowest`` up that fits."""

    def phrase(ok) -> str:
        best = None
        for k in range(lowest, value):
            if not ok(plan_of(k)):
                break
            best = k
        if best is None:
            return f"not even {budget.named(name, lowest)} fits"
        return f"{budget.named(name, best)} is the finest that fits"

    return phrase


def check_collide(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    refine: int,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    settings: FemSettings | None = None,
    force: bool = False,
    name: str = "refine",
    override: str = "force=True",
) -> FemPlan:
    """Refuse a :func:`restitution.fem.impact.fem_collide` at level ``refine`` that would not
    fit in memory, or take longer than :data:`restitution.budget.TIME_BOUND_S` unless
    ``force``; returns the estimate.

    Raises
    ------
    InputError
        One line with the estimate, the limit and the finest level that fits.
    """

    def plan_of(k):
        return collide_plan(material_or_nu, v, alpha, k, geometry, settings)

    finest = _finest(plan_of, name, refine, 0)
    return _check(plan_of, name, refine, finest, force, override)


def check_compare(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    refine: int,
    refine_min: int = 0,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    settings: FemSettings | None = None,
    force: bool = False,
    name: str = "refine",
    override: str = "force=True",
) -> FemPlan:
    """Refuse the FEM levels ``refine_min .. refine`` of
    :func:`restitution.fem.compare.compare_fem_modal` like :func:`check_collide`; the finest
    level named is the largest ``refine`` that fits with the same ``refine_min``."""

    def plan_of(k):
        return compare_plan(material_or_nu, v, alpha, range(refine_min, k + 1), geometry, settings)

    finest = _finest(plan_of, name, refine, refine_min)
    return _check(plan_of, name, refine, finest, force, override)


_FASTEST = 0.5
"""Fastest speed (``c``) :func:`check_epsilon` looks at for one that fits."""


def check_epsilon(
    material_or_nu: Material | float,
    v: float,
    *,
    force: bool = False,
    name: str = "v",
    override: str = "force=True",
    **options,
) -> FemPlan:
    """Refuse a :func:`restitution.fem.limits.fem_epsilon` (``options``: its keyword
    arguments) that would not fit in memory, or take longer than
    :data:`restitution.budget.TIME_BOUND_S` unless ``force``; returns the estimate.

    Slow collisions cost most: the contact-graded meshes shrink with the contact half-width
    (``a ~ sqrt(v)``) and the stable step with them, while the contact lasts longer, so the
    steps grow like ``v^-1/2``. The refusal names the slowest speed (two significant digits)
    that fits.

    Raises
    ------
    InputError
        One line with the estimate, the limit and the slowest speed that fits.
    """

    def plan_of(u):
        return epsilon_plan(material_or_nu, u, **options)

    def slowest(ok) -> str:
        if not ok(plan_of(_FASTEST)):
            return f"not even {budget.named(name, _FASTEST)} fits"
        lo, hi = math.log(v), math.log(_FASTEST)
        for _ in range(16):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if ok(plan_of(math.exp(mid))) else (mid, hi)
        fast = math.exp(hi)
        digits = 10.0 ** (math.floor(math.log10(fast)) - 1)
        rounded = math.ceil(fast / digits) * digits
        shown = float(f"{rounded:.2g}")
        if not ok(plan_of(shown)):
            shown = float(f"{fast:.3g}")
        return f"{budget.named(name, f'{shown:g}')} is the slowest that fits"

    return _check(plan_of, name, v, slowest, force, override)
