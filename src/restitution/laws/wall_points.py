"""The finite elements' stored points of a sphere on an elastic wall: read, and served where the
wall's routes have no value (issue 42).

Units: the ball's, ``E = rho = R = 1`` of its three-dimensional constants; ``v`` in
``c = sqrt(E / rho)``; the wall's constants as ratios to the ball's
(:class:`restitution.bodies.wall.HalfSpace`, :class:`~restitution.bodies.wall.Plate`).

The file ``restitution/laws/data/fem_reference_wall.json`` is written by
:mod:`restitution.fem.wall_reference` (the judge of the half-space and thin-plate routes, with
its provenance); :func:`load_wall_reference` reads it. Where the half-space route is beyond its
reach or Zener's thin-plate model does not hold, the issue's answer is the finite elements';
a run costs 10-45 minutes of one core, so a law served in seconds can only give the points
already computed. :func:`stored_wall_point` finds one for the asked ball, wall and speed: the
same ``nu`` and wall constants to a relative ``1e-6``, the speed within :data:`SPEED_MATCH`
(relative). Besides the shipped file it reads every file a user computed into
``<cache>/fem_wall`` (:func:`user_points_dir`, :func:`compute_command` says how), so that a
point computed once is served from then on: a file whose content digest does not match (changed
after :mod:`restitution.fem.wall_reference` wrote it) is not, with a warning, and no point with
impossible values (``epsilon`` outside ``(0, 1]``, a negative or non-finite error) is served.
Files without a digest (the shipped one, users' older ones: a point costs 10-45 minutes, it is
not recomputed on its own) are served when their values are possible.

A served point's error is the stored one plus a bound on the change of epsilon between the two
speeds: a loss ``L ~ v^p`` with ``p <= 1`` (``3/5`` on the half-space, ``1/5-3/5`` on a plate)
changes by at most ``dL = L (exp|ln(v / v_stored)| - 1)`` (to first order
``L |ln(v / v_stored)|``), epsilon by at most ``epsilon - sqrt(epsilon^2 - dL)``.
"""

from __future__ import annotations

import json
import math
import warnings
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from restitution.bodies.wall import HalfSpace, wall_from_dict
from restitution.errors import CorruptFileError, InputError
from restitution.estimate import Estimate, EstimateView
from restitution.jsonable import digest_matches
from restitution.laws.partners.base import WALL_KEY

__all__ = [
    "SPEED_MATCH",
    "WALL_REFERENCE_FILENAME",
    "WallReferencePoint",
    "compute_command",
    "load_wall_reference",
    "stored_wall_point",
    "user_points_dir",
]

WALL_REFERENCE_FILENAME = "fem_reference_wall.json"
"""The shipped file, in ``restitution/laws/data``."""

SPEED_MATCH = 1e-3
"""The largest ``|ln(v / v_stored)|`` at which a stored point answers an asked speed: the user's
``c`` from SI constants rounds a speed like 10 m/s to a ``v`` a few ``1e-6`` away from the
stored one."""

_SAME = 1e-6
"""The relative tolerance of ``nu`` and the wall's constants (they come from SI ratios)."""


@dataclass(frozen=True)
class WallReferencePoint(EstimateView):
    """One FEM reference value of a sphere on a wall (``nu`` the ball's, ``v`` in ``c``): its
    ``estimate`` (epsilon, its error, ``ok`` or ``not-asymptotic`` and the message, as stored;
    ``epsilon``, ``epsilon_err``, ``asymptotic_ok`` and ``message`` read it,
    :class:`~restitution.estimate.EstimateView`) and the energy loss with its error, as
    stored (``nan`` for none)."""

    nu: float
    wall: HalfSpace
    v: float
    estimate: Estimate
    energy_loss: float
    energy_loss_err: float


def load_wall_reference(path: str | Path | None = None) -> tuple[WallReferencePoint, ...]:
    """The reference points from ``path`` (default the shipped file)."""
    if path is None:
        text = resources.files("restitution.laws").joinpath("data", WALL_REFERENCE_FILENAME)
        text = text.read_text()
    else:
        text = Path(path).read_text()
    name = path or WALL_REFERENCE_FILENAME

    def number(x):
        return math.nan if x is None else float(x)

    try:
        doc = json.loads(text)
        if doc.get("geometry") != "sphere-on-wall":
            raise InputError(f"{name} is not an FEM reference of a sphere on a wall")
        if digest_matches(doc) is False:
            raise CorruptFileError(
                f"{name} was changed after it was written (its content no longer matches its "
                "digest), so none of its points is served; compute them again (the command "
                "that wrote it: python -m restitution.fem.wall_reference)"
            )
        return tuple(
            WallReferencePoint(
                nu=float(p["nu"]),
                wall=wall_from_dict(p[WALL_KEY]),
                v=float(p["v"]),
                estimate=Estimate.from_record(p),
                energy_loss=number(p["energy_loss"]),
                energy_loss_err=number(p["energy_loss_err"]),
            )
            for p in doc["points"]
        )
    except CorruptFileError:
        raise
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise InputError(
            f"{name} is not an FEM reference file of a sphere on a wall: {exc}"
        ) from exc


def user_points_dir() -> Path:
    """Where a user's computed wall points are read from: ``<cache>/fem_wall``
    (:func:`restitution._paths.cache_root`)."""
    from restitution._paths import cache_root

    return cache_root() / "fem_wall"


def compute_command(nu: float, wall: dict, v: float) -> str:
    """The command that computes the FEM point of a ball of ``nu`` on ``wall`` (its
    ``to_dict``) at ``v`` (``c``) into :func:`user_points_dir`, where the next call finds it."""
    thickness = wall.get("thickness", "inf")
    out = user_points_dir() / f"wall_{wall['kind']}_{thickness}_v{v:.6g}.json"
    return (
        f"python -m restitution.fem.wall_reference {out} {nu:.12g}:{v:.12g}:{thickness} "
        f"--modulus-ratio {wall['modulus_ratio']!r} --density-ratio {wall['density_ratio']!r} "
        f"--wall-nu {wall['nu']!r}"
    )


def _all_points() -> list[WallReferencePoint]:
    """The shipped points and those in :func:`user_points_dir` (unreadable files skipped)."""
    points = list(load_wall_reference())
    folder = user_points_dir()
    for path in sorted(folder.glob("*.json")) if folder.is_dir() else ():
        try:
            points += load_wall_reference(path)
        except CorruptFileError:
            warnings.warn(
                f"the stored FEM points of {path} are not served: the file was changed after "
                "it was written (its digest does not match); compute them again",
                stacklevel=3,
            )
        except (InputError, OSError):
            continue  # a file being written, or not a wall reference: not a point
    return points


def _possible(p: WallReferencePoint) -> bool:
    """Whether a stored point's values can be a collision's: ``v > 0``, ``0 < epsilon <= 1``,
    finite errors ``>= 0`` and a finite loss in ``[0, 1]`` (to the store's ``1e-9``,
    :mod:`restitution.limits.store`): a stored point with ``epsilon = 1.7`` is not served, nor
    is one whose FEM run failed (``nan``)."""
    numbers = (p.v, p.epsilon, p.epsilon_err, p.energy_loss, p.energy_loss_err)
    if not all(math.isfinite(x) for x in numbers):
        return False
    errors_ok = p.epsilon_err >= 0 and p.energy_loss_err >= 0
    return p.v > 0 and 0 < p.epsilon <= 1 and errors_ok and -1e-9 <= p.energy_loss <= 1


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= _SAME * max(abs(a), abs(b))


def _same_wall(a: HalfSpace, b: HalfSpace) -> bool:
    da, db = a.to_dict(), b.to_dict()
    if da.keys() != db.keys() or da["kind"] != db["kind"]:
        return False
    return all(_close(float(da[k]), float(db[k])) for k in da if k != "kind")


def stored_wall_point(nu: float, wall: HalfSpace, v: float, points=None) -> dict | None:
    """The stored FEM point of a ball of ``nu`` on ``wall`` at the speed ``v`` (``c``), as a
    law's record (``route`` ``"finite elements (stored point)"``, its error widened by the speed's
    offset, module docs), or ``None`` when none is stored there. ``points`` default the shipped
    file's and the user's (module docs)."""
    from restitution.status import Status

    for p in _all_points() if points is None else points:
        if not _possible(p):
            continue
        offset = abs(math.log(v / p.v))
        if not (_close(p.nu, nu) and _same_wall(p.wall, wall) and offset <= SPEED_MATCH):
            continue
        change = p.energy_loss * math.expm1(offset)  # the largest |L(v) - L(v_stored)|
        shift = p.epsilon - math.sqrt(max(p.epsilon**2 - change, 0.0))
        return {
            "v": float(v),
            "v_stored": p.v,
            "epsilon": p.epsilon,
            "epsilon_err": p.epsilon_err + shift,
            "energy_loss": p.energy_loss,
            "energy_loss_err": p.energy_loss_err + 2.0 * p.epsilon * shift,
            "asymptotic_ok": p.asymptotic_ok,
            "status": Status.OK if p.asymptotic_ok else Status.NOT_ASYMPTOTIC,
            "route": "finite elements (stored point)",
            "message": p.message,
        }
    return None
