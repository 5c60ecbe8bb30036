"""A mechanism's table at every speed of the elastic law: what a closed form of the mechanism
leaves, interpolated between the computed speeds.

Units: the elastic law's reduced units (``v`` in ``c``); the shape takes speeds in m/s.

Plastic flow turns epsilon down sharply at the yield speed ``v_y`` (Thornton's contact:
``epsilon_T = 1`` below, falling steeply above it) and curves it over the decade above. A
table of epsilon at four of the elastic law's speeds a decade (:mod:`restitution.laws.tabulated`)
missed the pulse computed at the speed by 0.11-0.25 of its stated error at 0.01-1 m/s (steel,
yield stress 1 GPa), the interpolation miss being most of that error. Interpolating instead the
factor the waves multiply (the ratio of Rayleigh's estimates, with the elastic law's loss exact
at every speed) missed more: that ratio carries the modes' structure too.

With a closed form ``s(w)`` of the mechanism's contact (Thornton's ``epsilon_T(w / v_y)``), the
rest

    y(w) = s(w)^2 - epsilon(w)^2

(the waves on the actual pulse, the viscous loss and what the integrated pulse adds to the
closed form) is smooth through the yield speed. :func:`shaped_records` interpolates ``y`` (PCHIP
in ``ln v``) from the computed speeds to **every** speed of the elastic law between them and
writes ``epsilon = sqrt(s^2 - y)`` there (from a computed speed below the onset, ``s = 1``,
``y`` is the elastic law's own loss at the speed times the interpolated ratio of the waves, 1
below the onset, plus the interpolated rest: the elastic loss's structure exact there): the kink
comes from the closed form at each of those speeds (2 % apart for the sphere's laws), the rest
from the computed pulses. At a computed speed the record is the computed point. A record's
mechanism error is the larger of the two computed speeds' around it, and not less than the
elastic law's own error at its speed carried by the waves (``R sigma_el epsilon_el / epsilon``,
``R`` the larger ratio of the waves' loss to the elastic loss at the two computed speeds). Its
loss parts are interpolated as ``y`` is, the waves' loss being what the others leave of ``1 -
epsilon^2`` where the computed points add up so. What this misses is measured by the caller at
the middle of every interval of
computed speeds (:func:`restitution.laws.tabulated.mechanism_table`).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution.laws.law_point import QUASISTATIC_ROUTE

__all__ = ["shaped_records"]

_SUM_TOL = 1e-9
"""How closely the computed points' loss parts must add up to ``1 - epsilon^2`` for a record's
waves' loss to be taken as the rest."""


def shaped_records(
    law,
    idx: np.ndarray,
    at,
    shape: Callable[[np.ndarray], np.ndarray],
    scale: float,
    parts_of: Callable,
) -> tuple[list[dict], np.ndarray]:
    """Records at every speed of the elastic ``law`` from ``idx[0]`` to ``idx[-1]`` (module
    docs).

    Parameters
    ----------
    law : EpsilonLaw
        The elastic law (reduced units).
    idx : ndarray of int, shape (n,)
        Its indices of the computed speeds, increasing.
    at : sequence of SIPoint, length n
        The mechanism's points there (``epsilon``, ``epsilon_err``, ``epsilon_elastic``).
    shape : callable
        The closed form ``s(w)`` at speeds ``w`` in m/s (an array), ``s >= epsilon``.
    scale : float
        m/s per unit of ``v``.
    parts_of : callable
        A point's numeric loss parts as a dict.

    Returns
    -------
    records : list of dict
        One per elastic speed (``v``, ``epsilon``, ``mechanism_err``, ``asymptotic_ok``,
        ``computed``, the loss parts; ``route`` where the elastic point is quasistatic).
    interval : ndarray of int
        The interval of computed speeds each record lies in (``0 .. n - 2``).
    """
    lo, hi = int(idx[0]), int(idx[-1])
    v = np.asarray(law.v, dtype=float)[lo : hi + 1]
    k_at = idx - lo
    eps_k = np.array([p.epsilon for p in at], dtype=float)
    s_k = np.asarray(shape(v[k_at] * scale), dtype=float)
    x_k, xv = np.log(v[k_at]), np.log(v)
    interval = np.clip(np.searchsorted(k_at, np.arange(v.size), side="right") - 1, 0, idx.size - 2)
    s = np.asarray(shape(v * scale), dtype=float)
    el_k = np.array([p.epsilon_elastic for p in at], dtype=float)
    parts_k = [parts_of(p) for p in at]
    waves_k = np.array([q.get("loss_waves", 0.0) for q in parts_k], dtype=float)
    ratio_k = waves_k / np.maximum(1.0 - el_k**2, 1e-300)
    eps_el = np.asarray(law.epsilon(v, outside="nan"), dtype=float)
    err_el = np.asarray(law.epsilon_err(v, outside="nan"), dtype=float)
    # Above the closed form's onset the rest y is interpolated whole: the waves on the actual
    # pulse carry that pulse's own structure, smoother than the ratio to the elastic law's.
    y = PchipInterpolator(x_k, s_k**2 - eps_k**2)(xv)
    # From a computed speed where the closed form is still 1 (below the yield speed, the pulse
    # Hertz's) the waves' loss is the elastic law's own at each speed times the interpolated
    # ratio (1 below the onset), plus the interpolated rest: the elastic loss's structure (the
    # sphere's slow loss turns by a factor 3 within 2 % of speed) is then exact there.
    if "loss_waves" in set.intersection(*(set(q) for q in parts_k)):
        rest_k = s_k**2 - eps_k**2 - waves_k
        onset = (s_k[interval] >= 1.0) & np.isfinite(eps_el)
        factored = (1.0 - eps_el**2) * PchipInterpolator(x_k, ratio_k)(xv) + PchipInterpolator(
            x_k, rest_k
        )(xv)
        y = np.where(onset, factored, y)
    eps = np.sqrt(np.maximum(s**2 - y, 0.0))

    # Errors: the computed points' (the larger of the two around), and the elastic law's at the
    # speed carried by the waves.
    err_k = np.array([p.epsilon_err for p in at], dtype=float)
    ratio = np.maximum(ratio_k[interval], ratio_k[interval + 1])
    carried = ratio * err_el * eps_el / np.where(eps > 0.0, eps, np.inf)
    err = np.maximum(np.maximum(err_k[interval], err_k[interval + 1]), carried)

    names = sorted(set.intersection(*(set(q) for q in parts_k))) if parts_k else []
    values = {n: np.array([q[n] for q in parts_k], dtype=float) for n in names}
    interp = {n: PchipInterpolator(x_k, y_n)(xv) for n, y_n in values.items()}
    adds_up = "loss_waves" in names and np.allclose(
        sum(values.values()), 1.0 - eps_k**2, rtol=0.0, atol=_SUM_TOL
    )
    elastic = law._records() if hasattr(law, "_records") else [{} for _ in law.v]
    computed = {int(k): j for j, k in enumerate(k_at)}
    records, kept = [], []
    for i in range(v.size):
        if i in computed:
            p = at[computed[i]]
            value, e, parts = float(p.epsilon), float(p.epsilon_err), parts_k[computed[i]]
        else:
            value, e = float(eps[i]), float(err[i])
            parts = {n: float(y_n[i]) for n, y_n in interp.items()}
            if adds_up:
                others = sum(x for n, x in parts.items() if n != "loss_waves")
                parts["loss_waves"] = 1.0 - value**2 - others
        if not (math.isfinite(value) and value > 0.0 and math.isfinite(e)):
            continue  # no rebound left by the interpolated rest: no record
        record = {"v": float(v[i]), "epsilon": value, "mechanism_err": e,
                  "asymptotic_ok": bool(law.asymptotic_ok[lo + i]),
                  "computed": i in computed, **parts}  # fmt: skip
        if elastic[lo + i].get("route") == QUASISTATIC_ROUTE:
            record["route"] = QUASISTATIC_ROUTE
        records.append(record)
        kept.append(int(interval[i]))
    return records, np.array(kept, dtype=int)
