"""Laws of two disks (issue 27): the partner in the store, the sweeps, the laws and the SI edge.

Independent checks: the identity of two identical disks and one disk on a wall at half the
speed, now through the whole pipeline (store keys, walls on the pair's compression scale, mode
windows, both extrapolations); closed forms of the pair's compression scale in its two limits
(identical disks, a rigid and infinitely heavy partner); the lowest modes of both bodies against
a brute-force selection; store keys of wall points unchanged by the new field.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest

from restitution.bodies.cache import get_modes
from restitution.bodies.disk.contact import max_compression_estimate
from restitution.bodies.pair import Partner, pair_of
from restitution.errors import InputError
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.law_nu import law_for
from restitution.laws.si_law import si_law
from restitution.limits.curves import epsilon_at
from restitution.limits.store import PointSpec, Store
from restitution.limits.sweep import DEFAULTS, grid, pair_settings
from restitution.provenance import code_version, package_modules
from restitution.quasistatic.hertz import contact_law, quasistatic_collision
from restitution.quasistatic.hertz_pair import pair_quasistatic_collision

# -- the partner ------------------------------------------------------------------------------


def test_pair_compression_scale_has_both_limits():
    """Eq. (61) written for the pair: identical disks give twice the wall's at half the speed;
    a flat (R2 -> inf), rigid (E2 -> inf), infinitely heavy partner gives the wall's (to the
    order of 1/R2 of the gap's curvature)."""
    w = np.array([1e-3, 0.04, 0.2, 0.6])
    same = Partner(1.0).max_compression(w)
    np.testing.assert_allclose(same, 2 * max_compression_estimate(w / 2), rtol=1e-14)
    wall = Partner(1e6, modulus_ratio=1e12, density_ratio=1e12).max_compression(w)
    np.testing.assert_allclose(wall, max_compression_estimate(w), rtol=1e-6)


def test_pair_compression_scale_follows_the_quasistatic_pair():
    """The scale that sets the pair's walls tracks the full quasistatic approach of the centres
    (2D Hertz of both disks, reduced mass) as the wall's eq. (61) tracks the disk's: the ratio of
    the two is within 2 % of the same ratio on the wall at half the speed (measured: 0.05-1.3 %
    apart at R2/R1 = 1.4 and 2, w = 0.01-0.2; the ratios themselves are 1.02-1.13)."""
    for r in (1.4, 2.0):
        for w in (0.01, 0.04, 0.2):
            q = pair_quasistatic_collision(w, 0.33, radius_ratio=r)
            pair_ratio = Partner(r).max_compression(w) / float(q.max_compression[0])
            qw = quasistatic_collision(contact_law(0.33, "centre"), np.array([w / 2]))
            wall_ratio = max_compression_estimate(w / 2) / float(qw.max_compression[0])
            assert abs(pair_ratio / wall_ratio - 1) < 0.02, (r, w, pair_ratio, wall_ratio)


@pytest.mark.parametrize("partner", [Partner(1.4), Partner(2.0, 2.0, 0.5, nu=0.5)])
def test_partner_pair_holds_the_lowest_modes_of_both(partner):
    """The modes the partner asks each body for (a Weyl share with a margin) hold the pair's
    ``N`` lowest: the same selection as from ``N`` modes of each body."""
    n = 400
    pair = partner.pair(0.33, n)
    full = pair_of(
        get_modes(0.33, n),
        get_modes(partner.nu2(0.33), n),
        radius_ratio=partner.radius_ratio,
        modulus_ratio=partner.modulus_ratio,
        density_ratio=partner.density_ratio,
    ).lowest(n)
    np.testing.assert_array_equal(np.sort(pair.omega), np.sort(full.omega))
    assert np.bincount(pair.member).tolist() == np.bincount(full.member).tolist()


def test_partner_refuses_bad_constants():
    for bad in (0.0, -1.0, math.inf, "x", True):
        with pytest.raises(InputError, match="radius ratio"):
            Partner(bad)


# -- the store ---------------------------------------------------------------------------------


def test_wall_keys_do_not_name_a_partner():
    """A wall point's key is that of the stores written before pairs: no ``partner`` in its
    inputs, the body's own code version."""
    spec = PointSpec(0.33, 0.1, 400.0, 300, options=(("energy_tol", 1e-5),))
    inputs = spec.inputs()
    assert "partner" not in inputs
    assert inputs["code_version"] == code_version("disk")


def test_pair_keys_name_the_partner_and_the_pair_code(tmp_path):
    spec = PointSpec(0.33, 0.1, 400.0, 300, partner=Partner(1.4))
    wall = PointSpec(0.33, 0.1, 400.0, 300)
    assert spec.key() != wall.key()
    assert spec.inputs()["partner"]["radius_ratio"] == (1.4).hex()
    assert spec.code_version == code_version("disk", pair=True) != code_version("disk")
    # The pair's version covers the pair's folder; a body's alone does not.
    pair_modules = set(package_modules("restitution.bodies.pair"))
    assert "restitution.bodies.pair.partner" in pair_modules
    with Store(tmp_path / "s.sqlite") as db:
        db.put_failure(spec, "test")
        (row,) = db.points(all_versions=True)
    assert row.spec == spec and row.spec.partner == Partner(1.4)


# -- the sweep and the limits -------------------------------------------------------------------


def test_pair_settings_carry_the_wall_sweep_over():
    base = replace(DEFAULTS, velocities=(0.01, 0.1), n_modes=(100, 200))
    s = pair_settings(base, Partner(1.4))
    assert s.velocities == (0.02, 0.2)
    assert s.n_modes == (296, 592)  # N (1 + 1.4^2)
    assert pair_settings(base, Partner(1.0)).n_modes == (200, 400)
    # The walls: alpha delta_pair(w) takes the wall's products.
    for w, v in zip(s.velocities, base.velocities, strict=True):
        products = np.array(s.alphas_at(w)) * Partner(1.4).max_compression(w)
        np.testing.assert_allclose(products, np.array(base.alphas_at(v)) * (
            max_compression_estimate(v)), rtol=1e-12)  # fmt: skip
    with pytest.raises(InputError, match="lowest"):
        replace(s, select="ranked")


@pytest.mark.slow  # 8 s of the default run (stop 76: the default run under 10 min)
def test_identical_pair_law_point_is_the_wall_point(tmp_path):
    """Both limits through the sweep, the store and the extrapolation: the identical pair at
    ``w`` (windows ``2N``, walls on the pair's scale) against the disk on the wall at ``w/2``
    (measured |d epsilon| = 7e-15)."""
    store = tmp_path / "s.sqlite"
    wall = replace(DEFAULTS, n_modes=(100, 200, 400))
    pair = pair_settings(wall, Partner(1.0))
    a = epsilon_at(0.33, 0.1, settings=wall, store=store, progress=False)
    b = epsilon_at(0.33, 0.2, settings=pair, store=store, progress=False)
    np.testing.assert_allclose(b.fit.alpha, a.fit.alpha / 2, rtol=1e-12)
    assert abs(b.epsilon - a.epsilon) < 1e-12
    assert b.epsilon_err == pytest.approx(a.epsilon_err, rel=1e-9)
    assert len(grid([0.33], pair)) == len(grid([0.33], wall))


# -- laws -------------------------------------------------------------------------------------


def _pair_law(nu=0.33, r=1.4, scale=1.0):
    v = [0.01, 0.04, 0.2, 0.6]
    eps = [1 - scale * 0.01, 1 - scale * 0.03, 1 - scale * 0.1, 1 - scale * 0.2]
    return EpsilonLaw.from_points(nu, v, eps, [1e-3] * 4, partner=Partner(r))


def test_pair_law_names_its_partner_and_round_trips(tmp_path):
    law = _pair_law()
    assert law_filename(0.33, partner=Partner(1.4)) == "law_pair_r1.4_nu0.33.json"
    assert law_filename(0.33, partner=Partner(2, 3, nu=0.5)) == "law_pair_r2_E3_nu20.5_nu0.33.json"
    path = law.to_json(tmp_path / law_filename(0.33, partner=Partner(1.4)))
    back = EpsilonLaw.from_json(path)
    assert back.partner == Partner(1.4) and back.geometry == "disk"
    assert back.metadata["code_version"] == code_version("disk", pair=True)
    assert "relative normal speed" in back.metadata["units"]
    text = (tmp_path / "t.txt").write_text("") or law.to_table(tmp_path / "t.txt").read_text()
    assert "disk pair (R2/R1 = 1.4)" in text
    with pytest.raises(InputError, match="relative speed"):
        back.epsilon(1.0)


def test_a_pair_law_is_not_served_for_the_wall_and_back(tmp_path):
    path = _pair_law().to_json(tmp_path / "p.json")
    with pytest.raises(InputError, match="pair R2/R1 = 1.4, not of the disk on the wall"):
        law_for(0.33, path=path)
    with pytest.raises(InputError, match="not of the pair R2/R1 = 2"):
        law_for(0.33, path=path, partner=Partner(2.0))
    assert law_for(0.33, path=path, partner=Partner(1.4)).partner == Partner(1.4)


def test_pair_laws_interpolate_in_nu_among_themselves():
    laws = [_pair_law(nu, scale=s) for nu, s in ((0.2, 1.0), (0.33, 1.2), (0.5, 1.4))]
    served = law_for(0.4, laws=laws, partner=Partner(1.4))
    assert served.partner == Partner(1.4)
    assert 1 - 1.4 * 0.1 < served.epsilon(0.2) < 1 - 1.2 * 0.1
    with pytest.raises(InputError, match="not all laws of the asked pair"):
        law_for(0.4, laws=laws, partner=Partner(2.0))


def test_si_law_serves_the_pair_at_the_relative_speed(tmp_path):
    """Glass cylinders (nu_2d = 0.33): w / c into the pair's law (no factor 2), either way
    round; the wall and the identical grain are refused a radius ratio / served as before."""
    path = _pair_law().to_json(tmp_path / "p.json")
    big = si_law(63e9, 0.2481, 2500, "cylinder", "grain", path=path, radius_ratio=1.4)
    small = si_law(63e9, 0.2481, 2500, "cylinder", "grain", path=path, radius_ratio=1 / 1.4)
    c = big.grain.c_m_s
    assert big.k == 1.0 and big.speed_scale_m_s == pytest.approx(c)
    assert big.epsilon(0.2 * c) == pytest.approx(0.9, abs=1e-12)  # a computed point
    assert small.epsilon(0.1 * c) == big.epsilon(0.1 * c)
    assert "1.4 times as large" in big.to_dict([1.0])["against_meaning"]
    with pytest.raises(InputError, match="against='grain'"):
        si_law(63e9, 0.2481, 2500, "cylinder", "wall", radius_ratio=1.4)
    with pytest.raises(InputError, match="radius ratio"):
        si_law(63e9, 0.2481, 2500, "cylinder", "grain", radius_ratio=-2.0)
    same = si_law(63e9, 0.2481, 2500, "cylinder", "grain", radius_ratio=1.0)
    assert same.law.partner is None and same.k == 2.0


# -- the command line ---------------------------------------------------------------------------


def test_cli_curve_writes_a_pair_law(tmp_path, cli):
    out = tmp_path / "out"
    code, text, err = cli(
        "curve", "--nu", "0.33", "--radius-ratio", "1.4", "--v", "0.2", "0.4",
        "--modes", "300", "600", "900", "--store", str(tmp_path / "s.sqlite"), "--out", str(out),
    )  # fmt: skip
    assert code == 0, err
    law = EpsilonLaw.from_json(out / "law_pair_r1.4_nu0.33.json")
    assert law.partner == Partner(1.4)
    assert law.v.tolist() == [0.2, 0.4]
    # The same points from the library with the same settings.
    settings = replace(
        pair_settings(DEFAULTS, Partner(1.4)), velocities=(0.2,), n_modes=(300, 600, 900)
    )
    p = epsilon_at(0.33, 0.2, settings=settings, store=tmp_path / "s.sqlite", run=False)
    assert law.epsilon(0.2) == pytest.approx(p.epsilon, abs=1e-14)


def test_cli_curve_refuses_a_partner_nu_for_several_nus(tmp_path, cli):
    args = ("curve", "--nu", "0.33", "0.9", "--partner-nu", "0.5", "--out", str(tmp_path))
    code, _, err = cli(*args)
    assert code == 2 and "--partner-nu" in err and len(err.strip().splitlines()) == 1


def test_cli_quasistatic_pair_of_identical_disks_is_the_wall_at_half_speed(cli):
    """Two identical disks at w: twice the approach of one disk on the wall at w/2 (centre
    law), the same contact time."""
    args = ("quasistatic", "--nu", "0.33", "--json")
    pair = json.loads(cli(*args, "--radius-ratio", "1", "--v", "0.04")[1])
    wall = json.loads(cli(*args, "--v", "0.02", "--law", "centre")[1])
    assert pair["max_compression"] == pytest.approx(2 * wall["max_compression"], rel=1e-9)
    assert pair["contact_time"] == pytest.approx(wall["contact_time"], rel=1e-9)
    assert pair["inputs"]["radius_ratio"] == 1.0


# -- the figure of the shipped laws ------------------------------------------------------------


def test_pair_figure_draws_the_shipped_laws_and_the_shares():
    """The figure's curves are the laws' points (ratio 1: the disk's law at w/2), and its share
    of the small disk is a direct collision's at the stated settings."""
    from restitution.dynamics.collision import collide
    from restitution.laws.law_load import law
    from restitution.reproduction.figures import pair_epsilon

    curves = pair_epsilon.compute(0.33, (1.0, 1.4), share_speeds=(0.2,), share_window=60)
    one, bi = curves
    np.testing.assert_array_equal(one.w, 2 * law(0.33).v)
    np.testing.assert_array_equal(bi.epsilon, law(0.33, partner=Partner(1.4)).epsilon_points)
    assert one.share_small[0] == pytest.approx(0.5, abs=1e-12)  # identical disks share evenly
    pair = Partner(1.4).pair(0.33, bi.share_modes)
    r = collide(pair, 0.2, pair_epsilon.SHARE_PRODUCT / Partner(1.4).max_compression(0.2))
    first, second = pair.member_energies(r.mode_energy_after)
    assert bi.share_small[0] == pytest.approx(first / (first + second), rel=1e-12)
    assert bi.share_small[0] < 0.5  # the large disk takes the larger share
