"""The oblique impact's friction routes, one module each, registered by importing it
(:mod:`restitution.dynamics.friction.base` says what a route is): one stick/slip state
(:mod:`~restitution.dynamics.friction.stick_slip`, the default), friction at every wall node
(:mod:`~restitution.dynamics.friction.microslip`) and one state on the dropped modes' static
residual (:mod:`~restitution.dynamics.friction.residual`)."""

from restitution.dynamics.friction import microslip, residual, stick_slip  # noqa: F401
from restitution.dynamics.friction.base import (
    ONE_WALL,
    FrictionRoute,
    default_friction_route,
    friction_names,
    friction_route,
    friction_routes,
    law_default,
    refuse_kappa,
    register_friction_route,
    routes_help,
    unregister_friction_route,
)

__all__ = [
    "ONE_WALL",
    "FrictionRoute",
    "default_friction_route",
    "friction_route",
    "friction_names",
    "friction_routes",
    "law_default",
    "refuse_kappa",
    "register_friction_route",
    "routes_help",
    "unregister_friction_route",
]
