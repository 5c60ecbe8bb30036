"""What a mechanism is: the protocol of every loss an answer may contain beside the elastic law,
its options, and the registry :func:`restitution.laws.serve.serve` applies them from.

Units: SI at the edge (each option states its own unit; the answer's speeds in m/s).

A **mechanism** (:class:`Mechanism`) is one way kinetic energy leaves a collision: the elastic
waves and vibrations of the bodies (the elastic law itself), the waves radiated into an elastic
wall, the material's viscosity, plastic flow, adhesion. Each declares

* its ``name`` and its ``words`` (what an answer's ``mechanisms`` and ``mechanisms_left_out``
  say),
* the request options it owns (:class:`MechanismOption`: the command-line option, the Python
  keyword, the help, the unit): options of :class:`~restitution.laws.request.LawRequest`'s own
  fields, or new ones, which the request keeps in its ``extra`` mapping, the command line offers
  (``restitution law --<option>``) and :func:`restitution.laws.request.request` takes as
  keywords,
* whether a request asks for it (:meth:`Mechanism.asked`) and what it refuses before any law is
  loaded (:meth:`Mechanism.check`: where it does not apply, what it does not go with),
* its slow-speed form (``slow_form``, in words: how ``1 - epsilon`` behaves as ``v -> 0``),
* and, for a mechanism of rank above 0, the answer it makes of the elastic law
  (:meth:`Mechanism.answer`, through :func:`restitution.laws.answer.finish`, which writes the
  constants and exports of the law it tabulates) and, optionally, ``table(request, si, note,
  progress)``: its law at every speed of the elastic law as an SI law, which
  :func:`restitution.laws.api.si_law` returns.

**How losses join: the rule, once.** The mechanisms that act on the contact's force (viscosity,
plastic flow, adhesion) act on one force pulse; the waves are then the elastic law's loss scaled
by how much the actual pulse drives the modes (and the wall) more or less than Hertz's:
``epsilon^2 = epsilon_contact^2 - loss_waves`` (:mod:`restitution.laws.plastic` for viscosity
and plastic flow, :mod:`restitution.laws.adhesive` for adhesion with viscosity). One request is
answered by the highest-``rank`` mechanism it asks for, which takes the others' parameters onto
its pulse (plastic flow takes the relaxation time, adhesion too); mechanisms whose pulses are
not derived together (:meth:`Mechanism.check` of each says which) are refused in one line. The
viscous loss alone is the damped law (:mod:`restitution.laws.damped`), whose sum of the elastic
and viscous losses is checked against damped modal collisions.

A new mechanism is one module that builds its object and calls :func:`register_mechanism`.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from restitution.errors import InputError

__all__ = [
    "Mechanism",
    "MechanismOption",
    "answering",
    "extra_options",
    "mechanism",
    "mechanism_fields",
    "mechanisms",
    "register_mechanism",
    "unregister_mechanism",
    "used_fields",
    "words",
]


@dataclass(frozen=True)
class MechanismOption:
    """One request option of a mechanism: the command-line ``option`` (``--work-of-adhesion``),
    the Python ``keyword`` (``work_of_adhesion``), its ``help``, its ``unit`` (``""``:
    dimensionless) and whether it must be ``positive``. ``field`` says the option is a field of
    :class:`~restitution.laws.request.LawRequest` itself (the older mechanisms'); otherwise the
    request keeps it in ``extra``."""

    keyword: str
    option: str
    help: str
    unit: str = ""
    positive: bool = False
    field: bool = False

    def metadata(self) -> dict:
        """The option as a request field's metadata
        (:func:`restitution.laws.request_fields.option`)."""
        return {"option": self.option, "help": self.help, "type": "float", "unit": self.unit,
                "positive": self.positive}  # fmt: skip


@runtime_checkable
class Mechanism(Protocol):
    """One loss mechanism (module docs)."""

    name: str
    """Its key in an answer (``"waves"``, ``"wall"``, ``"viscous"``, ``"plastic"``,
    ``"adhesion"``)."""

    words: str
    """What it is, in the words of an answer's ``mechanisms``."""

    rank: float
    """Which mechanism answers a request that asks for several: the highest rank; ``0`` for the
    mechanisms the elastic law holds (the waves, an elastic wall's radiation)."""

    options: tuple[MechanismOption, ...]
    """The request options it owns."""

    reads: tuple[str, ...]
    """Other fields of the request it reads (``radius``, ``relaxation_time``): a value given
    for them is used when this mechanism is asked."""

    slow_form: str
    """How ``1 - epsilon`` behaves at slow impacts, in words."""

    def asked(self, request) -> bool:
        """Whether ``request`` asks for this mechanism."""

    def check(self, request) -> None:
        """Refuse, in one line, what this mechanism cannot serve in ``request`` (before any law
        is loaded)."""

    def answer(self, request, si, note, progress: bool):
        """The answer (:class:`~restitution.laws.answer.LawAnswer`) of ``request`` with this
        mechanism on the elastic law ``si`` (an :class:`~restitution.laws.si_law.SILaw`) and
        the others it takes onto its pulse; never called for a mechanism of rank 0 (the elastic
        law holds it already)."""


_MECHANISMS: dict[str, Mechanism] = {}


def register_mechanism(mechanism: Mechanism) -> Mechanism:
    """Make ``mechanism`` known by its name (a mechanism of the same name is replaced)."""
    if not isinstance(mechanism, Mechanism):
        raise TypeError(
            f"{mechanism!r} does not implement the Mechanism protocol (name, words, rank, "
            "options, reads, slow_form, asked, check, answer)"
        )
    _MECHANISMS[mechanism.name] = mechanism
    return mechanism


def unregister_mechanism(name: str) -> None:
    """Forget the mechanism ``name`` (a test's toy); nothing when it is not registered."""
    _MECHANISMS.pop(name, None)


def mechanisms() -> tuple[Mechanism, ...]:
    """Every registered mechanism, the elastic law's first, then by rank."""
    return tuple(sorted(_MECHANISMS.values(), key=lambda m: (m.rank, m.name)))


def mechanism(name: str) -> Mechanism:
    """The mechanism ``name``; :class:`~restitution.errors.InputError` naming those there are."""
    try:
        return _MECHANISMS[name]
    except KeyError:
        raise InputError(f"no mechanism {name!r} (there are: {', '.join(_MECHANISMS)})") from None


def words(name: str) -> str:
    """What the mechanism ``name`` is, in an answer's words."""
    return mechanism(name).words


def mechanism_fields(names: Iterable[str]) -> dict:
    """``{"mechanisms": [...], "mechanisms_left_out": [...]}`` in words, for the mechanism
    ``names`` an answer contains: those it leaves out are the registered mechanisms a request
    may ask for (rank above 0) that it does not contain."""
    names = list(names)
    left = [m.name for m in mechanisms() if m.rank > 0 and m.name not in names]
    return {
        "mechanisms": [words(m) for m in names],
        "mechanisms_left_out": [words(m) for m in left],
    }


def extra_options() -> tuple[MechanismOption, ...]:
    """The options of the registered mechanisms that are not fields of the request (its
    ``extra``), in the mechanisms' order."""
    return tuple(o for m in mechanisms() for o in m.options if not o.field)


def answering(request) -> Mechanism | None:
    """The mechanism that answers ``request``: the highest-ranked one it asks for, after every
    asked mechanism's :meth:`~Mechanism.check`; ``None`` for the elastic law alone."""
    asked = [m for m in mechanisms() if m.rank > 0 and m.asked(request)]
    for m in asked:
        m.check(request)
    return max(asked, key=lambda m: m.rank) if asked else None


def used_fields(request) -> set[str]:
    """The request fields the mechanisms ``request`` asks for use (their options and what they
    read): a value given for another is one nothing reads."""
    out = set()
    for m in mechanisms():
        if m.rank > 0 and m.asked(request):
            out.update(o.keyword for o in m.options)
            out.update(m.reads)
    return out
