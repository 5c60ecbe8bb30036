"""The Table 1 study (:mod:`restitution.reproduction.table1_scores`) as Markdown: the tables of
docs/table1.md.

Command line (about 55 collisions, two minutes on one shared core)::

    python -m restitution.reproduction.table1_report [--quick] > tables.md
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from restitution.reproduction.table1_scores import (
    PAPER_AFTER,
    PAPER_LABELS,
    PAPER_MEAN,
    TOLERANCE,
    Result,
    Score,
    quick_setups,
    run,
)

__all__ = ["axes", "main", "to_markdown"]


def _pct(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{100.0 * x:+.0f} %"


def axes(s: Score) -> dict:
    """The protocol's choice on every axis, as text."""
    su, r = s.setup, s.reading
    speed = f"{su.v_i:g} {su.reading}" if su.v_i == 0.1 else f"{su.v:g} c (scan)"
    return {
        "speed": speed,
        "alpha": f"{su.alpha:g}",
        "modes": su.modes.label,
        "nu": f"{su.nu:g}",
        "edge nodes": "auto" if su.n_phi is None else str(su.n_phi),
        "window": r.window,
        "normalisation": r.norm,
        "after": r.after,
        "counting": r.count,
    }


def _by_mean(s: Score) -> float:
    return s.misfit_mean


def _by_after(s: Score) -> float:
    return s.misfit_after


def _table(header, rows) -> list[str]:
    return [
        "| " + " | ".join(header) + " |",
        "|" + "---|" * len(header),
        *("| " + " | ".join(str(c) for c in row) + " |" for row in rows),
    ]


def _summary(s: Score) -> list:
    return [
        f"{s.matched}/10",
        s.same_rank,
        _pct(s.d_mean[0]),
        _pct(s.d_after[0]),
        _pct(float(np.max(np.abs(s.d_mean)))),
        _pct(float(np.max(np.abs(s.d_after)))),
        f"{s.misfit:.3f}",
    ]


SUMMARY = ["matched", "same rank", "rank 1 mean", "rank 1 after", "max mean", "max after",
           "misfit"]  # fmt: skip


def _rows(s: Score) -> list[str]:
    rows = []
    for i, (n, l) in enumerate(PAPER_LABELS):
        rank = int(s.ranks[i])
        rows.append(
            [
                i + 1,
                f"({n},{l})",
                rank if rank <= 10 else f"{rank} (not in top ten)",
                f"{PAPER_MEAN[i]:.5f}",
                f"{s.mean[i]:.5f}",
                _pct(s.d_mean[i]),
                f"{PAPER_AFTER[i]:.6f}",
                f"{s.after[i]:.6f}",
                _pct(s.d_after[i]),
            ]
        )
    header = ["paper rank", "(n, l)", "our rank", "paper mean", "ours", "diff", "paper after",
              "ours", "diff"]  # fmt: skip
    return _table(header, rows)


def to_markdown(result: Result) -> str:
    """Every table of docs/table1.md."""
    out = []
    out += ["### The paper's words, read in four speed units", ""]
    out += _table(
        ["reading", "v [c]", "epsilon", *SUMMARY],
        [
            [k, f"{s.setup.v:.4g}", f"{s.epsilon:.4f}", *_summary(s)]
            for k, s in result.paper.items()
        ],
    )
    out += ["", "### The best protocol for each choice", ""]
    rows = []
    for axis in axes(result.best):
        seen = {}
        for s in result.scores:  # sorted by misfit: the first of each value is its best
            seen.setdefault(axes(s)[axis], s)
        for value, s in seen.items():
            rest = ", ".join(f"{a} {v}" for a, v in axes(s).items() if a != axis)
            rows.append([axis, value, *_summary(s), rest])
    out += _table(["axis", "value", *SUMMARY, "the other choices of that protocol"], rows)
    out += ["", "### The ten best protocols", ""]
    out += _table(["protocol", *SUMMARY], [[s.label, *_summary(s)] for s in result.scores[:10]])
    most = max(result.scores, key=lambda s: (s.matched, s.same_rank, -s.misfit))
    for title, s in (
        ("The paper's words read literally (this package's Table 1)", result.paper.get("c")),
        ("The best protocol", result.best),
        ("The best protocol for the mean energies alone", min(result.scores, key=_by_mean)),
        ("The best protocol for the energies after alone", min(result.scores, key=_by_after)),
        ("The protocol with the most of the paper's modes in its top ten", most),
    ):
        if s is not None:
            out += ["", f"### {title}: {s.label}", ""]
            out += [
                f"Misfit {s.misfit:.3f} (means {s.misfit_mean:.3f}, after {s.misfit_after:.3f}); "
                f"epsilon {s.epsilon:.4f}; our top ten: "
                + ", ".join(f"({n},{l})" for n, l in s.top)
                + ".",
                "",
            ]
            out += _rows(s)
    out += ["", *_consistency(result)]
    reproduced = result.reproduced
    out += [
        "",
        f"{len(result.scores)} protocols ({result.collisions} collisions, "
        f"{result.seconds:.0f} s of collisions); reproduced within {100 * TOLERANCE:g} %: "
        f"{len(reproduced)}.",
    ]
    return "\n".join(out) + "\n"


def _where(v: float) -> str:
    if not math.isfinite(v):
        return "nowhere in the scan"
    return (
        f"at v = {v:.4g} c ({v / 0.1:.3f} x 0.1; c_L would be 1.059 x, c_T 0.613 x, relative 0.5 x)"
    )


def _consistency(result: Result) -> list[str]:
    c = result.consistency
    out = ["### The paper against itself", ""]
    out += [
        f"The paper's ten energies after the collision sum to {c.after_sum:.4f} E0, so at its "
        f"settings epsilon <= sqrt(1 - {c.after_sum:.4f}) = {c.epsilon_bound:.4f}. Its ten mean "
        f"energies sum to {c.mean_sum:.4f} E0.",
        "",
    ]
    out += _table(
        [
            "reading",
            "v [c]",
            "our epsilon",
            "our 1 - eps^2",
            "share in the ten",
            "paper's implied 1 - eps^2",
            "implied epsilon",
        ],  # fmt: skip
        [
            [
                r[0],
                f"{r[1]:.4g}",
                f"{r[2]:.4f}",
                f"{r[3]:.4f}",
                f"{r[4]:.3f}",
                f"{r[5]:.4f}",
                f"{r[6]:.4f}",
            ]  # fmt: skip
            for r in c.by_reading
        ],
    )
    lo, hi = c.share_range
    out += [
        "",
        "Our ten labels' energies after sum to the paper's "
        f"{c.after_sum:.4f} {_where(c.speed_for_after)}; their mean energies reach the paper's "
        f"{c.mean_sum:.4f} {_where(c.speed_for_mean)}"
        + " (alpha = 500, 1600 lowest modes, contact window). Over every setup the paper's ten "
        f"labels hold {100 * lo:.0f}-{100 * hi:.0f} % of our 1 - eps^2; for the paper's sum to be "
        "its whole loss they would have to hold all of it.",
        "",
        "Ratios of two rows (independent of the normalisation), the paper's beside the range "
        "over every protocol that counts by mode:",
        "",
    ]
    out += _table(
        ["ratio", "paper", "our least", "our largest", "paper inside?", "least under"],
        [
            [name, f"{p:.3g}", f"{lo:.3g}", f"{hi:.3g}", "yes" if lo <= p <= hi else "**no**", at]
            for name, p, lo, hi, at in c.ratios
        ],
    )
    pulse = c.pulse
    pe, pr = pulse.paper()
    out += [
        "",
        "The breathing rows against one force pulse (our collision's at v = 0.1 c, alpha = 500, "
        f"contact time {pulse.contact_time:.2f} R/c), stretched in time at fixed impulse; the "
        "driven-oscillator formula against the collision's own breathing energies at stretch 1: "
        + ", ".join(
            f"({0},{k}) mean {_pct(pulse.predicted[0, k] / pulse.measured[0, k] - 1)}, after "
            f"{_pct(pulse.predicted[1, k] / pulse.measured[1, k] - 1)}"
            for k in range(3)
        )
        + ".",
        "",
    ]
    rows = []
    for what, values, target in (
        ("mean (0,0) = paper's", pulse.energies[:, 0, 0], pe[0, 0]),
        ("mean (0,1) = paper's", pulse.energies[:, 0, 1], pe[0, 1]),
        ("mean (0,0) / (0,1) = paper's", pulse.ratios[:, 0], pr[0]),
    ):
        s = pulse.first_stretch(values, target)
        if not math.isfinite(s):
            rows.append([what, "never", "", "", "", "", ""])
            continue
        k = pulse.at(s)
        e, r = pulse.energies[k], pulse.ratios[k]
        rows.append(
            [
                what,
                f"{s:.3g}",
                f"{s * pulse.contact_time:.2f}",
                f"{e[0, 0]:.4f}",
                f"{e[0, 1]:.4f}",
                f"{e[0, 2]:.5f}",
                f"{r[0]:.3g} / {r[1]:.3g}",
            ]  # fmt: skip
        )
    rows.append(
        [
            "paper",
            "",
            "",
            f"{pe[0, 0]:.4f}",
            f"{pe[0, 1]:.4f}",
            f"{pe[0, 2]:.5f}",
            f"{pr[0]:.3g} / {pr[1]:.3g}",
        ]  # fmt: skip
    )
    long = pulse.stretch >= 0.5
    out += _table(
        [
            "stretch where",
            "stretch",
            "contact [R/c]",
            "mean (0,0)",
            "mean (0,1)",
            "mean (0,2)",
            "mean (0,0)/(0,1) / (0,1)/(0,2)",
        ],  # fmt: skip
        rows,
    )
    out += [
        "",
        f"For every stretch >= 0.5 the pulse gives mean (0,0)/(0,1) >= "
        f"{float(pulse.ratios[long, 0].min()):.3g} (paper {pr[0]:.3g}).",
    ]
    return out


def main(argv=None) -> None:
    """Print the tables (``--quick``: the paper's setup in c and c_L only)."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="two setups instead of ~55")
    args = parser.parse_args(argv)
    t0 = time.perf_counter()
    result = run(quick_setups() if args.quick else None)
    print(to_markdown(result), end="")
    print(f"\nStudy time {time.perf_counter() - t0:.0f} s (wall).")


if __name__ == "__main__":
    main()
