"""A sphere runs through the same collision code as the disk (the body protocol): both paths
agree, energy is conserved, and a sphere whose modes do not couple rebounds elastically."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from restitution import collide
from restitution.bodies.base import ModalBody
from restitution.bodies.sphere.modes import compute_sphere_modes


@pytest.fixture(scope="module")
def sphere():
    return compute_sphere_modes(0.3, count=120)


def test_the_sphere_is_a_body(sphere):
    assert isinstance(sphere, ModalBody) and sphere.geometry == "sphere"


def test_compiled_and_numpy_paths_agree_and_conserve_energy(sphere):
    fast = collide(sphere, v=0.1, alpha=500.0, backend="compiled")
    ref = collide(sphere, v=0.1, alpha=500.0, backend="numpy")
    assert abs(fast.epsilon - ref.epsilon) < 1e-12
    np.testing.assert_allclose(fast.mode_energy_after, ref.mode_energy_after, atol=1e-12)
    # Energy balance: translation after plus vibrations after equals the energy before.
    assert fast.energy_drift < 1e-6
    assert abs(fast.epsilon**2 + fast.mode_energy_after.sum() - 1.0) < 1e-5
    assert 0.9 < fast.epsilon < 1.0


def test_uncoupled_modes_give_an_elastic_rebound(sphere):
    # All surface amplitudes zero: the rigid sphere, epsilon = 1 up to the energy tolerance.
    rigid = dataclasses.replace(sphere, C=np.zeros(len(sphere)), S=np.zeros(len(sphere)))
    r = collide(rigid, v=0.05, alpha=500.0)
    assert abs(r.epsilon - 1.0) < 1e-9
    assert np.all(r.mode_energy_after == 0.0)


def test_dop853_on_the_same_equations_agrees():
    # scipy's DOP853 with the dense wall matrix (an independent implementation of the same
    # equations) and with the solver's own order-by-order wall evaluation.
    from restitution.dynamics.reference import collide_dop853

    modes = compute_sphere_modes(0.3, count=60)
    ours = collide(modes, v=0.1, alpha=500.0, energy_tol=1e-10)
    for wall in ("dense", "orders"):
        ref = collide_dop853(modes, 0.1, 500.0, rtol=1e-11, atol=1e-13, wall=wall)
        assert abs(ours.epsilon - ref["epsilon"]) < 1e-8


def test_time_reversal_brings_the_sphere_back_at_rest():
    """Reverse the momenta of the final state and run back: speed v and no vibration."""
    from restitution.dynamics.collision import start_position
    from restitution.dynamics.integrators import free_modes

    modes = compute_sphere_modes(0.3, count=80)
    v, alpha = 0.1, 600.0
    fwd = collide(modes, v, alpha, energy_tol=1e-10)
    u = fwd.epsilon * v
    tau = (start_position(modes, u, alpha) - fwd.final_x0) / u
    Qr, Pr = free_modes(modes.omega, modes.mass, fwd.final_Q, -fwd.final_P, tau)
    back = collide(modes, u, alpha, initial=(Qr, Pr), energy_tol=1e-10)
    assert back.epsilon * u == pytest.approx(v, rel=1e-7)  # eps_reversed = 1 / eps
    # All the vibration energy went back into the translation.
    assert back.mode_energy_after.sum() * (u / v) ** 2 < 1e-7 * fwd.mode_energy_after.sum()


def test_the_rigid_sphere_turns_where_the_wall_holds_its_energy():
    """All amplitudes zero: the exponential wall on a rigid sphere, in closed form.

    With the tip at ``x = x0 + 1`` the wall energy is
    ``V = (1/alpha) int exp(alpha (x0 + cos theta)) dA = exp(alpha x) I / alpha`` with
    ``I = 2 pi (1 - e^-alpha) / alpha`` (:func:`restitution.bodies.sphere.surface.depth_transform`),
    and the force ``alpha V``. At the
    turning point ``V = E0 = (m/2) v^2``: the deepest tip position and the largest force follow.
    """
    import math

    sphere = compute_sphere_modes(0.3, count=40)
    rigid = dataclasses.replace(sphere, C=np.zeros(len(sphere)), S=np.zeros(len(sphere)))
    v, alpha = 0.05, 800.0
    r = collide(rigid, v=v, alpha=alpha, energy_tol=1e-10)
    e0 = 0.5 * (4 * math.pi / 3) * v**2
    area = 2 * math.pi * -math.expm1(-alpha) / alpha
    x_turn = math.log(alpha * e0 / area) / alpha
    # The run samples x at its steps: near the turn x = x_turn - (a/2) (t - t*)^2 with the
    # deceleration a = alpha E0 / m, so the deepest sample lies at most a dt^2 / 8 below it.
    bound = alpha * e0 / (4 * math.pi / 3) * r.dt**2 / 8
    assert -1e-12 <= x_turn - r.max_compression <= bound + 1e-12
    assert r.max_force == pytest.approx(alpha * e0, rel=1e-5)
    assert r.epsilon == pytest.approx(1.0, abs=1e-10)
