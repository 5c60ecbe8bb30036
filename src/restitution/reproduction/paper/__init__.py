"""Regenerate the paper: every computed figure, Table 1, and a comparison with its claims.

Gerl and Zippelius, "Coefficient of restitution for elastic disks". The package is split by
job:

* :mod:`~restitution.reproduction.paper.settings`: sizes of every computation (:data:`FULL`,
:data:`QUICK`)
  and the units the paper's speeds are read in (``c`` and ``c_L``);
* :mod:`~restitution.reproduction.paper.compute`: the sweep of section 4, the extrapolated curves
and the
  data of Figs. 1-3, 5-8, 10-12 and Table 1 (:func:`compute_paper`);
* :mod:`restitution.reproduction.claims`: every claim of the paper judged against those data;
* :mod:`~restitution.reproduction.paper.files`: figures, Table 1, law exports and JSON writing;
* :mod:`~restitution.reproduction.paper.report`: the report's content as blocks, rendered by
  :mod:`restitution.reproduction.report`;
* :mod:`~restitution.reproduction.paper.build`: :func:`build_paper`, the orchestration behind
  ``restitution paper``; :mod:`restitution.reproduction.report` renders the report.

Units: two-dimensional ``E = rho = R = 1``, speeds in ``c = sqrt(E/rho)`` (the disk's speed
towards the wall) unless labelled ``c_L``, times in ``R/c``, forces in ``E R``, energies as
fractions of the initial kinetic energy ``(m/2) v^2``.
"""

from __future__ import annotations

from restitution.reproduction.claims import Comparison, compare
from restitution.reproduction.paper.build import PaperRun, build_paper
from restitution.reproduction.paper.compute import (
    STAGES,
    PaperData,
    StageEvent,
    compute_paper,
    speed_unit_sweep,
    sweep_contact_times,
)
from restitution.reproduction.paper.files import (
    FIGURE_STEMS,
    FigureFile,
    LawExport,
    write_figures,
    write_law_exports,
    write_table1,
)
from restitution.reproduction.paper.settings import (
    FULL,
    QUICK,
    SPEED_UNITS,
    PaperSettings,
    speed_factor,
)

__all__ = [
    "FIGURE_STEMS",
    "FULL",
    "QUICK",
    "SPEED_UNITS",
    "STAGES",
    "Comparison",
    "FigureFile",
    "LawExport",
    "PaperData",
    "PaperRun",
    "PaperSettings",
    "StageEvent",
    "build_paper",
    "compare",
    "compute_paper",
    "speed_factor",
    "speed_unit_sweep",
    "sweep_contact_times",
    "write_figures",
    "write_law_exports",
    "write_table1",
]
