"""Time integrators for the disk-wall Hamiltonian (paper eqs. 41-45, corrected per ERRATA).

Units: ``E = rho = R = 1``; times in ``R / c``.

The Hamiltonian is ``H = H_free + V`` with the free part (translation and every mode an exact
harmonic oscillator)::

    H_free = p0^2 / (2m) + sum_k [P_k^2 / (2m) + (m/2) omega_k^2 Q_k^2]

and the wall potential ``V(x0, Q)`` of a contact law (:mod:`restitution.dynamics.contact`; the
paper's exponential wall by default). Every integrator implements
the same tiny interface: ``step(system, state, dt) -> state`` with class attributes ``order`` and
``symplectic``. States hold a batch of ``B`` independent collisions sharing one mode set.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import ClassVar, Protocol

import numpy as np

from restitution.bodies.base import SurfaceQuadrature
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.damping import damped_flow

__all__ = [
    "System",
    "State",
    "Integrator",
    "StrangSplit",
    "YoshidaSplit",
    "RK4Interaction",
    "INTEGRATORS",
    "free_modes",
    "initial_state",
    "total_energy",
    "mode_energies",
]


@dataclass(frozen=True, eq=False)
class System:
    """Everything constant during a batch of collisions.

    Attributes
    ----------
    omega : numpy.ndarray, shape (N,)
        Mode frequencies, ``c / R``.
    mass : float
        Disk mass ``m = pi``.
    quad : SurfaceQuadrature
        Edge quadrature of the wall integral for these modes.
    alpha : numpy.ndarray, shape (B,)
        Wall hardness per batch member (the exponential wall: ``1 / R``).
    damping : numpy.ndarray, shape (N,), or None
        Damping rate of every mode (``c / R``) of a viscoelastic body; ``None``: elastic.
    law : ContactLaw
        The contact law (:mod:`restitution.dynamics.contact`); the exponential wall by default.
    """

    omega: np.ndarray
    mass: float
    quad: SurfaceQuadrature
    alpha: np.ndarray
    damping: np.ndarray | None = None
    law: ContactLaw = EXPONENTIAL_WALL
    # Memo of the harmonic rotation (cos, sin, m omega sin, sin/(m omega)) per step size.
    _rotations: dict = field(default_factory=dict, repr=False, compare=False)

    def rotation(self, dt: float) -> tuple[np.ndarray, ...]:
        """``cos(omega dt)``, ``sin(omega dt) / (m omega)``, ``m omega sin(omega dt)``."""
        rot = self._rotations.get(dt)
        if rot is None:
            mw = self.mass * self.omega
            c, s = np.cos(self.omega * dt), np.sin(self.omega * dt)
            rot = (c, s / mw, mw * s)
            if len(self._rotations) < 16:
                self._rotations[dt] = rot
        return rot


@dataclass(frozen=True, eq=False)
class State:
    """Phase-space point of a batch, with the wall terms at its positions cached.

    Attributes
    ----------
    t : float
        Time, ``R / c``.
    x0, p0 : numpy.ndarray, shape (B,)
        Centre-of-mass position (``R``) and momentum (``m c``) towards the wall.
    Q, P : numpy.ndarray, shape (B, N)
        Modal coordinates and momenta.
    V, F : numpy.ndarray, shape (B,)
        Wall potential and total wall force at ``(x0, Q)``.
    f : numpy.ndarray, shape (B, N)
        Generalised wall forces ``dV/dQ`` at ``(x0, Q)``.
    dissipated : numpy.ndarray, shape (B,), or float
        Energy the modes' damping has taken since the start (``0.0``: none).
    """

    t: float
    x0: np.ndarray
    p0: np.ndarray
    Q: np.ndarray
    P: np.ndarray
    V: np.ndarray
    F: np.ndarray
    f: np.ndarray
    dissipated: np.ndarray | float = 0.0

    def take(self, index: np.ndarray) -> State:
        """Batch members at ``index``."""
        return State(
            t=self.t,
            x0=self.x0[index],
            p0=self.p0[index],
            Q=self.Q[index],
            P=self.P[index],
            V=self.V[index],
            F=self.F[index],
            f=self.f[index],
            dissipated=np.broadcast_to(self.dissipated, self.x0.shape)[index],
        )


def _evaluate(system: System, t: float, x0, p0, Q, P, dissipated=0.0) -> State:
    V, F, f = system.law.contact_terms(system.quad, system.alpha, x0, Q)
    return State(t=t, x0=x0, p0=p0, Q=Q, P=P, V=V, F=F, f=f, dissipated=dissipated)


def initial_state(
    system: System, x0: np.ndarray, p0: np.ndarray, Q: np.ndarray | None = None, P=None
) -> State:
    """Disks at ``x0`` moving with momenta ``p0``; modal state ``(Q, P)``, shape (B, N), or
    all modes at rest (undeformed disks) when omitted."""
    B, N = x0.size, system.omega.size
    Q = np.zeros((B, N)) if Q is None else np.array(Q, dtype=float)
    P = np.zeros((B, N)) if P is None else np.array(P, dtype=float)
    return _evaluate(system, 0.0, np.asarray(x0, float), np.asarray(p0, float), Q, P)


def mode_energies(system: System, state: State) -> np.ndarray:
    """Energy of every mode, ``P^2/(2m) + (m/2) omega^2 Q^2``; shape (B, N)."""
    m = system.mass
    return state.P**2 / (2.0 * m) + 0.5 * m * (system.omega * state.Q) ** 2


def total_energy(system: System, state: State) -> np.ndarray:
    """Total energy ``H`` of every batch member, with the energy dissipated so far counted
    (constant under the exact flow); shape (B,)."""
    kinetic = state.p0**2 / (2.0 * system.mass)
    return kinetic + mode_energies(system, state).sum(axis=1) + state.V + state.dissipated


class Integrator(Protocol):
    """One step of a time integrator: ``step(system, state, dt) -> state``."""

    name: ClassVar[str]
    order: ClassVar[int]
    symplectic: ClassVar[bool]

    def step(self, system: System, state: State, dt: float) -> State: ...


def free_modes(omega, mass: float, Q, P, t):
    """Exact free oscillation of the modes over a time ``t`` (``R / c``, may be negative).

    ``Q`` (``R``) and ``P`` (``m c``) have shape (..., N) and ``omega`` (``c / R``) shape (N,);
    ``t`` is a number or broadcasts against the leading axes (shape (B, 1) for a batch).
    Returns ``(Q(t), P(t))``; every mode's energy is unchanged.
    """
    omega = np.asarray(omega, dtype=float)
    Q = np.asarray(Q, dtype=float)
    P = np.asarray(P, dtype=float)
    arg = omega * np.asarray(t, dtype=float)
    c, s = np.cos(arg), np.sin(arg)
    mw = mass * omega
    return Q * c + P * (s / mw), P * c - Q * (mw * s)


def _free_flow(system: System, x0, p0, Q, P, dt: float):
    """Exact flow of ``H_free`` over ``dt``: translation and harmonic rotation (damped modes:
    their exact damped flow). Returns ``(x0, Q, P, lost)``, ``lost`` (shape (B,) or ``0.0``)
    the energy the damping took."""
    x0 = x0 + p0 * (dt / system.mass)
    if system.damping is None:
        c, s_over, s_times = system.rotation(dt)
        return x0, Q * c + P * s_over, P * c - Q * s_times, 0.0
    if dt < 0:
        raise ValueError("a damped mode cannot be flowed backwards in time")
    a, b, c, d = damped_flow(system.omega, system.damping, system.mass, dt)
    Qn = Q * a + P * b
    Pn = P * d - Q * c
    m, w2 = system.mass, system.omega**2
    lost = ((P**2 - Pn**2) / (2.0 * m) + 0.5 * m * w2 * (Q**2 - Qn**2)).sum(axis=-1)
    return x0, Qn, Pn, lost


@dataclass(frozen=True)
class StrangSplit:
    """Strang splitting: half kick of the wall, exact free flow, half kick.

    Second order, symplectic and time-reversible. The free motion of the centre of mass and of
    every mode is integrated exactly, so the step is limited only by how fast the wall force
    changes (the wall stiffness ``alpha F`` coupled through the edge amplitudes), not by the
    highest mode frequency. Like every impulse method it can resonate when ``omega_k dt`` is
    near a multiple of ``pi`` for a mode strongly driven by the wall; the collision driver
    therefore monitors the energy and refines the step. One wall evaluation per step.
    """

    name: ClassVar[str] = "split"
    order: ClassVar[int] = 2
    symplectic: ClassVar[bool] = True
    weights: ClassVar[tuple[float, ...]] = (1.0,)

    def step(self, system: System, state: State, dt: float) -> State:
        h = 0.5 * dt
        p0 = state.p0 - h * state.F
        P = state.P - h * state.f
        x0, Q, P, lost = _free_flow(system, state.x0, p0, state.Q, P, dt)
        new = _evaluate(system, state.t + dt, x0, p0, Q, P, state.dissipated + lost)
        return replace(new, p0=new.p0 - h * new.F, P=new.P - h * new.f)


_W1 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
_W0 = 1.0 - 2.0 * _W1
YOSHIDA = (_W1, _W0, _W1)
"""Yoshida's weights of three Strang steps: the fourth-order composition of ``split4``."""


@dataclass(frozen=True)
class YoshidaSplit:
    """Yoshida's fourth-order composition of three Strang steps (weights w1, w0, w1).

    Fourth order, symplectic and time-reversible; three wall evaluations per step. The middle
    sub-step runs backwards in time (w0 < 0).
    """

    name: ClassVar[str] = "split4"
    order: ClassVar[int] = 4
    symplectic: ClassVar[bool] = True
    weights: ClassVar[tuple[float, ...]] = (_W1, _W0, _W1)

    def step(self, system: System, state: State, dt: float) -> State:
        strang = StrangSplit()
        for w in self.weights:
            state = strang.step(system, state, w * dt)
        return state


@dataclass(frozen=True)
class RK4Interaction:
    """Classical fourth-order Runge-Kutta in the interaction picture (the paper's method).

    Each mode is written as ``z = q exp(i omega tau)`` with
    ``Q = Re z`` and ``P = -m omega Im z`` (ERRATA item 4), ``tau`` counted from the start of
    the step, so that the free oscillation is exact and only the wall term is integrated::

        dq/dtau = +i exp(-i omega tau) f / (m omega),  dx0/dtau = p0 / m,  dp0/dtau = -F.

    (With ``Q = Re(q e^{i omega t})`` the force enters with ``+i``: eq. (44) as printed, with
    ``-i``, drives the modes with the wrong sign; see docs/equations.md.) Fourth order, not
    symplectic, not time-reversible; four wall evaluations per step; the step must resolve the
    highest mode frequency because the forcing term oscillates at it.
    """

    name: ClassVar[str] = "rk4"
    order: ClassVar[int] = 4
    symplectic: ClassVar[bool] = False

    def step(self, system: System, state: State, dt: float) -> State:
        m, w = system.mass, system.omega
        mw = m * w
        q0 = state.Q - 1j * state.P / mw

        def deriv(tau, x0, p0, q, F=None, f=None):
            phase = np.exp(1j * w * tau)
            if F is None:
                Q = (q * phase).real
                _, F, f = system.law.contact_terms(system.quad, system.alpha, x0, Q)
            return p0 / m, -F, 1j * f / (mw * phase)

        k1 = deriv(0.0, state.x0, state.p0, q0, F=state.F, f=state.f)
        y2 = [a + 0.5 * dt * b for a, b in zip((state.x0, state.p0, q0), k1, strict=True)]
        k2 = deriv(0.5 * dt, *y2)
        y3 = [a + 0.5 * dt * b for a, b in zip((state.x0, state.p0, q0), k2, strict=True)]
        k3 = deriv(0.5 * dt, *y3)
        y4 = [a + dt * b for a, b in zip((state.x0, state.p0, q0), k3, strict=True)]
        k4 = deriv(dt, *y4)
        x0, p0, q = (
            a + dt / 6.0 * (b1 + 2.0 * b2 + 2.0 * b3 + b4)
            for a, b1, b2, b3, b4 in zip((state.x0, state.p0, q0), k1, k2, k3, k4, strict=True)
        )
        z = q * np.exp(1j * w * dt)
        return _evaluate(system, state.t + dt, x0, p0, z.real, -mw * z.imag)


INTEGRATORS: dict[str, Integrator] = {
    cls.name: cls() for cls in (StrangSplit, YoshidaSplit, RK4Interaction)
}
