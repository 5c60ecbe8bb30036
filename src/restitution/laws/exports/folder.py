"""The export folder: every file of one law written as a set, the DEM snippets from the registry.

:func:`write_folder` writes, into one folder, the table (``epsilon_table.txt``), the CSV
(``epsilon.csv``), the closed form where it follows the points (``epsilon_closed_form.json``),
the C header and the Fortran include that evaluate the law's table (``epsilon.h``,
``epsilon.f90``) and, given a constant or a damped sphere law's viscoelastic model
(:class:`~restitution.laws.exports.viscoelastic.Viscoelastic`), one snippet per registered DEM
target (:data:`~restitution.laws.exports.dem.DEM_TARGETS`, ``epsilon_<file_name>``): the
code's own viscoelastic contact where it has one and a model is given, else the constant; and
the LAMMPS plugin's tables and input lines, which carry the whole law per contact
(:mod:`~restitution.laws.exports.plugin_files`). Every snippet and the plugin's lines end with
the time step of each contact type (:mod:`~restitution.laws.exports.time_step`), set where the
grains' radius is known. Speeds in m/s, every file in SI units; each file is written whole or
not at all (:mod:`restitution.atomic`).
"""

from __future__ import annotations

import inspect
import json
from dataclasses import dataclass
from pathlib import Path

from restitution import atomic
from restitution.errors import InputError, RestitutionError
from restitution.file_set import file_set
from restitution.laws.exports.c_fortran import c_header, fortran_include
from restitution.laws.exports.closed_form import ClosedForm, fit_closed_form
from restitution.laws.exports.constants import Constant
from restitution.laws.exports.dem import DEM_TARGETS
from restitution.laws.exports.plugin_files import plugin_files
from restitution.laws.exports.table import write_csv, write_table
from restitution.laws.exports.time_step import TimeSteps, time_steps
from restitution.laws.exports.type_pairs import TypePairs
from restitution.laws.si_law import SILaw

__all__ = ["ExportFolder", "write_folder"]


def _with_friction(target, make, s, what, friction: float) -> str:
    """``make(s, what, friction=friction)``, refused in one line for a target whose snippet
    takes no friction."""
    if "friction" not in inspect.signature(make).parameters:
        raise InputError(
            f"the DEM target {target.name!r} sets no friction; leave out --friction, or give "
            "its snippet a friction argument"
        )
    return make(s, what, friction=friction)


@dataclass(frozen=True)
class ExportFolder:
    """What :func:`write_folder` wrote.

    Attributes
    ----------
    paths : tuple of pathlib.Path
        The files, in the order written.
    closed_form : ClosedForm or None
        The fitted closed form; ``None`` when none follows the points within their errors.
    no_closed_form : str or None
        Why no closed form was written (the fit's refusal), else ``None``.
    no_plugin : str or None
        Why no LAMMPS plugin tables were written (the plugin cannot carry the law), else
        ``None``.
    time_steps : TimeSteps or None
        The time step of each contact type that the snippets and the plugin's lines carry.
    """

    paths: tuple[Path, ...]
    closed_form: ClosedForm | None
    no_closed_form: str | None
    no_plugin: str | None = None
    time_steps: TimeSteps | None = None


def write_folder(
    s: SILaw,
    constant: Constant | TypePairs | None,
    out: Path,
    viscoelastic=None,
    friction: float | None = None,
    walls=None,
    radius_m: float | None = None,
    no_contact: str | None = None,
) -> ExportFolder:
    """Write the tables and closed form of ``s`` and, with ``constant`` (a ``Constant`` or the
    ``TypePairs`` of ``s``) or ``viscoelastic`` (a damped sphere law's
    :class:`~restitution.laws.exports.viscoelastic.Viscoelastic`, which a code with its own
    viscoelastic contact takes instead), a snippet per registered DEM target into ``out``
    (created if missing), as one set (:func:`restitution.file_set.file_set`): a failure leaves
    the folder as it was (``walls``: each grain type's law on the wall for the plugin's tables,
    :func:`~restitution.laws.exports.plugin_files.plugin_files`); files of an earlier export
    this one does not write (a closed form, snippets) are removed when they are unchanged, so
    the folder holds one law's files only; a file the package did not write (or one changed
    since) is never replaced or removed: the export is refused, naming it. ``radius_m``: the
    (type-1) grains' radius, m, for the time steps in seconds (default: the viscoelastic
    model's; without one the times are per millimetre of radius and no step is set).
    ``no_contact``: why the folder holds no law per contact of the plugin although the law's
    kind has one (a law given as a file), :mod:`~restitution.laws.exports.any_size`."""
    out = Path(out)
    # The three-parameter form exists only where it follows the points within their errors;
    # the C and Fortran evaluate the law's table either way.
    refusal = None
    try:
        fit = fit_closed_form(s)
    except RestitutionError as exc:
        fit = None
        refusal = str(exc)
    if radius_m is None and viscoelastic is not None:
        radius_m = viscoelastic.radii_m[1]
    steps = time_steps(s, constant, radius_m, walls)
    try:
        tau = None if viscoelastic is None else viscoelastic.relaxation_time_s
        plugin_args = (s, constant, walls, steps, tau, no_contact, friction)
        plugin, no_plugin = plugin_files(*plugin_args), None
    except InputError as exc:
        plugin, no_plugin = {}, str(exc)
    stem = "epsilon"
    names = [f"{stem}_table.txt", f"{stem}.csv"]
    with file_set(out, "export") as stage:
        write_table(s, stage / names[0])
        write_csv(s, stage / names[1])
        if fit is not None:
            names.append(f"{stem}_closed_form.json")
            atomic.write_text(stage / names[-1], json.dumps(fit.to_dict(), indent=1) + "\n")
        names += [f"{stem}.h", f"{stem}.f90"]
        atomic.write_text(stage / names[-2], c_header(s, fit))
        atomic.write_text(stage / names[-1], fortran_include(s, fit))
        for target in DEM_TARGETS.values():
            native = viscoelastic is not None and target.viscoelastic is not None
            if native:
                make, what = target.viscoelastic, viscoelastic
            elif constant is not None:
                make, what = target.snippet, constant
            else:
                continue
            text = make(s, what) if friction is None else _with_friction(target, make, s, what,
                                                                         friction)  # fmt: skip
            if target.time_step is not None:
                text = "\n".join([text.rstrip("\n"), *target.time_step(steps, native), ""])
            if target.plastic is not None and (lines := target.plastic(s)):
                text = "\n".join([text.rstrip("\n"), *lines, ""])
            names.append(f"{stem}_{target.file_name}")
            atomic.write_text(stage / names[-1], text)
        for name, text in plugin.items():
            names.append(name)
            atomic.write_text(stage / name, text)
    return ExportFolder(tuple(out / name for name in names), fit, refusal, no_plugin, steps)
