"""Table 1 under every protocol of :mod:`restitution.reproduction.table1_study` scored against
the paper, and the paper's Table 1 checked against itself (issue 65, item 4; docs/table1.md).

Units as in the study: ``E = rho = R = 1``, speeds in ``c``, times in ``R / c``, energies as
fractions of the initial kinetic energy ``E0 = (m/2) v^2`` unless a reading says otherwise.

**Score** of a protocol (:class:`Score`): which of the paper's ten (n, l) are in our top ten
and at the same rank, and for each of the paper's ten our mean and after energy of that label
(wherever it ranks) as ``ours / paper - 1``. The protocol *reproduces* Table 1 when all ten
modes are in our top ten and all twenty energies lie within :data:`TOLERANCE`; ``misfit`` orders
the protocols: the root mean square of ``ln(ours / paper)`` over the twenty energies.

**Consistency** (:func:`consistency`): the paper's ten energies after the collision sum to
0.0934 of ``E0``, so its epsilon at these settings is at most ``sqrt(1 - 0.0934) = 0.952``;
the share of ``1 - epsilon^2`` our collision puts into those ten modes turns the sum into the
paper's implied ``1 - epsilon^2``; our ten-mode sums against speed say which speed the paper's
sums would need. Ratios of two rows do not depend on the normalisation: their range over every
protocol, beside the paper's. Finally the breathing rows, ``(0, l)``, are driven by one and the
same force with couplings ``C_l cos(phi)``, so one force pulse fixes all three
(:func:`breathing_pulse`): a driven oscillator's energy is
``E_l(t) = |int_0^t C_l F(s) exp(-i omega_l s) ds|^2 / (2 m)``. Our own pulse, stretched in
time at fixed impulse, is tried at every duration against the paper's three rows.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from restitution.reproduction.table1_study import (
    AFTERS,
    COUNTS,
    NORMS,
    PAPER,
    PAPER_READING,
    PAPER_SETUP,
    SPEED_READINGS,
    WINDOWS,
    Energies,
    ModeChoice,
    ModeTable,
    Reading,
    Setup,
    Study,
    interval_mean,
    mode_table,
)

__all__ = [
    "PAPER_AFTER",
    "PAPER_LABELS",
    "PAPER_MEAN",
    "TOLERANCE",
    "BreathingPulse",
    "Consistency",
    "Result",
    "Score",
    "breathing_pulse",
    "consistency",
    "full_setups",
    "quick_setups",
    "readings",
    "run",
    "score",
]

TOLERANCE = 0.05
"""A protocol reproduces Table 1 when every energy lies within 5 % of the paper's."""

PAPER_LABELS = [(p[1], p[2]) for p in PAPER]
PAPER_MEAN = np.array([p[3] for p in PAPER])
PAPER_AFTER = np.array([p[4] for p in PAPER])

SCAN_SPEEDS = (0.03, 0.04, 0.06, 0.08, 0.12, 0.14, 0.17, 0.2, 0.25)
"""Speeds (``c``) of the scan beside the four readings of ``v_i = 0.1``."""

SCAN_ALPHAS = (250.0, 500.0, 1000.0)
"""Wall stiffness of the paper (500) and its neighbours, ``1 / R``."""

STRETCHES = np.geomspace(0.05, 4.0, 400)
"""Time stretches of our force pulse tried against the paper's breathing rows."""

PLANE_STRAIN_NU = 0.33 / (1.0 - 0.33)
"""``nu = 0.33`` read as the three-dimensional value of a plane-strain cylinder: eq. (2) maps it
onto the two-dimensional ``nu / (1 - nu)``."""

BREATHING = ((0, 0), (0, 1), (0, 2))


@dataclass(frozen=True, eq=False)
class Score:
    """One protocol against the paper's ten rows.

    Attributes
    ----------
    setup : Setup
    reading : Reading
    ranks : numpy.ndarray of int, shape (10,)
        Our rank (from 1) of each of the paper's ten labels, in the paper's order.
    mean, after : numpy.ndarray, shape (10,)
        Our energies of the paper's ten labels.
    top : list of (int, int)
        Our top ten labels.
    epsilon : float
    """

    setup: Setup
    reading: Reading
    ranks: np.ndarray
    mean: np.ndarray
    after: np.ndarray
    top: list
    epsilon: float

    @property
    def matched(self) -> int:
        """How many of the paper's ten are in our top ten."""
        return int(np.sum(self.ranks <= 10))

    @property
    def same_rank(self) -> int:
        return int(np.sum(self.ranks == np.arange(1, 11)))

    @property
    def d_mean(self) -> np.ndarray:
        """``ours / paper - 1`` of the mean energies, shape (10,)."""
        return self.mean / PAPER_MEAN - 1.0

    @property
    def d_after(self) -> np.ndarray:
        return self.after / PAPER_AFTER - 1.0

    @property
    def misfit(self) -> float:
        """RMS of ``ln(ours / paper)`` over the twenty energies."""
        return _rms_log(np.concatenate([self.mean / PAPER_MEAN, self.after / PAPER_AFTER]))

    @property
    def misfit_mean(self) -> float:
        """RMS of ``ln(ours / paper)`` over the ten mean energies."""
        return _rms_log(self.mean / PAPER_MEAN)

    @property
    def misfit_after(self) -> float:
        """RMS of ``ln(ours / paper)`` over the ten energies after."""
        return _rms_log(self.after / PAPER_AFTER)

    @property
    def worst(self) -> float:
        """Largest ``|ours / paper - 1|`` over the twenty energies."""
        return float(np.max(np.abs(np.concatenate([self.d_mean, self.d_after]))))

    @property
    def reproduced(self) -> bool:
        return self.matched == 10 and self.worst <= TOLERANCE

    @property
    def label(self) -> str:
        return f"{self.setup.label}; {self.reading.label}"


def _rms_log(ratio: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.log(np.clip(ratio, 1e-12, None)) ** 2)))


def score(table: ModeTable) -> Score:
    """Score one protocol's table against the paper's ten rows."""
    found = table.lookup()
    missing = (len(table.labels) + 1, 0.0, 0.0)  # a label the mode set lacks
    rows = [found.get(lab, missing) for lab in PAPER_LABELS]
    return Score(
        setup=table.setup,
        reading=table.reading,
        ranks=np.array([r[0] for r in rows]),
        mean=np.array([r[1] for r in rows]),
        after=np.array([r[2] for r in rows]),
        top=table.labels[:10],
        epsilon=table.epsilon,
    )


def readings() -> list[Reading]:
    """Every reading: window x normalisation x after x counting (``closest`` is an instant, so
    its two vibrational normalisations coincide and only ``vib`` is kept)."""
    out = []
    for window, norm, after, count in itertools.product(WINDOWS, NORMS, AFTERS, COUNTS):
        if window == "closest" and norm == "vib-mean":
            continue
        out.append(Reading(window=window, norm=norm, after=after, count=count))
    return out


def quick_setups() -> list[Setup]:
    """The paper's words with its speed read in ``c`` and in ``c_L`` (two collisions)."""
    return [PAPER_SETUP, Setup(reading="c_L")]


def full_setups() -> list[Setup]:
    """Every setup of docs/table1.md (57 collisions, about two minutes on a shared core).

    The four speed readings x the three walls on the 1600 lowest modes; the mode choices, the
    breathing normalisation, ``nu = 0.9``, ``nu = 0.33`` read as a plane-strain value and the
    paper's 256 edge nodes, one at a time, in the ``c`` and ``c_L`` readings; the speed scan at
    the three walls.
    """
    out = [Setup(reading=r, alpha=a) for r in SPEED_READINGS for a in SCAN_ALPHAS]
    variants = [
        {"modes": ModeChoice(count=800)},
        {"modes": ModeChoice(count=940)},
        {"modes": ModeChoice(count=3200)},
        {"modes": ModeChoice(rule="ranked")},
        {"modes": ModeChoice(rule="rectangle")},
        {"modes": ModeChoice(breathing_norm=1.0)},
        {"nu": 0.9},
        {"nu": PLANE_STRAIN_NU},
        {"n_phi": 256},
    ]
    for reading in ("c", "c_L"):
        out += [Setup(reading=reading, **kw) for kw in variants]
    out += [Setup(v_i=v, alpha=a) for v in SCAN_SPEEDS for a in SCAN_ALPHAS]
    return out


# -- the paper against itself ------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class BreathingPulse:
    """The paper's three breathing rows against one force pulse of our shape.

    Attributes
    ----------
    measured, predicted : numpy.ndarray, shape (2, 3)
        Our contact means (row 0) and after energies (row 1) of ``(0, 0), (0, 1), (0, 2)``:
        from the collision, and from its force pulse through the driven-oscillator formula
        (the check of the formula; fractions of ``E0``).
    stretch : numpy.ndarray, shape (S,)
        Time stretches tried (the pulse's duration times ``stretch`` at the same impulse).
    ratios : numpy.ndarray, shape (S, 4)
        At each stretch: mean (0,0)/(0,1), mean (0,1)/(0,2), after (0,0)/(0,1),
        after (0,1)/(0,2).
    energies : numpy.ndarray, shape (S, 2, 3)
        At each stretch: the means and the after energies, fractions of ``E0``.
    contact_time : float
        The unstretched contact time, ``R / c``.
    """

    measured: np.ndarray
    predicted: np.ndarray
    stretch: np.ndarray
    ratios: np.ndarray
    energies: np.ndarray
    contact_time: float

    @staticmethod
    def paper() -> tuple[np.ndarray, np.ndarray]:
        """The paper's ``(2, 3)`` energies and its four ratios."""
        index = [PAPER_LABELS.index(lab) for lab in BREATHING]
        e = np.array([PAPER_MEAN[index], PAPER_AFTER[index]])
        return e, _ratios(e)

    def first_stretch(self, values: np.ndarray, target: float) -> float:
        """The least stretch at which ``values`` (shape (S,), one per stretch) reaches
        ``target``, interpolated in ``ln(stretch)``; ``nan`` if it never does."""
        miss = values - target
        cross = np.nonzero(miss[:-1] * miss[1:] <= 0.0)[0]
        if cross.size == 0:
            return math.nan
        k = int(cross[0])
        w = miss[k] / (miss[k] - miss[k + 1])
        return float(np.exp((1.0 - w) * np.log(self.stretch[k]) + w * np.log(self.stretch[k + 1])))

    def at(self, stretch: float) -> int:
        """Index of the tried stretch nearest ``stretch`` (grid step 1.1 %)."""
        return int(np.argmin(np.abs(np.log(self.stretch / stretch))))


def _ratios(e: np.ndarray) -> np.ndarray:
    """Mean (0,0)/(0,1), mean (0,1)/(0,2), after (0,0)/(0,1), after (0,1)/(0,2)."""
    return np.array([e[0, 0] / e[0, 1], e[0, 1] / e[0, 2], e[1, 0] / e[1, 1], e[1, 1] / e[1, 2]])


def _driven(t, force, omega, coupling, mass, v, window) -> np.ndarray:
    """Means over ``window`` and final energies of oscillators driven by ``coupling * force``,
    shape (2, K), fractions of ``E0`` (the module docstring's formula)."""
    phase = np.exp(-1j * np.outer(t, omega)) * (coupling[None, :] * force[:, None])
    z = np.concatenate(
        [
            np.zeros((1, omega.size)),
            np.cumsum(0.5 * (phase[1:] + phase[:-1]) * np.diff(t)[:, None], 0),
        ]
    )
    e = np.abs(z) ** 2 / (mass * v) ** 2
    return np.array([interval_mean(t, e, *window), e[-1]])


def breathing_pulse(e: Energies) -> BreathingPulse:
    """Drive the three lowest breathing modes of ``e`` by its own wall force, stretched.

    The coupling of a breathing mode to the wall is ``C_l cos(phi)``, ``cos(phi) = 1`` on the
    contact to ``1e-2`` here, so each is driven by ``C_l`` times the total force. Stretching
    the pulse by ``s`` at fixed impulse (``t -> s t``, ``F -> F / s``) is any contact duration
    a different speed, unit or wall could give.
    """
    labels = list(zip(e.n.tolist(), e.l.tolist(), strict=True))
    index = [labels.index(lab) for lab in BREATHING]
    omega, coupling = e.omega[index], e.C[index]
    window = e.windows["contact"]
    v = e.setup.v
    measured = np.array([e.mean["contact"][index], e.after["end"][index]])
    predicted = _driven(e.t, e.force, omega, coupling, e.mass, v, window)
    energies = np.array(
        [
            _driven(
                s * e.t, e.force / s, omega, coupling, e.mass, v, (s * window[0], s * window[1])
            )
            for s in STRETCHES
        ]
    )
    return BreathingPulse(
        measured=measured,
        predicted=predicted,
        stretch=STRETCHES,
        ratios=np.array([_ratios(x) for x in energies]),
        energies=energies,
        contact_time=e.contact_time,
    )


@dataclass(frozen=True, eq=False)
class Consistency:
    """The paper's Table 1 checked against itself and against our collisions.

    Attributes
    ----------
    after_sum, mean_sum : float
        The paper's ten energies after, and ten mean energies, summed (fractions of ``E0``).
    epsilon_bound : float
        ``sqrt(1 - after_sum)``: the largest epsilon the paper's ten rows allow.
    by_reading : list of tuple
        Per speed reading of the paper's setup: ``(reading, v, epsilon, 1 - epsilon^2, share of
        1 - epsilon^2 in the paper's ten labels, implied 1 - epsilon^2, implied epsilon)``.
    share_range : (float, float)
        Least and largest share of our ``1 - epsilon^2`` in the paper's ten labels, over every
        setup (this package's reading).
    speed_for_after, speed_for_mean : float
        The speed (``c``; ``alpha = 500``, 1600 lowest modes, contact window) at which our ten
        labels' after (mean) energies sum to the paper's; ``nan`` outside the scan.
    ratios : list of tuple
        ``(name, paper, our least, our largest, the protocol of the least)`` over every protocol
        that counts by mode.
    pulse : BreathingPulse
    """

    after_sum: float
    mean_sum: float
    epsilon_bound: float
    by_reading: list
    share_range: tuple
    speed_for_after: float
    speed_for_mean: float
    ratios: list
    pulse: BreathingPulse


RATIOS = (
    ("mean (0,1) / (0,2)", "mean", (0, 1), (0, 2)),
    ("mean (0,0) / (0,1)", "mean", (0, 0), (0, 1)),
    ("mean (2,0) / (0,1)", "mean", (2, 0), (0, 1)),
    ("mean (2,0) / (3,0)", "mean", (2, 0), (3, 0)),
    ("after (2,0) / (4,0)", "after", (2, 0), (4, 0)),
    ("after (0,0) / (0,1)", "after", (0, 0), (0, 1)),
)
"""Ratios of two rows: independent of how the energies are normalised."""


def _ratio(values: np.ndarray, a, b) -> float:
    return float(values[PAPER_LABELS.index(a)] / values[PAPER_LABELS.index(b)])


def _speed_where(points: list, target: float) -> float:
    """Linear interpolation of ``v`` where the increasing ``y(v)`` of ``points`` reaches
    ``target``; ``nan`` outside."""
    points = sorted(points)
    for (v0, y0), (v1, y1) in itertools.pairwise(points):
        if (y0 - target) * (y1 - target) <= 0.0 and y1 != y0:
            return float(v0 + (target - y0) * (v1 - v0) / (y1 - y0))
    return math.nan


def consistency(study: Study, scores: list[Score]) -> Consistency:
    """Check the paper's rows against themselves and our collisions (module docstring)."""
    after_sum, mean_sum = float(PAPER_AFTER.sum()), float(PAPER_MEAN.sum())
    by_reading = []
    for name in SPEED_READINGS:
        e = study.energies(Setup(reading=name))
        s = score(mode_table(e, PAPER_READING))
        share = float(s.after.sum()) / e.loss
        implied = after_sum / share
        by_reading.append(
            (name, e.setup.v, e.epsilon, e.loss, share, implied, math.sqrt(max(1.0 - implied, 0)))
        )
    curve_after, curve_mean, shares = [], [], []
    for s in scores:
        su = s.setup
        if s.reading == PAPER_READING:
            shares.append(float(s.after.sum()) / (1.0 - s.epsilon**2))
        if (
            s.reading == PAPER_READING
            and su.alpha == PAPER_SETUP.alpha
            and su.modes == PAPER_SETUP.modes
            and su.nu == PAPER_SETUP.nu
            and su.n_phi is None
        ):
            curve_after.append((su.v, float(s.after.sum())))
            curve_mean.append((su.v, float(s.mean.sum())))
    curve_after, curve_mean = list(dict(curve_after).items()), list(dict(curve_mean).items())
    ratios = []
    by_mode = [s for s in scores if s.reading.count == "mode"]
    for name, column, a, b in RATIOS:
        paper = _ratio(PAPER_MEAN if column == "mean" else PAPER_AFTER, a, b)
        ours = [_ratio(s.mean if column == "mean" else s.after, a, b) for s in by_mode]
        k = int(np.argmin(ours))
        ratios.append((name, paper, ours[k], float(np.max(ours)), by_mode[k].label))
    return Consistency(
        after_sum=after_sum,
        mean_sum=mean_sum,
        epsilon_bound=math.sqrt(1.0 - after_sum),
        by_reading=by_reading,
        share_range=(min(shares), max(shares)),
        speed_for_after=_speed_where(curve_after, after_sum),
        speed_for_mean=_speed_where(curve_mean, mean_sum),
        ratios=ratios,
        pulse=breathing_pulse(study.energies(PAPER_SETUP)),
    )


# -- the study -------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Result:
    """Every score of one study run and the consistency checks.

    Attributes
    ----------
    scores : list of Score
        Sorted by ``misfit``, best first.
    paper : dict of str to Score
        The paper's setup and this package's reading, per speed reading present.
    consistency : Consistency
    collisions : int
    seconds : float
        Wall time of the collisions (scoring adds a few seconds).
    """

    scores: list
    paper: dict
    consistency: Consistency
    collisions: int
    seconds: float

    @property
    def best(self) -> Score:
        return self.scores[0]

    @property
    def reproduced(self) -> list:
        """The protocols that reproduce Table 1 (:data:`TOLERANCE`)."""
        return [s for s in self.scores if s.reproduced]


def run(setups=None, reading_list=None, study: Study | None = None) -> Result:
    """Score every setup under every reading (default: :func:`full_setups`, :func:`readings`).

    The four speed readings of the paper's setup are always run (the consistency check needs
    them). Pass ``study`` to reuse the collisions of an earlier run.
    """
    study = Study() if study is None else study
    setups = full_setups() if setups is None else list(setups)
    setups += [Setup(reading=r) for r in SPEED_READINGS if Setup(reading=r) not in setups]
    reading_list = readings() if reading_list is None else list(reading_list)
    if PAPER_READING not in reading_list:
        reading_list.insert(0, PAPER_READING)
    scores = [
        score(mode_table(study.energies(setup), reading))
        for setup in setups
        for reading in reading_list
    ]
    paper = {
        s.setup.reading: s
        for s in scores
        if s.reading == PAPER_READING and s.setup == Setup(reading=s.setup.reading)
    }
    return Result(
        scores=sorted(scores, key=lambda s: s.misfit),
        paper=paper,
        consistency=consistency(study, scores),
        collisions=len(study),
        seconds=study.seconds,
    )
