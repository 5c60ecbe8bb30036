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

__all__ = ["contact_time_estimate", "max_compression_estimate", "peak_force_estimate"]


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
