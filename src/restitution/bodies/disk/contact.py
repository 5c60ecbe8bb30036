"""The disk's quasistatic contact scales against a rigid wall (paper eq. 61), the one home of it.

Units: ``E = rho = R = 1`` (two-dimensional constants); ``v`` in ``c`` (speed towards the wall).

The two-dimensional Hertz force grows almost linearly with the compression (eq. 58), so the
energy balance ``pi v^2 / 2 ~ P delta`` gives, to leading logarithmic order (eq. 61)::

    delta_max ~ v sqrt(ln(4/v)),    tau ~ pi sqrt(ln(4/v)),    P_max ~ pi v / sqrt(ln(4/v)).

These are estimates (the full quasistatic theory is :mod:`restitution.quasistatic.hertz`); the
dynamics uses them to size steps and time bounds, the sweeps to scale the wall to the
compression, the FEM route to grade its meshes. Scalars are computed with :mod:`math`, arrays
with NumPy, as each caller did before this module existed (the two may differ in the last bit).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "contact_time_estimate",
    "max_compression_estimate",
    "pair_max_compression",
    "peak_force_estimate",
]


def _log_factor(v):
    """``sqrt(ln(4/v))``: :mod:`math` for a Python float, NumPy otherwise."""
    if isinstance(v, float):
        return math.sqrt(math.log(4.0 / v))
    return np.sqrt(np.log(4.0 / v))


def max_compression_estimate(v):
    """Quasistatic largest compression ``v sqrt(ln(4/v))`` (eq. 61), ``R``.

    Examples
    --------
    >>> round(max_compression_estimate(0.1), 6)
    0.192065
    """
    return v * _log_factor(v)


def contact_time_estimate(v):
    """Quasistatic contact time ``pi sqrt(ln(4/v))`` (eq. 61 with the prefactor pi), ``R / c``."""
    return math.pi * _log_factor(v)


def peak_force_estimate(v):
    """Quasistatic largest force ``pi v / sqrt(ln(4/v))`` (``2 E0 / delta_max``), ``E R``."""
    return math.pi * v / _log_factor(v)


def pair_max_compression(w, radius_ratio: float, modulus_ratio: float, density_ratio: float):
    """Two disks' quasistatic largest approach of the centres at relative speed ``w`` (``c1``),
    ``R1``: eq. (61) written for the pair, ``delta = s w sqrt(ln(4 R_K / (s w)))`` with
    ``s = sqrt(mu / (pi E_eff))``, ``1/E_eff = 1 + 1/E2`` and
    ``ln R_K = sum_i (E_eff/E_i) ln(R_i^2 / R_eff)`` (the pair's 2D Hertz law,
    :mod:`restitution.quasistatic.hertz_pair`); the second disk's constants in the first's units.

    Two identical disks give ``w sqrt(ln(8/w)) = 2 delta_wall(w/2)``, the disk on a wall at half
    the speed; a rigid, infinitely heavy and large partner gives the wall's ``w sqrt(ln(4/w))``.
    """
    r2, e2 = radius_ratio, modulus_ratio
    m1, m2 = math.pi, math.pi * density_ratio * r2 * r2
    mu = m1 * m2 / (m1 + m2)
    e_eff = 1.0 / (1.0 + 1.0 / e2)
    r_eff = r2 / (1.0 + r2)
    ln_rk = e_eff * math.log(1.0 / r_eff) + (e_eff / e2) * math.log(r2 * r2 / r_eff)
    s = math.sqrt(mu / (math.pi * e_eff))
    x = s * np.asarray(w, dtype=float)
    out = x * np.sqrt(np.log(4.0 * math.exp(ln_rk) / x))
    return float(out) if out.ndim == 0 else out
