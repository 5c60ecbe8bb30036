"""epsilon(w) of a sticky sphere: JKR adhesion, Kelvin-Voigt damping and elastic waves on one pulse.

Units: SI at the edge (speeds m/s, the work of adhesion J/m^2, the radius m, the relaxation time
in the law's ``R / c``); inside, the law's reduced units (``v`` in ``c``, pressures in the
grain's ``E``, lengths in its ``R``, so ``w`` in ``E R``; for two spheres the first one's).

A small grain sticks below a speed that grows as it shrinks (``v_s ~ w^(5/6) R^(-5/6)``: the
adhesion breaks the elastic law's scale invariance, so the law needs the radius).
:class:`AdhesiveLaw` computes, at every asked speed, one force pulse of the JKR contact
(:func:`restitution.quasistatic.adhesion.adhesive_collision`, with the Kelvin-Voigt force when
the material damps) and the elastic waves that pulse leaves, in the manner of
:class:`~restitution.laws.plastic.PlasticLaw`:

* ``loss_adhesion``, ``loss_viscous``: fractions of the impact energy the contact keeps (the JKR
  hysteresis ``Delta W``, the viscous work), ``epsilon_contact^2 = 1 - loss_adhesion -
  loss_viscous``;
* ``loss_waves``: the elastic law's loss at this speed times the ratio of the Rayleigh estimates
  (energy left in the modes) of the adhesive pulse **without its jumps** and of Hertz's pulse at
  the same speed;
* ``epsilon = sqrt(epsilon_contact^2 - loss_waves)``; 0 exactly where the contact keeps the grain
  (below the sticking speed);
* ``loss_waves_interference``: the interference of the jumps' waves with those of the pulse
  without them, over the same modes (below): not in epsilon, a term of its error.

**The waves on the pulse without its jumps.** The JKR force jumps at the snap-in (``-(4/3) pi w
R``) and at the neck break (``+(5/6) pi w R``). A point-force step has ``|F(omega)| ~ 1/omega``,
and its Rayleigh estimate over a sphere's modes grows like the set's top frequency (``x sqrt(2)``
per doubling of the set; 5.0e5 times Hertz's pulse's at ``1.01 v_s`` over the 1600 modes): the
law had no value between ``v_s`` and ``1.16 v_s``. That estimate counts ``Delta W`` twice. In JKR
theory the energy the grain does not get back, ``Delta W``, is the energy released at the
snap-in and at the neck break, which in an elastic body leaves as elastic waves; the point-force
step's divergent estimate is that energy computed with a singular force (the finite contact
makes it finite: cut at the shear speed over ``a0`` it is a fixed fraction, 0.13 to 0.17, of
``Delta W`` for ``w`` from 0.4 to 4 J/m^2, both going as ``w^(5/3)``), and ``loss_adhesion``
already holds it. So the waves go on ``F' = F'_smooth + sum_j Delta F_j delta(t - t_j)`` without
the delta functions: ``F(omega) = (1/(i omega)) int F'_smooth e^{-i omega t} dt``
(:meth:`~restitution.quasistatic.adhesion.AdhesiveCollision.spectrum` with ``jumps=False``).
``F'_smooth`` has an integrable ``(t_b - t)^(-1/2)`` before the break, ``|F| ~ omega^(-3/2)``, and
the sum grows like the logarithm of the top frequency, at the rate ``2 kappa B / (m v^2)`` per
e-fold of a half-space's point-force radiation (``kappa`` its conductance, ``B`` the force-rate
log coefficient): measured ``x 1.09`` per doubling of the set near ``v_s`` (the ratio 322 at
``1.01 v_s``, 295 over the lower half). The ratio is taken over the finite set of the elastic
law's low-speed route (the sphere's :data:`~restitution.quasistatic.low_speed.LOW_SPEED_MODES` or
the pair's, the set of :class:`~restitution.laws.plastic.PlasticLaw`, imported from there for
now); its change when the set is halved is counted in the error.

**What goes with the jumps besides their energy.** The full pulse leaves ``|F_smooth +
F_jumps|^2`` in a mode: the jump-free part, the jumps' own (``Delta W``) and the interference
``2 Re(F_smooth conj(F_jumps))`` (:meth:`~restitution.quasistatic.adhesion.AdhesiveCollision.
mode_energy_parts`; over the bead's modes the three add up to the full pulse's sum within 3e-8
of it). The interference is the contact force's work on the ringing the jumps leave; whether it
is a loss or already in ``Delta W`` the model cannot say, so epsilon leaves it out and its error
holds it whole: ``ratio_cross``, its sum over the same modes in units of Hertz's pulse's
estimate, is 7.9e3 at ``1.01 v_s`` (25 times the ratio kept), 2.7e3 at ``1.6 v_s`` (swinging
with the speed: 1.6e3 at ``1.65 v_s``), 24.9 at ``10 v_s``, 0.23 at ``100 v_s`` on the glass
bead; near ``v_s`` it leads the error (docs/adhesion.md).

The error (one number per speed, the terms added in quadrature; one standard deviation where the
elastic law's is one, bounds for the counted terms): the elastic law's error scaled by the ratio;
the change of the wave loss by the pulse at its full size; its change when the mode set is
halved; the viscous force's share of the waves' drive; the product of the wave loss and the
contact's loss (the pulse is computed without the waves); the finite sphere's stiffer contact on
the viscous loss (:data:`restitution.laws.damped.SPHERE_SIZE_COEFFICIENT`); the interference of
the jumps' waves with the smooth pulse's, ``base |ratio_cross|`` (above; 8.3e-3 of the impact
energy at ``1.01 v_s``, where it makes the error 21 % of epsilon). The error is linearised (that
of ``epsilon^2`` over ``2 epsilon``): counted as a loss the interference would move epsilon a
little beyond the error where it is large (to 0.105 at ``1.01 v_s``, against 0.139 - 0.030). It
does not cover the
JKR idealisation (Tabor's parameter, :attr:`AdhesiveLaw.tabor_parameter`; the half-space contact;
no roughness, humidity or plastic flow at the contact edge), the choice of the viscous force, the
finite contact's smoothing of the jumps (how their energy splits between modes: ``Delta W``
either way), nor the interference's growth with the mode set (about ``x 1.2`` per doubling).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import brentq

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError, real
from restitution.jsonable import finite_or_none
from restitution.laws.damped import SPHERE_SIZE_COEFFICIENT, UNINFORMATIVE
from restitution.laws.mechanisms.base import mechanism_fields
from restitution.laws.mechanisms.bounds import flag_points, wall_of
from restitution.laws.plastic import pulse_contact
from restitution.laws.si_law import SILaw
from restitution.laws.si_point import SIPoint
from restitution.quasistatic.adhesion import AdhesiveCollision, JKRContact, adhesive_collision
from restitution.quasistatic.hertz import QuasistaticError
from restitution.status import Status

__all__ = ["TABOR_Z0_M", "AdhesiveLaw", "adhesive_point", "adhesive_law"]

TABOR_Z0_M = 0.3e-9
"""The range of the surface forces in Tabor's parameter, m (an equilibrium spacing; assumed)."""

TABOR_JKR = 3.0
"""Tabor's parameter below which the JKR theory is marginal (its hysteresis overestimated)."""

_MODE_SET_NOTE = 0.1
"""A point whose waves' ratio moves by more than this fraction when the mode set is halved says
so in its note."""

_SCAN = 1.25  # factor between the speeds tried upwards for the damped sticking speed

REFERENCES = (
    "K. L. Johnson, K. Kendall and A. D. Roberts, Proc. R. Soc. Lond. A 324, 301 (1971): the "
    "JKR contact",
    "C. Thornton and Z. Ning, Powder Technol. 99, 154 (1998): the sticking speed (1.84, 7.09)",
    "D. Tabor, J. Colloid Interface Sci. 58, 2 (1977): the parameter mu",
)


def adhesive_point(
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
    loss_adhesion,
    loss_viscous,
    loss_waves,
    loss_waves_interference,
    stuck,
) -> SIPoint:
    """epsilon of a sticky (and possibly damping) sphere at one SI speed, with its parts.

    Parameters
    ----------
    speed_m_s, v_over_c : float
    epsilon, epsilon_err : float or None
        All mechanisms on one pulse (module docs); 0 and 0 when the grain sticks. The error adds
        the terms in quadrature (one standard deviation where the elastic law's is one; a bound
        for the counted terms).
    epsilon_elastic, epsilon_elastic_err : float or None
        The elastic law alone.
    epsilon_contact : float or None
        The contact alone (adhesion and viscosity; no waves).
    loss_adhesion, loss_viscous, loss_waves : float or None
        Fractions of the impact energy (``None`` when the grain sticks: its energy stays in the
        contact's well, how it divides over the oscillations there is not followed).
    loss_waves_interference : float or None
        The interference of the jumps' waves with those of the pulse without them, over the same
        modes, a fraction of the impact energy (signed; ``None`` where ``loss_waves`` is): not
        in epsilon, its size is a term of the error (module docs).
    stuck : bool
        The contact keeps the grain.
    status, note : str
    """
    parts = (
        ("epsilon_elastic", epsilon_elastic),
        ("epsilon_elastic_err", epsilon_elastic_err),
        ("epsilon_contact", epsilon_contact),
        ("loss_adhesion", loss_adhesion),
        ("loss_viscous", loss_viscous),
        ("loss_waves", loss_waves),
        ("loss_waves_interference", loss_waves_interference),
        ("stuck", stuck),
    )
    return SIPoint(speed_m_s, v_over_c, epsilon, epsilon_err, status, note, parts=parts)


@dataclass(frozen=True, eq=False)
class AdhesiveLaw:
    """epsilon(w) of a sphere with JKR adhesion (module docs); build it with
    :func:`adhesive_law`.

    Attributes
    ----------
    si : SILaw
        The elastic law of the sphere against a rigid wall or another sphere.
    work_of_adhesion : float
        Dupre's ``w = gamma1 + gamma2 - gamma12``, J/m^2 (``2 gamma`` for identical surfaces).
    radius_m : float
        The grain's radius (of a pair: the first grain's, the law's unit of length), m.
    tau : float
        Kelvin-Voigt constant in the law's units ``tau c / R`` (0: no damping).
    """

    si: SILaw
    work_of_adhesion: float
    radius_m: float
    tau: float = 0.0

    @property
    def reduced_work_of_adhesion(self) -> float:
        """``w`` of the collision's contact in the grain's ``E R``: ``w / (E R)``, halved for two
        identical grains, which the law serves as one on a rigid wall at half the speed (``k =
        2``): that wall takes ``w / 2`` (docs/adhesion.md)."""
        return self.work_of_adhesion / (self.si.grain.E * self.radius_m) / self.si.k

    @cached_property
    def _contact(self):
        return pulse_contact(self.si)

    @cached_property
    def jkr(self) -> JKRContact:
        """The JKR contact of the collision in the law's reduced units, with its mass."""
        c = self._contact
        return JKRContact(c.law.E_star, c.law.R, self.reduced_work_of_adhesion, mass=c.mass)

    @property
    def tabor_parameter(self) -> float:
        """Tabor's ``mu = (R w^2 / (E*^2 z0^3))^(1/3) = delta_s / (pi^(2/3) z0)`` of the physical
        contact (for two identical grains their ``R = R/2`` and ``E*``), ``z0`` =
        :data:`TABOR_Z0_M`. JKR holds for large ``mu`` (about 5 or more)."""
        delta_s = self.si.k * self.jkr.compression_scale * self.radius_m  # the pair's approach
        return delta_s / (math.pi ** (2.0 / 3.0) * TABOR_Z0_M)

    @cached_property
    def _sticking_v(self) -> float:
        """The sticking speed in the law's ``c`` (:meth:`sticking_speed_m_s`)."""
        jkr = self.jkr
        v0 = jkr.sticking_speed
        if self.tau == 0.0:
            return v0
        top = float(self.si.law.valid_range[1])

        def shortfall(v: float) -> float:
            # epsilon^2 of a rebound; of a stuck grain how far short of the pull-off it turned
            # (negative), both 0 at the threshold.
            c = adhesive_collision(jkr, v, tau=self.tau)
            if c.stuck:
                return (c.min_compression - jkr.pull_off_compression) / jkr.pull_off_compression
            return c.epsilon**2

        lo, hi = 0.9 * v0, v0  # the damping only adds loss: stuck below v0
        try:
            while shortfall(hi) <= 0.0:
                lo, hi = hi, hi * _SCAN
                if hi > top:
                    return math.inf
        except (InputError, QuasistaticError):
            return math.inf
        return brentq(shortfall, lo, hi, xtol=1e-13 * v0, rtol=1e-12)

    def sticking_speed_m_s(self) -> float:
        """The speed below which the grain sticks, m/s.

        Without damping ``v_s = sqrt(2 Delta W / m)`` (closed form, :class:`~restitution.
        quasistatic.adhesion.JKRContact`). With damping the lowest speed from which the integrated
        collision rebounds: scanned upwards from ``v_s`` by factors 1.25, then Brent's root of
        ``epsilon_contact^2`` (continued below by how far short of the pull-off the stuck grain
        turns); ``inf`` when it sticks at every speed the elastic law serves. Strong damping can
        keep the grain again at faster speeds (the viscous loss grows with the speed): each
        point's ``stuck`` says so. The waves are not in it (they are a loss on the rebound)."""
        return self._sticking_v * self.si.speed_scale_m_s

    def collision(self, speed_m_s: float) -> AdhesiveCollision:
        """The contact's collision alone (no waves) at the SI speed ``speed_m_s`` (m/s)."""
        v = real(speed_m_s, "speed_m_s", "> 0 (m/s)") / self.si.speed_scale_m_s
        return adhesive_collision(self.jkr, v, tau=self.tau)

    @property
    def mechanisms(self) -> list[str]:
        """The mechanisms this law's answers contain (their names,
        :mod:`restitution.laws.mechanisms.base`)."""
        return ["waves", "adhesion", *(["viscous"] if self.tau > 0 else [])]

    def points(self, speeds_m_s) -> tuple[SIPoint, ...]:
        """epsilon and its parts at every speed (m/s); never raises for range."""
        return tuple(self._point(p) for p in self.si.points(speeds_m_s))

    def _point(self, p) -> SIPoint:
        from restitution.quasistatic.plastic_collision import pulse_collision

        head = {"speed_m_s": p.speed_m_s, "v_over_c": p.v_over_c, "epsilon_elastic": p.epsilon,
                "epsilon_elastic_err": p.epsilon_err, "status": p.status}  # fmt: skip
        none = dict.fromkeys(("epsilon", "epsilon_err", "epsilon_contact", "loss_adhesion",
                              "loss_viscous", "loss_waves", "loss_waves_interference"))  # fmt: skip
        if p.epsilon is None:
            return adhesive_point(**head, **none, stuck=False, note=p.note)
        contact, v = self._contact, p.v_over_c
        try:
            actual = adhesive_collision(self.jkr, v, tau=self.tau)
            if actual.stuck:
                return adhesive_point(**{**head, **none, "epsilon": 0.0, "epsilon_err": 0.0,
                                        "epsilon_contact": 0.0}, stuck=True,
                                     note=self._stuck_note(p.speed_m_s))  # fmt: skip
            hertz = pulse_collision(contact.law, v, mass=contact.mass)
        except (InputError, QuasistaticError) as exc:
            return adhesive_point(**{**head, **none, "status": Status.OUTSIDE}, stuck=False,
                                 note=f"contact: {exc}")  # fmt: skip
        ratio, ratio_bare, ratio_half, ratio_cross = _ratios(actual, hertz, contact.modes,
                                                             self.tau)  # fmt: skip
        base = 1.0 - p.epsilon**2
        waves, cross = base * ratio, base * ratio_cross
        eps2 = actual.epsilon**2 - waves
        common = {"epsilon_contact": actual.epsilon, "loss_adhesion": actual.hysteresis,
                  "loss_viscous": actual.viscous_work, "loss_waves": waves,
                  "loss_waves_interference": cross, "stuck": False}  # fmt: skip
        moved = abs(ratio - ratio_half) / ratio
        if not eps2 > 0.0:
            kept = f"adhesion {100 * actual.hysteresis:.3g} %"
            if actual.viscous_work:
                kept += f", viscosity {100 * actual.viscous_work:.3g} %"
            note = (f"no rebound by the estimate: the contact returns epsilon = "
                    f"{actual.epsilon:.3g} ({kept} of the impact energy), and the waves' "
                    f"estimate on its pulse without the jumps, {100 * waves:.3g} % ({ratio:.3g} "
                    f"times their loss on Hertz's pulse; {100 * moved:.2g} % of it from the "
                    "mode set's upper half), is beyond the one-pulse model, which takes the "
                    "waves as a small loss; the grain probably sticks, but this is not "
                    "served")  # fmt: skip
            return adhesive_point(**{**head, "status": Status.OUTSIDE}, epsilon=None,
                                 epsilon_err=None, **{**common, "loss_waves": None,
                                                      "loss_waves_interference": None},
                                 note=note)  # fmt: skip
        eps = math.sqrt(eps2)
        terms = [ratio * 2.0 * p.epsilon * p.epsilon_err, base * abs(ratio - 1.0),
                 base * abs(ratio - ratio_half), base * abs(ratio - ratio_bare),
                 waves * (1.0 - actual.epsilon**2),
                 actual.viscous_work * SPHERE_SIZE_COEFFICIENT
                 * math.sqrt(actual.max_compression / contact.law.R), abs(cross)]  # fmt: skip
        err = math.sqrt(sum(t * t for t in terms)) / (2.0 * eps)
        notes = [p.note] if p.note else []
        if moved > _MODE_SET_NOTE:
            notes.append(f"the waves' estimate on the JKR pulse ({100 * waves:.3g} % of the "
                         f"impact energy) loses {100 * moved:.2g} % when the mode set is halved: "
                         "the force's rate before the neck break drives every mode, the sum "
                         "grows with the set's top frequency (counted in the error)")  # fmt: skip
        if err > UNINFORMATIVE * eps:
            why = ("the waves on the JKR pulse are beyond a small loss here" if abs(cross) <
                   max(terms[:-1]) else f"mostly the interference of the jumps' waves with the "
                   f"smooth pulse's ({100 * cross:.2g} % of the impact energy), which the model "
                   "cannot place (a loss, or already in the hysteresis)")  # fmt: skip
            notes.append(f"not informative: the error is {err / eps:.2g} times epsilon, {why}")
        note = "; ".join(notes)
        return adhesive_point(**head, epsilon=eps, epsilon_err=err, **common, note=note)

    def _stuck_note(self, speed_m_s: float) -> str:
        v_s = self.sticking_speed_m_s()
        head = "the grain sticks (epsilon 0): "
        if math.isinf(v_s):
            return head + "with this damping it sticks at every speed the elastic law serves"
        if speed_m_s > v_s:
            return (f"{head}above the sticking speed v_s = {v_s:.4g} m/s it rebounds, but with "
                    "this damping the viscous loss, which grows with the speed, keeps it here "
                    "again")  # fmt: skip
        return f"{head}the contact keeps it below the sticking speed v_s = {v_s:.4g} m/s"

    def to_dict(self, speeds_m_s, points=None) -> dict:
        """JSON of ``restitution law`` with adhesion: the elastic law's, with an ``"adhesion"``
        block (the model, its parameters, the sticking speed, Tabor's parameter, what the error
        covers) and, per point, every part beside epsilon (``points``: these, computed before,
        instead of computing them again)."""
        d = self.si.to_dict(speeds_m_s)
        mu = self.tabor_parameter
        tabor = (f"mu = {mu:.3g} (z0 = {TABOR_Z0_M:g} m assumed): JKR holds for large mu "
                 "(about 5 or more)")  # fmt: skip
        if mu < TABOR_JKR:
            tabor += (f"; below {TABOR_JKR:g} JKR is marginal, toward the DMT limit, where the "
                      "jumps and the hysteresis shrink: v_s is then probably too high (a "
                      "Maugis-Dugdale contact is not computed)")  # fmt: skip
        modes = self._contact.modes
        how = ("sqrt(2 Delta W / m)" if self.tau == 0 else
               "the lowest speed from which the damped collision rebounds")  # fmt: skip
        d["adhesion"] = {
            "model": "the JKR contact (snap-in at zero approach, neck break under displacement "
            "control) with Kelvin-Voigt damping on the flat punch's stiffness, on one force "
            "pulse; elastic waves on that pulse (docs/adhesion.md)",
            "references": list(REFERENCES),
            "work_of_adhesion_j_m2": self.work_of_adhesion,
            "work_of_adhesion_meaning": "Dupre's w = gamma1 + gamma2 - gamma12 (2 gamma for two "
            "identical surfaces; pull-off force (3/2) pi w R): codes that write JKR with gamma "
            "= w/2 (LAMMPS's granular jkr) need half this number",
            "radius_m": self.radius_m,
            "sticking_speed_m_s": finite_or_none(self.sticking_speed_m_s()),
            "sticking_speed_meaning": f"below it the contact keeps the grain (epsilon 0): {how}"
            "; the waves are not in it",
            "tau_c_over_R": self.tau,
            "tabor_parameter": mu,
            "tabor_z0_m": TABOR_Z0_M,
            "tabor_note": tabor,
            "wave_modes": len(modes),
            "wave_modes_top_omega_c_over_R": float(np.max(modes.omega)),
            "waves_meaning": "the waves on the pulse without its two force jumps: the energy "
            "the jumps release is the hysteresis Delta W, already in loss_adhesion; their "
            "point-force estimate would count it twice",
            "error_covers": "the elastic law's error scaled with the waves, the wave loss's "
            "change by the pulse at its full size, its change when the mode set is halved (the "
            "waves of the force's rate before the neck break grow like the logarithm of the "
            "set's top frequency), the viscous drive of the waves, the coupling of wave and "
            "contact losses, the finite sphere's viscous excess, and the interference of the "
            "jumps' waves with the smooth pulse's over the same modes (loss_waves_interference: "
            "a loss, or already in Delta W, the model cannot say; near the sticking speed it "
            "leads the error); one standard deviation where the elastic law's is one, bounds "
            "for the rest, added in quadrature in epsilon^2 and divided by 2 epsilon",
            "error_does_not_cover": "the JKR idealisation (see tabor_note; the half-space "
            "contact, whose finite sphere is stiffer by about sqrt(delta/R); no roughness, "
            "humidity or plastic flow at the contact edge), the point force of the waves' "
            "estimate (the contact's size smooths the pulse above about the shear speed over "
            "the contact radius; how the jumps' energy, Delta W, splits between modes; the "
            "interference's growth with the mode set, about x 1.2 per doubling), and the choice "
            "of the viscous force",
        }
        d.update(mechanism_fields(self.mechanisms))
        points = self.points(speeds_m_s) if points is None else points
        points, _ = flag_points(self.si, points)
        d["points"] = [p.to_dict() for p in points]
        return d


def _ratios(actual: AdhesiveCollision, hertz, modes, tau: float) -> tuple[float, ...]:
    """How much more the adhesive pulse without its jumps drives the modes than Hertz's at the
    same speed (module docs): the ratios of the Rayleigh sums over ``modes``, ``(with the viscous
    force, without it, over the lower half of the modes by frequency, the interference of the
    jumps' waves with the smooth pulse's)``: the last is ``(full - without the jumps - the jumps
    alone) / Hertz's`` over the same modes, the viscous force's jumps in the jumps."""
    on_hertz = hertz.mode_energy(modes)
    if tau > 0:
        both, _, cross = actual.mode_energy_parts(modes, viscous="both")
        on, bare, cross = both[:, 0], both[:, 1], cross[:, 0]
    else:
        on, _, cross = actual.mode_energy_parts(modes)
        bare = on
    half = np.argsort(modes.omega, kind="stable")[: len(modes) // 2]
    total = float(on_hertz.sum())
    return (float(on.sum()) / total, float(bare.sum()) / total,
            float(on[half].sum()) / float(on_hertz[half].sum()),
            float(cross.sum()) / total)  # fmt: skip


def adhesive_law(si: SILaw, *, work_of_adhesion: float, radius_m: float,
                 tau: float = 0.0) -> AdhesiveLaw:  # fmt: skip
    """The law of ``si``'s sphere with JKR adhesion.

    Parameters
    ----------
    si : SILaw
        The elastic law of a sphere on a rigid wall, or of two spheres (identical, or a pair's
        law of two sizes or materials).
    work_of_adhesion : float
        Dupre's work of adhesion ``w = gamma1 + gamma2 - gamma12``, J/m^2: the work per area
        that separates the interface into two free surfaces, ``2 gamma`` for two identical
        surfaces (not the ``gamma = w/2`` of codes that write JKR per surface).
    radius_m : float
        The grain's radius, m (of a pair: the first grain's).
    tau : float
        Kelvin-Voigt constant ``tau c / R`` (0: elastic material), as
        :attr:`restitution.laws.plastic.PlasticLaw.tau`.

    Examples
    --------
    >>> from restitution.laws.si_law import si_law
    >>> glass = si_law(63e9, 0.24, 2500, "sphere", "wall")
    >>> law = adhesive_law(glass, work_of_adhesion=0.4, radius_m=10e-6)
    >>> round(law.sticking_speed_m_s(), 4)
    0.062
    """
    if not isinstance(si, SILaw):
        raise InputError(f"si must be an SILaw (see si_law), got {type(si).__name__}")
    if si.grain.body != SPHERE.name:
        raise InputError(
            f"adhesion is computed for spheres (JKR's contact is three-dimensional); no adhesive "
            f"law of {si.grain.geometry}s is derived here: leave out the work of adhesion"
        )
    if wall_of(si.law) is not None:
        raise InputError(
            "adhesion on an elastic wall is not derived (the JKR pulse's force jumps make the "
            "wall's point-force radiation int (dF/dt)^2 dt diverge): use a rigid wall or two "
            "grains, or leave out the work of adhesion"
        )
    w = real(work_of_adhesion, "work_of_adhesion", "> 0 (J/m^2)")
    if not w > 0.0:
        raise InputError(
            f"work_of_adhesion must be > 0 (J/m^2, Dupre's w = gamma1 + gamma2 - gamma12), got "
            f"{w!r}; without adhesion leave it out"
        )
    radius = real(radius_m, "radius_m", "> 0 (m)")
    if not radius > 0.0:
        raise InputError(f"radius_m must be > 0 (the grain's radius, m), got {radius!r}")
    t = real(tau, "tau", ">= 0 (R/c)")
    if t < 0.0:
        raise InputError(f"tau must be >= 0 (tau c / R; 0: no damping), got {t!r}")
    return AdhesiveLaw(si, w, radius, t)
