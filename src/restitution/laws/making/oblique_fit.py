"""The DEM codes' tangential parameters of one material, fitted to its modal ``beta``: the
Python edge of ``restitution oblique-fit``.

Units: SI at the edge (Pa, kg/m^3, m/s, degrees); ``k_t`` in Pa (LAMMPS's ``mindlin``),
``chi``, ``beta``, ``e`` and ``mu`` dimensionless.

:func:`oblique_fit` computes the material's oblique table (every angle at every speed, the runs
of ``law --angle``: :func:`restitution.laws.making.oblique_table.compute_table`), after
estimating its time and refusing what would run past the bound of one run
(:mod:`restitution.budget`), and fits at each speed Walton's ``e, mu_W, beta_0`` and the
stiffness ``chi`` of LAMMPS's ``mindlin`` and ``linear_history`` and of Maw, Barber and
Fawcett's microslip law (:func:`restitution.laws.oblique_fits.fit_table`), each with its misfit.
:class:`ObliqueFit` holds both; its :meth:`~ObliqueFit.lammps_lines` are the ``tangential
mindlin`` words with the fitted ``k_t`` for the rigid wall's ``fix wall/gran`` line and for two
grains of the material (in place of the exported ``8 G*``, docs/oblique.md).

The fitted ``chi`` is the modal route's at its mode count on its softest wall, the numbers of
``law --angle``; its error is not propagated into the fit (the points' own error, the change
from half the modes, is stored beside them).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from restitution import budget
from restitution.errors import InputError
from restitution.laws.exports.dem.lammps import lammps_tangential
from restitution.laws.making.oblique_table import TablePlan, compute_table, table_seconds
from restitution.laws.oblique import worst_status
from restitution.laws.oblique_fits import FIT_NAMES, ObliqueFits, fit_table
from restitution.status import Status

__all__ = ["DEFAULT_ANGLES", "DEFAULT_SPEEDS", "ObliqueFit", "oblique_fit"]

DEFAULT_ANGLES = (0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
"""Degrees from the normal: the shipped steel table's (angle 0, the head-on impact of the same
modes and wall, is the baseline of ``epsilon_normal``)."""

DEFAULT_SPEEDS = (1.0,)
"""Normal speeds, m/s."""


def _silent(text: str) -> None:
    """The default ``say``: say nothing."""


@dataclass(frozen=True, eq=False)
class ObliqueFit:
    """A material's oblique table and the fits to it.

    Attributes
    ----------
    table : dict
        As :func:`~restitution.laws.making.oblique_table.compute_table` stores it (``rows``:
        one per angle and speed).
    fits : ObliqueFits
        Per speed (m/s): Walton, ``mindlin``, ``linear_history`` and microslip.
    """

    table: dict
    fits: ObliqueFits

    @property
    def status(self) -> Status:
        """The worst status of the table's points (:func:`~restitution.laws.oblique.
        worst_status`)."""
        return worst_status(r["status"] for r in self.table["rows"])

    @property
    def advice(self) -> str | None:
        """The advice of the first point of :attr:`status`."""
        return next((r["advice"] for r in self.table["rows"] if r["status"] == self.status),
                    None)  # fmt: skip

    def lammps_lines(self, speed: float) -> dict:
        """The ``tangential mindlin K_T 0.0 MU`` words with the ``k_t`` (Pa) fitted at
        ``speed`` (m/s): ``wall_fix`` for the rigid wall's ``fix wall/gran`` line (which
        carries ``E' = 2 E*``, ``nu = 0``), ``pair_coeff`` for two grains of the material.
        """
        m = self.fits.summary()[str(speed)]["mindlin"]
        mu = self.fits.friction
        return {"wall_fix": lammps_tangential(mu, m["wall_k_t_pa"]),
                "pair_coeff": lammps_tangential(mu, m["k_t_pa"])}  # fmt: skip

    def rows(self) -> list[dict]:
        """One flat record per speed and fit (``pandas.DataFrame(fit.rows())``): the fit's
        parameters and misfit; LAMMPS's ``k_t`` (Pa) for the ``mindlin`` rows."""
        out = []
        for speed, fits in self.fits.summary().items():
            for name in FIT_NAMES:
                out.append({"speed_m_s": float(speed), "fit": name, **fits[name]})
        return out

    def to_dict(self) -> dict:
        """The JSON payload: the table, the fits per speed and the LAMMPS words."""
        return {
            "table": self.table,
            "inertia_factor": self.fits.inertia_factor,
            "fits": self.fits.summary(),
            "lammps": {str(w): self.lammps_lines(w) for w in self.fits.speeds},
            "units": {
                "speed": "m/s (normal speed towards the wall)",
                "angle": "degrees from the wall's normal",
                "k_t": "Pa (LAMMPS's tangential mindlin: F_t = k_t a xi)",
                "chi": "mindlin: k_t a / k_n = k_t / (2 E*); linear_history: k_t / k_n("
                "delta_max); microslip: 2 (1 - nu) / (2 - nu)",
                "rms, largest": "of beta_model - beta over the oblique angles",
            },
        }


def oblique_fit(
    E: float,
    nu: float,
    rho: float,
    shape: str,
    friction: float,
    *,
    angles=DEFAULT_ANGLES,
    speeds=DEFAULT_SPEEDS,
    modes: int | None = None,
    friction_model: str | None = None,
    kappa: float | None = None,
    force: bool = False,
    say: Callable[[str], None] = _silent,
    steps: int = 4000,
    springs: int = 200,
    scan: int = 41,
) -> ObliqueFit:
    """The oblique table of a material (3D ``E`` Pa, ``nu``, ``rho`` kg/m^3, ``shape`` as
    ``law --shape``) on the rigid wall with Coulomb's ``friction`` at ``angles`` (degrees,
    two or more above 0) and ``speeds`` (m/s), and the fits to it (module docs).

    ``modes``, ``friction_model`` and ``kappa`` as ``law --angle`` (``None``: its defaults;
    the error of each point is its change from ``modes // 2``); ``force`` runs past the time
    bound; ``say`` is told the estimate and each point; ``steps``, ``springs`` and ``scan``
    are the fits' resolutions (:func:`restitution.laws.oblique_fits.fit_table`).

    Raises
    ------
    InputError
        A bad material, angle, speed or friction (one line, before any run); fewer than two
        oblique angles; an estimated time past the bound without ``force``.
    """
    angles = tuple(float(a) for a in angles)
    if sum(a > 0.0 for a in angles) < 2:
        raise InputError(f"give two or more angles above 0 degrees to fit (got {angles}), "
                         "e.g. --angle 10 30 50 70")  # fmt: skip
    if len(set(angles)) != len(angles):
        raise InputError(f"each angle once, please (got {angles})")
    if modes is not None and not (isinstance(modes, int) and modes >= 2):
        raise InputError(f"--modes must be an integer >= 2 (the error is the change from "
                         f"modes // 2), got {modes!r}")  # fmt: skip
    plan = TablePlan(name="oblique_fit", E=E, nu=nu, rho=rho, shape=shape, friction=friction,
                     speeds=tuple(float(w) for w in speeds), angles=angles, modes=modes,
                     friction_model=friction_model, kappa=kappa)  # fmt: skip
    seconds, how = table_seconds(plan)
    per_angle = seconds / len(angles)
    budget.check_time_total(
        "--angle",
        f"{len(angles)} angles",
        seconds,
        how,
        lambda bound: f"about {max(int(bound // per_angle), 0)} angles of these speeds fit",
        force=force,
        override="--force",
    )
    say(f"note: {len(angles)} angles x {len(plan.speeds)} speeds: about "
        f"{budget.format_duration(seconds)} expected ({how})")  # fmt: skip
    table = compute_table(plan, say=say)
    for r in table["rows"]:
        if r["angle_deg"] > 0.0 and (r["beta"] is None or not math.isfinite(r["beta"])):
            raise InputError(f"no beta at {r['angle_deg']:g} degrees, {r['speed_m_s']:g} m/s: "
                             f"{r['advice']}")  # fmt: skip
    fits = fit_table(table, steps=steps, springs=springs, scan=scan)
    return ObliqueFit(table, fits)
