"""Building a law from computed results: the result store's sweep, extrapolated.

:mod:`restitution.laws.law` serves laws; this module makes one from the collisions in a result
store (:mod:`restitution.limits.store`) through the extrapolations of
:func:`restitution.limits.curves.compute_curves`, without computing a collision.
"""

from __future__ import annotations

import os

from restitution.laws.law import EpsilonLaw
from restitution.limits.curves import compute_curves
from restitution.limits.store import Store
from restitution.limits.sweep import DEFAULTS, SweepSettings

__all__ = ["law_from_store"]


def law_from_store(
    nu: float,
    store: Store | str | os.PathLike,
    settings: SweepSettings = DEFAULTS,
) -> EpsilonLaw:
    """The law epsilon(v) for Poisson number ``nu`` from the points of a result store.

    Parameters
    ----------
    nu : float
        Poisson number of the body ``settings.geometry`` (two-dimensional for the disk,
        three-dimensional for the sphere).
    store : Store or path
        The result store; nothing is computed, missing points are left out (and flag their
        speed).
    settings : SweepSettings
        Grid of the store's sweep, and the body (``settings.geometry``) the law is of.

    Returns
    -------
    EpsilonLaw

    Raises
    ------
    RestitutionError
        If fewer than two speeds have a valid extrapolation.
    """
    curve = compute_curves([nu], settings, store=store, run=False)[float(nu)]
    return EpsilonLaw.from_curve(curve)
