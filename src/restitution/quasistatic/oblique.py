"""The oblique impact of an elastic grain on a rigid wall with Coulomb friction, quasistatic.

Units: ``E = rho = R = 1`` of the grain (3D constants); speeds in ``c = sqrt(E / rho)``, spins
in ``c / R``, times in ``R / c``, lengths in ``R``, forces in ``E R^2``, impulses in
``rho R^3 c``, energies in ``E R^3``. docs/oblique.md derives what follows and lists the checks.

The grain (mass ``m``, radius ``R``, ``K = 1 + m R^2 / I``: 7/2 for a solid sphere) arrives
with normal speed ``v_n > 0``, tangential speed ``v_t`` and spin ``omega`` (positive in the
rolling sense of ``v_t > 0``); its contact point slides at ``v_c = v_t - R omega``, and a
tangential force ``T`` changes that at the rate ``v_c' = (K / m) T``. The normal contact is
Hertz's, ``P = (4/3) E* sqrt(R) delta^(3/2)``, ``k_n = dP/d delta = 2 E* a``, ``a = sqrt(R
delta)``, not changed by ``T`` (Cattaneo-Mindlin). Mindlin's stiffness of a stuck circle is
``k_t = 8 G a / (2 - nu)``; on a rigid wall, and between two grains of one material,
``k_t / k_n = chi = 2 (1 - nu) / (2 - nu)`` (:func:`stiffness_ratio`). Two laws
(:data:`MODELS`):

* ``"no-microslip"``, the Hertz-Mindlin law of DEM codes: the elastic tangential displacement
  ``xi`` follows the contact point (``xi' = v_c``), ``T = -k_t(a) xi``, capped at
  ``|T| = mu P`` (``|xi| = (2/3)(mu/chi) delta``). DOP853 phase by phase, with events at the
  cap, at the end of slip and at separation, in ``s`` (``dt = 2 sqrt(delta) ds``), where every
  right-hand side is a polynomial. A stiffness that grows at fixed ``xi`` creates energy and
  one that shrinks destroys it (:attr:`ObliqueImpact.stiffness_loss`).
* ``"microslip"``, Mindlin and Deresiewicz for any history, by the method of dimensionality
  reduction (Popov and Hess 2015): springs at ``|x| < a`` of tangential stiffness
  ``chi E* dx`` with Coulomb's bound ``|w(x)| <= (mu/chi)(delta - x^2/R)``. A spring enters
  and leaves unstretched; energy goes only into slip. Stick zone and slip annulus follow; this
  is the physics of Maw, Barber and Fawcett (Wear 38, 101 (1976)). Velocity Verlet on a grid
  uniform in ``s``; error ~ ``springs^-2``.

``beta = -v_c(after) / v_c(before)`` (Foerster, Louge, Chang and Allia 1994: -1 smooth, +1
reversed) depends on the incidence only through ``psi = chi v_c / (mu v_n) = chi tan(theta) /
mu`` (Maw et al.'s ``psi_1``, ``theta`` the contact point's angle of incidence from the
normal) and not on ``v_n`` (Hertz's self-similarity).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import betainc, betaincinv

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError, RestitutionError, is_integer, is_real, real
from restitution.quasistatic.hertz_sphere import (
    CONTACT_TIME_CONSTANT,
    SPHERE_MASS,
    SphereHertzLaw,
    sphere_contact_law,
    sphere_quasistatic_collision,
)

__all__ = [
    "MODELS",
    "ObliqueHistory",
    "ObliqueImpact",
    "beta_of_psi",
    "gross_slip_beta",
    "gross_slip_psi",
    "no_slip_beta",
    "oblique_impact",
    "stiffness_ratio",
]

MODELS = ("no-microslip", "microslip")
"""The tangential laws of :func:`oblique_impact` (module docs)."""

SOLID = 3.5
"""``K = 1 + m R^2 / I`` of a solid sphere (``I = 2 m R^2 / 5``)."""

_PHASES = 200  # more stick/slip phases than this means a tolerance too loose to resolve them
# s of separation = _S_END sqrt(delta_max) / v_n: (2/5) B(1/5, 1/2), from dt = 2 sqrt(delta) ds
_S_END = 0.4 * math.gamma(0.2) * math.gamma(0.5) / math.gamma(0.7)


def stiffness_ratio(nu: float) -> float:
    """``chi = k_t / k_n = 2 (1 - nu) / (2 - nu)``, Mindlin's over Hertz's stiffness.

    >>> round(stiffness_ratio(0.3), 12)
    0.823529411765
    """
    nu = SPHERE.check_nu(nu)
    return 2.0 * (1.0 - nu) / (2.0 - nu)


def gross_slip_psi(nu: float, inertia_factor: float = SOLID, model: str = MODELS[1]) -> float:
    """The ``psi`` above which the contact slides throughout: ``2 K chi - 1`` (microslip, Maw
    et al.'s ``4 chi_MBF - 1``) or ``2 K chi - 2/3`` (no-microslip, whose cap ``(2/3) mu delta
    / chi`` is first reached at ``psi = 2/3``)."""
    start = {MODELS[0]: 2.0 / 3.0, MODELS[1]: 1.0}[_check_model(model)]
    return 2.0 * inertia_factor * stiffness_ratio(nu) - start


def gross_slip_beta(psi, nu: float, inertia_factor: float = SOLID):
    """``beta = -1 + 2 K chi / psi``, exact in gross slip (``psi >= gross_slip_psi``): the
    friction impulse is ``mu`` times the normal one, ``2 m v_n``.

    >>> round(float(gross_slip_beta(10.0, 0.3)), 12)
    -0.423529411765
    """
    return -1.0 + 2.0 * inertia_factor * stiffness_ratio(nu) / np.asarray(psi, dtype=float)


def no_slip_beta(nu: float, inertia_factor: float = SOLID) -> float:
    """``beta`` of the no-microslip law as ``psi -> 0`` (``mu -> infinity``), in closed form:

    ``beta_0 = -cos(pi q) / cos(pi / 10)``, ``q = sqrt(1 + 120 K chi) / 10``.

    ``xi'' + K chi k_n(t) xi / m = 0`` becomes hypergeometric in ``w = (delta/delta_max)^(5/2)``
    with ``a + b = 1/10``, ``ab = -(3/10) K chi``, ``c = 3/5`` (docs/oblique.md). ``K chi = 1``
    (the normal velocity's own equation) gives ``beta_0 = 1``.

    >>> round(no_slip_beta(0.3), 9)
    -0.954847528
    """
    q = math.sqrt(1.0 + 120.0 * inertia_factor * stiffness_ratio(nu)) / 10.0
    return -math.cos(math.pi * q) / math.cos(math.pi / 10.0)


@dataclass(frozen=True)
class ObliqueHistory:
    """The impact in time, arrays of shape ``(M,)``: ``t`` from first contact (``R / c``),
    ``delta`` (``R``), ``P`` and ``T`` on the grain (``E R^2``), ``v_c`` (``c``)."""

    t: np.ndarray
    compression: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    contact_velocity: np.ndarray


@dataclass(frozen=True)
class ObliqueImpact:
    """What :func:`oblique_impact` returns; speeds ``c``, spins ``c / R``, energies ``E R^3``.

    Attributes
    ----------
    model, nu, mu, inertia_factor, psi
        The law, the inputs and ``psi = chi v_c / (mu v_n)`` (:func:`stiffness_ratio`).
    normal_coefficient : float
        ``-(normal velocity after) / v_n``: 1 (Hertz is elastic and not changed by ``T``).
    beta : float
        ``-v_c(after) / v_c(before)`` (``nan`` if ``v_c = 0`` before).
    v_tangential, spin, contact_velocity : float
        Centre tangential speed, spin and contact-point speed after the impact.
    contact_time : float
        ``R / c``.
    kinetic_energy_before, kinetic_energy_after : float
        Translation and rotation.
    friction_work : float
        ``int mu P |slip rate| dt >= 0``.
    stiffness_loss : float
        No-microslip: ``-(1/2) int (dk_t/dt) xi^2 dt``, lost (negative: created) as ``k_t``
        changes at fixed ``xi``; microslip: 0.
    elastic_energy_left : float
        Tangential elastic energy at separation: 0.
    energy_balance : float
        Before minus after minus the three terms above: the numerical error.
    phases : tuple of (str, float)
        ``("stick" | "slip+" | "slip-", start time)`` (no-microslip; ``()`` for microslip).
    history : ObliqueHistory or None
    """

    model: str
    nu: float
    mu: float
    inertia_factor: float
    psi: float
    normal_coefficient: float
    beta: float
    v_tangential: float
    spin: float
    contact_velocity: float
    contact_time: float
    kinetic_energy_before: float
    kinetic_energy_after: float
    friction_work: float
    stiffness_loss: float
    elastic_energy_left: float
    energy_balance: float
    phases: tuple
    history: ObliqueHistory | None = None


@dataclass(frozen=True)
class _Case:
    """The checked inputs; ``lam = mu / chi`` bounds a spring's stretch per compression and
    ``kr = k_t / sqrt(delta) = 2 chi E* sqrt(R)``."""

    v_n: float
    v_c: float
    mu: float
    chi: float
    K: float
    mass: float
    law: SphereHertzLaw
    delta_max: float  # Hertz's largest compression, R
    lam: float
    kr: float
    s_end: float  # twice the s of separation


def _check_model(model: str) -> str:
    if model not in MODELS:
        raise InputError(f"model must be one of {MODELS}, got {model!r}; pick one of them")
    return model


def _no_microslip(c: _Case, rtol: float, history: bool):
    """Phases of DOP853 in ``s``; state ``[r, delta', v_c, xi, t, friction, gained]``,
    ``r = sqrt(delta)``. Returns the final state, the phases and the history."""
    Kh, m, kr, lam3, dm = c.law.K, c.mass, c.kr, 2.0 * c.lam / 3.0, c.delta_max
    energy, tau = 0.5 * m * (c.v_n**2 + c.v_c**2), dm / c.v_n
    xi = max(abs(c.v_c) * tau, lam3 * dm if math.isfinite(lam3) else 0.0) or dm  # v_c = 0: xi = 0
    vc = max(abs(c.v_c), c.v_n * min(c.mu, 1.0)) or c.v_n
    atol = 1e-3 * rtol * np.array([math.sqrt(dm), c.v_n, vc, xi, tau, energy, energy])

    def rhs(_s, y, slip):
        r, nd, vc, xi = y[:4]
        T = -kr * r * xi
        ts = 2.0 * r  # dt/ds; the last entry is (1/2) (dk_t/dt) xi^2 dt/ds
        out = [nd, -ts * Kh * r**3 / m, ts * c.K * T / m, ts * vc, ts, 0.0, 0.5 * kr * nd * xi**2]
        if slip:  # xi = slip lam3 delta; mu P |slip rate|
            out[3] = slip * lam3 * ts * nd
            out[5] = ts * c.mu * Kh * r**3 * (slip * vc - lam3 * nd)
        return out

    def separation(_s, y, _slip):
        return y[0]

    def cap_plus(_s, y, _slip):  # xi reaches +mu P / k_t
        return lam3 * y[0] ** 2 - y[3]

    def cap_minus(_s, y, _slip):
        return lam3 * y[0] ** 2 + y[3]

    def slip_ends(_s, y, slip):
        return slip * y[2] - lam3 * y[1]

    for event in (separation, slip_ends, cap_plus, cap_minus):
        event.terminal, event.direction = True, -1.0

    y = np.array([0.0, c.v_n, c.v_c, 0.0, 0.0, 0.0, 0.0])
    slip = math.copysign(1.0, c.v_c) if abs(c.v_c) > lam3 * c.v_n else 0.0
    s0, s1, phases, pieces = 0.0, c.s_end, [], []
    for _ in range(_PHASES):
        phases.append(("stick" if not slip else ("slip+" if slip > 0 else "slip-"), float(y[4])))
        events = [separation] + ([slip_ends] if slip else [cap_plus, cap_minus])
        if not (math.isfinite(lam3) and c.v_c):  # no cap, or xi stays 0
            events = [separation]
        sol = solve_ivp(
            rhs, (s0, s1), y, method="DOP853", rtol=rtol, atol=atol, events=events, args=(slip,)
        )
        if sol.status != 1:
            raise RestitutionError(
                f"the no-microslip integration failed ({sol.message}); "
                "loosen rtol or check the inputs"
            )
        pieces.append(sol.y)
        which = next(i for i, e in enumerate(sol.t_events) if len(e))
        s0, y = float(sol.t_events[which][0]), sol.y_events[which][0].copy()
        if events[which] is separation:
            break
        if slip:  # slip ends: the spring holds the contact point
            slip = 0.0
        else:  # the cap is reached: slide the way the spring pulls
            slip = 1.0 if events[which] is cap_plus else -1.0
            y[3] = slip * lam3 * y[0] ** 2
    else:
        raise RestitutionError(f"more than {_PHASES} stick/slip phases; tighten rtol")
    hist = None
    if history:
        Y = np.concatenate(pieces, axis=1)
        d = np.maximum(Y[0], 0.0) ** 2
        hist = ObliqueHistory(Y[4], d, Kh * d**1.5, -kr * np.maximum(Y[0], 0.0) * Y[3], Y[2])
    elastic = 0.5 * kr * max(y[0], 0.0) * y[3] ** 2
    return y[1], y[2], y[4], y[5], -y[6], elastic, tuple(phases), hist


def _microslip(c: _Case, springs: int, steps: int, history: bool):
    """Method of dimensionality reduction: ``springs`` springs, velocity Verlet on a grid
    uniform in ``s`` (springs then enter about one a step), where Hertz's motion is closed:
    ``s / s_half = I_w(1/5, 1/2)``, ``t / t_half = I_w(2/5, 1/2)``, ``w = (delta /
    delta_max)^(5/2)``, mirrored about closest approach. Returns what :func:`_no_microslip`
    does."""
    Kh, m, R, dm = c.law.K, c.mass, c.law.R, c.delta_max
    w = betaincinv(0.2, 0.5, np.linspace(0.0, 1.0, steps // 2 + 1))
    t = 0.5 * CONTACT_TIME_CONSTANT * dm / c.v_n * betainc(0.4, 0.5, w)
    t = np.concatenate([t, 2.0 * t[-1] - t[-2::-1]])
    delta = dm * w**0.4
    delta = np.concatenate([delta, delta[-2::-1]])
    delta[-1] = 0.0
    width = math.sqrt(R * dm) * (1.0 + 1e-9) / springs
    x2 = ((np.arange(springs) + 0.5) * width) ** 2 / R  # x^2 / R of each spring
    k = 2.0 * c.chi * c.law.E_star * width  # tangential stiffness of a spring (both sides)
    count = np.searchsorted(x2, delta)  # springs touching at each step: a prefix (x2 sorted)
    anchor, bound, w = np.zeros(springs), np.zeros(springs), np.zeros(0)
    u, vc, T, friction = 0.0, c.v_c, 0.0, 0.0
    Ts, vcs = [T], [vc]
    for n in range(steps):
        dt = t[n + 1] - t[n]
        u_new = u + dt * vc + 0.5 * dt * dt * c.K / m * T
        before, now = count[n], count[n + 1]
        if now > before:  # anchored where the contact point was when touched (u linear in dt)
            frac = (x2[before:now] - delta[n]) / (delta[n + 1] - delta[n])
            anchor[before:now] = u + np.clip(frac, 0.0, 1.0) * (u_new - u)
        j = max(before, now)  # springs that leave in this step slip to w = 0 first
        b_new = c.lam * np.maximum(delta[n + 1] - x2[:j], 0.0)
        w = np.clip(u_new - anchor[:j], -b_new, b_new)
        moved = np.abs(u_new - w - anchor[:j])
        friction += 0.5 * k * float(np.dot(bound[:j] + b_new, moved))  # mu p |slip|, trapezoid
        anchor[:j], bound[:j] = u_new - w, b_new
        T_new = -k * float(w.sum())
        vc += 0.5 * dt * c.K / m * (T + T_new)
        u, T = u_new, T_new
        Ts.append(T)
        vcs.append(vc)
    elastic = 0.5 * k * float(np.dot(w, w))
    hist = None
    if history:
        hist = ObliqueHistory(t, delta, Kh * delta**1.5, np.array(Ts), np.array(vcs))
    return -c.v_n, vc, t[-1], friction, 0.0, elastic, (), hist


def oblique_impact(
    v_normal: float,
    v_tangential: float,
    mu: float,
    nu: float,
    *,
    spin: float = 0.0,
    inertia_factor: float = SOLID,
    model: str = MODELS[1],
    law: SphereHertzLaw | None = None,
    mass: float = SPHERE_MASS,
    rtol: float | None = None,
    springs: int | None = None,
    steps_per_spring: int | None = None,
    history: bool = False,
) -> ObliqueImpact:
    """The oblique impact of a grain on a rigid wall, quasistatic, with Coulomb friction.

    Parameters
    ----------
    v_normal : float
        Approach speed, ``c``, ``0 < v_normal <= law.max_speed(mass)``.
    v_tangential, spin : float
        Centre tangential speed (``c``) and spin (``c / R``, positive in the rolling sense).
    mu : float
        Friction coefficient, ``>= 0``; ``inf`` (no-microslip only) never slips.
    nu : float
        Poisson number; sets ``chi`` and, without ``law``, Hertz's ``E* = 1 / (1 - nu^2)``.
    inertia_factor : float
        ``K = 1 + m R^2 / I >= 1``: 7/2 solid sphere (default), 3 disk, 5/2 thin shell.
    model : str
        ``"microslip"`` (default; ``springs`` springs, default 800, and ``steps_per_spring``
        steps each, default 8: ``beta`` to about 1e-6) or ``"no-microslip"`` (DOP853 with
        relative tolerance ``rtol``, default 1e-12).
    law, mass : SphereHertzLaw, float
        The normal law and mass. Two grains of one material (``chi`` holds only then):
        ``sphere_pair_contact_law(nu)``, ``sphere_pair_mass()``, relative speeds, ``K = 1 +
        m R^2 / I`` of one grain; ``beta`` and ``contact_velocity`` are the pair's.
    history : bool
        Keep the time history (:class:`ObliqueHistory`).

    Examples
    --------
    >>> out = oblique_impact(0.01, 0.02, 0.5, 0.3, model="no-microslip")
    >>> round(out.psi, 6), round(out.beta, 6), [name for name, _ in out.phases]
    (3.294118, 0.349495, ['slip+', 'stick', 'slip-'])
    >>> round(oblique_impact(0.01, 0.02, 0.5, 0.3).beta, 5)
    0.44095
    """
    model = _check_model(model)
    nu = SPHERE.check_nu(nu)
    law = sphere_contact_law(nu) if law is None else law
    if law.nu != nu:
        raise InputError(f"law.nu = {law.nu} differs from nu = {nu}; pass the law's nu")
    v_n, vmax = real(v_normal, "v_normal", "> 0 (c)"), law.max_speed(mass)
    v_t, omega = real(v_tangential, "v_tangential", "(c)"), real(spin, "spin", "(c/R)")
    K = real(inertia_factor, "inertia_factor", ">= 1")
    mu = math.inf if is_real(mu) and mu == math.inf else real(mu, "mu", ">= 0")
    for bad, what in (
        (not 0.0 < v_n <= vmax, f"v_normal in (0, {vmax:.6g}] c (Hertz needs delta << R)"),
        (K < 1.0, "inertia_factor = 1 + m R^2 / I >= 1"),
        (mu < 0.0 or (mu == math.inf and model != MODELS[0]), f"mu >= 0, inf for {MODELS[0]!r}"),
    ):
        if bad:
            raise InputError(f"pass {what}; got v_normal={v_n}, inertia_factor={K}, mu={mu}")
    R = law.R
    dm = float(sphere_quasistatic_collision(law, v_n, mass=mass).max_compression[0])
    chi = stiffness_ratio(nu)
    kr = 2.0 * chi * law.E_star * math.sqrt(R)
    s_end = 2.0 * _S_END * math.sqrt(dm) / v_n
    c = _Case(v_n, v_t - R * omega, mu, chi, K, float(mass), law, dm, mu / chi, kr, s_end)
    other = (springs, steps_per_spring) if model == MODELS[0] else (rtol,)
    if any(x is not None for x in other):
        raise InputError(
            f"rtol belongs to {MODELS[0]!r}, springs and steps_per_spring to "
            f"{MODELS[1]!r}; drop those of the other law"
        )
    if model == MODELS[0]:
        rtol = 1e-12 if rtol is None else real(rtol, "rtol", "in [1e-14, 1e-3]")
        if not 1e-14 <= rtol <= 1e-3:
            raise InputError(f"rtol must lie in [1e-14, 1e-3], got {rtol}")
        out = _no_microslip(c, rtol, history)
    else:
        springs = 800 if springs is None else springs
        per = 8 if steps_per_spring is None else steps_per_spring
        if not (is_integer(springs) and is_integer(per) and springs >= 10 and per >= 1):
            raise InputError(
                f"springs >= 10 and steps_per_spring >= 1 must be integers, got "
                f"{springs!r}, {per!r}"
            )
        out = _microslip(c, int(springs), 2 * ((int(springs) * int(per) + 1) // 2), history)
    nd_end, vc_end, tau, friction, stiff, elastic, phases, hist = out
    J = mass * (vc_end - c.v_c) / K  # dv_c = (K / m) J
    inertia = mass * R * R / (K - 1.0) if K > 1.0 else math.inf
    vt_end = v_t + J / mass
    omega_end = omega - R * J / inertia
    spin_energy = 0.5 * inertia if math.isfinite(inertia) else 0.0  # K = 1: spin never changes
    ke0 = 0.5 * mass * (v_n**2 + v_t**2) + spin_energy * omega**2
    ke1 = 0.5 * mass * (nd_end**2 + vt_end**2) + spin_energy * omega_end**2
    psi = 0.0 if not c.v_c else chi * c.v_c / (mu * v_n) if mu else math.copysign(math.inf, c.v_c)
    return ObliqueImpact(
        model=model,
        nu=nu,
        mu=mu,
        inertia_factor=K,
        psi=psi,
        normal_coefficient=float(-nd_end / v_n),
        beta=float(-vc_end / c.v_c) if c.v_c else math.nan,
        v_tangential=float(vt_end),
        spin=float(omega_end),
        contact_velocity=float(vc_end),
        contact_time=float(tau),
        kinetic_energy_before=float(ke0),
        kinetic_energy_after=float(ke1),
        friction_work=float(friction),
        stiffness_loss=float(stiff),
        elastic_energy_left=float(elastic),
        energy_balance=float(ke0 - ke1 - friction - stiff - elastic),
        phases=phases,
        history=hist,
    )


def beta_of_psi(
    psi, nu: float, *, inertia_factor: float = SOLID, model: str = MODELS[1], **options
) -> np.ndarray:
    """``beta(psi)``, shape of ``psi``: :func:`oblique_impact` at ``v_n = 0.01``, ``mu = 1``
    and ``v_c = psi v_n / chi`` (``beta`` depends on nothing else); ``options`` pass on.

    >>> b = beta_of_psi([2.0, 10.0], 0.3, model="no-microslip")
    >>> [round(float(x), 9) for x in b - gross_slip_beta([2.0, 10.0], 0.3)]
    [-1.624304063, 0.0]
    """
    psi = np.asarray(psi, dtype=float)
    if not np.all(np.isfinite(psi) & (psi > 0.0)):
        raise InputError("psi must be positive and finite; for psi -> 0 see no_slip_beta")
    chi, v_n = stiffness_ratio(nu), 0.01
    out = [
        oblique_impact(
            v_n, p * v_n / chi, 1.0, nu, inertia_factor=inertia_factor, model=model, **options
        ).beta
        for p in psi.ravel()
    ]
    return np.array(out).reshape(psi.shape)
