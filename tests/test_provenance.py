"""The code digest that keys stored results: it follows the solver of one body, not the others."""

from __future__ import annotations

import restitution.provenance as provenance


def test_a_new_body_leaves_the_disks_code_version_alone(monkeypatch):
    before = provenance.code_version("disk")
    real = provenance.package_modules

    def with_sphere(package):
        extra = ("restitution.bodies.sphere.modes",) if package == provenance.BODIES else ()
        return real(package) + extra

    monkeypatch.setattr(provenance, "package_modules", with_sphere)
    monkeypatch.setattr(provenance, "body_folders", lambda: ("disk", "sphere"))
    provenance.code_version.cache_clear()
    try:
        # The sphere's (here unreadable) module is not part of the disk's digest...
        assert provenance.code_version("disk") == before
        # ...but it is part of the sphere's, which without its source is the bare version.
        assert provenance.code_version("sphere") == provenance.__version__
    finally:
        provenance.code_version.cache_clear()


def test_the_digest_changes_with_a_solver_source(monkeypatch):
    modules = provenance.package_modules("restitution.dynamics")
    assert "restitution.dynamics.kernel" in modules
    one = provenance.source_digest(modules)
    two = provenance.source_digest(tuple(m for m in modules if not m.endswith(".kernel")))
    assert one != two and one.startswith(provenance.__version__ + "+")
