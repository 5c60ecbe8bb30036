"""Benchmark: memory and time of building the oblique route's wall nodes, in blocks against the
former single evaluation.

The wall nodes hold, per node and mode, the displacement along the two in-plane directions
(:mod:`restitution.bodies.node_jacobian`). Until stop 81 they were evaluated for every node at
once and stacked (``np.stack([d1, d2], axis=1)``); the project evaluates
:data:`~restitution.bodies.sphere.cap_nodes.BLOCK_NODES` nodes at a time into the stored array.
The baseline here is that former arithmetic, written out below; the project is the bodies'
``wall_nodes``. Runs alternate (baseline, project) ``RUNS`` times per body, each a traced call
for the peak memory (tracemalloc) and an untraced one for the wall time; the script prints
both, their ratios as min / median / max, the machine's load, whether the rows agree bit for
bit, and the project's ``wall_node_memory`` over its measured peak.

Run: PYTHONPATH=src python benchmarks/bench_wall_nodes.py
"""

from __future__ import annotations

import os
import time
import tracemalloc

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import math  # noqa: E402

import numpy as np  # noqa: E402

from restitution.bodies.cache import get_modes  # noqa: E402
from restitution.bodies.kinds import body_kind  # noqa: E402

RUNS = 5
CASES = (("sphere", 0.3, 80, 500.0), ("disk", 0.25, 640, 2000.0))


def _former(body, nodes) -> np.ndarray:
    """The rows as the former build made them: every node at once, then stacked."""
    if hasattr(nodes, "theta"):
        A = nodes.azimuths
        th = np.repeat(nodes.theta, A)
        ph = np.tile(2.0 * math.pi * np.arange(A) / A, nodes.theta.size)
        d1, d2, _ = body.displacement(th, ph)
        return np.ascontiguousarray(np.stack([d1, d2], axis=1))
    Ur, Up = body.displacement(nodes.phi)
    return np.ascontiguousarray(np.stack([Ur, Up], axis=1))


def _traced(make):
    """Peak traced memory and the result, then the wall time of a second, untraced call
    (tracemalloc slows the many small allocations of the sphere's per-order loop 5-fold)."""
    tracemalloc.start()
    out = make()
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    t0 = time.perf_counter()
    make()
    return peak, time.perf_counter() - t0, out


def main() -> None:
    load = os.getloadavg()
    print(f"load average before: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; {RUNS} runs each")

    def mmm(x):
        return f"{min(x):.3g} / {float(np.median(x)):.3g} / {max(x):.3g}"

    for geometry, nu, count, alpha in CASES:
        body = body_kind(geometry).oblique_body(get_modes(nu, count=count, geometry=geometry))
        reference = body.wall_nodes(alpha)
        unit = 8.0 * len(reference) * len(body)
        mem, tim, same, peaks = [], [], True, []
        for _ in range(RUNS):
            m_old, t_old, old = _traced(lambda b=body, r=reference: _former(b, r))
            m_new, t_new, new = _traced(lambda b=body, a=alpha: b.wall_nodes(a))
            rows = new.D if hasattr(new, "D") else new.U
            same = same and bool(np.array_equal(old, rows))
            mem.append(m_old / m_new)
            tim.append(t_new / t_old)
            peaks.append(m_new)
            print(f"  {geometry}: former {m_old / unit:.2f} arrays {t_old:.2f} s, "
                  f"blocks {m_new / unit:.2f} arrays {t_new:.2f} s")  # fmt: skip
        print(f"{geometry}, {count} modes ({len(body)} of both symmetries) on {len(reference)} "
              f"nodes (one node-by-mode array {unit / 2**20:.0f} MiB):")  # fmt: skip
        print(f"  peak memory, former / blocks (min / median / max): {mmm(mem)}")
        print(f"  time, blocks / former (min / median / max): {mmm(tim)}")
        print(f"  rows bit for bit: {same}; wall_node_memory over the measured peak: "
              f"{body.wall_node_memory(alpha) / max(peaks):.3f}")  # fmt: skip
    load = os.getloadavg()
    print(f"load average after: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


if __name__ == "__main__":
    main()
