"""Fig. 11: contact time and maximal compression of the quasistatic collision against speed.

Units: speeds in ``c``, times in ``R / c``, compressions in ``R`` (``E = rho = R = 1``).

Curves from the 2D Hertz law (:func:`restitution.quasistatic.hertz.quasistatic_collision`) with the
estimates of eq. (61); when given, the contact times of dynamic collisions (the paper: at the
hardest wall used for each speed) as points.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.quasistatic.hertz import contact_law, quasistatic_collision
from restitution.reproduction.figures._style import add_notes

__all__ = ["Fig11Data", "compute", "dynamic_contact_times", "plot"]


@dataclass(frozen=True)
class Fig11Data:
    """Numbers of Fig. 11.

    Attributes
    ----------
    nu : float
    v : numpy.ndarray, shape (K,)
        Speeds, ``c``.
    contact_time_paper, max_compression_paper : numpy.ndarray, shape (K,)
        With eq. (57) as printed.
    contact_time_centre, max_compression_centre : numpy.ndarray, shape (K,)
        With the centre-of-mass law (NaN above its largest speed).
    estimate_contact_time, estimate_max_compression : numpy.ndarray, shape (K,)
        Eq. (61) (``tau = pi sqrt(ln(4/v))``).
    dynamic_v, dynamic_contact_time : numpy.ndarray, shape (J,)
        Dynamic contact times (may be empty).
    """

    nu: float
    v: np.ndarray
    contact_time_paper: np.ndarray
    max_compression_paper: np.ndarray
    contact_time_centre: np.ndarray
    max_compression_centre: np.ndarray
    estimate_contact_time: np.ndarray
    estimate_max_compression: np.ndarray
    dynamic_v: np.ndarray
    dynamic_contact_time: np.ndarray


def dynamic_contact_times(
    nu: float = 0.33,
    v: Sequence[float] = (0.01, 0.02, 0.04, 0.1),
    alpha: float | Sequence[float] = 8000.0,
    n_modes: int = 200,
) -> tuple[np.ndarray, np.ndarray]:
    """Contact times (duration with ``x0 > -1``) from the modal collision solver.

    The defaults are the runs of ``docs/quasistatic.md`` (a few minutes in all): a hard wall
    matters more than many modes for the contact time at small ``v``.
    """
    from restitution.bodies.cache import get_modes
    from restitution.dynamics.collision import collide

    modes = get_modes(nu, count=n_modes)
    a = np.broadcast_to(np.asarray(alpha, float), np.shape(v))
    tau = [collide(modes, float(s), float(al)).contact_time for s, al in zip(v, a, strict=True)]
    return np.asarray(v, float), np.asarray(tau, float)


def compute(
    nu: float = 0.33,
    *,
    v_min: float = 1e-8,
    n_v: int = 200,
    dynamic: tuple[Sequence[float], Sequence[float]] | None = None,
) -> Fig11Data:
    """Compute Fig. 11 on ``n_v`` log-spaced speeds from ``v_min`` to the largest speed the
    printed law allows.

    Parameters
    ----------
    nu : float
    v_min : float
        Smallest speed, ``c``.
    n_v : int
    dynamic : (v, contact_time), optional
        Dynamic contact times, e.g. from :func:`dynamic_contact_times`.
    """
    paper = contact_law(nu, "paper")
    centre = contact_law(nu, "centre")
    v = np.geomspace(v_min, 0.999 * paper.max_speed(), n_v)
    qp = quasistatic_collision(paper, v)
    ok = v <= centre.max_speed()
    tc = np.full_like(v, np.nan)
    dc = np.full_like(v, np.nan)
    qc = quasistatic_collision(centre, v[ok])
    tc[ok], dc[ok] = qc.contact_time, qc.max_compression
    dv, dt = (np.empty(0), np.empty(0)) if dynamic is None else map(np.asarray, dynamic)
    return Fig11Data(
        nu=float(nu),
        v=v,
        contact_time_paper=qp.contact_time,
        max_compression_paper=qp.max_compression,
        contact_time_centre=tc,
        max_compression_centre=dc,
        estimate_contact_time=qp.estimate_contact_time,
        estimate_max_compression=qp.estimate_max_compression,
        dynamic_v=np.asarray(dv, float),
        dynamic_contact_time=np.asarray(dt, float),
    )


def plot(data: Fig11Data, path, note: str = "") -> None:
    """Draw Fig. 11 into ``path``: contact time (top) and maximal compression (bottom).

    ``note`` is printed under the axes.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.0, 6.5), sharex=True)
    ax1.semilogx(data.v, data.contact_time_paper, "k-", label="2D Hertz, eq. (57) as printed")
    ax1.semilogx(data.v, data.contact_time_centre, "k--", label="2D Hertz, centre of mass")
    ax1.semilogx(data.v, data.estimate_contact_time, ":", color="gray", label=r"eq. (61)")
    if data.dynamic_v.size:
        ax1.semilogx(data.dynamic_v, data.dynamic_contact_time, "D", mfc="none", label="dynamic")
    ax1.set_ylabel(r"contact time $\tau$  [$R/c$]")
    ax1.legend(fontsize=8)
    ax2.loglog(data.v, data.max_compression_paper, "k-", label="eq. (57) as printed")
    ax2.loglog(data.v, data.max_compression_centre, "k--", label="centre of mass")
    ax2.loglog(data.v, data.estimate_max_compression, ":", color="gray", label="eq. (61)")
    ax2.set_xlabel(r"$v_i$  [$c$]")
    ax2.set_ylabel(r"$\delta_{max}$  [$R$]")
    ax2.legend(fontsize=8)
    ax1.set_title(rf"Quasistatic collision, $\nu$ = {data.nu:g}")
    ax1.set_xlim(data.v[0], data.v[-1] * (1.0 + 1e-9) if math.isfinite(data.v[-1]) else None)
    add_notes(fig, [note])
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
