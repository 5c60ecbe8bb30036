"""Rayleigh's estimate of the energy left in the modes after a slow collision (paper eqs. 62-68).

Units: ``E = rho = R = 1``; speeds in ``c``, times in ``R / c``; energies as fractions of the
initial kinetic energy ``(m/2) v^2``.

The wall potential of eq. (41) is replaced by one acting only at the edge point ``phi = 0``,
whose position is ``x(0) = x0 + 1 + sum_k C_k Q_k`` (eq. 63). With the Hamiltonian (62)
corrected per ERRATA (``(m/2) omega^2 Q^2``), Hamilton's equations for a mode are::

    m Q_k'' = -m omega_k^2 Q_k - C_k P(t)                                        (64)

where the force ``P(t) = dV/dx`` is taken from the quasistatic collision with the 2D Hertz law
(:mod:`restitution.quasistatic.hertz`). Starting from rest, the exact solution (Duhamel) is
``Q_k(t) = -(C_k / (m omega_k)) int_0^t sin(omega_k (t - s)) P(s) ds``, and the energy left in
the mode after the contact, ``(m/2)(Q'^2 + omega^2 Q^2) = (m/2) omega^2 |q|^2`` (eq. 68
corrected, with ``q`` of eqs. 43 and 65), is::

    E_k = C_k^2 / (2m) |int_0^tau P(t) e^{-i omega_k t} dt|^2
        = (2 C_k^2 / m) [int_0^{tau/2} P(t) cos(omega_k (tau/2 - t)) dt]^2

because ``P`` is symmetric about ``tau/2``. The fraction of the initial kinetic energy is
``E_k / ((m/2) v^2)``.

Two independent evaluations: ``method="duhamel"`` (Gauss-Legendre panels on ``[0, tau/2]``,
graded towards ``t = 0`` where ``P ~ t / ln(1/t)``), and ``method="ivp"`` (eqs. 65-67 for the
complex amplitudes ``q_k`` integrated with DOP853 together with the collision, for checking).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from restitution.bodies.disk.modes import ModeSet
from restitution.errors import InputError
from restitution.quasistatic.hertz import HertzLaw, contact_law, quasistatic_trajectory

__all__ = ["RayleighResult", "rayleigh_energy", "rayleigh_sweep", "drive_integrals"]


@dataclass(frozen=True, eq=False)
class RayleighResult:
    """Energy left in the modes after a quasistatic collision.

    Attributes
    ----------
    v : float
        Incoming speed towards the wall, ``c``.
    nu : float
        Poisson number.
    law : str
        Name of the contact law (see :func:`restitution.quasistatic.hertz.contact_law`).
    method : str
        ``"duhamel"`` or ``"ivp"``.
    n, l : numpy.ndarray of int, shape (N,)
        Mode labels.
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

    def fraction_of(self, n: int, l: int) -> float:
        """Energy fraction in mode ``(n, l)`` (0 if it is not in the set)."""
        sel = (self.n == n) & (self.l == l)
        return float(self.mode_energy[sel].sum())

    @property
    def dominant(self) -> tuple[int, int, float]:
        """``(n, l, share)`` of the mode holding the largest share of the energy."""
        i = int(np.argmax(self.mode_energy))
        return int(self.n[i]), int(self.l[i]), float(self.mode_energy[i] / self.energy_fraction)


def _nodes(half: float, omega_max: float, per_panel: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on ``[0, half]``: uniform panels of at most a third of a
    period of ``omega_max`` (and at most ``half/64``), the first one split geometrically
    towards ``t = 0``."""
    width = min(2.0 * math.pi / (3.0 * max(omega_max, 1e-12)), half / 64.0)
    n_panels = int(math.ceil(half / width))
    edges = np.linspace(0.0, half, n_panels + 1)
    first = edges[1] * np.geomspace(1e-12, 1.0, 24)
    edges = np.concatenate([[0.0], first, edges[2:]])
    x, w = np.polynomial.legendre.leggauss(per_panel)
    a, b = edges[:-1, None], edges[1:, None]
    t = 0.5 * (b - a) * x[None, :] + 0.5 * (a + b)
    wt = 0.5 * (b - a) * w[None, :]
    return t.ravel(), wt.ravel()


def drive_integrals(
    law: HertzLaw, v: float, omega: np.ndarray, *, mass: float = math.pi
) -> tuple[np.ndarray, float, float]:
    """``I_k = int_0^{tau/2} P(t) cos(omega_k (tau/2 - t)) dt`` for the quasistatic pulse.

    Returns
    -------
    I : numpy.ndarray, shape (N,)
        In ``E R^2 / c`` (force times time).
    contact_time, max_compression : float
    """
    traj = quasistatic_trajectory(law, v, mass=mass)
    half = 0.5 * traj.contact_time
    t, w = _nodes(half, float(np.max(omega, initial=1.0)))
    P = traj.force(t)
    I = np.cos(np.outer(omega, half - t)) @ (w * P)
    return I, traj.contact_time, traj.max_compression


def _ivp_energies(
    law: HertzLaw, v: float, modes: ModeSet, mass: float, rtol: float
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
    traj_tau = quasistatic_trajectory(law, v, mass=mass).contact_time
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
    modes: ModeSet,
    v: float,
    law: HertzLaw | str = "paper",
    *,
    method: str = "duhamel",
    rtol: float = 1e-10,
) -> RayleighResult:
    """Energy left in every mode after a quasistatic collision at speed ``v``.

    Parameters
    ----------
    modes : ModeSet
        Modes driven at ``phi = 0`` through ``C_k``.
    v : float
        Incoming speed towards the wall, ``c`` (below the law's ``max_speed``).
    law : HertzLaw or str
        Contact law, or its name for :func:`restitution.quasistatic.hertz.contact_law` at
        ``modes.nu``.
    method : {"duhamel", "ivp"}
        Exact Duhamel integral with quadrature (default) or DOP853 on eqs. (65)-(67).
    rtol : float
        Tolerance of the ``"ivp"`` integration.

    Returns
    -------
    RayleighResult
    """
    if isinstance(law, str):
        law = contact_law(modes.nu, law)
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
    )


def rayleigh_sweep(
    modes: ModeSet, v: np.ndarray, law: HertzLaw | str = "paper"
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rayleigh energy fraction over speeds ``v`` (Duhamel method).

    Returns
    -------
    v : numpy.ndarray, shape (K,)
    total : numpy.ndarray, shape (K,)
        Energy fraction in all modes.
    quadrupole : numpy.ndarray, shape (K,)
        Energy fraction in the ``(n = 2, l = 0)`` mode.
    """
    v = np.atleast_1d(np.asarray(v, dtype=float))
    res = [rayleigh_energy(modes, float(x), law) for x in v]
    return (
        v,
        np.array([r.energy_fraction for r in res]),
        np.array([r.fraction_of(2, 0) for r in res]),
    )
