"""What a grain hits, as types: the partner kinds (:mod:`restitution.laws.partners.base` says
what one declares): the rigid wall (:mod:`~restitution.laws.partners.rigid_wall`), a second
grain (:mod:`~restitution.laws.partners.grain`), an elastic half-space
(:mod:`~restitution.laws.partners.half_space`) and an elastic plate
(:mod:`~restitution.laws.partners.plate`). Importing this package registers them."""

from restitution.laws.partners import grain, half_space, plate, rigid_wall  # noqa: F401
