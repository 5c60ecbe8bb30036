"""The compiled collision kernel against the NumPy reference path (same algorithm, two codes)."""

import pytest
from numpy.testing import assert_allclose, assert_array_equal

from restitution import get_modes
from restitution.dynamics.collision import CollisionSettings, collide, collide_batch
from restitution.errors import InputError

# (nu, N, v, alpha): soft and hard walls, slow and fast, both Poisson numbers of the paper.
CASES = [
    (0.33, 60, 0.1, 500.0),
    (0.33, 200, 0.02, 3000.0),
    (0.9, 120, 0.3, 300.0),
    (0.9, 300, 0.005, 12000.0),
]
FIELDS = ("contact_time", "max_compression", "max_force", "n_steps", "dt")
ARRAYS = ("mode_energy_after", "mode_energy_mean", "mode_energy_closest")


def _assert_same(a, b):
    # Only the summation order of reductions differs between the two codes.
    assert abs(a.epsilon - b.epsilon) < 1e-12, (a.epsilon, b.epsilon)
    for name in ARRAYS:
        assert_allclose(getattr(a, name), getattr(b, name), rtol=0, atol=1e-12, err_msg=name)
    for name in FIELDS:
        assert_allclose(getattr(a, name), getattr(b, name), rtol=1e-10, err_msg=name)
    assert abs(a.energy_drift - b.energy_drift) < 1e-10


@pytest.mark.parametrize("integrator", ["split4", "split"])
@pytest.mark.parametrize(("nu", "count", "v", "alpha"), CASES)
def test_single_collision_matches_numpy_path(nu, count, v, alpha, integrator):
    modes = get_modes(nu, count=count)
    tol = 1e-6 if integrator == "split4" else 1e-5
    kw = dict(integrator=integrator, energy_tol=tol)
    _assert_same(
        collide(modes, v, alpha, backend="compiled", **kw),
        collide(modes, v, alpha, backend="numpy", **kw),
    )


@pytest.mark.slow  # 7 s of the default run (stop 76: the default run under 10 min)
def test_batch_matches_numpy_path_member_by_member():
    modes = get_modes(0.33, count=150)
    v = [0.01, 0.05, 0.1, 0.2]
    alpha = [4000.0, 900.0, 500.0, 250.0]
    fast = collide_batch(modes, v, alpha, backend="compiled")
    ref = collide_batch(modes, v, alpha, backend="numpy")
    for a, b in zip(fast, ref, strict=True):
        _assert_same(a, b)


@pytest.mark.slow  # 7 s of the default run (stop 79: the default run under 10 min)
def test_member_does_not_depend_on_its_batch():
    # Each member has its own step, so a stored point is the same however a sweep batched it.
    modes = get_modes(0.33, count=100)
    alone = collide(modes, 0.1, 500.0)
    for backend in ("compiled", "numpy"):
        batch = collide_batch(modes, [0.02, 0.1, 0.3], [2000.0, 500.0, 200.0], backend=backend)
        assert batch[1].epsilon == pytest.approx(alone.epsilon, abs=1e-12)
        assert batch[1].dt == alone.dt
    compiled = collide_batch(modes, [0.02, 0.1, 0.3], [2000.0, 500.0, 200.0], backend="compiled")
    assert compiled[1].epsilon == alone.epsilon  # same code path: bit for bit
    assert_array_equal(compiled[1].mode_energy_after, alone.mode_energy_after)


def test_fixed_step_and_refinement_agree():
    modes = get_modes(0.33, count=80)
    # A fixed step too coarse for the tolerance is reported, not refined, by both codes.
    kw = dict(dt=0.02, energy_tol=1e-9)
    a = collide(modes, 0.1, 500.0, backend="compiled", **kw)
    b = collide(modes, 0.1, 500.0, backend="numpy", **kw)
    assert a.dt == b.dt == 0.02
    _assert_same(a, b)


def test_backend_choice():
    modes = get_modes(0.33, count=20)
    # rk4 and recorded histories run on the NumPy path under "auto" ...
    r = collide(modes, 0.1, 500.0, integrator="rk4")
    assert r.integrator == "rk4"
    h = collide(modes, 0.1, 500.0, record=True)
    assert h.history is not None and h.history.t.size > 10
    # ... and are refused, with the way out, when the compiled backend is forced.
    with pytest.raises(InputError, match="backend='numpy'"):
        collide(modes, 0.1, 500.0, integrator="rk4", backend="compiled")
    with pytest.raises(InputError, match="unknown backend"):
        CollisionSettings(backend="gpu")


def _split_runs(monkeypatch, modes, v, alpha, **kw):
    """The same collision on one thread and split over two (kernel.SPLIT_MIN_MODES lowered);
    returns ({threads: result}, {threads: parts run})."""
    import restitution.dynamics.kernel as kernel

    monkeypatch.setattr(kernel, "SPLIT_MIN_MODES", 100)
    one = kernel._one
    results, parts = {}, {}
    for threads in (1, 2):
        seen = []

        def spy(b, part, *args, seen=seen):
            seen.append(part)
            return one(b, part, *args)

        monkeypatch.setattr(kernel, "_one", spy)
        monkeypatch.setattr(kernel, "_threads", lambda t=threads: t)
        results[threads] = collide(modes, v, alpha, backend="compiled", **kw)
        parts[threads] = sorted(seen)
    return results, parts


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_two_threads_give_one_threads_collision_bit_for_bit(monkeypatch):
    # One large collision runs on two threads, one group of orders each, meeting at every
    # wall evaluation; the grouping depends on the mode set only, so the bits are the same.
    modes = get_modes(0.33, count=300)
    results, parts = _split_runs(monkeypatch, modes, 0.02, 3000.0)
    assert parts == {1: [-1], 2: [0, 1]}  # really split
    one, two = results[1], results[2]
    assert one.epsilon == two.epsilon
    for name in ARRAYS:
        assert_array_equal(getattr(one, name), getattr(two, name), err_msg=name)
    for name in FIELDS:
        assert getattr(one, name) == getattr(two, name), name
    _assert_same(two, collide(modes, 0.02, 3000.0, backend="numpy"))


def test_two_threads_stop_together_on_a_timeout(monkeypatch):
    # Every decision (here: out of steps) is taken by both threads from the same sums, so
    # neither is left waiting for the other, and both modes stop at the same step.
    import restitution.dynamics.kernel as kernel

    monkeypatch.setattr(kernel, "SPLIT_MIN_MODES", 100)
    calls = []
    run = kernel.run_batch
    monkeypatch.setattr(kernel, "run_batch", lambda *a: calls.append(a) or run(*a))
    collide(get_modes(0.33, count=300), 0.02, 3000.0, backend="compiled")
    args = list(calls[-1])
    args[9] = 50  # max_steps
    got = {}
    for threads in (1, 2):
        monkeypatch.setattr(kernel, "_threads", lambda t=threads: t)
        got[threads] = run(*args)
    for threads in (1, 2):
        assert got[threads]["status"][0] == kernel.STATUS_TIMEOUT
        assert got[threads]["steps"][0] == 50
    assert_array_equal(got[1]["final_Q"], got[2]["final_Q"])


@pytest.mark.parametrize("count", [300, 2200])  # one thread per member; two threads share one
def test_raised_stop_flag_ends_every_member_at_its_next_check(count):
    """Ctrl-C raises the kernel's stop flag (run_batch's _in_threads); each member, and both
    threads of a shared member together, then returns within CHECK_EVERY steps."""
    import numpy as np

    from restitution.dynamics.compiled_path import KERNEL_WEIGHTS
    from restitution.dynamics.kernel import CHECK_EVERY, STATUS_INTERRUPTED, run_batch
    from restitution.dynamics.settings import CONTACT_TOL, STOP_LOG
    from restitution.dynamics.start import start_of

    body = get_modes(0.33, count=count)
    v, alpha = np.array([0.1, 0.2][: 1 if count > 2000 else 2]), np.array([300.0, 300.0])
    alpha = alpha[: v.size]
    quad = body.surface_quadrature(body.contact_nodes(300.0))
    begin = start_of(body, v, alpha, quad, None)
    got = run_batch(
        body.omega, body.mass, quad, v, alpha, begin.x0, np.full(v.size, 1e-3), begin.t_max,
        KERNEL_WEIGHTS["split4"], 10**7, None, STOP_LOG, CONTACT_TOL,
        stop=np.ones(1, dtype=np.int64),
    )  # fmt: skip
    assert list(got["status"]) == [STATUS_INTERRUPTED] * v.size
    assert list(got["steps"]) == [CHECK_EVERY] * v.size
