"""The quasistatic oblique impact of the elastic sphere on the rigid wall with one stick/slip
state for the whole contact, its traction spread like the pressure: the low-speed limit of the
modal route's one-state friction (:func:`restitution.dynamics.oblique.oblique_collision`).

Units: ``E = rho = R = 1`` (three-dimensional constants), speeds in ``c = sqrt(E / rho)``.

**Why not law (a).** The modal route has one Coulomb contact whose tangential force ``F`` is
spread over the surface like the pressure, ``t = F p`` (``p`` the pressure over the normal
force), and whose slip is the pressure-weighted tangential velocity of the surface, ``v_s =
v_c + sum p_j u_j'`` (``v_c`` the contact point's rigid velocity, ``u`` the elastic tangential
displacement). Law (a) of :mod:`restitution.quasistatic.oblique` (Hertz-Mindlin without
microslip, the DEM codes' law) puts Mindlin's stick traction on the contact instead and lets it
grow with the stiffness ``k_t = 2 chi E* a`` increment by increment. The two differ in the
traction's shape, and the one-state contact redistributes its traction as the pressure's shape
changes.

**On the half-space** (Hertz's pressure, radius ``a = sqrt(delta)``; Mindlin's in-line
tangential displacement is ``1 / chi`` times the normal one of the same axisymmetric load,
``chi = 2 (1 - nu) / (2 - nu)``), per unit ``F`` the pressure-weighted displacement is ``C(a) =
3 / (5 chi E* a)`` (Boussinesq's ``u = 3 (2 a^2 - r^2) / (8 a^3 E*)`` averaged with Hertz's
pressure, where ``<r^2> = 2 a^2 / 5``) and its change with ``a`` at fixed ``F`` is ``M(a) = -3 /
(10 chi E* a^2)``. So ``v_s = v_c + F' C + F a' M``:

* **stick** (``v_s = 0``): ``F' - F a' / (2a) = -(5/3) chi E* a v_c``, i.e. ``G = F / sqrt(a)``
  obeys ``G' = -(5/3) chi E* sqrt(a) v_c`` while ``m v_c' = K F``. In the variable ``sigma =
  int sqrt(a) dt`` this is a harmonic oscillator of frequency ``sqrt((5/3) K chi E* / m)``,
  and Hertz's ``int sqrt(a) dt = (4 pi / 5) delta_max^(5/4) / v`` over the contact gives a
  contact that sticks throughout ``beta_0 = -cos(pi sqrt(K chi))`` at every speed (-0.582 for
  ``nu = 0.3``, ``K = 7/2``; law (a)'s ``beta_0`` is -0.954);
* **slip** (``F = -s mu P``, ``s`` the sign of ``v_s``): ``v_s = v_c - s mu v_n' / chi`` with
  ``v_n' = delta'`` (``P' C + P a' M = 2 a a' / chi``); slip ends where ``v_s`` reaches 0,
  stick where ``|F|`` reaches ``mu P``.

:func:`one_state_half_space` integrates this by DOP853 phase by phase (events at the
switches).

**On the finite sphere** (:func:`one_state_impact`) the same contact on the annuli of
:mod:`restitution.quasistatic.sphere_partial_slip`, with the sphere's own flexibility and
shape: per step the normal forces ``P_i`` of the annuli, ``p = P / sum P``, and the
tangential force from the discrete stick condition ``sum_i pbar_i (Y_i(new) - Y_i(old)) = 0``
(``Y_i = s + F (H_t p)_i``, ``pbar`` the mean of the two steps' ``p``), clipped to Coulomb's
``|F| <= mu sum P`` (a stick force beyond the bound slips at the bound, in its direction).

**Checks** (tests/test_sphere_one_state.py): the annuli on the half-space with Hertz's
parabola against :func:`one_state_half_space` (within 1.1e-4 at 40 annuli and 2.6e-5 at 80,
``tan(theta)/mu`` 0.3-8, ``v = 0.005``), the stick closed form ``-cos(pi sqrt(K chi))`` (both
routes), gross slip's impulse ratio, and the finite sphere's convergence in the annuli.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from restitution.dynamics.one_state import OneStateFriction
from restitution.errors import RestitutionError
from restitution.quasistatic.hertz_sphere import CONTACT_TIME_CONSTANT, SPHERE_MASS
from restitution.quasistatic.sphere_partial_slip import (
    INERTIA_FACTOR,
    AnnularContact,
    PartialSlipImpact,
    annular_impact,
    checked_impact,
    hertz_peak,
    run,
)

__all__ = [
    "OneStateFriction",
    "one_state_half_space",
    "one_state_impact",
    "one_state_run",
    "one_state_seconds",
    "stick_beta",
]

_MAX_PHASES = 200


def stick_beta(nu: float, inertia_factor: float = INERTIA_FACTOR) -> float:
    """``beta`` of a one-state contact on the half-space that sticks throughout: ``-cos(pi
    sqrt(K chi))`` at every speed (module docs)."""
    chi = 2.0 * (1.0 - nu) / (2.0 - nu)
    return -math.cos(math.pi * math.sqrt(inertia_factor * chi))


def one_state_half_space(v_normal: float, v_tangential: float, mu: float, nu: float, *,
                         rtol: float = 1e-11) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of the one-state contact on the half-space (module
    docs), from rest in spin; speeds in ``c``."""
    v, vt, mu, nu = checked_impact(v_normal, v_tangential, mu, nu)
    e_star, chi = 1.0 / (1.0 - nu * nu), 2.0 * (1.0 - nu) / (2.0 - nu)
    m, K = SPHERE_MASS, INERTIA_FACTOR

    def force(d):
        return 4.0 / 3.0 * e_star * max(d, 0.0) ** 1.5

    def stick(_t, y):  # y = (delta, delta', G = F / sqrt(a), v_c)
        root_a = max(y[0], 0.0) ** 0.25
        return [y[1], -force(y[0]) / m, -5.0 / 3.0 * chi * e_star * root_a * y[3],
                K * y[2] * root_a / m]  # fmt: skip

    def separation(t, y):
        return y[0] if t > 0.0 else 1.0

    def cap(_t, y):  # |F| reaches mu P
        return abs(y[2]) * max(y[0], 0.0) ** 0.25 - mu * force(y[0]) if y[0] > 0.0 else -1.0

    separation.terminal, separation.direction = True, -1
    cap.terminal, cap.direction = True, 1
    t, y = 0.0, np.array([0.0, v, 0.0, vt])
    # the stick force starts at -chi v_c / v of the normal one (G ~ t^(5/4), a ~ t^(1/2))
    sign = -1.0 if chi * vt > mu * v else 0.0
    horizon = 10.0 * CONTACT_TIME_CONSTANT * hertz_peak(v, nu) / v
    for _ in range(_MAX_PHASES):
        if sign == 0.0:
            rhs, events = stick, [separation, cap]
        else:
            s = sign

            def rhs(_t, y, s=s):
                return [y[1], -force(y[0]) / m, 0.0, K * s * mu * force(y[0]) / m]

            def slip_ends(_t, y, s=s):
                return y[3] + s * mu * y[1] / chi

            slip_ends.terminal = True
            events = [separation, slip_ends]
        out = solve_ivp(rhs, (t, t + horizon), y, method="DOP853", events=events, rtol=rtol,
                        atol=1e-16, first_step=None if t else 1e-6 * horizon)  # fmt: skip
        if out.status != 1:
            raise RestitutionError("the one-state contact did not end within ten contact times")
        t, y = float(out.t[-1]), out.y[:, -1].copy()
        if out.t_events[0].size:
            return float(-y[3] / vt), float(-y[1] / v)
        if sign == 0.0:
            sign = math.copysign(1.0, y[2])
        else:
            y[2] = sign * mu * force(y[0]) / max(y[0], 0.0) ** 0.25
            sign = 0.0
    raise RestitutionError(f"more than {_MAX_PHASES} stick/slip phases")


def one_state_run(contact: AnnularContact, v: float, v_tangential: float, mu: float, nu: float,
                  steps: int) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of one impact on ``contact`` with one stick/slip state,
    ``steps`` per Hertz contact time (module docs)."""
    return run(contact, v, v_tangential, mu, nu, steps, friction=OneStateFriction)


def one_state_seconds(v: float, nu: float) -> float:
    """The estimated seconds of :func:`one_state_impact` at its defaults: ``0.48 + 0.064 /
    a`` for Hertz's contact radius ``a`` (the flexibility's orders grow like ``1 / a``),
    fitted to runs at ``a`` = 0.022-0.155 (0.9-3.3 s, within 0.05 s; one core of the
    development machine, 5 Dec 2026)."""
    return 0.48 + 0.064 / math.sqrt(hertz_peak(v, nu))


def one_state_impact(v_normal: float, v_tangential: float, mu: float, nu: float, *,
                     annuli: int = 40, steps: int = 4000) -> PartialSlipImpact:  # fmt: skip
    """The finite solid sphere's quasistatic oblique impact on the rigid wall with one
    stick/slip state spread like the pressure (module docs), from rest in spin: the modal
    route's one-state friction at low speed. Arguments and answer as
    :func:`restitution.quasistatic.sphere_partial_slip.partial_slip_impact`."""
    v, vt, mu, nu = checked_impact(v_normal, v_tangential, mu, nu)
    return annular_impact(one_state_run, v, vt, mu, nu, annuli=annuli, steps=steps)
