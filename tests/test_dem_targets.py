"""The DEM targets of the exports: each code registers itself from its own module, and the export
folder (library and ``restitution law --export``) writes every registered target, so a new code
is one new module (docs/architecture.md, "Adding a DEM target")."""

import importlib
import sys

import numpy as np
import pytest

from restitution.laws import exports
from restitution.laws.exports import dem
from restitution.laws.exports.dem import DEM_TARGETS, DemTarget, register_dem_target
from restitution.laws.law import EpsilonLaw
from restitution.laws.si_law import SILaw
from restitution.laws.units import Grain

TOY_MODULE = "restitution.laws.exports.dem.toy_code"

# A toy DEM code as one module: all a new code takes (its snippet function and one registration).
TOY_SOURCE = '''"""A toy DEM code: one line per type pair."""

from restitution.laws.exports.dem._registry import DemTarget, register_dem_target


def toy_snippet(s, c):
    pairs = c.constants if hasattr(c, "constants") else {(1, 1): c}
    return "".join(f"toy {i} {j} {k.epsilon:.8f}\\n" for (i, j), k in pairs.items())


TARGET = register_dem_target(DemTarget(name="toy_code", file_name="toy.dem", snippet=toy_snippet))
'''


@pytest.fixture
def registry():
    """The registry as shipped, restored after the test (with the toy module forgotten)."""
    saved = dict(DEM_TARGETS)
    yield DEM_TARGETS
    DEM_TARGETS.clear()
    DEM_TARGETS.update(saved)
    sys.modules.pop(TOY_MODULE, None)


def _law(against="wall"):
    v = np.linspace(0.005, 0.3, 40)
    eps = 1.0 - 0.6 * v**0.85 / (1.0 + 1.5 * v**0.85)  # smooth and monotone, not physics
    law = EpsilonLaw.from_points(0.25, v, eps, np.full(v.size, 1e-5))
    return SILaw(Grain(E=63e9, nu=0.25, rho=2500.0, geometry="thin-disk"), against, law)


def test_each_shipped_code_registers_itself_from_its_own_module():
    assert list(DEM_TARGETS) == ["lammps", "liggghts", "mercurydpm", "yade"]
    for name, target in DEM_TARGETS.items():
        module = importlib.import_module(f"restitution.laws.exports.dem.{name}")
        assert module.TARGET is target
        assert target.snippet.__module__ == module.__name__
        assert getattr(exports, f"{name}_snippet") is target.snippet
    files = [t.file_name for t in DEM_TARGETS.values()]
    assert files == ["lammps.in", "liggghts.in", "mercurydpm.cpp", "yade.py"]


def test_a_target_registered_in_a_test_is_written_by_the_export(registry, tmp_path, cli):
    def toy_snippet(s, c):
        return f"toy {c.epsilon:.8f}\n"

    register_dem_target(DemTarget(name="toy", file_name="toy.dem", snippet=toy_snippet))
    s = _law()
    c = exports.constant_at(s, 500.0)
    written = exports.write_folder(s, c, tmp_path / "lib")
    toy = tmp_path / "lib" / "epsilon_toy.dem"
    # After the snippets, the LAMMPS plugin's table and input lines (the law per contact).
    plugin = ["epsilon_lammps_plugin_wall1.table", "epsilon_lammps_plugin.in"]
    assert [p.name for p in written.paths[-3:]] == [toy.name, *plugin]
    assert toy.read_text() == f"toy {c.epsilon:.8f}\n"
    # Without a constant no snippet is written, the toy's neither.
    bare = exports.write_folder(s, None, tmp_path / "bare")
    assert not (tmp_path / "bare" / "epsilon_toy.dem").exists()
    assert [p.name for p in bare.paths] == [
        "epsilon_table.txt",
        "epsilon.csv",
        "epsilon_closed_form.json",
        "epsilon.h",
        "epsilon.f90",
        *plugin,
    ]
    # The command line writes it too, after the shipped codes.
    out = tmp_path / "cli"
    code, stdout, err = cli("law", "--E", "63e9", "--nu", "0.2481", "--rho", "2500",
                            "--geometry", "cylinder", "--against", "wall", "--speed", "1",
                            "--reference-speed", "1", "--export", str(out))  # fmt: skip
    assert code == 0, err
    assert (out / "epsilon_toy.dem").read_text().startswith("toy 0.9")
    wrote = stdout.split("wrote ")[-1].strip().split(", ")
    assert [w.rsplit("/", 1)[-1] for w in wrote[-7:]] == [
        "epsilon_lammps.in",
        "epsilon_liggghts.in",
        "epsilon_mercurydpm.cpp",
        "epsilon_yade.py",
        "epsilon_toy.dem",
        *plugin,
    ]


def test_a_new_module_in_the_dem_package_is_found_and_written(registry, tmp_path, monkeypatch):
    # One new file beside lammps.py and the others; no other module edited.
    folder = tmp_path / "more_codes"
    folder.mkdir()
    (folder / "toy_code.py").write_text(TOY_SOURCE)
    monkeypatch.setattr(dem, "__path__", [*dem.__path__, str(folder)])
    dem._import_targets()
    assert list(DEM_TARGETS)[-1] == "toy_code"
    s = _law("grain")
    c = exports.constant_at(s, 500.0)
    exports.write_folder(s, c, tmp_path / "out")
    assert (tmp_path / "out" / "epsilon_toy.dem").read_text() == f"toy 1 1 {c.epsilon:.8f}\n"


def test_a_clash_of_names_or_files_is_refused(registry):
    before = dict(DEM_TARGETS)
    with pytest.raises(ValueError, match="clashes with the registered 'lammps'"):
        register_dem_target(DemTarget("lammps", "other.in", exports.lammps_snippet))
    with pytest.raises(ValueError, match=r"\(lammps.in\)"):
        register_dem_target(DemTarget("other", "lammps.in", exports.lammps_snippet))
    assert DEM_TARGETS == before
