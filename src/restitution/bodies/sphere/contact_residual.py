"""The static residual of a sphere cap's dropped modes at its contact, on hats of the projected
radius about the contact axis (issue 63; docs/oblique.md, "A static residual for the one-state
route").

Units: ``E = rho = R = 1`` (three-dimensional constants); flexibilities in ``1 / (E R)``,
between forces and mean displacements.

**Why.** A truncated modal body is too stiff at the contact, normally and tangentially, and the
two truncations do not cancel in the tangential restitution: the quasistatic twin on the
truncated normal flexibility with the continuum's tangential one gives ``beta = +0.79`` where
both truncated give -0.72 and both continuous -0.33 (20 modes, ``alpha = 2000``, ``v =
0.005``). The dropped modes are fast against the contact time, so they follow the load
statically; their flexibility is kept instead of their motion, as the head-on routes do
(:mod:`restitution.dynamics.residual`).

**Hats.** Hat ``i`` of the projected radius ``rho`` about the contact axis (the line through
the centre normal to the wall) peaks at the radius ``r_i = sin(theta_i)`` of the wall nodes'
ring ``i`` and falls linearly to its neighbours' (flat inside the first ring, falling to zero
at ``r_K``): the unturned sphere's ring ``i`` lies on hat ``i`` alone, and a turned sphere's
nodes spread over two hats, so the residual follows the contact as it rolls over the material
nodes. (A residual on the material rings instead, centred on the pole, is not rotation
invariant: it passed energy from the spin to the normal motion, ``epsilon_normal = 1.006`` for
a rigid sphere at ``alpha = 2000``, and moved ``beta`` by 0.11 and 0.39 at ``alpha = 2000``
and 8000.)

**Flexibility.** Between the hats' loads, taken as spread evenly on the annuli of the projected
plane between the rings' mid-radii: the continuum's annulus flexibility
(:func:`~restitution.bodies.sphere.contact_compliance.annulus_flexibility`, the free sphere
with its inertial relief) less the kept modes' own
(:func:`~restitution.bodies.sphere.contact_compliance.modal_annulus_flexibility`), divided by
the annuli's areas: normal (azimuthal order 0) and tangential in line (order 1). The loads of
one contact have no other order while the pressure is symmetric about the contact axis; the
kept modes of higher orders stay in the motion.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.sphere.contact_compliance import (
    annulus_flexibility,
    modal_annulus_flexibility,
)
from restitution.errors import InputError

__all__ = ["ContactResidual", "contact_residual"]


@dataclass(frozen=True, eq=False)
class ContactResidual:
    """The dropped modes' static flexibility on hats (module docs).

    Attributes
    ----------
    radii : numpy.ndarray, shape (K + 1,)
        Hat ``i`` peaks at ``radii[i]``; the last falls to zero at ``radii[K]`` (``R``).
    normal, tangential : numpy.ndarray, shape (K, K)
        Mean displacement along the wall's normal (inwards) and in line per unit force on each
        hat, symmetric, ``1 / (E R)``.
    """

    radii: np.ndarray
    normal: np.ndarray
    tangential: np.ndarray
    _c: np.ndarray
    _s: np.ndarray
    _z: np.ndarray

    def __len__(self) -> int:
        return int(self.normal.shape[0])

    def radius(self, count: int, rotation: float) -> tuple[np.ndarray, np.ndarray]:
        """The first ``count`` wall nodes' projected radius about the contact axis, from their
        rest places turned by ``rotation`` about ``e3``, and its derivative in the rotation."""
        c, s, z = self._c[:count], self._s[:count], self._z[:count]
        ct, st = math.cos(rotation), math.sin(rotation)
        y = c * st + s * ct
        rho = np.sqrt(y * y + z * z)
        return rho, y * (c * ct - s * st) / np.maximum(rho, 1e-300)


def contact_residual(cap, nodes, reach: float) -> ContactResidual:
    """The residual of ``cap``'s dropped modes on hats of its wall ``nodes``
    (:class:`~restitution.bodies.sphere.cap_nodes.CapNodes`) out to the projected radius
    ``reach`` (``R``, the contact's largest extent)."""
    theta = np.asarray(nodes.theta, float)
    radii_all = np.sin(theta)
    count = int(np.searchsorted(radii_all, float(reach))) + 1
    if count + 1 > theta.size or radii_all[count] >= 0.9:
        raise InputError(
            f"the contact's reach {reach:.3g} R leaves the sphere's wall nodes (their last ring "
            f"at {radii_all[-1]:.3g} R) or wraps too far round the sphere for the residual's "
            "flat annuli: lower the speed, or harden the wall"
        )
    if count < 2:
        raise InputError("the residual needs at least two rings inside the contact's reach")
    mid = 0.5 * (theta[:count] + theta[1 : count + 1])
    edges = np.sin(np.r_[0.0, mid])
    area = math.pi * np.diff(edges**2)
    scale = np.outer(area, area)
    out = []
    for direction in ("normal", "tangential"):
        G = annulus_flexibility(edges, cap.nu, direction)
        if len(cap):
            G = G - modal_annulus_flexibility(cap, edges, direction)
        out.append(G / scale)
    A = int(nodes.azimuths)
    phi = np.tile(2.0 * math.pi * np.arange(A) / A, theta.size)
    z = np.sin(np.repeat(theta, A)) * np.sin(phi)
    return ContactResidual(radii_all[: count + 1].copy(), out[0], out[1],
                           np.asarray(nodes.c), np.asarray(nodes.s), z)  # fmt: skip
