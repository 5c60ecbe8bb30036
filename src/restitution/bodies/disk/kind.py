"""The disk as a kind of body: what the layers above need of it, registered by name ``"disk"``.

Units: ``E = rho = R = 1`` of the disk's two-dimensional (plane-stress) constants; speeds in
``c``; frequencies in ``c / R``.

Besides the modes, the kind declares the disk's defaults and plans: its walls and mode windows,
its law files (``law_nu<nu>.json``, the first shipped, without a tag), the routes of its slow
impacts (:mod:`restitution.quasistatic.slow_disk`), and the settings and measured costs of its
shipped laws (``make law``, ``make law-pair``; docs/results.md says how each window was chosen).
"""

from __future__ import annotations

import numpy as np

from restitution.bodies.disk import contact
from restitution.bodies.disk.modes import _ALGORITHM_VERSION, ModeSet, compute_modes, weyl_count
from restitution.bodies.disk.rim import rim_modes
from restitution.bodies.disk.surface import edge_basis
from restitution.bodies.kinds import (
    BodyKind,
    PairPlan,
    ProductionPlan,
    SweepPlan,
    register,
    units_table,
)

__all__ = ["KIND"]

# -- the shipped laws' settings (restitution.laws.making.production says why) ----------------

# The paper's speeds from 0.02 c (Figs. 1 and 7: 0.02, 0.04, ..., 0.30) with the mode window
# N = 1880-15040: with the paper's N = 300-940 most points fail the curvature test in
# 1/sqrt(N) (4 of 34 passed); with this window all 15 pass at both nu and v = 0.1, 0.3 agree
# with the finite-element route within 0.3 of their errors.
_PAPER = SweepPlan(
    velocities=(0.02,) + tuple(round(0.04 + 0.02 * k, 2) for k in range(14)),
    n_modes=(1880, 3760, 7520, 15040),
)

# Slower speeds: the mode windows grow as the contact narrows (about 1 / delta_max(v)). Each
# window is the one that made the most points pass their checks at both nu; the failures of
# the windows tried before are in docs/results.md (section "Choosing the mode windows").
_SLOW = (
    SweepPlan((5e-3,), (3760, 7520, 15040, 30080), batch_size=3),
    SweepPlan((1e-2,), (7520, 15040, 30080, 60160), batch_size=3),
    SweepPlan((1e-3,), (3200, 6400, 12800, 25600), batch_size=3),
    SweepPlan((2e-4, 2e-3), (6400, 12800, 25600, 51200), batch_size=3),
    SweepPlan((1e-4, 5e-4), (12800, 25600, 51200, 102400), batch_size=3),
)

PRODUCTION = ProductionPlan(
    # The paper's 0.33 and 0.9 (Fig. 1) and a grid for real materials between them and beyond
    # (thin disks: 2D nu = 3D nu, glass 0.2-0.25, steel 0.3; long cylinders: nu / (1 - nu),
    # glass 0.3, steel 3/7 = 0.428571, polymers 0.5-0.8).
    nus=(0.2, 0.25, 0.33, 0.4285714285714286, 0.5, 0.6, 0.7, 0.8, 0.9),
    groups=(_PAPER, *_SLOW),
    # From 1e-7 (0.5 mm/s for a steel cylinder) up to the modal laws' slowest speed 1e-4, a
    # factor 1.07 apart.
    low_speeds=tuple(float(f"{v:.4g}") for v in np.geomspace(1e-7, 1e-4, 101)[:-1]),
    # The disk's 1320 collisions took 656-1442 s (one core, the largest of the shipped runs).
    seconds_per_collision=1.1,
    # 100 points for each of nine laws took 1838 s (two runs side by side, 26 Nov 2026).
    seconds_per_low_point=2.05,
    # The residual route (issue 46): points of nu = 0.33 at 1e-4, 1e-3, 0.02 and 0.3 took 13.9,
    # 7.9, 4.6 and 13.9 s on one core each (200, 400 and 800 kept modes; 29 Nov 2026).
    residual_seconds_per_point=10.0,
)

# A direct point at w = 0.02 (R2/R1 = 1.4, nu = 0.33, the windows of v = 5e-3) gave epsilon =
# 0.97642 +- 0.00021 where PCHIP between w = 0.01 and 0.04 gave 0.97852 +- 0.00024 (6.6 combined
# errors): the pairs' slow speeds are spaced like the disk's, v = 2.5e-3 and 1e-2 joining 5e-3
# with its windows. Not the disk's own windows of 1e-2 and 2e-3: at R2/R1 = 2 they would need
# 240640 and 204800 modes of one disk, above the mode cache's 200000; nor speeds below 1e-3.
PAIR_PRODUCTION = PairPlan(
    radius_ratios=(1.2, 1.4, 2.0),
    # The paper's 0.33 and 0.9 and steel cylinders (plane strain, nu = 0.3: nu_2d = 0.3 / 0.7).
    nus=(0.33, 0.3 / 0.7, 0.9),
    groups=(_PAPER, SweepPlan((2.5e-3, 5e-3, 1e-2), _SLOW[0].n_modes, batch_size=3), _SLOW[2]),
    # The disk's speeds doubled, up to 1e-3, a factor 1.1 apart.
    low_speeds=tuple(float(f"{w:.4g}") for w in np.geomspace(2e-7, 1e-3, 91)),
    # The pairs' 2052 collisions took 146 min of one core; two thirds of it went to the 684
    # collisions of R2/R1 = 2 (windows 5 times the wall's): 8.5 s each; the laws of 1.2 and 1.4
    # (2.44 and 2.96 times) took the rest: (2/3) / (1/3) = 5^p / ((2.44^p + 2.96^p) / 2) / 2
    # gives p = 2.25.
    seconds_at_5=8.5,
    cost_power=2.25,
    # 91 points for each of nine laws took 1925 s.
    seconds_per_low_point=2.35,
    # The residual route: the law of two disks of steel and glass (window scale 2.09), 24 points,
    # took 2.48 min on two workers (29 Nov 2026): 12.4 s a point, 5.9 per unit of window scale.
    residual_seconds_per_point=6.0,
)

KIND = register(
    BodyKind(
        geometry="disk",
        description=(
            "elastic disk in plane stress; E, nu, rho are its two-dimensional constants; "
            "mass pi rho R^2 per unit thickness"
        ),
        dimension=2,
        # Not all of (-1, 1): towards -1 the Bessel scan's grid grows and its normalisation
        # loses precision (issue 47): at nu = -0.9999, 100 modes took 17 s and came out with
        # NaN amplitudes, 600 did not finish in 60 s; at -0.999, 600 modes took 8 s, finite.
        nu_low=-0.999,
        nu_high=1.0,
        mode_class=ModeSet,
        algorithm=_ALGORITHM_VERSION,
        compute=compute_modes,
        weyl_count=weyl_count,
        max_compression=lambda v, nu: contact.max_compression_estimate(v),
        contact_time=lambda v, nu: contact.contact_time_estimate(v),
        # The scale-free Bessel scan (docs/numerics.md): 1e4 modes in about 2 s, 1e5 in 23-44 s
        # with 300-380 MiB peak on the project's 2-core machine; 2e5 take minutes and ~1 GiB.
        max_modes=200_000,
        units=units_table(
            "E = rho = R = 1: two-dimensional Young modulus, mass per area and disk radius",
            "disk",
            "E R",
            "m = pi",
        ),
        order_name="n",
        modes_title="Symmetric modes of the free disk (omega in c/R; C, S edge amplitudes)",
        shapes={"cylinder": "strain", "thin-disk": "stress"},
        shape_words={
            "cylinder": "long elastic cylinder hit along a diameter (the 2D disk in plane strain)",
            "thin-disk": "thin elastic disk hit on its rim (the 2D disk in plane stress)",
        },
        file_tag="",
        # alpha * delta_max(v) = 40, 80, 160: at v = 0.1 that is alpha = 210, 420, 840; slow
        # collisions get harder walls (v = 0.005: alpha = 3100-12300) while alpha * v stays
        # below ~65, where epsilon(dt) converges smoothly (at alpha v = 200, N = 100 the
        # hard-wall dynamics are chaotic: epsilon jumps by 1e-3 with dt; docs/numerics.md).
        alpha_products=(40.0, 80.0, 160.0),
        sweep_modes=(300, 400, 600, 940),
        scales_need_nu=False,
        law_model=(
            "Elastic disk (2D linear elasticity, plane stress constants E = rho = R = 1, Poisson "
            "number nu) expanded in its symmetric free eigenmodes, hitting a wall through the "
            "potential V = (1/alpha) int_{-pi/2}^{pi/2} exp(alpha x(phi)) dphi (Gerl & "
            "Zippelius, eqs. 40-45); energy loss 1 - epsilon^2 extrapolated linearly in 1/alpha "
            "(alpha -> infinity) and in 1/sqrt(N) (N modes -> infinity)."
        ),
        law_units=(
            "v is the disk's speed towards the wall before the collision in units of the 2D "
            "sound speed c = sqrt(E/rho); two identical disks approaching each other at +-v "
            "(relative speed 2v) collide identically. epsilon = -v_after / v_before of the "
            "centre of mass."
        ),
        low_speed_route="slow-modal",
        pair_low_speed_route="slow-modal",
        # The viscous loss of a damping disk on the 2D Hertz law of the centre of mass's
        # approach, the law the package's own evidence supports (docs/quasistatic.md), not the
        # paper's eq. (57) as printed (its theory's default, which the slow routes take).
        quasistatic_law="centre",
        basis_at=edge_basis,
        # Eq. (61) of the pair does not depend on the Poisson numbers.
        pair_compression=lambda w, r, e, rho, nu1, nu2: contact.pair_max_compression(w, r, e, rho),
        production=PRODUCTION,
        pair_production=PAIR_PRODUCTION,
        # The paper's two Poisson numbers (Fig. 1).
        default_nus=(0.33, 0.9),
        vibrating=True,
        ball=True,
        oblique_body=rim_modes,
        # collide --angle's default: 160 symmetric modes (about 330 on the rim) took 2-11 s at
        # alpha = 500, v = 0.005-0.05 and stay below the suspect regime (more than 320); the
        # head-on 1600 would take minutes here (docs/oblique.md, "On the command line").
        oblique_modes=160,
    )
)
"""The disk of the paper."""
