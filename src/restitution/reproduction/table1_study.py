"""Table 1 under the protocols the paper could have used (issue 65, item 4): the collisions and
the energies read off them. Scoring against the paper and the paper's own consistency are in
:mod:`restitution.reproduction.table1_scores`; the write-up is docs/table1.md.

Units: ``E = rho = R = 1`` (two-dimensional constants), speeds in ``c = sqrt(E/rho)``, times in
``R / c``, ``alpha`` in ``1 / R``; every energy is a fraction of the initial kinetic energy
``E0 = (m/2) v^2`` unless a reading normalises it by the vibrational energy.

A **protocol** is a :class:`Setup` (what collides: the paper's ``v_i = 0.1`` read in ``c``,
``c_L``, ``c_T`` or as a relative speed; the wall stiffness ``alpha``; which modes are kept and
how the breathing modes are normalised; the Poisson number; the edge quadrature) and a
:class:`Reading` (how a mode's energy is taken off that collision: the averaging window, the
normalisation, where "after" is taken, and whether modes are counted one by one or by their
(n, l) label within the radial or tangential class, partners summed). A setup costs one recorded
collision (about 0.5-2 s at 1600 modes); a reading costs nothing more. :class:`Study` keeps every
collision of one run in memory.

Speed readings (:data:`SPEED_READINGS`), ``v_i`` the paper's number:

* ``c``: ``v = v_i`` (the paper's stated unit);
* ``c_L``: ``v = v_i / sqrt(1 - nu^2)``, the plane-stress dilatational speed, the unit that
  reproduces Fig. 1's "epsilon ~ 0.65" (docs/results.md). It is also what a code does that uses
  ``kappa`` for ``omega`` in eq. (18): scaling time by ``sqrt(1 - nu^2)`` maps that code onto this
  one at speed ``v_i / sqrt(1 - nu^2)`` with the wall's amplitude changed, which only shifts the
  wall (``A exp(alpha x) = exp(alpha (x + ln A / alpha))``), so ``alpha`` stays;
* ``c_T``: ``v = v_i sqrt(mu / E) = v_i / sqrt(2 (1 + nu))``, speeds in the shear speed (a code
  with ``mu = 1``);
* ``relative``: ``v = v_i / 2``, the Fig. 1 caption's "initial relative velocity" of two disks.

Windows of the "average energy" (:data:`WINDOWS`): ``contact`` (centre closer than ``R``,
``x0 > -1``: the package's Table 1), ``force`` (wall force above 1 % of its peak), ``run`` (the
whole integration, from wall energy ``1e-12 E0`` before to after), ``closest`` (the instant of
closest approach, Fig. 6's protocol), and ``contact xk`` (from the start of contact over ``k``
contact times, the free flight after it included). Normalisations (:data:`NORMS`): ``E0``,
``vib`` (the time average of the mode's share ``E_k(t) / sum_j E_j(t)`` of the vibrational energy)
and ``vib-mean`` (its mean over the mean vibrational energy). "After" (:data:`AFTERS`): at the end
of the run (free flight: each mode's energy is constant from there on, so any window after the
contact gives the same) or at separation (the centre back at ``x0 = -1``), normalised as the mean
(``E0``, or the vibrational energy at that time).

Counting (:data:`COUNTS`): ``mode``, every mode by its (n, l), ``l`` the root index within
``n`` (this package's labels); ``class``, ``l`` counted within the radial (``|C| >= |S|``) and
the tangential modes of one ``n`` separately (section 2.2's two classes) and the two partners of
one (n, l) summed. The other degenerate partner of every mode, ``u_r ~ sin(n phi)``, takes no
energy in a head-on impact (its coupling to the symmetric wall force vanishes), so summing it
changes nothing; "1600 modes" counting those partners is the setup with the 800 lowest
symmetric modes.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field

import numpy as np

from restitution.bodies.cache import get_modes
from restitution.dynamics.collision import collide, rank_modes
from restitution.errors import InputError
from restitution.reproduction.figures.table1 import PAPER

__all__ = [
    "AFTERS",
    "COUNTS",
    "NORMS",
    "PAPER",
    "PAPER_READING",
    "PAPER_SETUP",
    "SPEED_READINGS",
    "WINDOWS",
    "Energies",
    "ModeChoice",
    "ModeTable",
    "Reading",
    "Setup",
    "Study",
    "interval_mean",
    "mode_table",
]

SPEED_READINGS = {
    "c": lambda v, nu: v,
    "c_L": lambda v, nu: v / math.sqrt(1.0 - nu * nu),
    "c_T": lambda v, nu: v / math.sqrt(2.0 * (1.0 + nu)),
    "relative": lambda v, nu: v / 2.0,
}
"""The paper's speed ``v_i`` (its unit) -> our speed towards the wall in ``c``."""

EXTENDED = (1.4, 2.0, 3.0)
"""Window lengths, in contact times, of the ``contact xk`` windows."""

WINDOWS = ("contact", "force", "run", "closest", *(f"contact x{k:g}" for k in EXTENDED))
NORMS = ("E0", "vib", "vib-mean")
AFTERS = ("end", "separation")
COUNTS = ("mode", "class")

FORCE_FRACTION = 0.01
"""The ``force`` window: wall force above this fraction of its peak."""

RECORD_INTERVAL = 0.005
"""History sampling, ``R / c``; windows are integrated on the linear interpolant (edges
interpolated), within 1e-3 of the kernel's own contact mean at 1600 modes."""

RECTANGLE = 40
"""Section 4 integrates "a given set (n <= n_max, l <= l_max)": 40 x 40 = 1600 modes."""


@dataclass(frozen=True)
class ModeChoice:
    """Which modes a collision keeps.

    Attributes
    ----------
    rule : {"lowest", "ranked", "rectangle"}
        ``lowest``: the ``count`` lowest frequencies; ``ranked``: the ``count`` modes with the
        most contact-averaged energy in a preliminary run of the ``pool`` lowest (section 4);
        ``rectangle``: ``n, l < RECTANGLE`` (section 4's ``n <= n_max, l <= l_max``).
    count, pool : int
    breathing_norm : float
        ``int_0^1 r U_r^2 dr`` of the ``n = 0`` modes: 1/2 (ERRATA), or 1 (eq. 26 read with
        ``int cos^2(0 phi) dphi = pi``, which scales their edge amplitudes by ``sqrt(2)``).
    """

    rule: str = "lowest"
    count: int = 1600
    pool: int = 3200
    breathing_norm: float = 0.5

    @property
    def label(self) -> str:
        text = {
            "lowest": f"{self.count} lowest",
            "ranked": f"{self.count} ranked of {self.pool}",
            "rectangle": f"n, l < {RECTANGLE}",
        }[self.rule]
        if self.breathing_norm != 0.5:
            text += f", int r U^2 = {self.breathing_norm:g} for n = 0"
        return text


@dataclass(frozen=True)
class Setup:
    """One collision: what the paper's "alpha = 500, v_i = 0.1c using 1600 modes" could mean.

    Attributes
    ----------
    reading : str
        Unit of the paper's speed, a key of :data:`SPEED_READINGS`.
    alpha : float
        Wall stiffness, ``1 / R``.
    modes : ModeChoice
    nu : float
        Two-dimensional Poisson number (the caption of Table 1 gives none; the text: "most of
        our data" at 0.33).
    v_i : float
        The paper's speed in its unit.
    n_phi : int or None
        Edge nodes on the quadrant (the paper: 256); ``None``: the contact law's choice.
    """

    reading: str = "c"
    alpha: float = 500.0
    modes: ModeChoice = field(default_factory=ModeChoice)
    nu: float = 0.33
    v_i: float = 0.1
    n_phi: int | None = None

    @property
    def v(self) -> float:
        """Speed towards the wall, ``c``."""
        return float(SPEED_READINGS[self.reading](self.v_i, self.nu))

    @property
    def label(self) -> str:
        text = f"v = {self.v_i:g} {self.reading} ({self.v:.4g} c), alpha = {self.alpha:g}, "
        text += self.modes.label
        if self.nu != 0.33:
            text += f", nu = {self.nu:g}"
        if self.n_phi is not None:
            text += f", {self.n_phi} edge nodes"
        return text


@dataclass(frozen=True)
class Reading:
    """How a mode's energy is read off a collision (module docstring)."""

    window: str = "contact"
    norm: str = "E0"
    after: str = "end"
    count: str = "mode"

    @property
    def label(self) -> str:
        return f"{self.window} / {self.norm} / after at {self.after} / by {self.count}"


PAPER_SETUP = Setup()
"""The paper's words read literally: ``v = 0.1 c``, ``alpha = 500``, the 1600 lowest modes."""

PAPER_READING = Reading()
"""This package's Table 1 (:mod:`restitution.reproduction.figures.table1`)."""


@dataclass(frozen=True, eq=False)
class Energies:
    """Every number a reading needs from one collision; the history is not kept.

    Attributes
    ----------
    setup : Setup
    n, l, l_class : numpy.ndarray of int, shape (N,)
        Labels; ``l_class`` counts within the mode's class (radial ``|C| >= |S|`` or tangential).
    radial : numpy.ndarray of bool, shape (N,)
    omega, C : numpy.ndarray, shape (N,)
        Frequency (``c / R``) and edge radial amplitude of eq. (28).
    epsilon, contact_time : float
        Coefficient of restitution; time with ``x0 > -1`` (``R / c``).
    mean, share : dict of str to numpy.ndarray, shape (N,)
        Per window: the mean energy (fraction of ``E0``) and the mean share of the vibrational
        energy.
    vib_mean : dict of str to float
        Per window: the mean vibrational energy, fraction of ``E0``.
    after : dict of str to numpy.ndarray, shape (N,)
        ``"end"`` and ``"separation"``: energy per mode, fraction of ``E0``.
    windows : dict of str to (float, float)
        ``[a, b]`` of every window but ``closest``, ``R / c``.
    t, force : numpy.ndarray, shape (T,)
        The recorded times (``R / c``) and total wall force (``E``, pushing the body away).
    mass : float
        The body's mass, ``rho R^2``.
    seconds : float
        Wall time of the collision(s) behind it.
    """

    setup: Setup
    n: np.ndarray
    l: np.ndarray
    l_class: np.ndarray
    radial: np.ndarray
    omega: np.ndarray
    C: np.ndarray
    epsilon: float
    contact_time: float
    mean: dict
    share: dict
    vib_mean: dict
    after: dict
    windows: dict
    t: np.ndarray
    force: np.ndarray
    mass: float
    seconds: float

    @property
    def loss(self) -> float:
        """``1 - epsilon^2``: the energy left in the modes, fraction of ``E0``."""
        return 1.0 - self.epsilon**2


@dataclass(frozen=True, eq=False)
class ModeTable:
    """Every label's mean and after energy under one protocol, ranked by the mean.

    Attributes
    ----------
    setup : Setup
    reading : Reading
    labels : list of (int, int)
        ``(n, l)`` in descending order of ``mean``.
    mean, after : numpy.ndarray, shape (K,)
    epsilon : float
    """

    setup: Setup
    reading: Reading
    labels: list
    mean: np.ndarray
    after: np.ndarray
    epsilon: float

    def lookup(self) -> dict:
        """``(n, l) -> (rank from 1, mean, after)``."""
        return {
            lab: (i + 1, float(self.mean[i]), float(self.after[i]))
            for i, lab in enumerate(self.labels)
        }


def _class_index(n: np.ndarray, radial: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Root index of every mode within its order and class, by frequency."""
    out = np.zeros(n.size, dtype=int)
    for key in set(zip(n.tolist(), radial.tolist(), strict=True)):
        members = np.nonzero((n == key[0]) & (radial == key[1]))[0]
        out[members[np.argsort(omega[members], kind="stable")]] = np.arange(members.size)
    return out


def _rows_at(t: np.ndarray, e: np.ndarray, when: float) -> np.ndarray:
    """Linear interpolation of the rows of ``e`` (shape (T, N)) at time ``when``; the last row
    beyond the end (free flight keeps every mode's energy)."""
    if when >= t[-1]:
        return e[-1]
    if when <= t[0]:
        return e[0]
    k = int(np.searchsorted(t, when))
    w = (when - t[k - 1]) / (t[k] - t[k - 1])
    return (1.0 - w) * e[k - 1] + w * e[k]


def interval_mean(t: np.ndarray, e: np.ndarray, a: float, b: float) -> np.ndarray:
    """Mean over ``[a, b]`` of the piecewise-linear interpolant of ``e`` (shape (T, N)),
    continued by its last row after ``t[-1]``."""
    inside = (t > a) & (t < min(b, t[-1]))
    tt = np.concatenate([[a], t[inside], [min(b, t[-1])]])
    ee = np.vstack([_rows_at(t, e, a), e[inside], _rows_at(t, e, min(b, t[-1]))])
    total = np.trapezoid(ee, tt, axis=0)
    if b > t[-1]:
        total = total + (b - t[-1]) * e[-1]
    return total / (b - a)


def _crossings(t: np.ndarray, y: np.ndarray, level: float) -> tuple[float, float]:
    """First upward and last downward crossing of ``level`` by ``y(t)``, interpolated."""
    above = np.nonzero(y > level)[0]
    i, j = int(above[0]), int(above[-1])

    def at(k0, k1):
        return float(t[k0] + (level - y[k0]) * (t[k1] - t[k0]) / (y[k1] - y[k0]))

    first = at(i - 1, i) if i > 0 else float(t[0])
    last = at(j, j + 1) if j + 1 < t.size else float(t[-1])
    return first, last


def _windows(t, x0, force) -> dict:
    """``[a, b]`` of every window but ``closest`` (times in ``R / c``)."""
    start, end = _crossings(t, x0, -1.0)
    out = {
        "contact": (start, end),
        "force": _crossings(t, force, FORCE_FRACTION * float(force.max())),
        "run": (float(t[0]), float(t[-1])),
    }
    for k in EXTENDED:
        out[f"contact x{k:g}"] = (start, start + k * (end - start))
    return out


def _measure(setup: Setup, body, seconds: float) -> Energies:
    """Run the recorded collision and reduce its history to :class:`Energies`."""
    t0 = time.perf_counter()
    overrides = {} if setup.n_phi is None else {"n_phi": setup.n_phi}
    r = collide(
        body, setup.v, setup.alpha, record=True, record_interval=RECORD_INTERVAL, **overrides
    )
    h = r.history
    e = h.mode_energy
    vib = e.sum(axis=1)
    share = e / np.where(vib > 0.0, vib, 1.0)[:, None]
    mean, shares, vib_mean = {}, {}, {}
    windows = _windows(h.t, h.x0, h.force)
    for name, (a, b) in windows.items():
        mean[name] = interval_mean(h.t, e, a, b)
        shares[name] = interval_mean(h.t, share, a, b)
        vib_mean[name] = float(mean[name].sum())
    closest = np.asarray(r.mode_energy_closest)
    mean["closest"] = closest
    shares["closest"] = closest / closest.sum()
    vib_mean["closest"] = float(closest.sum())
    _, leave = _crossings(h.t, h.x0, -1.0)
    after = {"end": np.asarray(r.mode_energy_after), "separation": _rows_at(h.t, e, leave)}
    radial = np.abs(body.C) >= np.abs(body.S)
    return Energies(
        setup=setup,
        n=np.asarray(body.n),
        l=np.asarray(body.l),
        l_class=_class_index(np.asarray(body.n), radial, np.asarray(body.omega)),
        radial=radial,
        omega=np.asarray(body.omega),
        C=np.asarray(body.C),
        epsilon=float(r.epsilon),
        contact_time=float(r.contact_time),
        mean=mean,
        share=shares,
        vib_mean=vib_mean,
        after=after,
        windows=windows,
        t=np.asarray(h.t),
        force=np.asarray(h.force),
        mass=float(body.mass),
        seconds=seconds + time.perf_counter() - t0,
    )


class Study:
    """The collisions of one study run, each computed once (in memory, never on disk)."""

    def __init__(self) -> None:
        self._energies: dict[Setup, Energies] = {}
        self._pools: dict = {}

    def _pool(self, nu: float, count: int):
        key = (nu, count)
        if key not in self._pools:
            self._pools[key] = get_modes(nu, count=count)
        return self._pools[key]

    def _rectangle(self, nu: float):
        key = (nu, "rectangle")
        if key not in self._pools:
            # omega <= 140 holds every n, l < 40 at nu = 0.33; a larger nu may need more.
            for omega_max in (140.0, 210.0, 315.0):
                big = get_modes(nu, omega_max=omega_max)
                keep = (big.n < RECTANGLE) & (big.l < RECTANGLE)
                if int(keep.sum()) == RECTANGLE**2:
                    break
            else:
                raise InputError(
                    f"the modes n, l < {RECTANGLE} at nu = {nu:g} lie above omega = 315; use "
                    "another mode rule"
                )
            self._pools[key] = big.take(np.nonzero(keep)[0])
        return self._pools[key]

    def body(self, setup: Setup):
        """The modes of ``setup`` (its breathing normalisation applied)."""
        m = setup.modes
        if m.rule == "lowest":
            body = self._pool(setup.nu, m.count)
        elif m.rule == "ranked":
            body = rank_modes(self._pool(setup.nu, m.pool), m.count, setup.v, setup.alpha)
        elif m.rule == "rectangle":
            body = self._rectangle(setup.nu)
        else:
            raise InputError(f"unknown mode rule {m.rule!r}; use lowest, ranked or rectangle")
        if m.breathing_norm != 0.5:
            s = np.where(body.n == 0, math.sqrt(2.0 * m.breathing_norm), 1.0)
            body = dataclasses.replace(body, A=body.A * s, B=body.B * s, C=body.C * s)
        return body

    def energies(self, setup: Setup) -> Energies:
        """The reduced collision of ``setup``, computed on first use."""
        if setup not in self._energies:
            t0 = time.perf_counter()
            body = self.body(setup)
            self._energies[setup] = _measure(setup, body, time.perf_counter() - t0)
        return self._energies[setup]

    @property
    def seconds(self) -> float:
        """Wall time of every collision run so far."""
        return float(sum(e.seconds for e in self._energies.values()))

    def __len__(self) -> int:
        return len(self._energies)


def mode_table(e: Energies, reading: Reading) -> ModeTable:
    """The labels of ``e`` under ``reading``, ranked by their mean energy."""
    if reading.norm == "E0":
        mean = e.mean[reading.window]
    elif reading.norm == "vib":
        mean = e.share[reading.window]
    else:
        mean = e.mean[reading.window] / e.vib_mean[reading.window]
    after = e.after[reading.after]
    if reading.norm != "E0":
        after = after / after.sum()
    if reading.count == "mode":
        labels = list(zip(e.n.tolist(), e.l.tolist(), strict=True))
    else:
        keys = list(zip(e.n.tolist(), e.l_class.tolist(), strict=True))
        index = {k: i for i, k in enumerate(dict.fromkeys(keys))}
        slot = np.array([index[k] for k in keys])
        labels = list(index)
        mean = np.bincount(slot, weights=mean, minlength=len(labels))
        after = np.bincount(slot, weights=after, minlength=len(labels))
    order = np.argsort(-mean, kind="stable")
    return ModeTable(
        setup=e.setup,
        reading=reading,
        labels=[labels[i] for i in order],
        mean=np.asarray(mean)[order],
        after=np.asarray(after)[order],
        epsilon=e.epsilon,
    )
