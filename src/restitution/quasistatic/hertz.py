"""Two-dimensional Hertz contact of a disk with a flat wall, and the quasistatic collision.

Paper section 5, eqs. (56)-(61). Units: ``E = rho = R = 1`` unless given (two-dimensional,
plane-stress constants); forces ``P`` are per unit thickness, in ``E R``; compressions ``delta``
in ``R``; speeds in ``c = sqrt(E / rho)``; times in ``R / c``; energies in ``E R^2``.

The contact law has the form of eq. (57) with a constant ``c``::

    delta(P) = P / (pi E) * (ln(4 pi E R / P) + c)                                     (57)

* ``c = -1 - nu``: eq. (57) as printed in the paper (law ``"paper"``).
* ``c = -1``: eq. (56) integrated correctly from the paper's own stresses (54)-(55); it is the
  approach of the contact point to the far end of the diameter (law ``"diameter"``). The
  transverse stress ``sigma_yy`` integrates to zero along the axis, so ``nu`` drops out.
* ``c = -1 - 2/pi - nu/4``: the approach of the *centre of mass* to the wall, which is what the
  quasistatic equation of motion ``m delta'' = -P(delta)`` needs (law ``"centre"``). The extra
  ``-2/pi - nu/4`` is the mean displacement of the disk relative to its far end, identified
  from the modal static response (see :func:`restitution.quasistatic.relaxation.centre_offset` and
  ``docs/quasistatic.md``). This is the default of :func:`contact_law`: the static relaxation
  and the dynamic contact times of the modal solver support it; ``"paper"`` stays available to
  redraw the paper's own curves.

Exact inversion (Lambert W): with ``z = delta e^{-c} / (4R)`` and ``Lambda = -W_{-1}(-z)``::

    P(delta) = pi E delta / Lambda,     Lambda = ln(4R/delta) + c + ln(Lambda)

whose leading order is eq. (59), ``P ~ pi E delta / ln(4R/delta)``. The potential energy
``V = int_0^delta P d delta'`` is, exactly,::

    V = pi E delta^2 / (2 Lambda) * (1 - 1 / (2 Lambda)) = P^2/(2 pi E) (ln(4 pi E R/P) + c - 1/2)

of which eq. (60) is the leading order. The law is monotonic only while
``d delta / dP = (ln(4 pi E R / P) + c - 1) / (pi E) > 0``, i.e. for ``P < P* = 4 pi E R e^{c-1}``
and ``delta < delta* = 4 R e^{c-1}`` (the branch point ``z = 1/e`` of ``W``). Loads,
compressions, energies or speeds beyond that raise :class:`~restitution.errors.InputError`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import lambertw

from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.material import Material
from restitution.errors import InputError, RestitutionError

__all__ = [
    "LAWS",
    "HertzLaw",
    "QuasistaticCollision",
    "QuasistaticError",
    "QuasistaticTrajectory",
    "checked_range",
    "contact_law",
    "quasistatic_collision",
    "quasistatic_trajectory",
    "contact_time_rate",
]

LAWS = ("paper", "diameter", "centre")
"""Names accepted by :func:`contact_law`."""

# Relative slack on the monotonic limit, so that values computed at the limit itself pass.
_SLACK = 1e-12
# Smallest speed: below it m v^2 / 2 underflows in the closed-form energy balance.
_V_MIN = 1e-100


def _as_nu(material: Material | float) -> float:
    return material.nu if isinstance(material, Material) else Material(nu=material).nu


@dataclass(frozen=True)
class HertzLaw:
    """The contact law ``delta(P) = P/(pi E) (ln(4 pi E R/P) + constant)`` (eq. 57).

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number (for the record; the law uses only ``constant``).
    constant : float
        The dimensionless constant ``c`` of the law.
    name : str
        Which law this is (one of :data:`LAWS`, or free text).
    E : float
        Two-dimensional Young modulus, default 1.
    R : float
        Disk radius, default 1.
    """

    nu: float
    constant: float
    name: str = "custom"
    E: float = 1.0
    R: float = 1.0

    geometry: ClassVar[str] = DISK.geometry

    # ---- limits of the monotonic branch ------------------------------------------------
    @property
    def max_force(self) -> float:
        """``P* = 4 pi E R exp(c - 1)``: the load where ``d delta / dP = 0``, in ``E R``."""
        return 4.0 * math.pi * self.E * self.R * math.exp(self.constant - 1.0)

    @property
    def max_compression(self) -> float:
        """``delta* = 4 R exp(c - 1) = P* / (pi E)``: the largest compression, in ``R``."""
        return 4.0 * self.R * math.exp(self.constant - 1.0)

    @property
    def max_energy(self) -> float:
        """``V(delta*) = P*^2 / (4 pi E)``: the largest storable energy, in ``E R^2``."""
        return self.max_force**2 / (4.0 * math.pi * self.E)

    def max_speed(self, mass: float = math.pi) -> float:
        """Largest incoming speed whose energy ``mass v^2 / 2`` the law can store, in ``c``."""
        return math.sqrt(2.0 * self.max_energy / mass)

    # ---- the law ---------------------------------------------------------------------------
    def compression(self, P: np.ndarray | float) -> np.ndarray:
        """Compression ``delta(P)`` of eq. (57), in ``R``; ``P`` in ``[0, P*]``."""
        P = self._check("load P", P, self.max_force)
        with np.errstate(divide="ignore", invalid="ignore"):
            d = P / (math.pi * self.E) * (np.log(4 * math.pi * self.E * self.R / P) + self.constant)
        return np.where(P > 0.0, d, 0.0)

    def _lambda(self, delta: np.ndarray) -> np.ndarray:
        """``Lambda = -W_{-1}(-delta e^{-c} / (4R))``; ``inf`` at ``delta = 0``."""
        z = -delta * math.exp(-self.constant) / (4.0 * self.R)
        z = np.maximum(z, -1.0 / math.e)  # round-off at the branch point
        with np.errstate(divide="ignore", invalid="ignore"):
            lam = -lambertw(z, k=-1).real
        return np.where(delta > 0.0, lam, np.inf)

    def force(self, delta: np.ndarray | float) -> np.ndarray:
        """Load ``P(delta)``, the exact inverse of eq. (57), in ``E R``.

        ``P = pi E delta / Lambda`` with ``Lambda = -W_{-1}(-delta e^{-c}/(4R))``.
        """
        delta = self._check("compression delta", delta, self.max_compression)
        return math.pi * self.E * delta / self._lambda(delta)

    def stiffness(self, delta: np.ndarray | float) -> np.ndarray:
        """``dP/d delta = pi E / (Lambda - 1)``, in ``E``; zero at ``delta = 0`` and infinite at
        ``delta*``."""
        delta = self._check("compression delta", delta, self.max_compression)
        with np.errstate(divide="ignore"):
            return math.pi * self.E / (self._lambda(delta) - 1.0)

    def potential(self, delta: np.ndarray | float) -> np.ndarray:
        """Potential energy ``V(delta) = int_0^delta P``, exact, in ``E R^2``.

        ``V = pi E delta^2 / (2 Lambda) (1 - 1/(2 Lambda))``.
        """
        delta = self._check("compression delta", delta, self.max_compression)
        lam = self._lambda(delta)
        return math.pi * self.E * delta**2 / (2.0 * lam) * (1.0 - 0.5 / lam)

    def potential_of_force(self, P: np.ndarray | float) -> np.ndarray:
        """``V`` at load ``P``: ``P^2/(2 pi E) (ln(4 pi E R/P) + c - 1/2)``, in ``E R^2``."""
        P = self._check("load P", P, self.max_force)
        with np.errstate(divide="ignore", invalid="ignore"):
            lg = np.log(4 * math.pi * self.E * self.R / P)
            V = P**2 / (2 * math.pi * self.E) * (lg + self.constant - 0.5)
        return np.where(P > 0.0, V, 0.0)

    def local_exponent(self, delta: np.ndarray | float) -> np.ndarray:
        """``epsilon = d ln(P/delta) / d ln delta = 1 / (Lambda - 1)``, dimensionless.

        It measures how far the law is from linear at ``delta``; ``~ 1/ln(4R/delta)`` as
        ``delta -> 0``.
        """
        delta = self._check("compression delta", delta, self.max_compression)
        return 1.0 / (self._lambda(delta) - 1.0)

    # ---- leading-order forms printed in the paper ----------------------------------------------
    def compression_leading(self, P: np.ndarray | float) -> np.ndarray:
        """Eq. (58): ``delta ~ P/(pi E) ln(4 pi E R / P)``, in ``R``."""
        P = np.asarray(P, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            d = P / (math.pi * self.E) * np.log(4 * math.pi * self.E * self.R / P)
        return np.where(P > 0.0, d, 0.0)

    def force_leading(self, delta: np.ndarray | float) -> np.ndarray:
        """Eq. (59): ``P ~ pi E delta / ln(4R/delta)``, in ``E R``."""
        delta = np.asarray(delta, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            P = math.pi * self.E * delta / np.log(4 * self.R / delta)
        return np.where(delta > 0.0, P, 0.0)

    def potential_leading(self, delta: np.ndarray | float) -> np.ndarray:
        """Eq. (60): ``V ~ delta^2 pi E / (2 ln(4R/delta))``, in ``E R^2``."""
        delta = np.asarray(delta, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            V = 0.5 * delta**2 * math.pi * self.E / np.log(4 * self.R / delta)
        return np.where(delta > 0.0, V, 0.0)

    # ---- helpers -----------------------------------------------------------------------------
    def _check(self, what: str, value, limit: float) -> np.ndarray:
        return checked_range(
            what,
            value,
            limit,
            f"where the 2D Hertz law '{self.name}' (c = {self.constant:.6g}) stops being "
            f"monotonic (d delta/dP = 0 at P* = {self.max_force:.6g}, delta* = "
            f"{self.max_compression:.6g}); the quasistatic theory does not apply there",
        )


def checked_range(what: str, value, limit: float, beyond: str) -> np.ndarray:
    """``value`` as an array in ``[0, limit]`` (``limit`` times ``1 + 1e-12`` tolerated and
    clipped); :class:`InputError` for non-finite, negative or larger values, saying ``beyond``
    (why the limit is one)."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{what} must be finite")
    if np.any(arr < 0.0):
        raise InputError(f"{what} must be non-negative, got {arr.min():.6g}")
    if np.any(arr > limit * (1.0 + _SLACK)):
        raise InputError(f"{what} = {arr.max():.6g} exceeds {limit:.6g}, {beyond}")
    return np.minimum(arr, limit)


def contact_law(
    material: Material | float, law: str = "centre", *, E: float = 1.0, R: float = 1.0
) -> HertzLaw:
    """The 2D Hertz law of a material.

    Parameters
    ----------
    material : Material or float
        The material or its two-dimensional Poisson number.
    law : {"centre", "paper", "diameter"}
        Default ``"centre"``, the law the package's own evidence supports (docs/quasistatic.md).
        ``"paper"``: eq. (57) as printed, ``c = -1 - nu``. ``"diameter"``: eq. (56) integrated
        correctly, ``c = -1`` (approach of the contact to the far end of the diameter).
        ``"centre"``: approach of the centre of mass, ``c = -1 - 2/pi - nu/4``.
    E, R : float
        Young modulus and radius (default: the package units).
    """
    nu = _as_nu(material)
    if law == "paper":
        c = -1.0 - nu
    elif law == "diameter":
        c = -1.0
    elif law == "centre":
        c = -1.0 - 2.0 / math.pi - 0.25 * nu
    else:
        raise InputError(f"unknown contact law {law!r}; choose one of {', '.join(LAWS)}")
    return HertzLaw(nu=nu, constant=c, name=law, E=E, R=R)


# ============================================================================================
# The quasistatic collision  m delta'' = -P(delta)
# ============================================================================================


@dataclass(frozen=True)
class QuasistaticCollision:
    """Maximal compression and contact time of the quasistatic collision, for speeds ``v``.

    Attributes
    ----------
    v : numpy.ndarray, shape (K,)
        Incoming speed towards the wall, in ``c``.
    max_compression : numpy.ndarray, shape (K,)
        ``delta_max`` from ``V(delta_max) = m v^2 / 2`` (exact, Lambert W), in ``R``.
    max_force : numpy.ndarray, shape (K,)
        ``P(delta_max)``, in ``E R``.
    contact_time : numpy.ndarray, shape (K,)
        ``tau = 2 int_0^delta_max d delta / sqrt(v^2 - 2 V(delta)/m)``, in ``R / c``.
    estimate_max_compression, estimate_contact_time : numpy.ndarray, shape (K,)
        Eq. (61): ``v R sqrt(ln(4c/v))`` and ``pi R/c sqrt(ln(4c/v))`` (the constant ``pi`` from
        the paper's ``tau ~ pi delta_max / v``).
    harmonic_ratio : numpy.ndarray, shape (K,)
        ``v tau / (pi delta_max)``; tends to 1 as ``v -> 0`` like
        :func:`contact_time_rate`.
    law : str
        Name of the contact law.
    constant : float
        Its constant ``c``.
    mass : float
        Disk mass, in ``rho R^2``.
    """

    v: np.ndarray
    max_compression: np.ndarray
    max_force: np.ndarray
    contact_time: np.ndarray
    estimate_max_compression: np.ndarray
    estimate_contact_time: np.ndarray
    harmonic_ratio: np.ndarray
    law: str
    constant: float
    mass: float


def _check_speeds(law: HertzLaw, v, mass: float) -> np.ndarray:
    v = np.atleast_1d(np.asarray(v, dtype=float))
    if not np.all(np.isfinite(v)) or np.any(v < _V_MIN):
        raise InputError(f"speeds v must be finite and at least {_V_MIN:g} (units of c)")
    vmax = law.max_speed(mass)
    if np.any(v > vmax):
        raise InputError(
            f"v = {v.max():.6g} c exceeds {vmax:.6g} c: the kinetic energy m v^2/2 is more than "
            f"the 2D Hertz law '{law.name}' can store before it stops being monotonic "
            f"(delta* = {law.max_compression:.6g} R); use a smaller v"
        )
    return v


def _peak_force(law: HertzLaw, v: np.ndarray, mass: float) -> np.ndarray:
    """Load at closest approach from ``V(P) = m v^2 / 2`` in closed form.

    With ``s = (P / (4 pi E R))^2`` the energy balance reads ``s (-ln s + 2c - 1) = D`` with
    ``D = 2 pi E m v^2 / (4 pi E R)^2``, so ``s = exp(c2 - Lambda2)`` with ``c2 = 2c - 1`` and
    ``Lambda2 = -W_{-1}(-D e^{-c2})``.
    """
    K = 4.0 * math.pi * law.E * law.R
    D = 2.0 * math.pi * law.E * mass * v**2 / K**2
    c2 = 2.0 * law.constant - 1.0
    z = np.maximum(-D * math.exp(-c2), -1.0 / math.e)
    lam2 = -lambertw(z, k=-1).real
    return K * np.exp(0.5 * (c2 - lam2))


@functools.cache
def _gauss_legendre(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on ``[-1, 1]``, read-only, computed once per
    ``n_nodes``: they come from an eigenvalue problem of that size (0.03-0.3 s for 400 on a
    busy machine), and a damped disk's law asks for the same 400 nodes in every one of its
    dozens of quasistatic collisions."""
    x, w = np.polynomial.legendre.leggauss(n_nodes)
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w


def _contact_time(
    law: HertzLaw, v: np.ndarray, dmax: np.ndarray, mass: float, n_nodes: int
) -> np.ndarray:
    """``tau`` by Gauss-Legendre quadrature in ``theta`` with ``delta = delta_max sin(theta)``.

    The substitution removes the inverse square root at the turning point: near ``theta = pi/2``
    the integrand tends to ``delta_max / sqrt(P_max delta_max / m)``. The remaining
    ``ln(delta)`` terms at ``theta = 0`` slow convergence only mildly (see the tests).
    """
    x, w = _gauss_legendre(n_nodes)
    theta = 0.25 * math.pi * (x + 1.0)
    w = 0.25 * math.pi * w
    s = np.sin(theta)[None, :]
    # V(delta) / V(delta_max) from the exact form, free of underflow for tiny v.
    lam_m = law._lambda(dmax)[:, None]
    lam = law._lambda(dmax[:, None] * s)
    ratio = s**2 * (lam_m / lam) * (1.0 - 0.5 / lam) / (1.0 - 0.5 / lam_m)
    integrand = (dmax / v)[:, None] * np.cos(theta)[None, :] / np.sqrt(1.0 - ratio)
    return 2.0 * integrand @ w


def quasistatic_collision(
    law: HertzLaw, v: np.ndarray | float, *, mass: float = math.pi, n_nodes: int = 400
) -> QuasistaticCollision:
    """Maximal compression and contact time of ``m delta'' = -P(delta)``, ``delta(0) = 0``,
    ``delta'(0) = v``.

    Parameters
    ----------
    law : HertzLaw
    v : array_like, shape (K,)
        Incoming speeds in ``c``, ``0 < v <= law.max_speed(mass)``.
    mass : float
        Disk mass, default ``pi`` (``rho = R = 1``).
    n_nodes : int
        Gauss-Legendre nodes for the contact-time integral (400 gives ~1e-10 relative).

    Returns
    -------
    QuasistaticCollision
    """
    v = _check_speeds(law, v, mass)
    Pm = _peak_force(law, v, mass)
    dmax = law.compression(np.minimum(Pm, law.max_force))
    tau = _contact_time(law, v, dmax, mass, n_nodes)
    with np.errstate(invalid="ignore"):
        lg = np.sqrt(np.log(4.0 / v))
    return QuasistaticCollision(
        v=v,
        max_compression=dmax,
        max_force=Pm,
        contact_time=tau,
        estimate_max_compression=v * law.R * lg,
        estimate_contact_time=math.pi * law.R * lg,
        harmonic_ratio=v * tau / (math.pi * dmax),
        law=law.name,
        constant=law.constant,
        mass=mass,
    )


def contact_time_rate(law: HertzLaw, max_compression: np.ndarray | float) -> np.ndarray:
    """Leading-order prediction of ``v tau / (pi delta_max) - 1``.

    For a force ``P = k(delta) delta`` whose stiffness varies slowly,
    ``epsilon = d ln k / d ln delta = 1/(Lambda - 1) ~ 1/ln(4R/delta_max)``, a first-order
    expansion of the contact-time integral gives::

        v tau / (pi delta_max) = 1 - (1 - ln 2)/2 * epsilon + O(epsilon^2)

    so ``tau -> pi delta_max / v`` only like ``0.153 / ln(4R/delta_max)``, i.e. logarithmically.
    """
    eps = law.local_exponent(max_compression)
    return -0.5 * (1.0 - math.log(2.0)) * eps


class QuasistaticError(RestitutionError):
    """The quasistatic equation of motion could not be integrated."""


@dataclass(frozen=True, eq=False)
class QuasistaticTrajectory:
    """The quasistatic collision as a function of time, from an ODE solution.

    Attributes
    ----------
    law : HertzLaw
    v : float
        Incoming speed, ``c``.
    mass : float
        Disk mass.
    max_compression : float
        ``delta_max`` from the ODE, ``R``.
    contact_time : float
        ``tau = 2 t_half``, ``R / c``, with ``t_half`` the time of closest approach.
    max_energy_error : float
        Largest ``|m delta'^2/2 + V(delta) - m v^2/2| / (m v^2 / 2)`` on the solver's steps.
    """

    law: HertzLaw
    v: float
    mass: float
    max_compression: float
    contact_time: float
    max_energy_error: float
    _sol: object

    def compression(self, t: np.ndarray) -> np.ndarray:
        """``delta(t)`` for ``t`` in ``[0, tau]`` (mirrored about ``tau/2``), ``R``."""
        t = np.asarray(t, dtype=float)
        half = 0.5 * self.contact_time
        tm = np.clip(np.where(t > half, self.contact_time - t, t), 0.0, half)
        s = tm * self.v / self.max_compression
        x = self._sol(s)[0]
        return np.clip(x, 0.0, 1.0) * self.max_compression

    def force(self, t: np.ndarray) -> np.ndarray:
        """``P(delta(t))``, ``E R``; zero outside ``[0, tau]``."""
        t = np.asarray(t, dtype=float)
        P = self.law.force(np.minimum(self.compression(t), self.law.max_compression))
        return np.where((t >= 0.0) & (t <= self.contact_time), P, 0.0)


def quasistatic_trajectory(
    law: HertzLaw, v: float, *, mass: float = math.pi, rtol: float = 1e-12
) -> QuasistaticTrajectory:
    """Integrate ``m delta'' = -P(delta)`` to closest approach with DOP853.

    The equation is scaled with the exact ``delta_max`` (``x = delta/delta_max``,
    ``s = t v / delta_max``) so that tolerances are relative; the second half of the
    collision is the mirror image of the first (time reversal symmetry).

    Parameters
    ----------
    law : HertzLaw
    v : float
        Incoming speed, ``c``.
    mass : float
        Disk mass, default ``pi``.
    rtol : float
        Relative tolerance of the integrator (``atol = rtol * 1e-3``).
    """
    v = float(_check_speeds(law, v, mass)[0])
    Pm = float(_peak_force(law, np.array([v]), mass)[0])
    dmax = float(law.compression(min(Pm, law.max_force)))
    g = dmax / (mass * v**2)
    dlim = law.max_compression

    def rhs(s, y):
        d = min(max(y[0], 0.0) * dmax, dlim)
        return [y[1], -g * float(law.force(d))]

    def turning(s, y):
        return y[1]

    turning.terminal = True
    turning.direction = -1
    sol = solve_ivp(
        rhs,
        (0.0, 50.0),
        [0.0, 1.0],
        method="DOP853",
        rtol=rtol,
        atol=rtol * 1e-3,
        events=turning,
        dense_output=True,
    )
    if sol.status != 1 or len(sol.t_events[0]) == 0:
        raise QuasistaticError(
            f"closest approach not reached for v = {v}: {sol.message}; try a larger rtol"
        )
    s_half = float(sol.t_events[0][0])
    x, xd = sol.y
    e_kin = xd**2  # in units of m v^2 / 2
    e_pot = law.potential(np.clip(x, 0.0, 1.0) * dmax) / (0.5 * mass * v**2)
    err = float(np.max(np.abs(e_kin + e_pot - 1.0)))
    return QuasistaticTrajectory(
        law=law,
        v=v,
        mass=mass,
        max_compression=float(sol.y_events[0][0][0]) * dmax,
        contact_time=2.0 * s_half * dmax / v,
        max_energy_error=err,
        _sol=sol.sol,
    )
