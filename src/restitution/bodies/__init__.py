"""Layer 1, the free elastic body: material constants, eigenmodes and the body protocol.

A body knows nothing of collisions. :mod:`restitution.bodies.base` states what the layers above
need from a body (:class:`~restitution.bodies.base.ModalBody`); :mod:`restitution.bodies.disk`
implements it for the elastic disk of the paper.
"""
