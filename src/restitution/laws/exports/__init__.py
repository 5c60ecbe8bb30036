"""epsilon in the forms simulation codes read, in SI units.

Every export starts from an :class:`~restitution.laws.si_law.SILaw` (material, geometry, partner,
reduced-unit law) and carries, in its comments (:mod:`~restitution.laws.exports._heading`): the
material, the geometry and the body of the law (a cylinder or thin disk is served by the disk's
law, a sphere by the sphere's), what the speed means (wall or two grains), ``c``, the law's
source and the package version. One module per form:

* :mod:`~restitution.laws.exports.table`: :func:`speed_table` / :func:`write_table` /
  :func:`write_csv`: ``speed_m_s epsilon [epsilon_err]`` on a uniform grid of the interpolant,
  for codes that interpolate linearly between ``[v, e]`` pairs (AcuTrace style); the CSV adds
  ``v_over_c`` and the status.
* :mod:`~restitution.laws.exports.closed_form`: :func:`fit_closed_form`: the form
  ``epsilon(w) = 1 - a x^p / (1 + b x^p)``, ``x = w / (k c)``, fitted to the computed points
  (weighted by their errors), with covariance, maximum deviation and the range where it follows
  every point within its error (and only there).
* :mod:`~restitution.laws.exports.pchip`: :func:`pchip_table`: the law as a monotone
  piecewise-cubic table in m/s, which :mod:`~restitution.laws.exports.c_fortran`'s
  :func:`c_header` (C99) and :func:`fortran_include` (Fortran 2003) evaluate at every speed a
  grain meets: the table on the computed speeds, the slow-impact continuation
  (:mod:`~restitution.laws.exports.below`) below them down to ``w = 0``, NaN with a status
  above them (:class:`TableStatus`); their headers state the range, the maximum deviation from
  the law in its error bars and the continuation's error bound.
* :mod:`~restitution.laws.exports.constants`: :func:`constant_at` (epsilon at a reference
  speed) and :func:`maxwell_constant` (averaged over the impact speeds of a gas at a granular
  temperature; :func:`maxwell_temperatures` the temperatures a law averages): one number for
  codes that take a constant per pair.
* :mod:`~restitution.laws.exports.type_pairs`: :func:`type_pair_constants`: the constants of a
  bidisperse packing of one material (type 1 the small grain, type 2 the large): 1-1 and 2-2
  from the law of identical grains, 1-2 from the pair's law, each at the same reference speed or
  temperature (:class:`TypePairs`). Of two materials (type 1 this grain, type 2 the partner
  grain of its own material and size), 1-1 and 2-2 come from each material's law of identical
  grains, and the snippets give each type its own constants.
* :mod:`~restitution.laws.exports.dem`: a snippet per DEM code taking a :class:`Constant` or a
  :class:`TypePairs`, one module per code registering itself in :data:`DEM_TARGETS`: LAMMPS
  ``pair_style granular`` or, against a wall, ``fix wall/gran granular``
  (:func:`lammps_snippet`), LIGGGHTS, MercuryDPM and YADE.
* :mod:`~restitution.laws.exports.folder`: :func:`write_folder`: all of the above for one law
  into one folder, a snippet per registered DEM target.

The speed ``w`` of a law of two grains of different sizes (``SILaw.law.partner``) is their
relative normal speed; every header says so (:attr:`SILaw.against_meaning`).
"""

from __future__ import annotations

from restitution.laws.exports.below import SlowContinuation, slow_continuation
from restitution.laws.exports.c_fortran import c_header, fortran_include
from restitution.laws.exports.closed_form import ClosedForm, fit_closed_form
from restitution.laws.exports.constants import (
    Constant,
    constant_at,
    distribution_constant,
    maxwell_constant,
    maxwell_temperatures,
)
from restitution.laws.exports.dem import DEM_TARGETS, DemTarget, register_dem_target
from restitution.laws.exports.dem.lammps import lammps_snippet
from restitution.laws.exports.dem.liggghts import liggghts_snippet
from restitution.laws.exports.dem.mercurydpm import mercurydpm_snippet
from restitution.laws.exports.dem.yade import yade_snippet
from restitution.laws.exports.folder import ExportFolder, write_folder
from restitution.laws.exports.pchip import PchipTable, TableStatus, pchip_table
from restitution.laws.exports.table import speed_table, write_csv, write_table
from restitution.laws.exports.type_pairs import (
    SAME_SIZE_NOTE,
    TWO_MATERIALS_NOTE,
    TypePairs,
    type_pair_constants,
)

__all__ = [
    "DEM_TARGETS",
    "SAME_SIZE_NOTE",
    "TWO_MATERIALS_NOTE",
    "ClosedForm",
    "Constant",
    "DemTarget",
    "ExportFolder",
    "PchipTable",
    "SlowContinuation",
    "TableStatus",
    "TypePairs",
    "c_header",
    "constant_at",
    "distribution_constant",
    "fit_closed_form",
    "fortran_include",
    "liggghts_snippet",
    "lammps_snippet",
    "maxwell_constant",
    "maxwell_temperatures",
    "mercurydpm_snippet",
    "pchip_table",
    "register_dem_target",
    "slow_continuation",
    "speed_table",
    "type_pair_constants",
    "write_csv",
    "write_folder",
    "write_table",
    "yade_snippet",
]
