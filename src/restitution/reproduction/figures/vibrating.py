"""Figures of vibrating disks (issue 17, ``docs/vibrating.md``).

* :func:`compute_distributions` / :func:`plot_distributions`: the distribution of epsilon at
  several ``v / v_th`` (thermal modes, ``(m/2) v_th^2 = T``).
* :func:`compute_phase` / :func:`plot_phase`: epsilon against the phase of one excited mode,
  with the fitted sinusoid.
* :func:`compute_bounce` / :func:`plot_bounce`: a disk bouncing under gravity, its vibrations
  carried over, against a constant-epsilon disk and a disk at rest at every impact.

``python -m restitution.reproduction.figures.vibrating --out docs/figures`` draws all three (a
few minutes on one core; ``--quick`` in seconds, coarse and marked so).
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from restitution.atomic import replacing
from restitution.bodies.cache import get_modes
from restitution.bodies.disk.contact import max_compression_estimate
from restitution.dynamics.collision import collide
from restitution.reproduction.figures._style import QUICK_NOTE, add_notes
from restitution.vibrating.ensemble import (
    Ensemble,
    SinusoidFit,
    fit_sinusoid,
    phase_scan,
    temperature_for,
    thermal_ensemble,
)
from restitution.vibrating.sequences import (
    Sequence,
    bounce,
    constant_epsilon_speeds,
    memoryless_speeds,
)
from restitution.vibrating.vibration import kinetic_energy

__all__ = [
    "compute_bounce",
    "compute_distributions",
    "compute_phase",
    "plot_bounce",
    "plot_distributions",
    "plot_histogram",
    "plot_phase",
]


def _alpha(v: float, alpha_delta: float) -> float:
    """Wall hardness with ``alpha * delta_max(v) = alpha_delta`` (the sweeps' scaling)."""
    return alpha_delta / max_compression_estimate(float(v))


def compute_distributions(
    nu=0.33, v=0.1, ratios=(4.0, 2.0, 1.0), count=40, samples=300, seed=0, alpha_delta=80.0,
    **overrides,
) -> list[Ensemble]:  # fmt: skip
    """One thermal ensemble per ``v / v_th`` in ``ratios`` at speed ``v`` (seeds ``seed + i``)."""
    ms = get_modes(nu, count=count)
    alpha = _alpha(v, alpha_delta)
    return [
        thermal_ensemble(ms, v, alpha, temperature_for(ms, v, r), samples, seed + i, **overrides)
        for i, r in enumerate(ratios)
    ]


def plot_histogram(ens: Ensemble, path: str | Path, note: str = "") -> None:
    """Histogram of epsilon of one ensemble."""
    plot_distributions([ens], path, note)


def plot_distributions(ensembles: list[Ensemble], path: str | Path, note: str = "") -> None:
    """Histograms of epsilon, one per ensemble, with mean, spread and fraction above 1."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    eps_all = np.concatenate([e.epsilon for e in ensembles])
    bins = np.linspace(eps_all.min(), eps_all.max(), 40)
    for e in ensembles:
        s = e.summary()
        ax.hist(e.epsilon, bins=bins, histtype="step", density=True, lw=1.4,
                label=f"v/v_th = {e.v_over_v_thermal:.3g}: mean {s['mean']:.3f}, "
                f"spread {s['spread']:.3f}, P(eps>1) = {s['fraction_above_1']:.2f}")  # fmt: skip
    ax.axvline(1.0, color="k", lw=0.6, ls=":")
    ax.set_xlabel(r"$\varepsilon$")
    ax.set_ylabel("probability density")
    first = ensembles[0]
    title = (f"Thermal modes: v = {first.v:g} c, alpha = {first.alpha:.4g}, "
             f"{first.n_modes} modes, {first.epsilon.size} samples each")  # fmt: skip
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7.5, loc="upper left")
    add_notes(fig, ["(m/2) v_th^2 = T, the mean energy per mode", note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)


@dataclass(frozen=True, eq=False)
class PhaseData:
    """Epsilon against the phase of mode ``index`` at mode energies ``fractions`` of ``E0``."""

    phases: np.ndarray
    fractions: np.ndarray
    epsilon: np.ndarray  # shape (len(fractions), len(phases))
    fits: tuple[SinusoidFit, ...]
    epsilon_rest: float
    index: int
    n: int
    l: int  # noqa: E741
    v: float
    alpha: float
    n_modes: int


def compute_phase(
    nu=0.33, v=0.1, alpha=500.0, count=40, fractions=(1e-6, 1e-4, 1e-2), n_phase=24,
    index=None, **overrides,
) -> PhaseData:  # fmt: skip
    """Phase scans of the mode the collision at rest excites most (or ``index``)."""
    ms = get_modes(nu, count=count)
    rest = collide(ms, v, alpha, **overrides)
    k = int(np.argmax(rest.mode_energy_after)) if index is None else int(index)
    phases = np.linspace(0, 2 * np.pi, n_phase, endpoint=False)
    e0 = float(kinetic_energy(ms, v))
    eps = np.array([phase_scan(ms, v, alpha, k, f * e0, phases, **overrides) for f in fractions])
    return PhaseData(
        phases=phases, fractions=np.asarray(fractions, dtype=float), epsilon=eps,
        fits=tuple(fit_sinusoid(phases, row) for row in eps), epsilon_rest=rest.epsilon,
        index=k, n=int(ms.n[k]), l=int(ms.l[k]), v=v, alpha=alpha, n_modes=count,
    )  # fmt: skip


def plot_phase(data: PhaseData, path: str | Path, note: str = "") -> None:
    """Epsilon minus its value at rest, divided by the amplitude ``sqrt(E_k / E0)``, against
    the phase, with the fitted sinusoids: the curves collapse where first order holds."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    fine = np.linspace(0, 2 * np.pi, 200)
    for f, row, fit in zip(data.fractions, data.epsilon, data.fits, strict=True):
        s = np.sqrt(f)
        (line,) = ax.plot(data.phases, (row - data.epsilon_rest) / s, "o", ms=4,
                          label=f"E_k/E0 = {f:g}: a/A = {fit.amplitude / s:.3f}, "
                          f"residual/A^2 = {fit.residual / f:.2f}")  # fmt: skip
        ax.plot(fine, (fit.mean - data.epsilon_rest + fit.amplitude
                       * np.cos(fine - fit.phase)) / s, color=line.get_color(), lw=1)  # fmt: skip
    ax.set_xlabel(r"phase $\varphi$ of the mode at the reference instant (rad)")
    ax.set_ylabel(r"$(\varepsilon - \varepsilon_{rest}) / \sqrt{E_k/E_0}$")
    ax.set_title(f"One excited mode (n, l) = ({data.n}, {data.l}): v = {data.v:g} c, "
                 f"alpha = {data.alpha:g}, {data.n_modes} modes", fontsize=9)  # fmt: skip
    ax.legend(fontsize=7.5)
    add_notes(fig, ["lines: least-squares fit eps0 + a cos(phi - phi0); A = sqrt(E_k/E0)", note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)


@dataclass(frozen=True, eq=False)
class BounceData:
    """A bouncing chain and its two comparisons (impact speeds, ``c``)."""

    sequence: Sequence
    constant: np.ndarray
    memoryless: np.ndarray
    epsilon_constant: float


def compute_bounce(
    nu=0.33, v=0.1, count=40, collisions=60, gravity=1e-6, alpha_delta=80.0, **overrides
) -> BounceData:
    """Bounce under ``gravity`` (``c^2/R``) on a wall with ``alpha delta_max(v) = alpha_delta``
    at the first speed; compare with the constant epsilon of the first impact (a disk at rest)
    and with a disk at rest at every impact."""
    ms = get_modes(nu, count=count)
    alpha = _alpha(v, alpha_delta)
    seq = bounce(ms, v, alpha, collisions, gravity=gravity, **overrides)
    eps_c = float(seq.epsilon[0])
    return BounceData(
        sequence=seq,
        constant=constant_epsilon_speeds(v, eps_c, collisions),
        memoryless=memoryless_speeds(ms, v, alpha, collisions, **overrides),
        epsilon_constant=eps_c,
    )


def plot_bounce(data: BounceData, path: str | Path, note: str = "") -> None:
    """Impact speeds against the collision number (log scale) and the energy shares."""
    import matplotlib.pyplot as plt

    seq = data.sequence
    k = np.arange(seq.v.size)
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
    ax.semilogy(k, seq.v / seq.v[0], "o-", ms=3, label="vibrations carried over")
    if np.all(np.isfinite(data.memoryless)):
        ax.semilogy(k, data.memoryless / seq.v[0], "s--", ms=3, label="at rest at every impact")
    ax.semilogy(k, data.constant / seq.v[0], "k:",
                label=f"constant eps = {data.epsilon_constant:.4f}")  # fmt: skip
    ax.set_ylabel("impact speed / first impact speed")
    ax.legend(fontsize=8)
    total = seq.translation_before + seq.vibration_before
    bx.plot(k, seq.vibration_before / total, "o-", ms=3, label="vibration / (translation + vib.)")
    bx.axhline(seq.n_modes / (seq.n_modes + 1.0), color="0.5", lw=0.6, ls="--",
               label="N / (N + 1)")  # fmt: skip
    bx.set_xlabel("collision k")
    bx.set_ylabel("share at impact")
    bx.legend(fontsize=8)
    ax.set_title(f"Bouncing under gravity g = {seq.gravity:g} c^2/R: alpha = {seq.alpha:.4g}, "
                 f"{seq.n_modes} modes", fontsize=9)  # fmt: skip
    add_notes(fig, ["gravity neglected during each contact; flights exact", note])
    with replacing(path) as tmp:
        fig.savefig(tmp)
    plt.close(fig)


def main(argv: list[str] | None = None) -> None:
    """Draw the three figures into ``--out`` (``--quick``: coarse grids, marked)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/figures"))
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    note = QUICK_NOTE if args.quick else ""
    if args.quick:
        dist = compute_distributions(count=10, samples=30, energy_tol=1e-5)
        phase = compute_phase(count=10, fractions=(1e-4, 1e-3), n_phase=8)
        bnc = compute_bounce(count=10, collisions=8)
    else:
        dist = compute_distributions(energy_tol=1e-5)
        phase = compute_phase(energy_tol=1e-9)
        bnc = compute_bounce()
    plot_distributions(dist, args.out / "vibrating_epsilon_distribution.png", note)
    plot_phase(phase, args.out / "vibrating_phase.png", note)
    plot_bounce(bnc, args.out / "vibrating_bounce.png", note)
    for e in dist:
        print(f"v/v_th = {e.v_over_v_thermal:.3g}: {e.summary()}")
    for f, fit in zip(phase.fractions, phase.fits, strict=True):
        print(f"E_k/E0 = {f:g}: {fit}")
    seq = bnc.sequence
    print("bounce v/v0:", np.round(seq.v / seq.v[0], 4).tolist())
    print("memoryless v/v0:", np.round(bnc.memoryless / seq.v[0], 4).tolist())
    print("constant eps:", bnc.epsilon_constant)
    share = seq.vibration_before / (seq.translation_before + seq.vibration_before)
    print("vibration share:", np.round(share, 4).tolist())
    print(f"max neglected impulse {seq.neglected_impulse.max():.3g}, "
          f"max drift {seq.energy_drift.max():.3g}")  # fmt: skip


if __name__ == "__main__":
    main()
