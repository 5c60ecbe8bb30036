"""Two free disks, or two free spheres, meeting head-on, as one finite-element body for their
contact.

Units: the *first* body's, ``E1 = rho1 = R1 = 1`` (a disk's 2D plane-stress constants, a
sphere's 3D ones). The second body, of the same kind, has ``R2 = radius_ratio``,
``E2 = modulus_ratio``, ``rho2 = density_ratio`` and its own Poisson number
(:class:`restitution.bodies.pair.partner.Partner`). Lengths in ``R1``, the relative normal speed
``w`` of the centres in ``c1 = sqrt(E1/rho1)``, ``alpha`` in ``1/R1``; disks: forces per unit
thickness in ``E1 R1``, energies in ``E1 R1^2``, masses in ``rho1 R1^2``; spheres: forces in
``E1 R1^2``, energies in ``E1 R1^3``, masses in ``rho1 R1^3``.

The kind is the ``geometry`` of every function (default :data:`PAIR_GEOMETRY`, the disk): a
kind the FEM route meshes (:func:`restitution.fem.section.fem_geometries`). What follows is
written for disks; a three-dimensional kind (the sphere) is the same construction on the
meridian sections (:mod:`restitution.fem.section`, the axis ``y = r``), with the differences
listed under **Spheres** below.

**The formulation** is the modal pair's (:mod:`restitution.bodies.pair.body`). Each disk is the
half disk of :mod:`restitution.fem.mesh` (the symmetric family, roller on the diameter), in its
own frame with its contact at ``+x``: ``u_i`` is the ``x`` displacement of body ``i``'s points
*towards the other body*, rigid translation included. Surface points are paired by their
undeformed height ``y = R1 sin(phi1) = R2 sin(phi2)``; the gap is

    g(y) = X2 - X1 - [R1 cos(phi1) + u1(phi1)] - [R2 cos(phi2) + u2(phi2)]

and the potential ``V = (1/alpha) int exp(-alpha g) ds_ref`` over the arc of the smaller body
(the *reference*; the first on a tie), as half-disk integrals over ``0 <= phi_ref <= pi/2``
(masses and energies of the half disks are halves too, so the dynamics are the whole pair's).
The reference body's arc quadrature (:func:`restitution.fem.contact.arc_quadrature`, its
Gauss points on the isoparametric arc) carries the integral; at each of its points the partner's
reference position and displacement are taken at the partner's boundary point of the same
undeformed height (the continuum's angle ``arcsin(y / R2)``; on the discrete arc the point of
its quadratic facet whose height is ``y``), interpolated with the P2 trace of that facet.

**The composite body.** Written with ``x0 = X1 - X2 + R1 + R2 - 1`` and the heights
``H = x1_ref + x2_ref - R2`` of the paired reference points (``H = 1`` at the tip),
``-g = x0 + H + B1 u1 + B2 u2``: the wall problem of :mod:`restitution.fem.impact` for one body
whose dofs are both bodies' (block-diagonal stiffness and lumped mass), whose wall rows are
``[B1 | B2]`` and whose surface heights are ``H``. Its "rigid" vector is
``(m2 / M) t1 + (m1 / M) t2`` (``t_i`` body ``i``'s unit translation, ``m_i`` its discrete mass,
``M = m1 + m2``): a start ``w * rigid`` gives the centre-of-mass frame, ``v1 = w m2 / M``
towards the partner and ``v2 = w m1 / M`` towards the first, its mass ``rigid^T M rigid`` is the
reduced mass ``mu`` and ``rigid^T M u / mu`` the approach of the centres. The collision of
:mod:`restitution.fem.impact` (velocity Verlet, energy monitor, stability monitor, stop test)
therefore runs the pair unchanged; ``epsilon`` is the relative speed after over before.

What the stop test needs: the largest frequency ``max(omega_K1, omega_K2)``, the largest
eigenvalue of ``M^-1 B^T W B`` of the composite (``W`` the reference weights) and, per point,
``chi1 + chi2``: each body's static compliance of the facet behind the point relative to its
own centre of mass. The gap's change from free vibrations of energies ``E1 + E2`` is bounded by
``1.25 (sqrt(2 E1 chi1) + sqrt(2 E2 chi2)) <= 1.25 sqrt(2 (E1 + E2)(chi1 + chi2))``.

Each body is computed in its own reduced units (:func:`restitution.fem.model.fem_model`, cached;
two identical disks share one model) and scaled: ``K = E_i K_own`` (2D elasticity does not
change under a change of length), ``M = rho_i R_i^2 M_own``, lengths and arc weights ``R_i``,
frequencies ``sqrt(E_i / rho_i) / R_i``, compliances ``1 / E_i``. In ``d`` dimensions
(:attr:`BodyKind.dimension <restitution.bodies.kinds.BodyKind.dimension>`) an energy is
``E R^d`` and a displacement ``R`` times the own one, so ``K = E_i R_i^(d-2) K_own``,
``M = rho_i R_i^d M_own``, surface weights ``R_i^(d-1)`` and compliances
``1 / (E_i R_i^(d-2))``.

**Meshes.** Both meshes are graded (:func:`restitution.fem.mesh.graded_half_disk`) by the
pair's quasistatic contact (:func:`pair_scales`): the 2D Hertz half-width ``b`` of two disks,
``b^2 = 4 F R_eff / (pi E_eff)`` (:mod:`restitution.quasistatic.hertz_pair`), with the peak
force ``F = 2 E0 / delta``, ``E0 = mu w^2 / 2`` and ``delta`` the pair's compression
(:meth:`Partner.max_compression`). Body ``i`` gets the contact size
``contact_fraction * b / R_i`` in its own units (the same physical size ``0.4 b 2^-level`` on
both), the contact zone ``1.2 sqrt(b^2 + 14 R_eff / alpha) / R_i`` (the wall's zone of
:func:`restitution.fem.impact.contact_angle_estimate` with the gap's curvature ``1/R_eff``) and
the far size ``h_far`` of its own radius. Two identical disks at ``w`` and ``alpha`` get the
meshes of the disk on the wall at ``v = w/2``, ``alpha_wall = 2 alpha``.

**Spheres** (a kind that is not :attr:`~restitution.bodies.kinds.BodyKind.planar`). Each body
is the sphere's meridian section (:mod:`restitution.fem.section`): its 3D material
(:func:`restitution.fem.section.fem_material`, no plane-stress conversion), its axisymmetric
matrices and its surface quadrature ``2 pi r ds`` over the near hemisphere; the section carries
the whole sphere (masses, energies and forces are the whole bodies'). The gap is the modal
sphere pair's (:mod:`restitution.bodies.pair.body`): surface points paired by their distance
``y = r`` from the common axis, ``R1 sin(theta1) = R2 sin(theta2)``; the composite and the
collision are unchanged, with the scalings above for ``d = 3`` (``K`` times ``E_i R_i``, ``M``
times ``rho_i R_i^3``, weights ``R_i^2``, compliances ``1 / (E_i R_i)``). The pair's contact
(:func:`pair_scales`) is 3D Hertz: the compression ``delta``
(:meth:`Partner.max_compression` with ``geometry`` and the first ``nu``), the peak force
``F = (4/3) E* sqrt(R_eff) delta^(3/2)`` with ``1/E* = (1 - nu1^2) + (1 - nu2^2) / E2``, the
contact radius ``a = sqrt(R_eff delta)`` (in place of ``b``), the peak pressure
``3 F / (2 pi a^2)`` and the contact time ``2.943 delta / w``; the reduced mass is that of the
whole spheres, ``m_i = (4/3) pi rho_i R_i^3``. The meshes are the sphere's grading
(:func:`restitution.fem.graded.default_grading`) with the same contact size, zone and far size
as above. Two identical spheres at ``w`` and ``alpha`` get the meshes of the sphere on the wall
at ``v = w/2``, ``alpha_wall = 2 alpha`` (``delta = 2 delta_wall(w/2)``, ``R_eff = 1/2``:
the same ``a``, force and pressure).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp

from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.kinds import BodyKind
from restitution.bodies.material import Material
from restitution.bodies.pair.partner import Partner
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.errors import InputError
from restitution.fem.contact import ArcQuadrature
from restitution.fem.elasticity import HalfDisk, as_material
from restitution.fem.graded import ContactGrading, default_grading
from restitution.fem.impact import FemSettings
from restitution.fem.model import FemModel, _largest_eigenvalue, fem_model
from restitution.fem.section import _kind as fem_kind

__all__ = [
    "PAIR_GEOMETRY",
    "PairModel",
    "PairScales",
    "check_pair_inputs",
    "pair_mesh_settings",
    "pair_model",
    "pair_scales",
]

PAIR_GEOMETRY = DISK.geometry
"""The default kind of both bodies of an FEM pair (the disk): the route computes two bodies of
one kind the FEM route meshes meeting head-on (module docs), each meshed as that body on the
wall is; ``geometry=`` names another (the sphere)."""

_TRACE = 3
"""Nodes of a quadratic arc facet: its two vertices and its midpoint."""


def check_pair_inputs(
    partner, w: float, alpha: float | None = None, geometry: str = PAIR_GEOMETRY
) -> tuple[Partner, float]:
    """Refuse what the FEM pair cannot compute; the :class:`Partner` and ``w`` as a float.

    ``partner`` must be a :class:`Partner` (of two bodies of the kind ``geometry``), ``w``
    (``c1``) in ``(0, 1)``, ``alpha`` (``1/R1``, when given) positive and finite; ``geometry``
    a kind the FEM route meshes.
    """
    kind = fem_kind(geometry)
    if not isinstance(partner, Partner):
        raise InputError(
            f"the second {kind.geometry} must be given as a restitution.bodies.pair.Partner (its "
            f"radius, modulus and density ratios and Poisson number), got {partner!r}"
        )
    w = float(w)
    if not 0.0 < w < 1.0:
        raise InputError(
            f"the relative normal speed w of the centres must lie in (0, 1) in units of c1, got {w}"
        )
    if alpha is not None and not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the contact hardness alpha must be positive (1/R1), got {alpha}")
    return partner, w


@dataclass(frozen=True)
class PairScales:
    """The pair's quasistatic contact at relative speed ``w`` (first body's units; the
    sphere's in brackets).

    Attributes
    ----------
    w : float
        Relative normal speed of the centres, ``c1``.
    compression : float
        Largest approach of the centres, ``R1`` (:meth:`Partner.max_compression`).
    force : float
        Peak contact force of the whole disks, ``2 E0 / compression``, ``E1 R1`` (3D Hertz,
        ``(4/3) E* sqrt(R_eff) compression^(3/2)``, ``E1 R1^2``).
    half_width : float
        2D Hertz half-width ``b`` of the common contact (Hertz contact radius
        ``sqrt(R_eff compression)``), ``R1``.
    pressure : float
        Hertz peak pressure ``2 F / (pi b)`` (``3 F / (2 pi b^2)``), ``E1``.
    contact_time : float
        ``pi compression / w`` (Hertz's ``2.943 compression / w``), ``R1 / c1`` (eq. 61's
        ``pi sqrt(ln(4/v))`` on the wall).
    effective_radius : float
        ``R1 R2 / (R1 + R2)``, ``R1``.
    """

    w: float
    compression: float
    force: float
    half_width: float
    pressure: float
    contact_time: float
    effective_radius: float


def _whole_masses(partner: Partner, kind: BodyKind) -> tuple[float, float]:
    """Masses of the whole bodies: the unit ball of the kind's dimension ``d`` times
    ``rho_i R_i^d`` (disks ``pi R^2``, per unit thickness, ``rho1 R1^2``; spheres
    ``(4/3) pi R^3``, ``rho1 R1^3``)."""
    d = kind.dimension
    unit = math.pi ** (d / 2) / math.gamma(d / 2 + 1)
    return unit, unit * partner.density_ratio * partner.radius_ratio**d


def _pair_nu(kind: BodyKind, nu: float | None) -> float | None:
    """The first body's Poisson number, checked by ``kind``, where the kind's scales need it
    (:attr:`BodyKind.scales_need_nu`); ``None`` where they do not (the disk's)."""
    if not kind.scales_need_nu:
        return None
    if nu is None:
        raise InputError(
            f"the contact scales of two {kind.geometry}s need the first one's Poisson number; "
            "pass nu="
        )
    return kind.check_nu(nu)


def pair_scales(
    partner: Partner, w: float, geometry: str = PAIR_GEOMETRY, nu: float | None = None
) -> PairScales:
    """The quasistatic scales of the pair at relative speed ``w`` (``c1``) that size its meshes
    and its time step (module docs); for identical bodies the wall's at ``v = w/2``.

    ``geometry`` is the kind of both bodies; a kind whose scales need the Poisson number (the
    sphere) takes the first body's ``nu`` (the partner's is :meth:`Partner.nu2`).

    Examples
    --------
    >>> s = pair_scales(Partner(), 0.2)
    >>> from restitution.fem.graded import contact_half_width
    >>> round(s.half_width, 12) == round(contact_half_width(0.1), 12)
    True
    """
    partner, w = check_pair_inputs(partner, w, geometry=geometry)
    kind = fem_kind(geometry)
    nu = _pair_nu(kind, nu)
    m1, m2 = _whole_masses(partner, kind)
    mu = m1 * m2 / (m1 + m2)
    delta = float(partner.max_compression(w, kind.geometry, nu))
    r2, e2 = partner.radius_ratio, partner.modulus_ratio
    r_eff = r2 / (1.0 + r2)
    if kind.planar:
        force = mu * w**2 / delta
        e_eff = e2 / (1.0 + e2)
        b = math.sqrt(4.0 * force * r_eff / (math.pi * e_eff))
        pressure = 2.0 * force / (math.pi * b)
        duration = math.pi * delta / w
    else:
        e_star = 1.0 / ((1.0 - nu**2) + (1.0 - partner.nu2(nu) ** 2) / e2)
        force = 4.0 / 3.0 * e_star * math.sqrt(r_eff) * delta**1.5
        b = math.sqrt(r_eff * delta)
        pressure = 3.0 * force / (2.0 * math.pi * b**2)
        duration = CONTACT_TIME_CONSTANT * delta / w  # Hertz's, as on the wall
    return PairScales(
        w=w,
        compression=delta,
        force=force,
        half_width=b,
        pressure=pressure,
        contact_time=duration,
        effective_radius=r_eff,
    )


def pair_mesh_settings(
    partner: Partner,
    w: float,
    alpha: float,
    level: int,
    grading: ContactGrading | None = None,
    base: FemSettings | None = None,
    geometry: str = PAIR_GEOMETRY,
    nu: float | None = None,
) -> tuple[FemSettings, FemSettings]:
    """The two bodies' mesh settings (each in its own units) for ``w`` (``c1``), ``alpha``
    (``1/R1``) and the mesh ``level`` (module docs: meshes); integrator fields from ``base``;
    ``geometry`` and ``nu`` as for :func:`pair_scales`.
    """
    partner, w = check_pair_inputs(partner, w, alpha, geometry)
    if int(level) != level or level < 0:
        raise InputError(f"the mesh level must be a non-negative integer, got {level}")
    grading = grading or default_grading(geometry)
    base = base or FemSettings()
    scales = pair_scales(partner, w, geometry, nu)
    b = scales.half_width
    zone = 1.2 * math.sqrt(b**2 + 14.0 * scales.effective_radius / alpha)
    out = []
    for radius in (1.0, partner.radius_ratio):
        out.append(
            replace(
                base,
                refine=int(level),
                contact_angle=float(min(zone / radius, 0.5 * math.pi)),
                h_contact=min(grading.contact_fraction * b / radius, grading.h_far),
                h_far=grading.h_far,
                grading=grading.grading,
            )
        )
    return out[0], out[1]


@dataclass(frozen=True)
class _Trace:
    """The quadratic arc facets of one body (own units): kept ``u_x`` dofs of the two vertices
    and the midpoint, their reference coordinates and the facet's compliance ``chi``."""

    nodes: np.ndarray  # (F, 3) int
    x: np.ndarray  # (F, 3)
    y: np.ndarray  # (F, 3)
    chi: np.ndarray  # (F,)


def _trace(model: FemModel) -> _Trace:
    """The arc facets behind a model's quadrature (:class:`restitution.fem.contact.ArcQuadrature`
    keeps, per point, its facet's ``u_x`` dofs in the order of the P2 shape functions, and the
    model the facet's largest nodal compliance)."""
    nodes, first = np.unique(model.quad.facet_nodes, axis=0, return_index=True)
    disk = model.disk
    where = disk.basis.doflocs[:, disk.free]
    return _Trace(nodes=nodes, x=where[0][nodes], y=where[1][nodes], chi=model.chi[first])


def _trace_at_heights(
    model: FemModel, height: np.ndarray
) -> tuple[sp.csr_matrix, np.ndarray, np.ndarray]:
    """The body's boundary points of undeformed heights ``height`` (own units, in ``[0, 1]``).

    On the facet whose end heights bracket ``y``, the facet parameter ``t`` solves
    ``Y(t) = y`` for the quadratic ``Y(t) = y_a (1-t)(1-2t) + y_b t(2t-1) + 4 y_m t(1-t)``
    (the root in ``[0, 1]`` nearest the linear guess, polished by two Newton steps).

    Returns
    -------
    B : scipy.sparse.csr_matrix, shape (P, n)
        ``u_x`` at the points from the body's kept dofs (the P2 trace of each facet).
    x : numpy.ndarray, shape (P,)
        Reference ``x`` of the points (own ``R``).
    chi : numpy.ndarray, shape (P,)
        Compliance of each point's facet (own ``R / E``).
    """
    tr = _trace(model)
    y = np.asarray(height, dtype=float)
    lo = np.minimum(tr.y[:, 0], tr.y[:, 1])
    hi = np.maximum(tr.y[:, 0], tr.y[:, 1])
    top = float(hi.max())
    if y.min() < -1e-12 or y.max() > top + 1e-9:
        raise InputError(
            f"heights {y.min():.3g}-{y.max():.3g} lie outside the partner's arc (0-{top:.6g}); "
            "the reference must be the smaller body"
        )
    y = np.clip(y, 0.0, top)
    inside = (lo[None, :] <= y[:, None]) & (y[:, None] <= hi[None, :])
    facet = np.argmax(inside, axis=1)
    ya, yb, ym = tr.y[facet, 0], tr.y[facet, 1], tr.y[facet, 2]
    # Y(t) = ya + t (-3 ya - yb + 4 ym) + t^2 (2 ya + 2 yb - 4 ym)
    qa = 2.0 * ya + 2.0 * yb - 4.0 * ym
    qb = -3.0 * ya - yb + 4.0 * ym
    qc = ya - y
    guess = np.where(yb != ya, (y - ya) / np.where(yb != ya, yb - ya, 1.0), 0.5)
    disc = np.sqrt(np.maximum(qb * qb - 4.0 * qa * qc, 0.0))
    q = -0.5 * (qb + np.copysign(disc, qb))
    with np.errstate(divide="ignore", invalid="ignore"):
        roots = np.stack([q / qa, qc / q])
    roots = np.where(np.isfinite(roots), roots, guess)
    t = roots[np.argmin(np.abs(roots - guess), axis=0), np.arange(y.size)]
    for _ in range(2):
        slope = qb + 2.0 * qa * t
        step = np.where(np.abs(slope) > 1e-300, (qa * t * t + qb * t + qc) / slope, 0.0)
        t = t - step
    t = np.clip(t, 0.0, 1.0)
    shape = np.stack([(1 - t) * (1 - 2 * t), t * (2 * t - 1), 4 * t * (1 - t)], axis=1)
    rows = np.repeat(np.arange(y.size), _TRACE)
    B = sp.csr_matrix(
        (shape.ravel(), (rows, tr.nodes[facet].ravel())), shape=(y.size, model.disk.n_dofs)
    )
    x = (shape * tr.x[facet]).sum(axis=1)
    return B, x, tr.chi[facet]


def _contact_chord(model: FemModel, half_angle: float) -> float:
    """Longest arc chord (own ``R``) of the facets that reach into ``|phi| <= half_angle``
    (all arc facets when none does), as :func:`restitution.fem.graded.mesh_summary`."""
    tr = _trace(model)
    chord = np.hypot(tr.x[:, 1] - tr.x[:, 0], tr.y[:, 1] - tr.y[:, 0])
    angle = np.minimum(np.arctan2(tr.y[:, 0], tr.x[:, 0]), np.arctan2(tr.y[:, 1], tr.x[:, 1]))
    inside = angle <= half_angle
    return float(chord[inside].max() if np.any(inside) else chord.max())


@dataclass(frozen=True, eq=False)
class PairModel:
    """Both meshes of a pair and the composite body the collision integrates (module docs).

    Attributes
    ----------
    partner : Partner
    geometry : str
        The kind of both bodies.
    materials : tuple of Material
        Each body's material in its own reduced units (``E = rho = 1``, its own ``nu``; a
        disk's 2D constants, a sphere's 3D ones).
    bodies : tuple of FemModel
        Each body's model in its own units.
    reference : int
        The body whose arc carries the potential: 0 (the first) unless the second is smaller.
    composite : FemModel
        The pair as one body in the first body's units; its dofs are the first body's followed
        by the second's (``R1``); ``disk.mesh`` and ``disk.basis`` are ``None`` (two meshes).
    n_first : int
        Kept dofs of the first body.
    masses : tuple of float
        The discrete masses ``m1, m2`` of the meshes: half disks (``rho1 R1^2``) or whole
        spheres (``rho1 R1^3``).
    contact_chords : tuple of float
        Each body's longest arc chord in the Hertz half-width ``b``, ``R1``.
    """

    partner: Partner
    geometry: str
    materials: tuple[Material, Material]
    bodies: tuple[FemModel, FemModel]
    reference: int
    composite: FemModel
    n_first: int
    masses: tuple[float, float]
    contact_chords: tuple[float, float]

    @property
    def n_dofs(self) -> tuple[int, int]:
        """Kept dofs of each mesh (half disk or meridian section)."""
        return tuple(int(m.disk.n_dofs) for m in self.bodies)

    def split(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A composite vector as the two bodies' parts (``R1``, first-body units)."""
        return u[: self.n_first], u[self.n_first :]


def _scale(partner: Partner, body: int) -> tuple[float, float, float]:
    """``(R, E, rho)`` of ``body`` in the first body's units."""
    if body == 0:
        return 1.0, 1.0, 1.0
    return partner.radius_ratio, partner.modulus_ratio, partner.density_ratio


def compose(
    models: tuple[FemModel, FemModel],
    scale: tuple[tuple[float, float, float], tuple[float, float, float]],
    ref: int,
    tip: float,
    dimension: int,
) -> tuple[FemModel, tuple[float, float]]:
    """Two bodies' models as the composite body of the module docs, in the first body's units.

    Parameters
    ----------
    models : tuple of FemModel
        Each body in its own units, its contact side at ``+x`` facing the other.
    scale : tuple of (R, E, rho)
        Each body's length, modulus and density in the first body's units.
    ref : int
        The body whose contact quadrature carries the potential (its points' heights must lie
        on the other's contact side).
    tip : float
        The other body's reference ``x`` where its contact side meets the axis, first body's
        units (``R2`` for a ball whose centre is its origin; ``0`` for a block whose top is,
        :mod:`restitution.fem.block`): the composite's heights are ``x1_ref + x2_ref - tip``.
    dimension : int
        ``d`` of the scalings (2 for a disk's half, 3 for a meridian section).

    Returns
    -------
    composite : FemModel
    masses : tuple of float
        The discrete masses of both bodies (first body's units).
    """
    d = dimension
    other = 1 - ref
    r_ref, r_other = scale[ref][0], scale[other][0]
    materials = tuple(model.disk.material for model in models)
    geometry = models[0].disk.geometry

    # The reference's quadrature; its points' heights (a sphere's: distances from the axis,
    # the modal pair's pairing) from the P2 trace of its own facets.
    rq = models[ref].quad
    where = models[ref].disk.basis.doflocs[:, models[ref].disk.free]
    height = r_ref * (rq.B @ where[1])
    B_other, x_other, chi_other = _trace_at_heights(models[other], height / r_other)
    blocks = [None, None]
    x_ref = [None, None]
    chi = [None, None]
    blocks[ref], x_ref[ref], chi[ref] = rq.B, r_ref * rq.x_ref, models[ref].chi
    blocks[other], x_ref[other], chi[other] = B_other, r_other * x_other, chi_other

    stiffness, mass_diagonal, translation = [], [], []
    for i, model in enumerate(models):
        radius, modulus, density = scale[i]
        stiffness.append(modulus * radius ** (d - 2) * model.disk.K)
        mass_diagonal.append(density * radius**d * model.disk.M.diagonal())
        translation.append(model.disk.rigid)
    m = tuple(float(t @ (md * t)) for t, md in zip(translation, mass_diagonal, strict=True))
    total = m[0] + m[1]
    rigid = np.concatenate([m[1] / total * translation[0], m[0] / total * translation[1]])
    mass_diag = np.concatenate(mass_diagonal)
    K = sp.block_diag(stiffness, format="csr")
    M = sp.diags(mass_diag).tocsr()
    n = mass_diag.size
    weight = r_ref ** (d - 1) * rq.weight
    B = sp.hstack(blocks, format="csr")
    offset = 0 if ref == 0 else int(models[0].disk.n_dofs)
    quad = ArcQuadrature(
        phi=rq.phi,
        x_ref=x_ref[0] + x_ref[1] - tip,
        weight=weight,
        B=B,
        BT=B.T.tocsr(),
        facet_nodes=rq.facet_nodes + offset,
    )
    disk = HalfDisk(
        material=materials[0],
        discretisation="P2+lumped",
        geometry=geometry,
        mesh=None,
        basis=None,
        free=np.arange(n),
        K=K,
        M=M,
        rigid=rigid,
        mass=float(rigid @ (M @ rigid)),
    )
    omega = [
        model.omega_K * math.sqrt(scale[i][1] / scale[i][2]) / scale[i][0]
        for i, model in enumerate(models)
    ]
    BtWB = (B.T @ sp.diags(weight) @ B).tocsr()
    composite = FemModel(
        disk=disk,
        quad=quad,
        inverse_mass=1.0 / mass_diag,
        r=M @ rigid,
        omega_K=max(omega),
        lambda_B=_largest_eigenvalue(BtWB, mass_diag),
        chi=chi[0] / (scale[0][1] * scale[0][0] ** (d - 2))
        + chi[1] / (scale[1][1] * scale[1][0] ** (d - 2)),
        h_min=min(model.h_min * scale[i][0] for i, model in enumerate(models)),
    )
    return composite, m


@functools.lru_cache(maxsize=4)
def pair_model(
    nu: float,
    partner: Partner,
    first: FemSettings,
    second: FemSettings,
    half_width: float,
    geometry: str = PAIR_GEOMETRY,
) -> PairModel:
    """Both bodies' models and the composite body (cached).

    Parameters
    ----------
    nu : float
        The first body's Poisson number (a disk's 2D one, a sphere's 3D one).
    partner : Partner
    first, second : FemSettings
        Each body's mesh in its own units (:func:`pair_mesh_settings`).
    half_width : float
        The pair's Hertz half-width ``b`` (``R1``), for the contact chords only.
    geometry : str
        The kind of both bodies (module docs).
    """
    kind = fem_kind(geometry)
    d = kind.dimension
    materials = (as_material(float(nu), kind.geometry),
                 as_material(partner.nu2(float(nu)), kind.geometry))  # fmt: skip
    models = tuple(
        fem_model(
            material, int(s.refine), float(s.contact_angle), s.h_contact, s.h_far, s.grading,
            s.n_gauss, kind.geometry,
        )
        for material, s in zip(materials, (first, second), strict=True)
    )  # fmt: skip
    ref = 0 if partner.radius_ratio >= 1.0 else 1
    scale = tuple(_scale(partner, i) for i in (0, 1))
    composite, m = compose(models, scale, ref, partner.radius_ratio, d)
    chords = tuple(
        scale[i][0] * _contact_chord(model, half_width / scale[i][0])
        for i, model in enumerate(models)
    )
    return PairModel(
        partner=partner,
        geometry=kind.geometry,
        materials=materials,
        bodies=models,
        reference=ref,
        composite=composite,
        n_first=int(models[0].disk.n_dofs),
        masses=m,
        contact_chords=chords,
    )
