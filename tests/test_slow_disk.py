"""The disk's slow impacts (restitution.quasistatic.slow_disk): the model's own checks, its
leading behaviour against Rayleigh's Duhamel integral, and the model against the finite elements
and the modal laws where their speeds meet."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from _sampling import representatives
from scipy.integrate import solve_ivp

from restitution.bodies.cache import get_modes
from restitution.errors import InputError
from restitution.laws.law_file import law_filename
from restitution.laws.law_point import leave_one_out
from restitution.laws.making.production import SHIPPED_NUS
from restitution.quasistatic.hertz import contact_law, quasistatic_collision
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.quasistatic.slow_disk import (
    MODEL_SPREAD,
    SLOW_MODES,
    asymptotic_loss,
    equations,
    shifted_law,
    slow_collision,
    slow_loss,
)

_DATA = __import__("importlib.resources").resources.files("restitution.laws") / "data"


@pytest.fixture(scope="module")
def modes():
    return get_modes(0.33, SLOW_MODES, geometry="disk")


def test_no_moving_modes_is_the_quasistatic_collision(modes):
    """With the cut below every mode the model is m delta'' = -P(delta) with the centre law:
    its contact time and compression are the quasistatic collision's and nothing is lost."""
    for v in (1e-6, 1e-4):
        r = slow_collision(modes, v, 0.0)
        qs = quasistatic_collision(contact_law(0.33, "centre"), v)
        assert r.n_dynamic == 0
        assert r.contact_time == pytest.approx(float(qs.contact_time[0]), rel=1e-7)
        assert r.max_compression == pytest.approx(float(qs.max_compression[0]), rel=1e-4)
        assert abs(r.energy_loss) < 1e-8


def test_the_loss_is_the_energy_in_the_moving_modes(modes):
    """Energy conservation: 1 - epsilon^2 equals the energy left in the kept modes, and both
    are positive."""
    r = slow_collision(modes, 1e-4, 10.0)
    assert r.n_dynamic > 40
    assert r.energy_loss > 1e-3
    assert r.energy_error < 1e-9 * r.energy_loss / 1e-3
    assert np.all(r.mode_energy >= 0)


def test_the_model_is_time_reversible(modes):
    """Run to the separation, reverse every velocity, run as long again: the start comes back
    (delta = 0, delta' = -v, modes at rest)."""
    v, cut = 1e-5, 7.07
    law, keep = shifted_law(modes, cut)
    om, C = modes.omega[keep], modes.C[keep]
    _, rhs = equations(law, om, C, modes.mass)
    r = slow_collision(modes, v, cut)
    y0 = np.zeros(2 + 2 * om.size)
    y0[1] = v
    opts = dict(method="DOP853", rtol=1e-11, atol=1e-15 * v)
    there = solve_ivp(rhs, (0, r.contact_time), y0, **opts).y[:, -1]
    flipped = there.copy()
    flipped[1] *= -1
    flipped[2 + om.size :] *= -1
    back = solve_ivp(rhs, (0, r.contact_time), flipped, **opts).y[:, -1]
    assert abs(back[1] + v) < 1e-7 * v
    assert np.max(np.abs(back[2 + om.size :])) < 1e-6 * v
    assert abs(back[0]) < 1e-6 * r.max_compression


@pytest.mark.slow  # 5 s of the default run (stop 79: the default run under 10 min)
def test_the_loss_converges_in_the_cut(modes):
    """At v = 1e-6 the change of the loss from one cut to the next (a factor sqrt(2)) falls, from
    Omega = 7.07 on, like a power of the cut between -4.5 and -2 (measured: -3.0; the dropped
    modes keep the kink's energy C_k^2 / omega_k^4 summed beyond Omega, a tail ~ Omega^-3)."""
    r = slow_loss(modes, 1e-6)
    steps = np.abs(np.diff(r.losses))[1:]
    slope = np.polyfit(np.log(np.asarray(r.cuts[2:])), np.log(steps), 1)[0]
    assert -4.5 < slope < -2.0, (r.cuts, r.losses)
    assert r.convergence_err < 0.01 * r.energy_loss


def test_the_error_counts_the_model_and_the_cut(modes):
    r = slow_loss(modes, 1e-5)
    assert r.model_err == pytest.approx(MODEL_SPREAD * r.energy_loss)
    assert r.energy_loss_err == pytest.approx(r.model_err + r.convergence_err)
    assert r.epsilon == pytest.approx(math.sqrt(1 - r.energy_loss))
    assert r.epsilon_err == pytest.approx(r.energy_loss_err / (2 * r.epsilon))
    assert len(r.cuts) == 6 and r.cuts[-1] == pytest.approx(28.28)


def _fem_points():
    data = json.loads((_DATA / "fem_reference.json").read_text())
    return [p for p in data["points"] if p["v"] <= 1e-3]


@pytest.mark.parametrize("point", _fem_points(), ids=lambda p: f"nu{p['nu']}-v{p['v']:g}")
def test_the_model_meets_the_finite_elements(point):
    """The finite-element route (laws/data/fem_reference.json: both limits of graded meshes)
    and the model agree within two combined errors at v = 1e-4 and 1e-3, nu = 0.33 and 0.9
    (the model's MODEL_SPREAD was read off the largest relative difference at 1e-4, so at
    nu = 0.33, v = 1e-4 this is a consistency check, not an independent one)."""
    m = get_modes(point["nu"], SLOW_MODES, geometry="disk")
    r = slow_loss(m, point["v"])
    both = math.hypot(r.energy_loss_err, point["energy_loss_err"])
    assert abs(r.energy_loss - point["energy_loss"]) < 2 * both, (r.energy_loss, point)
    assert abs(r.energy_loss / point["energy_loss"] - 1) < 0.02


def _modal_point(nu, v):
    meta = json.loads((_DATA / law_filename(nu, "disk", None)).read_text())["metadata"]
    return next(p for p in meta["points"] if p["v"] == v)


@pytest.mark.parametrize("nu", [0.33, 0.9])
@pytest.mark.parametrize("v", [5e-4, 1e-3])
def test_the_model_meets_the_modal_law(nu, v):
    """Where the modal law's slow points pass their checks, the model agrees within two
    combined errors (all nine laws at four speeds: the slow test below)."""
    p = _modal_point(nu, v)
    assert p["status"] == "ok"
    r = slow_loss(get_modes(nu, SLOW_MODES, geometry="disk"), v)
    both = math.hypot(r.energy_loss_err, p["energy_loss_err"])
    assert abs(r.energy_loss - p["energy_loss"]) < 2 * both


@pytest.mark.slow
def test_the_model_meets_every_modal_law():
    """All nine shipped disk laws at v = 1e-4, 2e-4, 5e-4, 1e-3 (flagged points included):
    within two combined errors at every one of the 36 (measured: at most 1.7)."""
    worst = 0.0
    for nu in SHIPPED_NUS:
        m = get_modes(nu, SLOW_MODES, geometry="disk")
        for v in (1e-4, 2e-4, 5e-4, 1e-3):
            p = _modal_point(nu, v)
            r = slow_loss(m, v)
            both = math.hypot(r.energy_loss_err, p["energy_loss_err"])
            worst = max(worst, abs(r.energy_loss - p["energy_loss"]) / both)
    assert worst < 2.0


def test_the_leading_behaviour_is_rayleighs_limit():
    """The closed-form leading behaviour (asymptotic_loss: the pulse's two ends, to first order
    in 1 / Lambda) tends to Rayleigh's Duhamel integral on the quasistatic pulse, which is
    computed by quadrature: within 4 % at 1e-6, within 1 % below 1e-16."""
    m = get_modes(0.33, 400, geometry="disk")
    law = contact_law(0.33, "centre")
    for v, tol in ((1e-6, 0.04), (1e-24, 0.01), (1e-48, 0.01)):
        exact = rayleigh_energy(m, v, law).energy_fraction
        assert asymptotic_loss(m, [v])[0] == pytest.approx(exact, rel=tol)


def test_the_loss_falls_like_the_inverse_square_log():
    """The leading behaviour's scale: (4 pi^2 / m^2) sum C^2 / omega^4 / ln^2(1/v) bounds the
    loss (times the 1/L_k factors' ratio to 1/ln(1/v)), so ln^2(1/v) (1 - epsilon^2) stays
    bounded from 1e-6 to 1e-64 while the loss falls a hundredfold."""
    m = get_modes(0.33, 400, geometry="disk")
    v = np.array([1e-6, 1e-16, 1e-32, 1e-64])
    loss = asymptotic_loss(m, v)
    bound = 4 * math.pi**2 / m.mass**2 * np.sum(m.C**2 / m.omega**4)
    scaled = loss * np.log(1 / v) ** 2
    assert np.all(scaled < 1.5 * bound)
    assert loss[0] / loss[-1] > 20


def test_refusals(modes):
    with pytest.raises(InputError, match="derived for the disk"):
        slow_collision(get_modes(0.3, 40, geometry="sphere"), 1e-4, 5.0)
    with pytest.raises(InputError, match="outside the slow-impact model's range"):
        slow_loss(modes, 0.05)
    with pytest.raises(InputError, match="reaches the contact width"):
        slow_collision(modes, 1e-3, 28.28)
    with pytest.raises(InputError, match="use the modal law there"):
        slow_loss(modes, 5e-3)
    with pytest.raises(InputError, match="load more modes"):
        slow_collision(modes.lowest(20), 1e-4, 10.0)


def test_leave_one_out_sees_a_kink_and_not_a_line():
    v = np.linspace(1.0, 2.0, 11)
    assert np.max(leave_one_out(v, 3 * v + 1)) < 1e-12
    kinked = np.abs(v - 1.5)
    gaps = leave_one_out(v, kinked)
    assert gaps[5] > 0.05 and gaps[2] < 1e-12


_DISK_FILES = [law_filename(nu, "disk", None) for nu in SHIPPED_NUS]


@pytest.mark.parametrize("name", _DISK_FILES)
def test_shipped_disk_laws_continue_to_the_low_speeds(name):
    """Every shipped disk law carries the low-speed points at production.DISK_LOW_SPEEDS, below
    its modal points, flagged 'quasistatic'; each point's error is the model's plus what PCHIP
    through its neighbours misses (leave_one_out of the stored losses)."""
    from restitution.laws.making.production import DISK_LOW_SPEEDS

    meta = json.loads((_DATA / name).read_text())["metadata"]
    low = [p for p in meta["points"] if p.get("route") == "quasistatic"]
    modal = [p for p in meta["points"] if p.get("route") != "quasistatic"]
    assert [p["v"] for p in low] == list(DISK_LOW_SPEEDS)
    assert max(p["v"] for p in low) < min(p["v"] for p in modal) == 1e-4
    assert all(p["status"] == "quasistatic" and not p["asymptotic_ok"] for p in low)
    gaps = leave_one_out([p["v"] for p in low], [p["energy_loss"] for p in low])
    np.testing.assert_allclose([p["interpolation_err"] for p in low], gaps, rtol=1e-9)
    np.testing.assert_allclose(
        [p["energy_loss_err"] for p in low],
        [p["estimate_err"] + p["interpolation_err"] for p in low],
        rtol=1e-12,
    )
    for p in low:
        assert p["epsilon"] == pytest.approx(math.sqrt(1 - p["energy_loss"]), rel=1e-12)
    assert meta["low_speed"]["n_modes"] == SLOW_MODES


@pytest.mark.parametrize("nu", representatives([0.33, 0.9], {0.33}))
def test_shipped_disk_low_speed_points_have_not_moved(nu):
    """The stale-data test of the disk's low-speed points: three of them (both ends and the
    middle) recomputed by the current code give the stored loss and estimate error (the other
    laws: the slow test)."""
    _recompute_sample(law_filename(nu, "disk", None))


@pytest.mark.slow
@pytest.mark.parametrize("nu", [nu for nu in SHIPPED_NUS if nu not in (0.33, 0.9)])
def test_every_shipped_disk_low_speed_point_sample_has_not_moved(nu):
    _recompute_sample(law_filename(nu, "disk", None))


def _recompute_sample(name):
    import warnings

    from restitution.laws.law import EpsilonLaw
    from restitution.laws.low_speed import low_speed_points
    from restitution.provenance import quasistatic_code_version

    served = EpsilonLaw.from_json(_DATA / name)
    meta = served.metadata
    low = [p for p in meta["points"] if p.get("route") == "quasistatic"]
    sample = [low[0], low[len(low) // 2], low[-1]]
    redo, _ = low_speed_points(
        meta["nu"], [p["v"] for p in sample], geometry="disk", partner=served.partner
    )
    for p, q in zip(sample, redo, strict=True):
        assert q["energy_loss"] == pytest.approx(p["energy_loss"], rel=1e-9), (
            f"{name}: the low-speed point v = {p['v']} moved; regenerate with `python -m "
            "restitution.laws.making.production --low-speeds-only` (--geometry pair for two disks)"
        )
        assert q["estimate_err"] == pytest.approx(p["estimate_err"], rel=1e-9)
    now = quasistatic_code_version("disk", "slow-modal", pair=served.partner is not None)
    if meta["low_speed"]["code_version"] != now:
        warnings.warn(
            f"{name}'s low-speed points were computed with code "
            f"{meta['low_speed']['code_version']}, this is {now}; the sampled points have not "
            "moved",
            stacklevel=1,
        )


# -- two disks ------------------------------------------------------------------------------


def test_two_identical_disks_are_the_disk_on_a_wall_at_half_the_speed(modes):
    """The pair's closure is twice the wall's compliance, its kept modes both disks' (the
    antisymmetric combinations stay at rest): at w the loss, the contact time and the energy in
    the modes are the wall's at w/2."""
    from restitution.bodies.pair.body import pair_of

    both = pair_of(modes)
    for w in (2e-6, 2e-4):
        wall = slow_collision(modes, w / 2, 10.0)
        pair = slow_collision(both, w, 10.0)
        assert pair.n_dynamic == 2 * wall.n_dynamic
        assert pair.energy_loss == pytest.approx(wall.energy_loss, rel=1e-8)
        assert pair.contact_time == pytest.approx(wall.contact_time, rel=1e-9)
        assert pair.mode_energy.sum() == pytest.approx(wall.mode_energy.sum(), rel=1e-8)


def test_the_pair_model_meets_the_pair_law():
    """Two disks of radii 1 and 2 (nu = 0.33) at w = 2e-3, the pair law's slowest modal point
    (it passes its checks): within two combined errors (measured: 0.3)."""
    from restitution.bodies.pair.partner import Partner
    from restitution.quasistatic.slow_disk import slow_modes

    partner = Partner(radius_ratio=2.0)
    meta = json.loads((_DATA / law_filename(0.33, "disk", partner)).read_text())["metadata"]
    p = next(p for p in meta["points"] if p["v"] == 2e-3)
    assert p["status"] == "ok"
    r = slow_loss(slow_modes(0.33, partner), 2e-3)
    both = math.hypot(r.energy_loss_err, p["energy_loss_err"])
    assert abs(r.energy_loss - p["energy_loss"]) < 2 * both


def _pair_files():
    from restitution.bodies.pair.partner import Partner
    from restitution.laws.making.production import PAIR_NUS, PAIR_RADIUS_RATIOS, PAIR_TWO_MATERIALS

    return [
        law_filename(nu, "disk", Partner(radius_ratio=r))
        for r in PAIR_RADIUS_RATIOS
        for nu in PAIR_NUS
    ] + [law_filename(nu, "disk", partner) for nu, partner in PAIR_TWO_MATERIALS]


@pytest.mark.parametrize("name", _pair_files())
def test_shipped_pair_laws_continue_to_the_low_speeds(name):
    """Every shipped law of two disks carries the low-speed points at
    production.PAIR_LOW_SPEEDS below its modal points, with the same error rule as the disk's."""
    from restitution.laws.making.production import PAIR_LOW_SPEEDS

    meta = json.loads((_DATA / name).read_text())["metadata"]
    low = [p for p in meta["points"] if p.get("route") == "quasistatic"]
    modal = [p for p in meta["points"] if p.get("route") != "quasistatic"]
    assert [p["v"] for p in low] == list(PAIR_LOW_SPEEDS)
    assert max(p["v"] for p in low) < min(p["v"] for p in modal)
    gaps = leave_one_out([p["v"] for p in low], [p["energy_loss"] for p in low])
    np.testing.assert_allclose([p["interpolation_err"] for p in low], gaps, rtol=1e-9)
    np.testing.assert_allclose(
        [p["energy_loss_err"] for p in low],
        [p["estimate_err"] + p["interpolation_err"] for p in low],
        rtol=1e-12,
    )


@pytest.mark.slow  # 14-67 s of the default run (issue 45: the default run under 10 min)
def test_a_shipped_pair_low_speed_sample_has_not_moved():
    """The stale-data test of one pair law's low-speed points (R2/R1 = 1.4, nu = 0.33)."""
    from restitution.bodies.pair.partner import Partner

    _recompute_sample(law_filename(0.33, "disk", Partner(radius_ratio=1.4)))


def test_the_slow_end_figure(tmp_path):
    """docs/figures/disk_low_speed.png: the law's two routes, the finite elements at that nu,
    Rayleigh's estimate and the leading form; the law's low-speed points are its quasistatic
    ones and reach 1e-7."""
    from restitution.reproduction.figures import disk_low_speed

    s = disk_low_speed.compute(0.33, n_rayleigh=3)
    assert s.v[0] == pytest.approx(1e-7) and s.v.max() <= 0.02
    assert s.quasistatic.sum() == 100 and not s.quasistatic[s.v >= 1e-4].any()
    assert list(s.fem_v) == [1e-5, 1e-4, 1e-3, 1e-2]
    assert np.isfinite(s.rayleigh).sum() == 3 and np.all(s.leading > 0)
    path = tmp_path / "slow.png"
    disk_low_speed.plot([s], path)
    assert path.stat().st_size > 10_000


# -- what a DEM user asks (issue 28's "done when") -------------------------------------------

_CYLINDERS = {
    "steel": ("210e9", "0.3", "7850"),
    "glass": ("63e9", "0.2481", "2500"),
}


@pytest.mark.parametrize("material", sorted(_CYLINDERS))
@pytest.mark.parametrize("against", ["wall", "grain"])
def test_cylinders_get_epsilon_at_granular_speeds_in_one_command(cli, material, against):
    """Steel and glass cylinders at 0.01, 0.1, 1 and 10 m/s, against a wall and as two
    grains: every speed gets epsilon with an error (none is `outside`); below the collisions
    the value is the slow-impact model's (status quasistatic), and its error is larger than
    the model's own 1.2 % of the loss."""
    E, nu, rho = _CYLINDERS[material]
    args = ("--E", E, "--nu", nu, "--rho", rho, "--geometry", "cylinder", "--against", against)
    code, out, err = cli("law", *args, "--speed", "0.01", "0.1", "1", "10", "--json")
    assert code == 0, err
    points = json.loads(out)["points"]
    assert [p["speed_m_s"] for p in points] == [0.01, 0.1, 1, 10]
    for p in points:
        assert p["epsilon"] is not None and 0.97 < p["epsilon"] < 1, p
        assert p["epsilon_err"] > 0
        loss = 1 - p["epsilon"] ** 2
        assert 2 * p["epsilon"] * p["epsilon_err"] >= MODEL_SPREAD * loss * (1 - 1e-9) or (
            not p["status"].startswith("quasistatic")
        )
    assert points[0]["status"].startswith("quasistatic")
