"""The slow-impact model of :mod:`restitution.quasistatic.slow_disk` with material damping: a
Kelvin-Voigt disk (one relaxation time ``tau``, viscosities ``tau`` times the moduli, the
material of :class:`restitution.bodies.viscoelastic.Viscoelastic`).

Units: as :mod:`restitution.quasistatic.slow_disk` (``E = rho = R = 1`` of the disk's
two-dimensional constants; ``v`` and ``tau`` in ``c`` and ``R / c``; energies as fractions of
``(m/2) v^2``); two disks in the first disk's units.

The damping enters both parts of the model. A kept mode is a damped oscillator,
``Q_k'' = -omega_k^2 (Q_k + tau Q_k') - C_k P / m``. The modes above the cut and the contact's
local field follow the force statically, so their viscous stress is ``tau`` times the rate of
their elastic stress, and the force at the contact becomes (as in the quasistatic Kelvin-Voigt
contact, :mod:`restitution.quasistatic.viscoelastic`, eq. 1)::

    P = P_el(s) + tau dP_el/dt = P_el(s) + tau P_el'(s) s',     s = delta + sum_{k<=K} C_k Q_k

with ``P_el`` the shifted 2D Hertz law of the cut. The contact ends when ``P`` first returns
to zero (the wall cannot pull: the ``"force"`` separation of the quasistatic viscous collision).
With no kept mode this is the quasistatic viscous collision
(:func:`restitution.quasistatic.viscoelastic.viscous_collision`, checked to 1e-9); with
``tau = 0`` it is the elastic model.

What it is for. The damped modal disk's viscous loss (its loss less the elastic law's) came out
0.885-0.89 times the quasistatic viscous law's at ``v = 1e-3 - 5e-3`` (docs/damping.md). In this
model the low modes take part in the contact as they do in the modal body, and the ratio comes
out the same (0.87-0.91 at ``v = 1e-3``): the quasistatic viscous law of the disk is a limit
approached only logarithmically, like the elastic one (docs/quasistatic.md, section 7).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from restitution.bodies.base import ModalBody
from restitution.errors import InputError
from restitution.quasistatic.hertz import quasistatic_collision
from restitution.quasistatic.slow_disk import (
    SLOW_CUTS,
    closure_law,
    cut_fits,
    equations,
    run_contact,
    shifted_law,
    slow_collision,
)

__all__ = ["DampedSlowLoss", "damped_slow_loss", "damped_slow_epsilon"]


def damped_slow_epsilon(modes: ModalBody, v: float, omega_cut: float, tau: float) -> float:
    """``epsilon`` of one slow collision of the damped disk (module docs) at one cut.

    Parameters
    ----------
    modes : ModalBody
        The disk's modes or a pair of disks (:func:`restitution.quasistatic.slow_disk.slow_modes`).
    v : float
        Speed towards the wall (a pair: relative speed), ``c``.
    omega_cut : float
        ``Omega``, ``c / R`` (0: the quasistatic viscous collision).
    tau : float
        Relaxation time, ``R / c``, ``>= 0``.
    """
    if not (isinstance(tau, (int, float)) and math.isfinite(tau) and tau >= 0):
        raise InputError(f"tau must be a number >= 0 (R/c), got {tau!r}")
    if tau == 0:
        return slow_collision(modes, v, omega_cut).epsilon
    slow_collision(modes, v, 0.0)  # the same checks of the body and the speed
    law, keep = shifted_law(modes, omega_cut)
    om, C, m = modes.omega[keep], modes.C[keep], modes.mass
    tau_qs = float(quasistatic_collision(closure_law(modes), v, mass=m).contact_time[0])
    force, rhs = equations(law, om, C, m, tau)
    # The contact opens when the force first returns to zero (the wall cannot pull).
    sol = run_contact(rhs, force, v, tau_qs, om.size,
                      f"damped slow collision at v = {v:g}, tau = {tau:g}")  # fmt: skip
    return -float(sol.y_events[0][0][1]) / v


@dataclass(frozen=True)
class DampedSlowLoss:
    """The damped disk's loss at a slow impact, its viscous part and their convergence.

    Attributes
    ----------
    v, tau : float
        Speed (``c``) and relaxation time (``R / c``).
    energy_loss : float
        ``1 - epsilon^2`` with damping, at the highest cut that fits.
    viscous_loss : float
        ``energy_loss`` less the elastic model's loss at the same cut.
    convergence_err : float
        The largest change of ``viscous_loss`` between the highest cut and the two below it.
    cuts, viscous_losses : tuple of float
        The cuts that fit and the viscous loss at each.
    """

    v: float
    tau: float
    energy_loss: float
    viscous_loss: float
    convergence_err: float
    cuts: tuple[float, ...]
    viscous_losses: tuple[float, ...]


def damped_slow_loss(modes: ModalBody, v: float, tau: float, *, cuts=SLOW_CUTS) -> DampedSlowLoss:
    """The damped model at every cut of ``cuts`` that fits
    (:func:`restitution.quasistatic.slow_disk.cut_fits`; at least three must): the loss and its
    viscous part at the highest, with the change between the cuts."""
    fitting = [float(x) for x in cuts if cut_fits(modes, v, float(x))]
    if len(fitting) < 3:
        raise InputError(
            f"only {len(fitting)} cuts fit at v = {v:g} c (the contact is too wide for the "
            "model); use the damped modal body there"
        )
    damped = [1.0 - damped_slow_epsilon(modes, v, x, tau) ** 2 for x in fitting]
    elastic = [slow_collision(modes, v, x).energy_loss for x in fitting]
    viscous = [d - e for d, e in zip(damped, elastic, strict=True)]
    last = viscous[-1]
    return DampedSlowLoss(
        v=float(v),
        tau=float(tau),
        energy_loss=float(damped[-1]),
        viscous_loss=float(last),
        convergence_err=float(max(abs(last - x) for x in viscous[-3:-1])),
        cuts=tuple(fitting),
        viscous_losses=tuple(float(x) for x in viscous),
    )
