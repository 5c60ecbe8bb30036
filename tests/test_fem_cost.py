"""The FEM runs' cost estimate and the refusals built on it (issue 30, :mod:`restitution.fem.cost`).

The machine's memory is monkeypatched (16 GiB available unless a test says otherwise), so the
refusals below do not depend on the machine that runs them; a refusal is checked to come before
any mesh is made (:func:`no_mesh`). No test times anything: the measured cost of real runs
against these estimates is in docs/fem.md.
"""

from __future__ import annotations

import re

import pytest
from _cli_checks import one_line_error

import restitution.budget as budget
from restitution.errors import InputError
from restitution.fem import cost
from restitution.fem.elasticity import as_material
from restitution.fem.impact import FemSettings, contact_angle_estimate, model_for
from restitution.fem.mesh import graded_half_disk

GIB = 2**30


@pytest.fixture
def machine(monkeypatch):
    """16 GiB available: one run may use 8 GiB."""
    monkeypatch.setattr(budget, "available_memory", lambda: 16 * GIB)


@pytest.fixture
def no_mesh(monkeypatch):
    """Fail the test if a refused command goes on to build an FEM model."""
    import restitution.fem.impact as impact

    def refuse(*args, **kwargs):
        raise AssertionError("an FEM model was built before the refusal")

    monkeypatch.setattr(impact, "fem_model", refuse)


# -- the mesh estimate against real meshes ---------------------------------------------------


@pytest.mark.parametrize(
    "refine, v, alpha",
    [(0, 0.1, 500.0), (1, 0.1, 500.0), (1, 0.01, 2000.0), (0, 0.3, 50.0)],
)
def test_estimated_dofs_lie_in_the_documented_band_of_real_meshes(refine, v, alpha):
    """collide's meshes (FemSettings' sizes): the real count within -12 % / +17 % of the
    estimate, the band of the 72 meshes the constants were fitted to (cost.py)."""
    s = FemSettings(refine=refine)
    angle = contact_angle_estimate(v, alpha, "disk", 0.33)
    mesh = graded_half_disk(refine, angle, h_contact=s.h_contact, h_far=s.h_far, grading=s.grading)
    real = 6 * mesh.t.shape[1] + 2 * len(mesh.boundaries["arc"]) + 1
    est = cost.estimate_mesh(refine, angle, s.h_contact, s.h_far, s.grading).n_dofs
    assert 0.88 <= real / est <= 1.17, (real, est)


def test_the_dof_count_formula_is_the_models():
    """``6 elements + 2 arc facets + 1`` (MeshEstimate.n_dofs) is the model's count exactly."""
    s = FemSettings(refine=0)
    angle = contact_angle_estimate(0.1, 500.0, "disk", 0.33)
    mesh = graded_half_disk(0, angle, h_contact=s.h_contact, h_far=s.h_far, grading=s.grading)
    model = model_for(as_material(0.33, "disk"), 0.1, 500.0, s)
    assert model.disk.n_dofs == 6 * mesh.t.shape[1] + 2 * len(mesh.boundaries["arc"]) + 1


def test_each_level_costs_more_and_steps_halve():
    """Each level multiplies the dofs by about 4 (finer than the coarse mesh) and halves the
    step; the set-up grows faster than the dofs (the factorisation's fill)."""
    runs = cost.compare_plan(0.33, 0.1, 500.0, range(4)).runs
    for a, b in zip(runs, runs[1:], strict=False):
        assert 3.0 < b.n_dofs / a.n_dofs < 4.5
        assert b.dt / a.dt == pytest.approx(0.5, rel=0.1)
        assert b.setup_s / a.setup_s > b.n_dofs / a.n_dofs


# -- refusals through the command line --------------------------------------------------------


def test_mesh_refine_9_is_refused_for_memory_naming_the_finest_level(cli, machine, no_mesh):
    need = cost.collide_plan(0.33, 0.1, 500.0, 9).peak_bytes
    for extra in ((), ("--force",)):
        code, _, err = cli("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "9",
                           *extra)  # fmt: skip
        one_line_error(code, err, "--mesh-refine 9", f"about {budget.format_bytes(need)} of "
                       "memory", "8 GiB one run may use", "--mesh-refine 3 is the finest that "
                       "fits")  # fmt: skip
        assert "--force" not in err  # memory is never overridden


def test_compare_fem_refine_9_is_refused(cli, machine, no_mesh):
    code, _, err = cli("compare-fem", "--refine", "9")
    one_line_error(code, err, "--refine 9", "of memory", "earlier models kept in the cache",
                   "--refine 3 is the finest that fits")  # fmt: skip


def test_fem_epsilon_at_v_1e_6_is_refused_for_time(cli, machine, no_mesh):
    code, _, err = cli("epsilon", "--method", "fem", "--nu", "0.33", "--v", "1e-6")
    plan = cost.epsilon_plan(0.33, 1e-6)
    assert plan.seconds > 2 * budget.TIME_BOUND_S  # far beyond the bound, not at its edge
    line = one_line_error(code, err, "--v 1e-06", f"about {budget.format_duration(plan.seconds)}",
                          "9 FEM runs", "1 h bound", "--force")  # fmt: skip
    shown = float(re.search(r"--v (\S+) is the slowest that fits", line).group(1))
    assert cost.epsilon_plan(0.33, shown).seconds <= budget.TIME_BOUND_S
    assert cost.epsilon_plan(0.33, 0.9 * shown).seconds > budget.TIME_BOUND_S


def test_a_cheap_fem_collision_is_not_refused(cli, machine):
    plan = cost.check_collide(0.33, 0.1, 500.0, 0)
    assert plan.seconds < budget.TIME_BOUND_S and plan.peak_bytes < 8 * GIB
    code, out, err = cli("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "0",
                         "--json")  # fmt: skip
    assert code == 0, err
    assert '"method": "fem"' in out


def test_force_lifts_the_time_bound(cli, machine, monkeypatch):
    monkeypatch.setattr(budget, "TIME_BOUND_S", 1e-3)
    args = ("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "0")
    code, _, err = cli(*args)
    one_line_error(code, err, "--mesh-refine 0 would take about", "bound of one run",
                   "not even --mesh-refine 0 fits", "--force")  # fmt: skip
    code, out, err = cli(*args, "--force", "--json")
    assert code == 0, err
    assert '"method": "fem"' in out


def test_force_does_not_lift_the_memory_bound(cli, monkeypatch, no_mesh):
    monkeypatch.setattr(budget, "available_memory", lambda: 8 * 2**20)  # 4 MiB for one run
    for extra in ((), ("--force",)):
        code, _, err = cli("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "0",
                           *extra)  # fmt: skip
        one_line_error(code, err, "--mesh-refine 0 needs about", "of memory",
                       "not even --mesh-refine 0 fits")  # fmt: skip
        assert "--force" not in err


def test_a_memory_refusal_names_a_level_that_also_fits_the_time_bound(cli, machine, no_mesh,
                                                                      monkeypatch):  # fmt: skip
    """Level 2 fits in memory but (estimated 18 s) not in a 10 s bound: the finest named is 1;
    with --force the time does not count, and it is 3."""
    monkeypatch.setattr(budget, "TIME_BOUND_S", 10.0)
    assert cost.collide_plan(0.33, 0.1, 500.0, 2).seconds > 10.0
    args = ("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "9")
    code, _, err = cli(*args)
    one_line_error(code, err, "of memory", "--mesh-refine 1 is the finest that fits")
    code, _, err = cli(*args, "--force")
    one_line_error(code, err, "of memory", "--mesh-refine 3 is the finest that fits")


@pytest.mark.parametrize(
    "args, words",
    [
        (("collide", "--v", "0.1", "--force"), "--force has no effect without --method fem"),
        (("epsilon", "--nu", "0.33", "--v", "0.1", "--force"),
         "--force has no effect with --method modal"),
        (("collide", "--method", "fem", "--v", "0.1", "--mesh-refine", "-1"),
         "--mesh-refine must be a level >= 0, got -1"),
        (("epsilon", "--method", "fem", "--nu", "0.33", "--v", "0.1", "--alpha", "0"),
         "alpha must be positive"),
    ],
)  # fmt: skip
def test_inputs_the_estimate_cannot_take_are_refused_in_one_line(cli, no_mesh, args, words):
    code, _, err = cli(*args)
    one_line_error(code, err, words)


# -- the library ------------------------------------------------------------------------------


def test_the_library_checks_refuse_and_take_force(machine, monkeypatch):
    with pytest.raises(InputError, match=r"refine = 9 needs about .* memory.* refine = 3 is"):
        cost.check_collide(0.33, 0.1, 500.0, 9, force=True)
    with pytest.raises(InputError, match=r"v = 1e-06 would take .* force=True"):
        cost.check_epsilon(0.33, 1e-6)
    assert cost.check_epsilon(0.33, 1e-6, force=True).seconds > budget.TIME_BOUND_S
    with pytest.raises(InputError, match=r"refine = 4 .* refine = 3 is the finest"):
        cost.check_compare(0.33, 0.1, 500.0, 4, 2)
    monkeypatch.setattr(budget, "TIME_BOUND_S", 1e-3)
    with pytest.raises(InputError, match="not even refine = 2 fits"):
        cost.check_compare(0.33, 0.1, 500.0, 3, 2)
