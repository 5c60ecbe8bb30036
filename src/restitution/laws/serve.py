"""Serve a :class:`~restitution.laws.request.LawRequest`: the one library call behind ``law``.

Units: SI (m/s; the law's own answer carries its units, :data:`restitution.laws.si_point.SI_UNITS`).

:func:`serve` takes the first route that serves the request (:mod:`restitution.laws.routes`:
an elastic wall, a given law file, a law computed on demand, a pair's low-speed route, the
shipped laws) for the elastic law, then the mechanism that answers
(:mod:`restitution.laws.mechanisms`: viscosity, plastic flow, adhesion; none: the elastic law
alone), which writes the constants for one-number DEM codes (per pair of particle types for two
grains) and the exports from the one law that served (:mod:`restitution.laws.answer`). It
returns a :class:`~restitution.laws.answer.LawAnswer`, the same object for a notebook as for the
command line, whose :meth:`~restitution.laws.answer.LawAnswer.to_dict` is the command's JSON.
Notes (what was computed, what was left out) go to the ``note`` callable instead of a terminal.

Example
-------
>>> from restitution.laws.request import LawRequest
>>> a = serve(LawRequest(E=63e9, nu=0.2481, rho=2500, shape="cylinder", against="wall",
...                      speeds=(1.0,)))
>>> 0.99 < a.points[0].epsilon < 1.0
True
"""

from __future__ import annotations

from collections.abc import Callable

from restitution.laws import mechanisms as _mechanisms  # noqa: F401  (registers them)
from restitution.laws import routes as _routes  # noqa: F401  (registers them)
from restitution.laws.answer import LawAnswer, elastic_answer
from restitution.laws.mechanisms.base import answering
from restitution.laws.oblique import ObliqueAnswer
from restitution.laws.request import LawRequest
from restitution.laws.routes.base import route_for

__all__ = ["LawAnswer", "head_on_points", "serve"]


def _silent(text: str) -> None:
    """The default ``note``: say nothing."""


def head_on_points(r, note: Callable[[str], None] = _silent) -> list | None:
    """The head-on law's points at the oblique request ``r``'s speeds, to read its
    ``epsilon_normal`` against (``None`` where no law serves the material)."""
    from restitution.errors import InputError

    try:
        return list(serve(r.head_on()).points)
    except InputError as exc:
        note(f"note: no head-on law to read epsilon_normal against ({exc})")
        return None


def serve(
    request: LawRequest, *, note: Callable[[str], None] = _silent, progress: bool = False
) -> LawAnswer | ObliqueAnswer:
    """The answer to ``request`` (module docs).

    Parameters
    ----------
    request : LawRequest
        The question; its construction refused inconsistent options already.
    note : callable, optional
        Called with one line for each note (the estimate of a computation, a closed form that
        could not be fitted); default: none.
    progress : bool
        Show a progress bar of a computation on stderr (``compute``), and, on a terminal, of
        a damped law's viscous collisions (inferring its relaxation time; tabulating it for
        the exports or constants, which a note announces with their number).

    Returns
    -------
    LawAnswer or ObliqueAnswer
        The latter for an oblique impact (``request.angle``; :mod:`restitution.laws.oblique`).

    Raises
    ------
    InputError
        When no law can serve (a Poisson number off the grid, two materials without a law),
        with the command or option that makes one.
    """
    r = request
    if r.oblique:  # an oblique impact is computed at the asked speeds, not read from a law
        from restitution.laws.oblique import oblique_answer

        return oblique_answer(r, note, head_on=head_on_points(r, note))
    mechanism = answering(r)  # its refusals before any law is loaded
    s = route_for(r).law(r, note, progress)
    if mechanism is None:
        return elastic_answer(r, s, note)
    return mechanism.answer(r, s, note, progress)
