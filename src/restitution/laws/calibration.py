"""One standard deviation of a served epsilon: the bound's components, scaled per route.

A law serves two errors of epsilon (issue 65):

* ``epsilon_err``, the **bound**: the points' own errors (the extrapolation in ``N`` and
  ``alpha``, interpolated between points) joined in quadrature with the interpolation term
  (:meth:`restitution.laws.law.EpsilonLaw.interpolation_err`); an upper estimate, unchanged;
* ``epsilon_sd``, **one standard deviation**: the same two components and the disagreement of a
  second interpolant (:meth:`restitution.laws.law.EpsilonLaw.spline_gap`, zero at the computed
  points), each scaled by a factor of the route that made the points, never above the bound,

      sd = min(sqrt((a * point_err)^2 + (b * interpolation_err)^2 + (d * spline_gap)^2), bound),

  and for a law interpolated in ``nu`` (:class:`restitution.laws.law_nu.NuInterpolatedLaw`) the
  grid laws' ``sd`` interpolated in ``nu`` joined with ``c`` times its ``nu``-interpolation
  term.

The factors were fitted on independent points (:mod:`restitution.fem.calibrate`: the
rule, the data and the coverage; docs/errors.md). A route without enough independent points
keeps its bound as its ``sd`` (factors 1, :attr:`RouteCalibration.calibrated` false) and says
so. The law files need no new field: the ``sd`` is computed when served.

Units: epsilon and its errors are dimensionless.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "BELOW",
    "CALIBRATIONS",
    "GIVEN",
    "MECHANISM",
    "MODAL",
    "NU",
    "QUASISTATIC",
    "RESIDUAL",
    "RESIDUAL_HARD",
    "SD_MEANING",
    "RouteCalibration",
    "point_factors",
    "sd_words",
]

MODAL = "modal"
"""Points of collisions extrapolated in ``N`` and ``alpha`` (a point without a ``route``)."""
QUASISTATIC = "quasistatic"
"""Points of a low-speed route (the disk's slow-impact model, the sphere's Rayleigh estimate)."""
RESIDUAL = "residual"
"""Points of collisions with a static residual (:mod:`restitution.laws.making.residual_law`)."""
RESIDUAL_HARD = "residual-hard"
"""Points of the residual route on walls 4 times the laws' (``alpha delta_max = 160, 320,
640``; the shipped disk laws' residual points, ``tools/residual_wall_ladder.py --apply``): a
calibration of its own, the route on the laws' walls being biased (docs/errors.md)."""
HARD_WALL = 160.0
"""The softest wall ``alpha delta_max`` of a residual point calibrated as :data:`RESIDUAL_HARD`."""
MECHANISM = "mechanism"
"""A law whose numbers hold more than the elastic waves (a damped, plastic or adhesive table, an
elastic wall's radiation): its errors are its own mechanism's."""
NU = "nu"
"""PCHIP in ``nu`` between grid laws."""
BELOW = "below"
"""A speed below a law computed at that speed by the law's low-speed route."""
GIVEN = "given"
"""A point this package did not compute (a law from given points, e.g. another program's data,
:meth:`restitution.laws.law.EpsilonLaw.from_points`): its error is its own."""


@dataclass(frozen=True)
class RouteCalibration:
    """The factors that turn a route's bound into one standard deviation.

    Attributes
    ----------
    route : str
        :data:`MODAL`, :data:`QUASISTATIC`, ...
    point_factor, interpolation_factor, gap_factor : float
        ``a``, ``b`` and ``d``: the scales of the point error, of the interpolation term and of
        the spline's gap.
    nu_factor : float
        ``c``: the scale of the ``nu``-interpolation term (route :data:`NU`).
    calibrated : bool
        Whether the factors come from independent points; ``False``: all 1, the ``sd`` is the
        bound.
    basis : str
        Where the factors come from, with the held-out coverage, or why none.
    """

    route: str
    point_factor: float = 1.0
    interpolation_factor: float = 1.0
    gap_factor: float = 1.0
    nu_factor: float = 1.0
    calibrated: bool = False
    basis: str = ""


CALIBRATIONS: dict[str, RouteCalibration] = {
    MODAL: RouteCalibration(
        MODAL,
        point_factor=0.54,
        interpolation_factor=0.07,
        gap_factor=0.77,
        calibrated=True,
        basis=(
            "a: maximum likelihood on 13 of the 26 finite-element points at modal laws' "
            "computed speeds (disk, sphere, two disks, steel-glass; the modal values where the "
            "shipped laws now serve the residual route's); b, d: on 47 of the 93 direct "
            "points between computed speeds (disk nu 0.33, 0.5; sphere 0.3, 0.4); held out: "
            "the other halves (restitution.fem.calibrate, docs/errors.md)"
        ),
    ),
    NU: RouteCalibration(
        NU,
        nu_factor=0.24,
        calibrated=True,
        basis=(
            "c: maximum likelihood on 51 of the 102 modal speeds of the direct laws at nu_2d = "
            "0.25, 3/7, 0.6, 0.8 against PCHIP in nu through 0.2, 0.33, 0.5, 0.7, 0.9, with "
            "each route's own values (the modal ones at rerouted speeds); held out: the other "
            "51 (docs/errors.md)"
        ),
    ),
    QUASISTATIC: RouteCalibration(
        QUASISTATIC,
        basis=(
            "not calibrated: 8 finite-element points lie in the low-speed routes' ranges, too "
            "few to fit and check; the sd is the bound (the route's model band)"
        ),
    ),
    RESIDUAL: RouteCalibration(
        RESIDUAL,
        basis=(
            "not calibrated: on the laws' own walls (alpha delta_max = 40-160) its 27 "
            "finite-element points share its walls and cannot judge its wall limit; on walls "
            "4-16 times harder (tests/data/residual_wall_ladder.json) the bound covers 28 of 36 "
            "points within one and 33 within two, so it is not a bound there (docs/errors.md); "
            "the sd is the bound"
        ),
    ),
    RESIDUAL_HARD: RouteCalibration(
        RESIDUAL_HARD,
        point_factor=0.50,
        interpolation_factor=0.07,
        gap_factor=0.77,
        calibrated=True,
        basis=(
            "f: maximum likelihood on 31 of the 62 comparisons of the route on walls 160-640 "
            "with the same route on harder walls (1280-5120 at the 38 points with v <= 1e-3, "
            "13 of them the modal route served before; 640-2560 at the 11 faster ones, at 12 "
            "speeds between its points and at the steel cylinder at 1 m/s; "
            "tests/data/residual_*ladder*.json); b, d: the modal route's; held out: the other "
            "31, 71.0 % within one, 96.8 % within two (docs/errors.md)"
        ),
    ),
    MECHANISM: RouteCalibration(
        MECHANISM,
        basis=(
            "not calibrated: a mechanism's table (damping, plastic flow, adhesion, an elastic "
            "wall) states its own error; the sd is that error (the damped sum lies 1.4-10.7 "
            "combined errors from its 10 stored modal points: not even a bound there, "
            "docs/errors.md)"
        ),
    ),
    BELOW: RouteCalibration(
        BELOW, basis="not calibrated: the low-speed route at the asked speed; the sd is its bound"
    ),
    GIVEN: RouteCalibration(
        GIVEN,
        basis="not calibrated: points given to the law, not computed here; the sd is their error",
    ),
}
"""Route -> its factors (:class:`RouteCalibration`)."""

SD_MEANING = (
    "epsilon_sd: one standard deviation, the bound's two components (the points' extrapolation "
    "error and the interpolation term) and a second interpolant's gap, scaled by factors "
    "fitted per route on independent points (finite elements, direct points between computed "
    "speeds, direct laws between Poisson numbers, the residual route on harder walls: 67-78 % "
    "of the held-out points within one sd, 96-100 % within two, docs/errors.md), never above "
    "the bound; where a route has too few independent points (low-speed routes, mechanisms' "
    "tables, residual laws on the laws' own walls) epsilon_sd is the bound and "
    "epsilon_sd_kind says 'bound'. epsilon_err: the bound, an upper estimate (not one for the "
    "residual route on the laws' own walls, docs/errors.md)"
)
"""What ``epsilon_sd`` covers, in the words of the JSON output."""


def sd_words(calibrated: bool) -> str:
    """``epsilon_sd_kind`` of a served value."""
    return "standard deviation" if calibrated else "bound"


def _point_routes(law) -> list[str]:
    """The route of each computed point of ``law`` (an :class:`EpsilonLaw`)."""
    from restitution.laws.mechanisms.bounds import law_mechanisms

    if law_mechanisms(law) != ["waves"]:
        return [MECHANISM] * int(law.v.size)
    out = []
    for record in law._records():
        # A modal point of this package keeps its extrapolation; one without came from outside.
        route = record.get("route") or (MODAL if "extrapolation" in record else GIVEN)
        if route == RESIDUAL and _softest_wall(record) >= HARD_WALL:
            route = RESIDUAL_HARD
        out.append(route if route in CALIBRATIONS else MECHANISM)
    return out


def _softest_wall(record: dict) -> float:
    """The softest wall ``alpha delta_max`` of a residual point (0 if it names none)."""
    walls = (record.get("residual") or {}).get("walls") or [0.0]
    return float(min(walls))


def point_factors(law) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(a, b, d, calibrated)`` at each computed point of ``law``, shape (K,) each."""
    routes = [CALIBRATIONS[r] for r in _point_routes(law)]
    return (
        np.array([r.point_factor for r in routes]),
        np.array([r.interpolation_factor for r in routes]),
        np.array([r.gap_factor for r in routes]),
        np.array([r.calibrated for r in routes], bool),
    )
