"""The routes that find the elastic law of a request, one module each, registered by importing
it and asked in the order of their ``order`` (:mod:`restitution.laws.routes.base`): an elastic
wall, a given law file, a law computed on demand, a pair's low-speed route, the shipped laws."""

from restitution.laws.routes import given, pair, shipped, wall  # noqa: F401  (they register)
