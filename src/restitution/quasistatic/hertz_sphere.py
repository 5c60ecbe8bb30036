"""Three-dimensional Hertz contact of a sphere with a rigid flat wall, and the quasistatic
collision.

Units: ``E = rho = R = 1`` of the sphere's three-dimensional constants unless given; forces
``P`` in ``E R^2``; compressions ``delta`` in ``R``; speeds in ``c = sqrt(E / rho)``; times in
``R / c``; energies in ``E R^3``; the mass ``m = 4 pi rho R^3 / 3`` in ``rho R^3``.

Hertz (1882) for a sphere of radius ``R`` on a rigid half-space (the wall's compliance is zero,
so ``1 / E* = (1 - nu^2) / E``)::

    P(delta) = (4/3) E* sqrt(R) delta^(3/2) = K delta^(3/2),      E* = E / (1 - nu^2)
    V(delta) = (8/15) E* sqrt(R) delta^(5/2) = (2/5) P delta
    a = sqrt(R delta)                       (contact radius)

``delta`` is the approach of the wall to points of the sphere far from the contact (the
half-space's far field); the theory holds for ``delta << R``. The law is refused beyond
``delta = R``, where the contact radius would equal the sphere's.

The quasistatic collision ``m delta'' = -P(delta)``, ``delta(0) = 0``, ``delta'(0) = v``, in closed
form. Energy: ``delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5)``. With ``x = delta / delta_max``,
``delta' = v sqrt(1 - x^(5/2))``, so the time to reach ``x`` is, with ``w = x^(5/2)``,::

    t(x) = (delta_max / v) int_0^x du / sqrt(1 - u^(5/2))
         = (delta_max / v) (2/5) B(2/5, 1/2) I_w(2/5, 1/2)

(``I`` the regularised incomplete beta function), hence the contact time::

    tau = kappa delta_max / v,   kappa = (4/5) B(2/5, 1/2) = 2 sqrt(pi) Gamma(7/5) / Gamma(9/10)
        = 2.9432752...                                                  (CONTACT_TIME_CONSTANT)

and the trajectory ``x(t) = [I^{-1}_{2 t / tau}(2/5, 1/2)]^(2/5)`` on the first half, mirrored
about ``tau / 2`` (time reversal); the force ``P(t) = P_max x(t)^(3/2)``. The tests check it
against DOP853.

Near either end the pulse is ``P ~ K (v t)^(3/2)``; its next terms are integer powers of ``t``
(``t^4``, ...), so its Fourier transform at ``omega tau >> 1`` is set by the two ends alone
(:func:`drive_asymptote`). That is what makes the Rayleigh estimate of the sphere scale like
``v`` at low speed (:mod:`restitution.quasistatic.rayleigh`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.special import betaincinv

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.errors import InputError
from restitution.quasistatic.hertz import checked_range

__all__ = [
    "CONTACT_TIME_CONSTANT",
    "SPHERE_MASS",
    "SphereHertzLaw",
    "SphereQuasistaticCollision",
    "SphereQuasistaticTrajectory",
    "drive_asymptote",
    "sphere_contact_law",
    "sphere_pair_contact_law",
    "sphere_pair_mass",
    "sphere_quasistatic_collision",
    "sphere_quasistatic_trajectory",
]

SPHERE_MASS = 4.0 * math.pi / 3.0
"""Mass of the sphere in ``rho R^3``."""

# Exponents of the incomplete beta function of the trajectory (module docs).
_A, _B = 0.4, 0.5
# Relative slack on the law's range, so that values computed at the limit itself pass.
_SLACK = 1e-12


@dataclass(frozen=True)
class SphereHertzLaw:
    """Hertz's law ``P = (4/3) E* sqrt(R) delta^(3/2)`` of a sphere on a rigid wall.

    Attributes
    ----------
    nu : float
        Three-dimensional Poisson number of the sphere, in ``(-1, 0.5)``.
    E : float
        Young modulus, default 1.
    R : float
        Radius, default 1.
    name : str
        ``"hertz"``.
    effective_modulus : float or None
        ``E*`` of two elastic spheres, ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2``
        (:func:`sphere_pair_contact_law`; ``R`` is then their ``R_eff``); ``None``: the
        sphere on the rigid wall.
    """

    nu: float
    E: float = 1.0
    R: float = 1.0
    name: str = "hertz"
    effective_modulus: float | None = None

    geometry: ClassVar[str] = SPHERE.geometry

    @property
    def E_star(self) -> float:
        """``E* = E / (1 - nu^2)`` on the rigid wall, or the :attr:`effective_modulus` of two
        elastic bodies (:func:`sphere_pair_contact_law`), in ``E``."""
        if self.effective_modulus is not None:
            return self.effective_modulus
        return self.E / (1.0 - self.nu**2)

    @property
    def K(self) -> float:
        """``K = (4/3) E* sqrt(R)`` of ``P = K delta^(3/2)``, in ``E sqrt(R)``."""
        return 4.0 / 3.0 * self.E_star * math.sqrt(self.R)

    @property
    def max_compression(self) -> float:
        """``delta = R``: the end of the law's range (the contact radius reaches ``R``)."""
        return self.R

    @property
    def max_force(self) -> float:
        """``P(R) = K R^(3/2)``, in ``E R^2``."""
        return self.K * self.R**1.5

    def max_speed(self, mass: float = SPHERE_MASS) -> float:
        """Speed whose ``delta_max`` is ``R``, in ``c``; faster collisions are refused."""
        return math.sqrt(2.0 * float(self.potential(self.R)) / mass)

    def force(self, delta: np.ndarray | float) -> np.ndarray:
        """``P(delta) = K delta^(3/2)``, in ``E R^2``."""
        delta = self._check("compression delta", delta, self.max_compression)
        return self.K * delta**1.5

    def compression(self, P: np.ndarray | float) -> np.ndarray:
        """``delta(P) = (P / K)^(2/3)``, in ``R``."""
        P = self._check("load P", P, self.max_force)
        return (P / self.K) ** (2.0 / 3.0)

    def stiffness(self, delta: np.ndarray | float) -> np.ndarray:
        """``dP / d delta = (3/2) K sqrt(delta) = 2 E* a``, in ``E R``."""
        delta = self._check("compression delta", delta, self.max_compression)
        return 1.5 * self.K * np.sqrt(delta)

    def potential(self, delta: np.ndarray | float) -> np.ndarray:
        """``V(delta) = (2/5) K delta^(5/2)``, in ``E R^3``."""
        delta = self._check("compression delta", delta, self.max_compression)
        return 0.4 * self.K * delta**2.5

    def potential_of_force(self, P: np.ndarray | float) -> np.ndarray:
        """``V`` at load ``P``: ``(2/5) P (P / K)^(2/3)``, in ``E R^3``."""
        P = self._check("load P", P, self.max_force)
        return 0.4 * P * (P / self.K) ** (2.0 / 3.0)

    def contact_radius(self, delta: np.ndarray | float) -> np.ndarray:
        """``a = sqrt(R delta)``, in ``R``."""
        delta = self._check("compression delta", delta, self.max_compression)
        return np.sqrt(self.R * delta)

    def _check(self, what: str, value, limit: float) -> np.ndarray:
        beyond = f"where the compression reaches the radius R = {self.R:g}; Hertz's theory "
        return checked_range(what, value, limit, beyond + "needs delta << R")


def sphere_contact_law(nu: float, *, E: float = 1.0, R: float = 1.0) -> SphereHertzLaw:
    """The 3D Hertz law of a sphere of Poisson number ``nu`` (in ``(-1, 0.5)``) on a rigid wall.

    >>> round(float(sphere_contact_law(0.0).force(1e-2)), 12)
    0.001333333333
    """
    nu = SPHERE.check_nu(nu)
    for name, value in (("E", E), ("R", R)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"{name} must be a positive number, got {value}")
    return SphereHertzLaw(nu=nu, E=float(E), R=float(R))


def sphere_pair_contact_law(
    nu1: float, nu2: float | None = None, *, radius_ratio: float = 1.0, modulus_ratio: float = 1.0
) -> SphereHertzLaw:
    """Hertz's law of two spheres pressed together, in the first sphere's units.

    ``P = (4/3) E* sqrt(R_eff) delta^(3/2)``, ``delta`` the approach of the centres, with
    ``1/E* = (1 - nu1^2) + (1 - nu2^2) / E2`` and ``R_eff = R2 / (1 + R2)`` (``E2 =
    modulus_ratio``, ``R2 = radius_ratio``; Johnson, Contact Mechanics, section 4.2). Two
    identical spheres have ``E* = E / (2 (1 - nu^2))`` and ``R_eff = 1/2``: at the same force
    their approach is twice a sphere's on the rigid wall. The law's ``nu`` is ``nu1``.
    """
    nu1 = SPHERE.check_nu(nu1)
    nu2 = nu1 if nu2 is None else SPHERE.check_nu(nu2)
    for name, value in (("radius_ratio", radius_ratio), ("modulus_ratio", modulus_ratio)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"{name} must be a positive number, got {value}")
    e_star = 1.0 / ((1.0 - nu1**2) + (1.0 - nu2**2) / float(modulus_ratio))
    r2 = float(radius_ratio)
    return SphereHertzLaw(
        nu=nu1,
        R=r2 / (1.0 + r2),
        name=f"hertz (two spheres, R2/R1 = {r2:g}, E2/E1 = {float(modulus_ratio):g})",
        effective_modulus=e_star,
    )


def sphere_pair_mass(radius_ratio: float = 1.0, density_ratio: float = 1.0) -> float:
    """The reduced mass ``m1 m2 / (m1 + m2)`` of two spheres, ``rho1 R1^3`` (``m_i = (4/3) pi
    rho_i R_i^3``)."""
    for name, value in (("radius_ratio", radius_ratio), ("density_ratio", density_ratio)):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(f"{name} must be a positive number, got {value}")
    m2 = SPHERE_MASS * float(density_ratio) * float(radius_ratio) ** 3
    return SPHERE_MASS * m2 / (SPHERE_MASS + m2)


# ============================================================================================
# The quasistatic collision  m delta'' = -P(delta)
# ============================================================================================


@dataclass(frozen=True)
class SphereQuasistaticCollision:
    """Largest compression, largest force and contact time of the quasistatic collision.

    Attributes
    ----------
    v : numpy.ndarray, shape (K,)
        Incoming speed towards the wall, ``c``.
    max_compression : numpy.ndarray, shape (K,)
        ``delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5)``, ``R``.
    max_force : numpy.ndarray, shape (K,)
        ``P(delta_max)``, ``E R^2``.
    contact_time : numpy.ndarray, shape (K,)
        ``tau = kappa delta_max / v`` (:data:`CONTACT_TIME_CONSTANT`), ``R / c``.
    contact_radius : numpy.ndarray, shape (K,)
        ``a = sqrt(R delta_max)``, ``R``.
    law : str
        ``"hertz"``.
    nu : float
        Poisson number of the sphere.
    mass : float
        Sphere mass, ``rho R^3``.
    """

    v: np.ndarray
    max_compression: np.ndarray
    max_force: np.ndarray
    contact_time: np.ndarray
    contact_radius: np.ndarray
    law: str
    nu: float
    mass: float


def _check_speeds(law: SphereHertzLaw, v, mass: float) -> np.ndarray:
    v = np.atleast_1d(np.asarray(v, dtype=float))
    if not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise InputError("speeds v must be positive and finite (units of c)")
    if not (math.isfinite(mass) and mass > 0.0):
        raise InputError(f"mass must be a positive number, got {mass}")
    vmax = law.max_speed(mass)
    if np.any(v > vmax * (1.0 + _SLACK)):
        raise InputError(
            f"v = {v.max():.6g} c exceeds {vmax:.6g} c, where the Hertz compression would reach "
            f"the radius R; Hertz's theory needs delta << R: use a smaller v"
        )
    return v


def _max_compression(law: SphereHertzLaw, v: np.ndarray, mass: float) -> np.ndarray:
    """``delta_max`` from ``(2/5) K delta^(5/2) = m v^2 / 2``."""
    return np.minimum((1.25 * mass * v**2 / law.K) ** 0.4, law.max_compression)


def sphere_quasistatic_collision(
    law: SphereHertzLaw, v: np.ndarray | float, *, mass: float = SPHERE_MASS
) -> SphereQuasistaticCollision:
    """Largest compression and contact time of ``m delta'' = -P(delta)`` in closed form.

    Parameters
    ----------
    law : SphereHertzLaw
    v : array_like, shape (K,)
        Incoming speeds, ``c``, ``0 < v <= law.max_speed(mass)``.
    mass : float
        Sphere mass, default ``4 pi / 3`` (``rho = R = 1``).

    Examples
    --------
    >>> q = sphere_quasistatic_collision(sphere_contact_law(0.3), 0.01)
    >>> round(float(q.contact_time[0] * q.v[0] / q.max_compression[0]), 6)
    2.943275
    """
    v = _check_speeds(law, v, mass)
    dmax = _max_compression(law, v, mass)
    return SphereQuasistaticCollision(
        v=v,
        max_compression=dmax,
        max_force=law.force(dmax),
        contact_time=CONTACT_TIME_CONSTANT * dmax / v,
        contact_radius=law.contact_radius(dmax),
        law=law.name,
        nu=law.nu,
        mass=mass,
    )


@dataclass(frozen=True)
class SphereQuasistaticTrajectory:
    """The quasistatic collision as a function of time, in closed form (module docs).

    Attributes
    ----------
    law : SphereHertzLaw
    v : float
        Incoming speed, ``c``.
    mass : float
        Sphere mass, ``rho R^3``.
    max_compression : float
        ``delta_max``, ``R``.
    max_force : float
        ``P(delta_max)``, ``E R^2``.
    contact_time : float
        ``tau = kappa delta_max / v``, ``R / c``.
    """

    law: SphereHertzLaw
    v: float
    mass: float
    max_compression: float
    max_force: float
    contact_time: float

    def _phase(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``w = x^(5/2)`` at times ``t`` (mirrored about ``tau / 2``), and the sign of the
        velocity (+1 before closest approach)."""
        t = np.asarray(t, dtype=float)
        half = 0.5 * self.contact_time
        late = t > half
        tm = np.clip(np.where(late, self.contact_time - t, t), 0.0, half)
        return betaincinv(_A, _B, tm / half), np.where(late, -1.0, 1.0)

    def compression(self, t: np.ndarray | float) -> np.ndarray:
        """``delta(t) = delta_max w^(2/5)`` for ``t`` in ``[0, tau]`` (clipped), ``R``."""
        w, _ = self._phase(t)
        return self.max_compression * w**0.4

    def velocity(self, t: np.ndarray | float) -> np.ndarray:
        """``delta'(t) = +-v sqrt(1 - w)``, ``c``; ``+v`` at ``t = 0``, ``-v`` at ``tau``."""
        w, sign = self._phase(t)
        return sign * self.v * np.sqrt(1.0 - w)

    def force(self, t: np.ndarray | float) -> np.ndarray:
        """``P(t) = P_max w^(3/5)``, ``E R^2``; zero outside ``[0, tau]``."""
        t = np.asarray(t, dtype=float)
        w, _ = self._phase(t)
        P = self.max_force * w**0.6
        return np.where((t >= 0.0) & (t <= self.contact_time), P, 0.0)


def sphere_quasistatic_trajectory(
    law: SphereHertzLaw, v: float, *, mass: float = SPHERE_MASS
) -> SphereQuasistaticTrajectory:
    """The closed-form trajectory of ``m delta'' = -P(delta)`` at speed ``v`` (module docs)."""
    if np.ndim(v):
        raise InputError("the trajectory takes one speed v")
    q = sphere_quasistatic_collision(law, v, mass=mass)
    return SphereQuasistaticTrajectory(
        law=law,
        v=float(q.v[0]),
        mass=float(mass),
        max_compression=float(q.max_compression[0]),
        max_force=float(q.max_force[0]),
        contact_time=float(q.contact_time[0]),
    )


def drive_asymptote(
    law: SphereHertzLaw, v: float, omega: np.ndarray, *, mass: float = SPHERE_MASS
) -> np.ndarray:
    """``I(omega) = int_0^{tau/2} P(t) cos(omega (tau/2 - t)) dt`` for ``omega tau >> 1``.

    Near ``t = 0`` the equation of motion gives ``delta = v t - (4/35) (K/m) v^(3/2) t^(7/2) +
    ...``, so the pulse is ``P = K v^(3/2) t^(3/2) - (6/35) (K^2/m) v^2 t^4 + O(t^(13/2))``; the
    end ``t = tau`` is its mirror image. With ``int_0^inf t^s e^{-i omega t} dt =
    Gamma(s + 1) (i omega)^(-s-1)`` the two ends give::

        I(omega) = K v^(3/2) Gamma(5/2) omega^(-5/2) cos(omega tau / 2 - 5 pi / 4)
                   - (144/35) (K^2/m) v^2 omega^(-5) sin(omega tau / 2)
                   + O(K v^(3/2) omega^(-5/2) (omega tau)^(-5))

    The second term is ``(omega tau)^(-5/2)`` times the first: at ``v -> 0`` (``tau ~
    v^(-1/5)``) the leading term is exact to ``O(v^(1/2))``. In ``E R^3 / c``.
    """
    tr = sphere_quasistatic_trajectory(law, v, mass=mass)
    omega = np.asarray(omega, dtype=float)
    phase = 0.5 * omega * tr.contact_time
    lead = law.K * tr.v**1.5 * math.gamma(2.5) * omega**-2.5 * np.cos(phase - 1.25 * math.pi)
    return lead - 144.0 / 35.0 * law.K**2 / mass * tr.v**2 * omega**-5.0 * np.sin(phase)
