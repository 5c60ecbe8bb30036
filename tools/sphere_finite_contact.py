"""The sphere's own contact stiffnesses against Mindlin's, and what they would do to the
quasistatic microslip ``beta`` (issue 63: which limit the modal route should reach).

Maw, Barber and Fawcett's theory (law (b), :mod:`restitution.quasistatic.oblique`) puts the
contact on a half-space: the incremental stiffnesses ``k_n = 2 E* a`` and ``k_t = chi k_n``,
``chi = 2 (1 - nu) / (2 - nu)``. A free sphere answers a slow load with its inertial relief,
and its contact stiffnesses at radius ``a`` are ``k_n = 1 / C_punch(a)`` and ``k_t = 1 /
C_stick(a)``, the compliances of the flat punch's pressure and of Mindlin's stick traction on
the elastic sphere (:func:`restitution.bodies.sphere.contact_compliance.continuum_compliance`;
tests/test_sphere_contact_compliance.py checks them against the half-space as ``a -> 0`` and
against the modes' sums). This prints

1. ``k_n``, ``k_t`` and their ratio over the half-space's against ``a``, with the impact speed
   whose Hertz contact radius that is (the sphere on a rigid wall, ``a = sqrt(delta_max)``) and
   that speed for a steel ball (``c = sqrt(E / rho) = 5172 m/s``);
2. ``beta`` of law (b) with those stiffnesses, by two quasistatic models that bracket how the
   finite body's compliance enters the microslip (neither is exact; both reduce to law (b) on
   the half-space, which the first row of each table checks against
   :func:`~restitution.quasistatic.oblique.oblique_impact`):

   * **density**: the method of dimensionality reduction's springs with the sphere's
     stiffness densities ``g(x) = dk/da`` at ``a = x`` (normal and tangential), the slip bound
     of a spring ``mu`` times its normal force; the normal motion is that of these springs.
   * **series**: the contact itself is the half-space's (law (b) exactly), and the sphere's
     global compliance ``C(a) - C_half-space(a)`` is a spring in series with it, normal
     (punch-shaped increments) and tangential (stick-shaped increments).

Both integrate by velocity Verlet at a fixed step (``STEPS`` per contact time); the half-space
row reproduces law (b) to about 1e-4, and halving the step and the springs moves ``beta`` by
less than 1e-4 (checked at ``v = 0.005``). Units: ``E = rho = R = 1``, ``nu = 0.3``, ``mu =
0.5``, no spin before, ``K = 7/2``.

Usage (from the project's root, with its venv; about 5 min on one core)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_finite_contact.py
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from scipy.interpolate import CubicSpline

from restitution.bodies.sphere.contact_compliance import continuum_compliance
from restitution.quasistatic.oblique import SOLID, oblique_impact, stiffness_ratio

NU = 0.3
MU = 0.5
RADII = (0.0025, 0.005, 0.01, 0.02, 0.03, 0.04, 0.06, 0.08, 0.1, 0.12, 0.14, 0.16, 0.18, 0.2)
SPEEDS = (0.005, 0.001, 2e-4, 4e-5)
STEEL_C = 5172.0  # m/s, sqrt(E / rho) of steel (E = 210 GPa, rho = 7850 kg/m^3)
SPRINGS, STEPS = 800, 80000
MASS = 4.0 * math.pi / 3.0


class Sphere:
    """The sphere's contact stiffnesses on a grid of radii, interpolated."""

    def __init__(self, nu: float, radii) -> None:
        self.nu, self.e_star, self.chi = nu, 1.0 / (1.0 - nu * nu), stiffness_ratio(nu)
        self.a = np.asarray(radii, dtype=float)
        self.c_n = np.array([continuum_compliance(a, nu, "punch") for a in self.a])
        self.c_t = np.array([continuum_compliance(a, nu, "stick") for a in self.a])
        # the half-space's: 1 / (2 E* a) and 1 / (2 chi E* a)
        self.hs_n = 1.0 / (2.0 * self.e_star * self.a)
        self.hs_t = self.hs_n / self.chi
        la = np.log(self.a)
        # stiffness over the half-space's, and the global compliance, smooth in ln a
        self._rn = CubicSpline(la, self.hs_n / self.c_n)
        self._rt = CubicSpline(la, self.hs_t / self.c_t)
        self._gn = CubicSpline(la, self.c_n - self.hs_n)
        self._gt = CubicSpline(la, self.c_t - self.hs_t)

    def _clip(self, x):
        return np.log(np.clip(x, self.a[0], self.a[-1]))

    def densities(self, x):
        """``dk_n/da`` and ``dk_t/da`` at ``a = x``: ``d(2 E* a r(a))/da = 2 E* (r + r')``
        with ``r' = dr / d ln a``."""
        la = self._clip(x)
        g = 2.0 * self.e_star
        return g * (self._rn(la) + self._rn(la, 1)), g * self.chi * (self._rt(la) + self._rt(la, 1))

    def global_compliance(self, a: float) -> tuple[float, float]:
        la = float(self._clip(a))
        return float(self._gn(la)), float(self._gt(la))


def _start(v: float, e_star: float, springs: int, reach: float):
    dm = (15.0 * MASS * v * v / (16.0 * e_star)) ** 0.4
    width = reach * math.sqrt(dm) / springs
    return dm, width, (np.arange(springs) + 0.5) * width


def density_model(sphere: Sphere | None, v: float, tan_over_mu: float, *, springs=SPRINGS,
                  steps=STEPS) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of the density model (``sphere=None``: the half-space)."""
    e_star = 1.0 / (1.0 - NU * NU)
    dm, width, x = _start(v, e_star, springs, 1.3)
    if sphere is None:
        chi = stiffness_ratio(NU)
        gn, gt = np.full(springs, 2.0 * e_star), np.full(springs, 2.0 * chi * e_star)
    else:
        gn, gt = sphere.densities(x)
    kn, kt, bound = gn * width, gt * width, MU * gn / gt
    vc0 = tan_over_mu * MU * v
    dt = 1.2 * 2.94 * dm / v / steps
    delta, vd, u, vc, force, T = 0.0, v, 0.0, vc0, 0.0, 0.0
    anchor, active, x2 = np.zeros(springs), np.zeros(springs, bool), x * x
    for _ in range(4 * steps):
        delta_new = delta + dt * vd - 0.5 * dt * dt * force / MASS
        u_new = u + dt * vc + 0.5 * dt * dt * SOLID / MASS * T
        h = np.maximum(delta_new - x2, 0.0)
        now = h > 0.0
        anchor = np.where(now & ~active, u_new, anchor)  # a spring enters unstretched
        w = np.where(now, np.clip(u_new - anchor, -bound * h, bound * h), 0.0)
        anchor, active = np.where(now, u_new - w, anchor), now
        force_new, T_new = float(kn @ h), -float(kt @ w)
        vd -= 0.5 * dt * (force + force_new) / MASS
        vc += 0.5 * dt * SOLID / MASS * (T + T_new)
        delta, u, force, T = delta_new, u_new, force_new, T_new
        if delta < 0.0 and vd < 0.0:
            return -vc / vc0, -vd / v
    raise RuntimeError("no separation; raise the steps")


def series_model(sphere: Sphere | None, v: float, tan_over_mu: float, *, springs=SPRINGS,
                 steps=STEPS) -> tuple[float, float]:  # fmt: skip
    """``beta`` and ``epsilon_normal`` of the series model (``sphere=None``: the half-space).
    The local compression and the contact's local tangential displacement are solved at each
    step from the global springs' increments (Newton, then a damped fixed point)."""
    e_star, chi = 1.0 / (1.0 - NU * NU), stiffness_ratio(NU)
    dm, width, x = _start(v, e_star, springs, 1.4)
    k, lam, x2 = 2.0 * chi * e_star * width, MU / chi, x * x
    vc0 = tan_over_mu * MU * v
    dt = 1.3 * 2.94 * dm / v / steps
    delta, vd, local, force = 0.0, v, 0.0, 0.0
    u, vc, u_global, T = 0.0, vc0, 0.0, 0.0
    anchor, active = np.zeros(springs), np.zeros(springs, bool)

    def hertz(d):
        return 4.0 / 3.0 * e_star * max(d, 0.0) ** 1.5

    for n in range(4 * steps):
        delta_new = delta + dt * vd - 0.5 * dt * dt * force / MASS
        u_new = u + dt * vc + 0.5 * dt * dt * SOLID / MASS * T
        cn, ct = sphere.global_compliance(math.sqrt(max(local, 0.0))) if sphere else (0.0, 0.0)
        local_new = local + delta_new - delta
        for _ in range(50):  # delta = local + global, d global = cn dF
            r = delta_new - local_new - (delta - local) - cn * (hertz(local_new) - force)
            local_new += r / (1.0 + cn * 2.0 * e_star * math.sqrt(max(local_new, 0.0)))
            if abs(r) < 1e-16:
                break
        force_new = hertz(local_new)
        now = x2 < local_new
        b = lam * np.maximum(local_new - x2, 0.0)
        T_new = T
        for _ in range(200):  # the local displacement u - u_global, d u_global = ct dT
            ul = u_new - u_global - ct * (T_new - T)
            w = np.where(now, np.clip(ul - np.where(now & ~active, ul, anchor), -b, b), 0.0)
            T_next = -k * float(w.sum())
            if abs(T_next - T_new) <= 1e-14 * (abs(T_next) + 1e-300):
                break
            T_new = 0.5 * (T_new + T_next)
        T_new = T_next
        ul = u_new - u_global - ct * (T_new - T)
        anchor = np.where(now, ul - w, anchor)
        active, u_global = now, u_global + ct * (T_new - T)
        vd -= 0.5 * dt * (force + force_new) / MASS
        vc += 0.5 * dt * SOLID / MASS * (T + T_new)
        delta, local, force, u, T = delta_new, local_new, force_new, u_new, T_new
        if local < 0.0 and vd < 0.0 and n > 10:
            return -vc / vc0, -vd / v
    raise RuntimeError("no separation; raise the steps")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speed", type=float, nargs="+", default=SPEEDS, help="c")
    parser.add_argument("--tan-over-mu", type=float, nargs="+", default=(0.3,))
    args = parser.parse_args()
    sphere = Sphere(NU, RADII)
    print("| a | v (c) | steel (m/s) | k_n / half-space | k_t / half-space | chi / chi_hs |")
    print("|---|---|---|---|---|---|")
    for a, cn, ct, hn, ht in zip(sphere.a, sphere.c_n, sphere.c_t, sphere.hs_n, sphere.hs_t,
                                 strict=True):  # fmt: skip
        v = math.sqrt(16.0 * sphere.e_star * a**5 / (15.0 * MASS))  # delta_max = a^2
        print(f"| {a:g} | {v:.3g} | {v * STEEL_C:.3g} | {hn / cn:.4f} | {ht / ct:.4f} | "
              f"{(ht / ct) / (hn / cn):.4f} |")  # fmt: skip
    print("\n| v (c) | tan(theta)/mu | law (b) | half-space, density | sphere, density | "
          "half-space, series | sphere, series |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    for v in args.speed:
        for q in args.tan_over_mu:
            law = oblique_impact(v, q * MU * v, MU, NU).beta
            row = [density_model(None, v, q)[0], density_model(sphere, v, q)[0],
                   series_model(None, v, q)[0], series_model(sphere, v, q)[0]]  # fmt: skip
            print(f"| {v:g} | {q:g} | {law:.4f} | " + " | ".join(f"{b:.4f}" for b in row) + " |",
                  flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
