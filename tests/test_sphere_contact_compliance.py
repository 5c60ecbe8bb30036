"""The sphere's contact compliance (restitution.bodies.sphere.contact_compliance): the toroidal
static closed form against Lamb's toroidal modes, the continuum against the half-space as the
contact shrinks, and the truncated modes' sums against the continuum as they grow; the annuli's
flexibility against Boussinesq's disk, the flat punch's and Mindlin's stiffness and the
half-space as the contact shrinks."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import curve_fit

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.contact_compliance import (
    DIRECTIONS,
    LOADS,
    ORDERS_PER_RADIUS,
    annulus_flexibility,
    continuum_compliance,
    half_space_annulus_flexibility,
    half_space_compliance,
    modal_compliance,
)
from restitution.bodies.sphere.modes import compute_sphere_modes
from restitution.bodies.sphere.static import toroidal_static_compliance
from restitution.bodies.sphere.toroidal import toroidal_modes
from restitution.errors import InputError
from restitution.quasistatic.oblique import stiffness_ratio

NU = 0.3


def test_toroidal_static_compliance_is_the_sum_of_the_modes():
    """``T_l = 2 (1 + nu) / (l - 1)``, and ``2 (1 + nu) / 7`` for the torque with the rotation's
    inertial relief (module docstring of static.py), against ``(4 pi l (l + 1) / (2l + 1)) sum
    T_n^2 / (m omega_n^2)`` over the toroidal modes below ``omega = 200``, whose ``1 / omega``
    tail is extrapolated by Richardson from the half band. Measured within 2.1e-4 relative for
    the orders 1-6 (5e-5 at ``omega = 400``); the partial sums stay below."""
    mass = 4.0 * math.pi / 3.0
    l, _, w, T = toroidal_modes(NU, 200.0, orders=np.arange(1, 7))
    for order in range(1, 7):
        exact = toroidal_static_compliance([order], NU)[0]

        def part(cut, order=order):
            k = (l == order) & (w < cut)
            factor = 4.0 * math.pi * order * (order + 1) / (2 * order + 1)
            return factor * np.sum(T[k] ** 2 / (mass * w[k] ** 2))

        assert part(200.0) < exact, order
        assert abs(2.0 * part(200.0) - part(100.0) - exact) < 5e-4 * exact, order


def test_toroidal_static_compliance_refuses_order_zero():
    with pytest.raises(InputError, match="integers >= 1"):
        toroidal_static_compliance([0, 1], NU)


def test_continuum_compliance_tends_to_the_half_space():
    """As the contact shrinks the sphere's compliance tends to the half-space's: Hertz's
    pressure departs like ``a`` (measured -0.62 %, -1.33 %, -2.81 % at ``a = 0.01, 0.02, 0.04``:
    order 1.09), the flat punch's likewise (-0.81 %, -1.67 %, -3.48 %: order 1.05), Mindlin's
    stick traction like ``a ln(1/a)`` (+2.04 %, +3.39 %, +5.31 %: 0.443, 0.434, 0.413 times
    ``a ln(1/a)``). A wrong factor anywhere would leave a constant."""
    radii = np.array([0.01, 0.02, 0.04])
    dev = {
        load: np.array([continuum_compliance(a, NU, load) / half_space_compliance(a, NU, load)
                        for a in radii]) - 1.0
        for load in ("pressure", "stick", "punch")
    }  # fmt: skip
    for load in ("pressure", "punch"):
        order = np.polyfit(np.log(radii), np.log(-dev[load]), 1)[0]
        assert np.all(dev[load] < 0) and 0.95 < order < 1.2, load
        assert abs(dev[load][0]) < 0.01, load
    scaled = dev["stick"] / (radii * np.log(1.0 / radii))
    assert np.all(dev["stick"] > 0) and np.ptp(scaled) < 0.1 * scaled.max()
    assert dev["stick"][0] < 0.025


def test_continuum_compliance_converges_in_its_orders():
    """Doubling the orders (and the quadrature with them) moves the smooth loads by 1.5e-9 and
    1.2e-9 and the stick traction and the punch, whose terms fall like ``l^-2``, by 1.8e-4 and
    2.3e-4 (measured at ``a = 0.15``)."""
    a = 0.15
    for load, tol in zip(LOADS, (1e-7, 4e-4, 1e-7, 4e-4), strict=True):
        base = continuum_compliance(a, NU, load)
        finer = continuum_compliance(a, NU, load, l_top=2 * int(math.ceil(ORDERS_PER_RADIUS / a)))
        assert abs(finer - base) < tol * base, load


def test_the_modes_are_partial_sums_of_the_continuum():
    """Every mode stores ``f^2 / (2 m omega^2) > 0``, so the truncated body's compliance is
    below the continuum's and rises with the modes (measured at ``a = 0.15``: pressure 0.51,
    0.68, 0.80, 0.86 of it at 20, 40, 80, 160 axisymmetric modes, punch 0.56, 0.69, 0.75,
    0.81); the modes of azimuthal order above 1 carry no generalised force (the full cap gives
    the ``m <= 1`` cap's sums to 1e-12)."""
    a = 0.15
    full = {load: continuum_compliance(a, NU, load) for load in LOADS}
    last = dict.fromkeys(LOADS, 0.0)
    for n in (20, 40, 80, 160):
        cap = cap_modes(compute_sphere_modes(NU, count=n), azimuthal=1)
        for load in LOADS:
            frac = modal_compliance(cap, a, load) / full[load]
            assert last[load] < frac < 1.0, (n, load)
            last[load] = frac
    every = cap_modes(compute_sphere_modes(NU, count=40))
    one = cap_modes(compute_sphere_modes(NU, count=40), azimuthal=1)
    for load in LOADS:
        assert modal_compliance(every, a, load) == pytest.approx(
            modal_compliance(one, a, load), rel=1e-12
        )


def test_the_modes_converge_to_the_continuum():
    """Two routes that share only the radial shapes' closed forms: the modal sums' deficits
    ``1 - C_N / C`` at 320, 640, 1280 and 2560 axisymmetric modes (``a = 0.15``; measured
    0.100, 0.071, 0.049, 0.035 for the pressure, 0.154, 0.116, 0.088, 0.065 stick, 0.128,
    0.089, 0.062, 0.043 slip, 0.143, 0.106, 0.079, 0.059 punch: like ``N^-0.4`` to ``N^-0.54``)
    fitted by ``d_inf + c N^-p`` leave a limit ``d_inf`` within 0.01 of zero (measured -5.6e-4,
    -6.8e-3, +2.6e-3, -2.3e-4; their fitted standard errors 1.3e-3, 2.0e-3, 3.9e-4, 4.1e-3).
    A continuum off by a per cent would leave that per cent. (Aitken's process on three of the
    counts, used before, scatters by about 0.01 with the counts chosen: the stick's limit is
    -2.4e-3 from 320-1280 and -1.15e-2 from 640-2560.)"""
    a = 0.15
    counts = np.array([320.0, 640.0, 1280.0, 2560.0])
    full = {load: continuum_compliance(a, NU, load) for load in LOADS}
    deficit = {load: [] for load in LOADS}
    for n in counts:
        cap = cap_modes(compute_sphere_modes(NU, count=int(n)), azimuthal=1)
        for load in LOADS:
            deficit[load].append(1.0 - modal_compliance(cap, a, load) / full[load])
    for load, d in deficit.items():
        assert np.all(np.diff(d) < 0.0) and d[-1] > 0.0, load
        (limit, _, power), _ = curve_fit(
            lambda n, d_inf, c, p: d_inf + c * n**-p, counts, d, p0=(0.0, 1.0, 0.5)
        )
        assert abs(limit) < 0.01 and 0.3 < power < 0.7, (load, limit, power)


def test_bad_input_is_refused():
    with pytest.raises(InputError, match="load must be one of"):
        continuum_compliance(0.1, NU, "shear")
    with pytest.raises(InputError, match="contact radius"):
        continuum_compliance(1.5, NU, "stick")
    with pytest.raises(InputError, match="not given"):
        half_space_compliance(0.1, NU, "slip")


def test_the_punch_gives_the_stiffness_ratio_of_the_half_space():
    """The punch's and the stick traction's half-space compliances are ``1 / k_n`` and
    ``1 / k_t``, so their ratio is Maw, Barber and Fawcett's ``chi = 2 (1 - nu) / (2 - nu)``
    (restitution.quasistatic.oblique.stiffness_ratio), at every ``a`` and ``nu``."""
    for nu in (0.0, 0.3, 0.45):
        for a in (0.05, 0.3):
            ratio = half_space_compliance(a, nu, "punch") / half_space_compliance(a, nu, "stick")
            assert ratio == pytest.approx(stiffness_ratio(nu), rel=1e-14)


def _stiffness(G: np.ndarray, edges: np.ndarray) -> float:
    """The force that moves every annulus by 1: ``sum Q`` for ``H Q = 1``, ``H = G / (A_i A_j)``."""
    area = math.pi * np.diff(edges**2)
    return float(np.linalg.solve(G / np.outer(area, area), np.ones(area.size)).sum())


def test_half_space_annuli_against_boussinesq_and_the_punch():
    """The closed form's one disk of radius ``a`` under unit pressure: ``int u dA = 16 a^3 /
    (3 E*)`` (Boussinesq's mean displacement of a uniformly loaded circle, ``16 p a / (3 pi
    E*)``). The force that moves ``n`` annuli by 1 is the flat punch's ``2 E* a`` (Mindlin's
    ``2 chi E* a`` along the surface) from below, the piecewise-constant traction missing the
    edge's ``1 / sqrt`` (measured 5.67e-3, 2.86e-3, 1.43e-3 short at 20, 40 and 80 annuli:
    order 1.0)."""
    e_star = 1.0 / (1.0 - NU * NU)
    one = half_space_annulus_flexibility([0.0, 0.1], NU, "normal")
    assert one[0, 0] == pytest.approx(16.0 * 0.1**3 / (3.0 * e_star), rel=1e-13)
    short = []
    for n in (20, 40, 80):
        edges = np.linspace(0.0, 0.2, n + 1)
        punch = 2.0 * e_star * 0.2
        exact = {"normal": punch, "tangential": stiffness_ratio(NU) * punch}
        k = {d: _stiffness(half_space_annulus_flexibility(edges, NU, d), edges) for d in DIRECTIONS}
        for d in DIRECTIONS:
            assert k[d] < exact[d]
        assert k["tangential"] / k["normal"] == pytest.approx(stiffness_ratio(NU), rel=1e-12)
        short.append(1.0 - k["normal"] / exact["normal"])
    order = np.log2(np.array(short[:-1]) / np.array(short[1:]))
    assert short[-1] < 2e-3 and np.all(np.abs(order - 1.0) < 0.05), (short, order)


def test_annulus_flexibility_tends_to_the_half_space():
    """The sphere's annuli (every order summed) against the closed form on ten annuli out to
    ``a``: symmetric, positive definite, and the relative (Frobenius) difference falls as
    ``a`` halves (measured normal 3.19e-2, 1.51e-2, 7.11e-3 at ``a = 0.04, 0.02, 0.01``:
    order 1.1; tangential 5.11e-2, 3.26e-2, 1.97e-2, like ``a ln(1/a)``, the stick
    traction's compliance's approach)."""
    for d in DIRECTIONS:
        gap = []
        for a in (0.04, 0.02, 0.01):
            edges = np.linspace(0.0, a, 11)
            S = annulus_flexibility(edges, NU, d)
            H = half_space_annulus_flexibility(edges, NU, d)
            assert np.array_equal(S, S.T) and np.linalg.eigvalsh(S).min() > 0.0
            gap.append(np.linalg.norm(S - H) / np.linalg.norm(H))
        assert gap[-1] < 0.025 and gap[0] / gap[1] > 1.5 and gap[1] / gap[2] > 1.5, (d, gap)


def test_annuli_stiffness_is_the_compliance_of_the_half_space_shapes():
    """At ``a = 0.155`` the sphere's own traction is close to the half-space's shape: the
    force that moves 80 annuli by 1 on the sphere, over that on the half-space's closed form
    (their common error of discretisation cancels), against ``1 / C`` of the punch and of the
    stick traction over the half-space's (measured 1.16641 against 1.16718 and 0.92436
    against 0.92437; at 40 annuli 1.16610 and 0.92432). Both are lower bounds of the true
    stiffness, equal within the orders' cut (about 4e-4, module constant
    ``ORDERS_PER_RADIUS``); their ratio is the sphere's ``chi``, 0.79 of Mindlin's."""
    a = 0.155
    edges = np.linspace(0.0, a, 81)
    for d, load in zip(DIRECTIONS, ("punch", "stick"), strict=True):
        k = _stiffness(annulus_flexibility(edges, NU, d), edges)
        k_hs = _stiffness(half_space_annulus_flexibility(edges, NU, d), edges)
        shape = half_space_compliance(a, NU, load) / continuum_compliance(a, NU, load)
        assert k / k_hs == pytest.approx(shape, rel=1e-3), d


def test_bad_annuli_are_refused():
    with pytest.raises(InputError, match="direction must be one of"):
        annulus_flexibility([0.0, 0.1], NU, "shear")
    with pytest.raises(InputError, match="increase"):
        half_space_annulus_flexibility([0.0, 0.1, 0.1], NU, "normal")
    with pytest.raises(InputError, match="at least two radii"):
        annulus_flexibility([0.0, 1.2], NU, "normal")
