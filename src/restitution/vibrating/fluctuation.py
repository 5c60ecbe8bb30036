"""Detailed balance of the collision of a disk with thermal modes, and its statistical test.

**The relation.** The collision is a Hamiltonian scattering map from the incoming state
``(v, Gamma)`` (speed towards the wall, modal state ``Gamma = (Q, P)`` at the reference instant)
to the outgoing one ``(v', Gamma')``. On a section ``x0 = const`` outside the wall's reach the
flow preserves the flux measure ``|p| dp dGamma`` (Liouville's theorem on a Poincare section);
the reference instant is that section shifted by a free flight, a symplectic map of ``Gamma``
whose Jacobian in ``(p, Gamma)`` is 1. The map conserves ``H = (m/2) v^2 + H_vib(Gamma)``, so it
carries the measure ``v exp(-H / T) dv dGamma`` on incoming states to the same measure on
outgoing ones. Time reversal (``P -> -P``, ``p -> -p``) maps every outgoing state to an
incoming one and reverses the map (``tests/test_vibration.py`` checks this numerically). With
``K(v'|v)`` the distribution of ``v'`` when the modes are canonical at ``T`` and the speed is
``v``, the joint density of ``(v, v')`` under ``v exp(-(m/2) v^2 / T) dv`` is therefore
symmetric::

    v exp(-(m/2) v^2 / T) K(v'|v) = v' exp(-(m/2) v'^2 / T) K(v|v')

It holds for the modes canonical *and* the translation weighted by the flux (effusion)
density ``f(v) ~ v exp(-(m/2) v^2 / T)``, at any number of modes, wall hardness and ``T``.
Consequences: ``f`` is stationary (a disk that arrives with speeds from ``f`` leaves with
speeds from ``f``), and, with ``W = (m/2)(v'^2 - v^2)`` the energy the translation gains,
``P_v(W) = P_{v'}(-W) exp(-W / T)`` (a Crooks-like relation whose reverse process starts at
the outgoing speed ``v'``; ``docs/vibrating.md``).

**The test.** Draw ``v`` from ``f`` restricted to a window ``[a, b]`` and the modes from the
canonical state, collide, and keep the pairs with ``v'`` in the window too: on the square
``[a, b]^2`` their joint distribution is symmetric. Bowker's test of symmetry on a table of
speed bins: ``chi^2 = sum_{i<j} (n_ij - n_ji)^2 / (n_ij + n_ji)`` has, under the relation, a
chi-squared distribution with as many degrees of freedom as pairs of bins with counts.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import stats

from restitution.bodies.disk.modes import ModeSet
from restitution.dynamics.collision import CollisionSettings
from restitution.errors import InputError
from restitution.vibrating.ensemble import collide_states
from restitution.vibrating.vibration import STEP_JUDGE, thermal_state

__all__ = [
    "BalanceTest",
    "SymmetryTest",
    "detailed_balance_test",
    "flux_speeds",
    "symmetry_test",
]


def flux_speeds(
    modes: ModeSet,
    temperature: float,
    window: tuple[float, float],
    size: int,
    rng: np.random.Generator,
) -> np.ndarray:
    """Speeds from the flux density ``f(v) ~ v exp(-(m/2) v^2 / T)`` restricted to ``window``.

    Inverse transform of the cumulative ``1 - exp(-(m/2) v^2 / T)``.
    """
    a, b = window
    if not (0 < a < b < 1):
        raise InputError(f"the speed window must satisfy 0 < a < b < 1 (c), got {window}")
    if not (math.isfinite(temperature) and temperature > 0):
        raise InputError(f"the temperature must be positive, got {temperature}")
    s = 0.5 * modes.mass / temperature
    lo, hi = -math.expm1(-s * a * a), -math.expm1(-s * b * b)
    u = rng.uniform(lo, hi, size)
    return np.sqrt(-np.log1p(-u) / s)


@dataclass(frozen=True, eq=False)
class SymmetryTest:
    """Bowker's test of symmetry of a square table of counts.

    Attributes
    ----------
    counts : numpy.ndarray, shape (K, K)
        ``counts[i, j]``: pairs with ``v`` in bin ``i`` and ``v'`` in bin ``j``.
    chi2 : float
        ``sum_{i<j} (n_ij - n_ji)^2 / (n_ij + n_ji)``.
    dof : int
        Pairs of bins ``i < j`` with ``n_ij + n_ji > 0``.
    p_value : float
        Chance of a ``chi2`` at least this large if the table is symmetric.
    z : numpy.ndarray, shape (K, K)
        ``(n_ij - n_ji) / sqrt(n_ij + n_ji)``, each about standard normal under symmetry.
    """

    counts: np.ndarray
    chi2: float
    dof: int
    p_value: float
    z: np.ndarray


def symmetry_test(v_in, v_out, edges) -> SymmetryTest:
    """Bowker's test that the pairs ``(v_in, v_out)`` binned by ``edges`` are symmetric.

    Pairs with either speed outside ``[edges[0], edges[-1]]`` are left out.
    """
    edges = np.asarray(edges, dtype=float)
    v_in = np.asarray(v_in, dtype=float)
    v_out = np.asarray(v_out, dtype=float)
    k = edges.size - 1
    inside = (v_in >= edges[0]) & (v_in <= edges[-1]) & (v_out >= edges[0]) & (v_out <= edges[-1])
    i = np.clip(np.searchsorted(edges, v_in[inside], side="right") - 1, 0, k - 1)
    j = np.clip(np.searchsorted(edges, v_out[inside], side="right") - 1, 0, k - 1)
    counts = np.zeros((k, k), dtype=int)
    np.add.at(counts, (i, j), 1)
    total = counts + counts.T
    diff = counts - counts.T
    with np.errstate(invalid="ignore", divide="ignore"):
        z = np.where(total > 0, diff / np.sqrt(total), 0.0)
    upper = np.triu(total > 0, k=1)
    chi2 = float(np.sum(diff[upper] ** 2 / total[upper]))
    dof = int(np.count_nonzero(upper))
    p = float(stats.chi2.sf(chi2, dof)) if dof else 1.0
    return SymmetryTest(counts=counts, chi2=chi2, dof=dof, p_value=p, z=z)


@dataclass(frozen=True, eq=False)
class BalanceTest:
    """Collisions of a detailed-balance test and the symmetry test of their speeds.

    ``v_in``, ``v_out``: speeds before and after (``c``), shape (S,); ``temperature`` of the
    modes and ``translation_temperature`` of the flux density the speeds were drawn from
    (reduced units; equal for the relation itself); ``window`` the speed window; ``test`` the
    :class:`SymmetryTest` on equal-probability bins of the window; ``failed`` the runs that
    outlasted the solver's time bound (a disk leaving far below the window; ``v_out = 0``);
    ``max_energy_drift`` the largest relative energy drift of a run and ``max_step_error`` the
    largest Richardson estimate of a run's epsilon error (``None`` when the energy drift judged
    the steps).
    """

    v_in: np.ndarray
    v_out: np.ndarray
    temperature: float
    translation_temperature: float
    window: tuple[float, float]
    n_modes: int
    alpha: float
    seed: int
    test: SymmetryTest
    max_energy_drift: float
    failed: int = 0
    max_step_error: float | None = None

    @property
    def stationary_moment(self) -> tuple[float, float, float]:
        """``<v^2>`` and ``<v'^2>`` over the pairs inside the window, and the standard error
        of their difference (equal under the relation)."""
        a, b = self.window
        keep = (self.v_out >= a) & (self.v_out <= b)
        d = self.v_out[keep] ** 2 - self.v_in[keep] ** 2
        return (float(np.mean(self.v_in[keep] ** 2)), float(np.mean(self.v_out[keep] ** 2)),
                float(d.std(ddof=1) / math.sqrt(d.size)))  # fmt: skip

    def antisymmetric_z(self) -> dict[str, float]:
        """``mean(h(v') - h(v)) / standard error`` over the pairs inside the window, for
        ``h = (m/2) v^2`` (the energy the translation gains: the most powerful statistic
        against a translation hotter or colder than the modes) and ``h = ln v`` (most powerful
        against a missing flux factor ``v``). Each is about standard normal under the
        relation."""
        a, b = self.window
        keep = (self.v_out >= a) & (self.v_out <= b)
        out = {}
        for name, h in (("energy", np.square), ("log_speed", np.log)):
            d = h(self.v_out[keep]) - h(self.v_in[keep])
            out[name] = float(d.mean() / (d.std(ddof=1) / math.sqrt(d.size)))
        return out


def detailed_balance_test(
    modes: ModeSet,
    alpha: float,
    temperature: float,
    window: tuple[float, float],
    samples: int,
    seed: int = 0,
    *,
    bins: int = 6,
    translation_temperature: float | None = None,
    settings: CollisionSettings | None = None,
    batch_size: int = 64,
    progress: Callable[[int], None] | None = None,
    step_judge: str = STEP_JUDGE,
    **overrides,
) -> BalanceTest:
    """Collide ``samples`` disks with canonical modes at ``temperature`` and speeds drawn from
    the flux density at ``translation_temperature`` (default: the same) in ``window``; test
    the symmetry of ``(v, v')`` on ``bins`` bins of equal probability under the flux density.

    A ``translation_temperature`` different from ``temperature`` is a control: the relation
    then predicts an asymmetric table, and the test should reject it. Every collision's step
    is judged by ``step_judge`` (:func:`restitution.vibrating.ensemble.collide_states`).
    """
    t_tr = temperature if translation_temperature is None else translation_temperature
    rng = np.random.default_rng(seed)
    v_in = flux_speeds(modes, t_tr, window, samples, rng)
    Q, P = thermal_state(modes, temperature, rng, size=samples)
    v_out = np.empty(samples)
    drift = 0.0
    step_error = None
    failed = 0
    for start in range(0, samples, batch_size):
        stop = min(start + batch_size, samples)
        res = collide_states(modes, v_in[start:stop], alpha, Q[start:stop], P[start:stop],
                             settings, step_judge=step_judge, **overrides)  # fmt: skip
        # A failed run is a disk still near the wall long after the incoming one would have
        # left: it leaves (far) below the window. It is counted apart (``failed``).
        v_out[start:stop] = [0.0 if isinstance(r, str) else r.epsilon * r.v for r in res]
        failed += sum(isinstance(r, str) for r in res)
        done = [r for r in res if not isinstance(r, str)]
        drift = max([drift, *(r.energy_drift for r in done)])
        errors = [r.step_error for r in done if r.step_error is not None]
        if errors:
            step_error = max([step_error or 0.0, *errors])
        if progress is not None:
            progress(stop)
    # Equal-probability edges of the flux density at the modes' temperature in the window.
    s = 0.5 * modes.mass / temperature
    lo, hi = -math.expm1(-s * window[0] ** 2), -math.expm1(-s * window[1] ** 2)
    edges = np.sqrt(-np.log1p(-np.linspace(lo, hi, bins + 1)) / s)
    edges[0], edges[-1] = window
    return BalanceTest(
        v_in=v_in,
        v_out=v_out,
        temperature=float(temperature),
        translation_temperature=float(t_tr),
        window=(float(window[0]), float(window[1])),
        n_modes=len(modes),
        alpha=float(alpha),
        seed=seed,
        test=symmetry_test(v_in, v_out, edges),
        max_energy_drift=drift,
        failed=failed,
        max_step_error=step_error,
    )
