"""The per-contact cost of the plugin (pair_style restitution, a table per type pair) against
LAMMPS's own ``pair_style granular`` with ``hertz/material`` and Tsuji's damping
(``damping coeff_restitution``: the same force law, one epsilon per type pair), on the same bed.

A bed of 384 steel beads of radii 0.8 ... 1.2 mm falling at 500 m/s^2 onto a wall (each style's
own wall: ``fix wall/restitution`` or ``fix wall/gran``) in a box periodic in x and y; the same
steps, time step and neighbor settings. The two runs alternate (REPEATS pairs) so that the load
of the shared machine weighs on both alike; the ratio is the plugin's loop time over LAMMPS's,
as min/median/max. Run: ``.venv/bin/python benchmarks/bench_plugin.py`` (the plugin is built
first, about 30 s).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import restitution
from restitution.laws.exports import lammps_plugin as lp
from restitution.laws.exports.pchip import pchip_table

STEEL = (210e9, 0.3, 7850.0)
STEPS = 20_000
REPEATS = 5
EPSILON = 0.9  # LAMMPS's constant epsilon (the plugin's is the table's, 0.99998 for steel)


def write_bed(folder: Path, seed: int = 7) -> None:
    """``bed.data``: 384 beads on a lattice 8 x 8 x 6 of 2.45 mm, random velocities."""
    rng = np.random.default_rng(seed)
    a, side, layers = 2.45e-3, 8, 6
    x = [((i + 0.5) * a, (j + 0.5) * a, 1.25e-3 + k * a)
         for k in range(layers) for i in range(side) for j in range(side)]  # fmt: skip
    radii = rng.uniform(0.8e-3, 1.2e-3, len(x)).tolist()
    v = rng.normal(0.0, 0.3, (len(x), 3)).tolist()
    rho = STEEL[2]
    data = ["a bed", "", f"{len(x)} atoms", "1 atom types", f"0 {side * a!r} xlo xhi",
            f"0 {side * a!r} ylo yhi", "0 0.1 zlo zhi", "", "Atoms # sphere", "",
            *(f"{k} 1 {2 * r!r} {rho!r} {p[0]!r} {p[1]!r} {p[2]!r}"
              for k, (p, r) in enumerate(zip(x, radii, strict=True), start=1)),
            "", "Velocities", "",
            *(f"{k} {u[0]!r} {u[1]!r} {u[2]!r} 0 0 0" for k, u in enumerate(v, start=1))]  # fmt: skip  # noqa: E501
    (folder / "bed.data").write_text("\n".join(data) + "\n")


def contact_lines(folder: Path, so: Path, style: str) -> list[str]:
    """The pair style and the wall of ``style`` ("plugin" or "granular")."""
    E, nu, _ = STEEL
    if style == "plugin":
        grain = restitution.si_law(*STEEL, "sphere", "grain")
        wall = restitution.si_law(*STEEL, "sphere", "wall")
        (folder / "g.table").write_text(lp.plugin_table(pchip_table(grain), ["steel"]))
        (folder / "w.table").write_text(lp.plugin_table(pchip_table(wall), ["steel, wall"]))
        pairs = {(1, 1): (lp.contact_modulus(E, nu, E, nu), "g.table")}
        return [lp.lammps_plugin_input(so, pairs, lp.PluginWall(lp.contact_modulus(E, nu),
                                                                "w.table"))]  # fmt: skip
    model = f"hertz/material {E!r} {EPSILON} {nu} damping coeff_restitution tangential linear_nohistory 0 0"  # noqa: E501
    return ["pair_style granular", f"pair_coeff * * {model}",
            f"fix wall all wall/gran granular {model} zplane 0 NULL"]  # fmt: skip


def loop_time(folder: Path, so: Path, style: str) -> float:
    """LAMMPS's loop time (s) of STEPS steps of the bed with ``style``."""
    lines = ["units si", "atom_style sphere", "boundary p p f", "read_data bed.data",
             "comm_modify vel yes", "neighbor 0.0002 bin", *contact_lines(folder, so, style),
             "fix grav all gravity 500 vector 0 0 -1", "fix nve all nve/sphere",
             "thermo 100000", "timestep 1e-7", f"run {STEPS}"]  # fmt: skip
    (folder / f"in.{style}").write_text("\n".join(lines) + "\n")
    env = dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"), OMP_NUM_THREADS="1")
    lmp = str(Path(sys.executable).with_name("lmp"))
    run = subprocess.run([lmp, "-in", f"in.{style}", "-log", "none", "-echo", "none"],
                         cwd=folder, env=env, capture_output=True, text=True)  # fmt: skip
    if run.returncode != 0:
        raise RuntimeError(run.stdout[-2000:] + run.stderr[-2000:])
    return float(re.search(r"^Loop time of (\S+)", run.stdout, re.M).group(1))


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        so = lp.build_plugin(folder / "plugin")
        write_bed(folder)
        times = {"plugin": [], "granular": []}
        for _ in range(REPEATS):
            for style in times:  # alternating: the machine's load falls on both
                times[style].append(loop_time(folder, so, style))
    ratio = np.array(times["plugin"]) / np.array(times["granular"])
    print(f"bed of 384 steel beads, {STEPS} steps of 1e-7 s, {REPEATS} alternating pairs, 1 rank")
    for style, t in times.items():
        print(f"  {style:9s} loop time (s): " + " ".join(f"{x:.3f}" for x in t))
    print(
        f"  plugin / granular: min {ratio.min():.3f}, median {np.median(ratio):.3f}, "
        f"max {ratio.max():.3f}"
    )
    print("  load average (1, 5, 15 min): " + " ".join(f"{x:.2f}" for x in os.getloadavg()))


if __name__ == "__main__":
    main()
