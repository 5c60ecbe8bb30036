"""Benchmark: the compiled collision kernel against its baselines, side by side in one run.

Sections (issue 13's targets), each timed in alternating rounds so that the load of a shared
machine falls on both sides alike; every ratio is printed per round and as min/median/max:

single  One collision, nu = 0.33, v = 0.1, alpha = 500, 1600 lowest modes, |eps error| <= 1e-6.
        Each solver's tolerance is first tightened tenfold until its epsilon is within 1e-6 of a
        reference (split4 at energy_tol 1e-10); then those settings are timed. Sides: the
        compiled kernel, the NumPy reference path, scipy's DOP853 with a dense right-hand side
        (restitution.dynamics.reference, as a user would write it) and DOP853 given the same
        order-by-order wall evaluation as the modal solver.
sphere  The same for the sphere (issue 26's target, >= 20x DOP853): nu = 0.3 (3D), v = 0.1,
        alpha = 500, 1600 lowest axisymmetric spheroidal modes, |eps error| <= 1e-6.
batch   32 speeds 0.02-0.3 at alpha = 500 on one mode set (N = 1600): one compiled batch
        against DOP853 one collision at a time (8 of the 32 speeds timed, times 4).
large   N = 1e4, v = 0.01, alpha = 1634: compiled kernel against the NumPy path; the kernel
        both as it runs (two threads when numba has two) and on one thread. The NumPy path gets
        one BLAS thread unless OPENBLAS_NUM_THREADS is set (set it to 2 to give it both cores).
huge    N = 1e5 at v = 1e-4 (alpha = 40 / delta_max): mode build and one collision, in a
        subprocess whose peak memory (max RSS) is reported.
kernel  This kernel against an earlier one (``--kernel-rev``, default: the last commit before
        single collisions on two threads; 68ac2fc is the last before the thread-pool batches,
        45e1558 the last before the fused passes), loaded from git under another module name,
        on the same inputs (captured from ``collide`` and ``collide_batch``): one collision at
        N = 1600, v = 0.1, alpha = 500, one at N = 1e4, v = 0.01, alpha = 1634, and the
        32-speed batch of "batch"; alternating rounds, max |eps difference| printed.
modes   Building 1e4 modes at nu = 0.33: the scale-free Bessel-pair scan against the previous
        scipy-jv scan, loaded from git (``--baseline-rev``, default: the last commit before
        the change).

Run: python benchmarks/bench_kernel.py [single sphere batch large huge kernel modes] [--rounds 3]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from restitution import collide, collide_batch, compute_modes, get_modes  # noqa: E402
from restitution.bodies.disk.contact import max_compression_estimate  # noqa: E402
from restitution.dynamics.reference import collide_dop853  # noqa: E402

NU, V, ALPHA, TARGET = 0.33, 0.1, 500.0, 1e-6
SPHERE_NU = 0.3  # three-dimensional, steel-like
BASELINE_REV = "4fcd9d3"  # last commit with the scipy-jv mode scan
KERNEL_REV = "84c90a9"  # last commit before two-thread single collisions (68ac2fc: batches)


def _load() -> str:
    one, five, _ = os.getloadavg()
    return f"load average {one:.2f} (1 min), {five:.2f} (5 min) on {os.cpu_count()} cores"


def _timed(fn):
    t = time.perf_counter()
    out = fn()
    return time.perf_counter() - t, out


def _summary(name: str, ratios: list[float]) -> None:
    r = np.array(ratios)
    print(
        f"  {name}: min {r.min():.1f}x  median {np.median(r):.1f}x  max {r.max():.1f}x  "
        f"({r.size} rounds)",
        flush=True,
    )


def _tighten(label: str, run, ref: float, start: float, floor: float) -> float:
    """Tighten a tolerance tenfold until |eps - ref| <= TARGET; returns that tolerance."""
    tol = start
    while True:
        eps = run(tol)
        print(f"  {label} tol {tol:.0e}: |err| {abs(eps - ref):.1e}", flush=True)
        if abs(eps - ref) <= TARGET or tol <= floor:
            return tol
        tol /= 10.0


def single(rounds: int, geometry: str = "disk") -> None:
    nu = SPHERE_NU if geometry == "sphere" else NU
    print(
        f"== single collision of a {geometry}, nu = {nu}, N = 1600, v = {V}, alpha = {ALPHA}; "
        f"{_load()}"
    )
    modes = get_modes(nu, count=1600, geometry=geometry)
    ref = collide(modes, V, ALPHA, energy_tol=1e-10).epsilon
    print(f"  reference epsilon (split4, energy_tol 1e-10): {ref:.10f}")
    tol = _tighten(
        "restitution energy_tol",
        lambda t: collide(modes, V, ALPHA, energy_tol=t).epsilon,
        ref,
        1e-3,
        1e-9,
    )
    rtol = _tighten(
        "DOP853 rtol",
        lambda t: collide_dop853(modes, V, ALPHA, rtol=t, atol=t * 1e-2)["epsilon"],
        ref,
        1e-5,
        1e-12,
    )
    sides = {
        "compiled": lambda: collide(modes, V, ALPHA, energy_tol=tol, backend="compiled"),
        "numpy": lambda: collide(modes, V, ALPHA, energy_tol=tol, backend="numpy"),
        "dop853 dense": lambda: collide_dop853(modes, V, ALPHA, rtol=rtol, atol=rtol * 1e-2),
        "dop853 orders": lambda: collide_dop853(
            modes, V, ALPHA, rtol=rtol, atol=rtol * 1e-2, wall="orders"
        ),
    }
    times: dict[str, list[float]] = {k: [] for k in sides}
    for i in range(rounds):
        for name, fn in sides.items():
            times[name].append(_timed(fn)[0])
        print(
            f"  round {i + 1}: "
            + "  ".join(f"{k} {v[-1]:.3f} s" for k, v in times.items())
            + f"; {_load()}",
            flush=True,
        )
    c = np.array(times["compiled"])
    for name in ("dop853 dense", "dop853 orders", "numpy"):
        _summary(f"{name} / compiled", list(np.array(times[name]) / c))


def batch(rounds: int) -> None:
    print(f"== 32 speeds batched, N = 1600, alpha = {ALPHA}; {_load()}")
    modes = get_modes(NU, count=1600)
    vs = np.linspace(0.02, 0.3, 32)
    # DOP853 at the tolerance that reaches 1e-6 at v = 0.1 (see "single"): rtol 1e-7.
    ratios, ratios_loop = [], []
    for i in range(rounds):
        t_batch, _ = _timed(lambda: collide_batch(modes, vs, ALPHA, backend="compiled"))
        t_one, _ = _timed(lambda: [collide(modes, v, ALPHA, backend="compiled") for v in vs])
        t_dop, _ = _timed(lambda: [collide_dop853(modes, v, ALPHA, rtol=1e-7) for v in vs[::4]])
        t_dop *= 4.0
        ratios.append(t_dop / t_batch)
        ratios_loop.append(t_one / t_batch)
        print(
            f"  round {i + 1}: compiled batch {t_batch:.2f} s ({32 / t_batch:.1f} collisions/s), "
            f"compiled one by one {t_one:.2f} s, DOP853 one by one {t_dop:.1f} s (8 timed x 4); "
            f"{_load()}",
            flush=True,
        )
    _summary("DOP853 one at a time / compiled batch", ratios)
    _summary("compiled one at a time / compiled batch", ratios_loop)


def large(rounds: int) -> None:
    import numba

    threads = numba.get_num_threads()
    blas = os.environ.get("OPENBLAS_NUM_THREADS")
    print(f"== N = 1e4, v = 0.01, alpha = 1634; NumPy path with {blas} BLAS thread(s); {_load()}")
    modes = get_modes(NU, count=10_000)
    times: dict[str, list[float]] = {"compiled": [], "one thread": [], "numpy": []}
    for i in range(rounds):
        t_c, rc = _timed(lambda: collide(modes, 0.01, 1634.0, backend="compiled"))
        numba.set_num_threads(1)
        try:
            t_1, r1 = _timed(lambda: collide(modes, 0.01, 1634.0, backend="compiled"))
        finally:
            numba.set_num_threads(threads)
        t_n, rn = _timed(lambda: collide(modes, 0.01, 1634.0, backend="numpy"))
        for name, t in (("compiled", t_c), ("one thread", t_1), ("numpy", t_n)):
            times[name].append(t)
        print(
            f"  round {i + 1}: compiled {t_c:.2f} s ({threads} threads), on one thread "
            f"{t_1:.2f} s, numpy {t_n:.2f} s, {rc.n_steps} steps, |eps difference| "
            f"{abs(rc.epsilon - rn.epsilon):.1e}, one thread / two bit for bit: "
            f"{rc.epsilon == r1.epsilon}; {_load()}",
            flush=True,
        )
    t = {name: np.array(v) for name, v in times.items()}
    _summary(f"numpy / compiled ({threads} threads)", list(t["numpy"] / t["compiled"]))
    _summary("numpy / compiled on one thread", list(t["numpy"] / t["one thread"]))
    _summary("compiled: one thread / as run", list(t["one thread"] / t["compiled"]))


_HUGE = """
import resource, time
from restitution import collide, compute_modes
t = time.perf_counter(); modes = compute_modes({nu}, count={n}); t_modes = time.perf_counter() - t
t = time.perf_counter(); r = collide(modes, {v}, {alpha}); t_coll = time.perf_counter() - t
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
print(f"  modes {{t_modes:.1f}} s, collision {{t_coll:.1f}} s ({{r.n_steps}} steps, "
      f"dt {{r.dt:.2e}}, drift {{r.energy_drift:.1e}}), epsilon {{r.epsilon:.6f}}, "
      f"peak RSS {{rss:.0f}} MiB")
"""


def huge(rounds: int) -> None:
    v = 1e-4
    alpha = 40.0 / max_compression_estimate(v)
    print(f"== N = 1e5, v = {v}, alpha = {alpha:.0f} (alpha delta_max = 40); {_load()}")
    code = _HUGE.format(nu=NU, n=100_000, v=v, alpha=alpha)
    subprocess.run([sys.executable, "-c", code], check=True)
    print(f"  {_load()}")


# Where a module lived before the layer subpackages (the baselines predate them), and where it
# lives now; a baseline's imports of moved modules are pointed at their new homes.
_MOVED = {
    "kernel": "dynamics/kernel",
    "spin": "dynamics/spin",
    "modes": "bodies/disk/modes",
    "frequency_equation": "bodies/disk/frequency_equation",
    "bessel_ratio": "bodies/disk/bessel_ratio",
    "material": "bodies/material",
}


def _git_show(rev: str, name: str) -> str:
    """Source of module ``name`` (a key of ``_MOVED``) at revision ``rev``, in either layout,
    with imports of moved modules rewritten to the current layout."""
    root = Path(__file__).resolve().parent.parent
    for path in (_MOVED[name], name):
        got = subprocess.run(
            ["git", "show", f"{rev}:src/restitution/{path}.py"],
            cwd=root,
            capture_output=True,
            text=True,
        )
        if got.returncode == 0:
            text = got.stdout
            for old, new in _MOVED.items():
                text = text.replace(
                    f"from restitution.{old} ", f"from restitution.{new.replace('/', '.')} "
                )
            return text
    raise SystemExit(f"no module {name} at revision {rev}")


def _old_quadrature(quad):
    """``quad`` with the attribute names of the kernels before the body protocol as well
    (``cos_phi``, ``trig``, ``phi``: now ``height``, ``basis``, ``nodes``)."""
    fields = {name: getattr(quad, name) for name in quad.__dataclass_fields__}
    return SimpleNamespace(
        **fields, n_orders=quad.n_orders, cos_phi=quad.height, trig=quad.basis, phi=quad.nodes
    )


def _baseline_kernel(rev: str):
    """``restitution.dynamics.kernel`` of revision ``rev``, as module ``baseline_kernel``."""
    text = _git_show(rev, "kernel")
    tmp = Path(tempfile.mkdtemp(prefix="bench-kernel-"))
    (tmp / "baseline_kernel.py").write_text(text)
    spec = importlib.util.spec_from_file_location("baseline_kernel", tmp / "baseline_kernel.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["baseline_kernel"] = module
    spec.loader.exec_module(module)
    return module


def _kernel_inputs(modes, v, alpha):
    """The arguments of the last ``run_batch`` call of ``collide_batch`` (its accepted steps)."""
    import restitution.dynamics.kernel as kernel

    calls = []
    run = kernel.run_batch

    def spy(*args, **kwargs):
        calls.append((args, kwargs))
        return run(*args, **kwargs)

    kernel.run_batch = spy
    try:
        collide_batch(modes, v, alpha, backend="compiled")
    finally:
        kernel.run_batch = run
    return calls[-1]


def _old_args(args: tuple) -> tuple:
    """``run_batch`` arguments for a baseline kernel: the quadrature (third) with old names, and
    without the arguments kernels before material damping and contact laws lack (the 16th,
    ``damping``, and 17th, ``stop``, must be ``None``: an elastic body; the 18th, ``law``, the
    exponential wall without parameters)."""
    if len(args) > 17:
        law, params = args[17], args[18] if len(args) > 18 else None
        assert law == 0 and (params is None or len(params) == 0), "only the exponential wall"
        args = args[:17]
    if len(args) > 15:
        assert all(a is None for a in args[15:]), "a damped body has no baseline kernel"
        args = args[:15]
    return (*args[:2], _old_quadrature(args[2]), *args[3:])


def kernel(rounds: int, rev: str) -> None:
    import restitution.dynamics.kernel as new

    print(f"== this kernel against the kernel of {rev}, same inputs; {_load()}")
    old = _baseline_kernel(rev)
    # Compile (or load) both sides outside the timing, single and batched (the old kernel has
    # a separate parallel function for batches).
    for v in (V, [V, 2 * V]):
        args, kwargs = _kernel_inputs(get_modes(NU, count=20), v, ALPHA)
        old.run_batch(*_old_args(args), **kwargs)
        new.run_batch(*args, **kwargs)
    cases = (
        ("one collision, N = 1600, v = 0.1, alpha = 500", 1600, V, ALPHA),
        ("one collision, N = 1e4, v = 0.01, alpha = 1634", 10_000, 0.01, 1634.0),
        (
            "32 speeds 0.02-0.3 batched, N = 1600, alpha = 500",
            1600,
            np.linspace(0.02, 0.3, 32),
            ALPHA,
        ),
    )
    for label, n, v, alpha in cases:
        args, kwargs = _kernel_inputs(get_modes(NU, count=n), v, alpha)
        times: dict[str, list[float]] = {"old": [], "new": []}
        sides = [
            ("old", lambda *a, **kw: old.run_batch(*_old_args(a), **kw)),
            ("new", new.run_batch),
        ]
        for i in range(rounds):
            out = {}
            # Alternate which side runs first, so that neither always finds warm caches.
            for name, run in sides if i % 2 == 0 else sides[::-1]:
                t, out[name] = _timed(lambda run=run, a=args, kw=kwargs: run(*a, **kw))
                times[name].append(t)
            d_eps = np.max(np.abs(out["old"]["epsilon"] - out["new"]["epsilon"]))
            same_steps = np.array_equal(out["old"]["steps"], out["new"]["steps"])
            print(
                f"  {label}, round {i + 1}: old {times['old'][-1]:.3f} s, "
                f"new {times['new'][-1]:.3f} s, {out['new']['steps'].sum()} steps "
                f"({'same' if same_steps else 'NOT the same'} as old), "
                f"max |eps difference| {d_eps:.1e}; {_load()}",
                flush=True,
            )
        _summary(f"{label}: old / new", list(np.array(times["old"]) / np.array(times["new"])))


def _baseline_modes(rev: str):
    """``compute_modes`` of revision ``rev`` (its modes.py and frequency_equation.py)."""
    tmp = Path(tempfile.mkdtemp(prefix="bench-baseline-"))
    for name in ("modes", "frequency_equation"):
        text = _git_show(rev, name).replace(
            "from restitution.bodies.disk.frequency_equation", "from baseline_frequency_equation"
        )
        (tmp / f"baseline_{name}.py").write_text(text)
    sys.path.insert(0, str(tmp))
    spec = importlib.util.spec_from_file_location("baseline_modes", tmp / "baseline_modes.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["baseline_modes"] = module
    spec.loader.exec_module(module)
    return module.compute_modes


def modes(rounds: int, rev: str) -> None:
    print(f"== 1e4 modes at nu = {NU}: Bessel-pair scan against the scipy-jv scan of {rev}")
    old = _baseline_modes(rev)
    compute_modes(NU, count=50)  # compile (or load) the numba functions outside the timing
    ratios = []
    for i in range(rounds):
        t_new, new = _timed(lambda: compute_modes(NU, count=10_000))
        t_old, ref = _timed(lambda: old(NU, count=10_000))
        same = np.array_equal(new.n, ref.n) and np.array_equal(new.l, ref.l)
        ratios.append(t_old / t_new)
        print(
            f"  round {i + 1}: new {t_new:.2f} s, baseline {t_old:.2f} s; same (n, l): {same}, "
            f"max |d omega| {np.max(np.abs(new.omega - ref.omega)):.1e}; {_load()}",
            flush=True,
        )
    _summary("baseline / new", ratios)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "sections",
        nargs="*",
        default=["single", "sphere", "batch", "large", "huge", "kernel", "modes"],
    )
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--baseline-rev", default=BASELINE_REV)
    parser.add_argument("--kernel-rev", default=KERNEL_REV)
    args = parser.parse_args()
    # Compile (or load) the serial and the threaded kernel once, outside every timing.
    collide(get_modes(NU, count=20), V, ALPHA)
    collide_batch(get_modes(NU, count=20), [V, 2 * V], ALPHA)
    for name in args.sections:
        if name == "modes":
            modes(args.rounds, args.baseline_rev)
        elif name == "kernel":
            kernel(args.rounds, args.kernel_rev)
        elif name == "sphere":
            single(args.rounds, "sphere")
        else:
            {"single": single, "batch": batch, "large": large, "huge": huge}[name](args.rounds)
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"peak RSS of this process {rss:.0f} MiB")


if __name__ == "__main__":
    main()
