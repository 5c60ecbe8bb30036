"""``restitution bounce``: a disk that keeps colliding, its vibrations carried over."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import click

from restitution.bodies.cache import check_mode_request, get_modes
from restitution.cli._common import (
    PathOption,
    check_figure_file,
    material_from,
    note,
    nu_option,
    plane_option,
    positive_finite,
    quiet_option,
)
from restitution.cli.report import Report, emit, format_options, output_format
from restitution.errors import InputError


@click.command()
@nu_option
@plane_option
@click.option("--v", "v", type=float, required=True,
              help="First impact speed towards the wall, units of c, in (0, 1).")  # fmt: skip
@click.option("--alpha", type=float, default=500.0, show_default=True,
              help="Wall hardness alpha (1/R), the same wall at every impact.")  # fmt: skip
@click.option("--modes", "n_modes", type=int, default=40, show_default=True,
              help="Number of modes (the lowest frequencies).")  # fmt: skip
@click.option("--collisions", type=int, default=10, show_default=True)
@click.option("--gravity", type=float, default=None,
              help="Acceleration towards the wall, c^2/R (a disk bouncing on the floor; "
              "neglected during each contact).")  # fmt: skip
@click.option("--walls-distance", type=float, default=None,
              help="Distance between two facing walls, R (> 2).")  # fmt: skip
@click.option("--energy-tol", type=float, default=1e-6, show_default=True,
              help="Largest accepted relative energy drift of each collision.")  # fmt: skip
@click.option("--plot", type=PathOption(dir_okay=False, path_type=Path), default=None,
              help="Draw the impact speeds against a constant-eps disk to this file.")  # fmt: skip
@format_options
@click.option("--force", is_flag=True,
              help="Run even when the estimated time exceeds the bound of one run (1 h); "
              "the memory bound is never lifted.")  # fmt: skip
@quiet_option
def bounce(nu, plane, v, alpha, n_modes, collisions, gravity, walls_distance, energy_tol,
           plot, fmt, as_json, force):  # fmt: skip
    """Successive collisions of one disk under gravity or between two walls.

    Units: E = rho = R = 1; speeds in c, times in R/c, energies in E R^2 (m = pi), gravity in
    c^2/R. Per collision: impact speed, epsilon, vibrational energy, contact time, flight time.
    A sequence that would not fit in memory, or take more than an hour (unless --force), is
    refused before it starts.
    """
    from restitution.dynamics.collision import CollisionSettings

    fmt = output_format(fmt, as_json)
    material = material_from(nu, plane)
    if not (0 < v < 1):
        raise InputError(f"--v must lie in (0, 1) (units of c), got {v}")
    positive_finite("--alpha", alpha)
    CollisionSettings(energy_tol=energy_tol)  # the library's check of --energy-tol, up front
    if n_modes < 1:
        raise InputError(f"--modes must be at least 1, got {n_modes}")
    if collisions < 1:
        raise InputError(f"--collisions must be at least 1, got {collisions}")
    if (gravity is None) == (walls_distance is None):
        raise InputError("give exactly one of --gravity (c^2/R) and --walls-distance (R)")
    if gravity is not None:
        positive_finite("--gravity", gravity)
    if walls_distance is not None and not (math.isfinite(walls_distance) and walls_distance > 2):
        raise InputError(f"--walls-distance must exceed the diameter 2 R, got {walls_distance}")
    check_mode_request(material.nu, n_modes)
    if plot is not None:
        check_figure_file(plot, "--plot")
    from restitution.vibrating.sequences import bounce as run
    from restitution.vibrating.sequences import (
        check_bounce_memory,
        check_bounce_time,
        constant_epsilon_speeds,
    )

    check_bounce_memory(collisions, cli=True, json=fmt != "text", name="--collisions")
    ms = get_modes(material, count=n_modes)
    check_bounce_time(ms, v, alpha, collisions, force=force, name="--collisions",
                      override="--force", energy_tol=energy_tol)  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        seq = run(ms, v, alpha, collisions, gravity=gravity, walls_distance=walls_distance,
                  energy_tol=energy_tol, force=force)  # fmt: skip
    constant = constant_epsilon_speeds(v, float(seq.epsilon[0]), collisions)
    if plot is not None:
        from restitution.reproduction.figures.vibrating import BounceData, plot_bounce

        plot_bounce(BounceData(seq, constant, memoryless=constant * math.nan,
                               epsilon_constant=float(seq.epsilon[0])), plot)  # fmt: skip
        note(f"wrote {plot}")
    inputs = {"nu": material.nu, "plane": plane, "v": v, "alpha": alpha, "modes": n_modes,
              "collisions": collisions, "gravity": gravity,
              "walls_distance": walls_distance, "energy_tol": energy_tol}  # fmt: skip
    payload = {**seq.to_dict(), "energy_unit": "E R^2 (reduced units; m = pi)",
               "constant_epsilon": {"epsilon": float(seq.epsilon[0]),
                                    "impact_speeds": constant.tolist()}}  # fmt: skip
    emit(Report("bounce", inputs, payload, text=lambda: "\n".join(_text(seq, constant)),
                rows=lambda: _rows(payload)), fmt)  # fmt: skip


def _text(seq, constant) -> list[str]:
    """One line per collision: impact speed, epsilon, vibrational energy, contact and flight
    times, and the impact speed of a disk with a constant epsilon."""
    lines = [f"{'k':>3} {'v':>10} {'epsilon':>10} {'E_vib':>11} {'contact':>8} "
             f"{'flight':>11} {'v const eps':>11}"]  # fmt: skip
    for k in range(seq.v.size):
        lines.append(f"{k:3d} {seq.v[k]:10.6f} {seq.epsilon[k]:10.6f} "
                     f"{seq.vibration_before[k]:11.4e} {seq.contact_time[k]:8.4f} "
                     f"{seq.flight_time[k]:11.4g} {constant[k]:11.6f}")  # fmt: skip
    return lines


def _rows(payload: dict) -> list[dict]:
    """One row per collision (``k`` from 0): the JSON's record and the constant-epsilon speed."""
    speeds = payload["constant_epsilon"]["impact_speeds"]
    return [{"k": k, **row, "v_constant_epsilon": speeds[k]}
            for k, row in enumerate(payload["collisions"])]  # fmt: skip
