"""Richardson extrapolation of a mesh-convergence study to zero element size.

Three meshes whose element sizes shrink by a constant ratio ``r`` (``r = 2`` for the graded
meshes of :mod:`restitution.fem.graded`) give values ``y0, y1, y2`` (coarse to fine) of a
quantity with error ``C h^p``. With the differences ``d1 = y1 - y0`` and ``d2 = y2 - y1``:

* **monotone** (``d1 d2 > 0``, ``|d2| < |d1|``): the observed order is
  ``p = log(d1 / d2) / log r``; the limit is ``y2 + d2 / (r^p - 1)`` and its error the size of
  that correction (the grid-convergence index of Roache with safety factor 1). ``p`` is
  clipped to ``[p_min, p_max]`` for the correction, and the fit is flagged when it had to be.
* **oscillatory** (``d1 d2 < 0``, ``|d2| < |d1|``): no order can be fitted; the limit is ``y2``
  and its error ``|d2|``, the last difference (the sequence still contracts).
* **not contracting** (``|d2| >= |d1|``): the limit is ``y2`` with error ``|d1| + |d2|`` and the
  study is flagged as not asymptotic.

With two levels the limit is ``y1`` with error ``|d1|`` (flagged: the order cannot be judged).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError
from restitution.jsonable import finite_or_none

__all__ = ["MeshLimit", "richardson_limit"]

P_MIN = 1.0
"""Smallest order used for a correction (below it the study is far from asymptotic)."""
P_MAX = 6.0
"""Largest order used for a correction (P2 elements converge at about 4 in energy)."""


@dataclass(frozen=True)
class MeshLimit:
    """The ``h -> 0`` limit of a mesh-convergence study.

    Attributes
    ----------
    values : tuple of float
        The study's values, coarse to fine.
    ratio : float
        Element-size ratio between consecutive levels.
    limit, limit_err : float
        Extrapolated value and its error.
    rate : float
        Observed order ``p`` (``nan`` when it cannot be fitted).
    kind : str
        ``"monotone"``, ``"oscillatory"``, ``"not contracting"`` or ``"two levels"``.
    asymptotic_ok : bool
    message : str
        Why not, when not asymptotic.
    """

    values: tuple[float, ...]
    ratio: float
    limit: float
    limit_err: float
    rate: float
    kind: str
    asymptotic_ok: bool
    message: str = ""

    def to_dict(self) -> dict:
        """JSON-ready dictionary (``nan`` as ``None``)."""
        return {
            "values": [finite_or_none(x) for x in self.values],
            "ratio": self.ratio,
            "limit": finite_or_none(self.limit),
            "limit_err": finite_or_none(self.limit_err),
            "rate": finite_or_none(self.rate),
            "kind": self.kind,
            "asymptotic_ok": self.asymptotic_ok,
            "message": self.message,
        }


def richardson_limit(
    values, ratio: float = 2.0, *, p_min: float = P_MIN, p_max: float = P_MAX
) -> MeshLimit:
    """Extrapolate the last three values of a refinement study to ``h = 0``.

    Parameters
    ----------
    values : sequence of float
        Values at levels of decreasing element size, coarse to fine (2 or more).
    ratio : float
        Element-size ratio between consecutive levels, > 1.
    p_min, p_max : float
        Bounds of the order used for the correction.

    Returns
    -------
    MeshLimit

    Examples
    --------
    >>> fit = richardson_limit([1 + 16e-4, 1 + 1e-4, 1 + 1 / 16 * 1e-4])
    >>> round(fit.rate, 6), round(fit.limit, 12)
    (4.0, 1.0)
    """
    y = tuple(float(x) for x in values)
    if len(y) < 2 or not all(math.isfinite(x) for x in y):
        raise InputError(f"need at least two finite values for a mesh limit, got {y}")
    if not ratio > 1:
        raise InputError(f"the refinement ratio must exceed 1, got {ratio}")
    if len(y) == 2:
        d = abs(y[1] - y[0])
        return MeshLimit(
            y, ratio, y[1], d, float("nan"), "two levels", False,
            "two levels: the order of convergence cannot be judged; add a third",
        )  # fmt: skip
    d1, d2 = y[-2] - y[-3], y[-1] - y[-2]
    if d2 == 0.0:
        return MeshLimit(y, ratio, y[-1], abs(d1) / ratio**p_max, float("inf"), "monotone", True)
    if abs(d2) >= abs(d1):
        return MeshLimit(
            y, ratio, y[-1], abs(d1) + abs(d2), float("nan"), "not contracting", False,
            f"the last difference {d2:.3g} is not smaller than the one before {d1:.3g}; "
            "refine further",
        )  # fmt: skip
    if d1 * d2 < 0:
        return MeshLimit(y, ratio, y[-1], abs(d2), float("nan"), "oscillatory", True)
    rate = math.log(d1 / d2) / math.log(ratio)
    used = float(np.clip(rate, p_min, p_max))
    correction = d2 / (ratio**used - 1.0)
    ok = p_min <= rate <= p_max
    message = "" if ok else f"observed order {rate:.2f} outside [{p_min:g}, {p_max:g}]; clipped"
    return MeshLimit(y, ratio, y[-1] + correction, abs(correction), rate, "monotone", ok, message)
