"""Shared figure furniture: notes printed under the axes (e.g. "quick run"), and the command line
every figure module's ``main`` offers (``--figures DIR``)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

__all__ = ["QUICK_NOTE", "add_notes", "figure_main", "limits_and_legends"]

QUICK_NOTE = "QUICK RUN: coarse grids, numbers not converged"
"""The note every figure of a quick paper run carries."""


def add_notes(fig, notes: Sequence[str], fontsize: float = 7.5) -> None:
    """Lay out ``fig`` tightly, leaving room for ``notes`` (one line each) at the bottom.

    A note that starts with ``"QUICK RUN"`` is drawn in bold red.
    """
    notes = [n for n in notes if n]
    line = fontsize * 1.5 / 72.0 / fig.get_figheight()  # one text line, figure fraction
    bottom = line * (len(notes) + 0.4) if notes else 0.0
    fig.tight_layout(rect=(0.0, bottom, 1.0, 1.0))
    for i, text in enumerate(reversed(notes)):
        quick = text.startswith("QUICK RUN")
        fig.text(
            0.01, line * (i + 0.3), text, fontsize=fontsize, ha="left", va="bottom",
            color="#b00000" if quick else "0.25", weight="bold" if quick else "normal",
        )  # fmt: skip


def limits_and_legends(ax, limit_inf, solid: str, dashed: str, n_speeds: int) -> None:
    """The shared furniture of Figs. 7 and 8: the extrapolated limits at ``x = 0`` (a negative
    one, an unphysical energy loss, as a red cross), a legend of the line styles below the axes
    and the legend of the speeds to the right, so that neither covers data."""
    import numpy as np
    from matplotlib.lines import Line2D

    negative = limit_inf < 0
    ax.plot(np.zeros(np.count_nonzero(~negative)), limit_inf[~negative], "kD", ms=4,
            clip_on=False, zorder=5)  # fmt: skip
    if np.any(negative):
        ax.plot(np.zeros(np.count_nonzero(negative)), limit_inf[negative], "rx", ms=8, mew=2,
                clip_on=False, zorder=5)  # fmt: skip
        ax.axhline(0.0, color="r", lw=0.5, ls=":")
    kinds = [
        Line2D([], [], color="k", marker="o", ms=4, lw=0.8, ls="-", label=solid),
        Line2D([], [], color="k", marker="o", mfc="none", ms=4, lw=0.6, ls="--", label=dashed),
        Line2D([], [], color="k", marker="D", ms=4, ls="none", label="both limits (at 0)"),
    ]
    if np.any(negative):
        kinds.append(Line2D([], [], color="r", marker="x", mew=2, ls="none",
                            label="1 - eps^2 < 0: unphysical"))  # fmt: skip
    first = ax.legend(handles=kinds, fontsize=8, loc="upper left", bbox_to_anchor=(0.0, -0.13),
                      ncol=2, frameon=False)  # fmt: skip
    ax.add_artist(first)
    ax.legend(title=r"$v_i/c$", fontsize=8, title_fontsize=8, loc="upper left",
              bbox_to_anchor=(1.01, 1.0), ncol=1 if n_speeds <= 9 else 2)  # fmt: skip


def figure_main(
    argv,
    description: str,
    file_name: Callable | str,
    draw: Callable,
    *,
    nu: tuple[float | list[float], str] | None = None,
) -> None:
    """The ``main`` of a figure module: ``--figures DIR`` (created if missing), an optional
    ``--nu`` (``nu = (default, help)``; a list default takes several values), then
    ``draw(args, path)`` with ``path = DIR / file_name`` (``file_name(args)`` when callable),
    and ``wrote PATH`` on stdout."""
    import argparse
    from pathlib import Path

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--figures", required=True, help="directory for the PNG")
    if nu is not None:
        default, help_text = nu
        many = {"nargs": "+"} if isinstance(default, list) else {}
        parser.add_argument("--nu", type=float, default=default, help=help_text, **many)
    args = parser.parse_args(argv)
    out = Path(args.figures)
    out.mkdir(parents=True, exist_ok=True)
    path = out / (file_name(args) if callable(file_name) else file_name)
    draw(args, path)
    print(f"wrote {path}")
