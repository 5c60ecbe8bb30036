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
    SphereHertzLaw,
    drive_asymptote,
    sphere_contact_law,
    sphere_quasistatic_collision,
)
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.status import Status

__all__ = [
    "CONTACT_TIME_SPREAD",
    "LOW_SPEED_MODES",
    "LowSpeedLoss",
    "asymptotic_loss",
    "interpolation_error",
    "low_speed_loss",
]

CONTACT_TIME_SPREAD = 0.335
"""``kappa``: the relative uncertainty of Hertz's contact time is ``kappa sqrt(delta_max / R)``.
Source: the deviation of the modal run's contact time from Hertz's, extrapolated in ``alpha`` and
``N``, ``-0.335 sqrt(delta_max)`` at ``v = 0.03, 0.01, 0.003, 0.001`` (``nu = 0.3``; the table of
docs/spheres.md, section "The quasistatic limit")."""

LOW_SPEED_MODES = 1600
"""Modes summed by default: the tail beyond them is below 0.05 % of the loss at ``nu = 0.3``."""

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
        ``1 - epsilon^2`` (Rayleigh's estimate, Duhamel integral) and its error (band plus tail).
    epsilon, epsilon_err : float
        ``sqrt(1 - energy_loss)`` and ``energy_loss_err / (2 epsilon)``.
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
    """

    v: float
    nu: float
    energy_loss: float
    energy_loss_err: float
    epsilon: float
    epsilon_err: float
    band: tuple[float, float]
    tail: float
    n_modes: int
    contact_time: float
    max_compression: float
    spread: float

    def to_dict(self) -> dict:
        return finite_tree(asdict(self))

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
    modes: ModalBody, v: float, *, spread: float = CONTACT_TIME_SPREAD
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

    Returns
    -------
    LowSpeedLoss
    """
    if modes.geometry != SPHERE.geometry:
        raise InputError(
            f"the low-speed estimate is derived for the sphere, not for the {modes.geometry} "
            "(a disk's slow impacts: restitution.quasistatic.slow_disk)"
        )
    if len(modes) < 16:
        raise InputError(f"{len(modes)} modes are too few for the tail estimate; use >= 16")
    if not (math.isfinite(v) and v > 0) or not (math.isfinite(spread) and spread >= 0):
        raise InputError(f"need v > 0 and spread >= 0, got v = {v!r}, spread = {spread!r}")
    law = sphere_contact_law(modes.nu)
    ray = rayleigh_energy(modes, v, law)
    dmax = ray.max_compression
    width = spread * math.sqrt(dmax)
    stretch = np.linspace(1.0 - width, 1.0 + width, _SAMPLES)
    shifted = _asymptotic_sum(law, modes, v, stretch)
    at_tau = float(_asymptotic_sum(law, modes, v, np.array([1.0]))[0])
    low = ray.energy_fraction + float(shifted.min()) - at_tau
    high = ray.energy_fraction + float(shifted.max()) - at_tau
    # The mean of each mode over its phase, summed from N/2 to N: the tail beyond N is about as
    # large (it falls like 1/N); twice it bounds the cos^2 factor.
    mean = v * 2.0 * math.pi * law.E_star**2 / modes.mass**2 * modes.C**2 / modes.omega**5
    tail = 2.0 * float(mean[len(modes) // 2 :].sum())
    loss = ray.energy_fraction
    err = max(high - loss, loss - low) + tail
    eps = math.sqrt(1.0 - loss)
    return LowSpeedLoss(
        v=float(v),
        nu=float(modes.nu),
        energy_loss=float(loss),
        energy_loss_err=float(err),
        epsilon=eps,
        epsilon_err=float(err / (2.0 * eps)),
        band=(float(low), float(high)),
        tail=tail,
        n_modes=len(modes),
        contact_time=float(ray.contact_time),
        max_compression=float(dmax),
        spread=float(spread),
    )


def asymptotic_loss(modes: ModalBody, v) -> np.ndarray:
    """The estimate from the two-term closed form of each mode's drive
    (:func:`restitution.quasistatic.hertz_sphere.drive_asymptote`) at speeds ``v``, shape (K,):
    cheap, and within ``2e-4`` of the Duhamel value below ``v = 3e-3`` (relative)."""
    law = sphere_contact_law(modes.nu)
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
