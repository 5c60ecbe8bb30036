"""The contact-law protocol: what the dynamics asks of the law that pushes a body off the wall.

Units: ``E = rho = R = 1``; lengths in ``R``, times in ``R / c``, energies absolute.

A contact law is a *family* of repulsions, one member per hardness ``alpha`` (a number per
collision; the arrays of a batch), so that the sweeps' limit ``alpha -> infinity`` is that of
any law. The law is local: a surface point at ``x`` (its position along the impact axis; the
wall is the plane ``x = 0`` and the body comes from ``x < 0``) stores an energy per unit area
that depends on ``x`` and ``alpha`` alone, and the body's surface quadrature sums it
(:mod:`restitution.dynamics.contact.surface`). A law that is not local (a compliant wall, a
partner body) replaces :meth:`ContactLaw.contact_terms` as a whole.

What the dynamics consumes, and where it used to be written out for the exponential wall:

* :meth:`~ContactLaw.node_terms`, :meth:`~ContactLaw.cutoff`: potential and forces on a batch
  of surface points, and the distance beyond which a point no longer counts;
* :meth:`~ContactLaw.contact_terms`: potential and forces on a body's
  :class:`~restitution.bodies.base.SurfaceQuadrature` (the NumPy path, the DOP853 reference);
* :meth:`~ContactLaw.separated`: the stop test;
* :meth:`~ContactLaw.step_time`: the time scale the first step resolves;
* :meth:`~ContactLaw.start_position`, :meth:`~ContactLaw.approach_gap`: where a collision
  begins, and how far the body flies before it touches (the work estimate);
* :meth:`~ContactLaw.nodes`: how many surface nodes the contact needs;
* :attr:`~ContactLaw.conservative`: whether the energy balance may judge the step (else epsilon
  judges it by Richardson's estimate, as for a damped body);
* :attr:`~ContactLaw.name`, :meth:`~ContactLaw.key`: what a result store keys a point with;
* :attr:`~ContactLaw.kernel`: the branch of the compiled kernel that runs the law, if any.

Every law registers itself by name when its class is defined (:data:`CONTACT_LAWS`), so a
store can rebuild a point's law from its key (:func:`law_from_key`) and the layers above never
compare names.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import fields, is_dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from restitution.dynamics.contact.surface import surface_terms
from restitution.errors import InputError

if TYPE_CHECKING:
    from restitution.bodies.base import ModalBody, SurfaceQuadrature

__all__ = ["CONTACT_LAWS", "CONTACT_TOL", "ContactLaw", "law_from_key"]

CONTACT_TOL = 1e-12
"""Wall potential energy at the start, and the wall force scale at the end, relative to E0."""

CONTACT_LAWS: dict[str, type[ContactLaw]] = {}
"""Every contact law class by its :attr:`ContactLaw.name`, filled as the classes are defined."""

# Bisection steps of the generic start position: enough to close any bracket of doubles.
_BISECTIONS = 200


class ContactLaw(ABC):
    """A family of contact laws, one per hardness ``alpha`` (module docstring).

    Subclasses are small frozen dataclasses whose fields are the law's parameters (numbers or
    strings: they enter store keys); the hardness is not a field but an argument of every
    method, an array of shape (B,) for a batch. A subclass sets :attr:`name` and implements
    :meth:`node_terms`, :meth:`cutoff` and :meth:`step_time`; the rest has defaults that hold
    for any local law.
    """

    name: ClassVar[str]
    """Stable name of the law: part of store keys, never reused for another law."""
    conservative: ClassVar[bool] = True
    """``True``: the forces derive from the potential and the energy drift judges the step.
    ``False``: epsilon judges it (Richardson, :mod:`restitution.dynamics.collision`)."""
    kernel: ClassVar[str | None] = None
    """Name of the law's branch in the compiled kernel (:data:`restitution.dynamics.kernel.
    KERNEL_LAWS`); ``None``: the law runs on the NumPy path only."""

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        name = cls.__dict__.get("name")
        if name is None:
            return  # an intermediate class; it inherits its parent's name
        other = CONTACT_LAWS.get(name)
        if other is not None and (other.__module__, other.__qualname__) != (
            cls.__module__,
            cls.__qualname__,
        ):
            raise InputError(
                f"the contact law name {name!r} is taken by {other.__module__}."
                f"{other.__qualname__}; give {cls.__qualname__} another name"
            )
        CONTACT_LAWS[name] = cls

    # -- what every law defines ------------------------------------------------------------

    @abstractmethod
    def node_terms(
        self, alpha: np.ndarray, x: np.ndarray, weight: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Potential and forces of surface points at positions ``x``.

        Parameters
        ----------
        alpha : numpy.ndarray, shape x.shape[:-1]
            Hardness of each batch member.
        x : numpy.ndarray, shape (..., M)
            Position of each surface point along the impact axis, ``R`` (the wall at 0).
        weight : numpy.ndarray, shape (M,)
            Quadrature weight of each point (``R`` for an edge, ``R^2`` for a surface).

        Returns
        -------
        V : numpy.ndarray, shape x.shape[:-1]
            Potential energy of the wall.
        F : numpy.ndarray, shape x.shape[:-1]
            ``dV/dx0``: the total force pushing the body back (``F = e.sum(-1)``).
        e : numpy.ndarray, shape x.shape
            ``dV/dx_j``: each point's share of the force, its weight included.
        """

    @abstractmethod
    def cutoff(self, alpha: np.ndarray) -> np.ndarray:
        """Distance from the wall (``R``, >= 0) beyond which a surface point's force is
        negligible (the exponential wall: below ``exp(-40)`` of its value at the wall); points
        farther out are skipped and a body leaving farther out is free."""

    @abstractmethod
    def step_time(self, alpha: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Time (``R / c``) in which the wall stops a surface point arriving at speed ``v``
        (``c``): the scale the first step resolves (:func:`restitution.dynamics.steps.
        initial_step`, which calibrates the factor per integrator)."""

    # -- defaults that hold for any local law ----------------------------------------------

    def contact_terms(
        self, quad: SurfaceQuadrature, alpha: np.ndarray, x0: np.ndarray, Q: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Potential ``V`` (B,), total force ``F = dV/dx0`` (B,) and generalised forces
        ``f = dV/dQ`` (B, N) of a batch of bodies at centres ``x0`` (B,) with modal coordinates
        ``Q`` (B, N): :func:`restitution.dynamics.contact.surface.surface_terms`."""
        return surface_terms(self, quad, alpha, x0, Q)

    def separated(
        self, gap: np.ndarray, alpha: np.ndarray, V: np.ndarray, e0: np.ndarray
    ) -> np.ndarray:
        """Stop test of a body moving away: ``gap`` (``R``) is how far the surface stays from
        the wall whatever its free vibration does, ``V`` the wall energy now and ``e0`` the
        kinetic energy before the collision. Default: no point can come within
        :meth:`cutoff`, and ``V < CONTACT_TOL e0``."""
        return (gap > self.cutoff(alpha)) & (V < CONTACT_TOL * e0)

    def start_position(
        self, alpha: np.ndarray, e0: np.ndarray, quad: SurfaceQuadrature
    ) -> np.ndarray:
        """Centre position (``R``, shape (B,)) where the undeformed body's wall energy is
        ``CONTACT_TOL * e0``. Default: bisection on :meth:`node_terms` (the energy grows
        towards the wall), the returned side at most that energy."""
        alpha = np.asarray(alpha, dtype=float)
        target = CONTACT_TOL * np.asarray(e0, dtype=float)

        def energy(x0: np.ndarray) -> np.ndarray:
            return self.node_terms(alpha, x0[:, None] + quad.height[None, :], quad.weight)[0]

        width = np.maximum(self.cutoff(alpha), 1e-6)
        lo = -1.0 - width
        hi = np.full(alpha.shape, -1.0 + 1e-6)
        for _ in range(64):  # widen both ends until they bracket the target
            low_high = energy(lo) > target
            high_low = energy(hi) <= target
            if not (np.any(low_high) or np.any(high_low)):
                break
            lo = np.where(low_high, lo - width, lo)
            hi = np.where(high_low, hi + width, hi)
            width = 2.0 * width
        else:
            raise InputError(
                f"the contact law {self.name!r} has no position where the wall energy is "
                f"{CONTACT_TOL:g} E0; its energy must grow towards the wall"
            )
        for _ in range(_BISECTIONS):
            mid = 0.5 * (lo + hi)
            if np.all((mid == lo) | (mid == hi)):
                break
            below = energy(mid) <= target
            lo = np.where(below, mid, lo)
            hi = np.where(below, hi, mid)
        return lo

    def approach_gap(self, body: ModalBody, alpha: np.ndarray, e0: np.ndarray) -> np.ndarray:
        """How far (``R``, shape (B,)) the undeformed tip is from the wall at the start
        position, before any quadrature exists (:func:`restitution.dynamics.steps.
        estimate_work`). Default: the bound :meth:`cutoff`."""
        return np.broadcast_to(self.cutoff(np.asarray(alpha, dtype=float)), np.shape(e0))

    def nodes(self, body: ModalBody, alpha: float) -> int:
        """Surface nodes the contact needs at hardness ``alpha``. Default: those that resolve
        a contact zone of depth ``1 / alpha``
        (:meth:`~restitution.bodies.base.ModalBody.contact_nodes`)."""
        return body.contact_nodes(alpha)

    def kernel_parameters(self) -> tuple[float, ...]:
        """Numbers the compiled branch :attr:`kernel` reads (``law_params`` of
        :func:`restitution.dynamics.kernel.run_batch`); none by default."""
        return ()

    def key(self) -> dict[str, Any]:
        """``{"name": name, **parameters}``: the law in a store key
        (:class:`restitution.limits.store.PointSpec`); :func:`law_from_key` inverts it."""
        params = {f.name: getattr(self, f.name) for f in fields(self)} if is_dataclass(self) else {}
        return {"name": self.name, **params}


def law_from_key(key: dict[str, Any] | str) -> ContactLaw:
    """The law of :meth:`ContactLaw.key` (or of a bare name, for a law without parameters)."""
    if isinstance(key, str):
        key = {"name": key}
    params = dict(key)
    name = params.pop("name", None)
    cls = CONTACT_LAWS.get(name)
    if cls is None:
        raise InputError(
            f"unknown contact law {name!r}; known: {sorted(CONTACT_LAWS)} (a law registers "
            "itself when the module defining it is imported: import it first)"
        )
    return cls(**params)
