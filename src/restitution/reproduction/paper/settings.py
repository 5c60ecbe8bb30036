"""Sizes of every computation of a paper run: :class:`PaperSettings`, :data:`FULL`, :data:`QUICK`.

Units: two-dimensional ``E = rho = R = 1``, so speeds are in ``c = sqrt(E/rho)`` (the disk's
speed towards the wall) and times in ``R/c``.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, replace

from restitution.errors import InputError
from restitution.jsonable import json_default
from restitution.limits.sweep import DEFAULTS, SweepSettings

__all__ = ["FULL", "QUICK", "SPEED_UNITS", "PaperSettings", "speed_factor"]

SPEED_UNITS: tuple[str, ...] = ("c", "c_L")
"""Units in which the paper's speeds can be read: ``"c"`` (``sqrt(E/rho)``, the paper's stated
unit) or ``"c_L"`` (the dilatational wave speed ``c / sqrt(1 - nu^2)`` of the plane-stress
disk; the hypothesis of issue 16 for the paper's ``epsilon ~ 0.65``)."""


def speed_factor(nu: float, unit: str) -> float:
    """Speed ``unit`` in units of ``c``: 1 for ``"c"``, ``1/sqrt(1 - nu^2)`` for ``"c_L"``."""
    if unit == "c":
        return 1.0
    if unit == "c_L":
        return 1.0 / math.sqrt(1.0 - float(nu) ** 2)
    raise InputError(f"speed unit must be one of {', '.join(SPEED_UNITS)}, not {unit!r}")


@dataclass(frozen=True)
class PaperSettings:
    """Sizes of every computation of a paper run (units as in the module docstring).

    Attributes
    ----------
    name : str
        ``"full"`` or ``"quick"``; printed in the report.
    nus : tuple of float
        Poisson numbers of Figs. 1, 7 and 8 (the paper: 0.33 and 0.9).
    sweep : SweepSettings
        Speeds, ``alpha`` and ``N`` sets, mode selection and solver options of the sweep.
    nu : float
        Poisson number of every other figure and of Table 1 (the paper: 0.33).
    shape_modes : tuple of (int, int)
        ``(n, l)`` of the modes drawn in Fig. 2.
    shape_amplitude : float
        Modal amplitude ``Q`` of the drawings of Fig. 2, ``R``.
    spectrum_omega_max : float
        Largest frequency of Fig. 3, ``c/R``.
    snapshot_v, snapshot_alpha, snapshot_modes : float, float, int
        Collision of Fig. 5 (the paper: ``v = 0.2``).
    collision_v, collision_alpha, collision_modes : float, float, int
        Collision of Fig. 6 and Table 1 (the paper: ``v = 0.1``, ``alpha = 500``, 1600 modes).
    relax_modes, relax_alpha, relax_points, relax_delta_max : int, float, int, float
        Static relaxation of Fig. 10 (the paper: 1300 modes, ``alpha = 500``); compressions
        uniform on ``[0, relax_delta_max]``.
    loop_speeds, loop_alpha, loop_modes : tuple, float, int
        Recorded collisions of Fig. 10 (the paper: ``v = 0.1, 0.04``, ``alpha = 500``).
    contact_points : int
        Speeds of the quasistatic curves of Fig. 11.
    rayleigh_modes, rayleigh_points : int, int
        Modes and speeds of Fig. 12 (the paper: the lowest 1800 modes).
    rayleigh_v_min, rayleigh_v_max : float
        Speed range of Fig. 12.
    law : {"centre", "paper", "diameter"}
        Quasistatic contact law of Fig. 12 and of the quasistatic claims
        (:func:`restitution.quasistatic.hertz.contact_law`); ``"centre"`` is the one the
        package's own relaxation and contact times support, ``"paper"`` redraws the paper's figures.
    speed_units : tuple of str
        Units the paper's speeds are read in for Fig. 1 and its claims (:data:`SPEED_UNITS`);
        ``"c_L"`` adds a second sweep at ``v / sqrt(1 - nu^2)``.
    """

    name: str = "full"
    nus: tuple[float, ...] = (0.33, 0.9)
    sweep: SweepSettings = DEFAULTS
    nu: float = 0.33
    shape_modes: tuple[tuple[int, int], ...] = ((2, 0), (0, 0), (1, 0))
    shape_amplitude: float = 0.12
    spectrum_omega_max: float = 20.0
    snapshot_v: float = 0.2
    snapshot_alpha: float = 500.0
    snapshot_modes: int = 400
    collision_v: float = 0.1
    collision_alpha: float = 500.0
    collision_modes: int = 1600
    relax_modes: int = 1300
    relax_alpha: float = 500.0
    relax_points: int = 31
    relax_delta_max: float = 0.3
    loop_speeds: tuple[float, ...] = (0.1, 0.04)
    loop_alpha: float = 500.0
    loop_modes: int = 300
    contact_points: int = 200
    rayleigh_modes: int = 1800
    rayleigh_points: int = 61
    rayleigh_v_min: float = 1e-5
    rayleigh_v_max: float = 0.1
    law: str = "centre"
    speed_units: tuple[str, ...] = SPEED_UNITS

    def __post_init__(self) -> None:
        if len(self.nus) == 0:
            raise InputError("a paper run needs at least one Poisson number")
        for name in ("snapshot_modes", "collision_modes", "relax_modes", "loop_modes"):
            if getattr(self, name) < 10:
                raise InputError(f"{name} must be at least 10 modes")
        from restitution.quasistatic.hertz import LAWS

        if self.law not in LAWS:
            raise InputError(f"law must be one of {', '.join(LAWS)}, not {self.law!r}")
        if not self.speed_units or self.speed_units[0] != "c":
            raise InputError('speed_units must start with "c" (the paper\'s stated unit)')
        for unit in self.speed_units:
            for nu in self.nus:
                if max(self.sweep.velocities) * speed_factor(nu, unit) >= 1.0:
                    raise InputError(f"speeds in {unit} exceed c at nu = {nu:g}")

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        d = {k: v for k, v in asdict(self).items() if k != "sweep"}
        d["sweep"] = self.sweep.to_dict()
        return json.loads(json.dumps(d, default=json_default))


FULL = PaperSettings()
"""The paper's sizes; the sweep is :data:`restitution.limits.sweep.DEFAULTS` (17 speeds x 2 nu x
3 alphas x 4 N = 408 collisions), and as many again at the speeds read in ``c_L``."""

QUICK = PaperSettings(
    name="quick",
    sweep=replace(
        DEFAULTS,
        velocities=(0.01, 0.04, 0.1, 0.3),
        n_modes=(20, 30, 40),
        # A looser drift bound halves the steps; the coarse grid dominates the error anyway.
        options=(("energy_tol", 1e-4),),
    ),
    snapshot_modes=60,
    collision_modes=200,
    relax_modes=200,
    relax_points=11,
    loop_modes=40,
    contact_points=60,
    rayleigh_modes=200,
    rayleigh_points=15,
)
"""Coarse grids through the same code: 4 speeds, N = 20, 30, 40, 200-mode collisions (and the
same grid again at the speeds read in ``c_L``)."""
