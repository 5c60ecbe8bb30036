"""Viscoelastic bodies (issue 29): the exact damped free flow, the damped collision on both
paths against DOP853, the energy balance, and zero viscosity as today's elastic body."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from _sampling import representatives

from restitution import collide, collide_batch, get_modes
from restitution.bodies.viscoelastic import Viscoelastic, mode_damping
from restitution.dynamics.damping import damped_flow
from restitution.dynamics.reference import collide_dop853
from restitution.errors import InputError


def _expm_reference(omega: float, gamma: float, m: float, h: float) -> np.ndarray:
    """The flow matrix of ``dQ/dt = P/m, dP/dt = -m omega^2 Q - gamma P`` by mpmath's
    matrix exponential at 40 digits: the closed form's independent judge."""
    mpmath.mp.dps = 40
    A = mpmath.matrix([[0, mpmath.mpf(1) / m], [-m * mpmath.mpf(omega) ** 2, -mpmath.mpf(gamma)]])
    E = mpmath.expm(A * h)
    return np.array([[float(E[i, j]) for j in range(2)] for i in range(2)])


@pytest.mark.parametrize(
    "omega, gamma",
    [
        (2.0, 0.0),  # undamped
        (2.0, 0.5),  # underdamped
        (2.0, 4.0),  # critical
        (2.0, 4.000001),  # just overdamped: the expm1 branch
        (2.0, 3.99999),  # just underdamped
        (2.0, 10.0),  # overdamped
        (50.0, 1e5),  # strongly overdamped: the two-rate branch
    ],
)
@pytest.mark.parametrize("h", [1e-3, 0.1, 1.0])
def test_damped_flow_is_the_oscillators_exact_flow(omega, gamma, h):
    m = 3.0
    a, b, c, d = (x[0] for x in damped_flow([omega], [gamma], m, h))
    exact = _expm_reference(omega, gamma, m, h)
    got = np.array([[a, b], [-c, d]])
    scale = np.where(exact != 0.0, np.abs(exact), 1.0)
    assert np.max(np.abs(got - exact) / scale) < 2e-15


def test_zero_viscosity_is_the_elastic_body_bit_for_bit():
    body = get_modes(0.33, count=60)
    assert mode_damping(Viscoelastic(body, 0.0)) is None
    for integrator in ("split4", "split"):
        a = collide_batch(body, [0.05, 0.2], [300, 800], integrator=integrator)
        b = collide_batch(Viscoelastic(body, 0.0), [0.05, 0.2], [300, 800], integrator=integrator)
        for x, y in zip(a, b, strict=True):
            assert x.epsilon == y.epsilon
            assert np.array_equal(x.mode_energy_after, y.mode_energy_after)
            assert y.energy_dissipated == 0.0


@pytest.fixture(scope="module")
def small():
    return get_modes(0.33, count=12)


@pytest.mark.parametrize("tau", representatives([0.01, 0.1], {0.1}))  # 0.01 (12 s): -m slow
def test_damped_collision_paths_agree_with_dop853(small, tau):
    body = Viscoelastic(small, tau)
    # The two paths do the same arithmetic: at one fixed step they agree to round-off.
    fixed = dict(integrator="split", dt=2e-3)
    kernel = collide(body, 0.1, 100, backend="compiled", **fixed)
    numpy = collide(body, 0.1, 100, backend="numpy", **fixed)
    assert abs(kernel.epsilon - numpy.epsilon) < 1e-12
    assert abs(kernel.energy_dissipated - numpy.energy_dissipated) < 1e-12
    kernel = collide(body, 0.1, 100, integrator="split", energy_tol=1e-10)
    # DOP853 integrates the same equations unsplit, to the time the splitting stopped.
    ref = collide_dop853(body, 0.1, 100, t_end=kernel.t_end, rtol=1e-12, atol=1e-14)
    assert abs(kernel.epsilon - ref["epsilon"]) < 1e-8
    assert abs(kernel.energy_dissipated - ref["energy_dissipated"]) < 1e-8
    assert np.max(np.abs(kernel.mode_energy_after - ref["energy_after"])) < 1e-8
    assert kernel.energy_dissipated > 1e-3
    # Epsilon judged the step (collision module docstring), to the tolerance asked for.
    assert kernel.step_error is not None and 2 * kernel.step_error <= 1e-10
    assert kernel.energy_tol is None  # the drift is reported, not held to energy_tol


def test_step_error_of_a_damped_collision_is_honest(small):
    """The Richardson estimate bounds the distance to a run at a far smaller fixed step."""
    body = Viscoelastic(small, 0.1)
    coarse = collide(body, 0.1, 100, integrator="split", energy_tol=1e-5)
    fine = collide(body, 0.1, 100, integrator="split", dt=coarse.dt / 16)
    assert coarse.step_error > 0.0
    assert abs(coarse.epsilon - fine.epsilon) <= 2.0 * coarse.step_error
    # The dissipated energy of the balance converges with epsilon; the fine step's drift (the
    # energy the kicks gave to damped modes) is 256 times smaller than the coarse one's.
    assert abs(coarse.energy_dissipated - fine.energy_dissipated) < 1e-5
    assert fine.energy_drift < coarse.energy_drift / 100


@pytest.mark.slow  # 8-18 s of the default run (issue 45: the default run under 10 min)
def test_more_viscous_material_loses_more(small):
    kw = dict(integrator="split", energy_tol=1e-9)
    loss = [
        collide(Viscoelastic(small, tau), 0.1, 100, **kw).energy_dissipated
        for tau in (1e-3, 1e-2, 1e-1)
    ]
    assert 0.0 < loss[0] < loss[1] < loss[2]


@pytest.mark.slow  # 8 s of the default run (stop 76: the default run under 10 min)
def test_damped_collision_same_bits_on_one_thread_or_two():
    # At least SPLIT_MIN_MODES modes: alone it runs on two threads, in a batch on one.
    body = Viscoelastic(get_modes(0.33, count=2200), 0.05)
    kw = dict(integrator="split")
    alone = collide(body, 0.1, 400, **kw)
    batch = collide_batch(body, [0.1, 0.1], [400, 400], **kw)
    assert alone.epsilon == batch[0].epsilon == batch[1].epsilon
    assert alone.energy_dissipated == batch[0].energy_dissipated


def test_damped_body_refusals(small):
    body = Viscoelastic(small, 0.01)
    with pytest.raises(InputError, match="integrator='split'"):
        collide(body, 0.1, 100)  # the default split4
    with pytest.raises(InputError, match="integrator='split'"):
        collide(body, 0.1, 100, integrator="rk4")
    Q = np.zeros(len(small))
    with pytest.raises(InputError, match="starts at rest"):
        collide(body, 0.1, 100, integrator="split", initial=(Q, Q))
    for bad in (-1.0, float("nan"), "0.1", None, True):
        with pytest.raises(InputError, match="relaxation_time"):
            Viscoelastic(small, bad)
    with pytest.raises(InputError, match="settings must be a CollisionSettings"):
        collide(small, 0.1, 100, settings="fast")
