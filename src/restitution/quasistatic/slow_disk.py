"""The disk's slow impacts: its low modes in motion, its high modes following the contact
statically, and the contact closed by the 2D Hertz law; for a disk on a wall and for two disks.

Units: two-dimensional (plane-stress) ``E = rho = R = 1``, ``m = pi``; ``v`` the speed towards the
wall in ``c``; times in ``R / c``; energies as fractions of the initial kinetic energy
``(m/2) v^2``. Two disks (a :class:`~restitution.bodies.pair.body.BodyPair`): the first disk's
units, ``v`` the relative speed ``w`` of the centres, ``m`` the reduced mass ``mu`` (every mode
rescaled to it, as the pair body does), energies fractions of ``(mu/2) w^2``.

Why a third route for the disk. Below ``v ~ 1e-4`` the modal collision does not converge within
the modes a mode scan affords (the contact half-width shrinks like ``sqrt(v)``, and the soft
wall's own limit needs ``alpha delta_max`` large), and the finite elements cost hours a point at
``v ~ 1e-6``. Rayleigh's estimate on the quasistatic pulse, which serves the sphere
(:mod:`restitution.quasistatic.low_speed`), does not work for the disk at any speed a user meets:
its contact time ``tau ~ pi sqrt(ln(4/v))`` grows only logarithmically, so the lowest modes
(``omega tau ~ 15``) still take part in the contact and shift its duration, and the drive of each
mode, which passes through zeros as ``tau`` changes, moves with it: against the modal law
Rayleigh's estimate is off by factors 0.3 to 2.5 (docs/results.md).

The model. Split the modes at a frequency ``Omega``. The modes below it (``K`` of them) move;
the modes above it are so fast against the contact (``omega tau >> 1``) that they follow the
force statically, and together with the contact's local field they make up the static
compliance the 2D Hertz law describes. With ``delta = x0 + 1`` the approach of the centre of
mass, the force ``P >= 0`` at the contact point and ``C_k`` the modes' normal amplitude there::

    m delta''  = -P
    m Q_k''    = -m omega_k^2 Q_k - C_k P            (k <= K)
    delta + sum_{k<=K} C_k Q_k = delta_law(P) - P S_K,   S_K = sum_{k<=K} C_k^2 / (m omega_k^2)

``delta_law`` is the centre-of-mass law of :func:`restitution.quasistatic.hertz.contact_law`
(``c = -1 - 2/pi - nu/4``): the whole static compliance of a load ``P``; for two disks their
law :func:`restitution.quasistatic.hertz_pair.pair_contact_law` (``E = E_eff``), with both
disks' modes below the cut in the sum: one common physical frequency cuts both. Two identical
disks at ``w`` are then the disk on a wall at ``w / 2`` (the tests: to 1e-9). The static part of the
kept modes, ``P S_K``, is taken out of it because those modes now move. The closure is again a
2D Hertz law, with the constant ``c - pi E S_K``, so ``P`` follows in closed form (Lambert W).
With ``K = 0`` the model is the quasistatic collision; as ``K`` grows the contact time and the
pulse take up the low modes' motion. It holds while the kept modes are long against the contact
half-width ``a`` (``Omega a << 1``: the load acts at a point for them) and the dropped modes fast
(``Omega tau >> 1``). Both hold better as ``v -> 0``; where ``Omega`` reaches the contact width
the shifted law stops being monotonic before ``delta_max`` and the cut is refused.

Energy: no energy leaves the model except into the kept modes, so
``1 - epsilon^2 = sum_{k<=K} E_k / ((m/2) v^2)`` (checked in the tests). The modes above
``Omega`` keep only what the static following leaves (of relative order ``(omega tau)^-2``):
it is what the convergence in ``Omega`` measures.

Checked: ``K = 0`` against the quasistatic collision; energy conservation and time reversal;
convergence in ``Omega`` (the loss changes like ``Omega^-2``); the modal law and the finite
elements at ``v = 1e-4 - 1e-3`` (docs/quasistatic.md, section 7).

The leading behaviour as ``v -> 0`` (:func:`asymptotic_loss`). For ``omega tau >> 1`` a mode's
drive comes from the two ends of the pulse, where ``P = pi E delta / Lambda(delta)`` with
``delta ~ v t``; to first order in ``1 / Lambda``::

    E_k / ((m/2) v^2) = (4 pi^2 E^2 / m^2) (C_k^2 / omega_k^4) [Re(exp(i omega_k tau/2) / L_k)]^2,
    L_k = ln(4 R omega_k / v) + c + ln(Lambda_max) + gamma_E - 1 + i pi / 2.

So ``1 - epsilon^2`` falls only like ``1 / ln^2(1/v)``, with oscillations through the phases
``omega_k tau / 2`` (``tau ~ pi sqrt(ln(4/v))``), and its relative corrections are of order
``1 / ln(1/v)``: the leading form is off by 10-40 % even at ``v = 1e-14``.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from scipy.integrate import solve_ivp

from restitution.bodies.base import ModalBody
from restitution.bodies.disk.kind import KIND as DISK
from restitution.errors import InputError, RestitutionError
from restitution.estimate import Estimate
from restitution.jsonable import finite_tree
from restitution.quasistatic.hertz import HertzLaw, contact_law, quasistatic_collision
from restitution.quasistatic.hertz_pair import pair_contact_law
from restitution.status import Status

__all__ = [
    "MODEL_SPREAD",
    "closure_law",
    "slow_modes",
    "equations",
    "run_contact",
    "shifted_law",
    "cut_fits",
    "SLOW_CUTS",
    "SLOW_MODES",
    "SlowCollision",
    "SlowLoss",
    "asymptotic_loss",
    "slow_collision",
    "slow_loss",
]

SLOW_CUTS = (5.0, 7.07, 10.0, 14.14, 20.0, 28.28)
"""Cut frequencies ``Omega`` (``c / R``) tried by :func:`slow_loss`, a factor ``sqrt(2)`` apart.
At ``v = 1e-4``, ``nu = 0.33`` they keep 14-421 modes."""

SLOW_MODES = 1200
"""Modes loaded for the cuts: the 1200 lowest reach above ``omega = 28.28`` for every ``nu``;
a pair of disks of radii 1 and ``r`` loads ``1200 (1 + r^2)`` (:func:`slow_modes`)."""

MODEL_SPREAD = 0.012
"""Relative error of the model itself, counted in every point: the largest relative deviation of
its loss from the finite-element reference points at ``v = 1e-4`` and ``1e-3``
(``laws/data/fem_reference.json``: ``nu = 0.33``, ``v = 1e-4``, 0.00527 against 0.005209;
docs/quasistatic.md, section 7)."""

# The cut must leave the shifted law monotonic well beyond the largest force: its limit P* at
# least this many times the quasistatic peak force (near P* its stiffness diverges). This keeps
# Omega a below about 0.55 (a the contact half-width); at v = 1e-3 the loss is converged in
# Omega up to the cut where the ratio is 2 (docs/quasistatic.md, section 7).
_MARGIN = 4.0
# Relative tolerance of DOP853; the energy error of a run is below 1e-9 of the initial energy.
_RTOL = 1e-10


class SlowCollisionError(RestitutionError):
    """The integration of the slow collision failed."""


@dataclass(frozen=True, eq=False)
class SlowCollision:
    """One slow collision of the model at one cut.

    Attributes
    ----------
    v, nu : float
        Speed towards the wall (``c``) and the disk's two-dimensional Poisson number.
    omega_cut : float
        ``Omega``, ``c / R``.
    n_dynamic : int
        ``K``, the modes below the cut.
    epsilon, energy_loss : float
        ``-delta'(end) / v`` and ``1 - epsilon^2``.
    mode_energy : numpy.ndarray, shape (K,)
        Energy left in each kept mode, fraction of ``(m/2) v^2``.
    energy_error : float
        ``|energy_loss - sum(mode_energy)|``: the integration's energy error.
    contact_time, quasistatic_contact_time : float
        Of this collision and of the quasistatic one (``K = 0``), ``R / c``.
    max_compression, max_force : float
        Largest ``delta`` (``R``) and ``P`` (``E R``).
    steps : int
        Right-hand side evaluations of DOP853.
    """

    v: float
    nu: float
    omega_cut: float
    n_dynamic: int
    epsilon: float
    energy_loss: float
    mode_energy: np.ndarray
    energy_error: float
    contact_time: float
    quasistatic_contact_time: float
    max_compression: float
    max_force: float
    steps: int


_BODIES = (DISK.geometry, f"{DISK.geometry}-pair")


def _checked(modes: ModalBody, v: float) -> None:
    if getattr(modes, "geometry", None) not in _BODIES:
        raise InputError(
            f"the slow-impact model is derived for the disk and two disks, not for the "
            f"{getattr(modes, 'geometry', type(modes).__name__)} (the sphere's slow impacts: "
            "restitution.quasistatic.low_speed)"
        )
    if not (isinstance(v, (int, float)) and math.isfinite(v) and 0 < v <= 2e-2):
        raise InputError(
            f"v = {v!r} c is outside the slow-impact model's range 0 < v <= 0.02 c; faster "
            "impacts come from the modal laws"
        )


def slow_modes(nu: float, partner=None) -> ModalBody:
    """The modes :func:`slow_loss` needs: the disk's :data:`SLOW_MODES` lowest, or for two
    disks (``partner``, a :class:`~restitution.bodies.pair.partner.Partner`) the
    ``SLOW_MODES (1 + r^2 rho2 / E2)`` lowest of the pair (both disks' modes up to one
    frequency: a disk of radius ``r`` and wave speed ``c2`` has ``(r / c2)^2`` times as many
    modes below it, as in :func:`restitution.limits.sweep.pair_settings`)."""
    if partner is None:
        from restitution.bodies.cache import get_modes

        return get_modes(nu, SLOW_MODES, geometry=DISK.geometry)
    share = partner.radius_ratio**2 * partner.density_ratio / partner.modulus_ratio
    count = int(round(SLOW_MODES * (1.0 + share)))
    return partner.pair(nu, count, geometry=DISK.geometry)


def closure_law(modes: ModalBody) -> HertzLaw:
    """The whole static compliance of the contact: the disk's centre-of-mass law
    (:func:`restitution.quasistatic.hertz.contact_law`), or two disks' law
    (:func:`restitution.quasistatic.hertz_pair.pair_contact_law`) for a
    :class:`~restitution.bodies.pair.body.BodyPair`."""
    if modes.geometry == DISK.geometry:
        return contact_law(modes.nu, "centre")
    return pair_contact_law(
        modes.nu,
        modes.nu2,
        radius_ratio=modes.radius_ratio,
        modulus_ratio=modes.modulus_ratio,
    )


def shifted_law(modes: ModalBody, omega_cut: float) -> tuple[HertzLaw, np.ndarray]:
    """The closure of the model at the cut ``omega_cut``: :func:`closure_law` with the kept
    modes' static compliance taken out, and the mask of the kept modes."""
    keep = modes.omega <= omega_cut
    base = closure_law(modes)
    S = float(np.sum(modes.C[keep] ** 2 / (modes.mass * modes.omega[keep] ** 2)))
    law = HertzLaw(
        nu=modes.nu, constant=base.constant - math.pi * base.E * S, name="slow", E=base.E,
        R=base.R,
    )  # fmt: skip
    return law, keep


def _quasistatic(modes: ModalBody, v: float):
    return quasistatic_collision(closure_law(modes), v, mass=modes.mass)


def cut_fits(modes: ModalBody, v: float, omega_cut: float) -> bool:
    """Whether the cut keeps the shifted law monotonic to 4 times the quasistatic peak force."""
    law, _ = shifted_law(modes, omega_cut)
    return law.max_force >= _MARGIN * float(_quasistatic(modes, v).max_force[0])


def equations(law: HertzLaw, omega: np.ndarray, C: np.ndarray, mass: float, tau: float = 0.0):
    """``(force, rhs)`` of the model for the state ``y = (delta, delta', Q, Q')``: the contact
    force ``force(y)`` and the right-hand side ``rhs(t, y)`` for
    :func:`scipy.integrate.solve_ivp`.

    The force is the closure ``P(s)`` of the gap closure ``s = delta + sum C_k Q_k``; with a
    relaxation time ``tau > 0`` (``R / c``; :mod:`restitution.quasistatic.slow_damped`) the
    Kelvin-Voigt force ``P(s) + tau P'(s) s'`` (zero where ``s <= 0``) and the kept modes damped,
    ``Q_k'' = -omega_k^2 (Q_k + tau Q_k') - C_k P / m``."""
    K = omega.size
    E, R, c = law.E, law.R, law.constant

    def closure(y) -> float:
        return y[0] + C @ y[2 : 2 + K]

    def force(y) -> float:
        s = closure(y)
        if s <= 0:
            return 0.0
        elastic = float(law.force(s))
        if tau == 0:
            return elastic
        stiffness = math.pi * E / (math.log(4.0 * math.pi * E * R / elastic) + c - 1.0)
        return elastic + tau * stiffness * (y[1] + C @ y[2 + K :])

    def rhs(t, y):
        Q, Qv = y[2 : 2 + K], y[2 + K :]
        P = force(y)
        out = np.empty_like(y)
        out[0] = y[1]
        out[1] = -P / mass
        out[2 : 2 + K] = Qv
        if tau == 0:
            out[2 + K :] = -(omega**2) * Q - C * (P / mass)
        else:
            out[2 + K :] = -(omega**2) * (Q + tau * Qv) - C * (P / mass)
        return out

    force.closure = closure
    return force, rhs


def run_contact(rhs, opened, v: float, tau_qs: float, K: int, what: str, *, dense: bool = False):
    """Integrate one slow collision from first touch (``delta = 0``, ``delta' = v``, the modes
    at rest) with DOP853 until ``opened(y)`` falls through zero after the first 5 % of the
    quasistatic contact time ``tau_qs``; at most ``3 tau_qs``. Returns the
    :func:`scipy.integrate.solve_ivp` solution; :class:`SlowCollisionError` naming ``what`` if
    the contact does not open."""

    def apart(t, y):
        return opened(y) if t > 0.05 * tau_qs else 1.0

    apart.terminal = True
    apart.direction = -1
    y0 = np.zeros(2 + 2 * K)
    y0[1] = v
    sol = solve_ivp(
        rhs, (0.0, 3.0 * tau_qs), y0, method="DOP853", rtol=_RTOL, atol=1e-14 * v,
        events=apart, dense_output=dense,
    )  # fmt: skip
    if sol.status != 1 or not sol.t_events[0].size:
        raise SlowCollisionError(
            f"the {what} did not end within {3.0 * tau_qs:.3g} R/c ({sol.message})"
        )
    return sol


def slow_collision(modes: ModalBody, v: float, omega_cut: float) -> SlowCollision:
    """One slow collision of the disk with the modes below ``omega_cut`` in motion.

    Parameters
    ----------
    modes : ModalBody
        The disk's modes (``geometry == "disk"``), reaching beyond ``omega_cut``.
    v : float
        Speed towards the wall, ``0 < v <= 0.01`` (``c``).
    omega_cut : float
        ``Omega`` (``c / R``), ``>= 0``; 0 gives the quasistatic collision.

    Returns
    -------
    SlowCollision
    """
    _checked(modes, v)
    if not (math.isfinite(omega_cut) and omega_cut >= 0):
        raise InputError(f"omega_cut must be >= 0, got {omega_cut!r}")
    if omega_cut >= float(np.max(modes.omega)):
        raise InputError(
            f"the {len(modes)} modes end at omega = {float(np.max(modes.omega)):.4g}, below the "
            f"cut {omega_cut:g}; load more modes"
        )
    qs = _quasistatic(modes, v)
    tau_qs = float(qs.contact_time[0])
    law, keep = shifted_law(modes, omega_cut)
    if law.max_force < _MARGIN * float(qs.max_force[0]):
        raise InputError(
            f"the cut Omega = {omega_cut:g} reaches the contact width at v = {v:g} c: the closure "
            f"stops being monotonic at P = {law.max_force:.3g} E R, within {_MARGIN:g} times the "
            f"peak force {float(qs.max_force[0]):.3g}; use a lower cut"
        )
    om, C, m = modes.omega[keep], modes.C[keep], modes.mass
    K = om.size
    force, rhs = equations(law, om, C, m)
    # The contact opens when the gap closure s falls back through 0.
    what = f"slow collision at v = {v:g}, Omega = {omega_cut:g}"
    sol = run_contact(rhs, force.closure, v, tau_qs, K, what, dense=True)
    t_end = float(sol.t_events[0][0])
    y = sol.y_events[0][0]
    Q, Qv = y[2 : 2 + K], y[2 + K :]
    mode_energy = 0.5 * m * (Qv**2 + om**2 * Q**2) / (0.5 * m * v**2)
    eps = -float(y[1]) / v
    loss = 1.0 - eps**2
    grid = np.linspace(0.0, t_end, 401)
    states = sol.sol(grid)
    return SlowCollision(
        v=float(v),
        nu=float(modes.nu),
        omega_cut=float(omega_cut),
        n_dynamic=int(K),
        epsilon=eps,
        energy_loss=float(loss),
        mode_energy=mode_energy,
        energy_error=float(abs(loss - mode_energy.sum())),
        contact_time=t_end,
        quasistatic_contact_time=tau_qs,
        max_compression=float(states[0].max()),
        max_force=max(force(states[:, j]) for j in range(grid.size)),
        steps=int(sol.nfev),
    )


@dataclass(frozen=True)
class SlowLoss:
    """The disk's loss at a slow impact, with its error.

    Attributes
    ----------
    v, nu : float
        Speed (``c``) and two-dimensional Poisson number.
    energy_loss, energy_loss_err : float
        ``1 - epsilon^2`` at the highest cut that fits, and its error: the convergence error
        plus :data:`MODEL_SPREAD` of the loss; :attr:`epsilon`, :attr:`epsilon_err` and
        :attr:`estimate` derive from them.
    cuts, losses : tuple of float
        The cuts that fit and the loss at each.
    convergence_err : float
        The largest change of the loss between the highest cut and the two below it.
    model_err : float
        ``MODEL_SPREAD * energy_loss``.
    contact_time, max_compression : float
        Of the collision at the highest cut.
    """

    v: float
    nu: float
    energy_loss: float
    energy_loss_err: float
    cuts: tuple[float, ...]
    losses: tuple[float, ...]
    convergence_err: float
    model_err: float
    contact_time: float
    max_compression: float

    @property
    def epsilon(self) -> float:
        """``sqrt(1 - energy_loss)``."""
        return math.sqrt(1.0 - self.energy_loss)

    @property
    def epsilon_err(self) -> float:
        """``energy_loss_err / (2 epsilon)``."""
        return self.energy_loss_err / (2.0 * self.epsilon)

    def to_dict(self) -> dict:
        """JSON-ready: the fields, epsilon and its error after the loss's."""
        fields = list(asdict(self).items())
        at = [name for name, _ in fields].index("energy_loss_err") + 1
        eps = [("epsilon", self.epsilon), ("epsilon_err", self.epsilon_err)]
        return finite_tree(dict(fields[:at] + eps + fields[at:]))

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return Estimate(self.epsilon, self.epsilon_err, Status.QUASISTATIC)


def slow_loss(modes: ModalBody, v: float, *, cuts=SLOW_CUTS) -> SlowLoss:
    """The disk's vibrational loss at speed ``v`` from the model, with its error.

    Runs :func:`slow_collision` at every cut of ``cuts`` that fits (:func:`cut_fits`); at least
    three must. The served value is the highest cut's; the error is the largest change between
    it and the two cuts below it, plus :data:`MODEL_SPREAD` of the loss.
    """
    _checked(modes, v)
    fitting = [float(c) for c in cuts if cut_fits(modes, v, float(c))]
    if len(fitting) < 3:
        raise InputError(
            f"only {len(fitting)} of the cuts {', '.join(f'{c:g}' for c in cuts)} fit at v = "
            f"{v:g} c (the contact is too wide for the model); use the modal law there"
        )
    runs = [slow_collision(modes, v, c) for c in fitting]
    losses = [r.energy_loss for r in runs]
    loss = losses[-1]
    conv = max(abs(loss - x) for x in losses[-3:-1])
    model = MODEL_SPREAD * loss
    err = conv + model
    return SlowLoss(
        v=float(v),
        nu=float(modes.nu),
        energy_loss=float(loss),
        energy_loss_err=float(err),
        cuts=tuple(fitting),
        losses=tuple(float(x) for x in losses),
        convergence_err=float(conv),
        model_err=float(model),
        contact_time=runs[-1].contact_time,
        max_compression=runs[-1].max_compression,
    )


def asymptotic_loss(modes: ModalBody, v, contact_time=None) -> np.ndarray:
    """The leading behaviour of the loss as ``v -> 0`` (module docs), at speeds ``v``.

    Parameters
    ----------
    modes : ModalBody
        The disk's modes.
    v : array_like, shape (S,)
        Speeds, ``c``.
    contact_time : array_like, shape (S,), optional
        ``tau`` in the phases; default the quasistatic contact time (the centre-of-mass law).

    Returns
    -------
    numpy.ndarray, shape (S,)
        ``1 - epsilon^2`` to leading order in ``1 / ln(1/v)``.
    """
    v = np.atleast_1d(np.asarray(v, dtype=float))
    if modes.geometry != DISK.geometry or np.any(~np.isfinite(v)) or np.any(v <= 0):
        raise InputError("asymptotic_loss needs one disk's modes (on a wall) and speeds v > 0")
    law = contact_law(modes.nu, "centre")
    qs = quasistatic_collision(law, v)
    tau = qs.contact_time if contact_time is None else np.asarray(contact_time, dtype=float)
    lam = law._lambda(qs.max_compression)
    om, C, m = modes.omega, modes.C, modes.mass
    out = np.empty(v.size)
    for i, x in enumerate(v):
        L = np.log(4.0 * om / x) + law.constant + math.log(lam[i]) + np.euler_gamma - 1.0
        amp = np.real(np.exp(0.5j * om * tau[i]) / (L + 0.5j * math.pi))
        out[i] = np.sum(4.0 * math.pi**2 * law.E**2 / m**2 * C**2 / om**4 * amp**2)
    return out
