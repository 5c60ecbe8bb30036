"""Thornton's elastic-perfectly-plastic sphere: the yield speed and epsilon(v) in closed form.

Units: any consistent set (the package's reduced units ``E = rho = R = 1`` of the first body, or
SI). The contact is the quasistatic one of two spheres (or a sphere and a flat), described by
Hertz's effective modulus ``E*`` (``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2``), effective radius
``R`` (``1/R = 1/R1 + 1/R2``), the reduced mass ``m`` and the limiting contact pressure ``p_y``.

**Loading** (Thornton, J. Appl. Mech. 64, 383 (1997)). Hertz's law ``F = (4/3) E* sqrt(R)
delta^(3/2)`` holds until its largest pressure ``p0 = (2 E* / pi) sqrt(delta / R)`` reaches
``p_y``, at::

    delta_y = R (pi p_y / (2 E*))^2,
    F_y = (4/3) E* sqrt(R) delta_y^(3/2) = (2/3) pi p_y R delta_y.

Beyond it the pressure is capped at ``p_y`` and the force grows linearly with the slope Hertz's
law has at ``delta_y`` (``dF/ddelta = 2 E* a_y = pi p_y R``)::

    F = F_y + pi p_y R (delta - delta_y) = F_y (3 delta / delta_y - 1) / 2.

**Unloading** is Hertz's law of an enlarged radius ``R_p`` from the permanent indentation
``delta_p``: ``F = (4/3) E* sqrt(R_p) (delta - delta_p)^(3/2)``, with the contact radius at the
turning point kept, ``a_p^2 = R delta_max = (2 F_max + F_y) / (2 pi p_y)``, so
``R_p = 4 E* a_p^3 / (3 F_max)`` and ``delta_max - delta_p = 3 F_max / (4 E* a_p)``. A collision
that stays below ``delta_y`` unloads along Hertz's law (``R_p = R``, ``delta_p = 0``).

**The yield speed** is the speed that just reaches ``delta_y``: ``(m/2) v_y^2 = (2/5) F_y
delta_y``, so::

    v_y^2 = (16/15) E* sqrt(R) delta_y^(5/2) / m = (pi^5 / 30) p_y^5 R^3 / (E*^4 m).

For a sphere on a rigid wall (``m = (4/3) pi rho R^3``) this is ``v_y = sqrt(pi^4 / 40)
sqrt(p_y^5 / (E*^4 rho)) = 1.5605 ...``, the constant Thornton and Ning (1998) quote; for any
other partner the effective ``E*``, ``R`` and ``m`` enter (:func:`yield_speed`).

**epsilon in closed form.** With ``s = (v / v_y)^2 >= 1`` and ``x = delta_max / delta_y``, the work
of loading is ``(m/2) v^2 = F_y delta_y [2/5 + (3/4)(x^2 - 1) - (x - 1)/2]``, so
``15 x^2 - 10 x + 3 - 8 s = 0``, ``x = (1 + sqrt((24 s - 4) / 5)) / 3``. The work returned on
unloading is ``(2/5) F_max (delta_max - delta_p) = (3/10) F_max^2 / (E* a_p)``, with ``F_max = F_y
(3 x - 1) / 2`` and ``a_p = a_y sqrt(x)``; divided by the work of loading::

    epsilon^2 = (3 x - 1)^2 / (4 s sqrt(x)),

equal to Thornton's printed form (the tests compare the two) and to 1 at ``v = v_y``. For
``v >> v_y``, ``x ~ sqrt(8 s / 15)`` and::

    epsilon ~ (3/2) (8/15)^(3/8) (v_y / v)^(1/4) = 1.18499 (v_y / v)^(1/4)

(:data:`HIGH_SPEED_CONSTANT`; Johnson's 1.185).

**From a yield stress.** The first yield of a Hertz contact is below the surface, on the axis,
where ``|sigma_z - sigma_r|`` (Tresca's and von Mises's measure there, ``sigma_theta =
sigma_r``) is largest; with Hertz's stresses on the axis (Johnson, Contact Mechanics, eq. 3.45),
``sigma_z / p0 = -1 / (1 + zeta^2)``, ``sigma_r / p0 = -(1 + nu)(1 - zeta arctan(1 / zeta)) +
1 / (2 (1 + zeta^2))``, ``zeta = z / a``. Yield begins when ``p0 = Y / max_zeta |sigma_z -
sigma_r| / p0``: 1.613 Y at ``nu = 0.3`` (at ``z = 0.48 a``; Johnson quotes ``1.60 Y``)
(:func:`onset_pressure_ratio`). Thornton's model caps the pressure at ``p_y`` from there on;
taking ``p_y`` as the onset pressure is this package's reading of a yield stress (``limiting
pressure`` gives ``p_y`` directly).

**Cylinders.** Two-dimensional contacts have no comparable closed form here: Thornton's model is
built on Hertz's 3D pressure and its contact radius; no 2D law is derived or invented
(:func:`restitution.laws.plastic` refuses disks and cylinders). Where plastic flow *starts* is
derived all the same, so that an elastic answer can say from which speed it is an upper bound.
A line contact of half-width ``b`` carries Hertz's pressure ``p0 = 2 P / (pi b)``, ``b^2 = 4 P R /
(pi E*)``, so ``P = pi R p0^2 / E*`` (Johnson, eq. 4.45); on the axis (Johnson, eq. 4.49)
``sigma_x / p0 = -((1 + 2 zeta^2) / sqrt(1 + zeta^2) - 2 zeta)``, ``sigma_z / p0 = -1 / sqrt(1 +
zeta^2)``, ``zeta = z / b``, and ``sigma_y = nu (sigma_x + sigma_z)`` in plane strain (a long
cylinder), 0 in plane stress (a thin disk). Von Mises's stress is largest at ``z = 0.70 b`` in
plane strain, where yield begins at ``p0 = 1.794 Y`` (``nu = 0.3``; Johnson quotes 1.79 Y), and
at the surface in plane stress, ``p0 = Y`` (:func:`line_onset_pressure_ratio`). The speed that
reaches it is the 2D law's (:func:`line_yield_speed`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from restitution.errors import InputError

__all__ = [
    "HIGH_SPEED_CONSTANT",
    "YIELD_SPEED_CONSTANT",
    "ThorntonContact",
    "line_onset_pressure_ratio",
    "line_yield_speed",
    "onset_pressure_ratio",
    "thornton_epsilon",
    "yield_speed",
]

HIGH_SPEED_CONSTANT = 1.5 * (8.0 / 15.0) ** 0.375
"""``epsilon (v / v_y)^(1/4)`` as ``v / v_y -> infinity``: ``(3/2)(8/15)^(3/8) = 1.18499``."""

YIELD_SPEED_CONSTANT = math.sqrt(math.pi**4 / 40.0)
"""``v_y / sqrt(p_y^5 / (E*^4 rho))`` of a sphere on a rigid wall: ``sqrt(pi^4/40) = 1.5605``."""


def _positive(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(f"{name} must be a number, got {value!r}")
    value = float(value)
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"{name} must be a finite number > 0, got {value!r}")
    return value


@dataclass(frozen=True)
class ThorntonContact:
    """Thornton's elastic-perfectly-plastic contact (module docs), in consistent units.

    Attributes
    ----------
    E_star : float
        Hertz's effective modulus.
    R : float
        Effective radius of curvature.
    p_y : float
        Limiting contact pressure (the same unit as ``E_star``).
    mass : float
        The (reduced) mass of the collision.
    """

    E_star: float
    R: float
    p_y: float
    mass: float

    def __post_init__(self) -> None:
        for name in ("E_star", "R", "p_y", "mass"):
            object.__setattr__(self, name, _positive(name, getattr(self, name)))
        if self.p_y >= self.E_star:
            raise InputError(
                f"a limiting pressure p_y = {self.p_y:.3g} at or above E* = {self.E_star:.3g}: no "
                "material yields there (the ideal strength is about E/10)"
            )

    @property
    def K(self) -> float:
        """Hertz's constant ``(4/3) E* sqrt(R)``."""
        return 4.0 / 3.0 * self.E_star * math.sqrt(self.R)

    @property
    def yield_compression(self) -> float:
        """``delta_y = R (pi p_y / (2 E*))^2``."""
        return self.R * (math.pi * self.p_y / (2.0 * self.E_star)) ** 2

    @property
    def yield_force(self) -> float:
        """``F_y = (2/3) pi p_y R delta_y``."""
        return 2.0 / 3.0 * math.pi * self.p_y * self.R * self.yield_compression

    @property
    def yield_speed(self) -> float:
        """``v_y``: the speed whose Hertz collision just reaches ``delta_y``."""
        return math.sqrt(0.8 * self.yield_force * self.yield_compression / self.mass)

    @property
    def plastic_stiffness(self) -> float:
        """The slope of plastic loading, ``pi p_y R``."""
        return math.pi * self.p_y * self.R

    def loading_force(self, delta):
        """``F(delta)`` on first loading (Hertz below ``delta_y``, linear above)."""
        d = np.maximum(np.asarray(delta, dtype=float), 0.0)
        dy = self.yield_compression
        return np.where(d <= dy, self.K * d**1.5, self.yield_force * (1.5 * d / dy - 0.5))

    def unloading(self, max_compression: float) -> tuple[float, float]:
        """``(R_p, delta_p)`` of the unloading branch after loading to ``max_compression``."""
        dmax = float(max_compression)
        if dmax <= self.yield_compression:
            return self.R, 0.0
        f_max = float(self.loading_force(dmax))
        a_p = math.sqrt(self.R * dmax)
        r_p = 4.0 * self.E_star * a_p**3 / (3.0 * f_max)
        return r_p, dmax - 3.0 * f_max / (4.0 * self.E_star * a_p)

    def epsilon(self, v) -> np.ndarray:
        """Thornton's epsilon at speeds ``v`` (module docs): 1 up to ``v_y``."""
        u = np.asarray(v, dtype=float) / self.yield_speed
        return thornton_epsilon(u)

    def high_speed_epsilon(self, v) -> np.ndarray:
        """The limit ``1.18499 (v_y / v)^(1/4)`` (:data:`HIGH_SPEED_CONSTANT`)."""
        return HIGH_SPEED_CONSTANT * (self.yield_speed / np.asarray(v, dtype=float)) ** 0.25

    def plastic_loss(self, v) -> np.ndarray:
        """``1 - epsilon^2``: the fraction of the kinetic energy the plastic flow keeps."""
        return 1.0 - self.epsilon(v) ** 2


def thornton_epsilon(u) -> np.ndarray:
    """epsilon of Thornton's contact at ``u = v / v_y`` (any shape; 1 where ``u <= 1``)."""
    u = np.asarray(u, dtype=float)
    if np.any(~np.isfinite(u)) or np.any(u < 0):
        raise InputError("v / v_y must be finite and >= 0")
    s = np.maximum(u, 1.0) ** 2
    x = (1.0 + np.sqrt((24.0 * s - 4.0) / 5.0)) / 3.0
    eps = (3.0 * x - 1.0) / (2.0 * np.sqrt(s) * x**0.25)
    return np.where(u <= 1.0, 1.0, eps)


def yield_speed(E_star: float, R: float, p_y: float, mass: float) -> float:
    """``v_y = sqrt((pi^5 / 30) p_y^5 R^3 / (E*^4 m))`` of any partner (module docs)."""
    return ThorntonContact(E_star, R, p_y, mass).yield_speed


def onset_pressure_ratio(nu: float) -> float:
    """``p0 / Y`` at first yield of a Hertz contact of Poisson number ``nu`` (module docs):
    1.613 at ``nu = 0.3``."""
    if isinstance(nu, bool) or not isinstance(nu, (int, float, np.integer, np.floating)):
        raise InputError(f"nu must be a number, got {nu!r}")
    nu = float(nu)
    if not -1.0 < nu <= 0.5:
        raise InputError(f"the 3D Poisson number must lie in (-1, 0.5], got {nu}")

    def minus_difference(zeta: float) -> float:
        sz = -1.0 / (1.0 + zeta * zeta)
        sr = -(1.0 + nu) * (1.0 - zeta * math.atan(1.0 / zeta)) + 0.5 / (1.0 + zeta * zeta)
        return -abs(sz - sr)

    best = minimize_scalar(minus_difference, bounds=(1e-6, 5.0), method="bounded",
                           options={"xatol": 1e-10})  # fmt: skip
    return 1.0 / -float(best.fun)


def line_onset_pressure_ratio(nu: float, plane: str) -> float:
    """``p0 / Y`` at first yield (von Mises) of a line contact of 3D Poisson number ``nu`` in
    ``plane`` ``"strain"`` (a long cylinder) or ``"stress"`` (a thin disk) (module docs): 1.794
    and 1 at ``nu = 0.3``."""
    if plane not in ("strain", "stress"):
        raise InputError(f"plane must be 'strain' or 'stress', got {plane!r}")
    nu = float(nu)
    if not -1.0 < nu <= 0.5:
        raise InputError(f"the 3D Poisson number must lie in (-1, 0.5], got {nu}")

    def minus_mises(zeta: float) -> float:
        root = math.sqrt(1.0 + zeta * zeta)
        sx = -((1.0 + 2.0 * zeta * zeta) / root - 2.0 * zeta)
        sz = -1.0 / root
        sy = nu * (sx + sz) if plane == "strain" else 0.0
        return -math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))

    best = minimize_scalar(minus_mises, bounds=(0.0, 5.0), method="bounded",
                           options={"xatol": 1e-10})  # fmt: skip
    return 1.0 / -float(min(best.fun, minus_mises(0.0)))


def line_yield_speed(law, p0: float, mass: float) -> float:
    """The speed whose quasistatic collision on the 2D contact ``law``
    (:class:`restitution.quasistatic.hertz.HertzLaw`, ``E`` its 2D modulus and ``E*`` of a disk
    on a rigid wall, ``R`` its radius) just reaches the largest pressure ``p0`` (module docs):
    ``(m/2) v^2 = V(P)``, ``P = pi R p0^2 / E``; per unit thickness, in the law's units."""
    force = math.pi * law.R * _positive("p0", p0) ** 2 / law.E
    return math.sqrt(2.0 * float(law.potential_of_force(force)) / _positive("mass", mass))
