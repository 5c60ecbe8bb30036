"""The compiled path of the collision: members run by the numba kernel
(:mod:`restitution.dynamics.kernel`), its results mapped onto :class:`~restitution.dynamics.run.
MemberRun`.

Units: ``E = rho = R = 1``; times in ``R / c``.
"""

from __future__ import annotations

import numpy as np

from restitution.bodies.viscoelastic import mode_damping
from restitution.dynamics.contact.base import ContactLaw
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL
from restitution.dynamics.integrators import INTEGRATORS
from restitution.dynamics.run import (
    UNSTABLE,
    CollisionError,
    MemberRun,
    contact_mean,
    timeout_message,
)
from restitution.dynamics.settings import CONTACT_TOL, STOP_LOG, CollisionSettings
from restitution.dynamics.start import start_of
from restitution.errors import InputError

__all__ = ["KERNEL_WEIGHTS", "run_kernel", "use_kernel"]

# Strang steps composing one step of each splitting that the compiled kernel runs.
KERNEL_WEIGHTS = {name: INTEGRATORS[name].weights for name in ("split", "split4")}


def use_kernel(settings: CollisionSettings, contact_law: ContactLaw = EXPONENTIAL_WALL) -> bool:
    """Whether the compiled kernel runs this setting (splittings, no recorded history, a contact
    law with a compiled branch)."""
    if settings.backend == "numpy":
        return False
    supported = settings.integrator in KERNEL_WEIGHTS and not settings.record
    if settings.backend == "compiled" and not supported:
        raise InputError(
            f"the compiled backend runs the integrators {sorted(KERNEL_WEIGHTS)} without "
            "recorded histories; use backend='numpy' (or 'auto') for "
            f"integrator={settings.integrator!r}, record={settings.record}"
        )
    if contact_law.kernel is None:
        if settings.backend == "compiled":
            raise InputError(
                f"the contact law {contact_law.name!r} has no branch in the compiled kernel; "
                "use backend='numpy' (or 'auto', which picks it)"
            )
        return False
    return supported


def run_kernel(
    body, v, alpha, dts, settings, quad, abort, initial, contact_law=EXPONENTIAL_WALL
) -> list[MemberRun | str]:
    """Run members on the compiled kernel; a dict per finished member, else ``"unstable"``."""
    from restitution.dynamics.kernel import KERNEL_LAWS, STATUS_OK, STATUS_TIMEOUT, run_batch

    if contact_law.kernel not in KERNEL_LAWS:
        raise InputError(
            f"the contact law {contact_law.name!r} names the kernel branch "
            f"{contact_law.kernel!r}, which the compiled kernel lacks (it has "
            f"{sorted(KERNEL_LAWS)}); set its kernel to None or use backend='numpy'"
        )
    m = body.mass
    e0 = 0.5 * m * v**2
    begin = start_of(body, v, alpha, quad, initial, contact_law)
    got = run_batch(
        body.omega,
        m,
        quad,
        v,
        alpha,
        begin.x0,
        dts,
        begin.t_max,
        KERNEL_WEIGHTS[settings.integrator],
        settings.max_steps,
        abort,
        STOP_LOG,
        CONTACT_TOL,
        begin.Q,
        begin.P,
        mode_damping(body),
        None,  # stop: a flag of the kernel's own
        KERNEL_LAWS[contact_law.kernel],
        np.asarray(contact_law.kernel_parameters(), dtype=float),
    )
    out: list[MemberRun | str] = []
    for i in range(v.size):
        status = got["status"][i]
        if status == STATUS_TIMEOUT:
            raise CollisionError(
                timeout_message(got["t_end"][i], got["steps"][i], dts[i], settings)
            )
        if status != STATUS_OK:
            if abort is None:
                raise CollisionError(
                    f"the integration overflowed at t = {got['t_end'][i]:.3g} with "
                    f"dt = {dts[i]:.3g}; the step is far too large for this wall hardness: "
                    "reduce dt"
                )
            out.append(UNSTABLE)
            continue
        contact = got["contact_time"][i]
        summed = got["energy_sum"][i]
        out.append(
            MemberRun(
                epsilon=float(got["epsilon"][i]),
                energy_after=got["energy"][i] / e0[i],
                steps=int(got["steps"][i]),
                t_end=float(got["t_end"][i] - begin.lead[i]),
                final_Q=got["final_Q"][i],
                final_P=got["final_P"][i],
                final_x0=float(got["final_x0"][i]),
                drift=float(got["drift"][i]),
                contact_time=float(contact),
                max_compression=float(got["max_compression"][i]),
                max_force=float(got["max_force"][i]),
                energy_mean=contact_mean(summed, contact, e0[i]),
                energy_closest=got["energy_closest"][i] / e0[i],
                dissipated=float(got["dissipated"][i] / e0[i]),
            )
        )
    return out
