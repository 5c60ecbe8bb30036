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
