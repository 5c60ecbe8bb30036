"""Collisions that start from a vibrating disk: the solver's state map (issue 17).

Independent checks: bit-for-bit reduction to the disk at rest, agreement of the compiled kernel
with the NumPy reference path, the energy balance, and time reversal of the state map.
"""

import numpy as np
import pytest

from restitution import get_modes
from restitution.dynamics.collision import collide, collide_batch, start_position
from restitution.dynamics.integrators import free_modes
from restitution.errors import InputError

N = 120


@pytest.fixture(scope="module")
def modes():
    return get_modes(0.33, count=N)


def _random_state(modes, v, energy, seed):
    """Modal state with total energy ``energy`` (fraction of (m/2) v^2), random phases."""
    rng = np.random.default_rng(seed)
    m = modes.mass
    e = rng.exponential(size=len(modes))
    e *= energy * 0.5 * m * v**2 / e.sum()
    phase = rng.uniform(0, 2 * np.pi, len(modes))
    amp = np.sqrt(2 * e / m) / modes.omega
    return amp * np.cos(phase), -m * modes.omega * amp * np.sin(phase)


@pytest.mark.parametrize("backend", ["compiled", "numpy"])
def test_zero_state_is_the_disk_at_rest_bit_for_bit(modes, backend):
    zeros = np.zeros(N)
    a = collide_batch(modes, [0.1, 0.03], [500, 2000], backend=backend)
    b = collide_batch(modes, [0.1, 0.03], [500, 2000], backend=backend, initial=(zeros, zeros))
    for x, y in zip(a, b, strict=True):
        assert x.epsilon == y.epsilon
        np.testing.assert_array_equal(x.mode_energy_after, y.mode_energy_after)
        np.testing.assert_array_equal(x.final_Q, y.final_Q)


@pytest.mark.slow  # 4 s of the default run (stop 79: the default run under 10 min)
def test_compiled_and_numpy_agree_on_a_vibrating_disk(modes):
    Q, P = _random_state(modes, 0.1, 0.5, seed=1)
    a = collide(modes, 0.1, 500, backend="compiled", initial=(Q, P))
    b = collide(modes, 0.1, 500, backend="numpy", initial=(Q, P))
    assert abs(a.epsilon - b.epsilon) < 1e-12
    np.testing.assert_allclose(a.final_Q, b.final_Q, rtol=0, atol=1e-12)
    np.testing.assert_allclose(a.final_P, b.final_P, rtol=0, atol=1e-11)
    np.testing.assert_allclose(a.mode_energy_after, b.mode_energy_after, rtol=1e-9, atol=1e-13)


@pytest.mark.slow  # 8-18 s of the default run (issue 45: the default run under 10 min)
def test_energy_balance_of_excited_collisions(modes):
    v = np.array([0.1, 0.1, 0.05])
    states = [_random_state(modes, 0.1, e, seed=k) for k, e in enumerate((0.2, 2.0, 5.0))]
    Q = np.array([q for q, _ in states])
    P = np.array([p for _, p in states])
    res = collide_batch(modes, v, 800, initial=(Q, P), energy_tol=1e-7)
    for r in res:
        before = 1.0 + r.mode_energy_before.sum()
        after = r.epsilon**2 + r.mode_energy_after.sum()
        # Energies are fractions of (m/2) v^2; the drift is relative to the total energy.
        assert abs(after - before) <= 2 * r.energy_drift * before + 1e-12
        assert r.energy_drift < 1e-7


def test_time_reversal_recovers_the_initial_state(modes):
    """Reverse every momentum of the final state, run back: speed v and the initial state."""
    v, alpha = 0.1, 600.0
    Q0, P0 = _random_state(modes, v, 1.0, seed=7)
    fwd = collide(modes, v, alpha, initial=(Q0, P0), energy_tol=1e-10)
    u = fwd.epsilon * v
    # The final state sits at final_x0; the reversed run's state is defined where its centre
    # passes the start position for speed u (free flight between the two).
    tau = (start_position(modes, u, alpha) - fwd.final_x0) / u
    Qr, Pr = free_modes(modes.omega, modes.mass, fwd.final_Q, -fwd.final_P, tau)
    back = collide(modes, u, alpha, initial=(Qr, Pr), energy_tol=1e-10)
    assert back.epsilon * u == pytest.approx(v, rel=1e-7)  # eps_reversed = 1 / eps
    tau_b = (start_position(modes, v, alpha) - back.final_x0) / v
    Qb, Pb = free_modes(modes.omega, modes.mass, back.final_Q, -back.final_P, tau_b)
    scale_Q = np.abs(Q0).max()
    scale_P = np.abs(P0).max()
    np.testing.assert_allclose(Qb, Q0, rtol=0, atol=1e-6 * scale_Q)
    np.testing.assert_allclose(Pb, P0, rtol=0, atol=1e-6 * scale_P)


def test_bad_initial_state_is_refused_in_one_line(modes):
    with pytest.raises(InputError, match="shape"):
        collide(modes, 0.1, 500, initial=(np.zeros(N + 1), np.zeros(N + 1)))
    with pytest.raises(InputError, match="non-finite"):
        collide(modes, 0.1, 500, initial=(np.full(N, np.nan), np.zeros(N)))
    with pytest.raises(InputError, match="pair"):
        collide(modes, 0.1, 500, initial=np.zeros(N))


@pytest.mark.slow  # 9 s of the default run (stop 79: the default run under 10 min)
def test_a_vibrating_disk_that_leaves_slowly_is_not_cut_off():
    """A thermal member of this batch leaves about 18 times slower than it came (epsilon 0.054):
    the time bound of a disk at rest (201 R/c) stopped it before the vibrating disk's bound."""
    from restitution.vibrating.fluctuation import flux_speeds
    from restitution.vibrating.vibration import thermal_state

    ms = get_modes(0.33, count=10)
    T = 0.5 * ms.mass * 0.1**2
    rng = np.random.default_rng(1)
    v = flux_speeds(ms, T, (0.05, 0.2), 64, rng)
    Q, P = thermal_state(ms, T, rng, size=64)
    res = collide_batch(ms, v, 200, initial=(Q, P))
    slow = min(res, key=lambda r: r.epsilon)
    assert slow.epsilon < 0.1 and slow.t_end > 201
    before = 1.0 + slow.mode_energy_before.sum()
    after = slow.epsilon**2 + slow.mode_energy_after.sum()
    assert abs(after - before) <= 2 * slow.energy_drift * before + 1e-12
