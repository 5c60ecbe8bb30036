"""The finite-element judge of the disk's oblique impact with Coulomb friction (issue 63).

Units: ``E = rho = R = 1`` (the disk's two-dimensional constants), speeds in ``c``. One speed and
wall throughout: ``v = 0.05``, ``alpha = 40 / delta_max(v)`` (the head-on judge's softest wall),
``nu = 0.33``, mesh level 0. Measured values are in docs/oblique.md, "A finite-element judge
with friction (the disk)".
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from restitution.bodies.disk.contact import max_compression_estimate
from restitution.errors import InputError
from restitution.fem.elasticity import as_material
from restitution.fem.graded import graded_settings
from restitution.fem.impact import fem_collide
from restitution.fem.mesh import uniform_half_disk
from restitution.fem.oblique_impact import (
    FemObliqueSettings,
    _Elastic,
    fem_oblique_collide,
    oblique_model_for,
)
from restitution.fem.whole_disk import mirrored_disk

NU = 0.33
V = 0.05
ALPHA = 40.0 / max_compression_estimate(V)
DATA = Path(__file__).parent / "data" / "fem_oblique_disk.json"


def _model():
    return oblique_model_for(as_material(NU), V, V, 0.5, ALPHA, FemObliqueSettings())


def test_mirrored_disk_is_the_whole_disk():
    mesh = mirrored_disk(uniform_half_disk(3))
    r = np.hypot(*mesh.doflocs[:, mesh.facets[:, mesh.boundaries["arc"]].ravel()])
    assert_allclose(r, 1.0, atol=1e-14)
    model = _model()
    assert_allclose(model.mass, math.pi, rtol=1e-5)
    assert_allclose(model.inertia, math.pi / 2, rtol=1e-5)
    assert_allclose(model.quad.weight.sum(), math.pi, rtol=1e-5)  # the rim |phi| <= pi/2
    n = model.disk.n_dofs
    for field in ((1.0, 0.0), (0.0, 1.0), (-model.X[1], model.X[0])):
        u = np.zeros(n)
        u[model.ix], u[model.iy] = field
        assert np.abs(model.disk.K @ u).max() < 1e-11


def test_corotated_energy_is_invariant_and_its_force_is_its_gradient():
    model = _model()
    elastic = _Elastic(model)
    rng = np.random.default_rng(1)
    th = 0.3
    co, si = math.cos(th), math.sin(th)
    rigid = np.zeros(model.disk.n_dofs)
    rigid[model.ix] = co * model.X[0] - si * model.X[1] - model.X[0] + 0.1
    rigid[model.iy] = si * model.X[0] + co * model.X[1] - model.X[1] - 0.2
    f, energy, theta = elastic(rigid)
    assert abs(energy) < 1e-25 and np.abs(f).max() < 1e-12
    assert_allclose(theta, th, atol=1e-14)
    u = rigid + 1e-2 * rng.standard_normal(rigid.size)
    du = 1e-7 * rng.standard_normal(rigid.size)
    f0, e0, _ = elastic(u)
    f1, e1, _ = elastic(u + du)
    assert_allclose(e1 - e0, -0.5 * (f0 + f1) @ du, rtol=1e-6)


def test_frictionless_45_degrees_is_the_head_on_fem():
    head_on = fem_collide(NU, V, ALPHA, settings=graded_settings(V, ALPHA, 0))
    out = fem_oblique_collide(NU, V, V, 0.0, ALPHA)
    # The same mesh mirrored; the steps differ (the whole disk's bounds): 8.2e-7 measured.
    assert abs(out.epsilon_normal - head_on.epsilon) < 5e-6
    assert_allclose(out.beta, -1.0, atol=1e-12)
    assert abs(out.spin) < 1e-12 and out.friction_work == 0.0
    assert abs(out.energy_balance) < 1e-5


def test_gross_sliding_is_the_impulse_ratio():
    mu, angle = 0.1, math.radians(80.0)
    out = fem_oblique_collide(NU, V, V * math.tan(angle), mu, ALPHA)
    impulse = -1.0 + 3.0 * mu * (1.0 + out.epsilon_normal) / math.tan(angle)
    # The lever R - delta and the pressure's torque, first order in the compression: the
    # modal route's 3.7e-3 at this speed (docs/oblique.md); measured 3.3e-3 here.
    assert 0.0 < impulse - out.beta < 5e-3
    assert abs(out.energy_balance) < 1e-5


@pytest.mark.parametrize("mu, tan", [(0.5, 0.25), (0.5, 1.0), (0.5, 3.0)])
def test_energy_balance_and_mirror_symmetry(mu, tan):
    out = fem_oblique_collide(NU, V, V * tan, mu, ALPHA)
    assert abs(out.energy_balance) < 1e-5 and out.energy_error < 1e-5
    assert out.friction_work > 0
    mirror = fem_oblique_collide(NU, V, -V * tan, mu, ALPHA)
    assert_allclose(mirror.beta, out.beta, atol=1e-9)
    assert_allclose(mirror.spin, -out.spin, atol=1e-11)
    assert_allclose(mirror.epsilon_normal, out.epsilon_normal, atol=1e-12)
    # Coulomb bounds every impact by the gross-slip line.
    assert out.beta <= -1.0 + 3.0 * mu * (1.0 + out.epsilon_normal) / tan + 1e-9


@pytest.mark.slow  # 5 s of the default run (stop 79: the default run under 10 min)
def test_friction_law_converges_in_kappa_and_in_the_step():
    betas = [fem_oblique_collide(NU, V, V, 0.5, ALPHA, kappa=k).beta for k in (4, 8, 16, 32)]
    steps = np.abs(np.diff(betas))
    assert np.all(np.diff(betas) < 0) and np.all(np.diff(steps) < 0)
    half = fem_oblique_collide(NU, V, V, 0.5, ALPHA, kappa=4, step_safety=0.45).beta
    assert abs(half - betas[0]) < 0.2 * steps[0]


def test_refusals_say_what_to_do():
    with pytest.raises(InputError, match="mu >= 0"):
        fem_oblique_collide(NU, V, V, -0.1, ALPHA)
    with pytest.raises(InputError, match="kappa"):
        FemObliqueSettings(kappa=0.0)
    with pytest.raises(InputError, match=r"\(0, 1\)"):
        fem_oblique_collide(NU, 1.5, V, 0.1, ALPHA)


def test_stored_study_has_its_provenance_and_obeys_coulomb():
    data = json.loads(DATA.read_text())
    for key in ("fem_code_version", "modal_code_version", "date", "wall_time_s", "command"):
        assert data[key]
    assert data["v_normal"] == V and data["nu"] == NU
    cases = data["cases"] + data["gross_sliding_low_speed"] + data["low_speed_cases"]
    assert len(cases) == 12
    for case in cases:
        for run in case["fem"] + case["modal"]:
            line = -1.0 + 3.0 * (1.0 + run["epsilon_normal"]) / case["tan_over_mu"]
            assert run["beta"] <= line + 1e-9
            assert abs(run["energy_balance"]) < 1e-5


def test_a_stored_point_is_reproduced():
    data = json.loads(DATA.read_text())
    case = next(c for c in data["cases"] if c["tan_over_mu"] == 2.0)
    stored = next(r for r in case["fem"] if r["level"] == 0 and r["kappa"] == 16.0)
    out = fem_oblique_collide(NU, V, V * case["mu"] * 2.0, case["mu"], data["alpha"], kappa=16.0)
    # The step comes from ARPACK's largest eigenvalues (tol 1e-4); stored with a random start,
    # which moved its last digits from run to run (3e-11 in beta measured; the start is fixed
    # since stop 70, fem.model.start_vector).
    for key in ("beta", "epsilon_normal", "spin", "friction_work", "energy_balance"):
        assert_allclose(getattr(out, key), stored[key], rtol=0, atol=1e-8)
