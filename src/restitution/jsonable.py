"""Turning results into JSON-safe values: the one home of the package's JSON conversions.

JSON has no NaN or infinity and knows no NumPy types. :func:`finite_or_none` maps one number to
a float or ``None``, :func:`finite_tree` does it for every float of a parsed JSON tree, and
:func:`json_default` is the ``default=`` of :func:`json.dumps` for NumPy scalars and arrays.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["finite_or_none", "finite_tree", "json_default"]


def finite_or_none(x: Any) -> float | None:
    """``float(x)`` when finite, else ``None`` (also for ``x is None``).

    Examples
    --------
    >>> finite_or_none(1), finite_or_none(float("nan")), finite_or_none(None)
    (1.0, None, None)
    """
    if x is None:
        return None
    x = float(x)
    return x if math.isfinite(x) else None


def finite_tree(obj: Any) -> Any:
    """``obj`` with every non-finite float replaced by ``None``, through dicts, lists and tuples
    (tuples become lists); other values are kept as they are."""
    if isinstance(obj, float):
        return finite_or_none(obj)
    if isinstance(obj, dict):
        return {k: finite_tree(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [finite_tree(v) for v in obj]
    return obj


def json_default(obj: Any) -> Any:
    """``json.dumps`` default for numpy scalars and arrays."""
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.floating):
        return float(obj)
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    raise TypeError(f"{type(obj).__name__} is not JSON serialisable")
