"""The quasistatic microslip ``beta`` of the finite sphere, from its own surface flexibility
(issue 63: the target the modal route should reach in partial slip).

Maw, Barber and Fawcett's theory (law (b), :mod:`restitution.quasistatic.oblique`) puts the
contact on a half-space. tools/sphere_finite_contact.py bracketed the finite sphere by two
models that are law (b) on the half-space but neither exact. This one solves the contact
problem itself, on annuli of the projected contact plane, with the sphere's flexibility
between them (:func:`~restitution.bodies.sphere.contact_compliance.annulus_flexibility`: the
static answer with the inertial relief of the free sphere, every order summed) or the
half-space's (:func:`~restitution.bodies.sphere.contact_compliance.half_space_annulus_flexibility`,
in closed form):

* **normal**: a pressure ``p_i >= 0`` per annulus, constant on it, such that the annulus's mean
  normal displacement is its mean overlap ``delta - h(r)`` where it presses and at least that
  elsewhere (a linear complementarity problem, by non-negative least squares on the Cholesky
  factor). ``h`` is the sphere's height above its lowest point (``1 - sqrt(1 - r^2)``) or
  Hertz's parabola ``r^2 / 2``.
* **tangential** (Mindlin's in-line approximation, the one law (b) rests on): a traction
  ``q_i`` per annulus along the tangential motion, ``|q_i| <= mu p_i``. Each annulus of the
  sphere's surface sticks to a point of the wall or slips to a new one; at every step the
  tractions minimise the complementary energy ``Q.H.Q / 2 + sum Q_i (s - A_i)`` (``Q_i`` the
  annulus's force, ``H`` the flexibility between forces and mean displacements, ``s`` the
  contact point's rigid tangential displacement, ``A_i`` the wall point annulus ``i`` was
  stuck to) inside the Coulomb box: where ``|Q_i|`` is below its bound the annulus sticks,
  where it is at its bound it slips against its force. An active-set solver, warm-started
  from the last step.

There is no coupling between them: an axisymmetric pressure and an in-line traction are
orthogonal on the sphere as on the half-space. The motion is velocity Verlet in the centre's
approach and the contact point's tangential velocity (``K = 7/2``, no spin before).

On the half-space with Hertz's parabola the solver is law (b)'s problem on a grid of annuli:
tests/test_sphere_partial_slip_tool.py checks it against
:func:`~restitution.quasistatic.oblique.oblique_impact`. Units: ``E = rho = R = 1``, ``nu =
0.3``, ``mu = 0.5``.

Usage (from the project's root, with its venv)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_partial_slip.py
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import cho_factor, cho_solve, solve_triangular
from scipy.optimize import lsq_linear, nnls

from restitution.bodies.sphere.contact_compliance import (
    annulus_flexibility,
    half_space_annulus_flexibility,
)
from restitution.quasistatic.oblique import SOLID, oblique_impact

NU, MU = 0.3, 0.5
MASS = 4.0 * math.pi / 3.0
ANNULI, STEPS, REACH = 80, 8000, 1.25


def hertz_peak(v: float, nu: float = NU) -> float:
    """Hertz's largest approach of the sphere on the rigid wall at normal speed ``v``."""
    return (15.0 * MASS * v * v * (1.0 - nu * nu) / 16.0) ** 0.4


@dataclass
class Contact:
    """The annuli ``edges``, their flexibilities between forces and mean displacements
    (``H[i, j] = G[i, j] / (area_i area_j)``) and the overlap's shape."""

    edges: np.ndarray
    Hn: np.ndarray
    Ht: np.ndarray
    parabola: bool

    @classmethod
    def build(cls, radius: float, *, body: str = "sphere", annuli: int = ANNULI,
              parabola: bool | None = None, l_top: int | None = None) -> Contact:  # fmt: skip
        """Annuli of equal width out to ``radius``; ``body`` is ``"sphere"`` or
        ``"half-space"`` (which takes Hertz's parabola unless ``parabola`` says otherwise)."""
        edges = np.linspace(0.0, radius, annuli + 1)
        area = math.pi * np.diff(edges**2)
        scale = np.outer(area, area)
        if body == "sphere":
            G = [annulus_flexibility(edges, NU, d, l_top=l_top) for d in ("normal", "tangential")]
        elif body == "half-space":
            G = [half_space_annulus_flexibility(edges, NU, d) for d in ("normal", "tangential")]
        else:
            raise ValueError(f"body must be 'sphere' or 'half-space', got {body!r}")
        if parabola is None:
            parabola = body == "half-space"
        return cls(edges, G[0] / scale, G[1] / scale, parabola)

    def __post_init__(self) -> None:
        self.area = math.pi * np.diff(self.edges**2)
        r2 = self.edges**2
        if self.parabola:  # int h dA over each annulus, divided by its area
            self.h = np.diff(math.pi * r2 * r2 / 4.0) / self.area
        else:
            self.h = np.diff(math.pi * r2 + 2.0 * math.pi / 3.0 * (1.0 - r2) ** 1.5) / self.area
        self._chol = np.linalg.cholesky(self.Hn)  # Hn = L L^T

    def normal(self, delta: float) -> np.ndarray:
        """The annuli's normal forces at the approach ``delta``."""
        overlap = delta - self.h
        if overlap[0] <= 0.0:
            return np.zeros_like(overlap)
        # min P.Hn.P / 2 - P.overlap over P >= 0  <=>  min |L^T P - L^-1 overlap|^2
        rhs = solve_triangular(self._chol, overlap, lower=True)
        return nnls(self._chol.T, rhs)[0]


def _box_qp(H: np.ndarray, c: np.ndarray, bound: np.ndarray, stick: np.ndarray,
            sign: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """``min Q.H.Q / 2 + Q.c`` with ``|Q| <= bound``; the active set ``stick`` (others at
    ``sign * bound``) is the guess. Returns ``Q`` and the final set and signs."""
    stick, sign = stick & (bound > 0.0), sign.copy()
    for _ in range(4 * c.size + 10):
        Q = sign * bound
        if stick.any():
            free = ~stick
            rhs = -(c[stick] + H[np.ix_(stick, free)] @ Q[free])
            Q[stick] = cho_solve(cho_factor(H[np.ix_(stick, stick)]), rhs)
        over = stick & (np.abs(Q) > bound)
        grad = H @ Q + c  # the slip increment of each annulus
        wrong = ~stick & (bound > 0.0) & (sign * grad > 0.0)  # slipping with its force
        if not over.any() and not wrong.any():
            return Q, stick, sign
        sign = np.where(over, np.sign(Q), sign)
        stick = (stick & ~over) | wrong
    # the active set cycled: a bounded least-squares solve (H = L L^T)
    L = np.linalg.cholesky(H)
    rhs = -solve_triangular(L, c, lower=True)
    hi = np.maximum(bound, 1e-300)
    Q = lsq_linear(L.T, rhs, bounds=(-hi, hi), method="bvls", tol=1e-14).x
    Q = np.clip(Q, -bound, bound)
    stick = np.abs(Q) < bound * (1.0 - 1e-9)
    return Q, stick, np.where(stick, sign, np.sign(Q))


def oblique(contact: Contact, v: float, tan_over_mu: float, *, mu: float = MU,
            steps: int = STEPS) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of the quasistatic impact at normal speed ``v`` and
    ``tan(theta) = tan_over_mu * mu``, ``steps`` per Hertz contact time."""
    dm = hertz_peak(v)
    dt = 2.94 * dm / v / steps
    vc0 = tan_over_mu * mu * v
    n = contact.edges.size - 1
    delta, vd, force = 0.0, v, 0.0
    s, vc, T = 0.0, vc0, 0.0
    anchor, Q = np.zeros(n), np.zeros(n)
    stick, sign = np.zeros(n, bool), -np.ones(n)
    for step in range(3 * steps):
        delta_new = delta + dt * vd - 0.5 * dt * dt * force / MASS
        s_new = s + dt * vc + 0.5 * dt * dt * SOLID / MASS * T
        P = contact.normal(delta_new)
        bound = mu * P
        if not bound.any():
            anchor, Q = np.full(n, s_new), np.zeros(n)  # out of contact: every annulus free
        else:
            Q, stick, sign = _box_qp(contact.Ht, s_new - anchor, bound, stick, sign)
            anchor = s_new + contact.Ht @ Q  # unchanged where it sticks
        force_new, T_new = float(P.sum()), float(Q.sum())
        vd -= 0.5 * dt * (force + force_new) / MASS
        vc += 0.5 * dt * SOLID / MASS * (T + T_new)
        delta, s, force, T = delta_new, s_new, force_new, T_new
        if step > 10 and force == 0.0 and vd < 0.0:
            return -vc / vc0, -vd / v
    raise RuntimeError("no separation; raise the steps")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speed", type=float, nargs="+", default=(0.005,), help="c")
    parser.add_argument("--tan-over-mu", type=float, nargs="+", default=(0.3, 1.0, 2.0))
    parser.add_argument("--annuli", type=int, nargs="+", default=(ANNULI,))
    parser.add_argument("--steps", type=int, default=STEPS)
    args = parser.parse_args()
    print("| v (c) | annuli | tan(theta)/mu | law (b) | half-space | sphere, parabola | sphere |")
    print("|---|---|---|---|---|---|---|")
    for v in args.speed:
        radius = REACH * math.sqrt(hertz_peak(v))
        for n in args.annuli:
            bodies = [Contact.build(radius, body="half-space", annuli=n),
                      Contact.build(radius, body="sphere", annuli=n, parabola=True)]  # fmt: skip
            bodies.append(Contact(bodies[1].edges, bodies[1].Hn, bodies[1].Ht, False))
            for q in args.tan_over_mu:
                law = oblique_impact(v, q * MU * v, MU, NU).beta
                row = [oblique(c, v, q, steps=args.steps) for c in bodies]
                cells = " | ".join(f"{b:.4f} ({e:.5f})" for b, e in row)
                print(f"| {v:g} | {n} | {q:g} | {law:.4f} | {cells} |", flush=True)


if __name__ == "__main__":
    main()
