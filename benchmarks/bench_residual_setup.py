"""Benchmark: the sphere's residual route before its first step, the project against its baseline
(before stop 88).

Every run of the residual route (``law --angle`` on the sphere: two mode counts on two walls,
each built once for the estimate and once for the run) places the wall's nodes
(:func:`restitution.bodies.sphere.cap_nodes.cap_nodes`) and builds the hats' flexibilities
(``cap.contact_residual``, cached for an estimate and its run: the continuum's, from
:func:`restitution.bodies.sphere.contact_compliance._coefficients`, thousands of Legendre orders
for every annulus). Two changes of stop 88:

- ``_coefficients`` evaluates ``P_l`` and ``P_l'`` for a block of orders and takes the products
  with every load as one matrix product per block; the baseline is the former loop, one
  matrix-vector product per order and load kind, written out below.
- The nodes' angular functions take the Legendre series of ``d^j P_l / dx^j`` from a cache
  (``harmonics._derivative``); the baseline differentiates the series at every call (the
  cache's own undecorated function, ``__wrapped__``).

And in the run, the Jacobian of the tilted hats' Newton solve
(:class:`restitution.dynamics.contact.residual_hats.TiltedHatWall`, ``2K x 2K``): the project
multiplies the flexibilities by the tridiagonal hat matrices column by column
(``residual_hats._times_band``); the baseline formed them dense and took matrix products into
``np.block`` (written out below), timed over ``JACOBIANS`` builds at the ball's 85 hats.

Runs alternate (baseline, project) ``--repeats`` times on the steel ball's 40-mode wall at 1 m/s
(``law --angle``'s larger build), check that they agree (the nodes bit for bit; the hats'
flexibilities to 1e-12 of their largest entry: another order of the sums), and print the
seconds, the ratio baseline / project as min / median / max, and the load average at the start
and the end.

Run: PYTHONPATH=src python benchmarks/bench_residual_setup.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution.bodies.cache import get_modes  # noqa: E402
from restitution.bodies.sphere import contact_compliance, contact_residual, harmonics  # noqa: E402
from restitution.bodies.sphere.cap import cap_modes  # noqa: E402
from restitution.bodies.sphere.cap_nodes import cap_nodes  # noqa: E402
from restitution.dynamics.contact import residual_hats  # noqa: E402
from restitution.dynamics.oblique_residual import _reach  # noqa: E402

V, ALPHA, MODES = 0.0001933, 44956.2, 40  # the steel ball at 1 m/s on law's wall
JACOBIANS = 2000


def _former_coefficients(theta, w, l_top, kind):
    """The baseline: ``_coefficients``' projections as they were taken, one matrix-vector
    product per order (the norms after them are the project's)."""
    x, s = np.cos(theta), np.sin(theta)
    proj = np.zeros((l_top + 1, 3, w.shape[0]))
    tangential = kind != "normal"
    wx, ws2, wxx = w * x, w * s * s, w * x * x
    ws, wxs = w * s, w * x * s
    p_prev, p = np.zeros_like(x), np.ones_like(x)
    d_prev, d = np.zeros_like(x), np.zeros_like(x)
    for l in range(l_top + 1):
        if kind == "tilt":
            ll = l * (l + 1.0)
            proj[l, 0], proj[l, 2] = -(wxs @ d), -(ws @ d)
            proj[l, 1] = ll * (ws @ p) - wxs @ d
        elif tangential:
            ll = l * (l + 1.0)
            proj[l, 0], proj[l, 2] = ws2 @ d, -ll * (w @ p)
            proj[l, 1] = ll * (wx @ p) - wxx @ d + w @ d
        else:
            proj[l, 0], proj[l, 1] = -(wx @ p), -(ws2 @ d)
        p_prev, p = p, ((2 * l + 1) * x * p - l * p_prev) / (l + 1)
        d_prev, d = d, (d_prev + (2 * l + 1) * p_prev if l else np.ones_like(x))
    return contact_compliance._normalised(proj, tangential)


def _hats(cap, nodes, coefficients):
    contact_compliance._coefficients = coefficients
    contact_residual._flexibility.cache_clear()  # the hats' own cache (an estimate and its run)
    t = time.perf_counter()
    hats = cap.contact_residual(nodes, _reach(cap, V, ALPHA))
    return time.perf_counter() - t, hats


def _nodes(cap, derivative):
    harmonics._derivative = derivative
    t = time.perf_counter()
    nodes = cap_nodes(cap, ALPHA)
    return time.perf_counter() - t, nodes


def _former_jacobian(H, H1, bands, a):
    """The baseline: the tilted solve's Jacobian with the hat matrices formed dense."""
    B00, B01, B11 = (np.diag(d) + np.diag(off, 1) + np.diag(off, -1) for d, off in bands)
    jac = a * np.block([[H @ B00, H @ B01], [H1 @ B01, H1 @ B11]])
    jac[np.diag_indices(jac.shape[0])] += 1.0
    return jac


def _jacobian(H, H1, bands, a):
    """The project's: :func:`residual_hats._times_band` into the blocks (as ``solve_tilted``)."""
    K = H.shape[0]
    (d0, o0), (d1, o1), (d2, o2) = bands
    jac = np.empty((2 * K, 2 * K))
    times = residual_hats._times_band
    jac[:K, :K], jac[:K, K:] = times(H, d0, o0), times(H, d1, o1)
    jac[K:, :K], jac[K:, K:] = times(H1, d1, o1), times(H1, d2, o2)
    jac *= a
    jac[np.diag_indices(2 * K)] += 1.0
    return jac


def _time_jacobians(build, hats, bands):
    t = time.perf_counter()
    for _ in range(JACOBIANS):
        jac = build(hats.normal, hats.tilt, bands, ALPHA)
    return time.perf_counter() - t, jac


def _ratios(label, base, new):
    r = np.asarray(base) / np.asarray(new)
    print(f"{label}: baseline {np.median(base):.2f} s, project {np.median(new):.2f} s (medians); "
          f"ratio min / median / max {r.min():.2f} / {np.median(r):.2f} / {r.max():.2f} over "
          f"{r.size} alternating runs")  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    print(f"load average at start: {os.getloadavg()}")
    cap = cap_modes(get_modes(0.3, count=MODES, geometry="sphere"))
    blocked, cached = contact_compliance._coefficients, harmonics._derivative
    uncached = cached.__wrapped__
    node_base, node_new, hat_base, hat_new, jac_base, jac_new = [], [], [], [], [], []
    rng = np.random.default_rng(88)
    try:
        for _ in range(args.repeats):
            cached.cache_clear()
            t_base, n_base = _nodes(cap, uncached)
            t_new, nodes = _nodes(cap, cached)
            assert np.array_equal(n_base.D, nodes.D)
            node_base.append(t_base)
            node_new.append(t_new)
            t_base, h_base = _hats(cap, nodes, _former_coefficients)
            t_new, hats = _hats(cap, nodes, blocked)
            for name in ("normal", "tangential", "tilt", "cross"):
                a, b = getattr(h_base, name), getattr(hats, name)
                assert np.max(np.abs(a - b)) <= 1e-12 * np.max(np.abs(a)), name
            hat_base.append(t_base)
            hat_new.append(t_new)
            K = len(hats)
            bands = [(rng.uniform(0, 1, K), rng.uniform(0, 0.5, K - 1)) for _ in range(3)]
            t_base, j_base = _time_jacobians(_former_jacobian, hats, bands)
            t_new, jac = _time_jacobians(_jacobian, hats, bands)
            assert np.max(np.abs(j_base - jac)) <= 1e-12 * np.max(np.abs(j_base))
            jac_base.append(t_base)
            jac_new.append(t_new)
    finally:
        contact_compliance._coefficients, harmonics._derivative = blocked, cached
    print(f"steel ball, {MODES} modes ({len(cap)} in the cap), alpha = {ALPHA:g}, v = {V:g}: "
          f"{nodes.D.shape[0]} wall nodes, {len(hats)} hats")  # fmt: skip
    _ratios("wall nodes (cap_nodes)", node_base, node_new)
    _ratios("hats' flexibilities (contact_residual)", hat_base, hat_new)
    _ratios(f"tilted solve's Jacobian, {JACOBIANS} builds", jac_base, jac_new)
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
