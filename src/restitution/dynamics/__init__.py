"""Layer 2, contact and dynamics: one body hits a wall through the exponential potential.

Knows a body only through :class:`restitution.bodies.base.ModalBody`.
"""
