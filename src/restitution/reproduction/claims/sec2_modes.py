"""Claims of section 2 (the free disk's modes): Figs. 2 and 3 and eq. (20).

Each claim is checked against a computation independent of :mod:`restitution.bodies.disk.modes`
where one exists (the breathing roots of eq. (20) by Brent's method).
"""

from __future__ import annotations

import math

import numpy as np

from restitution.reproduction.claims.verdict import Comparison, row

__all__ = ["breathing_roots", "mode_rows"]


def breathing_roots(nu: float, omega_max: float) -> np.ndarray:
    """Frequencies (``c/R``) of the breathing modes below ``omega_max`` from eq. (20).

    Roots of ``kappa J_1'(kappa) + nu J_1(kappa) = 0`` bracketed on a fine grid and refined by
    Brent's method; ``omega = kappa / sqrt(1 - nu^2)`` (eq. 18). Independent of the
    two-by-two determinant used by :mod:`restitution.bodies.disk.modes`.
    """
    from scipy.optimize import brentq
    from scipy.special import jv, jvp

    def f(k):
        return k * jvp(1, k) + nu * jv(1, k)

    scale = math.sqrt(1.0 - nu**2)
    k = np.linspace(1e-3, omega_max * scale, 4000)
    y = f(k)
    sign_change = np.nonzero(y[:-1] * y[1:] < 0)[0]
    roots = [brentq(f, k[i], k[i + 1], xtol=1e-14) for i in sign_change]
    return np.asarray(roots) / scale


def mode_rows(d) -> list[Comparison]:
    rows = []
    # Fig. 2: the centre moves only for n = 1 (displacement at r = 0 of each drawn mode).
    from restitution.bodies.cache import get_modes

    s = d.settings
    modes = get_modes(s.nu, omega_max=12.0)  # the set Fig. 2 draws from
    U_r, _ = modes.shapes(np.array([0.0]))
    shifts = []
    for n, l in s.shape_modes:
        # At r = 0 the n = 1 field (U_r cos phi, -U_r sin phi) is a translation by |U_r(0)|;
        # every other order has U_r(0) = U_phi(0) = 0 when the centre stays at rest.
        k = int(np.nonzero((modes.n == n) & (modes.l == l))[0][0])
        shifts.append((n, l, float(abs(U_r[k, 0]))))
    ok = all((u > 1e-3) if n == 1 else (u < 1e-9) for n, _, u in shifts)
    rows.append(
        row(
            "Fig. 2",
            "centre displaced only for n = 1",
            "for n = 1 there is displacement of the centre; for n >= 2 it vanishes like "
            "r^(n-1); breathing modes leave the centre at rest",
            ", ".join(f"(n, l) = ({n}, {l}): |u(r = 0)|/Q = {u:.3g}" for n, l, u in shifts),
            ok,
        )
    )
    # Fig. 3: the lowest mode and the breathing roots.
    f3 = d.fig03
    i = int(np.argmin(f3.omega))
    lowest = int(f3.n[i])  # the lowest mode of its order n, so l = 0
    rows.append(
        row(
            "Fig. 3",
            "lowest mode",
            "the mode with the lowest frequency is the quadrupole (n = 2, l = 0)",
            f"lowest: (n, l) = ({lowest}, 0), omega = {f3.omega[i]:.6f} c/R (nu = {f3.nu:g})",
            lowest == 2,
        )
    )
    ours_b = np.sort(f3.omega[f3.n == 0])
    ref = breathing_roots(f3.nu, float(np.max(f3.omega)) + 1e-9)
    m = min(ours_b.size, ref.size)
    dev = float(np.max(np.abs(ours_b[:m] - ref[:m]))) if m else float("nan")
    ok = ours_b.size == ref.size and m > 0 and dev < 1e-8
    rows.append(
        row(
            "Fig. 3 / eq. (20)",
            "breathing modes (n = 0)",
            "purely radial modes solve kappa J_1'(kappa) + nu J_1(kappa) = 0 (eq. 20)",
            f"{ours_b.size} breathing modes below omega = {np.max(f3.omega):.3g}; lowest "
            f"omega = {ours_b[0]:.6f} c/R = {ours_b[0] * math.sqrt(1 - f3.nu**2):.6f} c_p/R; "
            f"largest deviation from the roots of eq. (20): {dev:.1e}",
            ok,
            "" if ok else f"by {dev:.2e} ({ref.size} roots of eq. 20)",
        )
    )
    return rows
