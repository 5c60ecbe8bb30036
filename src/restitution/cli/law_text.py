"""The text of ``restitution law``'s answer, for people: the grain, the law, a row per speed,
the constants per type pair, the files written, and (on stderr) what the rows' statuses mean.

The JSON and CSV reports are the answer's own ``to_dict``; this module is only the text reporter.
"""

from __future__ import annotations

import math

from restitution.laws.partners.base import partner_of
from restitution.status import Status


def _constant_text(c) -> str:
    return f"epsilon = {c.epsilon:.6f} +- {c.epsilon_err:.2g} ({c.how}; {c.status})"


_ROUTE_WORDS = {
    "modal": "collisions extrapolated in N",
    "residual": "collisions with a static residual",
    "quasistatic": "the low-speed theory",
}
"""The law's routes (:attr:`restitution.laws.law.EpsilonLaw.routes`) in words."""


def text_lines(a) -> list[str]:
    """The answer for people: the grain, the law, a row per speed, the constants, the files."""
    from restitution.laws.exports import SAME_SIZE_NOTE

    r, s, result = a.request, a.law, a.to_dict()
    g, other, pair = s.grain, r.partner_grain, s.law.partner
    lines = [g.describe()]
    if other is not None:
        lines.append(f"partner: {other.describe()}")
    body = g.body if pair is None else f"{g.body} pair (R2/R1 = {pair.radius_ratio:g})"
    routes = [_ROUTE_WORDS.get(r, r) for r in result["law"]["routes"]]
    made = f"; its points from {', '.join(routes)}" if routes else ""
    lines.append(
        f"against {r.against}: {result['against_meaning']}; {body} law "
        f"{g.law_nu_name} = {float(s.law.nu):g} ({result['law']['source']}{made})"
    )
    if pair is not None and pair.same_material and r.partner_radius_ratio < 1.0:
        lines.append(
            f"the radius ratio {r.partner_radius_ratio:g} is the pair R2/R1 = "
            f"{pair.radius_ratio:g} seen from the large grain: the same collision"
        )
    lines.append("mechanisms: " + "; ".join(result["mechanisms"]))
    if result["mechanisms_left_out"]:
        lines.append("not in these numbers: " + "; ".join(result["mechanisms_left_out"]))
    if result.get("plastic_flow_expected_from_m_s") is not None:
        from restitution.laws.mechanisms.bounds import elastic_bound

        bound, text = elastic_bound(s)
        lines.append(f"from {bound:.2g} m/s: {text}")
    if a.plastic is not None:
        lines += _plastic_rows(a)
    else:
        lines += _damped_rows(a) if a.damped is not None else _rows(a)
    pairs = a.pairs
    if pairs is not None and pairs.two_materials:
        lines.append(
            f"type 1 = this grain, type 2 = the partner (R2 = {pairs.radius_ratio:g} R1); "
            "constants per type pair:"
        )
        for name, c in (("1-2", pairs.mixed), ("1-1", pairs.same), ("2-2", pairs.same2)):
            lines.append(f"  {name:>8}: {_constant_text(c)}")
    elif pairs is not None:
        lines.append(
            f"type 1 = the small grain, type 2 = the large one (R2 = {pairs.radius_ratio:g} R1); "
            f"constants per type pair:"
        )
        for name, c in (("1-2", pairs.mixed), ("1-1, 2-2", pairs.same)):
            lines.append(f"  {name:>8}: {_constant_text(c)}")
        lines.append(f"  ({SAME_SIZE_NOTE})")
    elif a.constant is not None:
        lines.append(f"constant: {_constant_text(a.constant)}")
    if r.export_dir is not None:
        lines.append("wrote " + ", ".join(result["exports"]))
    return lines


def _places(err) -> int:
    """Decimals for two significant digits of the error (slow impacts: 1 - 1e-8)."""
    return 6 if not err else max(6, 1 - math.floor(math.log10(err)))


def _eps(p) -> tuple[str, str]:
    eps = "-" if p.epsilon is None else f"{p.epsilon:.{_places(p.epsilon_err)}f}"
    err = "-" if p.epsilon_err is None else f"{p.epsilon_err:.2g}"
    return eps, err


def _sd(p) -> str:
    """The row's standard deviation, ``*`` where it is the bound (a route not calibrated)."""
    sd = getattr(p, "sd", None)
    if sd is None:
        return "-"
    return f"{sd:.2g}" + ("" if getattr(p, "sd_calibrated", False) else "*")


SD_LINE = (
    "errors: 'error' is the bound (an upper estimate); 'sd' one standard deviation, the "
    "bound's parts scaled per route by factors fitted on independent points (67-78 % of the "
    "held-out ones within one sd, docs/errors.md); sd* is the bound (a route without enough "
    "independent points)"
)
"""What the ``error`` and ``sd`` columns of the elastic law's rows mean (the line above them)."""


def _rows(a) -> list[str]:
    """The elastic law's rows."""
    split = any(getattr(p, "loss_shares", None) for p in a.points)
    head = "  speed [m/s]        v/c       epsilon      error         sd   status"
    split_head = partner_of(a.law.law).split_head  # ball / wall, grain 1 / 2
    lines = [SD_LINE, head + (split_head if split else "")]
    for p in a.points:
        eps, err = _eps(p)
        line = (
            f"  {p.speed_m_s:11.4g}  {p.v_over_c:9.3g}  {eps:>12}  {err:>9}  {_sd(p):>9}   "
            f"{p.status}"
        )
        if split and p.loss_shares is not None:
            first, second = (f"{100 * x:.3g} %" for x in p.loss_shares)
            line = f"{line:<81}{first:>8} / {second}"
        lines.append(line.rstrip())
    return lines


def _damped_rows(a) -> list[str]:
    """Rows of a damping grain: both losses, and each alone."""
    d = a.damped
    line = f"damping: tau c/R = {d.tau:.6g} +- {d.tau_err:.2g}"
    if d.relaxation_time_s is not None:
        line += f" (tau = {d.relaxation_time_s:.4g} s for R = {d.radius_m:g} m)"
    if d.measured is not None:
        line += f", from epsilon = {d.measured[0]:g} measured at {d.measured[1]:g} m/s"
    lines = [
        line,
        "  speed [m/s]        v/c       epsilon      error    elastic    viscous   status",
    ]
    for p in a.points:
        eps, err = _eps(p)
        el = "-" if p.epsilon_elastic is None else f"{p.epsilon_elastic:.6f}"
        vi = "-" if p.epsilon_viscous is None else f"{p.epsilon_viscous:.6f}"
        lines.append(
            f"  {p.speed_m_s:11.4g}  {p.v_over_c:9.3g}  {eps:>12}  {err:>9}  {el:>9}  {vi:>9}   "
            f"{p.status}"
        )
    return lines


def _plastic_rows(a) -> list[str]:
    """Rows of a yielding grain: epsilon on one pulse, its parts and the old sum as a check."""
    law = a.plastic
    line = (
        f"plastic flow: limiting pressure p_y = {law.p_y:.4g} Pa ({law.source}); yield speed "
        f"{law.yield_speed_m_s():.3g} m/s"
    )
    if law.tau > 0:
        line += f"; damping tau c/R = {law.tau:.6g} +- {law.tau_err:.2g}"
    lines = [
        line,
        "  speed [m/s]        v/c       epsilon      error    elastic  sum-of-parts   "
        "plastic  viscous    waves   status",
    ]
    for p in a.points:
        eps, err = _eps(p)
        digits = _places(p.epsilon_elastic_err)
        el = "-" if p.epsilon_elastic is None else f"{p.epsilon_elastic:.{digits}f}"
        check = "-" if p.epsilon_sum_of_parts is None else f"{p.epsilon_sum_of_parts:.{digits}f}"
        parts = [("-" if x is None else f"{100 * x:.3g} %")
                 for x in (p.loss_plastic, p.loss_viscous, p.loss_waves)]  # fmt: skip
        lines.append(
            f"  {p.speed_m_s:11.4g}  {p.v_over_c:9.3g}  {eps:>12}  {err:>9}  {el:>9}  "
            f"{check:>12}  {parts[0]:>8} {parts[1]:>8} {parts[2]:>8}   {p.status}"
        )
    return lines


def status_notes(a) -> list[str]:
    """What the statuses of the rows mean (stderr, with the text)."""
    statuses = a.to_dict()["statuses"]
    s = a.damped.si if a.damped is not None else a.law
    at_points = getattr(s.law, "at_points_only", False)  # its outside notes are each point's
    outside = any(p.status == Status.OUTSIDE for p in a.points)
    lo, hi = s.computed_range_m_s if outside and not at_points else (None, None)
    notes, own = {}, []
    for p in a.points:
        note = getattr(p, "note", "") or ""
        if p.status == Status.OUTSIDE and lo is not None and lo <= p.speed_m_s <= hi and note:
            # no value inside the range (no rebound: the losses exceed the impact energy; a
            # contact refused): the point's own words, not the range's
            own.append(f"note: at {p.speed_m_s:.4g} m/s: no value: {note}")
        elif p.status not in (Status.COMPUTED, Status.INTERPOLATED):
            notes[p.status] = statuses.get(p.status) or note
    out = list(own)
    for status, text in notes.items():
        if status == Status.OUTSIDE and getattr(s.law, "at_points_only", False):
            text = next(p.note for p in a.points if p.status == Status.OUTSIDE)
        elif status == Status.OUTSIDE:
            lo, hi = s.computed_range_m_s
            text += f"; the law serves {lo:.4g} m/s <= w <= {hi:.4g} m/s"
        out.append(f"note: {status}: {text}")
    for p in a.points:
        if not getattr(p, "informative", True):
            out.append(f"note: at {p.speed_m_s:.4g} m/s: {_uninformative_part(p.note)}")
        elif p.status != Status.OUTSIDE and "from the finite elements" in (p.note or ""):
            out.append(f"note: at {p.speed_m_s:.4g} m/s: {p.note}")  # a stored FEM point
    return out


def _uninformative_part(note: str) -> str:
    """The damped model's 'not informative here: ...' or 'no value: ...' of a point's note."""
    for head in ("not informative here", "no value: the losses"):
        if head in note:
            return note[note.index(head) :]
    return note


def oblique_lines(a) -> list[str]:
    """The oblique answer (:class:`restitution.laws.oblique.ObliqueAnswer`) for people: the
    grain and the impact, a row per speed with each number's change from half the modes."""
    r = a.request
    lines = [
        r.grain.describe(),
        f"oblique impact on the rigid wall: {r.angle:g} degrees from the normal, friction mu = "
        f"{r.friction:g} ({r.oblique_route.describe(r.oblique_kappa)}); each speed is the "
        "normal one (tangential: w tan(angle)), no spin before; modal oblique route "
        "(docs/oblique.md), +- the change from half the modes (with the distance from the "
        "limits shown below each row, where shown)",
    ]
    spin_unit = "rad/s" if r.radius is not None else "m/s (omega R; --radius gives rad/s)"
    lines.append(
        f"{'w (m/s)':>9} {'v/c':>10} {'epsilon_normal':>22} {'beta':>20} "
        f"{'spin after':>22} {'friction work':>20}  status"
    )
    for p in a.points:
        spin, err = (
            (p.spin_rad_s, p.spin_rad_s_error) if r.radius else (p.spin_R_m_s, p.spin_R_m_s_error)
        )
        beta = "undefined" if p.beta is None else f"{p.beta:.5f} +- {p.beta_error:.1g}"
        lines.append(
            f"{p.speed_m_s:>9.4g} {p.v:>10.4g} "
            f"{f'{p.epsilon_normal:.6f} +- {p.epsilon_normal_error:.1g}':>22} {beta:>20} "
            f"{f'{spin:.5g} +- {err:.1g}':>22} "
            f"{f'{p.friction_work:.4f} +- {p.friction_work_error:.1g}':>20}  {p.status}"
        )
        if p.epsilon_head_on_law is not None:
            lines.append(
                f"{'':>9} head-on law at this speed (N, alpha -> infinity): epsilon = "
                f"{p.epsilon_head_on_law:.6f} +- {p.epsilon_head_on_law_error:.2g} "
                f"({p.head_on_law_status}): read epsilon_normal against it"
            )
        if p.beta_quasistatic is not None:
            lines.append(
                f"{'':>9} quasistatic Hertz-Mindlin at this impact (on a half-space): beta = "
                f"{p.beta_quasistatic:.5f} with one stick/slip state (law (a), the DEM codes'), "
                f"{p.beta_microslip:.5f} with microslip (law (b))"
            )
            lines.append(_route_limit_line(p, r.oblique_route.every_node))
    if a.points:
        walls = ", ".join(f"{p.alpha:.4g}" for p in a.points)
        extra = r.oblique_route.law_walls[1:]
        if extra:
            walls += (f" and {' and '.join(f'{f:g} alpha' for f in extra)} each, extrapolated "
                      "to the rigid wall")  # fmt: skip
        lines.append(
            f"spin in {spin_unit}, positive in the rolling sense; friction work as a fraction "
            f"of the kinetic energy before; {a.points[0].modes} modes; walls alpha = {walls} "
            "(1/R); total time "
            f"{sum(p.wall_time_s for p in a.points):.1f} s"
        )
    return lines


def _route_limit_line(p, microslip: bool) -> str:
    """The oblique route's own low-speed limit under a point (the one in ``beta``'s error)."""
    friction = "microslip" if microslip else "one stick/slip state spread like the pressure"
    finite = p.beta_microslip_finite if microslip else p.beta_one_state_finite
    half_space = p.beta_microslip if microslip else p.beta_one_state
    if finite is None:
        return (
            f"{'':>9} this route's low-speed limit (in beta's error): beta = {half_space:.5f}, "
            f"{friction} on a half-space"
        )
    coupling = "" if microslip else " with Dundurs' coupling"
    return (
        f"{'':>9} this route's low-speed limit (in beta's error): beta = {finite:.5f}, "
        f"{friction} on the finite sphere's own flexibility{coupling} ({half_space:.5f} on a "
        "half-space)"
    )
