"""The rigid sphere in the exponential wall, in closed form: the sphere's own surface integral.

The checks every body passes (the sphere is a ModalBody; kernel against the NumPy path, DOP853,
time reversal, the rigid limits, the energy balance) run for the sphere in
tests/test_every_body.py.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from restitution import collide
from restitution.bodies.sphere.modes import compute_sphere_modes


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
