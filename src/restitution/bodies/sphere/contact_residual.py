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
the centre normal to the wall) peaks at ``r_i = i h`` and falls linearly to its neighbours'
(the last falls to zero at ``r_K``); ``h`` is :data:`HAT_SPACING` times the wall nodes' ring
spacing at the pole. Each node loads the two hats about its own radius, so the residual follows
the contact as the sphere rolls over its material nodes. (A residual on the material rings,
centred on the pole, is not rotation invariant: it passed energy from the spin to the normal
motion, ``epsilon_normal = 1.006`` for a rigid sphere at ``alpha = 2000``, and moved ``beta``
by 0.11 and 0.39 at ``alpha = 2000`` and 8000. Hats on the rings' own radii, every node at a
peak until the sphere turns, still coupled them: ``epsilon_normal - 1 = 1.8e-5`` at ``alpha =
500``, and a start turned by 0.05 rad moved ``beta`` by 1e-3; uniform hats twice the rings'
spacing apart: 3.9e-6 and 2.6e-4, docs/oblique.md.)

**Flexibility.** Between the hats' loads, taken as spread evenly on the annuli of the projected
plane between the hats' mid-radii: the continuum's annulus flexibility
(:func:`~restitution.bodies.sphere.contact_compliance.annulus_flexibility`, the free sphere
with its inertial relief) less the kept modes' own
(:func:`~restitution.bodies.sphere.contact_compliance.modal_annulus_flexibility`), divided by
the annuli's areas: normal (azimuthal order 0) and tangential in line (order 1); and, for
Dundurs' coupling (since stop 87), the normal displacement of order 1 under a tilting pressure
and under the in-line traction
(:func:`~restitution.bodies.sphere.contact_compliance.annulus_tilt_flexibility`, less the kept
modes' :func:`~restitution.bodies.sphere.contact_compliance.modal_annulus_tilt_flexibility`).
The kept modes of higher orders stay in the motion.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.sphere.contact_compliance import (
    annulus_flexibility,
    annulus_tilt_flexibility,
    modal_annulus_flexibility,
    modal_annulus_tilt_flexibility,
)
from restitution.errors import InputError

__all__ = ["HAT_SPACING", "ContactResidual", "contact_residual"]


@dataclass(frozen=True, eq=False)
class ContactResidual:
    """The dropped modes' static flexibility on hats (module docs).

    Attributes
    ----------
    radii : numpy.ndarray, shape (K + 1,)
        Hat ``i`` peaks at ``radii[i] = i h``; the last falls to zero at ``radii[K]`` (``R``).
    normal, tangential : numpy.ndarray, shape (K, K)
        Mean displacement along the wall's normal (inwards) and in line per unit force on each
        hat, symmetric, ``1 / (E R)``.
    tilt, cross : numpy.ndarray, shape (K, K)
        Dundurs' coupling (docs/oblique.md): the amplitude of the normal displacement (inwards)
        ``cos(psi)`` on each hat per unit of a hat's tilting load (its nodes' forces times
        ``cos(psi)``, ``psi`` the azimuth about the contact axis from the line of the friction
        force), symmetric; and that amplitude per unit in-line force on a hat (its transpose:
        the mean in-line displacement per unit tilting load, Betti).
    """

    radii: np.ndarray
    normal: np.ndarray
    tangential: np.ndarray
    tilt: np.ndarray
    cross: np.ndarray
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

    def azimuth(self, count: int, rotation: float) -> tuple[np.ndarray, np.ndarray]:
        """``cos(psi)`` of the first ``count`` wall nodes about the contact axis (``psi`` from
        the line of the friction force, ``y / rho``; 0 on the axis) and its derivative in the
        rotation."""
        c, s, z = self._c[:count], self._s[:count], self._z[:count]
        ct, st = math.cos(rotation), math.sin(rotation)
        y, dy = c * st + s * ct, c * ct - s * st
        rho2 = y * y + z * z
        on = rho2 > 1e-24
        safe = np.where(on, rho2, 1.0)
        cos = np.where(on, y / np.sqrt(safe), 0.0)
        return cos, np.where(on, dy * z * z / safe**1.5, 0.0)


HAT_SPACING = 2.0
"""The hats' spacing in the projected radius, in units of the wall nodes' ring spacing at the
pole (module docs)."""


def contact_residual(cap, nodes, reach: float, *, spacing: float = HAT_SPACING) -> ContactResidual:
    """The residual of ``cap``'s dropped modes on hats over its wall ``nodes``
    (:class:`~restitution.bodies.sphere.cap_nodes.CapNodes`) out to the projected radius
    ``reach`` (``R``, the contact's largest extent), ``spacing`` times the rings' spacing
    apart."""
    theta = np.asarray(nodes.theta, float)
    if theta.size < 2 or not spacing > 0.0:
        raise InputError("the residual needs two rings of wall nodes and a spacing > 0")
    h = float(spacing) * (math.sin(theta[1]) - math.sin(theta[0]))
    count = int(math.ceil(float(reach) / h)) + 1
    radii = h * np.arange(count + 1)
    if radii[-1] >= min(0.9, math.sin(theta[-1])):
        raise InputError(
            f"the contact's reach {reach:.3g} R leaves the sphere's wall nodes (their last ring "
            f"at {math.sin(theta[-1]):.3g} R) or wraps too far round the sphere for the "
            "residual's flat annuli: lower the speed, or harden the wall"
        )
    normal, tangential, tilt, cross = _flexibility(cap, h, count)
    A = int(nodes.azimuths)
    phi = np.tile(2.0 * math.pi * np.arange(A) / A, theta.size)
    z = np.sin(np.repeat(theta, A)) * np.sin(phi)
    return ContactResidual(radii, normal, tangential, tilt, cross, np.asarray(nodes.c),
                           np.asarray(nodes.s), z)  # fmt: skip


@functools.lru_cache(maxsize=8)
def _flexibility(cap, h: float, count: int) -> tuple[np.ndarray, ...]:
    """``H_n``, ``H_t``, the tilt's and the cross's of ``count`` hats ``h`` apart (module
    docs), kept for the last few (caps, spacings): an estimate and its run, or a law's two mode
    counts, build them once (the continuum's orders run to ``800 / (count h)``: seconds on hard
    walls). A tilting load ``q cos(phi)`` on an annulus is the hat load ``q A / 2`` and moves
    its nodes by ``u cos(phi)`` where ``int u cos(phi)^2 dA = u A / 2``: the tilt's flexibility
    is ``4 G / (A_i A_j)`` and the cross's ``2 G / (A_i A_j)``."""
    radii = h * np.arange(count + 1)
    edges = np.r_[0.0, 0.5 * (radii[:-2] + radii[1:-1]), 0.5 * (radii[-2] + radii[-1])]
    area = math.pi * np.diff(edges**2)
    scale = np.outer(area, area)
    out = []
    for direction in ("normal", "tangential"):
        G = annulus_flexibility(edges, cap.nu, direction)
        if len(cap):
            G = G - modal_annulus_flexibility(cap, edges, direction)
        out.append(G / scale)
    tilt, cross = annulus_tilt_flexibility(edges, cap.nu)
    if len(cap):
        kept_tilt, kept_cross = modal_annulus_tilt_flexibility(cap, edges)
        tilt, cross = tilt - kept_tilt, cross - kept_cross
    tilt, cross = 4.0 * tilt / scale, 2.0 * cross / scale
    # The first hat peaks on the axis, where a field cos(psi) jumps as a node crosses it: the
    # tilt leaves that hat out (its displacement would jump with the body's turn and break the
    # energy's balance: 3.3e-6 E0 at 6 modes, alpha = 300; docs/oblique.md).
    tilt[0, :], tilt[:, 0], cross[0, :] = 0.0, 0.0, 0.0
    out += [tilt, cross]
    for H in out:
        H.setflags(write=False)
    return tuple(out)
