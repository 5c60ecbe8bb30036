"""Fig. 10: force against compression from the 2D Hertz law, static relaxation and collisions.

Units: compression ``delta = x0 + 1`` in ``R``, force in ``E R`` (``E = rho = R = 1``).

On one plot: the quasistatic law (eq. 57 as printed and the centre-of-mass law of
``docs/quasistatic.md``), the static relaxation of :mod:`restitution.quasistatic.relaxation` (1300
modes, ``alpha = 500`` in the paper) and, when given, the force-compression loops of dynamic
collisions (``alpha = 500``, ``v = 0.1`` and ``0.04`` in the paper).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.quasistatic.hertz import contact_law
from restitution.quasistatic.relaxation import relaxation_curve
from restitution.reproduction.figures._style import add_notes

__all__ = ["Fig10Data", "Loop", "compute", "dynamic_loops", "plot"]


@dataclass(frozen=True)
class Loop:
    """Force-compression history of one dynamic collision.

    Attributes
    ----------
    v : float
        Incoming speed, ``c``.
    delta : numpy.ndarray, shape (T,)
        ``x0 + 1`` along the collision, ``R``.
    force : numpy.ndarray, shape (T,)
        Wall force, ``E R``.
    """

    v: float
    delta: np.ndarray
    force: np.ndarray


@dataclass(frozen=True)
class Fig10Data:
    """Numbers of Fig. 10.

    Attributes
    ----------
    nu, alpha : float
        Poisson number and wall hardness of the relaxation (``1/R``).
    n_modes : int
        Modes in the relaxation (the lowest ones).
    law_delta : numpy.ndarray, shape (K,)
        Compressions of the law curves, ``R``.
    law_force_paper, law_force_centre : numpy.ndarray, shape (K,)
        ``P(delta)`` of eq. (57) as printed and of the centre-of-mass law (NaN beyond its
        monotonic limit), ``E R``.
    relax_delta, relax_force : numpy.ndarray, shape (J,)
        Static relaxation.
    loops : tuple of Loop
        Dynamic collisions (may be empty).
    """

    nu: float
    alpha: float
    n_modes: int
    law_delta: np.ndarray
    law_force_paper: np.ndarray
    law_force_centre: np.ndarray
    relax_delta: np.ndarray
    relax_force: np.ndarray
    loops: tuple[Loop, ...]


def _as_loop(item) -> Loop:
    if isinstance(item, Loop):
        return item
    hist = getattr(item, "history", None)
    if hist is not None:  # a CollisionResult recorded with record=True
        return Loop(v=float(item.v), delta=np.asarray(hist.x0) + 1.0, force=np.asarray(hist.force))
    v, delta, force = item
    return Loop(v=float(v), delta=np.asarray(delta, float), force=np.asarray(force, float))


def dynamic_loops(
    nu: float = 0.33, v: Sequence[float] = (0.1, 0.04), alpha: float = 500.0, n_modes: int = 1300
) -> tuple[Loop, ...]:
    """Run the modal collision solver with histories and return its force-compression loops."""
    from restitution.dynamics.collision import collide

    modes = get_modes(nu, count=n_modes)
    out = []
    for speed in v:
        res = collide(modes, float(speed), float(alpha), record=True)
        out.append(_as_loop(res))
    return tuple(out)


def compute(
    nu: float = 0.33,
    *,
    n_modes: int = 1300,
    alpha: float = 500.0,
    delta_max: float = 0.3,
    n_delta: int = 31,
    dynamic: Sequence | None = None,
) -> Fig10Data:
    """Compute Fig. 10.

    Parameters
    ----------
    nu : float
        Two-dimensional Poisson number.
    n_modes : int
        Lowest modes used by the relaxation (the paper: 1300).
    alpha : float
        Wall hardness of the relaxation, ``1/R`` (the paper: 500).
    delta_max : float
        Largest compression of the relaxation, ``R``.
    n_delta : int
        Compressions of the relaxation, uniform on ``[0, delta_max]``.
    dynamic : sequence, optional
        Loops as :class:`Loop`, ``CollisionResult`` with a history, or ``(v, delta, force)``
        tuples; see :func:`dynamic_loops`.
    """
    paper = contact_law(nu, "paper")
    centre = contact_law(nu, "centre")
    d = np.linspace(0.0, paper.max_compression, 200)
    f_centre = np.full_like(d, np.nan)
    ok = d <= centre.max_compression
    f_centre[ok] = centre.force(d[ok])
    curve = relaxation_curve(
        get_modes(nu, count=n_modes), np.linspace(0.0, delta_max, n_delta), alpha
    )
    loops = tuple(_as_loop(x) for x in (dynamic or ()))
    return Fig10Data(
        nu=float(nu),
        alpha=float(alpha),
        n_modes=int(n_modes),
        law_delta=d,
        law_force_paper=paper.force(d),
        law_force_centre=f_centre,
        relax_delta=curve.delta,
        relax_force=curve.force,
        loops=loops,
    )


def plot(data: Fig10Data, path, note: str = "") -> None:
    """Draw Fig. 10 into ``path`` (format from the suffix). ``note`` is printed under the axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.0, 4.5))
    ax.plot(data.law_delta, data.law_force_paper, "k-", label="2D Hertz, eq. (57) as printed")
    ax.plot(data.law_delta, data.law_force_centre, "k--", label="2D Hertz, centre of mass")
    ax.plot(
        data.relax_delta,
        data.relax_force,
        "-.",
        color="tab:blue",
        label=f"static relaxation ({data.n_modes} modes, alpha={data.alpha:g})",
    )
    colours = ["tab:red", "tab:green", "tab:orange", "tab:purple"]
    for i, loop in enumerate(data.loops):
        c = colours[i % len(colours)]
        ax.plot(loop.delta, loop.force, color=c, lw=1.0, label=f"dynamic, v = {loop.v:g} c")
        # Arrows along the loop show the course of time.
        k = max(1, len(loop.delta) // 6)
        for j in range(k, len(loop.delta) - 1, k):
            ax.annotate(
                "",
                xy=(loop.delta[j + 1], loop.force[j + 1]),
                xytext=(loop.delta[j], loop.force[j]),
                arrowprops=dict(arrowstyle="->", color=c, lw=1.0),
            )
    top = np.nanmax(
        np.concatenate([data.relax_force, *[lp.force[lp.delta > 0] for lp in data.loops]])
    )
    ax.set_xlim(0.0, max(float(np.max(data.relax_delta)), 1e-3) * 1.05)
    ax.set_ylim(0.0, 1.1 * top if math.isfinite(top) else None)
    ax.set_xlabel(r"compression $\delta = x_0 + R$  [$R$]")
    ax.set_ylabel(r"force $P$  [$E R$]")
    ax.set_title(rf"Force vs compression, $\nu$ = {data.nu:g}")
    ax.legend(fontsize=8, loc="upper left")
    add_notes(fig, [note])
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
