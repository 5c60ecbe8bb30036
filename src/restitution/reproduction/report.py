"""A small document model written as Markdown and as self-contained HTML.

A report is a sequence of blocks (:class:`Heading`, :class:`Paragraph`, :class:`Table`,
:class:`Figure`, :class:`Code`). :func:`to_markdown` and :func:`to_html` render the same blocks,
so the two files always say the same thing. Text inside blocks uses a tiny Markdown subset that
both renderers understand: ```code```, ``**bold**`` and ``[text](relative/link)``.

In Markdown, figures are referenced by relative paths (``![..](fig01_epsilon.png)``); the HTML
page carries them inline (``data:image/png;base64``) when :func:`to_html` is given the folder
they live in, so ``report.html`` is one self-contained file. The HTML page carries a few lines of
script that mark every image as loaded or not (``data-loaded`` on each ``<img>``,
``data-images = "loaded/total"`` on ``<body>``) and count load and script errors
(``data-errors`` on ``<body>``), which a headless browser can read back.
"""

from __future__ import annotations

import base64
import html
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "Code",
    "Figure",
    "Heading",
    "Paragraph",
    "Table",
    "parse_markdown_table",
    "slug",
    "to_html",
    "to_markdown",
]


@dataclass(frozen=True)
class Heading:
    """A section heading of ``level`` 1-4."""

    level: int
    text: str


@dataclass(frozen=True)
class Paragraph:
    """A paragraph of inline text (Markdown subset, see the module docstring)."""

    text: str


@dataclass(frozen=True)
class Table:
    """A table: ``header`` cells and ``rows`` of cells (inline text)."""

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]

    def __post_init__(self) -> None:
        width = len(self.header)
        if any(len(r) != width for r in self.rows):
            raise ValueError(f"every row of a table needs {width} cells")


@dataclass(frozen=True)
class Figure:
    """An image with a caption and further links (e.g. the vector version).

    Attributes
    ----------
    src : str
        Relative path of a PNG (or any format a browser shows).
    alt : str
        Short alternative text.
    caption : str
        Inline text under the image.
    links : tuple of (str, str)
        ``(label, relative path)`` pairs shown after the caption.
    """

    src: str
    alt: str
    caption: str = ""
    links: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class Code:
    """Preformatted text."""

    text: str


Block = Heading | Paragraph | Table | Figure | Code

# -- inline text ---------------------------------------------------------------------------

_INLINE = re.compile(r"`([^`]+)`|\*\*(.+?)\*\*|\[([^\]]+)\]\(([^)\s]+)\)")


def _inline_html(text: str) -> str:
    out, pos = [], 0
    for m in _INLINE.finditer(text):
        out.append(html.escape(text[pos : m.start()]))
        code, bold, label, href = m.groups()
        if code is not None:
            out.append(f"<code>{html.escape(code)}</code>")
        elif bold is not None:
            out.append(f"<strong>{_inline_html(bold)}</strong>")
        else:
            out.append(f'<a href="{html.escape(href, quote=True)}">{_inline_html(label)}</a>')
        pos = m.end()
    out.append(html.escape(text[pos:]))
    return "".join(out)


def slug(text: str) -> str:
    """Anchor of a heading as GitHub makes it: ``"Table 1"`` -> ``"table-1"``."""
    kept = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return kept.replace(" ", "-")


def _cell_markdown(text: str) -> str:
    # A pipe ends a cell even inside a code span in GitHub's tables; escape every one.
    return text.replace("|", "\\|").replace("\n", " ")


# -- renderers -----------------------------------------------------------------------------


def to_markdown(blocks: Iterable[Block]) -> str:
    """The blocks as a Markdown document."""
    parts = []
    for b in blocks:
        if isinstance(b, Heading):
            parts.append(f"{'#' * b.level} {b.text}")
        elif isinstance(b, Paragraph):
            parts.append(b.text)
        elif isinstance(b, Table):
            lines = [
                "| " + " | ".join(_cell_markdown(c) for c in b.header) + " |",
                "|" + "|".join("---" for _ in b.header) + "|",
            ]
            lines += ["| " + " | ".join(_cell_markdown(c) for c in r) + " |" for r in b.rows]
            parts.append("\n".join(lines))
        elif isinstance(b, Figure):
            text = f"![{b.alt}]({b.src})"
            tail = " ".join(f"[{label}]({href})" for label, href in b.links)
            caption = " ".join(x for x in (b.caption, tail) if x)
            parts.append(text + ("\n\n" + caption if caption else ""))
        elif isinstance(b, Code):
            parts.append("```\n" + b.text.rstrip("\n") + "\n```")
        else:  # pragma: no cover - a programming error
            raise TypeError(f"not a report block: {b!r}")
    return "\n\n".join(parts) + "\n"


_STYLE = """
body { font-family: system-ui, sans-serif; max-width: 70rem; margin: 2rem auto; padding: 0 1rem;
       line-height: 1.45; color: #222; }
table { border-collapse: collapse; margin: 1rem 0; font-size: 0.9rem; }
th, td { border: 1px solid #bbb; padding: 0.25rem 0.5rem; vertical-align: top; text-align: left; }
th { background: #eee; }
td.agrees { background: #e6f4e6; }
td.differs { background: #fbe9e7; }
td.inconclusive { background: #fff6d5; }
p.quick { background: #b00000; color: white; padding: 0.5rem; font-weight: bold; }
p.quick code { background: white; color: #b00000; }
figure { margin: 1.5rem 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9rem; color: #444; }
code { background: #f4f4f4; padding: 0 0.2rem; }
pre { background: #f4f4f4; padding: 0.5rem; overflow-x: auto; }
"""

# Marks every image as loaded or not once the page has loaded, and counts script errors
# (read back by tests through a headless browser's DOM dump).
_SCRIPT = """
var reportErrors = 0;
window.addEventListener("error", function () { reportErrors++; }, true);
window.addEventListener("load", function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; i++) {
    var good = imgs[i].complete && imgs[i].naturalWidth > 0;
    imgs[i].setAttribute("data-loaded", good ? "yes" : "no");
    if (good) { ok++; }
  }
  document.body.setAttribute("data-images", ok + "/" + imgs.length);
  document.body.setAttribute("data-errors", String(reportErrors));
});
"""


def _verdict_class(text: str) -> str:
    low = text.lower()
    if low.startswith("agrees"):
        return ' class="agrees"'
    if low.startswith("differs"):
        return ' class="differs"'
    if low.startswith("inconclusive"):
        return ' class="inconclusive"'
    return ""


def _image_src(src: str, base: Path | None) -> str:
    """``src`` as a ``data:`` URI when ``base`` holds the file, else unchanged."""
    if base is None or "://" in src or src.startswith("data:"):
        return src
    path = Path(base) / src
    mime = {".png": "image/png", ".svg": "image/svg+xml", ".jpg": "image/jpeg"}.get(
        path.suffix.lower()
    )
    if mime is None or not path.is_file():
        return src
    return f"data:{mime};base64," + base64.b64encode(path.read_bytes()).decode("ascii")


def to_html(blocks: Iterable[Block], title: str, base: str | os.PathLike | None = None) -> str:
    """The blocks as one HTML page (inline style and script).

    With ``base`` (the folder the figures are in) every figure is embedded as a ``data:`` URI,
    so the page needs no other file to show its figures; links stay links.
    """
    base = None if base is None else Path(base)
    body = []
    for b in blocks:
        if isinstance(b, Heading):
            level = min(max(b.level, 1), 6)
            body.append(f'<h{level} id="{slug(b.text)}">{_inline_html(b.text)}</h{level}>')
        elif isinstance(b, Paragraph):
            cls = ' class="quick"' if b.text.startswith("**QUICK RUN") else ""
            body.append(f"<p{cls}>{_inline_html(b.text)}</p>")
        elif isinstance(b, Table):
            head = "".join(f"<th>{_inline_html(c)}</th>" for c in b.header)
            rows = []
            for r in b.rows:
                cells = "".join(f"<td{_verdict_class(c)}>{_inline_html(c)}</td>" for c in r)
                rows.append(f"<tr>{cells}</tr>")
            body.append(
                f"<table>\n<thead><tr>{head}</tr></thead>\n<tbody>\n"
                + "\n".join(rows)
                + "\n</tbody>\n</table>"
            )
        elif isinstance(b, Figure):
            links = " ".join(
                f'[<a href="{html.escape(href, quote=True)}">{html.escape(label)}</a>]'
                for label, href in b.links
            )
            caption = " ".join(x for x in (_inline_html(b.caption), links) if x)
            body.append(
                f'<figure>\n<img src="{html.escape(_image_src(b.src, base), quote=True)}" '
                f'alt="{html.escape(b.alt, quote=True)}">\n'
                f"<figcaption>{caption}</figcaption>\n</figure>"
            )
        elif isinstance(b, Code):
            body.append(f"<pre>{html.escape(b.text)}</pre>")
        else:  # pragma: no cover - a programming error
            raise TypeError(f"not a report block: {b!r}")
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        f"<title>{html.escape(title)}</title>\n<style>{_STYLE}</style>\n"
        f"<script>{_SCRIPT}</script>\n</head>\n<body>\n" + "\n".join(body) + "\n</body>\n</html>\n"
    )


# -- reading tables back -------------------------------------------------------------------


def _split_row(line: str) -> list[str]:
    """Cells of one Markdown table row; pipes inside code spans or escaped do not split."""
    line = line.strip()
    if line.startswith("|"):
        line = line[1:]
    if line.endswith("|") and not line.endswith("\\|"):
        line = line[:-1]
    cells, current, in_code, i = [], [], False, 0
    while i < len(line):
        ch = line[i]
        if ch == "\\" and i + 1 < len(line) and line[i + 1] == "|":
            current.append("|")
            i += 2
            continue
        if ch == "`":
            in_code = not in_code
        if ch == "|" and not in_code:
            cells.append("".join(current).strip())
            current = []
        else:
            current.append(ch)
        i += 1
    cells.append("".join(current).strip())
    return cells


def parse_markdown_table(lines: Sequence[str]) -> Table:
    """The first Markdown table in ``lines`` (header, separator, rows) as a :class:`Table`.

    Raises
    ------
    ValueError
        If ``lines`` holds no table.
    """
    rows: list[list[str]] = []
    started = False
    for line in lines:
        if line.lstrip().startswith("|"):
            started = True
            rows.append(_split_row(line))
        elif started:
            break
    if len(rows) < 2 or not all(set(c) <= set("-: ") for c in rows[1]):
        raise ValueError("no Markdown table found")
    header = tuple(rows[0])
    body = tuple(tuple((r + [""] * len(header))[: len(header)]) for r in rows[2:])
    return Table(header, body)
