"""Which mechanisms a law's numbers hold, the contact's scales, and from which speed an elastic
answer is a bound.

Units: SI at the edge (m/s); the contact's scales in the law's reduced units.

Every answer of the SI law names the mechanisms in its numbers (``mechanisms`` and
``mechanisms_left_out`` of its JSON, :func:`restitution.laws.mechanisms.base.mechanism_fields`;
:func:`law_mechanisms` those of a law's table). An elastic or
damped sphere's answer without a yield stress is an upper bound above the speed where plastic
flow starts; that speed is not known without the yield stress, but for the material class the
grain's constants suggest (:mod:`restitution.laws.material_classes`) it lies in a range:
:func:`elastic_bound` gives its lowest end and the sentence every such speed's note carries
(:func:`flag_points`).
"""

from __future__ import annotations

from dataclasses import replace

from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.laws.material_classes import material_class
from restitution.laws.partners.base import partner_of
from restitution.quasistatic.plastic import onset_pressure_ratio, yield_speed

__all__ = [
    "contact_scales",
    "elastic_bound",
    "flag_points",
    "half_space_of",
    "law_mechanisms",
    "wall_of",
]


def wall_of(law) -> dict | None:
    """The elastic wall of a law (its partner kind's record in its file,
    :meth:`restitution.laws.partners.base.PartnerKind.read`), ``None`` for a rigid one."""
    return partner_of(law).read(law)


def law_mechanisms(law) -> list[str]:
    """The mechanisms (their names, :mod:`restitution.laws.mechanisms.base`) in a law's tabulated
    numbers: the waves, an elastic wall's radiation, and the viscous loss of a damped law's table
    (its parameters carry the relaxation time); a law a mechanism tabulated names its own
    (``metadata["mechanisms"]``)."""
    metadata = getattr(law, "metadata", None) or {}
    if "mechanisms" in metadata:
        return list(metadata["mechanisms"])
    names = ["waves"]
    loss = partner_of(law).loss  # an elastic wall's radiation
    if loss is not None:
        names.append(loss)
    parameters = (getattr(law, "metadata", None) or {}).get("parameters", {})
    if "relaxation_time_c_over_R" in parameters:
        names.append("viscous")
    return names


def contact_scales(si):
    """``(Hertz's law, mass)`` of the collision of ``si`` (an :class:`~restitution.laws.si_law.
    SILaw` of spheres) in its reduced units: on a rigid wall, on an elastic half-space (``E*``
    of both), or two spheres (their ``E*``, ``R_eff`` and reduced mass; identical spheres are
    served as the wall at ``w/2``): the partner kind's :meth:`~restitution.laws.partners.base.
    PartnerKind.contact`. :class:`InputError` for another body or a plate."""
    if si.grain.body != SPHERE.name:
        raise InputError(
            f"plastic flow is computed for spheres (Thornton's contact is built on Hertz's 3D "
            f"pressure); no comparable law of {si.grain.geometry}s is derived here "
            "(docs/plasticity.md): leave out the plastic options"
        )
    return partner_of(si).contact(si)


def half_space_of(law):
    """The elastic half-space of a law's elastic wall (:class:`restitution.bodies.wall.
    HalfSpace`), ``None`` for a rigid wall or a plate."""
    return partner_of(law).half_space(law)


def elastic_bound(si) -> tuple[float | None, str]:
    """``(speed from which plastic flow is expected, m/s, or None; the sentence)`` for an
    elastic answer of ``si``: the yield speed of the lowest typical yield stress of the material
    class of the grain (and of a partner of another material), :mod:`restitution.laws.
    material_classes`; for disks and cylinders where their line contact first yields. ``(None,
    "")`` for plates and pairs of disks of two sizes or materials; ``(None, what the class does
    instead)`` for a brittle or polymer class; ``(None, "")`` for a law with plastic flow in its
    numbers (a plastic table, :mod:`restitution.laws.tabulated`)."""
    if "plastic" in law_mechanisms(si.law):
        return None, ""
    if si.grain.kind.planar:
        return _line_bound(si)
    try:
        law, mass = contact_scales(si)
    except InputError:
        return None, ""
    bodies = [(si.grain, "grain")]
    if getattr(si, "partner_grain", None) is not None:
        bodies.append((si.partner_grain, "partner"))
    lowest, named = None, []
    for g, who in bodies:
        cls = material_class(g.E, g.rho, g.nu)
        if cls is None or cls.yield_stress is None:
            if cls is not None:
                named.append(f"{who}: {cls.name} ({cls.remark})")
            continue
        # A pressure of first yield at or above the contact's E* is never reached (Hertz's
        # pressure stays below about 0.6 E*: a wall far softer than the grain): no plastic flow
        # of this body from there (ThorntonContact refuses it, in reduced units).
        pressures = [onset_pressure_ratio(g.nu) * y / si.grain.E for y in cls.yield_stress]
        speeds = [yield_speed(law.E_star, law.R, p, mass) * si.speed_scale_m_s
                  for p in pressures if p < law.E_star]  # fmt: skip
        stress = (f"{who}: {cls.name}, yield stress {cls.yield_stress[0] / 1e6:.0f}-"
                  f"{cls.yield_stress[1] / 1e6:.0f} MPa")  # fmt: skip
        if not speeds:
            named.append(
                f"{stress}: not reached on this contact (its effective modulus E* = "
                f"{law.E_star * si.grain.E:.3g} Pa is below the pressure of first yield)"
            )
            continue
        if len(speeds) > 1:
            named.append(f"{stress}, plastic flow from {speeds[0]:.2g}-{speeds[1]:.2g} m/s")
        else:
            named.append(f"{stress}, plastic flow from {speeds[0]:.2g} m/s (the strongest of "
                         "the class never yields on this contact)")  # fmt: skip
        lowest = speeds[0] if lowest is None else min(lowest, speeds[0])
    if lowest is None:
        return None, "; ".join(named)
    return lowest, (
        "upper bound (no plastic flow): plastic flow is not in this answer and is expected for "
        f"typical materials of its class ({'; '.join(named)}); give --yield-stress (or "
        "--limiting-pressure) for the plastic loss"
    )


def _line_bound(si) -> tuple[float | None, str]:
    """:func:`elastic_bound` of a disk or cylinder on a wall (or two identical ones): where its
    2D Hertz contact first yields (:func:`restitution.quasistatic.plastic.
    line_onset_pressure_ratio`, :func:`~restitution.quasistatic.plastic.line_yield_speed`).
    ``(None, "")`` for two disks of different sizes or materials (their pair law's ``R`` is not
    a radius of curvature)."""
    from restitution.quasistatic.plastic import line_onset_pressure_ratio, line_yield_speed
    from restitution.quasistatic.pulse import THEORIES, contact_law_for

    if si.law.partner is not None:
        return None, ""
    g = si.grain
    cls = material_class(g.E, g.rho, g.nu)
    if cls is None:
        return None, ""
    if cls.yield_stress is None:
        return None, f"grain: {cls.name} ({cls.remark})"
    kind = g.kind
    law = contact_law_for(kind.geometry, g.law_nu, kind.quasistatic_law)
    ratio = line_onset_pressure_ratio(g.nu, g.plane)
    mass = THEORIES[kind.geometry].mass
    speeds = [line_yield_speed(law, ratio * y / g.E_2d, mass) * si.speed_scale_m_s
              for y in cls.yield_stress]  # fmt: skip
    named = (
        f"grain: {cls.name}, yield stress {cls.yield_stress[0] / 1e6:.0f}-"
        f"{cls.yield_stress[1] / 1e6:.0f} MPa, plastic flow from {speeds[0]:.2g}-{speeds[1]:.2g} "
        f"m/s (first yield of the line contact in plane {g.plane})"
    )
    return speeds[0], (
        "upper bound (no plastic flow): plastic flow is not in this answer and is expected for "
        f"typical materials of its class ({named}); no plastic law of two-dimensional contacts is "
        "derived (docs/plasticity.md)"
    )


def flag_points(si, points) -> tuple[tuple, float | None]:
    """``points`` (with a ``speed_m_s`` and a ``note``) with :func:`elastic_bound`'s sentence
    added to the note of every speed at or above its speed, and that speed (``None``: none)."""
    bound, text = elastic_bound(si)
    if bound is None:
        return tuple(points), None
    out = []
    for p in points:
        if p.speed_m_s >= bound:
            p = replace(p, note=f"{p.note}; {text}" if p.note else text)
        out.append(p)
    return tuple(out), bound
