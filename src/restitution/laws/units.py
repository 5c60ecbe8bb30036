"""The edge between SI units and the package's reduced units.

Inside, everything is reduced: ``E = rho = R = 1`` of the body's own constants, speeds in units
of ``c = sqrt(E/rho)`` of them: the **two-dimensional** constants of eq. (6) for the disk, the
three-dimensional ones for the sphere. At the edge a user names

* a material by its three-dimensional constants: Young modulus ``E`` in Pa, Poisson number
  ``nu``, density ``rho`` in kg/m^3 (any consistent units work; speeds then come out in
  ``sqrt(unit of E / unit of rho)``);
* a geometry, which picks the body whose law is served and the constants of ``c``:

  - ``"cylinder"``: a long cylinder hit along a diameter, the disk in plane strain, eq. (2):
    ``E_2d = E / (1 - nu^2)``, law parameter ``nu_2d = nu / (1 - nu)``,
    ``c = sqrt(E_2d / rho)``;
  - ``"thin-disk"``: the disk in plane stress: ``E_2d = E``, ``nu_2d = nu``, ``c = sqrt(E/rho)``;
  - ``"sphere"``: the elastic sphere with the 3D constants as they are: law parameter ``nu``
    itself (in ``(-1, 0.5)``), ``c = sqrt(E / rho)``; no two-dimensional constants exist;

* a collision partner: ``"wall"`` (the model's rigid flat wall, hit at speed ``w``: ``v = w/c``)
  or ``"grain"`` (two identical grains at relative normal speed ``w``: by symmetry each moves at
  ``w/2`` towards the contact plane, so ``v = w / (2c)``): the ``against`` of a partner kind
  (:mod:`restitution.laws.partners`), whose ``speed_factor`` and ``speed_meaning`` these are.

The radius never enters ``epsilon`` (the model has no other length), so it is not asked for.
Every result of this module says which geometry and partner it belongs to.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import numpy as np

from restitution.bodies.kinds import BodyKind, geometries, kinds
from restitution.bodies.material import Material
from restitution.errors import InputError, describe, is_real, non_negative
from restitution.laws.partners.base import against_choices, by_against

__all__ = [
    "BODIES",
    "GEOMETRIES",
    "PARTNERS",
    "SHAPES",
    "SLOWEST_V",
    "Grain",
    "partner_factor",
]

Shape = str
"""A shape name: how a real grain is made of a kind of body (:data:`SHAPES`). The package's
vocabulary: a *kind* (``disk``, ``sphere``; :mod:`restitution.bodies.kinds`) is the modal body
whose law serves, a *shape* (``cylinder``, ``thin-disk``, ``sphere``) the real grain in SI
units; ``geometry`` meant either and is kept where it always named a kind (the reduced units'
commands and functions) and as a deprecated alias of ``shape`` here."""
Against = str
"""The collision partner of an SI answer: the ``against`` of a registered partner kind
(:data:`PARTNERS`)."""


def _shape_kinds() -> dict[str, BodyKind]:
    """Geometry name -> the kind of body whose law serves it: the
    :attr:`~restitution.bodies.kinds.BodyKind.shapes` of every kind, the default kind's first
    (a kind registered later included)."""
    every = kinds()
    return {shape: every[name] for name in geometries() for shape in every[name].shapes}


SHAPES: dict[str, str | None] = {
    shape: kind.shapes[shape] for shape, kind in _shape_kinds().items()
}
"""Shape name -> plane condition of eq. (2); ``None`` for the sphere (a 3D body): the
``shapes`` of the package's kinds (:attr:`~restitution.bodies.kinds.BodyKind.shapes`)."""

GEOMETRIES = SHAPES
"""Deprecated name of :data:`SHAPES`."""

BODIES: dict[str, str] = {shape: kind.geometry for shape, kind in _shape_kinds().items()}
"""Geometry name -> the body whose law serves it (:data:`restitution.bodies.kinds.GEOMETRIES`),
from the same ``shapes``."""


def _choices(shapes: dict[str, BodyKind]) -> str:
    """``'cylinder' (plane strain), 'thin-disk' (plane stress) or 'sphere'``: the geometries,
    each with its plane condition where it has one."""
    names = [
        f"'{shape}' (plane {kind.shapes[shape]})" if kind.shapes[shape] else f"'{shape}'"
        for shape, kind in shapes.items()
    ]
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


class _Partners(Mapping):
    """``against`` -> what the speed ``w`` means: the registered partner kinds' (read when
    asked, so a kind registered later is in it)."""

    def __getitem__(self, against: str) -> str:
        if against not in against_choices():
            raise KeyError(against)
        return by_against(against).speed_meaning

    def __iter__(self) -> Iterator[str]:
        return iter(against_choices())

    def __len__(self) -> int:
        return len(against_choices())


PARTNERS: Mapping[str, str] = _Partners()
"""Collision partner (``against``) -> what the speed ``w`` means."""


def partner_factor(against: str) -> float:
    """``k`` in ``v = w / (k c)``: 1 against a wall, 2 for two identical grains (the partner
    kind's :attr:`~restitution.laws.partners.base.PartnerKind.speed_factor`)."""
    return by_against(against).speed_factor


SLOWEST_V = 1e-16
"""Slowest nonzero reduced speed (``c``) a grain is asked about. The sphere's vibrational loss
there is 1.05e-17 (Rayleigh's estimate at nu = 0.3; ``1 - epsilon`` rounds to 0), and the
routes' quadratures of the contact pulse are not sized for the ever longer pulses below it."""


@dataclass(frozen=True, init=False)
class Grain:
    """A grain material in SI units, its shape, and the conversion to reduced units.

    Parameters
    ----------
    E : float
        Three-dimensional Young modulus, Pa.
    nu : float
        Three-dimensional Poisson number, in (-1, 0.5] (``< 0.5`` for a cylinder and a sphere).
    rho : float
        Three-dimensional density, kg/m^3.
    shape : {"cylinder", "thin-disk", "sphere"}
        Long cylinder (the disk in plane strain), thin disk (plane stress) or sphere
        (:data:`SHAPES`); ``geometry=`` is its deprecated alias.

    Examples
    --------
    >>> g = Grain(E=210e9, nu=0.3, rho=7850, shape="thin-disk")
    >>> round(g.c_m_s)
    5172
    >>> round(float(g.v_over_c(1.0, "grain")), 7)
    9.67e-05
    >>> s = Grain(E=210e9, nu=0.3, rho=7850, shape="sphere")
    >>> (s.body, s.law_nu, round(s.c_m_s))
    ('sphere', 0.3, 5172)
    """

    E: float
    nu: float
    rho: float
    shape: Shape

    def __init__(self, E, nu, rho, shape=None, *, geometry=None) -> None:
        if shape is None:
            shape = geometry
        elif geometry is not None and geometry != shape:
            raise InputError(
                f"shape={shape!r} and geometry={geometry!r}: give one (geometry is the old name "
                "of shape)"
            )
        for name, value in (("E", E), ("nu", nu), ("rho", rho), ("shape", shape)):
            object.__setattr__(self, name, value)
        self.__post_init__()

    def __post_init__(self) -> None:
        shapes = _shape_kinds()
        if not (isinstance(self.shape, str) and self.shape in shapes):
            raise InputError(f"the geometry must be {_choices(shapes)}, got {describe(self.shape)}")
        for name, unit in (("E", "Pa"), ("nu", "dimensionless"), ("rho", "kg/m^3")):
            value = getattr(self, name)
            if not is_real(value):
                raise InputError(
                    f"{name} must be a number ({unit}), got {describe(value)}; pass {name} as a "
                    "float"
                )
            object.__setattr__(self, name, float(value))
        # One-line messages for E, nu, rho: the 3D checks of Material.from_3d (nu in
        # (-1, 0.5]), then, where the 3D nu is the law's (a sphere), the kind's open interval.
        Material.from_3d(E=self.E, nu=self.nu, plane=self.plane or "stress", rho=self.rho)
        if not self.kind.planar:
            self.kind.check_nu(self.nu)
        # E and rho each in range of a float, their ratio not: c = 0 divided every speed by zero
        # (a numpy warning, then v/c = inf), c = inf made every speed 0 ("need v > 0").
        c = self.c_m_s
        if not (math.isfinite(c) and c > 0.0):
            raise InputError(
                f"E = {self.E:.3g} Pa and rho = {self.rho:.3g} kg/m^3 give the speed unit "
                f"{self.c_formula.split(',')[0]} = {c:.3g} m/s, not a finite speed; check the "
                "units of E (Pa) and rho (kg/m^3)"
            )

    @property
    def geometry(self) -> str:
        """Deprecated name of :attr:`shape`."""
        return self.shape

    @property
    def kind(self) -> BodyKind:
        """The kind of body whose law serves this grain (the kind whose
        :attr:`~restitution.bodies.kinds.BodyKind.shapes` name its geometry)."""
        return _shape_kinds()[self.shape]

    @property
    def body(self) -> str:
        """The body whose law serves this grain: ``"disk"`` (cylinder, thin disk) or
        ``"sphere"``."""
        return self.kind.geometry

    @property
    def plane(self) -> str | None:
        """``"strain"`` for a cylinder, ``"stress"`` for a thin disk, ``None`` for a sphere."""
        return self.kind.shapes[self.shape]

    def _planar_only(self, what: str) -> None:
        if not self.kind.planar:
            raise InputError(
                f"a {self.shape} has no {what}: its law takes the 3D nu (Grain.law_nu) and "
                "c = sqrt(E / rho) (Grain.c_m_s)"
            )

    @property
    def material(self) -> Material:
        """The 2D constants per unit thickness (``E_2d`` in Pa, ``rho`` in kg/m^3); disks only."""
        self._planar_only("two-dimensional material")
        return Material.from_3d(E=self.E, nu=self.nu, plane=self.plane, rho=self.rho)

    @property
    def nu_2d(self) -> float:
        """Two-dimensional Poisson number of eq. (6), the disk law's parameter; disks only."""
        self._planar_only("two-dimensional Poisson number")
        return self.material.nu

    @property
    def E_2d(self) -> float:
        """Two-dimensional Young modulus per unit thickness, Pa; disks only."""
        self._planar_only("two-dimensional Young modulus")
        return self.material.E

    @property
    def law_nu(self) -> float:
        """The Poisson number of the law that serves this grain: ``nu_2d`` for a disk, ``nu``
        itself for a sphere."""
        return self.nu_2d if self.kind.planar else float(self.nu)

    @property
    def law_E(self) -> float:
        """The Young modulus of the law's reduced units, Pa: ``E_2d`` for a disk, ``E`` itself
        for a sphere (what a partner's modulus ratio is made of)."""
        return self.E_2d if self.kind.planar else float(self.E)

    @property
    def law_nu_name(self) -> str:
        """What :attr:`law_nu` is called: ``"nu_2d"`` (disk) or ``"nu"`` (sphere), the kind's
        :attr:`~restitution.bodies.kinds.BodyKind.nu_name`."""
        return self.kind.nu_name

    @property
    def c_m_s(self) -> float:
        """The velocity unit, m/s: ``c = sqrt(E_2d / rho)`` for a disk, ``sqrt(E / rho)`` with
        the 3D ``E`` for a sphere."""
        if self.kind.planar:
            return self.material.c
        return math.sqrt(self.E / self.rho)

    @property
    def c_formula(self) -> str:
        """How :attr:`c_m_s` is made, in words."""
        if self.kind.planar:
            return "c = sqrt(E_2d / rho), E_2d the two-dimensional Young modulus"
        return "c = sqrt(E / rho), the three-dimensional constants"

    def speed_scale(self, against: str) -> float:
        """``k c`` in m/s: the SI speed ``w`` that corresponds to ``v = 1``."""
        return partner_factor(against) * self.c_m_s

    def v_over_c(self, speed_m_s, against: str):
        """Reduced speed ``v`` (towards the wall, units of ``c``) of SI speed(s) ``w``.

        Parameters
        ----------
        speed_m_s : float or array_like
            Impact speed ``w`` in m/s: towards the wall, or the relative normal speed of two
            grains; non-negative.
        against : {"wall", "grain"}
            Collision partner.

        Returns
        -------
        float or numpy.ndarray
            ``v = w / (k c)`` with ``k = 1`` (wall) or ``2`` (grain).
        """
        w = non_negative(speed_m_s, "speeds", "m/s")
        scale = self.speed_scale(against)
        v = w / scale
        slow = (np.asarray(v) > 0) & (np.asarray(v) < SLOWEST_V)
        if np.any(slow):  # issue 47: 1e-300 m/s (or E = 1e300 Pa) ended in a ZeroDivisionError
            first = float(np.asarray(w)[slow].flat[0])
            raise InputError(
                f"the speed {first:.3g} m/s is {first / scale:.3g} c of this grain (c = "
                f"{self.c_m_s:.3g} m/s): below {SLOWEST_V:g} c the vibrational loss (under "
                f"1e-17) vanishes in double precision and epsilon is 1; ask for at least "
                f"{SLOWEST_V * scale:.3g} m/s"
            )
        return float(v) if np.ndim(speed_m_s) == 0 else v

    def speed_m_s(self, v, against: str):
        """SI speed ``w`` (m/s) of reduced speed(s) ``v``: the inverse of :meth:`v_over_c`."""
        v_arr = non_negative(v, "speeds", "units of c")
        w = v_arr * self.speed_scale(against)
        return float(w) if np.ndim(v) == 0 else w

    def to_dict(self) -> dict:
        """JSON-ready description with units in every key.

        Every grain: ``E_Pa``, ``nu``, ``rho_kg_m3`` (the 3D constants as given), ``shape``,
        ``kind`` (the kind of body whose law serves), ``geometry`` and ``body`` (their
        deprecated names, kept for scripts), ``law_nu`` (the law's Poisson number), ``c_m_s`` and
        ``c_formula``. A disk adds ``plane``, ``E_2d_Pa`` and ``nu_2d``; a sphere has no 2D
        constants and no such keys.
        """
        out = {
            "E_Pa": self.E,
            "nu": self.nu,
            "rho_kg_m3": self.rho,
            "shape": self.shape,
            "kind": self.body,
            "geometry": self.shape,
            "body": self.body,
        }
        if self.kind.planar:
            out.update(plane=self.plane, E_2d_Pa=self.E_2d, nu_2d=self.nu_2d)
        out.update(law_nu=self.law_nu, c_m_s=self.c_m_s, c_formula=self.c_formula)
        return out

    def describe(self) -> str:
        """One line: material, geometry, the law's constants and ``c``."""
        head = f"E = {self.E:.4g} Pa, nu = {self.nu:g}, rho = {self.rho:.4g} kg/m^3, "
        if not self.kind.planar:
            return (
                head + f"{self.shape} (3D constants as they are): law nu = {self.nu:g}, "
                f"c = sqrt(E/rho) = {self.c_m_s:.6g} m/s"
            )
        plane = "plane strain" if self.plane == "strain" else "plane stress"
        return head + f"{self.shape} ({plane}): nu_2d = {self.nu_2d:.6g}, c = {self.c_m_s:.6g} m/s"
