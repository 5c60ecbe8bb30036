"""Finite-element solutions of the free disk and of its impact on the wall.

An independent check of the modal pipeline (paper sections 2-4) with no modal truncation:
plane elasticity on the half disk (symmetric family) with isoparametric quadratic triangles
(scikit-fem). Modules: :mod:`~restitution.fem.mesh` (half-disk meshes),
:mod:`~restitution.fem.elasticity` (stiffness and mass), :mod:`~restitution.fem.eigen`
(frequencies, inertia counts), :mod:`~restitution.fem.contact` (the wall on the arc),
:mod:`~restitution.fem.impact` (the collision), :mod:`~restitution.fem.compare` (against the
modal solver).
"""

from restitution.fem.compare import Comparison, compare_fem_modal
from restitution.fem.eigen import fem_count_below, fem_symmetric_frequencies
from restitution.fem.impact import FemCollisionError, FemSettings, fem_collide

__all__ = [
    "Comparison",
    "FemCollisionError",
    "FemSettings",
    "compare_fem_modal",
    "fem_collide",
    "fem_count_below",
    "fem_symmetric_frequencies",
]
