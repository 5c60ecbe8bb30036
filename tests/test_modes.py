"""Eigenmodes of the free disk: closed forms, boundary conditions, orthonormality, counts."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import brentq

from restitution import Material, compute_modes, get_modes, weyl_count
from restitution.bodies.disk.frequency_equation import boundary_matrix, eq25, normalized_determinant


@pytest.fixture(scope="module")
def modes033():
    return get_modes(0.33, count=400)


def test_breathing_roots_closed_form():
    # Issue 2: roots of eq. (20) for nu = 0.33, omega R / c_P with c_P^2 = E / (rho (1 - nu^2)).
    expected = [2.067364, 5.395106, 8.575401, 11.734360]
    ms = get_modes(0.33, omega_max=14.0)
    c_p = Material(nu=0.33).c_p
    breathing = ms.omega[ms.n == 0][:4] / c_p
    assert_allclose(breathing, expected, atol=5e-7)


def test_no_torsional_n0_and_no_rigid_translation(modes033):
    # Torsional n = 0 roots solve J_2(kappa') = 0 (eq. 21 with R = 1); none may appear.
    from scipy.special import jn_zeros

    nu = 0.33
    torsional = jn_zeros(2, 5) / np.sqrt(2 * (1 + nu))
    n0 = modes033.omega[modes033.n == 0]
    assert np.min(np.abs(n0[:, None] - torsional[None, :])) > 1e-3
    assert modes033.omega.min() > 1.0  # the omega = 0 translation is not a mode
    assert np.all(modes033.S[modes033.n == 0] == 0)


def _shape_derivative(ms, r, h=1e-5):
    up, vp = ms.shapes(np.array([r + h]))
    um, vm = ms.shapes(np.array([r - h]))
    return (up - um)[:, 0] / (2 * h), (vp - vm)[:, 0] / (2 * h)


@pytest.mark.parametrize("nu", [0.33, 0.9, -0.5])
def test_stress_free_edge(nu):
    ms = get_modes(nu, count=300)
    U, V = (a[:, 0] for a in ms.shapes(np.array([1.0])))
    dU, dV = _shape_derivative(ms, 1.0)
    n = ms.n
    sigma_rr = dU + nu * (U + n * V)  # eq. (16) with eps_rr = U', eps_phiphi = U + n V at r = 1
    sigma_rphi = dV - V - n * U  # 2 eps_rphi at r = 1
    scale = np.abs(dU) + np.abs(U) + n * np.abs(V) + np.abs(dV)
    assert np.max(np.abs(sigma_rr) / scale) < 1e-7
    assert np.max(np.abs(sigma_rphi) / scale) < 1e-7


@pytest.mark.parametrize("nu", [0.33, 0.9])
def test_orthonormal_by_quadrature(nu):
    # Independent of the closed-form Lommel norms used in the code: Gauss-Legendre on [0, 1].
    ms = get_modes(nu, count=250)
    x, w = np.polynomial.legendre.leggauss(400)
    r, w = 0.5 * (x + 1), 0.5 * w
    U, V = ms.shapes(r)
    for n in np.unique(ms.n):
        idx = np.nonzero(ms.n == n)[0]
        if n == 0:
            gram = (U[idx] * r * w) @ U[idx].T
            target = 0.5 * np.eye(idx.size)
        else:
            gram = (U[idx] * r * w) @ U[idx].T + (V[idx] * r * w) @ V[idx].T
            target = np.eye(idx.size)
        assert_allclose(gram, target, atol=1e-8)


def test_eq25_has_the_same_roots(modes033):
    nu = 0.33
    for n in (1, 2, 3, 5, 8):
        roots = modes033.omega[modes033.n == n][:6]
        for w in roots:
            # eq. (25) changes sign across each determinant root, and its own root is there.
            lo, hi = w - 1e-3, w + 1e-3
            assert eq25(n, lo, nu) * eq25(n, hi, nu) < 0
            root = brentq(lambda x, n=n: eq25(n, x, nu), lo, hi, xtol=1e-14)
            assert abs(root - w) < 1e-10


def test_amplitudes_solve_edge_conditions(modes033):
    m = boundary_matrix(modes033.n, modes033.omega, 0.33)
    ab = np.stack([modes033.A, modes033.B], axis=-1)
    resid = np.einsum("kij,kj->ki", m, ab)
    scale = np.abs(m).max(axis=(1, 2)) * np.abs(ab).max(axis=1)
    assert np.max(np.abs(resid).max(axis=1) / scale) < 1e-10


def test_weyl_law():
    # The count tends to Weyl's leading term from above (positive perimeter correction) and
    # the relative excess decays roughly like 1/omega.
    ms = get_modes(0.33, count=1600)
    excess = []
    for w in (20.0, 40.0, 58.0):
        count = np.count_nonzero(ms.omega < w)
        excess.append(count / weyl_count(w, 0.33) - 1)
    assert all(e > 0 for e in excess)
    assert excess[0] > excess[1] > excess[2]
    assert excess[2] < 0.05


def test_near_degenerate_pairs_are_split():
    # Closest pair of roots within one order n: the scan step is 0.04; pairs closer than that
    # are found by the local-minimum refinement. All roots of an order are distinct and
    # the normalized determinant changes sign between neighbours only once.
    ms = get_modes(0.33, count=1600)
    gaps = []
    for n in np.unique(ms.n):
        w = ms.omega[ms.n == n]
        gaps.append(np.diff(w).min() if w.size > 1 else np.inf)
        # Dense independent re-scan of the determinant between consecutive roots.
        if n >= 1 and w.size > 1:
            mid = 0.5 * (w[1:] + w[:-1])
            f = normalized_determinant(n, mid, 0.33)
            assert np.all(f[1:] * f[:-1] < 0), f"missed or extra root for n = {n}"
    assert min(gaps) > 0


def test_count_and_omega_max_selections_agree():
    a = get_modes(0.9, omega_max=15.0)
    b = get_modes(0.9, count=len(a))
    assert_allclose(a.omega, b.omega, rtol=1e-13)


def test_cache_rejects_corrupt_and_foreign_files(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path))
    ref = compute_modes(0.25, count=30)
    first = get_modes(0.25, count=30)
    files = list(tmp_path.glob("modes-*.npz"))
    assert len(files) == 1
    files[0].write_bytes(b"not a zip file")
    again = get_modes(0.25, count=30)
    assert_allclose(again.omega, ref.omega)
    # A valid npz written for other inputs (foreign key) must not be trusted.
    other = list(tmp_path.glob("modes-*.npz"))[0]
    import shutil

    get_modes(0.26, count=30)
    foreign = [f for f in tmp_path.glob("modes-*.npz") if f != other][0]
    shutil.copy(foreign, other)
    assert_allclose(get_modes(0.25, count=30).omega, ref.omega)
    assert_allclose(first.omega, ref.omega)


def test_plane_strain_maps_onto_plane_stress():
    m = Material.from_3d(E=2.0, nu=0.3, plane="strain")
    assert_allclose(m.nu, 0.3 / 0.7)
    assert_allclose(m.E, 2.0 / (1 - 0.09))
    mu_k = Material.from_moduli(mu=m.mu, K=m.K)
    assert_allclose([mu_k.nu, mu_k.E], [m.nu, m.E])


@pytest.mark.parametrize(
    "kwargs",
    [dict(nu=1.0), dict(nu=-1.0), dict(nu=float("nan")), dict(nu=0.3, E=0.0), dict(nu=0.3, E=-1)],
)
def test_material_rejects_bad_input(kwargs):
    from restitution import MaterialError

    with pytest.raises(MaterialError, match="must"):
        Material(**kwargs)


def test_3d_poisson_range():
    from restitution import MaterialError

    with pytest.raises(MaterialError, match=r"\(-1, 0.5\]"):
        Material.from_3d(E=1.0, nu=0.6, plane="stress")


def test_shapes_are_finite_and_continuous_at_the_centre():
    # J_n(x)/x is evaluated through the recurrence, so r = 0 is exact: only n = 1 modes move
    # the centre (u ~ r^(n-1)), and the value at r = 0 is the limit r -> 0.
    ms = get_modes(0.33, count=200)
    U0, V0 = ms.shapes(np.array([0.0]))
    Ue, Ve = ms.shapes(np.array([1e-7]))
    assert np.all(np.isfinite(U0)) and np.all(np.isfinite(V0))
    assert_allclose(U0, Ue, atol=1e-5)
    assert_allclose(V0, Ve, atol=1e-5)
    moving = np.abs(U0[:, 0]) > 1e-12
    assert set(ms.n[moving]) == {1}
    # For n = 1 the centre moves rigidly: u_r = U cos(phi), u_phi = V sin(phi) with V = -U.
    one = ms.n == 1
    assert_allclose(V0[one, 0], -U0[one, 0], rtol=1e-12)


@pytest.mark.parametrize(("nu", "omega"), [(-0.9, 10.0), (-0.95, 5.5)])
def test_negative_nu_count_matches_fem(nu, omega):
    # For nu -> -1 the Rayleigh speed c_R falls far below c_s (c_R / c_s = 0.316 at nu = -0.9,
    # 0.224 at -0.95); a scan floor in c_s lost 7 of these 16 modes at nu = -0.9 and 5 of 7 at
    # -0.95, among them (n = 10, omega = 8.134) and (n = 5, omega = 4.589). The FEM count
    # (Sylvester's inertia of K - omega^2 M on the level-5 half disk) is independent.
    from restitution.fem.eigen import fem_count_below, half_disk_system

    modes = compute_modes(nu, omega_max=omega)
    assert len(modes) == fem_count_below(half_disk_system(nu, 5), omega)
    # The count is not at the mercy of a root next to omega: the nearest lies > 0.2 away.
    near = compute_modes(nu, omega_max=omega + 1.0).omega
    assert np.min(np.abs(near - omega)) > 0.2


def test_rayleigh_speed_closed_form():
    # nu = 0 in 2D plane stress: s^2 = 1/2 and the Rayleigh cubic in eta = xi^2 reads
    # eta^3 - 8 eta^2 + 16 eta - 8 = (eta - 2)(eta^2 - 6 eta + 4); the root below 1 is
    # eta = 3 - sqrt(5), so c_R = sqrt(3 - sqrt 5) c_s with c_s = 1/sqrt(2).
    from restitution.bodies.disk.modes import rayleigh_speed

    assert rayleigh_speed(0.0) == pytest.approx(
        math.sqrt(3.0 - math.sqrt(5.0)) / math.sqrt(2.0), rel=1e-13
    )


def test_ten_thousand_modes_are_complete_and_finite():
    # Weyl's law with its positive perimeter correction: the count below omega_max exceeds the
    # leading term by a fraction that falls like 1/omega (7% at omega = 20 above).
    modes = compute_modes(0.33, count=10_000)
    w = modes.omega.max()
    excess = len(modes) / weyl_count(w, 0.33) - 1.0
    assert 0.0 < excess < 0.07 * 20.0 / w * 1.5, excess
    assert np.all(np.isfinite(modes.C)) and np.all(np.isfinite(modes.S))
    assert np.all(np.diff(modes.omega) >= 0)
