"""Synthetic epsilon(v) laws for the tests of the SI edge and its exports (not physics: smooth,
monotone curves whose values the tests know exactly)."""

from __future__ import annotations


def eps_pair(v):
    """The law of two different grains (type pair 1-2)."""
    return 1.0 - 0.6 * v**0.9 / (1.0 + 1.3 * v**0.9)


def eps_same(v):
    """The law of two identical grains of the first material (type pair 1-1)."""
    return 1.0 - 0.4 * v**0.8 / (1.0 + 1.1 * v**0.8)


def eps_glass(v):
    """The law of two identical grains of a second material (type pair 2-2)."""
    return 1.0 - 0.3 * v**0.85 / (1.0 + 0.9 * v**0.85)
