"""The measured order of convergence in N: power laws with a free exponent, local exponents."""

from __future__ import annotations

import numpy as np
import pytest

from restitution.errors import InputError
from restitution.limits.order import local_exponents, power_law_fit

N = np.array([100, 150, 200, 300, 400, 600, 800, 1200, 1600, 2400, 3200])


@pytest.mark.parametrize("p", [0.5, 0.8, 1.0])
def test_a_pure_power_law_is_recovered(p):
    loss = 0.0123 + 0.04 * N**-p
    fit = power_law_fit(N, loss)
    assert fit.exponent == pytest.approx(p, rel=1e-6)
    assert fit.limit == pytest.approx(0.0123, rel=1e-8)
    assert fit.amplitude == pytest.approx(0.04, rel=1e-5)
    mid, local = local_exponents(N, loss)
    # Every doubling triple of the two ladders (100, 150 * 2^k), exact for a pure power law.
    np.testing.assert_array_equal(mid, [200, 300, 400, 600, 800, 1200, 1600])
    np.testing.assert_allclose(local, p, rtol=1e-10)


def test_noise_shows_in_the_exponent_error():
    rng = np.random.default_rng(3)
    loss = 0.01 + 0.05 * N**-0.5 + rng.normal(0, 2e-6, N.size)
    fit = power_law_fit(N, loss)
    assert abs(fit.exponent - 0.5) < 3 * fit.exponent_err
    assert 0 < fit.exponent_err < 0.2


def test_a_sign_change_has_no_local_exponent():
    loss = np.array([1.0, 0.92, 0.9, 0.91, 0.95, 0.94, 0.93, 0.929, 0.928, 0.9275, 0.927])
    mid, local = local_exponents(N, loss)
    assert mid[0] == 200 and np.isnan(local[0])  # 100 -> 200 falls, 200 -> 400 rises
    assert mid[-1] == 1600 and local[-1] == pytest.approx(1.0)  # 0.002 then 0.001


def test_bad_input_is_refused():
    with pytest.raises(InputError, match="at least 4"):
        power_law_fit([1, 2, 3], [1.0, 0.5, 0.3])
    with pytest.raises(InputError, match="increasing"):
        local_exponents([2, 1, 4], [1.0, 0.5, 0.3])
