"""Rayleigh's approach (paper eqs. 62-68, corrected per ERRATA): energy left in the modes.

References: the Duhamel integral against DOP853 on the complex amplitudes of eq. (65), and
against DOP853 on the real equation m Q'' = -m omega^2 Q - C P(t) with the energy
(m/2)(Q'^2 + omega^2 Q^2) taken directly from the Hamiltonian.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from restitution.bodies.cache import get_modes
from restitution.errors import InputError
from restitution.quasistatic.hertz import contact_law, quasistatic_trajectory
from restitution.quasistatic.rayleigh import rayleigh_energy

NU = 0.33


@pytest.fixture(scope="module")
def modes():
    return get_modes(NU, count=400)


def test_duhamel_matches_ode_of_eq65(modes):
    few = modes.lowest(30)
    for v in (1e-4, 1e-2):
        a = rayleigh_energy(few, v, method="duhamel")
        b = rayleigh_energy(few, v, method="ivp", rtol=1e-11)
        assert_allclose(a.mode_energy, b.mode_energy, rtol=1e-7, atol=1e-10 * a.energy_fraction)
        assert_allclose(a.contact_time, b.contact_time, rtol=1e-6)


def test_energy_factors_from_the_real_equation(modes):
    # m Q'' = -m w^2 Q - C P(t) from rest; after contact E = (m/2)(Q'^2 + w^2 Q^2).
    law = contact_law(NU, "paper")  # the law rayleigh_energy uses by default
    v = 1e-3
    traj = quasistatic_trajectory(law, v)
    k = int(np.flatnonzero((modes.n == 2) & (modes.l == 0))[0])
    w, C, m = modes.omega[k], modes.C[k], modes.mass

    def rhs(t, y):
        return [y[1], -(w**2) * y[0] - C * float(traj.force(t)) / m]

    sol = solve_ivp(
        rhs, (0.0, traj.contact_time), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-16
    )
    Q, Qd = sol.y[:, -1]
    energy = 0.5 * m * (Qd**2 + w**2 * Q**2) / (0.5 * m * v**2)
    res = rayleigh_energy(modes, v)
    assert_allclose(res.fraction_of(2, 0), energy, rtol=1e-7)


@pytest.mark.parametrize("v", [1e-6, 1e-4, 1e-3])
def test_quadrupole_dominates_at_low_speed(modes, v):
    # Holds at these speeds; near v = 1.6e-5 (eq. 57 as printed) the drive of (2,0) passes
    # through a zero of the pulse's Fourier transform and (3,0) leads (docs/quasistatic.md).
    res = rayleigh_energy(modes, v)
    n, l, share = res.dominant
    assert (n, l) == (2, 0)
    assert share > 0.6


def test_converges_with_number_of_modes(modes):
    Ns = [50, 100, 200, 400]
    tot = np.array([rayleigh_energy(modes.lowest(N), 1e-3).energy_fraction for N in Ns])
    steps = np.abs(np.diff(tot))
    assert np.all(np.diff(tot) > 0.0)  # every added mode takes energy, none gives it back
    assert np.all(np.diff(steps) < 0.0)
    assert steps[-1] / tot[-1] < 1e-3


def test_bad_input(modes):
    with pytest.raises(InputError):
        rayleigh_energy(modes, 0.5)  # beyond the monotonic branch of the law
    with pytest.raises(InputError):
        rayleigh_energy(modes, 1e-3, method="rk4")


def test_fig12_compute_and_plot(tmp_path):
    from restitution.reproduction.figures import fig12_rayleigh

    data = fig12_rayleigh.compute(
        NU, n_modes=60, n_v=4, v_min=1e-4, v_max=1e-2, dynamic=([0.01], [0.02])
    )
    assert data.dynamic_ok.tolist() == [True]  # no statuses given: all counted as checked
    fig12_rayleigh.plot(data, tmp_path / "fig12.png")
    assert (tmp_path / "fig12.png").stat().st_size > 1000
    marked = fig12_rayleigh.compute(
        NU, n_modes=60, n_v=4, v_min=1e-4, v_max=1e-2,
        dynamic=([0.005, 0.01], [0.03, 0.02], [False, True]),
    )  # fmt: skip
    assert marked.dynamic_ok.tolist() == [False, True]
    fig12_rayleigh.plot(marked, tmp_path / "fig12_marked.png")
    assert (tmp_path / "fig12_marked.png").stat().st_size > 1000
    ref = rayleigh_energy(get_modes(NU, count=60), 1e-4).energy_fraction
    assert_allclose(data.total[0], ref, rtol=1e-12)
    assert np.all(data.quadrupole <= data.total)


def test_cli_json_and_errors():
    from click.testing import CliRunner

    from restitution.cli.quasistatic import quasistatic

    runner = CliRunner()
    res = runner.invoke(quasistatic, ["--nu", "0.33", "--v", "0.01", "--json", "--modes", "60"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.output)
    for key in (
        "max_compression",
        "contact_time",
        "rayleigh_energy_fraction",
        "eq61_max_compression",
        "eq61_contact_time",
    ):
        assert math.isfinite(out[key])
    # v = 0.01: delta_max = 0.0245210 R, tau = 7.49016 R/c (this module's quadrature, checked
    # against DOP853 in tests/test_hertz.py).
    assert_allclose(out["max_compression"], 0.0245210, rtol=1e-5)
    assert_allclose(out["contact_time"], 7.49016, rtol=1e-5)
    bad = runner.invoke(quasistatic, ["--v", "0.5"])
    assert isinstance(bad.exception, InputError)
    assert "use a smaller v" in str(bad.exception)
    bad = runner.invoke(quasistatic, ["--v", "0"])
    assert isinstance(bad.exception, InputError)


@pytest.mark.slow  # 4 s of the default run (stop 79: the default run under 10 min)
def test_the_drive_of_many_modes_is_built_in_blocks(monkeypatch):
    """Issue 30: the cosine table of the drive grew like N^(3/2) (150000 disk modes took 24 GB).
    20000 frequencies up to 300 c/R at v = 0.01 need about 12000 quadrature nodes: a 1.9 GB
    table at once. Built in blocks, the peak stays below 256 MB, and the blocks change the
    numbers by round-off only (against one block: 1 of 401 rows moved, by 4e-18 of the largest
    drive)."""
    import tracemalloc

    from restitution.quasistatic import pulse as pulse_module

    p = pulse_module.force_pulse(contact_law(0.33, "paper"), 0.01, mass=math.pi)
    omega = np.linspace(1.0, 300.0, 20000)
    tracemalloc.start()
    try:
        blocked = pulse_module.pulse_drive(p, omega)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 256 * 2**20, peak
    pick = np.r_[np.arange(0, omega.size, 50), omega.size - 1]  # the nodes follow omega.max()
    monkeypatch.setattr(pulse_module, "_BLOCK", 1 << 40)  # one block
    one = pulse_module.pulse_drive(p, omega[pick])
    assert np.max(np.abs(one - blocked[pick])) <= 1e-15 * np.max(np.abs(one))
