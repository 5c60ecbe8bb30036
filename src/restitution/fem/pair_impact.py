"""One head-on collision of two free disks (or two free spheres) solved with finite elements
(no modal truncation).

Units: the first body's, ``E1 = rho1 = R1 = 1`` (a disk's 2D plane-stress constants, a sphere's
3D ones); ``w`` (relative normal speed of the centres) in ``c1``, ``alpha`` in ``1/R1``, times
in ``R1 / c1``, forces per unit thickness in ``E1 R1`` (spheres: forces in ``E1 R1^2``).

The pair is the composite body of :mod:`restitution.fem.pair_model` (both half-disk meshes,
the gap of the modal pair :mod:`restitution.bodies.pair.body`), integrated by the disk-wall
collision of :mod:`restitution.fem.impact`: velocity Verlet
(:func:`restitution.fem.impact.verlet_step`), the energy and stability monitors, the start where
the undeformed pair's contact energy is ``CONTACT_TOL`` of the kinetic energy ``(mu/2) w^2`` in
the centre-of-mass frame and the stop once no free vibration of either disk can close the gap
again. Both disks start at rest internally, the first moving at ``v1 = w m2 / (m1 + m2)``
towards the second and the second at ``w m1 / (m1 + m2)`` towards the first.
``epsilon = -w_after / w``; the energy drift is relative to ``(mu/2) w^2``. The step starts at
``step_safety`` of the stability limit with the Hertz pressure of the pair
(:func:`restitution.fem.pair_model.pair_scales`) doubled, and is reduced as in
:func:`restitution.fem.impact.fem_collide` when a run meets a larger pressure or drifts more than
``energy_tol``.

``geometry`` names the kind of both bodies (default the disk,
:data:`restitution.fem.pair_model.PAIR_GEOMETRY`); two spheres are the same collision of their
meridian sections (:mod:`restitution.fem.pair_model`, **Spheres**), started and stopped alike.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

from restitution.bodies.pair.partner import Partner
from restitution.dynamics.results import CollisionResult
from restitution.fem.graded import ContactGrading
from restitution.fem.impact import (
    INTEGRATOR,
    FemSettings,
    _stable_step,
    _start_position,
    run_accepted,
)
from restitution.fem.pair_model import (
    PAIR_GEOMETRY,
    PairModel,
    check_pair_inputs,
    pair_mesh_settings,
    pair_model,
    pair_scales,
)

__all__ = ["PairCollision", "fem_collide_pair", "pair_model_for"]


@dataclass(frozen=True)
class PairCollision:
    """One FEM collision of two disks (or spheres).

    Attributes
    ----------
    result : CollisionResult
        ``method="fem"``, ``nu`` the first body's, ``v`` the relative speed ``w`` (``c1``),
        ``alpha`` (``1/R1``), ``epsilon`` of the relative speed, ``max_compression`` the
        largest approach of the centres past touching (``R1``), ``max_force`` the whole
        bodies' contact force (``E1 R1``; spheres ``E1 R1^2``), ``energy_drift`` relative to
        ``(mu/2) w^2``.
    partner : Partner
    nu2 : float
        The second body's Poisson number.
    level : int
        Mesh level of both bodies.
    n_dofs : tuple of int
        Kept dofs of each mesh (half disk or meridian section).
    contact_chords : tuple of float
        Each body's longest arc chord within the Hertz half-width, ``R1``.
    reference : int
        The body whose arc carries the potential (0: the first).
    geometry : str
        The kind of both bodies.
    """

    result: CollisionResult
    partner: Partner
    nu2: float
    level: int
    n_dofs: tuple[int, int]
    contact_chords: tuple[float, float]
    reference: int
    geometry: str = PAIR_GEOMETRY

    @property
    def epsilon(self) -> float:
        """``-w_after / w_before`` of the relative normal speed of the centres."""
        return self.result.epsilon

    def to_dict(self) -> dict:
        """JSON-ready summary (the collision's scalars and both meshes)."""
        r = self.result
        return {
            "geometry": self.geometry,
            "nu": r.nu,
            "nu2": self.nu2,
            "partner": self.partner.to_dict(),
            "w": r.v,
            "alpha": r.alpha,
            "level": self.level,
            "epsilon": r.epsilon,
            "energy_drift": r.energy_drift,
            "n_steps": r.n_steps,
            "dt": r.dt,
            "max_compression": r.max_compression,
            "max_force": r.max_force,
            "contact_time": r.contact_time,
            "n_dofs": list(self.n_dofs),
            "contact_chords": list(self.contact_chords),
            "reference": self.reference,
            "wall_time_s": r.wall_time_s,
        }


def pair_model_for(
    nu: float,
    partner: Partner,
    w: float,
    alpha: float,
    level: int,
    grading: ContactGrading | None = None,
    n_gauss: int = FemSettings.n_gauss,
    geometry: str = PAIR_GEOMETRY,
) -> PairModel:
    """The (cached) :class:`PairModel` that :func:`fem_collide_pair` uses for these inputs
    (``n_gauss`` Gauss points per arc facet of the reference body, ``geometry`` the kind)."""
    mesh_only = FemSettings(n_gauss=int(n_gauss))
    first, second = pair_mesh_settings(partner, w, alpha, level, grading, mesh_only, geometry,
                                       nu)  # fmt: skip
    half_width = pair_scales(partner, w, geometry, nu).half_width
    return pair_model(float(nu), partner, first, second, half_width, geometry)


def fem_collide_pair(
    nu: float,
    partner: Partner,
    w: float,
    alpha: float,
    *,
    geometry: str = PAIR_GEOMETRY,
    level: int = 1,
    grading: ContactGrading | None = None,
    settings: FemSettings | None = None,
    **overrides,
) -> PairCollision:
    """Two free disks (or spheres) meeting head-on, solved with finite elements (module docs).

    Parameters
    ----------
    nu : float
        The first body's Poisson number (a disk's 2D one, a sphere's 3D one).
    partner : Partner
        The second body: radius, modulus and density in the first body's units, own ``nu``.
    w : float
        Relative normal speed of the centres before the collision, ``c1``, in (0, 1).
    alpha : float
        Hardness of the contact potential, ``1/R1``.
    geometry : str
        The kind of both bodies, a kind the FEM route meshes
        (:func:`restitution.fem.section.fem_geometries`; default the disk).
    level : int
        Mesh level of both bodies (each level halves all element sizes).
    grading : ContactGrading, optional
        How both meshes are graded (default :func:`restitution.fem.graded.default_grading` of
        the kind).
    settings : FemSettings, optional
        Integrator settings (``step_safety``, ``energy_tol``, ``max_step_reductions``,
        ``n_gauss``, ``record``, ...); its mesh fields are replaced by the pair's. Keyword
        ``overrides`` replace single fields.

    Returns
    -------
    PairCollision

    Raises
    ------
    InputError
        For a partner that is not a :class:`Partner`, ``w`` outside (0, 1), a non-positive
        ``alpha``, a negative level, a kind the FEM route does not mesh or a Poisson number
        outside the kind's range.
    FemCollisionError
        When no step within ``max_step_reductions`` reductions meets ``energy_tol``.
    """
    partner, w = check_pair_inputs(partner, w, alpha, geometry)
    alpha = float(alpha)
    settings = settings or FemSettings()
    if overrides:
        settings = replace(settings, **overrides)
    start = time.perf_counter()
    scales = pair_scales(partner, w, geometry, nu)
    pair = pair_model_for(nu, partner, w, alpha, level, grading, settings.n_gauss, geometry)
    model = pair.composite
    e0 = 0.5 * model.disk.mass * w**2
    x_c = _start_position(model, alpha, e0)
    if settings.max_time is None:
        # Approach, four quasistatic contact times and a margin, as on the wall.
        settings = replace(settings, max_time=(-1.0 - x_c) / w + 4.0 * scales.contact_time + 10)
    dt = _stable_step(model, alpha, 2.0 * scales.pressure, settings.step_safety)
    run = run_accepted(model, w, alpha, dt, settings, "the pair's run")
    result = CollisionResult(
        method="fem",
        nu=float(pair.materials[0].nu),
        v=w,
        alpha=alpha,
        n_modes=0,
        epsilon=float(run.epsilon),
        energy_drift=float(run.drift),
        contact_time=float(run.contact_time),
        max_compression=float(run.max_compression),
        max_force=float(run.max_force),
        n_steps=int(run.steps),
        dt=float(run.dt),
        wall_time_s=time.perf_counter() - start,
        integrator=INTEGRATOR,
    )
    return PairCollision(
        result=result,
        partner=partner,
        nu2=float(pair.materials[1].nu),
        level=int(level),
        n_dofs=pair.n_dofs,
        contact_chords=pair.contact_chords,
        reference=pair.reference,
        geometry=pair.geometry,
    )
