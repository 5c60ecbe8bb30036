"""The sphere's loss to its vibrations at slow impacts: Rayleigh's estimate on Hertz's pulse, with
an error band.

Units: ``E = rho = R = 1`` of the sphere's 3D constants; ``v`` in ``c = sqrt(E/rho)`` (speed
towards the wall); energies as fractions of the initial kinetic energy ``(m/2) v^2``.

Why a third route. Below ``v ~ 0.005`` the modal collision is not asymptotic in the number of
modes within the 20000 the mode scan affords (the contact radius shrinks like ``v^(2/5)``), and
the finite-element route costs about ten minutes a point, too much for the closely spaced speeds
an oscillating ``epsilon(v)`` needs. As ``v -> 0`` every mode is slow against the contact
(``omega_k tau >> 1``), the force pulse tends to Hertz's, and the energy left in the modes tends
to Rayleigh's estimate (:func:`restitution.quasistatic.rayleigh.rayleigh_energy`, the Duhamel
integral of Hertz's pulse at the tip)::

    E_k / ((m/2) v^2) ~ v (4 pi E*^2 R / m^2) (C_k^2 / omega_k^5) cos^2(omega_k tau / 2 - 5 pi / 4)

(:func:`restitution.quasistatic.hertz_sphere.drive_asymptote`). The total is ``v`` times a factor
that oscillates with ``v`` through the phases ``omega_k tau / 2``, ``tau ~ v^(-1/5)``.

Its error is the phase. The contact time of the dynamic collision differs from Hertz's by a
relative amount of order ``sqrt(delta_max / R)``: measured on the modal runs as
``-0.335 sqrt(delta_max)`` at ``v = 0.001-0.03``, ``nu = 0.3`` (:data:`CONTACT_TIME_SPREAD`,
docs/spheres.md). The band is the range of the asymptotic sum as ``tau`` runs over
``tau_Hertz (1 +- kappa sqrt(delta_max))``, taken about the Duhamel value; to it is added twice the
tail of the mode sum beyond the ``N`` modes used (the tail falls like ``1/N``, so it is estimated
by the sum between ``N/2`` and ``N``). The served value is the Duhamel value, the error the larger
distance to the band's ends plus the tail. Corrections to the amplitudes (of relative order
``sqrt(delta_max)`` as well, under 2 % below ``v = 1e-4``) are not in the band; the
finite-element points of ``laws/data/fem_reference_sphere.json`` at ``v = 2e-4 - 1e-3`` judge the
whole (docs/spheres.md).

The estimate is for the sphere only: the disk's pulse starts like ``v t / ln(1/(v t))``, its
Rayleigh estimate carries no power of ``v`` and does not become exact at slow speeds in this
way (the paper's section 5).

**Two spheres** (a :class:`~restitution.bodies.pair.BodyPair` of spheres, any radii and
materials; ``v`` is then the relative speed ``w`` in ``c1``, energies fractions of
``(mu/2) w^2``). The pulse is Hertz's of the pair (:func:`~restitution.quasistatic.
hertz_sphere.sphere_pair_contact_law`: ``E*`` of both, ``R_eff``, the reduced mass ``mu``), and
each sphere's modes are driven by it at its own pole: the pair body holds both mode sets with
amplitudes rescaled to ``mu``, so the formulas above hold term by term with ``m = mu`` and
``R = R_eff``. Two identical spheres at ``w`` give the sphere on the wall at ``w/2``. The band's
width is ``kappa a / R_min`` with ``a = sqrt(R_eff delta_max)`` the contact radius and
``R_min`` the smaller radius: on the wall ``a / R = sqrt(delta_max)``, for two identical spheres
the same number; for two radii the smaller sphere's, the one on which the contact is widest (a
choice, judged against modal collisions of the pair in tests/test_sphere_pair.py). Each
sphere's share of the loss is in :attr:`LowSpeedLoss.shares`.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.bodies.base import ModalBody
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.estimate import Estimate
from restitution.jsonable import finite_tree
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    SphereHertzLaw,
    drive_asymptote,
    sphere_contact_law,
    sphere_pair_contact_law,
    sphere_quasistatic_collision,
)
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.status import Status

__all__ = [
    "CONTACT_TIME_SPREAD",
    "LOW_SPEED_MODES",
    "PAIR_LOW_SPEED_MODES",
    "LowSpeedLoss",
    "asymptotic_loss",
    "interpolation_error",
    "low_speed_loss",
    "reach",
    "width_reach",
]

CONTACT_TIME_SPREAD = 0.335
"""``kappa``: the relative uncertainty of Hertz's contact time is ``kappa sqrt(delta_max / R)``.
Source: the deviation of the modal run's contact time from Hertz's, extrapolated in ``alpha`` and
``N``, ``-0.335 sqrt(delta_max)`` at ``v = 0.03, 0.01, 0.003, 0.001`` (``nu = 0.3``; the table of
docs/spheres.md, section "The quasistatic limit")."""

LOW_SPEED_MODES = 1600
"""Modes summed by default: the tail beyond them is below 0.05 % of the loss at ``nu = 0.3``."""

PAIR_LOW_SPEED_MODES = 3200
"""Modes of both spheres summed by default for a pair (one common frequency cutoff): the
sphere's 1600 twice, so that two identical spheres sum each sphere's 1600 lowest."""

_SAMPLES = 81  # contact times sampled across the band (the quadrupole's phase moves <= 1.2 rad)


@dataclass(frozen=True)
class LowSpeedLoss:
    """The energy left in a sphere's modes after a slow impact, with its error band.

    Attributes
    ----------
    v : float
        Speed towards the wall, ``c``.
    nu : float
        The sphere's 3D Poisson number.
    energy_loss, energy_loss_err : float
        ``1 - epsilon^2`` (Rayleigh's estimate, Duhamel integral) and its error (band plus
        tail); :attr:`epsilon`, :attr:`epsilon_err` and :attr:`estimate` derive from them.
    band : tuple of float
        ``(low, high)`` ends of the loss as the contact time runs over its uncertainty.
    tail : float
        Twice the estimated loss in the modes beyond the ``n_modes`` summed.
    n_modes : int
        Modes summed.
    contact_time, max_compression : float
        Hertz's ``tau`` (``R / c``) and ``delta_max`` (``R``).
    spread : float
        ``kappa`` of the band.
    shares : tuple of float
        The loss left in each body's modes: ``(energy_loss,)`` on the wall, ``(first,
        second)`` for two spheres (fractions of ``(mu/2) w^2``; they add up to
        ``energy_loss``).
    """

    v: float
    nu: float
    energy_loss: float
    energy_loss_err: float
    band: tuple[float, float]
    tail: float
    n_modes: int
    contact_time: float
    max_compression: float
    spread: float
    shares: tuple[float, ...] = ()

    @property
    def epsilon(self) -> float:
        """``sqrt(1 - energy_loss)``."""
        return math.sqrt(1.0 - self.energy_loss)

    @property
    def epsilon_err(self) -> float:
        """``energy_loss_err / (2 epsilon)``."""
        return self.energy_loss_err / (2.0 * self.epsilon)

    def to_dict(self) -> dict:
        """JSON-ready: the fields, epsilon and its error after the loss's."""
        fields = list(asdict(self).items())
        at = [name for name, _ in fields].index("energy_loss_err") + 1
        eps = [("epsilon", self.epsilon), ("epsilon_err", self.epsilon_err)]
        return finite_tree(dict(fields[:at] + eps + fields[at:]))

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return Estimate(self.epsilon, self.epsilon_err, Status.QUASISTATIC)


def _asymptotic_sum(law: SphereHertzLaw, modes: ModalBody, v: float, stretch: np.ndarray):
    """The asymptotic loss at contact times ``stretch * tau``, shape (S,): the leading term of
    :func:`drive_asymptote` with the phase of the stretched time."""
    # drive_asymptote's leading term is K v^1.5 Gamma(5/2) w^-2.5 cos(w tau/2 - 5 pi/4); its
    # amplitude does not depend on tau, so evaluating it once at tau and re-phasing is exact.
    m = modes.mass
    tau = float(sphere_quasistatic_collision(law, v, mass=m).contact_time[0])
    om, C = modes.omega, modes.C
    amp = law.K * v**1.5 * math.gamma(2.5) * om**-2.5
    phase = 0.5 * np.outer(stretch, om) * tau - 1.25 * math.pi
    energy = 2.0 * C**2 / m * (amp * np.cos(phase)) ** 2
    return energy.sum(axis=1) / (0.5 * m * v**2)


def low_speed_loss(
    modes: ModalBody,
    v: float,
    *,
    spread: float = CONTACT_TIME_SPREAD,
    law: SphereHertzLaw | None = None,
) -> LowSpeedLoss:
    """Rayleigh's estimate of a sphere's vibrational loss at speed ``v``, with its error band.

    Parameters
    ----------
    modes : ModalBody
        The sphere's lowest modes (``geometry == "sphere"``), e.g.
        ``get_modes(nu, LOW_SPEED_MODES, geometry="sphere")``; at least 16.
    v : float
        Speed towards the wall, ``c``; Hertz's law must hold (``delta_max << R``).
    spread : float
        ``kappa`` of the contact time's uncertainty ``kappa sqrt(delta_max)``
        (:data:`CONTACT_TIME_SPREAD`).
    law : SphereHertzLaw, optional
        The pulse's contact law (default: the rigid wall's, or the two spheres' of a pair); a
        compliant wall's for a sphere on an elastic half-space
        (:func:`restitution.quasistatic.half_space.half_space_loss`).

    Returns
    -------
    LowSpeedLoss
    """
    if getattr(modes, "kind", modes.geometry) != SPHERE.geometry:
        raise InputError(
            f"the low-speed estimate is derived for the sphere, not for the {modes.geometry} "
            "(a disk's slow impacts: restitution.quasistatic.slow_disk)"
        )
    if len(modes) < 16:
        raise InputError(f"{len(modes)} modes are too few for the tail estimate; use >= 16")
    if not (math.isfinite(v) and v > 0) or not (math.isfinite(spread) and spread >= 0):
        raise InputError(f"need v > 0 and spread >= 0, got v = {v!r}, spread = {spread!r}")
    default, smallest = _law_of(modes)
    law = default if law is None else law
    ray = rayleigh_energy(modes, v, law)
    dmax = ray.max_compression
    width = spread * float(law.contact_radius(dmax)) / smallest
    stretch = np.linspace(1.0 - width, 1.0 + width, _SAMPLES)
    shifted = _asymptotic_sum(law, modes, v, stretch)
    at_tau = float(_asymptotic_sum(law, modes, v, np.array([1.0]))[0])
    low = ray.energy_fraction + float(shifted.min()) - at_tau
    high = ray.energy_fraction + float(shifted.max()) - at_tau
    # The mean of each mode over its phase, summed from N/2 to N (the modes sorted by
    # frequency; a pair's by one common cutoff): the tail beyond N is about as large (it falls
    # like 1/N); twice it bounds the cos^2 factor.
    order = np.argsort(modes.omega, kind="stable")
    mean = v * 2.0 * math.pi * law.E_star**2 * law.R / modes.mass**2 * modes.C**2 / modes.omega**5
    tail = 2.0 * float(mean[order[len(modes) // 2 :]].sum())
    member = getattr(modes, "member", None)
    if member is None:
        shares = (float(ray.energy_fraction),)
    else:
        shares = tuple(float(ray.mode_energy[member == i].sum()) for i in (0, 1))
    loss = ray.energy_fraction
    err = max(high - loss, loss - low) + tail
    return LowSpeedLoss(
        v=float(v),
        nu=float(modes.nu),
        energy_loss=float(loss),
        energy_loss_err=float(err),
        band=(float(low), float(high)),
        tail=tail,
        n_modes=len(modes),
        contact_time=float(ray.contact_time),
        max_compression=float(dmax),
        spread=float(spread),
        shares=shares,
    )


def _law_of(modes: ModalBody) -> tuple[SphereHertzLaw, float]:
    """Hertz's law of the sphere on the wall, or of the two spheres of a pair, and the smaller
    radius (``R1`` units; module docs)."""
    member = getattr(modes, "member", None)
    if member is None:
        return sphere_contact_law(modes.nu), 1.0
    law = sphere_pair_contact_law(
        modes.nu, modes.nu2, radius_ratio=modes.radius_ratio, modulus_ratio=modes.modulus_ratio
    )
    return law, min(modes.radii)


def asymptotic_loss(modes: ModalBody, v) -> np.ndarray:
    """The estimate from the two-term closed form of each mode's drive
    (:func:`restitution.quasistatic.hertz_sphere.drive_asymptote`) at speeds ``v``, shape (K,):
    cheap, and within ``2e-4`` of the Duhamel value below ``v = 3e-3`` (relative)."""
    law, _ = _law_of(modes)
    out = []
    for x in np.atleast_1d(np.asarray(v, dtype=float)):
        drive = drive_asymptote(law, float(x), modes.omega, mass=modes.mass)
        out.append(np.sum(2.0 * modes.C**2 / modes.mass * drive**2) / (0.5 * modes.mass * x**2))
    return np.array(out)


def interpolation_error(modes: ModalBody, speeds, *, interior: int = 3) -> np.ndarray:
    """How far PCHIP through the estimate at ``speeds`` strays from the estimate between them.

    The asymptotic loss (:func:`asymptotic_loss`) at the speeds is interpolated with
    :class:`scipy.interpolate.PchipInterpolator` (in ``v``, as a law interpolates its points) and
    compared with the asymptotic loss at ``interior`` evenly spaced speeds inside every interval.

    Returns
    -------
    numpy.ndarray, shape (K,)
        For every speed, the largest deviation found in the intervals on either side (loss,
        fraction of ``(m/2) v^2``).
    """
    v = np.asarray(speeds, dtype=float)
    if v.size < 2 or np.any(np.diff(v) <= 0):
        raise InputError("interpolation_error needs at least two increasing speeds")
    frac = np.arange(1, interior + 1) / (interior + 1)
    inside = (v[:-1, None] + frac[None, :] * np.diff(v)[:, None]).ravel()
    through = PchipInterpolator(v, asymptotic_loss(modes, v))(inside)
    gap = np.abs(through - asymptotic_loss(modes, inside)).reshape(-1, interior).max(axis=1)
    out = np.zeros(v.size)
    out[:-1] = gap
    out[1:] = np.maximum(out[1:], gap)
    return out


REACH_WALL_SPEED = SPHERE.production.groups[0].velocities[0]
"""The fastest speed (``c``) at which the sphere's law on the wall is served by this route: its
modal points begin there (0.003; up to 0.02 the modal points lie within the route's band,
tests/test_sphere_low_speed.py)."""

SLOWEST_PHASE = 11.5
"""The least ``omega_1 tau`` (the lowest mode of either sphere times the contact time) at which
the route serves two spheres. The band and the tail are drawn from the asymptote of the drive,
which holds for ``omega tau >> 1``; the sphere on the wall has ``omega_1 tau >= 41`` within its
reach. Source: the modal pairs of ``tests/data/sphere_pair_judge_*.json`` met the route within
one error down to ``omega_1 tau = 11.6`` (``R2/R1 = 2``, ``w = 0.024``); the next point
(``9.99``, ``w = 0.05``) did not."""


def _lowest_omega(nu: float, partner) -> float:
    """The lowest frequency of either sphere, ``c1 / R1``."""
    from restitution.bodies.cache import get_modes

    own = float(get_modes(nu, 8, geometry=SPHERE.geometry).omega.min())
    if partner is None:
        return own
    nu2 = partner.nu2(nu)
    other = float(get_modes(nu2, 8, geometry=SPHERE.geometry).omega.min())
    return min(own, other * partner.speed_ratio / partner.radius_ratio)


def width_reach(
    nu: float, law: SphereHertzLaw, smallest: float, mass: float, at: float = REACH_WALL_SPEED
) -> float:
    """The speed at which the contact of ``law`` (a body of ``mass``), relative to the smaller
    radius ``smallest``, is as wide as the sphere's on the rigid wall at ``at`` (default
    :data:`REACH_WALL_SPEED`): ``a / R_min`` fixes the band's width (module docs)."""
    a_max = math.sqrt(float(SPHERE.max_compression(at, nu)))
    delta = (a_max * smallest) ** 2 / law.R
    return math.sqrt(2.0 * float(law.potential(delta)) / mass)


def reach(nu: float, partner=None) -> float:
    """The fastest speed the route serves, ``c`` (for two spheres the relative speed ``w``, in
    ``c1``): the lower of two bounds.

    * The contact's width: where the contact, relative to the smaller sphere, is as wide as the
      sphere's on the wall at :data:`REACH_WALL_SPEED` (``a / R_min`` fixes the band's width,
      module docs). Two identical spheres reach twice the wall's speed; a small sphere on a
      large one reaches less (its contact widens faster), a sphere on a softer partner less,
      on a stiffer one more.
    * The slowest mode: where ``omega_1 tau`` falls to :data:`SLOWEST_PHASE` (``tau ~
      w^(-1/5)``, so the bound is ``w (omega_1 tau(w) / SLOWEST_PHASE)^5``). It binds for a
      partner much larger or softer than the first sphere, whose lowest modes are slow against
      the contact: a large enough partner is an elastic half-space, not a body that rings.
    """
    if partner is None:
        law, smallest, mass = sphere_contact_law(nu), 1.0, SPHERE_MASS
        width = float(REACH_WALL_SPEED)
    else:
        r = partner.radius_ratio
        law = sphere_pair_contact_law(
            nu, partner.nu2(nu), radius_ratio=r, modulus_ratio=partner.modulus_ratio
        )
        smallest = min(1.0, r)
        m2 = SPHERE_MASS * partner.density_ratio * r**3
        mass = SPHERE_MASS * m2 / (SPHERE_MASS + m2)
        width = width_reach(nu, law, smallest, mass)
    tau = float(sphere_quasistatic_collision(law, width, mass=mass).contact_time[0])
    phase = _lowest_omega(nu, partner) * tau
    return width * min(1.0, (phase / SLOWEST_PHASE) ** 5)
