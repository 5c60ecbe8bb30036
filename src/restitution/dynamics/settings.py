"""Numerical settings of a collision run.

Units: ``E = rho = R = 1``; times in ``R / c``. The contact threshold of a collision's start and
stop (``CONTACT_TOL``, ``STOP_LOG``) belongs to the contact law
(:mod:`restitution.dynamics.contact`); it is re-exported here for the callers that import it
from this module.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.dynamics.contact.base import CONTACT_TOL
from restitution.dynamics.contact.exponential import STOP_LOG
from restitution.dynamics.integrators import INTEGRATORS
from restitution.errors import InputError, describe

__all__ = ["BACKENDS", "CONTACT_TOL", "DEFAULT_ENERGY_TOL", "STOP_LOG", "CollisionSettings"]

BACKENDS = ("auto", "compiled", "numpy")


DEFAULT_ENERGY_TOL = 1e-6
"""The default relative energy drift a collision's step is refined to."""


@dataclass(frozen=True)
class CollisionSettings:
    """Numerical settings of a collision run.

    Attributes
    ----------
    integrator : {"split4", "split", "rk4"}
        Time integrator (see :mod:`restitution.dynamics.integrators`); the default ``split4`` is the
        fourth-order symplectic composition of the exact-free-flow splitting.
    n_phi : int or None
        Nodes of the surface quadrature (the disk's edge on ``[0, pi/2]``); ``None`` picks
        the contact law's demand (:meth:`~restitution.dynamics.contact.base.ContactLaw.nodes`).
    energy_tol : float
        Largest accepted relative energy drift ``max |H(t) - H(0)| / H(0)``.
    dt : float or None
        Fixed step in ``R / c``. ``None`` chooses it automatically and refines it until the
        drift is below ``energy_tol``; a fixed step is never refined (the drift is reported).
    max_refinements : int
        How often the automatic step may be reduced before the run fails.
    step_safety : float
        Multiplies the automatic first step; smaller is more cautious.
    record : bool
        Keep time histories (:class:`restitution.dynamics.results.History`).
    record_interval : float
        Time between history samples, ``R / c``.
    max_steps : int
        Hard bound on the number of steps of one run.
    backend : {"auto", "compiled", "numpy"}
        ``compiled`` runs the splittings in the numba kernel (:mod:`restitution.dynamics.kernel`);
        ``numpy`` runs the NumPy reference path (needed for ``rk4`` and recorded histories);
        ``auto`` takes the kernel whenever it applies. Both give the same numbers to round-off.
    """

    integrator: str = "split4"
    n_phi: int | None = None
    energy_tol: float = DEFAULT_ENERGY_TOL
    dt: float | None = None
    max_refinements: int = 6
    step_safety: float = 1.0
    record: bool = False
    record_interval: float = 0.02
    max_steps: int = 2_000_000
    backend: str = "auto"

    def __post_init__(self) -> None:
        # A name only: a list or an array is unhashable, or compares elementwise (issue 47).
        if not (isinstance(self.integrator, str) and self.integrator in INTEGRATORS):
            raise InputError(
                f"unknown integrator {describe(self.integrator)}; choose one of "
                f"{', '.join(map(repr, sorted(INTEGRATORS)))}"
            )
        _require(
            _is_real(self.energy_tol) and 0 < self.energy_tol < 1,
            f"energy_tol must be a number in (0, 1) (relative energy drift), got "
            f"{self.energy_tol!r}",
        )
        _require(
            self.dt is None or (_is_real(self.dt) and self.dt > 0),
            f"dt must be None (automatic) or a positive number in R/c, got {self.dt!r}",
        )
        _require(
            self.n_phi is None or (_is_int(self.n_phi) and self.n_phi >= 16),
            f"n_phi must be None (automatic) or an integer >= 16, got {self.n_phi!r}",
        )
        _require(
            _is_int(self.max_refinements) and self.max_refinements >= 0,
            f"max_refinements must be an integer >= 0, got {self.max_refinements!r}",
        )
        _require(
            _is_real(self.step_safety) and self.step_safety > 0,
            f"step_safety must be a positive number (it multiplies the automatic step), got "
            f"{self.step_safety!r}",
        )
        _require(
            isinstance(self.record, bool | np.bool_),
            f"record must be True or False, got {self.record!r}",
        )
        _require(
            _is_real(self.record_interval) and self.record_interval > 0,
            f"record_interval must be a positive time in R/c, got {self.record_interval!r}",
        )
        _require(
            _is_int(self.max_steps) and self.max_steps >= 1,
            f"max_steps must be a positive integer, got {self.max_steps!r}",
        )
        _require(
            isinstance(self.backend, str) and self.backend in BACKENDS,
            f"unknown backend {describe(self.backend)}; choose one of "
            f"{', '.join(map(repr, BACKENDS))}",
        )


def _require(condition: bool, message: str) -> None:
    if not condition:
        raise InputError(message)


def _is_int(value) -> bool:
    return isinstance(value, int | np.integer) and not isinstance(value, bool | np.bool_)


def _is_real(value) -> bool:
    return (
        isinstance(value, int | float | np.integer | np.floating)
        and not isinstance(value, bool | np.bool_)
        and math.isfinite(value)
    )
