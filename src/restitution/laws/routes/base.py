"""What a route is: the protocol of every way the elastic law of a request is found, and the
ordered list :func:`restitution.laws.serve.serve` takes the first serving one from.

Units: SI at the edge (the request's); a computing route's plan in seconds of wall time on one
core.

A **route** (:class:`Route`) answers two questions: does it serve this request
(:meth:`Route.serves`), and what is the elastic law (:meth:`Route.law`, an
:class:`~restitution.laws.si_law.SILaw` whose points the mechanisms then add their losses to).
A route that computes the asked speeds alone (an elastic wall, a pair's low-speed route) also has a
``table``, its law at every speed of its range (:func:`law_at_every_speed`: what
:func:`restitution.si_law` and the exports serve). The routes shipped, in the order they are asked
(:func:`routes`): an elastic wall (half-space or plate), a law file the user gives, a law computed
on demand (``--compute``), a pair's low-speed route, the shipped laws (interpolated in ``nu``). A
new route is one module that builds its object and calls :func:`register_route`; its ``order`` says
where it is asked (the shipped laws serve everything else, so they stay last).

A **computing route** (:class:`ComputingRoute`) makes a law file while the request waits: the
modal production settings and the static residual (``--route``). They belong to the making
side of the laws (:mod:`restitution.laws.making`), which the serving side never imports: they
register themselves here (:mod:`restitution.laws.making.routes`), and serving asks for them by
name (:func:`computing_route`), for their plan (what a refusal advises) or their law.
"""

from __future__ import annotations

from pathlib import Path
from typing import Protocol, runtime_checkable

from restitution import budget
from restitution.errors import InputError

__all__ = [
    "ComputingRoute",
    "Plan",
    "Route",
    "check_speed_count",
    "computing_route",
    "computing_routes",
    "law_at_every_speed",
    "register_computing_route",
    "register_route",
    "route_for",
    "routes",
]


@runtime_checkable
class Route(Protocol):
    """One way of finding the elastic law that answers a request (module docs)."""

    name: str
    """A short name, for the registry and the notes."""

    order: float
    """Where it is asked: routes of lower order first (the shipped ones: 10 an elastic wall,
    20 a given law file, 30 a computed one, 40 a pair's low-speed route, 100 the shipped laws,
    which serve everything else)."""

    def serves(self, request) -> bool:
        """Whether this route answers ``request`` (a
        :class:`~restitution.laws.request.LawRequest`); asked in :func:`routes` order."""

    def law(self, request, note, progress: bool):
        """The elastic law of ``request`` (an :class:`~restitution.laws.si_law.SILaw`), with
        ``note`` called for each line worth telling (what is computed and how long it takes)
        and ``progress`` the wish for a progress bar on stderr. Refuses, before anything is
        computed, what it cannot finish (:class:`~restitution.errors.InputError`)."""


def law_at_every_speed(request, note, progress: bool = False):
    """The elastic law of ``request`` at every speed of its range: the serving route's
    ``table`` where it has one (a route that computes the asked speeds alone: an elastic wall,
    a pair's low-speed route), else its :meth:`Route.law`, which serves every speed already."""
    route = route_for(request)
    table = getattr(route, "table", None)
    return (route.law if table is None else table)(request, note, progress)


class Plan(Protocol):
    """What a computing route will do, before it does it."""

    path: Path
    exists: bool
    seconds: float

    def words(self) -> str:
        """One line for the user: what is computed and how long it takes."""


@runtime_checkable
class ComputingRoute(Protocol):
    """A route that makes a law file while the request waits (module docs)."""

    name: str
    """Its name as ``--route`` takes it."""

    def plan(self, nu: float, geometry: str, partner=None, *, reuse: bool = True) -> Plan:
        """The plan of :meth:`compute` with the same arguments (nothing is computed);
        ``reuse=False``: a law file already made is computed again."""

    def check(self, plan: Plan, force: bool = False) -> None:
        """Refuse ``plan`` when it would take longer than
        :data:`restitution.budget.TIME_BOUND_S` unless ``force`` (one line, with the numbers)."""

    def compute(
        self, nu: float, geometry: str, partner=None, *, store=None, progress=False,
        force: bool = False,
    ) -> Path:  # fmt: skip
        """The law file, computed unless it was made before; refused beyond
        :data:`restitution.budget.TIME_BOUND_S` unless ``force``."""


_ROUTES: list[Route] = []
_COMPUTING: dict[str, ComputingRoute] = {}


def register_route(route: Route) -> Route:
    """Add ``route`` to the routes :func:`route_for` asks, in the order of their ``order``; a
    route of the same name is replaced."""
    if not isinstance(route, Route):
        raise TypeError(
            f"{route!r} does not implement the Route protocol (name, order, serves, law)"
        )
    _ROUTES[:] = sorted([r for r in _ROUTES if r.name != route.name] + [route],
                        key=lambda r: r.order)  # fmt: skip
    return route


def routes() -> tuple[Route, ...]:
    """The registered routes, in the order they are asked."""
    return tuple(_ROUTES)


def route_for(request) -> Route:
    """The first route that serves ``request``."""
    for route in _ROUTES:
        if route.serves(request):
            return route
    raise InputError(
        "no route serves this request (routes: "
        f"{', '.join(r.name for r in _ROUTES) or 'none registered'}); import restitution "
        "before restitution.laws, which registers them"
    )


def register_computing_route(route: ComputingRoute) -> ComputingRoute:
    """Make ``route`` the computing route of its name (``--route NAME``)."""
    if not isinstance(route, ComputingRoute):
        raise TypeError(f"{route!r} does not implement the ComputingRoute protocol")
    _COMPUTING[route.name] = route
    return route


def computing_routes() -> tuple[str, ...]:
    """The names of the registered computing routes."""
    return tuple(_COMPUTING)


def computing_route(name: str) -> ComputingRoute:
    """The computing route ``name``; :class:`~restitution.errors.InputError` naming the ones
    there are when it is not registered."""
    try:
        return _COMPUTING[name]
    except KeyError:
        there = ", ".join(_COMPUTING) or "none: import restitution, which registers them"
        raise InputError(f"no computing route {name!r} (there are: {there})") from None


def check_speed_count(count: int, per_speed: float, what: str) -> None:
    """Refuse, before anything is computed, ``count`` speeds of ``per_speed`` seconds each
    beyond the bound of one run (:data:`restitution.budget.TIME_BOUND_S`), with the numbers."""
    need = count * per_speed
    if need > budget.TIME_BOUND_S:
        most = int(budget.TIME_BOUND_S // per_speed)
        raise InputError(
            f"{count} speeds would take about {budget.format_duration(need)} ({what}, about "
            f"{per_speed:g} s a speed), more than the {budget.format_duration(budget.TIME_BOUND_S)}"
            f" bound of one run; ask for at most {most} speeds at a time"
        )
