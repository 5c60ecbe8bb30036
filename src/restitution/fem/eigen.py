"""Finite-element eigenfrequencies of the free disk (symmetric family) and of the free sphere
(axisymmetric spheroidal family); checks of the modal route's frequencies.

Units: ``E = rho = R = 1`` of the body's own constants; frequencies ``omega`` in ``c / R``.

The symmetric modes of the free disk are the modes of the half disk with a roller on the
diameter (:mod:`restitution.fem.elasticity`): ``K x = omega^2 M x``. The axisymmetric,
torsion-free modes of the free sphere (Lamb's spheroidal modes of every order ``l``, the
breathing mode ``l = 0`` included) are the modes of its meridian section with ``u_r = 0`` on the
axis (``geometry="sphere"``, :mod:`restitution.fem.axisymmetric`). The one zero eigenvalue
(rigid translation along ``x``) is dropped, so the remaining spectrum is what
:func:`restitution.get_modes` computes from the frequency equation (``geometry="sphere"``:
Lamb's). Conforming elements on the exact domain give upper bounds converging like ``h^(2p)``;
with the isoparametric arc the P2 frequencies converge like ``h^4`` (measured for the sphere
too: consistent P2, fitted rates 3.8-3.9 over levels 3-5, ``tests/test_fem_sphere.py``).

Two independent ways to use the discrete spectrum:

* :func:`fem_symmetric_frequencies`: the lowest frequencies (shift-invert Lanczos).
* :func:`fem_count_below`: the number of frequencies below ``omega`` from Sylvester's law of
  inertia: the number of negative pivots of an ``L D L^T`` factorisation of
  ``K - omega^2 M`` equals the number of eigenvalues below ``omega^2``. No eigenvalue is
  computed, so near-degenerate pairs cannot be merged or missed.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as sla

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.errors import InputError, RestitutionError
from restitution.fem.elasticity import (
    Discretisation,
    HalfDisk,
    as_material,
    assemble_half_disk,
)
from restitution.fem.mesh import uniform_half_disk
from restitution.fem.model import start_vector

__all__ = [
    "fem_count_below",
    "fem_symmetric_frequencies",
    "half_disk_system",
    "symmetric_frequencies",
]

# Shift of the shift-invert Lanczos iteration (omega^2 units): negative, so K - sigma M is
# positive definite although K is singular.
_SHIFT = -1.0


def half_disk_system(
    material_or_nu: Material | float,
    refine: int,
    discretisation: Discretisation = "P2",
    geometry: str = DEFAULT_GEOMETRY,
) -> HalfDisk:
    """Half disk (or the sphere's meridian section, ``geometry="sphere"``) on the uniform mesh
    of level ``refine`` (element size ``~2^-refine R``)."""
    return assemble_half_disk(
        uniform_half_disk(refine),
        as_material(material_or_nu, geometry),
        discretisation,
        geometry,
    )


def symmetric_frequencies(disk: HalfDisk, count: int) -> np.ndarray:
    """The ``count`` lowest nonzero frequencies of a discretised half disk.

    Parameters
    ----------
    disk : HalfDisk
    count : int
        Number of frequencies, >= 1 and below the number of degrees of freedom.

    Returns
    -------
    numpy.ndarray, shape (count,)
        Ascending frequencies, ``c / R``.
    """
    if not 1 <= count < disk.n_dofs - 1:
        raise InputError(
            f"count must lie in [1, {disk.n_dofs - 2}] for this mesh, got {count}; "
            "refine the mesh for more frequencies"
        )
    w2 = sla.eigsh(
        disk.K, k=count + 1, M=disk.M, sigma=_SHIFT, which="LM", return_eigenvectors=False,
        v0=start_vector(disk.K.shape[0]),
    )  # fmt: skip
    w2 = np.sort(w2)
    # The rigid translation: zero up to round-off relative to the first elastic eigenvalue.
    if abs(w2[0]) > 1e-8 * w2[1]:
        raise RestitutionError(
            f"expected one zero eigenvalue (rigid translation), got {w2[0]:.3g}; "
            "the roller condition on the diameter is wrong"
        )
    return np.sqrt(w2[1:])


def fem_symmetric_frequencies(
    material_or_nu: Material | float,
    count: int,
    refine: int,
    discretisation: Discretisation = "P2",
    geometry: str = DEFAULT_GEOMETRY,
) -> np.ndarray:
    """Lowest ``count`` symmetric frequencies of the free disk (or axisymmetric frequencies of
    the free sphere) by finite elements.

    Parameters
    ----------
    material_or_nu : Material or float
        Material, or the Poisson number (``E = rho = 1``): two-dimensional for the disk,
        three-dimensional for the sphere.
    count : int
        Number of frequencies.
    refine : int
        Level of the uniform mesh (:func:`restitution.fem.mesh.uniform_half_disk`); each level
        halves the element size and quadruples the number of unknowns.
    discretisation : {"P2", "P2+lumped"}
        Consistent P2 (default) or the mass-lumped P2 + bubble element of the impact solver.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The disk's symmetric family or the sphere's axisymmetric spheroidal modes.

    Returns
    -------
    numpy.ndarray, shape (count,)
        Ascending frequencies, ``c / R``; the rigid translation is left out.

    Examples
    --------
    >>> w = fem_symmetric_frequencies(0.33, count=3, refine=3)
    >>> w.shape
    (3,)
    """
    return symmetric_frequencies(
        half_disk_system(material_or_nu, refine, discretisation, geometry), count
    )


def _negative_pivots(A) -> int:
    """Number of negative eigenvalues of the symmetric sparse matrix ``A`` (Sylvester)."""
    lu = sla.splu(
        A.tocsc(),
        permc_spec="MMD_AT_PLUS_A",
        diag_pivot_thresh=0.0,
        options={"SymmetricMode": True},
    )
    # With symmetric (diagonal) pivoting A = P^T L U P and U = D L^T, so A is congruent to D.
    if not np.array_equal(lu.perm_r, lu.perm_c):
        raise RestitutionError(
            "the factorisation used off-diagonal pivots; the inertia count is not valid here "
            "(omega may be an eigenvalue to round-off: shift it slightly)"
        )
    return int(np.count_nonzero(lu.U.diagonal() < 0))


def fem_count_below(disk: HalfDisk, omega: float) -> int:
    """Number of nonzero symmetric frequencies below ``omega`` (``c / R``) of a half disk.

    Uses the inertia of ``K - omega^2 M`` (see the module docstring); the rigid translation
    (frequency 0) is subtracted.
    """
    if not omega > 0:
        raise InputError(f"omega must be positive, got {omega}")
    return _negative_pivots(disk.K - omega**2 * disk.M) - 1
