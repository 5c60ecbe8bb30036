"""Rayleigh's estimate of the energy left in the modes after a slow collision (paper eqs. 62-68),
for any body with a quasistatic contact theory (the disk, eqs. 62-68; the sphere).

Units: ``E = rho = R = 1`` of the body's own constants; speeds in ``c``, times in ``R / c``;
energies as fractions of the initial kinetic energy ``(m/2) v^2``.

The wall potential of eq. (41) is replaced by one acting only at the contact point (the disk's
edge point ``phi = 0``, the sphere's tip ``theta = 0``), whose position along the axis is
``x0 + 1 + sum_k C_k Q_k`` (eq. 63; the same for the sphere, see
:mod:`restitution.bodies.sphere.surface`). With the Hamiltonian (62) corrected per ERRATA
(``(m/2) omega^2 Q^2``), Hamilton's equations for a mode are::

    m Q_k'' = -m omega_k^2 Q_k - C_k P(t)                                        (64)

where the force ``P(t) = dV/dx`` is taken from the quasistatic collision
(:mod:`restitution.quasistatic.pulse`): the 2D Hertz law
(:mod:`restitution.quasistatic.hertz`) for the disk, Hertz's 3D law
(:mod:`restitution.quasistatic.hertz_sphere`) for the sphere. Starting from rest, the exact
solution (Duhamel) is ``Q_k(t) = -(C_k / (m omega_k)) int_0^t sin(omega_k (t - s)) P(s) ds``, and
the energy left in the mode after the contact, ``(m/2)(Q'^2 + omega^2 Q^2) = (m/2) omega^2 |q|^2``
(eq. 68 corrected, with ``q`` of eqs. 43 and 65), is::

    E_k = C_k^2 / (2m) |int_0^tau P(t) e^{-i omega_k t} dt|^2
        = (2 C_k^2 / m) [int_0^{tau/2} P(t) cos(omega_k (tau/2 - t)) dt]^2

because ``P`` is symmetric about ``tau/2``. The fraction of the initial kinetic energy is
``E_k / ((m/2) v^2)``.

Two independent evaluations: ``method="duhamel"`` (Gauss-Legendre panels on ``[0, tau/2]``,
graded towards ``t = 0``, :func:`restitution.quasistatic.pulse.pulse_drive`), and
``method="ivp"`` (eqs. 65-67 for the complex amplitudes ``q_k`` integrated with DOP853 together
with the collision, for checking).

**The sphere at low speed.** Near both ends of the pulse ``P ~ K (v t)^(3/2)`` with
``K = (4/3) E* sqrt(R)``, so for ``omega_k tau >> 1`` (every mode, as ``v -> 0``)
:func:`restitution.quasistatic.hertz_sphere.drive_asymptote` gives
``I_k ~ K v^(3/2) Gamma(5/2) omega_k^(-5/2) cos(omega_k tau/2 - 5 pi/4)`` and, with
``4 K^2 Gamma(5/2)^2 = 4 pi E*^2 R``::

    E_k / ((m/2) v^2) = 4 C_k^2 I_k^2 / (m^2 v^2)
                      = v (4 pi E*^2 R / m^2) (C_k^2 / omega_k^5)
                        * [cos^2(omega_k tau/2 - 5 pi/4) + O((omega_k tau)^(-5/2))],

``tau = 2.943 delta_max / v ~ v^(-1/5)``. The total fraction is ``v`` times a bounded factor
that oscillates with ``v`` through the phases ``omega_k tau``: between 0 and twice its mean
``(2 pi E*^2 R / m^2) sum_k C_k^2 omega_k^(-5)`` (0.20 at ``nu = 0.3``, so the fraction is
``~0.2 v``); the lowest quadrupole ``(l = 2, n = 0)`` carries 62 % of that sum at
``nu = 0.3``. The mode sum converges:
``sum_{omega_k < Omega} C_k^2 ~ Omega^3`` (0.51 ``Omega^3`` at ``nu = 0.3``; the exponent is that
of Boussinesq's ``1/r`` surface compliance, ``sum C_k^2 / omega_k^2 ~ Omega``), so the terms
beyond ``Omega`` add ``~ Omega^(-2) ~ 1/N``: 0.7/N of the mean at ``nu = 0.3``. The disk differs:
its pulse starts like ``pi E v t / ln(1/(v t))``, so ``I_k ~ v omega^(-2)`` up to logarithms and
its fractions carry no power of ``v``, only logarithms.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from restitution.bodies.base import ModalBody
from restitution.errors import InputError
from restitution.quasistatic.pulse import ContactLaw, contact_law_for, force_pulse, pulse_drive

__all__ = ["RayleighResult", "rayleigh_energy", "rayleigh_sweep", "drive_integrals"]


@dataclass(frozen=True, eq=False)
class RayleighResult:
    """Energy left in the modes after a quasistatic collision.

    Attributes
    ----------
    v : float
        Incoming speed towards the wall, ``c``.
    nu : float
        Poisson number of the body (the disk's two-dimensional one, the sphere's 3D one).
    law : str
        Name of the contact law (:func:`restitution.quasistatic.pulse.contact_law_for`).
    method : str
        ``"duhamel"`` or ``"ivp"``.
    n, l : numpy.ndarray of int, shape (N,)
        Mode labels as the mode set names them: the disk's order ``n`` and root index ``l``,
        the sphere's root index ``n`` and order ``l``.
    order : numpy.ndarray of int, shape (N,)
        Angular order of every mode (``n`` of the disk, ``l`` of the sphere).
    geometry : str
        ``"disk"`` or ``"sphere"``.
    omega : numpy.ndarray, shape (N,)
        Mode frequencies, ``c / R``.
    mode_energy : numpy.ndarray, shape (N,)
        Energy left in each mode, fraction of ``(m/2) v^2``.
    energy_fraction : float
        ``sum(mode_energy)``.
    contact_time, max_compression : float
        Of the quasistatic collision, ``R / c`` and ``R``.
    """

    v: float
    nu: float
    law: str
    method: str
    n: np.ndarray
    l: np.ndarray
    omega: np.ndarray
    mode_energy: np.ndarray
    energy_fraction: float
    contact_time: float
    max_compression: float
    order: np.ndarray
    geometry: str

    def fraction_of(self, n: int, l: int) -> float:
        """Energy fraction in mode ``(n, l)`` (0 if it is not in the set)."""
        sel = (self.n == n) & (self.l == l)
        return float(self.mode_energy[sel].sum())

    @property
    def quadrupole(self) -> float:
        """Energy fraction in the lowest mode of order 2 (the disk's ``(n, l) = (2, 0)``, the
        sphere's ``(l, n) = (2, 0)``); 0 if the set has none."""
        sel = np.flatnonzero(self.order == 2)
        if sel.size == 0:
            return 0.0
        return float(self.mode_energy[sel[np.argmin(self.omega[sel])]])

    @property
    def dominant(self) -> tuple[int, int, float]:
        """``(n, l, share)`` of the mode holding the largest share of the energy."""
        i = int(np.argmax(self.mode_energy))
        return int(self.n[i]), int(self.l[i]), float(self.mode_energy[i] / self.energy_fraction)


def drive_integrals(
    law: ContactLaw, v: float, omega: np.ndarray, *, mass: float | None = None
) -> tuple[np.ndarray, float, float]:
    """``I_k = int_0^{tau/2} P(t) cos(omega_k (tau/2 - t)) dt`` for the quasistatic pulse.

    Parameters
    ----------
    law : HertzLaw or SphereHertzLaw
        The contact law; it names its geometry.
    v : float
        Incoming speed, ``c``.
    omega : numpy.ndarray, shape (N,)
        Frequencies, ``c / R``.
    mass : float, optional
        Body mass (default: ``pi`` for a disk law, ``4 pi / 3`` for a sphere law).

    Returns
    -------
    I : numpy.ndarray, shape (N,)
        Force times time (``E R^2 / c`` for the disk, ``E R^3 / c`` for the sphere).
    contact_time, max_compression : float
    """
    pulse = force_pulse(law, v, mass=mass)
    return pulse_drive(pulse, omega), pulse.contact_time, pulse.max_compression


def _ivp_energies(
    law: ContactLaw, v: float, modes: ModalBody, mass: float, rtol: float
) -> tuple[np.ndarray, float, float]:
    """Eqs. (65)-(67) with DOP853: ``q_k' = -i e^{-i omega t} C_k P / (m omega)``,
    ``delta'' = -P / m``; energies ``(m/2) omega^2 |q|^2`` at ``delta`` back to 0."""
    om, C = modes.omega, modes.C
    N = len(modes)

    def rhs(t, y):
        d = min(max(y[0], 0.0), law.max_compression)
        P = float(law.force(d)) if d > 0 else 0.0
        dq = -1j * np.exp(-1j * om * t) * C * P / (mass * om)
        return np.concatenate([[y[1], -P / mass], dq.real, dq.imag])

    def leave(t, y):
        return y[0]

    leave.terminal = True
    leave.direction = -1
    y0 = np.zeros(2 + 2 * N)
    y0[1] = v
    # A tiny head start avoids the event firing at t = 0.
    t0 = 1e-9 * 1.0 / v
    y0[0] = v * t0
    traj_tau = force_pulse(law, v, mass=mass).contact_time
    sol = solve_ivp(
        rhs,
        (t0, 2.0 * traj_tau),
        y0,
        method="DOP853",
        rtol=rtol,
        atol=rtol * 1e-6 * v,
        events=leave,
    )
    q = sol.y[2 : 2 + N, -1] + 1j * sol.y[2 + N :, -1]
    energy = 0.5 * mass * om**2 * np.abs(q) ** 2
    return energy, float(sol.t[-1]), float(np.max(sol.y[0]))


def rayleigh_energy(
    modes: ModalBody,
    v: float,
    law: ContactLaw | str | None = None,
    *,
    method: str = "duhamel",
    rtol: float = 1e-10,
) -> RayleighResult:
    """Energy left in every mode after a quasistatic collision at speed ``v``.

    Parameters
    ----------
    modes : ModalBody
        Modes driven at the contact point (the disk's ``phi = 0``, the sphere's ``theta = 0``)
        through ``C_k``: a disk's ``ModeSet`` or a ``SphereModes``.
    v : float
        Incoming speed towards the wall, ``c`` (below the law's ``max_speed``).
    law : HertzLaw, SphereHertzLaw, str or None
        Contact law of the body's geometry, or its name at ``modes.nu``
        (:func:`restitution.quasistatic.pulse.contact_law_for`); ``None``: the geometry's
        default, ``"paper"`` (eq. 57 as printed) for the disk, ``"hertz"`` for the sphere.
    method : {"duhamel", "ivp"}
        Exact Duhamel integral with quadrature (default) or DOP853 on eqs. (65)-(67).
    rtol : float
        Tolerance of the ``"ivp"`` integration.

    Returns
    -------
    RayleighResult
    """
    # A pair of bodies of one kind is driven by the pair's law of that kind's theory.
    law = contact_law_for(getattr(modes, "kind", modes.geometry), modes.nu, law)
    m = modes.mass
    if method == "duhamel":
        I, tau, dmax = drive_integrals(law, v, modes.omega, mass=m)
        energy = 2.0 * modes.C**2 / m * I**2
    elif method == "ivp":
        energy, tau, dmax = _ivp_energies(law, v, modes, m, rtol)
    else:
        raise InputError(f"unknown method {method!r}; choose 'duhamel' or 'ivp'")
    frac = energy / (0.5 * m * v**2)
    return RayleighResult(
        v=float(v),
        nu=float(modes.nu),
        law=law.name,
        method=method,
        n=modes.n.copy(),
        l=modes.l.copy(),
        omega=modes.omega.copy(),
        mode_energy=frac,
        energy_fraction=float(frac.sum()),
        contact_time=tau,
        max_compression=dmax,
        order=np.asarray(modes.order).copy(),
        geometry=modes.geometry,
    )


def rayleigh_sweep(
    modes: ModalBody, v: np.ndarray, law: ContactLaw | str | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rayleigh energy fraction over speeds ``v`` (Duhamel method).

    Returns
    -------
    v : numpy.ndarray, shape (K,)
    total : numpy.ndarray, shape (K,)
        Energy fraction in all modes.
    quadrupole : numpy.ndarray, shape (K,)
        Energy fraction in the lowest mode of order 2 (:attr:`RayleighResult.quadrupole`).
    """
    v = np.atleast_1d(np.asarray(v, dtype=float))
    res = [rayleigh_energy(modes, float(x), law) for x in v]
    return (
        v,
        np.array([r.energy_fraction for r in res]),
        np.array([r.quadrupole for r in res]),
    )
