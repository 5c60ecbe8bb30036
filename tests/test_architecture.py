"""The layers of docs/architecture.md hold: no module imports the package root, and no import runs
from a lower layer to a higher one (read from the source with :mod:`ast`, imports inside
functions included); and above the body layer no module names a kind of body by a literal
string: the layers above read the kind's attributes (issue 40)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import restitution
from restitution.bodies.kinds import geometries

SRC = Path(restitution.__file__).parent

# Rank of every top-level part of the package: a module may import only parts of lower or equal
# rank (docs/architecture.md). The foundation modules serve every layer.
RANK = {
    "_version": 0,
    "_paths": 0,
    "errors": 0,
    "status": 0,
    "jsonable": 0,
    "provenance": 0,
    "atomic": 0,
    "file_set": 0,
    "estimate": 0,
    "budget": 0,
    "bodies": 1,
    "dynamics": 2,
    "vibrating": 3,
    "quasistatic": 3,
    "limits": 4,
    "laws": 5,
    "fem": 6,
    "reproduction": 7,
    "cli": 8,
}


def _modules():
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC)
        if rel.parts == ("__init__.py",):
            continue  # the root re-exports the public API
        yield rel, ast.parse(path.read_text(), filename=str(path))


def _imports(tree):
    """``(line, dotted name)`` of every restitution module a file imports."""
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if node.module == "restitution" or node.module.startswith("restitution."):
                for alias in node.names:
                    yield node.lineno, f"{node.module}.{alias.name}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name == "restitution" or alias.name.startswith("restitution."):
                    yield node.lineno, alias.name


def _part(rel: Path) -> str:
    return rel.parts[0].removesuffix(".py")


def test_every_part_has_a_rank():
    parts = {_part(rel) for rel, _ in _modules()}
    assert parts <= set(RANK), parts - set(RANK)


def _violations(rel: Path, tree) -> list[str]:
    own = RANK[_part(rel)]
    found = []
    for line, name in _imports(tree):
        parts = name.split(".")
        if len(parts) < 2 or parts[1] not in RANK:
            found.append(f"{rel}:{line} imports the package root ({name})")
        elif RANK[parts[1]] > own:
            found.append(f"{rel}:{line} imports {name} from a higher layer")
    return found


@pytest.mark.parametrize(
    "rel,tree", list(_modules()), ids=lambda x: "" if isinstance(x, ast.Module) else str(x)
)
def test_no_import_of_the_root_or_from_a_higher_layer(rel, tree):
    assert _violations(rel, tree) == []


def test_the_check_sees_violations():
    source = (
        "import restitution\n"
        "from restitution import get_modes\n"
        "def f():\n"
        "    from restitution.laws.law_load import law\n"
        "from restitution.bodies.material import Material\n"
    )
    found = _violations(Path("dynamics/x.py"), ast.parse(source))
    assert len(found) == 3, found
    assert "root" in found[0] and "root" in found[1] and "higher layer" in found[2]


# -- no kind by name above the body layer -------------------------------------------------------


def _docstrings(tree) -> set[int]:
    """``id`` of every docstring (module, class, function) and attribute docstring (a string
    statement after an assignment): prose may name a kind."""
    found = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        for statement in body if isinstance(body, list) else ():
            if (
                isinstance(statement, ast.Expr)
                and isinstance(statement.value, ast.Constant)
                and isinstance(statement.value.value, str)
            ):
                found.add(id(statement.value))
    return found


def _kind_literals(rel: Path, tree, names) -> list[str]:
    """Every string constant equal to a kind's name in a module outside ``bodies/``."""
    if rel.parts[0] == "bodies":
        return []
    skip = _docstrings(tree)
    return [
        f"{rel}:{node.lineno} names the kind {node.value!r}; read an attribute of "
        "restitution.bodies.kinds.body_kind(...) instead"
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and node.value in names and id(node) not in skip
    ]


@pytest.mark.parametrize(
    "rel,tree", list(_modules()), ids=lambda x: "" if isinstance(x, ast.Module) else str(x)
)
def test_no_kind_is_named_by_a_literal_above_the_body_layer(rel, tree):
    assert _kind_literals(rel, tree, set(geometries())) == []


def test_the_kind_check_sees_literals_but_not_prose():
    source = (
        '"""The disk\'s law: ``geometry="disk"``."""\n'
        "def f(geometry):\n"
        '    """For a "sphere" too."""\n'
        '    if geometry == "disk":\n'
        '        return {"sphere": 1}\n'
        "X = 1\n"
        '"""X of the "disk"."""\n'
    )
    names = {"disk", "sphere"}
    found = _kind_literals(Path("laws/x.py"), ast.parse(source), names)
    assert sorted(line.split(" names")[0] for line in found) == ["laws/x.py:4", "laws/x.py:5"]
    assert "names the kind 'disk'; read an attribute" in found[0] + found[1]
    assert _kind_literals(Path("bodies/disk/kind.py"), ast.parse(source), names) == []
