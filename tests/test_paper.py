"""`restitution paper --quick`: files, report, and one independent number per figure.

One quick run (module fixture: 72 small collisions and the coarse figures, about a minute on
two cores) feeds every test; each figure's data is checked against a value computed here by
another method (closed forms, np.polyfit, scipy's DOP853).
"""

import csv
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import jv, jvp

from restitution.cli.paper import paper
from restitution.paper import FIGURE_STEMS, QUICK
from restitution.report import (
    Figure,
    Heading,
    Paragraph,
    Table,
    parse_markdown_table,
    slug,
    to_html,
    to_markdown,
)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    root = tmp_path_factory.mktemp("paper")
    args = ["--quick", "--out", str(root / "out"), "--store", str(root / "results.sqlite")]
    result = CliRunner().invoke(
        paper, [*args, "--no-progress"], standalone_mode=False, catch_exceptions=False
    )
    return result.return_value


def breathing_kappa(nu: float) -> float:
    """Lowest root of eq. (20), kappa J_1'(kappa) + nu J_1(kappa) = 0 (bracket by inspection)."""
    return brentq(lambda k: k * jvp(1, k) + nu * jv(1, k), 1.0, 3.0, xtol=1e-15)


# -- files and report ----------------------------------------------------------------------


def test_every_figure_is_written_and_decodes(run):
    import matplotlib.image

    written = {f.stem: f for f in run.figures}
    for base in FIGURE_STEMS:
        assert any(s.startswith(base) for s in written), base
    assert len(written) == len(FIGURE_STEMS) + 2  # Figs. 7 and 8 once per nu
    for f in run.figures:
        image = matplotlib.image.imread(f.png)
        assert image.ndim == 3 and image.shape[0] > 100 and image.shape[1] > 100, f.png
        assert np.ptp(image[..., :3]) > 0.5, f"{f.png} is blank"
        assert f.vector.suffix == ".svg"
        root = ET.parse(f.vector).getroot()
        assert root.tag.endswith("svg"), f.vector
        assert sum(1 for _ in root.iter()) > 20, f"{f.vector} has no drawing"


def test_table1_has_ten_rows(run):
    md_path, csv_path = run.table1
    with csv_path.open() as fh:
        rows = list(csv.DictReader(fh))
    assert [int(r["rank"]) for r in rows] == list(range(1, 11))
    table = parse_markdown_table(md_path.read_text().splitlines())
    assert len(table.rows) == 10
    t = run.data.table1
    assert np.all(np.diff(t.mean_contact) <= 0)  # ranked by mean energy
    # Energy conservation: the modes cannot keep more than the lost kinetic energy, 1 - eps^2.
    assert t.after.sum() <= 1.0 - t.epsilon**2 + 1e-3


def _links(text: str, pattern: str) -> list[str]:
    return [x for x in re.findall(pattern, text) if not x.startswith("#")]


def test_report_links_and_images_resolve(run):
    html = run.report_html.read_text()
    md = run.report_md.read_text()
    html_links = _links(html, r'(?:src|href)="([^"]+)"')
    md_links = _links(md, r"\]\(([^)\s]+)\)")
    images = re.findall(r'<img src="([^"]+)"', html)
    assert sorted(images) == sorted(f.png.name for f in run.figures)
    assert len(md_links) > len(run.figures)
    for link in html_links + md_links:
        assert "://" not in link, link
        assert (run.out / link).is_file(), link
    # Anchors point at headings.
    for anchor in re.findall(r'href="#([^"]+)"', html):
        assert f'id="{anchor}"' in html


def test_report_compares_with_the_paper_and_records_the_run(run):
    md = run.report_md.read_text()
    claims = {c.claim for c in run.comparisons}
    for claim in (
        "epsilon at nu = 0.9, v = 0.3 c",
        "more inelastic for nu = 0.9 than for nu = 0.33",
        "epsilon -> 1 as v -> 0, decreasing with v",
        "lowest mode",
        "breathing modes (n = 0)",
        "tau ~ pi delta_max / v",
        "contact time diverges logarithmically",
        "Rayleigh energy dominated by (2, 0)",
        "rank 1: mode (2, 0)",
    ):
        assert claim in claims
    for c in run.comparisons:
        assert c.verdict.split()[0] in ("agrees", "differs", "undetermined:"), c
        assert c.claim in md
    assert "epsilon ~ 0.65 for nu = 0.9" in md
    assert "Errata" in md and "docs/equations.md" in md and "-1 - 2/pi - nu/4" in md
    assert "N lowest frequencies" in md and "alpha_scale" in md and "Quick run" in md
    from restitution import __version__

    assert f"restitution {__version__}" in md
    assert run.record.is_file() and run.run_time_s > 0


def test_second_run_reuses_the_store(run, tmp_path):
    from restitution.store import Store
    from restitution.sweep import grid, run_sweep

    s = QUICK
    assert run.data.sweep_report.failed == ()
    with Store(run.out.parent / "results.sqlite") as db:
        report = run_sweep(grid(s.nus, s.sweep), store=db)
    assert report.computed == 0 and report.skipped == report.total == 72


# -- one independent number per figure -----------------------------------------------------


def test_fig01_fig07_fig08_limits_equal_direct_fits(run):
    d = run.data
    for k_nu, nu in enumerate(d.fig01.nus):
        f7, f8, curve = d.fig07[k_nu], d.fig08[k_nu], d.curves[nu]
        for k, lim in enumerate(curve.limits):
            # Fig. 7: straight line in 1/alpha through the plotted points at N = max.
            slope, icpt = np.polyfit(1.0 / f7.alpha[k], f7.loss[k], 1)
            assert_allclose([f7.limit[k], f7.slope[k]], [icpt, slope], rtol=1e-9, atol=1e-12)
            # Fig. 8: straight line in 1/sqrt(N) at the largest alpha.
            slope, icpt = np.polyfit(1.0 / np.sqrt(f8.n_modes), f8.loss[k], 1)
            assert_allclose([f8.limit[k], f8.slope[k]], [icpt, slope], rtol=1e-9, atol=1e-12)
            # Fig. 1: both limits, N first (each alpha), then alpha, by np.polyfit.
            at_alpha = [np.polyfit(1.0 / np.sqrt(lim.n_modes), row, 1)[1] for row in lim.loss]
            loss = np.polyfit(1.0 / lim.alpha, at_alpha, 1)[1]
            assert_allclose(d.fig01.epsilon[k_nu][k], math.sqrt(1.0 - loss), rtol=1e-9)


def test_fig02_breathing_mode_edge_from_bessel_functions(run):
    # n = 0: U_r = -A kappa J_1(kappa r), normalised by int_0^1 r U_r^2 dr = 1/2 (eq. 26), so
    # the edge moves by Q C with C = |J_1(kappa)| / sqrt(2 int_0^1 r J_1(kappa r)^2 dr).
    nu, amp = QUICK.nu, QUICK.shape_amplitude
    kappa = breathing_kappa(nu)
    norm = quad(lambda r: r * jv(1, kappa * r) ** 2, 0.0, 1.0, epsabs=1e-14)[0]
    C = abs(jv(1, kappa)) / math.sqrt(2.0 * norm)
    k = list(QUICK.shape_modes).index((0, 0))
    x, y = run.data.fig02.lines[k][5]  # the outermost of fig02_shapes' six circles, r = 1
    assert_allclose(np.hypot(x, y), 1.0 + amp * C, rtol=1e-10)


def test_fig03_lowest_breathing_root(run):
    f3 = run.data.fig03
    nu = f3.nu
    # Lowest root of eq. (20) for nu = 0.33: kappa = 2.067364 (brentq here); omega = kappa c_p.
    kappa = breathing_kappa(nu)
    assert_allclose(kappa, 2.067364, atol=1e-6)
    assert_allclose(np.min(f3.omega[f3.n == 0]), kappa / math.sqrt(1 - nu**2), rtol=1e-10)


def test_fig05_first_snapshot_is_the_undeformed_circle(run):
    f5 = run.data.fig05
    x, y = f5.x[0], f5.y[0]
    centre = 0.5 * (x.max() + x.min())
    assert centre < -1.0  # not yet touching the wall at x = 0
    assert_allclose(np.hypot(x - centre, y), 1.0, atol=1e-9)


def test_fig06_grid_is_the_collision_result(run):
    from restitution import collide, get_modes

    f6 = run.data.fig06
    s = QUICK
    r = collide(get_modes(s.nu, count=s.collision_modes), s.collision_v, s.collision_alpha)
    for n, l, e in zip(r.mode_n, r.mode_l, r.mode_energy_closest, strict=True):
        if n < f6.energy.shape[0] and l < f6.energy.shape[1]:
            assert_allclose(f6.energy[n, l], e, rtol=1e-12)
    assert np.nanargmax(f6.energy) == np.ravel_multi_index((2, 0), f6.energy.shape)


def test_fig10_law_solves_printed_eq57(run):
    f10 = run.data.fig10
    nu = f10.nu
    i = f10.law_delta.size // 3
    d, P = f10.law_delta[i], f10.law_force_paper[i]
    # Eq. (57) as printed: delta = P/(pi E) (ln(4 pi E R / P) - 1 - nu), E = R = 1.
    assert_allclose(d, P / math.pi * (math.log(4 * math.pi / P) - 1 - nu), rtol=1e-10)
    assert f10.relax_force[-1] > f10.relax_force[0] > 0


def test_fig11_contact_time_against_dop853(run):
    from restitution.hertz import contact_law

    f11 = run.data.fig11
    law = contact_law(f11.nu, "paper")
    k = int(np.argmin(np.abs(np.log(f11.v / 1e-3))))
    v, m = float(f11.v[k]), math.pi

    def rhs(t, y):
        return [y[1], -float(law.force(max(y[0], 0.0))) / m]

    def leaves(t, y):
        return y[0]

    def turns(t, y):
        return y[1]

    leaves.terminal, leaves.direction = True, -1
    sol = solve_ivp(
        rhs, (0.0, 100.0), [0.0, v], method="DOP853", rtol=1e-11, atol=1e-16,
        events=[leaves, turns], first_step=1e-6,
    )  # fmt: skip
    assert_allclose(f11.contact_time_paper[k], sol.t_events[0][0], rtol=1e-6)
    assert_allclose(f11.max_compression_paper[k], sol.y_events[1][0][0], rtol=1e-6)


def test_fig12_quadrupole_against_dop853(run):
    from restitution import get_modes
    from restitution.hertz import contact_law, quasistatic_trajectory

    f12 = run.data.fig12
    k = int(np.argmin(np.abs(np.log(f12.v / 1e-3))))
    v, m = float(f12.v[k]), math.pi
    modes = get_modes(f12.nu, count=f12.n_modes)
    q = int(np.nonzero((modes.n == 2) & (modes.l == 0))[0][0])
    w, C = float(modes.omega[q]), float(modes.C[q])
    traj = quasistatic_trajectory(contact_law(f12.nu, f12.law), v)
    tau = traj.contact_time

    # m Q'' + m w^2 Q = -C P(t) from rest (eq. 64 corrected); Q in units of v.
    def rhs(t, y):
        return [y[1], -(w**2) * y[0] - C * float(traj.force(t)) / (m * v)]

    sol = solve_ivp(rhs, (0.0, tau), [0.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-14,
                    max_step=tau / 400)  # fmt: skip
    Q, Qdot = sol.y[:, -1]
    energy = Qdot**2 + w**2 * Q**2  # (m/2)(Q'^2 + w^2 Q^2) / ((m/2) v^2)
    assert_allclose(f12.quadrupole[k], energy, rtol=1e-5)
    assert f12.total[k] >= f12.quadrupole[k]


# -- the command line and the report writer --------------------------------------------------


def test_paper_command_rejects_bad_options(tmp_path):
    runner = CliRunner()
    result = runner.invoke(paper, ["--format", "gif", "--out", str(tmp_path)])
    assert result.exit_code == 2 and "gif" in result.output
    result = runner.invoke(paper, ["--workers", "0", "--out", str(tmp_path)])
    assert result.exit_code == 2
    assert "--quick" in runner.invoke(paper, ["--help"]).output


def test_report_writer_renders_the_same_blocks():
    blocks = [
        Heading(2, "Table 1"),
        Paragraph("see `a|b` and [the table](t.csv) <x>"),
        Table(("a", "b"), (("`omega |q|^2`", "agrees"), ("2", "differs by 3"))),
        Figure("f.png", "Fig. 1", "cap", (("SVG", "f.svg"),)),
    ]
    md = to_markdown(blocks)
    assert "`omega \\|q\\|^2`" in md and "![Fig. 1](f.png)" in md and "[SVG](f.svg)" in md
    assert parse_markdown_table(md.splitlines()).rows[0][0] == "`omega |q|^2`"
    html = to_html(blocks, "t")
    assert '<h2 id="table-1">' in html and slug("Table 1") == "table-1"
    assert "<code>a|b</code>" in html and '<a href="t.csv">' in html and "&lt;x&gt;" in html
    assert '<td class="agrees">agrees</td>' in html and 'class="differs"' in html
    assert '<img src="f.png" alt="Fig. 1">' in html
