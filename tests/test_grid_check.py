"""A grid no collision can resolve is refused before any worker starts (restitution.limits.
grid_check; issue 64: `epsilon --nu 0.33 --v 1e-9` ran ten failing collisions and 5 GB)."""

from __future__ import annotations

import os
from dataclasses import replace

import numpy as np
import pytest
from _cli_checks import one_line_error

from restitution.bodies.cache import get_modes
from restitution.dynamics.collision import CollisionSettings
from restitution.dynamics.steps import estimate_work
from restitution.errors import InputError
from restitution.limits.grid_check import check_grid
from restitution.limits.sweep import defaults_for, grid


def test_a_speed_below_the_collisions_is_refused_in_one_line(cli, tmp_path):
    code, out, err = cli("epsilon", "--nu", "0.33", "--v", "1e-9", "--store",
                         str(tmp_path / "s.sqlite"))  # fmt: skip
    line = one_line_error(code, err, "--v 1e-09", "restitution quasistatic", "--nu 0.33")
    assert "GiB" in line  # the estimate's numbers, not only a verdict


def test_the_check_is_the_collisions_own_refusal(tmp_path):
    """check_grid raises exactly where a collision of the grid's smallest N would refuse
    itself (restitution.dynamics.steps.check_work), at the same estimate."""
    store = tmp_path / "s.sqlite"
    settings = replace(defaults_for("disk"), velocities=(1e-9,))
    specs = grid([0.33], settings)
    with pytest.raises(InputError, match=r"edge quadrature nodes"):
        check_grid(specs, store)
    check_grid(grid([0.33], replace(settings, velocities=(0.1,))), store)  # the paper's speeds


def test_the_fastest_modes_step_grows_as_weyl_says():
    """The check scales the body-limited step count from the smallest N to the largest as
    N^(1/d); the disk's modes (d = 2) at N = 300 and 940 bear it out within 2 %."""
    omega = [float(get_modes(0.33, count=n).omega.max()) for n in (300, 940)]
    assert omega[1] / omega[0] == pytest.approx((940 / 300) ** 0.5, rel=0.02)
    settings = CollisionSettings(energy_tol=1e-5)
    v, alpha = np.array([0.3]), np.array([40.0])
    steps = [estimate_work(get_modes(0.33, count=n), v, alpha, settings).steps for n in (300, 940)]
    assert steps[1] / steps[0] == pytest.approx((940 / 300) ** 0.5, rel=0.02)


def test_the_grid_states_its_work_before_it_starts(tmp_path):
    """The points the store lacks, and their steps' time from the collisions' own estimate
    (restitution.budget.collision_seconds of restitution.dynamics.steps.estimate_work), summed
    over the grid's mode counts; a stored grid has nothing left."""
    from restitution.budget import collision_seconds

    settings = replace(defaults_for("disk"), velocities=(0.1,), n_modes=(40, 80))
    specs = grid([0.33], settings)
    work = check_grid(specs, tmp_path / "s.sqlite")
    assert work.collisions == len(specs) == 6
    by_hand = 0.0
    for s in specs:
        est = estimate_work(get_modes(0.33, count=s.n_modes), np.array([s.v]),
                            np.array([s.alpha]), CollisionSettings(**dict(s.options)))  # fmt: skip
        by_hand += collision_seconds(est.steps, s.n_modes)
    # The check scales the step of N = 40 to N = 80 by Weyl's law where the fastest mode sets
    # it, so the two sums agree to the 2 % of that law (test_the_fastest_modes_step_...).
    assert work.seconds == pytest.approx(by_hand, rel=0.02)
    assert "6 collisions to compute" in work.words()


def test_a_ctrl_c_while_the_grid_is_checked_is_raised_after_it(tmp_path, monkeypatch):
    """The check builds modes and compiles numba's kernels in this process; a KeyboardInterrupt
    raised inside llvmlite's ctypes callback was printed as "Exception ignored" and lost, and
    the sweep ran to its end (test_hostile's Ctrl-C at 0 s, make test-slow of this stop). A
    Ctrl-C during the check is now raised when the check ends, and Ctrl-C works again after."""
    import signal

    import restitution.limits.grid_check as gc

    def interrupted(*args):
        os.kill(os.getpid(), signal.SIGINT)  # delivered while the check runs
        return gc.GridWork(0, 0.0)

    monkeypatch.setattr(gc, "_check_grid", interrupted)
    # Python's own Ctrl-C, as a command has it (a pytest-xdist worker ignores SIGINT).
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            check_grid([], tmp_path / "s.sqlite")
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    finally:
        signal.signal(signal.SIGINT, previous)
