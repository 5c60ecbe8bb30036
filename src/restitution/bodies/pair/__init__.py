"""Two free bodies of one kind meeting head-on (two disks of different radii and materials), as
one modal body for the contact: :class:`~restitution.bodies.pair.body.BodyPair`."""

from restitution.bodies.pair.body import BodyPair, pair_of

__all__ = ["BodyPair", "pair_of"]
