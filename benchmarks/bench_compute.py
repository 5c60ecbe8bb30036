"""Benchmark: ``restitution law --compute`` of a new law from a cold cache, against five minutes.

Issue 62: a law the package does not ship (a sphere of ``nu = 0.33``: the shipped sphere laws
are at ``nu = 0.2, 0.25, ..., 0.45``) is computed by ``restitution law ... --compute`` with the
production settings; from a cold cache (no modes, no stored collisions, no law file) it should
take at most five minutes on the project's two-core machine. The script runs, alternating,

* **cold**: the command with ``RESTITUTION_CACHE_DIR`` and ``--store`` in a new empty folder
  (modes, collisions, the law file and numba's kernels all computed);
* **warm** (the baseline: what the user pays once the law is in the cache): the same command
  again on the folder the cold run filled;

and prints each run's wall time, min / median / max over the repeats, the ratio of cold to the
target and of cold to warm, the command's own estimate (its first ``note:`` line on stderr) and
the load average at the start and the end (the machine is shared: read the load with the times).

Run: python benchmarks/bench_compute.py [--nu 0.33] [--shape sphere] [--route modal]
     [--repeats 1]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET_S = 300.0
"""Issue 62: a new law from a cold cache in at most five minutes."""


def _command(nu: float, shape: str, route: str, store: Path) -> list[str]:
    exe = Path(sys.executable).with_name("restitution")
    return [
        str(exe), "law", "--E", "210e9", "--nu", str(nu), "--rho", "7850", "--shape", shape,
        "--against", "wall", "--speed", "1", "--compute", "--route", route,
        "--store", str(store), "--json",
    ]  # fmt: skip


def _run(cmd: list[str], cache: Path) -> tuple[float, str]:
    """Wall time of ``cmd`` with the cache at ``cache`` and its first ``note:`` line."""
    env = {**os.environ, "RESTITUTION_CACHE_DIR": str(cache)}
    t0 = time.perf_counter()
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - t0
    if done.returncode not in (0, 1):  # 1: a status other than ok, still a law
        raise SystemExit(f"the command failed ({done.returncode}): {done.stderr.strip()[-400:]}")
    note = next((ln for ln in done.stderr.splitlines() if ln.startswith("note:")), "")
    return seconds, note


def _spread(xs: list[float]) -> str:
    return f"min {min(xs):8.1f}  median {statistics.median(xs):8.1f}  max {max(xs):8.1f}"


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--nu", type=float, default=0.33)
    ap.add_argument("--shape", default="sphere")
    ap.add_argument("--route", default="modal", choices=("modal", "residual"))
    ap.add_argument("--repeats", type=int, default=1)
    a = ap.parse_args(argv)
    print(f"load average at the start: {os.getloadavg()}")
    cold, warm = [], []
    for k in range(a.repeats):
        folder = Path(tempfile.mkdtemp(prefix="restitution-bench-compute-"))
        try:
            cmd = _command(a.nu, a.shape, a.route, folder / "store.sqlite")
            seconds, note = _run(cmd, folder / "cache")
            cold.append(seconds)
            print(f"round {k + 1}: cold {seconds:8.1f} s   ({note})")
            seconds, _ = _run(cmd, folder / "cache")
            warm.append(seconds)
            print(f"round {k + 1}: warm {seconds:8.1f} s")
        finally:
            shutil.rmtree(folder, ignore_errors=True)
    print(f"cold (s):  {_spread(cold)}")
    print(f"warm (s):  {_spread(warm)}")
    ratios = [c / TARGET_S for c in cold]
    print(f"cold / five-minute target: min {min(ratios):.2f}  median "
          f"{statistics.median(ratios):.2f}  max {max(ratios):.2f}  "
          f"({'meets' if statistics.median(ratios) <= 1.0 else 'misses'} the target)")  # fmt: skip
    ratio = statistics.median(c / w for c, w in zip(cold, warm, strict=True))
    print(f"cold / warm: median {ratio:.0f}")
    print(f"load average at the end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
