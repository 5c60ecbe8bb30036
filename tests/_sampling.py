"""Parameters of which only a representative runs by default; the rest run with ``-m slow``."""

from __future__ import annotations

import pytest


def representatives(values, keep):
    """``values`` as parameters, each not in ``keep`` marked ``slow`` (``make test-slow``)."""
    return [v if v in keep else pytest.param(v, marks=pytest.mark.slow) for v in values]
