"""Two free bodies of one kind meeting head-on (two disks of different radii and materials), as
one modal body for the contact: :class:`~restitution.bodies.pair.body.BodyPair`; the second body
by its constants before any mode exists: :class:`~restitution.bodies.pair.partner.Partner`."""

from restitution.bodies.pair.body import BodyPair, pair_of
from restitution.bodies.pair.partner import Partner

__all__ = ["BodyPair", "Partner", "pair_of"]
