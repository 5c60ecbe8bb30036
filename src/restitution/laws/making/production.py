"""The shipped epsilon(v) laws: what they are computed from, and how to regenerate them.

``make law`` (``python -m restitution.laws.making.production``) recomputes every disk law file
``restitution/laws/data/law_nu<nu>.json`` with the current code; ``python -m
restitution.laws.making.production --geometry sphere`` computes the sphere's,
``law_sphere_nu<nu>.json`` (each kind's :attr:`~restitution.bodies.kinds.BodyKind.production`:
:func:`production`);
``make law-pair`` (``--geometry pair``) the laws of two
disks of one material, ``law_pair_r<R2/R1>_nu<nu>.json`` (:data:`PAIR_RADIUS_RATIOS`,
:data:`PAIR_NUS`, :func:`pair_groups`). All go through the same sweep, store and
extrapolation as ``restitution curve`` (:mod:`restitution.limits.curves`), with a progress bar. The
result store is reused, so an interrupted run resumes. ``tests/test_every_body.py`` fails
when the shipped files no longer match the code. ``make law`` then draws the slow-point figures
with :mod:`restitution.reproduction.law_figures` (laws never import the reproduction layer).

Two groups of speeds, both with walls scaled to the compression (``alpha delta_max(v) = 40,
80, 160``):

* the paper's speeds ``0.02 <= v <= 0.3`` with the ``N = 1880, 3760, 7520, 15040`` lowest
  modes (the paper used 300-940; with those most points fail the curvature test);
* slower speeds ``1e-4 <= v <= 0.01`` with windows from ``N = 3200 ... 25600`` to
  ``N = 12800 ... 102400`` (:data:`SLOW`). The contact half-width shrinks with the
  compression, so slow collisions need far more modes before the energy loss is linear in
  ``1/sqrt(N)``: at ``v = 1e-3`` (``nu = 0.33``) the loss still falls by 5% per doubling of
  ``N`` between 1600 and 25600, linearly in ``1/sqrt(N)`` from 3200 on (docs/results.md).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from restitution.bodies.cache import writable_folder
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind, kinds
from restitution.errors import InputError
from restitution.laws.low_speed import low_speed_points, low_speed_route, low_speeds_of, routed
from restitution.limits.run_options import Executor, Progress, executor_of, progress_of
from restitution.limits.sweep import SweepSettings, pair_settings, planned

__all__ = [
    "PAIR_NUS",
    "PAIR_RADIUS_RATIOS",
    "PAIR_WALL_GROUPS",
    "SETTINGS_GROUPS",
    "SHIPPED_NUS",
    "PAPER",
    "build",
    "rejoin_low_speeds",
    "reextrapolate",
    "DISK_LOW_SPEEDS",
    "PAIR_LOW_SPEEDS",
    "pair_groups",
    "PAIR_TWO_MATERIALS",
    "route_pair_laws",
    "production",
    "production_groups",
]

_DISK = body_kind(DEFAULT_GEOMETRY)


def production_groups(geometry: str) -> tuple[SweepSettings, ...]:
    """The sweeps behind the shipped laws of the body ``geometry`` on the wall (its kind's
    :attr:`~restitution.bodies.kinds.BodyKind.production`, whose declaration says how each
    window was chosen); every point of a law records the group it came from."""
    plan = _plan(geometry)
    return tuple(planned(geometry, g) for g in plan.groups)


def _plan(geometry: str):
    plan = body_kind(geometry).production
    if plan is None:
        raise InputError(
            f"no production settings for the geometry {geometry!r}; choose one of "
            f"{', '.join(_produced())}"
        )
    return plan


def _produced() -> list[str]:
    """The kinds that have production settings."""
    return [name for name, kind in kinds().items() if kind.production is not None]


SHIPPED_NUS = _DISK.production.nus
"""Two-dimensional Poisson numbers of the shipped disk laws: the paper's 0.33 and 0.9 (Fig. 1)
and a grid for real materials between them and beyond, served in between by interpolation in
nu with an error estimated from leave-one-out errors (:mod:`restitution.laws.law_nu`). The first
grid was 0.2, 0.33, 0.5, 0.7, 0.9; 0.25, 0.428571, 0.6 and 0.8 joined after they were computed
as direct checks of the interpolation between those five (docs/materials.md)."""

SETTINGS_GROUPS = production_groups(DEFAULT_GEOMETRY)
"""The sweeps behind every shipped disk law: the paper's speeds ``0.02 <= v <= 0.3`` and the
slower ones with their growing mode windows."""

PAPER = SETTINGS_GROUPS[0]
"""The disk's group of the paper's speeds (``0.02 <= v <= 0.3``, ``N = 1880 ... 15040``)."""

# -- two bodies -------------------------------------------------------------------------------

PAIR_RADIUS_RATIOS = _DISK.pair_production.radius_ratios
"""Radius ratios ``R2 / R1 >= 1`` of the shipped laws of two disks of one material (ratio 1 is the
disk on the wall at half the speed, the disk's own law)."""

PAIR_NUS = _DISK.pair_production.nus
"""Two-dimensional Poisson numbers of the pairs' laws: the paper's 0.33 and 0.9 (Fig. 1) and
steel cylinders (plane strain, ``nu = 0.3``: ``nu_2d = 0.3 / 0.7``). Glass cylinders
(``nu = 0.2481``) have ``nu_2d = 0.33``."""

PAIR_WALL_GROUPS = tuple(planned(DEFAULT_GEOMETRY, g) for g in _DISK.pair_production.groups)
"""The disk's groups that the pairs' groups are made of (:func:`pair_groups`): its speeds
``0.02 <= v <= 0.3``, ``1e-3``, and ``2.5e-3, 5e-3, 1e-2`` with the windows of ``5e-3``
(the disk's kind says why)."""


def _steel_glass(shape: str, radius_ratio: float):
    """``(law nu, Partner)`` of a steel grain of ``shape`` with a glass one ``radius_ratio``
    times as large."""
    from restitution.laws.si_law import pair_partner
    from restitution.laws.units import Grain

    steel = Grain(E=210e9, nu=0.3, rho=7850.0, shape=shape)
    glass = Grain(E=63e9, nu=0.2481, rho=2500.0, shape=shape)
    return steel.law_nu, pair_partner(steel, glass, radius_ratio)


PAIR_TWO_MATERIALS = (_steel_glass("cylinder", 1.4),)
"""``(nu_2d, Partner)`` of the shipped laws of two disks of two materials: a steel cylinder
(``E = 210 GPa``, ``nu = 0.3``, ``rho = 7850 kg/m^3``) with a glass cylinder (``63 GPa``,
``0.2481``, ``2500 kg/m^3``) 1.4 times as large, in the steel's plane-strain units
(:func:`restitution.laws.si_law.pair_partner`). Other pairs of materials are computed on
demand (:func:`restitution.laws.making.compute.computed_law`, ``restitution law ... --compute``)."""


def _routed_pairs():
    """The kinds whose pairs' laws are their low-speed route alone (no modal groups: the
    sphere)."""
    return [k for k in kinds().values() if k.pair_production and not k.pair_production.groups]


def route_pair_laws() -> list[tuple[str, float, object]]:
    """``(geometry, nu, Partner)`` of every shipped law of a pair made by its low-speed route
    alone (``make law-sphere-pair``): each such kind's pair plan (for the sphere radius ratios
    1.5, 2 and 4 at ``nu = 0.3``) and a steel grain of the kind with a glass one of its size
    (the constants of :data:`PAIR_TWO_MATERIALS`, the kind's own)."""
    from restitution.bodies.pair.partner import Partner

    out = []
    for kind in _routed_pairs():
        plan = kind.pair_production
        out += [(kind.geometry, nu, Partner(radius_ratio=r))
                for r in plan.radius_ratios for nu in plan.nus]  # fmt: skip
        out.append((kind.geometry, *_steel_glass(next(iter(kind.shapes)), 1.0)))
    return out


def pair_groups(
    partner, groups=None, geometry: str = DEFAULT_GEOMETRY
) -> tuple[SweepSettings, ...]:
    """The sweeps of the law of two bodies of the kind ``geometry``: each of the kind's wall
    groups for pairs (:attr:`~restitution.bodies.kinds.PairPlan.groups`; the disk's are
    :data:`PAIR_WALL_GROUPS`) carried over by :func:`restitution.limits.sweep.pair_settings`
    (relative speeds ``w = 2 v``, walls on the pair's compression scale, mode windows
    ``N (1 + r^2 rho2 / E2)``).

    ``partner`` is the second body, a :class:`~restitution.bodies.pair.partner.Partner` (any
    material), or a radius ratio ``R2 / R1`` for a body of the same material."""
    from restitution.bodies.pair.partner import Partner

    if not isinstance(partner, Partner):
        partner = Partner(radius_ratio=float(partner))
    if groups is None:
        plan = body_kind(geometry).pair_production
        if plan is None:
            raise InputError(
                f"laws of two {geometry}s are not computed on demand; pairs of "
                f"{', '.join(k.geometry + 's' for k in _paired())} are"
            )
        groups = tuple(planned(geometry, g) for g in plan.groups)
    return tuple(pair_settings(g, partner) for g in groups)


def _paired():
    """The kinds whose pairs have production settings."""
    return [kind for kind in kinds().values() if kind.pair_production is not None]


def _collided():
    """The kinds whose pairs' laws are made of collisions (``--geometry pair``: the disk)."""
    return [kind for kind in _paired() if kind.pair_production.groups]


DISK_LOW_SPEEDS = _DISK.production.low_speeds
"""Speeds of the disk's low-speed points (:func:`low_speed_points`,
:mod:`restitution.quasistatic.slow_disk`), ``c``: from ``1e-7`` (0.5 mm/s for a steel cylinder)
up to the modal laws' slowest speed ``1e-4``, a factor 1.07 apart. The loss varies slowly in
``ln v`` there; each point's error includes what PCHIP through its neighbours strays from it
(:func:`low_speed_points`)."""

PAIR_LOW_SPEEDS = _DISK.pair_production.low_speeds
"""Relative speeds ``w`` of the low-speed points of two disks' laws (``c1``), a factor 1.1
apart: the disk's speeds doubled, up to ``1e-3``, where three cuts of the model still fit at
``nu = 0.9`` (the pairs' modal points start at ``w = 2e-3``)."""


def production(
    geometry: str = DEFAULT_GEOMETRY,
) -> tuple[tuple[float, ...], tuple[SweepSettings, ...]]:
    """``(nus, groups)`` of the shipped laws of the body ``geometry``."""
    return _plan(geometry).nus, production_groups(geometry)


def build(
    out_dir: str | Path,
    nus=SHIPPED_NUS,
    groups=SETTINGS_GROUPS,
    *,
    store=None,
    executor: Executor | None = None,
    progress: Progress | bool | None = None,
    low_speeds=None,
    workers: int | None = None,
    refine_rounds: int = 1,
    geometry: str | None = None,
    partner=None,
) -> list[Path]:
    """Compute the laws for ``nus`` and write them into ``out_dir``.

    The body is the groups' ``geometry`` and ``partner`` (one for all): the files are
    :func:`restitution.laws.law.law_filename` ``(nu, geometry, partner)``, ``law_nu<nu>.json``
    for the disk, ``law_sphere_nu<nu>.json`` for the sphere and ``law_pair_r<r>_nu<nu>.json``
    for two disks (:func:`pair_groups`).

    Parameters
    ----------
    out_dir : path
        Target folder (``src/restitution/laws/data`` for the shipped files).
    nus : iterable of float
        Poisson numbers: two-dimensional for the disk, three-dimensional for the sphere.
    groups : iterable of SweepSettings
        Sweeps whose points are merged into each law (speeds must not repeat), all of one body.
    store, executor, progress
        Passed to :func:`restitution.limits.curves.compute_curves` (``workers``: the older
        spelling of ``executor=Executor(workers=...)``); the progress bar also shows the
        low-speed points.
    low_speeds : iterable of float, optional
        Speeds of the low-speed points joined to each law (:func:`low_speed_points`); default
        the body's production speeds (:func:`low_speeds_of`), ``()`` for none.
    refine_rounds : int
        Rounds of :func:`restitution.laws.making.refine.refine`: a point computed, with its
        neighbour's settings, wherever epsilon(v) turns unresolved between the groups' speeds
        (``0``: the groups' speeds only).
    geometry, partner
        The body of a law without collisions (no ``groups``: the low-speed route alone, as for
        two spheres); with groups they are the groups'.

    Returns
    -------
    list of Path
        The files written.
    """
    from restitution.laws.law import EpsilonLaw
    from restitution.laws.law_file import law_filename
    from restitution.laws.making.refine import refine
    from restitution.limits.curves import compute_curves

    groups = tuple(groups)
    if groups:
        bodies = {g.geometry for g in groups}
        if len(bodies) != 1:
            raise InputError(
                f"the groups of one law need one body, got {', '.join(sorted(bodies))}"
            )
        geometry = bodies.pop()
        partners = {g.partner for g in groups}
        if len(partners) != 1:
            raise InputError(
                "the groups of one law need one partner (one pair, or all on the wall)"
            )
        partner = partners.pop()
    elif geometry is None:
        raise InputError("a law without collisions (no groups) needs its geometry")
    out = writable_folder(out_dir)  # the laws are written at the end: refused before the work
    nus = [float(nu) for nu in nus]
    if low_speed_route(geometry, partner) is None and (
        not groups or (low_speeds is not None and tuple(low_speeds))
    ):
        raise InputError(
            f"low-speed points are derived for {', '.join(routed())}, not for the "
            f"{geometry}{' pair' if partner is not None else ''}"
        )
    for nu in nus:  # in seconds, not after every collision of a window has failed
        _check_windows(nu, groups, store)
    per_group = [
        compute_curves(nus, g, store=store, executor=executor, workers=workers, progress=progress)
        for g in groups
    ]
    written = []
    for nu in nus:
        low = tuple(low_speeds_of(geometry, partner, nu) if low_speeds is None else low_speeds)
        if not groups:  # a law of the low-speed route alone (two spheres)
            records, parameters = low_speed_points(
                nu, low, geometry=geometry, partner=partner, progress=progress
            )
            law = EpsilonLaw.from_records(
                nu, records, key="low_speed", parameters=parameters, geometry=geometry,
                partner=partner,
            )  # fmt: skip
            written.append(law.to_json(out / law_filename(nu, geometry, partner)))
            continue
        law = EpsilonLaw.from_curves([curves[nu] for curves in per_group])
        law = refine(
            law, rounds=refine_rounds, store=store,
            executor=executor_of(executor, workers=workers), progress=progress_of(progress),
        )  # fmt: skip
        if low:
            records, parameters = low_speed_points(
                nu, low, geometry=geometry, partner=partner, progress=progress
            )
            law = law.joined(records, key="low_speed", parameters=parameters)
        written.append(law.to_json(out / law_filename(nu, geometry, partner)))
    return written


def _check_windows(nu: float, groups, store) -> None:
    """Refuse a law whose mode windows cannot be built at ``nu``
    (:func:`restitution.limits.grid_check.check_mode_sets`), in the production's words."""
    from restitution.limits.grid_check import check_mode_sets
    from restitution.limits.sweep import grid

    specs = [s for g in groups for s in grid([nu], g)]
    try:
        check_mode_sets(specs, store)
    except InputError as exc:
        kind = body_kind(specs[0].geometry)
        plan = kind.production
        reach = f" (its shipped laws reach nu = {max(plan.nus):g})" if plan else ""
        raise InputError(
            f"no law of the production at nu = {nu:g}: {exc}; its mode windows are fixed"
            f"{reach}; smaller windows (`restitution curve --modes`, without --production) "
            "may still be built"
        ) from None


def rejoin_low_speeds(path: str | Path, speeds=None, *, progress: Progress | bool = False) -> Path:
    """Compute the low-speed points of the law file ``path`` again and join them to its modal
    points (which stay as they are), writing the file in place.

    Parameters
    ----------
    path : path
        A law of a disk or a sphere on a wall.
    speeds : iterable of float, optional
        The low speeds; default the body's production speeds (:func:`low_speeds_of`).
    progress : Progress or bool
        The progress bar (:class:`restitution.limits.run_options.Progress`).
    """
    from restitution.laws.law import EpsilonLaw

    law = EpsilonLaw.from_json(path).modal_part()
    geometry, partner = law.geometry, law.partner
    low = low_speeds_of(geometry, partner, law.nu) if speeds is None else tuple(map(float, speeds))
    records, parameters = low_speed_points(
        law.nu, low, geometry=geometry, partner=partner, progress=progress
    )
    return law.joined(records, key="low_speed", parameters=parameters).to_json(path)


def reextrapolate(path: str | Path) -> Path:
    """Redo the extrapolation of every modal point of the law file ``path`` from its stored
    loss grid with the current code (:meth:`restitution.laws.law.EpsilonLaw.reextrapolated`),
    writing the file in place."""
    from restitution.laws.law import EpsilonLaw

    return EpsilonLaw.from_json(path).reextrapolated().to_json(path)


def _count(groups, nus) -> int:
    return sum(len(g.velocities) * len(g.alphas) * len(g.n_modes) for g in groups) * len(nus)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description="Regenerate the shipped epsilon(v) laws.")
    parser.add_argument("--out", default=str(Path(__file__).parents[1] / "data"))
    parser.add_argument(
        "--geometry",
        choices=(*_produced(), "pair", "sphere-pair"),
        default=DEFAULT_GEOMETRY,
        help="the body: disk (law_nu<nu>.json), sphere (law_sphere_nu<nu>.json), pair (two "
        "disks of one material, law_pair_r<R2/R1>_nu<nu>.json for PAIR_RADIUS_RATIOS, and the "
        "steel-glass pair of PAIR_TWO_MATERIALS) or sphere-pair (two spheres by their "
        "low-speed route: route_pair_laws())",
    )
    parser.add_argument("--workers", type=int, default=None, help="local processes")
    parser.add_argument("--store", default=None, help="result store (default: user cache)")
    parser.add_argument(
        "--low-speeds-only",
        action="store_true",
        help="recompute only the low-speed points of the laws in --out and join them to their "
        "modal points",
    )
    parser.add_argument(
        "--reextrapolate-only",
        action="store_true",
        help="redo every law's extrapolations in --out from their stored loss grids (no "
        "collisions): after a change of the extrapolation's error rules",
    )
    args = parser.parse_args(argv)
    if args.reextrapolate_only:
        for path in sorted(Path(args.out).glob("law_*.json")):
            print(f"wrote {reextrapolate(path)}", flush=True)
        return
    if args.geometry == "sphere-pair":
        start = time.perf_counter()
        for geometry, nu, partner in route_pair_laws():
            (path,) = build(args.out, [nu], (), geometry=geometry, partner=partner,
                            progress=True)  # fmt: skip
            print(f"wrote {path}", flush=True)
        print(f"{len(route_pair_laws())} laws in {time.perf_counter() - start:.0f} s")
        return
    if args.low_speeds_only:
        from restitution.bodies.pair.partner import Partner
        from restitution.laws.law_file import law_filename

        start = time.perf_counter()
        if args.geometry == "pair":
            names = [law_filename(nu, kind.geometry, Partner(radius_ratio=r))
                     for kind in _collided() for r in kind.pair_production.radius_ratios
                     for nu in kind.pair_production.nus]  # fmt: skip
            names += [law_filename(nu, DEFAULT_GEOMETRY, p) for nu, p in PAIR_TWO_MATERIALS]
        else:
            names = [law_filename(nu, args.geometry, None) for nu in production(args.geometry)[0]]
        for name in names:
            print(f"wrote {rejoin_low_speeds(Path(args.out) / name, progress=True)}", flush=True)
        print(f"low-speed points of {len(names)} laws in {time.perf_counter() - start:.0f} s")
        return
    if args.geometry == "pair":
        runs = [(kind.pair_production.nus, pair_groups(r, geometry=kind.geometry))
                for kind in _collided() for r in kind.pair_production.radius_ratios]  # fmt: skip
        runs += [((nu,), pair_groups(p)) for nu, p in PAIR_TWO_MATERIALS]
    else:
        runs = [production(args.geometry)]
    start = time.perf_counter()
    files = []
    for nus, groups in runs:
        files += build(args.out, nus, groups, store=args.store, workers=args.workers, progress=True)
    elapsed = time.perf_counter() - start
    n = sum(_count(groups, nus) for nus, groups in runs)
    for path in files:
        print(f"wrote {path}")
    print(f"{n} collisions (stored ones reused) in {elapsed:.0f} s, {n / elapsed:.2f} collisions/s")


if __name__ == "__main__":
    main()
