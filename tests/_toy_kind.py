"""A toy body kind, defined outside the package: the disk's physics under another name.

Importing this module registers the kind ``"toy"`` (:func:`restitution.bodies.kinds.register`);
``tests/test_extension_points.py`` names the module in ``RESTITUTION_KINDS`` so that the spawned
workers of a sweep register it too. Its modes are the disk's modes in a class of its own, so
every number it gives must be the disk's: what the test checks is that nothing outside this
module needed to know the new name.
"""

from __future__ import annotations

from dataclasses import replace
from typing import ClassVar

from restitution.bodies.disk.modes import ModeSet, compute_modes
from restitution.bodies.kinds import body_kind, kinds, register

NAME = "toy"


class ToyModes(ModeSet):
    """The disk's modes as a body of the kind ``"toy"``."""

    geometry: ClassVar[str] = NAME

    def take(self, index) -> ToyModes:
        return ToyModes(**vars(ModeSet.take(self, index)))


def _compute(nu, count=None, omega_max=None) -> ToyModes:
    return ToyModes(**vars(compute_modes(nu, count, omega_max)))


KIND = kinds().get(NAME) or register(
    replace(
        body_kind("disk"),
        geometry=NAME,
        description="the disk's modes under another name (a test of the extension points)",
        mode_class=ToyModes,
        compute=_compute,
        file_tag=NAME,
        shapes={},
        shape_words={},
        production=None,
        pair_production=None,
        low_speed_route=None,
        pair_low_speed_route=None,
        default_nus=(),
        vibrating=False,
    )
)
