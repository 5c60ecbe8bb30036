"""The disk's rim in both mode families, for impacts that are not head-on.

Units: ``E = rho = R = 1`` (two-dimensional plane-stress constants), ``omega`` in ``c / R``,
modal coordinates ``Q`` in ``R`` (normalisation of eq. 26, ERRATA), mass ``m = pi``, moment of
inertia ``I = m R^2 / 2 = pi / 2``.

A head-on impact excites only the symmetric family (``u_r ~ cos n phi``, ``u_phi ~ sin n phi``,
:mod:`restitution.bodies.disk.modes`). A tangential force at the contact excites the other one,
which the paper mentions after eq. (18) and leaves out:

* the **antisymmetric** family, ``u_r = U_r(r) sin(n phi)``, ``u_phi = -U_phi(r) cos(n phi)``
  for ``n >= 1``: the symmetric mode of the same ``(n, l)`` turned by ``pi / (2 n)`` (its
  components in the polar basis at ``phi - pi/(2n)``), so with the same ``omega``, ``U_r``,
  ``U_phi``, normalisation and rim amplitudes ``C = U_r(1)``, ``S = U_phi(1)``;
* the **torsional** modes, ``n = 0``: ``u_r = 0``, ``u_phi = A J_1(kappa' r)``, whose free edge
  ``sigma_rphi(1) = mu (U_phi' - U_phi / r)(1) = -mu A kappa' J_2(kappa') = 0`` gives the roots of
  ``J_2(kappa') = 0``, ``omega = kappa' / sqrt(2 (1 + nu))`` (eq. 18). The paper's eq. (21)
  prints ``dJ_1/dR - (nu / R) J_1``; the shear stress has no ``nu`` in it (derived above; checked
  in the tests by the Rayleigh quotient and the orthogonality to the rigid rotation). With
  ``int_0^1 r U_phi^2 dr = 1/2`` (the ``n = 0`` normalisation) Lommel's integral gives
  ``A = 1 / |J_1(kappa')|``: every torsional mode has the rim amplitude ``S = 1``.

The root ``kappa' = 0`` of the torsional family is the rigid rotation and that of ``n = 1`` the
rigid translation: they are the rigid-body coordinates of an oblique impact, not modes.

A :class:`Rim` is what :mod:`restitution.dynamics.oblique` consumes: every mode's rim
displacement ``(u_r, u_phi)`` per unit ``Q`` at material angles ``phi`` of the body frame, the
frequencies, the mass and the moment of inertia.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.special import jn_zeros

from restitution.bodies.disk import contact
from restitution.bodies.disk.modes import ModeSet
from restitution.bodies.disk.surface import default_n_phi
from restitution.bodies.node_jacobian import NodeJacobian, row_products
from restitution.errors import InputError

__all__ = ["BLOCK_NODES", "FAMILIES", "Rim", "RimNodes", "rim_modes", "torsional_frequencies"]

FAMILIES = ("symmetric", "antisymmetric", "torsional")
"""The families of :attr:`Rim.family`, by index."""

BLOCK_NODES = 512
"""Rim nodes whose displacements :meth:`Rim.wall_nodes` evaluates at once: the build holds
the stored rows (2 per node and mode) and the displacements' arrays for one block, not for
every node (tracemalloc at 2344 nodes: all at once peaked at 6.0 times one node-by-mode array,
in blocks at 3.33)."""


@dataclass(frozen=True, eq=False)
class Rim:
    """The in-plane modes of a disk on its rim, both families (module docs).

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number.
    family : numpy.ndarray of int, shape (N,)
        Index into :data:`FAMILIES`.
    n, l : numpy.ndarray of int, shape (N,)
        Directional nodes and root index (torsional: ``n = 0``, ``l`` from 0).
    omega : numpy.ndarray, shape (N,)
        Angular frequencies, ``c / R``.
    C, S : numpy.ndarray, shape (N,)
        Rim amplitudes ``U_r(1)``, ``U_phi(1)`` per unit ``Q``, ``R``.
    """

    nu: float
    family: np.ndarray
    n: np.ndarray
    l: np.ndarray
    omega: np.ndarray
    C: np.ndarray
    S: np.ndarray

    geometry: ClassVar[str] = "disk"

    def __len__(self) -> int:
        return int(self.omega.size)

    @property
    def mass(self) -> float:
        """``m = pi`` (``rho R^2``)."""
        return math.pi

    @property
    def inertia(self) -> float:
        """Moment of inertia about the centre, ``m R^2 / 2 = pi / 2`` (``rho R^4``)."""
        return 0.5 * math.pi

    def displacement(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rim displacement per unit ``Q`` at material angles ``phi``, in the body's polar
        basis.

        Parameters
        ----------
        phi : numpy.ndarray, shape (M,)
            Angles from the body's impact axis, radians.

        Returns
        -------
        u_r, u_phi : numpy.ndarray, shape (M, N)
            Radial and tangential (counter-clockwise) displacement, ``R``.
        """
        phi = np.asarray(phi, dtype=float)[:, None]
        arg = self.n[None, :] * phi
        cos, sin = np.cos(arg), np.sin(arg)
        sym = self.family[None, :] == 0
        anti = self.family[None, :] == 1
        u_r = np.where(sym, cos, np.where(anti, sin, 0.0)) * self.C[None, :]
        u_phi = np.where(sym, sin, np.where(anti, -cos, 1.0)) * self.S[None, :]
        return u_r, u_phi

    def node_spacing(self, alpha: float) -> float:
        """Spacing (radians) of a uniform node grid on the rim that resolves a contact zone of
        depth ``1 / alpha``: that of the head-on quadrature
        (:func:`restitution.bodies.disk.surface.default_n_phi` nodes on ``[0, pi/2]``), so
        that the two runs sum the wall over the same points."""
        n_max = int(self.n.max()) if len(self) else 0
        return 0.5 * math.pi / (default_n_phi(float(alpha), n_max) - 1)

    def contact_time_estimate(self, v):
        """Quasistatic contact time ``pi sqrt(ln(4/v))`` of eq. (61), ``R / c``."""
        return contact.contact_time_estimate(v)

    def wall_node_count(self, alpha: float, n_nodes: int | None = None) -> int:
        """The number of nodes :meth:`wall_nodes` would make, without making them."""
        if n_nodes is not None:
            return int(n_nodes)
        return int(round(2.0 * math.pi / float(self.node_spacing(alpha))))

    def wall_node_memory(self, alpha: float, n_nodes: int | None = None) -> float:
        """Bytes of :meth:`wall_nodes` at its build's peak: the stored rows (2 per node and
        mode) and 7 arrays of one block of nodes by the modes, the displacements and their
        temporaries (:data:`BLOCK_NODES`; tracemalloc measured 3.33 times the node-by-mode
        array at 2344 nodes, this formula 3.53)."""
        count = self.wall_node_count(alpha, n_nodes)
        return 8.0 * len(self) * (2 * count + 7 * min(count, BLOCK_NODES))

    def wall_nodes(self, alpha: float, n_nodes: int | None = None) -> RimNodes:
        """The wall quadrature: ``n_nodes`` uniform rim nodes on the whole circle (default the
        spacing of :meth:`node_spacing`), ``phi = 0`` among them; their displacements are
        evaluated :data:`BLOCK_NODES` at a time (:meth:`wall_node_memory`)."""
        M = self.wall_node_count(alpha, n_nodes)
        phi = 2.0 * math.pi * np.arange(M) / M - math.pi  # phi = 0 is a node
        U = np.empty((M, 2, len(self)))
        for start in range(0, M, BLOCK_NODES):
            part = slice(start, start + BLOCK_NODES)
            U[part, 0], U[part, 1] = self.displacement(phi[part])
        return RimNodes(
            phi=phi,
            weight=2.0 * math.pi / M,
            U=U,
            reach=np.abs(np.asarray(self.C, float)) + np.abs(np.asarray(self.S, float)),
        )

    def mode_labels(self) -> list[dict]:
        """One dict per mode: ``family`` (a name of :data:`FAMILIES`), ``n``, ``l``."""
        return [
            {"family": FAMILIES[int(f)], "n": int(n), "l": int(l)}
            for f, n, l in zip(self.family, self.n, self.l, strict=True)
        ]

    def take(self, index) -> Rim:
        """The modes at ``index`` (integer or boolean array), in the order given."""
        idx = np.arange(len(self))[index]
        return Rim(self.nu, *(getattr(self, f)[idx] for f in _FIELDS))


_FIELDS = ("family", "n", "l", "omega", "C", "S")


@dataclass(frozen=True, eq=False)
class RimNodes:
    """The rim's wall nodes for :mod:`restitution.dynamics.oblique`: material angles ``phi``
    (shape (M,)), the weight ``2 pi / M`` of each, the displacements ``Ur``, ``Up`` (shape (M,
    N)) per unit ``Q`` there (stored interleaved as ``U``, shape (M, 2, N):
    :mod:`restitution.bodies.node_jacobian`) and ``reach = |C| + |S|`` (shape (N,)), which
    bounds them.

    A node at angle ``phi`` of a disk turned by ``Theta`` sits at ``X = x0 + (1 + u_r)
    cos(phi + Theta) - u_phi sin(phi + Theta)``, ``Y = y0 + (1 + u_r) sin(phi + Theta) + u_phi
    cos(phi + Theta)``.
    """

    phi: np.ndarray
    weight: float
    U: np.ndarray
    reach: np.ndarray

    def __len__(self) -> int:
        return int(self.phi.size)

    @property
    def Ur(self) -> np.ndarray:
        """Radial displacement per unit ``Q``, shape (M, N) (a view of ``U``)."""
        return self.U[:, 0, :]

    @property
    def Up(self) -> np.ndarray:
        """Tangential displacement per unit ``Q``, shape (M, N) (a view of ``U``)."""
        return self.U[:, 1, :]

    @functools.cached_property
    def _rows(self) -> np.ndarray:
        return row_products(self.U)

    def start_integral(self, alpha: float) -> float:
        """``sum_j w exp(alpha (cos phi_j - 1))``: the undeformed rim's wall integral, ``R``."""
        return self.weight * np.sum(np.exp(alpha * (np.cos(self.phi) - 1.0)))

    def _active(self, x0, rotation, reach: float, cutoff: float):
        """``(act, cos, sin)``: the nodes with ``x0 + cos(phi + Theta) + reach > cutoff`` and
        their turned angle's cosine and sine; ``None`` if there are none."""
        ang = self.phi + rotation
        c = np.cos(ang)
        act = np.nonzero(x0 + c + reach > cutoff)[0]
        return None if act.size == 0 else (act, c[act], np.sin(ang[act]))

    def place(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes that may touch (``x0 + cos(phi + Theta) + reach > cutoff``), placed:
        ``None`` or ``(weight, X, Y - y0, xi, eta, project)``
        (:class:`restitution.dynamics.oblique.WallNodes`). The Jacobians are formed, as the
        one-state route has always summed them."""
        active = self._active(x0, rotation, reach, cutoff)
        if active is None:
            return None
        act, c, s = active
        Ur, Up = self.Ur[act], self.Up[act]
        ur, up = Ur @ Q, Up @ Q
        X = x0 + (1.0 + ur) * c - up * s
        Yr = (1.0 + ur) * s + up * c
        dXdQ = Ur * c[:, None] - Up * s[:, None]
        dYdQ = Ur * s[:, None] + Up * c[:, None]

        def project(e, p):
            return e @ dXdQ, p @ dYdQ

        return self.weight, X, Yr, dXdQ @ Qd, dYdQ @ Qd, project

    def jacobian(self, x0, rotation, Q, Qd, reach: float, cutoff: float):
        """The nodes that may touch with their identity and their position's derivatives in
        the modal coordinates: ``None`` or ``(index, weight, X, Y - y0, eta, J)`` (index shape
        (M,) into the whole grid, ``eta = dY/dQ @ Qd``, ``J`` a
        :class:`~restitution.bodies.node_jacobian.NodeJacobian` with each node's own turn
        ``phi + Theta``), for friction point by point
        (:mod:`restitution.dynamics.oblique_microslip`)."""
        active = self._active(x0, rotation, reach, cutoff)
        if active is None:
            return None
        act, c, s = active
        J = NodeJacobian(self.U[act], c, s, self._rows[:, act])
        P = (J.flat() @ Q).reshape(-1, 2)
        ur, up = P[:, 0], P[:, 1]
        X = x0 + (1.0 + ur) * c - up * s
        Yr = (1.0 + ur) * s + up * c
        return act, self.weight, X, Yr, J.dY(Qd), J

    def jacobians(self, x0, rotation, Q, reach: float, cutoff: float):
        """:meth:`jacobian` at rest (``Qd = 0``) with the Jacobians formed: ``None`` or
        ``(index, weight, X, Y - y0, dX/dQ, dY/dQ)`` (the matrices (M, N); for checks)."""
        placed = self.jacobian(x0, rotation, Q, np.zeros_like(Q), reach, cutoff)
        return None if placed is None else (*placed[:4], *placed[5].formed())


def torsional_frequencies(nu: float, omega_max: float) -> np.ndarray:
    """Frequencies of the torsional modes below ``omega_max`` (``c / R``), ascending:
    ``kappa'_l / sqrt(2 (1 + nu))`` with ``J_2(kappa'_l) = 0``.

    >>> [round(float(w), 6) for w in torsional_frequencies(0.33, 7.0)]
    [3.148852, 5.160944]
    """
    speed = 1.0 / math.sqrt(2.0 * (1.0 + nu))  # the shear wave speed, c
    count = int(omega_max / (math.pi * speed)) + 2  # zeros of J_2 are about pi apart
    kappa = jn_zeros(2, count)
    return kappa[kappa * speed < omega_max] * speed


def rim_modes(modes: ModeSet, *, torsional: bool = True, antisymmetric: bool = True) -> Rim:
    """The rim of a symmetric mode set with its mirror family (module docs).

    The symmetric modes come first, in the order of ``modes`` (so a head-on run and an oblique
    one with zero friction share them), then the antisymmetric partners of its ``n >= 1``
    modes, then the torsional modes below ``modes``' highest frequency. For a set cut at a
    frequency (``omega_max``) the result is every in-plane mode below it.

    Parameters
    ----------
    modes : ModeSet
    torsional, antisymmetric : bool
        Leave a family out (for checks: without them a tangential force has no modes to
        excite).
    """
    if not isinstance(modes, ModeSet):
        raise InputError(f"modes must be the disk's ModeSet, got {type(modes).__name__}")
    one = modes.n >= 1 if antisymmetric else np.zeros(len(modes), bool)
    w_tor = (
        torsional_frequencies(modes.nu, float(modes.omega.max()) * (1 + 1e-12))
        if torsional and len(modes)
        else np.zeros(0)
    )
    k = w_tor.size
    return Rim(
        nu=modes.nu,
        family=np.r_[np.zeros(len(modes), int), np.ones(int(one.sum()), int), np.full(k, 2)],
        n=np.r_[modes.n, modes.n[one], np.zeros(k, int)].astype(int),
        l=np.r_[modes.l, modes.l[one], np.arange(k)].astype(int),
        omega=np.r_[modes.omega, modes.omega[one], w_tor],
        C=np.r_[modes.C, modes.C[one], np.zeros(k)],
        S=np.r_[modes.S, modes.S[one], np.ones(k)],
    )
