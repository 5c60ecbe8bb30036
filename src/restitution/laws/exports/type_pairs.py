"""The constants of a bidisperse packing, one per pair of particle types.

One material: type 1 the small grain, type 2 the large; 1-1 and 2-2 from the law of identical
grains, 1-2 from the pair's law. Two materials: type 1 this grain, type 2 the partner grain of
its own material and size; 1-1 and 2-2 from each material's law of identical grains. Every
constant (dimensionless) at one reference relative normal speed (m/s) or granular temperature
(m^2/s^2) (:func:`type_pair_constants`, :class:`TypePairs`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError
from restitution.laws.exports.constants import Constant, constant_at, maxwell_constant
from restitution.laws.partners.base import partner_of
from restitution.laws.si_law import SILaw

__all__ = ["SAME_SIZE_NOTE", "TWO_MATERIALS_NOTE", "TypePairs", "type_pair_constants"]


SAME_SIZE_NOTE = (
    "identical grains of one material have the same epsilon(w) whatever their size: the law "
    "depends on w/c only (the model has no other length), so 1-1 and 2-2 share one constant"
)
"""Why the type pairs 1-1 and 2-2 of one material take the same constant."""

TWO_MATERIALS_NOTE = (
    "two materials: 1-1 and 2-2 are each material's law of identical grains (whatever their "
    "size), 1-2 the law of the two grains; the speeds of all three are relative normal speeds "
    "in m/s"
)
"""How the type pairs of two materials are served."""


def _check_type_pair_laws(pair: SILaw, identical: SILaw, identical2: SILaw | None = None) -> None:
    """One-line refusal unless ``pair`` is a pair's law and ``identical`` the law of two
    identical grains of its first material and geometry (and, for two materials,
    ``identical2`` that of the partner's)."""
    if pair.law.partner is None:
        raise InputError(
            "the 1-2 constant needs the law of two different grains (an SILaw with "
            "law.partner, si_law(..., against='grain', radius_ratio=R) with R != 1, or with "
            "partner_grain); give that as the pair's law"
        )
    for law, which in ((identical, "1-1"), (identical2, "2-2")):
        if law is not None and (law.law.partner is not None or not partner_of(law).is_grain):
            raise InputError(
                f"the {which} constant needs the law of two identical grains (si_law(..., "
                f"against='grain') without a radius ratio), got {law.against_meaning!r}"
            )
    if pair.grain != identical.grain:
        raise InputError(
            f"the pair's law is for {pair.grain.describe()}, the identical grains' for "
            f"{identical.grain.describe()}; give both laws for one material and geometry"
        )
    other = pair.partner_grain
    if other is None and identical2 is not None:
        raise InputError(
            "the pair is of one material: 1-1 and 2-2 share the law of identical grains; leave "
            "out the second one"
        )
    if other is not None and (identical2 is None or identical2.grain != other):
        raise InputError(
            f"the pair's second grain is {other.describe()}: give the law of two identical "
            "grains of that material for the 2-2 constant (identical2)"
        )


@dataclass(frozen=True, eq=False)
class TypePairs:
    """The constants of a bidisperse packing, per pair of particle types.

    One material: type 1 is the small grain (radius ``R1``), type 2 the large one (``R2 =
    radius_ratio R1``). Two identical grains of one material have the same ``epsilon(w)``
    whatever their size (the law depends on ``w / c`` only), so 1-1 and 2-2 share :attr:`same`,
    from the law of identical grains; 1-2 (:attr:`mixed`) comes from the pair's law.

    Two materials (``pair.partner_grain``): type 1 is this grain (material of ``pair.grain``,
    radius ``R1``), type 2 the partner (``pair.partner_grain``, ``R2 = radius_ratio R1``); 1-1
    comes from :attr:`identical`, 2-2 from :attr:`identical2` (:attr:`same2`).

    Built by :func:`type_pair_constants`; every snippet function takes it in place of a
    :class:`Constant` (with ``s`` its :attr:`pair`).

    Attributes
    ----------
    pair : SILaw
        The pair's law: ``w`` the relative normal speed of the two grains, m/s.
    identical : SILaw
        The law of two identical grains of type 1's material and geometry (``w`` their relative
        normal speed, m/s).
    mixed : Constant
        Type pair 1-2.
    same : Constant
        Type pair 1-1 (and 2-2 for one material).
    identical2 : SILaw or None
        Two materials: the law of two identical grains of type 2's material.
    same2 : Constant or None
        Two materials: type pair 2-2.
    """

    pair: SILaw
    identical: SILaw
    mixed: Constant
    same: Constant
    identical2: SILaw | None = None
    same2: Constant | None = None

    def __post_init__(self) -> None:
        _check_type_pair_laws(self.pair, self.identical, self.identical2)
        if (self.identical2 is None) != (self.same2 is None):
            raise InputError("give identical2 and same2 together (two materials) or neither")

    @property
    def radius_ratio(self) -> float:
        """``R2 / R1``: type 2's radius over type 1's (``> 1`` for one material)."""
        return self.pair.law.partner.radius_ratio

    @property
    def two_materials(self) -> bool:
        """Whether the types are of two materials."""
        return self.pair.partner_grain is not None

    @property
    def grains(self) -> dict[int, object]:
        """Type -> its :class:`~restitution.laws.units.Grain` (material and geometry)."""
        return {1: self.pair.grain, 2: self.pair.partner_grain or self.pair.grain}

    @property
    def constants(self) -> dict[tuple[int, int], Constant]:
        """``(i, j) -> Constant`` for the type pairs ``(1, 1)``, ``(2, 2)`` and ``(1, 2)``."""
        return {(1, 1): self.same, (2, 2): self.same2 or self.same, (1, 2): self.mixed}

    def matrix(self) -> np.ndarray:
        """epsilon per type pair, a symmetric 2 x 2 array (row, column: type - 1)."""
        c = self.constants
        return np.array([[c[1, 1].epsilon, c[1, 2].epsilon], [c[1, 2].epsilon, c[2, 2].epsilon]])

    def type_words(self) -> dict[str, str]:
        """What types 1 and 2 are, for comments and JSON."""
        r = self.radius_ratio
        if self.two_materials:
            g1, g2 = self.grains[1], self.grains[2]
            return {
                "1": f"this grain (radius R1): {g1.describe()}",
                "2": f"the partner grain (R2 = {r:g} R1): {g2.describe()}",
            }
        return {
            "1": "the small grain (radius R1)",
            "2": f"the large grain (R2 = {r:g} R1), same material",
        }

    def to_dict(self) -> dict:
        """JSON-ready: the types, the three constants and the laws they come from."""
        name = self.pair.grain.law_nu_name

        def source(s: SILaw) -> dict:
            return {name: float(s.law.nu), "source": s.law_source}

        if self.two_materials:
            laws = {"1-1": source(self.identical), "2-2": source(self.identical2)}
            note = TWO_MATERIALS_NOTE
        else:
            laws = {"1-1, 2-2": source(self.identical)}
            note = SAME_SIZE_NOTE
        return {
            "types": self.type_words(),
            "radius_ratio": self.radius_ratio,
            **{f"{i}-{j}": c.to_dict() for (i, j), c in self.constants.items()},
            "laws": {**laws, "1-2": source(self.pair)},
            "note": note,
        }


def type_pair_constants(
    pair: SILaw,
    identical: SILaw,
    *,
    speed_m_s: float | None = None,
    temperature_m2_s2: float | None = None,
    identical2: SILaw | None = None,
) -> TypePairs:
    """The constants of a bidisperse packing per pair of particle types, at one reference.

    Parameters
    ----------
    pair : SILaw
        The law of two different grains (``pair.law.partner`` set; from ``si_law(...,
        against="grain", radius_ratio=R[, partner_grain=...])``); gives type pair 1-2.
    identical : SILaw
        The law of two identical grains of the pair's first material and geometry
        (``si_law(..., against="grain")``); gives type pair 1-1 (and 2-2 for one material).
    speed_m_s : float, optional
        Reference relative normal speed ``w``, m/s: each constant is its law at ``w``
        (:func:`constant_at`).
    temperature_m2_s2 : float, optional
        Granular temperature ``<v_x^2>`` of both sizes, m^2/s^2: each constant is its law
        averaged over a Maxwell gas (:func:`maxwell_constant`). Give this or ``speed_m_s``.
    identical2 : SILaw, optional
        Two materials: the law of two identical grains of the partner's material; gives 2-2.

    Returns
    -------
    TypePairs

    Raises
    ------
    InputError
        For laws that do not fit together, neither or both references, or a reference outside
        a law (the message names the type pair).
    """
    if (speed_m_s is None) == (temperature_m2_s2 is None):
        raise InputError(
            "the type-pair constants need one reference: a speed (m/s) or a Maxwell "
            "temperature (m^2/s^2), not both and not neither"
        )
    _check_type_pair_laws(pair, identical, identical2)
    laws = tuple(x for x in (pair, identical, identical2) if x is not None)

    def one(s: SILaw, name: str) -> Constant:
        try:
            if speed_m_s is not None:
                return constant_at(s, speed_m_s)
            others = tuple(x for x in laws if x is not s)
            return maxwell_constant(s, temperature_m2_s2, together=others)
        except InputError as exc:
            raise InputError(f"type pair {name}: {exc}") from None

    if identical2 is None:
        return TypePairs(
            pair,
            identical,
            mixed=one(pair, "1-2 (small with large)"),
            same=one(identical, "1-1 and 2-2 (identical grains)"),
        )
    return TypePairs(
        pair,
        identical,
        mixed=one(pair, "1-2 (this grain with the partner)"),
        same=one(identical, "1-1 (two grains of this material)"),
        identical2=identical2,
        same2=one(identical2, "2-2 (two grains of the partner's material)"),
    )
