"""Result types shared by the collision solvers (modal and finite-element).

Units: lengths in ``R``, times in ``R / c``, velocities in ``c``, forces in ``E`` (2D Young
modulus times length / length), energies as fractions of the initial kinetic energy
``(m/2) v_i^2`` unless stated otherwise.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.status import Status

__all__ = ["UNITS", "CollisionResult", "History"]

UNITS: dict[str, str] = body_kind(DEFAULT_GEOMETRY).units
"""The units of every number this package reports of a disk; every JSON output carries the
table of its body (:attr:`restitution.bodies.kinds.BodyKind.units`)."""


@dataclass(frozen=True, eq=False)
class History:
    """Time histories of one collision, sampled every ``stride`` steps.

    Attributes
    ----------
    t : numpy.ndarray, shape (T,)
        Time in ``R / c``.
    x0, v : numpy.ndarray, shape (T,)
        Centre-of-mass position (the wall is at ``x = 0``; touching at ``x0 = -1``) and velocity
        towards the wall, in ``R`` and ``c``.
    force : numpy.ndarray, shape (T,)
        Total wall force on the disk (pushing it away from the wall), in ``E``.
    mode_energy : numpy.ndarray, shape (T, N)
        Energy of every mode, fraction of the initial kinetic energy (empty for FEM).
    Q : numpy.ndarray, shape (T, N)
        Modal coordinates (empty for FEM); with the mode set they give the edge shape.
    """

    t: np.ndarray
    x0: np.ndarray
    v: np.ndarray
    force: np.ndarray
    mode_energy: np.ndarray
    Q: np.ndarray


@dataclass(frozen=True, eq=False)
class CollisionResult:
    """Outcome of one disk-wall collision.

    Attributes
    ----------
    method : str
        ``"modal"`` or ``"fem"``.
    nu, v, alpha : float
        Poisson number, incoming speed towards the wall (units of ``c``) and wall hardness
        (``1 / R``) of the potential ``V = (1/alpha) int exp(alpha x(phi)) dphi``.
    n_modes : int
        Number of modes (0 for FEM).
    epsilon : float
        Coefficient of restitution ``-v_f / v_i`` of the centre of mass.
    energy_drift : float
        Largest relative deviation of the total energy from its initial value during the run.
    contact_time : float
        Time during which the centre is closer than ``R`` to the wall (``x0 > -1``), ``R / c``.
    max_compression : float
        Largest ``x0 + 1``, in ``R``.
    max_force : float
        Largest total wall force, in ``E``.
    n_steps : int
        Time steps taken (of the accepted run).
    dt : float
        Step size of the accepted run, ``R / c``.
    wall_time_s : float
        Wall-clock time of the computation, seconds.
    integrator : str
        Name of the time integrator.
    mode_n, mode_l : numpy.ndarray of int, shape (N,)
        Mode labels as the body's mode records name them (empty for FEM): ``n`` and ``l`` of the
        disk (order, root index), of the sphere (radial index, order).
    mode_order : numpy.ndarray of int, shape (N,)
        The angular order of every mode, whatever the body calls it (the one name for it).
    mode_energy_after, mode_energy_mean, mode_energy_closest : numpy.ndarray, shape (N,)
        Energy per mode after the collision, averaged over the contact (``x0 > -1``), and at
        closest approach (largest ``x0``); fractions of the initial kinetic energy.
    history : History or None
        Time histories when requested.
    energy_tol : float or None
        The drift the run had to meet (``None``: not checked against a tolerance).
    mode_energy_before : numpy.ndarray, shape (N,)
        Energy per mode at the start (zero for a disk at rest), fraction of ``(m/2) v^2``.
    final_Q, final_P : numpy.ndarray, shape (N,)
        Modal coordinates (``R``) and momenta (``m c``) where the run stopped (modal only):
        with ``final_x0`` and ``-epsilon v`` the state from which a later collision continues.
    final_x0 : float
        Centre position where the run stopped, ``R`` (``nan`` when not recorded).
    t_end : float
        Time from the moment the centre passed the start position to the stop, ``R / c``.
    relaxation_time : float
        ``tau`` of a viscoelastic body (:class:`restitution.bodies.viscoelastic.Viscoelastic`),
        ``R / c``; ``0`` for an elastic one.
    energy_dissipated : float
        Energy the material's damping took up to the stop, fraction of the initial kinetic
        energy (``0`` for an elastic body): ``1 - epsilon^2`` minus the vibration energy after
        (a damped body starts at rest; :mod:`restitution.dynamics.collision` says why the
        balance and not the sum of the flows' losses).
    step_error : float or None
        A viscoelastic body's step is judged by epsilon, not by the energy drift: the
        Richardson estimate ``|eps(dt) - eps(dt/2)| / 3`` of the error of the reported epsilon
        (run with ``dt/2``), held below ``energy_tol / 2``; ``None`` for an elastic body (and
        a fixed step). Its ``energy_drift`` includes the energy the splitting's kicks give to
        damped modes and is reported, not checked (docs/damping.md).
    """

    method: str
    nu: float
    v: float
    alpha: float
    n_modes: int
    epsilon: float
    energy_drift: float
    contact_time: float
    max_compression: float
    max_force: float
    n_steps: int
    dt: float
    wall_time_s: float
    integrator: str
    mode_n: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    mode_l: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    mode_order: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    mode_energy_after: np.ndarray = field(default_factory=lambda: np.zeros(0))
    mode_energy_mean: np.ndarray = field(default_factory=lambda: np.zeros(0))
    mode_energy_closest: np.ndarray = field(default_factory=lambda: np.zeros(0))
    history: History | None = None
    energy_tol: float | None = None
    mode_energy_before: np.ndarray = field(default_factory=lambda: np.zeros(0))
    final_Q: np.ndarray = field(default_factory=lambda: np.zeros(0))
    final_P: np.ndarray = field(default_factory=lambda: np.zeros(0))
    final_x0: float = float("nan")
    t_end: float = float("nan")
    relaxation_time: float = 0.0
    energy_dissipated: float = 0.0
    step_error: float | None = None

    @property
    def status(self) -> Status:
        """``ok``, ``drift-exceeded`` (a fixed step broke ``energy_tol``) or ``not-finite``
        (:class:`restitution.status.Status`); :attr:`advice` says what to do."""
        if not math.isfinite(self.epsilon) or not math.isfinite(self.energy_drift):
            return Status.NOT_FINITE
        if self.energy_tol is not None and self.energy_drift > self.energy_tol:
            return Status.DRIFT_EXCEEDED
        return Status.OK

    @property
    def advice(self) -> str | None:
        """What to change when :attr:`status` is not ``ok``; ``None`` when it is."""
        if self.status == Status.DRIFT_EXCEEDED:
            return (
                f"energy drift {self.energy_drift:.2g} exceeds energy_tol = "
                f"{self.energy_tol:.2g}: epsilon may be off by about the drift; use a smaller "
                "fixed dt, or dt=None to choose and refine the step automatically"
            )
        if self.status == Status.NOT_FINITE:
            return "the run produced no finite epsilon; use a smaller step"
        return None

    @property
    def energy_loss(self) -> float:
        """``1 - epsilon^2``: the fraction of kinetic energy lost: left in vibrations and, for a
        viscoelastic body, dissipated (:attr:`energy_dissipated`)."""
        return 1.0 - self.epsilon**2

    def to_dict(self, *, modes: bool = True) -> dict:
        """JSON-ready dictionary (histories are omitted)."""
        skip = ("history", "final_Q", "final_P")
        d = {k: v for k, v in asdict(self).items() if k not in skip and not k.startswith("mode_")}
        d["vibration_energy_before"] = float(np.sum(self.mode_energy_before))
        d["vibration_energy_after"] = float(np.sum(self.mode_energy_after))
        d["energy_loss"] = self.energy_loss
        d["status"] = self.status
        d["advice"] = self.advice
        if modes:
            order = self.mode_order if self.mode_order.size == self.mode_n.size else None
            d["mode_energies_after"] = [
                {
                    **({} if order is None else {"order": int(order[i])}),
                    "n": int(n),
                    "l": int(l),
                    "energy": float(e),
                }
                for i, (n, l, e) in enumerate(
                    zip(self.mode_n, self.mode_l, self.mode_energy_after, strict=True)
                )
            ]
        return d
