"""Fig. 2: the deformed polar grid of a few low modes.

Radii and circles of the undeformed disk are drawn displaced by ``amplitude * u`` of one mode,
``u_r = U_r(r) cos(n phi)``, ``u_phi = U_phi(r) sin(n phi)`` (eq. 19).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.reproduction.figures._style import add_notes

DEFAULT_MODES = ((2, 0), (0, 0), (1, 0))
"""The quadrupole, the lowest breathing mode and the lowest n = 1 mode."""


@dataclass(frozen=True, eq=False)
class ShapeData:
    """Deformed grid lines, one entry per mode.

    ``lines[i]`` is a list of ``(x, y)`` arrays in units of ``R``; ``labels[i]`` names the mode.
    """

    nu: float
    labels: tuple[str, ...]
    lines: tuple[tuple[tuple[np.ndarray, np.ndarray], ...], ...]
    max_edge_displacement: tuple[float, ...]


def _deformed(modes, k: int, amplitude: float, n_r: int = 6, n_phi: int = 16):
    r_lines = np.linspace(0.0, 1.0, 200)
    phi_lines = np.linspace(0.0, 2.0 * np.pi, 361)
    sub = modes.take([k])
    n = int(sub.n[0])
    lines = []

    def displaced(r, phi):
        U, V = sub.shapes(r)
        ur = amplitude * U[0] * np.cos(n * phi)
        up = amplitude * V[0] * np.sin(n * phi)
        x = (r + ur) * np.cos(phi) - up * np.sin(phi)
        y = (r + ur) * np.sin(phi) + up * np.cos(phi)
        return x, y

    for rc in np.linspace(1.0 / n_r, 1.0, n_r):
        lines.append(displaced(np.full_like(phi_lines, rc), phi_lines))
    for pc in np.linspace(0.0, 2.0 * np.pi, n_phi, endpoint=False):
        lines.append(displaced(r_lines, np.full_like(r_lines, pc)))
    return tuple(lines)


def compute(nu: float = 0.33, which=DEFAULT_MODES, amplitude: float = 0.12) -> ShapeData:
    """Deformed grids of the modes ``which`` (pairs ``(n, l)``), ``amplitude`` in units of Q."""
    modes = get_modes(nu, omega_max=12.0)
    labels, lines, edge = [], [], []
    for n, l in which:
        k = int(np.nonzero((modes.n == n) & (modes.l == l))[0][0])
        labels.append(f"n = {n}, l = {l}, omega = {modes.omega[k]:.4f} c/R")
        lines.append(_deformed(modes, k, amplitude))
        edge.append(float(amplitude * max(abs(modes.C[k]), abs(modes.S[k]))))
    return ShapeData(
        nu=nu, labels=tuple(labels), lines=tuple(lines), max_edge_displacement=tuple(edge)
    )


def plot(data: ShapeData, path: str | Path, note: str = "") -> None:
    """Write the figure to ``path`` (format from the suffix). ``note`` is printed under the axes."""
    import matplotlib.pyplot as plt

    k = len(data.labels)
    fig, axes = plt.subplots(1, k, figsize=(3.6 * k, 3.8))
    for ax, label, lines in zip(np.atleast_1d(axes), data.labels, data.lines, strict=True):
        t = np.linspace(0, 2 * np.pi, 361)
        ax.plot(np.cos(t), np.sin(t), color="0.8", lw=1.0)
        for x, y in lines:
            ax.plot(x, y, color="C0", lw=0.8)
        ax.set_aspect("equal")
        ax.set_axis_off()
        ax.set_title(label, fontsize=9)
    fig.suptitle(rf"Symmetric eigenmodes, $\nu$ = {data.nu} (grey: undeformed edge)")
    add_notes(fig, [note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)
