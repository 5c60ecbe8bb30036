"""Two bodies meeting head-on (restitution.bodies.pair): the pair as one modal body.

Independent checks: two identical bodies against the same body on a wall at half the speed
(mirror symmetry; the module's alpha mapping alpha_wall = 2 alpha), the loss booked in both
bodies, and the limit of a partner that is much larger, heavier and stiffer (it tends to the
rigid wall). The checks every body passes (scipy's DOP853 with the dense surface matrix of each
body, time reversal, the rigid limits, the energy balance, the kernel against the NumPy path)
run for an unequal pair in tests/test_every_body.py.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from numpy.testing import assert_allclose

from restitution import get_modes
from restitution.bodies.base import ModalBody
from restitution.bodies.kinds import KINDS
from restitution.bodies.pair import BodyPair, pair_of
from restitution.dynamics.collision import collide
from restitution.errors import InputError

V, ALPHA = 0.05, 500.0


@pytest.fixture(scope="module")
def disk():
    return get_modes(0.33, count=60)


@pytest.mark.parametrize("geometry", ["disk", "sphere"])
def test_identical_pair_is_the_body_on_a_wall_at_half_speed(geometry):
    """Relative speed 2v and alpha / 2 against the wall at v and alpha: the same collision to
    round-off (measured 1.8e-14 for the disk, 1.0e-14 for the sphere in epsilon)."""
    body = get_modes(0.3 if geometry == "sphere" else 0.33, count=60, geometry=geometry)
    pair = pair_of(body)
    assert isinstance(pair, ModalBody) and pair.identical and len(pair) == 2 * len(body)
    assert pair.geometry == f"{geometry}-pair" and pair.mass == pytest.approx(body.mass / 2)
    wall = collide(body, V, ALPHA)
    both = collide(pair, 2 * V, ALPHA / 2)
    assert abs(both.epsilon - wall.epsilon) < 1e-12
    assert both.n_steps == wall.n_steps
    assert both.contact_time == pytest.approx(wall.contact_time, rel=1e-12)
    # The separation of the centres moves twice as far as the centre against the wall.
    assert both.max_compression == pytest.approx(2 * wall.max_compression, rel=1e-12)
    # Each body keeps what the body on the wall keeps; as fractions of (mu/2) w^2 = 2 (m/2) v^2
    # that is half of it, mode by mode.
    first, second = pair.member_energies(both.mode_energy_after)
    assert first == pytest.approx(second, rel=1e-12)
    assert first == pytest.approx(0.5 * wall.mode_energy_after.sum(), rel=1e-10)
    assert_allclose(
        both.mode_energy_after[pair.member == 0], 0.5 * wall.mode_energy_after, atol=1e-14
    )


def test_unequal_pair_books_its_loss_in_both_bodies(disk):
    """Radius ratio 1.4, twice as stiff, half as dense, another Poisson number: whatever the
    relative motion lost sits in the two bodies' modes, each taking a part (measured
    |first + second - (1 - epsilon^2)| = 1e-12 at energy_tol 1e-10). The pair's agreement with
    DOP853 and its time reversal: tests/test_every_body.py."""
    pair = pair_of(
        disk.lowest(24),
        get_modes(0.5, count=24),
        radius_ratio=1.4,
        modulus_ratio=2.0,
        density_ratio=0.5,
    )
    r = collide(pair, 0.1, 250.0, energy_tol=1e-10)
    assert r.energy_drift < 1e-10
    first, second = pair.member_energies(r.mode_energy_after)
    assert first > 0 and second > 0
    assert first + second == pytest.approx(1.0 - r.epsilon**2, abs=1e-9)


def test_a_large_heavy_stiff_partner_tends_to_the_wall(disk):
    """A partner of radius R, modulus R^2 and density R^2 (same wave speed) against the disk on
    the wall at the same speed and alpha: the difference falls like 1/R (the gap's curvature
    1 + 1/R; measured 1.4e-5 at R = 100 and 1.6e-6 at R = 1000)."""
    wall = collide(disk, V, ALPHA).epsilon
    gaps = []
    for R in (100.0, 1000.0):
        big = pair_of(disk, disk, radius_ratio=R, modulus_ratio=R**2, density_ratio=R**2)
        gaps.append(abs(collide(big, V, ALPHA).epsilon - wall))
    assert gaps[1] < 1e-5
    assert 5.0 < gaps[0] / gaps[1] < 20.0


def test_lowest_is_a_common_frequency_cutoff(disk):
    pair = pair_of(disk, disk, radius_ratio=1.4)  # the larger disk's modes lie lower
    low = pair.lowest(80)
    kept = np.sort(low.omega)
    assert np.all(np.diff(low.omega) >= 0)
    dropped = np.setdiff1d(np.arange(len(pair)), low.index)
    assert pair.omega[dropped].min() >= kept[-1]
    n1, n2 = np.bincount(low.member, minlength=2)
    assert n2 > n1  # about 1.4 times as many below one frequency
    assert isinstance(low, BodyPair) and low.take([0]).omega[0] == low.omega[0]


def test_pair_refuses_what_it_cannot_be(disk, monkeypatch):
    sphere = get_modes(0.3, count=10, geometry="sphere")
    with pytest.raises(InputError, match="two bodies of one kind"):
        pair_of(disk, sphere)
    with pytest.raises(InputError, match="radius_ratio must be a positive number"):
        pair_of(disk, radius_ratio=-1.0)
    # A kind without a surface basis at arbitrary angles pairs only bodies of one radius.
    monkeypatch.setitem(KINDS, "sphere", replace(KINDS["sphere"], basis_at=None))
    with pytest.raises(InputError, match="different radii are not implemented"):
        pair_of(sphere, radius_ratio=1.4).surface_quadrature(64)
    with pytest.raises(InputError, match="only 120"):
        pair_of(disk).lowest(121)


def test_cli_collides_two_disks(capsys):
    """``restitution collide --radius-ratio``: an identical pair answers what the wall answers
    at half the speed and twice the hardness; a bidisperse pair splits the loss between its
    disks; options that a pair would ignore are refused."""
    import json

    from restitution.cli import main

    def run(*args):
        main(["collide", "--nu", "0.33", "--json", *args])
        return json.loads(capsys.readouterr().out)

    wall = run("--v", "0.05", "--alpha", "500", "--modes", "60")
    pair = run("--v", "0.1", "--alpha", "250", "--modes", "120", "--radius-ratio", "1")
    assert abs(pair["epsilon"] - wall["epsilon"]) < 1e-12
    assert pair["pair"]["modes"] == [60, 60]
    assert "relative normal speed" in pair["units"]["speed"]
    bi = run("--v", "0.05", "--alpha", "500", "--modes", "200", "--radius-ratio", "1.4")
    first, second = bi["pair"]["energy_after"]
    assert first > 0 and second > 0
    assert first + second == pytest.approx(1 - bi["epsilon"] ** 2, abs=1e-5)
    assert bi["inputs"]["radius_ratio"] == 1.4 and bi["inputs"]["partner_nu"] == 0.33
    with pytest.raises(SystemExit):
        main(["collide", "--v", "0.05", "--radius-ratio", "1.4", "--method", "fem"])
    assert "no effect for two bodies" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["collide", "--v", "0.05", "--radius-ratio", "-2"])
    assert "--radius-ratio must be a positive number" in capsys.readouterr().err


def test_pair_hertz_law_is_the_sum_of_both_disks_at_one_contact_width():
    """The pair's 2D Hertz law (quasistatic/hertz_pair.py) against its definition written out:
    delta_1 + delta_2 with each disk's eq. (57) at the common Hertz half-width b; for identical
    disks twice the wall's law at the same force."""
    import math

    from restitution.quasistatic.hertz import contact_law
    from restitution.quasistatic.hertz_pair import pair_contact_law

    P = np.array([1e-5, 1e-3, 1e-2])
    r2, e2, nu1, nu2 = 1.4, 2.5, 0.33, 0.5
    pair = pair_contact_law(nu1, nu2, radius_ratio=r2, modulus_ratio=e2)
    r_eff, e_eff = 1 / (1 + 1 / r2), 1 / (1 + 1 / e2)
    b = np.sqrt(4 * P * r_eff / (math.pi * e_eff))
    by_hand = sum(
        P / (math.pi * E) * (2 * np.log(4 * R / b) + contact_law(nu).constant)
        for E, R, nu in ((1.0, 1.0, nu1), (e2, r2, nu2))
    )
    assert_allclose(pair.compression(P), by_hand, rtol=1e-12)
    same = pair_contact_law(nu1)
    assert_allclose(same.compression(P), 2 * contact_law(nu1).compression(P), rtol=1e-12)


@pytest.mark.slow  # 7 s of the default run (stop 76: the default run under 10 min)
def test_modal_pair_approaches_the_quasistatic_pair():
    """Bidisperse disks (R2/R1 = 1.4, 400 lowest modes of both, alpha = 4000): the modal contact
    time approaches the quasistatic one of the pair's law as the speed falls (measured 9.4 % off
    at w = 0.2, 0.14 % at w = 0.04; identical disks 9.1 % and 0.40 %, as the disk on a wall)."""
    from restitution.quasistatic.hertz_pair import pair_quasistatic_collision

    pool = get_modes(0.33, count=400)
    pair = pair_of(pool, pool, radius_ratio=1.4).lowest(400)
    dev = []
    for w in (0.2, 0.04):
        tau = collide(pair, w, 4000.0).contact_time
        quasi = pair_quasistatic_collision(w, 0.33, radius_ratio=1.4).contact_time[0]
        dev.append(abs(tau / quasi - 1.0))
    assert dev[1] < dev[0] / 10
    assert dev[1] < 0.01
