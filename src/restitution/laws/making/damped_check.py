"""The modal model with damped modes against the sum of the elastic law and the viscous law.

Units: the body's reduced units (``E = rho = R = 1``): speeds in ``c``, ``tau`` in ``R / c``.

The law of a damping grain (:mod:`restitution.laws.damped`) adds two losses computed apart: the
shipped elastic law (the loss to vibrations) and the quasistatic viscous collision
(:mod:`restitution.quasistatic.viscoelastic`). The modal model with every mode damped
(:class:`restitution.bodies.viscoelastic.Viscoelastic`) computes both at once, from the same
equations of the body, through the same sweeps and ``alpha, N -> infinity`` extrapolations as
the elastic laws (the production windows of the speed). This module computes such points
(:func:`modal_point`), stores them with their provenance in
``laws/data/damped_reference.json`` (:func:`main`) and compares them with the sum
(:func:`compare`): the check of issue 29 that the modal viscoelastic body reproduces the
published quasistatic viscoelastic law at low speed.
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path

import numpy as np

from restitution.bodies.disk.kind import KIND as DISK
from restitution.bodies.kinds import body_kind
from restitution.bodies.sphere.kind import KIND as SPHERE
from restitution.errors import InputError
from restitution.estimate import Estimate, estimate_of, nan_for_none
from restitution.laws.law_point import law_estimate

__all__ = [
    "CHECK_POINTS",
    "Comparison",
    "TrajectoryCheck",
    "compare",
    "load_reference",
    "modal_point",
    "trajectory_check",
]

CHECK_POINTS = (
    (SPHERE.name, 0.3, 0.003, 0.05),
    (SPHERE.name, 0.3, 0.00627, 0.05),
    (SPHERE.name, 0.3, 0.0131, 0.05),
    (DISK.name, 0.33, 0.02, 0.05),
    (DISK.name, 0.33, 0.005, 0.05),
    (DISK.name, 0.33, 0.001, 0.05),
    # The disk's viscous loss at three relaxation times: is a difference from the sum linear
    # in tau (the first-order viscous loss itself), or of higher order (docs/damping.md)?
    (DISK.name, 0.33, 0.005, 0.01),
    (DISK.name, 0.33, 0.005, 0.025),
    (DISK.name, 0.33, 0.02, 0.01),
    (DISK.name, 0.33, 0.02, 0.025),
)
"""``(geometry, nu, v, tau)`` of the stored modal points: reference points of each body, named
by its kind (:mod:`restitution.bodies.sphere.kind`, :mod:`restitution.bodies.disk.kind`)."""

REFERENCE_FILE = "damped_reference.json"


def _group(geometry: str, v: float):
    """The production sweep whose speeds hold ``v`` (its windows and walls)."""
    from restitution.laws.making.production import production

    _, groups = production(geometry)
    for g in groups:
        if any(abs(x - v) <= 1e-12 * v for x in g.velocities):
            return g
    raise InputError(f"no production sweep of the {geometry} computes v = {v:g} c")


def modal_point(geometry: str, nu: float, v: float, tau: float, *, store=None, workers=None):
    """The modal model's epsilon of a damped body through the production sweep of ``v``:
    ``(CombinedLimit, seconds)``."""
    from restitution.limits.curves import compute_curves

    settings = replace(_group(geometry, v), velocities=(v,), relaxation_time=tau, integrator=None)
    start = time.perf_counter()
    curve = compute_curves([nu], settings, store=store, workers=workers, progress=False)[nu]
    return curve.limits[0], time.perf_counter() - start


def modal_compression(geometry: str, nu: float, v: float, *, store=None, workers=None):
    """The elastic modal body's largest compression (``R``) at ``v`` in the limits
    ``alpha, N -> infinity``: the production sweep of ``v`` run for the undamped body, its
    compressions fitted by ``d0 + A / (alpha delta) + B / sqrt(N)`` (the fit of docs/spheres.md).
    Returns ``(d0, its standard error)``."""
    from restitution.limits.curves import compute_curves
    from restitution.limits.store import Store
    from restitution.limits.sweep import grid

    settings = replace(_group(geometry, v), velocities=(v,))
    db = store if isinstance(store, Store) else Store(store)
    compute_curves([nu], settings, store=db, workers=workers, progress=False)
    rows = [(s.alpha, s.n_modes, db.get(s).max_compression) for s in grid([nu], settings)]
    alpha, n, d = (np.array(c, dtype=float) for c in zip(*rows, strict=True))
    design = np.column_stack([np.ones_like(d), 1.0 / (alpha * d), 1.0 / np.sqrt(n)])
    coef, *_ = np.linalg.lstsq(design, d, rcond=None)
    resid = d - design @ coef
    dof = max(d.size - 3, 1)
    cov = np.linalg.inv(design.T @ design) * float(resid @ resid) / dof
    return float(coef[0]), float(math.sqrt(cov[0, 0]))


@dataclass(frozen=True)
class Comparison:
    """One point: the modal model against the sum of the two laws.

    Attributes
    ----------
    geometry, nu, v, tau
        The point (reduced units).
    modal_estimate : Estimate
        The damped modal model's extrapolated epsilon, its error and whether its extrapolation
        passed every check; :attr:`modal`, :attr:`modal_err` and :attr:`modal_asymptotic`
        read it.
    elastic_estimate : Estimate
        The shipped elastic law at ``v`` (:func:`restitution.laws.law_point.law_estimate`);
        :attr:`elastic` and :attr:`elastic_err` read it.
    viscous : float
        The quasistatic viscous collision's epsilon.
    predicted : float
        ``sqrt(elastic^2 + viscous^2 - 1)``.
    sigma : float
        ``(modal - predicted) / sqrt(modal_err^2 + (elastic_err elastic / predicted)^2)``.
    compression, compression_err : float or None
        The elastic modal body's own largest compression (:func:`modal_compression`).
    hertz_compression : float
        The quasistatic law's.
    viscous_own, predicted_own, sigma_own : float or None
        The same with the viscous collision on the body's own stiffness: the law's modulus
        scaled so that its largest compression is the modal body's (a sphere:
        ``(hertz / modal)^(5/2)``; a disk: the factor found by root finding).
    """

    geometry: str
    nu: float
    v: float
    tau: float
    modal_estimate: Estimate
    elastic_estimate: Estimate
    viscous: float
    predicted: float
    sigma: float
    compression: float | None
    compression_err: float | None
    hertz_compression: float
    viscous_own: float | None
    predicted_own: float | None
    sigma_own: float | None

    @property
    def modal(self) -> float:
        """The modal model's epsilon."""
        return nan_for_none(self.modal_estimate.epsilon)

    @property
    def modal_err(self) -> float:
        """Its error."""
        return nan_for_none(self.modal_estimate.epsilon_err)

    @property
    def modal_asymptotic(self) -> bool:
        """Whether its extrapolation passed every check."""
        return self.modal_estimate.asymptotic

    @property
    def elastic(self) -> float:
        """The elastic law's epsilon at ``v``."""
        return nan_for_none(self.elastic_estimate.epsilon)

    @property
    def elastic_err(self) -> float:
        """Its error."""
        return nan_for_none(self.elastic_estimate.epsilon_err)

    def to_dict(self) -> dict:
        """The numbers under the names the reference file keeps (``comparison_at_writing``)."""
        return {
            "geometry": self.geometry,
            "nu": self.nu,
            "v": self.v,
            "tau": self.tau,
            "modal": self.modal,
            "modal_err": self.modal_err,
            "modal_asymptotic": self.modal_asymptotic,
            "elastic": self.elastic,
            "elastic_err": self.elastic_err,
            **{name: getattr(self, name) for name in _AFTER},
        }

    @property
    def viscous_ratio(self) -> float:
        """The modal body's viscous loss (its loss of kinetic energy less the elastic law's)
        over the quasistatic viscous collision's: 1 when the sum holds."""
        elastic_loss = 1.0 - self.elastic**2
        return ((1.0 - self.modal**2) - elastic_loss) / (1.0 - self.viscous**2)


_AFTER = ("viscous", "predicted", "sigma", "compression", "compression_err", "hertz_compression",
          "viscous_own", "predicted_own", "sigma_own")  # fmt: skip


def _hertz(geometry: str, nu: float, E: float = 1.0):
    """The quasistatic contact law of the damped law of the body ``geometry`` (its kind's
    :attr:`~restitution.bodies.kinds.BodyKind.quasistatic_law`, as :mod:`restitution.laws.damped`
    takes it) with the Young modulus ``E`` times the body's own."""
    from restitution.quasistatic.pulse import contact_law_for

    return replace(contact_law_for(geometry, nu, body_kind(geometry).quasistatic_law), E=E)


def _stiffness_for(geometry: str, nu: float, v: float, compression: float) -> float:
    """The modulus factor of the law whose largest compression at ``v`` is ``compression``."""
    from scipy.optimize import brentq

    from restitution.quasistatic.viscoelastic import viscous_collision

    def gap(log_e: float) -> float:
        c = viscous_collision(_hertz(geometry, nu, math.exp(log_e)), v, 0.0)
        return float(c.max_compression[0]) - compression

    return math.exp(brentq(gap, -1.0, 1.0, xtol=1e-12))


def compare(geometry: str, nu: float, v: float, tau: float, modal: float, modal_err: float,
            modal_asymptotic: bool = True, compression: float | None = None,
            compression_err: float | None = None) -> Comparison:  # fmt: skip
    """Compare a modal damped epsilon with the sum of the shipped elastic law and the
    quasistatic viscous law at the same point: on the law's stiffness (the published law),
    and, given the elastic modal body's own ``compression``, on that stiffness."""
    from restitution.laws.law_load import law
    from restitution.quasistatic.viscoelastic import viscous_collision

    elastic = law_estimate(law(nu, geometry=geometry), v)
    modal_estimate = estimate_of(modal, modal_err, bool(modal_asymptotic))
    el, el_err = nan_for_none(elastic.epsilon), nan_for_none(elastic.epsilon_err)
    plain = viscous_collision(_hertz(geometry, nu), v, tau)
    vis = float(plain.epsilon[0])
    pred = math.sqrt(el**2 + vis**2 - 1.0)
    err = math.hypot(modal_err, el_err * el / pred)
    own = pred_own = sigma_own = None
    if compression is not None:
        factor = _stiffness_for(geometry, nu, v, compression)
        own = float(viscous_collision(_hertz(geometry, nu, factor), v, tau).epsilon[0])
        pred_own = math.sqrt(el**2 + own**2 - 1.0)
        # The compression's error moves the stiffness, and so the viscous part.
        hi = _stiffness_for(geometry, nu, v, compression + (compression_err or 0.0))
        own_hi = float(viscous_collision(_hertz(geometry, nu, hi), v, tau).epsilon[0])
        spread = abs(math.sqrt(el**2 + own_hi**2 - 1.0) - pred_own)
        sigma_own = (modal - pred_own) / math.hypot(err, spread)
    return Comparison(geometry, nu, v, tau, modal_estimate, elastic, vis, pred,
                      (modal - pred) / err, compression, compression_err,
                      float(plain.elastic_max_compression[0]), own, pred_own,
                      sigma_own)  # fmt: skip


@dataclass(frozen=True)
class TrajectoryCheck:
    """One modal collision (``N`` modes, wall ``alpha``) elastic and damped, against the
    quasistatic Kelvin-Voigt dissipation on the elastic body's own path (:func:`trajectory_check`).

    Attributes
    ----------
    modal : float
        The damped body's loss of kinetic energy less the elastic body's (fraction of ``E0``).
    on_path : float
        ``tau * integral xi' dF/dt dt / E0`` on the elastic modal collision's recorded path
        (centre approach ``xi``, wall force ``F``): the quasistatic viscous loss of a body whose
        force-compression relation is the modal body's.
    law : float
        The quasistatic viscous collision's loss on the body's 2D (or Hertz) law.
    """

    modal: float
    on_path: float
    law: float


def trajectory_check(geometry: str, nu: float, v: float, tau: float, n_modes: int,
                     alpha: float, record_interval: float = 0.005) -> TrajectoryCheck:  # fmt: skip
    """Where the damped modal body departs from the quasistatic viscous law: ``on_path`` close
    to ``law`` means the law's force-compression relation is the body's; ``modal`` away from
    ``on_path`` means the body does not dissipate as a body in quasistatic deformation would
    (docs/damping.md). One elastic run on the NumPy path with its history, one damped run."""
    from restitution.bodies.cache import get_modes
    from restitution.bodies.viscoelastic import Viscoelastic
    from restitution.dynamics.collision import collide
    from restitution.quasistatic.viscoelastic import viscous_collision

    modes = get_modes(nu, count=n_modes, geometry=geometry)
    elastic = collide(modes, v, alpha, integrator="split", record=True,
                      record_interval=record_interval, backend="numpy")  # fmt: skip
    damped = collide(Viscoelastic(modes, tau), v, alpha, integrator="split")
    h = elastic.history
    xi = h.x0 + 1.0  # the centre past its touching position
    work = np.trapezoid(np.gradient(xi, h.t) * np.gradient(h.force, h.t), h.t)
    e0 = 0.5 * modes.mass * v**2
    law = viscous_collision(_hertz(geometry, nu), np.array([v]), tau)
    return TrajectoryCheck(
        modal=float(elastic.epsilon**2 - damped.epsilon**2),
        on_path=float(tau * work / e0),
        law=float(1.0 - law.epsilon[0] ** 2),
    )


def load_reference(path=None) -> list[dict]:
    """The stored modal points (``laws/data/damped_reference.json``)."""
    if path is None:
        text = resources.files("restitution.laws").joinpath("data", REFERENCE_FILE).read_text()
    else:
        text = Path(path).read_text()
    return json.loads(text)["points"]


def main(argv=None) -> None:
    """``python -m restitution.laws.making.damped_check [--out FILE] [--workers N]``: compute the
    :data:`CHECK_POINTS` (through the result store) and write them with their provenance."""
    import argparse
    import datetime

    from restitution import atomic
    from restitution.provenance import code_version

    parser = argparse.ArgumentParser(description="Modal damped points for docs/damping.md.")
    parser.add_argument("--out", default=None, help="JSON file [the shipped reference]")
    parser.add_argument("--workers", type=int, default=1)
    args = parser.parse_args(argv)
    out = Path(args.out) if args.out else Path(__file__).parents[1] / "data" / REFERENCE_FILE
    points = []
    for geometry, nu, v, tau in CHECK_POINTS:
        limit, seconds = modal_point(geometry, nu, v, tau, workers=args.workers)
        d0, d0_err = modal_compression(geometry, nu, v, workers=args.workers)
        c = compare(geometry, nu, v, tau, limit.epsilon, limit.epsilon_err, limit.asymptotic_ok,
                    d0, d0_err)  # fmt: skip
        points.append(
            {
                "geometry": geometry,
                "nu": nu,
                "v": v,
                "tau": tau,
                "epsilon": limit.epsilon,
                "epsilon_err": limit.epsilon_err,
                "asymptotic_ok": bool(limit.asymptotic_ok),
                "message": limit.message,
                "alphas": sorted({float(a) for a in np.asarray(limit.alpha)}),
                "n_modes": sorted({int(n) for n in np.asarray(limit.n_modes)}),
                "seconds": seconds,
                "elastic_compression": d0,
                "elastic_compression_err": d0_err,
                "comparison_at_writing": {**c.to_dict(), "viscous_ratio": c.viscous_ratio},
            }
        )
        print(f"{geometry} nu={nu:g} v={v:g} tau={tau:g}: modal {limit.epsilon:.6f} +- "
              f"{limit.epsilon_err:.2g}, sum {c.predicted:.6f} ({c.sigma:+.2f} sigma), on the "
              f"body's stiffness {c.predicted_own:.6f} ({c.sigma_own:+.2f} sigma); viscous "
              f"loss modal / quasistatic {c.viscous_ratio:.4f}", flush=True)  # fmt: skip
    doc = {
        "what": "epsilon of the modal model with every mode damped (Kelvin-Voigt, one "
        "relaxation time tau in R/c), extrapolated alpha, N -> infinity through the production "
        "sweep of the speed; reduced units of the body",
        "source": "python -m restitution.laws.making.damped_check",
        "code_version": {g: code_version(g) for g in sorted({p[0] for p in CHECK_POINTS})},
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "points": points,
    }
    with atomic.replacing(out) as tmp:
        Path(tmp).write_text(json.dumps(doc, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
