"""One point of epsilon(v) by the residual route: the collision with a static residual at three
kept-mode counts and three walls, and the hard-wall limit (issue 46, item 3).

Units: the body's ``E = rho = R = 1`` (a pair's: the first body's); ``v`` in ``c`` (a pair's
relative speed); the loss ``1 - epsilon^2`` as a fraction of the initial kinetic energy (a
pair's: in the centre-of-mass frame); walls ``alpha delta_max(v)`` (the kind's
:attr:`~restitution.bodies.kinds.BodyKind.alpha_products`, as the laws; a pair's on its own
compression scale, :meth:`~restitution.bodies.pair.partner.Partner.max_compression`).

At every wall the collision runs with ``N1``, ``N2 = 2 N1`` and ``N3 = 4 N1`` kept modes
(:func:`restitution.dynamics.residual.collide_residual`, the dropped modes static), the finest
with Richardson's step check. The loss at ``N3`` carries two errors, added in quadrature:

* **modes**: the larger change of the last two doublings, ``max(|L3 - L2|, |L2 - L1|)``. With
  the residual the loss converges at about second order in ``N`` but not monotonically
  (docs/numerics.md, "Fewer modes"): the last change alone was smaller than the error left
  behind it in 3 of the 19 cases of the stored study at ``N = 800`` (up to 9.8 times, the sphere
  at ``v = 0.0993`` on the hardest wall), the larger of the last two covered all 19 at ``N =
  400`` and ``800`` (the error left measured against ``N = 1600``; at most 0.93 and 0.42 of
  it). It is stated as the error, not divided;
* **step**: Richardson's ``|eps(dt) - eps(dt/2)| / 15``, carried to the loss.

A pair's counts are the body's times :func:`restitution.limits.sweep.window_scale` (both bodies'
modes below the frequency of the body's ``N`` lowest, as the modal sweeps of pairs).

The limit ``alpha -> infinity`` is the laws' own (:func:`restitution.limits.extrapolation.
extrapolate_alpha`, linear in ``1/alpha``, its standard error, drop-one spread and the points'
errors) with the wall's curvature (:func:`~restitution.limits.extrapolation.
alpha_curvature_shift`) in quadrature: the same error model as the shipped laws' points, with
the ``N -> infinity`` fit replaced by the residual's three sets.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import body_kind
from restitution.dynamics.residual import collide_residual
from restitution.estimate import Estimate, estimate_of
from restitution.limits.extrapolation import (
    FromLoss,
    alpha_curvature_shift,
    extrapolate_alpha,
)
from restitution.limits.sweep import window_scale

__all__ = ["NODES_PER_CONTACT", "RESIDUAL_MODES", "ResidualPoint", "residual_point"]

RESIDUAL_MODES = (200, 400, 800)
"""Kept modes ``(N1, N2, N3)`` of a point on the wall (measured: the sphere at ``v = 0.1``
within 2e-5 of ``N = 1600`` at 800; the disk at ``v = 0.1`` and ``alpha delta_max = 160``
within 4e-5 at ``nu = 0.33``, 2.7e-4 at ``nu = 0.9``, the slowest to converge)."""

NODES_PER_CONTACT = 80.0
"""Surface nodes across the contact's half-width (measured on the sphere at ``v = 0.1``:
2.6e-6 from the wall's finer rule)."""


@dataclass(frozen=True)
class ResidualPoint(FromLoss):
    """epsilon at one speed by the residual route, with its error budget (module docstring).

    ``energy_loss``, ``energy_loss_err``: the hard-wall limit of the loss and its error
    (:attr:`epsilon`, :attr:`epsilon_err` and :attr:`estimate` derive from them);
    ``losses``: shape (walls, 3), the loss at ``N1, N2, N3``; ``mode_err``, ``step_err``:
    per wall; ``alpha_err``: the hard-wall fit's error (with the points' errors);
    ``curvature``: the wall's curvature shift; ``seconds``: wall-clock time of the point;
    ``partner``: the second body's constants (:meth:`~restitution.bodies.pair.partner.
    Partner.to_dict`), ``None`` on the wall.
    """

    geometry: str
    nu: float
    v: float
    energy_loss: float
    energy_loss_err: float
    walls: tuple[float, ...]
    alphas: tuple[float, ...]
    modes: tuple[int, ...]
    losses: np.ndarray
    mode_err: np.ndarray
    step_err: np.ndarray
    alpha_err: float
    curvature: float
    asymptotic_ok: bool
    message: str
    seconds: float
    partner: dict | None = None

    @property
    def estimate(self) -> Estimate:
        """epsilon, its error and its status as one :class:`~restitution.estimate.Estimate`."""
        return estimate_of(self.epsilon, self.epsilon_err, self.asymptotic_ok, self.message)


def residual_point(
    geometry: str,
    nu: float,
    v: float,
    *,
    partner=None,
    walls: tuple[float, ...] | None = None,
    modes: tuple[int, ...] = RESIDUAL_MODES,
    nodes_per_contact: float = NODES_PER_CONTACT,
) -> ResidualPoint:
    """epsilon of the body ``geometry`` (Poisson number ``nu``) on the rigid wall at ``v``; with
    a ``partner`` (:class:`~restitution.bodies.pair.partner.Partner`, equal radii) of two such
    bodies at the relative speed ``v``."""
    start = time.perf_counter()
    kind = body_kind(geometry)
    walls = tuple(float(w) for w in (walls or kind.alpha_products))
    if partner is None:
        delta = float(kind.max_compression(v, nu))
        counts = tuple(int(n) for n in modes)
        bodies = [get_modes(nu, count=n, geometry=geometry) for n in counts]
    else:
        delta = float(partner.max_compression(v, geometry, nu))
        scale = window_scale(partner, geometry)
        counts = tuple(int(round(n * scale)) for n in modes)
        bodies = [partner.pair(nu, n, geometry) for n in counts]
    alphas = tuple(w / delta for w in walls)
    losses = np.empty((len(walls), len(counts)))
    step_err = np.empty(len(walls))
    for i, alpha in enumerate(alphas):
        for j, body in enumerate(bodies):
            finest = j == len(bodies) - 1
            run = collide_residual(
                body, v, alpha, nodes_per_contact=nodes_per_contact, richardson=finest
            )
            losses[i, j] = run.loss
        step_err[i] = 2.0 * run.epsilon * run.step_error
    changes = np.abs(np.diff(losses, axis=1))
    mode_err = changes[:, -2:].max(axis=1)
    point_err = np.hypot(mode_err, step_err)
    fit = extrapolate_alpha(np.array(alphas), losses[:, -1], loss_err=point_err)
    curvature = alpha_curvature_shift(fit)
    loss_err = math.hypot(fit.limit_err, curvature)
    return ResidualPoint(
        geometry=geometry,
        nu=float(nu),
        v=float(v),
        energy_loss=float(fit.limit),
        energy_loss_err=loss_err,
        walls=walls,
        alphas=alphas,
        modes=counts,
        losses=losses,
        mode_err=mode_err,
        step_err=step_err,
        alpha_err=float(fit.limit_err),
        curvature=float(curvature),
        asymptotic_ok=bool(fit.asymptotic_ok),
        message=fit.message,
        seconds=time.perf_counter() - start,
        partner=None if partner is None else partner.to_dict(),
    )
