"""Energy radiated into an elastic half-space by a slow impact: Hertz's pulse through Lamb's
point-force radiation (issue 42, the half-space's low-speed route; ``law --wall-E ...``).

Units: SI-free, any consistent set; the tests use the ball's ``E = rho = R = 1``. The wall is a
half-space of density ``rho_w``, shear modulus ``mu_w = E_w / (2 (1 + nu_w))`` and shear speed
``c_T = sqrt(mu_w / rho_w)``.

**Radiation of a vertical point force** (Lamb 1904; Miller and Pursey 1954-55). A force
``F cos(omega t)`` normal to the surface puts the time-averaged power ``W = (1/2) F^2 omega
Im G(omega)`` into the half-space, ``G`` the vertical surface displacement under the force per
unit force. With ``s = k / k_T`` and ``gamma = c_T / c_L``, Lamb's integral is
``G = (k_T / (2 pi mu_w)) J``, ``J = int_0^inf a s / D ds``, ``a = sqrt(s^2 - gamma^2)``,
``b = sqrt(s^2 - 1)``, ``D = (2 s^2 - 1)^2 - 4 s^2 a b`` (the Rayleigh function); its static
part is Boussinesq's ``(1 - nu) / (2 pi mu r)``. The imaginary part, the radiated power, has
three parts (:func:`radiation_integrals`):

* ``s < gamma``: compressional and shear waves, ``int_0^gamma p s / D ds`` with
  ``p = sqrt(gamma^2 - s^2)``, ``q = sqrt(1 - s^2)``, ``D = (2 s^2 - 1)^2 + 4 s^2 p q``;
* ``gamma < s < 1``: shear waves alone, ``int 4 s^3 a^2 q / |D|^2 ds``;
* the pole of ``D`` at ``s_R = c_T / c_R``: Rayleigh waves, ``pi a_R s_R / |D'(s_R)|``.

Their sum ``I(nu) = Im J`` gives ``W = I omega^2 F^2 / (4 pi rho_w c_T^3)``: the point force's
radiation conductance grows like ``omega^2`` and does not depend on the size of the loaded
area as long as it is small against the wavelengths.

**A pulse** ``P(t)`` (the force between ball and wall) delivers
``E_rad = (1/pi) int_0^inf |P(omega)|^2 omega Im G d omega`` into the waves, and with
Parseval's theorem::

    E_rad = I / (2 pi rho_w c_T^3) int (dP/dt)^2 dt

**Hertz's pulse** ``P = K delta^(3/2)`` of a collision at speed ``v`` (mass ``m``, ``K = (4/3) E*
sqrt(R)``, ``E*`` of ball and wall) is self-similar: with ``x = delta / delta_max`` and
``v tau = kappa delta_max`` (``kappa = 2.9433``, :mod:`restitution.quasistatic.hertz_sphere`),
``int (dP/dt)^2 dt = (9/5) B(4/5, 3/2) K^2 delta_max^2 v`` (``B`` Euler's beta function: the
integral of ``(9/4) x (dx/dt)^2`` over the two halves of the pulse). Divided by ``(m/2) v^2 =
(2/5) K delta_max^(5/2)``::

    E_rad / E_kin = I / (2 pi rho_w c_T^3) (9/2) B(4/5, 3/2) K v / sqrt(delta_max) ~ v^(3/5)

since ``delta_max ~ v^(4/5)``: the ``(v/c)^(3/5)`` law of Hunter (1957) and Reed (1985), here
with its constant from Lamb's integral and Hertz's exact pulse. It holds while the radiated
energy is small (the pulse is Hertz's, unchanged by the loss) and the contact is small against
the wavelengths the pulse excites (``a << c_T tau``); the ball's own vibrations are a separate
loss (:mod:`restitution.quasistatic.low_speed`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import beta

from restitution.errors import InputError

__all__ = [
    "BALL_QUADRATURE_PHASE",
    "HALF_SPACE_REACH_SPEED",
    "HERTZ_PULSE_FACTOR",
    "PULSE_EXPONENT",
    "LossBeyondEnergy",
    "RadiationIntegrals",
    "ball_envelope",
    "ball_integrated",
    "half_space_loss",
    "half_space_reach",
    "radiated_fraction",
    "radiation_conductance",
    "radiation_integrals",
]

PULSE_EXPONENT = 3.0
"""``int (dP/dt)^2 dt ~ J^2 / T^3`` at a fixed impulse ``J``: a relative change ``s`` of the
pulse's duration changes the radiated energy by ``3 s`` (:func:`half_space_loss`'s error)."""


class LossBeyondEnergy(InputError):
    """The half-space route has no value at a speed: the losses it computes on Hertz's pulse
    reach the kinetic energy (a very dense or soft wall), where the pulse, computed without the
    energy it loses, no longer holds (:func:`half_space_loss`)."""


HERTZ_PULSE_FACTOR = 1.8 * beta(0.8, 1.5)
"""``int (dP/dt)^2 dt / (K^2 delta_max^2 v) = (9/5) B(4/5, 3/2)`` for Hertz's pulse (module
docs)."""


@dataclass(frozen=True)
class RadiationIntegrals:
    """The three parts of ``Im J`` of a vertical point force (module docs), dimensionless.

    Attributes
    ----------
    nu : float
        The half-space's Poisson number.
    body_both, body_shear, rayleigh : float
        Compressional and shear waves (``s < gamma``), shear waves alone (``gamma < s < 1``),
        Rayleigh waves (the pole).
    rayleigh_speed : float
        ``c_R / c_T``.
    """

    nu: float
    body_both: float
    body_shear: float
    rayleigh: float
    rayleigh_speed: float

    @property
    def total(self) -> float:
        """``I = Im J``: ``W = I omega^2 F^2 / (4 pi rho c_T^3)``."""
        return self.body_both + self.body_shear + self.rayleigh

    @property
    def rayleigh_share(self) -> float:
        """The Rayleigh waves' share of the radiated power."""
        return self.rayleigh / self.total


def radiation_integrals(nu: float) -> RadiationIntegrals:
    """Lamb's radiation integrals of a half-space of Poisson number ``nu`` (module docs)."""
    if not (isinstance(nu, int | float) and -1.0 < nu < 0.5):
        raise InputError(f"the half-space's Poisson number must lie in (-1, 0.5), got {nu!r}")
    g = math.sqrt((1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)))

    def both(s):
        p, q = math.sqrt(g * g - s * s), math.sqrt(1.0 - s * s)
        return p * s / ((2.0 * s * s - 1.0) ** 2 + 4.0 * s * s * p * q)

    def shear(s):
        a2, q = s * s - g * g, math.sqrt(1.0 - s * s)
        re, im = (2.0 * s * s - 1.0) ** 2, 4.0 * s * s * math.sqrt(a2) * q
        return 4.0 * s**3 * a2 * q / (re * re + im * im)

    def rayleigh_function(s):
        return (2.0 * s * s - 1.0) ** 2 - 4.0 * s * s * math.sqrt(s * s - g * g) * math.sqrt(
            s * s - 1.0
        )

    def slope(s):  # dD/ds, analytic
        a, b = math.sqrt(s * s - g * g), math.sqrt(s * s - 1.0)
        return 8.0 * s * (2.0 * s * s - 1.0) - 8.0 * s * a * b - 4.0 * s**3 * (b / a + a / b)

    first = quad(both, 0.0, g, epsabs=0.0, epsrel=1e-12, limit=200)[0]
    second = quad(shear, g, 1.0, epsabs=0.0, epsrel=1e-12, limit=200)[0]
    s_r = brentq(rayleigh_function, 1.0 + 1e-12, 10.0, xtol=1e-15, rtol=1e-15)
    pole = math.pi * math.sqrt(s_r * s_r - g * g) * s_r / abs(slope(s_r))
    return RadiationIntegrals(float(nu), first, second, pole, 1.0 / s_r)


def radiated_fraction(
    v: float,
    *,
    mass: float,
    radius: float,
    e_star: float,
    wall_density: float,
    wall_shear_speed: float,
    wall_nu: float,
) -> float:
    """``E_rad / E_kin`` of a ball of ``mass`` and ``radius`` hitting the half-space at ``v``
    (module docs); ``e_star`` is Hertz's ``1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w``."""
    given = {"v": v, "mass": mass, "radius": radius, "e_star": e_star,
             "wall_density": wall_density, "wall_shear_speed": wall_shear_speed}  # fmt: skip
    for name, x in given.items():
        if not (math.isfinite(x) and x > 0):
            raise InputError(f"{name} must be a positive number, got {x!r}")
    k = 4.0 / 3.0 * e_star * math.sqrt(radius)
    delta = (1.25 * mass * v * v / k) ** 0.4
    conductance = radiation_conductance(wall_density, wall_shear_speed, wall_nu)
    return conductance * 4.5 * beta(0.8, 1.5) * k * v / math.sqrt(delta)


def radiation_conductance(wall_density: float, wall_shear_speed: float, wall_nu: float) -> float:
    """``I / (2 pi rho_w c_T^3)``: ``E_rad = conductance * int (dP/dt)^2 dt`` for any pulse
    ``P(t)`` on the half-space (module docs)."""
    integral = radiation_integrals(wall_nu).total
    return integral / (2.0 * math.pi * wall_density * wall_shear_speed**3)


def half_space_loss(modes, v: float, wall):
    """A sphere's loss on an elastic half-space at speed ``v`` (``c``), split into its own
    vibrations and the wall's waves, each from the same Hertz pulse (``E*`` of ball and wall).

    The ball's part is Rayleigh's estimate of its modes with its band
    (:func:`restitution.quasistatic.low_speed.low_speed_loss` on the compliant pulse); on a
    wall soft enough that the ball's slowest mode is slow against the contact
    (:data:`BALL_QUADRATURE_PHASE`) half its envelope, the other half its error. The
    wall's part is :func:`radiated_fraction`; its error estimate is the fraction times three
    times the band's relative contact-time spread ``0.335 a / R`` (the dynamic pulse differs
    from Hertz's at that order, and the radiated energy ``int (dP/dt)^2 dt`` goes like
    ``J^2 / T^3`` at a fixed impulse ``J``: three times the relative change of the duration
    ``T``) plus the fraction itself (the pulse computed without the energy it loses: first
    order in the loss). Both errors add. The factor 3 was missing before the FEM judge
    (:mod:`restitution.fem.wall_reference`, docs/walls.md) measured the wave share above
    Hertz's by up to about ``a / R`` on walls harder than the ball.

    Parameters
    ----------
    modes : ModalBody
        The sphere's modes (:data:`restitution.quasistatic.low_speed.LOW_SPEED_MODES`).
    v : float
        Speed towards the wall, ``c``.
    wall : restitution.bodies.wall.HalfSpace

    Returns
    -------
    LowSpeedLoss
        With ``shares = (ball, wall)`` (fractions of ``(m/2) v^2``).

    Raises
    ------
    LossBeyondEnergy
        Where the two losses reach the kinetic energy (``epsilon`` would be imaginary): the
        route has no value there.
    """
    from dataclasses import replace

    from restitution.quasistatic.hertz_sphere import sphere_contact_law
    from restitution.quasistatic.low_speed import CONTACT_TIME_SPREAD

    e_star = wall.effective_modulus(modes.nu)
    law = replace(sphere_contact_law(modes.nu), effective_modulus=e_star,
                  name="hertz (sphere on an elastic half-space)")  # fmt: skip
    ball = _ball_part(modes, v, law)
    waves = radiated_fraction(
        v, mass=modes.mass, radius=1.0, e_star=e_star, wall_density=wall.density_ratio,
        wall_shear_speed=wall.shear_speed, wall_nu=wall.nu,
    )  # fmt: skip
    spread = CONTACT_TIME_SPREAD * math.sqrt(ball.max_compression)
    loss = ball.energy_loss + waves
    if not loss < 1.0:  # a wall dense enough radiates, on Hertz's pulse, more than there is
        raise LossBeyondEnergy(
            f"the ball's vibrations and the waves radiated into the wall take {loss:.3g} times "
            f"the kinetic energy at v = {v:.3g} c on Hertz's pulse (the route holds while they "
            "take little of it)"
        )
    err = ball.energy_loss_err + waves * (PULSE_EXPONENT * spread + waves)
    return replace(ball, energy_loss=loss, energy_loss_err=err, shares=(ball.energy_loss, waves))


def ball_envelope(modes, v: float, wall) -> float:
    """An upper bound on the ball's own loss on the half-space at ``v`` (fraction of
    ``(m/2) v^2``): Rayleigh's leading asymptotic term with every mode's phase factor
    ``cos^2(omega tau / 2 - 5 pi / 4)`` set to 1 (:func:`restitution.quasistatic.hertz_sphere.
    drive_asymptote`; up to its ``O(sqrt(delta_max))`` corrections and the modes beyond the
    set). It grows like ``v``; between two speeds the loss may swing anywhere below it, so it
    bounds what interpolating the ball's part can miss
    (:mod:`restitution.laws.wall_grid`). It bounds the ball's loss on a plate too
    (:func:`restitution.laws.wall_route.plate_record`): Zener's pulse starts and ends like
    ``t^(3/2)``, at the rates ``v`` and ``epsilon v``, so its spectrum's leading term is at
    most twice this one's amplitude, ``|F|^2 <= 4 amp^2``."""
    from dataclasses import replace

    from restitution.quasistatic.hertz_sphere import sphere_contact_law

    law = replace(sphere_contact_law(modes.nu), effective_modulus=wall.effective_modulus(modes.nu))
    return float(_envelope_terms(modes, v, law).sum())


def _envelope_terms(modes, v: float, law) -> np.ndarray:
    """Each mode's share of :func:`ball_envelope` on the pulse of ``law``, shape (N,)."""
    amp = law.K * v**1.5 * math.gamma(2.5) * modes.omega**-2.5
    m = modes.mass
    return 2.0 * modes.C**2 / m * amp**2 / (0.5 * m * v**2)


BALL_QUADRATURE_PHASE = 300.0
"""``omega_1 tau`` (the ball's slowest mode times Hertz's contact time on the wall) from which
the ball's part of the loss is not integrated (:func:`half_space_loss`): its quadrature grows
like ``tau`` (a wall of 63 Pa under a steel ball asked 1.7 GiB a node array and would have
taken hours), while the part itself falls far below the wall's error. It is then half its
envelope (:func:`ball_envelope`, every phase factor 1) with the other half and the tail beyond
the modes as its error: every phase is covered. Measured on the project's machine: steel on
glass reaches 231 at ``v = 1e-6`` (the grid's slowest speed), so glass, steel and harder walls
are integrated as before; at 331 (a 1 GPa wall at its reach) the envelope is 4e-7 of the
wall's error, at 691 (3 GPa, ``v = 1e-6``) 7e-6."""


def ball_integrated(modes, contact_time: float) -> bool:
    """Whether the ball's part is integrated over a contact of ``contact_time`` (``R / c``)
    rather than bounded by its envelope (:data:`BALL_QUADRATURE_PHASE`)."""
    return float(np.min(modes.omega)) * contact_time < BALL_QUADRATURE_PHASE


HALF_SPACE_REACH_SPEED = 0.005
"""The half-space route serves contacts as wide, for the ball, as the sphere's on the rigid
wall at this speed (``c``): ``a / R = 0.155`` at ``nu = 0.3``. Sources: the ball's band holds
the shipped modal law's points on the rigid wall up to ``v = 0.02`` (``a / R = 0.27``,
tests/test_sphere_low_speed.py), so the ball's part reaches further; the wave part was judged
by the finite elements up to ``a / R = 0.14`` (a steel ball on a glass block at 10 m/s,
``laws/data/fem_reference_wall.json``, docs/walls.md). A steel ball on glass reaches 12.3
m/s, on steel 18.3 m/s."""


def half_space_reach(nu: float, wall) -> float:
    """The fastest speed (``c``) the half-space route serves: where the contact is as wide, for
    the ball, as on the rigid wall at :data:`HALF_SPACE_REACH_SPEED`
    (:func:`restitution.quasistatic.low_speed.width_reach`: ``a / R`` fixes the band)."""
    from dataclasses import replace

    from restitution.quasistatic.hertz_sphere import SPHERE_MASS, sphere_contact_law
    from restitution.quasistatic.low_speed import width_reach

    law = replace(sphere_contact_law(nu), effective_modulus=wall.effective_modulus(nu))
    return width_reach(nu, law, 1.0, SPHERE_MASS, at=HALF_SPACE_REACH_SPEED)


def _ball_part(modes, v: float, law):
    """The ball's own loss on the pulse of ``law`` (:func:`half_space_loss`): Rayleigh's
    estimate (:func:`restitution.quasistatic.low_speed.low_speed_loss`) where the contact is
    short enough to integrate, half the envelope otherwise (:data:`BALL_QUADRATURE_PHASE`)."""
    from restitution.quasistatic.hertz_sphere import sphere_quasistatic_collision
    from restitution.quasistatic.low_speed import (
        CONTACT_TIME_SPREAD,
        LowSpeedLoss,
        low_speed_loss,
    )

    hertz = sphere_quasistatic_collision(law, v, mass=modes.mass)
    tau = float(hertz.contact_time[0])
    if ball_integrated(modes, tau):
        return low_speed_loss(modes, v, law=law)
    terms = _envelope_terms(modes, v, law)
    envelope = float(terms.sum())
    order = np.argsort(modes.omega, kind="stable")
    tail = float(terms[order[len(modes) // 2 :]].sum())  # twice the phase mean, as low_speed's
    loss, err = 0.5 * envelope, 0.5 * envelope + tail
    return LowSpeedLoss(
        v=float(v), nu=float(modes.nu), energy_loss=loss, energy_loss_err=err,
        band=(0.0, envelope), tail=tail, n_modes=len(modes),
        contact_time=tau, max_compression=float(hertz.max_compression[0]),
        spread=CONTACT_TIME_SPREAD, shares=(loss,),
    )  # fmt: skip
