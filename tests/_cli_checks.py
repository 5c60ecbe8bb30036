"""Checks shared by the tests of the command line's refusals."""

from __future__ import annotations


def one_line_error(code, err, *words):
    """Assert a one-line refusal: exit status 2, ``error: ...`` alone on stderr, no traceback,
    every one of ``words`` in it; returns the line."""
    lines = [x for x in err.splitlines() if x.strip()]
    assert code == 2, err
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert "Traceback" not in err
    for w in words:
        assert w in lines[0], (w, lines[0])
    return lines[0]
