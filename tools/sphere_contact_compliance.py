"""The sphere's contact compliances in its truncated modes, as fractions of the continuum's
(issue 63: why the sphere's microslip ``beta`` is not monotonic in the mode count).

For each contact radius ``a`` and count of axisymmetric modes ``N`` (the cap of every azimuthal
order below the same frequency, as :func:`restitution.bodies.sphere.cap.cap_modes` builds it
for the oblique collision), prints the modal compliance of Hertz's pressure, Mindlin's stick
traction, the gross-slip traction and the flat punch over the elastic sphere's
(:mod:`restitution.bodies.sphere.contact_compliance`), the tangential fractions over the
pressure's (the modal body's tangential-to-normal compliance ratio relative to the
continuum's), and the punch's over the stick's: the modal body's stiffness ratio ``k_t / k_n``
over the sphere's. ``nu = 0.3``. Prints the tables of docs/oblique.md.

Usage (from the project's root, with its venv; about 3 min on one core)::

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=src .venv/bin/python tools/sphere_contact_compliance.py
"""

from __future__ import annotations

import argparse

from restitution.bodies.sphere.cap import cap_modes
from restitution.bodies.sphere.contact_compliance import (
    LOADS,
    continuum_compliance,
    half_space_compliance,
    modal_compliance,
)
from restitution.bodies.sphere.modes import compute_sphere_modes

NU = 0.3
RADII = (0.12, 0.15, 0.18)
COUNTS = (20, 40, 80, 160, 320, 640, 1280, 2560)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radius", type=float, nargs="+", default=RADII)
    parser.add_argument("--modes", type=int, nargs="+", default=COUNTS)
    args = parser.parse_args()
    caps = {n: cap_modes(compute_sphere_modes(NU, count=n), azimuthal=1) for n in args.modes}
    for a in args.radius:
        full = {load: continuum_compliance(a, NU, load) for load in LOADS}
        hs = {load: half_space_compliance(a, NU, load) for load in LOADS if load != "slip"}
        print(
            f"\na = {a}: continuum C a = "
            + ", ".join(f"{load} {full[load] * a:.5f}" for load in LOADS)
            + "; over the half-space's: "
            + ", ".join(f"{load} {full[load] / hs[load]:.5f}" for load in hs)
        )
        print(
            "| N | highest l | pressure | stick | slip | punch | stick / pressure "
            "| slip / pressure | punch / stick |"
        )
        print("|---|---|---|---|---|---|---|---|---|")
        for n, cap in caps.items():
            f = {load: modal_compliance(cap, a, load) / full[load] for load in LOADS}
            print(
                f"| {n} | {int(cap.l.max())} | {f['pressure']:.4f} | {f['stick']:.4f} | "
                f"{f['slip']:.4f} | {f['punch']:.4f} | {f['stick'] / f['pressure']:.4f} | "
                f"{f['slip'] / f['pressure']:.4f} | {f['punch'] / f['stick']:.4f} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
