"""One Coulomb contact spread like the pressure, with a compliance in series, step by step
(issue 63): the tangential force of the one-state contact on annuli or hats whose tangential
flexibility ``Ht`` (between forces and mean displacements) carries its stick.

Units: ``E = rho = R = 1``; forces in ``E R^2``, displacements in ``R``.

**Stick.** The force ``F`` spread like the pressure, ``F p`` (``p = P / sum P``), moves the
contact in line by ``Ht F p``; its pressure-weighted displacement is ``p . Ht . p F``. The
contact sticks when that displacement's change cancels the rigid (or kept) slip ``ds`` over the
step, with ``p`` at the step's mean, ``pbar``::

    F_new (pbar . Ht . p_new) - F_old (pbar . Ht . p_old) = -ds,

the discrete form of ``v_s = F' C + F C' / 2 + v_rigid = 0`` (``C = p . Ht . p``), whose power
``F v_s`` is the rate of the stored ``F^2 C / 2`` plus the rigid motion's. **Slip:** the force
is clipped to Coulomb's bound ``mu sum P``. :mod:`restitution.quasistatic.sphere_one_state`
(the finite sphere on annuli) and :mod:`restitution.dynamics.oblique_residual` (the modal route
with the dropped modes' residual on hats) step it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["OneStateFriction"]


class OneStateFriction:
    """The one-state contact's tangential force, step by step, on annuli with the flexibility
    ``Ht`` between tangential forces and mean displacements (module docs): the discrete stick
    condition, clipped to Coulomb's bound."""

    def __init__(self, Ht: np.ndarray) -> None:
        self.Ht = Ht
        self.force = 0.0
        self._p: np.ndarray | None = None
        self._Hp: np.ndarray | None = None

    def flexibility(self, P: np.ndarray) -> np.ndarray:
        """The in-line flexibility at the annuli's normal forces ``P``: ``Ht`` (a subclass may
        make it depend on the contact, as
        :class:`~restitution.quasistatic.sphere_coupling.TiltedOneStateFriction`)."""
        return self.Ht

    def step(self, P: np.ndarray, s_old: float, s_new: float, mu: float) -> float:
        """The force after the contact point moved rigidly from ``s_old`` to ``s_new``, with
        the annuli's normal forces ``P`` at the step's end."""
        ds = s_new - s_old
        total = float(P.sum())
        if total <= 0.0:
            self.force, self._p, self._Hp = 0.0, None, None
            return 0.0
        p = P / total
        Hp = self.flexibility(P) @ p
        if self._p is None:
            F = -ds / (p @ Hp)
        else:
            pbar = 0.5 * (p + self._p)
            F = (self.force * (pbar @ self._Hp) - ds) / (pbar @ Hp)
        self.force = min(max(float(F), -mu * total), mu * total)
        self._p, self._Hp = p, Hp
        return self.force
