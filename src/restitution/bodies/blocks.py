"""Matrices on the first ``count`` surface nodes, kept for their leading blocks.

Units: none (whatever the matrices hold).

A body's static kernel between the hats of its first ``count`` nodes (the residual's
``residual_flexibility``) does not depend on ``count``: the kernel of fewer nodes is the leading
block of the kernel of more. A law point asks for it at several kept-mode counts and walls, with
node counts that differ by the walls' reach; :class:`LeadingBlocks` builds it once per body and
quadrature, at the largest count asked so far, and serves the smaller ones as slices (issue 46:
the disk's kernel took 3 s of a 4.7 s collision at ``v = 0.001``).
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any

__all__ = ["LeadingBlocks"]


class LeadingBlocks:
    """``blocks(key, count)``: ``build(key, count)`` cut to ``count`` nodes, built anew only
    when ``count`` exceeds what is kept for ``key`` (the ``size`` most recent keys are kept).

    ``cut(value, count)`` slices a built value to its first ``count`` nodes; ``nodes(value)``
    says how many it holds.
    """

    def __init__(
        self,
        build: Callable[[Hashable, int], Any],
        cut: Callable[[Any, int], Any],
        nodes: Callable[[Any], int],
        size: int = 4,
    ) -> None:
        self._build, self._cut, self._nodes, self._size = build, cut, nodes, size
        self._kept: OrderedDict[Hashable, Any] = OrderedDict()

    def __call__(self, key: Hashable, count: int):
        value = self._kept.get(key)
        if value is None or self._nodes(value) < count:
            value = self._build(key, count)
        self._kept[key] = value
        self._kept.move_to_end(key)
        while len(self._kept) > self._size:
            self._kept.popitem(last=False)
        return self._cut(value, count)

    def cache_clear(self) -> None:
        """Forget every kept value."""
        self._kept.clear()
