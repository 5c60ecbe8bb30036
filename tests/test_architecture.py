"""The layers of docs/architecture.md hold: no module imports the package root, and no import runs
from a lower layer to a higher one (read from the source with :mod:`ast`, imports inside
functions included); above the body layer no module names a kind of body by a literal
string: the layers above read the kind's attributes (issue 40); and outside the partner kinds
no module compares or keys on a partner's name (issue 60)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import restitution
from restitution.bodies.kinds import geometries
from restitution.laws.partners.base import against_choices, partner_kinds

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


# -- no partner by name outside the partner kinds (issue 60) -----------------------------------

PARTNER_HOMES = (("bodies",), ("laws", "partners"))
"""Where a partner's name may be written: its constants' classes (``bodies/wall.py``'s
``"half-space"`` and ``"plate"`` records, ``bodies/pair/``) and the partner kinds."""

OTHER_WALLS = (("dynamics",), ("reproduction", "figures", "residual_convergence.py"))
"""Modules where ``"wall"`` has another meaning, left out of the rule: in ``dynamics/`` it is
the contact law's exponential wall (``steps.py`` names the step limit of its stiffness
``alpha v`` ``"wall"``), a body-on-wall collision's own vocabulary below the laws, which knows
no partner kinds; in the residual study's records (``residual_convergence.py``) ``"wall"`` is
that wall's stiffness ``alpha R``, a number, not a partner. ``fem/`` and ``reproduction/``
otherwise are checked: the finite elements' wall records use the partners'
:data:`~restitution.laws.partners.base.WALL_KEY`, the figures the kinds' ``against``."""


def _used(node, parents) -> bool:
    """Whether a string constant is compared, used as a key or an index, passed to a call or
    given as a parameter's default (an element of a tuple, list or set that is so counts):
    what selects a partner by its name. Prose (docstrings, an f-string's text, a label put into
    a message, a class field's default) is not."""
    parent = parents.get(id(node))
    while isinstance(parent, ast.Tuple | ast.List | ast.Set):
        node, parent = parent, parents.get(id(parent))
    if isinstance(parent, ast.Compare | ast.keyword | ast.arguments | ast.MatchValue):
        return True
    if isinstance(parent, ast.Subscript):
        return parent.slice is node
    if isinstance(parent, ast.Dict):
        return any(k is node for k in parent.keys)
    if isinstance(parent, ast.Call):
        return any(a is node for a in parent.args)
    return False


def _partner_literals(rel: Path, tree, names) -> list[str]:
    """Every string constant equal to a partner's name (or ``against`` value) that is compared
    or used as a key (:func:`_used`) in a module outside the partners' homes and the modules
    of another ``"wall"``."""
    if any(rel.parts[: len(home)] == home for home in PARTNER_HOMES + OTHER_WALLS):
        return []
    skip = _docstrings(tree)
    parents = {id(child): node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)}
    return [
        f"{rel}:{node.lineno} names the partner {node.value!r}; read an attribute of "
        "restitution.laws.partners.base.partner_of(...) instead"
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and node.value in names
        and id(node) not in skip
        and _used(node, parents)
    ]


def _partner_names() -> set[str]:
    return {k.name for k in partner_kinds()} | set(against_choices())


@pytest.mark.parametrize(
    "rel,tree", list(_modules()), ids=lambda x: "" if isinstance(x, ast.Module) else str(x)
)
def test_no_partner_is_named_by_a_literal_outside_the_partner_kinds(rel, tree):
    assert _partner_literals(rel, tree, _partner_names()) == []


def test_the_partner_check_sees_comparisons_and_keys_but_not_prose():
    source = (
        '"""Against the ``"wall"``."""\n'
        'def f(s, law, against="grain"):\n'  # 2: a default
        '    """For a "plate" too."""\n'
        '    if s.against == "wall":\n'  # 4: compared
        '        return law.metadata["wall"]\n'  # 5: a key
        '    if s.against in ("grain", "x"):\n'  # 6: compared, in a tuple
        '        return {"half-space": 1}\n'  # 7: a dict key
        '    g(s, "wall")\n'  # 8: passed
        '    g(s, against="grain")\n'  # 9: passed by keyword
        '    who = [(s, "grain")]\n'  # a message's label
        '    raise ValueError(f"wall{1}: no {who}")\n'  # an f-string's text
        "class K:\n"
        '    name: str = "wall"\n'  # a field's default
        "X = 1\n"
        '"""X of the "wall"."""\n'
    )
    names = {"wall", "grain", "plate", "half-space"}
    found = _partner_literals(Path("laws/x.py"), ast.parse(source), names)
    lines = sorted(int(line.split(" names")[0].split(":")[1]) for line in found)
    assert lines == [2, 4, 5, 6, 7, 8, 9], found
    assert "names the partner 'wall'; read an attribute" in found[1] + found[2]
    for home in ("bodies/wall.py", "laws/partners/plate.py", "dynamics/steps.py"):
        assert _partner_literals(Path(home), ast.parse(source), names) == []
    assert _partner_literals(Path("fem/x.py"), ast.parse(source), names) != []


# -- laws/: serving apart from making, no cycle, no module over 800 lines (issue 60) -----------

MAKING = ("laws", "making")
"""The making side of the laws (production, laws computed on demand, refinement, judges,
offline checks); the rest of ``laws/`` serves."""

MAX_LAW_MODULE_LINES = 800


def _module_names() -> dict[str, Path]:
    """``{dotted module name: path}`` of every module of the package (a package by its
    ``__init__``)."""
    out = {}
    for path in SRC.rglob("*.py"):
        parts = ("restitution", *path.relative_to(SRC).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _module_of(name: str, modules) -> str | None:
    """The module an imported dotted name lives in: the longest prefix that is a module."""
    parts = name.split(".")
    for end in range(len(parts), 0, -1):
        candidate = ".".join(parts[:end])
        if candidate in modules:
            return candidate
    return None


def _law_graph(modules) -> dict[str, set[str]]:
    """Imports between modules of ``laws/`` (inside functions too), ``{module: {imported}}``;
    an import of a package's submodule does not count its ``__init__`` as well."""
    graph = {}
    for name, path in modules.items():
        if not name.startswith("restitution.laws"):
            continue
        edges = set()
        for _, imported in _imports(ast.parse(path.read_text())):
            target = _module_of(imported, modules)
            if target and target.startswith("restitution.laws") and target != name:
                edges.add(target)
        graph[name] = edges
    return graph


def _cycles(graph) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, found = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def _is_making(name: str) -> bool:
    return name.split(".")[1:3] == list(MAKING)


def _serving_imports_making(graph) -> list[str]:
    return [f"{a} imports {b}" for a, edges in sorted(graph.items()) if not _is_making(a)
            for b in sorted(edges) if _is_making(b)]  # fmt: skip


def test_serving_never_imports_making():
    assert _serving_imports_making(_law_graph(_module_names())) == []


def test_laws_have_no_import_cycle():
    assert _cycles(_law_graph(_module_names())) == []


def test_the_law_checks_see_cycles_and_wrong_way_imports():
    graph = {
        "restitution.laws.a": {"restitution.laws.b"},
        "restitution.laws.b": {"restitution.laws.making.c"},
        "restitution.laws.making.c": {"restitution.laws.a"},
        "restitution.laws.making.d": {"restitution.laws.a"},
    }
    assert _cycles(graph) == [
        ["restitution.laws.a", "restitution.laws.b", "restitution.laws.making.c"]
    ]
    assert _serving_imports_making(graph) == [
        "restitution.laws.b imports restitution.laws.making.c"
    ]
    # An import inside a function is an edge: the cycle of issue 60 was hidden that way.
    source = "def f():\n    from restitution.laws.making.compute import plan\n"
    modules = {"restitution.laws.making.compute": Path("x")}
    assert [_module_of(n, modules) for _, n in _imports(ast.parse(source))] == [
        "restitution.laws.making.compute"
    ]


@pytest.mark.parametrize(
    "name", sorted(n for n in _module_names() if n.startswith("restitution.laws"))
)
def test_no_law_module_is_over_800_lines(name):
    lines = len(_module_names()[name].read_text().splitlines())
    assert lines <= MAX_LAW_MODULE_LINES, f"{name}: {lines} lines; split it by job"
