"""Contact laws: what pushes a body off the wall, as one object the dynamics consumes.

:mod:`~restitution.dynamics.contact.base` is the protocol (:class:`ContactLaw`) and the
registry of laws by name; :mod:`~restitution.dynamics.contact.surface` sums a local law over a
body's surface quadrature; :mod:`~restitution.dynamics.contact.exponential` is the paper's wall,
the default everywhere. A new law is one module here (or anywhere: it registers itself) and,
for the compiled path, one branch of :mod:`restitution.dynamics.kernel` (docs/architecture.md).
"""

from restitution.dynamics.contact.base import CONTACT_LAWS, CONTACT_TOL, ContactLaw, law_from_key
from restitution.dynamics.contact.exponential import EXPONENTIAL_WALL, ExponentialWall

__all__ = [
    "CONTACT_LAWS",
    "CONTACT_TOL",
    "EXPONENTIAL_WALL",
    "ContactLaw",
    "ExponentialWall",
    "law_from_key",
]
