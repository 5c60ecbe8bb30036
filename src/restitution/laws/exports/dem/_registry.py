"""The registry of DEM codes the exports write snippets for: one :class:`DemTarget` per code.

Each code's module in :mod:`restitution.laws.exports.dem` registers its target on import
(:func:`register_dem_target`); the export folder (:mod:`restitution.laws.exports.folder`) writes
one file per entry of :data:`DEM_TARGETS`, in registration order, reading the entry's attributes.
The snippets are text in SI units.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["DEM_TARGETS", "DemTarget", "register_dem_target"]


@dataclass(frozen=True)
class DemTarget:
    """A DEM code the exports write a snippet for.

    Attributes
    ----------
    name : str
        Its key in :data:`DEM_TARGETS` (``"lammps"``).
    file_name : str
        The snippet's file in an export folder, after the stem and ``_``
        (``"lammps.in"`` -> ``epsilon_lammps.in``).
    snippet : callable
        ``snippet(s, c) -> str``: the code's input lines for the law ``s``
        (:class:`~restitution.laws.si_law.SILaw`) and the constant ``c``
        (:class:`~restitution.laws.exports.constants.Constant`, or the
        :class:`~restitution.laws.exports.type_pairs.TypePairs` of ``s``), SI units; with a
        keyword ``friction`` (Coulomb's ``mu`` or ``None``) when the code's snippet can set
        the user's friction (all shipped ones do).
    viscoelastic : callable or None
        ``viscoelastic(s, model) -> str``: the code's input lines that carry a damped sphere
        law in its own viscoelastic contact
        (:class:`~restitution.laws.exports.viscoelastic.Viscoelastic`), the velocity dependence
        instead of a constant; ``None`` when the code has no such model.
    time_step : callable or None
        ``time_step(steps, viscoelastic) -> list of str``: the lines that set the code's time
        step for the contacts of the export (``steps``, a
        :class:`~restitution.laws.exports.time_step.TimeSteps`): comments with each contact's
        time and, where the grains' radius is known, the code's own command; ``viscoelastic``
        says whether the snippet is the code's viscoelastic one. ``None``: the export adds
        nothing on the step.
    plastic : callable or None
        ``plastic(s) -> list of str``: comment lines on the code's own elastic-plastic contact
        for a law with plastic flow (:mod:`restitution.laws.exports.plastic_native`): how far it
        is from the package's law, or that the code has none. ``None``: nothing said.
    """

    name: str
    file_name: str
    snippet: Callable[..., str]
    viscoelastic: Callable[..., str] | None = None
    time_step: Callable[..., list[str]] | None = None
    plastic: Callable[..., list[str]] | None = None


DEM_TARGETS: dict[str, DemTarget] = {}
"""Every registered DEM target by name, in registration order."""


def register_dem_target(target: DemTarget) -> DemTarget:
    """Add ``target`` to :data:`DEM_TARGETS` and return it (a code's module calls this once).

    Raises
    ------
    ValueError
        When its name or its file name is taken by a registered target (two codes would write
        one file).
    """
    for other in DEM_TARGETS.values():
        if target.name == other.name or target.file_name == other.file_name:
            raise ValueError(
                f"DEM target {target.name!r} ({target.file_name}) clashes with the registered "
                f"{other.name!r} ({other.file_name}); give it its own name and file name"
            )
    DEM_TARGETS[target.name] = target
    return target
