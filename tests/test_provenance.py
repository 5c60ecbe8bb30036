"""The code digest that keys stored results: it follows the solver of one body, not the others."""

from __future__ import annotations

import pytest

import restitution.provenance as provenance


def test_a_new_body_leaves_the_disks_code_version_alone(monkeypatch):
    before = provenance.code_version("disk")
    real_modules, real_folders = provenance.package_modules, provenance.body_folders

    def with_cube(package):
        extra = ("restitution.bodies.cube.modes",) if package == provenance.BODIES else ()
        return real_modules(package) + extra

    monkeypatch.setattr(provenance, "package_modules", with_cube)
    monkeypatch.setattr(provenance, "body_folders", lambda: (*real_folders(), "cube"))
    provenance.code_version.cache_clear()
    try:
        # A new body's (here unreadable) module is not part of the disk's digest...
        assert provenance.code_version("disk") == before
        # ...but it is part of its own, which without its source is the bare version.
        assert provenance.code_version("cube") == provenance.__version__
    finally:
        provenance.code_version.cache_clear()


def test_each_body_digests_its_own_folder_only(monkeypatch):
    seen = {}
    real = provenance.source_digest
    monkeypatch.setattr(
        provenance,
        "source_digest",
        lambda modules, tag="": seen.setdefault(tag, modules) and real(modules, tag),
    )
    for geometry in ("disk", "sphere"):
        seen.clear()
        provenance.code_version.cache_clear()
        provenance.code_version(geometry)
        modules = seen[""]
        other = "sphere" if geometry == "disk" else "disk"
        assert any(m.startswith(f"restitution.bodies.{geometry}.") for m in modules)
        assert not any(m.startswith(f"restitution.bodies.{other}.") for m in modules)
        assert "restitution.dynamics.kernel" in modules and "restitution.bodies.base" in modules
    provenance.code_version.cache_clear()


def test_the_digest_changes_with_a_solver_source(monkeypatch):
    modules = provenance.package_modules("restitution.dynamics")
    assert "restitution.dynamics.kernel" in modules
    one = provenance.source_digest(modules)
    two = provenance.source_digest(tuple(m for m in modules if not m.endswith(".kernel")))
    assert one != two and one.startswith(provenance.__version__ + "+")


@pytest.mark.parametrize("listed", ["QUASISTATIC_MODULES", "DISK_QUASISTATIC_MODULES"])
def test_the_low_speed_version_covers_what_the_estimate_imports(listed):
    """Every quasistatic module that a module of the sphere's or the disk's list imports is in
    the list, so an edit of a low-speed route's sources always changes
    quasistatic_code_version."""
    import ast
    import importlib.util

    QUASISTATIC_MODULES = getattr(provenance, listed)
    for name in QUASISTATIC_MODULES:
        origin = importlib.util.find_spec(name).origin
        tree = ast.parse(open(origin).read())
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith(
                "restitution.quasistatic."
            ):
                assert node.module in QUASISTATIC_MODULES, (name, node.module)
