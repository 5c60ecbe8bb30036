"""One point of epsilon(v) by the residual route: the collision with a static residual at a
few kept-mode counts and three walls, and the hard-wall limit (issue 46, item 3).

Units: the body's ``E = rho = R = 1``; ``v`` in ``c``; the loss ``1 - epsilon^2`` as a fraction
of the initial kinetic energy; walls ``alpha delta_max(v)`` (the kind's
:attr:`~restitution.bodies.kinds.BodyKind.alpha_products`, as the laws).

At every wall the collision runs with ``N1`` and ``N2 = 2 N1`` kept modes
(:func:`restitution.dynamics.residual.collide_residual`, the dropped modes static), the finer
one with Richardson's step check. The loss at ``N2`` carries two errors, added in quadrature:

* **modes**: ``|L(N2) - L(N1)|``. With the residual the loss converges at about second order
  in ``N`` (docs/numerics.md, "Fewer modes"), so the difference bounds the error left at ``N2``
  by a factor of about 3; it is stated as the error, not divided;
* **step**: Richardson's ``|eps(dt) - eps(dt/2)| / 15``, carried to the loss.

The limit ``alpha -> infinity`` is the laws' own (:func:`restitution.limits.extrapolation.
extrapolate_alpha`, linear in ``1/alpha``, its standard error, drop-one spread and the points'
errors) with the wall's curvature (:func:`~restitution.limits.extrapolation.
alpha_curvature_shift`) in quadrature: the same error model as the shipped laws' points, with
the ``N -> infinity`` fit replaced by the residual's two sets.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import body_kind
from restitution.dynamics.residual import collide_residual
from restitution.limits.extrapolation import (
    alpha_curvature_shift,
    epsilon_from_loss,
    extrapolate_alpha,
)

__all__ = ["NODES_PER_CONTACT", "RESIDUAL_MODES", "ResidualPoint", "residual_point"]

RESIDUAL_MODES = (400, 800)
"""Kept modes ``(N1, N2)`` of a point (measured: the sphere at ``v = 0.1`` within 2e-6 of its
limit at 400; the disk at ``v = 0.1`` and ``alpha delta_max = 160`` within 3e-5)."""

NODES_PER_CONTACT = 80.0
"""Surface nodes across the contact's half-width (measured on the sphere at ``v = 0.1``:
2.6e-6 from the wall's finer rule)."""


@dataclass(frozen=True)
class ResidualPoint:
    """epsilon at one speed by the residual route, with its error budget (module docstring).

    ``losses``: shape (walls, 2), the loss at ``N1`` and ``N2``; ``mode_err``, ``step_err``:
    per wall; ``alpha_err``: the hard-wall fit's error (with the points' errors);
    ``curvature``: the wall's curvature shift; ``seconds``: wall-clock time of the point.
    """

    geometry: str
    nu: float
    v: float
    epsilon: float
    epsilon_err: float
    energy_loss: float
    energy_loss_err: float
    walls: tuple[float, ...]
    alphas: tuple[float, ...]
    modes: tuple[int, int]
    losses: np.ndarray
    mode_err: np.ndarray
    step_err: np.ndarray
    alpha_err: float
    curvature: float
    asymptotic_ok: bool
    message: str
    seconds: float


def residual_point(
    geometry: str,
    nu: float,
    v: float,
    *,
    walls: tuple[float, ...] | None = None,
    modes: tuple[int, int] = RESIDUAL_MODES,
    nodes_per_contact: float = NODES_PER_CONTACT,
) -> ResidualPoint:
    """epsilon of the body ``geometry`` (Poisson number ``nu``) on the rigid wall at ``v``."""
    start = time.perf_counter()
    kind = body_kind(geometry)
    walls = tuple(float(w) for w in (walls or kind.alpha_products))
    delta = float(kind.max_compression(v, nu))
    alphas = tuple(w / delta for w in walls)
    bodies = [get_modes(nu, count=n, geometry=geometry) for n in modes]
    losses = np.empty((len(walls), 2))
    step_err = np.empty(len(walls))
    for i, alpha in enumerate(alphas):
        coarse = collide_residual(bodies[0], v, alpha, nodes_per_contact=nodes_per_contact)
        fine = collide_residual(
            bodies[1], v, alpha, nodes_per_contact=nodes_per_contact, richardson=True
        )
        losses[i] = coarse.loss, fine.loss
        step_err[i] = 2.0 * fine.epsilon * fine.step_error
    mode_err = np.abs(losses[:, 1] - losses[:, 0])
    point_err = np.hypot(mode_err, step_err)
    fit = extrapolate_alpha(np.array(alphas), losses[:, 1], loss_err=point_err)
    curvature = alpha_curvature_shift(fit)
    loss_err = math.hypot(fit.limit_err, curvature)
    eps, eps_err = epsilon_from_loss(fit.limit, loss_err)
    return ResidualPoint(
        geometry=geometry,
        nu=float(nu),
        v=float(v),
        epsilon=eps,
        epsilon_err=eps_err,
        energy_loss=float(fit.limit),
        energy_loss_err=loss_err,
        walls=walls,
        alphas=alphas,
        modes=(int(modes[0]), int(modes[1])),
        losses=losses,
        mode_err=mode_err,
        step_err=step_err,
        alpha_err=float(fit.limit_err),
        curvature=float(curvature),
        asymptotic_ok=bool(fit.asymptotic_ok),
        message=fit.message,
        seconds=time.perf_counter() - start,
    )
