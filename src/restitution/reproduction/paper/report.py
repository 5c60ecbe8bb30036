"""The reproduction report of a paper run as document blocks
(:mod:`restitution.reproduction.report`).

:func:`paper_blocks` lays out the report: a quick-run banner, the summary of every claim with its
verdict, which reading of the paper's speeds reproduces which claim, links to this run's
epsilon(v) law exports, every figure with its caption and claims, Table 1, the errata and the
parameters. Rendering is :func:`restitution.reproduction.report.to_markdown` and ``to_html``.
"""

from __future__ import annotations

import json
import math
import os
import platform

import numpy as np

from restitution._version import __version__
from restitution.reproduction.report import (
    Block,
    Code,
    Figure,
    Heading,
    Paragraph,
    Table,
    parse_markdown_table,
)

__all__ = ["paper_blocks"]

_CAPTIONS = {
    "fig01_epsilon": (
        "Fig. 1: coefficient of restitution against the speed towards the wall, extrapolated "
        "to a hard wall (alpha -> infinity) and infinitely many modes; open markers did not "
        "pass the asymptotic checks (marked * in the table). Lines: shape-preserving (PCHIP) "
        "interpolation between the computed points only; nothing is drawn below the slowest "
        "computed speed. Speeds in c = sqrt(E/rho), the paper's stated unit."
    ),
    "fig01_epsilon_c_L": (
        "Fig. 1 with the paper's speeds read in units of the dilatational wave speed "
        "c_L = c / sqrt(1 - nu^2): every collision ran at v_i c_L (2.294 v_i at nu = 0.9, "
        "1.059 v_i at nu = 0.33, in c) through the same sweep and extrapolation; the axis is "
        "v_i / c_L. Markers as in Fig. 1."
    ),
    "fig02_shapes": (
        "Fig. 2: radii and circles of the undeformed disk displaced by one mode each "
        "(amplitude Q = {amp:g} R)."
    ),
    "fig03_spectrum": (
        "Fig. 3: frequencies of the symmetric modes against the number n of directional nodes "
        "(the caption's 'radial nodes' is a misprint); radial type |C| > |S|."
    ),
    "fig05_snapshots": (
        "Fig. 5: the disk hitting the wall, {modes} modes, alpha = {alpha:g}; times in R/c. "
        "The last frames (orange) follow the separation over one period of the quadrupole, "
        "by the exact free flow of the modes: the vibrations left after the collision."
    ),
    "fig06_mode_energy": (
        "Fig. 6: log10 of the energy in the low (n, l) modes at closest approach, {modes} modes, "
        "v = {v:g} c, alpha = {alpha:g}. White cells: (n, l) is not among the {modes} "
        "lowest modes used (its frequency lies above the cut), so no energy was computed."
    ),
    "fig07_alpha": (
        "Fig. 7: 1 - epsilon^2 against 1/alpha at the largest N (filled, solid lines) and "
        "extrapolated to N -> infinity at each alpha (open, dashed); black bars at 1/alpha = 0 "
        "are both limits, a red cross one that extrapolates below zero (unphysical)."
    ),
    "fig08_modes": (
        "Fig. 8: 1 - epsilon^2 against 1/sqrt(N) at the largest alpha (filled, solid) and "
        "extrapolated to alpha -> infinity at each N (open, dashed); black bars at "
        "1/sqrt(N) = 0 are both limits, a red cross one that extrapolates below zero."
    ),
    "fig10_force": (
        "Fig. 10: force against compression: both contact laws, eq. (57) as printed (paper) "
        "and the centre-of-mass law (centre), "
        "static relaxation ({modes} modes, alpha = {alpha:g}) and recorded collisions "
        "({loop_modes} modes, alpha = {loop_alpha:g})."
    ),
    "fig11_contact": (
        "Fig. 11: contact time and maximal compression of the quasistatic collision under both "
        "contact laws (eq. 57 as printed and centre of mass); "
        "diamonds: contact times of the sweep's collisions with the hardest wall at each speed "
        "(N = {n})."
    ),
    "fig12_rayleigh": (
        "Fig. 12: energy left in the lowest {modes} modes after a quasistatic collision "
        "(Rayleigh, contact law '{law}'), all modes and (2, 0) alone; diamonds: the "
        "extrapolated dynamic loss of the sweep."
    ),
}

_FIGURE_CLAIMS = {
    "fig01_epsilon": ("Fig. 1", "Sec. 6 / Fig. 1"),
    "fig01_epsilon_c_L": ("Fig. 1", "Sec. 6 / Fig. 1"),
    "fig02_shapes": ("Fig. 2",),
    "fig03_spectrum": ("Fig. 3", "Fig. 3 / eq. (20)"),
    "fig05_snapshots": ("Fig. 5",),
    "fig06_mode_energy": ("Fig. 6",),
    "fig07_alpha": ("Fig. 7",),
    "fig08_modes": ("Fig. 8",),
    "fig10_force": ("Eq. (57)", "Fig. 10"),
    "fig11_contact": ("Fig. 11", "Fig. 11 / Sec. 6"),
    "fig12_rayleigh": ("Fig. 12",),
}


def _caption(stem: str, d) -> str:
    s = d.settings
    base = stem.split("_nu")[0]
    n_contact = d.contact_points[0][2] if d.contact_points else max(s.sweep.n_modes)
    return _CAPTIONS[base].format(
        amp=s.shape_amplitude,
        modes={
            "fig05_snapshots": s.snapshot_modes,
            "fig06_mode_energy": s.collision_modes,
            "fig10_force": s.relax_modes,
            "fig12_rayleigh": s.rayleigh_modes,
        }.get(base, 0),
        alpha=s.snapshot_alpha if base == "fig05_snapshots" else (
            s.relax_alpha if base == "fig10_force" else s.collision_alpha),
        v=s.collision_v,
        loop_modes=s.loop_modes,
        loop_alpha=s.loop_alpha,
        n=n_contact,
        law=s.law,
    )  # fmt: skip


def _epsilon_table(f, unit: str = "c") -> Table:
    """epsilon(v) +- error per Poisson number (Fig. 1 data); '*': not asymptotic."""
    speeds = sorted({round(float(v), 9) for vs in f.v for v in vs})
    rows = []
    for v in speeds:
        cells = [f"{v:g}"]
        for k in range(len(f.nus)):
            hit = np.nonzero(np.isclose(f.v[k], v, rtol=1e-9, atol=0.0))[0]
            if hit.size == 0 or not np.isfinite(f.epsilon[k][hit[0]]):
                cells.append("")
                continue
            i = hit[0]
            star = "" if f.asymptotic_ok[k][i] else " *"
            cells.append(f"{f.epsilon[k][i]:.4f} +- {f.epsilon_err[k][i]:.4f}{star}")
        rows.append(tuple(cells))
    header = (f"v [{unit}]", *(f"epsilon (nu = {nu:g})" for nu in f.nus))
    return Table(header, tuple(rows))


def _unit_table(comps) -> Table | None:
    """Which reading of the paper's speeds reproduces which claim (rows judged in both)."""
    by_claim: dict[str, dict[str, str]] = {}
    for c in comps:
        if c.speed_unit:
            name = c.claim.split(" [speeds in")[0]
            by_claim.setdefault(name, {})[c.speed_unit] = c.verdict
    units = sorted({u for d in by_claim.values() for u in d}, key=lambda u: u != "c")
    if len(units) < 2:
        return None
    rows = tuple(
        (name, *(d.get(u, "") for u in units))
        for name, d in by_claim.items()
        if len(d) == len(units)
    )
    return Table(("claim", *(f"speeds in {u}" for u in units)), rows)


def _verdict_text(c) -> str:
    """The verdict, and for a row that differs its protocol or attribution."""
    return f"{c.verdict}. Why: {c.why}" if c.why else c.verdict


def _comparison_table(rows) -> Table:
    return Table(
        ("where", "result", "paper says", "we get", "verdict"),
        tuple((c.figure, c.claim, c.paper, c.ours, _verdict_text(c)) for c in rows),
    )


def _errata_blocks(run) -> list[Block]:
    blocks: list = [Heading(2, "Errata: what the code uses instead of the printed equations")]
    docs = {p.name: p for p in run.docs}
    eq = docs.get("equations.md")
    if eq is not None:
        text = eq.read_text().splitlines()
        try:
            start = next(i for i, line in enumerate(text) if line.startswith("## List of corr"))
            table = parse_markdown_table(text[start + 1 :])
        except (StopIteration, ValueError):
            table = None
        blocks.append(
            Paragraph(
                "The printed paper carries misprints; the code follows the corrected equations "
                "of [docs/equations.md](docs/equations.md) (copied into this folder). Its list "
                "of corrections:"
            )
        )
        if table is not None:
            blocks.append(table)
    else:
        blocks.append(
            Paragraph(
                "The corrected equations and the list of corrections are in `docs/equations.md` "
                "of the source distribution (not found beside this installation)."
            )
        )
    from restitution.quasistatic.hertz import contact_law

    nu = run.data.settings.nu
    c_p, c_d, c_c = (contact_law(nu, k).constant for k in ("paper", "diameter", "centre"))
    blocks.append(Heading(3, "Eq. (57): the constant of the 2D Hertz law"))
    link = (
        "[docs/quasistatic.md](docs/quasistatic.md)"
        if "quasistatic.md" in docs
        else "`docs/quasistatic.md`"
    )
    blocks.append(
        Paragraph(
            "Eq. (57) prints delta = P/(pi E) (ln(4 pi E R/P) + c) with c = -1 - nu "
            f"({c_p:.3f} at nu = {nu:g}). Integrating eqs. (54)-(55) along the axis gives "
            f"c = -1 ({c_d:.3f}): the transverse stress integrates to zero and nu drops out. "
            "The equation of motion needs the approach of the centre of mass, not of the far "
            f"end of the diameter: c = -1 - 2/pi - nu/4 ({c_c:.3f}), identified numerically "
            "from the modes to 5e-4. The static relaxation (Fig. 10) and the dynamic contact "
            "times (Fig. 11) side with the centre-of-mass law, so it is the package's default "
            "(`restitution.quasistatic.hertz.contact_law`); Figs. 10 and 11 draw both laws, "
            "Fig. 12 uses "
            f"the '{run.data.settings.law}' law, and `law=\"paper\"` redraws the paper's own "
            f"curves. Details: {link}."
        )
    )
    if "quasistatic.md" in docs:
        text = docs["quasistatic.md"].read_text().splitlines()
        try:
            start = next(i for i, line in enumerate(text) if line.startswith("## 6."))
            end = next(
                (i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text)
            )
            quote = "\n".join(text[start + 1 : end]).strip()
        except StopIteration:
            quote = ""
        if quote:
            blocks.append(Paragraph(f"Disagreements with section 5, as summarised in {link}:"))
            blocks.append(Code(quote))
    return blocks


def _shipped_law_blocks() -> list[Block]:
    """The shipped epsilon(v) laws judged by the independent finite-element route."""
    from restitution.fem.judge import judge_shipped_law

    judged = judge_shipped_law()
    rows = tuple(
        (
            f"{p.nu:g}",
            f"{p.v:g}",
            f"{p.reference:.5f} +- {p.reference_err:.5f}",
            f"{p.law:.5f} +- {p.law_err:.5f}",
            f"{p.difference:+.5f}",
            f"{p.sigma:+.2f}" if math.isfinite(p.sigma) else (p.note or "n/a"),
        )
        for p in judged.points
    )
    return [
        Heading(2, "The shipped epsilon(v) laws against finite elements"),
        Paragraph(
            "The package's shipped laws (`restitution.laws.law`, collisions for "
            "1e-4 <= v/c <= 0.3 by `make law` and the slow-impact model below, independent "
            "of this run) against the finite-element route on "
            "contact-graded meshes with both limits h -> 0 and alpha -> infinity "
            "(`src/restitution/laws/data/fem_reference.json`, docs/fem.md). The last column is the "
            f"difference in combined errors. Coverage: {judged.coverage(1.0):.0%} within one, "
            f"{judged.coverage(2.0):.0%} within two combined errors "
            f"({len(judged.compared)} points)."
        ),
        Table(("nu", "v [c]", "FEM epsilon", "law epsilon", "difference", "sigma"), rows),
    ]


def _sphere_blocks(run) -> list[Block]:
    """Beyond the paper: the shipped sphere laws beside the cylinders' (its outlook)."""
    from restitution.bodies.sphere.kind import KIND as SPHERE
    from restitution.laws.law_nu import shipped_nus
    from restitution.reproduction.figures.sphere_cylinder import MATERIALS

    blocks: list = [Heading(2, "Beyond the paper: elastic spheres")]
    nus = shipped_nus(SPHERE.geometry)
    copied = any(p.name == "spheres.md" for p in run.docs)
    doc = "[docs/spheres.md](docs/spheres.md)" if copied else "`docs/spheres.md`"
    if run.spheres is None:
        blocks.append(
            Paragraph(
                "No sphere laws are shipped with this installation (`make law-sphere` computes "
                f"them); see {doc}."
            )
        )
        return blocks
    materials = "; ".join(
        f"{name}: E = {E / 1e9:g} GPa, nu = {nu:g}, rho = {rho:g} kg/m^3"
        for name, (E, nu, rho) in MATERIALS.items()
    )
    blocks += [
        Paragraph(
            "The paper's outlook names spheres. The package computes a sphere's vibrational "
            "epsilon(v) by the same modal method (Lamb's axisymmetric spheroidal modes, the same "
            "exponential wall integrated over the surface, both limits alpha, N -> infinity); "
            f"its shipped laws cover the 3D Poisson numbers {', '.join(f'{n:g}' for n in nus)} "
            "(independent of this run), from collisions at v/c = 0.003-0.3 and, down to v/c = "
            "1e-6, from Rayleigh's estimate on Hertz's force pulse with an error band (status "
            "'quasistatic', checked against the finite elements). Below they are served at SI "
            "speeds against a rigid wall "
            "beside the long cylinders (the paper's disk in plane strain) of the same materials "
            f"({materials}). Equations, checks and the measured convergence: {doc}."
        ),
        Figure(
            run.spheres.name,
            "epsilon of spheres and cylinders against impact speed",
            "Spheres (red) and long cylinders (blue) of three materials against a rigid wall; "
            "bands: the laws' errors; hollow points did not pass every asymptotic check; dashed: "
            "the sphere's low-speed theory.",
        ),
    ]
    return blocks


def paper_blocks(run, store_path: str = "") -> list[Block]:
    """The report of a paper run (:class:`restitution.reproduction.paper.PaperRun`) as blocks.

    Sections: summary table of every comparison, the figures each with its comparisons,
    Table 1, the errata, and the parameters (mode selection, extrapolation sets, sweep and
    stage timings, versions, date).
    """
    from restitution.bodies.kinds import DEFAULT_GEOMETRY
    from restitution.provenance import code_version
    from restitution.reproduction.figures.table1 import to_markdown

    d, s = run.data, run.data.settings
    from restitution.reproduction.claims import counts

    comps = run.comparisons
    n = counts(comps)
    sr = d.sweep_report
    blocks: list = [Heading(1, "Coefficient of restitution for elastic disks: reproduction report")]
    if s.name == "quick":
        blocks.append(
            Paragraph(
                "**QUICK RUN: coarse grids (few speeds, N = "
                f"{', '.join(str(n) for n in s.sweep.n_modes)} modes, small collisions); the "
                "numbers are not converged and the verdicts describe this run only.** Run "
                "`restitution paper` without `--quick` for the paper's sizes."
            )
        )
    blocks += [
        Paragraph(
            'F. Gerl and A. Zippelius, "Coefficient of restitution for elastic disks", '
            f"regenerated by `restitution paper` (restitution {__version__}, code "
            f"{code_version(DEFAULT_GEOMETRY)}) on {run.started} in {run.run_time_s:.0f} s."
        ),
    ]
    blocks += [
        Paragraph(
            "Units: two-dimensional E = rho = R = 1, so speeds v are in c = sqrt(E/rho) and "
            "are the disk's speed towards the wall (two identical disks approaching at +-v, "
            "relative speed 2v, collide the same way); times in R/c; energies as fractions of "
            "the initial kinetic energy."
        ),
        Heading(2, "Summary: the paper beside this reproduction"),
        Paragraph(
            f"{len(comps)} comparisons: {n['agrees']} agree, {n['differs']} differ, "
            f"{n['inconclusive']} inconclusive. 'agrees' means within the tolerance stated in "
            "the row, on points that passed their own checks; 'differs by' gives our value "
            "minus the paper's; 'inconclusive' means the points the claim rests on did not pass "
            "their checks (e.g. an extrapolation flagged as not asymptotic) or their errors "
            "exceed the tolerance, and the row says which way they lean at face value. The "
            "mode-by-mode rows of Table 1 are in the [Table 1](#table-1) section."
        ),
        _comparison_table([c for c in comps if not c.detail]),
    ]
    units = _unit_table(comps)
    if units is not None:
        blocks += [
            Heading(2, "Which unit of speed reproduces which claim"),
            Paragraph(
                "The paper states its speeds in c = sqrt(E/rho). Read in the dilatational wave "
                "speed c_L = c / sqrt(1 - nu^2) instead, every collision runs faster by "
                "1/sqrt(1 - nu^2) (2.294 at nu = 0.9, 1.059 at nu = 0.33). Every Fig. 1 claim, "
                "judged in both readings by the same rules:"
            ),
            units,
        ]
    blocks += [
        Heading(2, "epsilon(v) laws of this run"),
        Paragraph(
            "The extrapolated epsilon(v) of this run's sweep (speeds in c), written by "
            "`restitution.laws.law.EpsilonLaw` as JSON (points, fits, validity), CSV and a plain "
            "`v epsilon epsilon_err` table for DEM/ED codes"
            + (" (quick run: not converged)" if s.name == "quick" else "")
            + ": "
            + "; ".join(
                f"nu = {law.nu:g}: [JSON]({law.json.name}), [CSV]({law.csv.name}), "
                f"[table]({law.table.name})"
                for law in run.laws
            )
            + "."
        ),
        Heading(2, "Figures"),
    ]
    for f in run.figures:
        base = f.stem.split("_nu")[0]
        blocks.append(Heading(3, f.title))
        blocks.append(
            Figure(
                src=f.png.name,
                alt=f.title,
                caption=_caption(f.stem, d),
                links=((f.vector.suffix[1:].upper(), f.vector.name), ("PNG", f.png.name)),
            )
        )
        unit = "c_L" if base.endswith("_c_L") else "c"
        rows = [
            c
            for c in comps
            if c.figure in _FIGURE_CLAIMS.get(base, ())
            and (f.nu is None or f"(nu = {f.nu:g})" in c.claim)
            and c.speed_unit in ("", unit)
        ]
        if rows:
            blocks.append(_comparison_table(rows))
        if base.startswith("fig01_epsilon"):
            blocks.append(_epsilon_table(d.fig01_units[unit], unit))
    t = d.table1
    blocks += [
        Heading(2, "Table 1"),
        Paragraph(
            f"The ten modes with the most energy averaged over the contact, nu = {s.nu:g}, "
            f"v = {s.collision_v:g} c, alpha = {s.collision_alpha:g}, the "
            f"{s.collision_modes} lowest modes (epsilon = {t.epsilon:.4f}). Files: "
            f"[{run.table1[0].name}]({run.table1[0].name}), "
            f"[{run.table1[1].name}]({run.table1[1].name})."
        ),
        parse_markdown_table(to_markdown(t).splitlines()),
        _comparison_table([c for c in comps if c.figure == "Table 1"]),
    ]
    blocks += _shipped_law_blocks()
    blocks += _sphere_blocks(run)
    blocks += _errata_blocks(run)
    # Parameters.
    sw = s.sweep
    alpha_rows = tuple(
        (f"{v:g}", ", ".join(f"{a:.4g}" for a in sw.alphas_at(v))) for v in sw.velocities
    )
    blocks += [
        Heading(2, "Parameters"),
        Paragraph(
            f"Run `{s.name}`. Poisson numbers of Figs. 1, 7, 8: "
            f"{', '.join(f'{nu:g}' for nu in s.nus)}; all other figures and Table 1: "
            f"nu = {s.nu:g}."
        ),
        Paragraph(
            f'**Mode selection**: the N lowest frequencies (`select = "{sw.select}"`) for every '
            "computation; the paper instead ranked 1600 modes by their energy in a preliminary "
            "run (section 4)."
        ),
        Paragraph(
            "**Extrapolation sets** of the sweep: N = "
            f"{', '.join(str(n) for n in sw.n_modes)} (linear in 1/sqrt(N)); alpha values "
            f'{", ".join(f"{a:g}" for a in sw.alphas)} with `alpha_scale = "{sw.alpha_scale}"`'
            + (
                " (products alpha * delta_max(v), delta_max = v sqrt(ln(4/v)))"
                if sw.alpha_scale == "compression"
                else " (1/R at every speed)"
            )
            + f", linear in 1/alpha; order of the limits `{sw.order}`; integrator "
            f"`{sw.integrator}`; solver options "
            f"{', '.join(f'`{k} = {v}`' for k, v in sw.options if v is not None)}."
        ),
        Table(("v [c]", "alpha used [1/R]"), alpha_rows),
        Table(
            ("setting", "value"),
            tuple((k, json.dumps(v)) for k, v in d.settings.to_dict().items() if k != "sweep"),
        ),
        Paragraph(
            f"**Sweep**: {sr.total} collisions, {sr.skipped} found in the store, "
            f"{sr.computed} computed, {len(sr.failed)} failed, {sr.wall_time_s:.1f} s "
            f"({sr.executor}). Store: `{store_path}`."
            + "".join(
                f" **Sweep at the speeds read in {u}** (every speed times "
                f"1/sqrt(1 - nu^2)): {r.total} collisions, {r.skipped} found in the store, "
                f"{r.computed} computed, {len(r.failed)} failed, {r.wall_time_s:.1f} s."
                for u, r in d.sweep_reports.items()
                if u != "c"
            )
        ),
        Table(
            ("stage", "seconds"),
            tuple((label, f"{sec:.1f}") for label, sec in run.timings)
            + (("total (until this report was written)", f"{run.run_time_s:.1f}"),),
        ),
        Paragraph(
            f"restitution {__version__} (code {code_version(DEFAULT_GEOMETRY)}), Python "
            f"{platform.python_version()}, numpy {np.__version__}, {os.cpu_count()} CPU(s); "
            f"started {run.started}. Machine-readable record: [paper.json](paper.json)."
        ),
    ]
    return blocks
