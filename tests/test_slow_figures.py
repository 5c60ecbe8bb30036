"""Figures of the slow points: they show the law's own numbers (read, not recomputed)."""

import numpy as np
import pytest

from restitution.bodies.cache import get_modes
from restitution.laws.law_load import law
from restitution.limits.extrapolation import extrapolate_modes
from restitution.quasistatic.hertz import contact_law
from restitution.quasistatic.rayleigh import rayleigh_energy
from restitution.reproduction.figures import slow_convergence, slow_routes


def test_slow_convergence_shows_the_served_numbers(tmp_path):
    served = law(0.33)
    points = slow_convergence.compute(served, v_max=0.02, count=4)
    # The four slowest modal points (as make law draws them): one served by the residual route
    # (issue 65; every point up to 1e-3 since 4 Dec 2026) has no fit in 1/sqrt(N) to show.
    routes = {r["v"]: r.get("route", "modal") for r in served._records()}
    speeds = sorted(v for v, route in routes.items() if route == "modal" and v <= 0.02)[:4]
    assert len(speeds) == 4 and min(speeds) > 1e-3
    assert [p.v for p in points] == pytest.approx(speeds)
    for p in points:
        # The diamond is what the law serves: 1 - epsilon^2 at that speed.
        assert p.limit == pytest.approx(1.0 - served.epsilon(p.v) ** 2, rel=1e-9)
        # Each square is the N -> infinity fit of its row, redone from the plotted points.
        for i in range(p.alpha.size):
            redo = extrapolate_modes(p.n_modes, p.loss[i])
            assert p.n_limit[i] == pytest.approx(redo.limit, rel=1e-12)
    fig = slow_convergence.plot(points[:2], 0.33, tmp_path / "conv.png")
    assert len(fig.axes) == 4 and (tmp_path / "conv.png").stat().st_size > 10_000


def test_slow_routes_put_the_law_beside_rayleigh(tmp_path):
    served = law(0.9)
    data = slow_routes.compute(served, n_modes=60, v_max=1e-3, n_v=6)
    direct = rayleigh_energy(get_modes(0.9, count=60), float(data.v[0]), contact_law(0.9, "centre"))
    assert data.rayleigh["centre"][0] == pytest.approx(direct.energy_fraction, rel=1e-12)
    rows = slow_routes.compare(data)
    assert rows[0]["dynamic"] == pytest.approx(1.0 - served.epsilon(rows[0]["v"]) ** 2, rel=1e-9)
    assert all(np.isfinite(r["ratio_paper"]) and r["ratio_paper"] > 0 for r in rows)
    slow_routes.plot(data, tmp_path / "routes.png")
    assert (tmp_path / "routes.png").stat().st_size > 10_000


@pytest.mark.slow  # 13 s (stop 76: the default run under 10 min)
def test_make_law_draws_both_figures_of_a_shipped_law(tmp_path):
    """restitution.reproduction.law_figures (the step of ``make law`` that draws
    docs/figures/slow_*_nu<nu>.png): both figures of the law at ``nu = 0.33`` are written, the
    convergence figure with two panels for each of its four slowest modal points."""
    import matplotlib.pyplot as plt

    from restitution.laws.law_file import law_filename
    from restitution.reproduction.law_figures import draw_figures, shipped_law_files

    (path,) = [p for p in shipped_law_files() if p.name == law_filename(0.33)]
    written = draw_figures([path], tmp_path)
    assert [p.name for p in written] == ["slow_convergence_nu0.33.png", "slow_routes_nu0.33.png"]
    assert all(p.stat().st_size > 10_000 for p in written)
    plt.close("all")
    points = slow_convergence.compute(law(0.33), v_max=0.02, count=4)
    fig = slow_convergence.plot(points, 0.33)
    assert len(fig.axes) == 8 and all(p.v > 1e-3 for p in points)
