"""Turning results into JSON-safe values: the one home of the package's JSON conversions.

JSON has no NaN or infinity and knows no NumPy types. :func:`finite_or_none` maps one number to
a float or ``None``, :func:`finite_tree` does it for every float of a parsed JSON tree, and
:func:`json_default` is the ``default=`` of :func:`json.dumps` for NumPy scalars and arrays.

Content digests: a file the package writes and later serves again (a computed law, a kept
point, a finite-element point) carries ``"digest": "sha256:<hex>"`` (:data:`DIGEST_KEY`,
:func:`signed`), the SHA-256 of the canonical JSON (:func:`canonical_json`) of the rest of the
document, so that a change made after writing (one digit of an epsilon) is seen on reading
(:func:`digest_matches`) instead of served.
"""

from __future__ import annotations

import hashlib
import json
import math
from typing import Any

import numpy as np

__all__ = [
    "DIGEST_KEY",
    "canonical_json",
    "content_digest",
    "digest_matches",
    "finite_or_none",
    "finite_tree",
    "json_default",
    "signed",
]

DIGEST_KEY = "digest"
"""The top-level key of a document's content digest (:func:`signed`)."""


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


# -- content digests -----------------------------------------------------------------------


def canonical_json(doc: Any) -> str:
    """The canonical text of a parsed JSON value, the one a content digest is taken of:
    ``json.dumps(doc, sort_keys=True, separators=(",", ":"), ensure_ascii=True,
    allow_nan=True)`` (keys sorted, no spaces, non-ASCII escaped, floats as Python's shortest
    round-tripping ``repr``, non-finite ones as ``NaN``/``Infinity`` as :mod:`json` writes them).

    >>> canonical_json({"b": [1, 0.5], "a": "x"})
    '{"a":"x","b":[1,0.5]}'
    """
    return json.dumps(doc, sort_keys=True, separators=(",", ":"), ensure_ascii=True, allow_nan=True)


def content_digest(doc: dict) -> str:
    """``"sha256:<hex>"`` of :func:`canonical_json` of ``doc`` without its :data:`DIGEST_KEY`
    (of the value as a reader parses it: :func:`signed` takes it of the written text's)."""
    rest = {k: v for k, v in doc.items() if k != DIGEST_KEY}
    return "sha256:" + hashlib.sha256(canonical_json(rest).encode("ascii")).hexdigest()


def signed(doc: dict, *, default=json_default) -> dict:
    """``doc`` as a reader will parse it (NumPy values and tuples turned into JSON's by
    ``default``), with its content digest under :data:`DIGEST_KEY` (a stale one is replaced):
    what a writer dumps.

    >>> signed({"epsilon": 0.9932})["digest"][:7]
    'sha256:'
    >>> digest_matches(signed({"epsilon": 0.9932}) | {"epsilon": 0.5932})
    False
    """
    parsed = json.loads(json.dumps(doc, allow_nan=True, default=default))
    parsed.pop(DIGEST_KEY, None)
    parsed[DIGEST_KEY] = content_digest(parsed)
    return parsed


def digest_matches(doc: dict) -> bool | None:
    """Whether the parsed document ``doc`` is what was written with its digest (:func:`signed`):
    ``None`` when it carries none (older files, the shipped data), ``False`` when its digest is
    not the one of its content (it was changed after it was written) or not a string."""
    if not isinstance(doc, dict) or DIGEST_KEY not in doc:
        return None
    stored = doc[DIGEST_KEY]
    return isinstance(stored, str) and stored == content_digest(doc)
