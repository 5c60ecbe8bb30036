"""The file of the LAMMPS plugin's law per contact (docs/lammps-plugin.md, "A law per contact"):
the text ``pair_coeff i j E* FILE`` and ``fix ... wall/restitution E* FILE ...`` read when its
first line is ``restitution-contact 1``, or ``restitution-contact 2`` for a law with plastic flow
(a ``restitution-table 1`` is the table per type pair). A law without plastic flow is written as
version 1, byte for byte as before; the plugin reads both.

Grammar (``contact_law.h``; ``#`` starts a comment line, numbers with 17 significant digits)::

    restitution-contact 1
    units si
    contact pair | contact wall
    relaxation-time TAU_S                       Kelvin-Voigt relaxation time, s (0: elastic)
    viscous-map N C1 C2 H                       epsilon_v(q); below the first knot the series
    ln_q epsilon_v depsilon_v_dlnq              N rows      1 - C1 q + C2 q^2 + H q^(5/2)
    # a pair: one section per material (1: both grains; 2: type i's, then type j's)
    materials K
    material E_PA NU RHO_KG_M3
    reach X_LO WIDTH_MAX                        the route's reach (contact_law.py)
    loss-knots N
    x G dG_dx                                   N rows, x evenly spaced from X_LO
    beyond power P                              G = G_N (x_N / x)^P above the last knot
    # a wall: the elastic law of the grain on the wall, as the table per type pair
    knots N
    w_m_s epsilon slope_s_m                     N rows
    below power L0 w0 q | below log L0 w0 ws p
    beta-map M                                  Tsuji's beta(epsilon)
    epsilon beta dbeta_dlnepsilon               M rows
    end

Version 2 (plastic flow) adds, after the relaxation time's viscous map, ::

    plastic-flow P_Y_PA                         Thornton's limiting pressure, Pa
    material E_PA NU RHO_KG_M3                  (a wall only: the grain's, for x = t_c c / R)

and, before the beta-map, the wave ratio ``r(x, u)`` of the (one) material::

    wave-ratio K ETA_STEP                       K knots in eta = arccosh(u), ETA_STEP apart from 0
    eta-knot ETA                                K times, each followed by
    ratio-knots N                               N rows
    x r dr_dx
"""

from __future__ import annotations

from collections.abc import Sequence

from restitution.errors import InputError
from restitution.laws.exports.contact_law import PairContactLaw, WallContactLaw
from restitution.laws.exports.lammps_plugin import (
    TSUJI_EPSILON_MIN,
    _continuation_line,
    _number,
    tsuji_map,
)
from restitution.laws.exports.sphere_loss import BEYOND_POWER

__all__ = ["CONTACT_FORMAT", "PLASTIC_CONTACT_FORMAT", "contact_law_file"]

CONTACT_FORMAT = "restitution-contact 1"
"""The first line of a file of the law per contact."""

PLASTIC_CONTACT_FORMAT = "restitution-contact 2"
"""The first line of a file of the law per contact with plastic flow."""


def _rows(*columns) -> list[str]:
    return [" ".join(_number(v) for v in row) for row in zip(*columns, strict=True)]


def _viscous_lines(law) -> list[str]:
    v = law.viscous
    c1, c2, h = v.series
    return [
        f"relaxation-time {_number(law.relaxation_time_s)}",
        "# epsilon_v(q), q = (3/2) tau (K / m*)^(2/5) w^(1/5), K = (4/3) E* sqrt(R*): cubic "
        "Hermite in ln q;",
        "# below the first knot 1 - C1 q + C2 q^2 + H q^(5/2); no value above the last",
        f"viscous-map {v.u.size} {_number(c1)} {_number(c2)} {_number(h)}",
        "# ln_q epsilon_v depsilon_v_dlnq",
        *_rows(v.u, v.epsilon, v.slope),
    ]


def _plastic_lines(law, material: bool) -> list[str]:
    p = law.plastic
    lines = [
        "# plastic flow: Thornton's contact of limiting pressure P_Y (" + p.source + "); yield",
        "# speed v_y = sqrt((pi^5 / 30) P_Y^5 R*^3 / (E*^4 m*)), u = w / v_y; epsilon^2 =",
        "# epsilon_T(u)^2 - (the waves, each sphere's loss times r(x, u))",
        f"plastic-flow {_number(p.limiting_pressure_pa)}",
    ]
    if material:
        g = law.grain
        lines.append(f"material {_number(g.E)} {_number(g.nu)} {_number(g.rho)}")
    return lines


def _ratio_lines(waves) -> list[str]:
    lines = [
        "# r(x, u): the plastic pulse's Rayleigh sum over Hertz's; cubic Hermite in x at the four",
        "# nearest knots in eta = arccosh(u), Lagrange's cubic through them in eta; 1 for u <= 1",
        f"wave-ratio {waves.eta.size} {_number(waves.eta[1] - waves.eta[0])}",
    ]
    for j, eta in enumerate(waves.eta):
        lines += [f"eta-knot {_number(eta)}", f"ratio-knots {waves.x.size}"]
        lines += _rows(waves.x, waves.ratio[j], waves.slope[j])
    return lines


def _pair_lines(law: PairContactLaw) -> list[str]:
    one = law.grains[0] == law.grains[1]
    pairs = list(zip(law.grains, law.losses, strict=True))[: 1 if one else 2]
    lines = [
        "# the elastic waves: L_el = (m*/m1) G1(x1) + (m*/m2) G2(x2), x_i = t_c c_i / R_i,",
        "# t_c = 2.9432752 delta_max / w (Hertz), c_i = sqrt(E_i / rho_i); each material's G",
        "# (Rayleigh's estimate summed over its lowest modes) cubic Hermite in x",
        f"materials {len(pairs)}",
    ]
    for grain, loss in pairs:
        lines += [
            f"material {_number(grain.E)} {_number(grain.nu)} {_number(grain.rho)}",
            "# the route's reach: x >= X_LO for each grain, contact radius / smaller radius "
            "<= WIDTH_MAX",
            f"reach {_number(loss.x_lo)} {_number(loss.width_max)}",
            f"loss-knots {loss.x.size}",
            "# x G dG_dx",
            *_rows(loss.x, loss.g, loss.slope),
            f"beyond power {_number(BEYOND_POWER)}",
        ]
    if law.plastic is not None:
        lines += _ratio_lines(law.plastic.waves)
    return lines


def _wall_lines(law: WallContactLaw) -> list[str]:
    t = law.wall
    return [
        "# the elastic waves: the grain's law on the wall, epsilon(w), cubic Hermite between",
        f"# the knots; {t.below.describe()}",
        f"knots {t.w_m_s.size}",
        "# w_m_s epsilon slope_s_m",
        *_rows(t.w_m_s, t.epsilon, t.slope_s_m),
        _continuation_line(t.below),
        *([] if law.plastic is None else _ratio_lines(law.plastic.waves)),
    ]


def contact_law_file(law: PairContactLaw | WallContactLaw, comments: Sequence[str]) -> str:
    """The text of the plugin's file of ``law`` (module docs for the grammar).

    Parameters
    ----------
    law : PairContactLaw or WallContactLaw
        :func:`~restitution.laws.exports.contact_law.pair_contact_law` (``pair_coeff``) or
        :func:`~restitution.laws.exports.contact_law.wall_contact_law` (``fix
        wall/restitution``).
    comments : list of str
        Provenance lines, written first as comments.

    Returns
    -------
    str
        The file's text (a pair's: some 370 kB for one material, the curve's 4900 knots).
    """
    if isinstance(law, PairContactLaw):
        kind, body = "pair", _pair_lines(law)
    elif isinstance(law, WallContactLaw):
        if law.wall.epsilon.min() < TSUJI_EPSILON_MIN:
            raise InputError(
                f"the wall law's epsilon reaches {law.wall.epsilon.min():.4g}, below the plugin's "
                f"least {TSUJI_EPSILON_MIN}"
            )
        kind, body = "wall", _wall_lines(law)
    else:
        raise InputError(
            f"law must be a PairContactLaw or a WallContactLaw, got {type(law).__name__}"
        )
    m = tsuji_map()
    lines = [f"# {part}" for c in comments for part in str(c).splitlines() or [""]]
    plastic = law.plastic is not None
    lines += [
        "# LAMMPS plugin law per contact (docs/lammps-plugin.md, 'A law per contact'):",
        "# pair_style restitution / fix wall/restitution read it. At a contact's first touch",
        "# 1 - epsilon^2 = L_el + L_v from the contact's own radii, masses, E* and impact speed w",
        "# (m/s); Tsuji's beta(epsilon) is then kept for the contact.",
        PLASTIC_CONTACT_FORMAT if plastic else CONTACT_FORMAT,
        "units si",
        f"contact {kind}",
        *_viscous_lines(law),
        *(_plastic_lines(law, isinstance(law, WallContactLaw)) if plastic else []),
        *body,
        "# beta(epsilon) of Tsuji's damping: cubic Hermite in ln(epsilon)",
        f"beta-map {m.epsilon.size}",
        "# epsilon beta dbeta_dlnepsilon",
        *_rows(m.epsilon, m.beta, m.slope),
        "end",
    ]
    return "\n".join(lines) + "\n"
