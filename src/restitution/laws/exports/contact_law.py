"""The LAMMPS plugin's law per contact: epsilon of a contact from its own radii, masses, modulus
and impact speed, so that grains of any sizes get the package's law (docs/lammps-plugin.md,
"A law per contact").

Units: SI throughout (m, kg, Pa, s, m/s).

The package adds the losses of kinetic energy of its mechanisms (:mod:`restitution.laws.damped`)::

    1 - epsilon^2 = L_el + L_v,

* ``L_el``, the elastic waves: two spheres ``(mu / m1) G1(x1) + (mu / m2) G2(x2)``, each sphere's
  own curve of its contact time over its transit time ``x_i = t_c c_i / R_i``
  (:mod:`~restitution.laws.exports.sphere_loss`: the pair's low-speed route, which serves the
  shipped pairs and computes the others); a sphere on the rigid wall the wall's law ``epsilon(w)``
  (any radius: the law has no scale), the plugin's table of the wall;
* ``L_v = 1 - epsilon_v(q)^2``, the viscous loss of a Kelvin-Voigt material, a function of the
  group ``q = (3/2) tau (K / mu)^(2/5) w^(1/5)`` of the contact
  (:mod:`~restitution.laws.exports.viscous_map`), 0 for an elastic material.

With plastic flow (a limiting pressure ``p_y``, the package's plastic law
:mod:`restitution.laws.plastic`: Thornton's force and the waves on one pulse) the contact has the
yield speed ``v_y`` of its own ``E*, R*, m*`` and ``p_y``
(:func:`~restitution.laws.exports.plastic_waves.yield_speed`), and with ``u = w / v_y``::

    epsilon^2 = epsilon_T(u)^2 - sum_i L_i r_i(x_i, u),

``epsilon_T`` Thornton's closed form (:func:`restitution.quasistatic.plastic.thornton_epsilon`,
1 for ``u <= 1``), ``L_i`` each sphere's elastic loss above (the wall's: its law's) and ``r_i``
how much more the plastic pulse drives that sphere's modes than Hertz's
(:mod:`~restitution.laws.exports.plastic_waves`; 1 for ``u <= 1``). Not with damping: the
package's pulse then carries both forces, a function of ``(u, q)`` that is not tabulated here.

:class:`PairContactLaw` and :class:`WallContactLaw` evaluate what the plugin's C++ evaluates
(``contact_law.cpp``), in the same order of operations; :mod:`~restitution.laws.exports.
contact_file` writes them for it. A contact outside what the package answers (the route's reach,
a loss above all the energy, a viscous group beyond the map) gets no epsilon and a note, as the
plugin stops the run there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.bodies.sphere.surface import CONTACT_TIME_CONSTANT
from restitution.errors import InputError, real
from restitution.laws.exports.lammps_plugin import TSUJI_EPSILON_MIN, tsuji_map
from restitution.laws.exports.pchip import PchipTable, TableStatus, pchip_table
from restitution.laws.exports.plastic_waves import PlasticWaves, plastic_waves, yield_speed
from restitution.laws.exports.sphere_loss import SphereLoss, sphere_loss
from restitution.laws.exports.viscous_map import ViscousMap, viscous_group, viscous_map
from restitution.laws.units import Grain
from restitution.status import Status

__all__ = [
    "ContactAnswer",
    "PairContactLaw",
    "PlasticFlow",
    "WallContactLaw",
    "pair_contact_law",
    "wall_contact_law",
]


@dataclass(frozen=True)
class ContactAnswer:
    """epsilon of one contact and its parts.

    Attributes
    ----------
    epsilon : float or None
        The coefficient of restitution; ``None`` where the contact is outside the law (then the
        plugin stops the run with :attr:`note`).
    elastic_loss, viscous_loss : float
        ``L_el`` and ``L_v`` (fractions of the contact's kinetic energy); NaN where not reached.
        With plastic flow ``L_el`` is the waves on the plastic pulse.
    status : Status
        ``OK`` or ``OUTSIDE``.
    note : str
        Why there is no epsilon, and what to do; empty when there is one.
    epsilon_contact : float
        Thornton's epsilon of the contact alone (1 without plastic flow or below its yield
        speed).
    speed_over_yield : float
        ``u = w / v_y`` (0 without plastic flow).
    """

    epsilon: float | None
    elastic_loss: float
    viscous_loss: float
    status: Status = Status.OK
    note: str = ""
    epsilon_contact: float = 1.0
    speed_over_yield: float = 0.0

    @property
    def beta(self) -> float | None:
        """Tsuji's damping coefficient the plugin keeps for the contact
        (:func:`~restitution.laws.exports.lammps_plugin.tsuji_map`)."""
        return None if self.epsilon is None else float(tsuji_map()(self.epsilon))


def _outside(note: str, elastic=math.nan, viscous=math.nan) -> ContactAnswer:
    return ContactAnswer(None, elastic, viscous, Status.OUTSIDE, note)


def _sum(elastic: float, viscous: float, what: str, contact: float = 1.0,
         u: float = 0.0) -> ContactAnswer:  # fmt: skip
    """epsilon of the losses added to the contact's (the package's sum; ``contact``: Thornton's
    epsilon), or the refusal below the map."""
    square = contact * contact - elastic - viscous
    if not square >= TSUJI_EPSILON_MIN**2:
        plastic = "" if contact == 1.0 else f" with the plastic flow's (epsilon {contact:.4g})"
        return ContactAnswer(None, elastic, viscous, Status.OUTSIDE,
                             f"{what}: the losses to vibrations ({elastic:.3g}) and viscosity "
                             f"({viscous:.3g}){plastic} leave epsilon below {TSUJI_EPSILON_MIN} "
                             "(the plugin's least)", contact, u)  # fmt: skip
    return ContactAnswer(math.sqrt(square), elastic, viscous, Status.OK, "", contact, u)


@dataclass(frozen=True)
class PlasticFlow:
    """The plastic flow of a law per contact (module docs).

    Attributes
    ----------
    limiting_pressure_pa : float
        Thornton's limiting pressure ``p_y``, Pa.
    source : str
        Where it comes from (:func:`restitution.laws.plastic.limiting_pressure`).
    waves : PlasticWaves
        The wave ratio ``r(x, u)`` of the material.
    """

    limiting_pressure_pa: float
    source: str
    waves: PlasticWaves

    def speed_over_yield(self, w, estar, rstar, mstar) -> float:
        """``u = w / v_y`` of a contact (SI)."""
        return w / yield_speed(self.limiting_pressure_pa, estar, rstar, mstar)

    def ratio(self, x: float, u: float, what: str, radius: float) -> float:
        """``r(x, u)``; raises :class:`_Outside` beyond the table."""
        r = self.waves(x, u)
        if math.isnan(r):
            w = self.waves
            if u > w.u_top:
                raise _Outside(
                    f"{what}: the impact speed is {u:.6g} times the contact's yield speed, beyond "
                    f"the {w.u_top:.6g} to which the table of the plastic pulse's waves reaches; "
                    "no epsilon is extrapolated"
                )
            if x < w.x[0]:
                raise _Outside(
                    f"{what}: the contact time is {x:.4g} transit times of the grain of radius "
                    f"{radius:.6g} m, below the {w.x[0]:.4g} from which the package's estimate "
                    "of its vibrations holds (the low-speed route's reach); no epsilon is "
                    "extrapolated"
                )
            raise _Outside(
                f"{what}: the contact time is {x:.4g} transit times of the grain of radius "
                f"{radius:.6g} m, beyond the {w.x[-1]:.4g} to which the table of the plastic "
                "pulse's waves reaches (a yielding contact this slow against the grain's modes: "
                "a limiting pressure far below this one's material); no epsilon is extrapolated"
            )
        return r


class _Outside(Exception):
    """A contact outside the plastic table (its message is the note)."""


def _thornton(u: float) -> float:
    """Thornton's epsilon at ``u`` (:func:`restitution.quasistatic.plastic.thornton_epsilon`),
    in the C++'s order of operations."""
    if u <= 1.0:
        return 1.0
    s = u * u
    x = (1.0 + math.sqrt((24.0 * s - 4.0) / 5.0)) / 3.0
    return (3.0 * x - 1.0) / (2.0 * math.sqrt(s) * x**0.25)


def _viscous_loss(vmap: ViscousMap, tau: float, estar, rstar, mstar, w) -> float:
    """``L_v`` of a contact; NaN above the map."""
    if tau == 0.0:
        return 0.0
    eps = float(vmap(viscous_group(tau, estar, rstar, mstar, w))[0])
    return 1.0 - eps * eps


@dataclass(frozen=True)
class PairContactLaw:
    """epsilon of two spheres of any radii (module docs).

    Attributes
    ----------
    grains : tuple of Grain
        The first type's material and the second's (the same twice for one material).
    relaxation_time_s : float
        The Kelvin-Voigt relaxation time of both, s (0: elastic grains).
    losses : tuple of SphereLoss
        Each material's curve ``G`` (:func:`~restitution.laws.exports.sphere_loss.sphere_loss`).
    viscous : ViscousMap
        ``epsilon_v(q)``.
    plastic : PlasticFlow or None
        The plastic flow of the grains (one material), or none.
    """

    grains: tuple[Grain, Grain]
    relaxation_time_s: float
    losses: tuple[SphereLoss, SphereLoss]
    viscous: ViscousMap
    plastic: PlasticFlow | None = None

    def __call__(self, w, r1, m1, r2, m2, estar) -> ContactAnswer:
        """The contact of grain 1 (radius ``r1`` m, mass ``m1`` kg, of the first material) and
        grain 2 at relative normal speed ``w`` (m/s), contact modulus ``estar`` (Pa)."""
        if w == 0.0:
            return ContactAnswer(1.0, 0.0, 0.0)
        if not (math.isfinite(w) and w > 0.0):
            return _outside(f"impact speed {w} m/s is not a finite number >= 0")
        rstar = r1 * r2 / (r1 + r2)
        mstar = m1 * m2 / (m1 + m2)
        k = 4.0 / 3.0 * estar * math.sqrt(rstar)
        dmax = (1.25 * mstar * w * w / k) ** 0.4
        width = math.sqrt(rstar * dmax) / min(r1, r2)
        top = min(self.losses[0].width_max, self.losses[1].width_max)
        what = f"impact at {w:.8g} m/s of radii {r1:.6g} and {r2:.6g} m"
        if width > top:
            return _outside(
                f"{what}: its contact radius is {width:.4g} of the smaller radius, beyond the "
                f"{top:.4g} to which the package's estimate of the elastic waves reaches (the "
                "low-speed route's reach); no epsilon is extrapolated"
            )
        tc = CONTACT_TIME_CONSTANT * dmax / w  # Hertz's (sphere_loss.contact_time)
        u = 0.0 if self.plastic is None else self.plastic.speed_over_yield(w, estar, rstar, mstar)
        elastic = 0.0
        for grain, loss, r, m in zip(self.grains, self.losses, (r1, r2), (m1, m2), strict=True):
            x = tc * grain.c_m_s / r
            if x < loss.x_lo:
                return _outside(
                    f"{what}: the contact time is {x:.4g} transit times of the grain of radius "
                    f"{r:.6g} m, below the {loss.x_lo:.4g} from which the package's estimate of "
                    "its vibrations holds (its lowest mode is too slow against the contact: the "
                    "low-speed route's reach); no epsilon is extrapolated"
                )
            part = mstar / m * float(loss(x)[0])
            if u > 1.0:
                try:
                    part *= self.plastic.ratio(x, u, what, r)
                except _Outside as exc:
                    return _outside(str(exc))
            elastic += part
        viscous = _viscous_loss(self.viscous, self.relaxation_time_s, estar, rstar, mstar, w)
        if math.isnan(viscous):
            return _outside(f"{what}: the viscous loss alone leaves epsilon below 0.008", elastic)
        return _sum(elastic, viscous, what, _thornton(u), u)

    def epsilon(self, w, r1, m1, r2, m2, estar) -> float:
        """:meth:`__call__`'s epsilon; NaN outside."""
        e = self(w, r1, m1, r2, m2, estar).epsilon
        return math.nan if e is None else e


@dataclass(frozen=True)
class WallContactLaw:
    """epsilon of a sphere of any radius on the rigid wall (module docs).

    Attributes
    ----------
    grain : Grain
        The material.
    relaxation_time_s : float
        Its Kelvin-Voigt relaxation time, s (0: elastic).
    wall : PchipTable
        Its elastic law on the wall (the plugin's table of it).
    viscous : ViscousMap
        ``epsilon_v(q)``.
    plastic : PlasticFlow or None
        The grain's plastic flow, or none.
    """

    grain: Grain
    relaxation_time_s: float
    wall: PchipTable
    viscous: ViscousMap
    plastic: PlasticFlow | None = None

    def __call__(self, w, r, m, estar) -> ContactAnswer:
        """The contact of a grain of radius ``r`` (m) and mass ``m`` (kg) hitting the wall at
        ``w`` (m/s), contact modulus ``estar`` (Pa)."""
        what = f"impact at {w:.8g} m/s of radius {r:.6g} m on the wall"
        status = self.wall.status(w)
        if status not in (TableStatus.INSIDE, TableStatus.BELOW):
            lo, hi = self.wall.range_m_s
            return _outside(
                f"{what}: above the range {lo:.8g} ... {hi:.8g} m/s of the elastic wall law; no "
                "epsilon is extrapolated"
                if status == TableStatus.ABOVE
                else f"impact speed {w} m/s is not a finite number >= 0"
            )
        eps_el = float(self.wall(w))
        elastic = 1.0 - eps_el * eps_el
        u = 0.0 if self.plastic is None else self.plastic.speed_over_yield(w, estar, r, m)
        if u > 1.0:
            k = 4.0 / 3.0 * estar * math.sqrt(r)
            dmax = (1.25 * m * w * w / k) ** 0.4
            x = CONTACT_TIME_CONSTANT * dmax / w * self.grain.c_m_s / r
            try:
                elastic *= self.plastic.ratio(x, u, what, r)
            except _Outside as exc:
                return _outside(str(exc))
        viscous = _viscous_loss(self.viscous, self.relaxation_time_s, estar, r, m, w)
        if math.isnan(viscous):
            return _outside(f"{what}: the viscous loss alone leaves epsilon below 0.008", elastic)
        return _sum(elastic, viscous, what, _thornton(u), u)

    def epsilon(self, w, r, m, estar) -> float:
        """:meth:`__call__`'s epsilon; NaN outside."""
        e = self(w, r, m, estar).epsilon
        return math.nan if e is None else e


def _sphere(grain, what: str) -> Grain:
    if not isinstance(grain, Grain):
        raise InputError(f"{what} must be a Grain (restitution.Grain), got {type(grain).__name__}")
    if grain.kind is not SPHERE:
        raise InputError(
            f"{what}: the law per contact is derived for spheres (Hertz's contact and a sphere's "
            f"modes), not for a {grain.shape}; use the plugin's table per type pair"
        )
    return grain


def _relaxation(tau) -> float:
    tau = real(tau, "relaxation_time_s", ">= 0 (s)")
    if not (math.isfinite(tau) and tau >= 0.0):
        raise InputError(f"relaxation_time_s must be a finite number >= 0 (s), got {tau!r}")
    return tau


def _plastic(grain: Grain, tau: float, yield_stress_pa, limiting_pressure_pa, two: bool):
    """The :class:`PlasticFlow` of ``grain`` from a yield stress or the limiting pressure (Pa),
    or ``None`` when neither is given."""
    from restitution.quasistatic.plastic import onset_pressure_ratio

    if yield_stress_pa is None and limiting_pressure_pa is None:
        return None
    if yield_stress_pa is not None and limiting_pressure_pa is not None:
        raise InputError(
            "give the yield stress or the limiting pressure, not both (the limiting pressure is "
            "what the yield stress is turned into)"
        )
    if two:
        raise InputError(
            "plastic flow in the law per contact is done for one material (both grains yield at "
            "the same pressure); for two materials use a table per type pair from the package's "
            "plastic law of that pair"
        )
    if tau > 0.0:
        raise InputError(
            "plastic flow with damping is not in the law per contact: the package puts "
            "Thornton's and the viscous force on one pulse, a function of u = w / v_y and the "
            "viscous group q not tabulated here; give relaxation_time_s = 0, or use a table per "
            "type pair from the package's plastic law with its relaxation time"
        )
    if yield_stress_pa is not None:
        y = real(yield_stress_pa, "yield_stress_pa", "> 0 (Pa)")
        if not (math.isfinite(y) and y > 0.0):
            raise InputError(f"yield_stress_pa must be a finite number > 0 (Pa), got {y!r}")
        ratio = onset_pressure_ratio(grain.nu)
        p_y = ratio * y
        source = f"onset of yield: {ratio:.4f} x the grain's yield stress {y:.4g} Pa"
    else:
        p_y = real(limiting_pressure_pa, "limiting_pressure_pa", "> 0 (Pa)")
        if not (math.isfinite(p_y) and p_y > 0.0):
            raise InputError(f"limiting_pressure_pa must be a finite number > 0 (Pa), got {p_y!r}")
        source = "given"
    if p_y >= grain.E:
        raise InputError(
            f"the limiting pressure {p_y:.3g} Pa is at or above the Young modulus {grain.E:.3g} Pa "
            "of the grain: no material yields there; check the units (Pa)"
        )
    return PlasticFlow(p_y, source, plastic_waves(grain.law_nu))


def pair_contact_law(
    grain: Grain,
    partner: Grain | None = None,
    *,
    relaxation_time_s: float = 0.0,
    yield_stress_pa: float | None = None,
    limiting_pressure_pa: float | None = None,
) -> PairContactLaw:
    """The law per contact of two spheres of ``grain``'s material (or of ``grain`` and
    ``partner``), of any radii, with the Kelvin-Voigt relaxation time ``relaxation_time_s``
    (s; 0 for elastic grains; one time for both: the package does not model two), and with
    plastic flow from the yield stress ``yield_stress_pa`` (Pa; the limiting pressure is its
    onset pressure, as :func:`restitution.laws.plastic.limiting_pressure` takes it) or from the
    limiting pressure ``limiting_pressure_pa`` (Pa) itself: one material, no damping.

    Builds each material's curve and the viscous map: a few seconds the first time in a
    process.

    Examples
    --------
    >>> from restitution.laws.units import Grain
    >>> law = pair_contact_law(Grain(210e9, 0.3, 7850, "sphere"), relaxation_time_s=1e-7)
    >>> m1, m2 = (4 / 3 * 3.141592653589793 * r**3 * 7850 for r in (1e-3, 2e-3))
    >>> round(law.epsilon(1.0, 1e-3, m1, 2e-3, m2, 210e9 / (2 * 0.91)), 4)
    0.9259
    """
    first = _sphere(grain, "the grain")
    second = first if partner is None else _sphere(partner, "the partner")
    tau = _relaxation(relaxation_time_s)
    plastic = _plastic(first, tau, yield_stress_pa, limiting_pressure_pa, second != first)
    losses = (sphere_loss(first.law_nu), sphere_loss(second.law_nu))
    return PairContactLaw((first, second), tau, losses, viscous_map(), plastic)


def wall_contact_law(
    grain: Grain,
    *,
    relaxation_time_s: float = 0.0,
    wall=None,
    yield_stress_pa: float | None = None,
    limiting_pressure_pa: float | None = None,
) -> WallContactLaw:
    """The law per contact of spheres of ``grain``'s material, of any radius, on the rigid wall,
    with the relaxation time ``relaxation_time_s`` (s; 0 for elastic grains); ``wall``: the
    grain's elastic law on the wall (an :class:`~restitution.laws.si_law.SILaw`), by default
    the shipped one; plastic flow as :func:`pair_contact_law` takes it (the rigid wall does not
    yield)."""
    from restitution.laws.partners.rigid_wall import KIND as WALL
    from restitution.laws.si_law import si_law

    grain = _sphere(grain, "the grain")
    tau = _relaxation(relaxation_time_s)
    plastic = _plastic(grain, tau, yield_stress_pa, limiting_pressure_pa, False)
    law = si_law(grain=grain, against=WALL.against) if wall is None else wall
    return WallContactLaw(grain, tau, pchip_table(law), viscous_map(), plastic)
