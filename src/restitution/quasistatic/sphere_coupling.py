"""The one-state quasistatic impact of the finite sphere with Dundurs' coupling: the in-line
traction tilts the contact, the wall holds it flat with a tilting pressure, and that pressure
pulls the surface back in line (issue 63; docs/oblique.md, "Dundurs' coupling").

Units: ``E = rho = R = 1`` (three-dimensional constants), speeds in ``c``.

**Why.** An elastic sphere on a rigid wall is a dissimilar pair: Dundurs' ``beta_D = (1 - 2
nu) / (2 (1 - nu))`` (0.286 at ``nu = 0.3``) couples the normal and tangential problems. The
one-state twin (:func:`restitution.quasistatic.sphere_one_state.one_state_impact`), like Maw,
Barber and Fawcett's theory, leaves it out; the modal route keeps it in its modes of azimuthal
order 1 (:func:`~restitution.bodies.sphere.contact_compliance.modal_annulus_tilt_flexibility`),
whose share of it grows with the mode count, and the route's residual covers only the
axisymmetric pressure and the in-line traction. That growing share is the residual route's
drift in the modes (docs/oblique.md).

**The model.** The one-state contact of :mod:`restitution.quasistatic.sphere_one_state` on
annuli, with the in-line traction ``T`` (forces on the annuli, spread like the pressure) also
moving the surface along the wall's normal by ``cos(phi)`` times ``X A^-1 T`` (``X`` the
annuli's ``cross`` of
:func:`~restitution.bodies.sphere.contact_compliance.annulus_tilt_flexibility`, ``A`` their
areas). The wall answers on the annuli ``c`` in contact with a pressure ``q
cos(phi)`` (per projected area) that keeps their tilt at the wall's own: ``(G_c + W) q = -X_c
A^-1 T``, ``G`` the ``tilt`` flexibility and ``W = diag(A / (2 alpha p))`` the exponential
wall's compliance to it (``p`` the annulus's pressure; ``0`` for the rigid wall). The tilting
pressure moves the surface in line by ``A^-1 X_c^T q``, so the in-line flexibility between the
annuli's forces and mean displacements is the Schur complement::

    H_eff = H_t - A^-1 X_c^T (G_c + W)^-1 X_c A^-1

symmetric and no larger than ``H_t`` (the constraint stiffens the contact), and the one-state
stick condition runs on it as on ``H_t``.

**Checks** (tests/test_sphere_coupling.py): the tilt and cross flexibilities against the
half-space's Hankel integrals as the annuli shrink; gross slip unchanged; the coupling's effect
falls with ``1 - 2 nu``; the flexibility no larger than the uncoupled one.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from restitution.bodies.sphere.contact_compliance import annulus_tilt_flexibility
from restitution.dynamics.one_state import OneStateFriction
from restitution.errors import InputError
from restitution.quasistatic.sphere_partial_slip import (
    AnnularContact,
    PartialSlipImpact,
    annular_impact,
    checked_impact,
    hertz_peak,
    run,
)

__all__ = [
    "TiltedOneStateFriction",
    "coupled_one_state_impact",
    "coupled_one_state_run",
    "coupled_one_state_seconds",
]


class TiltedOneStateFriction(OneStateFriction):
    """:class:`~restitution.dynamics.one_state.OneStateFriction` on the coupled in-line
    flexibility ``H_eff`` of the annuli in contact (module docs): ``tilt`` and ``cross`` their
    order-1 flexibilities (annulus by annulus, :func:`annulus_tilt_flexibility`), ``area``
    their areas, ``alpha`` the wall's hardness (``None``: rigid)."""

    def __init__(self, Ht, tilt, cross, area, alpha: float | None = None) -> None:
        super().__init__(Ht)
        self.tilt, self.area = np.asarray(tilt, float), np.asarray(area, float)
        self.cross = np.asarray(cross, float) / self.area[None, :]
        if alpha is not None and not alpha > 0.0:
            raise InputError(f"alpha must be > 0 or None (the rigid wall), got {alpha!r}")
        self.alpha = alpha

    def flexibility(self, P: np.ndarray) -> np.ndarray:
        """``H_eff`` at the annuli's normal forces ``P`` (module docs)."""
        on = np.flatnonzero(P > 0.0)
        if on.size == 0:
            return self.Ht
        M = self.tilt[np.ix_(on, on)]
        if self.alpha is not None:
            M = M + np.diag(0.5 * self.area[on] ** 2 / (self.alpha * P[on]))
        X = self.cross[on]
        return self.Ht - X.T @ np.linalg.solve(M, X)


@functools.lru_cache(maxsize=4)
def _tilt(edges: tuple[float, ...], nu: float) -> tuple[np.ndarray, np.ndarray]:
    return annulus_tilt_flexibility(np.array(edges), nu)


def coupled_one_state_run(contact: AnnularContact, v: float, v_tangential: float, mu: float,
                          nu: float, steps: int, *, alpha: float | None = None,
                          flexibility=None) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of one impact on ``contact`` with one stick/slip state
    and Dundurs' coupling (module docs), ``steps`` per Hertz contact time; ``flexibility``
    (default the continuum's) gives ``(tilt, cross)`` for the annuli's edges: the kept modes'
    (:func:`~restitution.bodies.sphere.contact_compliance.modal_annulus_tilt_flexibility`)
    make the modal route's share of the coupling."""
    if flexibility is None:
        tilt, cross = _tilt(tuple(contact.edges.tolist()), float(nu))
    else:
        tilt, cross = flexibility(contact.edges)

    def law(Ht):
        return TiltedOneStateFriction(Ht, tilt, cross, contact.area, alpha)

    return run(contact, v, v_tangential, mu, nu, steps, friction=law)


def coupled_one_state_seconds(v: float, nu: float) -> float:
    """The estimated seconds of :func:`coupled_one_state_impact` at its defaults: ``0.5 + 0.14
    / a`` for Hertz's contact radius ``a``, fitted to runs at ``a`` = 0.017-0.27 (1.0-8.8 s,
    within 0.6 s; one core of the development machine, 5 Dec 2026)."""
    return 0.5 + 0.14 / math.sqrt(hertz_peak(v, nu))


def coupled_one_state_impact(v_normal: float, v_tangential: float, mu: float, nu: float, *,
                             annuli: int = 40, steps: int = 4000) -> PartialSlipImpact:  # fmt: skip
    """The finite solid sphere's quasistatic oblique impact on the rigid wall with one
    stick/slip state and Dundurs' coupling (module docs), from rest in spin; arguments and
    answer as :func:`restitution.quasistatic.sphere_one_state.one_state_impact`.

    Examples
    --------
    >>> from restitution.quasistatic.sphere_one_state import one_state_impact
    >>> v = 0.0001933  # 1 m/s on steel, in c
    >>> free = one_state_impact(v, 0.57735 * v, 0.3, 0.3, annuli=20, steps=1000)
    >>> held = coupled_one_state_impact(v, 0.57735 * v, 0.3, 0.3, annuli=20, steps=1000)
    >>> round(free.beta, 2), round(held.beta, 2)
    (0.34, 0.32)
    """
    v, vt, mu, nu = checked_impact(v_normal, v_tangential, mu, nu)
    return annular_impact(coupled_one_state_run, v, vt, mu, nu, annuli=annuli, steps=steps)
