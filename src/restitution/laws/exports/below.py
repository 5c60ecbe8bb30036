"""Below a law's slowest point: the slow-impact asymptote that carries an export to ``w -> 0``.

A DEM code calls its coefficient at every impact speed, down to a contact that is nearly at rest.
Below the slowest computed speed ``w0`` the exports continue with the leading behaviour of the
loss ``L = 1 - epsilon^2`` as ``w -> 0``, anchored at ``w0`` (``L0 = 1 - epsilon(w0)^2``):

* ``"power"``: ``L(w) = L0 (w / w0)^q``;
* ``"log"``: ``L(w) = L0 (ln(ws / w0) / ln(ws / w))^p`` for ``0 < w < w0 < ws``;

both give ``epsilon = 1`` at ``w = 0``. The form comes from the mechanism that dominates the loss
at vanishing speed and the contact's dimension (:func:`slow_continuation`):

=====================  ================================  =========================================
mechanism              3D (Hertz contact)                2D (the disk's logarithmic contact)
=====================  ================================  =========================================
elastic waves (modes)  power, ``q = 1`` (Rayleigh's       log, ``p = 2``, ``ws = k c``
                       estimate, docs/spheres.md)        (``slow_disk.asymptotic_loss``,
                                                         docs/quasistatic.md)
viscous (damped law)   power, ``q = 1/5`` (Kelvin-       log, ``p = 1/2``, ``ws = k c``
                       Voigt on Hertz's pulse)           (``viscoelastic.loss_slope``:
                                                         ``S sqrt(ln(1/v))`` constant within 1 %
                                                         on ``1e-3 ... 1e-15 c``)
radiation into an      power, ``q = 3/5`` (Hunter's      (no 2D elastic wall)
elastic half-space     ``(v/c)^(3/5)``)
a thin plate's         power, ``q = 1/5`` (Zener's        (no 2D elastic wall)
flexural waves         parameter ``lambda ~ v^(1/5)``:
                       the loss's first order,
                       tests/test_plate.py)
=====================  ================================  =========================================

A damped law continues with the viscous form: at vanishing speed the viscous loss outgrows the
elastic one in both dimensions (``v^(1/5)`` against ``v``; ``ln^(-1/2)`` against ``ln^(-2)``).
A law on an elastic wall continues with the wall's radiation, which outgrows the ball's own
vibrations the same way; on a plate the flexural waves outgrow the radiation into its depth
(``v^(1/5)`` against ``v^(3/5)``), and Zener's model holds better the slower the impact (the
pulse longer against the plate's thickness and transit).

What the continuation is worth: the leading order only, so its error is stated as a bound equal
to its own loss ``1 - epsilon`` (:attr:`SlowContinuation.error_bound`). Against the law's
low-speed route, measured on the steel cylinder and sphere from ``w0`` down to ``1e-6 w0``
(``tests/test_exports_below.py``), the route's loss lay between a fraction and 1.21 times the
continuation's on the cylinder (0.31-1.21: the 2D loss oscillates about its leading form) and
below it on the sphere (0.13-0.86: there the loss falls faster than ``v`` until ``v ~ 1e-12``):
within that bound. The bound is claimed only where the anchor is a point of that route
(:attr:`SlowContinuation.on_route`, every shipped law); a law of collisions alone says so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from restitution.errors import InputError
from restitution.laws.mechanisms.bounds import law_mechanisms
from restitution.laws.partners.base import partner_of

__all__ = ["SlowContinuation", "slow_continuation"]


@dataclass(frozen=True)
class SlowContinuation:
    """The loss's leading behaviour below the slowest point ``w0`` (module docs).

    Attributes
    ----------
    form : str
        ``"power"`` or ``"log"``.
    w0_m_s : float
        The anchor: the law's slowest computed speed, m/s.
    loss0 : float
        ``1 - epsilon(w0)^2`` there.
    exponent : float
        ``q`` of the power form, ``p`` of the log form.
    scale_m_s : float or None
        ``ws`` of the log form (m/s; ``ws > w0``), ``None`` for the power form.
    why : str
        The mechanism and the theory the form comes from, for the exports' comments.
    on_route : bool
        Whether the anchor is a point of the law's low-speed route (every shipped law's
        slowest point is): only there is the error bound checked (module docs). A law of
        collisions alone starts above the low-speed range, and its continuation is a guess.
    """

    form: str
    w0_m_s: float
    loss0: float
    exponent: float
    scale_m_s: float | None
    why: str
    on_route: bool = True

    def loss(self, speed_m_s) -> np.ndarray:
        """``1 - epsilon^2`` at speeds ``0 <= w <= w0`` (m/s); 0 at ``w = 0``."""
        w = np.asarray(speed_m_s, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            if self.form == "power":
                ratio = (w / self.w0_m_s) ** self.exponent
            else:
                ws = self.scale_m_s
                ratio = (math.log(ws / self.w0_m_s) / np.log(ws / w)) ** self.exponent
        return np.where(w > 0.0, self.loss0 * ratio, 0.0)

    def __call__(self, speed_m_s):
        """epsilon at speeds ``0 <= w <= w0`` (m/s)."""
        eps = np.sqrt(1.0 - self.loss(speed_m_s))
        return float(eps) if np.ndim(speed_m_s) == 0 else eps

    def error_bound(self, speed_m_s):
        """The stated error of :meth:`__call__`: a bound, its own loss ``1 - epsilon``; NaN
        (not known) unless the anchor is on the low-speed route (:attr:`on_route`)."""
        bound = 1.0 - np.asarray(self(speed_m_s))
        return bound if self.on_route else np.full_like(bound, np.nan)

    def describe(self) -> str:
        """What the continuation is and what its error means, in one line for comments."""
        bound = (
            "the leading order only: its error is bounded by its own loss 1 - epsilon"
            if self.on_route
            else "anchored on a computed collision, not on the low-speed route: a guess, "
            "its error not known"
        )
        return (
            f"below {self.w0_m_s:.6g} m/s, down to w = 0: the slow-impact asymptote of the "
            f"{self.why}, {self.formula()}; epsilon = 1 at w = 0; {bound}"
        )

    def formula(self) -> str:
        """The continuation in one line, with its numbers (m/s), for comments."""
        if self.form == "power":
            return f"1 - epsilon^2 = {self.loss0:.10g} (w / {self.w0_m_s:.10g})^{self.exponent:g}"
        return (
            f"1 - epsilon^2 = {self.loss0:.10g} (ln({self.scale_m_s:.10g} / {self.w0_m_s:.10g}) "
            f"/ ln({self.scale_m_s:.10g} / w))^{self.exponent:g}"
        )


def slow_continuation(s, w0_m_s: float, epsilon0: float) -> SlowContinuation:
    """The continuation of the law of ``s`` (an :class:`~restitution.laws.si_law.SILaw`) below
    its slowest point ``w0`` (m/s), where it is ``epsilon0`` (module docs for the forms).

    Raises
    ------
    InputError
        For a 2D body on an elastic wall (no leading form derived) or an ``epsilon0`` outside
        ``(0, 1]``.
    """
    if not 0.0 < epsilon0 <= 1.0:
        raise InputError(
            f"the law's slowest point has epsilon = {epsilon0!r}; no slow-impact continuation "
            "starts from a value outside (0, 1]"
        )
    planar = s.grain.kind.planar
    names = law_mechanisms(s.law)
    # The mechanism that dominates the loss as w -> 0 (module docs): viscosity, else an elastic
    # wall's radiation, else the body's own vibrations.
    partner = partner_of(s.law)
    dominant = next(m for m in ("viscous", partner.loss, "waves") if m is not None and m in names)
    if dominant == partner.loss:  # the partner's own loss: its form (none for a 2D body)
        form, exponent, why = partner.slow_form(planar)
    else:
        form, exponent, why = _FORMS[dominant, planar]
    ws = float(s.speed_scale_m_s) if form == "log" else None
    if ws is not None and not ws > w0_m_s:
        raise InputError(
            f"the law's slowest point {w0_m_s:.4g} m/s is not below its speed scale {ws:.4g} "
            "m/s; no slow-impact continuation starts there"
        )
    on_route = bool(np.asarray(getattr(s.law, "quasistatic", [False]), dtype=bool)[0])
    loss0 = 1.0 - float(epsilon0) ** 2
    return SlowContinuation(form, w0_m_s, loss0, exponent, ws, why, on_route)


_FORMS = {
    ("viscous", False): ("power", 0.2, "viscous loss on Hertz's pulse, ~ v^(1/5)"),
    ("viscous", True): ("log", 0.5, "viscous loss of the 2D contact, ~ 1/sqrt(ln(1/v))"),
    ("waves", False): ("power", 1.0, "vibrations of the 3D body, ~ v (Rayleigh)"),
    ("waves", True): ("log", 2.0, "vibrations of the 2D body, ~ 1/ln^2(1/v)"),
}
"""``(dominant mechanism, planar) -> (form, exponent, what it is)``: the table of the module
docs; where an elastic wall's radiation dominates, its partner kind's
(:meth:`~restitution.laws.partners.base.PartnerKind.slow_form`)."""
