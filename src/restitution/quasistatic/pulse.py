"""The quasistatic force pulse at the contact point, for any body, and its drive of the modes.

Units: ``E = rho = R = 1`` of the body's own constants; times in ``R / c``; forces in ``E R``
(disk, per unit thickness) or ``E R^2`` (sphere).

A slow collision presses the body's contact point with the force ``P(t) >= 0`` of the
quasistatic equation of motion ``m delta'' = -P(delta)`` for ``0 <= t <= tau``; by time reversal
the pulse is symmetric about ``tau / 2``. Its drive of a mode of frequency ``omega`` is::

    I(omega) = int_0^{tau/2} P(t) cos(omega (tau/2 - t)) dt,
    |int_0^tau P(t) e^{-i omega t} dt| = 2 |I(omega)|.

What the two geometries share lives here: the protocol of a pulse (:class:`ForcePulse`), the
quadrature of ``I`` (:func:`pulse_drive`), and the table of which contact law a body of each
geometry takes (:data:`THEORIES`): the 2D Hertz law of :mod:`restitution.quasistatic.hertz` for
the disk (default ``"paper"``, eq. 57 as printed), Hertz's 3D law of
:mod:`restitution.quasistatic.hertz_sphere` for the sphere.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

from restitution.errors import InputError
from restitution.quasistatic.hertz import LAWS, HertzLaw, contact_law, quasistatic_trajectory
from restitution.quasistatic.hertz_pair import pair_contact_law, pair_mass
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    SphereHertzLaw,
    sphere_contact_law,
    sphere_pair_contact_law,
    sphere_pair_mass,
    sphere_quasistatic_trajectory,
)

__all__ = [
    "THEORIES",
    "pair_contact_for",
    "ContactLaw",
    "ForcePulse",
    "QuasistaticTheory",
    "contact_law_for",
    "force_pulse",
    "panel_nodes",
    "pulse_drive",
    "pulse_spectrum",
]

ContactLaw = HertzLaw | SphereHertzLaw
"""A quasistatic contact law of one of the geometries."""


@runtime_checkable
class ForcePulse(Protocol):
    """A force pulse ``P(t)`` on ``[0, contact_time]``, symmetric about its middle.

    :class:`~restitution.quasistatic.hertz.QuasistaticTrajectory` (disk, DOP853) and
    :class:`~restitution.quasistatic.hertz_sphere.SphereQuasistaticTrajectory` (sphere, closed
    form) are pulses.
    """

    contact_time: float  # tau, R / c
    max_compression: float  # delta_max, R

    def force(self, t: np.ndarray) -> np.ndarray:
        """``P(t)``, zero outside ``[0, contact_time]``."""


@dataclass(frozen=True)
class QuasistaticTheory:
    """The quasistatic contact theory of one geometry.

    Attributes
    ----------
    law_type : type
        The class of its contact laws.
    laws : tuple of str
        Names :attr:`make_law` accepts.
    default_law : str
        The law taken when none is named.
    make_law : callable
        ``make_law(nu, name)`` -> law, at the body's own Poisson number.
    trajectory : callable
        ``trajectory(law, v, mass=...)`` -> :class:`ForcePulse`.
    mass : float
        The body's mass in reduced units (the default of the trajectory).
    make_pair_law : callable
        ``make_pair_law(nu, partner)`` -> the law of two such bodies pressed together (the
        second of :class:`~restitution.bodies.pair.partner.Partner`'s size and material), in
        the first body's units.
    pair_mass : callable
        ``pair_mass(partner)`` -> their reduced mass ``m1 m2 / (m1 + m2)``, reduced units.
    """

    law_type: type
    laws: tuple[str, ...]
    default_law: str
    make_law: Callable[[float, str], ContactLaw]
    trajectory: Callable[..., ForcePulse]
    mass: float
    make_pair_law: Callable[..., ContactLaw]
    pair_mass: Callable[..., float]


THEORIES: dict[str, QuasistaticTheory] = {
    HertzLaw.geometry: QuasistaticTheory(
        law_type=HertzLaw,
        laws=LAWS,
        default_law="paper",
        make_law=lambda nu, name: contact_law(nu, name),
        trajectory=quasistatic_trajectory,
        mass=math.pi,
        make_pair_law=lambda nu, p: pair_contact_law(
            nu, p.nu2(nu), radius_ratio=p.radius_ratio, modulus_ratio=p.modulus_ratio
        ),
        pair_mass=lambda p: pair_mass(p.radius_ratio, p.density_ratio),
    ),
    SphereHertzLaw.geometry: QuasistaticTheory(
        law_type=SphereHertzLaw,
        laws=("hertz",),
        default_law="hertz",
        make_law=lambda nu, name: sphere_contact_law(nu),
        trajectory=sphere_quasistatic_trajectory,
        mass=SPHERE_MASS,
        make_pair_law=lambda nu, p: sphere_pair_contact_law(
            nu, p.nu2(nu), radius_ratio=p.radius_ratio, modulus_ratio=p.modulus_ratio
        ),
        pair_mass=lambda p: sphere_pair_mass(p.radius_ratio, p.density_ratio),
    ),
}
"""The quasistatic theory of every geometry that has one."""


def pair_contact_for(geometry: str, nu: float, partner) -> tuple[ContactLaw, float]:
    """``(law, reduced mass)`` of a body of ``geometry`` (Poisson number ``nu``) pressed against
    its ``partner`` (:class:`~restitution.bodies.pair.partner.Partner`), first body's units."""
    theory = _theory(geometry)
    return theory.make_pair_law(nu, partner), theory.pair_mass(partner)


def _theory(geometry: str) -> QuasistaticTheory:
    theory = THEORIES.get(geometry)
    if theory is None:
        raise InputError(
            f"no quasistatic contact theory for the geometry {geometry!r}; there is one for "
            f"{', '.join(THEORIES)}"
        )
    return theory


def contact_law_for(geometry: str, nu: float, law: ContactLaw | str | None = None) -> ContactLaw:
    """The contact law of a body of ``geometry`` and Poisson number ``nu``.

    Parameters
    ----------
    geometry : str
        A body kind's name with a theory here (:data:`THEORIES`: the disk, the sphere).
    nu : float
        The body's Poisson number (the disk's two-dimensional one, the sphere's 3D one).
    law : law object, str or None
        A law (checked to suit the geometry), a law's name, or ``None`` for the geometry's
        default (``"paper"`` for the disk, ``"hertz"`` for the sphere).
    """
    theory = _theory(geometry)
    if law is None:
        law = theory.default_law
    if isinstance(law, str):
        if law not in theory.laws:
            raise InputError(
                f"unknown contact law {law!r} for the {geometry}; choose one of "
                f"{', '.join(theory.laws)}"
            )
        return theory.make_law(nu, law)
    if not isinstance(law, theory.law_type):
        raise InputError(
            f"a {type(law).__name__} is not a contact law of the {geometry}; give a "
            f"{theory.law_type.__name__} or one of {', '.join(theory.laws)}"
        )
    return law


def force_pulse(law: ContactLaw, v: float, *, mass: float | None = None) -> ForcePulse:
    """The quasistatic pulse of ``law`` at speed ``v`` (``c``) for a body of ``mass`` (default:
    the law's geometry's reduced mass, ``pi`` for the disk, ``4 pi / 3`` for the sphere)."""
    theory = _theory(getattr(law, "geometry", None))
    return theory.trajectory(law, v, mass=theory.mass if mass is None else mass)


_BLOCK = 1 << 22
"""Most entries (8 bytes each: 32 MiB) of one block of the drive's cosine table."""


def _nodes(half: float, omega_max: float, per_panel: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on ``[0, half]``: uniform panels of at most a third of a
    period of ``omega_max`` (and at most ``half/64``), the first one split geometrically
    towards ``t = 0``, where the pulse is not smooth (``t / ln(1/t)`` for the disk,
    ``t^(3/2)`` for the sphere)."""
    return panel_nodes(0.0, half, omega_max, start=True, per_panel=per_panel)


def panel_nodes(
    a: float, b: float, omega_max: float, *, start: bool = False, end: bool = False,
    per_panel: int = 16,
) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """Gauss-Legendre nodes and weights on ``[a, b]``: uniform panels of at most a third of a
    period of ``omega_max`` (and at most ``(b - a)/64``); the first panel split geometrically
    towards ``a`` when ``start``, the last towards ``b`` when ``end`` (where a pulse is not
    smooth)."""
    span = b - a
    width = min(2.0 * math.pi / (3.0 * max(omega_max, 1e-12)), span / 64.0)
    n_panels = int(math.ceil(span / width))
    edges = np.linspace(a, b, n_panels + 1)
    if start:
        first = a + (edges[1] - a) * np.geomspace(1e-12, 1.0, 24)
        edges = np.concatenate([[a], first, edges[2:]])
    if end:
        last = b - (b - edges[-2]) * np.geomspace(1e-12, 1.0, 24)
        edges = np.concatenate([edges[:-2], last[::-1], [b]])
    x, w = np.polynomial.legendre.leggauss(per_panel)
    a, b = edges[:-1, None], edges[1:, None]
    t = 0.5 * (b - a) * x[None, :] + 0.5 * (a + b)
    wt = 0.5 * (b - a) * w[None, :]
    return t.ravel(), wt.ravel()


def pulse_drive(pulse: ForcePulse, omega: np.ndarray) -> np.ndarray:
    """``I_k = int_0^{tau/2} P(t) cos(omega_k (tau/2 - t)) dt`` of a symmetric pulse.

    Gauss-Legendre panels on ``[0, tau/2]`` (:func:`_nodes`); exact up to the quadrature.

    Parameters
    ----------
    pulse : ForcePulse
    omega : numpy.ndarray, shape (N,)
        Frequencies, ``c / R``.

    Returns
    -------
    numpy.ndarray, shape (N,)
        Force times time (``E R^2 / c`` for the disk, ``E R^3 / c`` for the sphere).
    """
    half = 0.5 * pulse.contact_time
    t, w = _nodes(half, float(np.max(omega, initial=1.0)))
    wP = w * pulse.force(t)
    lag = half - t
    omega = np.asarray(omega, dtype=float)
    # The nodes grow with the highest frequency, so the table cos(omega_k lag_j) would grow
    # like N^(3/2) (24 GB for 150000 disk modes): it is built in blocks of modes instead.
    rows = max(1, _BLOCK // max(lag.size, 1))
    out = np.empty(omega.shape)
    for i in range(0, omega.size, rows):
        out[i : i + rows] = np.cos(np.outer(omega[i : i + rows], lag)) @ wP
    return out


def pulse_spectrum(forces, nodes, omega) -> np.ndarray:
    """``F(omega_k) = int P(t) e^{-i omega_k t} dt`` of pulses sampled on one quadrature.

    Parameters
    ----------
    forces : numpy.ndarray, shape (J,) or (J, M)
        The pulse (or ``M`` pulses) at the quadrature's nodes.
    nodes : tuple of numpy.ndarray
        ``(t, w)``, shape (J,) each, e.g. :func:`panel_nodes` on each smooth piece of the
        pulse, joined.
    omega : numpy.ndarray, shape (N,)

    Returns
    -------
    numpy.ndarray of complex, shape (N,) or (N, M)

    The drive of a pulse that is not symmetric (an elastic-plastic one); for a symmetric pulse
    ``|F| = 2 |I|`` of :func:`pulse_drive`. Built in blocks of modes as :func:`pulse_drive`.
    """
    t, w = nodes
    wP = w.reshape((-1,) + (1,) * (np.ndim(forces) - 1)) * np.asarray(forces, dtype=float)
    omega = np.asarray(omega, dtype=float)
    rows = max(1, _BLOCK // max(t.size, 1))
    out = np.empty(omega.shape + wP.shape[1:], dtype=complex)
    for i in range(0, omega.size, rows):
        phase = np.outer(omega[i : i + rows], t)
        out[i : i + rows] = np.cos(phase) @ wP - 1j * (np.sin(phase) @ wP)
    return out
