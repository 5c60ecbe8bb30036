"""Elasticity on the half disk: stiffness and mass matrices with the symmetry condition.

Units: ``E = rho = R = 1`` unless the material says otherwise; displacements in ``R``.

One implementation, two weightings (:mod:`restitution.fem.section`): ``geometry="disk"`` is
plane stress on the upper half of the disk (below); ``geometry="sphere"`` is axisymmetric
elasticity on the sphere's meridian section, every integral weighted by ``2 pi r`` with the hoop
strain ``u_r / r`` and the three-dimensional Lame constants
(:mod:`restitution.fem.axisymmetric`, which also holds its lumped mass). The sphere's diameter
is its axis, where ``u_r = 0``: the same roller as the disk's ``u_y = 0``.

The two-dimensional (plane-stress) constants of eq. (6) enter through the Lame constants

    lambda_2d = E nu / (1 - nu^2),     mu = E / (2 (1 + nu)),

so the stress is ``sigma = 2 mu eps + lambda_2d tr(eps) I`` and the elastic energy is
``(1/2) u^T K u``; the kinetic energy is ``(1/2) udot^T M udot`` (density ``rho``).

Symmetry: the symmetric family of the paper (``u_r(phi) = u_r(-phi)``,
``u_phi(-phi) = -u_phi(phi)``) is ``u_x`` even and ``u_y`` odd in ``y``. On the half disk
``y >= 0`` that is a roller on the diameter: ``u_y = 0`` there, while the shear traction vanishes
naturally. The ``u_y`` degrees of freedom on the diameter are removed; what is left still holds
the rigid translation along ``x`` (the centre-of-mass motion), the one zero-frequency motion.
Energies and masses of the half disk are half those of the whole disk.

Two discretisations, both on the isoparametric meshes of :mod:`restitution.fem.mesh`:

* ``"P2"``: quadratic Lagrange triangles with the consistent mass matrix (for eigenvalues).
* ``"P2+lumped"``: quadratic triangles enriched with the cubic bubble, in the nodal basis of
  the 7 points vertices / edge midpoints / centroid, with the mass matrix lumped by the
  quadrature rule on those points (weights 1/20, 2/15, 9/20 of the area). This is the
  mass-lumped element of Cohen, Joly, Roberts and Tordjman (SIAM J. Numer. Anal. 38 (2001)
  2047) for explicit wave propagation: the mass matrix is diagonal and positive and the
  P2 accuracy is kept. ``tests/test_fem_modes.py`` checks its frequencies against the root
  finder (they converge like ``h^4`` here, with smaller errors than consistent P2).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import scipy.sparse as sp
from skfem import (
    Basis,
    BilinearForm,
    ElementTriP2,
    ElementTriP2B,
    ElementVector,
    MeshTri2,
    asm,
)
from skfem.helpers import dot
from skfem.models.elasticity import linear_elasticity

from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.errors import InputError
from restitution.fem.axisymmetric import axisymmetric_elasticity, axisymmetric_mass, lumped_weights
from restitution.fem.mesh import DIAMETER
from restitution.fem.section import Section, fem_material, section

__all__ = ["Discretisation", "HalfDisk", "assemble_half_disk", "as_material"]

Discretisation = Literal["P2", "P2+lumped"]

# Quadrature order of the assembly: exact for the P2 mass matrix on straight elements (4) with
# room for the bubble and for the rational integrands of the curved arc elements.
_INTORDER = 6

# Lumping rule on the reference triangle (area 1/2): vertices, edge midpoints in the facet
# order of skfem's triangles (0-1, 1-2, 0-2), centroid.
_LUMP_POINTS = np.array(
    [[0.0, 1.0, 0.0, 0.5, 0.5, 0.0, 1.0 / 3.0], [0.0, 0.0, 1.0, 0.0, 0.5, 0.5, 1.0 / 3.0]]
)
_LUMP_WEIGHTS = 0.5 * np.array([1 / 20, 1 / 20, 1 / 20, 2 / 15, 2 / 15, 2 / 15, 9 / 20])
# Values of the P2 vertex and edge shape functions at the centroid.
_P2_AT_CENTROID_VERTEX = -1.0 / 9.0
_P2_AT_CENTROID_EDGE = 4.0 / 9.0


def as_material(material_or_nu: Material | float, geometry: str = DEFAULT_GEOMETRY) -> Material:
    """A :class:`Material` from itself or from a Poisson number (two-dimensional for the disk,
    three-dimensional for the sphere; :func:`restitution.fem.section.fem_material`)."""
    return fem_material(material_or_nu, geometry)


@dataclass(frozen=True, eq=False)
class HalfDisk:
    """Discretised half disk: matrices on the kept degrees of freedom.

    Attributes
    ----------
    material : Material
    discretisation : {"P2", "P2+lumped"}
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body the half disk stands for (:mod:`restitution.fem.section`).
    mesh : skfem.MeshTri2
    basis : skfem.Basis
        Vector basis on ``mesh`` (all degrees of freedom, before the roller is applied).
    free : numpy.ndarray of int, shape (n,)
        Indices of the kept degrees of freedom in the numbering of ``basis``.
    K, M : scipy.sparse.csr_matrix, shape (n, n)
        Stiffness (``E``; sphere ``E R``) and mass (``rho R^2``; sphere ``rho R^3``) matrices
        on the kept dofs; ``M`` is diagonal for ``"P2+lumped"``.
    rigid : numpy.ndarray, shape (n,)
        Unit translation along ``x`` (1 on every ``u_x`` dof, 0 elsewhere).
    mass : float
        ``rigid^T M rigid``: the mass of the discretised half disk (``pi/2`` for the exact one)
        or of the whole sphere (``4 pi / 3``).
    """

    material: Material
    discretisation: str
    geometry: str
    mesh: MeshTri2
    basis: Basis
    free: np.ndarray
    K: sp.csr_matrix
    M: sp.csr_matrix
    rigid: np.ndarray
    mass: float

    @property
    def n_dofs(self) -> int:
        """Number of kept degrees of freedom."""
        return int(self.free.size)

    @property
    def section(self) -> Section:
        """How the half disk stands for the body (:func:`restitution.fem.section.section`)."""
        return section(self.geometry)

    @property
    def lumped(self) -> bool:
        """Whether ``M`` is diagonal."""
        return self.discretisation == "P2+lumped"

    def reduced_index(self) -> np.ndarray:
        """Map from the full dof numbering to the kept one (-1 for removed dofs)."""
        index = np.full(self.basis.N, -1, dtype=np.int64)
        index[self.free] = np.arange(self.free.size)
        return index


def _stiffness_form(material: Material, body: Section) -> BilinearForm:
    """Plane stress (disk) or the axisymmetric form (sphere), with the body's Lame constants."""
    if body.axisymmetric:
        return axisymmetric_elasticity(*body.lame(material))
    return linear_elasticity(*body.lame(material))


def _consistent(
    mesh: MeshTri2, material: Material, body: Section
) -> tuple[Basis, sp.spmatrix, sp.spmatrix]:
    basis = Basis(mesh, ElementVector(ElementTriP2()), intorder=_INTORDER)
    rho = material.rho

    @BilinearForm
    def mass_form(u, v, w):
        return rho * dot(u, v)

    mass = axisymmetric_mass(rho) if body.axisymmetric else mass_form
    return basis, asm(_stiffness_form(material, body), basis), asm(mass, basis)


def _lumped(
    mesh: MeshTri2, material: Material, body: Section
) -> tuple[Basis, sp.spmatrix, sp.spmatrix]:
    """P2 + bubble in the nodal basis of the lumping points, with the lumped mass."""
    basis = Basis(mesh, ElementVector(ElementTriP2B()), intorder=_INTORDER)
    K_hier = asm(_stiffness_form(material, body), basis)
    # skfem's P2B basis is hierarchical: P2 Lagrange functions plus the bubble with value 1
    # at the centroid. Nodal value at the centroid u_c = sum_i phi_i(c) u_i + b, hence the
    # bubble coefficient b = u_c - sum_i phi_i(c) u_i; T maps nodal to hierarchical values.
    n_el = mesh.t.shape[1]
    rows, cols, vals = [np.arange(basis.N)], [np.arange(basis.N)], [np.ones(basis.N)]
    if body.axisymmetric:
        weights = lumped_weights(mesh, _LUMP_POINTS, _LUMP_WEIGHTS, _INTORDER)  # (n_el, 7)
    else:
        weights = _LUMP_WEIGHTS[None, :] * np.abs(mesh._mapping().detDF(_LUMP_POINTS))
    lumped = np.zeros(basis.N)
    for comp in range(2):
        vert = basis.nodal_dofs[comp][mesh.t]  # (3, n_el)
        edge = basis.facet_dofs[comp][mesh.t2f]  # (3, n_el)
        bubble = basis.interior_dofs[comp]  # (n_el,)
        for k in range(3):
            rows += [bubble, bubble]
            cols += [vert[k], edge[k]]
            vals += [
                np.full(n_el, -_P2_AT_CENTROID_VERTEX),
                np.full(n_el, -_P2_AT_CENTROID_EDGE),
            ]
            np.add.at(lumped, vert[k], weights[:, k])
            np.add.at(lumped, edge[k], weights[:, 3 + k])
        np.add.at(lumped, bubble, weights[:, 6])
    T = sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
        shape=(basis.N, basis.N),
    )
    K = (T.T @ K_hier @ T).tocsr()
    return basis, K, sp.diags(material.rho * lumped).tocsr()


def assemble_half_disk(
    mesh: MeshTri2,
    material_or_nu: Material | float,
    discretisation: Discretisation = "P2",
    geometry: str = DEFAULT_GEOMETRY,
) -> HalfDisk:
    """Assemble stiffness and mass matrices of the half disk with ``u_y = 0`` on the diameter.

    Parameters
    ----------
    mesh : skfem.MeshTri2
        A mesh from :mod:`restitution.fem.mesh` (it names the ``"diameter"`` boundary).
    material_or_nu : Material or float
        The body's constants (two-dimensional for the disk, three-dimensional for the sphere).
    discretisation : {"P2", "P2+lumped"}
        Consistent P2, or P2 + bubble with the diagonal (lumped) mass matrix.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The half disk itself (plane stress) or the sphere's meridian section (axisymmetric).

    Returns
    -------
    HalfDisk
    """
    body = section(geometry)
    material = as_material(material_or_nu, geometry)
    if discretisation == "P2":
        basis, K, M = _consistent(mesh, material, body)
    elif discretisation == "P2+lumped":
        basis, K, M = _lumped(mesh, material, body)
    else:
        raise InputError(f"unknown discretisation {discretisation!r}; choose 'P2' or 'P2+lumped'")
    roller = basis.get_dofs(mesh.boundaries[DIAMETER]).all("u^2")
    free = np.setdiff1d(np.arange(basis.N), roller)
    K = K[free][:, free].tocsr()
    M = M[free][:, free].tocsr()
    rigid = np.zeros(basis.N)
    rigid[basis.split_indices()[0]] = 1.0
    rigid = rigid[free]
    return HalfDisk(
        material=material,
        discretisation=discretisation,
        geometry=geometry,
        mesh=mesh,
        basis=basis,
        free=free,
        K=K,
        M=M,
        rigid=rigid,
        mass=float(rigid @ (M @ rigid)),
    )
