"""The Python edge of the laws: :func:`si_law` with the options of every mechanism, the equal of
``restitution law`` for a law at every speed.

Units: SI at the edge (Pa, kg/m^3, m/s, s, m, J/m^2; each mechanism's option states its unit).

Without a mechanism's option this is :func:`restitution.laws.si_law.si_law`, the elastic law.
With one (``relaxation_time=`` and ``radius=``, ``measured_epsilon=`` and ``measured_speed=``,
or a registered mechanism's own, :func:`restitution.laws.mechanisms.base.extra_options`), the
options make the same :class:`~restitution.laws.request.LawRequest` as the command line's, the
first route that serves it gives the elastic law, and the mechanism that answers makes its law
at every speed of the elastic law (its ``table``: the damped law's sum at every computed speed);
a mechanism that makes none yet is refused in one line that names the call that answers at
asked speeds (``serve(request(...))``).
"""

from __future__ import annotations

import os

from restitution.errors import InputError
from restitution.laws import mechanisms as _mechanisms  # noqa: F401  (registers them)
from restitution.laws import routes as _routes  # noqa: F401  (registers them)
from restitution.laws.mechanisms.base import answering
from restitution.laws.request import request
from restitution.laws.routes.base import law_at_every_speed
from restitution.laws.si_law import SILaw
from restitution.laws.si_law import si_law as elastic_si_law
from restitution.laws.units import Grain

__all__ = ["si_law"]


def _silent(text: str) -> None:
    """The default ``note``: say nothing."""


def si_law(
    E: float | None = None,
    nu: float | None = None,
    rho: float | None = None,
    shape: str | None = None,
    against: str | None = None,
    *,
    grain: Grain | None = None,
    path: str | os.PathLike | None = None,
    radius_ratio: float | None = None,
    partner_grain: Grain | None = None,
    geometry: str | None = None,
    note=None,
    progress: bool = False,
    **options,
) -> SILaw:
    """epsilon at SI speeds for a material given by its 3D constants (or as a ``grain``), with
    the losses of the mechanisms whose options are given (module docs).

    The arguments before ``note`` are those of :func:`restitution.laws.si_law.si_law`;
    ``options`` are the options of ``restitution law`` as keywords (``relaxation_time``,
    ``radius``, ``measured_epsilon``, ``measured_speed``, a mechanism's own such as a toy's);
    ``note`` is called with each line worth telling (what is computed), ``progress`` asks for a
    progress bar on stderr.

    Examples
    --------
    >>> glass = si_law(63e9, 0.2481, 2500, "cylinder", "wall")
    >>> round(glass.grain.c_m_s)
    5182
    """
    if not options:
        return elastic_si_law(E, nu, rho, shape, against, grain=grain, path=path,
                              radius_ratio=radius_ratio, partner_grain=partner_grain,
                              geometry=geometry)  # fmt: skip
    if grain is not None:
        if (E, nu, rho, shape, geometry) != (None,) * 5:
            raise InputError("give the grain as grain=Grain(...) or as E, nu, rho and shape, "
                             "not both")  # fmt: skip
        E, nu, rho, shape = grain.E, grain.nu, grain.rho, grain.shape
    given = dict(E=E, nu=nu, rho=rho, shape=shape or geometry, against=against, law_file=path,
                 partner_radius_ratio=radius_ratio)  # fmt: skip
    if partner_grain is not None:
        given.update(partner_E=partner_grain.E, partner_nu=partner_grain.nu,
                     partner_rho=partner_grain.rho)  # fmt: skip
    r = request(**{k: v for k, v in given.items() if v is not None}, **options)
    mechanism = answering(r)
    s = law_at_every_speed(r, note or _silent, progress)
    if mechanism is None:
        return s
    table = getattr(mechanism, "table", None)
    if table is None:
        raise InputError(
            f"{mechanism.words}: no law at every speed is made yet; ask for the speeds you need "
            "with restitution.serve(restitution.laws.request.request(..., speeds=[...]))"
        )
    return table(r, s, note or _silent, progress)
