"""The loss mechanisms, one module each, registered by importing it
(:mod:`restitution.laws.mechanisms.base` says what a mechanism is): the elastic waves and an
elastic wall's radiation (:mod:`~restitution.laws.mechanisms.waves`), the material's viscosity
(:mod:`~restitution.laws.mechanisms.viscous`), plastic flow
(:mod:`~restitution.laws.mechanisms.plastic_flow`) and adhesion
(:mod:`~restitution.laws.mechanisms.adhesion`). :mod:`~restitution.laws.mechanisms.bounds` holds
what they share: the contact's scales, the mechanisms of a law's table, and from which speed an
elastic answer is a bound."""

from restitution.laws.mechanisms import adhesion, plastic_flow, viscous, waves  # noqa: F401
