"""The checks every body passes, written once and run for every body the package knows.

As scipy's ``solve_ivp`` tests every entry of its ``METHODS`` table and scikit-fem runs one
convergence test per element, these checks take their bodies from the registry: every
:class:`~restitution.bodies.kinds.BodyKind` in :data:`~restitution.bodies.kinds.KINDS` (its
modes from ``get_modes(nu, count, geometry=...)``, its wall from ``kind.max_compression``) and a
pair of unequal disks (:class:`~restitution.bodies.pair.Partner`). A kind registered in ``KINDS``
is checked here without an edit of this file. Its mode class must be a dataclass with the
arrays ``omega``, ``C`` and ``S`` (the rigid limits replace them).

Per body (speed ``V = 0.1`` of its own ``c``; the wall ``alpha = WALL / delta_max(V)``):

* the compiled kernel against the NumPy path (two codes of one algorithm);
* scipy's DOP853 on the same equations (an independent integrator and a dense wall matrix);
* time reversal: the symmetric splittings step back to the start, and a collision run back
  from its reversed final state returns all the vibration energy to the translation;
* the rigid limits: modes that do not touch the surface take no energy, stiffened modes less
  and less;
* the energy balance ``1 - epsilon^2 = sum of the mode energies``.

Per shipped law file (``restitution/laws/data/law_*.json``, every body and pair): the stored
points are physical and their flags are the current extrapolation's, and the cheapest stored
collisions have not moved (the stale-data test). Per body with shipped laws and per FEM
reference of pairs: the laws cover the finite-element reference points as their error bars
claim.
"""

from __future__ import annotations

import json
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from _sampling import representatives
from numpy.testing import assert_allclose

from restitution import get_modes
from restitution.bodies.base import ModalBody
from restitution.bodies.kinds import GEOMETRIES, KINDS, BodyKind
from restitution.bodies.pair import BodyPair, Partner
from restitution.dynamics.collision import CollisionSettings, collide, start_position
from restitution.dynamics.integrators import INTEGRATORS, System, free_modes, initial_state
from restitution.dynamics.reference import collide_dop853
from restitution.fem.judge import LawJudgement, judge_law
from restitution.fem.pair_reference import load_pair_reference
from restitution.fem.reference import load_reference, reference_filename
from restitution.laws.calibration import HARD_WALL
from restitution.laws.law import EpsilonLaw
from restitution.laws.law_file import law_filename
from restitution.laws.law_load import law
from restitution.laws.law_nu import shipped_nus
from restitution.laws.making.production import route_pair_laws
from restitution.limits.extrapolation import (
    alpha_curvature_shift,
    combined_limit,
    epsilon_from_loss,
    extrapolate_alpha,
)
from restitution.provenance import code_version

V = 0.1
"""Speed towards the wall, ``c`` of the body (the first body's for the pair)."""

WALL = 100.0
"""``alpha delta_max(V)``: a hard wall among the sweeps' 40-160 (``alpha`` = 521, 379 and 541
for the disk, the sphere and the pair below)."""

PARTNER = Partner(radius_ratio=1.4, modulus_ratio=2.0, density_ratio=0.5, nu=0.5)
"""The second disk of the pair: larger, stiffer, lighter, of another Poisson number, so that
the two bodies' modes differ in frequency, amplitude scale and order (tests/test_pair.py checks
the identical pair against the wall)."""


def _nu(kind: BodyKind) -> float:
    """A typical solid's 0.3 where the kind allows it, else the middle of its range."""
    return 0.3 if kind.nu_low < 0.3 < kind.nu_high else 0.5 * (kind.nu_low + kind.nu_high)


@dataclass(frozen=True)
class Body:
    """A body to check: its name, its ``count`` lowest modes, its compression at ``V``."""

    name: str
    modes: Callable[[int], ModalBody]
    max_compression: float

    @property
    def alpha(self) -> float:
        return WALL / self.max_compression


def _kind_body(kind: BodyKind) -> Body:
    nu = _nu(kind)
    return Body(
        kind.geometry,
        lambda count: get_modes(nu, count, geometry=kind.geometry),
        float(kind.max_compression(V, nu)),
    )


SPHERE_PARTNER = Partner(radius_ratio=1.4, modulus_ratio=2.0, density_ratio=0.5, nu=0.2)
"""The second sphere of the sphere pair: as the disks' partner, with a sphere's Poisson number
(the first sphere's is 0.3): its modes are sampled off the nodes of its own quadrature
(``BodyKind.basis_at``)."""


BODIES = [
    *(_kind_body(kind) for kind in KINDS.values()),
    # Pairs of different radii are computed for the kinds with a pair compression.
    Body(
        "disk-pair",
        lambda count: PARTNER.pair(_nu(KINDS["disk"]), count),
        float(PARTNER.max_compression(V)),
    ),
    Body(
        "sphere-pair",
        lambda count: SPHERE_PARTNER.pair(0.3, count, "sphere"),
        float(SPHERE_PARTNER.max_compression(V, "sphere", 0.3)),
    ),
]


@pytest.fixture(params=BODIES, ids=lambda b: b.name, scope="module")
def body(request) -> Body:
    return request.param


def _each_body(body: ModalBody, change) -> ModalBody:
    """``body`` with ``change`` applied to its own mode set (a pair: to both bodies')."""
    if isinstance(body, BodyPair):
        return replace(body, first=change(body.first), second=change(body.second))
    return change(body)


def test_every_body_is_a_modal_body(body):
    modes = body.modes(24)
    assert isinstance(modes, ModalBody) and len(modes) == 24
    assert modes.geometry == body.name


# -- the compiled kernel against the NumPy path ---------------------------------------------


def test_compiled_kernel_matches_the_numpy_path(body):
    """One algorithm, two codes: only the summation order of the reductions differs, so they
    agree to round-off. Measured at N = 60: at most 4.5e-14 in epsilon and 1.5e-14 in any mode
    energy (the pair), 2.5e-14 in the drift; the tolerances of tests/test_kernel.py (1e-12 in
    epsilon and mode energies, 1e-10 relative in the scalars, which depend on the step count)
    leave a margin of 20 and more. The step sequence must be the same."""
    modes = body.modes(60)
    fast = collide(modes, V, body.alpha, backend="compiled", energy_tol=1e-6)
    ref = collide(modes, V, body.alpha, backend="numpy", energy_tol=1e-6)
    assert fast.n_steps == ref.n_steps and fast.dt == ref.dt
    assert abs(fast.epsilon - ref.epsilon) < 1e-12, (fast.epsilon, ref.epsilon)
    for name in ("mode_energy_after", "mode_energy_mean", "mode_energy_closest"):
        assert_allclose(getattr(fast, name), getattr(ref, name), rtol=0, atol=1e-12, err_msg=name)
    for name in ("contact_time", "max_compression", "max_force"):
        assert_allclose(getattr(fast, name), getattr(ref, name), rtol=1e-10, err_msg=name)
    assert abs(fast.energy_drift - ref.energy_drift) < 1e-10


# -- scipy's DOP853 on the same equations ----------------------------------------------------


def test_agrees_with_dop853(body):
    """DOP853 (order 8, adaptive) with the dense surface matrix, no grouping by order: an
    independent integrator and wall assembly. Measured at N = 24: split4 at energy_tol 1e-10
    is 1.2e-10 (disk), 5.9e-11 (sphere), 4.7e-11 (pair) from it in epsilon and at most 8.6e-11
    in a mode energy; DOP853 moves by at most 6.4e-13 from rtol 1e-11 to 1e-12. The tolerance
    1e-9 is that of the disk's and the pair's former tests (the sphere's was 1e-8); the error
    scales with energy_tol, so a loss of accuracy of ten times shows.

    DOP853 with the solver's own order-by-order wall sums instead of the dense matrix isolates
    the wall evaluation from the integrator: measured 1.2e-14, 6.3e-15 and 1.8e-13 from the
    dense run; tolerance 1e-11."""
    modes = body.modes(24)
    dense = collide_dop853(modes, V, body.alpha, rtol=1e-11, atol=1e-13)
    orders = collide_dop853(modes, V, body.alpha, rtol=1e-11, atol=1e-13, wall="orders")
    assert abs(orders["epsilon"] - dense["epsilon"]) < 1e-11
    assert_allclose(orders["energy_after"], dense["energy_after"], rtol=0, atol=1e-11)
    r = collide(modes, V, body.alpha, integrator="split4", energy_tol=1e-10)
    assert dense["energy_drift"] < 1e-10 and r.energy_drift < 1e-10
    assert abs(r.epsilon - dense["epsilon"]) < 1e-9
    assert_allclose(r.mode_energy_after, dense["energy_after"], rtol=0, atol=1e-9)


# -- time reversal ------------------------------------------------------------------------------


@pytest.mark.parametrize("integrator", ["split", "split4"])
def test_symmetric_splittings_retrace_their_steps(body, integrator):
    """The symmetric splittings stepped back with flipped momenta retrace the trajectory
    through the stiff contact to round-off (measured at most 3.5e-15 after 2 x 400 steps;
    tolerance 1e-11 as before for the disk and the pair)."""
    modes = body.modes(24)
    quad = modes.surface_quadrature(300)
    system = System(omega=modes.omega, mass=modes.mass, quad=quad, alpha=np.array([body.alpha]))
    s0 = initial_state(system, np.array([-1.01]), np.array([modes.mass * V]))
    step = INTEGRATORS[integrator].step
    s = s0
    for _ in range(400):  # 0.1 R/c of flight, then 1.9 R/c into the contact
        s = step(system, s, 0.005)
    assert s.x0[0] > -1.0  # in contact
    back = replace(s, p0=-s.p0, P=-s.P)
    for _ in range(400):
        back = step(system, back, 0.005)
    assert_allclose(back.x0, s0.x0, atol=1e-11)
    assert_allclose(-back.p0, s0.p0, atol=1e-11)
    assert_allclose(back.Q, s0.Q, atol=1e-11)
    assert_allclose(-back.P, s0.P, atol=1e-11)


def test_reversed_collision_gives_the_vibration_back_to_the_translation(body):
    """Reverse every momentum of the final state and run the collision back: the body leaves
    at the speed it came with (``epsilon_back = 1 / epsilon``) and no vibration. Measured at
    N = 80: 8.7e-13 in the speed, 6e-17 of the vibration energy left; tolerances 1e-7 as the
    sphere's former test."""
    modes = body.modes(80)
    fwd = collide(modes, V, body.alpha, energy_tol=1e-10)
    u = fwd.epsilon * V
    # The reversed run starts where its centre passes the start position for speed u.
    tau = (start_position(modes, u, body.alpha) - fwd.final_x0) / u
    Q, P = free_modes(modes.omega, modes.mass, fwd.final_Q, -fwd.final_P, tau)
    back = collide(modes, u, body.alpha, initial=(Q, P), energy_tol=1e-10)
    assert back.epsilon * u == pytest.approx(V, rel=1e-7)
    assert back.mode_energy_after.sum() * (u / V) ** 2 < 1e-7 * fwd.mode_energy_after.sum()


# -- the rigid limits ---------------------------------------------------------------------------


def test_uncoupled_modes_give_an_elastic_rebound(body):
    """Modes that do not move the surface (C = S = 0) cannot take energy: epsilon = 1 to the
    energy tolerance (measured 6e-13) and no mode energy at all."""
    modes = body.modes(24)
    rigid = _each_body(modes, lambda m: replace(m, C=np.zeros(len(m)), S=np.zeros(len(m))))
    r = collide(rigid, V, body.alpha)
    assert abs(r.epsilon - 1.0) < 1e-9
    assert np.all(r.mode_energy_after == 0.0)


def test_stiffened_modes_take_less_and_less_energy(body):
    """Stiffening every mode drives the loss to zero. The wall force rises within
    ~1/(alpha v) = 0.02-0.03 R/c, so its spectrum reaches omega ~ 50: the loss vanishes once
    the lowest mode lies well above that (k = 100 puts it at omega = 145-165). Measured:
    losses[2] / losses[0] = 6e-7 (disk), 3e-7 (pair), round-off (sphere)."""
    modes = body.modes(24)
    losses = []
    for k in (1.0, 10.0, 100.0):
        stiff = _each_body(modes, lambda m, k=k: replace(m, omega=m.omega * k))
        losses.append(collide(stiff, V, body.alpha).energy_loss)
    assert losses[0] > losses[1] > losses[2]
    assert losses[2] < 1e-4 * losses[0]


# -- the energy balance ------------------------------------------------------------------------


def test_energy_lost_by_the_translation_sits_in_the_modes(body):
    """``1 - epsilon^2 = sum_k E_k`` after the collision, to the step's energy error: measured
    drifts 3e-8 to 9.5e-8 at N = 120, balance to 1e-12 (tolerance 2e-7, the disk's former
    test; the sphere's was 1e-5)."""
    r = collide(body.modes(120), V, body.alpha, energy_tol=1e-7)
    assert r.energy_drift < 1e-7
    assert_allclose(r.mode_energy_after.sum(), 1.0 - r.epsilon**2, rtol=0, atol=2e-7)
    assert np.all(r.mode_energy_after >= 0.0)
    assert 0.0 < r.epsilon < 1.0
    assert r.contact_time > 0 and r.max_compression > 0 and r.max_force > 0


# -- the shipped laws cannot go stale silently ------------------------------------------------

_DATA = resources.files("restitution.laws").joinpath("data")
LAW_FILES = sorted(p.name for p in _DATA.iterdir() if p.name.startswith("law_"))

ROUTE_LAW_FILES = sorted(
    law_filename(nu, geometry, partner) for geometry, nu, partner in route_pair_laws()
)
"""The laws of a low-speed route alone (two spheres; tests/test_sphere_pair.py checks their
points): no collisions to redo."""

MODAL_LAW_FILES = [name for name in LAW_FILES if name not in ROUTE_LAW_FILES]


def _meta(name: str) -> dict:
    return json.loads(_DATA.joinpath(name).read_text())["metadata"]


def _modal(points: list[dict]) -> list[dict]:
    """The points from collisions extrapolated in ``N`` (the low-speed points:
    tests/test_slow_disk.py and tests/test_sphere_laws.py; the residual route's: below)."""
    return [p for p in points if p.get("route") in (None, "modal")]


def _residual(points: list[dict]) -> list[dict]:
    """The points from collisions with a static residual (issue 65, item 2)."""
    return [p for p in points if p.get("route") == "residual"]


def _redo_residual(p: dict) -> tuple[float, float, bool]:
    """A residual-route point's hard-wall limit redone from its stored grid, as
    :func:`restitution.limits.residual_point.residual_point` makes it: ``(epsilon, error, ok)``."""
    r = p["residual"]
    point_err = np.hypot(r["mode_err"], r["step_err"])
    losses = np.array(r["energy_loss_grid"], dtype=float)[:, -1]
    fit = extrapolate_alpha(np.array(r["alpha"]), losses, loss_err=point_err)
    loss_err = math.hypot(fit.limit_err, alpha_curvature_shift(fit))
    eps, err = epsilon_from_loss(float(fit.limit), loss_err)
    return eps, err, bool(fit.asymptotic_ok)


def test_there_are_shipped_laws():
    assert {"law_nu0.33.json", "law_nu0.9.json", "law_sphere_nu0.3.json"} <= set(LAW_FILES)
    assert {"law_pair_r1.4_nu0.33.json", "law_pair_r2_nu0.9.json"} <= set(LAW_FILES)
    for geometry in GEOMETRIES:
        assert {law_filename(nu, geometry) for nu in shipped_nus(geometry)} <= set(LAW_FILES)


@pytest.mark.parametrize("name", LAW_FILES)
def test_shipped_law_points_are_physical_and_their_flags_truthful(name):
    """Every point's extrapolation, redone by the current code from the loss grid stored in the
    file, gives the stored epsilon, error and verdict, so a point that fails its checks cannot
    be served unflagged; the law serves the file's body."""
    meta = _meta(name)
    served = EpsilonLaw.from_json(_DATA.joinpath(name))
    assert served.geometry == meta["geometry"] in GEOMETRIES
    partner = meta.get("partner")
    assert served.partner == (None if partner is None else Partner.from_key(partner))
    modal, residual = _modal(meta["points"]), _residual(meta["points"])
    assert bool(modal) == (name not in ROUTE_LAW_FILES)
    assert served.v[~served.quasistatic].size == len(modal) + len(residual)
    rerouted = {c["v"] for c in (meta.get("rerouted") or {}).get("points", [])}
    assert rerouted == {p["v"] for p in residual}
    for p in residual:
        eps, err, ok = _redo_residual(p)
        assert eps == pytest.approx(p["epsilon"], rel=0, abs=1e-12), p["v"]
        assert err == pytest.approx(p["epsilon_err"], rel=1e-9), p["v"]
        assert ok == bool(p["asymptotic_ok"]) == (p["status"] == "ok"), p["v"]
    for p in meta["points"]:
        assert p["epsilon"] <= 1.0, (p["v"], p["epsilon"])
        assert np.isfinite(p["epsilon_err"]) and p["epsilon_err"] > 0
    for p in modal:
        ex = p["extrapolation"]
        redo = combined_limit(
            ex["alpha"],
            ex["n_modes"],
            np.array(ex["energy_loss_grid"], dtype=float),
            order=p["settings"]["order"],
        )
        assert redo.epsilon == pytest.approx(p["epsilon"], rel=0, abs=1e-12), p["v"]
        assert redo.epsilon_err == pytest.approx(p["epsilon_err"], rel=1e-9), p["v"]
        assert bool(redo.asymptotic_ok) == bool(p["asymptotic_ok"]), (p["v"], redo.message)


# One law of each kind by default (the disk's, the sphere's, a pair's: 13-15 s each for the
# sphere); every law with `make test-slow`.
_STALE_DEFAULT = {"law_nu0.33.json", "law_sphere_nu0.3.json", "law_pair_r1.4_nu0.33.json"}


@pytest.mark.parametrize("name", representatives(MODAL_LAW_FILES, _STALE_DEFAULT))
def test_shipped_law_cheap_collisions_have_not_moved(name):
    """Three of the cheapest stored collisions (the smallest mode count, softest wall; first,
    middle and last speed), recomputed by the current code with the file's own settings, have
    moved by less than a tenth of their point's error. A changed code version with unmoved
    numbers is only reported. Regenerate with `make law` (`law-sphere`, `law-pair`)."""
    meta = _meta(name)
    points = _modal(meta["points"])
    # The slow points need 1e4-1e5 modes; their stored grids are checked above.
    smallest = min(min(p["extrapolation"]["n_modes"]) for p in points)
    cheap = [p for p in points if min(p["extrapolation"]["n_modes"]) == smallest]
    geometry, partner = meta["geometry"], meta.get("partner")
    moved = []
    for p in (cheap[0], cheap[len(cheap) // 2], cheap[-1]):
        params = p["settings"]
        if params.get("select", "lowest") != "lowest":
            pytest.fail(f"{name}: the sample recomputation knows only the 'lowest' selection")
        settings = CollisionSettings(integrator=params["integrator"], **params["options"])
        ex = p["extrapolation"]
        j, i = int(np.argmin(ex["n_modes"])), int(np.argmin(ex["alpha"]))
        count = int(ex["n_modes"][j])
        if partner is None:
            modes = get_modes(meta["nu"], count, geometry=geometry)
        else:
            modes = Partner.from_key(partner).pair(meta["nu"], count, geometry=geometry)
        now = 1.0 - collide(modes, p["v"], ex["alpha"][i], settings).epsilon ** 2
        stored = ex["energy_loss_grid"][i][j]
        moved.append(abs(now - stored) / p["energy_loss_err"])
        assert abs(now - stored) <= 0.1 * p["energy_loss_err"], (
            f"{name}: the collision at v = {p['v']}, alpha = {ex['alpha'][i]:.4g}, N = {count} "
            f"moved from {stored:.8f} to {now:.8f}, more than a tenth of the point's error "
            f"{p['energy_loss_err']:.2e}; regenerate the law"
        )
    now = code_version(geometry, pair=partner is not None)
    if meta["code_version"] != now:
        warnings.warn(
            f"{name} was computed with code {meta['code_version']}, this is {now}; "
            f"its sampled collisions moved by at most {max(moved):.1e} of their point errors",
            stacklevel=1,
        )


# -- the shipped laws against their finite-element references ----------------------------------

PAIR_REFERENCES = sorted(
    p.name for p in _DATA.iterdir() if p.name.startswith("fem_reference_disk_pair")
)

FEM_REFERENCES = [
    *(
        pytest.param(
            lambda g=geometry: load_reference(geometry=g),
            lambda p, g=geometry: law(p.nu, geometry=g),
            id=reference_filename(geometry),
        )
        for geometry in GEOMETRIES
        if shipped_nus(geometry)  # a body that ships laws ships their judge
    ),
    *(
        pytest.param(
            lambda name=name: load_pair_reference(_DATA.joinpath(name)),
            lambda p: law(p.nu, partner=p.partner),
            id=name,
        )
        for name in PAIR_REFERENCES
    ),
]


def _served_on_harder_walls(law_, v: float) -> bool:
    """Whether ``law_`` serves its point at ``v`` from the residual route on walls other than
    the laws' own (tools/residual_wall_ladder.py --apply)."""
    for r in law_._records():
        if abs(r["v"] - v) <= 1e-9 * v and r.get("route") == "residual":
            return r["residual"]["walls"][0] >= HARD_WALL
    return False


def _ladder_soft_walls() -> dict[tuple[float, float], dict]:
    """``(nu, v) -> `` the wall ladder's limit on the laws' walls ``40, 80, 160``."""
    path = Path(__file__).parent / "data" / "residual_wall_ladder.json"
    return {(p["nu"], p["v"]): p["triples"][0] for p in json.loads(path.read_text())["points"]}


@pytest.mark.parametrize(("reference", "law_of"), FEM_REFERENCES)
def test_shipped_laws_cover_their_fem_reference(reference, law_of):
    """The finite-element route (its own mesh and wall limits, docs/fem.md) judges the shipped
    modal laws: each reference point's difference from its law in units of the combined error
    ``sqrt(err_FEM^2 + err_law^2)``.

    Both error bars claim one standard deviation (restitution.limits.extrapolation: close to
    the nominal 68 % coverage), so at least 68 % of the points must lie within one combined
    error (rounded down to whole points), and every point within two, the judge's rule for
    every body (docs/two-disks.md; stricter than the nominal 95 % for fewer than 20 points).
    Measured (sigma, nu, v; the tables: docs/results.md, docs/spheres.md, docs/two-disks.md):

    * disk, fem_reference.json, 10 points: 80 % within one, 100 % within two; +0.50 (0.33,
      1e-5), -0.78 (0.33, 1e-4), -0.41 (0.33, 1e-3), -0.05 (0.33, 0.01), +0.00 (0.33, 0.1),
      +1.41 (0.9, 1e-4, FEM flagged), +1.38 (0.9, 1e-3, FEM flagged), -0.01 (0.9, 0.01),
      +0.10 (0.9, 0.1), -0.27 (0.9, 0.3);
    * sphere, 14 points: all within 0.51;
    * pairs of disks, 5 points: -0.06, -0.02, -0.04, -0.10, +0.08; steel and glass, 3
      points: -0.05, -0.06, -0.40.

    The sphere's and the pairs' bars look too large rather than too small (all 22 points
    within 0.51, where honest ones would leave about 7 outside one); this test cannot see
    that.

    Where the law serves the residual route on walls 4 times harder than the laws' own
    (``alpha delta_max = 160-640``, docs/errors.md: the disk at ``v = 1e-4`` and, since the
    modal points up to 1e-3 are served so too, ``1e-3``, ``nu = 0.33`` and 0.9), the finite
    elements, which extrapolate from the laws' walls ``40-160``, are judged against the same
    route on their walls (the wall ladder's first triple, tests/data/residual_wall_ladder.json):
    measured within 0.06, 0.12, 0.00 and 0.06 combined errors, where the served hard-wall values
    lie 2.2, 2.4, 0.98 and 0.38 from them (the soft walls' bias, docs/errors.md). The table
    above lists the modal law's values at 1e-3, from before 4 Dec 2026.
    """
    points = reference()
    ladder = _ladder_soft_walls()
    served_hard = [p for p in points if _served_on_harder_walls(law_of(p), p.v)]
    for p in served_hard:
        soft = ladder[(p.nu, p.v)]
        sigma = (p.epsilon - soft["epsilon"]) / math.hypot(p.epsilon_err, soft["epsilon_err"])
        assert abs(sigma) <= 1.0, (p.nu, p.v, sigma)
    points = [p for p in points if p not in served_hard]
    judged = LawJudgement(tuple(row for p in points for row in judge_law([p], law_of(p)).points))
    table = judged.to_markdown()
    assert points and len(judged.compared) == len(points), table  # every point has a law value
    within_one = sum(abs(row.sigma) <= 1.0 for row in judged.compared)
    assert within_one >= math.floor(0.68 * len(points)), table
    assert judged.coverage(2.0) == 1.0, table


@pytest.mark.parametrize("geometry", sorted(KINDS))
def test_every_body_names_the_angular_order_alike(geometry):
    """Issue 40: the disk calls its angular order n, the sphere l; records and collision
    results also carry it as ``order``."""
    from restitution.dynamics.collision import collide

    modes = get_modes(0.3, count=12, geometry=geometry)
    records = modes.as_records()
    assert [r["order"] for r in records] == [int(o) for o in modes.order]
    assert [r[KINDS[geometry].order_name] for r in records] == [int(o) for o in modes.order]
    result = collide(modes, 0.1, 500.0)
    np.testing.assert_array_equal(result.mode_order, modes.order)
    assert [m["order"] for m in result.to_dict()["mode_energies_after"]] == list(modes.order)
