"""Sequences of collisions with the vibrations carried over (issue 17).

Independent checks: each collision of a chain is the single collision started from the state
carried by hand (ballistic flight solved here, free modes); the energy bookkeeping of a chain
(translation + vibration + gravity) closes to the drift and the documented neglected work.
"""

import math

import numpy as np
import pytest

from restitution import get_modes
from restitution.dynamics.collision import collide, start_position
from restitution.dynamics.integrators import free_modes
from restitution.vibrating.sequences import bounce, constant_epsilon_speeds, memoryless_speeds
from restitution.vibrating.vibration import STEP_JUDGE

V, ALPHA, G = 0.1, 400.0, 1e-5


@pytest.fixture(scope="module")
def modes():
    return get_modes(0.33, count=30)


@pytest.fixture(scope="module")
def chain(modes):
    return bounce(modes, V, ALPHA, 6, gravity=G)


def test_chain_collisions_are_single_collisions_from_the_carried_state(modes, chain):
    # A chain judges every step by epsilon (STEP_JUDGE), as `restitution collide` does.
    first = collide(modes, V, ALPHA, step_judge=STEP_JUDGE)
    assert chain.epsilon[0] == first.epsilon  # bit for bit: a disk at rest
    # The second collision by hand: fly up at u and back under gravity to the start position
    # of the return speed w, w^2 = u^2 + 2 g (x_start(w) - x_end), then collide from there.
    u = first.epsilon * V
    w = u
    for _ in range(20):
        w = math.sqrt(u * u + 2 * G * (start_position(modes, w, ALPHA) - first.final_x0))
    assert chain.v[1] == pytest.approx(w, rel=1e-14)
    t = (u + w) / G
    assert chain.flight_time[0] == pytest.approx(t, rel=1e-14)
    Q, P = free_modes(modes.omega, modes.mass, first.final_Q, first.final_P, t)
    second = collide(modes, w, ALPHA, initial=(Q, P), step_judge=STEP_JUDGE)
    assert chain.epsilon[1] == pytest.approx(second.epsilon, rel=1e-13)


def test_energy_bookkeeping_of_a_bouncing_chain(modes, chain):
    total = chain.total_before
    e = chain.translation_before + chain.vibration_before
    # Each collision conserves translation + vibration to its drift; gravity's work during the
    # run is neglected and reported; the flights are exact.
    step = np.diff(total) - chain.neglected_work[:-1]
    assert np.all(np.abs(step) <= 2 * chain.energy_drift[:-1] * e[:-1] + 1e-15)
    assert np.all(chain.neglected_impulse < 2e-3)  # g t_end / v: gravity is negligible here
    assert chain.vibration_before[0] == 0 and np.all(chain.vibration_before[1:] > 0)
    np.testing.assert_allclose(chain.vibration_after[:-1], chain.vibration_before[1:], rtol=1e-12)


def test_two_walls_chain_conserves_energy_and_mirrors(modes):
    seq = bounce(modes, V, ALPHA, 4, walls_distance=10.0)
    e = seq.translation_before + seq.vibration_before
    np.testing.assert_allclose(e, e[0], rtol=4 * seq.energy_drift.max())
    # No gravity: the departure speed is the next impact speed.
    np.testing.assert_allclose(seq.v[1:], (seq.epsilon * seq.v)[:-1], rtol=1e-15)
    distance = 10.0 + seq.x_end[:-1] + seq.x_start[1:]  # each in its own wall's frame
    np.testing.assert_allclose(seq.flight_time[:-1], distance / seq.v[1:], rtol=1e-14)


def test_comparison_sequences(modes):
    np.testing.assert_allclose(constant_epsilon_speeds(0.1, 0.9, 3), [0.1, 0.09, 0.081])
    speeds = memoryless_speeds(modes, V, ALPHA, 2)
    assert speeds[1] == collide(modes, V, ALPHA, step_judge=STEP_JUDGE).epsilon * V
