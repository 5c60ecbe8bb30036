"""The modal microslip route's quasistatic twin: the truncated sphere's own partial slip on the
exponential wall, to tell what in the modal ``beta`` is its truncation (issue 63).

:func:`restitution.dynamics.oblique_microslip.microslip_collision` moves ``N`` modes of the
sphere against the exponential wall (pressure ``exp(alpha x)`` at a penetration ``x``) with a
tangential spring ``kappa alpha e_j`` and Coulomb's bound at every node. Without the modes'
inertia (each mode answering the load statically, ``q_k = f_k / (m omega_k^2)``) that is a
quasistatic contact problem on the truncated body's flexibility, which this solves on annuli as
:mod:`restitution.quasistatic.sphere_partial_slip` does on the continuum's:

* the flexibility between annuli is the modes' sum ``G[i, j] = sum_k f_ki f_kj / (m
  omega_k^2)``, ``f_ki`` the mode's displacement along the load summed over annulus ``i``
  (azimuthal order 0 normal, 1 tangential in line; the other orders are orthogonal to both);
* the normal forces minimise ``P.H.P / 2 + sum (P_i / alpha) (ln(P_i / A_i) - 1) - sum P_i
  (delta - h_i)``, so each annulus's pressure is ``exp(alpha x_i)`` at its mean penetration
  ``x_i``, as the wall's (Newton, kept positive);
* the tangential forces minimise the complementary energy inside the Coulomb box with each
  annulus's spring ``kappa alpha P_i`` in series
  (:func:`~restitution.quasistatic.sphere_partial_slip.box_qp`).

As ``N``, ``alpha`` and ``kappa`` grow this becomes the finite sphere's quasistatic partial slip
(``beta = +0.139`` at ``v = 0.005``, ``tan(theta)/mu = 0.3``); at the modal runs' ``N``,
``alpha`` and ``kappa`` it is what those runs would give without their modes' inertia. Units:
``E = rho = R = 1``, ``nu = 0.3``, ``mu = 0.5``, ``v = 0.005``.

Usage (from the project's root, with its venv)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_modal_partial_slip.py \\
        --modes 80 160 --alpha 500 8000

(``--modes 0 --alpha 8000 16000 32000 64000 128000``: the continuum's, docs/oblique.md's
table; about 30 s an impact.) ``--one-state`` gives the twin of the one-state route instead
(:func:`restitution.dynamics.oblique.oblique_collision`: one stick/slip state spread like the
pressure, :class:`~restitution.dynamics.one_state.OneStateFriction`, no springs),
docs/oblique.md ("The one-state route's own limit").
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.contact_compliance import (
    annulus_flexibility,
    modal_annulus_flexibility,
)
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.dynamics.one_state import OneStateFriction
from restitution.quasistatic.hertz_sphere import CONTACT_TIME_CONSTANT, SPHERE_MASS
from restitution.quasistatic.sphere_partial_slip import REACH, box_qp, hertz_peak, mean_height

NU, MU, V, KAPPA = 0.3, 0.5, 0.005, 64.0
_K = 3.5  # 1 + m R^2 / I of the solid sphere


class ModalContact:
    """The annuli ``edges`` with the truncated body's normal flexibility ``Hn`` (between forces
    and mean displacements) on the exponential wall ``alpha``; the sphere's own shape."""

    def __init__(self, edges: np.ndarray, Hn: np.ndarray, alpha: float) -> None:
        self.edges, self.Hn, self.alpha = edges, Hn, alpha
        self.area = math.pi * np.diff(edges**2)
        self.h = mean_height(edges)
        self._P = np.zeros(edges.size - 1)

    def normal(self, delta: float) -> np.ndarray:
        """The annuli's normal forces at the approach ``delta`` (module docs)."""
        g = delta - self.h
        P = self._P.copy()
        live = (self.alpha * g > -40.0) | (P > 1e-30)
        if not live.any():
            self._P = np.zeros_like(g)
            return self._P
        P = np.where(live & (P <= 0.0), self.area * np.exp(np.minimum(self.alpha * g, 0.0)), P)
        idx = np.flatnonzero(live)
        H, A, a = self.Hn[np.ix_(idx, idx)], self.area[idx], self.alpha
        p = P[idx]

        def phi(p):
            return 0.5 * p @ H @ p + np.sum(p / a * (np.log(p / A) - 1.0)) - p @ g[idx]

        for _ in range(200):
            grad = H @ p + np.log(p / A) / a - g[idx]
            step = -np.linalg.solve(H + np.diag(1.0 / (a * p)), grad)
            dec = -grad @ step
            if dec < 1e-26 * max(1.0, abs(phi(p))):
                break
            neg = step < 0.0
            lam = min(1.0, 0.9 * float(np.min(-p[neg] / step[neg]))) if neg.any() else 1.0
            f0 = phi(p)
            while phi(p + lam * step) > f0 - 0.25 * lam * dec and lam > 1e-12:
                lam *= 0.5
            p = p + lam * step
        P = np.zeros_like(g)
        P[idx] = p
        self._P = P
        return P


def impact(cap, alpha: float, kappa: float, tan_over_mu: float, *, annuli: int = 60,
           steps: int = 6000, one_state: bool = False) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of the truncated sphere's quasistatic impact (``cap``
    ``None``: the continuous sphere's, every order summed); ``one_state``: with the one-state
    route's friction (:class:`~restitution.dynamics.one_state.OneStateFriction`,
    no springs: ``kappa`` unused) instead of microslip."""
    radius = REACH * math.sqrt(hertz_peak(V, NU))
    edges = np.linspace(0.0, radius, annuli + 1)
    area = math.pi * np.diff(edges**2)
    scale = np.outer(area, area)
    if cap is None:  # the continuum's flexibility
        Hn, Ht = (annulus_flexibility(edges, NU, d) / scale for d in ("normal", "tangential"))
    else:
        Hn, Ht = (modal_annulus_flexibility(cap, edges, d) / scale
                  for d in ("normal", "tangential"))  # fmt: skip
    contact = ModalContact(edges, Hn, alpha)
    vt = tan_over_mu * MU * V
    dm = hertz_peak(V, NU)
    dt = CONTACT_TIME_CONSTANT * dm / V / steps
    n = annuli
    delta, vd = -30.0 / alpha, V
    force = float(contact.normal(delta).sum())
    s, vc, T = 0.0, vt, 0.0
    anchor, Q = np.zeros(n), np.zeros(n)
    stick, sign = np.zeros(n, bool), -np.ones(n)
    kick = _K / SPHERE_MASS
    one = OneStateFriction(Ht) if one_state else None
    for _ in range(4 * steps):
        delta_new = delta + dt * vd - 0.5 * dt * dt * force / SPHERE_MASS
        s_new = s + dt * vc + 0.5 * dt * dt * kick * T
        P = contact.normal(delta_new)
        live = P > 1e-14 * max(P.max(), 1e-300)
        Q = np.zeros(n)
        if one is not None:
            Q = one.step(P, s, s_new, MU) * P / max(P.sum(), 1e-300)
        elif live.any():
            i = np.flatnonzero(live)
            H = Ht[np.ix_(i, i)] + np.diag(1.0 / (kappa * alpha * P[i]))
            Qi, st, sg = box_qp(H, s_new - anchor[i], MU * P[i], stick[i], sign[i])
            Q[i], stick[i], sign[i] = Qi, st, sg
            anchor[i] = s_new + H @ Qi  # unchanged where it sticks (its spring included)
        if one is None:
            free = ~live
            anchor[free] = s_new + (Ht @ Q)[free]
            stick[free] = False
        force_new, T_new = float(P.sum()), float(Q.sum())
        vd -= 0.5 * dt * (force + force_new) / SPHERE_MASS
        vc += 0.5 * dt * kick * (T + T_new)
        delta, s, force, T = delta_new, s_new, force_new, T_new
        if vd < 0.0 and alpha * delta < -30.0:
            return -vc / vt, -vd / V
    raise RuntimeError("no separation; raise the steps")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--modes", type=int, nargs="+", default=(80, 160),
                        help="mode counts; 0 is the continuum's flexibility")  # fmt: skip
    parser.add_argument("--alpha", type=float, nargs="+", default=(500.0, 2000.0, 8000.0))
    parser.add_argument("--kappa", type=float, default=KAPPA)
    parser.add_argument("--tan-over-mu", type=float, default=0.3)
    parser.add_argument("--annuli", type=int, default=60)
    parser.add_argument("--steps", type=int, default=6000)
    parser.add_argument("--one-state", action="store_true",
                        help="the one-state route's friction instead of microslip")  # fmt: skip
    args = parser.parse_args()
    print("| modes | alpha | kappa | beta | epsilon_normal | s |")
    print("|---|---|---|---|---|---|")
    for n in args.modes:
        cap = cap_modes(compute_sphere_modes(NU, count=n), azimuthal=1) if n else None
        for alpha in args.alpha:
            start = time.perf_counter()
            beta, eps = impact(cap, alpha, args.kappa, args.tan_over_mu, annuli=args.annuli,
                               steps=args.steps, one_state=args.one_state)  # fmt: skip
            print(f"| {n} | {alpha:g} | {args.kappa:g} | {beta:.4f} | {eps:.6f} | "
                  f"{time.perf_counter() - start:.0f} |", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
