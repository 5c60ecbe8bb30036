"""Layer 4, limits and sweeps: the extrapolations alpha, N -> infinity, the sweeps and their store.

Knows collisions only through their results.
"""
