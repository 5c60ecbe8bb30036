"""What a friction route is: the protocol of every way the package computes an oblique impact's
Coulomb friction (``--friction-model``), and its registry (issue 63).

Units: the dynamics' reduced units (``E = rho = R = 1``, speeds in ``c``, ``alpha`` in ``1 /
R``); estimates in seconds and bytes.

A **friction route** (:class:`FrictionRoute`) takes a grain's modes (the kind's
``oblique_body``), the normal and tangential speeds, ``mu`` and the wall, and returns an
:class:`~restitution.dynamics.oblique.ObliqueCollision`. Each declares

* its ``name`` (``--friction-model``'s word), ``help`` (the option's sentence on it),
  ``order`` (the lowest is the default) and ``law_rank`` (the lowest that serves a kind is
  ``law --angle``'s default for it: the law is served by its best route),
* whether it serves a body kind (:meth:`FrictionRoute.serves`) and, where not, what it
  ``needs`` (the refusal's words),
* whether friction acts at every wall node (``every_node``: its low-speed limit is microslip's,
  law (b); else one stick/slip state's) and whether it takes ``kappa``,
* its work before it starts (:meth:`FrictionRoute.work`, an
  :class:`~restitution.dynamics.oblique_cost.ObliqueWork`) and its run
  (:meth:`FrictionRoute.collision`), with the words the command line prints of both,
* and what ``law --angle`` runs (:meth:`FrictionRoute.law_collision`, :meth:`FrictionRoute.
  law_work`, ``law_walls``, ``law_how``, ``law_advice``): one wall, or two and the rigid wall
  extrapolated from them.

The layers above (the command line, the law request, the law's answer and its text) read these
attributes; none compares a route's name. A new route is one module of this package that builds
its object and calls :func:`register_friction_route`, and one line in the package's
``__init__`` that imports it.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

from restitution.errors import InputError

__all__ = [
    "ONE_WALL",
    "OneWallLaw",
    "FrictionRoute",
    "default_friction_route",
    "friction_route",
    "friction_names",
    "friction_routes",
    "law_default",
    "refuse_kappa",
    "routes_help",
    "register_friction_route",
    "unregister_friction_route",
]


@runtime_checkable
class FrictionRoute(Protocol):
    """One way to compute an oblique impact's friction (module docs)."""

    name: str
    """``--friction-model``'s word for it."""

    help: str
    """What it is, in the option's help: one sentence."""

    order: int
    """Its place among the choices; the lowest is the default (``collide --angle``'s)."""

    law_rank: int
    """Its place among the routes that serve a kind when ``law --angle`` names none: the
    lowest that serves the kind is the law's default for it (:func:`law_default`)."""

    integrator: str
    """The steps it takes, in words (``"DOP853"``, ``"Verlet"``)."""

    every_node: bool
    """Friction at every wall node (its low-speed limit is microslip's, law (b)), or one
    stick/slip state for the contact (the one-state limit)."""

    takes_kappa: bool
    """Whether ``kappa`` (the tangential spring at each node over the normal one) is its
    setting."""

    needs: str
    """What a kind needs for it, in a refusal's words (``""`` when every kind is served)."""

    law_walls: tuple[float, ...]
    """The walls ``law --angle`` runs it on, as multiples of the law's ``alpha``; with two the
    answer is extrapolated to the rigid wall from them (:meth:`law_collision`)."""

    law_how: str
    """How :meth:`law_work` estimates, in the law's note."""

    law_advice: str
    """What ``law --angle``'s answer is and is not (its points' advice)."""

    def serves(self, kind) -> bool:
        """Whether it computes the body kind ``kind`` (a
        :class:`~restitution.bodies.kinds.BodyKind`)."""

    def describe(self, kappa: float | None) -> str:
        """The friction in an answer's words, with its setting."""

    def contact(self, result) -> str:
        """How the contact went in ``result`` (an ``ObliqueCollision``), in words."""

    def work(self, body, v_normal: float, v_tangential: float, alpha: float,
             kappa: float | None):  # fmt: skip
        """The estimated work of :meth:`collision`
        (:class:`~restitution.dynamics.oblique_cost.ObliqueWork`)."""

    def plan(self, work) -> str:
        """What :meth:`collision` will do, in words, from its ``work``."""

    def collision(self, body, v_normal: float, v_tangential: float, mu: float, alpha: float,
                  kappa: float | None):  # fmt: skip
        """One oblique collision of ``body`` (an ``ObliqueCollision``)."""

    def law_work(self, body, v_normal: float, v_tangential: float, alpha: float,
                 kappa: float | None):  # fmt: skip
        """The estimated work of :meth:`law_collision`."""

    def law_collision(self, body, v_normal: float, v_tangential: float, mu: float,
                      alpha: float, kappa: float | None):  # fmt: skip
        """What ``law --angle`` reports at the wall ``alpha``: :meth:`collision` there, or on
        ``law_walls`` and extrapolated."""


ONE_WALL = (
    "one mode count on one wall, not extrapolated to N, alpha -> infinity: the error is the "
    "change from half the modes; beta in partial slip still moves with the modes "
    "(docs/oblique.md)"
)
"""The ``law_advice`` of a route that ``law --angle`` runs on one wall."""


class OneWallLaw:
    """A route's law runs as its own runs: ``law --angle`` takes :meth:`collision` on the law's
    wall alone (``law_walls = (1.0,)``, advice :data:`ONE_WALL`). Mixed into a route."""

    law_walls: tuple[float, ...] = (1.0,)
    law_advice: str = ONE_WALL

    def law_work(self, body, v_normal, v_tangential, alpha, kappa):
        return self.work(body, v_normal, v_tangential, alpha, kappa)

    def law_collision(self, body, v_normal, v_tangential, mu, alpha, kappa):
        return self.collision(body, v_normal, v_tangential, mu, alpha, kappa)


_ROUTES: dict[str, FrictionRoute] = {}


def register_friction_route(route: FrictionRoute) -> FrictionRoute:
    """Make ``route`` known by its name (a route of the same name is replaced); returns it."""
    if not isinstance(route, FrictionRoute):
        raise TypeError(
            f"{route!r} does not implement the FrictionRoute protocol (name, help, order, "
            "law_rank, integrator, every_node, takes_kappa, needs, law_walls, law_how, law_advice, "
            "serves, describe, contact, work, plan, collision, law_work, law_collision)"
        )
    _ROUTES[route.name] = route
    return route


def unregister_friction_route(name: str) -> None:
    """Forget the route ``name`` (a test's toy); nothing when it is not registered."""
    _ROUTES.pop(name, None)


def friction_routes() -> tuple[FrictionRoute, ...]:
    """Every registered route, the default first."""
    return tuple(sorted(_ROUTES.values(), key=lambda r: (r.order, r.name)))


def friction_names() -> tuple[str, ...]:
    """``--friction-model``'s choices: the routes' names, the default first."""
    return tuple(r.name for r in friction_routes())


def routes_help() -> str:
    """``--friction-model``'s help: each route's name and sentence, the default first, with the
    kinds it serves where not every kind, and where it is the default (``collide``'s; ``law``'s
    for the kinds of :func:`law_default`)."""
    from restitution.bodies.kinds import kinds

    oblique = [k for k in kinds().values() if k.oblique_body is not None]
    parts = []
    for r in friction_routes():
        served = [k.geometry for k in oblique if r.serves(k)]
        only = "" if len(served) == len(oblique) else f"the {' and the '.join(served)}: "
        where = ["collide's default"] if r is default_friction_route() else []
        law_kinds = [k.geometry for k in oblique if law_default(k) is r]
        if law_kinds:
            where.append(f"law's default for the {' and the '.join(law_kinds)}")
        parts.append(f"'{r.name}' ({only}{r.help}{'; ' if where else ''}{', '.join(where)})")
    return "; or ".join(parts)


def law_default(kind) -> FrictionRoute:
    """The route ``law --angle`` takes for the body kind ``kind`` when none is named: the
    lowest ``law_rank`` among the routes that serve it."""
    serving = [r for r in friction_routes() if r.serves(kind)]
    if not serving:
        raise InputError(f"no friction route serves the {kind.geometry}")
    return min(serving, key=lambda r: (r.law_rank, r.order, r.name))


def default_friction_route() -> FrictionRoute:
    """The route an oblique impact takes when none is named (the lowest ``order``)."""
    return friction_routes()[0]


def friction_route(name: str | None, kind=None, flag: str = "--friction-model") -> FrictionRoute:
    """The route ``name`` (``None``: the default), checked to serve the body kind ``kind`` when
    one is given.

    Raises
    ------
    InputError
        If no route has that name, or the route does not serve ``kind``: one line naming the
        routes there are, or the kinds it serves and the routes that serve ``kind``.
    """
    route = default_friction_route() if name is None else _ROUTES.get(name)
    if route is None:
        raise InputError(
            f"{flag} {name!r} is not a friction route; choose one of "
            f"{', '.join(r.name for r in friction_routes())}"
        )
    if kind is not None and not route.serves(kind):
        from restitution.bodies.kinds import kinds

        served = [k.geometry for k in kinds().values() if route.serves(k)]
        others = [r.name for r in friction_routes() if r.serves(kind)]
        raise InputError(
            f"{flag} {route.name} needs {route.needs}, which the {' and the '.join(served)} "
            f"has and the {kind.geometry} has not yet; use {flag} {' or '.join(others)}"
        )
    return route


def refuse_kappa(route: FrictionRoute, kappa: float | None) -> None:
    """Refuse a ``kappa`` given to a route that does not take it, naming those that do.

    Raises
    ------
    InputError
        If ``kappa`` is given and ``route`` does not take it.
    """
    if kappa is None or route.takes_kappa:
        return
    takers = "; or ".join(f"--friction-model {r.name} ({r.help.split(';')[0]})"
                          for r in friction_routes() if r.takes_kappa)  # fmt: skip
    raise InputError(
        f"--kappa has no effect with --friction-model {route.name} ({route.describe(None)}); "
        f"add {takers}"
    )
