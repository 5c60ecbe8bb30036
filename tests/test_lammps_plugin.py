"""The LAMMPS plugin (pair_style restitution, fix wall/restitution) and its Python side.

Fast: the universal map beta(epsilon) of Tsuji's damping against an independent integration
(Radau, dimensional variables) and against the closed form of Antypov & Elliott (which LAMMPS's
``coeff_restitution`` uses), its limits and its grid's interpolation error; the table file read
back by a reader of its grammar written here; the slow-impact continuation at ``w = 0``, tiny
``w`` and ``w0``. Slow: the plugin built into a temporary folder and run in the PyPI wheel's
``lmp``: rebound ratios of steel cylinders (2D) and spheres (3D) against the law within its
error, per-contact state, the refusal above the table's range, the C++ reader against Python.
"""

import math
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

import restitution
from restitution.errors import InputError
from restitution.laws.exports import lammps_plugin as lp
from restitution.laws.exports.below import SlowContinuation
from restitution.laws.exports.pchip import pchip_table

STEEL = dict(E=210e9, nu=0.3, rho=7850.0)
BETA_CRITICAL = 2.0 * math.sqrt(5.0 / 6.0)  # beta' = sqrt(3/2) beta = sqrt(5)

# -- the universal map --------------------------------------------------------------------------


def _dimensional_epsilon(beta, w, estar=1.15e11, rstar=0.005, mstar=0.0164):
    """epsilon of one Hertz + Tsuji contact in SI variables (m, s), integrated by Radau: an
    independent route (another method, another scaling, a physical impact speed)."""
    k0 = 4.0 / 3.0 * estar * math.sqrt(rstar)
    tc = 3.2181 * (mstar**2 / (k0**2 * w)) ** 0.2  # Hertz's contact time
    delta_max = (5.0 * mstar * w**2 / (4.0 * k0)) ** 0.4  # scale of the overlap

    def rhs(_t, y):
        d, v = y[0] * delta_max, y[1] * w  # scaled state: y = (delta / delta_max, v / w)
        d = max(d, 0.0)
        k = 2.0 * estar * math.sqrt(rstar * d)
        force = k0 * d**1.5 + beta * math.sqrt(mstar * k) * v
        return [v / delta_max, -force / mstar / w]

    def back(_t, y):
        return y[0]

    back.terminal, back.direction = True, -1
    sol = solve_ivp(
        rhs, (0.0, 50 * tc), [0.0, 1.0], method="Radau", rtol=1e-11, atol=1e-13, events=back
    )
    return -sol.y_events[0][0][1]


@pytest.mark.parametrize("beta", [0.01, 0.3, 1.0, 1.6])
def test_map_matches_an_independent_integration_at_two_speeds(beta):
    # DOP853 in x'' = -x^(3/2) - beta' x^(1/4) x' against Radau on the dimensional contact at
    # 0.1 and 10 m/s: the same epsilon, whatever the speed.
    eps = lp.tsuji_epsilon(beta)
    for w in (0.1, 10.0):
        assert_allclose(_dimensional_epsilon(beta, w), eps, rtol=0, atol=2e-8)


def test_map_equals_the_closed_form_of_antypov_and_elliott():
    # LAMMPS's coeff_restitution form, beta = -2 sqrt(5/6) ln e / sqrt(pi^2 + ln^2 e), is not an
    # approximation for this force law: the integrated inverse agrees with it to 1e-9.
    eps = np.array([0.02, 0.3, 0.7, 0.9, 0.99, 0.9999])
    beta = lp.tsuji_beta(eps)
    assert_allclose(beta, lp.lammps_coeff_restitution_beta(eps), rtol=1e-8, atol=1e-11)
    # and so the forward map reproduces each epsilon from the closed form's beta
    back = [lp.tsuji_epsilon(b) for b in lp.lammps_coeff_restitution_beta(eps)]
    assert_allclose(back, eps, rtol=0, atol=1e-10)


def test_map_limits():
    # epsilon -> 1: beta -> sqrt(10/3) (1 - epsilon) / pi, the perturbative loss of a Hertz
    # pulse (1 - eps^2 = 4 beta (pi/5) sqrt(15/8), docs/lammps-plugin.md), here and in LAMMPS's
    # form alike.
    for loss in (1e-3, 1e-5):
        b = lp.tsuji_beta(1.0 - loss)
        assert_allclose(b / loss, math.sqrt(10.0 / 3.0) / math.pi, rtol=2 * loss + 1e-7)
    assert lp.tsuji_beta(1.0) == 0.0 and lp.tsuji_epsilon(0.0) == 1.0
    # epsilon -> 0: the critical damping 2 sqrt(5/6); beyond it the contact never opens.
    assert lp.tsuji_epsilon(1.001 * BETA_CRITICAL) == 0.0
    near = lp.tsuji_epsilon(0.9 * BETA_CRITICAL)  # closed form: exp(-0.9 pi / sqrt(0.19))
    assert_allclose(near, math.exp(-0.9 * math.pi / math.sqrt(1 - 0.81)), rtol=1e-6)
    assert lp.tsuji_beta(1e-6) < BETA_CRITICAL
    with pytest.raises(InputError, match=r"\(0, 1\]"):
        lp.tsuji_beta(1.2)
    with pytest.raises(InputError, match="beta must be >= 0"):
        lp.tsuji_epsilon(-0.1)


def test_map_grid_interpolates_to_1e_10_in_epsilon():
    # The plugin's beta(epsilon): cubic Hermite in ln epsilon on the grid. At the midpoints of
    # every 4th interval and the two end intervals, integrate the interpolated beta forward:
    # epsilon comes back within 1e-10 (largest over all midpoints: 7e-11, docs).
    m = lp.tsuji_map()
    assert m.epsilon[0] == lp.TSUJI_EPSILON_MIN and m.epsilon[-1] == 1.0 and m.beta[-1] == 0.0
    assert np.all(np.diff(m.epsilon) > 0) and np.all(np.diff(m.beta) < 0)
    assert np.all(m.slope[:-1] < 0)  # beta decreases with epsilon: a monotone grid
    u = np.log(m.epsilon)
    picks = sorted({0, 1, *range(2, u.size - 1, 4), u.size - 3, u.size - 2})
    mid = np.exp(0.5 * (u[picks] + u[np.add(picks, 1)]))
    back = np.array([lp.tsuji_epsilon(b) for b in m(mid)])
    assert np.max(np.abs(back - mid)) < 1e-10
    assert_allclose(m(m.epsilon), m.beta, rtol=0, atol=0)  # the knots themselves, exactly


# -- the table file -----------------------------------------------------------------------------


@dataclass
class ReadTable:
    """A table file read by the grammar of restitution_table.h (written again, independently)."""

    comments: list
    w: np.ndarray
    eps: np.ndarray
    slope: np.ndarray
    below: tuple
    map_eps: np.ndarray
    map_beta: np.ndarray
    map_slope: np.ndarray

    @staticmethod
    def hermite(x, xs, ys, ds):
        i = min(max(int(np.searchsorted(xs, x, side="right")) - 1, 0), xs.size - 2)
        h = xs[i + 1] - xs[i]
        t = (x - xs[i]) / h
        return (
            (1 + 2 * t) * (1 - t) ** 2 * ys[i]
            + t * (1 - t) ** 2 * h * ds[i]
            + t**2 * (3 - 2 * t) * ys[i + 1]
            - t**2 * (1 - t) * h * ds[i + 1]
        )

    def epsilon(self, w):
        if w > self.w[-1]:
            return math.nan
        if w >= self.w[0]:
            return self.hermite(w, self.w, self.eps, self.slope)
        if w == 0.0:
            return 1.0
        form, *p = self.below
        if form == "power":
            loss0, w0, q = p
            ratio = (w / w0) ** q
        else:
            loss0, w0, ws, power = p
            ratio = (math.log(ws / w0) / math.log(ws / w)) ** power
        return math.sqrt(1.0 - loss0 * ratio)


def read_table(text):
    lines = text.splitlines()
    comments = [ln[2:] for ln in lines if ln.startswith("# ")]
    words = [ln.split() for ln in lines if ln.strip() and not ln.lstrip().startswith("#")]
    assert words[0] == ["restitution-table", "1"] and words[1] == ["units", "si"]
    assert words[2][0] == "knots"
    n = int(words[2][1])
    knots = np.array(words[3 : 3 + n], dtype=float)
    below = words[3 + n]
    assert below[0] == "below"
    assert words[4 + n][0] == "beta-map"
    m = int(words[4 + n][1])
    grid = np.array(words[5 + n : 5 + n + m], dtype=float)
    assert words[5 + n + m] == ["end"] and len(words) == 6 + n + m
    return ReadTable(
        comments,
        *knots.T,
        (below[1], *map(float, below[2:])),
        *grid.T,
    )


def steel_table(geometry, against, **kw):
    s = restitution.si_law(**STEEL, geometry=geometry, against=against, **kw)
    return s, pchip_table(s)


@pytest.mark.parametrize("geometry", ["cylinder", "sphere"])
def test_table_file_round_trip(geometry):
    s, t = steel_table(geometry, "wall")
    comments = ["steel against a rigid wall", "two\nlines"]
    r = read_table(lp.plugin_table(t, comments))
    assert r.comments[:3] == ["steel against a rigid wall", "two", "lines"]
    assert np.array_equal(r.w, t.w_m_s) and np.array_equal(r.eps, t.epsilon)
    assert np.array_equal(r.slope, t.slope_s_m)
    b = t.below
    scale = () if b.form == "power" else (b.scale_m_s,)
    assert r.below == (b.form, b.loss0, b.w0_m_s, *scale, b.exponent)
    m = lp.tsuji_map()
    assert np.array_equal(r.map_eps, m.epsilon) and np.array_equal(r.map_beta, m.beta)
    assert np.array_equal(r.map_slope, m.slope)
    # the file, evaluated by its grammar, is the table, inside and below the knots
    lo, hi = t.range_m_s
    for w in [0.0, 1e-3 * lo, 0.5 * lo, lo, math.sqrt(lo * hi), 0.999 * hi, hi]:
        assert_allclose(r.epsilon(w), t(w), rtol=0, atol=2e-16)
    assert math.isnan(r.epsilon(1.001 * hi)) and math.isnan(t(1.001 * hi))


@pytest.mark.parametrize("form", ["power", "log"])
def test_continuation_at_zero_tiny_and_w0(form):
    # A stand-in table (two knots) with each continuation: epsilon = 1 at w = 0, the knot's
    # value at w0, below 1 and rising as w falls in between.
    w0, e0 = 0.002, 0.99
    loss0 = 1 - e0**2
    below = (
        SlowContinuation("power", w0, loss0, 1.0, None, "stand-in")
        if form == "power"
        else SlowContinuation("log", w0, loss0, 2.0, 50.0, "stand-in")
    )
    t = SimpleNamespace(
        w_m_s=np.array([w0, 1.0]),
        epsilon=np.array([e0, 0.9]),
        slope_s_m=np.array([-0.1, -0.05]),
        range_m_s=(w0, 1.0),
        below=below,
    )
    r = read_table(lp.plugin_table(t, ["stand-in"]))
    assert r.epsilon(0.0) == 1.0
    assert_allclose(r.epsilon(w0), e0, rtol=0, atol=1e-15)  # continuous at w0
    assert_allclose(r.epsilon(w0 * (1 - 1e-12)), e0, rtol=0, atol=1e-12)
    ws = np.geomspace(1e-300, 0.999 * w0, 40)
    eps = np.array([r.epsilon(w) for w in ws])
    assert np.all(np.diff(eps) <= 0) and np.all((eps > e0) & (eps <= 1.0))
    assert_allclose(eps, below(ws), rtol=0, atol=2e-16)  # the continuation's own formula
    if form == "power":  # 1 - eps^2 = L0 (w/w0): at 1e-300 m/s nothing is left of the loss
        assert eps[0] == 1.0
    else:  # L0 (ln(ws/w0) / ln(ws/w))^2: only logarithmically small at 1e-300 m/s
        assert_allclose(1 - eps[0] ** 2, loss0 * (math.log(25_000) / math.log(5e301)) ** 2)


def test_table_refuses_what_the_plugin_cannot_serve():
    _, t = steel_table("cylinder", "wall")
    bad = SimpleNamespace(
        w_m_s=t.w_m_s, epsilon=np.full_like(t.epsilon, 0.005), slope_s_m=t.slope_s_m, below=t.below
    )
    with pytest.raises(InputError, match=r"beta map's range"):
        lp.plugin_table(bad, [])
    back = SimpleNamespace(
        w_m_s=t.w_m_s[::-1], epsilon=t.epsilon, slope_s_m=t.slope_s_m, below=t.below
    )
    with pytest.raises(InputError, match="strictly increasing"):
        lp.plugin_table(back, [])


def test_input_lines(tmp_path):
    text = lp.lammps_plugin_input(
        tmp_path / "restitutionplugin.so",
        {(1, 2): (1.2e11, "t12.table"), (1, 1): (1.1e11, "t11.table")},
        lp.PluginWall(2.3e11, "wall.table", plane="yplane", position_m=0.0),
    )
    lines = [ln for ln in text.splitlines() if not ln.startswith("#")]
    assert lines == [
        f"plugin load {tmp_path / 'restitutionplugin.so'}",
        "pair_style restitution",
        "pair_coeff 1 1 110000000000 t11.table",
        "pair_coeff 1 2 120000000000 t12.table",
        "fix wall all wall/restitution 230000000000 wall.table yplane 0",
    ]
    assert "FRICTIONLESS" in text
    with pytest.raises(InputError, match="1 <= i <= j"):
        lp.lammps_plugin_input("p.so", {(2, 1): (1e11, "t")})
    with pytest.raises(InputError, match="plane"):
        lp.lammps_plugin_input("p.so", {(1, 1): (1e11, "t")}, lp.PluginWall(1e11, "w", "wplane"))
    assert_allclose(lp.contact_modulus(210e9, 0.3, 210e9, 0.3), 210e9 / (2 * (1 - 0.09)))


def test_build_says_what_to_install(monkeypatch, tmp_path):
    import builtins

    real_import = builtins.__import__

    def no_lammps(name, *args, **kwargs):
        if name == "lammps":
            raise ImportError("no lammps")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_lammps)
    with pytest.raises(InputError, match=r"pip install -e '\.\[lammps\]'"):
        lp.build_plugin(tmp_path)
    monkeypatch.setattr(builtins, "__import__", real_import)
    # With a lammps package (a stand-in with its cmake config: the default tests run without
    # the extra) but no cmake on PATH, the refusal names cmake, before anything is written.
    wheel = tmp_path / "wheel"
    (wheel / "cmake" / "LAMMPS").mkdir(parents=True)
    (wheel / "cmake" / "LAMMPS" / "LAMMPSConfig.cmake").write_text("# stand-in\n")
    monkeypatch.setattr(lp, "_lammps_package", lambda: wheel)
    monkeypatch.setattr(lp.shutil, "which", lambda name: None)
    dest = tmp_path / "dest"
    with pytest.raises(InputError, match="needs cmake"):
        lp.build_plugin(dest)
    assert not dest.exists()  # nothing written before the tools are there


# -- the plugin in LAMMPS (slow) ----------------------------------------------------------------

STEPS_PER_CONTACT = 20_000
"""dt = Hertz's contact time / this; each ratio is checked against the run at dt / 2."""

TIME_STEP_MARGIN = 1e-7
"""What velocity Verlet (fix nve/sphere) may still change in a rebound ratio at
STEPS_PER_CONTACT: |ratio - table| of the steel cylinders at 0.01, 1, 10 m/s, wall and pair,
was at most 7e-8 at 16 000 steps per contact and 1.1e-8 at 32 000 (docs/lammps-plugin.md,
time-step table); every test checks it again by halving dt."""


def _lmp_env():
    return dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))


@pytest.fixture(scope="module")
def plugin(tmp_path_factory):
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    source = Path(lp.__file__).parent / "dem" / "lammps_plugin"
    before = sorted(p.name for p in source.iterdir())
    so = lp.build_plugin(tmp_path_factory.mktemp("plugin"))
    assert sorted(p.name for p in source.iterdir()) == before  # nothing built in the sources
    return so


def contact_time(estar, rstar, mstar, w):
    """Hertz's contact time (s) of an undamped contact at impact speed w (m/s)."""
    k0 = 4.0 / 3.0 * estar * math.sqrt(rstar)
    return 3.2181 * (mstar**2 / (k0**2 * w)) ** 0.2


@dataclass(frozen=True)
class Grain:
    x: tuple  # m
    v: tuple  # m/s
    radius: float = 0.01  # m
    type: int = 1


def run_lammps(folder, plugin, grains, pairs, wall, dt, steps, dimension, prints):
    """One LAMMPS run of the plugin; returns the printed ``NAME value`` pairs and the process."""
    box = "-0.2 0.2 -0.2 0.2 -0.5 0.5" if dimension == 2 else "-0.2 0.2 -0.2 0.2 -0.2 0.2"
    atoms = []
    for k, g in enumerate(grains, start=1):
        atoms += [
            f"create_atoms {g.type} single {g.x[0]!r} {g.x[1]!r} {g.x[2]!r}",
            f"set atom {k} diameter {2 * g.radius!r} density {STEEL['rho']!r}",
            f"set atom {k} vx {g.v[0]!r} vy {g.v[1]!r} vz {g.v[2]!r}",
        ]
    ntypes = max(g.type for g in grains)
    text = "\n".join(
        [
            "units si",
            f"dimension {dimension}",
            "atom_style sphere",
            "atom_modify map array",
            "boundary f f f" if dimension == 3 else "boundary f f p",
            f"region box block {box}",
            f"create_box {ntypes} box",
            *atoms,
            "comm_modify vel yes",
            lp.lammps_plugin_input(plugin, pairs, wall),
            "fix nve all nve/sphere" + (" disc" if dimension == 2 else ""),
            *(["fix 2d all enforce2d"] if dimension == 2 else []),
            "compute pr all pair restitution",
            "thermo_style custom step c_pr[1] c_pr[2]" + (" f_wall[1] f_wall[2]" if wall else ""),
            "thermo 1000000",
            f"timestep {dt!r}",
            f"run {steps}",
            'print "PAIR_CONTACTS $(c_pr[1]) $(c_pr[2])"',
            *(['print "WALL_CONTACTS $(f_wall[1]) $(f_wall[2])"'] if wall else []),
            *(f'print "{name} $({expr}:%.17g)"' for name, expr in prints.items()),
        ]
    )
    (folder / "in.run").write_text(text + "\n")
    run = subprocess.run(
        [str(Path(sys.executable).with_name("lmp")), "-in", "in.run", "-log", "none"],
        cwd=folder,
        env=_lmp_env(),
        capture_output=True,
        text=True,
    )
    found = dict(re.findall(r"^(\w+) (.*)$", run.stdout, re.M))
    return found, run


def write_table(folder, name, t):
    path = folder / name
    path.write_text(lp.plugin_table(t, [f"test table {name}"]))
    return path.name


def impact_ratio(folder, plugin, case, steps_per_contact):
    """The rebound ratio of one impact (``case``: a wall or a head-on pair) in LAMMPS."""
    dt = case["tc"] / steps_per_contact
    w = case["w"]
    lead = 3.5 * dt  # the contact opens half-way between steps 3 and 4, whatever dt
    steps = int((lead + 3.0 * case["tc"]) / dt)
    if case["against"] == "wall":
        r, axis = case["radii"][0], case["axis"]
        x = [0.0, 0.0, 0.0]
        x[axis] = r + w * lead
        v = [0.0, 0.0, 0.0]
        v[axis] = -w
        grains = [Grain(tuple(x), tuple(v), r)]
        plane = "yplane" if axis == 1 else "zplane"
        wall = lp.PluginWall(case["estar"], case["table"], plane=plane)
        pairs = {(1, 1): (case["estar"], case["table"])}  # no second grain: never used
        name = "vy" if axis == 1 else "vz"
        prints = {"AFTER": f"{name}[1]", "GAP": f"{'yz'[axis - 1]}[1]-{r!r}"}
    else:
        r1, r2 = case["radii"]
        gap = w * lead
        grains = [
            Grain((-r1 - gap / 2, 0.0, 0.0), (w / 2, 0.0, 0.0), r1, 1),
            Grain((r2 + gap / 2, 0.0, 0.0), (-w / 2, 0.0, 0.0), r2, 2 if r2 != r1 else 1),
        ]
        wall = None
        pairs = case["pairs"]
        prints = {"AFTER": "vx[2]-vx[1]", "GAP": f"x[2]-x[1]-{r1 + r2!r}"}
    found, run = run_lammps(
        folder, plugin, grains, pairs, wall, dt, steps, case["dimension"], prints
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    assert float(found["GAP"]) > 0  # separated again
    live, opened = map(float, found["WALL_CONTACTS" if wall else "PAIR_CONTACTS"].split())
    assert (live, opened) == (0.0, 1.0)  # one contact, opened once, dropped when it ended
    return float(found["AFTER"]) / w


def check_impact(folder, plugin, case, s, t):
    """The ratio at dt and dt / 2: converged to TIME_STEP_MARGIN, the table's value within it,
    the law's within its error and the table's deviation plus it."""
    w = case["w"]
    coarse = impact_ratio(folder, plugin, case, STEPS_PER_CONTACT)
    fine = impact_ratio(folder, plugin, case, 2 * STEPS_PER_CONTACT)
    law, err = float(s.epsilon(w)), float(s.epsilon_err(w))
    print(
        f"{case['label']} w={w:g} m/s: LAMMPS {fine:.10f} (dt/2), {coarse:.10f} (dt); table "
        f"{t(w):.10f}; law {law:.10f} +- {err:.2e}; LAMMPS - law = {fine - law:+.2e}"
    )
    assert abs(coarse - fine) < TIME_STEP_MARGIN
    assert abs(fine - t(w)) < TIME_STEP_MARGIN
    assert abs(fine - law) <= err + t.max_deviation + TIME_STEP_MARGIN


def _estar(partner_rigid):
    E, nu = STEEL["E"], STEEL["nu"]
    return lp.contact_modulus(E, nu) if partner_rigid else lp.contact_modulus(E, nu, E, nu)


@pytest.mark.slow
@pytest.mark.parametrize("against", ["wall", "grain"])
def test_steel_cylinders_in_2d_rebound_with_the_law(tmp_path, plugin, against):
    """The issue's done-when: 2D (disks), 0.01, 1 and 10 m/s."""
    s, t = steel_table("cylinder", against)
    table = write_table(tmp_path, f"cyl_{against}.table", t)
    r = 0.01
    m = 4.0 / 3.0 * math.pi * r**3 * STEEL["rho"]  # LAMMPS's mass of a sphere, 2D or not
    estar = _estar(against == "wall")
    for w in (0.01, 1.0, 10.0):
        if against == "wall":
            case = dict(against="wall", axis=1, radii=(r,), tc=contact_time(estar, r, m, w))
        else:
            tc = contact_time(estar, r / 2, m / 2, w)
            case = dict(against="grain", radii=(r, r), tc=tc, pairs={(1, 1): (estar, table)})
        case.update(w=w, estar=estar, table=table, dimension=2, label=f"cylinder/{against}")
        check_impact(tmp_path, plugin, case, s, t)


@pytest.mark.slow
def test_steel_spheres_in_3d_rebound_with_the_law(tmp_path, plugin):
    """Two spheres of radius ratio 2 head-on at 0.1 and 10 m/s; a sphere on the wall at 1 m/s."""
    s12, t12 = steel_table("sphere", "grain", radius_ratio=2)
    s11, t11 = steel_table("sphere", "grain")
    sw, tw = steel_table("sphere", "wall")
    estar = _estar(False)
    pairs = {
        (1, 1): (estar, write_table(tmp_path, "s11.table", t11)),
        (1, 2): (estar, write_table(tmp_path, "s12.table", t12)),
        (2, 2): (estar, "s11.table"),  # identical spheres: the law does not see their size
    }
    r1, r2 = 0.01, 0.02
    m1, m2 = (4.0 / 3.0 * math.pi * r**3 * STEEL["rho"] for r in (r1, r2))
    for w in (0.1, 10.0):
        tc = contact_time(estar, r1 * r2 / (r1 + r2), m1 * m2 / (m1 + m2), w)
        case = dict(against="grain", radii=(r1, r2), tc=tc, pairs=pairs, w=w, dimension=3)
        check_impact(tmp_path, plugin, {**case, "label": "sphere pair R2/R1=2"}, s12, t12)
    ew = _estar(True)
    case = dict(
        against="wall", axis=2, radii=(r1,), tc=contact_time(ew, r1, m1, 1.0), w=1.0,
        estar=ew, table=write_table(tmp_path, "sw.table", tw), dimension=3, label="sphere/wall",
    )  # fmt: skip
    check_impact(tmp_path, plugin, case, sw, tw)


@pytest.mark.slow
def test_each_contact_keeps_its_own_epsilon(tmp_path, plugin):
    """Three contacts open at once in one 2D run: a pair head-on at 10 m/s, a grain on the wall
    at 1 m/s and another at 0.01 m/s. Each rebounds with the table's value at its own speed."""
    sg, tg = steel_table("cylinder", "grain")
    sw, tw = steel_table("cylinder", "wall")
    r = 0.01
    m = 4.0 / 3.0 * math.pi * r**3 * STEEL["rho"]
    eg, ew = _estar(False), _estar(True)
    dt = contact_time(eg, r / 2, m / 2, 10.0) / STEPS_PER_CONTACT  # the shortest contact
    lead = 3.5 * dt
    grains = [
        Grain((-0.05, r + 1.0 * lead, 0.0), (0.0, -1.0, 0.0)),
        Grain((0.05, r + 0.01 * lead, 0.0), (0.0, -0.01, 0.0)),
        Grain((-r - 5.0 * lead, 0.1, 0.0), (5.0, 0.0, 0.0)),
        Grain((r + 5.0 * lead, 0.1, 0.0), (-5.0, 0.0, 0.0)),
    ]
    steps = int((lead + 3.0 * contact_time(ew, r, m, 0.01)) / dt)
    prints = {"W1": "vy[1]", "W2": "vy[2]", "PAIR": "vx[4]-vx[3]"}
    found, run = run_lammps(
        tmp_path,
        plugin,
        grains,
        {(1, 1): (eg, write_table(tmp_path, "g.table", tg))},
        lp.PluginWall(ew, write_table(tmp_path, "w.table", tw), plane="yplane"),
        dt,
        steps,
        2,
        prints,
    )
    assert run.returncode == 0, run.stdout[-3000:]
    got = [float(found["W1"]) / 1.0, float(found["W2"]) / 0.01, float(found["PAIR"]) / 10.0]
    want = [tw(1.0), tw(0.01), tg(10.0)]
    print("one run, three contacts:", got, "tables:", want)
    assert_allclose(got, want, rtol=0, atol=TIME_STEP_MARGIN)
    assert abs(want[0] - want[1]) > 1000 * TIME_STEP_MARGIN  # distinct epsilons, all kept
    assert found["PAIR_CONTACTS"].split() == ["0", "1"]
    assert found["WALL_CONTACTS"].split() == ["0", "2"]


@pytest.mark.slow
@pytest.mark.parametrize("against", ["grain", "wall"])
def test_an_impact_above_the_range_stops_the_run(tmp_path, plugin, against):
    # The pair of spheres R2/R1 = 2 is computed up to 17.26 m/s; a wall table cut at 2 m/s.
    r = 0.01
    estar = _estar(against == "wall")
    if against == "grain":
        _, t = steel_table("sphere", "grain", radius_ratio=2)
        table = write_table(tmp_path, "s12.table", t)
        grains = [
            Grain((-r - 1e-4, 0, 0), (15.0, 0, 0)),
            Grain((2 * r + 1e-4, 0, 0), (-15.0, 0, 0), 2 * r, 2),
        ]
        pairs, wall = {(1, 1): (estar, table), (1, 2): (estar, table), (2, 2): (estar, table)}, None
        words = ["30 m/s", "atoms 1 and 2", "types 1 2", "0.010344388 ... 17.259612 m/s"]
    else:
        _, t = steel_table("sphere", "wall")
        keep = t.w_m_s <= 2.0
        cut = SimpleNamespace(
            w_m_s=t.w_m_s[keep], epsilon=t.epsilon[keep], slope_s_m=t.slope_s_m[keep], below=t.below
        )
        table = write_table(tmp_path, "cut.table", cut)
        grains = [Grain((0, 0, r + 1e-4), (0, 0, -3.0))]
        pairs, wall = {(1, 1): (estar, table)}, lp.PluginWall(estar, table)
        words = ["3 m/s", "atom 1 (type 1) on the wall", f"{t.w_m_s[keep][-1]:.8g} m/s"]
    found, run = run_lammps(tmp_path, plugin, grains, pairs, wall, 1e-8, 20_000, 3, {})
    out = run.stdout + run.stderr
    assert run.returncode != 0
    message = re.search(r"ERROR.*", out).group(0)
    print(message)
    for word in [*words, "above the range", "no epsilon is extrapolated"]:
        assert word in message


@pytest.mark.slow
def test_cpp_reader_evaluates_the_table_as_python(tmp_path, plugin):
    # restitution_table_probe (the plugin's reader, outside LAMMPS) against PchipTable and
    # TsujiMap: the same doubles up to rounding, every status code, a malformed file refused.
    probe = plugin.with_name("restitution_table_probe")
    for geometry in ("cylinder", "sphere"):
        _, t = steel_table(geometry, "wall")
        (tmp_path / "t.table").write_text(lp.plugin_table(t, ["probe"]))
        lo, hi = t.range_m_s
        ws = np.concatenate([[0.0, 1e-9 * lo, 0.3 * lo], t.w_m_s, np.geomspace(lo, hi, 57)])
        eps = np.concatenate([lp.tsuji_map().epsilon, np.linspace(0.0101, 0.99999, 41)])
        args = [*map(repr, ws.tolist()), repr(2 * hi), "-1", "--", *map(repr, eps.tolist())]
        out = subprocess.run(
            [str(probe), str(tmp_path / "t.table"), *args], capture_output=True, text=True
        ).stdout.split("\n")
        rows = [ln.split() for ln in out if ln.startswith("w ")]
        got = np.array([float(r[3]) for r in rows[: ws.size]])
        assert_allclose(got, t(ws), rtol=5e-16, atol=0)  # two ulps: the order of operations
        assert [int(r[2]) for r in rows[: ws.size]] == list(t.status(ws))
        assert rows[-2][2:] == ["2", "nan"] and rows[-1][2:] == ["3", "nan"]
        betas = np.array([float(ln.split()[2]) for ln in out if ln.startswith("eps ")])
        assert_allclose(betas, lp.tsuji_map()(eps), rtol=1e-15, atol=1e-16)
    text = (tmp_path / "t.table").read_text().replace("units si", "units cgs")
    (tmp_path / "bad.table").write_text(text)
    bad = subprocess.run([str(probe), str(tmp_path / "bad.table")], capture_output=True, text=True)
    assert bad.returncode == 1 and "line" in bad.stderr and "units cgs are not si" in bad.stderr


@pytest.mark.slow
def test_the_export_folder_runs_as_written(tmp_path, plugin, cli):
    # `restitution law ... --export DIR` writes the plugin's tables and input lines; LAMMPS,
    # run in that folder with the built plugin beside them, `include`s the lines as written: a
    # steel cylinder on the wall (a 2D run, the wall along y) at 1 m/s rebounds with the law.
    out = tmp_path / "export"
    code, _, err = cli("law", "--E", str(STEEL["E"]), "--nu", str(STEEL["nu"]), "--rho",
                       str(STEEL["rho"]), "--shape", "cylinder", "--against", "wall", "--speed",
                       "1", "--export", str(out))  # fmt: skip
    assert code == 0, err
    text = (out / "epsilon_lammps_plugin.in").read_text()
    assert "wall/restitution" in text and "yplane 0" in text
    (out / lp.PLUGIN_NAME).symlink_to(plugin)
    s = restitution.si_law(STEEL["E"], STEEL["nu"], STEEL["rho"], "cylinder", "wall")
    w, r = 1.0, 0.01
    tc = contact_time(_estar(True), r, 4 / 3 * math.pi * r**3 * STEEL["rho"], w)
    ratios = []
    for per_contact in (STEPS_PER_CONTACT, 2 * STEPS_PER_CONTACT):
        dt = tc / per_contact
        lead = 3.5 * dt
        lines = [
            "units si", "dimension 2", "atom_style sphere", "atom_modify map array",
            "boundary f f p", "region box block -0.2 0.2 -0.2 0.2 -0.5 0.5", "create_box 1 box",
            f"create_atoms 1 single 0 {r + w * lead!r} 0",
            f"set atom 1 diameter {2 * r!r} density {STEEL['rho']!r}",
            f"set atom 1 vy {-w!r}", "comm_modify vel yes", "include epsilon_lammps_plugin.in",
            "fix nve all nve/sphere disc", "fix 2d all enforce2d", f"timestep {dt!r}",
            f"run {int((lead + 3 * tc) / dt)}", 'print "AFTER $(vy[1]:%.17g)"',
        ]  # fmt: skip
        (out / "in.run").write_text("\n".join(lines) + "\n")
        run = subprocess.run([str(Path(sys.executable).with_name("lmp")), "-in", "in.run",
                              "-log", "none"], cwd=out, env=_lmp_env(), capture_output=True,
                             text=True)  # fmt: skip
        assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
        ratios.append(float(re.search(r"^AFTER (\S+)", run.stdout, re.M).group(1)) / w)
    law, err = float(s.epsilon(w)), float(s.epsilon_err(w))
    print(f"exported plugin: LAMMPS {ratios[1]:.10f} (dt/2), {ratios[0]:.10f}; law {law:.10f}")
    assert abs(ratios[0] - ratios[1]) < TIME_STEP_MARGIN
    assert abs(ratios[1] - law) <= err + pchip_table(s).max_deviation + TIME_STEP_MARGIN


def test_the_export_writes_a_table_per_contact_and_their_input_lines():
    from restitution.laws import exports
    from restitution.laws.exports.any_size import ANY_SIZE_INPUT
    from restitution.laws.exports.plugin_files import INPUT_NAME, plugin_files

    steel = (STEEL["E"], STEEL["nu"], STEEL["rho"])
    pair = restitution.si_law(*steel, "sphere", "grain", radius_ratio=2)
    same = restitution.si_law(*steel, "sphere", "grain")
    c = exports.type_pair_constants(pair, same, speed_m_s=1.0)
    files = plugin_files(pair, c)
    names = ["epsilon_lammps_plugin_11.table", "epsilon_lammps_plugin_12.table",
             "epsilon_lammps_plugin_22.table", "epsilon_lammps_plugin_wall1.table",
             INPUT_NAME]  # fmt: skip
    # Beside them the law per contact of the one material, for every pair of its types
    # (tests/test_any_size_export.py).
    laws = ["epsilon_lammps_plugin_11.law", "epsilon_lammps_plugin_wall1.law", ANY_SIZE_INPUT]
    assert sorted(files) == sorted(names + laws)
    for i, j in ((1, 1), (1, 2), (2, 2)):
        assert f"pair_coeff {i} {j} " in files[ANY_SIZE_INPUT]
        assert files[ANY_SIZE_INPUT].count(f"pair_coeff {i} {j} ") == 1
    assert files[ANY_SIZE_INPUT].count("epsilon_lammps_plugin_11.law") == 3
    # 1-1 and 2-2 are the law of identical grains, 1-2 the pair's: each file its own knots.
    for name, law in (("11", same), ("12", pair), ("22", same)):
        got = read_table(files[f"epsilon_lammps_plugin_{name}.table"])
        assert_allclose(got.w, pchip_table(law).w_m_s, rtol=1e-16)
    e_star = lp.contact_modulus(*steel[:2], *steel[:2])
    for i, j in ((1, 1), (1, 2), (2, 2)):
        line = f"pair_coeff {i} {j} {e_star:.12g} epsilon_lammps_plugin_{i}{j}.table"
        assert line in files[INPUT_NAME]
    assert "plugin load ./restitutionplugin.so" in files[INPUT_NAME]
    # The grains on the rigid wall too (one material: one table and one fix for every size).
    wall = restitution.si_law(*steel, "sphere", "wall")
    assert_allclose(read_table(files["epsilon_lammps_plugin_wall1.table"]).w,
                    pchip_table(wall).w_m_s, rtol=1e-16)  # fmt: skip
    e_wall = lp.contact_modulus(*steel[:2])
    assert (
        f"fix wall all wall/restitution {e_wall:.12g} epsilon_lammps_plugin_wall1.table"
        in (files[INPUT_NAME])
    )
    # One constant of a pair: the 1-2 table only, and the lines say how to get the others.
    only = plugin_files(pair, exports.constant_at(pair, 1.0))
    assert sorted(only) == sorted(["epsilon_lammps_plugin.in", "epsilon_lammps_plugin_12.table",
                                   "epsilon_lammps_plugin_wall1.table", *laws])  # fmt: skip
    assert "to export 1-1 and 2-2 too" in only[INPUT_NAME]
    # The law per contact serves every pair of the two types all the same.
    assert only[ANY_SIZE_INPUT].count("epsilon_lammps_plugin_11.law") == 3


@pytest.mark.slow
def test_an_export_of_two_materials_runs_each_on_the_wall(tmp_path, plugin, cli):
    # Steel with glass spheres (the shipped pair of two materials): the folder holds each
    # material's wall table and one fix per type's group; a glass grain (type 2) dropped on the
    # wall at 1 m/s rebounds with glass's law on the wall, not steel's.
    out = tmp_path / "export"
    code, _, err = cli("law", "--E", "210e9", "--nu", "0.3", "--rho", "7850", "--shape",
                       "sphere", "--against", "grain", "--partner-radius-ratio", "1",
                       "--partner-E", "63e9", "--partner-nu", "0.2481", "--partner-rho", "2500",
                       "--speed", "1", "--reference-speed", "1", "--export", str(out))  # fmt: skip
    assert code == 0, err
    (out / lp.PLUGIN_NAME).symlink_to(plugin)
    glass = restitution.si_law(63e9, 0.2481, 2500.0, "sphere", "wall")
    steel = restitution.si_law(STEEL["E"], STEEL["nu"], STEEL["rho"], "sphere", "wall")
    w, r = 1.0, 0.01
    tc = contact_time(lp.contact_modulus(63e9, 0.2481), r, 4 / 3 * math.pi * r**3 * 2500, w)
    dt = tc / STEPS_PER_CONTACT
    lead = 3.5 * dt
    lines = [
        "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
        "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2", "create_box 2 box",
        f"create_atoms 2 single 0 0 {r + w * lead!r}",
        f"set atom 1 diameter {2 * r!r} density 2500.0", f"set atom 1 vz {-w!r}",
        "comm_modify vel yes", "include epsilon_lammps_plugin.in", "fix nve all nve/sphere",
        f"timestep {dt!r}", f"run {int((lead + 3 * tc) / dt)}", 'print "AFTER $(vz[1]:%.17g)"',
    ]  # fmt: skip
    (out / "in.run").write_text("\n".join(lines) + "\n")
    lmp = str(Path(sys.executable).with_name("lmp"))
    run = subprocess.run([lmp, "-in", "in.run", "-log", "none"], cwd=out, env=_lmp_env(),
                         capture_output=True, text=True)  # fmt: skip
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    ratio = float(re.search(r"^AFTER (\S+)", run.stdout, re.M).group(1)) / w
    print(f"glass on the wall: LAMMPS {ratio:.10f}, glass law {glass.epsilon(w):.10f}, steel's "
          f"{steel.epsilon(w):.10f}")  # fmt: skip
    bound = glass.epsilon_err(w) + pchip_table(glass).max_deviation + TIME_STEP_MARGIN
    assert abs(ratio - glass.epsilon(w)) <= bound
    assert abs(ratio - glass.epsilon(w)) < abs(ratio - steel.epsilon(w))


# -- several MPI ranks (slow) -------------------------------------------------------------------


def _bed(folder, plugin, seed=7):
    """A bed of 384 glass beads of radii uniform in 0.8 ... 1.2 mm, on a lattice 8 x 8 x 6 of
    2.45 mm with random velocities (0.3 m/s each component), falling at 500 m/s^2 onto a wall at
    z = 0 in a box periodic in x and y; the input script, written into ``folder``, runs it
    ``$steps`` steps and dumps every grain (``$tag``). The tables are a stand-in epsilon(w),
    0.95 at rest falling to 0.5 at 100 m/s, so that a contact's state (its impact speed)
    matters: one re-opened mid-contact would take another beta."""
    w = np.geomspace(1e-3, 100.0, 81)
    eps = 0.95 - 0.45 * w / (w + 0.5)
    below = SlowContinuation("power", w[0], 1.0 - eps[0] ** 2, 1.0, None, "stand-in")
    table = SimpleNamespace(w_m_s=w, epsilon=eps, slope_s_m=-0.225 / (w + 0.5) ** 2, below=below)
    (folder / "steep.table").write_text(lp.plugin_table(table, ["stand-in, 0.95 ... 0.5"]))
    rng = np.random.default_rng(seed)
    a, side, layers = 2.45e-3, 8, 6
    x = [((i + 0.5) * a, (j + 0.5) * a, 1.25e-3 + k * a)
         for k in range(layers) for i in range(side) for j in range(side)]  # fmt: skip
    radii = rng.uniform(0.8e-3, 1.2e-3, len(x)).tolist()
    v = rng.normal(0.0, 0.3, (len(x), 3)).tolist()
    rho = 2500.0
    data = ["a bed", "", f"{len(x)} atoms", "1 atom types", f"0 {side * a!r} xlo xhi",
            f"0 {side * a!r} ylo yhi", "0 0.1 zlo zhi", "", "Atoms # sphere", "",
            *(f"{k} 1 {2 * r!r} {rho!r} {p[0]!r} {p[1]!r} {p[2]!r}"
              for k, (p, r) in enumerate(zip(x, radii, strict=True), start=1)),
            "", "Velocities", "",
            *(f"{k} {u[0]!r} {u[1]!r} {u[2]!r} 0 0 0"
              for k, u in enumerate(v, start=1))]  # fmt: skip
    (folder / "bed.data").write_text("\n".join(data) + "\n")
    glass = (63e9, 0.2481)
    pairs = {(1, 1): (lp.contact_modulus(*glass, *glass), "steep.table")}
    wall = lp.PluginWall(lp.contact_modulus(*glass), "steep.table")
    dump = "id x y z vx vy vz c_proc modify sort id format float %.17g"
    lines = [
        "units si", "atom_style sphere", "boundary p p f", "processors ${grid}",
        "read_data bed.data", "comm_modify vel yes",
        # a list every step: atoms change ranks at every step, mid-contact too
        "neighbor 0.0002 bin", "neigh_modify delay 0 every 1 check no",
        lp.lammps_plugin_input(plugin, pairs, wall),
        "fix grav all gravity 500 vector 0 0 -1", "fix nve all nve/sphere",
        "compute pr all pair restitution", "compute proc all property/atom proc",
        "thermo_style custom step c_pr[1] c_pr[2] f_wall[1] f_wall[2]", "thermo 20000",
        "timestep 1e-7", "run 0", f"write_dump all custom start_${{tag}}.txt {dump}",
        "run ${steps}", f"write_dump all custom end_${{tag}}.txt {dump}",
        'print "COUNTS $(c_pr[1]) $(c_pr[2]) $(f_wall[1]) $(f_wall[2])"',
    ]  # fmt: skip
    (folder / "in.bed").write_text("\n".join(lines) + "\n")


def _read_dump(path):
    """``(ids, state, owner)``: the atoms' IDs, ``x y z vx vy vz`` (n x 6) and owning rank."""
    rows = np.loadtxt(path, skiprows=9)
    return rows[:, 0].astype(int), rows[:, 1:7], rows[:, 7].astype(int)


@pytest.mark.slow
def test_a_bed_on_two_mpi_ranks_moves_as_on_one(tmp_path, plugin):
    """Issue 61: the plugin on several MPI ranks gives the numbers of one rank, bit for bit.

    384 grains of continuous sizes settle into a bed (contacts that last thousands of steps)
    while atoms migrate between the two ranks (the box cut in x, a list every step); after
    60 000 steps every position and velocity of the 2-rank run equals the 1-rank run's, and so
    do the contact counters. Bitwise, not to a tolerance: each contact's state travels with its
    atoms, both owners fix the same state from the same bits at the first touch, and each atom's
    forces are summed in the order of its partners' IDs, never in the neighbor list's, which
    depends on the decomposition (docs/lammps-plugin.md, "Several MPI ranks")."""
    mpiexec = Path(sys.executable).with_name("mpiexec")
    if not mpiexec.is_file():
        pytest.skip(f"no MPI launcher: {mpiexec} is missing (the mpich wheel of the lammps "
                    "extra brings it: pip install -e '.[lammps]')")  # fmt: skip
    _bed(tmp_path, plugin)
    lmp = str(Path(sys.executable).with_name("lmp"))
    runs = {}
    for ranks, grid in ((1, "1 1 1"), (2, "2 1 1")):
        head = [] if ranks == 1 else [str(mpiexec), "-n", str(ranks)]
        run = subprocess.run(
            [*head, lmp, "-in", "in.bed", "-log", "none", "-var", "grid", grid, "-var", "steps",
             "60000", "-var", "tag", str(ranks)],
            cwd=tmp_path, env=_lmp_env(), capture_output=True, text=True,
        )  # fmt: skip
        assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
        counts = [float(c) for c in re.search(r"^COUNTS (.*)$", run.stdout, re.M).group(1).split()]
        runs[ranks] = (counts, _read_dump(tmp_path / f"end_{ranks}.txt"))
    (one_counts, (ids, one, _)), (two_counts, (ids2, two, owner)) = runs[1], runs[2]
    _, _, owner0 = _read_dump(tmp_path / "start_2.txt")
    moved = int(np.sum(owner != owner0))
    print(f"contacts open/opened, wall open/opened: 1 rank {one_counts}, 2 ranks {two_counts}; "
          f"grains on another rank than at the start: {moved} of {ids.size}")  # fmt: skip
    assert np.array_equal(ids, ids2)
    assert np.array_equal(one, two)  # bitwise
    assert one_counts == two_counts
    open_pairs, opened_pairs, _, opened_wall = one_counts
    assert open_pairs >= 20 and opened_pairs > 5000 and opened_wall > 500  # a bed, many impacts
    assert moved >= 5 and set(owner) == {0, 1}  # grains did change ranks
