"""The comment lines every export opens with: what the law is for, in words.

Every file and snippet of :mod:`restitution.laws.exports` carries them: the package version and
the time of writing, the grain (geometry and body of the law: a cylinder or thin disk is served
by the disk's law, a sphere by the sphere's), its material (and the partner's), what the speed
``w`` means (a wall, or two grains' relative normal speed) with the speed unit ``k c`` in m/s,
which law serves it and where it is from, the computed speeds in m/s, and the loss mechanisms
in the numbers (and from which speed they are an upper bound without plastic flow).
"""

from __future__ import annotations

import datetime

from restitution._version import __version__
from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.laws.mechanisms.base import mechanism_fields
from restitution.laws.mechanisms.bounds import elastic_bound, law_mechanisms
from restitution.laws.si_law import SILaw


def _law_line(s: SILaw) -> str:
    """``law: ...``: which law serves ``s`` (the body's, or the pair's) and where it is from."""
    g = s.grain
    pair = s.law.partner
    if pair is not None:
        which = (
            f"this {g.body} and one of the partner's material"
            if s.partner_grain is not None
            else f"a small and a large {g.body} of one material"
        )
        return (
            f"law: the pair's ({which}, R2/R1 = {pair.radius_ratio:g}; w their relative normal "
            f"speed), {g.law_nu_name} = {float(s.law.nu):g}, {s.law_source}"
        )
    if g.body == DEFAULT_GEOMETRY:
        return f"law: {g.law_nu_name} = {float(s.law.nu):g}, {s.law_source}"
    return f"law: the {g.body}'s, nu = {float(s.law.nu):g}, {s.law_source}"


def _header(s: SILaw) -> list[str]:
    g = s.grain
    lo, hi = s.computed_range_m_s
    return [
        f"restitution {__version__}, {datetime.datetime.now(datetime.UTC):%Y-%m-%dT%H:%M:%SZ}: "
        "coefficient of restitution of an elastic grain from its vibrational modes "
        "(Gerl & Zippelius model)",
        f"grain: {g.geometry}: {g.kind.shape_words[g.geometry]}",
        f"material: {g.describe()}",
        *([f"partner material: {s.partner_grain.describe()}"] if s.partner_grain else []),
        f"partner: {s.against}: {s.against_meaning}; speed unit k c = {s.speed_scale_m_s:.6g} m/s",
        _law_line(s),
        f"computed speeds: {lo:.6g} ... {hi:.6g} m/s; the law serves nothing outside them",
        *_mechanism_lines(s),
    ]


def _mechanism_lines(s: SILaw) -> list[str]:
    """``mechanisms: ...``, what the numbers leave out, and from which speed they are an
    upper bound without plastic flow (:mod:`restitution.laws.mechanisms`)."""
    fields = mechanism_fields(law_mechanisms(s.law))
    lines = [f"mechanisms: {'; '.join(fields['mechanisms'])}"]
    if fields["mechanisms_left_out"]:
        lines.append(f"not in these numbers: {'; '.join(fields['mechanisms_left_out'])}")
    bound, text = elastic_bound(s)
    if bound is not None:
        lines.append(f"from {bound:.2g} m/s: {text}")
    return lines
