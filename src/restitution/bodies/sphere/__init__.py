"""The free homogeneous isotropic elastic sphere: Lamb's axisymmetric spheroidal modes, their
surface quadrature against a flat wall and the Hertz contact time (docs/architecture.md,
"Adding a body", item 1)."""
