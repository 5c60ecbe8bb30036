"""A hostile pass over the command line and the Python API: every case in its own process, with a
time and memory bound, sorted into the classes of the hostile-input issue.

Usage (from the project's root, with its venv)::

    .venv/bin/python tools/hostile_pass.py [--jobs 2] [--timeout 30] [--json out.json]
    PYTHONPATH=OTHER/src .venv/bin/python tools/hostile_pass.py ...   # another checkout's code

Classes (the first that applies):

* ``hang``: no answer within the timeout;
* ``blow-up``: killed by the memory bound (``--memory``, default 4 GiB), or a MemoryError;
* ``traceback``: a Python traceback on stderr;
* ``silently wrong``: an answer (exit 0 or 1) whose JSON holds a served epsilon outside
  ``(0, 1]``, or an ``ok`` value whose error exceeds it;
* ``raw warning``: an answer or refusal with a Python warning (``...Warning:`` and a source
  path) on stderr;
* ``accepted silently``: an answer without a ``warning:`` line to a value that has no meaning
  (zero, negative, non-finite, not a number, empty) or to a Python call that must be refused;
* ``implausible, no word``: an answer without a ``warning:`` line to a value of no grain (huge,
  tiny, or a number in the wrong unit); counted apart, as the issue counts plausibility;
* ``messy refusal``: exit 2 without exactly one ``error: ...`` line;
* ``refused``: exit 2 with one ``error: ...`` line (the wanted form of a refusal);
* ``answer``: exit 0 or 1 (1: speeds without a value, documented).

Whether a refusal's words are right, or an answer's value, is for a reader: the pass prints
each case's class and its last stderr line.
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter

STEEL = ["--E", "210e9", "--nu", "0.3", "--rho", "7850"]
GLASS = ["--E", "63e9", "--nu", "0.2481", "--rho", "2500"]
WALL = ["--wall-E", "63e9", "--wall-nu", "0.2481", "--wall-rho", "2500"]

BASES = {
    "cylinder-wall": ["law", *GLASS, "--shape", "cylinder", "--against", "wall"],
    "sphere-wall": ["law", *STEEL, "--shape", "sphere", "--against", "wall"],
    "sphere-block": ["law", *STEEL, "--shape", "sphere", "--against", "wall", *WALL],
    "sphere-plate": [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        *WALL,
        "--wall-thickness",
        "0.003",
        "--radius",
        "0.001",
    ],  # fmt: skip
    "damped": [
        "law",
        *GLASS,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--measured-epsilon",
        "0.9",
        "--measured-speed",
        "1",
        "--radius",
        "0.001",
    ],  # fmt: skip
    "plastic": [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--yield-stress",
        "1e9",
        "--radius",
        "0.001",
    ],  # fmt: skip
    "sphere-pair": [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "grain",
        "--partner-radius-ratio",
        "2",
    ],  # fmt: skip
}
"""Valid requests that the bad values are put into (one option at a time)."""

OPTIONS = {
    "--E": ["cylinder-wall", "sphere-plate", "plastic"],
    "--nu": ["cylinder-wall", "sphere-wall", "damped"],
    "--rho": ["cylinder-wall", "sphere-block"],
    "--speed": [
        "cylinder-wall",
        "sphere-block",
        "sphere-plate",
        "damped",
        "plastic",
        "sphere-pair",
    ],  # fmt: skip
    "--wall-E": ["sphere-block", "sphere-plate"],
    "--wall-nu": ["sphere-block"],
    "--wall-rho": ["sphere-block", "sphere-plate"],
    "--wall-thickness": ["sphere-plate"],
    "--radius": ["sphere-plate", "damped", "plastic"],
    "--measured-epsilon": ["damped"],
    "--measured-speed": ["damped"],
    "--yield-stress": ["plastic"],
    "--partner-radius-ratio": ["sphere-pair"],
    "--friction": ["cylinder-wall"],
    "--reference-speed": ["cylinder-wall"],
}
"""Each option, and the requests it is tried in."""

BAD = ["0", "-1", "nan", "inf", "1e300", "1e-300", "abc", "", "63"]
"""Values a careless or hostile user types: zero, negative, non-finite, huge, tiny, not a
number, empty, and a number in the wrong unit (GPa typed where Pa is asked)."""

MEANINGLESS = {"0", "-1", "nan", "inf", "abc", ""}
"""The values of :data:`BAD` that no option of a grain can take: an answer to them is wrong."""

ZERO_IS_VALID = {"--nu", "--wall-nu", "--friction"}
"""Options for which 0 is a value of real materials (cork's Poisson number, a smooth contact)."""

UNIT_SLIPS = {"--E", "--wall-E", "--yield-stress", "--radius", "--wall-thickness"}
"""Options where 63 is a number in the wrong unit (GPa typed as Pa, mm as m); elsewhere (a
density, a speed) it is a value of real grains."""

TINY_IS_VALID = {"--nu", "--wall-nu", "--measured-epsilon"}
"""Options for which 1e-300 is a limit of real values (nu = 0, a grain that sticks)."""

EXTRA_OPTION_VALUE = {"--friction": ["--reference-speed", "1"], "--reference-speed": []}
"""Options that need another to be read (a friction sets a constant's snippet)."""

OTHER_CLI = [
    ["epsilon", "--nu", "0.33", "--v", "1e-9"],
    ["epsilon", "--nu", "0.33", "--v", "nan"],
    ["epsilon", "--nu", "2", "--v", "0.1"],
    ["epsilon", "--nu", "0.33", "--v", "0.1", "--modes", "0"],
    ["epsilon", "--nu", "0.33", "--v", "0.1", "--alphas", "-1"],
    ["collide", "--nu", "0.33", "--v", "1e10", "--alpha", "500", "--modes", "60"],
    ["collide", "--nu", "0.33", "--v", "0.1", "--alpha", "1e300", "--modes", "60"],
    ["collide", "--nu", "0.33", "--v", "0.1", "--alpha", "500", "--modes", "1000000000"],
    [
        "collide",
        "--nu",
        "0.33",
        "--v",
        "0.1",
        "--alpha",
        "500",
        "--modes",
        "60",
        "--relaxation-time",
        "1e300",
    ],  # fmt: skip
    ["quasistatic", "--v", "1e300"],
    ["quasistatic", "--v", "-1"],
    ["quasistatic", "--geometry", "sphere", "--nu", "0.3", "--v", "1e-300"],
    ["modes", "--nu", "0.33", "--count", "-5"],
    ["modes", "--nu", "0.33", "--count", "100000000"],
    ["modes", "--nu", "nan", "--count", "5"],
    ["curve", "--nu", "0.33", "--v", "1e-9", "--out", "{tmp}/curve"],
    [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--speed",
        "1",
        "--export",
        "/dev/null/x",
    ],  # fmt: skip
    [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--speed",
        "1",
        "--plot",
        "{tmp}",
    ],  # fmt: skip
    [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--speed",
        "1",
        "--law-file",
        "/dev/null",
    ],  # fmt: skip
    [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--speed",
        "1",
        "--route",
        "residual",
    ],  # fmt: skip
    [
        "law",
        *STEEL,
        "--shape",
        "sphere",
        "--against",
        "wall",
        "--speed",
        "1",
        "--measured-fixes",
        "both",
    ],  # fmt: skip
    ["law", *STEEL, "--shape", "cube", "--against", "wall", "--speed", "1"],
    ["law", *STEEL, "--shape", "sphere", "--against", "moon", "--speed", "1"],
    ["lammps-plugin", "--out", "/dev/null/x"],
]
"""Other commands and options, one case each."""

PY_VALID = {2, 15}
"""Indices of :data:`PY` that are valid calls (an answer is right there)."""

PY = [
    "import restitution as r; r.si_law(63e9, 0.2481, 2500, 'cylinder', 'wall').epsilon([1.0, 'x'])",
    "import restitution as r; r.si_law(63e9, 0.2481, 2500, 'cylinder', 'wall').epsilon(-1.0)",
    "import restitution as r; r.si_law(63e9, 0.2481, 2500, 'cylinder', 'wall').epsilon("
    "[1e-3, 1.0, 1e4], outside='nan')",
    "import restitution as r; r.si_law('63e9', 0.2481, 2500, 'cylinder', 'wall')",
    "import restitution as r; r.si_law(63e9, 0.2481, 2500, 'cube', 'wall')",
    "import restitution as r; r.si_law(63e9, 0.2481, 2500, 'cylinder', None)",
    "import restitution as r; r.si_law(63e9, float('nan'), 2500, 'cylinder', 'wall')",
    "import restitution as r; r.law(2.0)",
    "import restitution as r; r.law(0.33, path=123)",
    "import restitution as r; r.law(0.33, geometry='cube')",
    "from restitution.laws.request import LawRequest as L; L(E=True, nu=0.3, rho=7850, "
    "shape='sphere', against='wall')",
    "from restitution.laws.request import LawRequest as L; L(E=210e9, nu=0.3, rho=7850, "
    "shape='sphere', against='wall', wall_E='63e9')",
    "from restitution.laws.request import LawRequest as L; L(E=210e9, nu=0.3, rho=7850, "
    "shape='sphere', against='wall', speeds=[[1.0]])",
    "from restitution.laws.request import LawRequest as L; L(E=210e9, nu=0.3, rho=7850, "
    "shape='sphere', against='wall', measured_epsilon=0.9, measured_speed=1, radius=1e-3, "
    "measured_fixes='relaxation_time')",
    "from restitution.laws.law import EpsilonLaw as E; E.from_json('/dev/null')",
    "from restitution.laws.law import EpsilonLaw as E; repr(E(0.3, [1e-3, 1e-2], [0.99, 0.98], "
    "[1e-3, 1e-3], [True, True], {}))",
    "from restitution.dynamics.collision import CollisionSettings as C; C(integrator=['x'])",
    "from restitution.dynamics.collision import CollisionSettings as C; C(energy_tol=-1)",
    "from restitution.bodies.cache import get_modes; get_modes(0.33, count=-1)",
    "from restitution.bodies.cache import get_modes; get_modes(float('inf'), count=5)",
]
"""Python cases: each a program; a refusal is an exception of the package (``InputError`` and
its kin) with a one-line message, anything else a traceback."""

_PY_WRAPPER = (
    "import sys\n"
    "from restitution.errors import RestitutionError\n"
    "try:\n"
    "    exec(sys.argv[1])\n"
    "except RestitutionError as exc:\n"
    "    msg = str(exc)\n"
    "    print('error: ' + msg.replace(chr(10), ' | '), file=sys.stderr)\n"
    "    sys.exit(2)\n"
)

_CLI_WRAPPER = "import sys\nfrom restitution.cli import main\nmain(sys.argv[1:])\n"

_RAISED = re.compile(r"^[\w.]*(Error|Exception|Interrupt)\b(: |$)")
"""The last line of a traceback (its head may be cut from a long stderr)."""

_WARNING = re.compile(r"\w*Warning: |^\s*warnings\.warn\(", re.M)


def cases(tmp: str) -> list[tuple[str, str, list[str], str]]:
    """Every case: ``(name, kind, argv, expect)``, kind ``cli`` or ``py``; ``expect`` is
    ``"refusal"`` (an answer is accepted silently), ``"plausible"`` (an answer needs a warning)
    or ``"any"``."""
    out = []
    for opt, bases in OPTIONS.items():
        for base in bases:
            for value in BAD:
                argv = list(BASES[base])
                if opt in argv:
                    argv[argv.index(opt) + 1] = value
                else:
                    argv += [opt, value, *EXTRA_OPTION_VALUE.get(opt, [])]
                if opt != "--speed":
                    argv += ["--speed", "1"]
                expect = "refusal" if value in MEANINGLESS else "plausible"
                if (
                    (value == "0" and opt in ZERO_IS_VALID)
                    or (value == "63" and opt not in UNIT_SLIPS)
                    or (value == "1e-300" and opt in TINY_IS_VALID)
                ):
                    expect = "any"
                if opt == "--speed" and value in ("1e300", "63"):
                    expect = "any"  # a speed outside a law's range is answered "no value"
                out.append((f"{base} {opt} {value!r}", "cli", [*argv, "--json"], expect))
    for argv in OTHER_CLI:
        argv = [a.replace("{tmp}", tmp) for a in argv]
        out.append((" ".join(argv), "cli", argv, "any"))
    for k, code in enumerate(PY):
        expect = "any" if k in PY_VALID else "refusal"
        out.append((code.split(";", 1)[-1].strip()[:90], "py", [code], expect))
    return out


def _served_wrong(stdout: str) -> str | None:
    """Why a JSON answer holds a value it should not serve, or ``None``."""
    try:
        doc = json.loads(stdout)
    except ValueError:
        return None
    rows = []

    def walk(x):
        if isinstance(x, dict):
            if "epsilon" in x and isinstance(x.get("epsilon"), int | float):
                rows.append(x)
            for v in x.values():
                walk(v)
        elif isinstance(x, list):
            for v in x:
                walk(v)

    walk(doc)
    for row in rows:
        eps, err, status = row["epsilon"], row.get("epsilon_err"), row.get("status")
        if not 0.0 < eps <= 1.0:
            return f"epsilon = {eps!r} served"
        if status == "ok" and isinstance(err, int | float) and err > eps:
            return f"ok epsilon = {eps:.3g} +- {err:.3g}"
    return None


def classify(rc: int | None, out: str, err: str, expect: str = "any") -> tuple[str, str]:
    """The case's class and the line that shows it."""
    lines = [x for x in err.splitlines() if x.strip()]
    last = lines[-1] if lines else ""
    if rc is None:
        return "hang", last
    if rc < 0 or rc == 137 or "MemoryError" in err or "Unable to allocate" in err:
        return "blow-up", last
    if "Traceback (most recent call last)" in err or _RAISED.match(last):
        return "traceback", last
    if rc in (0, 1):
        wrong = _served_wrong(out)
        if wrong:
            return "silently wrong", wrong
    if _WARNING.search(err):
        return "raw warning", next(x for x in lines if _WARNING.search(x))
    if rc == 2:
        errors = [x for x in lines if x.startswith("error: ")]
        others = [x for x in lines if not x.startswith(("error: ", "warning: ", "note: "))]
        if len(errors) == 1 and not others:
            return "refused", errors[0]
        return "messy refusal", last
    if rc in (0, 1):
        warned = any(x.startswith("warning: ") for x in lines) or "Warning" in err
        if expect == "refusal" and not warned:
            return "accepted silently", last
        if expect == "plausible" and not warned:
            return "implausible, no word", last
        return "answer", last
    return "messy refusal", f"exit {rc}: {last}"


def run_case(case, timeout: float, memory: int, cache: str) -> dict:
    name, kind, argv, expect = case
    wrapper = _CLI_WRAPPER if kind == "cli" else _PY_WRAPPER
    cmd = ["prlimit", f"--as={memory}", sys.executable, "-c", wrapper, *argv]
    env = dict(os.environ, RESTITUTION_CACHE_DIR=cache, MPLBACKEND="Agg", OPENBLAS_NUM_THREADS="1")
    t0 = time.perf_counter()
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env,
                             stdin=subprocess.DEVNULL)  # fmt: skip
        rc, out, err = run.returncode, run.stdout, run.stderr
    except subprocess.TimeoutExpired as exc:
        rc, out = None, ""
        err = exc.stderr.decode() if isinstance(exc.stderr, bytes) else (exc.stderr or "")
    seconds = time.perf_counter() - t0
    cls, line = classify(rc, out, err, expect)
    kept = err if len(err) <= 3000 else err[:1000] + "\n...\n" + err[-2000:]
    return {"case": name, "kind": kind, "class": cls, "line": line[:300], "exit": rc,
            "seconds": round(seconds, 1), "stderr": kept, "stdout": out[-20000:],
            "expect": expect}  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--memory", type=int, default=4 << 30, help="bytes of address space")
    parser.add_argument("--json", help="write every case's result here")
    parser.add_argument("--only", help="run the cases whose name contains this")
    parser.add_argument("--reclassify", help="classify the results of an earlier --json again")
    args = parser.parse_args()
    if args.reclassify:
        with open(args.reclassify) as fh:
            results = json.load(fh)
        expect = {name: e for name, _, _, e in cases("{tmp}")}
        for r in results:
            e = expect.get(r["case"], r.get("expect", "any"))
            r["class"], r["line"] = classify(r["exit"], r.get("stdout", ""), r["stderr"], e)
        _summary(results, args.json)
        return
    with tempfile.TemporaryDirectory(prefix="hostile-") as tmp:
        cache = os.environ.get("RESTITUTION_CACHE_DIR") or os.path.join(tmp, "cache")
        todo = [c for c in cases(tmp) if not args.only or args.only in c[0]]
        results = []
        with cf.ThreadPoolExecutor(args.jobs) as pool:
            futures = [pool.submit(run_case, c, args.timeout, args.memory, cache) for c in todo]
            for f in cf.as_completed(futures):
                r = f.result()
                results.append(r)
                print(f"{r['class']:>15}  {r['seconds']:5.1f} s  {r['case']}  | {r['line']}",
                      flush=True)  # fmt: skip
    _summary(results, args.json)


def _summary(results: list[dict], path: str | None) -> None:
    """Print the counts by class (and the cases not refused); write ``path`` if given."""
    counts = Counter(r["class"] for r in results)
    for r in sorted(results, key=lambda r: (r["class"], r["case"])):
        if r["class"] not in ("refused", "answer"):
            print(f"{r['class']:>22}  {r['case']}  | {r['line'][:200]}")
    print(f"\n{len(results)} cases: " + ", ".join(f"{n} {c}" for c, n in counts.most_common()))
    if path:
        with open(path, "w") as fh:
            json.dump(sorted(results, key=lambda r: r["case"]), fh, indent=1)


if __name__ == "__main__":
    main()
