"""A ball on an infinite thin plate: Zener's model (Phys. Rev. 59, 669 (1941)) solved as the
coupled equation (issue 42).

Units: the ball's, ``E = rho = R = 1`` (a sphere's 3D constants); speeds in ``c``; times in
``R / c``; forces in ``E R^2``.

The ball (mass ``m``) meets the plate through Hertz's law ``P = K delta^(3/2)`` (``K = (4/3) E*
sqrt(R)``, ``E*`` of ball and plate material: the indentation is local, as on a half-space). An
infinite thin plate answers a point force with the velocity ``P / Z`` of the loaded point, its
impedance ``Z = 8 sqrt(D rho_w h)`` real (Kirchhoff plate theory: the flexural waves carry the
energy away and never return). With the ball's displacement ``x`` and velocity ``u``::

    m du/dt = -P(delta),     d delta / dt = u - P(delta) / Z,     delta(0) = 0, u(0) = v

until ``delta`` returns to zero: ``epsilon = -u / v`` then; the plate took ``int P^2 / Z dt``,
which with the ball's final energy makes up ``(m/2) v^2`` (:class:`PlateImpact` records the
balance). It is solved with DOP853, not as a perturbation: on a thin plate the loss is large.
When the ball leaves the plate moving towards it, or does not leave within
:data:`MAX_CONTACT_TIMES` Hertz contact times, there is no rebound and no epsilon
(:attr:`PlateImpact.rebounds`).

**Where the thin-plate model holds** (:func:`validity`): the contact radius small against the
thickness (``a < h / 2``: the indentation is the half-space's), the thickness small against
the flexural wavelength at the pulse's frequency ``pi / tau`` (``h < lambda_f / 6``) and the
compressional transit across ``h`` short against the contact (``h / c_L < tau / 10``). The
thresholds are this module's choice, stated with every answer; outside them the plate's answer
is not served (a point of the finite elements' judge stored at that speed answers instead,
:mod:`restitution.laws.wall_points`).

**Its error** (:func:`model_error`) is the loss times the largest of those ratios, plus the
body waves a thick plate sends into its depth before it bends (the half-space's radiation of the
same ball, :attr:`PlateImpact.depth_radiation`), which the Kirchhoff plate has not.

**The ball's own vibrations** (:func:`ball_vibrations`) are driven by the same force history:
each mode keeps ``C_k^2 |F(omega_k)|^2 / (2 m)`` of it (``F`` the pulse's spectrum; Rayleigh's
estimate, :mod:`restitution.quasistatic.rayleigh`, for a pulse that is not symmetric), a
separate loss beside the plate's (on a rigid wall 5e-5 of a steel ball's energy at 1 m/s; on a
plate far less, the pulse being longer and softer).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from restitution.errors import InputError
from restitution.quasistatic.half_space import radiated_fraction

__all__ = [
    "MAX_CONTACT_TIMES",
    "STICKING_PARAMETER",
    "PlateImpact",
    "ball_vibrations",
    "echo_ratio",
    "model_error",
    "plate_impact",
    "validity",
    "zener_parameter",
]

STICKING_PARAMETER = 25.0
"""Zener's parameter (:func:`zener_parameter`) above which the ball is taken not to rebound:
epsilon falls exponentially with it (measured: 0.26 at 0.81, 2.1e-7 at 20, 4.8e-8 at 27, 1.1e-8
at 36), while the equation stiffens (the contact relaxes on a time ~ 1/lambda of the pulse) and
its solution slows without bound (2.3 s at 36, more than a minute on a plate of 1e-4 R). Above
it the answer is "no rebound" (epsilon below 1e-7) without integrating."""

MAX_CONTACT_TIMES = 200.0
"""The longest contact followed, in Hertz contact times on the rigid-backed plate material."""

_CONTACT_FRACTION = 0.5  # a < h / 2
_WAVELENGTH_FRACTION = 1.0 / 6.0  # h < lambda_f / 6
_TRANSIT_FRACTION = 0.1  # h / c_L < tau / 10


@dataclass(frozen=True)
class PlateImpact:
    """The coupled impact of a ball on a thin plate.

    Attributes
    ----------
    v : float
        Impact speed, ``c``.
    rebounds : bool
        Whether the ball leaves the plate moving away from it.
    epsilon : float or None
        ``-u_end / v`` (``None`` without a rebound).
    plate_energy : float
        ``int P^2 / Z dt`` over ``(m/2) v^2``: the flexural waves' share.
    balance : float
        ``|1 - eps^2 - plate_energy|`` (0 up to the integration's error).
    contact_time, max_compression, max_force : float
        ``R / c``, ``R``, ``E R^2``.
    depth_radiation : float
        What the same ball would radiate into a half-space of the plate's material (Hertz's
        pulse with that ``E*``, :func:`restitution.quasistatic.half_space.radiated_fraction`),
        over ``(m/2) v^2``: the order of the body waves a thick plate sends into its depth,
        which the Kirchhoff plate has not (:func:`model_error`).
    """

    v: float
    rebounds: bool
    epsilon: float | None
    plate_energy: float
    balance: float
    contact_time: float
    max_compression: float
    max_force: float
    depth_radiation: float = 0.0
    force_history: Callable[[np.ndarray], np.ndarray] | None = field(
        default=None, compare=False, repr=False
    )
    """``P(t)`` on ``[0, contact_time]`` (``E R^2``), for :func:`ball_vibrations`."""


def ball_vibrations(impact: PlateImpact, modes) -> float:
    """The energy the plate's force history leaves in the ball's ``modes`` (a sphere's
    :class:`~restitution.bodies.base.ModalBody` of the ball's ``nu``), over ``(m/2) v^2``
    (module docs): Gauss-Legendre panels of 6 nodes over the contact (a third of the fastest
    mode's period each), split towards both ends where the pulse is not smooth; 6 nodes agree
    with 16 to 1e-11 of the energy at 1e-6 and 1e-3 ``c`` on a 3 mm glass plate under a 5 mm
    steel ball."""
    from restitution.quasistatic.pulse import panel_nodes, pulse_spectrum

    if impact.force_history is None:
        raise InputError("this plate impact holds no force history; compute it with plate_impact")
    omega = np.asarray(modes.omega, dtype=float)
    t, w = panel_nodes(0.0, impact.contact_time, float(omega.max()), start=True, end=True,
                       per_panel=6)  # fmt: skip
    spectrum = pulse_spectrum(impact.force_history(t), (t, w), omega)
    m = modes.mass
    energy = modes.C**2 / (2.0 * m) * np.abs(spectrum) ** 2
    return float(energy.sum() / (0.5 * m * impact.v**2))


def plate_impact(v: float, plate, *, nu: float, mass: float, rtol: float = 1e-11) -> PlateImpact:
    """The impact of a ball of Poisson number ``nu`` and ``mass`` at ``v`` (``c``) on
    ``plate`` (:class:`restitution.bodies.wall.Plate`), module docs."""
    if not (math.isfinite(v) and v > 0):
        raise InputError(f"the impact speed must be a positive number (c), got {v!r}")
    e_star = plate.effective_modulus(nu)
    k = 4.0 / 3.0 * e_star
    z = plate.impedance
    depth = radiated_fraction(
        v, mass=mass, radius=1.0, e_star=e_star, wall_density=plate.density_ratio,
        wall_shear_speed=plate.shear_speed, wall_nu=plate.nu,
    )  # fmt: skip
    if zener_parameter(v, plate, nu=nu, mass=mass) > STICKING_PARAMETER:
        nan = math.nan  # no rebound to follow: the plate takes it all (module docs)
        return PlateImpact(float(v), False, None, 1.0, 0.0, nan, nan, nan, depth)
    # Hertz's contact time on the rigid wall of the same E*: the scale of the integration.
    delta_rigid = (1.25 * mass * v * v / k) ** 0.4
    tau = 2.9432752 * delta_rigid / v

    def force(delta):
        return k * max(delta, 0.0) ** 1.5

    def rhs(t, y):
        x, u, delta, energy = y
        p = force(delta)
        return [u, -p / mass, u - p / z, p * p / z]

    def leaves(t, y):
        return y[2]

    leaves.terminal, leaves.direction = True, -1.0
    sol = solve_ivp(rhs, (0.0, MAX_CONTACT_TIMES * tau), [0.0, v, 0.0, 0.0], method="DOP853",
                    rtol=rtol, atol=1e-14 * max(delta_rigid, 1e-300), events=leaves,
                    dense_output=True, max_step=tau / 50.0)  # fmt: skip
    ended = sol.t_events[0].size > 0
    x, u, delta, energy = sol.y_events[0][0] if ended else sol.y[:, -1]
    kinetic = 0.5 * mass * v * v
    plate_energy = energy / kinetic
    rebounds = bool(ended and u < 0.0)
    eps = -u / v if rebounds else None
    final = 0.5 * mass * u * u / kinetic
    grid = np.linspace(0.0, sol.t[-1], 2001)
    deltas = sol.sol(grid)[2]
    return PlateImpact(
        v=float(v),
        rebounds=rebounds,
        epsilon=None if eps is None else float(eps),
        plate_energy=float(plate_energy),
        balance=float(abs(1.0 - final - plate_energy)),
        contact_time=float(sol.t_events[0][0] if ended else sol.t[-1]),
        max_compression=float(deltas.max()),
        max_force=float(force(deltas.max())),
        depth_radiation=depth,
        force_history=lambda t: k * np.clip(sol.sol(np.asarray(t, dtype=float))[2], 0.0,
                                            None) ** 1.5,
    )  # fmt: skip


def _neglected(impact: PlateImpact, plate) -> tuple[float, float, float]:
    """The thin-plate model's three small ratios at ``impact`` (module docs): the contact
    radius over the thickness, the thickness over the flexural wavelength at ``pi / tau`` and
    the compressional transit across the thickness over the contact time."""
    h = plate.thickness
    c_l = plate.compressional_speed
    omega = math.pi / impact.contact_time
    flexural = 2.0 * math.pi * (plate.bending_stiffness / (plate.density_ratio * h)) ** 0.25
    wavelength = flexural / math.sqrt(omega)
    return math.sqrt(impact.max_compression) / h, h / wavelength, h / c_l / impact.contact_time


def echo_ratio(impact: PlateImpact, plate) -> float:
    """The compressional waves' round trip across the plate over the contact time: above 1 the
    echo of the plate's far side returns after the ball has left, and to the ball the plate is
    a block (the elastic half-space)."""
    return 2.0 * _neglected(impact, plate)[2]


def validity(impact: PlateImpact, plate) -> list[str]:
    """What of the thin-plate model fails for ``impact`` (empty: it holds; module docs)."""
    h = plate.thickness
    contact, thickness, transit = _neglected(impact, plate)
    out = []
    if contact > _CONTACT_FRACTION:
        out.append(
            f"the contact radius {contact * h:.3g} R is not small against the thickness {h:g} R"
        )
    if thickness > _WAVELENGTH_FRACTION:
        out.append(
            f"the thickness {h:g} R is not small against the flexural wavelength "
            f"{h / thickness:.3g} R of the pulse"
        )
    if transit > _TRANSIT_FRACTION:
        out.append(
            f"the waves' transit across the thickness ({transit * impact.contact_time:.3g} R/c) "
            f"is not short against the contact time ({impact.contact_time:.3g} R/c)"
        )
    return out


def zener_parameter(v: float, plate, *, nu: float, mass: float) -> float:
    """``lambda = K^(2/5) m^(3/5) v^(1/5) / Z``: the one parameter of the scaled equations
    (``delta = delta0 xi``, ``t = (delta0 / v) s``, ``delta0 = (m v^2 / K)^(2/5)``:
    ``dw/ds = -xi^(3/2)``, ``d xi / ds = w - lambda xi^(3/2)``); epsilon depends on it alone
    (Zener's inelasticity parameter, up to a constant factor)."""
    k = 4.0 / 3.0 * plate.effective_modulus(nu)
    return k**0.4 * mass**0.6 * v**0.2 / plate.impedance


def model_error(impact: PlateImpact, plate) -> float:
    """An estimate of the loss ``1 - epsilon^2`` the thin-plate model misses: the loss times
    the largest of its neglected ratios (the contact radius over the thickness, the thickness
    over the flexural wavelength squared, the transit time over the contact time), plus the
    body waves sent into the plate's depth, of the order of a half-space's radiation
    (:attr:`PlateImpact.depth_radiation`). The finite-element judge (issue 42,
    docs/walls.md) found the 10 mm glass plate under a 5 mm steel ball at 2.6 m/s losing
    0.1118 against Zener's 0.0923: 2.3 times the ratios' estimate (0.0085); the depth term
    (0.0159) was missing from it."""
    contact, thickness, transit = _neglected(impact, plate)
    return impact.plate_energy * max(contact, thickness**2, transit) + impact.depth_radiation
