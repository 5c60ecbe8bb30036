"""Benchmark: the microslip route's step with the wall nodes' Jacobians unformed (one
matrix-vector pass per product, :mod:`restitution.bodies.node_jacobian`) against formed
matrices (the baseline).

The baseline wraps the same body's wall nodes so that each step forms ``dX/dQ`` and ``dY/dQ``
as matrices and takes every product and row norm from them, as
:mod:`restitution.dynamics.oblique_microslip` did before stop 80. Both runs use today's loop
(two slip products a step, not the three of before), so the ratio is the Jacobians' share and
understates the gain over the route before (docs/oblique.md measures that once).
Cases: the disk at 160 and 640 modes (``nu = 0.33``, ``v = 0.005``, ``alpha = 2000``, ``mu =
0.5``, ``tan(theta)/mu = 0.3``, ``kappa = 64``: docs/oblique.md's comparison with the finite
elements) and the sphere at 20 and 40 axisymmetric modes (``nu = 0.3``, ``alpha = 500``, the
same impact: ``psi = 0.247``, the low-speed table's first row). Times alternate, baseline
first; prints the ratio baseline / unformed as min / median / max over the repetitions, the
two ``beta`` (they differ by rounding), and the load average at the start and the end.
Run: python benchmarks/bench_microslip.py [--repeats 3] [--cases disk160,sphere20]
"""

from __future__ import annotations

import argparse
import math
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution.bodies.disk.modes import compute_modes  # noqa: E402
from restitution.bodies.disk.rim import rim_modes  # noqa: E402
from restitution.bodies.sphere.cap import cap_modes  # noqa: E402
from restitution.bodies.sphere.modes import compute_sphere_modes  # noqa: E402
from restitution.dynamics.oblique_microslip import (  # noqa: E402
    MicroslipSettings,
    microslip_collision,
)


class _Formed:
    """The Jacobians as matrices, with :class:`~restitution.bodies.node_jacobian.NodeJacobian`'s
    products (the baseline)."""

    def __init__(self, dXdQ, dYdQ):
        self.dXdQ, self.dYdQ = dXdQ, dYdQ

    def dY(self, v):
        return self.dYdQ @ v

    def pull(self, cx, cy):
        return cx @ self.dXdQ + cy @ self.dYdQ

    def norms(self):
        return (np.einsum("ij,ij->i", self.dXdQ, self.dXdQ),
                np.einsum("ij,ij->i", self.dYdQ, self.dYdQ))  # fmt: skip


class _FormedNodes:
    def __init__(self, nodes):
        self._nodes = nodes

    def __getattr__(self, name):
        return getattr(self._nodes, name)

    def __len__(self):
        return len(self._nodes)

    def jacobian(self, x0, rotation, Q, Qd, reach, cutoff):
        placed = self._nodes.jacobians(x0, rotation, Q, reach, cutoff)
        if placed is None:
            return None
        J = _Formed(*placed[4:])
        return (*placed[:4], J.dY(Qd), J)


class _FormedBody:
    """``body`` whose wall nodes form their Jacobians."""

    def __init__(self, body):
        self._body = body

    def __getattr__(self, name):
        return getattr(self._body, name)

    def __len__(self):
        return len(self._body)

    def wall_nodes(self, alpha, n_nodes=None):
        return _FormedNodes(self._body.wall_nodes(alpha, n_nodes))


def _cases():
    def disk(n):
        return rim_modes(compute_modes(0.33, count=n)), 2000.0, 0.3 * 0.5, None

    def sphere(n):
        return cap_modes(compute_sphere_modes(0.3, count=n)), 500.0, 0.3 * 0.5, None

    return {"disk160": lambda: disk(160), "disk640": lambda: disk(640),
            "sphere20": lambda: sphere(20), "sphere40": lambda: sphere(40)}  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--cases", default="disk160,sphere20")
    args = parser.parse_args()
    print(f"load average at start: {os.getloadavg()}")
    makers = _cases()
    for name in args.cases.split(","):
        body, alpha, tan_theta, _ = makers[name]()
        v_n = 0.005
        settings = MicroslipSettings(kappa=64)

        def run(b, v_n=v_n, tan_theta=tan_theta, alpha=alpha, settings=settings):
            start = time.perf_counter()
            r = microslip_collision(b, v_n, v_n * tan_theta, 0.5, alpha, settings=settings)
            return time.perf_counter() - start, r

        ratios, base_t, new_t = [], [], []
        for _ in range(args.repeats):
            tb, rb = run(_FormedBody(body))
            tn, rn = run(body)
            ratios.append(tb / tn)
            base_t.append(tb)
            new_t.append(tn)
        r = np.asarray(ratios)
        print(f"{name} ({len(body)} modes, tan(theta) = {tan_theta:.4g}, {rn.steps} steps): "
              f"formed {np.median(base_t):.2f} s, unformed {np.median(new_t):.2f} s (medians); "
              f"ratio min / median / max {r.min():.2f} / {np.median(r):.2f} / {r.max():.2f} "
              f"over {args.repeats} alternating runs; beta {rb.beta:.12f} formed, "
              f"{rn.beta:.12f} unformed (difference {abs(rb.beta - rn.beta):.1e}); "
              f"epsilon_normal difference "
              f"{abs(rb.epsilon_normal - rn.epsilon_normal):.1e}")  # fmt: skip
        assert math.isfinite(rn.beta)
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
