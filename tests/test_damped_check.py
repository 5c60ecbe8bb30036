"""The damped modal model against the quasistatic viscous law (issue 29, docs/damping.md).

The stored points (``laws/data/damped_reference.json``, written by
``python -m restitution.laws.making.damped_check``) are the modal model with every mode damped,
extrapolated alpha, N -> infinity through the production sweeps; the comparison is recomputed
here from the quasistatic route and the shipped elastic laws."""

from __future__ import annotations

import math

import pytest

from restitution.laws.making.damped_check import CHECK_POINTS, compare, load_reference, modal_point


@pytest.fixture(scope="module")
def reference():
    return load_reference()


def test_reference_holds_every_check_point(reference):
    got = {(p["geometry"], p["nu"], p["v"], p["tau"]) for p in reference}
    assert got == set(CHECK_POINTS)


def _comparisons(reference):
    return [
        (p, compare(p["geometry"], p["nu"], p["v"], p["tau"], p["epsilon"], p["epsilon_err"],
                    p["asymptotic_ok"], p["elastic_compression"], p["elastic_compression_err"]))
        for p in reference
    ]  # fmt: skip


def test_slow_damped_sphere_is_the_viscous_law_on_its_own_stiffness(reference):
    """At low speed the damped modal sphere is the elastic law plus the quasistatic viscous law
    on the sphere's own quasistatic stiffness (its elastic modal compression), well within the
    combined error (measured: +0.24 and +0.14 sigma at v = 0.003 and 0.00627)."""
    slow = [(p, c) for p, c in _comparisons(reference) if p["geometry"] == "sphere"
            and p["v"] <= 0.007]  # fmt: skip
    assert len(slow) == 2
    for _, c in slow:
        assert abs(c.sigma_own) < 1.0, c


def test_sum_misses_the_sphere_by_at_most_a_few_percent_of_the_loss(reference):
    """The sphere's sum on its own stiffness misses its damped modal body by less than 3 % of
    the loss (measured: 0.1 %, 0.1 %, 1.9 % at v = 0.003, 0.00627, 0.0131)."""
    spheres = [c for p, c in _comparisons(reference) if p["geometry"] == "sphere"]
    assert len(spheres) == 3
    for c in spheres:
        loss = 1.0 - c.modal**2
        assert abs(loss - (1.0 - c.predicted_own**2)) < 0.03 * loss, c


def test_disk_viscous_loss_differs_from_the_quasistatic_law_by_a_first_order_factor(reference):
    """The damped modal disk does not reproduce the quasistatic viscous law on the paper's 2D
    law: its viscous loss is 0.88-0.89 of it at v = 0.001 and 0.005, 1.05-1.09 at v = 0.02
    (docs/damping.md). The ratio does not depend on tau (0.01-0.05) within a few per cent at
    the slow speed, so the difference is in the first-order viscous loss, not a higher order
    in tau; the damped disk law counts it in its error (DISK_VISCOUS_SPREAD)."""
    from restitution.laws.damped import DISK_VISCOUS_SPREAD

    disks = {(p["v"], p["tau"]): c for p, c in _comparisons(reference) if p["geometry"] == "disk"}
    ratios = {key: c.viscous_ratio for key, c in disks.items()}
    assert set(ratios) >= {(0.001, 0.05), (0.005, 0.01), (0.005, 0.025), (0.005, 0.05)}
    slow = [ratios[(0.005, tau)] for tau in (0.01, 0.025, 0.05)]
    assert max(slow) - min(slow) < 0.01  # linear in tau: one factor at all three
    assert max(slow) < 0.9 and ratios[(0.001, 0.05)] < 0.9  # short of the law, beyond errors
    assert all(abs(c.sigma) > 5 for (v, _), c in disks.items() if v <= 0.005)
    assert min(ratios[(0.02, tau)] for tau in (0.01, 0.025, 0.05)) > 1.0
    # The law's error term covers every measured ratio.
    assert max(abs(r - 1.0) for r in ratios.values()) <= DISK_VISCOUS_SPREAD


@pytest.mark.slow  # 4 s of the default run (stop 79: the default run under 10 min)
def test_sphere_beyond_hertz_by_its_finite_size(reference):
    """On Hertz's law (the published viscoelastic law) the sphere's viscous loss falls short of
    the modal body's by about the factor by which Hertz's compression exceeds the finite
    sphere's, a deviation that grows like sqrt(delta_max) and vanishes as v -> 0."""
    from restitution.laws.damped import SPHERE_SIZE_COEFFICIENT

    ratios = []
    for p, c in _comparisons(reference):
        if p["geometry"] != "sphere":
            continue
        assert c.sigma < -3.0  # the half-space law misses the finite sphere
        modal_viscous = 1.0 - c.modal**2 - (1.0 - c.elastic**2)
        hertz_viscous = 1.0 - c.viscous**2
        excess = modal_viscous / hertz_viscous - 1.0
        stiffer = c.hertz_compression / p["elastic_compression"] - 1.0
        assert excess == pytest.approx(stiffer, rel=0.35)
        ratios.append(excess / math.sqrt(c.hertz_compression))
    # The law's error term covers every measured excess.
    assert 0.25 < min(ratios) and max(ratios) <= SPHERE_SIZE_COEFFICIENT


@pytest.mark.slow
def test_reference_point_is_reproduced(reference, tmp_path):
    """Regression: the fastest stored point, recomputed through a fresh store (the stored value
    is this package's own earlier output)."""
    p = max((p for p in reference if p["geometry"] == "sphere"), key=lambda p: p["v"])
    limit, _ = modal_point(p["geometry"], p["nu"], p["v"], p["tau"], store=tmp_path / "s.db")
    assert limit.epsilon == pytest.approx(p["epsilon"], abs=0.1 * p["epsilon_err"])


@pytest.mark.slow  # 8-18 s of the default run (issue 45: the default run under 10 min)
def test_trajectory_diagnostic_at_a_small_disk():
    """``trajectory_check`` (docs/damping.md) on a small disk, v = 0.02, N = 400, alpha = 869.
    Regression values of this package (measured once, not from an independent route): the damped
    run's extra loss 1.018 times the quasistatic loss on the elastic body's own path, that path's
    loss 0.937 of the 2D law's; at N = 1880 the same wall gave 1.013 and 0.933."""
    from restitution.laws.making.damped_check import trajectory_check

    c = trajectory_check("disk", 0.33, 0.02, 0.05, 400, 869.0)
    assert 0 < c.modal < 1 and 0 < c.on_path < 1 and 0 < c.law < 1
    assert c.modal / c.on_path == pytest.approx(1.018, abs=0.005)
    assert c.on_path / c.law == pytest.approx(0.937, abs=0.005)
