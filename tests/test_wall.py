"""The exponential wall on a disk's edge: quadrature, forces as derivatives, truncation to the
active nodes (:class:`restitution.dynamics.contact.exponential.ExponentialWall`)."""

import numpy as np
from numpy.testing import assert_allclose
from scipy.integrate import quad as adaptive

from restitution import get_modes
from restitution.bodies.disk.surface import dense_edge_matrix
from restitution.dynamics.contact import EXPONENTIAL_WALL

wall_terms = EXPONENTIAL_WALL.contact_terms


def _state(modes, seed=3):
    # A compressed, deformed disk: centre 0.05 R past touching, modal amplitudes ~1e-3.
    rng = np.random.default_rng(seed)
    Q = rng.normal(scale=1e-3, size=(1, len(modes))) / (1 + modes.omega)
    return np.array([-0.95]), Q


def test_potential_matches_adaptive_quadrature():
    modes = get_modes(0.33, count=60)
    x0, Q = _state(modes)
    alpha = np.array([300.0])
    V, F, f = wall_terms(modes.surface_quadrature(800), alpha, x0, Q)

    def x(phi):
        g = modes.C * np.cos(modes.n * phi) * np.cos(phi) - modes.S * np.sin(
            modes.n * phi
        ) * np.sin(phi)
        return x0[0] + np.cos(phi) + g @ Q[0]

    ref_V = adaptive(
        lambda p: np.exp(alpha[0] * x(p)) / alpha[0],
        -np.pi / 2,
        np.pi / 2,
        limit=400,
        epsabs=0,
        epsrel=1e-12,
    )[0]
    ref_F = adaptive(
        lambda p: np.exp(alpha[0] * x(p)), -np.pi / 2, np.pi / 2, limit=400, epsabs=0, epsrel=1e-12
    )[0]
    assert_allclose(V[0], ref_V, rtol=1e-10)
    assert_allclose(F[0], ref_F, rtol=1e-10)


def test_forces_are_derivatives_of_the_potential():
    modes = get_modes(0.33, count=40)
    x0, Q = _state(modes)
    quad = modes.surface_quadrature(600)
    alpha = np.array([200.0])
    _, F, f = wall_terms(quad, alpha, x0, Q)
    h = 1e-7
    Vp = wall_terms(quad, alpha, x0 + h, Q)[0]
    Vm = wall_terms(quad, alpha, x0 - h, Q)[0]
    assert_allclose(F, (Vp - Vm) / (2 * h), rtol=1e-6)
    for k in (0, 5, 17, 39):
        dQ = np.zeros_like(Q)
        dQ[0, k] = h
        num = wall_terms(quad, alpha, x0, Q + dQ)[0] - wall_terms(quad, alpha, x0, Q - dQ)[0]
        assert_allclose(f[0, k], num[0] / (2 * h), rtol=1e-5, atol=1e-12)


def test_active_node_truncation_is_exact_to_roundoff():
    modes = get_modes(0.33, count=200)
    quad = modes.surface_quadrature(1200)
    for x0c, alpha in ((-0.99, 2000.0), (-0.9, 500.0), (-0.6, 100.0), (-1.2, 500.0)):
        x0, Q = _state(modes)
        x0 = np.array([x0c])
        V, F, f = wall_terms(quad, np.array([alpha]), x0, Q)
        # Full sum over all nodes, written out independently.
        # Full dense sum over all nodes and modes (eq. 40 written out), no order grouping.
        G = dense_edge_matrix(modes, quad.nodes)
        x = x0[:, None] + quad.height + Q @ G.T
        e = np.exp(alpha * x) * quad.weight
        # Skipped nodes contribute at most exp(-40) * pi = 1.3e-17 in force units (E).
        assert_allclose(F, e.sum(axis=1), rtol=1e-12, atol=1.3e-17)
        gmax = np.abs(G).max()
        assert_allclose(f, e @ G, rtol=1e-10, atol=1e-14 * max(F[0], 1e-3) * gmax)
