"""The law per contact in an export folder: the plugin's files for grains of any sizes.

An export's tables hold ``epsilon(w)`` for the radii the law was made for; a bed with a
continuous size distribution needs each contact's own law, which the plugin evaluates at first
touch from the contact's radii, masses, ``E*`` and impact speed
(:mod:`~restitution.laws.exports.contact_law`, docs/lammps-plugin.md, "A law per contact").
:func:`any_size_files` writes one such file per contact kind of the export (each pair of grain
types, each type on the wall) where the package has that law: spheres, their elastic waves and
Kelvin-Voigt damping, on each other and on the rigid wall. Elsewhere it says why not (the
folder's tables still serve the exported radii). SI units.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from restitution.errors import InputError
from restitution.laws.exports._heading import _header
from restitution.laws.exports.contact_file import contact_law_file
from restitution.laws.exports.contact_law import pair_contact_law, wall_contact_law
from restitution.laws.mechanisms.bounds import law_mechanisms, wall_of

__all__ = [
    "ANY_SIZE_INPUT", "AnySize", "any_size_files", "any_size_header", "contact_file_name"
]  # fmt: skip

ANY_SIZE_INPUT = "epsilon_lammps_plugin_any_size.in"
"""The input lines that load the laws per contact, in an export folder."""

_CARRIED = {"waves", "viscous"}
"""The mechanisms the law per contact holds (the rest: plastic flow, adhesion, an elastic
wall's radiation, are tabulated for the exported radii only)."""


def contact_file_name(i: int, j: int) -> str:
    """The file of the law per contact of types ``i``-``j`` (``j = 0``: type ``i`` on the
    wall)."""
    return f"epsilon_lammps_plugin_wall{i}.law" if j == 0 else f"epsilon_lammps_plugin_{i}{j}.law"


@dataclass(frozen=True)
class AnySize:
    """The laws per contact of an export: ``files`` (``{file name: text}``), ``names``
    (``(i, j) -> file name``, ``j = 0`` the wall) and, where there are none, ``why``."""

    files: dict = field(default_factory=dict)
    names: dict = field(default_factory=dict)
    why: str = ""


def any_size_files(
    s, system, relaxation_time_s: float | None, why_not: str | None = None
) -> AnySize:
    """The laws per contact of the export of ``s`` (an :class:`~restitution.laws.si_law.SILaw`)
    for the contacts of ``system`` (:class:`~restitution.laws.exports.plugin_files.
    SystemContacts`): every pair of its grain types (1-1, and with two materials 1-2 and 2-2)
    and each type on the wall. ``relaxation_time_s``: the Kelvin-Voigt time of a damped law
    (s; ``None`` for an elastic one); ``why_not``: the caller's reason for none."""
    if why_not is not None:
        return AnySize(why=why_not)
    extra = sorted(set(law_mechanisms(s.law)) - _CARRIED)
    if extra:
        left = ", ".join(extra)
        return AnySize(why=f"the law per contact holds the waves and damping, not {left}")
    damped = "viscous" in law_mechanisms(s.law)
    if damped and relaxation_time_s is None:
        return AnySize(why="the damped law's relaxation time in seconds needs the grain's "
                           "radius (--radius)")  # fmt: skip
    tau = relaxation_time_s if damped else 0.0
    walls = [i for i, j in system.laws if j == 0]
    if any(wall_of(system.laws[i, 0].law) is not None for i in walls):
        return AnySize(why="an elastic wall: the law per contact is the rigid wall's")
    # One material: every pair of types (two sizes of it) takes the one law of that material;
    # two: each pair of materials its own. Two types: every pair of them (1-1, 1-2, 2-2), also
    # where the tables hold 1-2 only (LAMMPS stops on a type pair without a file).
    two = system.two_materials
    material = (lambda i: i) if two else (lambda i: 1)
    keys = [key for key in system.laws if key[1] != 0]
    if any(2 in key for key in keys):
        keys = [(1, 1), (1, 2), (2, 2)]
    laws = {}
    try:
        for i, j in keys:
            a, b = material(i), material(j)
            if (a, b) not in laws:
                partner = None if a == b else system.grains[b]
                laws[a, b] = pair_contact_law(system.grains[a], partner, relaxation_time_s=tau)
        for i in walls:
            laws[material(i), 0] = wall_contact_law(system.grains[i], relaxation_time_s=tau)
    except InputError as exc:
        return AnySize(why=str(exc))
    names = {(i, j): contact_file_name(material(i), material(j) if j else 0) for i, j in keys}
    names.update({(i, 0): contact_file_name(material(i), 0) for i in walls})
    comments = any_size_header(s, tau)
    files = {
        contact_file_name(*key): contact_law_file(law, [*comments, _who(*key)])
        for key, law in laws.items()
    }
    return AnySize(files, names)


def any_size_header(s, tau: float) -> list[str]:
    """The comment lines of the laws per contact of ``s``'s export: the package, the materials
    and what the law per contact holds (not the exported law's speeds and radius, which it does
    not depend on)."""
    keep = ("restitution ", "grain:", "material:", "partner material:", "mechanisms:",
            "not in these numbers:", "from ")  # fmt: skip
    lines = [line for line in _header(s) if line.startswith(keep)]
    damping = f"Kelvin-Voigt relaxation time {tau:.6g} s" if tau > 0 else "no damping"
    return [
        *lines,
        f"law per contact (docs/lammps-plugin.md, 'A law per contact'): {damping}; each "
        "contact's epsilon from its own radii, masses, E* and impact speed, within the reach of "
        "the package's low-speed route (beyond it the run stops naming the contact)",
    ]


def _who(i: int, j: int) -> str:
    return f"contact: material {i} on the wall" if j == 0 else f"contact: materials {i}-{j}"
