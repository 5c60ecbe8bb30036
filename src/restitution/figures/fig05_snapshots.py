"""Fig. 5: snapshots of the deformed disk hitting the wall (v = 0.2 c)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.cache import get_modes
from restitution.collision import collide


@dataclass(frozen=True, eq=False)
class SnapshotData:
    """Edge outlines ``(x, y)`` at selected times, ``R`` units; wall at ``x = 0``."""

    t: np.ndarray
    x: np.ndarray  # shape (K, P)
    y: np.ndarray
    v: float
    epsilon: float


def edge_outline(modes, x0: float, Q: np.ndarray, n_points: int = 721):
    """Deformed edge (eq. 39) for centre ``x0`` and modal coordinates ``Q`` (shape (N,))."""
    phi = np.linspace(-np.pi, np.pi, n_points)
    n = modes.n[:, None]
    ur = (Q * modes.C) @ np.cos(n * phi)
    up = (Q * modes.S) @ np.sin(n * phi)
    x = x0 + (1 + ur) * np.cos(phi) - up * np.sin(phi)
    y = (1 + ur) * np.sin(phi) + up * np.cos(phi)
    return x, y


def compute(nu=0.33, v=0.2, alpha=500.0, count=400, n_snapshots=8) -> SnapshotData:
    """Integrate with histories and pick evenly spaced snapshots around the contact."""
    modes = get_modes(nu, count=count)
    r = collide(modes, v, alpha, record=True, record_interval=0.01)
    h = r.history
    touching = np.nonzero(h.x0 > -1.06)[0]
    idx = np.linspace(touching[0], min(touching[-1] + 10, h.t.size - 1), n_snapshots).astype(int)
    xs, ys = zip(*(edge_outline(modes, h.x0[i], h.Q[i]) for i in idx), strict=True)
    return SnapshotData(t=h.t[idx], x=np.array(xs), y=np.array(ys), v=v, epsilon=r.epsilon)


def plot(data: SnapshotData, path: str | Path) -> None:
    """Write the figure to ``path``."""
    import matplotlib.pyplot as plt

    k = data.t.size
    fig, axes = plt.subplots(1, k, figsize=(1.9 * k, 3.0), sharey=True)
    for ax, t, x, y in zip(axes, data.t, data.x, data.y, strict=True):
        ax.fill(x, y, color="C0", alpha=0.35)
        ax.plot(x, y, color="C0", lw=0.8)
        ax.axvline(0.0, color="k", lw=2)
        ax.set_xlim(-2.3, 0.3)
        ax.set_ylim(-1.2, 1.2)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.2f}", fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle(f"Disk hitting the wall at v = {data.v} c (epsilon = {data.epsilon:.3f})")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
