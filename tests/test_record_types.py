"""One record type for an epsilon with its error (issue 60, item 4): at most three classes of the
package hold a coefficient of restitution and its error as fields of their own, and every class
whose instances answer ``epsilon`` and ``epsilon_err`` answers ``estimate`` too (read from the
source with :mod:`ast`, as ``tests/test_architecture.py`` reads the imports).

Before the issue seventeen classes answered an epsilon with its error, fifteen of them holding
both as fields and five without ``estimate``. Now :class:`restitution.estimate.Estimate` and the
SI answer (:class:`restitution.laws.si_point.SIPoint`) hold them; a law's point
(:class:`~restitution.laws.law_point.LawPoint`), a stored reference point and a constant for a
DEM code hold an ``Estimate``; a route's result keeps what it computes, the energy loss and its
error, and derives epsilon from it (``restitution.limits.extrapolation.epsilon_from_loss``).

The rule reads names: a field holds an epsilon when its name has ``eps`` or ``epsilon`` as a
word, its error when it is that name with ``_err`` or ``_error`` added or with ``epsilon``
replaced by ``epsilon_err``, ``error`` or ``err`` (``fem_epsilon`` and ``fem_error``); both
scalars by their annotations (``float``, ``float | None``, none in ``__init__``), so a curve's
arrays (a figure's, a law's points) and an error message (a result store's row) are not such a
pair. A pair under other names (a judge's ``reference`` and ``reference_err``) escapes it.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import restitution

SRC = Path(restitution.__file__).parent

MOST = 3
"""Classes that may hold an epsilon and its error as fields: the value (``Estimate``), a law's
point and an SI answer (issue 60)."""

_SCALAR_NAMES = {"float", "int", "None", "Optional", "Union"}
_EPSILON = re.compile(r"(^|_)eps(ilon)?(_|$)")
_PROPERTIES = {"property", "cached_property"}


def _trees():
    for path in sorted(SRC.rglob("*.py")):
        yield path.relative_to(SRC), ast.parse(path.read_text(), filename=str(path))


def _scalar(annotation) -> bool:
    """Whether an annotation is a number (``None``: a field set in ``__init__``, unknown)."""
    if annotation is None:
        return True
    if isinstance(annotation, ast.Constant) and isinstance(annotation.value, str):
        annotation = ast.parse(annotation.value, mode="eval").body
    names = {n.id for n in ast.walk(annotation) if isinstance(n, ast.Name)}
    names |= {n.attr for n in ast.walk(annotation) if isinstance(n, ast.Attribute)}
    return bool(names) and names <= _SCALAR_NAMES


def _fields(cls: ast.ClassDef) -> dict[str, ast.expr | None]:
    """Name -> annotation of every field: the class body's annotated names (a dataclass's, a
    named tuple's) and the ``self.name = ...`` of its ``__init__`` (annotation ``None``)."""
    out: dict[str, ast.expr | None] = {}
    for statement in cls.body:
        if isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
            if "ClassVar" not in ast.unparse(statement.annotation):
                out[statement.target.id] = statement.annotation
        elif isinstance(statement, ast.FunctionDef) and statement.name == "__init__":
            for node in ast.walk(statement):
                targets = node.targets if isinstance(node, ast.Assign) else []
                if isinstance(node, ast.AnnAssign):
                    targets = [node.target]
                for t in targets:
                    if isinstance(t, ast.Attribute) and getattr(t.value, "id", None) == "self":
                        out.setdefault(t.attr, None)
    return out


def _error_names(name: str) -> set[str]:
    """The names of ``name``'s error: ``epsilon`` -> ``epsilon_err``, ``epsilon_error``,
    ``error``, ``err``; ``fem_epsilon`` -> ``fem_error``; ``epsilon_law`` ->
    ``epsilon_law_err``."""
    word = "epsilon" if "epsilon" in name else "eps"
    out = {f"{name}_err", f"{name}_error"}
    out |= {name.replace(word, f"{word}_err", 1), name.replace(word, "error", 1)}
    out.add(name.replace(word, "err", 1))
    return out - {name}


def epsilon_pairs(cls: ast.ClassDef) -> list[tuple[str, str]]:
    """``(epsilon, error)`` field names a class holds, both scalars."""
    scalars = {n for n, a in _fields(cls).items() if _scalar(a)}
    return sorted(
        (name, err)
        for name in scalars
        if _EPSILON.search(name) and "err" not in name
        for err in _error_names(name) & scalars
    )


def holders(trees) -> list[str]:
    """``module:Class`` of every class holding an epsilon and its error as fields."""
    return [
        f"{rel}:{node.name} ({', '.join(f'{e}, {x}' for e, x in epsilon_pairs(node))})"
        for rel, tree in trees
        for node in ast.walk(tree)
        if isinstance(node, ast.ClassDef) and epsilon_pairs(node)
    ]


def _is_property(statement) -> str | None:
    """The name a class-body statement defines as a scalar property (``@property def x`` not
    annotated as an array, ``x = property(...)``), or ``None``."""
    if isinstance(statement, ast.FunctionDef):
        decorators = {getattr(d, "id", getattr(d, "attr", None)) for d in statement.decorator_list}
        scalar = _scalar(statement.returns) or statement.name == "estimate"
        return statement.name if decorators & _PROPERTIES and scalar else None
    if isinstance(statement, ast.Assign) and isinstance(statement.value, ast.Call):
        if getattr(statement.value.func, "id", None) in _PROPERTIES:
            names = [t.id for t in statement.targets if isinstance(t, ast.Name)]
            return names[0] if names else None
    return None


def without_estimate(trees) -> list[str]:
    """Every class whose instances answer a scalar ``epsilon`` and ``epsilon_err`` (fields or
    properties; a curve's arrays aside) but not ``estimate`` (field or property), ``Estimate``
    itself aside."""
    out = []
    for rel, tree in trees:
        for node in ast.walk(tree):
            if not isinstance(node, ast.ClassDef) or node.name == "Estimate":
                continue
            fields = _fields(node)
            names = {n for n, a in fields.items() if _scalar(a)}
            names |= {_is_property(s) for s in node.body} - {None}
            if {"epsilon", "epsilon_err"} <= names and "estimate" not in {*names, *fields}:
                out.append(f"{rel}:{node.name}")
    return out


def test_at_most_three_classes_hold_an_epsilon_with_its_error():
    found = holders(_trees())
    assert len(found) <= MOST, (
        f"{len(found)} classes hold an epsilon and its error as fields (at most {MOST}): "
        f"{'; '.join(found)}. Hold a restitution.estimate.Estimate (EstimateView gives it the "
        "names epsilon, epsilon_err, status, asymptotic_ok and message), a LawPoint or an "
        "SIPoint instead, or keep the energy loss and derive epsilon from it"
    )


def test_every_class_answering_an_epsilon_with_its_error_answers_an_estimate():
    assert without_estimate(_trees()) == []


NEW_RECORDS = """
import numpy as np
from dataclasses import dataclass
from typing import NamedTuple

@dataclass(frozen=True)
class NewPoint:
    v: float
    epsilon: float
    epsilon_err: float | None

class Row(NamedTuple):
    fem_epsilon: float
    fem_error: float

class Built:
    def __init__(self, eps, err):
        self.epsilon_law = eps
        self.epsilon_law_err = err

@dataclass
class Curve:
    epsilon: np.ndarray
    epsilon_err: np.ndarray

@dataclass
class Row2:
    epsilon: float
    error: str | None

@dataclass
class Derived:
    energy_loss: float
    energy_loss_err: float

    @property
    def epsilon_curve(self) -> np.ndarray:
        return np.zeros(3)

    @property
    def epsilon(self) -> float:
        return (1 - self.energy_loss) ** 0.5

    @property
    def epsilon_err(self) -> float:
        return self.energy_loss_err / (2 * self.epsilon)
"""


def test_the_rules_see_a_new_record_but_not_curves_messages_or_derived_values():
    new = [(Path("laws/new.py"), ast.parse(NEW_RECORDS))]
    found = holders(new)
    assert [line.split(" (")[0] for line in found] == [
        "laws/new.py:NewPoint",
        "laws/new.py:Row",
        "laws/new.py:Built",
    ], found
    assert "(epsilon, epsilon_err)" in found[0] and "(fem_epsilon, fem_error)" in found[1]
    # The package's holders and two new ones exceed the bound: the first test would fail.
    assert len(holders(_trees())) + 2 > MOST
    # A class answering epsilon and epsilon_err without estimate: the new point and the one
    # that derives them from its loss (the array curve is not a scalar's).
    assert without_estimate(new) == ["laws/new.py:NewPoint", "laws/new.py:Derived"]
