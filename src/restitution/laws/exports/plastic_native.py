"""What each DEM code's own elastic-plastic contact makes of a plastic law (issue 61, item 2).

Units: SI (speeds m/s, the slope ``a`` in s/m); epsilon dimensionless.

The package's plastic law (:mod:`restitution.laws.plastic`: Thornton's elastic-perfectly-plastic
contact, with the waves and damping on one pulse) reaches a DEM code as a constant (its
snippets), as the plugin's table or as the plugin's law per contact (LAMMPS). Where a code has
an elastic-plastic normal contact of its own, the export says how far it is from the package's
law, in one comment block per snippet (each code's module registers its lines as its target's
``plastic``, :class:`~restitution.laws.exports.dem.DemTarget`):

* **Luding's hysteretic spring** (MercuryDPM's ``LinearPlasticViscoelasticNormalSpecies``,
  YADE's ``Law2_ScGeom_LudingPhys_Basic``): loading stiffness ``k1``, unloading ``k2`` growing
  linearly with the largest overlap ``delta_max`` up to ``k2max``; without cohesion or viscous
  damping the grain leaves with ``epsilon^2 = k1 / k2``, and ``delta_max = w sqrt(m* / k1)``, so
  below ``k2max``

      epsilon(w) = (1 + a w)^(-1/2),

  one slope ``a = (k2max / k1 - 1) sqrt(m* / k1) / delta*`` per contact (``delta*`` the
  overlap where ``k2`` reaches ``k2max``: ``a`` holds the masses and the stiffnesses).
  :func:`luding_fit` takes the ``a`` that comes nearest the package's law over its served
  speeds (the smallest largest miss) and states that miss: the model falls as ``w^(-1/2)``
  where Thornton's contact falls as ``w^(-1/4)``, so no ``a`` follows it over decades.
* **LAMMPS** has the granular ``mdr`` normal model (Zunker and Kamrin 2024), elastic-plastic; its
  epsilon(w) is that of a run of LAMMPS, not a closed form, and it is not mapped here.
* **LIGGGHTS-PUBLIC** has no elastic-plastic normal model (its ``doc/Section_gran_models``:
  hertz, hertz/stiffness, hooke, hooke/stiffness).

The snippets keep the package's constant (the law at the reference speed); the lines say what
the code's own model would miss.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from restitution.laws.mechanisms.bounds import law_mechanisms

__all__ = ["LudingFit", "is_plastic", "luding_fit", "luding_lines"]


def is_plastic(s) -> bool:
    """Whether the law ``s`` (an :class:`~restitution.laws.si_law.SILaw`) holds plastic flow."""
    return "plastic" in law_mechanisms(s.law)


@dataclass(frozen=True)
class LudingFit:
    """Luding's ``epsilon = (1 + a w)^(-1/2)`` nearest a plastic law (module docs).

    Attributes
    ----------
    a_s_m : float
        The slope ``a``, s/m.
    largest_miss : float
        The largest ``|model - law|`` over the law's computed speeds in the range.
    at_m_s : float
        Where it is, m/s.
    range_m_s : tuple of float
        The speeds compared, m/s (the law's computed speeds there).
    """

    a_s_m: float
    largest_miss: float
    at_m_s: float
    range_m_s: tuple[float, float]

    def epsilon(self, w) -> np.ndarray:
        """The model at speeds ``w`` (m/s)."""
        return 1.0 / np.sqrt(1.0 + self.a_s_m * np.asarray(w, dtype=float))


def luding_fit(s) -> LudingFit:
    """The slope ``a`` (s/m) whose ``(1 + a w)^(-1/2)`` has the smallest largest miss of the
    plastic law ``s`` at its computed speeds (a bounded search in ``ln a``)."""
    w = np.asarray(s.law.v, dtype=float) * s.speed_scale_m_s
    eps = np.asarray(s.law.epsilon_points, dtype=float)
    keep = np.isfinite(eps) & (eps > 0.0)
    w, eps = w[keep], eps[keep]

    def worst(ln_a: float) -> float:
        return float(np.max(np.abs(1.0 / np.sqrt(1.0 + math.exp(ln_a) * w) - eps)))

    # a w ~ 1 somewhere in the range: from a hundredth of the slowest speed's to a hundred
    # times the fastest's.
    lo, hi = math.log(0.01 / w[-1]), math.log(100.0 / w[0])
    best = minimize_scalar(worst, bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-10})  # fmt: skip
    a = math.exp(float(best.x))
    miss = np.abs(1.0 / np.sqrt(1.0 + a * w) - eps)
    k = int(np.argmax(miss))
    return LudingFit(a, float(miss[k]), float(w[k]), (float(w[0]), float(w[-1])))


def luding_lines(s, model: str, mark: str) -> list[str]:
    """Comment lines (``mark`` the code's comment sign) on Luding's model ``model`` (the code's
    name for it) against the plastic law ``s``."""
    f = luding_fit(s)
    lo, hi = f.range_m_s
    return [
        f"{mark} plastic flow: this code's own elastic-plastic contact, {model} (Luding's",
        f"{mark} hysteretic spring), gives epsilon = (1 + a w)^(-1/2) without cohesion and",
        f"{mark} damping; the nearest a = {f.a_s_m:.4g} s/m misses the package's law by up to",
        f"{mark} {f.largest_miss:.3f} (at {f.at_m_s:.3g} m/s) over {lo:.3g} ... {hi:.3g} m/s "
        "(it falls as",
        f"{mark} w^(-1/2), Thornton's contact as w^(-1/4)). To use it anyway: a = (k2max/k1 - 1)",
        f"{mark} sqrt(m*/k1) / delta*, delta* the overlap where k2 reaches k2max (per contact: a",
        f"{mark} holds the masses). The constant below is the package's law at one speed",
        f"{mark} (restitution.laws.exports.plastic_native)",
    ]
