"""The FEM impact solver against the modal solver extrapolated to infinitely many modes.

Units: ``E = rho = R = 1``; ``v`` in ``c``, ``alpha`` in ``1/R``; wall times in seconds.

For one ``(material, v, alpha)`` the FEM runs at increasing mesh refinement; its error is
estimated by the last Cauchy difference ``|eps_K - eps_(K-1)|`` (an overestimate when the
differences fall quickly, as they do: 8-30x per level at nu = 0.33, v = 0.1, alpha = 500).
The modal solver runs with the ``N`` lowest modes for several ``N`` and ``1 - eps^2`` is
extrapolated linearly in ``1/sqrt(N)`` (:func:`restitution.limits.extrapolation.extrapolate_modes`,
paper Fig. 8) at the same ``alpha``. Neither side is extrapolated in ``alpha``: both solve the
same soft-wall problem. ``geometry="sphere"`` compares the sphere's FEM with Lamb's modes.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace

import numpy as np

from restitution.bodies.cache import get_modes
from restitution.bodies.kinds import DEFAULT_GEOMETRY
from restitution.bodies.material import Material
from restitution.dynamics.results import CollisionResult
from restitution.errors import InputError
from restitution.fem.elasticity import as_material
from restitution.fem.impact import FemSettings, fem_collide, model_for
from restitution.limits.extrapolation import LinearLimit, epsilon_from_loss, extrapolate_modes

__all__ = ["Comparison", "compare_fem_modal", "fem_refinement", "modal_extrapolation"]


@dataclass(frozen=True, eq=False)
class Comparison:
    """FEM and modal results for one collision.

    Attributes
    ----------
    fem : tuple of CollisionResult
        One per refinement level, coarse to fine.
    fem_levels : tuple of int
    fem_dofs : tuple of int
        Degrees of freedom of the half disk at each level.
    modal : tuple of CollisionResult
        One per number of modes, ascending.
    modal_limit : LinearLimit or None
        Extrapolation of ``1 - eps^2`` to ``N -> infinity`` (``None`` with fewer than 2 ``N``).

    Each method's epsilon and error are read from its runs: :attr:`fem_epsilon`,
    :attr:`fem_error` (:func:`fem_refinement`), :attr:`modal_epsilon`, :attr:`modal_error`
    (:func:`modal_extrapolation`).
    """

    fem: tuple[CollisionResult, ...]
    fem_levels: tuple[int, ...]
    fem_dofs: tuple[int, ...]
    modal: tuple[CollisionResult, ...]
    modal_limit: LinearLimit | None

    @property
    def fem_epsilon(self) -> float:
        """The finest FEM epsilon."""
        return _finest(self.fem)[0]

    @property
    def fem_error(self) -> float:
        """Its error estimate: the last Cauchy difference (``nan`` with one level)."""
        return _finest(self.fem)[1]

    @property
    def modal_epsilon(self) -> float:
        """The extrapolated modal epsilon (the last run's with one ``N``)."""
        return _modal_limit(self.modal, self.modal_limit)[0]

    @property
    def modal_error(self) -> float:
        """Its error (``nan`` with one ``N``)."""
        return _modal_limit(self.modal, self.modal_limit)[1]

    @property
    def difference(self) -> float:
        """``fem_epsilon - modal_epsilon``."""
        return self.fem_epsilon - self.modal_epsilon

    @property
    def combined_error(self) -> float:
        """``sqrt(fem_error^2 + modal_error^2)``."""
        return math.hypot(self.fem_error, self.modal_error)

    def to_dict(self) -> dict:
        """JSON-ready dictionary."""
        return {
            "fem": [
                {"refine": k, "dofs": n, **r.to_dict(modes=False)}
                for k, n, r in zip(self.fem_levels, self.fem_dofs, self.fem, strict=True)
            ],
            "fem_epsilon": self.fem_epsilon,
            "fem_error": self.fem_error,
            "modal": [r.to_dict(modes=False) for r in self.modal],
            "modal_limit": self.modal_limit.to_dict() if self.modal_limit else None,
            "modal_epsilon": self.modal_epsilon,
            "modal_error": self.modal_error,
            "difference": self.difference,
            "combined_error": self.combined_error,
        }


def fem_refinement(
    material: Material,
    v: float,
    alpha: float,
    levels,
    settings: FemSettings | None = None,
    geometry: str = DEFAULT_GEOMETRY,
) -> tuple[list[CollisionResult], list[int], float, float]:
    """FEM runs of the body ``geometry`` at the given refinement levels.

    Returns
    -------
    results : list of CollisionResult
    dofs : list of int
    epsilon, error : float
        Finest epsilon and the last Cauchy difference (``nan`` with one level).
    """
    settings = settings or FemSettings()
    results, dofs = [], []
    for k in levels:
        level = replace(settings, refine=int(k))
        results.append(fem_collide(material, v, alpha, geometry=geometry, settings=level))
        dofs.append(model_for(material, v, alpha, level, geometry).disk.n_dofs)
    return results, dofs, *_finest(results)


def _finest(results) -> tuple[float, float]:
    """The finest level's epsilon and the last Cauchy difference (``nan`` with one level)."""
    eps = results[-1].epsilon
    err = abs(eps - results[-2].epsilon) if len(results) > 1 else float("nan")
    return eps, err


def modal_extrapolation(
    material: Material,
    v: float,
    alpha: float,
    counts,
    geometry: str = DEFAULT_GEOMETRY,
    **collide_options,
) -> tuple[list[CollisionResult], LinearLimit | None, float, float]:
    """Modal runs with the ``N`` lowest modes of the body ``geometry`` and the ``N -> infinity``
    limit.

    Returns
    -------
    results : list of CollisionResult
    limit : LinearLimit or None
    epsilon, error : float
        Extrapolated epsilon and its error (the last run's epsilon and ``nan`` with one ``N``).
    """
    from restitution.dynamics.collision import collide

    counts = sorted(int(n) for n in counts)
    pool = get_modes(material, count=counts[-1], geometry=geometry)
    results = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for n in counts:
            results.append(collide(pool.lowest(n), v, alpha, **collide_options))
    limit = None
    if len(counts) >= 2:
        loss = np.array([r.energy_loss for r in results])
        limit = extrapolate_modes(np.array(counts), loss)
    return results, limit, *_modal_limit(results, limit)


def _modal_limit(results, limit: LinearLimit | None) -> tuple[float, float]:
    """epsilon of ``limit`` and its error; the last run's epsilon and ``nan`` without one."""
    if limit is None:
        return results[-1].epsilon, float("nan")
    return epsilon_from_loss(limit.limit, limit.limit_err)


def compare_fem_modal(
    material_or_nu: Material | float,
    v: float,
    alpha: float,
    *,
    geometry: str = DEFAULT_GEOMETRY,
    levels=(0, 1, 2),
    counts=(200, 400, 800, 1600),
    settings: FemSettings | None = None,
) -> Comparison:
    """Run both methods for one collision and collect the comparison.

    Parameters
    ----------
    material_or_nu : Material or float
    v : float
        Speed towards the wall, ``c``.
    alpha : float
        Wall hardness, ``1/R``.
    geometry : str
        A body kind the FEM route meshes, by name (:func:`restitution.fem.section.fem_geometries`).
        The body; both methods use it.
    levels : sequence of int
        FEM refinement levels, ascending.
    counts : sequence of int
        Numbers of modes of the modal runs.
    settings : FemSettings, optional
        FEM settings other than the level.
    """
    material = as_material(material_or_nu, geometry)
    levels = tuple(int(k) for k in levels)
    if not levels or list(levels) != sorted(set(levels)):
        raise InputError(f"levels must be distinct and ascending, got {levels}")
    if not counts:
        raise InputError("give at least one number of modes")
    fem, dofs, *_ = fem_refinement(material, v, alpha, levels, settings, geometry)
    modal, limit, *_ = modal_extrapolation(material, v, alpha, counts, geometry)
    return Comparison(
        fem=tuple(fem),
        fem_levels=levels,
        fem_dofs=tuple(dofs),
        modal=tuple(modal),
        modal_limit=limit,
    )
