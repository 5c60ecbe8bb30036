"""Toroidal (torsional) eigenmodes of the free elastic sphere (Lamb 1882, his "first class").

Units: ``E = rho = R = 1`` of the three-dimensional material, ``omega`` in ``c / R``, shear
modulus ``mu = 1 / (2 (1 + nu))``, shear speed ``c_T = sqrt(mu)``.

A toroidal field has no radial component and no divergence::

    u = W(r) r_hat x grad_1 Y_l,     u_theta = W (1 / sin theta) dY/dphi,
                                     u_phi = -W dY/dtheta,

``Y_l`` a surface harmonic of order ``l`` and ``grad_1`` the gradient on the unit sphere. With
``div u = 0`` Navier's equation is ``mu lap u = -omega^2 u``, whose regular solution is
``W(r) = j_l(k r)``, ``k = omega / c_T``. The only traction on the surface ``r = 1`` is the
shear ``sigma_r(theta, phi) = mu r d/dr (W / r)`` times the angular pattern (``u_r = 0``, and
``sigma_rr = 2 mu du_r/dr = 0``), so the free surface asks ``k j_l'(k) - j_l(k) = 0``; with
``j_l'(x) = (l / x) j_l(x) - j_(l+1)(x)`` this is Lamb's

    (l - 1) j_l(k) = k j_(l+1)(k).

(Not ``(l - 1) j_l = k j_l'``: that drops the ``-W / r`` of the shear strain.) ``l = 1`` reads
``k j_2(k) = 0``: the root ``k = 0`` is the rigid rotation ``u = Omega x r`` (``W = r``), a
degree of freedom of its own, not a mode; the others are the roots of ``j_2``. There is no
``l = 0`` field. The frequency does not depend on the azimuthal order ``m`` (``2 l + 1``
degenerate modes per root).

Normalisation: ``int rho |u|^2 dV = m = 4 pi / 3``, as the spheroidal modes
(:mod:`restitution.bodies.sphere.modes`), with the angular functions normalised to
``int |Y|^2 dOmega = 4 pi / (2 l + 1)`` (that of ``P_l`` with ``m = 0``,
:mod:`restitution.bodies.sphere.harmonics`), so that ``int |grad_1 Y|^2 dOmega = l (l + 1) 4 pi /
(2 l + 1)`` and

    W = A j_l(k r),    A^2 int_0^1 r^2 j_l(k r)^2 dr = (2 l + 1) / (3 l (l + 1)).

The radial integral has a closed form (the spherical Lommel integral): for ``j_l(k) != 0`` it
is ``(1/2) [j_l(k)^2 - j_(l-1)(k) j_(l+1)(k)]``. The surface amplitude is ``T = W(1) = A
j_l(k)``, signed ``T > 0``.

Root finding: ``f = [(l - 1) j_l(k) - k j_(l+1)(k)] / hypot(...)`` (values in [-1, 1]) on a
grid in ``omega`` from ``0.8 l c_T`` (the lowest root of order ``l`` is above ``l c_T``: the
shear whispering-gallery wave), brackets from sign changes, polished
(:func:`restitution.bodies.roots.bracket_and_polish`).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import spherical_jn

from restitution.bodies.roots import bracket_and_polish
from restitution.errors import InputError, RestitutionError

__all__ = ["normalized_frequency_function", "toroidal_amplitude", "toroidal_modes"]

_SCAN_STEP = 0.02
"""Grid step of the scan in ``k = omega / c_T``; the roots of one order are about ``pi`` apart."""

_TINY = 1e-280


def _shear_speed(nu: float) -> float:
    return math.sqrt(0.5 / (1.0 + nu))


def normalized_frequency_function(l, omega, nu: float) -> np.ndarray:
    """``[(l - 1) j_l(k) - k j_(l+1)(k)] / hypot((l - 1) j_l(k), k j_(l+1)(k))``,
    ``k = omega / c_T`` (module docs); ``nan`` where both terms underflow."""
    l, omega = np.broadcast_arrays(np.asarray(l), np.asarray(omega, dtype=float))
    k = omega / _shear_speed(nu)
    a = (l - 1.0) * spherical_jn(l, k)
    b = k * spherical_jn(l + 1, k)
    norm = np.hypot(a, b)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(norm < _TINY, np.nan, (a - b) / norm)


def toroidal_amplitude(l, omega, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """``(A, T)``: the factor of ``W = A j_l(k r)`` for the normalisation of the module docs
    and the surface amplitude ``T = W(1) > 0``, for roots ``(l, omega)`` (shape (N,))."""
    l = np.asarray(l)
    k = np.asarray(omega, dtype=float) / _shear_speed(nu)
    jl = spherical_jn(l, k)
    radial = 0.5 * (jl**2 - spherical_jn(l - 1, k) * spherical_jn(l + 1, k))
    A = np.sqrt((2.0 * l + 1.0) / (3.0 * l * (l + 1.0)) / radial) * np.sign(jl)
    return A, A * jl


def toroidal_modes(nu: float, omega_max: float, orders=None) -> tuple[np.ndarray, ...]:
    """Every toroidal root with ``0 < omega < omega_max`` (``c / R``), sorted by frequency.

    Parameters
    ----------
    nu : float
        Poisson number in (-1, 0.5).
    omega_max : float
        Upper frequency, ``c / R``.
    orders : array of int, optional
        Only these orders (``>= 1``); default every order with a root below ``omega_max``.

    Returns
    -------
    l, n, omega, T : numpy.ndarray, shape (K,)
        Order, root index within the order (from 0, the rigid rotation not counted),
        frequency and surface amplitude ``W(1)``.

    >>> l, n, w, T = toroidal_modes(0.25, 2.0)
    >>> [(int(a), round(float(b) / math.sqrt(0.4), 5)) for a, b in zip(l, w)]
    [(2, 2.50113)]
    """
    if not -1.0 < nu < 0.5:
        raise InputError(f"the Poisson number nu must be in (-1, 0.5), got {nu!r}")
    c_T = _shear_speed(nu)
    k_max = float(omega_max) / c_T
    if orders is None:
        orders = np.arange(1, int(k_max / 0.8) + 2)
    orders = np.asarray(orders, dtype=int)
    if np.any(orders < 1):
        raise InputError("toroidal orders start at l = 1 (there is no l = 0 field)")
    floor = np.maximum(0.3, 0.8 * orders) * c_T  # l = 1 roots start at j_2's 5.76
    orders, floor = orders[floor < omega_max], floor[floor < omega_max]
    if orders.size == 0:
        return (np.zeros(0, int), np.zeros(0, int), np.zeros(0), np.zeros(0))
    n_pts = int(np.ceil((omega_max - floor.min()) / (_SCAN_STEP * c_T))) + 2
    w = floor.min() + np.arange(n_pts) * _SCAN_STEP * c_T
    grid = np.broadcast_to(w[None, :], (orders.size, n_pts))
    ll = np.broadcast_to(orders[:, None], grid.shape)
    inside = grid >= floor[:, None]
    f = np.where(inside, normalized_frequency_function(ll, grid, nu), np.nan)
    if np.any(inside & ~np.isfinite(f)):
        raise InputError(
            f"a toroidal order is beyond spherical_jn's range at nu = {nu}; lower omega_max"
        )
    rl, roots = bracket_and_polish(
        lambda lo, x: normalized_frequency_function(lo, x, nu),
        orders,
        grid,
        f,
        inside,
        lambda: RestitutionError("toroidal root polishing failed; this is a bug"),
    )
    keep = (roots < omega_max) & (roots > 0.0)
    rl, roots = rl[keep].astype(int), roots[keep]
    by_order = np.lexsort((roots, rl))
    rl, roots = rl[by_order], roots[by_order]
    first = np.r_[True, rl[1:] != rl[:-1]] if rl.size else np.zeros(0, bool)
    start = np.maximum.accumulate(np.where(first, np.arange(rl.size), 0)) if rl.size else rl
    n = np.arange(rl.size) - start
    _, T = toroidal_amplitude(rl, roots, nu)
    order = np.argsort(roots, kind="stable")
    return rl[order], n[order], roots[order], T[order]
