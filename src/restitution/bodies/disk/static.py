"""The disk's static flexibility at its edge, and the part its truncated modes leave out.

Units: two-dimensional (plane-stress) ``E = rho = R = 1``, ``m = pi``; displacements per unit
force per unit angle of the edge (a traction on the unit circle).

**Per order, in closed form.** A traction ``sigma_rr = A cos(n phi)``,
``sigma_rphi = B sin(n phi)`` on the free edge of the disk deforms it, for ``n >= 2``, into
``u_r = U cos(n phi)``, ``u_phi = W sin(n phi)`` with ``[U, W] = K_n [A, B]``::

    K_n = 1 / (n^2 - 1) [[2n - 1 + nu,  n - 2 - n nu],
                         [n - 2 - n nu, 2n - 1 + nu ]]           (n >= 2)

(derived from Navier's equations with the ansatz ``u_r = (p r^(n-1) + q r^(n+1)) cos(n phi)``,
``u_phi = (s r^(n-1) + t r^(n+1)) sin(n phi)``, which holds the whole regular solution; the
large-``n`` limit is the half-plane's ``2 / (E k)`` normal and ``(1 - nu) / (E k)`` coupling
compliance of plane stress). For ``n = 0`` (a uniform pressure) ``U = (1 - nu) A``. For
``n = 1`` the load has a net force ``pi (A - B)``: the free modes answer it as the static
response to the load and the uniform inertial body force that balances it ("inertia relief"),
with the rigid translation taken out (``int u_x dA = 0``)::

    K_1 = 1/2 [[1 - nu, 1 - nu], [1 - nu, 3 + nu]]

The modal sums obey ``K_n = pi sum_l [C, S] [C, S]^T / (m omega^2)`` over the modes of order
``n`` (``2 pi`` for ``n = 0``): the tests check both against each other at 1e5 modes, to
1e-5 after the sums' ``1 / omega`` tail is extrapolated.

**The residual on the edge nodes** (:func:`residual_flexibility`). Along the impact axis the
edge of order ``n`` moves by ``b_n(phi) = [cos(n phi) cos(phi), -sin(n phi) sin(phi)]`` per
unit ``(C, S)``, so a force ``f`` per unit angle at ``phi'`` (and its mirror at ``-phi'``)
displaces the edge at ``phi`` by ``-G(phi, phi') f`` with
``G = sum_n b_n(phi)^T M_n b_n(phi')``, ``M_n = K_n / pi`` (``K_0 / (2 pi)``). Written in
cosines, ``b_n = [cos((n+1) phi) (1, 1) + cos((n-1) phi) (1, -1)] / 2``. ``G`` has the
logarithmic singularity of a line load at ``phi = phi'``; on the quadrature's uniform nodes
(spacing ``h``) it is taken between hat functions (Galerkin): every ``cos(m phi)`` on either
side is multiplied by the hat's transform ``sinc^2(m h / 2)``, which makes the series converge
like ``m^-5`` beyond ``m ~ 1 / h``; it is summed to :data:`ORDERS_PER_SPACING` ``/ h``. The
residual is this full kernel less the kept modes' own ``sum_k g_k g_k^T / (m omega_k^2)``
taken between the same hats: the compliance the truncation drops.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from restitution.bodies.blocks import LeadingBlocks
from restitution.errors import InputError

if TYPE_CHECKING:
    from restitution.bodies.disk.modes import ModeSet

__all__ = ["ORDERS_PER_SPACING", "hat_transform", "residual_flexibility", "static_compliance"]

ORDERS_PER_SPACING = 64.0
"""The hat-averaged kernel is summed over orders ``m <= ORDERS_PER_SPACING / h``; the terms
beyond fall like ``(m h)^-4 / m`` (doubling it changes the kernel by less than 1e-7 of its
diagonal, a test)."""


_CHUNK = 2048
"""Orders per block of the one-dimensional sums (bounds their memory)."""


def static_compliance(orders, nu: float) -> np.ndarray:
    """``K_n`` of the module docstring for every order, shape (len(orders), 2, 2).

    Rows and columns: (radial, tangential); ``E = R = 1`` (plane stress).
    """
    n = np.asarray(orders, dtype=float)
    if n.ndim != 1 or np.any(n < 0) or np.any(n != np.round(n)):
        raise InputError("orders must be a one-dimensional array of integers >= 0")
    out = np.zeros((n.size, 2, 2))
    high = n >= 2
    d = n[high] ** 2 - 1.0
    diag = (2.0 * n[high] - 1.0 + nu) / d
    cross = (n[high] - 2.0 - n[high] * nu) / d
    out[high, 0, 0] = out[high, 1, 1] = diag
    out[high, 0, 1] = out[high, 1, 0] = cross
    out[n == 0, 0, 0] = 1.0 - nu
    one = n == 1
    out[one, 0, 0] = out[one, 0, 1] = out[one, 1, 0] = 0.5 * (1.0 - nu)
    out[one, 1, 1] = 0.5 * (3.0 + nu)
    return out


def hat_transform(m, h: float) -> np.ndarray:
    """``sinc^2(m h / 2)``: ``cos(m phi)`` averaged over a hat of half-width ``h`` at ``phi``,
    divided by ``cos(m phi)`` (exact for every ``phi``)."""
    return np.sinc(np.asarray(m, dtype=float) * h / (2.0 * math.pi)) ** 2


def _full_kernel(nu: float, count: int, h: float, n_top: int) -> np.ndarray:
    """The hat-averaged ``G`` of all orders ``0..n_top`` on the nodes ``phi_i = i h``,
    ``i < count``, by one-dimensional sums over ``i - j`` and ``i + j``."""
    n = np.arange(n_top + 1)
    M = static_compliance(n, nu) / math.pi
    M[0] *= 0.5
    e = {1: np.array([1.0, 1.0]), -1: np.array([1.0, -1.0])}
    i = np.arange(count)
    G = np.zeros((count, count))
    lags = np.arange(-(count - 1), 2 * count - 1)  # every i - j and i + j
    for s in (1, -1):
        for t in (1, -1):
            gamma = 0.25 * np.einsum("a,nab,b->n", e[s], M, e[t])
            gamma = gamma * hat_transform(n + s, h) * hat_transform(n + t, h)
            C = np.zeros(lags.size)
            S = np.zeros(lags.size)
            for start in range(0, n.size, _CHUNK):
                arg = np.outer(lags * h, n[start : start + _CHUNK])
                C += np.cos(arg) @ gamma[start : start + _CHUNK]
                S += np.sin(arg) @ gamma[start : start + _CHUNK]
            # cos((n+s) phi_i) cos((n+t) phi_j)
            #     = [cos(n (i-j) h + beta-) + cos(n (i+j) h + beta+)] / 2
            d = (i[:, None] - i[None, :]) - lags[0]
            p = (i[:, None] + i[None, :]) - lags[0]
            bm = (s * i[:, None] - t * i[None, :]) * h
            bp = (s * i[:, None] + t * i[None, :]) * h
            G += 0.5 * (
                C[d] * np.cos(bm) - S[d] * np.sin(bm) + C[p] * np.cos(bp) - S[p] * np.sin(bp)
            )
    return G


_KERNELS = LeadingBlocks(
    lambda key, count: _full_kernel(key[0], count, key[1], key[2]),
    lambda G, count: G[:count, :count],
    lambda G: G.shape[0],
)
"""The full kernel per ``(nu, h, n_top)``, built once at the largest node count asked
(:class:`~restitution.bodies.blocks.LeadingBlocks`: every entry depends on its two nodes
alone)."""


def residual_flexibility(modes: ModeSet, count: int, h: float) -> np.ndarray:
    """The static flexibility the modes of ``modes`` leave out, on the edge nodes
    ``phi_i = i h`` (``i < count``), hat-averaged; shape (count, count), symmetric.

    ``-residual_flexibility(...) @ (weight * p)`` is the edge's displacement along the impact
    axis that the modes above the set add under the node forces ``weight * p`` when they follow
    the load statically (module docstring).
    """
    if count < 1 or not h > 0.0:
        raise InputError(f"need at least one node and a positive spacing, got {count}, {h}")
    n_top = int(math.ceil(ORDERS_PER_SPACING / h))
    if int(modes.n.max(initial=0)) + 1 > n_top:
        raise InputError(
            f"the node spacing {h:.3g} does not resolve the kept modes' highest order "
            f"{int(modes.n.max())}: use more than "
            f"{int(modes.n.max()) * h / ORDERS_PER_SPACING:.1f} times as many nodes"
        )
    G = _KERNELS((float(modes.nu), float(h), n_top), int(count))
    phi = np.arange(count) * h
    n = modes.n
    cp = np.cos(np.outer(phi, n + 1)) * hat_transform(n + 1, h)
    cm = np.cos(np.outer(phi, n - 1)) * hat_transform(n - 1, h)
    kept = 0.5 * (modes.C * (cp + cm) + modes.S * (cp - cm))
    kept /= np.sqrt(modes.mass) * modes.omega
    return G - kept @ kept.T
