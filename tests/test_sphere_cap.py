"""The sphere's modes for oblique impacts (restitution.bodies.sphere.toroidal, harmonics, cap,
cap_nodes): the toroidal frequency equation against an energy route of its own (the Rayleigh
quotient, which holds only for a free surface) and Lamb's values, the static limit of the
toroidal modal sums, normalisation and orthogonality of every family and azimuthal order by
quadrature over the ball (with the rigid translation and rotation), the surface displacement
against the interior fields, and the wall nodes' ring sums against the head-on quadrature.
Units: E = rho = R = 1 (three-dimensional constants), omega in c/R. Measured values are in
docs/oblique.md ("The sphere")."""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import roots_legendre, spherical_jn

from restitution.bodies.sphere import cap as cap_module
from restitution.bodies.sphere import cap_nodes as nodes_module
from restitution.bodies.sphere import harmonics, toroidal
from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.bodies.sphere.surface import sphere_quadrature
from restitution.bodies.sphere.toroidal import toroidal_amplitude, toroidal_modes
from restitution.dynamics.oblique import RimBody
from restitution.errors import InputError

NU = 0.3


@pytest.fixture(scope="module")
def modes20():
    return compute_sphere_modes(NU, count=20)


@pytest.fixture(scope="module")
def cap20(modes20):
    return cap_modes(modes20, azimuthal=2)


def test_doctests():
    for module in (toroidal, harmonics, cap_module, nodes_module):
        assert doctest.testmod(module).failed == 0


# -- toroidal frequencies ------------------------------------------------------------------


def _rayleigh_quotient(l: int, k: float, nu: float) -> float:
    """``omega^2`` of ``W = j_l(k r)`` by the toroidal energies (Dahlen and Tromp, Theoretical
    Global Seismology, 1998, sec. 8.6): ``int mu [(r W' - W)^2 + (L - 2) W^2] dr`` over
    ``int rho W^2 r^2 dr``, ``L = l (l + 1)``. It equals ``mu k^2`` only if the surface
    traction ``mu (W' - W / r)`` vanishes (the boundary term of the integration by parts)."""
    mu = 0.5 / (1.0 + nu)

    def W(r):
        return spherical_jn(l, k * r)

    def dW(r):
        return k * spherical_jn(l, k * r, derivative=True)

    L = l * (l + 1.0)
    top = quad(lambda r: (r * dW(r) - W(r)) ** 2 + (L - 2.0) * W(r) ** 2, 0, 1, epsrel=1e-13)[0]
    bottom = quad(lambda r: W(r) ** 2 * r * r, 0, 1, epsrel=1e-13)[0]
    return mu * top / bottom


@pytest.mark.parametrize("nu", [-0.5, 0.25, 0.3, 0.45])
def test_toroidal_roots_are_free_surfaces(nu):
    """Every root below omega = 8 c/R is its shape's Rayleigh quotient (to 1e-10); the roots
    of the equation with j_l' for j_(l+1), ``(l - 1) j_l = k j_l'`` (the same as Lamb's at
    l = 2 only), fail it at l = 3 (the check can fail); l = 1 has the roots of j_2 (the rigid
    rotation ``k = 0`` left out)."""
    c_T = math.sqrt(0.5 / (1.0 + nu))
    l, n, w, T = toroidal_modes(nu, 8.0)
    assert l.size >= 5 and np.all(np.diff(w) >= 0) and np.all(T > 0)
    for li, wi in zip(l, w, strict=True):
        assert_allclose(_rayleigh_quotient(int(li), wi / c_T, nu), wi**2, rtol=1e-10)
    first_j2 = brentq(lambda x: spherical_jn(2, x), 4.0, 7.0, xtol=1e-15)
    assert_allclose(w[(l == 1) & (n == 0)][0] / c_T, first_j2, rtol=1e-12)
    wrong = brentq(lambda k: 2 * spherical_jn(3, k) - k * spherical_jn(3, k, True), 2.0, 4.5)
    assert abs(_rayleigh_quotient(3, wrong, nu) / (wrong**2 * c_T**2) - 1.0) > 1e-2


def test_lambs_gravest_toroidal_mode():
    """Lamb (1882), first class, l = 2: omega R / c_T = 2.501 (three digits, any nu: the
    toroidal equation has no nu in it); here 2.50113. l = 1's first root is the first zero of
    j_2, tan x = 3 x / (3 - x^2): 5.7635."""
    for nu in (0.0, 0.25, 0.45):
        c_T = math.sqrt(0.5 / (1.0 + nu))
        l, n, w, _ = toroidal_modes(nu, 6.0 * c_T)
        assert_allclose(w[(l == 2) & (n == 0)][0] / c_T, 2.501, atol=5e-4)
        assert_allclose(w[(l == 1) & (n == 0)][0] / c_T, 5.7635, atol=5e-5)


def test_toroidal_static_limit():
    """A toroidal surface traction of order l >= 2 holds the sphere still with ``u_r = 0``,
    ``W = tau r^l / (mu (l - 1))`` (``sigma = mu r (W / r)' = tau`` at ``r = 1``). The modal
    static response sums ``T_n^2 L (4 pi / (2l + 1)) / (m omega_n^2)`` over the roots; its
    partial sums approach 1 / (mu (l - 1)) like 1/n (measured: -4.2e-4 at 476 roots, l = 2),
    and their Richardson extrapolation within 2e-5 (measured 1.8e-6, 5.3e-6, 1.1e-5 at l = 2,
    3, 5)."""
    mu = 0.5 / (1.0 + NU)
    for l in (2, 3, 5):
        _, _, w, T = toroidal_modes(NU, 1500.0 * math.sqrt(mu), orders=[l])
        terms = T**2 * l * (l + 1) * (4 * math.pi / (2 * l + 1)) / (4 * math.pi / 3) / w**2
        S = np.cumsum(terms) * mu * (l - 1)
        N = S.size
        half, full = 1.0 - S[N // 2 - 1], 1.0 - S[N - 1]
        assert 0.0 < full < 0.6 * half  # from below, falling like 1/n
        assert abs(2.0 * S[N - 1] - S[N // 2 - 1] - 1.0) < 2e-5


# -- the fields: normalisation, orthogonality, rigid motions -------------------------------


def _fields(cap, modes, r, theta, phi, drop_phi=False):
    """Every mode's displacement at the points ``(r, theta, phi)`` (shape (P,)), Cartesian in
    the body frame, from the radial shapes written out here (not the module's surface code)."""
    c_L = math.sqrt(NU / ((1 + NU) * (1 - 2 * NU)) + 1.0 / (1 + NU))
    c_T = math.sqrt(0.5 / (1.0 + NU))
    P = r.size
    out = np.zeros((P, 3, len(cap)))
    st, ct, sp, cp = np.sin(theta), np.cos(theta), np.sin(phi), np.cos(phi)
    rhat = np.stack([ct, st * cp, st * sp], 1)
    that = np.stack([-st, ct * cp, ct * sp], 1)
    phat = np.stack([np.zeros(P), -sp, cp], 1)
    for k in range(len(cap)):
        l, m, w = int(cap.l[k]), int(cap.m[k]), cap.omega[k]
        Y, dY, Ys = harmonics.angular_functions(l, m, theta)
        if cap.family[k] == 0:
            i = np.flatnonzero((modes.l == l) & (modes.n == cap.n[k]))[0]
            h, kk, A, B = w / c_L, w / c_T, modes.A[i], modes.B[i]
            U = A * h * spherical_jn(l, h * r, True) + B * l * (l + 1) * spherical_jn(l, kk * r) / r
            V = A * spherical_jn(l, h * r) / r + B * (
                spherical_jn(l, kk * r) / r + kk * spherical_jn(l, kk * r, True)
            )
            cos, sin = np.cos(m * phi), np.sin(m * phi)
            ur, ut, up = U * Y * cos, V * dY * cos, -V * m * Ys * sin * (not drop_phi)
        else:
            A, _ = toroidal_amplitude(np.array([l]), np.array([w]), NU)
            W = A[0] * spherical_jn(l, w / c_T * r)
            ur, ut, up = 0.0 * r, W * m * Ys * np.cos(m * phi), -W * dY * np.sin(m * phi)
        out[:, :, k] = ur[:, None] * rhat + ut[:, None] * that + up[:, None] * phat
    return out


def _ball_rule(nr=48, nt=40, nphi=24):
    t, wt = roots_legendre(nr)
    r, wr = 0.5 * (t + 1), 0.5 * wt * (0.5 * (t + 1)) ** 2
    x, wx = roots_legendre(nt)
    phi = 2 * math.pi * np.arange(nphi) / nphi
    R, X, F = np.meshgrid(r, x, phi, indexing="ij")
    Wt = wr[:, None, None] * wx[None, :, None] * np.full(nphi, 2 * math.pi / nphi)[None, None, :]
    return R.ravel(), np.arccos(X.ravel()), F.ravel(), Wt.ravel()


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_normalisation_orthogonality_and_rigid_motions(modes20, cap20):
    """int rho u_a . u_b dV = m delta_ab for every pair of the cap's modes (m = 0, 1, 2,
    spheroidal and toroidal; measured <= 3e-13), and every mode carries no momentum along e2
    and no angular momentum about e3 (the collision's rigid degrees of freedom)."""
    r, theta, phi, w = _ball_rule()
    u = _fields(cap20, modes20, r, theta, phi)
    gram = np.einsum("p,pik,pil->kl", w, u, u)
    assert_allclose(gram, cap20.mass * np.eye(len(cap20)), atol=1e-10)
    pos = r[:, None] * np.stack(
        [np.cos(theta), np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi)], 1
    )
    momentum = np.einsum("p,pk->k", w, u[:, 1, :])
    spin = np.einsum("p,pk->k", w, pos[:, 0, None] * u[:, 1, :] - pos[:, 1, None] * u[:, 0, :])
    assert np.all(np.abs(momentum) < 1e-12) and np.all(np.abs(spin) < 1e-12)


def _strain_energy_quotient(cap, modes, drop_phi=False):
    """``omega^2`` of every mode of ``cap`` by its Rayleigh quotient in Cartesian coordinates:
    the strain energy ``int (lambda/2 (tr eps)^2 + mu eps:eps) dV`` with the displacement
    gradient by central differences of the fields over the ball (no spherical formula), over
    ``(1/2) int rho |u|^2 dV``. It equals the mode's omega^2 only for a free vibration of the
    sphere with that frequency."""
    lam, mu = NU / ((1 + NU) * (1 - 2 * NU)), 0.5 / (1 + NU)
    r, theta, phi, w = _ball_rule(40, 32, 24)
    x = r[:, None] * np.stack(
        [np.cos(theta), np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi)], 1
    )

    def field(points):
        rr = np.linalg.norm(points, axis=1)
        th = np.arccos(np.clip(points[:, 0] / rr, -1.0, 1.0))
        return _fields(cap, modes, rr, th, np.arctan2(points[:, 2], points[:, 1]), drop_phi)

    h = 1e-5
    grad = np.zeros((r.size, 3, 3, len(cap)))  # d u_i / d x_j
    for j in range(3):
        step = np.zeros(3)
        step[j] = h
        grad[:, :, j, :] = (field(x + step) - field(x - step)) / (2 * h)
    eps = 0.5 * (grad + grad.transpose(0, 2, 1, 3))
    trace = np.einsum("piik->pk", eps)
    density = 0.5 * lam * trace**2 + mu * np.einsum("pijk,pijk->pk", eps, eps)
    kinetic = 0.5 * np.einsum("p,pik,pik->k", w, field(x), field(x))
    return (w @ density) / kinetic


@pytest.mark.slow  # 10 s of the default run (stop 76: the default run under 10 min)
def test_every_azimuthal_order_vibrates_at_its_roots_frequency(modes20):
    """The m = 1 and m = 2 spheroidal fields built on the axisymmetric shapes and the toroidal
    fields have, as their strain-energy Rayleigh quotient in Cartesian coordinates, the
    frequency they are given (30 modes of l <= 3: measured 2.4e-9, test 1e-6; the check of
    "same frequency for every m"). The l = 2, m = 1 field without its u_phi (the axisymmetric
    recipe carried over) fails it (its quotient 4.05 times omega^2)."""
    cap = cap_modes(modes20, azimuthal=2)
    pick = np.flatnonzero((cap.m >= 1) & (cap.l <= 3))
    assert {(int(f), int(m)) for f, m in zip(cap.family[pick], cap.m[pick], strict=True)} == {
        (0, 1),
        (0, 2),
        (1, 1),
        (1, 2),
    }
    sub = cap.take(pick)
    assert_allclose(_strain_energy_quotient(sub, modes20), sub.omega**2, rtol=1e-6)
    one = sub.take(np.flatnonzero((sub.family == 0) & (sub.m == 1) & (sub.l == 2))[:1])
    bad = _strain_energy_quotient(one, modes20, drop_phi=True)[0]
    assert abs(bad / one.omega[0] ** 2 - 1.0) > 1e-2


def test_cap_layout(modes20, cap20):
    """The axisymmetric modes first as given, then per m the spheroidal partners of the orders
    l >= m (same frequencies) and the toroidal modes below the set's top frequency; the
    surface displacement is the interior field at r = 1; the cap is an oblique body."""
    N = len(modes20)
    assert_allclose(cap20.omega[:N], modes20.omega, rtol=0)
    assert np.all(cap20.m[:N] == 0) and np.all(cap20.family[:N] == 0)
    for mm in (1, 2):
        sph = (cap20.m == mm) & (cap20.family == 0)
        assert sph.sum() == np.sum(modes20.l >= mm)
        tor = (cap20.m == mm) & (cap20.family == 1)
        assert np.all(cap20.omega[tor] <= modes20.omega.max() * (1 + 1e-12))
        assert np.all(cap20.l[tor] >= mm) and tor.sum() >= 3
    theta = np.linspace(0.0, 1.4, 9)
    phi = np.linspace(-3.0, 3.0, 9)
    d = np.stack(cap20.displacement(theta, phi), 1)
    assert_allclose(d, _fields(cap20, modes20, np.ones(9), theta, phi), atol=1e-12)
    assert isinstance(cap20, RimBody) and cap20.inertia == pytest.approx(0.4 * cap20.mass)


def test_wall_nodes_sum_the_rings_of_the_head_on_quadrature(modes20, cap20):
    """Without rotation the ring sums of any axisymmetric integrand equal the head-on
    quadrature's, and the m >= 1 modes' generalised forces of an axisymmetric pressure vanish
    (to round-off); the reach bounds the displacement along the normal at any rotation."""
    alpha = 500.0
    nodes = cap20.wall_nodes(alpha)
    head = sphere_quadrature(modes20, modes20.contact_nodes(alpha))
    assert_allclose(nodes.theta, head.nodes, rtol=0)
    assert_allclose(nodes.start_integral(alpha), np.exp(alpha * (head.height - 1)) @ head.weight,
                    rtol=1e-13)  # fmt: skip
    pressure = nodes.weight * np.exp(alpha * (nodes.c - 1.0))
    force = pressure @ nodes.D1
    N = len(modes20)
    scale = np.abs(force[:N]).max()
    assert np.all(np.abs(force[N:]) < 1e-13 * scale)
    for rot in (0.0, 0.3, -1.0):
        normal = nodes.D1 * math.cos(rot) - nodes.D2 * math.sin(rot)
        assert np.all(np.abs(normal) <= nodes.reach[None, :] * (1 + 1e-12))


def test_refusals(modes20):
    with pytest.raises(InputError):
        cap_modes(modes20.take(np.arange(3)).l, azimuthal=1)
    with pytest.raises(InputError):
        cap_modes(modes20, azimuthal=-1)
    with pytest.raises(InputError):
        cap_modes(modes20).with_azimuths(7)
    nodes = cap_modes(modes20, azimuthal=1).wall_nodes(100.0)
    zero = np.zeros(53)
    assert nodes.place(-1.0, 1.0, zero, zero, 0.0, -0.01) is not None  # turned, within reach
    with pytest.raises(InputError, match="edge of the sphere's wall nodes"):
        nodes.place(-1.0, 1.0, zero, zero, 0.0, -1.0)  # every ring, the last one above
    with pytest.raises(InputError):
        toroidal_modes(0.6, 5.0)
    with pytest.raises(InputError):
        toroidal_modes(NU, 5.0, orders=[0])
