"""The exponential wall of the paper (eqs. 41-42, 45): the default contact law.

Units: ``E = rho = R = 1``; ``alpha`` in ``1 / R``.

A surface point at ``x`` (the wall at ``x = 0``) stores ``exp(alpha x) / alpha`` per unit
weight and feels the pressure ``exp(alpha x)``: a soft wall whose decay length ``1 / alpha``
goes to zero in the rigid limit ``alpha -> infinity``. Conservative; the compiled kernel runs
it (branch ``"exponential"`` of :data:`restitution.dynamics.kernel.KERNEL_LAWS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from restitution.dynamics.contact.base import CONTACT_TOL, ContactLaw

if TYPE_CHECKING:
    from restitution.bodies.base import ModalBody, SurfaceQuadrature

__all__ = ["EXPONENTIAL_WALL", "NEGLIGIBLE", "STOP_LOG", "ExponentialWall"]

NEGLIGIBLE = 40.0
"""Nodes whose exponent ``alpha x`` is certainly below ``-NEGLIGIBLE`` contribute less than
``exp(-40) = 4e-18`` of the force at the wall and are skipped."""

STOP_LOG = math.log(1.0 / CONTACT_TOL)
"""A body leaving the wall is free once ``alpha * gap`` exceeds this (and ``V < CONTACT_TOL
E0``): every surface point's pressure is then below ``CONTACT_TOL``."""


@dataclass(frozen=True)
class ExponentialWall(ContactLaw):
    """The exponential wall ``V = (1/alpha) int exp(alpha x) dA`` (eq. 41).

    Conservative; no parameters besides the hardness ``alpha`` (``1 / R``). Every method is the
    arithmetic the package has always done, bit for bit.
    """

    name = "exponential"
    conservative = True
    kernel = "exponential"

    def node_terms(self, alpha, x, weight):
        """``e_j = weight_j exp(alpha x_j)``, ``F = sum e``, ``V = F / alpha``."""
        alpha = np.asarray(alpha)
        e = np.exp(alpha[..., None] * x) * weight
        F = e.sum(axis=-1)
        return F / alpha, F, e

    def cutoff(self, alpha):
        """``NEGLIGIBLE / alpha``: beyond it the pressure is below ``exp(-40)``."""
        return NEGLIGIBLE / alpha

    def step_time(self, alpha, v):
        """``1 / (alpha v)``: a point arriving at ``v`` is stopped within the decay length."""
        return 1.0 / (alpha * v)

    def separated(self, gap, alpha, V, e0):
        """``alpha * gap > STOP_LOG`` and ``V < CONTACT_TOL * e0``."""
        return (gap * alpha > STOP_LOG) & (V < CONTACT_TOL * e0)

    def start_position(self, alpha, e0, quad: SurfaceQuadrature):
        """Closed form: ``V(x0) = exp(alpha (x0 + 1)) I / alpha`` with the quadrature's
        ``I = int exp(alpha (h - 1)) dA``."""
        integral = np.exp(alpha[:, None] * (quad.height[None, :] - 1.0)) @ quad.weight
        return -1.0 + np.log(CONTACT_TOL * e0 * alpha / integral) / alpha

    def approach_gap(self, body: ModalBody, alpha, e0):
        """The start position's gap with the body's own
        :meth:`~restitution.bodies.base.ModalBody.depth_transform` for ``I``."""
        integral = body.depth_transform(alpha)
        with np.errstate(over="ignore", divide="ignore"):
            return np.maximum(0.0, -np.log(CONTACT_TOL * e0 * alpha / integral) / alpha)


EXPONENTIAL_WALL = ExponentialWall()
"""The paper's wall, the default law of every collision, sweep and store key."""
