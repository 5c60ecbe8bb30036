"""The time step a DEM code needs for the contacts of an export: Hertz's contact time, / 50.

Units: SI (Pa, m, kg, m/s, s).

What the codes integrate. Every snippet of :mod:`restitution.laws.exports.dem` and the LAMMPS
plugin give the code Hertz's normal contact of spherical particles (LAMMPS's and LIGGGHTS's
``hertz``, YADE's Mindlin, MercuryDPM's Hertzian species, the plugin's Hertz + Tsuji), also in
a 2D run, whose particles are still spheres to the code (LAMMPS's ``set density`` gives them a
sphere's mass). The disk's own two-dimensional contact (:mod:`restitution.quasistatic.hertz`)
is the grain's physics inside the law, not the force the code integrates, so it does not set
the code's step. (MercuryDPM's linear species of a constant take the user's collision time
``tc``: their step is ``tc / 50``, :mod:`~restitution.laws.exports.dem.mercurydpm`.)

Hertz's contact time. Two spheres (or a sphere on a flat) of reduced modulus ``E*``, radius
``R*`` and mass ``m*`` that meet at speed ``w`` stay in contact for::

    t_c = kappa delta_max / w,   delta_max = (15 m* w^2 / (16 E* sqrt(R*)))^(2/5),
    t_c = kappa (15/16)^(2/5) (m*^2 / (E*^2 R* w))^(1/5) = 2.8683 (m*^2 / (E*^2 R* w))^(1/5),

with ``kappa = 2 sqrt(pi) Gamma(7/5) / Gamma(9/10) = 2.9433`` the duration of a Hertz impact in
units of ``delta_max / w`` (:data:`restitution.bodies.sphere.surface.CONTACT_TIME_CONSTANT`;
Johnson, *Contact Mechanics*, 1985, ch. 11, gives ``2.94 delta_max / w = 2.87 (m^2 / (R E*^2
w))^(1/5)``). The contact shortens as ``w^(-1/5)``: the fastest impact the exported law serves
has the shortest contact of its range, ``t_c(w_max)``, which is what every contact type's step
is taken from (:func:`time_steps`).

The rule ``dt = t_c / 50`` (:data:`STEPS_PER_CONTACT`). Velocity Verlet (LAMMPS's ``fix
nve/sphere``, the force from the half-step velocity) on Hertz's contact with Tsuji's damping
(the plugin's and LAMMPS's ``coeff_restitution``), ``dt = t_c / N``, gives epsilon off by at
most (over where between two steps the contact opens; tests/test_time_step.py)::

    epsilon    N = 20     50       100      200
    1          4.3e-4   4.1e-5   7.1e-6   1.2e-6
    0.99       4.1e-4   5.3e-5   1.8e-5   1.2e-5
    0.9        2.0e-3   7.7e-4   1.5e-4   1.3e-4
    0.7        6.3e-3   2.4e-3   5.5e-4   4.9e-4
    0.5        1.1e-2   4.3e-3   1.4e-3   9.2e-4

At 50 steps per contact the error is below ``0.01 (1 - epsilon) + 5e-5``, one percent of the
loss: finer than the laws' own error bars where damping makes the loss large (the glass bead's
damped law, epsilon = 0.900 +- 0.0015 at 1 m/s), and it shrinks further for every slower impact,
whose contact spans more steps. (The plugin's LAMMPS runs at one opening phase lie within these:
docs/lammps-plugin.md, "Time-step error".)

A grain's size. ``t_c`` grows as the grains' radius at one density (``m* ~ R^3``, ``R* ~ R``):
without a radius the times are given for a type-1 radius of :data:`REFERENCE_RADIUS_M` and
scale with it, and no step is set.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.errors import InputError
from restitution.laws.exports.plugin_files import system_contacts
from restitution.laws.partners.base import partner_of

__all__ = [
    "REFERENCE_RADIUS_M",
    "STEPS_PER_CONTACT",
    "ContactTime",
    "TimeSteps",
    "hertz_contact_time",
    "time_steps",
]

STEPS_PER_CONTACT = 50
"""Time steps per contact of the recommended step ``dt = t_c / 50`` (module docs)."""

REFERENCE_RADIUS_M = 1e-3
"""The type-1 radius (m) the contact times are given for when the export knows no radius."""


def hertz_contact_time(e_star_pa, r_eff_m, m_eff_kg, speed_m_s):
    """Hertz's contact time (s) of a contact of ``E*`` (Pa), ``R*`` (m) and ``m*`` (kg) hit at
    ``w`` (m/s): ``kappa delta_max / w`` (module docs), the sphere's Hertz scales of
    :mod:`restitution.bodies.sphere.surface` in SI units.

    >>> round(hertz_contact_time(1.0, 1.0, 1.0, 1.0), 4)  # 2.9433 (15/16)^(2/5)
    2.8683
    """
    w = speed_m_s
    delta_max = (15.0 * m_eff_kg * w**2 / (16.0 * e_star_pa * math.sqrt(r_eff_m))) ** 0.4
    return CONTACT_TIME_CONSTANT * delta_max / w


def _floor3(x: float) -> float:
    """``x`` rounded down to three significant digits: a printed bound no larger than ``x``."""
    e = math.floor(math.log10(x)) - 2
    return math.floor(x / 10.0**e * (1.0 + 1e-12)) * 10.0**e


@dataclass(frozen=True)
class ContactTime:
    """One contact type's Hertz constants, its fastest impact and its contact time.

    Attributes
    ----------
    contact : str
        Which contact: ``"types 1-2"``, ``"type 1 on the wall"``.
    E_star_pa, R_eff_m, m_eff_kg : float
        ``E*`` (Pa), ``R*`` (m) and ``m*`` (kg) of the contact (a wall: the grain's ``R`` and
        ``m``).
    speed_m_s : float
        The fastest impact speed (m/s) of the exported law of this contact.
    whose : str
        Whose range ``speed_m_s`` is: ``"its law"``, or the exported law's when the export
        has none of this contact.
    """

    contact: str
    E_star_pa: float
    R_eff_m: float
    m_eff_kg: float
    speed_m_s: float
    whose: str = "its law"

    @property
    def contact_time_s(self) -> float:
        """Hertz's contact time at :attr:`speed_m_s`, s: the shortest of the law's range."""
        return hertz_contact_time(self.E_star_pa, self.R_eff_m, self.m_eff_kg, self.speed_m_s)

    @property
    def time_step_s(self) -> float:
        """The recommended step ``t_c / STEPS_PER_CONTACT``, s."""
        return self.contact_time_s / STEPS_PER_CONTACT


@dataclass(frozen=True)
class TimeSteps:
    """The recommended time step of every contact type of an export (module docs).

    Attributes
    ----------
    contacts : tuple of ContactTime
    radius_m : float or None
        The type-1 grain's radius the times hold for; ``None``: none was given, the times are
        for :data:`REFERENCE_RADIUS_M` and scale with the radius.
    """

    contacts: tuple[ContactTime, ...]
    radius_m: float | None

    @property
    def steps_per_contact(self) -> int:
        """The rule's steps per contact, :data:`STEPS_PER_CONTACT`."""
        return STEPS_PER_CONTACT

    @property
    def sized(self) -> bool:
        """Whether the times are for the grains' own radius (a step can be set)."""
        return self.radius_m is not None

    @property
    def time_step_s(self) -> float:
        """The step for all contacts together, s: the smallest, rounded down to three digits."""
        return _floor3(min(c.time_step_s for c in self.contacts))

    def lines(self) -> list[str]:
        """Comment lines (without a comment mark): the rule, each contact's time and step
        (:meth:`contact_lines`), how slower impacts and another size change them."""
        return [
            f"time step: dt = t_c/{STEPS_PER_CONTACT}, t_c = 2.868 (m*^2/(E*^2 R* w))^(1/5) "
            "Hertz's contact time (Johnson, Contact Mechanics, 1985, ch. 11) of the code's "
            "spherical particles at the fastest impact w of each contact's law (the shortest "
            f"contact, t_c ~ w^(-1/5)); at {STEPS_PER_CONTACT} steps per contact velocity "
            "Verlet's epsilon is off by at most 1 % of the loss 1 - epsilon, + 5e-5 "
            "(restitution.laws.exports.time_step)",
            *self.contact_lines(),
        ]

    def contact_lines(self) -> list[str]:
        """One comment line per contact type (``E*``, ``R*``, ``m*``, its fastest impact, its
        contact time and step), then how slower impacts and another size change them."""
        scale = "" if self.sized else " x R1/(1 mm)"
        out = []
        for c in self.contacts:
            radius = "" if self.sized else f" ({c.R_eff_m / REFERENCE_RADIUS_M:.4g} R1)"
            out.append(
                f"  {c.contact}: w = {c.speed_m_s:.4g} m/s ({c.whose}), E* = {c.E_star_pa:.4g} Pa,"
                f" R* = {c.R_eff_m:.4g} m{radius}, m* = {c.m_eff_kg:.4g} kg: t_c = "
                f"{c.contact_time_s:.3g} s{scale}, dt <= {_floor3(c.time_step_s):.3g} s{scale}"
            )
        w_max = max(c.speed_m_s for c in self.contacts)
        out.append(
            "impacts slower than w last longer: if none is faster than u, dt may be "
            f"(w/u)^(1/5) times larger ({w_max**0.2:.3g} times for u = 1 m/s and the fastest w "
            "here)"
        )
        if not self.sized:
            out.append(
                f"for grains of type-1 radius R1 (R1 = {REFERENCE_RADIUS_M * 1e3:g} mm above; "
                "t_c grows as R1 at one density); no step set: give --radius (m) for one in "
                "seconds"
            )
        return out

    def to_dict(self) -> dict:
        """JSON-ready: the rule, the step, and each contact's time (SI units)."""
        return {
            "steps_per_contact": STEPS_PER_CONTACT,
            "radius_m": self.radius_m,
            "reference_radius_m": None if self.sized else REFERENCE_RADIUS_M,
            "time_step_s": self.time_step_s,
            "contacts": [
                {
                    "contact": c.contact,
                    "speed_m_s": c.speed_m_s,
                    "E_star_pa": c.E_star_pa,
                    "R_eff_m": c.R_eff_m,
                    "m_eff_kg": c.m_eff_kg,
                    "contact_time_s": c.contact_time_s,
                    "time_step_s": c.time_step_s,
                }
                for c in self.contacts
            ],
        }


def _sphere_mass(radius_m: float, rho: float) -> float:
    return 4.0 / 3.0 * math.pi * radius_m**3 * rho


def time_steps(s, c=None, radius_m: float | None = None, walls=None) -> TimeSteps:
    """The time step of every contact type of the export of the law ``s`` (an
    :class:`~restitution.laws.si_law.SILaw`; ``c``, ``walls``: as for
    :func:`~restitution.laws.exports.plugin_files.plugin_files`).

    The contact types: a wall's law, type 1 on the wall; grains, every pair of their types
    (1-1, and 1-2 and 2-2 for two sizes or materials, type 1 the grain of radius ``R1``, type 2
    of ``R2 = radius_ratio R1``) and each type on the wall (a grain export carries the grains'
    wall laws too). Each contact's speed is the fastest its exported law serves, the exported
    law's own where the export has none of that contact (a type pair of a one-constant pair).

    Parameters
    ----------
    radius_m : float, optional
        ``R1``, m; default: the times for :data:`REFERENCE_RADIUS_M` (they scale with it).

    Returns
    -------
    TimeSteps
    """
    if radius_m is not None and not (math.isfinite(radius_m) and radius_m > 0.0):
        raise InputError(f"the grains' radius must be a positive number of m, got {radius_m!r}")
    system = system_contacts(s, c, walls)
    r1 = REFERENCE_RADIUS_M if radius_m is None else float(radius_m)
    pair = s.law.partner
    two = pair is not None
    radii = {1: r1, 2: float(pair.radius_ratio) * r1} if two else {1: r1}
    mass = {i: _sphere_mass(r, system.grains[i].rho) for i, r in radii.items()}
    fastest = s.speed_range_m_s[1]
    if partner_of(s).is_grain:
        keys = [(i, j) for i in radii for j in radii if i <= j] + [(i, 0) for i in radii]
    else:
        keys = [(1, 0)]
    out = []
    for i, j in keys:
        law = system.laws.get((i, j))
        if law is None and j == 0 and system.grains[i] == system.grains[1]:
            law = system.laws.get((1, 0))  # one material: one wall law for every size
        w, whose = (law.speed_range_m_s[1], "its law") if law is not None else (
            fastest, "no law of this contact exported: the exported law's")  # fmt: skip
        if j == 0:
            r_eff, m_eff, what = radii[i], mass[i], f"type {i} on the wall"
        else:
            r_eff = radii[i] * radii[j] / (radii[i] + radii[j])
            m_eff = mass[i] * mass[j] / (mass[i] + mass[j])
            what = f"types {i}-{j}"
        out.append(ContactTime(what, system.contact_modulus(i, j), r_eff, m_eff, w, whose))
    return TimeSteps(tuple(out), None if radius_m is None else r1)
