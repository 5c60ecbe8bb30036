"""Extension points (issue 40): a new body kind is one module, registered, and nothing else.

``tests/_toy_kind.py`` registers the kind ``"toy"``: the disk's modes in a class and under a name
of their own, declared outside the package. Run through ``collide``, a sweep on spawned worker
processes (which find the kind through ``RESTITUTION_KINDS``) and the result store, it must give
the disk's numbers bit for bit -- same code path, same machine -- while every stored key and
every answer names the toy. No module of the package was edited for it.
"""

from __future__ import annotations

import numpy as np
import pytest

from restitution import get_modes
from restitution.bodies.kinds import PLUGINS_ENV, body_kind, geometries, register, unregister
from restitution.dynamics.collision import collide
from restitution.errors import InputError
from restitution.limits.curves import compute_curves
from restitution.limits.store import Store
from restitution.limits.sweep import SweepSettings, defaults_for, grid, run_sweep
from restitution.provenance import code_version


@pytest.fixture
def toy(monkeypatch):
    """The toy kind, registered here and, through the environment, in spawned workers."""
    monkeypatch.setenv(PLUGINS_ENV, "_toy_kind")
    import _toy_kind

    register(_toy_kind.KIND)
    yield _toy_kind
    unregister(_toy_kind.NAME)


def test_the_toy_kind_is_found_and_refused_after_it_is_removed(toy):
    assert "toy" in geometries() and body_kind("toy") is toy.KIND
    assert defaults_for("toy").geometry == "toy"
    assert defaults_for("toy").alphas == body_kind("disk").alpha_products
    unregister("toy")
    with pytest.raises(InputError, match="unknown geometry 'toy'; choose one of disk, sphere"):
        body_kind("toy")
    register(toy.KIND)
    with pytest.raises(InputError, match="registered already"):
        register(body_kind("disk").__class__(**{**vars(toy.KIND), "compute": None}))


def test_a_toy_body_collides_as_the_disk_does(toy):
    modes = get_modes(0.33, count=60, geometry="toy")
    disk = get_modes(0.33, count=60)
    assert isinstance(modes, toy.ToyModes) and modes.geometry == "toy"
    assert isinstance(modes.lowest(10), toy.ToyModes)
    for backend in ("compiled", "numpy"):
        a = collide(modes, 0.1, 500.0, backend=backend)
        b = collide(disk, 0.1, 500.0, backend=backend)
        assert a.epsilon == b.epsilon and a.n_steps == b.n_steps
        np.testing.assert_array_equal(a.mode_energy_after, b.mode_energy_after)
    # The energy balance of the toy's own run: what the rebound lacks is in its modes.
    assert abs(1.0 - a.epsilon**2 - a.mode_energy_after.sum()) < 1e-6


@pytest.mark.slow  # 9 s of the default run (stop 76: the default run under 10 min)
def test_a_toy_kind_runs_through_the_sweep_and_the_store(toy, tmp_path):
    """Spawned workers compute the toy's points (they register it from the environment); the
    store keys them by the toy's name and code version; the curves read back are the disk's."""
    small = dict(velocities=(0.1, 0.2), n_modes=(20, 30, 40), batch_size=3)
    curves = {}
    for geometry in ("toy", "disk"):
        settings = SweepSettings(geometry=geometry, **small)
        path = tmp_path / f"{geometry}.sqlite"
        report = run_sweep(grid([0.33], settings), store=path)
        assert report.computed == 18 and not report.failed, report
        curves[geometry] = compute_curves([0.33], settings, store=path, run=False)[0.33]
        with Store(path) as db:
            rows = db.points(geometry=geometry)
        assert len(rows) == 18
        assert {r.spec.geometry for r in rows} == {geometry}
        assert {r.code_version for r in rows} == {code_version(geometry)}
    assert code_version("toy") != code_version("disk")
    toy_eps = [lim.epsilon for lim in curves["toy"].limits]
    disk_eps = [lim.epsilon for lim in curves["disk"].limits]
    assert toy_eps == disk_eps and all(0.9 < e < 1.0 for e in toy_eps)
