"""The sphere as a kind of body: what the layers above need of it, registered as ``"sphere"``.

Units: ``E = rho = R = 1`` of the sphere's three-dimensional constants; speeds in ``c``;
frequencies in ``c / R``.

Besides the modes, the kind declares the sphere's defaults and plans: harder walls and larger
mode windows than the disk's (docs/spheres.md says why), its law files
(``law_sphere_nu<nu>.json``), the route of its slow impacts (Rayleigh's estimate on Hertz's
force pulse, :mod:`restitution.quasistatic.low_speed`), and the settings and measured costs of
its shipped laws (``make law-sphere``).
"""

from __future__ import annotations

import numpy as np

from restitution.bodies.kinds import (
    BodyKind,
    PairPlan,
    ProductionPlan,
    SweepPlan,
    register,
    units_table,
)
from restitution.bodies.sphere import surface
from restitution.bodies.sphere.modes import (
    _ALGORITHM_VERSION,
    SphereModes,
    compute_sphere_modes,
    weyl_count,
)

__all__ = ["KIND"]

# The sphere's epsilon(v) oscillates (the phase omega tau / 2 of its quadrupole mode drifts with
# tau ~ v^(-1/5); docs/spheres.md): at nu = 0.3 the loss changes tenfold between v = 0.02 and
# 0.04, so the speeds are spaced by a factor 1.2 (26 from 0.003 to 0.3). The mode window is one
# doubling above the default because at the hardest wall N = 1600 is not yet asymptotic (at
# v = 0.3 the slope in 1/sqrt(N) was 0.104 between 1600 and 3200, 0.135-0.145 above). Below
# v ~ 0.005 even this window is not asymptotic at every wall (docs/spheres.md); those points are
# flagged.
_SPEEDS = tuple(float(f"{v:.3g}") for v in np.geomspace(0.003, 0.3, 26))

PRODUCTION = ProductionPlan(
    # Glass 0.2-0.25, steel and aluminium 0.3-0.35, brass and lead 0.35-0.45.
    nus=(0.2, 0.25, 0.3, 0.35, 0.4, 0.45),
    groups=(SweepPlan(_SPEEDS, (2400, 4800, 9600, 19200), batch_size=3),),
    # From 1e-6 (5 mm/s for steel) up to the modal laws' slowest speed, a factor 1.02 apart.
    # The loss oscillates with v; at this spacing PCHIP between the points strays from the
    # estimate by at most 0.006 v (median 4e-5 v; measured at nu = 0.3 against a grid 10 times
    # finer), and each point's error includes what its two intervals stray.
    low_speeds=tuple(float(f"{v:.4g}") for v in np.geomspace(1e-6, _SPEEDS[0], 405)[:-1]),
    # The sphere's 1872 collisions took 32 min of one core.
    seconds_per_collision=1.0,
    # 404 points for six laws took about 10 minutes (docs/spheres.md).
    seconds_per_low_point=0.25,
    # The residual route (issue 46): the 44 modal speeds of nu = 0.3 took 197 s on two
    # processes (200, 400 and 800 kept modes; 29 Nov 2026): 8.9 s a point on one core.
    residual_seconds_per_point=9.0,
)

# Two spheres: their low-speed route up to its reach (restitution.quasistatic.low_speed.reach,
# which depends on the pair: twice the wall's 0.003 for two identical spheres) on the sphere's
# spacing, a factor 1.02, from 2e-6 (twice the wall's lowest speed). No modal groups: a pair's
# windows would need the wall's times 1 + (R2 c1 / (R1 c2))^3 modes (nine times at R2/R1 = 2,
# above the 20000 a sphere's mode scan computes; docs/spheres.md).
PAIR_PRODUCTION = PairPlan(
    # The shipped laws of one material (make law-sphere-pair): steel, aluminium.
    radius_ratios=(1.5, 2.0, 4.0),
    nus=(0.3,),
    groups=(),
    low_speeds=tuple(float(f"{w:.4g}") for w in np.geomspace(2e-6, 0.03, 487)),
    # 376 points of R2/R1 = 2 took 213 s (another computation on the second core).
    seconds_per_low_point=0.57,
)


def _cap_modes(modes):
    """The sphere's cap of every azimuthal order (imported when asked: the cap module imports
    this kind's modes)."""
    from restitution.bodies.sphere.cap import cap_modes

    return cap_modes(modes)


KIND = register(
    BodyKind(
        geometry="sphere",
        description=(
            "elastic sphere; E, nu, rho are its three-dimensional constants; mass 4 pi rho R^3 / 3"
        ),
        dimension=3,
        nu_low=-1.0,
        nu_high=0.5,
        mode_class=SphereModes,
        algorithm=_ALGORITHM_VERSION,
        compute=compute_sphere_modes,
        weyl_count=weyl_count,
        max_compression=surface.max_compression_estimate,
        contact_time=surface.contact_time_estimate,
        # The dense scan over (l, omega) grows like N^(3/2): 6400 modes in 18 s at nu = 0.3
        # (0.8 million grid points); 20000 modes scan about 2.6 million.
        max_modes=20_000,
        units=units_table(
            "E = rho = R = 1: the sphere's Young modulus, density and radius",
            "sphere",
            "E R^2",
            "m = 4 pi / 3",
        ),
        order_name="l",
        modes_title=(
            "Axisymmetric spheroidal modes of the free sphere (omega in c/R; C = U(1), "
            "S = V(1) surface amplitudes)"
        ),
        shapes={"sphere": None},
        shape_words={"sphere": "elastic sphere (3D)"},
        file_tag="sphere",
        # The sphere's loss is linear in 1/alpha only from alpha * delta_max ~ 80 (Hertz
        # delta_max): at nu = 0.3, N = 12800 its slope in 1/alpha changes by 16-25 % between
        # the products 40-80 and 80-160 at v = 0.01-0.1, by at most 7 % between 80-160, 160-320
        # and 320-640 (by 12 % at v = 0.003); with 40-160 the curvature test flags v = 0.006
        # (docs/spheres.md).
        alpha_products=(80.0, 160.0, 320.0),
        # The sphere's loss settles into its N -> infinity trend later than the disk's: at
        # nu = 0.3, v = 0.003 it still jumps by 50 % between N = 100 and 400 and climbs
        # monotonically only from N ~ 1600 (docs/spheres.md, measured for N = 100-12800); a
        # sphere collision with 12800 modes takes 1-5 s, so the window is the disk's times 16.
        sweep_modes=(1600, 3200, 6400, 12800),
        scales_need_nu=True,
        law_model=(
            "Elastic sphere (3D linear elasticity, constants E = rho = R = 1, Poisson number "
            "nu) expanded in its axisymmetric spheroidal free eigenmodes (Lamb), hitting a wall "
            "through the potential V = (1/alpha) int exp(alpha x(theta)) dS over the near "
            "hemisphere (the disk's eqs. 40-45 of Gerl & Zippelius on the sphere's surface); "
            "energy loss 1 - epsilon^2 extrapolated linearly in 1/alpha (alpha -> infinity) and "
            "in 1/sqrt(N) (N modes -> infinity), each point's fits in its record."
        ),
        law_units=(
            "v is the sphere's speed towards the wall before the collision in units of "
            "c = sqrt(E/rho) of its three-dimensional constants; two identical spheres "
            "approaching each other at +-v (relative speed 2v) collide identically. epsilon = "
            "-v_after / v_before of the centre of mass."
        ),
        low_speed_route="rayleigh",
        # Two spheres: Rayleigh's estimate on the pair's Hertz pulse, each sphere's modes
        # driven at its own pole (restitution.quasistatic.low_speed).
        pair_low_speed_route="rayleigh",
        basis_at=surface.surface_basis,
        pair_compression=surface.pair_max_compression,
        production=PRODUCTION,
        pair_production=PAIR_PRODUCTION,
        ball=True,
        # The cap of every azimuthal order (bodies/sphere/cap.py): collide --angle and law
        # --angle.
        oblique_body=_cap_modes,
        oblique_modes=20,
        # law --angle on the hard walls of real grains: steel at 1 m/s (v = 1.93e-4, alpha =
        # 80 / delta_max = 4.5e4), 30 degrees, mu = 0.3 took 3.0, 7.6 and 39.5 s at 10, 20 and
        # 40 axisymmetric modes (2 Dec 2026, this shared 2-core machine); beta moved by 0.027
        # from 10 to 20 modes and by 0.054 from 20 to 40, so 20 with the error from 10 would
        # understate it: 40 modes, the error from 20, about 50 s a speed (docs/oblique.md).
        oblique_law_modes=40,
        # Its low-speed limit: Hertz-Mindlin without microslip (Maw, Barber and Fawcett's law
        # (a), quasistatic/oblique.py), which 10-40 modes approach (docs/oblique.md).
        oblique_quasistatic="hertz-mindlin",
        # The cap's dropped modes' static residual on hats about the contact axis
        # (bodies/sphere/contact_residual.py): collide --angle --friction-model residual.
        oblique_residual=True,
    )
)
"""The elastic sphere (docs/spheres.md)."""
