"""What a partner is: the protocol of everything a grain may hit, and the registry the layers
above read it from.

Units: SI at the edge (the request's); a partner's constants in the grain's reduced units
(``E = rho = R = 1`` of the grain's own constants, speeds in ``c``).

A **partner kind** (:class:`PartnerKind`) is what a grain hits: a rigid wall, a second grain (of
any size and material: :class:`~restitution.bodies.pair.partner.Partner`), an elastic
half-space, an elastic plate (:mod:`restitution.bodies.wall`). Each declares

* its ``name`` and the ``against`` value it answers (``restitution law --against``'s choices
  are the registered kinds' ``against``, :func:`against_choices`; several kinds may answer one
  value, told apart by the options a request gives: :meth:`PartnerKind.matches`),
* the request options it owns (``options``),
* its speed scale (``speed_factor``: ``k`` in ``v = w / (k c)``) and what the speed ``w`` means
  (``speed_meaning``),
* its contact constants (:meth:`PartnerKind.contact`, :meth:`PartnerKind.half_space`), the
  mechanism of the energy it takes itself (``loss``), its low-speed form
  (:meth:`PartnerKind.slow_form`), its quasistatic note and status words,
* its DEM words (``is_grain``: a grain-grain contact, the exports carrying each grain on the
  wall too; ``dem_mass``, ``dem_mass_line``, ``variance_factor``),
* and how it is written into a law file and read back (:meth:`PartnerKind.write`,
  :meth:`PartnerKind.read`: an elastic wall's constants under :data:`WALL_KEY` of the law's
  metadata).

The layers above read these attributes; they never compare a partner's name. A new partner
kind is one module that builds its object and calls :func:`register_partner`; a built-in one is
imported in :mod:`restitution.laws.partners`.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

from restitution.errors import InputError, describe

__all__ = [
    "WALL_KEY",
    "NoWall",
    "PartnerKind",
    "against_choices",
    "by_against",
    "owner",
    "partner_for",
    "partner_kind",
    "partner_kinds",
    "partner_of",
    "partner_of_body",
    "register_partner",
    "stored_wall",
    "unregister_partner",
]

WALL_KEY = "wall"
"""The key under which an elastic wall's constants (:meth:`restitution.bodies.wall.HalfSpace.
to_dict`) are written: in a law file's metadata, and in a finite-element reference point of a
wall (:mod:`restitution.fem.wall_reference`)."""


@runtime_checkable
class PartnerKind(Protocol):
    """One kind of partner a grain hits (module docs)."""

    name: str
    """Its name in the registry (and, for an elastic wall, the ``kind`` of its record)."""

    against: str
    """The ``against`` value (``--against``) it answers."""

    order: float
    """Where it is asked (:func:`partner_for`): lower first; the first kind of an ``against``
    value is the one a law without a record of its own is served against."""

    options: tuple[str, ...]
    """The request fields it owns (``wall_E``, ``partner_radius_ratio``, ...)."""

    speed_factor: float
    """``k`` in ``v = w / (k c)``: 1 for a wall, 2 for two identical grains."""

    speed_meaning: str
    """What the SI speed ``w`` means, in words."""

    body: type | None
    """The class of its constants in the body layer (:class:`~restitution.bodies.wall.HalfSpace`,
    :class:`~restitution.bodies.wall.Plate`, :class:`~restitution.bodies.pair.partner.Partner`);
    ``None``: it has none (the rigid wall)."""

    is_grain: bool
    """Whether it is a second grain: ``w`` is the relative speed of two grains, its DEM contact
    is grain-grain, and the exports carry each grain on the rigid wall too."""

    loss: str | None
    """The name of the mechanism of the energy it takes itself (an elastic wall's radiation,
    :mod:`restitution.laws.mechanisms.waves`); ``None``: it takes none."""

    quasistatic_note: str | None
    """What a low-speed point of its law is; ``None``: its body kind's route says."""

    route_words: str
    """What its laws computed at the asked speeds only are called in a status
    (``"elastic wall"``, ``"pair"``)."""

    model_words: str
    """Whose model refused a speed, in a status (``"half-space"``, ``"plate"``)."""

    served_further: str
    """Advice added where its route's value is not informative (``""``: none)."""

    split_head: str
    """The head of the column of the loss's split between the two bodies."""

    dem_mass: str
    """The effective mass of its contact, in the words of a DEM snippet's comment."""

    dem_mass_line: str
    """The same as a line of C++ (MercuryDPM's ``mass``)."""

    variance_factor: float
    """``sigma^2 / T`` of the normal impact speed of a gas of grains: 2 between two grains, 1
    against a wall."""

    def matches(self, request) -> bool:
        """Whether ``request`` (a :class:`~restitution.laws.request.LawRequest`) asks for this
        partner."""

    def meaning(self, si) -> str:
        """What the SI speed ``w`` of the answer ``si`` means (with its constants)."""

    def contact(self, si):
        """``(Hertz's law, mass)`` of the contact of ``si`` (an
        :class:`~restitution.laws.si_law.SILaw` of spheres) with this partner, reduced units;
        :class:`~restitution.errors.InputError` where no such contact is modelled."""

    def half_space(self, law):
        """The elastic half-space of ``law`` (:class:`restitution.bodies.wall.HalfSpace`) whose
        ``E*`` and radiation the contact takes; ``None``: none."""

    def slow_form(self, planar: bool) -> tuple[str, float, str] | None:
        """``(form, exponent, what it is)`` of ``1 - epsilon^2`` as ``v -> 0`` when the energy
        it takes dominates (:mod:`restitution.laws.exports.below`); ``None``: it takes none."""

    def read(self, law) -> dict | None:
        """Its record in ``law``'s file (``None``: the law holds none of this kind)."""

    def write(self, law, wall) -> None:
        """Write ``wall`` (its :mod:`restitution.bodies.wall` object) into ``law``'s file."""


_KINDS: dict[str, PartnerKind] = {}


class NoWall:
    """The answers of a partner kind that is no elastic wall (the rigid wall, a grain): no
    half-space, no slow form of its own, nothing in a law file. A kind inherits them instead
    of writing them again."""

    def half_space(self, law):
        return None

    def slow_form(self, planar: bool):
        return None

    def read(self, law) -> dict | None:
        return None

    def write(self, law, wall) -> None:
        """Nothing: the law carries no record of this partner (a pair's law carries its
        partner in its own ``partner``)."""


def register_partner(kind: PartnerKind) -> PartnerKind:
    """Make ``kind`` known by its name (a kind of the same name is replaced)."""
    if not isinstance(kind, PartnerKind):
        raise TypeError(f"{kind!r} does not implement the PartnerKind protocol")
    _KINDS[kind.name] = kind
    return kind


def unregister_partner(name: str) -> None:
    """Forget the partner kind ``name`` (a test's toy); nothing when it is not registered."""
    _KINDS.pop(name, None)


def partner_kinds() -> tuple[PartnerKind, ...]:
    """Every registered partner kind, in the order they are asked."""
    return tuple(sorted(_KINDS.values(), key=lambda k: (k.order, k.name)))


def partner_kind(name: str) -> PartnerKind:
    """The partner kind ``name``; :class:`~restitution.errors.InputError` naming those there
    are."""
    try:
        return _KINDS[name]
    except KeyError:
        there = ", ".join(k.name for k in partner_kinds())
        raise InputError(f"no partner kind {name!r} (there are: {there})") from None


def against_choices() -> tuple[str, ...]:
    """The ``against`` values the registered kinds answer, each once, in their order."""
    return tuple(dict.fromkeys(k.against for k in partner_kinds()))


def _choices_words() -> str:
    names = [repr(a) for a in against_choices()]
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


def by_against(against) -> PartnerKind:
    """The first kind that answers ``against`` (the one a law without a record of its own is
    served against); :class:`~restitution.errors.InputError` for another value."""
    if isinstance(against, str):
        for kind in partner_kinds():
            if kind.against == against:
                return kind
    raise InputError(
        f"against (the collision partner) must be {_choices_words()}, got {describe(against)}"
    )


def owner(option: str) -> PartnerKind:
    """The partner kind that owns the request field ``option`` (its ``options``)."""
    for kind in partner_kinds():
        if option in kind.options:
            return kind
    raise InputError(f"no partner kind owns the option {option!r}")


def partner_for(request) -> PartnerKind:
    """The partner kind ``request`` asks for: the first, in order, whose :meth:`~PartnerKind.
    matches` holds."""
    for kind in partner_kinds():
        if kind.matches(request):
            return kind
    return by_against(request.against)


def stored_wall(law) -> dict | None:
    """The elastic wall written into ``law``'s file (under :data:`WALL_KEY` of its metadata),
    ``None`` for none: what :meth:`PartnerKind.read` reads."""
    metadata = getattr(law, "metadata", None)
    return None if metadata is None else metadata.get(WALL_KEY)


def partner_of_body(body) -> PartnerKind:
    """The partner kind whose constants ``body`` holds (a :class:`~restitution.bodies.wall.
    HalfSpace`, a :class:`~restitution.bodies.wall.Plate`, ...)."""
    for kind in partner_kinds():
        if kind.body is not None and type(body) is kind.body:
            return kind
    raise InputError(f"no partner kind holds a {type(body).__name__}")


def partner_of(obj) -> PartnerKind:
    """The partner kind of ``obj``: a law (an elastic wall's, from its file; a pair's, from its
    ``partner``; else the rigid wall's) or an answer with an ``against`` and a ``law`` (an
    :class:`~restitution.laws.si_law.SILaw`: its law's elastic wall, else its ``against``)."""
    against = getattr(obj, "against", None)
    law = obj.law if against is not None else obj
    for kind in partner_kinds():
        if kind.read(law) is not None:
            return kind
    if against is not None:
        return by_against(against)
    pair = getattr(law, "partner", None)
    kinds = partner_kinds()
    if pair is not None:  # the kind of its second body's class, else the first grain kind
        return next((k for k in kinds if k.body is not None and type(pair) is k.body),
                    next(k for k in kinds if k.is_grain))  # fmt: skip
    return next(k for k in kinds if not k.is_grain and k.body is None)
