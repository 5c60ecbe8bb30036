"""Two free bodies of one kind meeting head-on, as one modal body for the contact.

Units: the reduced units of the *first* body, ``E1 = rho1 = R1 = 1`` (its Young modulus, density
and radius; for disks the 2D constants), ``c = c1 = sqrt(E1/rho1)``, frequencies in ``c1/R1``.
The second body has ``R2 = radius_ratio``, ``E2 = modulus_ratio``, ``rho2 = density_ratio`` in
these units; its own modes (computed in its own reduced units) are rescaled here.

**The formulation** (docs/two-disks.md). The bodies approach along the ``x`` axis, the first
from the left. In the centre-of-mass frame only the separation of the centres couples to the
contact; it carries the reduced mass ``mu = m1 m2 / (m1 + m2)``. The contact acts on the gap
between the two deformed surfaces: the surface points of both bodies are paired by their
undeformed height ``y`` above the axis, ``y = R1 sin(phi1) = R2 sin(phi2)``, and the gap at
``y`` is the distance along the axis between the paired points::

    g(y) = X2 - X1 - [R1 cos(phi1) + u1(phi1)] - [R2 cos(phi2) + u2(phi2)]

with ``u_i`` the displacement of body ``i``'s surface point towards the other body (each body's
own wall basis, eq. 40 for a disk). The potential is the paper's exponential, integrated over
the surface of the smaller body (the reference; the first on a tie)::

    V = (1/alpha) int exp(-alpha g) dA_ref

(``dA_ref`` the reference body's arc length for disks, area for spheres). Pairing by undeformed
height neglects the difference of the two points' tangential displacements, a term of second
order in the contact's slope; for two identical bodies moving mirror-symmetrically the paired
points are mirror images and the gap is exactly twice the distance to the mid-plane.

**The composite body.** With ``x0 = X1 - X2 + R1 + R2 - 1``, ``g = -(x0 + H + u1 + u2)`` and
``H = R1 cos(phi1) + R2 cos(phi2) - R2`` (``H = 1`` at the tip): exactly the wall problem of a
body whose centre is ``x0``, whose surface heights are ``H`` and whose modes are both bodies'
modes. Every mode coordinate is rescaled to the common mass ``mu`` (``Q' = sqrt(m_i / mu) Q``,
so its amplitudes ``C, S`` shrink by ``sqrt(mu / m_i)``): the kinetic energy is then
``(mu/2)(x0'^2 + sum Q'^2)`` and the compiled kernel integrates the pair unchanged. ``x0'`` is
the relative speed ``w`` of the centres: ``epsilon = -w_after / w_before``, energies are
fractions of ``(mu/2) w^2``, the kinetic energy in the centre-of-mass frame.

**Two identical bodies** (same kind, Poisson number and constants, equal radii): the pair at
relative speed ``w`` and hardness ``alpha`` is the body on a wall at ``v = w/2`` with
``alpha_wall = 2 alpha`` (the gap is twice the distance to the mid-plane): the quadrature, the
heights ``2 cos(phi) - 1``, the steps and the start are those of the wall problem, and
``tests/test_pair.py`` checks the identity to round-off.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from restitution.bodies.base import ModalBody, SurfaceQuadrature, surface_quadrature
from restitution.bodies.kinds import BodyKind, kinds
from restitution.errors import InputError

__all__ = ["BodyPair", "pair_of"]


def _kind(name: str) -> BodyKind:
    """The kind of both bodies (:class:`~restitution.bodies.kinds.BodyKind`: its dimension
    scales masses like ``R^dimension`` and surfaces like ``R^(dimension - 1)``; its
    ``basis_at`` gives the surface basis at arbitrary angles, needed when the radii differ)."""
    found = kinds().get(name)
    if found is None:
        raise InputError(f"no pair of {name}s is defined")
    return found


@dataclass(frozen=True, eq=False)
class BodyPair:
    """Two bodies of one kind as one modal body for their head-on contact (module docs).

    Implements :class:`restitution.bodies.base.ModalBody`; its modes are a selection
    (:attr:`index`) of both bodies' modes, rescaled to the first body's units and the reduced
    mass.

    Attributes
    ----------
    first, second : ModalBody
        The two bodies, each in its own reduced units, of one ``geometry``.
    radius_ratio, modulus_ratio, density_ratio : float
        ``R2 / R1``, ``E2 / E1`` and ``rho2 / rho1``.
    index : numpy.ndarray of int, shape (N,)
        The pair's modes as indices into ``first``'s modes followed by ``second``'s.
    """

    first: ModalBody
    second: ModalBody
    radius_ratio: float = 1.0
    modulus_ratio: float = 1.0
    density_ratio: float = 1.0
    index: np.ndarray = field(default=None)  # type: ignore[assignment]

    def __post_init__(self) -> None:
        if self.first.geometry != self.second.geometry:
            raise InputError(
                f"a pair needs two bodies of one kind, got a {self.first.geometry} and a "
                f"{self.second.geometry}"
            )
        _kind(self.first.geometry)
        for name in ("radius_ratio", "modulus_ratio", "density_ratio"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise InputError(f"{name} must be a positive number, got {value!r}")
        total = len(self.first) + len(self.second)
        if self.index is None:
            object.__setattr__(self, "index", np.arange(total))
        index = np.asarray(self.index, dtype=int)
        if index.ndim != 1 or index.size == 0 or index.min() < 0 or index.max() >= total:
            raise InputError(f"a pair's mode index must select from its {total} modes")
        object.__setattr__(self, "index", index)
        s1, s2 = self._scales()
        ratio = math.sqrt(self.modulus_ratio / self.density_ratio) / self.radius_ratio
        both = {
            "omega": np.r_[self.first.omega, self.second.omega * ratio],
            "C": np.r_[self.first.C * s1, self.second.C * s2],
            "S": np.r_[self.first.S * s1, self.second.S * s2],
            "n": np.r_[self.first.n, self.second.n],
            "l": np.r_[self.first.l, self.second.l],
            "order": np.r_[self.first.order, self.second.order],
            "member": np.r_[np.zeros(len(self.first), int), np.ones(len(self.second), int)],
        }
        for name, values in both.items():
            object.__setattr__(self, "_" + name, values[index])

    # -- what the pair is -------------------------------------------------------------------

    @property
    def geometry(self) -> str:
        """``"<kind>-pair"``, e.g. ``"disk-pair"``."""
        return f"{self.first.geometry}-pair"

    @property
    def kind(self) -> str:
        """The kind of both bodies (``"disk"``, ``"sphere"``)."""
        return self.first.geometry

    @property
    def nu(self) -> float:
        """The first body's Poisson number."""
        return float(self.first.nu)

    @property
    def nu2(self) -> float:
        """The second body's Poisson number."""
        return float(self.second.nu)

    @property
    def member_masses(self) -> tuple[float, float]:
        """``(m1, m2)`` in the first body's units (``rho1 R1^d``)."""
        d = _kind(self.first.geometry).dimension
        return (
            float(self.first.mass),
            float(self.second.mass) * self.density_ratio * self.radius_ratio**d,
        )

    @property
    def mass(self) -> float:
        """The reduced mass ``mu = m1 m2 / (m1 + m2)``: of the relative coordinate and, after
        rescaling, of every mode."""
        m1, m2 = self.member_masses
        return m1 * m2 / (m1 + m2)

    @property
    def identical(self) -> bool:
        """Whether both bodies are one body twice: same constants, radius and modes (then the
        pair is the body on a wall at half the speed, module docs)."""
        return (
            self.radius_ratio == 1.0
            and self.modulus_ratio == 1.0
            and self.density_ratio == 1.0
            and self.first.nu == self.second.nu
            and len(self.first) == len(self.second)
            and np.array_equal(self.first.omega, self.second.omega)
        )

    omega = property(lambda self: self._omega, doc="Frequencies, ``c1 / R1``, shape (N,).")
    C = property(lambda self: self._C, doc="Normal surface amplitudes, rescaled, shape (N,).")
    S = property(lambda self: self._S, doc="Tangential surface amplitudes, rescaled, (N,).")
    n = property(lambda self: self._n, doc="First mode label of each mode's own body, (N,).")
    l = property(lambda self: self._l, doc="Second mode label of each mode's own body, (N,).")  # noqa: E741
    member = property(lambda self: self._member, doc="0 for the first body's modes, 1 else.")

    @property
    def order(self) -> np.ndarray:
        """Angular order of every mode in its own body, shape (N,)."""
        return self._order

    def __len__(self) -> int:
        return int(self.index.size)

    def take(self, index) -> BodyPair:
        """The modes at ``index`` (integer or boolean array), in the order given."""
        idx = np.arange(len(self))[index]
        return BodyPair(
            self.first,
            self.second,
            self.radius_ratio,
            self.modulus_ratio,
            self.density_ratio,
            self.index[idx],
        )

    def lowest(self, count: int) -> BodyPair:
        """The ``count`` lowest-frequency modes of both bodies together: one common frequency
        cutoff, not a common count."""
        if count > len(self):
            raise InputError(f"asked for {count} modes but the pair holds only {len(self)}")
        return self.take(np.argsort(self.omega, kind="stable")[:count])

    def _members(self) -> tuple[ModalBody, ModalBody]:
        """Each body restricted to the pair's modes, in the pair's order within each."""
        n1 = len(self.first)
        return (
            self.first.take(self.index[self.index < n1]),
            self.second.take(self.index[self.index >= n1] - n1),
        )

    # -- the contact ------------------------------------------------------------------------

    @property
    def radii(self) -> tuple[float, float]:
        """``(R1, R2)`` in the first body's units."""
        return 1.0, float(self.radius_ratio)

    @property
    def effective_radius(self) -> float:
        """``R1 R2 / (R1 + R2)``: the gap near the axis is ``y^2 / (2 R_eff)``."""
        r1, r2 = self.radii
        return r1 * r2 / (r1 + r2)

    def _reference(self) -> int:
        """Which body's surface carries the potential: the smaller (the first on a tie)."""
        return 0 if self.radius_ratio >= 1.0 else 1

    def contact_nodes(self, s: float) -> int:
        """Nodes on the reference body's surface for a contact zone of gap depth ``1 / s``:
        those it needs for a zone of the same width on its own surface, ``s R_ref / R_eff`` in
        its own units, and those each body's orders need (``2 s`` for identical bodies, as on
        the wall)."""
        ref_radius = self.radii[self._reference()]
        a_ref = float(s) * ref_radius / self.effective_radius * ref_radius
        return max(m.contact_nodes(a_ref) for m in self._members() if len(m))

    def surface_quadrature(self, n_nodes: int) -> SurfaceQuadrature:
        """The gap quadrature with ``n_nodes`` nodes of the reference body (module docs)."""
        members = self._members()
        bodies = (self.first, self.second)
        radii = self.radii
        ref = self._reference()
        # Each body with the reference's radius uses its own quadrature, built once; the nodes
        # and weights are the reference body's (of its own modes, or of all if it has none
        # here), scaled to R1 = 1.
        own_quads = [
            member.surface_quadrature(int(n_nodes)) if len(member) and radii[i] == radii[ref]
            else None
            for i, member in enumerate(members)
        ]  # fmt: skip
        rq = own_quads[ref] or bodies[ref].surface_quadrature(int(n_nodes))
        psi = rq.nodes
        weight = rq.weight * radii[ref] ** (_kind(self.kind).dimension - 1)
        y = radii[ref] * np.sin(psi)
        height = -radii[1] * np.ones_like(psi)
        normal, tangential = [], []
        column = np.empty(len(self), int)
        C, S = np.empty(len(self)), np.empty(len(self))
        offset = 0
        for i, (member, scale) in enumerate(zip(members, self._scales(), strict=True)):
            if radii[i] == radii[ref]:
                height += radii[i] * rq.height
            else:
                angle = np.arcsin(np.clip(y / radii[i], -1.0, 1.0))
                height += radii[i] * np.cos(angle)
            if not len(member):
                continue
            if radii[i] == radii[ref]:
                own = own_quads[i]
                if not np.array_equal(own.nodes, psi):
                    raise InputError("bodies of one kind must share their quadrature nodes")
                basis, own_column, own_C, own_S = own.basis, own.column, own.C, own.S
            else:
                basis_at = _kind(self.kind).basis_at
                if basis_at is None:
                    raise InputError(
                        f"pairs of {self.kind}s of different radii are not implemented yet; "
                        "give equal radii"
                    )
                orders, own_column = np.unique(member.order, return_inverse=True)
                basis, own_C, own_S = basis_at(orders, angle), member.C, member.S
                # The stop test and the active-node bound take basis values of magnitude <= 1:
                # a tangential column beyond it (the sphere's dP_l/dtheta grows like l) is
                # divided by its largest magnitude and that order's S multiplied by it, so
                # S * basis is unchanged (a disk's columns never exceed 1 and stay as they are).
                k = basis.shape[1] // 2
                top = np.max(np.abs(basis[:, k:]), axis=0, initial=0.0)
                top = np.where(top > 1.0, top, 1.0)
                basis = np.hstack([basis[:, :k], basis[:, k:] / top])
                own_S = own_S * top[own_column]
            k = basis.shape[1] // 2
            normal.append(basis[:, :k])
            tangential.append(basis[:, k:])
            sel = self.member == i
            column[sel] = own_column + offset
            C[sel], S[sel] = own_C * scale, own_S * scale
            offset += k
        basis = np.hstack(normal + tangential)
        return surface_quadrature(psi, weight, height, basis, column, C, S)

    def residual_flexibility(self, quad: SurfaceQuadrature, count: int) -> np.ndarray:
        """The static flexibility of both bodies' modes above the pair's set on the first
        ``count`` nodes of the pair's quadrature ``quad``, shape (count, count), first body's
        units (the static residual, :mod:`restitution.dynamics.residual`).

        One force on the gap compresses both bodies, and the gap closes by the sum of their
        displacements: the pair's flexibility is the sum of each body's own residual (its
        :meth:`~restitution.bodies.base.ModalBody.residual_flexibility` with the modes the
        pair keeps of it), the second body's carried to the first's units by
        ``R2^(2-d) / E2`` (a displacement in ``R``, a force in ``E R^(d-1)``). Both bodies
        must share the nodes: equal radii only."""
        if self.radius_ratio != 1.0:
            raise InputError(
                f"the static residual of a pair needs equal radii (got R2/R1 = "
                f"{self.radius_ratio:g}): the bodies' surface nodes differ; collide the pair "
                "without the residual"
            )
        d = _kind(self.kind).dimension
        factors = (1.0, self.radius_ratio ** (2 - d) / self.modulus_ratio)
        total = np.zeros((int(count), int(count)))
        for body, member, factor in zip(
            (self.first, self.second), self._members(), factors, strict=True
        ):
            own = getattr(body, "residual_flexibility", None)
            if not callable(own):
                raise InputError(f"the {body.geometry} has no static residual yet")
            total += factor * member.residual_flexibility(quad, count)
        return total

    def _scales(self) -> tuple[float, float]:
        """``sqrt(mu / m_i)``: what each body's amplitudes are multiplied by (module docs)."""
        m1, m2 = self.member_masses
        mu = self.mass
        return math.sqrt(mu / m1), math.sqrt(mu / m2)

    def surface_matrix(self, nodes: np.ndarray) -> np.ndarray:
        """Dense displacement towards the other body per unit (rescaled) ``Q_k`` at the
        reference body's angles ``nodes``, shape (M, N); for checks and baselines."""
        radii = self.radii
        y = radii[self._reference()] * np.sin(np.asarray(nodes, dtype=float))
        out = np.empty((y.size, len(self)))
        n1 = len(self.first)
        bodies = (self.first, self.second)
        for i, (body, scale) in enumerate(zip(bodies, self._scales(), strict=True)):
            sel = self.member == i
            if not sel.any():
                continue
            own = self.index[sel] - (n1 if i else 0)
            angle = np.arcsin(np.clip(y / radii[i], -1.0, 1.0))
            out[:, sel] = body.take(own).surface_matrix(angle) * scale
        return out

    def contact_time_estimate(self, w):
        """An estimate of the contact time at relative speed ``w`` (``c1``), ``R1 / c1``: the
        longer of the two bodies' own estimates against a wall at ``w / 2`` (exact for
        identical bodies). It only sizes the run; the quasistatic theory of two bodies is
        :mod:`restitution.quasistatic.hertz_pair`."""
        w = np.asarray(w, dtype=float)
        speed_ratio = math.sqrt(self.modulus_ratio / self.density_ratio)
        t1 = self.first.contact_time_estimate(0.5 * w)
        t2 = self.second.contact_time_estimate(0.5 * w / speed_ratio)
        return np.maximum(t1, t2 * self.radius_ratio / speed_ratio)

    def depth_transform(self, s):
        """``int exp(-s (1 - H)) dA_ref`` (``1 - H`` the gap's depth): the Gaussian of the
        gap's curvature, ``sqrt(pi R_eff / (2 s))`` per side for disks (``R1``; the quarter arc
        of the reference body for small ``s``), ``2 pi R_eff / s`` for spheres (``R1^2``)."""
        s = np.asarray(s, dtype=float)
        r_eff = self.effective_radius
        ref_radius = self.radii[self._reference()]
        if _kind(self.first.geometry).dimension == 2:
            return np.minimum(0.5 * math.pi * ref_radius, np.sqrt(0.5 * math.pi * r_eff / s))
        return 2.0 * math.pi * r_eff * (1.0 - np.exp(-s * ref_radius / r_eff)) / s

    def member_energies(self, mode_energy: np.ndarray) -> tuple[float, float]:
        """Split per-mode energies (shape (N,), in the pair's order) into each body's share."""
        e = np.asarray(mode_energy, dtype=float)
        return float(e[self.member == 0].sum()), float(e[self.member == 1].sum())


def pair_of(
    first: ModalBody,
    second: ModalBody | None = None,
    *,
    radius_ratio: float = 1.0,
    modulus_ratio: float = 1.0,
    density_ratio: float = 1.0,
) -> BodyPair:
    """Two bodies as a :class:`BodyPair`; ``second`` defaults to ``first`` (an identical pair).

    ``first`` and ``second`` are each in their own reduced units; the ratios are the second
    body's constants in units of the first's. All modes of both are kept: take a common
    frequency cutoff with :meth:`BodyPair.lowest` or by computing both up to one frequency.
    """
    return BodyPair(
        first,
        first if second is None else second,
        float(radius_ratio),
        float(modulus_ratio),
        float(density_ratio),
    )
