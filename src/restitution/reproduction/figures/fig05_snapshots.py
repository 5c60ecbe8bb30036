"""Fig. 5: snapshots of the deformed disk hitting the wall (v = 0.2 c)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.dynamics.collision import collide
from restitution.reproduction.figures._style import add_notes


@dataclass(frozen=True, eq=False)
class SnapshotData:
    """Edge outlines ``(x, y)`` at times ``t`` (``R/c``), ``R`` units; wall at ``x = 0``."""

    t: np.ndarray
    x: np.ndarray  # shape (K, P)
    y: np.ndarray
    v: float
    epsilon: float
    separated: np.ndarray  # shape (K,), bool: the frame is after the separation


def edge_outline(modes, x0: float, Q: np.ndarray, n_points: int = 721):
    """Deformed edge (eq. 39) for centre ``x0`` and modal coordinates ``Q`` (shape (N,))."""
    phi = np.linspace(-np.pi, np.pi, n_points)
    n = modes.n[:, None]
    ur = (Q * modes.C) @ np.cos(n * phi)
    up = (Q * modes.S) @ np.sin(n * phi)
    x = x0 + (1 + ur) * np.cos(phi) - up * np.sin(phi)
    y = (1 + ur) * np.sin(phi) + up * np.cos(phi)
    return x, y


def compute(nu=0.33, v=0.2, alpha=500.0, count=400, n_contact=5, n_after=3) -> SnapshotData:
    """Snapshots from first touch to after the separation.

    ``n_contact`` frames span the contact (first touch to the last recorded time the edge is
    within ``0.06 R`` of the wall); ``n_after`` frames follow the separation, over one period of
    the quadrupole (2, 0), by the exact free flow of the modes (no force acts once the disk has
    left; ``Q(t) = Q cos(w t) + (Qdot/w) sin(w t)``, centre at the final speed). ``Qdot`` at the
    end of the record follows from each mode's recorded energy, its sign from the record.
    Times in ``R/c`` from the start of the run.
    """
    modes = get_modes(nu, count=count)
    r = collide(modes, v, alpha, record=True, record_interval=0.01)
    h = r.history
    touching = np.nonzero(h.x0 > -1.06)[0]
    idx = np.linspace(touching[0], touching[-1], n_contact).astype(int)
    frames = [(h.t[i], h.x0[i], h.Q[i]) for i in idx]
    # Free flow after the record: mode energy e = Qdot^2 / v^2 + w^2 Q^2 / v^2 (fraction of E0).
    w, Q_end = modes.omega, h.Q[-1]
    speed2 = np.maximum(v**2 * h.mode_energy[-1] - (w * Q_end) ** 2, 0.0)
    sign = np.sign(h.Q[-1] - h.Q[-2]) if h.t.size > 1 else np.ones_like(Q_end)
    Qdot = sign * np.sqrt(speed2)
    period = 2.0 * np.pi / float(w[(modes.n == 2) & (modes.l == 0)][0])
    for tau in np.linspace(0.0, period, n_after + 1)[1:]:
        Q = Q_end * np.cos(w * tau) + Qdot / w * np.sin(w * tau)
        frames.append((h.t[-1] + tau, h.x0[-1] + h.v[-1] * tau, Q))
    xs, ys = zip(*(edge_outline(modes, x0, Q) for _, x0, Q in frames), strict=True)
    return SnapshotData(
        t=np.array([f[0] for f in frames]),
        x=np.array(xs),
        y=np.array(ys),
        v=v,
        epsilon=r.epsilon,
        separated=np.arange(len(frames)) >= n_contact,
    )


def plot(data: SnapshotData, path: str | Path, note: str = "") -> None:
    """Write the figure to ``path``; ``note`` is printed under the axes."""
    import matplotlib.pyplot as plt

    k = data.t.size
    fig, axes = plt.subplots(1, k, figsize=(1.7 * k, 2.6), sharey=True)
    left = min(-2.3, float(np.min(data.x)) - 0.1)
    for ax, t, x, y, after in zip(axes, data.t, data.x, data.y, data.separated, strict=True):
        color = "C1" if after else "C0"
        ax.fill(x, y, color=color, alpha=0.35)
        ax.plot(x, y, color=color, lw=0.8)
        ax.axvline(0.0, color="k", lw=2)
        ax.set_xlim(left, 0.3)
        ax.set_ylim(-1.2, 1.2)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.2f} R/c", fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(
        f"Disk hitting the wall at v = {data.v:g} c (epsilon = {data.epsilon:.3f})", fontsize=10
    )
    after = "orange: after the separation (free vibrations), deformation to scale"
    add_notes(fig, [after, note])
    with replacing(path) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
