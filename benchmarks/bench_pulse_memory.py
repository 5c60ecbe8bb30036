"""Benchmark: memory and time of the quasistatic drive of many modes, in blocks against one table.

Rayleigh's estimate and the sphere's low-speed points drive every mode with the contact force
through ``restitution.quasistatic.pulse.pulse_drive``, a cosine table of modes x quadrature
nodes. The nodes grow with the highest frequency, so one table grows like ``N^(3/2)`` (issue 30:
150000 disk modes took 24 GB). The project builds it in blocks of ``_BLOCK`` entries; the
baseline is the former single table (``_BLOCK`` set above the table's size). Both runs use the
same pulse (disk, ``nu = 0.33``, ``v = 0.01``) and frequencies, alternate ``RUNS`` times, and
the script prints the peak traced memory (tracemalloc) and the wall time of each, their ratios
as min / median / max, the machine's load, and the largest difference of the results.

Run: python benchmarks/bench_pulse_memory.py
"""

from __future__ import annotations

import os
import time
import tracemalloc

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import math  # noqa: E402

import numpy as np  # noqa: E402

from restitution.quasistatic import pulse as pulse_module  # noqa: E402
from restitution.quasistatic.hertz import contact_law  # noqa: E402

N, OMEGA_MAX, V, RUNS = 20000, 300.0, 0.01, 5
BLOCKED = pulse_module._BLOCK


def _run(block: int, p, omega) -> tuple[float, float, np.ndarray]:
    pulse_module._BLOCK = block
    tracemalloc.start()
    t0 = time.perf_counter()
    out = pulse_module.pulse_drive(p, omega)
    elapsed = time.perf_counter() - t0
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak, elapsed, out


def main() -> None:
    p = pulse_module.force_pulse(contact_law(0.33, "paper"), V, mass=math.pi)
    omega = np.linspace(1.0, OMEGA_MAX, N)
    load = os.getloadavg()
    mem_ratio, time_ratio, diff = [], [], 0.0
    for _ in range(RUNS):
        m_blk, t_blk, a = _run(BLOCKED, p, omega)
        m_one, t_one, b = _run(1 << 40, p, omega)
        mem_ratio.append(m_one / m_blk)
        time_ratio.append(t_blk / t_one)
        diff = max(diff, float(np.max(np.abs(a - b)) / np.max(np.abs(b))))
        print(
            f"blocks: {m_blk / 2**20:8.1f} MiB {t_blk:6.2f} s   one table: "
            f"{m_one / 2**20:8.1f} MiB {t_one:6.2f} s"
        )
    pulse_module._BLOCK = BLOCKED

    def mmm(x):
        return f"{min(x):.3g} / {float(np.median(x)):.3g} / {max(x):.3g}"

    print(f"N = {N} modes up to omega = {OMEGA_MAX:g}, v = {V:g}; {RUNS} alternating runs")
    print(f"load average before: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"peak memory, one table / blocks (min / median / max): {mmm(mem_ratio)}")
    print(f"time, blocks / one table (min / median / max): {mmm(time_ratio)}")
    print(f"largest relative difference of the drives: {diff:.2g}")


if __name__ == "__main__":
    main()
