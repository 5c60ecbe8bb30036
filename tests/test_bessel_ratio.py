"""Scale-free Bessel pairs against scipy (where it does not underflow) and mpmath (everywhere)."""

import mpmath
import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.special import jv

from restitution.bodies.disk.bessel_ratio import scaled_pairs, scaled_pairs_grid


def _scipy_pairs(n, x):
    a, b = jv(n - 1, x), jv(n, x)
    s = np.hypot(a, b)
    return a / s, b / s, np.log(s)


def test_points_match_scipy_where_it_is_representable():
    rng = np.random.default_rng(7)
    n = rng.integers(1, 400, 5000)
    x = rng.uniform(0.05, 500.0, 5000)
    jm, jn, log_s = scaled_pairs(n, x)
    ok = np.hypot(jv(n - 1, x), jv(n, x)) > 1e-250
    assert ok.mean() > 0.8
    rm, rn, rlog = _scipy_pairs(n[ok], x[ok])
    # scipy's jv itself is off by up to ~3e-13 at orders ~400 (checked against mpmath below).
    assert_allclose(jm[ok], rm, rtol=0, atol=2e-12)
    assert_allclose(jn[ok], rn, rtol=0, atol=2e-12)
    assert_allclose(log_s[ok], rlog, rtol=0, atol=1e-8 * np.abs(rlog).max())


@pytest.mark.parametrize(
    ("n", "x"),
    [(395, 317.7), (1500, 300.0), (900, 190.0), (3, 2.404825557695773), (1, 1e-3), (700, 1400.0)],
)
def test_points_match_mpmath_including_underflow(n, x):
    # (1500, 300) and (900, 190): J_n is about 1e-590 and 1e-400, far below double precision.
    mpmath.mp.dps = 40
    a, b = mpmath.besselj(n - 1, x), mpmath.besselj(n, x)
    s = mpmath.sqrt(a * a + b * b)
    jm, jn, log_s = scaled_pairs([n], [x])
    assert_allclose([jm[0], jn[0]], [float(a / s), float(b / s)], rtol=0, atol=1e-13)
    assert log_s[0] == pytest.approx(float(mpmath.log(s)), rel=1e-12)


def test_grid_equals_points():
    x = np.linspace(0.3, 250.0, 400)
    gm, gn = scaled_pairs_grid(5, 260, x)
    n = np.arange(5, 261)[:, None]
    pm, pn, _ = scaled_pairs(
        np.broadcast_to(n, gm.shape).ravel(), np.broadcast_to(x, gm.shape).ravel()
    )
    assert_allclose(gm.ravel(), pm, rtol=0, atol=1e-14)
    assert_allclose(gn.ravel(), pn, rtol=0, atol=1e-14)
    # A unit vector, by construction.
    assert_allclose(np.hypot(gm, gn), 1.0, rtol=1e-15)


def test_refuses_orders_below_one():
    with pytest.raises(ValueError, match="n >= 1"):
        scaled_pairs([0], [1.0])
