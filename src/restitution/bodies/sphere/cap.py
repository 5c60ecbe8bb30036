"""The sphere's surface in every mode a force in the plane of incidence excites: the
counterpart of the disk's :class:`~restitution.bodies.disk.rim.Rim` for oblique impacts.

Units: ``E = rho = R = 1`` (three-dimensional constants), ``omega`` in ``c / R``, modal
coordinates ``Q`` in ``R`` (``int rho |u|^2 dV = m``), mass ``m = 4 pi / 3``, moment of inertia
``I = (2/5) m R^2 = 8 pi / 15`` (``K = 1 + m R^2 / I = 7/2``).

**Body frame.** ``e1`` from the centre to the material pole that meets the wall (the head-on
impact axis), ``e2`` the tangential direction of the plane of incidence, ``e3`` out of it. A
surface point at polar angle ``theta`` from ``e1`` and azimuth ``phi`` from ``e2`` towards
``e3`` sits at ``r_hat = (cos theta, sin theta cos phi, sin theta sin phi)``.

**Modes.** A normal force and a tangential one along ``e2`` at the pole, and a rotation about
``e3``, keep the mirror symmetry ``e3 -> -e3`` (``phi -> -phi``): only fields with ``u_r``,
``u_theta`` even and ``u_phi`` odd in ``phi`` are excited. Per order ``l`` and azimuthal order
``m`` (angular functions ``N_lm P_l^m``, :mod:`restitution.bodies.sphere.harmonics`):

* **spheroidal** ``(l, m)``, ``Y = N_lm P_l^m(cos theta) cos(m phi)``::

      u_r = C Y,   u_theta = S dY/dtheta,   u_phi = (S / sin theta) dY/dphi,

  the radial shapes, frequency, ``C = U(1)`` and ``S = V(1)`` of the axisymmetric mode
  ``(l, m = 0)`` (:mod:`restitution.bodies.sphere.modes`): Navier's equations separate with
  ``l`` alone, so the ``2 l + 1`` modes of one root share them (checked in the tests by the
  stress-free surface and the orthogonality of the ``m = 1`` fields);
* **toroidal** ``(l, m >= 1)``, ``Y = N_lm P_l^m(cos theta) sin(m phi)``::

      u_r = 0,   u_theta = (T / sin theta) dY/dphi,   u_phi = -T dY/dtheta,

  ``T = W(1)`` (:mod:`restitution.bodies.sphere.toroidal`); ``m = 0`` twists the sphere about
  ``e1`` (an even ``u_phi``), which the symmetry excludes.

The rigid motions are not modes: the translation along ``e2`` is the zero root of the
spheroidal ``l = 1``, ``m = 1`` family and the rotation about ``e3`` the zero root of the
toroidal ``l = 1``, ``m = 1`` family (``W = r``); both are degrees of freedom of the collision.
Every mode is orthogonal to them (no momentum, no angular momentum).

:func:`cap_modes` puts the axisymmetric modes first, in the order given (so that a head-on
run and a frictionless oblique one share them), then, for ``m = 1 ... azimuthal``, the
spheroidal partners of the modes of order ``l >= m``, then the toroidal modes of orders
``l >= m`` below the set's highest frequency.

A :class:`SphereCap` is what :mod:`restitution.dynamics.oblique` consumes: frequencies, mass,
moment of inertia, the contact time estimate and its wall nodes
(:mod:`restitution.bodies.sphere.cap_nodes`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from restitution.bodies.sphere import surface
from restitution.bodies.sphere.harmonics import angular_functions
from restitution.bodies.sphere.modes import SphereModes
from restitution.bodies.sphere.toroidal import toroidal_modes
from restitution.errors import InputError

__all__ = ["FAMILIES", "SphereCap", "cap_modes"]

FAMILIES = ("spheroidal", "toroidal")
"""The families of :attr:`SphereCap.family`, by index."""

DEFAULT_AZIMUTHS = 32
"""Nodes per ring of the wall quadrature (:mod:`restitution.bodies.sphere.cap_nodes`)."""


@dataclass(frozen=True, eq=False)
class SphereCap:
    """The sphere's modes that keep the plane of incidence's mirror symmetry (module docs).

    Attributes
    ----------
    nu : float
        Poisson number.
    family : numpy.ndarray of int, shape (N,)
        Index into :data:`FAMILIES`.
    l, m, n : numpy.ndarray of int, shape (N,)
        Order, azimuthal order, root index within ``(family, l)``.
    omega : numpy.ndarray, shape (N,)
        Angular frequencies, ``c / R``.
    C, S : numpy.ndarray, shape (N,)
        Surface amplitudes: spheroidal ``U(1)``, ``V(1)``; toroidal ``0``, ``W(1)``; ``R``.
    azimuths : int
        Nodes per ring of the wall quadrature.
    """

    nu: float
    family: np.ndarray
    l: np.ndarray
    m: np.ndarray
    n: np.ndarray
    omega: np.ndarray
    C: np.ndarray
    S: np.ndarray
    azimuths: int = DEFAULT_AZIMUTHS

    geometry: ClassVar[str] = "sphere"

    def __len__(self) -> int:
        return int(self.omega.size)

    @property
    def mass(self) -> float:
        """``m = 4 pi / 3`` (``rho R^3``)."""
        return 4.0 * math.pi / 3.0

    @property
    def inertia(self) -> float:
        """Moment of inertia about a diameter, ``(2/5) m R^2 = 8 pi / 15`` (``rho R^5``)."""
        return 0.4 * self.mass

    def contact_time_estimate(self, v):
        """Hertz contact time ``2.9433 delta_max / v`` against a rigid wall, ``R / c``."""
        return surface.contact_time_estimate(v, self.nu)

    def displacement(self, theta, phi) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Surface displacement per unit ``Q`` at material points ``(theta, phi)`` (shape
        (M,) each), in the body frame's Cartesian components.

        Returns
        -------
        d1, d2, d3 : numpy.ndarray, shape (M, N)
            Along ``e1`` (the impact axis), ``e2`` (tangential, in the plane), ``e3``; ``R``.
        """
        theta = np.asarray(theta, dtype=float)
        phi = np.asarray(phi, dtype=float)
        M, N = theta.size, len(self)
        ur, ut, up = np.zeros((M, N)), np.zeros((M, N)), np.zeros((M, N))
        for key in sorted(set(zip(self.l.tolist(), self.m.tolist(), strict=True))):
            cols = np.flatnonzero((self.l == key[0]) & (self.m == key[1]))
            Y, dY, Ys = angular_functions(key[0], key[1], theta)
            mm = key[1]
            cos, sin = np.cos(mm * phi), np.sin(mm * phi)
            for k in cols:
                if self.family[k] == 0:
                    ur[:, k] = self.C[k] * Y * cos
                    ut[:, k] = self.S[k] * dY * cos
                    up[:, k] = -self.S[k] * mm * Ys * sin
                else:
                    ut[:, k] = self.S[k] * mm * Ys * cos
                    up[:, k] = -self.S[k] * dY * sin
        ct, st = np.cos(theta)[:, None], np.sin(theta)[:, None]
        cp, sp = np.cos(phi)[:, None], np.sin(phi)[:, None]
        d1 = ur * ct - ut * st
        d2 = (ur * st + ut * ct) * cp - up * sp
        d3 = (ur * st + ut * ct) * sp + up * cp
        return d1, d2, d3

    def wall_node_count(self, alpha: float, n_nodes: int | None = None) -> int:
        """The number of nodes :meth:`wall_nodes` would make, without making them."""
        from restitution.bodies.sphere.cap_nodes import ring_count

        return ring_count(self, float(alpha), n_nodes) * int(self.azimuths)

    def wall_node_memory(self, alpha: float, n_nodes: int | None = None) -> float:
        """Bytes of :meth:`wall_nodes` at its build's peak: the stored rows (2 per node and
        mode) and 11 arrays of one block of nodes by the modes, the displacements and their
        temporaries (:data:`~restitution.bodies.sphere.cap_nodes.BLOCK_NODES`; tracemalloc
        measured 2.40 times the node-by-mode array at 13248 nodes, this formula 2.43)."""
        from restitution.bodies.sphere.cap_nodes import BLOCK_NODES

        count = self.wall_node_count(alpha, n_nodes)
        return 8.0 * len(self) * (2 * count + 11 * min(count, BLOCK_NODES))

    def wall_nodes(self, alpha: float, n_nodes: int | None = None):
        """The wall quadrature for hardness ``alpha`` (``1 / R``): ``n_nodes`` rings (default
        the head-on sphere's count) of :attr:`azimuths` nodes
        (:class:`restitution.bodies.sphere.cap_nodes.CapNodes`)."""
        from restitution.bodies.sphere.cap_nodes import cap_nodes

        return cap_nodes(self, float(alpha), n_nodes)

    def contact_residual(self, nodes, reach: float):
        """The static flexibility of the modes this cap drops, on hats of the projected radius
        about the contact axis out to ``reach`` (``R``) over its wall ``nodes``
        (:class:`restitution.bodies.sphere.contact_residual.ContactResidual`)."""
        from restitution.bodies.sphere.contact_residual import contact_residual

        return contact_residual(self, nodes, reach)

    def mode_labels(self) -> list[dict]:
        """One dict per mode: ``family`` (a name of :data:`FAMILIES`), ``n``, ``l``, ``m``."""
        return [
            {"family": FAMILIES[int(f)], "n": int(n), "l": int(l), "m": int(m)}
            for f, n, l, m in zip(self.family, self.n, self.l, self.m, strict=True)
        ]

    def take(self, index) -> SphereCap:
        """The modes at ``index`` (integer or boolean array), in the order given."""
        idx = np.arange(len(self))[index]
        fields = {f: getattr(self, f)[idx] for f in _FIELDS}
        return SphereCap(self.nu, azimuths=self.azimuths, **fields)

    def with_azimuths(self, azimuths: int) -> SphereCap:
        """The same modes with another number of nodes per ring (even, >= 8)."""
        if not (isinstance(azimuths, int) and azimuths >= 8 and azimuths % 2 == 0):
            raise InputError(f"azimuths must be an even integer >= 8, got {azimuths!r}")
        return SphereCap(self.nu, azimuths=azimuths, **{f: getattr(self, f) for f in _FIELDS})


_FIELDS = ("family", "l", "m", "n", "omega", "C", "S")


def cap_modes(
    modes: SphereModes, *, azimuthal: int | None = None, toroidal: bool = True
) -> SphereCap:
    """The sphere's modes for an oblique impact, built on an axisymmetric set (module docs).

    Parameters
    ----------
    modes : SphereModes
        The axisymmetric spheroidal modes (the head-on set).
    azimuthal : int, optional
        Highest azimuthal order ``m`` (``>= 0``); default every order (``m <= l``): then the
        modes of each root span a space that rotations about ``e3`` map into itself, and the
        rolling contact meets the same truncated body wherever it is. 1 is what a force at the
        fixed pole excites; docs/oblique.md measures what the higher orders change.
    toroidal : bool
        Leave the toroidal family out (for checks).
    """
    if not isinstance(modes, SphereModes):
        raise InputError(f"modes must be the sphere's SphereModes, got {type(modes).__name__}")
    if azimuthal is None:
        azimuthal = 1 << 30
    if not (isinstance(azimuthal, int) and azimuthal >= 0):
        raise InputError(f"azimuthal must be None or an integer >= 0, got {azimuthal!r}")
    N = len(modes)
    parts = [(np.zeros(N, int), modes.l, np.zeros(N, int), modes.n, modes.omega, modes.C, modes.S)]
    w_top = float(modes.omega.max()) * (1 + 1e-12) if N else 0.0
    tor = toroidal_modes(modes.nu, w_top) if (toroidal and N) else None
    top = max(int(modes.l.max()) if N else 0, int(tor[0].max()) if tor and tor[0].size else 0)
    for mm in range(1, min(azimuthal, top) + 1):
        sel = modes.l >= mm
        k = int(sel.sum())
        parts.append(
            (np.zeros(k, int), modes.l[sel], np.full(k, mm), modes.n[sel], modes.omega[sel],
             modes.C[sel], modes.S[sel])
        )  # fmt: skip
        if tor is not None:
            tl, tn, tw, tT = tor
            ts = tl >= mm
            k = int(ts.sum())
            parts.append(
                (np.ones(k, int), tl[ts], np.full(k, mm), tn[ts], tw[ts], np.zeros(k), tT[ts])
            )
    cols = [np.concatenate([p[i] for p in parts]) for i in range(7)]
    return SphereCap(
        nu=modes.nu,
        family=cols[0].astype(int),
        l=cols[1].astype(int),
        m=cols[2].astype(int),
        n=cols[3].astype(int),
        omega=cols[4].astype(float),
        C=cols[5].astype(float),
        S=cols[6].astype(float),
    )
