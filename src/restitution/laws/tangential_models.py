"""The tangential coefficient ``beta`` of the DEM codes' tangential contact models and of
Walton's three-parameter law, as functions of the impact angle: what the fits to the package's
``beta`` (:mod:`restitution.laws.oblique_fits`) compare with.

Units: dimensionless. ``X = tan(theta) / mu`` (``theta`` the contact point's angle of incidence
from the normal, ``mu`` the friction coefficient), ``K = 1 + m R^2 / I`` (3 for a disk or
cylinder, 7/2 a solid sphere), ``beta = -v_c(after) / v_c(before)``.

**Walton** (Walton, in *Particulate Two-Phase Flow*, 1993; Foerster, Louge, Chang and Allia,
Phys. Fluids 6, 1108 (1994)): the normal coefficient ``e``, a friction coefficient ``mu_W`` and
the rolling-contact coefficient ``beta_0``,

    beta = min(beta_0, -1 + K (mu_W / mu) (1 + e) / X)

(sticking contacts at small angles, gross sliding at large ones; in the rigid-body parameter
``psi' = tan(theta) / (K mu (1 + e))`` of the docs, ``-1 + 1 / psi'``).

**LAMMPS's history models** (``pair_style granular``, ``tangential linear_history k_t
x_gamma,t mu_s`` and ``tangential mindlin k_t|NULL x_gamma,t mu_s``; the LAMMPS manual, "pair_style
granular"): the tangential force is ``-k_t xi`` (``linear_history``) or ``-k_t a xi``
(``mindlin``, ``a`` the contact radius) on the accumulated tangential displacement ``xi``, cut
at ``mu F_n`` with ``xi`` rescaled to the cut (LAMMPS's eq. of the critical force; no damping
here: ``x_gamma,t = 0``), on Hertz's normal force. A rigid grain on a rigid wall then follows,
in the time unit ``delta_max / v_n``, with ``x = delta / delta_max`` and the variables
``c = v_c / (mu v_n)``, ``s = xi / (mu delta_max)``,

    x'' = -(5/4) x^(3/2),    s' = c,    c' = -(15/8) K chi g(x) s,
    |s| <= (2/3) x^(3/2) / (chi g(x)),

``g = 1`` and ``chi = k_t / k_n(delta_max)`` for ``linear_history`` (``k_n = dF_n/d delta``),
``g = x^(1/2)`` and ``chi = k_t a / k_n`` (speed-free) for ``mindlin``; ``c(0) = X``,
``beta = -c(end) / X``. :func:`history_beta` integrates this as the codes do (velocity Verlet on
``x``, ``xi`` accumulated and rescaled each step), first order in the step; its ``mindlin`` is
the no-microslip law of :mod:`restitution.quasistatic.oblique` (the tests compare them).
"""

from __future__ import annotations

import math

import numpy as np

from restitution.errors import InputError

__all__ = ["HISTORY_MODELS", "history_beta", "walton_beta"]

HISTORY_MODELS = ("linear_history", "mindlin")
"""The LAMMPS tangential models :func:`history_beta` computes."""

# x'' = -(5/4) x^(3/2) from x = 0, x' = 1 returns to x = 0 at t = 2 (2/5) B(2/5, 1/2) = 2.9432
# (Hertz's contact time in delta_max / v_n, docs/oblique.md).
_CONTACT_TIME = 0.8 * math.gamma(0.4) * math.sqrt(math.pi) / math.gamma(0.9)


def walton_beta(X, e: float, mu_ratio: float, beta_0: float, inertia_factor: float = 3.0):
    """Walton's ``beta = min(beta_0, -1 + K mu_ratio (1 + e) / X)``, ``mu_ratio = mu_W / mu``.

    >>> round(float(walton_beta(10.0, 1.0, 1.0, 0.4)), 6)
    -0.4
    """
    X = np.asarray(X, dtype=float)
    return np.minimum(beta_0, -1.0 + inertia_factor * mu_ratio * (1.0 + e) / X)


def history_beta(X, chi, model: str = "mindlin", *, inertia_factor: float = 3.0,
                 steps: int = 20000) -> np.ndarray:  # fmt: skip
    """``beta(X)`` of LAMMPS's ``linear_history`` or ``mindlin`` model (module docs), shape of
    ``X`` (at least 1-D); ``steps`` steps over the contact (error about ``1 / steps``). ``chi``
    may be a 1-D array of stiffnesses: then one row per ``chi`` (every row as its own call
    gives it: the normal motion is the same for all).

    >>> b = history_beta([0.5, 20.0], 0.85, "mindlin")
    >>> round(float(b[1]), 3)
    -0.7
    """
    if model not in HISTORY_MODELS:
        raise InputError(f"model must be one of {HISTORY_MODELS}, got {model!r}")
    chis = np.asarray(chi, dtype=float)
    if chis.ndim > 1 or not (np.all(np.isfinite(chis)) and np.all(chis > 0.0)):
        raise InputError(f"chi (k_t over the normal stiffness) must be > 0, got {chi}")
    X = np.atleast_1d(np.asarray(X, dtype=float))
    k = chis.reshape(-1, 1)  # one row per stiffness
    K = float(inertia_factor)
    dt = _CONTACT_TIME / steps
    x, u = 0.0, 1.0
    c = np.broadcast_to(X, (k.shape[0], X.size)).copy()
    s = np.zeros_like(c)
    linear = model == "linear_history"
    while True:
        # velocity Verlet for the normal motion; the tangential state as the codes update it
        u_half = u - 0.5 * dt * 1.25 * max(x, 0.0) ** 1.5
        x_new = x + dt * u_half
        if x_new <= 0.0:
            break
        g = 1.0 if linear else math.sqrt(x_new)
        s = s + dt * c
        cap = (2.0 / 3.0) * x_new**1.5 / (k * g)
        s = np.clip(s, -cap, cap)
        c = c - dt * 1.875 * K * k * g * s
        x = x_new
        u = u_half - 0.5 * dt * 1.25 * x**1.5
    beta = -c / X
    return beta if chis.ndim else beta[0]
