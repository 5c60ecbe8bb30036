"""Finite-element solutions of the free disk and sphere and of their impact on the wall.

An independent check of the modal pipeline (paper sections 2-4) with no modal truncation:
plane elasticity on the half disk (symmetric family) or axisymmetric elasticity on the sphere's
meridian section (the same half disk, weighted by ``2 pi r``; ``geometry="sphere"``) with
isoparametric quadratic triangles (scikit-fem). Modules: :mod:`~restitution.fem.mesh` (half-disk
meshes), :mod:`~restitution.fem.section` (what the half disk stands for: disk or sphere),
:mod:`~restitution.fem.elasticity` (stiffness and mass), :mod:`~restitution.fem.axisymmetric`
(the sphere's weak forms and lumped mass), :mod:`~restitution.fem.eigen`
(frequencies, inertia counts), :mod:`~restitution.fem.contact` (the wall on the arc),
:mod:`~restitution.fem.impact` (the collision), :mod:`~restitution.fem.compare` (against the
modal solver), :mod:`~restitution.fem.graded` (meshes sized by the contact half-width),
:mod:`~restitution.fem.richardson` (the limit h -> 0), :mod:`~restitution.fem.limits` (epsilon
with h -> 0 and alpha -> infinity), :mod:`~restitution.fem.reference` (stored reference values
with provenance) and :mod:`~restitution.fem.judge` (a law against the reference). Two free disks
or two free spheres meeting head-on (the judge of the modal pair; ``geometry=`` the kind of
both): :mod:`~restitution.fem.pair_model` (both meshes as one body),
:mod:`~restitution.fem.pair_impact` (one collision), :mod:`~restitution.fem.pair_limits` (both
limits) and :mod:`~restitution.fem.pair_reference` (stored reference values of pairs).
The oblique impact of the disk with Coulomb friction (issue 63, the judge of the modal route):
:mod:`~restitution.fem.whole_disk` (the whole disk: mesh, matrices, rim quadrature),
:mod:`~restitution.fem.oblique_impact` (one collision, friction point by point) and
:mod:`~restitution.fem.oblique_reference` (the stored study against the modal route).
"""

from restitution.fem.compare import Comparison, compare_fem_modal
from restitution.fem.eigen import fem_count_below, fem_symmetric_frequencies
from restitution.fem.graded import ContactGrading, contact_half_width
from restitution.fem.impact import FemCollisionError, FemSettings, fem_collide
from restitution.fem.judge import LawJudgement, judge_law
from restitution.fem.limits import FemEpsilon, FemGrid, fem_epsilon
from restitution.fem.oblique_impact import FemOblique, FemObliqueSettings, fem_oblique_collide
from restitution.fem.pair_impact import PairCollision, fem_collide_pair
from restitution.fem.pair_limits import FemPairEpsilon, fem_pair_epsilon
from restitution.fem.reference import load_reference

__all__ = [
    "Comparison",
    "ContactGrading",
    "FemCollisionError",
    "FemEpsilon",
    "FemGrid",
    "FemOblique",
    "FemObliqueSettings",
    "FemPairEpsilon",
    "FemSettings",
    "LawJudgement",
    "PairCollision",
    "compare_fem_modal",
    "contact_half_width",
    "fem_collide",
    "fem_collide_pair",
    "fem_count_below",
    "fem_epsilon",
    "fem_oblique_collide",
    "fem_pair_epsilon",
    "fem_symmetric_frequencies",
    "judge_law",
    "load_reference",
]
