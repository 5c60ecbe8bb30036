"""One force pulse with every mechanism: Thornton's elastic-plastic contact, Kelvin-Voigt damping,
and the elastic waves that pulse leaves in the bodies and radiates into a wall.

Units: the first body's reduced units ``E = rho = R = 1`` (speeds in ``c``, times in ``R / c``,
forces in ``E R^2``, the limiting pressure ``p_y`` in ``E``); energies as fractions of the
initial kinetic energy ``(m/2) v^2``.

**The contact** (issue 43). ``m delta'' = -F``, ``delta(0) = 0``, ``delta'(0) = v``, with::

    F = F_ep(delta; history) + A delta' dF_ep/ddelta,

``F_ep`` Thornton's elastic-perfectly-plastic force (:mod:`restitution.quasistatic.plastic`:
Hertz up to ``delta_y``, linear plastic loading, Hertzian unloading with the enlarged radius
``R_p`` from ``delta_p``) and ``A`` the Kelvin-Voigt constant of
:mod:`restitution.quasistatic.viscoelastic` (``A = tau`` for proportional viscosities): the viscous
stress is ``tau`` times the rate of the elastic stress, whose resultant at the current
compression is ``F_ep``; on the plastic branch its rate is the branch's slope ``pi p_y R`` times
``delta'`` (a choice of this package: the capped pressure's rate, as the unloading's is Hertz's).
Without plastic flow (``p_y = None``) this is the viscous collision of
:mod:`restitution.quasistatic.viscoelastic` (the tests compare the two); without damping
(``A = 0``) it is Thornton's collision, whose epsilon has a closed form (the tests fit the
order of their difference in ``rtol``). The contact ends when the total force first reaches
zero (``"force"``, the contact that cannot pull) or when ``delta`` returns to ``delta_p``
(``"compression"``). It is integrated with DOP853 in three pieces (Hertz loading, plastic
loading, unloading), each ended by an event, so that the pieces' joins are points of the
pulse's quadrature.

**The energy of the pulse.** Besides ``epsilon``, the integration carries the work of ``F_ep``
(the plastic work plus the elastic energy still stored at separation), the viscous work, and
``int (dF_ep/dt)^2 dt``, the integral Lamb's point-force radiation into an elastic half-space
needs (:mod:`restitution.quasistatic.half_space`). ``epsilon^2 + plastic + viscous + stored = 1``
is the integrator's check.

**Elastic waves on the actual pulse.** The energy left in a body's modes by the pulse is
Rayleigh's, ``E_k / ((m/2) v^2) = C_k^2 |F(omega_k)|^2 / (m^2 v^2)``
(:mod:`restitution.quasistatic.rayleigh`; ``F(omega)`` the Fourier transform of the pulse, no
longer symmetric, :func:`restitution.quasistatic.pulse.pulse_spectrum`), and the energy
radiated into a half-space is its conductance times ``int (dF/dt)^2 dt``. Both are first order
in the wave loss: the pulse is computed without it. The viscous force starts like ``A v
sqrt(delta)`` (a ``t^(1/2)`` front), whose spectrum falls slowly (``|F| ~ omega^(-3/2)``): the
point force's wave loss on it grows like ``ln`` of the highest frequency kept, a divergence
the finite contact cuts off. The radiation into a wall is therefore taken on ``F_ep`` alone
(damping with an elastic wall is not served), and :class:`PulseCollision.mode_energy` can take
either force (``viscous=False`` leaves the viscous part out).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from restitution.errors import InputError
from restitution.quasistatic.hertz import QuasistaticError
from restitution.quasistatic.hertz_sphere import SPHERE_MASS, SphereHertzLaw
from restitution.quasistatic.plastic import ThorntonContact
from restitution.quasistatic.pulse import panel_nodes, pulse_spectrum

__all__ = ["PulseCollision", "SEPARATIONS", "pulse_collision"]

SEPARATIONS = ("force", "compression")
"""End of contact: the total force reaches zero (default), or ``delta`` returns to ``delta_p``."""

# The scaled window of each piece, in units of the elastic delta_max / v (the plastic pulse is
# longer, by (v / v_y)^(1/5) at most a few times; strong damping slows the restitution).
_S_END = 400.0


@dataclass(frozen=True)
class _Branch:
    """One branch of ``F_ep``: ``kind`` ``"hertz"`` (``K (delta - d0)^(3/2)``) or ``"linear"``
    (``F_y (3 delta / delta_y - 1) / 2``)."""

    kind: str
    K: float = 0.0
    d0: float = 0.0
    slope: float = 0.0
    offset: float = 0.0

    def force_stiffness(self, d):
        """``(F_ep, dF_ep/ddelta)`` at compressions ``d`` (arrays or floats)."""
        if self.kind == "linear":
            return self.slope * d - self.offset, self.slope + 0.0 * d
        e = np.maximum(d - self.d0, 0.0)
        root = np.sqrt(e)
        return self.K * e * root, 1.5 * self.K * root


@dataclass(frozen=True, eq=False)
class _Piece:
    """One integrated piece of the pulse: its branch and DOP853's dense output in the scaled
    time ``s`` (``t = s D / v``)."""

    branch: _Branch
    s0: float
    s1: float
    sol: object


@dataclass(frozen=True, eq=False)
class PulseCollision:
    """One collision with Thornton's contact and Kelvin-Voigt damping (module docs).

    Attributes
    ----------
    v : float
        Incoming (relative) speed, ``c``.
    epsilon : float
        Speed at separation over ``v``, from the contact alone (no wave loss).
    contact_time : float
        First touch to separation, ``R / c``.
    max_compression : float
        Largest ``delta``, ``R``.
    yielded : bool
        Whether the contact went past ``delta_y``.
    plastic_work, viscous_work, stored_energy : float
        Fractions of ``(m/2) v^2``: the work of ``F_ep`` not returned, the viscous work, and
        the elastic energy left in the contact at separation (``"force"``).
    energy_error : float
        ``|epsilon^2 + plastic + viscous + stored - 1|``.
    force_rate_integral : float
        ``int (dF_ep/dt)^2 dt`` over the contact, ``E^2 R^3 c`` (reduced units).
    tau : float
        The Kelvin-Voigt constant ``A``, ``R / c``.
    mass : float
        The (reduced) mass.
    """

    v: float
    epsilon: float
    contact_time: float
    max_compression: float
    yielded: bool
    plastic_work: float
    viscous_work: float
    stored_energy: float
    energy_error: float
    force_rate_integral: float
    tau: float
    mass: float
    _pieces: tuple = field(repr=False)
    _scale: float = field(repr=False)

    def force(self, t, *, viscous: bool = True) -> np.ndarray:
        """The contact force at times ``t`` (``R / c``), zero outside the contact; without the
        viscous part when ``viscous`` is false."""
        t = np.asarray(t, dtype=float)
        s = t * self.v / self._scale
        out = np.zeros(t.shape)
        for p in self._pieces:
            inside = (s >= p.s0) & (s <= p.s1) & (out == 0.0)
            if not np.any(inside):
                continue
            x, y = p.sol(s[inside])[:2]
            F, k = p.branch.force_stiffness(x * self._scale)
            out[inside] = F + (self.tau * self.v * y * k if viscous else 0.0)
        return np.maximum(out, 0.0)

    def spectrum(self, omega, *, viscous: bool = True, per_panel: int = 8) -> np.ndarray:
        """``int F(t) e^{-i omega t} dt`` at frequencies ``omega`` (``c / R``), shape (N,), or
        (N, 2) with and without the viscous part when ``viscous`` is ``"both"``: Gauss-Legendre
        panels of ``per_panel`` nodes and at most a third of the shortest period on each
        piece, graded towards the first touch and the separation."""
        omega = np.asarray(omega, dtype=float)
        t, w = self.quadrature(float(np.max(omega, initial=1.0)), per_panel=per_panel)
        if viscous == "both":
            forces = np.stack([self.force(t), self.force(t, viscous=False)], axis=1)
        else:
            forces = self.force(t, viscous=bool(viscous))
        return pulse_spectrum(forces, (t, w), omega)

    def quadrature(self, omega_max: float, *, per_panel: int = 8) -> tuple[np.ndarray, np.ndarray]:
        """``(t, w)``: the nodes (``R / c``) and weights :meth:`spectrum` integrates on up to
        the frequency ``omega_max`` (``c / R``), Gauss-Legendre panels on each piece."""
        ts, ws = [], []
        last = len(self._pieces) - 1
        for i, p in enumerate(self._pieces):
            a, b = p.s0 * self._scale / self.v, p.s1 * self._scale / self.v
            t, w = panel_nodes(a, b, omega_max, start=i == 0, end=i == last, per_panel=per_panel)
            ts.append(t)
            ws.append(w)
        return np.concatenate(ts), np.concatenate(ws)

    def mode_energy(self, modes, *, viscous: bool | str = True) -> np.ndarray:
        """The energy the pulse leaves in each of ``modes`` (a :class:`~restitution.bodies.
        base.ModalBody` in the same units, driven at its pole), fractions of ``(m/2) v^2``:
        ``C_k^2 |F(omega_k)|^2 / (m^2 v^2)``; shape (N, 2) for ``viscous="both"`` (with and
        without the viscous force)."""
        F = self.spectrum(modes.omega, viscous=viscous)
        C2 = modes.C**2 if F.ndim == 1 else (modes.C**2)[:, None]
        return C2 * np.abs(F) ** 2 / (modes.mass**2 * self.v**2)

    def radiated_fraction(self, conductance: float) -> float:
        """The energy radiated into a half-space, ``conductance * int (dF_ep/dt)^2 dt``
        (:func:`restitution.quasistatic.half_space.radiation_conductance`), a fraction of
        ``(m/2) v^2``."""
        return conductance * self.force_rate_integral / (0.5 * self.mass * self.v**2)


def _check(v, tau, separation, rtol) -> tuple[float, float]:
    for name, x in (("v", v), ("rtol", rtol)):
        if not (isinstance(x, (int, float, np.floating)) and math.isfinite(x) and x > 0):
            raise InputError(f"{name} must be a finite number > 0, got {x!r}")
    if not (isinstance(tau, (int, float, np.floating)) and math.isfinite(tau) and tau >= 0):
        raise InputError(f"tau must be a finite number >= 0, got {tau!r}")
    if separation not in SEPARATIONS:
        raise InputError(f"unknown separation {separation!r}; choose one of {SEPARATIONS}")
    return float(v), float(tau)


def pulse_collision(
    law: SphereHertzLaw,
    v: float,
    *,
    p_y: float | None = None,
    tau: float = 0.0,
    mass: float = SPHERE_MASS,
    separation: str = "force",
    rtol: float = 1e-10,
) -> PulseCollision:
    """One collision at speed ``v`` (``c``) on Hertz's ``law`` (any partner's ``E*`` and
    ``R``), with plastic flow above the limiting pressure ``p_y`` (``E``; ``None``: none) and the
    Kelvin-Voigt constant ``tau`` (``R / c``), for the (reduced) ``mass``.

    Examples
    --------
    >>> from restitution.quasistatic.hertz_sphere import sphere_contact_law
    >>> law = sphere_contact_law(0.3)
    >>> c = pulse_collision(law, 1e-4, p_y=1e-3)
    >>> closed = ThorntonContact(law.E_star, law.R, 1e-3, c.mass).epsilon(1e-4)
    >>> c.yielded, abs(c.epsilon - float(closed)) < 1e-9
    (True, True)
    """
    if not isinstance(law, SphereHertzLaw):
        raise InputError(f"law must be a SphereHertzLaw, got {type(law).__name__}")
    v, tau = _check(v, tau, separation, rtol)
    if not (math.isfinite(mass) and mass > 0):
        raise InputError(f"mass must be a positive number, got {mass!r}")
    thornton = None if p_y is None else ThorntonContact(law.E_star, law.R, p_y, mass)
    K = law.K
    D = (1.25 * mass * v * v / K) ** 0.4  # the elastic delta_max: the scale of x
    g = D / (mass * v * v)
    kv = tau * v / D
    norm = K * K * D

    def rhs_of(branch: _Branch):
        def rhs(s, y):
            F, k = branch.force_stiffness(y[0] * D)
            total = F + tau * v * y[1] * k
            return [y[1], -g * total, 2.0 * g * F * y[1], 2.0 * g * tau * v * k * y[1] ** 2,
                    k * k / norm * y[1] ** 2]  # fmt: skip

        return rhs

    def too_deep(s, y):
        return y[0] * D - law.max_compression

    too_deep.terminal, too_deep.direction = True, 1
    # A window long enough for the slowest piece: the plastic one is a linear spring.
    window = _S_END * (1.0 + kv)
    if thornton is not None:
        window += 10.0 * math.sqrt(mass / thornton.plastic_stiffness) * v / D

    def run(branch, s0, y0, events):
        sol = solve_ivp(rhs_of(branch), (s0, s0 + window), y0, method="DOP853", rtol=rtol,
                        atol=rtol * 1e-3, events=[*events, too_deep],
                        dense_output=True)  # fmt: skip
        if sol.status == 1 and len(sol.t_events[-1]):
            raise InputError(
                f"at v = {v:g} c the compression reaches the radius R (limiting pressure "
                f"{p_y:g} E): far outside the contact theory; the grain is crushed, not bounced"
            )
        if sol.status != 1:
            raise QuasistaticError(
                f"no end of the {branch.kind} piece at v = {v:g}, tau = {tau:g}: {sol.message}; "
                "try a smaller tau"
            )
        hit = next(i for i, te in enumerate(sol.t_events) if len(te))
        return sol, hit, float(sol.t_events[hit][0]), sol.y_events[hit][0]

    def turning(s, y):
        return y[1]

    turning.terminal, turning.direction = True, -1
    pieces = []
    hertz = _Branch("hertz", K=K)
    events = [turning]
    if thornton is not None:
        xy = thornton.yield_compression / D

        def yielding(s, y):
            return y[0] - xy

        yielding.terminal, yielding.direction = True, 1
        events.append(yielding)
    sol, hit, s1, y1 = run(hertz, 0.0, [0.0, 1.0, 0.0, 0.0, 0.0], events)
    pieces.append(_Piece(hertz, 0.0, s1, sol.sol))
    yielded = hit == 1
    if yielded:
        plastic = _Branch("linear", slope=thornton.plastic_stiffness,
                          offset=0.5 * thornton.yield_force)  # fmt: skip
        s0 = s1
        sol, hit, s1, y1 = run(plastic, s0, list(y1), [turning])
        pieces.append(_Piece(plastic, s0, s1, sol.sol))
    dmax = float(y1[0]) * D
    r_p, d_p = thornton.unloading(dmax) if yielded else (law.R, 0.0)
    unload = _Branch("hertz", K=4.0 / 3.0 * law.E_star * math.sqrt(r_p), d0=d_p)
    xp = d_p / D

    def force_zero(s, y):
        return (y[0] - xp) / 1.5 + kv * y[1]  # F_total / (dF_ep/ddelta D) on this branch

    def back(s, y):
        return y[0] - xp

    end = force_zero if separation == "force" else back
    end.terminal, end.direction = True, -1
    s0 = s1
    sol, hit, s1, y_end = run(unload, s0, list(y1), [end])
    pieces.append(_Piece(unload, s0, s1, sol.sol))
    x_end, xs_end, w_ep, w_v, z = (float(c) for c in y_end)
    eps = max(-xs_end, 0.0)
    sep = max(x_end - xp, 0.0) * D if separation == "force" else 0.0
    stored = 0.4 * unload.K * sep**2.5 / (0.5 * mass * v * v)
    # Without plastic flow the work of F_ep is all stored: its difference is the integrator's.
    plastic_work = w_ep - stored if yielded else 0.0
    return PulseCollision(
        v=v,
        epsilon=eps,
        contact_time=s1 * D / v,
        max_compression=dmax,
        yielded=yielded,
        plastic_work=plastic_work,
        viscous_work=w_v,
        stored_energy=stored,
        energy_error=abs(eps**2 + w_ep + w_v - 1.0),  # plastic + stored = w_ep
        force_rate_integral=z * norm * D * v,
        tau=tau,
        mass=float(mass),
        _pieces=tuple(pieces),
        _scale=D,
    )
