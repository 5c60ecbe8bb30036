"""The hats' wall with Dundurs' coupling
(:class:`restitution.dynamics.contact.residual_hats.TiltedHatWall`): its equilibrium, its
untilted limit and the derivative of its condensed energy in the in-line forces, on a small
made-up contact (six hats, 300 nodes)."""

from __future__ import annotations

import numpy as np
import pytest

from restitution.dynamics.contact.residual_hats import HatWall, TiltedHatWall

ALPHA = 2000.0


def _contact(seed: int = 5):
    rng = np.random.default_rng(seed)
    K = 6
    radii = 0.01 * np.arange(K + 1)
    rho = rng.uniform(0.0, 0.055, 300)
    cos = rng.uniform(-1.0, 1.0, 300)
    log_e = np.log(rng.uniform(0.5, 1.5, 300) / 300.0) + ALPHA * 1e-4 * rng.standard_normal(300)

    def spd(scale):
        B = rng.standard_normal((K, K))
        return scale * (B @ B.T / K + np.eye(K))

    return radii, rho, cos, log_e, spd(2e-3), spd(1e-3), 3e-4 * rng.standard_normal((K, K))


def test_untilted_it_is_the_hat_wall():
    """Nodes on the contact axis (``cos = 0``) with no in-line force carry no tilting load: the
    solve is :class:`HatWall`'s to its tolerance."""
    radii, rho, cos, log_e, H, H1, X = _contact()
    e0, P0, slope0 = HatWall(H, radii, ALPHA).solve(log_e, rho)
    e, P, P1, slope, _, value = TiltedHatWall(H, radii, ALPHA, H1, X).solve_tilted(
        log_e, rho, 0.0 * cos, np.zeros(len(H))
    )
    assert np.allclose(e, e0, rtol=1e-10, atol=0.0) and np.allclose(P, P0, rtol=1e-10)
    assert np.allclose(slope, slope0, rtol=1e-8, atol=1e-14)
    assert np.all(P1 == 0.0) and np.all(value == 0.0)


def test_equilibrium_and_the_energy_s_derivative_in_the_in_line_forces():
    """At the solve ``V = -H1 P1 - X T`` (the hats' tilt), and the condensed energy's
    derivative in ``T`` is ``-X^T P1`` (the envelope theorem the route's energy bookkeeping
    rests on), checked by central differences (step 1e-4 of ``T``'s scale; measured 2e-10 of
    its size; the tilting loads reach 0.15 of the hats' normal ones here)."""
    radii, rho, cos, log_e, H, H1, X = _contact()
    T = np.array([0.3, 0.2, 0.1, 0.05, 0.02, 0.0])
    wall = TiltedHatWall(H, radii, ALPHA, H1, X)
    e, P, P1, *_ = wall.solve_tilted(log_e, rho, cos, T)
    assert np.max(np.abs(wall.V + H1 @ P1 + X @ T)) * ALPHA < 1e-10
    assert np.max(np.abs(wall.U + H @ P)) * ALPHA < 1e-10
    assert np.max(np.abs(P1)) > 1e-3 * np.max(P)  # the tilt carries a real load
    grad = -X.T @ P1
    step = 1e-4 * np.max(np.abs(T))
    fd = np.zeros(len(T))
    for i in range(len(T)):
        energies = []
        for sign in (1.0, -1.0):
            shifted = T.copy()
            shifted[i] += sign * step
            e_s = wall.solve_tilted(log_e, rho, cos, shifted)[0]
            energies.append(wall.energy(e_s))
        fd[i] = (energies[0] - energies[1]) / (2.0 * step)
    assert fd == pytest.approx(grad, rel=1e-6, abs=1e-8 * np.max(np.abs(grad)))
