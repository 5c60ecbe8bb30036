"""Fig. 6: logarithm of the energy in the low (n, l) modes at closest approach."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.dynamics.collision import collide
from restitution.reproduction.figures._style import add_notes


@dataclass(frozen=True, eq=False)
class ModeEnergyData:
    """Energy at closest approach on an (n, l) grid (fraction of E0; NaN where no mode)."""

    energy: np.ndarray  # shape (n_max + 1, l_max + 1)
    v: float
    alpha: float
    n_modes: int


def compute(nu=0.33, v=0.1, alpha=500.0, count=1600, n_max=12, l_max=12, result=None):
    """Energy per mode at closest approach; pass ``result`` to reuse a collision."""
    if result is None:
        result = collide(get_modes(nu, count=count), v, alpha)
    grid = np.full((n_max + 1, l_max + 1), np.nan)
    for n, l, e in zip(result.mode_n, result.mode_l, result.mode_energy_closest, strict=True):
        if n <= n_max and l <= l_max:
            grid[n, l] = e
    return ModeEnergyData(energy=grid, v=result.v, alpha=result.alpha, n_modes=result.n_modes)


def plot(data: ModeEnergyData, path: str | Path, note: str = "") -> None:
    """Write the figure to ``path``. ``note`` is printed under the axes."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.0, 4.8))
    img = ax.imshow(np.log10(data.energy.T), origin="lower", cmap="viridis", aspect="auto")
    fig.colorbar(img, ax=ax, label=r"$\log_{10}$(energy / $E_0$)")
    ax.set_xlabel("n (directional nodes)")
    ax.set_ylabel("l")
    ax.set_title(
        f"Mode energy at closest approach\nv = {data.v:g} c, alpha = {data.alpha:g}, "
        f"{data.n_modes} modes",
        fontsize=10,
    )
    white = "white: (n, l) not among the modes of the collision (above its frequency cut)"
    add_notes(fig, [white, note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)
