"""epsilon(w) of a grain that yields: plastic flow, viscous loss and elastic waves on one pulse.

Units: SI at the edge (speeds m/s, pressures Pa, the relaxation time in the law's ``R / c``);
inside, the law's reduced units (``v`` in ``c``, pressures in the grain's ``E``; for two spheres
the first one's).

A metal grain loses far more to plastic flow above its yield speed than to its vibrations
(issue 43). :class:`PlasticLaw` computes, at every asked speed, one force pulse of the contact
with all its mechanisms (:mod:`restitution.quasistatic.plastic_collision`: Thornton's
elastic-perfectly-plastic force, the Kelvin-Voigt viscous force when the material damps) and the
elastic waves that pulse leaves:

* ``loss_plastic``, ``loss_viscous``, ``loss_stored``: fractions of the kinetic energy the
  contact keeps (plastic work, viscous work, elastic energy still in the contact at separation);
* ``loss_waves``: the elastic law's loss (its modal or low-speed value at this speed, with its
  split between the bodies or into an elastic wall), each part scaled by how much more or less
  the actual pulse drives it than Hertz's pulse at the same speed: the ratio of the two
  Rayleigh estimates of the body's modes, and of ``int (dF/dt)^2 dt`` for the waves radiated
  into a wall;
* ``epsilon = sqrt(epsilon_contact^2 - loss_waves)``.

The old sum of parts, ``1 - eps^2 = (1 - eps_elastic^2) + (1 - eps_viscous^2) + (1 -
eps_Thornton^2)`` (each mechanism on its own pulse), is reported beside it as a check
(``epsilon_sum_of_parts``); where all losses are small the two agree (the tests), and
docs/plasticity.md shows where they part.

The error (one number per speed, the terms added in quadrature as for the damped law): the
elastic law's error scaled with the waves; the change of the wave loss by the pulse, counted at
its full size (the ratio of two Rayleigh estimates is not judged against modal collisions); the
viscous force's share of the waves' drive (a point force's ``t^(1/2)`` front, module docs of
:mod:`~restitution.quasistatic.plastic_collision`); the product of the wave loss and the
contact's loss (the pulse is computed without the wave loss); the finite sphere's stiffer
contact on the viscous loss (:data:`restitution.laws.damped.SPHERE_SIZE_COEFFICIENT`); and, for
an inferred parameter, its spread. The error does not cover Thornton's idealisation itself
(perfect plasticity without hardening or rate dependence, the limiting pressure as one number):
it is the model's value within its stated approximations.

Where the limiting pressure comes from: a yield stress ``Y`` of each body (``p_y`` the onset
pressure of the softer body, :func:`restitution.quasistatic.plastic.onset_pressure_ratio`), the
limiting pressure itself, or one measured coefficient of restitution at one speed (then it is
the one that fixes ``p_y``; the relaxation time, if the grain damps, must be given: one
measurement fixes one parameter).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np
from scipy.optimize import brentq

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.laws.damped import SPHERE_SIZE_COEFFICIENT
from restitution.laws.mechanisms.base import mechanism_fields
from restitution.laws.mechanisms.bounds import contact_scales, half_space_of, wall_of
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw
from restitution.laws.si_point import SIPoint
from restitution.quasistatic.hertz import QuasistaticError
from restitution.quasistatic.plastic import onset_pressure_ratio, yield_speed

__all__ = [
    "PlasticLaw",
    "plastic_point",
    "pulse_contact",
    "fit_two_measurements",
    "infer_relaxation_time",
    "limiting_pressure",
    "plastic_law",
]


@dataclass(frozen=True)
class _Contact:
    """The contact of a law's collision in its reduced units: Hertz's law (``E*``, ``R``), the
    mass, the modes the pulse drives, and an elastic wall's radiation conductance."""

    law: object
    mass: float
    modes: object
    conductance: float | None = None


def pulse_contact(si: SILaw) -> _Contact:
    """The contact of ``si``'s collision (:func:`restitution.laws.mechanisms.bounds.contact_scales`)
    with the modes its pulse drives (the sphere's, or both spheres' of a pair) and an elastic
    half-space's radiation conductance."""
    from restitution.bodies.cache import get_modes
    from restitution.quasistatic.low_speed import LOW_SPEED_MODES, PAIR_LOW_SPEED_MODES

    law, mass = contact_scales(si)
    nu = float(si.law.nu)
    pair = si.law.partner
    if pair is not None:
        return _Contact(law, mass, pair.pair(nu, PAIR_LOW_SPEED_MODES, SPHERE.geometry))
    modes = get_modes(nu, LOW_SPEED_MODES, geometry=SPHERE.geometry)
    hs = half_space_of(si.law)  # contact_scales refused a plate
    if hs is None:
        return _Contact(law, mass, modes)
    from restitution.quasistatic.half_space import radiation_conductance

    return _Contact(law, mass, modes,
                    radiation_conductance(hs.density_ratio, hs.shear_speed, hs.nu))  # fmt: skip


def limiting_pressure(
    si: SILaw,
    *,
    yield_stress_pa: float | None = None,
    partner_yield_stress_pa: float | None = None,
    limiting_pressure_pa: float | None = None,
) -> tuple[float, str]:
    """:func:`_limiting_pressure`, refused at or above the Young modulus of the body it is of
    (no material yields there; the ideal strength is about E/10), and at or above the contact's
    ``E*`` (Hertz's pressure stays below about ``0.6 E*``: the contact never yields, as on a wall
    much softer than the grain), each in Pa with the options it comes from."""
    p_y, source, modulus, whose = _limiting_pressure(si, yield_stress_pa,
                                                     partner_yield_stress_pa,
                                                     limiting_pressure_pa)  # fmt: skip
    if p_y >= modulus:
        raise InputError(
            f"the limiting pressure {p_y:.3g} Pa ({source}) is at or above the Young modulus "
            f"{modulus:.3g} Pa of {whose}: no material yields there (the ideal strength is about "
            "E/10); check the units (Pa)"
        )
    law, _ = contact_scales(si)
    e_star = law.E_star * si.grain.E
    if p_y >= e_star:
        partner = " and --wall-E" if wall_of(si.law) is not None else ""
        if si.law.partner is not None and not si.law.partner.same_material:
            partner = " and --partner-E"
        raise InputError(
            f"the limiting pressure {p_y:.3g} Pa ({source}) is at or above the contact's "
            f"effective modulus E* = {e_star:.3g} Pa (of --E{partner}): Hertz's pressure stays "
            "below about 0.6 E*, so this contact never yields; leave out the plastic options "
            "(the elastic answer), or check the units (Pa)"
        )
    return p_y, source


def _moduli(si: SILaw) -> tuple[tuple[float, str], tuple[float, str] | None]:
    """``(E, whose)`` in Pa of the grain and of its partner (an elastic wall or a grain of
    another material; ``None`` for a rigid wall or one material), in the options' words."""
    grain = (float(si.grain.E), "the grain (--E)")
    wall = wall_of(si.law)
    if wall is not None:
        return grain, (wall["modulus_ratio"] * si.grain.E, "the wall (--wall-E)")
    pair = si.law.partner
    if pair is not None and not pair.same_material:
        return grain, (pair.modulus_ratio * si.grain.law_E, "the partner (--partner-E)")
    return grain, None


def _limiting_pressure(
    si: SILaw, yield_stress_pa, partner_yield_stress_pa, limiting_pressure_pa
) -> tuple[float, str, float, str]:
    """``(p_y in Pa, where it comes from, the Young modulus in Pa of the body it is of, that
    body)``: the limiting pressure given (of the softer body), or the onset pressure of the
    softer of the bodies whose yield stress is given (module docs). Identical grains share the
    grain's yield stress; a partner of another material or an elastic wall without its own
    stays elastic."""
    given = [x for x in (yield_stress_pa, partner_yield_stress_pa) if x is not None]
    grain, other = _moduli(si)
    if limiting_pressure_pa is not None:
        if given:
            raise InputError(
                "give the limiting pressure or yield stresses, not both (the limiting pressure "
                "is what the yield stresses are turned into)"
            )
        softer = min(grain, other or grain)
        return (_positive("limiting pressure", limiting_pressure_pa), "given, --limiting-pressure",
                *softer)  # fmt: skip
    if not given:
        raise InputError("a plastic law needs a yield stress or the limiting pressure")
    wall = wall_of(si.law)
    two = si.law.partner is not None and not si.law.partner.same_material
    if partner_yield_stress_pa is not None and not (two or wall is not None):
        raise InputError(
            "--partner-yield-stress is the yield stress of a partner of another material or of "
            "an elastic wall; identical grains share --yield-stress, a rigid wall never yields"
        )
    options = []
    if yield_stress_pa is not None:
        y = _positive("yield stress", yield_stress_pa)
        ratio = onset_pressure_ratio(si.grain.nu)
        options.append((ratio * y, f"onset of yield: {ratio:.4f} x the grain's yield stress "
                        f"{y:.4g} Pa, --yield-stress", *grain))  # fmt: skip
    if partner_yield_stress_pa is not None:
        y = _positive("partner's yield stress", partner_yield_stress_pa)
        nu2 = wall["nu"] if wall is not None else si.law.partner.nu2(si.grain.law_nu)
        ratio = onset_pressure_ratio(nu2)
        who = "wall's" if wall is not None else "partner's"
        options.append((ratio * y, f"onset of yield: {ratio:.4f} x the {who} yield stress "
                        f"{y:.4g} Pa, --partner-yield-stress", *other))  # fmt: skip
    return min(options)


def _positive(name: str, value, unit: str = "Pa") -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"the {name} must be a number ({unit}), got {value!r}")
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"the {name} must be a finite number > 0 ({unit}), got {value!r}")
    return value


def plastic_point(
    *,
    speed_m_s,
    v_over_c,
    epsilon,
    epsilon_err,
    status,
    note="",
    epsilon_elastic,
    epsilon_elastic_err,
    epsilon_contact,
    epsilon_sum_of_parts,
    loss_plastic,
    loss_viscous,
    loss_stored,
    loss_waves,
    loss_wall,
    yielded,
) -> SIPoint:
    """epsilon of a yielding (and possibly damping) grain at one SI speed: an
    :class:`~restitution.laws.si_point.SIPoint` with the parts below (each an attribute and a key
    of its ``to_dict``).

    Parameters
    ----------
    speed_m_s, v_over_c : float
    epsilon, epsilon_err : float or None
        All mechanisms on one pulse (module docs); the error adds the terms in quadrature (one
        standard deviation where the elastic law's is one; a bound for the counted terms).
    epsilon_elastic, epsilon_elastic_err : float or None
        The elastic law alone.
    epsilon_contact : float
        The contact alone (plastic, viscous, stored energy; no waves).
    epsilon_sum_of_parts : float or None
        The check: the three mechanisms each on its own pulse, their losses added.
    loss_plastic, loss_viscous, loss_stored, loss_waves, loss_wall : float or None
        Fractions of the kinetic energy (``loss_wall`` for an elastic wall only).
    yielded : bool
    status, note : str
    """
    parts = (
        ("epsilon_elastic", epsilon_elastic),
        ("epsilon_elastic_err", epsilon_elastic_err),
        ("epsilon_contact", epsilon_contact),
        ("epsilon_sum_of_parts", epsilon_sum_of_parts),
        ("loss_plastic", loss_plastic),
        ("loss_viscous", loss_viscous),
        ("loss_stored", loss_stored),
        ("loss_waves", loss_waves),
        ("loss_wall", loss_wall),
        ("yielded", yielded),
    )
    return SIPoint(speed_m_s, v_over_c, epsilon, epsilon_err, status, note, parts=parts)


@dataclass(frozen=True, eq=False)
class PlasticLaw:
    """epsilon(w) of a grain with plastic flow (module docs).

    Attributes
    ----------
    si : SILaw
        The elastic law of the grain against its partner.
    p_y : float
        Limiting contact pressure, Pa.
    source : str
        Where ``p_y`` comes from.
    tau, tau_err : float
        Kelvin-Voigt constant in the law's units ``tau c / R`` (0: no damping) and its error.
    p_y_err : float
        Error of an inferred ``p_y``, Pa.
    """

    mechanism: ClassVar[str] = "plastic"
    """The mechanism that answers with this law (:mod:`restitution.laws.mechanisms`)."""

    si: SILaw
    p_y: float
    source: str
    tau: float = 0.0
    tau_err: float = 0.0
    p_y_err: float = 0.0

    @property
    def reduced_p_y(self) -> float:
        """``p_y`` in the grain's ``E``."""
        return self.p_y / self.si.grain.E

    def yield_speed_m_s(self) -> float:
        """The speed ``w`` from which the contact yields, m/s."""
        law, mass = contact_scales(self.si)  # no modes needed
        return yield_speed(law.E_star, law.R, self.reduced_p_y, mass) * self.si.speed_scale_m_s

    @property
    def mechanisms(self) -> list[str]:
        """The mechanisms this law's answers contain (their names,
        :mod:`restitution.laws.mechanisms.base`)."""
        names = ["waves"]
        loss = partner_of(self.si.law).loss  # an elastic wall's radiation
        if loss is not None:
            names.append(loss)
        if self.tau > 0:
            names.append("viscous")
        return [*names, "plastic"]

    def points(self, speeds_m_s) -> tuple[SIPoint, ...]:
        """epsilon and its parts at every speed (m/s); never raises for range."""
        contact = pulse_contact(self.si)
        return tuple(self._point(p, contact) for p in self.si.points(speeds_m_s))

    def _point(self, p, contact: _Contact, p_y: float | None = None, tau: float | None = None,
               ratios: tuple[float, float, float] | None = None) -> SIPoint:  # fmt: skip
        """The point of the elastic law's point ``p`` (reduced ``p_y`` and ``tau`` as given,
        else the law's). ``ratios``: the waves' ratios (:func:`_ratios`) taken as given instead
        of computed (the root searches of an inferred parameter), and then no spread."""
        from restitution.quasistatic.plastic import ThorntonContact
        from restitution.quasistatic.plastic_collision import pulse_collision

        probing = ratios is not None
        p_y = self.reduced_p_y if p_y is None else p_y
        tau = self.tau if tau is None else tau
        v = p.v_over_c
        head = {"speed_m_s": p.speed_m_s, "v_over_c": v, "epsilon_elastic": p.epsilon,
                "epsilon_elastic_err": p.epsilon_err, "status": p.status}  # fmt: skip
        empty = {"epsilon": None, "epsilon_err": None, "epsilon_contact": None,
                 "epsilon_sum_of_parts": None, "loss_plastic": None, "loss_viscous": None,
                 "loss_stored": None, "loss_waves": None, "loss_wall": None,
                 "yielded": False}  # fmt: skip
        if p.epsilon is None:
            return plastic_point(**head, **empty, note=p.note)
        law, mass = contact.law, contact.mass
        try:
            actual = pulse_collision(law, v, p_y=p_y, tau=tau, mass=mass)
            if not probing:
                hertz = pulse_collision(law, v, mass=mass)
                ratios = _ratios(actual, hertz, contact, tau)
        except (InputError, QuasistaticError) as exc:
            return plastic_point(**{**head, "status": "outside"}, **empty, note=f"contact: {exc}")
        ratio, ratio_bare, wall_ratio = ratios
        base = 1.0 - p.epsilon**2
        base_err = 2.0 * p.epsilon * p.epsilon_err
        wall_part = None
        if contact.conductance is not None and p.loss_shares is not None:
            ball, wall = (base * share for share in p.loss_shares)  # shares of the loss
            wall_part = wall * wall_ratio
            waves = ball * ratio + wall_part
            moved = abs(ball * (ratio - 1.0)) + abs(wall * (wall_ratio - 1.0))
        else:
            waves = base * ratio
            moved = base * abs(ratio - 1.0)
        eps2 = actual.epsilon**2 - waves
        sum_of_parts = None
        if not probing:
            viscous = pulse_collision(law, v, tau=tau, mass=mass).epsilon if tau > 0 else 1.0
            th = ThorntonContact(law.E_star, law.R, p_y, mass)
            parts = base + (1.0 - viscous**2) + float(th.plastic_loss(v))
            sum_of_parts = math.sqrt(max(1.0 - parts, 0.0))
        common = {"epsilon_contact": actual.epsilon, "epsilon_sum_of_parts": sum_of_parts,
                  "loss_plastic": actual.plastic_work, "loss_viscous": actual.viscous_work,
                  "loss_stored": actual.stored_energy, "loss_waves": waves,
                  "loss_wall": wall_part, "yielded": actual.yielded}  # fmt: skip
        if not eps2 > 0.0 and waves > 1.0:
            # The waves' Rayleigh estimate, scaled from Hertz's pulse, above the impact energy
            # itself (3.9e3 times it for tau c/R = 5e3): the one-pulse model, the waves a small
            # loss on the contact's pulse, does not hold; their number is not served.
            parts = (("plastic flow", actual.plastic_work), ("viscosity", actual.viscous_work),
                     ("the contact's stored energy", actual.stored_energy))  # fmt: skip
            shares = ", ".join(f"{name} {100 * x:.3g} %" for name, x in parts if x)
            note = (f"no rebound: the contact alone returns epsilon = {actual.epsilon:.3g} "
                    f"({shares}), and the waves' estimate on its pulse, {waves:.3g} times the "
                    f"impact energy ({ratio:.3g} times their loss on Hertz's pulse), is beyond "
                    "the one-pulse model, which takes them as a small loss; a relaxation time "
                    f"this long (tau c/R = {tau / law.R:.3g}) is hardly a solid's")  # fmt: skip
            return plastic_point(**{**head, "status": "outside"}, epsilon=None, epsilon_err=None,
                                **{**common, "loss_waves": None}, note=note)  # fmt: skip
        if not eps2 > 0.0:
            parts = (
                ("plastic flow", actual.plastic_work),
                ("viscosity", actual.viscous_work),
                ("the contact's stored energy", actual.stored_energy),
                ("waves", waves),
            )
            shares = ", ".join(f"{name} {100 * x:.3g} %" for name, x in parts if x)
            note = (f"no rebound: the losses exceed the impact energy ({shares}: "
                    f"{100 * (1.0 - eps2):.3g} % of it); the grain stays on its partner "
                    "(epsilon 0)")  # fmt: skip
            return plastic_point(**{**head, "status": "outside"}, epsilon=None, epsilon_err=None,
                                **common, note=note)  # fmt: skip
        eps = math.sqrt(eps2)
        terms = [ratio * base_err, moved, base * abs(ratio - ratio_bare),
                 waves * (1.0 - actual.epsilon**2),
                 actual.viscous_work * SPHERE_SIZE_COEFFICIENT
                 * math.sqrt(actual.max_compression / law.R)]  # fmt: skip
        err = math.sqrt(sum(t * t for t in terms)) / (2.0 * eps)
        if not probing:
            err = math.hypot(err, self._spread(contact, v))
        return plastic_point(**head, epsilon=eps, epsilon_err=err, **common, note=p.note)

    def _spread(self, contact: _Contact, v: float) -> float:
        """How far the contact's epsilon moves over an inferred parameter's error (half the
        difference of its two ends), 0 for given parameters."""
        from restitution.quasistatic.plastic_collision import pulse_collision

        law, mass = contact.law, contact.mass
        ends = []
        if self.p_y_err > 0:
            for s in (-1.0, 1.0):
                p_y = max(self.p_y + s * self.p_y_err, 1e-6 * self.p_y) / self.si.grain.E
                ends.append(pulse_collision(law, v, p_y=p_y, tau=self.tau, mass=mass).epsilon)
        if self.tau_err > 0:
            for s in (-1.0, 1.0):
                tau = max(self.tau + s * self.tau_err, 0.0)
                ends.append(pulse_collision(law, v, p_y=self.reduced_p_y, tau=tau,
                                            mass=mass).epsilon)  # fmt: skip
        return 0.5 * (max(ends) - min(ends)) if ends else 0.0

    def to_dict(self, speeds_m_s, points=None) -> dict:
        """JSON of ``restitution law`` with plastic flow: the elastic law's, with the contact's
        parameters and, per point, every part beside epsilon (``points``: these, computed
        before, instead of computing them again)."""
        d = self.si.to_dict(speeds_m_s)
        d["plasticity"] = {
            "model": "Thornton's elastic-perfectly-plastic sphere (J. Appl. Mech. 64, 383 "
            "(1997)) with Kelvin-Voigt damping, on one force pulse; elastic waves on that pulse "
            "(docs/plasticity.md)",
            "limiting_pressure_pa": self.p_y,
            "limiting_pressure_err_pa": self.p_y_err,
            "limiting_pressure_source": self.source,
            "yield_speed_m_s": self.yield_speed_m_s(),
            "tau_c_over_R": self.tau,
            "tau_c_over_R_err": self.tau_err,
            "error_covers": "the elastic law's error, the wave loss's change by the pulse, the "
            "viscous drive of the waves, the coupling of wave and contact losses, the finite "
            "sphere's viscous excess and an inferred parameter's spread; not Thornton's "
            "idealisation (no hardening, no rate dependence)",
        }
        d.update(mechanism_fields(self.mechanisms))
        d.pop("plastic_flow_expected_from_m_s", None)
        points = self.points(speeds_m_s) if points is None else points
        d["points"] = [p.to_dict() for p in points]
        return d


def _ratios(actual, hertz, contact: _Contact, tau: float) -> tuple[float, float, float]:
    """How much more the ``actual`` pulse drives the waves than Hertz's at the same speed:
    ``(modes, modes without the viscous force, wall radiation)``, ratios of the Rayleigh sums
    of ``contact.modes`` and of ``int (dF_ep/dt)^2 dt``."""
    on_hertz = float(hertz.mode_energy(contact.modes).sum())
    if tau > 0:
        with_viscous, bare = actual.mode_energy(contact.modes, viscous="both").sum(axis=0)
        ratio, ratio_bare = float(with_viscous) / on_hertz, float(bare) / on_hertz
    else:
        ratio = ratio_bare = float(actual.mode_energy(contact.modes).sum()) / on_hertz
    return ratio, ratio_bare, actual.force_rate_integral / hertz.force_rate_integral


_RANGES = {"p_y": (1e-7, 0.9), "tau": (1e-9, 1e3)}
"""Where the root searches of an inferred parameter look: ``p_y`` in the contact's ``E*`` (at
``0.9 E*`` the yield speed is above any speed a law serves, about ``c``), ``tau`` in ``R / c``."""


def _range(which: str, contact: _Contact) -> tuple[float, float]:
    """:data:`_RANGES` of ``which`` in reduced units (``p_y`` scaled with the contact's ``E*``)."""
    lo, hi = _RANGES[which]
    scale = contact.law.E_star if which == "p_y" else 1.0
    return lo * scale, hi * scale


def _infer(law: PlasticLaw, eps_m: float, speed: float, which: str) -> tuple[float, float]:
    """``(value, error)`` in reduced units of the parameter ``which`` (``"p_y"`` or ``"tau"``)
    for which ``law`` gives ``eps_m`` at ``speed`` (m/s), the other parameter as ``law`` has it;
    the error from the elastic law's error there (half the spread of its two ends)."""
    si = law.si
    (p,) = si.points([speed])
    if p.epsilon is None:
        raise InputError(
            f"the elastic law has no value at the measured speed {speed:g} m/s ({p.note}); "
            "measure at a speed the law serves"
        )
    contact = pulse_contact(si)
    E = si.grain.E
    lo, hi = (math.log(x) for x in _range(which, contact))
    # The end of the range where epsilon is largest: no plastic flow, no damping.
    weakest = hi if which == "p_y" else lo

    ratios = (1.0, 1.0, 1.0)

    def at(q, log_x: float) -> float:
        kw = {"p_y": math.exp(log_x)} if which == "p_y" else {"tau": math.exp(log_x)}
        got = law._point(q, contact, ratios=ratios, **kw).epsilon
        return 0.0 if got is None else got

    def solve(shift: float) -> float:
        q = replace(p, epsilon=min(p.epsilon + shift, 1.0))
        top = at(q, weakest)
        if eps_m >= top:
            raise InputError(_unexplained(law, which, eps_m, speed, top, q.epsilon))
        strongest = lo if which == "p_y" else hi
        if at(q, strongest) > eps_m:
            reach = at(q, strongest)
            if which == "p_y":
                end = f"the lowest limiting pressure searched, {math.exp(strongest) * E:.3g} Pa"
            else:
                end = (
                    f"the longest relaxation time searched, {math.exp(strongest):.3g} R/c "
                    f"({math.exp(strongest) * 1e-3 / si.grain.c_m_s:.3g} s for a grain of 1 mm "
                    "radius)"
                )
            raise InputError(
                f"the measured epsilon {eps_m:.6g} at {speed:g} m/s is below {reach:.6g}, what "
                f"the model gives with {end}; check the measurement"
            )
        return math.exp(brentq(lambda x: at(q, x) - eps_m, lo, hi, xtol=1e-10, rtol=1e-8))

    # Two rounds: the waves' ratios frozen at 1 (the waves are small), then at the first
    # root's, where the root moves by the ratios' change over it (second order).
    value = solve(0.0)
    kw = {which: value}
    v = p.v_over_c
    from restitution.quasistatic.plastic_collision import pulse_collision

    pulse = pulse_collision(contact.law, v, mass=contact.mass,
                            **{"p_y": law.reduced_p_y, "tau": law.tau, **kw})  # fmt: skip
    ratios = _ratios(pulse, pulse_collision(contact.law, v, mass=contact.mass), contact,
                     kw.get("tau", law.tau))  # fmt: skip
    value = solve(0.0)
    ends = [solve(s * p.epsilon_err) for s in (-1.0, 1.0)]
    return value, 0.5 * abs(ends[1] - ends[0])


def _unexplained(law: PlasticLaw, which: str, eps_m: float, speed: float, top: float,
                 elastic: float) -> str:  # fmt: skip
    """The refusal of a measurement ``eps_m`` at ``speed`` (m/s) not below ``top``, the value
    with the parameter ``which`` (``"p_y"`` or ``"tau"``) at its weakest and the other one as
    ``law`` has it: it blames that other parameter where it alone takes the value below the
    elastic one (``elastic``), the measurement otherwise."""
    head = f"the measured epsilon {eps_m:.6g} at {speed:g} m/s is not below {top:.6g}"
    fixed, lowers = ("limiting pressure", "plastic flow") if which == "p_y" else (
        "relaxation time", "damping")  # fmt: skip
    given = law.tau > 0 if which == "p_y" else True
    if not (given and eps_m < elastic):
        return (
            f"{head}, the value there without {lowers}: no {lowers} explains it; check the "
            "measurement"
        )
    if which == "p_y":
        other, short = "the damping given (--relaxation-time, with --radius)", "the damping"
        way = "check --relaxation-time, or let the measurement fix the relaxation time instead"
    else:
        other = f"the plastic flow given (p_y = {law.p_y:.4g} Pa: {law.source})"
        short = "the plastic flow"
        way = (
            "check the yield stress or limiting pressure given, or let the measurement fix the "
            "limiting pressure instead (--measured-fixes limiting-pressure, without the yield "
            "stresses and --limiting-pressure)"
        )
    what = "no rebound" if top <= 0.0 else "the value"
    return (
        f"{head}, {what} there with {other} and no {lowers} (the elastic value is "
        f"{elastic:.6g}): {lowers} only lowers epsilon, so no {fixed} explains the measurement, "
        f"and {short} given loses too much for it; {way}"
    )


def plastic_law(
    si: SILaw,
    *,
    yield_stress_pa: float | None = None,
    partner_yield_stress_pa: float | None = None,
    limiting_pressure_pa: float | None = None,
    tau: float = 0.0,
    tau_err: float = 0.0,
    measured_epsilon: float | None = None,
    measured_speed_m_s: float | None = None,
) -> PlasticLaw:
    """The law of ``si``'s grain with plastic flow.

    Parameters
    ----------
    si : SILaw
        The elastic law (a sphere's: on a rigid wall or a half-space, or two spheres).
    yield_stress_pa, partner_yield_stress_pa, limiting_pressure_pa : float, optional
        The yield stress of the grain and of a partner of another material or of an elastic
        wall, or the limiting pressure itself (:func:`limiting_pressure`).
    tau, tau_err : float
        Kelvin-Voigt constant ``tau c / R`` and its error (0: elastic material).
    measured_epsilon, measured_speed_m_s : float, optional
        Instead of a yield stress: one measured coefficient of restitution at one speed fixes
        the limiting pressure.

    Examples
    --------
    >>> from restitution.laws.si_law import si_law
    >>> steel = si_law(210e9, 0.3, 7850, "sphere", "wall")
    >>> law = plastic_law(steel, yield_stress_pa=1e9)
    >>> round(law.yield_speed_m_s(), 4)
    0.0345
    """
    if not isinstance(si, SILaw):
        raise InputError(f"si must be an SILaw (see si_law), got {type(si).__name__}")
    pulse_contact(si)  # refuses disks and plates first
    measured = (measured_epsilon, measured_speed_m_s) != (None, None)
    if measured:
        if None in (measured_epsilon, measured_speed_m_s):
            raise InputError("a measurement needs both the epsilon and the speed")
        if (yield_stress_pa, partner_yield_stress_pa, limiting_pressure_pa) != (None,) * 3:
            raise InputError(
                "one measurement fixes one parameter: give the yield stress or let the "
                "measurement fix the limiting pressure, not both"
            )
        eps_m = float(measured_epsilon)
        if not 0.0 < eps_m < 1.0:
            raise InputError(f"the measured epsilon must lie in (0, 1), got {eps_m!r}")
        speed = _positive("measured speed", measured_speed_m_s, "m/s")
        probe = PlasticLaw(si, si.grain.E, "probe", tau)
        p_y, p_err = _infer(probe, eps_m, speed, "p_y")
        E = si.grain.E
        return PlasticLaw(si, p_y * E, f"inferred from epsilon = {eps_m:g} at {speed:g} m/s",
                          tau, tau_err, p_err * E)  # fmt: skip
    p_y, source = limiting_pressure(
        si,
        yield_stress_pa=yield_stress_pa,
        partner_yield_stress_pa=partner_yield_stress_pa,
        limiting_pressure_pa=limiting_pressure_pa,
    )
    return PlasticLaw(si, p_y, source, tau, tau_err)


def infer_relaxation_time(law: PlasticLaw, eps_m: float, speed_m_s: float) -> PlasticLaw:
    """``law`` with the relaxation time (``tau c / R``) for which it gives ``eps_m`` at
    ``speed_m_s`` (m/s), and its error: the damping inferred with the plastic flow on the same
    pulse (the measurement fixes the relaxation time; the limiting pressure is ``law``'s)."""
    eps_m = float(eps_m)
    if not 0.0 < eps_m < 1.0:
        raise InputError(f"the measured epsilon must lie in (0, 1), got {eps_m!r}")
    speed = _positive("measured speed", speed_m_s, "m/s")
    tau, tau_err = _infer(replace(law, tau=0.0, tau_err=0.0), eps_m, speed, "tau")
    return replace(law, tau=tau, tau_err=tau_err)


def _measured_point(si: SILaw, speed: float):
    """The elastic law's point at a measured ``speed`` (m/s); refused without a value."""
    (p,) = si.points([speed])
    if p.epsilon is None:
        raise InputError(
            f"the elastic law has no value at the measured speed {speed:g} m/s ({p.note}); "
            "measure at a speed the law serves"
        )
    return p


def fit_two_measurements(si: SILaw, first, second) -> PlasticLaw:
    """The law whose relaxation time and limiting pressure give both measured coefficients
    ``first = (epsilon, speed_m_s)`` and ``second``: two measurements fix two parameters.

    The limiting pressure is solved from the faster measurement for each relaxation time, and
    the relaxation time so that the slower one holds too (nested root searches on the contact,
    the waves' ratios frozen, then refined once at the root, as for one measurement). The errors
    carry each measured point's elastic-law error through the two equations' Jacobian.
    Refused when no pair of values fits both, or when the two measurements do not fix both
    (their Jacobian is singular: both below the yield speed, or the same speed).
    """
    from restitution.quasistatic.plastic_collision import pulse_collision

    (e_s, w_s), (e_f, w_f) = sorted(
        ((float(e), _positive("measured speed", w, "m/s")) for e, w in (first, second)),
        key=lambda m: m[1],
    )
    for e in (e_s, e_f):
        if not 0.0 < e < 1.0:
            raise InputError(f"a measured epsilon must lie in (0, 1), got {e!r}")
    if w_f <= w_s * (1.0 + 1e-9):
        raise InputError(
            "two measurements at one speed cannot fix two parameters: measure at two speeds"
        )
    slow, fast = _measured_point(si, w_s), _measured_point(si, w_f)
    contact = pulse_contact(si)
    probe = PlasticLaw(si, si.grain.E, "probe")
    ratios = {id(slow): (1.0, 1.0, 1.0), id(fast): (1.0, 1.0, 1.0)}
    (p_lo, p_hi), (t_lo, t_hi) = _range("p_y", contact), _range("tau", contact)

    def eps(point, tau: float, p_y: float) -> float:
        got = probe._point(point, contact, p_y=p_y, tau=tau, ratios=ratios[id(point)]).epsilon
        return 0.0 if got is None else got

    def p_y_of(tau: float) -> float | None:
        """The limiting pressure that gives the faster measurement with ``tau``; ``None`` where
        the damping alone already loses more."""
        if eps(fast, tau, p_hi) <= e_f:
            return None
        if eps(fast, tau, p_lo) >= e_f:
            raise InputError(
                f"the measured epsilon {e_f:.6g} at {w_f:g} m/s is below what any limiting "
                "pressure gives: check the measurement"
            )
        return math.exp(brentq(lambda x: eps(fast, tau, math.exp(x)) - e_f, math.log(p_lo),
                               math.log(p_hi), xtol=1e-9, rtol=1e-7))  # fmt: skip

    def gap(log_tau: float) -> float:
        p_y = p_y_of(math.exp(log_tau))
        return (eps(slow, math.exp(log_tau), p_hi if p_y is None else p_y)) - e_s

    def solve() -> tuple[float, float]:
        if eps(fast, t_lo, p_hi) <= e_f:
            raise InputError(
                f"the measured epsilon {e_f:.6g} at {w_f:g} m/s is not below the elastic value "
                "there: neither damping nor plastic flow explains it; check the measurement"
            )
        # The largest relaxation time: where the damping alone gives the faster measurement.
        top = math.log(t_hi)
        if eps(fast, t_hi, p_hi) < e_f:
            top = brentq(lambda x: eps(fast, math.exp(x), p_hi) - e_f, math.log(t_lo), top,
                         xtol=1e-9, rtol=1e-7)  # fmt: skip
        lo, hi = math.log(t_lo), top - 1e-7
        g_lo, g_hi = gap(lo), gap(hi)
        if g_lo * g_hi > 0:
            raise InputError(
                f"no relaxation time and limiting pressure give both measurements: with the "
                f"faster one ({e_f:g} at {w_f:g} m/s) fitted, the slower one ({w_s:g} m/s) lies "
                f"between {min(g_lo, g_hi) + e_s:.6g} and {max(g_lo, g_hi) + e_s:.6g}, not "
                f"{e_s:g}; check the measurements or fit one parameter (--measured-fixes)"
            )
        tau = math.exp(brentq(gap, lo, hi, xtol=1e-9, rtol=1e-7))
        return tau, p_y_of(tau)

    tau, p_y = solve()
    for point in (slow, fast):  # the waves' ratios at the first root, then once more
        v = point.v_over_c
        pulse = pulse_collision(contact.law, v, p_y=p_y, tau=tau, mass=contact.mass)
        hertz = pulse_collision(contact.law, v, mass=contact.mass)
        ratios[id(point)] = _ratios(pulse, hertz, contact, tau)
    tau, p_y = solve()
    # Errors: each point's elastic error through the Jacobian in (ln tau, ln p_y).
    h = 1e-4
    base = np.array([eps(slow, tau, p_y), eps(fast, tau, p_y)])
    jac = np.empty((2, 2))
    for j, (dt, dp) in enumerate(((math.exp(h), 1.0), (1.0, math.exp(h)))):
        jac[:, j] = (np.array([eps(slow, tau * dt, p_y * dp), eps(fast, tau * dt, p_y * dp)])
                     - base) / h  # fmt: skip
    if not np.isfinite(np.linalg.cond(jac)) or np.linalg.cond(jac) > 1e8:
        raise InputError(
            "the two measurements do not fix both parameters (is the slower one below the yield "
            "speed and the faster one dominated by one loss?); give one parameter instead"
        )
    shifts = []
    for i, point in enumerate((slow, fast)):
        moved = replace(point, epsilon=min(point.epsilon + point.epsilon_err, 1.0))
        ratios[id(moved)] = ratios[id(point)]
        delta = np.zeros(2)
        delta[i] = eps(moved, tau, p_y) - base[i]
        shifts.append(np.linalg.solve(jac, -delta))
    err_log = np.sqrt(np.sum(np.square(shifts), axis=0))
    E = si.grain.E
    return PlasticLaw(
        si,
        p_y * E,
        f"inferred with the relaxation time from epsilon = {e_s:g} at {w_s:g} m/s and {e_f:g} "
        f"at {w_f:g} m/s",
        tau,
        tau * float(err_log[0]),
        p_y * E * float(err_log[1]),
    )
