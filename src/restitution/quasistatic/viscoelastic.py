"""Material damping in the quasistatic collision: a Kelvin-Voigt material with one relaxation time.

Units: the body's reduced units ``E = rho = R = 1`` (a disk's two-dimensional plane-stress
constants, :mod:`restitution.quasistatic.hertz`; a sphere's three-dimensional ones,
:mod:`restitution.quasistatic.hertz_sphere`; a pair of disks in the first disk's,
:mod:`restitution.quasistatic.hertz_pair`). Speeds in ``c = sqrt(E / rho)``, times (``tau``,
``A``, contact times) in ``R / c``, compressions in ``R``, energies in ``E R^2`` (disk, per unit
thickness) or ``E R^3`` (sphere). Nothing here converts to SI.

The material. The viscous stress is ``tau`` times the rate of the elastic stress: shear
viscosity ``eta = tau mu`` and bulk viscosity ``zeta = tau K`` (``mu``, ``K`` the shear and bulk
moduli), the material of :class:`restitution.bodies.viscoelastic.Viscoelastic`. In the
quasistatic approximation the displacement field is the static one at the current compression
``xi(t)``, so the viscous stress is ``tau d/dt`` of the static stress and the contact force is::

    F = F_el(xi) + A xi' F_el'(xi),        A = tau                                          (1)

for any body and any force law (the contact pressure vanishes at the edge of the contact, so
``d/dt`` passes through the integral over the growing contact). Brilliantov, Spahn, Hertzsch
and Poschel (PRE 53, 5382 (1996)) derived (1) for 3D Hertz with two independent viscosities::

    A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) * (1 - nu^2)(1 - 2 nu) / (E nu^2)      (2)

with ``sigma'_ij = eta1 (u'_ij - delta_ij u'_ll / 3) + eta2 delta_ij u'_ll``, i.e.
``eta1 = 2 eta`` (twice the Newtonian shear viscosity) and ``eta2 = zeta``, the form of the
elastic stress ``E1 (u_ij - delta_ij u_ll / 3) + E2 delta_ij u_ll``, ``E1 = E / (1 + nu)``,
``E2 = E / (3 (1 - 2 nu))``. With ``eta1 = tau E1``, ``eta2 = tau E2`` eq. (2) is ``tau``
exactly (:func:`dissipative_constant`, :func:`proportional_viscosities`; the tests check it at
several ``nu``). Where this comes from: eq. (2) as printed in Ramirez, Poschel, Brilliantov and
Schwager (PRE 60, 4465 (1999), arXiv cond-mat/9905382, its eq. (4); text seen at
https://ru.scribd.com/document/419574380/Ramirez-2008), which says only that "the viscous
constants eta1, eta2 relate the dissipative stress tensor to the deformation rate tensor". The
search returned no text defining them, so the convention above is fixed by (1): of the two
readings ``eta1 = 2 eta`` and ``eta1 = eta``, only the first gives ``A = tau`` for proportional
viscosities (the second would make ``A`` diverge like ``1/nu^2`` as ``nu -> 0``). Eq. (2) is a
3D Hertz result; for the disk's 2D law only the proportional case, ``A = tau`` from (1), is
derived. Goldobin, Susloparov, Pimenova and Brilliantov (EPJ E 2015; summary at
http://lab16.icmm.ru/en/archives/511) criticise (2) for fixed viscosities (it vanishes as
``nu -> 1/2``); ``A = tau`` of proportional viscosities has no such limit.

The collision. ``m xi'' = -F_el(xi) - A xi' F_el'(xi)``, ``xi(0) = 0``, ``xi'(0) = v``, with
the body's quasistatic law (3D Hertz for a sphere on a wall, the paper's 2D law eq. (57) for a
disk, inverted exactly with Lambert W, the pair law for two disks), integrated with DOP853
(:func:`viscous_collision`). Two ways to end the contact (:data:`SEPARATIONS`):

* ``"compression"``: the contact ends when ``xi`` returns to 0, the criterion of the earlier
  calculations (Ramirez et al. 1999) that Schwager and Poschel (2008) revisited (the search
  returned no text of either stating it; the series below are consistent with it). Near the end
  ``A |xi'| F_el' > F_el`` and the force (1) pulls the body back: the wall is sticky.
* ``"force"`` (default): the contact ends when the total force (1) first reaches zero; the body
  leaves with the speed it has then, ``xi > 0``, and its surface recovers afterwards ("delayed
  recovery", Schwager and Poschel, PRE 78, 051304 (2008); the same rule is the end of contact in
  Thornton's Hertzian dashpot, https://gitlab.com/yade-dev/trunk/-/merge_requests/919, and a
  public C implementation of (1) found by search clips the force at zero citing Poschel and
  Schwager, Computational Granular Dynamics, p. 22). The modal model of this package has a
  purely repulsive contact (the wall only pushes), so this is the criterion consistent with
  it. The elastic energy ``V(xi_sep)`` still stored at separation never returns to the flight
  (:attr:`ViscousCollision.stored_energy`).

The sphere at low speed. With ``alpha = K / m`` (``F_el = K xi^(3/2)``) and
``q = (3/2) A alpha^(2/5) v^(1/5)`` the equation depends on ``q`` alone, and::

    epsilon = 1 - C1 q + C2 q^2 + h q^(5/2) + O(q^3)                                      (3)

``C1 = sqrt(pi) Gamma(3/5) / (2^(1/5) 5^(2/5) Gamma(21/10)) = 1.1534489`` and
``C2 = 3 C1^2 / 5 = 0.7982666`` (the tests refit ``C2`` from the equation of motion to
``1e-4``; Ramirez et al. print 1.15344 and 0.79826 with
``(3/2) A alpha^(2/5)``; a public script found by search that implements the [1/4] Pade
approximant of Muller and Poschel, PRE 84, 021302 (2011), uses
``v*^2 = (3/2) A (rho/m_eff)^(2/5) v^(1/5)`` with the Hertz constant ``rho``, the same ``q``).
``h = 0`` for ``"compression"`` and ``h = 4/15`` for ``"force"``: derived here (module notes
below) and identical to the ``v*^5`` coefficient of that Pade approximant,
``a_1 b_4 = 0.501086 * 0.532178 = 0.26667``. The search tool returned neither the text of
Schwager and Poschel 2008 nor of Muller and Poschel 2011, only that script.

The disk. Schwager, "Coefficient of restitution for viscoelastic disks", PRE 75, 051305 (2007),
arXiv cond-mat/0701142: the search returned its abstract and introduction only
(https://www.arxiv-vanity.com/papers/cond-mat/0701142/: two identical disks, "a known law for the
elastic part ... and the viscoelastic damping model", epsilon "approaches one for small
velocities and decreases for increasing velocities"), not its formulas, so nothing of it is
implemented. In their place, the first order in ``A`` (:func:`loss_slope`, any law): the
dissipated work along the elastic trajectory gives::

    1 - epsilon = A S(v) + O(A^2),   S(v) = (2 / (m v^2)) int_0^xi_max F_el'(xi) xi'_el(xi) d xi,
    xi'_el = sqrt(v^2 - 2 V(xi) / m),

and a closed form of it (:func:`loss_slope_estimate`): for ``F_el = K xi^(1+e)`` exactly::

    S = 2 (1+e) sqrt((2+e)/2) B((1+e)/(2+e), 3/2) / (2+e) * sqrt(F_el(xi_max) / (m xi_max)),

exact for the sphere (``e = 1/2``, where it is ``C1 (3/2) alpha^(2/5) v^(1/5)``); for the disk
with the local exponent ``e = 1/(Lambda - 1)`` at ``xi_max`` it is off by ``O(e^2)``
(``e ~ 1/ln(4R/xi_max)``). Its ``e -> 0`` limit is the linear oscillator's
``(pi/2) sqrt(k/m)``, ``k = pi E / Lambda``: ``1 - epsilon ~ A / sqrt(ln(1/v))`` tends to 0
as ``v -> 0``, slowly, as Schwager's abstract says.

Notes: the ``q^(5/2)`` term. Where ``xi < xi_c = (3/2) A |xi'|`` the sphere's force (1) pulls.
Under ``"compression"`` the body crosses that layer pulled, at speed ``~ v``, taking the impulse
``int_0^xi_c K xi^(1/2) (xi - xi_c) d xi / v = -(4/15) K xi_c^(5/2) / v``, so it leaves slower by
``(4/15) alpha ((3/2) A v)^(5/2) / v``: ``epsilon_force - epsilon_compression = (4/15) q^(5/2)``
to leading order. The perturbation series of ``"compression"`` runs in integer powers of ``q``
(the tests find its ``q^3`` coefficient near ``-0.52``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import beta, gamma, lambertw

from restitution.errors import InputError
from restitution.quasistatic.hertz import HertzLaw, QuasistaticError, quasistatic_collision
from restitution.quasistatic.hertz_pair import pair_contact_law, pair_mass
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    SphereHertzLaw,
    sphere_quasistatic_collision,
)

__all__ = [
    "C1",
    "C2",
    "DELAYED_RECOVERY",
    "SEPARATIONS",
    "ViscousCollision",
    "dissipative_constant",
    "loss_slope",
    "loss_slope_estimate",
    "pair_viscous_collision",
    "proportional_viscosities",
    "sphere_damping_parameter",
    "sphere_viscous_expansion",
    "tau_from_epsilon",
    "viscous_collision",
]

SEPARATIONS = ("force", "compression")
"""End of contact: the total force reaches zero (default), or the compression returns to zero."""

C1 = math.sqrt(math.pi) * gamma(0.6) / (2.0**0.2 * 5.0**0.4 * gamma(2.1))
"""First coefficient of eq. (3), 1.1534489 (Ramirez et al. 1999 print 1.15344)."""

C2 = 0.6 * C1**2
"""Second coefficient of eq. (3), ``3 C1^2 / 5 = 0.7982666`` (Ramirez et al. print 0.79826)."""

DELAYED_RECOVERY = 4.0 / 15.0
"""Coefficient of ``q^(5/2)`` in eq. (3) under the ``"force"`` criterion (module notes)."""

# End of the scaled integration window, in units of the elastic xi_max / v, per unit of the
# damping parameter tau v / xi_max (a strongly damped restitution is slow).
_S_END = 200.0


def _positive(name: str, value, *, allow_zero: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(f"{name} must be a number, got {value!r}")
    value = float(value)
    if not math.isfinite(value) or value < 0.0 or (value == 0.0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise InputError(f"{name} must be finite and {bound}, got {value!r}")
    return value


def _poisson_3d(nu) -> float:
    if isinstance(nu, bool) or not isinstance(nu, (int, float, np.integer, np.floating)):
        raise InputError(f"nu must be a number, got {nu!r}")
    nu = float(nu)
    if not -1.0 < nu < 0.5:
        raise InputError(f"the 3D Poisson number must lie in (-1, 0.5), got nu = {nu}")
    return nu


# ============================================================================================
# The dissipative constant
# ============================================================================================


def dissipative_constant(shear_viscosity: float, bulk_viscosity: float, E: float, nu: float):
    """Brilliantov et al.'s ``A`` of a 3D Hertz contact, eq. (2) of the module docs, in time units.

    Parameters
    ----------
    shear_viscosity : float
        Newtonian shear viscosity ``eta`` (``sigma'_ij = 2 eta (u'_ij - delta_ij u'_ll/3) + ...``),
        so that Brilliantov's ``eta1 = 2 eta``; in ``E`` times the time unit.
    bulk_viscosity : float
        Bulk viscosity ``zeta`` (``+ zeta delta_ij u'_ll``), Brilliantov's ``eta2``.
    E : float
        Young modulus.
    nu : float
        3D Poisson number in ``(-1, 0.5)``, not 0: there eq. (2) is ``0/0`` for proportional
        viscosities (``A = tau``) and infinite otherwise.

    Returns
    -------
    float
        ``A``, in the time unit of ``viscosity / E``.

    Examples
    --------
    >>> eta, zeta = proportional_viscosities(0.02, 1.0, 0.3)
    >>> round(dissipative_constant(eta, zeta, 1.0, 0.3), 12)
    0.02
    """
    eta = _positive("shear_viscosity", shear_viscosity, allow_zero=True)
    zeta = _positive("bulk_viscosity", bulk_viscosity, allow_zero=True)
    E = _positive("E", E)
    nu = _poisson_3d(nu)
    if nu == 0.0:
        raise InputError(
            "eq. (2) for A is 0/0 at nu = 0 with proportional viscosities (then A = tau) and "
            "infinite otherwise; use A = tau, or a nu slightly off 0"
        )
    eta1, eta2 = 2.0 * eta, zeta
    if 3.0 * eta2 + 2.0 * eta1 == 0.0:
        return 0.0
    shape = (3.0 * eta2 - eta1) ** 2 / (3.0 * (3.0 * eta2 + 2.0 * eta1))
    return shape * (1.0 - nu**2) * (1.0 - 2.0 * nu) / (E * nu**2)


def proportional_viscosities(tau: float, E: float, nu: float) -> tuple[float, float]:
    """``(eta, zeta) = (tau mu, tau K)``: the shear and bulk viscosities of a Kelvin-Voigt
    material of relaxation time ``tau`` (``mu = E / (2 (1 + nu))``, ``K = E / (3 (1 - 2 nu))``).

    With them :func:`dissipative_constant` returns ``tau`` exactly at every ``nu``.
    """
    tau = _positive("tau", tau, allow_zero=True)
    E = _positive("E", E)
    nu = _poisson_3d(nu)
    return tau * E / (2.0 * (1.0 + nu)), tau * E / (3.0 * (1.0 - 2.0 * nu))


# ============================================================================================
# The damped quasistatic collision
# ============================================================================================


@dataclass(frozen=True)
class ViscousCollision:
    """The quasistatic collision with the dissipative force (1), for speeds ``v``.

    Attributes
    ----------
    v : numpy.ndarray, shape (K,)
        Incoming speed towards the wall (the relative speed for a pair), ``c``.
    epsilon : numpy.ndarray, shape (K,)
        Coefficient of restitution from damping alone: speed at separation over ``v``.
    contact_time : numpy.ndarray, shape (K,)
        Time from first touch to separation, ``R / c``.
    max_compression : numpy.ndarray, shape (K,)
        Largest ``xi``, ``R``.
    separation_compression : numpy.ndarray, shape (K,)
        ``xi`` at separation, ``R``: 0 for ``"compression"``, positive for ``"force"``.
    dissipated_work : numpy.ndarray, shape (K,)
        ``int A F_el'(xi) xi'^2 dt`` up to separation, as a fraction of ``m v^2 / 2``.
    stored_energy : numpy.ndarray, shape (K,)
        ``V(xi_sep)``, the elastic energy left in the body at separation (it never returns to
        the flight), as a fraction of ``m v^2 / 2``.
    energy_error : numpy.ndarray, shape (K,)
        ``|epsilon^2 + dissipated_work + stored_energy - 1|``: the integrator's energy balance.
    elastic_max_compression, elastic_contact_time : numpy.ndarray, shape (K,)
        The undamped collision's, ``R`` and ``R / c`` (the ``A -> 0`` limits).
    tau : float
        The dissipative constant ``A`` (``= tau`` for proportional viscosities), ``R / c``.
    separation : str
        One of :data:`SEPARATIONS`.
    law : str
        Name of the contact law.
    geometry : str
        ``"disk"`` or ``"sphere"`` (a pair of disks is ``"disk"``).
    mass : float
        The (reduced) mass, ``rho R^2`` (disk) or ``rho R^3`` (sphere).
    """

    v: np.ndarray
    epsilon: np.ndarray
    contact_time: np.ndarray
    max_compression: np.ndarray
    separation_compression: np.ndarray
    dissipated_work: np.ndarray
    stored_energy: np.ndarray
    energy_error: np.ndarray
    elastic_max_compression: np.ndarray
    elastic_contact_time: np.ndarray
    tau: float
    separation: str
    law: str
    geometry: str
    mass: float


def _check_law(law) -> None:
    if not isinstance(law, (HertzLaw, SphereHertzLaw)):
        raise InputError(
            f"law must be a disk's HertzLaw (contact_law, pair_contact_law) or a sphere's "
            f"SphereHertzLaw (sphere_contact_law), got {type(law).__name__}"
        )


def _mass(law, mass) -> float:
    if mass is None:
        return SPHERE_MASS if isinstance(law, SphereHertzLaw) else math.pi
    return _positive("mass", mass)


def _check_separation(separation: str) -> str:
    if separation not in SEPARATIONS:
        raise InputError(
            f"unknown separation {separation!r}; choose one of {', '.join(SEPARATIONS)}"
        )
    return separation


def _elastic(law, v, mass: float):
    """The undamped collision (checks the speeds): ``(v, xi_max, contact time)``."""
    if isinstance(law, SphereHertzLaw):
        q = sphere_quasistatic_collision(law, v, mass=mass)
    else:
        q = quasistatic_collision(law, v, mass=mass)
    return q.v, q.max_compression, q.contact_time


def _force_stiffness(law, d: float) -> tuple[float, float]:
    """``(F_el(d), F_el'(d))`` for one compression ``0 <= d <= law.max_compression``.

    The scalar form of ``law.force`` and ``law.stiffness`` (same formulas, without their array
    checks: the equation of motion calls it thousands of times; the tests compare the two).
    """
    if d <= 0.0:
        return 0.0, 0.0
    if isinstance(law, SphereHertzLaw):
        root = math.sqrt(d)
        return law.K * d * root, 1.5 * law.K * root
    z = max(-d * math.exp(-law.constant) / (4.0 * law.R), -1.0 / math.e)
    lam = -lambertw(z, k=-1).real
    stiff = math.pi * law.E / (lam - 1.0) if lam > 1.0 else math.inf
    return math.pi * law.E * d / lam, stiff


_K_MAX = 1e12
"""Largest ``tau v / xi_max`` integrated: far beyond it the damping force overflows in double
precision (tau = 1e150 R/c at v = 2e-4), and at 1e7 the grain hardly rebounds (the sphere at
v = 2e-4: epsilon = 1.1e-12)."""


def _collide_one(law, v: float, tau: float, mass: float, dmax: float, separation: str, rtol):
    """Integrate one collision in the scaled variables ``x = xi / xi_max``, ``s = t v / xi_max``
    (``xi_max`` the elastic one), with the scaled dissipated work ``w`` as a third component."""
    g = dmax / (mass * v * v)
    k = tau * v / dmax
    dlim = law.max_compression / dmax
    if not k <= _K_MAX:
        # tau = 1e300 overflowed the damping term and DOP853 never reached the separation.
        raise QuasistaticError(
            f"tau = {tau:g} is {k:.3g} times the compression time at v = {v:g} (at most "
            f"{_K_MAX:g} is integrated; the damping force would overflow and the grain does not "
            "rebound); give a relaxation time of a solid, far below the contact time (e.g. "
            "1e-9 to 1e-3 s)"
        )

    def rhs(s, y):
        x, xs = y[0], y[1]
        F, S = _force_stiffness(law, min(x, dlim) * dmax) if x > 0.0 else (0.0, 0.0)
        return [xs, -g * (F + tau * v * xs * S), 2.0 * g * tau * v * S * xs * xs]

    def turning(s, y):
        return y[1]

    turning.direction = -1

    def force_zero(s, y):
        # (F_el / F_el' + A xi') / xi_max: the total force over the stiffness, continued by x
        # below x = 0 so that A = 0 separates at x = 0.
        x = y[0]
        r = x
        if x > 0.0:
            F, S = _force_stiffness(law, min(x, dlim) * dmax)
            r = F / (S * dmax) if S > 0.0 else x
        return r + k * y[1]

    def compression_zero(s, y):
        return y[0]

    end = force_zero if separation == "force" else compression_zero
    end.terminal = True
    end.direction = -1
    sol = solve_ivp(
        rhs,
        (0.0, _S_END * (1.0 + k)),
        [0.0, 1.0, 0.0],
        method="DOP853",
        rtol=rtol,
        atol=rtol * 1e-3,
        events=(turning, end),
    )
    if sol.status != 1 or len(sol.t_events[1]) == 0:
        raise QuasistaticError(
            f"no separation ({separation!r}) for v = {v:g}, tau = {tau:g}: {sol.message}; "
            f"try a larger rtol or a smaller tau"
        )
    x_end, xs_end, w_end = sol.y_events[1][0]
    x_top = sol.y_events[0][0][0] if len(sol.t_events[0]) else float(np.max(sol.y[0]))
    # Under "compression" the event is xi = 0 itself; only "force" leaves the body compressed.
    sep = max(float(x_end), 0.0) * dmax if separation == "force" else 0.0
    stored = float(law.potential(min(sep, law.max_compression))) / (0.5 * mass * v * v)
    eps = max(-float(xs_end), 0.0)
    return (
        eps,
        float(sol.t_events[1][0]) * dmax / v,
        float(x_top) * dmax,
        sep,
        float(w_end),
        stored,
        abs(eps**2 + float(w_end) + stored - 1.0),
    )


def viscous_collision(
    law: HertzLaw | SphereHertzLaw,
    v,
    tau: float,
    *,
    mass: float | None = None,
    separation: str = "force",
    rtol: float = 1e-10,
    advance: Callable[[int], None] | None = None,
) -> ViscousCollision:
    """``m xi'' = -F_el(xi) - tau xi' F_el'(xi)``, ``xi(0) = 0``, ``xi'(0) = v``, with DOP853.

    DOP853 (order 8, adaptive, not symplectic: the damping is the point) on the equation scaled
    with the elastic ``xi_max`` and contact time, so that ``rtol`` is relative; the separation
    is an event located on the dense output. Limits: the quasistatic approximation (contact time
    long against the body's vibrations) and the law's range (``v <= law.max_speed(mass)``).

    Parameters
    ----------
    law : HertzLaw or SphereHertzLaw
        The elastic law: :func:`restitution.quasistatic.hertz.contact_law` (disk on a wall),
        :func:`restitution.quasistatic.hertz_sphere.sphere_contact_law` (sphere on a wall), or a
        pair's law (use :func:`pair_viscous_collision`, which also sets the reduced mass).
    v : array_like, shape (K,)
        Incoming speeds, ``c``.
    tau : float
        The dissipative constant ``A`` of eq. (1), ``R / c``: the relaxation time for
        proportional viscosities, else :func:`dissipative_constant` (sphere). ``0`` is elastic.
    mass : float, optional
        Default the body's: ``pi`` (disk), ``4 pi / 3`` (sphere).
    separation : {"force", "compression"}
        End of contact (module docs); ``"force"``, the contact that cannot pull, by default.
    rtol : float
        Relative tolerance of DOP853 (``atol = 1e-3 rtol`` on the scaled variables of size 1).
    advance : callable, optional
        Called with 1 after each speed's collision (a progress meter, such as
        :class:`restitution.limits.run_options.Meter`).

    Returns
    -------
    ViscousCollision

    Examples
    --------
    >>> from restitution.quasistatic.hertz_sphere import sphere_contact_law
    >>> c = viscous_collision(sphere_contact_law(0.3), [1e-3, 1e-2], 0.0)
    >>> [round(float(e), 8) for e in c.epsilon]
    [1.0, 1.0]
    """
    _check_law(law)
    mass = _mass(law, mass)
    tau = _positive("tau", tau, allow_zero=True)
    separation = _check_separation(separation)
    rtol = _positive("rtol", rtol)
    v, dmax, t_el = _elastic(law, v, mass)
    rows = []
    for vi, di in zip(v, dmax, strict=True):
        rows.append(_collide_one(law, float(vi), tau, mass, float(di), separation, rtol))
        if advance is not None:
            advance(1)
    cols = [np.array(c, dtype=float) for c in zip(*rows, strict=True)]
    return ViscousCollision(
        v=v,
        epsilon=cols[0],
        contact_time=cols[1],
        max_compression=cols[2],
        separation_compression=cols[3],
        dissipated_work=cols[4],
        stored_energy=cols[5],
        energy_error=cols[6],
        elastic_max_compression=np.asarray(dmax, dtype=float),
        elastic_contact_time=np.asarray(t_el, dtype=float),
        tau=tau,
        separation=separation,
        law=law.name,
        geometry=law.geometry,
        mass=mass,
    )


def pair_viscous_collision(
    w,
    tau: float,
    nu1: float,
    nu2: float | None = None,
    *,
    radius_ratio: float = 1.0,
    modulus_ratio: float = 1.0,
    density_ratio: float = 1.0,
    law: str = "centre",
    separation: str = "force",
    rtol: float = 1e-10,
) -> ViscousCollision:
    """Two disks of one relaxation time ``tau`` meeting at relative speed ``w`` (``c1``).

    With a common ``tau`` each disk's contact force is ``(1 + tau d/dt) P_el,i(delta_i)``; both
    equal the same ``P`` from the same start, so ``P_el,1(delta_1) = P_el,2(delta_2)`` at all
    times and the pair obeys (1) with the pair's law
    (:func:`restitution.quasistatic.hertz_pair.pair_contact_law`) and reduced mass. Disks of
    different relaxation times do not reduce to (1) and are not modelled. Units: the first
    disk's (``tau`` in ``R1 / c1``).
    """
    hertz = pair_contact_law(
        nu1, nu2, radius_ratio=radius_ratio, modulus_ratio=modulus_ratio, law=law
    )
    return viscous_collision(
        hertz,
        w,
        tau,
        mass=pair_mass(radius_ratio, density_ratio),
        separation=separation,
        rtol=rtol,
    )


# ============================================================================================
# First order in A, and the sphere's low-speed series
# ============================================================================================


def loss_slope(law: HertzLaw | SphereHertzLaw, v, *, mass: float | None = None) -> np.ndarray:
    """``S(v) = lim_{A -> 0} (1 - epsilon) / A``, ``c / R``, by quadrature on the elastic path.

    ``S = (2 / (m v^2)) int_0^xi_max F_el'(xi) sqrt(v^2 - 2 V(xi)/m) d xi`` (module docs), with
    ``xi = xi_max sin(theta)`` (adaptive quadrature in ``theta``, relative accuracy ~1e-11).
    Both separation criteria share it: they differ at higher order in ``A``.
    """
    _check_law(law)
    mass = _mass(law, mass)
    v, dmax, _ = _elastic(law, v, mass)
    out = np.empty(v.size)
    for i, (vi, dm) in enumerate(zip(v, dmax, strict=True)):
        vm = float(law.potential(dm))

        def integrand(theta, dm=float(dm), vm=vm):
            d = dm * math.sin(theta)
            _, stiff = _force_stiffness(law, d)
            left = max(1.0 - float(law.potential(d)) / vm, 0.0)
            return stiff * math.sqrt(left) * dm * math.cos(theta)

        value, _ = quad(integrand, 0.0, 0.5 * math.pi, epsabs=0.0, epsrel=1e-11, limit=200)
        out[i] = 2.0 * value / (mass * vi)
    return out


def loss_slope_estimate(
    law: HertzLaw | SphereHertzLaw, v, *, mass: float | None = None
) -> np.ndarray:
    """Closed form of :func:`loss_slope` for the local power law at ``xi_max``, ``c / R``.

    ``S = 2 (1+e) sqrt((2+e)/2) B((1+e)/(2+e), 3/2) / (2+e) sqrt(F_el(xi_max) / (m xi_max))``
    with ``e`` the law's local exponent ``d ln(F/xi) / d ln xi`` at ``xi_max``: exact for the
    sphere (``e = 1/2``), relative error ``O(e^2)`` for the disk (``e = 1/(Lambda - 1)``).
    """
    _check_law(law)
    mass = _mass(law, mass)
    _, dmax, _ = _elastic(law, v, mass)
    if isinstance(law, SphereHertzLaw):
        e = np.full(dmax.shape, 0.5)
    else:
        e = law.local_exponent(dmax)
    shape = 2.0 * (1.0 + e) * np.sqrt(1.0 + 0.5 * e) * beta((1.0 + e) / (2.0 + e), 1.5) / (2.0 + e)
    return shape * np.sqrt(law.force(dmax) / (mass * dmax))


def sphere_damping_parameter(
    law: SphereHertzLaw, v, tau: float, *, mass: float = SPHERE_MASS
) -> np.ndarray:
    """``q = (3/2) A alpha^(2/5) v^(1/5)``, ``alpha = K / m``: the sphere's one parameter."""
    if not isinstance(law, SphereHertzLaw):
        raise InputError("the low-speed series (3) is the sphere's; law must be a SphereHertzLaw")
    mass = _positive("mass", mass)
    tau = _positive("tau", tau, allow_zero=True)
    v, _, _ = _elastic(law, v, mass)
    return 1.5 * tau * (law.K / mass) ** 0.4 * v**0.2


def sphere_viscous_expansion(
    law: SphereHertzLaw,
    v,
    tau: float,
    *,
    mass: float = SPHERE_MASS,
    separation: str = "force",
    terms: int = 3,
) -> np.ndarray:
    """Eq. (3): ``epsilon = 1 - C1 q + C2 q^2 + h q^(5/2)``, ``q`` from
    :func:`sphere_damping_parameter`.

    Parameters
    ----------
    terms : {1, 2, 3}
        How many terms after 1: ``C1`` (Ramirez et al.), ``C2`` (Ramirez et al.), and ``h``
        (``4/15`` for ``"force"``, 0 for ``"compression"``; derived in the module notes). The
        error is then ``O(q^2)``, ``O(q^(5/2))`` (``"force"``) or ``O(q^3)``, and ``O(q^3)``.

    Examples
    --------
    >>> from restitution.quasistatic.hertz_sphere import sphere_contact_law
    >>> law = sphere_contact_law(0.3)
    >>> q = float(sphere_damping_parameter(law, 1e-3, 1e-3)[0])
    >>> e = float(sphere_viscous_expansion(law, 1e-3, 1e-3, terms=1)[0])
    >>> round((1 - e) / q, 7)
    1.1534489
    """
    separation = _check_separation(separation)
    if terms not in (1, 2, 3):
        raise InputError(f"terms must be 1, 2 or 3, got {terms!r}")
    q = sphere_damping_parameter(law, v, tau, mass=mass)
    eps = 1.0 - C1 * q
    if terms >= 2:
        eps = eps + C2 * q**2
    if terms >= 3 and separation == "force":
        eps = eps + DELAYED_RECOVERY * q**2.5
    return eps


# ============================================================================================
# From a measured epsilon to tau
# ============================================================================================


def tau_from_epsilon(
    law: HertzLaw | SphereHertzLaw,
    v: float,
    epsilon: float,
    *,
    mass: float | None = None,
    separation: str = "force",
    rtol: float = 1e-10,
) -> float:
    """The ``tau`` (``A``) at which :func:`viscous_collision` gives ``epsilon`` at speed ``v``.

    Brent's method on ``epsilon(tau) - epsilon``, bracketed from the first-order guess
    ``(1 - epsilon) / S(v)`` (:func:`loss_slope`) by doubling. Damping alone: vibrations and
    every other loss are left out, so a measured ``epsilon`` gives an upper bound on ``tau``.

    Parameters
    ----------
    v : float
        Speed, ``c``.
    epsilon : float
        Target, in ``(0, 1 - 1e-7]``: closer to 1 the integrator's tolerance would decide it.

    Returns
    -------
    float
        ``tau`` in ``R / c``.
    """
    _check_law(law)
    if np.ndim(v) or np.ndim(epsilon):
        raise InputError("tau_from_epsilon takes one speed v and one epsilon")
    target = float(epsilon)
    if not 0.0 < target <= 1.0 - 1e-7:
        raise InputError(
            f"epsilon must lie in (0, 1 - 1e-7], got {epsilon!r}; 1 - epsilon below 1e-7 is "
            f"within the integrator's tolerance of the elastic collision"
        )
    separation = _check_separation(separation)
    mass = _mass(law, mass)

    def miss(tau: float) -> float:
        c = viscous_collision(law, v, tau, mass=mass, separation=separation, rtol=rtol)
        return float(c.epsilon[0]) - target

    hi = 2.0 * (1.0 - target) / float(loss_slope(law, v, mass=mass)[0])
    for _ in range(80):
        if miss(hi) < 0.0:
            break
        hi *= 2.0
    else:
        raise QuasistaticError(
            f"no tau up to {hi:.3g} R/c brings epsilon down to {target} at v = {v}; "
            "check the target"
        )
    return float(brentq(miss, 0.0, hi, xtol=1e-14 * hi, rtol=1e-12))
