"""The energy a slow impact radiates into an elastic half-space (restitution.quasistatic.half_space,
issue 42's low-speed route; not yet served by `law`).

Independent checks: Rayleigh's wave speed against the closed-form root of Rayleigh's equation at
nu = 1/4; the Rayleigh waves' share of a point force's radiation against Miller and Pursey's
67.4 % (Proc. R. Soc. A 233, 55 (1955), the partition quoted throughout the literature); the
closed form of Hertz's pulse integral against the trajectory differentiated numerically; the
time-domain formula (Parseval) against the frequency integral of the sampled pulse's spectrum;
the exact v^(3/5) scaling.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from restitution.quasistatic.half_space import (
    HERTZ_PULSE_FACTOR,
    radiated_fraction,
    radiation_integrals,
)
from restitution.quasistatic.hertz_sphere import (
    SPHERE_MASS,
    sphere_contact_law,
    sphere_quasistatic_trajectory,
)

NU = 0.3
STEEL_ON_STEEL = {
    "mass": SPHERE_MASS,
    "radius": 1.0,
    "e_star": 1.0 / (2.0 * (1.0 - NU**2)),
    "wall_density": 1.0,
    "wall_shear_speed": math.sqrt(1.0 / (2.0 * (1.0 + NU))),
    "wall_nu": NU,
}


def test_rayleigh_speed_and_share_at_a_quarter():
    """At nu = 1/4, c_R / c_T = sqrt(2 - 2/sqrt(3)) exactly, and Miller and Pursey's Rayleigh
    share of a vertical point force is 67.4 % (measured 67.36 %)."""
    r = radiation_integrals(0.25)
    assert r.rayleigh_speed == pytest.approx(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), rel=1e-10)
    assert r.rayleigh_share == pytest.approx(0.674, abs=0.001)
    # the compressional and shear part holds the P waves' 6.9 %, the rest is shear alone
    assert r.body_both / r.total > 0.069


def test_hertz_pulse_integral_matches_the_trajectory():
    """(9/5) B(4/5, 3/2) K^2 delta^2 v against int (dP/dt)^2 dt of the closed-form trajectory,
    differentiated by central differences and integrated by quadrature (measured 3e-11)."""
    law = sphere_contact_law(NU)
    v = 1e-3
    tr = sphere_quasistatic_trajectory(law, v)
    tau = tr.contact_time
    h = 1e-6 * tau

    def rate2(t):
        return ((tr.force(t + h) - tr.force(t - h)) / (2 * h)) ** 2

    numeric = 2 * quad(lambda t: float(rate2(t)), h, 0.5 * tau, limit=400, epsrel=1e-10)[0]
    closed = HERTZ_PULSE_FACTOR * law.K**2 * tr.max_compression**2 * v
    assert numeric == pytest.approx(closed, rel=1e-8)


def test_the_time_formula_is_the_frequency_integral_of_the_pulse():
    """E_rad = I / (2 pi rho c_T^3) int (dP/dt)^2 dt against (1/pi) int |P(w)|^2 w Im G dw with
    the spectrum of the sampled pulse (Parseval; measured 6e-11)."""
    law = sphere_contact_law(NU)
    v = 1e-3
    tr = sphere_quasistatic_trajectory(law, v)
    n = 1 << 16
    t = np.linspace(0.0, tr.contact_time, n)
    dt = t[1] - t[0]
    spectrum = np.fft.rfft(tr.force(t), n=8 * n) * dt
    omega = 2 * math.pi * np.fft.rfftfreq(8 * n, dt)
    rho, c_t = STEEL_ON_STEEL["wall_density"], STEEL_ON_STEEL["wall_shear_speed"]
    integral = radiation_integrals(NU).total
    conductance = integral / (2.0 * math.pi * rho * c_t**3)
    # omega Im G(omega) = conductance * omega^2 (module docs)
    freq = np.trapezoid(np.abs(spectrum) ** 2 * omega**2, omega) / math.pi * conductance
    time = conductance * HERTZ_PULSE_FACTOR * law.K**2 * tr.max_compression**2 * v
    assert freq == pytest.approx(time, rel=1e-8)


def test_the_fraction_grows_like_the_three_fifths_power_of_the_speed():
    """E_rad / E_kin = C (v/c)^(3/5) exactly; for a steel ball on a steel half-space C = 1.132
    (the (v/c)^(3/5) law of Hunter 1957 and Reed 1985, c = sqrt(E/rho))."""
    a = radiated_fraction(1e-5, **STEEL_ON_STEEL)
    b = radiated_fraction(1e-3, **STEEL_ON_STEEL)
    assert b / a == pytest.approx(100**0.6, rel=1e-12)
    assert a / 1e-5**0.6 == pytest.approx(1.1318, rel=1e-4)
    # a 5 mm steel ball at 1 m/s: about a hundred times its own vibrations' 5e-5
    assert 100 < radiated_fraction(1.0 / 5172.19, **STEEL_ON_STEEL) / 5e-5 < 150
