"""One claim of the paper beside our value, and the rules that turn the two into a verdict.

A verdict is one of

* ``"agrees"``: the claim holds within a tolerance stated in the row, on points that passed
  their own checks;
* ``"differs"``: it does not, by more than the tolerance plus the points' errors;
* ``"inconclusive"``: the points it rests on did not pass their checks (e.g. an extrapolation
  flagged as not asymptotic), or their errors are larger than the tolerance, so the data cannot
  decide. The row still says what the data would say at face value ("leans ...").

Every rule is a function of the data; nothing here knows the answer in advance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = [
    "AGREES",
    "DIFFERS",
    "INCONCLUSIVE",
    "Comparison",
    "compare_value",
    "pct",
    "row",
]

AGREES, DIFFERS, INCONCLUSIVE = "agrees", "differs", "inconclusive"


@dataclass(frozen=True)
class Comparison:
    """One of the paper's stated values or claims beside ours.

    Attributes
    ----------
    figure : str
        Where the paper says it, e.g. ``"Fig. 1"``, ``"Table 1"``, ``"Eq. (57)"``.
    claim : str
        Short name of the result.
    paper : str
        What the paper says (value or claim).
    ours : str
        What we get.
    verdict : str
        Starts with ``"agrees"``, ``"differs"`` or ``"inconclusive"``, then the tolerance or
        the reason.
    agrees : bool or None
        ``None`` when inconclusive.
    detail : bool
        A row of a detailed list (e.g. one mode of Table 1) that a summary may leave out.
    speed_unit : str
        ``"c"`` or ``"c_L"``: the unit the paper's speeds were read in for this row (``""``
        when the row involves no speed).
    why : str
        For a row that differs: the protocol that reproduces the paper's claim or the
        attribution, with its evidence (:mod:`restitution.reproduction.claims.attributions`).
    """

    figure: str
    claim: str
    paper: str
    ours: str
    verdict: str
    agrees: bool | None
    detail: bool = False
    speed_unit: str = ""
    why: str = ""

    @property
    def outcome(self) -> str:
        """``"agrees"``, ``"differs"`` or ``"inconclusive"``."""
        return {True: AGREES, False: DIFFERS, None: INCONCLUSIVE}[self.agrees]


def pct(x: float) -> str:
    """``x`` as a signed percentage, ``"+1.2 %"``."""
    return "nan" if not math.isfinite(x) else f"{100.0 * x:+.1f} %"


def row(
    figure: str,
    claim: str,
    paper: str,
    ours: str,
    agrees: bool | None,
    differs: str = "",
    *,
    agrees_note: str = "",
    detail: bool = False,
    speed_unit: str = "",
) -> Comparison:
    """A :class:`Comparison`.

    ``differs`` completes "differs ..." (or, with ``agrees=None``, says why inconclusive);
    ``agrees_note`` qualifies "agrees (...)".
    """
    agrees = None if agrees is None else bool(agrees)
    if agrees is None:
        verdict = f"{INCONCLUSIVE}: {differs}" if differs else INCONCLUSIVE
    elif agrees:
        verdict = AGREES + (f" ({agrees_note})" if agrees_note else "")
    else:
        verdict = f"{DIFFERS} {differs}" if differs else DIFFERS
    return Comparison(figure, claim, paper, ours, verdict, agrees, detail, speed_unit)


def compare_value(
    ours: float, err: float, paper: float, tol: float, *, checked: bool, why: str = ""
) -> tuple[bool | None, str]:
    """Verdict on a single value ``ours +- err`` against the paper's ``paper +- tol``.

    Agrees when ``|ours - paper| <= tol``; differs when ``|ours - paper| > tol + 2 err``;
    inconclusive in between, when ``checked`` is false (the value failed its own checks,
    ``why``), when ``2 err > tol`` (our error is too large to test the claim) or when ``ours`` is
    not finite.

    Returns
    -------
    agrees : bool or None
    note : str
        The difference, the tolerance and, if inconclusive, why and which way it leans at face
        value (agrees within the tolerance, differs beyond it by more than two errors).
    """
    if not (math.isfinite(ours) and math.isfinite(err)):
        return None, "no finite value"
    diff = ours - paper
    base = f"difference {diff:+.3f} +- {err:.3f}, tolerance {tol:.3f}"
    if abs(diff) <= tol:
        lean = f"at face value {AGREES}"
    elif abs(diff) > tol + 2.0 * err:
        lean = f"at face value {DIFFERS}"
    else:
        lean = "leans neither way (within two errors of the tolerance)"
    if not checked:
        return None, f"{why or 'the value failed its checks'}; {lean} ({base})"
    if 2.0 * err > tol:
        return None, f"error {err:.3f} too large for the tolerance; {lean} ({base})"
    if abs(diff) <= tol:
        return True, base
    if abs(diff) > tol + 2.0 * err:
        return False, f"by {diff:+.3f} ({pct(diff / paper)}); {base}"
    return None, f"{lean} ({base})"
