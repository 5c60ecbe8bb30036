"""A viscoelastic body: any elastic body of the protocol, its material given one relaxation time.

Units: reduced units of the body's material, ``E = rho = R = 1``; ``tau`` in ``R / c``, damping
rates in ``c / R``.

The material is Kelvin-Voigt with a single relaxation time ``tau``: the viscous stress is ``tau``
times the rate of the elastic stress, i.e. the shear and bulk viscosities are ``tau`` times the
shear and bulk moduli. The stiffness and the damping are then proportional, so the free modes of
the elastic body stay the modes of the damped one, each with its own decay::

    m Q_k'' + m gamma_k Q_k' + m omega_k^2 Q_k = f_k,    gamma_k = tau omega_k^2,

(the modal damping matrix ``tau K`` is diagonal in the modes that diagonalise ``K``). Modes with
``gamma_k > 2 omega_k``, i.e. ``omega_k > 2 / tau``, are overdamped. The collision integrates
each mode's damped free flow exactly (:mod:`restitution.dynamics.damping`).

In the quasistatic limit this material gives the dissipative contact force
``F_dis = tau dF_el/dt``: Brilliantov et al.'s constant ``A`` is ``tau`` exactly for
proportional viscosities (:mod:`restitution.quasistatic.viscoelastic`).

A viscosity that is not proportional to the moduli couples the modes (the damping matrix is not
diagonal in them); it is not modelled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.bodies.base import ModalBody
from restitution.errors import InputError

__all__ = ["Viscoelastic", "mode_damping"]


@dataclass(frozen=True, eq=False)
class Viscoelastic:
    """``body`` made of a Kelvin-Voigt material with relaxation time ``relaxation_time``.

    Everything of the body protocol is the elastic body's; :attr:`damping` adds each mode's
    decay rate. ``take`` and ``lowest`` keep the material.

    Parameters
    ----------
    body : ModalBody
        The elastic body (a disk's ``ModeSet``, a sphere's modes, a pair of disks).
    relaxation_time : float
        ``tau``, in ``R / c`` of the body's reduced units; ``0`` is the elastic body.

    Examples
    --------
    >>> from restitution import get_modes
    >>> body = Viscoelastic(get_modes(0.33, count=20), relaxation_time=0.01)
    >>> bool(body.damping[0] == 0.01 * body.omega[0] ** 2)
    True
    """

    body: ModalBody
    relaxation_time: float

    def __post_init__(self) -> None:
        if not isinstance(self.body, ModalBody):
            raise InputError(
                f"body must be an elastic body's mode set (see get_modes), got "
                f"{type(self.body).__name__}"
            )
        tau = self.relaxation_time
        if isinstance(tau, bool) or not isinstance(tau, (int, float, np.floating, np.integer)):
            raise InputError(f"relaxation_time must be a number (R/c), got {type(tau).__name__}")
        if not math.isfinite(tau) or tau < 0:
            raise InputError(
                f"relaxation_time must be finite and >= 0 (R/c), got {tau!r}; 0 is the elastic body"
            )
        object.__setattr__(self, "relaxation_time", float(tau))

    def __getattr__(self, name: str):
        # Everything else of the protocol (and of the body) is the elastic body's.
        if name == "body":
            raise AttributeError(name)
        return getattr(self.body, name)

    def __len__(self) -> int:
        return len(self.body)

    @property
    def damping(self) -> np.ndarray:
        """``gamma_k = tau omega_k^2`` of every mode, ``c / R``."""
        return self.relaxation_time * self.body.omega**2

    def take(self, index) -> Viscoelastic:
        """The modes at ``index``, of the same material."""
        return Viscoelastic(self.body.take(index), self.relaxation_time)

    def lowest(self, count: int) -> Viscoelastic:
        """The ``count`` lowest-frequency modes, of the same material."""
        return Viscoelastic(self.body.lowest(count), self.relaxation_time)


def mode_damping(body: ModalBody) -> np.ndarray | None:
    """The damping rates of ``body``'s modes (``c / R``), or ``None`` for an elastic body
    (no :attr:`Viscoelastic.damping`, or all rates zero)."""
    gamma = getattr(body, "damping", None)
    if gamma is None:
        return None
    gamma = np.asarray(gamma, dtype=float)
    return gamma if np.any(gamma != 0.0) else None
