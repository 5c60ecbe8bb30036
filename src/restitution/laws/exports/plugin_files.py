"""The LAMMPS plugin's files of one export: a table per contact and the input lines that load
them (docs/lammps-plugin.md).

The plugin (:mod:`~restitution.laws.exports.lammps_plugin`) carries the whole law, every speed,
per contact; an export folder holds, beside the constants' snippets, the plugin's table of the
law's contact and, for a :class:`~restitution.laws.exports.type_pairs.TypePairs`, of each type
pair (1-1 and 2-2 from the laws of identical grains), and ``epsilon_lammps_plugin.in`` with the
``plugin load``, ``pair_style``/``pair_coeff`` or ``fix wall/restitution`` lines. An export of
grains also carries each material's law on the rigid wall (the shipped law of that grain on a
wall, whatever its size): one folder for a system of walls and grains. SI units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.errors import InputError
from restitution.laws.exports._heading import _header
from restitution.laws.exports.any_size import (
    ANY_SIZE_INPUT,
    any_size_files,
    any_size_header,
)
from restitution.laws.exports.dem.lammps import lammps_time_step
from restitution.laws.exports.lammps_plugin import (
    PLUGIN_NAME,
    PluginFriction,
    PluginWall,
    contact_modulus,
    contact_shear_modulus,
    lammps_plugin_input,
    plugin_table,
)
from restitution.laws.exports.pchip import pchip_table
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.mechanisms.bounds import wall_of
from restitution.laws.partners.base import partner_of
from restitution.laws.partners.rigid_wall import KIND as WALL
from restitution.laws.si_law import si_law

__all__ = ["INPUT_NAME", "SystemContacts", "plugin_files", "system_contacts"]

INPUT_NAME = "epsilon_lammps_plugin.in"
"""The input lines' file in an export folder."""


def _table_name(i: int, j: int) -> str:
    return f"epsilon_lammps_plugin_wall{i}.table" if j == 0 else (
        f"epsilon_lammps_plugin_{i}{j}.table"
    )  # fmt: skip


@dataclass(frozen=True)
class SystemContacts:
    """The contacts of the system an export serves, each with its law (SI units).

    Attributes
    ----------
    laws : dict
        ``(i, j) -> SILaw`` per pair of particle types (``i <= j``) and ``(i, 0)`` for type
        ``i`` on the wall, in the order the plugin writes their tables.
    grains : dict
        ``type -> Grain`` (material and geometry of each particle type).
    missing : list of str
        The contacts without a law, each with why (a grain's wall law that could not be had).
    two_materials : bool
        Whether the types are of two materials (one wall fix per type's group).
    """

    laws: dict
    grains: dict
    missing: list
    two_materials: bool

    def _partner(self, i: int, j: int) -> tuple[float, float]:
        """``E`` (Pa) and ``nu`` of what type ``i`` meets in the contact ``(i, j)``: grain
        ``j``'s material, or for ``j = 0`` the wall of type ``i``'s law (an elastic wall's
        material, else rigid: ``inf``, 0)."""
        if j != 0:
            return self.grains[j].E, self.grains[j].nu
        law = self.laws.get((i, 0), self.laws.get((1, 0)))  # one wall for every type
        elastic = wall_of(law.law) if law is not None else None
        if elastic is None:
            return math.inf, 0.0
        return float(elastic["modulus_ratio"]) * self.grains[i].E, float(elastic["nu"])

    def contact_modulus(self, i: int, j: int) -> float:
        """``E*`` (Pa) of the contact ``(i, j)``: two grains' materials, or type ``i`` on the
        wall of its law (an elastic wall's material, else rigid)."""
        a = self.grains[i]
        return contact_modulus(a.E, a.nu, *self._partner(i, j))

    def contact_shear_modulus(self, i: int, j: int) -> float:
        """Mindlin's ``G*`` (Pa) of the contact ``(i, j)``, as :meth:`contact_modulus`."""
        a = self.grains[i]
        return contact_shear_modulus(a.E, a.nu, *self._partner(i, j))


def system_contacts(s, c=None, walls=None) -> SystemContacts:
    """The contacts of the system the law ``s`` (an :class:`~restitution.laws.si_law.SILaw`)
    and, for grains of two sizes or materials, the :class:`TypePairs` ``c`` (their 1-1 and 2-2
    laws) serve: the law's own contact; for grains, also each material on the wall (the
    shipped law of that grain on a wall, whatever its size, or ``walls``: the law of each grain
    type on the wall as the answer's mechanisms make it, ``{type: SILaw}``, or a sentence why
    there is none)."""
    g = s.grain
    laws = {}
    partner = partner_of(s)
    if not partner.is_grain:
        laws[1, 0] = s
    elif isinstance(c, TypePairs):
        laws[1, 1], laws[1, 2] = c.identical, s
        laws[2, 2] = c.identical2 if c.two_materials else c.identical
    elif s.law.partner is not None:
        laws[1, 2] = s
    else:
        laws[1, 1] = s
    two = isinstance(c, TypePairs) and c.two_materials
    grains = {1: g, 2: s.partner_grain or g}
    missing = []
    if partner.is_grain:  # each material on the wall too: one folder for the system
        for i in (1, 2) if two else (1,):
            given = (walls or {}).get(i)
            if isinstance(given, str):
                missing.append(f"type {i} on the wall: {given}")
                continue
            try:
                if given is None:
                    given = si_law(grain=grains[i], against=WALL.against)
                laws[i, 0] = given
            except InputError as exc:
                missing.append(f"type {i} on the wall: {exc}")
    return SystemContacts(laws, grains, missing, two)


def plugin_files(
    s, c=None, walls=None, steps=None, relaxation_time_s=None, no_contact=None, friction=None
) -> dict[str, str]:
    """``{file name: text}`` of the plugin's tables and input lines for the law ``s`` (an
    :class:`~restitution.laws.si_law.SILaw`) and, for grains of two sizes or materials, the
    :class:`TypePairs` ``c`` (their 1-1 and 2-2 laws); a ``Constant`` or ``None`` adds nothing.
    ``walls``: the law of each grain type on the wall as the answer's mechanisms make it
    (``{type: SILaw}``, or a sentence why there is none), instead of the shipped elastic law of
    the grain on a wall: a damped grain's wall table is damped (:func:`system_contacts`).
    ``steps``: the contacts' time steps
    (:class:`~restitution.laws.exports.time_step.TimeSteps`), written after the lines.
    ``relaxation_time_s``: a damped law's Kelvin-Voigt time (s), for the laws per contact of
    spheres (:mod:`~restitution.laws.exports.any_size`), which the folder holds beside the
    tables where the package has them; ``no_contact``: why not, where the caller knows (a law
    given as a file). ``friction``: Coulomb's ``mu`` of every contact, carried beside the
    plugin by LAMMPS's granular Mindlin model (:class:`~restitution.laws.exports.lammps_plugin.
    PluginFriction`); ``None``: frictionless, and the lines say so.

    Raises
    ------
    InputError
        Where the plugin cannot carry the law (an epsilon below the map's range, a table
        without two knots): the message says why.
    """
    system = system_contacts(s, c, walls)
    files = {}
    for (i, j), law in system.laws.items():
        what = f"type {i} on the wall" if j == 0 else f"types {i}-{j}"
        files[_table_name(i, j)] = plugin_table(pchip_table(law), [*_header(law),
                                                                   f"contact: {what}"])  # fmt: skip
    lines = [f"# {line}" for line in _header(s)]
    sizes = any_size_files(s, system, relaxation_time_s, no_contact)
    if sizes.files:
        lines.append(f"# grains of any sizes: {ANY_SIZE_INPUT} (the law per contact) in place "
                     "of this file's tables, which hold the exported radii only")  # fmt: skip
    else:
        lines.append(f"# no law per contact (grains of any sizes): {sizes.why}")
    tables = {key: _table_name(*key) for key in system.laws}
    files[INPUT_NAME] = _input(s, system, tables, steps, lines, friction)
    if sizes.files:
        files.update(sizes.files)
        head = [f"# {line}" for line in any_size_header(s, relaxation_time_s or 0.0)] + [
            "# the time step below is for the exported radius: Hertz's contact time goes as the",
            "# radius at a given speed, so scale it by your smallest radius over that one",
        ]  # fmt: skip
        files[ANY_SIZE_INPUT] = _input(s, system, sizes.names, steps, head, friction)
    return files


def _input(s, system: SystemContacts, names: dict, steps, lines: list[str], friction=None) -> str:
    """The input lines of the plugin for the contacts ``names`` (``(i, j) -> file``, ``j = 0``
    the wall) of ``system``, after the comment ``lines``; ``friction``: Coulomb's ``mu`` of
    every contact, or ``None``."""
    missing, two = system.missing, system.two_materials
    # A 2D run (a disk's law) has its wall along y: LAMMPS's 2D plane is x-y.
    plane = "yplane" if s.grain.kind.planar else "zplane"
    pairs, walls = {}, []
    for (i, j), name in names.items():
        if j == 0:
            group, fix_id = (f"restitution_type{i}", f"wall{i}") if two else ("all", "wall")
            estar = system.contact_modulus(i, 0)
            walls.append((i, PluginWall(estar, name, plane=plane, group=group, fix_id=fix_id)))
        else:
            pairs[i, j] = (system.contact_modulus(i, j), name)
    lines = list(lines)
    lines += [
        f"# the plugin: build it with `restitution lammps-plugin --out DIR` and put {PLUGIN_NAME}",
        "# here (or give its path after plugin load); the tables are read from where LAMMPS runs;",
        "# the wall: a static plane at 0 with the grains on its + side (change it to yours)",
    ]
    if not pairs:
        lines.append(
            "# grain-grain contacts need the law of two grains (--against grain): this export "
            "holds the wall's only"
        )
    elif (1, 2) in pairs and (1, 1) not in pairs:
        lines.append(
            "# only the 1-2 contact's table: give --reference-speed or --maxwell-temperature "
            "to export 1-1 and 2-2 too (LAMMPS stops on a type pair without a table)"
        )
    lines += [f"# no table for {m}" for m in missing]
    # Two materials: one wall fix per type's group.
    lines += [f"group {w.group} type {i}" for i, w in walls if w.group != "all"]
    # "./": dlopen looks for a bare file name on the library path, not where LAMMPS runs.
    rub = None
    if friction is not None:
        rub = PluginFriction(
            float(friction),
            {key: system.contact_shear_modulus(*key) for key in pairs},
            {w.fix_id: system.contact_shear_modulus(i, 0) for i, w in walls},
        )
    body = lammps_plugin_input(f"./{PLUGIN_NAME}", pairs, [w for _, w in walls], rub)
    if steps is not None:
        body += "\n".join(lammps_time_step(steps)) + "\n"
    return "\n".join(lines) + "\n" + body
