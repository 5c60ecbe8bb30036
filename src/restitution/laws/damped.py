"""epsilon(w) of a real, damping grain: the loss to vibrations and the material's viscous loss.

Units: SI at the edge (speeds in m/s, the relaxation time in s, the radius in m); inside, the
law's reduced units (``v`` in ``c``, ``tau`` in ``R / c``, ``R`` the grain's radius; for two
grains of different sizes the smaller one's).

A grain of a Kelvin-Voigt material with one relaxation time ``tau`` (viscosities ``tau`` times
the moduli, :mod:`restitution.bodies.viscoelastic`) loses kinetic energy in two ways: to its
vibrations (the elastic law, :class:`restitution.laws.si_law.SILaw`) and to the viscous force
of the quasistatic contact, ``tau dF_el/dt`` (:mod:`restitution.quasistatic.viscoelastic`; for
a sphere the law of Brilliantov et al. 1996 and Ramirez et al. 1999). The two fractions of the
kinetic energy add::

    1 - epsilon^2 = (1 - epsilon_elastic^2) + (1 - epsilon_viscous^2),

the first order of both small losses; the product of the two is the size of what this leaves
out. The modal model with the damping in every mode (:class:`~restitution.bodies.viscoelastic.
Viscoelastic`) computes the two together; docs/damping.md compares it with this sum.

The relaxation time comes from the user (``relaxation_time_s`` with the grain's ``radius_m``:
``tau c / R`` is what enters), or from one measured coefficient of restitution at one speed:
``tau`` is then the one for which the sum gives the measured value there. Only ``tau c / R``
is inferred, so no radius is needed: grains of the measured size (and material) follow the same
law at every speed.

Errors: the elastic law's error, and, for an inferred ``tau``, how far ``tau`` moves when the
elastic law at the measured speed moves by its error; added in quadrature (they are counted
as independent, which overstates the error near the measured speed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np
from scipy.optimize import brentq

from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.laws.mechanisms.base import mechanism_fields
from restitution.laws.mechanisms.bounds import flag_points, law_mechanisms
from restitution.laws.si_law import SILaw
from restitution.laws.si_point import SIPoint
from restitution.limits.run_options import Progress, progress_of
from restitution.status import Status

__all__ = [
    "DISK_VISCOUS_SPREAD",
    "SPHERE_SIZE_COEFFICIENT",
    "DampedLaw",
    "damped_point",
    "damped_law",
    "viscous_epsilon",
    "viscous_max_speed",
]

DISK_VISCOUS_SPREAD = 0.13
"""The disk's viscous loss differs from the quasistatic viscous collision's on the 2D law by up to
this fraction of it. The damped modal disk measured 0.89 and 0.885 of it at ``v = 0.001`` and
``0.005``, 1.055-1.085 at ``v = 0.02`` (``nu = 0.33``; the same ratio at ``tau = 0.01, 0.025,
0.05``; :mod:`restitution.laws.making.damped_check`). The damped slow-impact model
(:mod:`restitution.quasistatic.slow_damped`), which reproduces the modal disk at ``v = 0.001``,
gives 0.96-1.13 from ``v = 1e-7`` to ``1e-4`` (``tau = 0.001-0.05``): the largest deviation,
0.127 at ``v = 1e-4``, ``tau = 0.01``, is this spread (docs/damping.md). The low modes take part
in the disk's contact, and the quasistatic law is only their ``v -> 0`` limit. Counted in the
error of a disk's damped law, not corrected."""

SPHERE_SIZE_COEFFICIENT = 0.44
"""The finite sphere's viscous loss exceeds the one on Hertz's law by up to this times
``sqrt(delta_max / R)`` (relative): its quasistatic contact is stiffer than Hertz's half-space
(docs/spheres.md), and the damped modal sphere dissipates accordingly more. The damped modal
points (:mod:`restitution.laws.making.damped_check`, ``nu = 0.3``) measured 0.31, 0.32 and 0.44 at
``v = 0.003, 0.00627, 0.0131``; the largest is used. Counted in the error of a sphere's
damped law, not corrected (one Poisson number, three speeds)."""

# What each body's modal viscous loss exceeds the quasistatic one by, measured for each body
# (:mod:`restitution.laws.making.damped_check`): the factor on the quasistatic viscous loss at its
# largest compression (``R``) for a grain of the kind named.
_MODAL_VISCOUS_FACTOR = {
    DISK.name: lambda compression: 1.0 + DISK_VISCOUS_SPREAD,
    SPHERE.name: lambda compression: 1.0 + SPHERE_SIZE_COEFFICIENT * np.sqrt(compression),
}


def _modal_viscous_factor(si: SILaw, compression: np.ndarray):
    """The measured factor of ``si``'s body (:data:`_MODAL_VISCOUS_FACTOR`) at the quasistatic
    largest compressions; :class:`InputError` for a body never measured."""
    factor = _MODAL_VISCOUS_FACTOR.get(si.grain.body)
    if factor is None:
        raise InputError(
            f"the viscous loss of a damping {si.grain.body} is not compared with its modal "
            f"model (restitution.laws.making.damped_check); damped laws are served for "
            f"{', '.join(name + 's' for name in _MODAL_VISCOUS_FACTOR)}"
        )
    return factor(compression)


def _contact(si: SILaw):
    """The quasistatic contact law and mass of ``si``'s body (reduced units): a body on the
    wall takes its kind's law (:attr:`~restitution.bodies.kinds.BodyKind.quasistatic_law`) and
    its own mass (``None``: the law's body's), a pair its law and reduced mass."""
    from restitution.quasistatic.pulse import contact_law_for, pair_contact_for

    nu = float(si.law.nu)
    pair = si.law.partner
    kind = si.grain.kind
    if pair is not None:  # the pair's own law and reduced mass, of its kind (issue 44: the
        # sphere pair took the disk pair's law and 2D mass until a LAMMPS run disagreed)
        return pair_contact_for(kind.geometry, nu, pair)
    return contact_law_for(kind.geometry, nu, kind.quasistatic_law), None


def viscous_max_speed(si: SILaw) -> float:
    """The largest reduced speed (``c``) the quasistatic contact law of ``si``'s body takes."""
    law, mass = _contact(si)
    return float(law.max_speed() if mass is None else law.max_speed(mass))


TABLE_PER_DECADE = 12
"""Speeds a decade of the viscous table (:func:`_viscous` with ``table``): for more asked
speeds than the table computes, the viscous collision is computed on a geometric grid spanning
them (and midway between its speeds) and interpolated (PCHIP in ``ln v``), its error twice the
largest deviation measured midway (1e-7 for steel; at worst 12 times the deviation midway in
the same interval, which passes through zero). 1000 speeds from 0.01 to 10 m/s (steel, an
inferred relaxation time) took 85 s, one collision a speed and three with the time's spread;
the table computes 73 (8 s)."""


@dataclass(frozen=True)
class _ViscousParts:
    """What the damped law takes of the viscous collisions at its speeds: ``epsilon``, the
    undamped ``elastic_max_compression`` (``R``) and ``table_err``, the interpolation's error
    of ``epsilon`` (zero where each speed was computed), shape (K,) each."""

    epsilon: np.ndarray
    elastic_max_compression: np.ndarray
    table_err: np.ndarray


def _table_speeds(v: np.ndarray) -> np.ndarray | None:
    """The viscous table's speeds for the asked ``v`` (``c``), or ``None`` where computing each
    speed costs no more (:data:`TABLE_PER_DECADE`)."""
    lo, hi = float(np.min(v)), float(np.max(v))
    if not hi > lo:
        return None
    n = max(2, math.ceil(TABLE_PER_DECADE * math.log10(hi / lo)) + 1)
    if np.unique(v).size <= 2 * n - 1:
        return None
    return np.geomspace(lo, hi, n)


def _viscous(si: SILaw, v, tau: float, advance=None, *, table: bool = False) -> _ViscousParts:
    """The quasistatic viscous collision of the law's body at reduced speeds ``v``
    (``advance(1)`` after each speed, when given); with ``table``, interpolated from a grid
    spanning them where that computes fewer collisions (:data:`TABLE_PER_DECADE`)."""
    from scipy.interpolate import PchipInterpolator

    from restitution.quasistatic.viscoelastic import viscous_collision

    law, mass = _contact(si)
    v = np.atleast_1d(np.asarray(v, dtype=float))
    grid = _table_speeds(v) if table else None
    if grid is None:
        col = viscous_collision(law, v, tau, mass=mass, advance=advance)
        return _ViscousParts(col.epsilon, col.elastic_max_compression, np.zeros(v.shape))
    mid = np.sqrt(grid[:-1] * grid[1:])
    col = viscous_collision(law, np.concatenate([grid, mid]), tau, mass=mass, advance=advance)
    eps_grid, eps_mid = col.epsilon[: grid.size], col.epsilon[grid.size :]
    through = PchipInterpolator(np.log(grid), eps_grid)
    # Midway the deviation may pass through zero where it is large elsewhere in the interval:
    # the table's error is twice the largest one measured, at every speed between its own.
    gap = 2.0 * float(np.max(np.abs(through(np.log(mid)) - eps_mid)))
    at_grid = np.isin(v, grid)
    compression = PchipInterpolator(np.log(grid), np.log(col.elastic_max_compression[: grid.size]))
    return _ViscousParts(
        through(np.log(v)), np.exp(compression(np.log(v))), np.where(at_grid, 0.0, gap)
    )


def viscous_epsilon(si: SILaw, v, tau: float, *, advance=None) -> np.ndarray:
    """epsilon of the viscous force alone at the law's reduced speeds ``v`` (``c``) for the
    reduced relaxation time ``tau`` (``R / c``): the quasistatic collision of the law's body
    (disk or sphere on a wall, identical grains as the wall at ``v``, two sizes as the pair).
    ``advance``: called with 1 after each speed (a progress meter)."""
    return _viscous(si, v, tau, advance).epsilon


def damped_point(
    *,
    speed_m_s,
    v_over_c,
    epsilon,
    epsilon_err,
    status,
    note="",
    epsilon_elastic,
    epsilon_elastic_err,
    epsilon_viscous,
    informative=True,
) -> SIPoint:
    """epsilon of a damping grain at one SI speed: an :class:`~restitution.laws.si_point.SIPoint`
    with the parts below (each an attribute and a key of its ``to_dict``).

    Parameters
    ----------
    speed_m_s, v_over_c : float
        Impact speed ``w`` (m/s) and the law's reduced speed (``c``).
    epsilon, epsilon_err : float or None
        Both losses together (module docstring) and its error; ``None`` where the elastic law
        has no value (``status`` says why).
    epsilon_elastic, epsilon_elastic_err : float or None
        The loss to vibrations alone: the elastic law.
    epsilon_viscous : float or None
        The viscous loss alone (quasistatic); ``None`` beyond the quasistatic law's range.
    status : str
        The elastic law's status at this speed (:class:`restitution.status.Status`).
    note : str
    informative : bool
        False where the error exceeds :data:`UNINFORMATIVE` times epsilon: the note then says
        which approximation of the damped model the error comes from.
    """
    parts = (
        ("epsilon_elastic", epsilon_elastic),
        ("epsilon_elastic_err", epsilon_elastic_err),
        ("epsilon_viscous", epsilon_viscous),
        ("informative", informative),
    )
    return SIPoint(speed_m_s, v_over_c, epsilon, epsilon_err, status, note, parts=parts)


UNINFORMATIVE = 0.25
"""A damped answer whose error exceeds this fraction of its epsilon gets a note saying that the
model stops being informative there and which of its approximations the error comes from."""

_TERMS = {
    "elastic": "the elastic law's own error",
    "tau": "the spread of the inferred relaxation time",
    "table": "the interpolation of the viscous collisions between the table's speeds",
    "sum": "the product of the two losses, which their sum leaves out (both losses are large)",
    SPHERE.name: "the finite sphere's stiffer contact (SPHERE_SIZE_COEFFICIENT: measured only "
    "for weak damping up to v = 0.0131 c, here counted at its full size)",
    DISK.name: "how far the modal disk's viscous loss strays from the quasistatic one "
    "(DISK_VISCOUS_SPREAD)",
}
"""The error terms of a damped answer (:meth:`DampedLaw._terms`; ``size`` by the body), in
words."""


def _overspent(eps_el: float, eps_v: float) -> str:
    """The note of a speed where the two losses add up to all the kinetic energy or more."""
    return (
        f"no value: the losses to vibrations ({1.0 - eps_el**2:.3g} of the kinetic energy) and "
        f"to viscosity ({1.0 - eps_v**2:.3g}) add up to all of it, where the model of two added "
        f"small losses does not hold; epsilon is below {min(eps_el, eps_v):.4g} (each loss "
        "alone)"
    )


def _uninformative(eps: float, err: float, terms: dict, eps_v: float, body: str) -> str:
    """The note of a damped answer whose error is large against epsilon."""
    big = max(terms, key=lambda k: terms[k])
    what = _TERMS.get(body if big == "size" else big, big)
    return (
        f"not informative here: epsilon lies in [{max(eps - err, 0.0):.3g}, "
        f"{min(eps + err, 1.0):.3g}]; the error {err:.2g} is mostly {what}; the viscous part "
        f"alone (the quasistatic Kelvin-Voigt collision) gives {eps_v:.4g}"
    )


def _combine(eps_el, eps_v):
    """``sqrt(eps_el^2 + eps_v^2 - 1)``: the two losses of kinetic energy added; ``0`` when
    they add up to all of it."""
    sq = np.asarray(eps_el, dtype=float) ** 2 + np.asarray(eps_v, dtype=float) ** 2 - 1.0
    return np.sqrt(np.maximum(sq, 0.0))


@dataclass(frozen=True, eq=False)
class DampedLaw:
    """epsilon(w) of a grain whose material damps (module docstring).

    Attributes
    ----------
    si : SILaw
        The elastic law of the grain against its partner.
    tau : float
        Relaxation time in the law's units, ``tau c / R``.
    tau_err : float
        Its error (inferred ``tau``: from the elastic law's error at the measured speed; given
        ``tau``: 0).
    radius_m : float or None
        The grain's radius, m, when known (then :attr:`relaxation_time_s` is known).
    measured : tuple of (float, float) or None
        ``(epsilon, speed_m_s)`` the relaxation time was inferred from.
    """

    mechanism: ClassVar[str] = "viscous"
    """The mechanism that answers with this law (:mod:`restitution.laws.mechanisms`)."""

    si: SILaw
    tau: float
    tau_err: float = 0.0
    radius_m: float | None = None
    measured: tuple[float, float] | None = None

    @property
    def relaxation_time_s(self) -> float | None:
        """``tau`` in seconds (``tau R / c``), when the radius is known."""
        if self.radius_m is None:
            return None
        return self.tau * self.radius_m / self.si.grain.c_m_s

    def points(self, speeds_m_s) -> tuple[SIPoint, ...]:
        """epsilon, its parts and errors at every speed (m/s); never raises for range. The
        viscous collisions of all speeds at once, from a table for many speeds
        (:data:`TABLE_PER_DECADE`; its error among the terms); where that is refused (a speed
        beyond the quasistatic law's range), speed by speed."""
        elastic_points = self.si.points(speeds_m_s)
        batch = self._batch(elastic_points)
        out = []
        for i, p in enumerate(elastic_points):
            head = {"speed_m_s": p.speed_m_s, "v_over_c": p.v_over_c}
            elastic = {"epsilon_elastic": p.epsilon, "epsilon_elastic_err": p.epsilon_err}
            try:
                if i in batch:
                    eps_v, eps, terms = batch[i]
                else:
                    eps_v, eps, terms = self._terms(p.v_over_c, p.epsilon, p.epsilon_err)
            except InputError as exc:
                out.append(damped_point(**head, epsilon=None, epsilon_err=None, **elastic,
                                       epsilon_viscous=None, status=Status.OUTSIDE,
                                       note=f"viscous part: {exc}"))  # fmt: skip
                continue
            both, note, informative = {"epsilon": None, "epsilon_err": None}, p.note, True
            if p.epsilon is not None and not float(eps[0]) > 0.0:
                informative = False
                why = _overspent(p.epsilon, float(eps_v[0]))
                note = f"{note}; {why}" if note else why
            elif p.epsilon is not None:
                parts = {k: float(t[0]) for k, t in terms.items()}
                eps1, err = float(eps[0]), math.sqrt(sum(t**2 for t in parts.values()))
                both = {"epsilon": eps1, "epsilon_err": err}
                informative = err <= UNINFORMATIVE * eps1
                if not informative:
                    why = _uninformative(eps1, err, parts, float(eps_v[0]), self.si.grain.body)
                    note = f"{note}; {why}" if note else why
            out.append(damped_point(**head, **both, **elastic, epsilon_viscous=float(eps_v[0]),
                                   status=p.status, note=note,
                                   informative=informative))  # fmt: skip
        return tuple(out)

    def _batch(self, points) -> dict:
        """:meth:`_terms` of the points within the quasistatic law's range at once (a table for
        many speeds), by index; ``{}`` where that is refused (the others speed by speed)."""
        top = viscous_max_speed(self.si)
        index = [i for i, p in enumerate(points) if 0.0 < p.v_over_c <= top]
        if len(index) < 2:
            return {}
        chosen = [points[i] for i in index]
        v = np.array([p.v_over_c for p in chosen], dtype=float)
        eps_el = np.array([np.nan if p.epsilon is None else p.epsilon for p in chosen])
        err_el = np.array([np.nan if p.epsilon_err is None else p.epsilon_err for p in chosen])
        try:
            eps_v, eps, terms = self._terms(v, eps_el, err_el, table=True)
        except InputError:
            return {}
        out = {}
        for k, (i, p) in enumerate(zip(index, chosen, strict=True)):
            if p.epsilon is None:
                out[i] = (eps_v[k : k + 1], np.full(1, np.nan), {})
            else:
                out[i] = (eps_v[k : k + 1], eps[k : k + 1],
                          {name: t[k : k + 1] for name, t in terms.items()})  # fmt: skip
        return out

    def _parts(self, v, eps_el, err_el, advance=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(epsilon_viscous, epsilon, error)``: :meth:`_terms` with the error's terms added
        in quadrature."""
        eps_v, eps, terms = self._terms(v, eps_el, err_el, advance)
        err = np.sqrt(sum(t**2 for t in terms.values())) if terms else np.full(eps.shape, np.nan)
        return eps_v, eps, err

    def _terms(
        self, v, eps_el, err_el, advance=None, *, table: bool = False
    ) -> tuple[np.ndarray, np.ndarray, dict]:
        """``(epsilon_viscous, epsilon, error)`` at reduced speeds ``v`` with the elastic law's
        ``eps_el +- err_el`` there (``eps_el`` may be ``None``: then only the first is
        finite). The error adds in quadrature the elastic law's error carried through the sum,
        the spread of an inferred ``tau``, the product of the two losses (what the sum leaves
        out), and the measured difference of the modal body's viscous loss from the quasistatic
        one: for a sphere the size of its contact beyond Hertz's half-space
        (:data:`SPHERE_SIZE_COEFFICIENT`), for a disk :data:`DISK_VISCOUS_SPREAD`.
        ``advance(1)`` follows each viscous collision (a progress meter). With ``table`` the
        viscous collisions of many speeds come from a table (:func:`_viscous`), whose error
        joins the terms (``"table"``, carried through the sum)."""
        col = _viscous(self.si, v, self.tau, advance, table=table)
        eps_v = col.epsilon
        if eps_el is None:
            return eps_v, np.full(eps_v.shape, np.nan), {}
        eps_el = np.asarray(eps_el, dtype=float)
        err_el = np.asarray(err_el, dtype=float)
        eps = _combine(eps_el, eps_v)
        # Where the losses add up to all the energy (eps = 0) the terms are undefined: nan.
        positive = np.where(eps > 0.0, eps, np.nan)
        terms = {"elastic": eps_el * err_el / positive}
        if np.any(col.table_err > 0.0):
            terms["table"] = eps_v * col.table_err / positive
        if self.tau_err > 0.0:
            spread = [max(self.tau - self.tau_err, 0.0), self.tau + self.tau_err]
            lo, hi = (_viscous(self.si, v, t, advance, table=table).epsilon for t in spread)
            terms["tau"] = 0.5 * np.abs(_combine(eps_el, lo) - _combine(eps_el, hi))
        # What the sum leaves out: the product of the two losses (docs/damping.md).
        terms["sum"] = (1.0 - eps_el**2) * (1.0 - eps_v**2) / (2.0 * positive)
        grow = _modal_viscous_factor(self.si, col.elastic_max_compression)
        bigger = np.sqrt(np.maximum(1.0 - (1.0 - eps_v**2) * grow, 0.0))
        terms["size"] = np.abs(_combine(eps_el, bigger) - eps)
        return eps_v, eps, terms

    def _served(self) -> np.ndarray:
        """Which computed speeds of the elastic law the quasistatic viscous law takes."""
        return np.asarray(self.si.law.v, dtype=float) <= viscous_max_speed(self.si)

    def table_collisions(self) -> int:
        """How many quasistatic viscous collisions :meth:`as_si_law` integrates: one at each of
        the elastic law's computed speeds it tabulates, three with an inferred ``tau`` (its
        error's two ends too)."""
        return int(np.sum(self._served())) * (3 if self.tau_err > 0.0 else 1)

    def as_si_law(self, progress: Progress | bool | None = False) -> SILaw:
        """The damped law as an :class:`SILaw` of its own: the sum at every computed speed of
        the elastic law (errors as in :meth:`points`), so that tables, closed forms, constants
        and snippets (:mod:`restitution.laws.exports`) serve it as they serve an elastic law.
        Points of the low-speed theory keep their route.

        It integrates :meth:`table_collisions` viscous collisions (one per computed speed of
        the elastic law, over a hundred for a disk's, over four hundred for a sphere's; three
        each with an inferred ``tau``); ``progress``
        (:class:`~restitution.limits.run_options.Progress` or its shorthand) draws a bar over
        them on stderr."""
        from restitution.laws.law import EpsilonLaw
        from restitution.laws.law_point import QUASISTATIC_ROUTE

        law = self.si.law
        served = self._served()
        if served.sum() < 2:
            raise InputError(
                "the quasistatic viscous law serves fewer than two of the elastic law's speeds; "
                "no damped law can be tabulated"
            )
        v = np.asarray(law.v, dtype=float)[served]
        total = self.table_collisions()
        with progress_of(progress).bar(total, "damped law: viscous collisions") as meter:
            eps_el = law.epsilon(v)
            eps_v, eps, err = self._parts(v, eps_el, law.epsilon_err(v), advance=meter)
        # Where the two losses add up to all the kinetic energy the sum means nothing: the
        # table stops below the first such speed (issue 47: it served 0 +- 1e298 as ok).
        spent = np.flatnonzero(~(eps > 0.0))
        if spent.size:
            stop = int(spent[0])
            if stop < 2:
                raise InputError(
                    f"the losses to vibrations and to viscosity add up to all the kinetic energy "
                    f"from {v[stop] * self.si.speed_scale_m_s:.3g} m/s on; "
                    "no damped law can be tabulated (a smaller relaxation time or a larger "
                    "measured epsilon damps less)"
                )
            served[np.flatnonzero(served)[stop:]] = False
            v, eps, err = v[:stop], eps[:stop], err[:stop]
            eps_el, eps_v = eps_el[:stop], eps_v[:stop]
            limit = (
                f"; served up to {v[-1] * self.si.speed_scale_m_s:.4g} m/s: above, the losses "
                "add up to all the kinetic energy"
            )
        else:
            limit = ""
        quasi = np.asarray(getattr(law, "quasistatic", np.zeros(served.size, bool)), bool)[served]
        # Each point keeps its two losses (fractions of the impact energy): SILaw.losses.
        records = [
            {"v": float(x), "loss_waves": float(1.0 - e**2), "loss_viscous": float(1.0 - d**2),
             **({"route": QUASISTATIC_ROUTE} if q else {})}
            for x, q, e, d in zip(v, quasi, eps_el, eps_v, strict=True)
        ]  # fmt: skip
        source = (
            f"{self.si.law_source}, damped: tau c/R = {self.tau:.6g} +- {self.tau_err:.2g}{limit}"
        )
        damped = EpsilonLaw.from_points(
            float(law.nu),
            v,
            eps,
            err,
            asymptotic_ok=np.asarray(law.asymptotic_ok, bool)[served],
            parameters={"relaxation_time_c_over_R": self.tau},
            geometry=law.geometry,
            partner=law.partner,
        )
        metadata = {**damped.metadata, "source": source, "points": records}
        from restitution.laws.below_route import Below, below_seconds

        lowest = np.array([float(law.v[0]) * 0.1])
        each = below_seconds(law, lowest)  # the elastic route's, which its points below take
        below = Below(self.points, each, "the damped law", batch=True)
        return SILaw(
            self.si.grain, self.si.against, replace(damped, metadata=metadata), below=below
        )

    def to_dict(self, speeds_m_s, points=None) -> dict:
        """JSON of ``restitution law`` with damping: the elastic law's, with the relaxation
        time and, per point, ``epsilon_elastic`` and ``epsilon_viscous`` beside ``epsilon``
        (``points``: these, computed and flagged before by :func:`restitution.laws.mechanisms.
        flag_points`, instead of integrating their viscous collisions again)."""
        if points is None:
            points, _ = flag_points(self.si, self.points(speeds_m_s))
        d = self.si.to_dict(speeds_m_s, points=points)
        d["damping"] = {
            "model": "Kelvin-Voigt, one relaxation time (viscosities = tau x moduli); viscous "
            "loss of the quasistatic contact, F = F_el + tau dF_el/dt; losses of kinetic "
            "energy added: 1 - eps^2 = (1 - eps_elastic^2) + (1 - eps_viscous^2)",
            "tau_c_over_R": self.tau,
            "tau_c_over_R_err": self.tau_err,
            "relaxation_time_s": self.relaxation_time_s,
            "radius_m": self.radius_m,
            "measured": None
            if self.measured is None
            else {"epsilon": self.measured[0], "speed_m_s": self.measured[1]},
        }
        # The elastic law's JSON holds the speed from which plastic flow is expected.
        d.update(mechanism_fields([*law_mechanisms(self.si.law), "viscous"]))
        d["points"] = [p.to_dict() for p in points]
        return d


def _positive(name: str, value, unit: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number ({unit}), got {type(value).__name__}")
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be a finite number > 0 ({unit}), got {value!r}")
    return value


def _infer_tau(
    si: SILaw, eps_m: float, speed: float, progress: Progress | bool | None = False
) -> tuple[float, float]:
    """``tau c / R`` for which the sum gives ``eps_m`` at ``speed`` (m/s), and its error: three
    root searches of a dozen or more viscous collisions each (``progress``: a bar over them)."""
    (p,) = si.points([speed])
    if p.epsilon is None:
        raise InputError(
            f"the elastic law has no value at the measured speed {speed:g} m/s ({p.note}); "
            "measure at a speed the law serves, or give --relaxation-time"
        )
    v = p.v_over_c

    def solve(eps_el: float) -> float:
        if eps_m >= eps_el:
            return 0.0
        # The viscous epsilon the sum needs, then the tau that gives it.
        need = math.sqrt(max(eps_m**2 + 1.0 - eps_el**2, 0.0))

        def gap(log_tau: float) -> float:
            return float(viscous_epsilon(si, v, math.exp(log_tau))[0]) - need

        lo, hi = math.log(1e-9), math.log(1e3)
        if gap(hi) > 0:
            raise InputError(
                f"the measured epsilon {eps_m:.10g} at {speed:g} m/s needs more damping than a "
                "relaxation time of 1000 R/c gives; check the measurement"
            )
        if gap(lo) < 0:
            return math.exp(lo)
        return math.exp(brentq(gap, lo, hi, xtol=1e-12, rtol=1e-10))

    if eps_m > p.epsilon + p.epsilon_err:
        raise InputError(
            f"the measured epsilon {eps_m:.10g} at {speed:g} m/s is above the elastic law's "
            f"{p.epsilon:.6f} +- {p.epsilon_err:.2g} there: the grain would lose less than to its "
            "vibrations alone, which no damping explains; check the measurement and the "
            "material constants"
        )
    with progress_of(progress).bar(3, "relaxation time: root searches") as meter:
        tau = solve(p.epsilon)
        meter(1)
        spread = []
        for s in (-1.0, 1.0):
            spread.append(solve(min(p.epsilon + s * p.epsilon_err, 1.0)))
            meter(1)
    return tau, 0.5 * abs(spread[1] - spread[0])


def damped_law(
    si: SILaw,
    *,
    relaxation_time_s: float | None = None,
    radius_m: float | None = None,
    measured_epsilon: float | None = None,
    measured_speed_m_s: float | None = None,
    progress: Progress | bool | None = False,
) -> DampedLaw:
    """The law of ``si``'s grain made of a material that damps.

    Parameters
    ----------
    si : SILaw
        The elastic law (:func:`restitution.laws.si_law.si_law`).
    relaxation_time_s, radius_m : float, optional
        The material's relaxation time (s) and the grain's radius (m; for two sizes the smaller
        grain's): ``tau c / R`` follows.
    measured_epsilon, measured_speed_m_s : float, optional
        Instead: one measured coefficient of restitution and the impact speed (m/s, the same
        meaning as the law's speeds) it was measured at.
    progress : Progress or bool or None
        A bar on stderr over the root searches that infer ``tau`` from the measurement
        (:func:`restitution.limits.run_options.progress_of`); default none.

    Examples
    --------
    >>> from restitution.laws.si_law import si_law
    >>> steel = si_law(210e9, 0.3, 7850, "sphere", "wall")
    >>> d = damped_law(steel, measured_epsilon=0.9, measured_speed_m_s=1.0)
    >>> round(d.points([1.0])[0].epsilon, 6)
    0.9
    """
    if not isinstance(si, SILaw):
        raise InputError(f"si must be an SILaw (see si_law), got {type(si).__name__}")
    given = relaxation_time_s is not None
    measured = measured_epsilon is not None or measured_speed_m_s is not None
    if given == measured:
        raise InputError(
            "give the relaxation time (relaxation_time_s with radius_m) or one measurement "
            "(measured_epsilon with measured_speed_m_s), one of the two"
        )
    if given:
        tau_s = _positive("relaxation_time_s", relaxation_time_s, "s")
        if radius_m is None:
            raise InputError(
                "a relaxation time in seconds needs the grain's radius (radius_m, m): tau c / R "
                "is what sets the viscous loss"
            )
        radius = _positive("radius_m", radius_m, "m")
        return DampedLaw(si, tau_s * si.grain.c_m_s / radius, 0.0, radius)
    if measured_epsilon is None or measured_speed_m_s is None:
        raise InputError("a measurement needs both measured_epsilon and measured_speed_m_s")
    eps_m = _positive("measured_epsilon", measured_epsilon, "dimensionless")
    if eps_m >= 1.0:
        raise InputError(f"measured_epsilon must lie in (0, 1), got {eps_m!r}")
    speed = _positive("measured_speed_m_s", measured_speed_m_s, "m/s")
    radius = None if radius_m is None else _positive("radius_m", radius_m, "m")
    tau, tau_err = _infer_tau(si, eps_m, speed, progress)
    return DampedLaw(si, tau, tau_err, radius, (eps_m, speed))
