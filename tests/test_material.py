"""Material constants in SI units, checked against independent wave-speed formulas and textbook
values, and the modal path's refusal of constants it would ignore."""

import math

import pytest
from numpy.testing import assert_allclose

from restitution import Material, MaterialError, compute_modes, get_modes

# Structural steel: E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3 (e.g. EN 1993-1-1, 3.2.6).
STEEL = dict(E=210e9, nu=0.3, rho=7850.0)


def test_thin_disk_c_is_the_bar_speed_of_steel():
    m = Material.from_3d(plane="stress", **STEEL)
    assert_allclose(m.c, math.sqrt(210e9 / 7850.0), rtol=1e-14)
    # Textbook bar (extensional) wave speed of steel: about 5.1-5.2 km/s (e.g. Kinsler et al.,
    # Fundamentals of Acoustics, table of speeds of sound in solids).
    assert 5.0e3 < m.c < 5.3e3
    # The 2D dilatational speed of a thin plate is the plate speed sqrt(E / (rho (1 - nu^2))).
    assert_allclose(m.c_p, math.sqrt(210e9 / (7850.0 * (1 - 0.09))), rtol=1e-14)


def test_cylinder_wave_speeds_are_the_3d_bulk_speeds():
    # Plane strain: the 2D constants of eq. (2) must reproduce the 3D P and S wave speeds,
    # computed here from the Lame form, an independent route.
    E, nu, rho = STEEL["E"], STEEL["nu"], STEEL["rho"]
    m = Material.from_3d(plane="strain", **STEEL)
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    assert_allclose(m.c_p, math.sqrt((lam + 2 * mu) / rho), rtol=1e-13)
    assert_allclose(m.c_s, math.sqrt(mu / rho), rtol=1e-13)
    # Textbook steel: longitudinal bulk wave about 5.9-6.0 km/s, shear about 3.2 km/s.
    assert 5.8e3 < m.c_p < 6.1e3
    assert 3.1e3 < m.c_s < 3.3e3
    # c itself is the plate speed sqrt(E / (rho (1 - nu^2))), about 5.4 km/s.
    assert_allclose(m.c, math.sqrt(E / (rho * (1 - nu**2))), rtol=1e-14)


def test_from_3d_density_is_per_volume_and_checked():
    a = Material.from_3d(E=70e9, nu=0.33, rho=2700.0)
    assert a.rho == 2700.0
    with pytest.raises(MaterialError, match="density"):
        Material.from_3d(E=70e9, nu=0.33, rho=-1.0)


@pytest.mark.parametrize("kwargs", [dict(E=4.0), dict(rho=2.0), dict(E=210e9, rho=7850.0)])
def test_modal_path_refuses_constants_it_would_ignore(kwargs):
    m = Material(0.33, **kwargs)
    with pytest.raises(MaterialError, match=r"reduced units.*material\.reduced\(\)"):
        compute_modes(m, count=5)
    with pytest.raises(MaterialError, match="reduced units"):
        get_modes(m, count=5, use_cache=False)


def test_reduced_material_gives_the_same_modes_as_its_poisson_number(tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path))
    m = Material.from_3d(plane="strain", **STEEL).reduced()
    assert m.is_reduced and m.nu == pytest.approx(0.3 / 0.7)
    assert_allclose(get_modes(m, count=12).omega, compute_modes(0.3 / 0.7, count=12).omega)


def test_cli_plane_strain_still_reaches_the_modal_path(capsys, tmp_path, monkeypatch):
    import json

    from restitution.cli import main

    monkeypatch.setenv("RESTITUTION_CACHE_DIR", str(tmp_path))
    main(["modes", "--nu", "0.3", "--plane", "strain", "--count", "3", "--format", "json"])
    out = json.loads(capsys.readouterr().out)
    assert_allclose([m["omega"] for m in out["modes"]], compute_modes(0.3 / 0.7, count=3).omega)
