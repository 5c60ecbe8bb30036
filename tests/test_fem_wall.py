"""The FEM route for a sphere on an elastic wall, both meshed (restitution.fem.block,
wall_impact, wall_limits, wall_reference): the judge of the half-space and thin-plate routes
(issue 42).

Numbers quoted in docstrings are measurements of this package on the development machine
(Nov 2026, one core); the tests assert them against exact identities of the construction or
against independent routes: the rigid wall's FEM (a wall stiff and heavy enough is rigid), the
momentum balance, the half-space's radiation integral (quasistatic/half_space.py) and Zener's
coupled plate equation (quasistatic/plate.py).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import restitution
from restitution import InputError
from restitution.bodies.material import Material
from restitution.bodies.wall import HalfSpace, Plate, wall_from_dict
from restitution.fem.block import block_model, graded_block
from restitution.fem.impact import fem_collide
from restitution.fem.mesh import ARC, DIAMETER
from restitution.fem.wall_impact import fem_collide_wall, wall_model, wall_scales
from restitution.fem.wall_reference import STEEL_ON_GLASS, WALL_REFERENCE_POINTS
from restitution.laws.wall_points import load_wall_reference
from restitution.quasistatic.half_space import half_space_loss, radiated_fraction
from restitution.quasistatic.low_speed import LOW_SPEED_MODES
from restitution.quasistatic.plate import model_error, plate_impact

NU = 0.3
SPHERE = "sphere"


# -- the block's mesh ---------------------------------------------------------------------


def test_the_block_mesh_covers_the_section_with_its_boundaries_named():
    """The meridian section ``[-depth, 0] x [0, radius]``: its top (x = 0) is the contact side,
    its axis (y = 0) the roller; both run over the whole edge, and the elements at the
    contact are no longer than the contact size."""
    m = graded_block(12.0, 7.0, 0.5, h_contact=0.05, h_far=1.0, grading=0.5)
    assert m.p[0].min() == -7.0 and m.p[0].max() == 0.0
    assert m.p[1].min() == 0.0 and m.p[1].max() == 12.0
    for name, coordinate, across in ((ARC, 0, 1), (DIAMETER, 1, 0)):
        ends = m.p[:, m.facets[:, m.boundaries[name]]]
        assert np.all(ends[coordinate] == 0.0)
        lengths = np.abs(ends[across, 1] - ends[across, 0])
        assert lengths.sum() == pytest.approx(12.0 if name == ARC else 7.0, rel=1e-12)
    top = m.facets[:, m.boundaries[ARC]]
    near = np.all(m.p[1, top] <= 0.5, axis=0)
    assert np.abs(np.diff(m.p[1, top[:, near]], axis=0)).max() <= 0.05 + 1e-12


def test_the_block_mesh_near_the_contact_does_not_depend_on_its_size():
    """Cells of side ``h_far`` before the grading: a block twice as large has the same
    elements within 3 R of the contact, so the size check changes the block and nothing
    else."""

    def near(m):
        p = m.p[:, (np.abs(m.p[0]) < 3.0) & (m.p[1] < 3.0)]
        return p[:, np.lexsort(p)]

    small = graded_block(28.0, 28.0, 0.5, h_contact=0.044, h_far=1.36, grading=0.5)
    large = graded_block(56.0, 56.0, 0.5, h_contact=0.044, h_far=1.36, grading=0.5)
    assert near(small).shape == near(large).shape
    assert np.array_equal(near(small), near(large))


def test_the_block_has_the_mass_of_its_cylinder():
    """The lumped mass of the axisymmetric section is the cylinder's ``rho pi R^2 depth``:
    the weighted lumping rule (and HRZ on the axis) keeps each element's mass exactly."""
    material = Material(nu=0.25, E=0.3, rho=0.32)
    model = block_model(material, 6.0, 4.0, 0.3, 0, 0.1, 1.0, 0.5)
    assert model.disk.mass == pytest.approx(0.32 * math.pi * 36.0 * 4.0, rel=1e-12)


def test_walls_and_points_are_refused_in_one_line():
    with pytest.raises(InputError, match="HalfSpace or Plate"):
        wall_scales(NU, "glass", 1e-3)
    with pytest.raises(InputError, match=r"\(0, 1\)"):
        wall_scales(NU, STEEL_ON_GLASS, 1.5)
    with pytest.raises(InputError, match="block's size"):
        wall_model(NU, STEEL_ON_GLASS, 1e-3, 1e4, 0, size=0.0)
    with pytest.raises(InputError, match="radius"):
        graded_block(-1.0, 1.0, 0.1)


def test_hertz_scales_on_the_wall_are_those_of_the_half_space_route():
    """The mesh's compression is the one the radiation integral uses:
    ``(5 m v^2 / (4 K))^(2/5)`` with ``K = (4/3) E*``."""
    s = wall_scales(NU, STEEL_ON_GLASS, 1e-3)
    k = 4.0 / 3.0 * STEEL_ON_GLASS.effective_modulus(NU)
    assert s.compression == pytest.approx((1.25 * 4.0 * math.pi / 3.0 * 1e-6 / k) ** 0.4,
                                          rel=1e-14)  # fmt: skip
    assert s.force == pytest.approx(k * s.compression**1.5, rel=1e-14)


# -- collisions -----------------------------------------------------------------------------


@pytest.mark.slow
def test_what_a_stiff_heavy_wall_takes_falls_like_its_impedance_towards_the_rigid_wall():
    """Walls whose modulus and density are 1e2 and 1e4 times the ball's (waves as fast as the
    ball's, impedance 1e2 and 1e4 times larger) against the rigid wall's FEM with the ball
    meshed alike (``v = 0.01``, ``alpha delta = 160``, level 0). What the block takes,
    ``eps_rigid^2 - eps_block^2``, must vanish like ``1 / (rho_w c_T^3)`` towards the rigid
    wall: the ratio of the two walls' takes is the radiation integral's
    (quasistatic/half_space.py: 98.83, ``E*`` differing by 1 %). Measured 98.42 (takes
    2.024e-3 and 2.057e-5 of the ball's energy; the rigid wall's loss 2.561e-3).

    The absolute take is not the radiation integral's here: it is 1.25 times it at ``v = 0.01``
    and 1.084 times at ``v = 1e-3`` (E = 1e2; the same at contact levels 1 and 2 and with the
    bulk halved), where the ball's own vibrations on the rigid wall (2.6e-3, 2.0e-4) are not
    small against the wall's share; docs/walls.md, the judge."""
    v = 0.01
    takes, waves = [], []
    for ratio in (1e2, 1e4):
        wall = HalfSpace(ratio, ratio, NU)
        alpha = 160.0 / wall_scales(NU, wall, v).compression
        model = wall_model(NU, wall, v, alpha, 0)
        on_block = fem_collide_wall(NU, wall, v, alpha)
        rigid = fem_collide(NU, v, alpha, geometry=SPHERE, settings=model.ball_mesh)
        takes.append(rigid.epsilon**2 - on_block.epsilon**2)
        waves.append(radiated_fraction(
            v, mass=4.0 * math.pi / 3.0, radius=1.0, e_star=wall.effective_modulus(NU),
            wall_density=wall.density_ratio, wall_shear_speed=wall.shear_speed,
            wall_nu=wall.nu,
        ))  # fmt: skip
    assert takes[1] > 0.0
    # 1 %: the takes' ratio differs from the integral's by the change of the ball's own loss
    # with E* (1 % softer contact) and the coupling of the loss to the pulse (2e-3).
    assert takes[0] / takes[1] == pytest.approx(waves[0] / waves[1], rel=0.01)


@pytest.mark.slow
def test_the_ball_does_not_feel_a_block_twice_as_large():
    """A steel ball on glass at ``v = 0.01``, level 0, ``alpha delta = 160``: the default block
    (``0.75 c_L t_c``) and one twice as large (8 times the mass). No reflection comes back
    before the ball leaves, so the ball's epsilon is the same: measured 5.0e-14 (epsilon
    0.951276, 10960 and 11024 steps of the same dt). A reflection that came back would change
    it by far more than the bound, the runs' energy drift (3.7e-8): a step that differs
    (ARPACK's random start, fixed since stop 70, moved each model's stability bound) changes
    epsilon by about as
    much. The relative speed of the centres holds the block's recoil, ``(1 + eps) m / M``:
    0.95273 and 0.95146."""
    v = 0.01
    alpha = 160.0 / wall_scales(NU, STEEL_ON_GLASS, v).compression
    small = fem_collide_wall(NU, STEEL_ON_GLASS, v, alpha)
    large = fem_collide_wall(NU, STEEL_ON_GLASS, v, alpha, size=1.5)
    assert large.block_mass == pytest.approx(8.0 * small.block_mass, rel=1e-12)
    assert abs(small.epsilon - large.epsilon) < 1e-7
    assert small.relative_epsilon - large.relative_epsilon > 1e-3


# -- the judge: the shipped reference against the routes -----------------------------------


def _route(point):
    """The half-space route's (ball's modes and the wall's waves) or Zener's plate route's
    loss and its error at a stored point; the plate's route holds no ball vibrations (they are
    below 1e-4 of its loss here)."""
    if isinstance(point.wall, Plate):
        impact = plate_impact(point.v, point.wall, nu=point.nu, mass=4.0 * math.pi / 3.0)
        return 1.0 - impact.epsilon**2, model_error(impact, point.wall)
    from restitution import get_modes

    modes = get_modes(point.nu, LOW_SPEED_MODES, geometry=SPHERE)
    r = half_space_loss(modes, point.v, point.wall)
    return r.energy_loss, r.energy_loss_err


def test_the_shipped_wall_reference_holds_the_asked_points():
    """A steel ball on a glass block at 2.6, 5.2 and 10 m/s and on glass plates 3 mm and 10 mm
    thick (issue 42's four points, the block and the 10 mm plate at 10 m/s, both plates, the
    block and a 30 mm plate at 1 m/s), every one with both limits taken and both checks."""
    points = load_wall_reference()
    kinds = sorted((p.wall.to_dict()["kind"], getattr(p.wall, "thickness", 0.0), p.v)
                   for p in points)  # fmt: skip
    asked = sorted((w.to_dict()["kind"], getattr(w, "thickness", 0.0), v)
                   for _, w, v, _ in WALL_REFERENCE_POINTS)  # fmt: skip
    assert kinds == asked
    for p in points:
        assert math.isfinite(p.epsilon) and p.energy_loss_err > 0, p


def test_the_routes_lie_within_two_combined_errors_of_the_finite_elements():
    """The judge: each stored FEM point (both limits, the block's size and the bulk checked)
    against the route the package serves there: the half-space route on the block, Zener's
    coupled equation on the plates, within 2 combined errors (the other judges' criterion).
    Measured sigmas: +0.12, +0.10 and +0.08 (block at v = 5e-4, 1e-3, 1.93e-3), +0.48 and +0.80
    (plates 3 and 10 mm at v = 5e-4), +0.61 and +0.88 (3 and 10 mm at 1.93e-4, 1 m/s), +0.15
    (the block at 1 m/s), +0.51 (30 mm at 1 m/s, where Zener's model fails and its band is
    wide: FEM loss 0.01452, Zener 0.0089 +- 0.011); before
    the depth term of
    Zener's error the 10 mm plate at v = 5e-4 had +2.29. The 10 mm plate at v = 1.93e-3
    (10 m/s) lies outside Zener's model (the package serves the stored point there); its
    unrefused value is +0.69 off, 23 % below the FEM loss."""
    for point in load_wall_reference():
        loss, err = _route(point)
        sigma = (point.energy_loss - loss) / math.hypot(point.energy_loss_err, err)
        assert abs(sigma) < 2.0, (point, loss, err, sigma)


def test_a_stored_wall_round_trips_through_its_dictionary():
    for wall in (STEEL_ON_GLASS, Plate(0.3, 0.32, 0.25, thickness=1.2)):
        assert wall_from_dict(json.loads(json.dumps(wall.to_dict()))) == wall
    with pytest.raises(InputError, match="half-space' or 'plate'"):
        wall_from_dict({"kind": "cube", "modulus_ratio": 1, "density_ratio": 1, "nu": 0.3})


@pytest.mark.slow
def test_a_stored_run_of_the_judge_is_reproduced():
    """Regression (this package's own earlier output): the block at ``v = 1e-3``, the softest
    wall of its grid, level 0, recomputed by today's code against the value the stored file
    holds (computed at commit feb2c88). The runs' step depends on ARPACK's stability bound,
    stored with a random start (fixed since stop 70), which moves epsilon by about the run's
    energy drift, hence 1e-8."""
    data = Path(restitution.__file__).parent / "laws" / "data" / "fem_reference_wall.json"
    points = json.loads(data.read_text())["points"]
    point = next(p for p in points if p["wall"]["kind"] == "half-space" and p["v"] == 1e-3)
    run = next(r for r in point["grid"]["runs"] if r["level"] == 0)
    wall = wall_from_dict(point["wall"])
    again = fem_collide_wall(point["nu"], wall, point["v"], run["alpha"], level=0)
    assert abs(again.epsilon - run["epsilon"]) < 1e-8, (again.epsilon, run["epsilon"])
