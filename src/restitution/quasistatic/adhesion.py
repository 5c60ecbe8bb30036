"""JKR adhesion in the quasistatic collision: the contact, its hysteresis, the sticking speed and
epsilon(v), and the collision integrated with DOP853 (with Kelvin-Voigt damping if asked).

Units: any consistent set (the package's reduced units ``E = rho = R = 1`` of the grain, or SI).
The contact is the quasistatic one of two spheres (or a sphere and a flat) with Hertz's effective
modulus ``E*`` (``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2``), effective radius ``R`` (``1/R = 1/R1
+ 1/R2``), the reduced mass ``m`` and the work of adhesion ``w`` (energy per area). SI enters
only through :func:`reduced_work_of_adhesion` (``w`` in J/m^2 to the grain's ``E R``).

**The work of adhesion** is Dupre's: ``w = gamma1 + gamma2 - gamma12``, the work per unit area to
separate the interface into two free surfaces (``gamma1``, ``gamma2`` their surface energies,
``gamma12`` the interface's); ``w = 2 gamma`` for two identical surfaces in vacuum
(:func:`work_of_adhesion`). Beware the literature: many write the JKR law with a surface energy
per surface, ``gamma = w/2`` (LAMMPS's granular ``jkr``: ``delta = a^2/R - 2 sqrt(pi gamma a /
E)``, pull-off ``3 pi gamma R``); here every formula takes ``w`` (pull-off ``(3/2) pi w R``).

**The JKR contact** (Johnson, Kendall and Roberts 1971; Johnson, Contact Mechanics, section 5.5).
The contact radius ``a`` parametrises force and approach::

    F(a) = 4 E* a^3 / (3 R) - sqrt(8 pi w E* a^3),     delta(a) = a^2 / R - sqrt(2 pi w a / E*).

With ``l = (pi w R^2 / E*)^(1/3)``, ``x = a / l``, ``delta_s = l^2 / R`` and the force scale
``pi w R`` this is ``F = pi w R (4 x^3 / 3 - 2 sqrt(2) x^(3/2))``, ``delta = delta_s (x^2 -
sqrt(2 x))``, and every JKR number is a pure number in these units:

* zero load: ``x^3 = 9/2``, ``a0 = (9 pi w R^2 / (2 E*))^(1/3)``;
* snap-in on approach at ``delta = 0``: ``a`` jumps from 0 to ``x^3 = 2``, ``(2 pi w R^2 /
  E*)^(1/3) = 0.7631 a0``, and the force from 0 to ``-(4/3) pi w R`` (attraction);
* pull-off under load control (``dF/da = 0``): ``x^3 = 9/8``, ``F = -(3/2) pi w R``;
* pull-off under displacement control (an impact, ``d delta/da = 0``): ``x = 1/2``, ``a_c =
  l/2 = a0 / 6^(2/3)``, ``delta_c = -(3/4) delta_s = -(3/4)(pi^2 w^2 R / E*^2)^(1/3)`` and ``F_c
  = -(5/6) pi w R``: the neck breaks and the force jumps to 0.

For ``delta >= delta_c`` the stable branch ``x >= 1/2`` gives one ``a`` per ``delta`` (the root of a
quartic in ``sqrt(x)``, solved in closed form by Ferrari's resolvent cubic
``m^3 + d m - 1/4 = 0``, ``d = delta / delta_s``), so the contact is conservative there, with the
potential (energy along the branch, zero at the snap-in state)::

    U = pi w R delta_s [P(x) - P(2^(1/3))],   P(x) = 8 x^5 / 15 - (4 sqrt(2)/3) x^(7/2) + x^2.

**The hysteresis.** On approach the force is zero until ``delta = 0``; the snap-in at fixed
``delta`` does no work on the grain. Between the snap-in and the pull-off the force is the branch's,
conservative; the grain returns to ``delta = 0`` with its approach speed and then works against
the tension down to ``delta_c``. The energy lost in one cycle is therefore
``Delta W = U(delta_c) = pi w R delta_s [P(1/2) - P(2^(1/3))]``, with ``P(1/2) = 1/10`` and
``P(2^(1/3)) = -(3/5) 2^(2/3)``::

    Delta W = c (w^5 R^4 / E*^2)^(1/3),    c = pi^(5/3) (3 * 2^(2/3) / 5 + 1/10) = 7.09220
    (:data:`HYSTERESIS_CONSTANT`).

(the energies released at the snap-in and at the neck break, into waves in reality, are what
the grain does not get back). Thornton and Ning (Powder Technol. 99, 154 (1998)) quote 7.09 for
this constant (as cited by a public DEM script found by search; the search returned no text of
the paper itself), with their ``gamma`` our ``w``.

**The sticking speed and epsilon.** An elastic, otherwise lossless contact keeps
``(m/2) v^2 - Delta W``: the grain sticks below ``v_s = sqrt(2 Delta W / m)`` and above it::

    epsilon = sqrt(1 - (v_s / v)^2)  (exact in this model, at every v > v_s),

so ``1 - epsilon^2 = (v_s/v)^2``, ``1 - epsilon ~ (v_s/v)^2 / 2`` far above ``v_s``, and
``epsilon ~ sqrt(2 (v - v_s) / v_s)`` just above it (:func:`adhesive_epsilon`). For a sphere of
density ``rho`` and radius ``R`` on a rigid wall (``m = 4 pi rho R^3 / 3``)::

    v_s = k (w^5 / (rho^3 E*^2 R^5))^(1/6),  k = sqrt(3 c / (2 pi)) = 1.84018
    (:data:`STICKING_SPEED_WALL`),

Thornton and Ning's 1.84 is this ``k``: their number and ours agree when their surface energy is
the Dupre ``w`` and ``E*``, ``R``, ``m`` are those of a sphere on a rigid wall (the search returned
no text of the paper, so their definitions are inferred from the agreement). With ``gamma = w/2``
in place of ``w`` the constant would read ``2^(5/6) k = 3.279``. Two identical spheres (``R``
each, the pair's ``E* = E / (2 (1 - nu^2))``, ``R_eff = R/2``, ``m = m1/2``) meet at the
relative speed ``v_s = 2^(-1/6) k (w^5 / (rho^3 E*^2 R^5))^(1/6) = 1.63942 (...)^(1/6)``
(:data:`STICKING_SPEED_PAIR`, in the sphere's radius ``R``; ``k / 2 = 0.92009`` in ``R_eff``;
``2^(1/6) k = 2.0655`` with the wall's ``E* = E / (1 - nu^2)``): two identical spheres are one on
a rigid frictionless wall with ``w/2`` at half the speed. Fixed density: ``v_s ~ w^(5/6)
R^(-5/6) E*^(-1/3) rho^(-1/2)``.

**The integrated collision** (:func:`adhesive_collision`, the independent check of the above).
``m delta'' = -F``: the approach force-free from ``delta < 0`` to ``delta = 0`` (one DOP853 piece
ended by an event), the snap-in, then ``F = F_JKR + A delta' 2 E* a`` on the stable branch,
integrated in the contact radius ``x = a / l`` against a variable ``sigma`` with ``dt = (delta_s
/ v) g'(x) dsigma`` (``g(x) = delta / delta_s``; a Sundman transformation): the equations are then
smooth through the pull-off, where ``F(delta)`` has a square-root singularity (DOP853 stepping in
``t`` on ``delta`` lost up to 6e-7 of the energy there, in 80 runs of 40 speeds with and without
damping; in ``sigma`` the energy error stays below
1e-10 at ``rtol = 1e-10``). Events: the largest compression, the separation at ``x = 1/2``
(``delta = delta_c``), and the turn back into the contact, ``delta' = 0`` upwards, which with
``A = 0`` repeats forever: the grain is stuck. ``A`` is the Kelvin-Voigt constant of
:mod:`restitution.quasistatic.viscoelastic` (``A = tau`` for proportional viscosities). The
viscous force is ``A`` times the rate of the elastic stress at fixed contact radius, whose
resultant is the flat punch's ``2 E* a delta'`` (``dF/ddelta`` at fixed ``a``): a choice of this
package. It is Hertz's ``A delta' dF_H/ddelta`` as ``w -> 0`` (the viscous collision of
:mod:`~restitution.quasistatic.viscoelastic`, ended where ``delta`` returns to 0, its
``"compression"`` criterion, since ``delta_c -> 0``; ``a`` differs from Hertz's ``sqrt(R delta)`` by
``O(w^(1/2))``, and so does epsilon); the full ``A dF_JKR/dt`` would be infinite at the pull-off,
where ``dF/ddelta`` is. Brilliantov, Albers, Spahn and Poschel (PRE 76, 051302 (2007)) treat JKR
with viscosity; the search returned their abstract only, so their dissipative force is not
compared here.

**The pulse for the waves.** :class:`AdhesiveCollision` has the force ``F(t)`` (with or without its
viscous part), its spectrum and the energy it leaves in a body's modes (``mode_energy``, the
formula and signature of :class:`~restitution.quasistatic.plastic_collision.PulseCollision`), so a
mechanism layer can put waves on it. The JKR pulse jumps twice (``-(4/3) pi w R`` at the snap-in,
``+(5/6) pi w R`` at the neck break) and rises like ``sqrt(t_sep - t)`` before the second jump, so
``int (dF/dt)^2 dt`` (the point-force radiation into a half-space) is infinite:
:attr:`AdhesiveCollision.force_rate_integral` is ``inf``, :meth:`AdhesiveCollision.
smooth_force_rate_integral` gives the integral without the jumps and the last ``cutoff`` before
separation, which grows like ``B ln(1/cutoff)``, ``B = (2/3) (pi w R)^2 u / delta_s``
(:attr:`AdhesiveCollision.force_rate_log_coefficient`, ``u`` the rebound speed). A physical
cutoff (the contact's size over the wave speed) is the mechanism layer's to choose.

**The pulse without its jumps.** ``F(omega) = (1/(i omega)) int F'(t) e^{-i omega t} dt`` with
``F' = F'_smooth + F(0+) delta(t) - F(T-) delta(t - T)`` (``T`` the contact time); ``spectrum`` and
``mode_energy`` with ``jumps=False`` keep ``F'_smooth`` only, the force's rate along the branch
(:meth:`AdhesiveCollision.jump_free_terms` gives ``F(0+)``, ``F(T-)``). Integrated as ``int
(dF/dsigma) e^{-i omega t(sigma)} dsigma``, smooth in ``sigma``. Before the neck break ``F ~ F_c +
K sqrt(T - t)``, ``K = -2 pi w R sqrt(2 u / (3 delta_s))``, so ``|F(omega)| ~ |K| sqrt(pi) / (2
omega^(3/2))`` and the sum over a body's modes grows like the logarithm of the top frequency (the
waves of :meth:`AdhesiveCollision.smooth_force_rate_integral`, ``B = K^2 / 4``). The law of
:mod:`restitution.laws.adhesive` puts the waves on this pulse: the jumps' energy is ``Delta W``.
``jumps="only"`` gives the two steps alone (closed form), and :meth:`AdhesiveCollision.
mode_energy_parts` the modes' energy of the pulse without its jumps, of the jumps alone and of
their interference ``2 Re(F_smooth conj(F_jumps))``, which add up to the full pulse's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from restitution.errors import InputError, real
from restitution.quasistatic.hertz import QuasistaticError
from restitution.quasistatic.pulse import panel_nodes, pulse_spectrum

__all__ = [
    "HYSTERESIS_CONSTANT",
    "STICKING_SPEED_PAIR",
    "STICKING_SPEED_WALL",
    "AdhesiveCollision",
    "JKRContact",
    "adhesive_collision",
    "adhesive_epsilon",
    "reduced_work_of_adhesion",
    "sticking_speed",
    "work_of_adhesion",
]

_SQRT2 = math.sqrt(2.0)
_X_SNAP = 2.0 ** (1.0 / 3.0)  # contact radius after the snap-in, in l
_X_PULL = 0.5  # contact radius at the pull-off under displacement control, in l
_D_PULL = -0.75  # approach at the pull-off, in delta_s


def _P(x):
    """The scaled potential along the branch, ``8 x^5/15 - (4 sqrt 2/3) x^(7/2) + x^2``."""
    return 8.0 / 15.0 * x**5 - 4.0 * _SQRT2 / 3.0 * x**3.5 + x * x


HYSTERESIS_CONSTANT = math.pi ** (5.0 / 3.0) * (0.6 * 2.0 ** (2.0 / 3.0) + 0.1)
"""``c`` of ``Delta W = c (w^5 R^4 / E*^2)^(1/3)``: ``pi^(5/3) (3 2^(2/3)/5 + 1/10) = 7.09220``."""

STICKING_SPEED_WALL = math.sqrt(1.5 * HYSTERESIS_CONSTANT / math.pi)
"""``k`` of a sphere on a rigid wall, ``v_s = k (w^5 / (rho^3 E*^2 R^5))^(1/6)``: 1.84018."""

STICKING_SPEED_PAIR = STICKING_SPEED_WALL * 2.0 ** (-1.0 / 6.0)
"""``k`` of two identical spheres (relative speed; ``R`` the sphere's, ``E*`` the pair's):
1.63942."""


def _x_of(d: float) -> float:
    """The stable branch's scaled contact radius ``x >= 1/2`` at the scaled approach ``d``.

    ``d = x^2 - sqrt(2 x)`` is the quartic ``u^4 - sqrt(2) u - d = 0`` in ``u = sqrt(x)``;
    Ferrari's resolvent ``m^3 + d m - 1/4 = 0`` (one positive root for ``d >= -3/4``, taken as
    ``(1/4) / (A^2 - A B + B^2)`` of Cardano's ``A + B``, free of cancellation) factors it into
    ``u^2 - sqrt(2 m) u + m - 1/(2 sqrt m)``, whose larger root is the branch's. Below ``-3/4``
    (past the pull-off, only in trial steps) ``x = 1/2``.
    """
    if d <= _D_PULL:
        return _X_PULL
    s = math.sqrt(max(1.0 / 64.0 + d**3 / 27.0, 0.0))
    A = (0.125 + s) ** (1.0 / 3.0)
    B = -d / (3.0 * A)
    m = 0.25 / (A * A - A * B + B * B)
    u = 0.5 * (math.sqrt(2.0 * m) + math.sqrt(max(2.0 / math.sqrt(m) - 2.0 * m, 0.0)))
    return u * u


def _checked(name: str, value, *, zero: bool = False) -> float:
    bound = ">= 0" if zero else "> 0"
    x = real(value, name, bound)
    if x < 0.0 or (x == 0.0 and not zero):
        raise InputError(f"{name} must be {bound}, got {x!r}; pass a finite {name} {bound}")
    return x


def work_of_adhesion(gamma1: float, gamma2: float | None = None, gamma12: float = 0.0) -> float:
    """Dupre's work of adhesion ``w = gamma1 + gamma2 - gamma12`` (energy per area).

    ``gamma1``, ``gamma2`` the surface energies of the two bodies (``gamma2`` defaults to
    ``gamma1``), ``gamma12`` their interface energy (0 in vacuum): two identical surfaces in
    vacuum have ``w = 2 gamma``.

    >>> work_of_adhesion(0.1)
    0.2
    """
    g1 = _checked("gamma1", gamma1, zero=True)
    g2 = g1 if gamma2 is None else _checked("gamma2", gamma2, zero=True)
    g12 = _checked("gamma12", gamma12, zero=True)
    w = g1 + g2 - g12
    if w < 0.0:
        raise InputError(
            f"gamma1 + gamma2 - gamma12 = {w:g} < 0: the surfaces repel; give gamma12 <= "
            "gamma1 + gamma2"
        )
    return w


def reduced_work_of_adhesion(w_si: float, E_si: float, R_si: float) -> float:
    """``w / (E R)``: a work of adhesion in J/m^2 in the reduced units ``E = rho = R = 1`` of a
    grain of Young modulus ``E_si`` (Pa) and radius ``R_si`` (m).

    >>> f"{reduced_work_of_adhesion(0.4, 63e9, 10e-6):.4g}"
    '6.349e-07'
    """
    return _checked("w_si", w_si, zero=True) / _checked("E_si", E_si) / _checked("R_si", R_si)


@dataclass(frozen=True)
class JKRContact:
    """The JKR contact of the module docs, in consistent units.

    Attributes
    ----------
    E_star : float
        Hertz's effective modulus.
    R : float
        Effective radius of curvature.
    w : float
        Dupre's work of adhesion (energy per area; ``2 gamma`` for identical surfaces).
    mass : float or None
        The (reduced) mass of the collision; needed for the speeds only.
    """

    E_star: float
    R: float
    w: float
    mass: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "E_star", _checked("E_star", self.E_star))
        object.__setattr__(self, "R", _checked("R", self.R))
        object.__setattr__(self, "w", _checked("w", self.w, zero=True))
        if self.mass is not None:
            object.__setattr__(self, "mass", _checked("mass", self.mass))

    # -- scales and the JKR numbers ------------------------------------------------------------

    @property
    def length_scale(self) -> float:
        """``l = (pi w R^2 / E*)^(1/3)``, the unit of the contact radius."""
        return (math.pi * self.w * self.R**2 / self.E_star) ** (1.0 / 3.0)

    @property
    def compression_scale(self) -> float:
        """``delta_s = l^2 / R = (pi^2 w^2 R / E*^2)^(1/3)``."""
        return self.length_scale**2 / self.R

    @property
    def force_scale(self) -> float:
        """``pi w R``."""
        return math.pi * self.w * self.R

    @property
    def zero_load_radius(self) -> float:
        """``a0 = (9 pi w R^2 / (2 E*))^(1/3)``."""
        return 4.5 ** (1.0 / 3.0) * self.length_scale

    @property
    def snap_in_radius(self) -> float:
        """``(2 pi w R^2 / E*)^(1/3)``: the contact radius the snap-in at ``delta = 0`` jumps to."""
        return _X_SNAP * self.length_scale

    @property
    def snap_in_force(self) -> float:
        """``-(4/3) pi w R``: the force right after the snap-in."""
        return -4.0 / 3.0 * self.force_scale

    @property
    def pull_off_radius(self) -> float:
        """``a_c = l / 2 = a0 / 6^(2/3)``: the contact radius at the neck break of an impact."""
        return _X_PULL * self.length_scale

    @property
    def pull_off_compression(self) -> float:
        """``delta_c = -(3/4) delta_s < 0``: where the neck breaks under displacement control."""
        return _D_PULL * self.compression_scale

    @property
    def pull_off_force(self) -> float:
        """``F_c = -(5/6) pi w R``: the force at ``delta_c`` (displacement control)."""
        return -5.0 / 6.0 * self.force_scale

    @property
    def load_control_pull_off_force(self) -> float:
        """``-(3/2) pi w R``: the least force of the branch (the pull-off under load control)."""
        return -1.5 * self.force_scale

    @property
    def hysteresis(self) -> float:
        """``Delta W = c (w^5 R^4 / E*^2)^(1/3)``: the energy one approach and separation lose."""
        return HYSTERESIS_CONSTANT * (self.w**5 * self.R**4 / self.E_star**2) ** (1.0 / 3.0)

    @property
    def sticking_speed(self) -> float:
        """``v_s = sqrt(2 Delta W / m)``."""
        if self.mass is None:
            raise InputError("the sticking speed needs the mass; give JKRContact(..., mass=m)")
        return math.sqrt(2.0 * self.hysteresis / self.mass)

    # -- the curve ----------------------------------------------------------------------------

    def force(self, a) -> np.ndarray:
        """``F(a) = 4 E* a^3 / (3 R) - sqrt(8 pi w E* a^3)`` at contact radii ``a >= 0``."""
        a = np.asarray(a, dtype=float)
        return 4.0 * self.E_star * a**3 / (3.0 * self.R) - np.sqrt(
            8.0 * math.pi * self.w * self.E_star * a**3
        )

    def compression(self, a) -> np.ndarray:
        """``delta(a) = a^2 / R - sqrt(2 pi w a / E*)`` at contact radii ``a >= 0``."""
        a = np.asarray(a, dtype=float)
        return a * a / self.R - np.sqrt(2.0 * math.pi * self.w * a / self.E_star)

    def contact_radius(self, delta) -> np.ndarray:
        """The stable branch's ``a >= a_c`` at approaches ``delta >= delta_c`` (Ferrari's root)."""
        d = np.asarray(delta, dtype=float)
        if np.any(~np.isfinite(d)):
            raise InputError("delta must be finite; pass finite approaches")
        if np.any(d < self.pull_off_compression * (1.0 + 1e-12)):
            raise InputError(
                f"no contact below delta_c = {self.pull_off_compression:.6g}: the neck broke; "
                "pass delta >= delta_c"
            )
        if self.w == 0.0:
            return np.sqrt(self.R * np.maximum(d, 0.0))
        x = np.vectorize(_x_of, otypes=[float])(d / self.compression_scale)
        return x * self.length_scale

    def potential(self, delta) -> np.ndarray:
        """Energy stored along the branch relative to the snap-in state (``delta = 0``), at
        ``delta >= delta_c``: ``pi w R delta_s [P(x) - P(2^(1/3))]``; Hertz's ``(8/15) E*
        sqrt(R) delta^(5/2)`` for ``w = 0``."""
        if self.w == 0.0:
            d = np.maximum(np.asarray(delta, dtype=float), 0.0)
            return 8.0 / 15.0 * self.E_star * math.sqrt(self.R) * d**2.5
        x = self.contact_radius(delta) / self.length_scale
        return self.force_scale * self.compression_scale * (_P(x) - _P(_X_SNAP))

    def epsilon(self, v) -> np.ndarray:
        """``sqrt(1 - (v_s/v)^2)`` above ``v_s``, 0 below (:func:`adhesive_epsilon`)."""
        return adhesive_epsilon(v, self.sticking_speed)


def sticking_speed(E_star: float, R: float, w: float, mass: float) -> float:
    """``v_s = sqrt(2 c (w^5 R^4 / E*^2)^(1/3) / m)`` of any partner (module docs)."""
    return JKRContact(E_star, R, w, mass).sticking_speed


def adhesive_epsilon(v, v_s: float) -> np.ndarray:
    """epsilon of an elastic adhesive contact: ``sqrt(1 - (v_s/v)^2)`` for ``v > v_s``, else 0.

    ``1 - epsilon^2 = (v_s/v)^2`` exactly above ``v_s``; far above, ``1 - epsilon ~ (v_s/v)^2/2``.

    >>> round(float(adhesive_epsilon(2.0, 1.0)) ** 2, 12)
    0.75
    """
    v = np.asarray(v, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v < 0):
        raise InputError("v must be finite and >= 0; pass impact speeds")
    v_s = _checked("v_s", v_s, zero=True)
    ratio = np.divide(v_s, v, out=np.full(v.shape, np.inf), where=v > 0)
    return np.where(ratio < 1.0, np.sqrt(np.maximum(1.0 - ratio**2, 0.0)), 0.0)


# ============================================================================================
# The integrated collision
# ============================================================================================

_S_END = 400.0  # window of one piece, in the scaled time t v / D
_BISECTIONS = 60  # halvings of a piece's sigma interval when a time is mapped back to sigma
_END_ULPS = 8.0  # times this close to a piece's end (units of rounding) are its end


def _f(x):
    """Scaled force ``4 x^3/3 - 2 sqrt(2) x^(3/2)`` (``F / (pi w R)``)."""
    return 4.0 / 3.0 * x**3 - 2.0 * _SQRT2 * x**1.5


def _g1(x):
    """``d(delta/delta_s)/dx = 2 x - sqrt(1/(2 x))``: zero at the pull-off ``x = 1/2``."""
    return 2.0 * x - np.sqrt(0.5 / x)


@dataclass(frozen=True, eq=False)
class _Piece:
    """One integrated piece of the contact: DOP853's dense output of ``(x, delta'/v, t v/D,
    viscous work)`` in the variable ``sigma`` on ``[sigma0, sigma1]``."""

    sigma0: float
    sigma1: float
    sol: object

    def sigma_of(self, s: np.ndarray) -> np.ndarray:
        """The ``sigma`` of scaled times ``s`` in the piece (``t`` grows with ``sigma``),
        by bisection on the dense output. Times within :data:`_END_ULPS` rounding units of the
        piece's ends are its ends: at the neck break ``dt/dsigma -> 0`` (``t`` is quadratic in
        ``sigma`` there), so one unit of rounding in a time computed from the contact time
        moved ``sigma`` by 3e-8 and the force at the end by 7e-8 of itself (measured, tau = 0.05,
        where the dense output's BLAS kernel left the end time one unit below its own)."""
        lo = np.full(s.shape, self.sigma0)
        hi = np.full(s.shape, self.sigma1)
        for _ in range(_BISECTIONS):
            mid = 0.5 * (lo + hi)
            later = self.sol(mid)[2] > s
            hi = np.where(later, mid, hi)
            lo = np.where(later, lo, mid)
        t0, t1 = (float(t) for t in self.sol(np.array([self.sigma0, self.sigma1]))[2])
        tol = _END_ULPS * np.finfo(float).eps * max(abs(t0), abs(t1))
        out = np.where(s >= t1 - tol, self.sigma1, 0.5 * (lo + hi))
        return np.where(s <= t0 + tol, self.sigma0, out)


@dataclass(frozen=True, eq=False)
class AdhesiveCollision:
    """One collision on the JKR contact, integrated (module docs).

    Attributes
    ----------
    v : float
        Impact speed.
    epsilon : float
        Speed at separation over ``v``; 0 when stuck.
    stuck : bool
        The grain turned back into the contact before ``delta_c`` (``bounces`` times).
    contact_time : float
        Snap-in to separation (to the last turn when stuck).
    max_compression, min_compression : float
        Largest ``delta``; smallest ``delta`` reached (``delta_c`` when it separated).
    hysteresis, viscous_work : float
        ``Delta W`` and the viscous work up to the end, fractions of ``(m/2) v^2``.
    energy_error : float
        ``|kinetic + U(delta_end) + viscous - (m/2) v^2| / ((m/2) v^2)`` at the end (``U`` the
        branch's potential, :meth:`JKRContact.potential`): the integrator's check of the
        conservative branch.
    force_rate_integral : float
        ``int (dF/dt)^2 dt`` of the pulse: ``inf`` (its jumps; module docs), ``nan`` when stuck.
    force_rate_log_coefficient : float
        ``B`` of :meth:`smooth_force_rate_integral` ``~ B ln(1/cutoff)``; ``nan`` when stuck.
    tau : float
        The Kelvin-Voigt constant ``A``.
    mass : float
        The (reduced) mass.
    contact : JKRContact
    """

    v: float
    epsilon: float
    stuck: bool
    contact_time: float
    max_compression: float
    min_compression: float
    hysteresis: float
    viscous_work: float
    energy_error: float
    force_rate_integral: float
    force_rate_log_coefficient: float
    tau: float
    mass: float
    contact: JKRContact
    _pieces: tuple = field(repr=False)
    _scale: float = field(repr=False)

    def _state(self, t) -> tuple[np.ndarray, np.ndarray]:
        """``(x, delta'/v)`` at times ``t`` (within the contact; ``nan`` outside)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        s = t * self.v / self._scale
        x, y = np.full(t.shape, np.nan), np.full(t.shape, np.nan)
        for p in self._pieces:
            t0, t1 = p.sol(p.sigma0)[2], p.sol(p.sigma1)[2]
            inside = (s >= t0) & (s <= t1) & np.isnan(x)
            if np.any(inside):
                state = p.sol(p.sigma_of(s[inside]))
                x[inside], y[inside] = state[0], state[1]
        return x, y

    def trajectory(self, t) -> tuple[np.ndarray, np.ndarray]:
        """``(delta, delta')`` at times ``t`` since the snap-in, within the contact."""
        x, y = self._state(t)
        c = self.contact
        return c.compression_scale * (x * x - np.sqrt(2.0 * x)), y * self.v

    def force(self, t, *, viscous: bool = True) -> np.ndarray:
        """The contact force at times ``t`` since the snap-in, 0 outside the contact; without
        its viscous part when ``viscous`` is false."""
        t = np.asarray(t, dtype=float)
        out = np.zeros(t.shape)
        inside = (t >= 0.0) & (t <= self.contact_time)
        if np.any(inside):
            x, y = self._state(t[inside])
            out[inside] = self._force(x, y, viscous)
        return out

    def _force(self, x, y, viscous: bool) -> np.ndarray:
        c = self.contact
        F = c.force_scale * _f(x)
        if viscous:
            F = F + self.tau * y * self.v * 2.0 * c.E_star * c.length_scale * x
        return F

    def _nodes(self, top: float, per_panel: int, end_sigma: float | None = None):
        """Gauss-Legendre nodes in ``sigma`` on the contact, with their weights in ``t``
        (``dt = (delta_s / v) g'(x) dsigma``), fine enough for frequencies up to ``top``."""
        if self.stuck:
            raise InputError(
                f"the grain stuck at v = {self.v:g}: no finite pulse; ask above the sticking speed"
            )
        (p,) = self._pieces
        b = p.sigma1 if end_sigma is None else end_sigma
        grid = p.sol(np.linspace(p.sigma0, b, 257))
        rate = self.contact.compression_scale / self.v * float(np.max(_g1(grid[0])))
        sig, w = panel_nodes(p.sigma0, b, top * rate, start=True, end=True, per_panel=per_panel)
        state = p.sol(sig)
        dt = self.contact.compression_scale / self.v * _g1(state[0])
        return state, w, w * dt

    def spectrum(self, omega, *, viscous: bool | str = True, per_panel: int = 8,
                 jumps: bool | str = True) -> np.ndarray:  # fmt: skip
        """``int F(t) e^{-i omega t} dt`` at frequencies ``omega`` (shape (N,), or (N, 2) with and
        without the viscous part for ``viscous="both"``): Gauss-Legendre panels in ``sigma``, in
        which the pulse, its jumps included, is smooth.

        ``jumps=False``: the pulse without its jumps, ``(1/(i omega)) int F'_smooth(t) e^{-i omega
        t} dt``, ``F'_smooth`` the force's rate along the branch (the snap-in's and the neck
        break's delta functions left out; :meth:`jump_free_terms`), which is the full spectrum
        less ``(F(0+) - F(T-) e^{-i omega T}) / (i omega)``. Computed as ``int (dF/dsigma)
        e^{-i omega t(sigma)} dsigma``: smooth in ``sigma``, where ``F'_smooth``'s ``(T -
        t)^(-1/2)`` before the neck break is not; it falls like ``omega^(-3/2)``.

        ``jumps="only"``: the two jumps alone, that step spectrum ``(F(0+) - F(T-) e^{-i omega
        T}) / (i omega)`` in closed form (no quadrature), so that the full spectrum is the one
        without the jumps plus this."""
        omega = np.asarray(omega, dtype=float)
        if jumps == "only":
            return self._step_spectrum(omega, viscous)
        if not isinstance(jumps, bool):
            raise InputError(f"jumps must be True, False or 'only', got {jumps!r}")
        state, w_sigma, w = self._nodes(float(np.max(omega, initial=1.0)), per_panel)
        x, y = state[0], state[1]
        t = state[2] * self._scale / self.v
        if not jumps:
            if np.any(omega <= 0.0):
                raise InputError("the spectrum without the jumps needs omega > 0; pass omega > 0")
            w, pick = w_sigma, self._force_rate_sigma
        else:
            pick = self._force
        if viscous == "both":
            forces = np.stack([pick(x, y, True), pick(x, y, False)], axis=1)
        else:
            forces = pick(x, y, bool(viscous))
        out = pulse_spectrum(forces, (t, w), omega)
        if jumps:
            return out
        return out / (1j * omega.reshape(omega.shape + (1,) * (out.ndim - 1)))

    def _step_spectrum(self, omega: np.ndarray, viscous: bool | str) -> np.ndarray:
        """The jumps alone, ``(F(0+) - F(T-) e^{-i omega T}) / (i omega)`` (:meth:`spectrum`)."""
        if np.any(omega <= 0.0):
            raise InputError("the spectrum of the jumps alone needs omega > 0; pass omega > 0")
        flags = (True, False) if viscous == "both" else (bool(viscous),)
        T = self.contact_time
        cols = [(a - b * np.exp(-1j * omega * T)) / (1j * omega)
                for a, b in (self.jump_free_terms(viscous=f) for f in flags)]  # fmt: skip
        return np.stack(cols, axis=-1) if viscous == "both" else cols[0]

    def _force_rate_sigma(self, x, y, viscous: bool) -> np.ndarray:
        """``dF/dsigma`` along the branch (``dx/dsigma = y``, ``dy/dsigma = -F g'(x) delta_s /
        (m v^2)`` with the full force ``F``, the integration's right-hand side)."""
        c = self.contact
        rate = c.force_scale * (4.0 * x * x - 3.0 * _SQRT2 * np.sqrt(x)) * y
        if viscous:
            dy = -self._force(x, y, True) * _g1(x) * c.compression_scale / (self.mass * self.v**2)
            rate = rate + self.tau * self.v * 2.0 * c.E_star * c.length_scale * (y * y + x * dy)
        return rate

    def jump_free_terms(self, *, viscous: bool = True) -> tuple[float, float]:
        """``(F(0+), F(T-))``: the force right after the snap-in and right before the neck break
        (``T`` the contact time), whose steps ``F(0+)`` and ``-F(T-)`` the spectrum without the
        jumps leaves out: ``F(omega) = F_jump_free(omega) + (F(0+) - F(T-) e^{-i omega T}) / (i
        omega)``. Without damping ``(-(4/3) pi w R, -(5/6) pi w R)``."""
        if self.stuck:
            raise InputError(
                f"the grain stuck at v = {self.v:g}: no finite pulse; ask above the sticking speed"
            )
        (p,) = self._pieces
        ends = p.sol(np.array([p.sigma0, p.sigma1]))
        F = self._force(ends[0], ends[1], viscous)
        return float(F[0]), float(F[1])

    def mode_energy(self, modes, *, viscous: bool | str = True,
                    jumps: bool | str = True) -> np.ndarray:  # fmt: skip
        """The energy the pulse leaves in each of ``modes`` (``omega``, ``C``, ``mass`` in the same
        units, driven at its pole), fractions of ``(m/2) v^2``: ``C_k^2 |F(omega_k)|^2 / (m^2
        v^2)``, as :meth:`~restitution.quasistatic.plastic_collision.PulseCollision.mode_energy`.
        The jumps make ``|F| ~ 1/omega``: the sum over a body's modes does not converge as modes
        are added (module docs). ``jumps=False``: of the pulse without its jumps
        (:meth:`spectrum`), ``|F| ~ omega^(-3/2)``, whose sum grows like the logarithm of the
        set's top frequency; ``jumps="only"``: of the two jumps alone (:meth:`mode_energy_parts`
        has the interference of the two)."""
        return self._energy(modes, self.spectrum(modes.omega, viscous=viscous, jumps=jumps))

    def mode_energy_parts(self, modes, *, viscous: bool | str = True):
        """``(without_jumps, jumps_alone, interference)``: the energy per mode (each shaped as
        :meth:`mode_energy`'s) of the pulse without its jumps, of the jumps alone, and their
        interference ``C_k^2 2 Re(F_smooth conj(F_jumps)) / (m^2 v^2)``, whose sum is the full
        pulse's :meth:`mode_energy` (``|F_smooth + F_jumps|^2``). One quadrature, that of
        ``jumps=False``; the jumps' spectrum is closed (:meth:`spectrum`). The interference is
        computed from the two parts, not as the difference of the full pulse's energy and theirs,
        which loses digits where the jumps lead (high frequency)."""
        smooth = self.spectrum(modes.omega, viscous=viscous, jumps=False)
        steps = self._step_spectrum(np.asarray(modes.omega, dtype=float), viscous)
        return (self._energy(modes, smooth), self._energy(modes, steps),
                self._energy(modes, smooth, steps))  # fmt: skip

    def _energy(self, modes, F: np.ndarray, G: np.ndarray | None = None) -> np.ndarray:
        """``C_k^2 |F_k|^2 / (m^2 v^2)``, or with ``G`` the interference ``C_k^2 2 Re(F_k
        conj(G_k)) / (m^2 v^2)``."""
        C2 = modes.C**2 if F.ndim == 1 else (modes.C**2)[:, None]
        F2 = np.abs(F) ** 2 if G is None else 2.0 * np.real(F * np.conj(G))
        return C2 * F2 / (modes.mass**2 * self.v**2)

    def smooth_force_rate_integral(self, cutoff: float, *, per_panel: int = 16) -> float:
        """``int (dF_JKR/dt)^2 dt`` from the snap-in to ``cutoff`` before the separation, without
        the jumps and the viscous force; ``~ B ln(1/cutoff)`` as ``cutoff -> 0``
        (:attr:`force_rate_log_coefficient`). In ``sigma``: ``(dF/dsigma)^2 / (dt/dsigma)``."""
        cutoff = _checked("cutoff", cutoff)
        if cutoff >= self.contact_time:
            raise InputError(
                f"cutoff {cutoff:g} is not below the contact time {self.contact_time:g}; "
                "pass a shorter cutoff"
            )
        (p,) = self._pieces
        end = float(p.sigma_of(np.array([(self.contact_time - cutoff) * self.v / self._scale]))[0])
        state, _, w = self._nodes(1.0, per_panel, end)
        c = self.contact
        x, y = state[0], state[1]
        # dF/dt = (pi w R) f'(x) dx/dt, dx/dt = delta' / (delta_s g'(x)); the weights carry dt.
        rate = c.force_scale * (4.0 * x * x - 3.0 * _SQRT2 * np.sqrt(x)) * y * self.v
        rate = rate / (c.compression_scale * _g1(x))
        return float(np.sum(w * rate**2))


def _checked_contact(contact) -> JKRContact:
    if not isinstance(contact, JKRContact):
        raise InputError(f"contact must be a JKRContact, got {type(contact).__name__}")
    if contact.mass is None:
        raise InputError("the collision needs the mass; give JKRContact(..., mass=m)")
    if contact.w == 0.0:
        raise InputError(
            "w = 0 is Hertz's contact without adhesion; use restitution.quasistatic."
            "viscoelastic.viscous_collision (separation='compression') instead"
        )
    return contact


def adhesive_collision(
    contact: JKRContact,
    v: float,
    *,
    tau: float = 0.0,
    rtol: float = 1e-10,
    bounces: int = 1,
) -> AdhesiveCollision:
    """One collision at speed ``v`` on the JKR ``contact`` (with its ``mass``), with the
    Kelvin-Voigt constant ``tau`` (``A``; 0: elastic), integrated with DOP853.

    ``m delta'' = -F`` in two pieces, each DOP853 (order 8, adaptive, ``atol = 1e-3 rtol`` on
    variables of size 1) ended by events. The approach: ``delta / D`` and ``delta' / v`` against
    ``s = t v / D`` (``D`` the larger of ``|delta_c|`` and Hertz's largest compression), force-free
    from ``delta = -D/2`` to the touch ``delta = 0``. The contact, after the snap-in: the state is
    the contact radius ``x = a / l`` (``delta = delta_s g(x)``, ``g = x^2 - sqrt(2 x)``) with
    ``delta' / v``, ``s`` and the viscous work, against ``sigma`` with ``dt = (delta_s / v) g'(x)
    dsigma`` (a Sundman transformation): then ``dx/dsigma = delta'/v`` and ``d(delta'/v)/dsigma =
    -F g'(x) delta_s / (m v^2)`` are smooth through the pull-off, where ``F(delta)`` has a square
    root singularity and ``g'(1/2) = 0``. Events: the largest compression, the separation ``x =
    1/2`` (``delta = delta_c``), the turn back into the contact (``delta' = 0`` upwards, repeated
    ``bounces`` times: stuck), and ``delta = R`` (refused).

    Examples
    --------
    >>> c = JKRContact(1.0, 1.0, 1e-6, mass=4.18879)
    >>> r = adhesive_collision(c, 2.0 * c.sticking_speed)
    >>> r.stuck, abs(r.epsilon - float(c.epsilon(2.0 * c.sticking_speed))) < 1e-8
    (False, True)
    """
    contact = _checked_contact(contact)
    v = _checked("v", v)
    tau = _checked("tau", tau, zero=True)
    rtol = _checked("rtol", rtol)
    if not (isinstance(bounces, int) and not isinstance(bounces, bool) and bounces >= 1):
        raise InputError(f"bounces must be an integer >= 1, got {bounces!r}")
    m, Es, R = contact.mass, contact.E_star, contact.R
    l, ds, Fs = contact.length_scale, contact.compression_scale, contact.force_scale
    hertz = (15.0 * m * v * v / (16.0 * Es * math.sqrt(R))) ** 0.4
    D = max(-contact.pull_off_compression, hertz)
    e0 = 0.5 * m * v * v
    gF = ds / (m * v * v)  # force to d(delta'/v)/dsigma per g'(x)
    gW = 2.0 * tau * 2.0 * Es * l * ds / (m * v)  # viscous power per x (delta'/v)^2 g'(x)
    kT = ds / D  # ds/dsigma per g'(x)

    def rhs_free(s, y):
        return [y[1], 0.0]

    def touch(s, y):
        return y[0]

    touch.terminal, touch.direction = True, 1
    sol = solve_ivp(rhs_free, (-0.5, 10.0), [-0.5, 1.0], method="DOP853", rtol=rtol,
                    atol=rtol * 1e-3, events=touch)  # fmt: skip
    # The snap-in: delta (and delta') continuous, the contact radius jumps to 2^(1/3) l.
    y = [_X_SNAP, float(sol.y_events[0][0][1]), 0.0, 0.0]

    def rhs(sigma, y):
        x, u = max(y[0], 0.05), y[1]  # trial steps past the pull-off (x = 1/2) stay real
        g1 = 2.0 * x - math.sqrt(0.5 / x)
        F = Fs * (4.0 / 3.0 * x**3 - 2.0 * _SQRT2 * x**1.5) + tau * v * u * 2.0 * Es * l * x
        return [u, -gF * F * g1, kT * g1, gW * x * u * u * g1]

    def separation(sigma, y):
        return y[0] - _X_PULL

    def top(sigma, y):
        return y[1]

    def turn_in(sigma, y):
        return y[1]

    def too_deep(sigma, y):
        x = max(y[0], _X_PULL)
        return ds * (x * x - math.sqrt(2.0 * x)) - R

    separation.terminal, separation.direction = True, -1
    top.direction = -1
    turn_in.terminal, turn_in.direction = True, 1
    too_deep.terminal, too_deep.direction = True, 1
    # sigma advances like x: a piece spans at most the largest x plus the scaled window.
    window = _S_END * (1.0 + tau * v / D) * math.sqrt(max(hertz / ds, 1.0))
    pieces, sigma0, d_max, d_min = [], 0.0, 0.0, 0.0
    stuck = True
    for _ in range(bounces):
        sol = solve_ivp(rhs, (sigma0, sigma0 + window), y, method="DOP853", rtol=rtol,
                        atol=rtol * 1e-3, events=[separation, top, turn_in, too_deep],
                        dense_output=True)  # fmt: skip
        if len(sol.t_events[3]):
            raise InputError(
                f"at v = {v:g} the compression reaches R = {R:g}: far outside the contact "
                "theory; give a slower impact"
            )
        if sol.status != 1:
            raise QuasistaticError(
                f"no separation and no turn at v = {v:g}, tau = {tau:g}: {sol.message}; try a "
                "larger rtol"
            )
        sigma1 = float(sol.t[-1])
        pieces.append(_Piece(sigma0, sigma1, sol.sol))
        if len(sol.t_events[1]):
            d_max = max(d_max, float(np.max(contact.compression(sol.y_events[1][:, 0] * l))))
        y = [float(c) for c in sol.y[:, -1]]
        d_min = min(d_min, float(contact.compression(y[0] * l)))
        sigma0 = sigma1
        if len(sol.t_events[0]):
            stuck = False
            break
    x_end, u_end, s_end, w_v = y
    stored = Fs * ds * float(_P(max(x_end, _X_PULL)) - _P(_X_SNAP)) / e0
    eps = 0.0 if stuck else max(-u_end, 0.0)
    return AdhesiveCollision(
        v=v,
        epsilon=eps,
        stuck=stuck,
        contact_time=s_end * D / v,
        max_compression=d_max,
        min_compression=max(d_min, contact.pull_off_compression),
        hysteresis=contact.hysteresis / e0,
        viscous_work=w_v,
        energy_error=abs(u_end * u_end + stored + w_v - 1.0),
        force_rate_integral=math.nan if stuck else math.inf,
        force_rate_log_coefficient=math.nan if stuck else 2.0 / 3.0 * Fs * Fs * eps * v / ds,
        tau=tau,
        mass=m,
        contact=contact,
        _pieces=tuple(pieces),
        _scale=D,
    )
