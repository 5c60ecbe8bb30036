"""A damped sphere law in the DEM codes' own viscoelastic contact: what carries it, what it drops.

The damped law (:mod:`restitution.laws.damped`) is Kelvin-Voigt with one relaxation time
``tau`` (s) on Hertz's quasistatic contact, so its viscous force is::

    F = F_el + tau dF_el/dt,   F_el = (4/3) E* sqrt(R*) delta^(3/2),
    F_diss = tau (dF_el/d delta) delta' = 2 tau E* sqrt(R* delta) delta' = A_n a delta',   (1)

``a = sqrt(R* delta)`` the contact radius and ``A_n = 2 tau E*`` (N s/m^2), the
Brilliantov-Spahn-Hertzsch-Poschel (1996) dissipative force with their ``A = tau``. The contact
ends when the total force first reaches zero (``separation="force"``, docs/damping.md):
afterwards the force stays clipped at zero. Several DEM codes carry (1) natively, each with its
own parameter (:class:`Viscoelastic` holds ``tau`` and each type pair's ``E*``, ``R*``, ``m*``;
each code's module maps them, :mod:`restitution.laws.exports.dem`). With them the simulation
gets the law's velocity dependence, not one constant.

What they drop. (1) is the viscous loss only. The law adds the elastic waves (the grain's
vibrations), which no such model carries: :attr:`Viscoelastic.dropped` states, per speed, the
law's epsilon, the native model's (the package's own quasistatic viscous collision, which the
codes integrate: :func:`restitution.quasistatic.viscoelastic.viscous_collision`) and their
difference, so a user sees how large the left-out part is at the speeds of their simulation.

Every contact of the system. (1) with one ``tau`` holds for every contact of the material, so
one export carries the grains of each size with each other and with a rigid wall (type pairs
``(i, j)``, the wall ``(i, 0)``), whatever the law's own contact; the part dropped is stated for
the law's contact (:attr:`Viscoelastic.law_pair`), where the waves are known.

Only spheres (3D Hertz): the codes' viscoelastic models are Hertz's contact, and a disk's or a
cylinder's contact is not (docs/quasistatic.md); their damped laws reach a DEM code as a
constant or through the LAMMPS plugin. SI units throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError
from restitution.laws.exports.lammps_plugin import contact_modulus, contact_shear_modulus
from restitution.laws.partners.base import partner_of
from restitution.laws.si_point import SIPoint

__all__ = ["ContactScales", "DroppedPart", "Viscoelastic", "viscoelastic_model"]


@dataclass(frozen=True)
class ContactScales:
    """One contact's Hertz constants in SI units.

    Attributes
    ----------
    E_star_pa : float
        ``E*``, Pa: ``1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2`` (a rigid wall: ``E/(1-nu^2)``).
    R_eff_m : float
        ``R* = R1 R2/(R1+R2)``, m (a flat wall: ``R``).
    m_eff_kg : float
        ``m* = m1 m2/(m1+m2)``, kg (a wall: ``m``).
    G_star_pa : float
        Mindlin's ``G*``, Pa: ``1/G* = (2-nu1)/G1 + (2-nu2)/G2`` (a rigid wall: ``G/(2-nu)``),
        for codes whose tangential stiffness is ``8 G* a``.
    """

    E_star_pa: float
    R_eff_m: float
    m_eff_kg: float
    G_star_pa: float

    def epsilon(self, tau_s: float, speeds_m_s) -> np.ndarray:
        """epsilon of (1) at impact speeds ``w`` (m/s): the package's quasistatic viscous
        collision (:func:`~restitution.quasistatic.viscoelastic.viscous_collision`, DOP853) on
        this contact's Hertz law in SI units."""
        from restitution.quasistatic.hertz_sphere import SphereHertzLaw
        from restitution.quasistatic.viscoelastic import viscous_collision

        law = SphereHertzLaw(nu=0.0, R=self.R_eff_m, name="Hertz, SI units",
                             effective_modulus=self.E_star_pa)  # fmt: skip
        w = np.atleast_1d(np.asarray(speeds_m_s, dtype=float))
        return viscous_collision(law, w, tau_s, mass=self.m_eff_kg).epsilon


@dataclass(frozen=True)
class DroppedPart:
    """At one speed: the law's epsilon and the native viscoelastic model's.

    Attributes
    ----------
    law : SIPoint
        The damped law's point (waves and viscosity; its error one standard deviation).
    epsilon_model : float
        The viscous loss alone, what the codes' model (1) gives.
    """

    law: SIPoint
    epsilon_model: float

    speed_m_s = property(lambda self: self.law.speed_m_s, doc="Impact speed, m/s (the law's).")
    epsilon_law = property(lambda self: self.law.epsilon, doc="The damped law's epsilon.")
    epsilon_law_err = property(lambda self: self.law.epsilon_err, doc="Its error.")
    estimate = property(lambda self: self.law.estimate, doc="The law's point as an Estimate.")

    @property
    def dropped(self) -> float:
        """``epsilon_model - epsilon_law``: how much higher the native model's coefficient is,
        the elastic waves it leaves out."""
        return self.epsilon_model - self.epsilon_law


@dataclass(frozen=True)
class Viscoelastic:
    """The damped law as the codes' viscoelastic model (module docs).

    Attributes
    ----------
    relaxation_time_s : float
        ``tau``, s.
    relaxation_time_err_s : float
        Its error (an inferred ``tau``; 0 for a given one), s.
    contacts : dict
        ``(i, j) -> ContactScales`` per pair of particle types, the rigid wall as type ``0``:
        the grains with each other, then each type with the wall.
    law_pair : tuple of int
        The law's own contact among them.
    dropped : tuple of DroppedPart
        The law against the model at the asked speeds, for the law's own contact.
    radii_m : dict
        ``type -> radius`` (m) the constants hold for.
    density : float
        The grains' density, kg/m^3.
    """

    relaxation_time_s: float
    relaxation_time_err_s: float
    contacts: dict
    law_pair: tuple
    dropped: tuple
    radii_m: dict
    density: float

    @property
    def grain_pairs(self) -> list[tuple[int, int]]:
        """The type pairs of two grains, in order."""
        return [pair for pair in self.contacts if pair[1] != 0]

    @property
    def wall_pairs(self) -> list[tuple[int, int]]:
        """``(i, 0)`` for each type ``i`` on the wall."""
        return [pair for pair in self.contacts if pair[1] == 0]

    def damping_coefficient(self, pair: tuple[int, int]) -> float:
        """``A_n = 2 tau E*`` (N s/m^2) of a type pair: ``F_diss = A_n a delta'`` (1)."""
        return 2.0 * self.relaxation_time_s * self.contacts[pair].E_star_pa

    def describe(self) -> list[str]:
        """Comment lines every code's snippet carries: the model, the constants, the radii they
        hold for, and the part left out per speed."""
        lines = [
            "damping: Kelvin-Voigt on Hertz's contact (Brilliantov et al. 1996), F = F_el + tau "
            f"dF_el/dt, tau = {self.relaxation_time_s:.6g} +- {self.relaxation_time_err_s:.2g} s; "
            "the contact ends when the total force reaches zero (no attraction)",
            "the constants below hold for grains of radius "
            + ", ".join(f"{r:.6g} m (type {t})" for t, r in sorted(self.radii_m.items()))
            + f" and density {self.density:.6g} kg/m^3; another size needs its own",
        ]
        for (i, j), c in self.contacts.items():
            who = f"type {i} on the wall" if j == 0 else f"types {i}-{j}"
            lines.append(
                f"{who}: E* = {c.E_star_pa:.8g} Pa, R* = {c.R_eff_m:.6g} m, m* = "
                f"{c.m_eff_kg:.6g} kg, A_n = 2 tau E* = {self.damping_coefficient((i, j)):.8g} "
                "N s/m^2"
            )
        if self.dropped:
            i, j = self.law_pair
            who = f"type {i} on the wall" if j == 0 else f"types {i}-{j}"
            lines.append(
                "left out: the elastic waves (the grains' vibrations), which this model cannot "
                f"carry; for {who} (the law's contact; the others drop theirs too), the law's "
                "epsilon against the model's, per impact speed:"
            )
            lines += [
                f"  w = {d.speed_m_s:.4g} m/s: law {d.epsilon_law:.6f} +- {d.epsilon_law_err:.2g}"
                f", model {d.epsilon_model:.6f}, model - law = {d.dropped:.2g}"
                for d in self.dropped
            ]
        return lines


def _sphere_mass(radius_m: float, rho: float) -> float:
    return 4.0 / 3.0 * math.pi * radius_m**3 * rho


def viscoelastic_model(damped, speeds_m_s, radius_m: float | None = None) -> Viscoelastic:
    """The damped law ``damped`` (a :class:`~restitution.laws.damped.DampedLaw` of spheres, of
    one material) as the codes' viscoelastic model, with the part it drops at ``speeds_m_s``.

    ``radius_m`` (m): the grain's radius (for two sizes the smaller grain's), default the one
    the damped law knows. Types: on a wall ``(1, 0)``; identical grains ``(1, 1)``; two sizes
    ``(1, 1)``, ``(2, 2)`` and ``(1, 2)``, type 1 the small grain.

    Raises
    ------
    InputError
        For a body other than the sphere, grains of two materials, or no radius.
    """
    si = damped.si
    g = si.grain
    if g.kind.dimension != 3:
        raise InputError(
            f"the DEM codes' viscoelastic models are Hertz's contact of spheres; a "
            f"{g.geometry}'s damped law reaches them as a constant (--reference-speed) or "
            "through the LAMMPS plugin (docs/lammps-plugin.md)"
        )
    pair = si.law.partner
    if pair is not None and not pair.same_material:
        raise InputError(
            "a viscoelastic model of grains of two materials needs each material's relaxation "
            "time; this damped law has one: export grains of one material"
        )
    radius = radius_m if radius_m is not None else damped.radius_m
    if radius is None or not radius > 0.0:
        raise InputError(
            "the viscoelastic constants depend on the grain's size: give --radius (m), the "
            "grain's radius (for two sizes the smaller grain's)"
        )
    tau_s = damped.tau * radius / g.c_m_s
    tau_err_s = damped.tau_err * radius / g.c_m_s
    e_one = contact_modulus(g.E, g.nu)  # one sphere's E / (1 - nu^2): on the rigid wall
    g_one = contact_shear_modulus(g.E, g.nu)  # G / (2 - nu): on the rigid wall
    ratio = 1.0 if pair is None else float(pair.radius_ratio)
    radii = {1: radius} if ratio == 1.0 else {1: radius, 2: ratio * radius}
    mass = {t: _sphere_mass(r, g.rho) for t, r in radii.items()}
    contacts = {}
    for i in radii:
        for j in radii:
            if i <= j:
                ri, rj, mi, mj = radii[i], radii[j], mass[i], mass[j]
                contacts[i, j] = ContactScales(e_one / 2.0, ri * rj / (ri + rj),
                                               mi * mj / (mi + mj), g_one / 2.0)  # fmt: skip
    for i in radii:
        contacts[i, 0] = ContactScales(e_one, radii[i], mass[i], g_one)
    if not partner_of(si).is_grain:
        law_pair = (1, 0)
    else:
        law_pair = (1, 2) if ratio != 1.0 else (1, 1)
    dropped = tuple(
        DroppedPart(p, p.epsilon_viscous)
        for p in damped.points(list(speeds_m_s))
        if p.epsilon is not None and p.epsilon_viscous is not None
    )
    return Viscoelastic(tau_s, tau_err_s, contacts, law_pair, dropped, radii, float(g.rho))
