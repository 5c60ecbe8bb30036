"""Figures of vibrating disks on coarse grids: each checks one number and that it draws."""

import numpy as np
import pytest

from restitution import get_modes
from restitution.dynamics.collision import collide
from restitution.reproduction.figures import vibrating


def test_distribution_figure(tmp_path):
    ens = vibrating.compute_distributions(count=8, ratios=(2.0,), samples=8, energy_tol=1e-5)
    assert ens[0].v_over_v_thermal == pytest.approx(2.0)
    assert np.all(ens[0].balance_error <= 2 * ens[0].energy_drift + 1e-12)
    vibrating.plot_distributions(ens, tmp_path / "d.png")
    assert (tmp_path / "d.png").stat().st_size > 10_000


def test_phase_figure(tmp_path):
    data = vibrating.compute_phase(count=10, fractions=(1e-6,), n_phase=6, energy_tol=1e-9)
    # At vanishing amplitude the fitted mean is the disk at rest's epsilon.
    assert data.fits[0].mean == pytest.approx(data.epsilon_rest, abs=1e-5)
    vibrating.plot_phase(data, tmp_path / "p.png")
    assert (tmp_path / "p.png").stat().st_size > 10_000


def test_bounce_figure(tmp_path):
    data = vibrating.compute_bounce(count=8, collisions=3, gravity=1e-5)
    alpha = data.sequence.alpha
    # The memoryless speeds judge the step by epsilon, as the chain does (STEP_JUDGE).
    rest = collide(get_modes(0.33, count=8), data.memoryless[1], alpha, step_judge="epsilon")
    assert data.memoryless[2] == pytest.approx(rest.epsilon * data.memoryless[1], rel=1e-14)
    vibrating.plot_bounce(data, tmp_path / "b.png")
    assert (tmp_path / "b.png").stat().st_size > 10_000
