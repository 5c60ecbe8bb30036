"""The paper's claims beside this package's numbers, one module per section of the paper.

:func:`compare` takes the data of a paper run (:class:`restitution.reproduction.paper.PaperData`)
and returns one :class:`Comparison` per stated value or claim, with a verdict computed from the data
(:mod:`restitution.reproduction.claims.verdict`: agrees, differs or inconclusive).

Modules: :mod:`~restitution.reproduction.claims.sec2_modes` (Figs. 2, 3, eq. 20),
:mod:`~restitution.reproduction.claims.sec4_epsilon` (Figs. 1, 7, 8 and the conclusions' epsilon ~
0.65, once per speed unit), :mod:`~restitution.reproduction.claims.sec4_collisions` (Figs. 5, 6,
Table 1), :mod:`~restitution.reproduction.claims.sec5_quasistatic` (eq. 57, Figs. 10-12).
"""

from __future__ import annotations

from collections import Counter

from restitution.reproduction.claims.attributions import attributed
from restitution.reproduction.claims.sec2_modes import breathing_roots, mode_rows
from restitution.reproduction.claims.sec4_collisions import collision_rows, table1_rows
from restitution.reproduction.claims.sec4_epsilon import epsilon_rows, fit_rows
from restitution.reproduction.claims.sec5_quasistatic import quasistatic_rows
from restitution.reproduction.claims.verdict import AGREES, DIFFERS, INCONCLUSIVE, Comparison

__all__ = [
    "AGREES",
    "DIFFERS",
    "INCONCLUSIVE",
    "Comparison",
    "breathing_roots",
    "compare",
    "counts",
]


def compare(data) -> tuple[Comparison, ...]:
    """Every stated value or claim of the paper beside ours, with a verdict.

    Parameters
    ----------
    data : restitution.reproduction.paper.PaperData
    """
    return attributed(
        epsilon_rows(data.fig01_units)
        + fit_rows(data.fig07, data.fig08)
        + mode_rows(data)
        + collision_rows(data)
        + table1_rows(data)
        + quasistatic_rows(data)
    )


def counts(comparisons) -> dict[str, int]:
    """Number of rows per outcome: ``{"agrees": a, "differs": d, "inconclusive": i}``."""
    c = Counter(x.outcome for x in comparisons)
    return {k: c.get(k, 0) for k in (AGREES, DIFFERS, INCONCLUSIVE)}
