"""Fig. 3: mode frequencies against the number of directional nodes n.

Radial-type modes (``|C| > |S|`` at the edge) are marked apart from tangential-type modes.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.reproduction.figures._style import add_notes


@dataclass(frozen=True, eq=False)
class SpectrumData:
    """Frequencies (``c / R``) with their order ``n`` and edge character."""

    nu: float
    n: np.ndarray
    omega: np.ndarray
    radial: np.ndarray


def compute(nu: float = 0.33, omega_max: float = 20.0) -> SpectrumData:
    """All symmetric modes below ``omega_max`` (``c / R``)."""
    modes = get_modes(nu, omega_max=omega_max)
    return SpectrumData(
        nu=nu, n=modes.n, omega=modes.omega, radial=np.abs(modes.C) > np.abs(modes.S)
    )


def plot(data: SpectrumData, path: str | Path, note: str = "") -> None:
    """Write the figure to ``path`` (format from the suffix). ``note`` is printed under the axes."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    r = data.radial
    ax.scatter(data.n[r], data.omega[r], marker="o", s=18, label="radial type, |C| > |S|")
    ax.scatter(data.n[~r], data.omega[~r], marker="x", s=18, label="tangential type, |C| < |S|")
    ax.set_xlabel("number of directional nodes n")
    ax.set_ylabel(r"$\omega_{n,l}$  [c/R]")
    ax.set_title(
        rf"Symmetric modes of the free disk, $\nu$ = {data.nu} (c = $\sqrt{{E/\rho}}$ = 1)"
    )
    # Below the lowest branch (large n, small omega) no mode lives: the legend covers nothing.
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)
    add_notes(fig, [note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)
