"""The velocity-dependent coefficient of restitution epsilon(v) as a callable law, and exports.

Paper Fig. 1. For every speed ``v`` (the disk's speed towards the wall, units of
``c = sqrt(E/rho)``; two identical disks approaching at ``+-v`` collide the same way, at relative
speed ``2 v``) the energy loss ``1 - epsilon^2`` is extrapolated to a hard wall and to infinitely
many modes (:mod:`restitution.extrapolation`). :class:`EpsilonLaw` interpolates those points
with a monotone cubic (:class:`scipy.interpolate.PchipInterpolator`, shape preserving: monotone
wherever the data are) anchored at the quasistatic limit ``epsilon(0) = 1`` (paper section 5).

Validity: ``0 <= v <= v_max``, the largest computed speed. Between 0 and the smallest computed
speed the curve rests on the quasistatic anchor, not on dynamic data. Outside the range the law
raises :class:`restitution.errors.InputError` (or warns, on request).

Sources of a law: the package's precomputed files ``restitution/data/law_nu<nu>.json``
(:func:`law`), a JSON file written by :meth:`EpsilonLaw.to_json`, or a result store / a
:class:`Curve` computed here (:func:`compute_curves`).

Exports (all carry the model, every parameter, the package version and the date):

* JSON (:meth:`EpsilonLaw.to_json`): metadata, the points and the fits behind every point;
* CSV (:meth:`EpsilonLaw.to_csv`): ``#`` metadata lines, then ``v,epsilon,epsilon_err,...``;
* a plain table (:meth:`EpsilonLaw.to_table`): ``#`` comments, then columns
  ``v epsilon epsilon_err`` of the interpolant on a uniform grid, for event-driven and DEM codes
  (read with e.g. ``numpy.loadtxt``).
"""

from __future__ import annotations

import csv
import datetime
import json
import math
import os
import warnings
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from scipy.interpolate import PchipInterpolator

from restitution import __version__
from restitution.errors import InputError, RestitutionError
from restitution.extrapolation import (
    CombinedLimit,
    LinearLimit,
    combined_limit,
    epsilon_from_loss,
    extrapolate_modes,
)
from restitution.store import Store, code_version, json_default
from restitution.sweep import DEFAULTS, SweepSettings, collide_points, grid, load_grid, run_sweep

__all__ = [
    "Curve",
    "EpsilonLaw",
    "PointEpsilon",
    "compute_curves",
    "epsilon_at",
    "law",
    "law_filename",
]

_FORMAT = "restitution-law"
_FORMAT_VERSION = 1

MODEL = (
    "Elastic disk (2D linear elasticity, plane stress constants E = rho = R = 1, Poisson number "
    "nu) expanded in its symmetric free eigenmodes, hitting a wall through the potential "
    "V = (1/alpha) int_{-pi/2}^{pi/2} exp(alpha x(phi)) dphi (Gerl & Zippelius, eqs. 40-45); "
    "energy loss 1 - epsilon^2 extrapolated linearly in 1/alpha (alpha -> infinity) and in "
    "1/sqrt(N) (N modes -> infinity)."
)
UNITS = (
    "v is the disk's speed towards the wall before the collision in units of the 2D sound speed "
    "c = sqrt(E/rho); two identical disks approaching each other at +-v (relative speed 2v) "
    "collide identically. epsilon = -v_after / v_before of the centre of mass."
)


def law_filename(nu: float) -> str:
    """File name of the law for ``nu``, e.g. ``law_nu0.33.json``."""
    return f"law_nu{float(nu):g}.json"


# -- computing curves ----------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Curve:
    """Extrapolated epsilon at several speeds for one Poisson number.

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number.
    settings : SweepSettings
        Grid and solver settings behind the points.
    velocities : numpy.ndarray, shape (K,)
        Speeds towards the wall, units of ``c``.
    limits : tuple of CombinedLimit
        The extrapolation at each speed (grid and fits included).
    """

    nu: float
    settings: SweepSettings
    velocities: np.ndarray
    limits: tuple[CombinedLimit, ...]

    @property
    def epsilon(self) -> np.ndarray:
        return np.array([c.epsilon for c in self.limits])

    @property
    def epsilon_err(self) -> np.ndarray:
        return np.array([c.epsilon_err for c in self.limits])


def compute_curves(
    nus: Iterable[float],
    settings: SweepSettings = DEFAULTS,
    *,
    store: Store | str | os.PathLike | None = None,
    run: bool = True,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
    progress: bool | None = None,
    batch_function=collide_points,
) -> dict[float, Curve]:
    """Run (or read) the sweep of ``settings`` for every ``nu`` and extrapolate every speed.

    Parameters
    ----------
    nus : iterable of float
        Poisson numbers.
    settings : SweepSettings
        Velocities, ``alpha`` and ``N`` sets, solver settings (default :data:`DEFAULTS`).
    store : Store or path, optional
        Result store (default :func:`restitution.store.default_store_path`).
    run : bool
        Compute missing points first; with ``False`` only the store is read (missing points
        become ``nan`` and are flagged).
    workers, scheduler, client, progress, batch_function
        Passed to :func:`restitution.sweep.run_sweep`.

    Returns
    -------
    dict of float to Curve
    """
    nus = [float(nu) for nu in nus]
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        if run:
            run_sweep(
                grid(nus, settings),
                store=db,
                workers=workers,
                scheduler=scheduler,
                client=client,
                batch_size=settings.batch_size,
                batch_function=batch_function,
                progress=progress,
            )
        curves = {}
        for nu in nus:
            limits = []
            for v in settings.velocities:
                data = load_grid(db, nu, v, settings)
                limit = combined_limit(data.alpha, data.n_modes, data.loss, order=settings.order)
                lost = len(data.missing) + len(data.failures)
                if lost:
                    note = f"{len(data.failures)} failed and {len(data.missing)} missing point(s)"
                    limit = replace(
                        limit,
                        asymptotic_ok=False,
                        message="; ".join(filter(None, [limit.message, note])),
                    )
                limits.append(limit)
            curves[nu] = Curve(nu, settings, np.array(settings.velocities), tuple(limits))
        return curves
    finally:
        if own:
            db.close()


@dataclass(frozen=True, eq=False)
class PointEpsilon:
    """epsilon at one speed, with the grid and fits behind it.

    Attributes
    ----------
    nu, v : float
        Poisson number and speed towards the wall (units of ``c``).
    alpha : float or None
        The fixed wall hardness (``1/R``) when only ``N -> infinity`` was taken; ``None`` when
        both limits were taken.
    epsilon, epsilon_err : float
        Extrapolated coefficient of restitution and its error.
    energy_loss, energy_loss_err : float
        ``1 - epsilon^2`` and its error.
    asymptotic_ok : bool
        Whether the extrapolation passed its checks; ``message`` says why not.
    message : str
        Empty when asymptotic.
    fit : CombinedLimit or LinearLimit
        The extrapolation (grid and fits).
    settings : SweepSettings
        Grid and solver settings.
    failures : tuple of (float, int, str)
        ``(alpha, N, message)`` of grid points that failed.
    """

    nu: float
    v: float
    alpha: float | None
    epsilon: float
    epsilon_err: float
    energy_loss: float
    energy_loss_err: float
    asymptotic_ok: bool
    message: str
    fit: CombinedLimit | LinearLimit
    settings: SweepSettings
    failures: tuple = ()

    def to_dict(self) -> dict:
        """JSON-ready dictionary: epsilon, epsilon_err, the grid and the fits."""
        if isinstance(self.fit, CombinedLimit):
            grid_d = {
                "alpha": self.fit.to_dict(fits=False)["alpha"],
                "n_modes": [int(n) for n in self.fit.n_modes],
                "energy_loss": self.fit.to_dict(fits=False)["energy_loss_grid"],
            }
            fits = self.fit.to_dict()["fits"]
        else:
            grid_d = {
                "alpha": [self.alpha],
                "n_modes": [int(n) for n in self.fit.parameter],
                "energy_loss": [self.fit.to_dict()["y"]],
            }
            fits = {"N": self.fit.to_dict()}
        return {
            "nu": self.nu,
            "v": self.v,
            "v_units": "c (speed of the disk towards the wall)",
            "alpha": self.alpha,
            "limits": ["N"] if self.alpha is not None else ["alpha", "N"],
            "epsilon": _finite(self.epsilon),
            "epsilon_err": _finite(self.epsilon_err),
            "energy_loss": _finite(self.energy_loss),
            "energy_loss_err": _finite(self.energy_loss_err),
            "asymptotic_ok": bool(self.asymptotic_ok),
            "message": self.message,
            "grid": grid_d,
            "fits": fits,
            "failed_points": [
                {"alpha": a, "n_modes": n, "message": m} for a, n, m in self.failures
            ],
            "settings": self.settings.to_dict(),
            "version": __version__,
        }


def _finite(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def epsilon_at(
    nu: float,
    v: float,
    *,
    alpha: float | None = None,
    settings: SweepSettings = DEFAULTS,
    store: Store | str | os.PathLike | None = None,
    run: bool = True,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
    progress: bool | None = None,
    batch_function=collide_points,
) -> PointEpsilon:
    """epsilon at one speed ``v`` (units of ``c``, towards the wall).

    With ``alpha`` only ``N -> infinity`` is taken at that wall hardness; without it both limits
    on the grid ``settings.alphas_at(v) x settings.n_modes``. Missing collisions are computed first
    (unless ``run=False``); the executor keywords go to :func:`restitution.sweep.run_sweep`.
    """
    if alpha is not None and not (alpha > 0 and math.isfinite(alpha)):
        raise InputError(f"the wall hardness alpha must be positive (1/R), got {alpha}")
    settings = replace(settings, velocities=(float(v),))
    if alpha is not None:
        settings = replace(settings, alphas=(float(alpha),), alpha_scale="absolute")
    own = not isinstance(store, Store)
    db = Store(store) if own else store
    try:
        if run:
            run_sweep(
                grid([nu], settings),
                store=db,
                workers=workers,
                scheduler=scheduler,
                client=client,
                batch_size=settings.batch_size,
                batch_function=batch_function,
                progress=progress,
            )
        data = load_grid(db, nu, v, settings)
    finally:
        if own:
            db.close()
    failures = tuple((s.alpha, s.n_modes, m) for s, m in data.failures)
    if alpha is None:
        fit = combined_limit(data.alpha, data.n_modes, data.loss, order=settings.order)
        loss, loss_err, ok, msg = fit.limit, fit.limit_err, fit.asymptotic_ok, fit.message
        eps, eps_err = fit.epsilon, fit.epsilon_err
    else:
        fit = extrapolate_modes(data.n_modes, data.loss[0])
        loss, loss_err, ok, msg = fit.limit, fit.limit_err, fit.asymptotic_ok, fit.message
        eps, eps_err = epsilon_from_loss(loss, loss_err)
        if not math.isfinite(eps):
            ok = False
            msg = "; ".join(filter(None, [msg, f"energy loss {loss:.4g} is outside [0, 1)"]))
    if failures:
        ok = False
        msg = "; ".join(filter(None, [msg, f"{len(failures)} grid point(s) failed"]))
    return PointEpsilon(
        float(nu), float(v), alpha, eps, eps_err, loss, loss_err, ok, msg, fit, settings, failures
    )


# -- the law -------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class EpsilonLaw:
    """epsilon(v) for one Poisson number: points, a monotone interpolant and exports.

    Attributes
    ----------
    nu : float
        Two-dimensional Poisson number.
    v : numpy.ndarray, shape (K,)
        Speeds towards the wall with a valid extrapolation, units of ``c``, increasing.
    epsilon_points, epsilon_err_points : numpy.ndarray, shape (K,)
        Extrapolated epsilon and its error at ``v``.
    asymptotic_ok : numpy.ndarray of bool, shape (K,)
        Whether each point's extrapolation passed the asymptotic checks.
    metadata : dict
        Model, parameters, version, date, and the per-point extrapolation records.
    """

    nu: float
    v: np.ndarray
    epsilon_points: np.ndarray
    epsilon_err_points: np.ndarray
    asymptotic_ok: np.ndarray
    metadata: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        v = np.asarray(self.v, dtype=float)
        if v.size < 1 or np.any(v <= 0) or np.any(np.diff(v) <= 0):
            raise InputError("a law needs at least one speed, positive and increasing")
        if not np.all(np.isfinite(self.epsilon_points)):
            raise InputError("a law's epsilon values must be finite")

    # -- evaluation ----------------------------------------------------------------------

    @property
    def valid_range(self) -> tuple[float, float]:
        """``(0, v_max)`` in units of ``c``; below ``v[0]`` the quasistatic anchor rules."""
        return 0.0, float(self.v[-1])

    @property
    def monotone(self) -> bool:
        """Whether the points (with ``epsilon(0) = 1``) decrease monotonically."""
        return bool(np.all(np.diff(np.r_[1.0, self.epsilon_points]) <= 0))

    def _interpolant(self, values: np.ndarray, anchor: float) -> PchipInterpolator:
        return PchipInterpolator(np.r_[0.0, self.v], np.r_[anchor, values], extrapolate=True)

    def _check(self, v: np.ndarray, outside: str) -> np.ndarray:
        if outside not in ("raise", "warn", "nan"):
            raise InputError(f"outside must be 'raise', 'warn' or 'nan', not {outside!r}")
        lo, hi = self.valid_range
        bad = ~((v >= lo) & (v <= hi))
        if np.any(bad):
            text = (
                f"speed(s) {np.unique(v[bad])[:5].tolist()} outside the law's validity range "
                f"0 <= v <= {hi:g} (units of c) for nu = {self.nu:g}"
            )
            if outside == "raise":
                raise InputError(text + "; compute the curve further with `restitution curve`")
            if outside == "warn":
                warnings.warn(text + "; extrapolated", stacklevel=3)
        return bad

    def epsilon(self, v, *, outside: str = "raise"):
        """Coefficient of restitution at speed(s) ``v`` towards the wall (units of ``c``).

        Parameters
        ----------
        v : float or array_like
            Speeds, ``0 <= v <= v_max``.
        outside : {"raise", "warn", "nan"}
            What to do with speeds outside the validity range: raise ``InputError``, warn and
            extrapolate the cubic, or return ``nan``.

        Returns
        -------
        float or numpy.ndarray
            ``epsilon(v)``, same shape as ``v``.
        """
        arr = np.asarray(v, dtype=float)
        bad = self._check(arr, outside)
        out = self._interpolant(self.epsilon_points, 1.0)(arr)
        if outside == "nan":
            out = np.where(bad, np.nan, out)
        return float(out) if np.ndim(v) == 0 else out

    def epsilon_err(self, v, *, outside: str = "raise"):
        """Error of :meth:`epsilon` at ``v`` (interpolated; zero at the anchor ``v = 0``)."""
        arr = np.asarray(v, dtype=float)
        bad = self._check(arr, outside)
        out = np.abs(self._interpolant(self.epsilon_err_points, 0.0)(arr))
        if outside == "nan":
            out = np.where(bad, np.nan, out)
        return float(out) if np.ndim(v) == 0 else out

    __call__ = epsilon

    # -- construction --------------------------------------------------------------------

    @classmethod
    def from_curve(cls, curve: Curve) -> EpsilonLaw:
        """Law from a computed curve; points without a valid extrapolation are left out and
        listed in ``metadata["dropped"]``."""
        pairs = list(zip(curve.velocities, curve.limits, strict=True))
        kept = [(float(v), c) for v, c in pairs if math.isfinite(c.epsilon)]
        dropped = [
            {"v": float(v), "message": c.message} for v, c in pairs if not math.isfinite(c.epsilon)
        ]
        if not kept:
            raise RestitutionError(
                f"no speed of the curve for nu = {curve.nu:g} has a valid extrapolation; "
                "run the sweep first (restitution curve)"
            )
        vs = np.array([v for v, _ in kept])
        keep = [c for _, c in kept]
        points = [
            {
                "v": float(v),
                "epsilon": c.epsilon,
                "epsilon_err": c.epsilon_err,
                "energy_loss": c.limit,
                "energy_loss_err": c.limit_err,
                "asymptotic_ok": bool(c.asymptotic_ok),
                "message": c.message,
                "extrapolation": c.to_dict(),
            }
            for v, c in zip(vs, keep, strict=True)
        ]
        metadata = _metadata(curve.nu, curve.settings.to_dict())
        metadata["dropped"] = dropped
        metadata["points"] = points
        return cls(
            nu=curve.nu,
            v=vs,
            epsilon_points=np.array([c.epsilon for c in keep]),
            epsilon_err_points=np.array([c.epsilon_err for c in keep]),
            asymptotic_ok=np.array([c.asymptotic_ok for c in keep]),
            metadata=metadata,
        )

    @classmethod
    def from_points(
        cls, nu: float, v, epsilon, epsilon_err, *, asymptotic_ok=None, parameters=None
    ) -> EpsilonLaw:
        """Law from given points (e.g. another program's data); ``parameters`` go to metadata."""
        v = np.asarray(v, dtype=float)
        order = np.argsort(v)
        ok = np.ones(v.size, bool) if asymptotic_ok is None else np.asarray(asymptotic_ok, bool)
        metadata = _metadata(nu, dict(parameters or {}))
        return cls(
            float(nu),
            v[order],
            np.asarray(epsilon, dtype=float)[order],
            np.asarray(epsilon_err, dtype=float)[order],
            ok[order],
            metadata,
        )

    @classmethod
    def from_json(cls, path: str | os.PathLike) -> EpsilonLaw:
        """Read a law written by :meth:`to_json` (or shipped with the package)."""
        path = Path(path)
        try:
            d = json.loads(path.read_text())
        except (OSError, ValueError) as exc:
            raise RestitutionError(f"cannot read law file {path}: {exc}") from exc
        return cls._from_dict(d, str(path))

    @classmethod
    def _from_dict(cls, d: dict, source: str) -> EpsilonLaw:
        if not isinstance(d, dict) or d.get("format") != _FORMAT:
            raise RestitutionError(f"{source} is not a restitution law file (format {_FORMAT!r})")
        if d.get("format_version") != _FORMAT_VERSION:
            raise RestitutionError(
                f"{source} has law format version {d.get('format_version')}; this code reads "
                f"{_FORMAT_VERSION}"
            )
        points = d["metadata"]["points"]
        metadata = dict(d["metadata"])
        metadata["source"] = source
        return cls(
            nu=float(d["metadata"]["nu"]),
            v=np.array([p["v"] for p in points], dtype=float),
            epsilon_points=np.array([p["epsilon"] for p in points], dtype=float),
            epsilon_err_points=np.array([p["epsilon_err"] for p in points], dtype=float),
            asymptotic_ok=np.array([p["asymptotic_ok"] for p in points], dtype=bool),
            metadata=metadata,
        )

    # -- exports -------------------------------------------------------------------------

    def to_dict(self) -> dict:
        """JSON-ready dictionary (the JSON export's content)."""
        meta = dict(self.metadata)
        meta.setdefault("points", self._plain_points())
        meta["validity"] = self._validity()
        return {"format": _FORMAT, "format_version": _FORMAT_VERSION, "metadata": meta}

    def _plain_points(self) -> list[dict]:
        return [
            {"v": float(v), "epsilon": float(e), "epsilon_err": float(s), "asymptotic_ok": bool(o)}
            for v, e, s, o in zip(
                self.v,
                self.epsilon_points,
                self.epsilon_err_points,
                self.asymptotic_ok,
                strict=True,
            )
        ]

    def _validity(self) -> dict:
        lo, hi = self.valid_range
        return {
            "v_min": lo,
            "v_max": hi,
            "v_data_min": float(self.v[0]),
            "note": (
                f"valid for 0 <= v <= {hi:g} c; below {float(self.v[0]):g} c the curve is "
                "interpolated to the quasistatic limit epsilon(0) = 1 (paper section 5)"
            ),
            "monotone": self.monotone,
            "all_asymptotic": bool(np.all(self.asymptotic_ok)),
        }

    def to_json(self, path: str | os.PathLike) -> Path:
        """Write the JSON export; returns the path."""
        path = Path(path)
        path.write_text(json.dumps(self.to_dict(), indent=1, allow_nan=False, default=json_default))
        return path

    def _header_lines(self) -> list[str]:
        meta = {k: v for k, v in self.metadata.items() if k not in ("points", "dropped")}
        lines = [
            f"restitution law epsilon(v), nu = {self.nu:g}",
            f"package: restitution {meta.get('version', __version__)} "
            f"(code {meta.get('code_version', '?')}); date: {meta.get('date')}",
            f"model: {MODEL}",
            f"units: {UNITS}",
            f"validity: {self._validity()['note']}",
            "parameters: " + json.dumps(meta.get("parameters", {}), default=json_default),
        ]
        return lines

    def to_csv(self, path: str | os.PathLike) -> Path:
        """Write the points as CSV with ``#`` metadata lines; returns the path."""
        path = Path(path)
        with open(path, "w", newline="") as fh:
            for line in self._header_lines():
                fh.write(f"# {line}\n")
            writer = csv.writer(fh)
            writer.writerow(["v", "epsilon", "epsilon_err", "asymptotic_ok"])
            for p in self._plain_points():
                writer.writerow(
                    [
                        repr(p["v"]),
                        repr(p["epsilon"]),
                        repr(p["epsilon_err"]),
                        int(p["asymptotic_ok"]),
                    ]
                )
        return path

    def to_table(self, path: str | os.PathLike, *, points: int = 301) -> Path:
        """Write ``v epsilon epsilon_err`` of the interpolant on a uniform grid of ``[0, v_max]``.

        A plain whitespace table with ``#`` comment lines, for event-driven and DEM codes that
        interpolate linearly; returns the path.
        """
        if points < 2:
            raise InputError("a table needs at least 2 points")
        v = np.linspace(0.0, self.valid_range[1], points)
        table = np.column_stack([v, self.epsilon(v), self.epsilon_err(v)])
        header = "\n".join(
            [*self._header_lines(), "columns: v [c]  epsilon  epsilon_err (PCHIP interpolant)"]
        )
        np.savetxt(path, table, fmt="%.8f", header=header, comments="# ")
        return Path(path)


def _metadata(nu: float, parameters: Mapping) -> dict:
    return {
        "nu": float(nu),
        "model": MODEL,
        "units": UNITS,
        "parameters": {"nu": float(nu), "E": 1.0, "rho": 1.0, "R": 1.0, **parameters},
        "package": "restitution",
        "version": __version__,
        "code_version": code_version(),
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "interpolant": "scipy.interpolate.PchipInterpolator through (0, 1) and the points",
    }


def law(
    nu: float = 0.33,
    *,
    path: str | os.PathLike | None = None,
    store: Store | str | os.PathLike | None = None,
    settings: SweepSettings = DEFAULTS,
) -> EpsilonLaw:
    """The coefficient of restitution epsilon(v) for Poisson number ``nu``.

    Parameters
    ----------
    nu : float
        Two-dimensional Poisson number.
    path : path, optional
        A law JSON file (:meth:`EpsilonLaw.to_json`).
    store : Store or path, optional
        Build the law from this result store (nothing is computed; missing points are left
        out). With neither ``path`` nor ``store`` the package's precomputed file is loaded.
    settings : SweepSettings
        Grid of the store's sweep (with ``store``).

    Returns
    -------
    EpsilonLaw
        Call ``.epsilon(v)`` with ``v`` the speed towards the wall in units of ``c``.

    Raises
    ------
    InputError
        If no precomputed law exists for ``nu``; the message says how to compute one.
    """
    if path is not None:
        return EpsilonLaw.from_json(path)
    if store is not None:
        curve = compute_curves([nu], settings, store=store, run=False)[float(nu)]
        return EpsilonLaw.from_curve(curve)
    data = resources.files("restitution").joinpath("data")
    name = law_filename(nu)
    try:
        text = data.joinpath(name).read_text()
    except (FileNotFoundError, NotADirectoryError, OSError):
        shipped = []
        try:
            shipped = sorted(
                p.name[len("law_nu") : -len(".json")]
                for p in data.iterdir()
                if p.name.startswith("law_nu") and p.name.endswith(".json")
            )
        except (FileNotFoundError, NotADirectoryError, OSError):
            pass
        raise InputError(
            f"no precomputed law for nu = {float(nu):g} (shipped: {', '.join(shipped) or 'none'}); "
            f"compute one with `restitution curve --nu {float(nu):g} --out DIR` and load it "
            f"with restitution.law(path='DIR/{name}')"
        ) from None
    return EpsilonLaw._from_dict(json.loads(text), f"restitution/data/{name}")
