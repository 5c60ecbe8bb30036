"""Layer 3, vibrating bodies: collisions that start from a ringing body, ensembles, chains."""
