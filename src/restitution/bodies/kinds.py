"""The kinds of body the package knows, by name: everything the layers above need of a kind.

Units: ``E = rho = R = 1`` of the body's own constants (the disk's two-dimensional plane-stress
constants, the sphere's three-dimensional ones); speeds in ``c = sqrt(E / rho)``; compressions in
``R``; times in ``R / c``; frequencies in ``c / R``.

A :class:`~restitution.bodies.base.ModalBody` answers for itself once its modes are computed.
Everything else the layers above ask of a kind -- which Poisson numbers it takes and which one
that is, how many modes lie below a frequency, how far a wall compresses it, its default walls
and mode windows, how its law files are named, the route of its slow impacts, the settings its
shipped laws were computed with, the units of its output -- is one :class:`BodyKind`. The
layers above read these attributes; they never compare a kind's name.

**Adding a kind** is one new package ``restitution/bodies/<name>/`` whose module ``kind.py``
builds its :class:`BodyKind` and passes it to :func:`register`. The registry finds the packages
itself (:func:`kinds`, scipy's ``solve_ivp`` ``METHODS`` in spirit): no module outside the new
package is edited. A kind outside the package (a user's, a test's toy kind) is a module that
calls :func:`register` on import, named in the environment variable :data:`PLUGINS_ENV` so that
the spawned workers of a sweep find it too; :func:`unregister` removes a kind again.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import os
import pkgutil
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from restitution.bodies.base import ModalBody
from restitution.errors import InputError, real

__all__ = [
    "DEFAULT_GEOMETRY",
    "PLUGINS_ENV",
    "GEOMETRIES",
    "KINDS",
    "BodyKind",
    "PairPlan",
    "ProductionPlan",
    "SweepPlan",
    "body_kind",
    "geometries",
    "kind_of",
    "register",
    "unregister",
]

DEFAULT_GEOMETRY = "disk"
"""The body of the paper, the default of every function and command that takes a kind."""


@dataclass(frozen=True)
class SweepPlan:
    """One group of a sweep as plain numbers (the limits layer builds its ``SweepSettings``).

    Attributes
    ----------
    velocities : tuple of float or None
        Speeds, ``c`` (``None``: the package's default speeds).
    n_modes : tuple of int
        The mode window of the ``N -> infinity`` extrapolation.
    batch_size : int or None
        Collisions per task (``None``: the default).
    """

    velocities: tuple[float, ...] | None
    n_modes: tuple[int, ...]
    batch_size: int | None = None

    def fields(self) -> dict:
        """The sweep fields this plan sets (the others keep the kind's defaults)."""
        out: dict = {"n_modes": tuple(self.n_modes)}
        if self.velocities is not None:
            out["velocities"] = tuple(self.velocities)
        if self.batch_size is not None:
            out["batch_size"] = self.batch_size
        return out


@dataclass(frozen=True)
class ProductionPlan:
    """How the shipped laws of a kind on the rigid wall are computed, and what that costs.

    Attributes
    ----------
    nus : tuple of float
        Poisson numbers of the shipped laws (the kind's :attr:`BodyKind.nu_name`).
    groups : tuple of SweepPlan
        The sweeps behind every law (walls: the kind's :attr:`BodyKind.alpha_products`).
    low_speeds : tuple of float
        Speeds (``c``) of the low-speed points joined below the collisions (may be empty).
    seconds_per_collision : float
        Measured wall time of one production collision on one core, s.
    seconds_per_low_point : float
        Measured wall time of one low-speed point, s.
    residual_seconds_per_point : float or None
        Measured wall time of one point by the residual route
        (:mod:`restitution.laws.making.residual_law`) on one core, s; ``None``: the kind has no
        static residual.
    """

    nus: tuple[float, ...]
    groups: tuple[SweepPlan, ...]
    low_speeds: tuple[float, ...] = ()
    seconds_per_collision: float = 1.0
    seconds_per_low_point: float = 1.0
    residual_seconds_per_point: float | None = None


@dataclass(frozen=True)
class PairPlan:
    """How the laws of two bodies of a kind are computed (their walls, windows and costs).

    Attributes
    ----------
    radius_ratios : tuple of float
        ``R2 / R1`` of the shipped laws of one material.
    nus : tuple of float
        Poisson numbers of those laws.
    groups : tuple of SweepPlan
        The body-on-wall groups a pair's groups are carried over from (speeds doubled, walls
        on the pair's compression scale, windows scaled by the pair's mode density).
    low_speeds : tuple of float
        Relative speeds (``c1``) of the pairs' low-speed points.
    seconds_at_5, cost_power : float
        A pair's seconds per collision is ``seconds_at_5 (scale / 5)^cost_power`` with
        ``scale`` its windows over the wall's (never below the body's own on the wall).
    seconds_per_low_point : float
        Wall time of one of the pairs' low-speed points, s.
    residual_seconds_per_point : float or None
        One point of a pair by the residual route on one core at window scale 1, s (times the
        pair's window scale); ``None``: none.
    """

    radius_ratios: tuple[float, ...]
    nus: tuple[float, ...]
    groups: tuple[SweepPlan, ...]
    low_speeds: tuple[float, ...] = ()
    seconds_at_5: float = 1.0
    cost_power: float = 2.0
    seconds_per_low_point: float = 1.0
    residual_seconds_per_point: float | None = None


@dataclass(frozen=True)
class BodyKind:
    """Everything known about a kind of body before its modes are computed (module docs).

    Attributes
    ----------
    geometry : str
        The name (``"disk"``, ``"sphere"``), equal to the bodies' ``geometry``.
    description : str
        One line for users: the body and which constants its reduced units are made of.
    dimension : int
        Space dimension: masses scale like ``R^dimension``, surfaces like ``R^(dimension-1)``.
        A two-dimensional kind takes two-dimensional constants, made from a material's 3D
        ones by a plane condition (eq. 2): :attr:`planar`.
    nu_low, nu_high : float
        The open interval of allowed Poisson numbers (of the body's own elasticity).
    mode_class : type
        The dataclass of its mode sets (the cache stores its array fields).
    algorithm : int
        Version of the mode algorithm (part of the mode cache key).
    compute : callable
        ``compute(nu, count=None, omega_max=None)`` -> mode set (no cache).
    weyl_count : callable
        ``weyl_count(omega, nu)``: leading estimate of the number of modes below ``omega``.
    max_compression : callable
        ``max_compression(v, nu)``: quasistatic largest compression against a rigid wall, ``R``.
    contact_time : callable
        ``contact_time(v, nu)``: quasistatic contact time against a rigid wall, ``R / c``.
    max_modes : int
        Most modes the mode cache computes (their cost is measured in the module of the modes).
    units : dict of str to str
        The units of every number reported for this body (every JSON output carries them).
    order_name : str
        What the angular order of a mode is called in its records (``"n"``, ``"l"``).
    modes_title : str
        One line over a table of its modes.
    shapes : mapping of str to str or None
        The real grains this kind stands for in SI units, each with the plane condition
        (``"strain"``, ``"stress"``) that makes the kind's constants from the grain's 3D ones,
        or ``None`` where the 3D constants are the kind's own.
    shape_words : mapping of str to str
        Each shape in words, for the heads of exported files.
    file_tag : str
        The kind's part of file names (law files, FEM references); ``""`` for the disk, whose
        files were named before there was another kind.
    alpha_products : tuple of float
        Default walls ``alpha * delta_max(v)`` of its sweeps and its FEM route.
    sweep_modes : tuple of int
        Default mode window of its sweeps.
    scales_need_nu : bool
        Whether :attr:`max_compression` depends on ``nu`` (then the walls of a sweep need it).
    law_model : str
        The model behind its laws, one paragraph (a law's ``model``).
    law_units : str
        What ``v`` and ``epsilon`` of its laws on the wall mean.
    low_speed_route : str or None
        Name of the route of its slow impacts on the wall (the quasistatic layer's routes,
        ``restitution.laws.making.production``); ``None``: none.
    pair_low_speed_route : str or None
        The same for two bodies of this kind.
    quasistatic_law : str or None
        Name of its quasistatic contact law on the rigid wall (one of the laws of its theory,
        :func:`restitution.quasistatic.pulse.contact_law_for`) on which the viscous loss of a
        damping body is computed (:mod:`restitution.laws.damped`); ``None``: the theory's
        default.
    basis_at : callable or None
        ``basis_at(orders, angle)``: the surface basis of the orders at any angles, shape
        (M, 2K) (what a pair of two radii needs); ``None``: not available.
    pair_compression : callable or None
        ``pair_compression(w, radius_ratio, modulus_ratio, density_ratio, nu1, nu2)``: the
        quasistatic largest approach of two such bodies' centres at relative speed ``w``
        (``c1``), ``R1`` (``nu1``, ``nu2`` their own Poisson numbers, which a kind with
        :attr:`scales_need_nu` needs); ``None``: pairs of this kind are not sized yet.
    production : ProductionPlan or None
        How its shipped laws on the wall are computed.
    pair_production : PairPlan or None
        How the laws of two bodies of this kind are computed.
    default_nus : tuple of float
        Poisson numbers of its curves when none are given (empty: they must be given).
    vibrating : bool
        Whether the vibrating-body layer (a ringing start, chains of collisions:
        ``collide --excite``, ``bounce``) takes this kind (docs/vibrating.md).
    ball : bool
        Whether the body is the ball of radius ``R`` of its dimension (the disk, the sphere),
        the body the finite-element route meshes: on the half disk, a planar kind's upper half
        or a three-dimensional kind's meridian section (:mod:`restitution.fem.section`).
    oblique_body : callable or None
        ``oblique_body(modes)``: from a mode set of this kind, the body an oblique collision
        with Coulomb friction takes (the disk: its rim in both mode families,
        :func:`restitution.bodies.disk.rim.rim_modes`, which
        :func:`restitution.dynamics.oblique.oblique_collision` consumes); ``None``: no oblique
        route for this kind yet (``law --angle`` and ``collide --angle`` refuse it).
    oblique_modes : int
        ``collide --angle``'s default mode count for this kind (the disk: 160 symmetric modes;
        the sphere: 20 axisymmetric, 146 in its cap of every azimuthal order).
    oblique_law : str or None
        Why ``law --angle`` does not serve this kind although it has an oblique body (the
        route's cost on the hard walls of real grains), or ``None``: it does.
    oblique_law_modes : int or None
        The modes of ``law --angle``'s answer (:func:`restitution.laws.oblique.oblique_answer`),
        its error the change from half as many; ``None``: :attr:`oblique_modes` (the disk: 160
        and 80; the sphere: 40 and 20, which the hard walls of real grains afford).
    oblique_quasistatic : str or None
        Name of the quasistatic oblique theory that is this kind's modal oblique route's limit
        at low speed (one stick/slip state for the contact; the names are
        :data:`restitution.laws.oblique.QUASISTATIC`'s keys: the sphere's ``"hertz-mindlin"``),
        served beside ``law --angle``'s ``beta``; ``None``: none is clean (the disk, whose
        tangential compliance has no Mindlin constant, docs/oblique.md).
    oblique_residual : bool
        Whether this kind's oblique body knows the static flexibility of the modes it drops at
        its contact (``contact_residual``), so that ``collide --angle --friction-model
        residual`` (:func:`restitution.dynamics.oblique_residual.residual_collision`) takes it.
    """

    geometry: str
    description: str
    dimension: int
    nu_low: float
    nu_high: float
    mode_class: type
    algorithm: int
    compute: Callable[..., ModalBody]
    weyl_count: Callable[[float, float], float]
    max_compression: Callable[[float, float], float]
    contact_time: Callable[[float, float], float]
    max_modes: int
    units: dict[str, str]
    order_name: str
    modes_title: str
    shapes: Mapping[str, str | None]
    shape_words: Mapping[str, str]
    file_tag: str
    alpha_products: tuple[float, ...]
    sweep_modes: tuple[int, ...]
    scales_need_nu: bool
    law_model: str
    law_units: str
    low_speed_route: str | None = None
    pair_low_speed_route: str | None = None
    quasistatic_law: str | None = None
    basis_at: Callable | None = None
    pair_compression: Callable | None = None
    production: ProductionPlan | None = None
    pair_production: PairPlan | None = None
    default_nus: tuple[float, ...] = ()
    vibrating: bool = False
    ball: bool = False
    oblique_body: Callable | None = None
    oblique_modes: int = 160
    oblique_law: str | None = None
    oblique_law_modes: int | None = None
    oblique_quasistatic: str | None = None
    oblique_residual: bool = False

    @property
    def name(self) -> str:
        """The kind's name (:attr:`geometry`)."""
        return self.geometry

    @property
    def planar(self) -> bool:
        """Whether its constants are two-dimensional ones, made from 3D constants by a plane
        condition (plane stress or plane strain, eq. 2)."""
        return self.dimension == 2

    @property
    def nu_name(self) -> str:
        """Which Poisson number its laws and modes take: ``"nu_2d"`` (a planar kind) or
        ``"nu"`` (the 3D one as it is)."""
        return "nu_2d" if self.planar else "nu"

    @property
    def option(self) -> str:
        """The command-line option that selects this kind (empty for the default kind)."""
        return "" if self.geometry == DEFAULT_GEOMETRY else f"--geometry {self.geometry}"

    def check_nu(self, nu) -> float:
        """``nu`` as a float if it is a number in ``(nu_low, nu_high)``, else
        :class:`InputError` naming ``nu`` (a bool or a string is not a number)."""
        allowed = f"in ({self.nu_low:g}, {self.nu_high:g})"
        nu = real(nu, "nu", f"{allowed} (the Poisson number of the {self.geometry})")
        if not self.nu_low < nu < self.nu_high:
            raise InputError(
                f"the Poisson number nu of the {self.geometry} must lie {allowed}, got {nu!r}; "
                f"pass nu {allowed}"
            )
        return nu

    def omega_for(self, count: int, nu: float) -> float:
        """The frequency below which about ``count`` modes lie (inverse of ``weyl_count``)."""
        return math.sqrt(count / self.weyl_count(1.0, nu))

    def file_name(self, head: str) -> str:
        """``head`` with the kind's :attr:`file_tag`: ``law`` -> ``law`` (disk) or
        ``law_sphere``."""
        return f"{head}_{self.file_tag}" if self.file_tag else head


def units_table(system: str, body: str, force: str, mass: str) -> dict[str, str]:
    """The :attr:`BodyKind.units` of a kind: ``system`` (what ``E = rho = R = 1`` are),
    ``body`` (its name in the speed's definition), the unit of force and the mass."""
    return {
        "system": system,
        "length": "R",
        "time": "R/c",
        "speed": f"c = sqrt(E/rho) (v: the {body}'s speed towards the wall)",
        "frequency": "c/R",
        "alpha": "1/R",
        "force": force,
        "energy": f"fraction of the initial kinetic energy (m/2) v^2, {mass}",
        "wall_time": "s",
    }


KINDS: dict[str, BodyKind] = {}
"""Every registered kind of body, by name (filled by :func:`register`; read it through
:func:`kinds`, which first finds the kinds of the package)."""

_found = False


PLUGINS_ENV = "RESTITUTION_KINDS"
"""Environment variable naming modules (comma-separated) that register kinds of their own: a
kind outside the package, known to every process of a sweep (spawned workers inherit it)."""


def _discover() -> None:
    """Import ``restitution.bodies.<name>.kind`` of every subpackage that has one, then the
    modules named in :data:`PLUGINS_ENV` (once)."""
    global _found
    if _found:
        return
    _found = True
    import restitution.bodies as package

    for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda i: i.name):
        if info.ispkg:
            name = f"{package.__name__}.{info.name}.kind"
            if importlib.util.find_spec(name) is not None:
                importlib.import_module(name)
    for name in filter(None, (n.strip() for n in os.environ.get(PLUGINS_ENV, "").split(","))):
        try:
            importlib.import_module(name)
        except ImportError as exc:
            raise InputError(
                f"{PLUGINS_ENV} names the module {name!r}, which does not import ({exc}); "
                f"fix the name or unset {PLUGINS_ENV}"
            ) from None


def register(kind: BodyKind) -> BodyKind:
    """Add ``kind`` to the registry (a kind's own ``kind.py`` calls it); returns it.

    Raises
    ------
    InputError
        If another kind of the same name is registered.
    """
    old = KINDS.get(kind.geometry)
    if old is not None and old is not kind:
        raise InputError(
            f"a body kind named {kind.geometry!r} is registered already; pick another name"
        )
    KINDS[kind.geometry] = kind
    return kind


def unregister(name: str) -> None:
    """Remove the kind ``name`` (a test's toy kind) from the registry."""
    KINDS.pop(name, None)


def kinds() -> dict[str, BodyKind]:
    """Every kind, by name, the package's own found first (:data:`DEFAULT_GEOMETRY` first)."""
    _discover()
    return KINDS


def geometries() -> tuple[str, ...]:
    """The names of every kind, the default first."""
    names = sorted(kinds())
    return tuple(sorted(names, key=lambda n: n != DEFAULT_GEOMETRY))


def body_kind(geometry: str) -> BodyKind:
    """The :class:`BodyKind` named ``geometry``; :class:`InputError` naming the choices if none."""
    found = kinds().get(geometry) if isinstance(geometry, str) else None
    if found is None:
        raise InputError(f"unknown geometry {geometry!r}; choose one of {', '.join(geometries())}")
    return found


def kind_of(body: ModalBody) -> BodyKind:
    """The kind of a body of one kind (for a pair: of both its bodies, ``body.kind``)."""
    return body_kind(getattr(body, "kind", body.geometry))


_discover()
GEOMETRIES: tuple[str, ...] = geometries()
"""The names of the package's own kinds, the disk first (a kind registered later is in
:func:`geometries`)."""
