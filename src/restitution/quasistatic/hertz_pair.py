"""Two-dimensional Hertz contact of two disks, and their quasistatic collision.

Units: the first disk's, ``E1 = rho1 = R1 = 1`` (2D plane-stress constants); the second disk
has ``E2 = modulus_ratio``, ``R2 = radius_ratio``, ``rho2 = density_ratio``. Forces ``P`` per
unit thickness in ``E1 R1``, compressions in ``R1``, speeds (the relative speed ``w`` of the
centres) in ``c1``, times in ``R1 / c1``.

Two disks pressed together by ``P`` share one contact of half-width ``b``,
``b^2 = 4 P R_eff / (pi E_eff)`` with ``1/R_eff = 1/R1 + 1/R2`` and ``1/E_eff = 1/E1 + 1/E2``
(Hertz). Each disk, loaded on its edge by that pressure, approaches by eq. (57) with its own
modulus, radius and constant, written with the common width (``ln(4 pi E R / P) = 2 ln(4 R /
b)`` for a disk on a wall)::

    delta_i(P) = P / (pi E_i) (2 ln(4 R_i / b) + c_i)

and the centres approach by ``delta = delta_1 + delta_2``. With the weights ``w_i = E_eff /
E_i`` (``w_1 + w_2 = 1``) this is again the form of eq. (57)::

    delta(P) = P / (pi E_eff) (ln(4 pi E_eff R_K / P) + c),
    ln R_K = sum_i w_i ln(R_i^2 / R_eff),     c = sum_i w_i c_i,

so :class:`restitution.quasistatic.hertz.HertzLaw` with ``E = E_eff``, ``R = R_K`` and
``constant = c`` is the pair's law, and its quasistatic collision is that of a body of the
reduced mass ``mu``. For two identical disks ``E_eff = E/2``, ``R_K = 2R``, ``c = c_1``:
``delta = 2 delta_wall(P)``, the disk on a wall at half the relative speed.
"""

from __future__ import annotations

import math

import numpy as np

from restitution.errors import InputError
from restitution.quasistatic.hertz import (
    HertzLaw,
    QuasistaticCollision,
    contact_law,
    quasistatic_collision,
)

__all__ = ["pair_contact_law", "pair_mass", "pair_quasistatic_collision"]


def _positive(name: str, value: float) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{name} must be a positive number, got {value!r}")
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be a positive number, got {value!r}")
    return float(value)


def pair_contact_law(
    nu1: float,
    nu2: float | None = None,
    *,
    radius_ratio: float = 1.0,
    modulus_ratio: float = 1.0,
    law: str = "centre",
) -> HertzLaw:
    """The 2D Hertz law of two disks (module docs), in the first disk's units.

    Parameters
    ----------
    nu1, nu2 : float
        Two-dimensional Poisson numbers (``nu2`` defaults to ``nu1``).
    radius_ratio, modulus_ratio : float
        ``R2 / R1`` and ``E2 / E1``.
    law : {"centre", "paper", "diameter"}
        Which constant each disk's eq. (57) takes (:func:`restitution.quasistatic.hertz.
        contact_law`); ``"centre"``, the approach of the centres of mass, is what the
        quasistatic collision needs.
    """
    r2 = _positive("radius_ratio", radius_ratio)
    e2 = _positive("modulus_ratio", modulus_ratio)
    first = contact_law(nu1, law)
    second = contact_law(nu1 if nu2 is None else nu2, law)
    e_eff = 1.0 / (1.0 + 1.0 / e2)
    r_eff = r2 / (1.0 + r2)
    w1, w2 = e_eff, e_eff / e2
    ln_rk = w1 * math.log(1.0 / r_eff) + w2 * math.log(r2 * r2 / r_eff)
    return HertzLaw(
        nu=first.nu,
        constant=w1 * first.constant + w2 * second.constant,
        name=f"{law} (two disks, R2/R1 = {r2:g}, E2/E1 = {e2:g})",
        E=e_eff,
        R=math.exp(ln_rk),
    )


def pair_mass(radius_ratio: float = 1.0, density_ratio: float = 1.0) -> float:
    """The reduced mass ``m1 m2 / (m1 + m2)`` of two disks, ``rho1 R1^2`` (``m_i = pi rho_i
    R_i^2``)."""
    m2 = (
        math.pi
        * _positive("density_ratio", density_ratio)
        * _positive("radius_ratio", radius_ratio) ** 2
    )
    return math.pi * m2 / (math.pi + m2)


def pair_quasistatic_collision(
    w,
    nu1: float,
    nu2: float | None = None,
    *,
    radius_ratio: float = 1.0,
    modulus_ratio: float = 1.0,
    density_ratio: float = 1.0,
    law: str = "centre",
) -> QuasistaticCollision:
    """Largest compression of the centres' separation and contact time of two disks meeting at
    relative speed ``w`` (``c1``), from ``mu delta'' = -P(delta)`` with the pair's law."""
    hertz = pair_contact_law(
        nu1, nu2, radius_ratio=radius_ratio, modulus_ratio=modulus_ratio, law=law
    )
    return quasistatic_collision(
        hertz, np.asarray(w, dtype=float), mass=pair_mass(radius_ratio, density_ratio)
    )
