"""Making laws: the shipped laws' production, laws computed on demand, their refinement, judges
and offline checks.

The serving side of :mod:`restitution.laws` (the law model, SI units, requests, serving, the
writers) never imports this package (``tests/test_architecture.py``); what it needs from here,
the routes that compute a law while a request waits (``--compute``, ``--route residual``), it
finds in :mod:`restitution.laws.routes`, where :mod:`restitution.laws.making.routes` registers
them. Importing this package registers them.
"""

from restitution.laws.making import routes  # noqa: F401  (registers the computing routes)
