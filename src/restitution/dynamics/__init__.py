"""Layer 2, contact and dynamics: one body hits a wall through a contact law (the paper's
exponential potential by default, :mod:`restitution.dynamics.contact`).

Knows a body only through :class:`restitution.bodies.base.ModalBody`.
"""
