"""Shared figure furniture: notes printed under the axes (e.g. "quick run")."""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["QUICK_NOTE", "add_notes"]

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
