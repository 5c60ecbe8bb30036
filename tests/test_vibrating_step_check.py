"""One step control for every path: a vibrating disk's step is judged by epsilon, as the plain
collision's (issue "one step control for every path", docs/vibrating.md).

Independent checks: a zero excitation (zero temperature, zero amplitude, the first collision of
a chain from rest) is the plain collision of ``restitution collide``, for the disk and the
sphere, from the library and from the command line; a thermal collision's epsilon converges as
the tolerance falls, against fixed-step runs that no judge chose.
"""

import json

import numpy as np
import pytest

from restitution import get_modes
from restitution.dynamics.collision import collide
from restitution.errors import InputError
from restitution.vibrating.ensemble import (
    collide_states,
    phase_scan,
    temperature_for,
    thermal_ensemble,
)
from restitution.vibrating.sequences import JUDGE_WORK, bounce, check_collisions_time
from restitution.vibrating.vibration import thermal_state

V, ALPHA, N = 0.05, 500.0, 12


@pytest.mark.parametrize(("geometry", "nu"), [("disk", 0.33), ("sphere", 0.3)])
def test_zero_excitation_is_the_plain_collision(geometry, nu):
    body = get_modes(nu, count=N, geometry=geometry)
    plain = collide(body, V, ALPHA, step_judge="epsilon")  # what `restitution collide` runs
    cold = thermal_ensemble(body, V, ALPHA, 0.0, 2, seed=1)
    silent = phase_scan(body, V, ALPHA, 0, 0.0, [0.0, 2.0])
    chain = bounce(body, V, ALPHA, 1, gravity=1e-5)
    got = np.concatenate([cold.epsilon, silent, chain.epsilon])
    # Measured: equal here. A batch of two or more zero states can differ from the disk at rest
    # in the last bits (9e-16 at N = 20, with either judge; the batch's kernel path).
    np.testing.assert_allclose(got, plain.epsilon, rtol=0, atol=1e-9)
    assert np.all(cold.mode_energy_before == 0)
    # The drift alone, the judge these paths used before, misses by far more (measured 1.3e-6
    # for the disk, 4.0e-6 for the sphere): the check above has the power to see the old path.
    drift_judged = thermal_ensemble(body, V, ALPHA, 0.0, 1, seed=1, step_judge="energy")
    assert abs(drift_judged.epsilon[0] - plain.epsilon) > 1e-8


def _cli_epsilon(cli, *args) -> tuple[float, dict]:
    code, out, err = cli("collide", "--nu", "0.33", "--v", str(V), "--alpha", str(ALPHA),
                         "--modes", str(N), *args, "--json")  # fmt: skip
    assert code == 0, err
    d = json.loads(out)
    return (d["mean"] if "mean" in d else d["epsilon"]), d


def test_zero_excitation_on_the_command_line_is_the_plain_collision(cli):
    plain, _ = _cli_epsilon(cli)
    cold, d = _cli_epsilon(cli, "--excite", "thermal", "--temperature", "0", "--samples", "2")
    assert d["inputs"]["step_check"] == "epsilon"
    silent, _ = _cli_epsilon(cli, "--excite", "mode", "--amplitude", "0")
    assert cold == pytest.approx(plain, rel=0, abs=1e-9)
    assert silent == pytest.approx(plain, rel=0, abs=1e-9)
    # --step-check energy is the drift alone on every path.
    drift, d = _cli_epsilon(cli, "--excite", "thermal", "--temperature", "0", "--step-check",
                            "energy")  # fmt: skip
    assert d["inputs"]["step_check"] == "energy"
    assert drift == collide(get_modes(0.33, count=N), V, ALPHA, step_judge="energy").epsilon


@pytest.mark.slow  # 4 s of the default run (stop 79: the default run under 10 min)
def test_thermal_epsilon_converges_under_the_step_check():
    """The judge holds epsilon's Richardson error to energy_tol / 2 (docs/numerics.md)."""
    modes = get_modes(0.33, count=10)
    v, alpha = 0.1, 500.0
    Q, P = thermal_state(modes, temperature_for(modes, v, 2.0), np.random.default_rng(7), size=4)
    # Independent reference: fixed steps, no judge. Measured: dt = 2.5e-4 is within 2e-9 of
    # dt = 1.25e-4 on these four states.
    ref = np.array([r.epsilon for r in collide_states(modes, v, alpha, Q, P, dt=2.5e-4)])
    tols = np.array([1e-5, 1e-6, 5e-7, 1e-7])
    eps = {}
    for tol in tols:
        runs = collide_states(modes, v, alpha, Q, P, energy_tol=tol)
        assert all(0 < r.step_error <= tol / 2 for r in runs)
        eps[tol] = np.array([r.epsilon for r in runs])
        # Measured: 0.53, 0.52, 0.52, 0.52 of tol / 2 for the worst of the four.
        assert np.abs(eps[tol] - ref).max() <= tol / 2
    # Halving the tolerance moves epsilon by less than the bound the tolerance states.
    assert np.abs(eps[1e-6] - eps[5e-7]).max() < 1e-6 / 2
    # The error falls like the tolerance (the step aims at half of it): fitted order 1.01.
    errors = [np.abs(eps[tol] - ref).max() for tol in tols]
    assert np.polyfit(np.log(tols), np.log(errors), 1)[0] == pytest.approx(1.0, abs=0.15)


def test_the_time_estimate_counts_the_judge():
    modes = get_modes(0.33, count=N)
    energy = check_collisions_time(modes, V, ALPHA, 2, step_judge="energy")
    # The epsilon judge's reruns at half the step are counted (measured 1.1-6.1 times the steps).
    judged = check_collisions_time(modes, V, ALPHA, 2)
    assert judged == pytest.approx(JUDGE_WORK["epsilon"] * energy)
    with pytest.raises(InputError, match="step_judge must be one of"):
        check_collisions_time(modes, V, ALPHA, 2, step_judge="drift")
