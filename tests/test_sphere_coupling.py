"""Dundurs' coupling of the sphere's contact: its order-1 flexibilities against the half-space,
and the one-state quasistatic impact with it (issue 63; docs/oblique.md, "Dundurs'
coupling")."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import j0, j1, struve

from restitution.bodies.cache import get_modes
from restitution.bodies.sphere import contact_compliance as cc
from restitution.bodies.sphere.cap import cap_modes
from restitution.quasistatic.sphere_coupling import (
    TiltedOneStateFriction,
    coupled_one_state_impact,
)
from restitution.quasistatic.sphere_one_state import one_state_impact
from restitution.quasistatic.sphere_partial_slip import AnnularContact

V = 0.0001933  # the steel ball at 1 m/s, in c
MU = 0.3


def _half_space(edges: np.ndarray, nu: float) -> tuple[np.ndarray, np.ndarray]:
    """The half-space's tilt and cross flexibilities of the annuli, by Hankel transforms
    (``E = 1``). A pressure ``f(r) cos(phi)`` has the transform ``-2 pi i cos(phi_k) F1(k)``,
    ``F1 = int f r J1(k r) dr``, Boussinesq's kernel ``2 / (E* k)`` for every azimuthal order,
    so ``tilt = (2 pi / E*) int F1_i F1_j dk``; Cerruti's normal displacement under an in-line
    point force ``Q`` is ``(1 + nu)(1 - 2 nu) Q x / (2 pi E r^2)`` (transform ``-2 pi i
    cos(phi_k) / k``), so ``cross = pi (1 + nu)(1 - 2 nu) int F1_i F0_j dk`` with ``F0 = int f r
    J0(k r) dr``. On an annulus ``int r J0 = [r J1 / k]`` and ``int r J1 = [pi r (J1 H0 - J0
    H1) / (2 k)]`` (Struve's ``H``); the ``k`` integral by Gauss-Legendre panels to ``4000 /
    a`` (doubling both moves it by 1e-6)."""
    kmax = 4000.0 / edges[-1]
    t, w = np.polynomial.legendre.leggauss(32)
    panels = np.linspace(0.0, kmax, 100_000 // 32 + 1)
    half = 0.5 * np.diff(panels)[:, None]
    k = (half * (t + 1.0) + panels[:-1, None]).ravel()
    wk = (half * w).ravel()

    def f0(r):
        return r * j1(k * r) / k

    def f1(r):
        z = k * r
        return 0.5 * math.pi * r / k * (j1(z) * struve(0, z) - j0(z) * struve(1, z))

    pairs = list(zip(edges[:-1], edges[1:], strict=True))
    a0 = np.array([f0(hi) - f0(lo) for lo, hi in pairs])
    a1 = np.array([f1(hi) - f1(lo) for lo, hi in pairs])
    tilt = 2.0 * math.pi * (1.0 - nu * nu) * (a1 * wk) @ a1.T
    return tilt, math.pi * (1.0 + nu) * (1.0 - 2.0 * nu) * (a1 * wk) @ a0.T


@pytest.mark.parametrize("nu", [0.3, 0.45])
def test_tilt_and_cross_tend_to_the_half_space(nu):
    """The sphere's order-1 flexibilities (its series of every order) on ten annuli out to
    ``a`` against the half-space's Hankel integrals: symmetric positive definite tilt, the
    cross's sign, and the relative (Frobenius) gaps halving with ``a`` (measured at ``a =
    0.04, 0.02, 0.01``: tilt 1.86e-3, 9.6e-4, 4.9e-4 at ``nu = 0.3`` and 3.3e-4, 1.1e-4,
    5.5e-5 at 0.45; cross 4.7e-2, 2.1e-2, 1.0e-2 and 0.21, 0.092, 0.042: the half-space's
    cross falls with ``1 - 2 nu``, the sphere's curvature's part of it does not)."""
    gaps = []
    for a in (0.04, 0.02, 0.01):
        edges = np.linspace(0.0, a, 11)
        tilt, cross = cc.annulus_tilt_flexibility(edges, nu)
        ht, hx = _half_space(edges, nu)
        assert np.array_equal(tilt, tilt.T) and np.linalg.eigvalsh(tilt).min() > 0.0
        assert np.all(np.diag(cross) > 0.0) and np.all(np.diag(hx) > 0.0)
        gaps.append(
            (np.linalg.norm(tilt - ht) / np.linalg.norm(ht),
             np.linalg.norm(cross - hx) / np.linalg.norm(hx))
        )  # fmt: skip
    gaps = np.array(gaps)
    assert gaps[-1, 0] < 1e-3 and gaps[-1, 1] < {0.3: 0.02, 0.45: 0.08}[nu], gaps
    assert np.all(gaps[:-1] / gaps[1:] > 1.7), gaps


def test_cross_is_betti_symmetric():
    """The displacement in line under the tilting pressures, summed the other way round
    (tangential loads against the tilting ones' field), is the cross's transpose: the
    coefficients of the two loads and the orders' flexibility agree."""
    edges = np.linspace(0.0, 0.06, 21)
    _, cross = cc.annulus_tilt_flexibility(edges, 0.3)
    theta, loads, l_top = cc._annulus_loads(edges, None, None)
    line = cc._coefficients(theta, loads, l_top, "tangential")
    back = cc._bilinear(line, 0.3, cc._coefficients(theta, loads, l_top, "tilt"))
    assert np.max(np.abs(back.T - cross)) < 1e-12 * np.max(np.abs(cross))


def test_kept_modes_hold_a_growing_share_of_the_coupling():
    """The modes of azimuthal order 1 carry part of the tilt and cross flexibilities, growing
    with the mode count and below the continuum's (measured, traces over 20 annuli to 0.06:
    tilt 0.3 % and 0.9 %, cross 6 % and 11 % at 20 and 40 modes): the share of Dundurs'
    coupling the modal route keeps without a residual for it."""
    edges = np.linspace(0.0, 0.06, 21)
    tilt, cross = cc.annulus_tilt_flexibility(edges, 0.3)
    shares = []
    for count in (20, 40):
        cap = cap_modes(get_modes(0.3, count=count, geometry="sphere"), azimuthal=1)
        kt, kx = cc.modal_annulus_tilt_flexibility(cap, edges)
        assert np.linalg.eigvalsh(tilt - kt).min() > 0.0
        shares.append((np.trace(kt) / np.trace(tilt), np.trace(kx) / np.trace(cross)))
    (t20, x20), (t40, x40) = shares
    assert 0.0 < t20 < t40 < 0.05 and 0.0 < x20 < x40 < 0.3, shares


def test_coupled_flexibility_is_symmetric_and_no_larger():
    """The Schur complement ``H_eff`` is symmetric and ``p . H_eff . p <= p . H_t . p`` for any
    contact (the flat wall's constraint stiffens it); with the cross at zero it is ``H_t``."""
    contact = AnnularContact.build(0.06, 0.3, annuli=20)
    tilt, cross = cc.annulus_tilt_flexibility(contact.edges, 0.3)
    law = TiltedOneStateFriction(contact.Ht, tilt, cross, contact.area)
    rng = np.random.default_rng(3)
    for reach in (5, 12, 20):
        P = np.r_[rng.uniform(0.1, 1.0, reach), np.zeros(20 - reach)]
        H = law.flexibility(P)
        assert np.allclose(H, H.T, rtol=0.0, atol=1e-12 * np.abs(H).max())
        p = P / P.sum()
        assert p @ H @ p < p @ contact.Ht @ p
    none = TiltedOneStateFriction(contact.Ht, tilt, 0.0 * cross, contact.area, 1e5)
    assert np.array_equal(none.flexibility(np.ones(20)), contact.Ht)


def test_coupling_leaves_gross_slip_and_falls_with_one_minus_two_nu():
    """In gross slip (``tan(theta) / mu = 6``) the force sits at Coulomb's bound and the
    coupling changes nothing. In partial slip (30 degrees) it lowers ``beta``; at ``nu = 0.45``
    (Dundurs' ``beta_D`` 0.091 against 0.286) by about a tenth as much as at 0.3 (``beta_D^2``:
    measured -0.0198 and -0.0021 at 40 annuli)."""
    kw = {"annuli": 20, "steps": 1000}
    slide = 6.0 * MU * V
    assert coupled_one_state_impact(V, slide, MU, 0.3, **kw).beta == pytest.approx(
        one_state_impact(V, slide, MU, 0.3, **kw).beta, abs=1e-12
    )
    vt = math.tan(math.radians(30.0)) * V
    shift = {}
    for nu in (0.3, 0.45):
        coupled = coupled_one_state_impact(V, vt, MU, nu, **kw)
        shift[nu] = coupled.beta - one_state_impact(V, vt, MU, nu, **kw).beta
        assert coupled.beta_change < 1e-3
    assert shift[0.3] < -0.01 and 0.0 < shift[0.45] / shift[0.3] < 0.2, shift
