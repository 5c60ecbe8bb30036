"""The quasistatic oblique impact of the finite elastic sphere on the rigid wall, with Coulomb
friction point by point: its partial slip on its own surface flexibility.

Units: ``E = rho = R = 1`` (three-dimensional constants), speeds in ``c = sqrt(E / rho)``.

**Why.** Maw, Barber and Fawcett's theory (law (b) of :mod:`restitution.quasistatic.oblique`)
puts the contact on a half-space. A free sphere's contact is stiffer normally and softer
tangentially than the half-space's at the same radius (its stiffness ratio ``chi`` is 0.65 at
``a = 0.155`` against Mindlin's 0.82; docs/oblique.md), and ``beta`` in partial slip is very
sensitive to ``chi``: this is the low-speed limit the modal microslip route
(:mod:`restitution.dynamics.oblique_microslip`) tends to as its modes grow, law (b) only as the
contact shrinks (``a -> 0``).

**The model.** The contact plane is cut into ``annuli`` annuli of equal width out to
``REACH`` times Hertz's largest contact radius, with the sphere's Galerkin flexibility between
them (:func:`restitution.bodies.sphere.contact_compliance.annulus_flexibility`: the static
answer of the free sphere with its inertial relief, every order summed).

* **normal**: a pressure ``p_i >= 0`` per annulus, constant on it, such that the annulus's mean
  normal displacement is its mean overlap ``delta - h(r)`` where it presses and at least that
  elsewhere, ``h = 1 - sqrt(1 - r^2)`` the sphere's height above its lowest point (a linear
  complementarity problem: non-negative least squares on the Cholesky factor);
* **tangential**, in Mindlin's in-line approximation (the one law (b) rests on): a traction
  ``q_i`` per annulus along the tangential motion, ``|q_i| <= mu p_i``. Each annulus sticks to
  a point of the wall or slips to a new one: at every step the forces ``Q`` minimise the
  complementary energy ``Q.H.Q / 2 + sum Q_i (s - A_i)`` (``H`` the flexibility between forces
  and mean displacements, ``s`` the contact point's rigid tangential displacement, ``A_i`` the
  wall point annulus ``i`` sticks to) inside the Coulomb box, by an active set warm-started
  from the step before.

An axisymmetric pressure and an in-line traction are orthogonal on the sphere as on the
half-space, so the two problems do not couple. The motion is velocity Verlet in the centre's
approach and the contact point's tangential velocity (``K = 7/2``) at a fixed step,
``steps`` per Hertz contact time.

**Checks** (tests/test_sphere_partial_slip.py): on the half-space with Hertz's parabola (the
closed-form flexibility) the same solver is law (b) within 3.2e-5; in gross slip ``beta`` is
the impulse ratio's; the sphere's ``beta`` converges in the annuli and steps and tends to law
(b) as the contact shrinks. ``beta_change`` is the change from half the annuli and half the
steps: a measure of the discretisation, not a bound (at 12 impacts, ``v`` from 4e-5 to 0.005
and ``tan(theta)/mu`` 0.3-2, the defaults were 3e-6 to 7.2e-4 from 80 annuli and 8000 steps,
and the change from half was the larger at 11).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import cho_factor, cho_solve, solve_triangular
from scipy.optimize import lsq_linear, nnls

from restitution.bodies.sphere.contact_compliance import (
    annulus_flexibility,
    half_space_annulus_flexibility,
)
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError, RestitutionError, is_integer, real
from restitution.quasistatic.hertz_sphere import CONTACT_TIME_CONSTANT, SPHERE_MASS

__all__ = [
    "BODIES",
    "REACH",
    "INERTIA_FACTOR",
    "AnnularContact",
    "Microslip",
    "PartialSlipImpact",
    "annular_impact",
    "box_qp",
    "checked_impact",
    "mean_height",
    "partial_slip_impact",
    "partial_slip_seconds",
]

BODIES = ("finite", "half-space")
"""The flexibilities of :meth:`AnnularContact.build`: the finite sphere's own (every order
summed) or the half-space's (closed form)."""

REACH = 1.25
"""The annuli reach this many times Hertz's largest contact radius (the sphere's, stiffer
normally, is smaller); an impact whose outermost annulus presses is refused."""

_MAX_REACH = 0.9  # R: beyond this the annuli wrap too far round the sphere for its flat wall
INERTIA_FACTOR = 3.5
"""``K = 1 + m R^2 / I`` of the solid sphere."""


def partial_slip_seconds(v: float, nu: float) -> float:
    """The estimated seconds of :func:`partial_slip_impact` at its defaults: ``0.56 + 0.068 /
    a`` for Hertz's contact radius ``a`` (the orders summed grow like ``1 / a``), fitted to
    runs at ``a`` = 0.017-0.106 (1.2-4.6 s, within 0.2 s; one core of the development
    machine, 5 Dec 2026)."""
    return 0.56 + 0.068 / math.sqrt(hertz_peak(v, nu))


def mean_height(edges: np.ndarray, parabola: bool = False) -> np.ndarray:
    """Each annulus's mean height above the sphere's lowest point, ``int h dA / A``: ``h = 1 -
    sqrt(1 - r^2)`` (the sphere's own) or ``r^2 / 2`` (Hertz's parabola)."""
    r2 = np.asarray(edges, dtype=float) ** 2
    area = math.pi * np.diff(r2)
    if parabola:
        return np.diff(math.pi * r2 * r2 / 4.0) / area
    return np.diff(math.pi * r2 + 2.0 * math.pi / 3.0 * (1.0 - r2) ** 1.5) / area


def hertz_peak(v: float, nu: float) -> float:
    """Hertz's largest approach of the sphere on the rigid wall at normal speed ``v``."""
    return (15.0 * SPHERE_MASS * v * v * (1.0 - nu * nu) / 16.0) ** 0.4


@dataclass
class AnnularContact:
    """The annuli ``edges``, their flexibilities between forces and mean displacements
    (``H[i, j] = G[i, j] / (A_i A_j)``, ``A_i`` the annulus's area) and the overlap's shape
    (Hertz's parabola or the sphere's own)."""

    edges: np.ndarray
    Hn: np.ndarray
    Ht: np.ndarray
    parabola: bool

    @classmethod
    def build(cls, radius: float, nu: float, *, body: str = BODIES[0], annuli: int = 40,
              parabola: bool | None = None, l_top: int | None = None):  # fmt: skip
        """Annuli of equal width out to ``radius``; ``body`` is one of :data:`BODIES` (the
        half-space takes Hertz's parabola unless ``parabola`` says otherwise)."""
        if body not in BODIES:
            raise InputError(f"body must be one of {', '.join(BODIES)}, got {body!r}")
        edges = np.linspace(0.0, radius, int(annuli) + 1)
        area = math.pi * np.diff(edges**2)
        scale = np.outer(area, area)
        flexibility = annulus_flexibility if body == BODIES[0] else half_space_annulus_flexibility
        kw = {"l_top": l_top} if body == BODIES[0] else {}
        Hn, Ht = (flexibility(edges, nu, d, **kw) / scale for d in ("normal", "tangential"))
        return cls(edges, Hn, Ht, body == BODIES[1] if parabola is None else parabola)

    def __post_init__(self) -> None:
        self.area = math.pi * np.diff(self.edges**2)
        self.h = mean_height(self.edges, self.parabola)
        self._chol = np.linalg.cholesky(self.Hn)  # Hn = L L^T

    def normal(self, delta: float) -> np.ndarray:
        """The annuli's normal forces at the approach ``delta``."""
        overlap = delta - self.h
        if overlap[0] <= 0.0:
            return np.zeros_like(overlap)
        # min P.Hn.P / 2 - P.overlap over P >= 0  <=>  min |L^T P - L^-1 overlap|^2
        rhs = solve_triangular(self._chol, overlap, lower=True)
        return nnls(self._chol.T, rhs)[0]


def box_qp(H: np.ndarray, c: np.ndarray, bound: np.ndarray, stick: np.ndarray,
            sign: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """``min Q.H.Q / 2 + Q.c`` with ``|Q| <= bound``, from the guess ``stick`` (the others at
    ``sign * bound``). Returns ``Q`` and the final set and signs."""
    stick, sign = stick & (bound > 0.0), sign.copy()
    for _ in range(4 * c.size + 10):
        Q = sign * bound
        if stick.any():
            free = ~stick
            rhs = -(c[stick] + H[np.ix_(stick, free)] @ Q[free])
            Q[stick] = cho_solve(cho_factor(H[np.ix_(stick, stick)]), rhs)
        over = stick & (np.abs(Q) > bound)
        grad = H @ Q + c  # each annulus's slip if it were let go
        wrong = ~stick & (bound > 0.0) & (sign * grad > 0.0)  # slipping along its force
        if not over.any() and not wrong.any():
            return Q, stick, sign
        sign = np.where(over, np.sign(Q), sign)
        stick = (stick & ~over) | wrong
    # the active set cycled: bounded least squares on the Cholesky factor (H = L L^T)
    L = np.linalg.cholesky(H)
    hi = np.maximum(bound, 1e-300)
    Q = lsq_linear(L.T, -solve_triangular(L, c, lower=True), bounds=(-hi, hi), method="bvls")
    Q = np.clip(Q.x, -bound, bound)
    stick = np.abs(Q) < bound * (1.0 - 1e-9)
    return Q, stick, np.where(stick, sign, np.sign(Q))


class Microslip:
    """Friction point by point on the annuli (module docs): each annulus sticks to its point of
    the wall, ``anchor``, or slips to a new one; the forces from :func:`box_qp`, warm-started
    from the step before."""

    def __init__(self, Ht: np.ndarray) -> None:
        n = Ht.shape[0]
        self.Ht = Ht
        self.anchor = np.zeros(n)
        self.stick, self.sign = np.zeros(n, bool), -np.ones(n)

    def step(self, P: np.ndarray, s_old: float, s_new: float, mu: float) -> float:
        """The tangential force after the contact point moved rigidly from ``s_old`` to
        ``s_new``, with the annuli's normal forces ``P`` at the step's end."""
        bound = mu * P
        if not bound.any():
            self.anchor = np.full(P.size, s_new)  # out of contact: every annulus free
            return 0.0
        Q, self.stick, self.sign = box_qp(self.Ht, s_new - self.anchor, bound, self.stick,
                                          self.sign)  # fmt: skip
        self.anchor = s_new + self.Ht @ Q  # unchanged where it sticks
        return float(Q.sum())


def run(contact: AnnularContact, v: float, v_tangential: float, mu: float, nu: float,
        steps: int, friction=Microslip) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of one impact on ``contact``, ``steps`` per Hertz
    contact time; ``friction(Ht)`` makes the tangential law (``step(P, s_old, s_new, mu) ->
    force``): :class:`Microslip` or
    :class:`~restitution.dynamics.one_state.OneStateFriction`."""
    dm = hertz_peak(v, nu)
    dt = CONTACT_TIME_CONSTANT * dm / v / steps
    kick = INERTIA_FACTOR / SPHERE_MASS
    law = friction(contact.Ht)
    delta, vd, force = 0.0, v, 0.0
    s, vc, T = 0.0, v_tangential, 0.0
    for step in range(3 * steps):
        delta_new = delta + dt * vd - 0.5 * dt * dt * force / SPHERE_MASS
        s_new = s + dt * vc + 0.5 * dt * dt * kick * T
        P = contact.normal(delta_new)
        if P[-1] > 0.0:
            raise RestitutionError(
                f"the contact reached the outermost annulus (r = {contact.edges[-1]:.4g} R); "
                "widen the annuli"
            )
        force_new, T_new = float(P.sum()), law.step(P, s, s_new, mu)
        vd -= 0.5 * dt * (force + force_new) / SPHERE_MASS
        vc += 0.5 * dt * kick * (T + T_new)
        delta, s, force, T = delta_new, s_new, force_new, T_new
        if step > 10 and force == 0.0 and vd < 0.0:
            return -vc / v_tangential, -vd / v
    raise RestitutionError(f"no separation in {3 * steps} steps; raise the steps")


@dataclass(frozen=True)
class PartialSlipImpact:
    """:func:`partial_slip_impact`'s answer (speeds in ``c``, spin in ``c / R``).

    Attributes
    ----------
    beta, beta_change : float
        The contact point's tangential coefficient of restitution, and its change from half
        the annuli and half the steps.
    epsilon_normal : float
        The normal coefficient (1 but for the integration: the quasistatic contact is elastic).
    spin_after : float
        The spin after, positive in the rolling sense (no spin before).
    contact_radius : float
        The annuli's reach over ``REACH``: Hertz's largest contact radius (``R``).
    annuli, steps : int
        The resolution of ``beta``.
    """

    beta: float
    beta_change: float
    epsilon_normal: float
    spin_after: float
    contact_radius: float
    annuli: int
    steps: int


def partial_slip_impact(v_normal: float, v_tangential: float, mu: float, nu: float, *,
                        annuli: int = 40, steps: int = 4000) -> PartialSlipImpact:  # fmt: skip
    """The finite solid sphere's quasistatic oblique impact on the rigid wall with microslip
    (module docs), from rest in spin.

    Parameters
    ----------
    v_normal, v_tangential : float
        The centre's normal and tangential speeds before (``c``; ``v_tangential > 0``).
    mu : float
        Friction coefficient, ``> 0``.
    nu : float
        Poisson number of the sphere.
    annuli, steps : int
        Annuli across the contact's reach and steps per Hertz contact time (about 1 s at the
        defaults; the change from half of each is ``beta_change``).
    """
    v, vt, mu, nu = checked_impact(v_normal, v_tangential, mu, nu)
    return annular_impact(run, v, vt, mu, nu, annuli=annuli, steps=steps)


def checked_impact(v_normal, v_tangential, mu, nu) -> tuple[float, float, float, float]:
    """The impact's speeds (``c``, both ``> 0``), friction coefficient (``> 0``) and Poisson
    number, checked."""
    nu = SPHERE.check_nu(nu)
    v = real(v_normal, "v_normal", "> 0 (c)")
    vt = real(v_tangential, "v_tangential", "> 0 (c)")
    mu = real(mu, "mu", "> 0")
    if not (v > 0.0 and vt > 0.0 and 0.0 < mu < math.inf):
        raise InputError(f"pass v_normal > 0, v_tangential > 0 and mu > 0; got {v}, {vt}, {mu}")
    return v, vt, mu, nu


def annular_impact(impact, v: float, vt: float, mu: float, nu: float, *, annuli: int,
                   steps: int) -> PartialSlipImpact:  # fmt: skip
    """The answer of ``impact(contact, v, vt, mu, nu, steps) -> (beta, epsilon_normal)`` on
    the finite sphere's annuli at ``annuli`` and ``steps``, with its change from half of each
    (checked inputs; the annuli's reach is checked here)."""
    if not (is_integer(annuli) and is_integer(steps) and annuli >= 10 and steps >= 400):
        raise InputError(f"annuli >= 10 and steps >= 400 must be integers, got {annuli}, {steps}")
    a_hertz = math.sqrt(hertz_peak(v, nu))
    if REACH * a_hertz > _MAX_REACH:
        top = (16.0 * (_MAX_REACH / REACH) ** 5 / (15.0 * SPHERE_MASS * (1.0 - nu * nu))) ** 0.5
        raise InputError(
            f"v_normal = {v:.4g} c gives Hertz's contact radius {a_hertz:.3g} R; the annuli "
            f"reach {REACH} times it, which must stay below {_MAX_REACH} R: pass v_normal <= "
            f"{top:.4g} c"
        )
    out = []
    for n, k in ((int(annuli), int(steps)), (int(annuli) // 2, int(steps) // 2)):
        contact = AnnularContact.build(REACH * a_hertz, nu, annuli=n)
        out.append(impact(contact, v, vt, mu, nu, k))
    (beta, eps), (coarse, _) = out
    vc_after = -beta * vt
    vt_after = vt + (vc_after - vt) / INERTIA_FACTOR  # J / m = (dv_c) / K
    return PartialSlipImpact(
        beta=beta,
        beta_change=abs(beta - coarse),
        epsilon_normal=eps,
        spin_after=vt_after - vc_after,  # v_c = v_t - R omega
        contact_radius=a_hertz,
        annuli=int(annuli),
        steps=int(steps),
    )
