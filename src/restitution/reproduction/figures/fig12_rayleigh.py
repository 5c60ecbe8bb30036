"""Fig. 12: energy left in the modes after a slow collision, Rayleigh's approach.

Units: speeds in ``c``; energies as fractions of the initial kinetic energy ``(m/2) v^2``.

The curve is :func:`restitution.quasistatic.rayleigh.rayleigh_energy` (the paper: the lowest 1800
modes, eq. 57 as printed) for all modes and for the quadrupole ``(n = 2, l = 0)`` alone; when given,
the dynamic energy losses ``1 - epsilon^2`` extrapolated to a hard wall and infinitely many modes
(section 4) as points: filled where the extrapolation passed its asymptotic checks, open where it
did not (as in Fig. 1).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.quasistatic.hertz import contact_law
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.reproduction.figures._style import add_notes

__all__ = ["Fig12Data", "compute", "plot"]


@dataclass(frozen=True)
class Fig12Data:
    """Numbers of Fig. 12.

    Attributes
    ----------
    nu : float
    law : str
        Contact law of the quasistatic force.
    n_modes : int
    v : numpy.ndarray, shape (K,)
        Speeds, ``c``.
    total, quadrupole : numpy.ndarray, shape (K,)
        Energy fraction in all modes and in ``(2, 0)``.
    dynamic_v, dynamic_loss : numpy.ndarray, shape (J,)
        Extrapolated dynamic ``1 - epsilon^2`` (may be empty).
    dynamic_ok : numpy.ndarray of bool, shape (J,)
        Whether each dynamic point passed the asymptotic checks.
    """

    nu: float
    law: str
    n_modes: int
    v: np.ndarray
    total: np.ndarray
    quadrupole: np.ndarray
    dynamic_v: np.ndarray
    dynamic_loss: np.ndarray
    dynamic_ok: np.ndarray


def compute(
    nu: float = 0.33,
    *,
    n_modes: int = 1800,
    law: str = "paper",
    v_min: float = 1e-5,
    v_max: float = 0.1,
    n_v: int = 61,
    dynamic: tuple[Sequence[float], ...] | None = None,
) -> Fig12Data:
    """Compute Fig. 12 on ``n_v`` log-spaced speeds in ``[v_min, v_max]``.

    Parameters
    ----------
    nu : float
    n_modes : int
        Lowest modes driven (the paper: 1800).
    law : {"paper", "centre", "diameter"}
        Contact law for the quasistatic force.
    v_min, v_max : float
        Speed range, ``c`` (``v_max`` below the law's largest speed).
    n_v : int
    dynamic : (v, loss) or (v, loss, ok), optional
        Extrapolated dynamic energy losses, e.g. from the sweeps of section 4, and whether each
        passed the asymptotic checks (all passed when ``ok`` is not given).
    """
    modes = get_modes(nu, count=n_modes)
    hl = contact_law(nu, law)
    v = np.geomspace(v_min, min(v_max, 0.999 * hl.max_speed()), n_v)
    res = [rayleigh_energy(modes, float(s), hl) for s in v]
    dv, dl, ok = np.empty(0), np.empty(0), np.empty(0, bool)
    if dynamic is not None:
        dv, dl = np.asarray(dynamic[0], float), np.asarray(dynamic[1], float)
        ok = np.asarray(dynamic[2], bool) if len(dynamic) > 2 else np.ones(dv.size, bool)
    return Fig12Data(
        nu=float(nu),
        law=law,
        n_modes=int(n_modes),
        v=v,
        total=np.array([r.energy_fraction for r in res]),
        quadrupole=np.array([r.fraction_of(2, 0) for r in res]),
        dynamic_v=dv,
        dynamic_loss=dl,
        dynamic_ok=ok,
    )


def plot(data: Fig12Data, path, note: str = "") -> None:
    """Draw Fig. 12 into ``path``. ``note`` is printed under the axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.0, 4.5))
    ax.loglog(data.v, data.total, "k-", label=f"Rayleigh, {data.n_modes} modes")
    ax.loglog(data.v, data.quadrupole, "--", color="tab:blue", label="Rayleigh, (n=2, l=0) only")
    for sel, face, label in (
        (data.dynamic_ok, "tab:red", "dynamic, extrapolated, checks passed"),
        (~data.dynamic_ok, "none", "dynamic, extrapolated, not asymptotic"),
    ):
        if np.any(sel):
            ax.loglog(
                data.dynamic_v[sel], data.dynamic_loss[sel], "D", color="tab:red", mfc=face,
                label=label,
            )  # fmt: skip
    ax.set_xlabel(r"$v_i$  [$c$]")
    ax.set_ylabel(r"energy in modes / $(m/2) v_i^2$")
    ax.set_title(rf"Rayleigh's estimate, $\nu$ = {data.nu:g} (contact law: {data.law})")
    ax.legend(fontsize=8)
    add_notes(fig, [note])
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
