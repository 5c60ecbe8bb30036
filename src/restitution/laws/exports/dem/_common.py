"""What every DEM snippet says in its comments, and the constants it serves per type pair.

The snippets' comment block (the export heading, the constant or the constants per type pair
with their statuses, and what the code's particles stand for), and ``(i, j) -> Constant`` per
pair of particle types. SI units, epsilon dimensionless.
"""

from __future__ import annotations

from types import SimpleNamespace

from restitution.errors import InputError
from restitution.laws.exports._heading import _header, _law_line
from restitution.laws.exports.constants import Constant
from restitution.laws.exports.type_pairs import SAME_SIZE_NOTE, TWO_MATERIALS_NOTE, TypePairs
from restitution.laws.mechanisms.bounds import wall_of
from restitution.laws.si_law import SILaw


def _constants(s: SILaw, c: Constant | TypePairs) -> dict[tuple[int, int], Constant]:
    """``(i, j) -> Constant`` per pair of particle types: ``{(1, 1): c}`` for one constant."""
    if isinstance(c, TypePairs):
        if c.pair is not s:
            raise InputError(
                "constants per type pair go with their pair's law: pass TypePairs.pair as the law"
            )
        return c.constants
    return {(1, 1): c}


def _constant_line(c: Constant) -> str:
    return f"epsilon = {c.epsilon:.6f} +- {c.epsilon_err:.2g}, {c.how}"


def _comment(s: SILaw, c: Constant | TypePairs, mark: str) -> str:
    lines = _header(s)
    if isinstance(c, TypePairs) and c.two_materials:
        words = c.type_words()
        lines += [
            f"type 1 = {words['1']}",
            f"type 2 = {words['2']}",
            f"1-2: {_constant_line(c.mixed)}; status: {c.mixed.status}",
            f"1-1: {_constant_line(c.same)}; status: {c.same.status}",
            f"2-2: {_constant_line(c.same2)}; status: {c.same2.status}",
            f"1-1 {_law_line(c.identical)}",
            f"2-2 {_law_line(c.identical2)}",
            TWO_MATERIALS_NOTE,
        ]
    elif isinstance(c, TypePairs):
        lines += [
            f"types: 1 = the small grain (radius R1), 2 = the large one (R2 = "
            f"{c.radius_ratio:g} R1), one material",
            f"1-2 (small with large): {_constant_line(c.mixed)}; status: {c.mixed.status}",
            f"1-1 and 2-2 (two grains of one size): {_constant_line(c.same)}; status: "
            f"{c.same.status}",
            f"1-1 and 2-2 {_law_line(c.identical)}",
            SAME_SIZE_NOTE,
        ]
    else:
        lines += [f"constant: {_constant_line(c)}", f"status: {c.status}"]
    lines.append(
        "only epsilon comes from restitution; stiffness and contact time come from the code's "
        "own contact model"
    )
    return "\n".join(f"{mark} {line}" for line in lines)


def friction_line(friction: float | None, where: str) -> str:
    """What the snippet sets for friction, and where the user's goes (``where``: the code's
    parameter): restitution computes the normal coefficient only."""
    if friction is None:
        return (
            f"friction: mu = 0 here, because none was given (--friction MU sets yours; or edit "
            f"{where}); restitution computes only the normal coefficient"
        )
    return f"friction: mu = {friction:g} as given (--friction), in {where}"


RIGID = 1e6
"""A rigid wall in a code that mixes the two sides' materials (LIGGGHTS's Hertz, YADE's
Hertz-Mindlin): the wall's own material with this many times the grains' modulus. The mixed
``1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w`` and ``1/G* = (2 - nu)/G + (2 - nu_w)/G_w`` are then
the rigid wall's ``E / (1 - nu^2)`` and ``G / (2 - nu)`` within about ``1e-6``."""


def wall_material(s: SILaw) -> SimpleNamespace:
    """The wall's own material where a code mixes the two sides' (LIGGGHTS, YADE): ``E``,
    ``nu``, ``rho`` and ``rigid``; an elastic wall's from its law, the rigid wall's
    :data:`RIGID` times the grains' modulus with their ``nu`` and ``rho``."""
    elastic = wall_of(s.law)
    if elastic is None:
        return SimpleNamespace(E=RIGID * s.grain.E, nu=s.grain.nu, rho=s.grain.rho, rigid=True)
    return SimpleNamespace(
        E=float(elastic["modulus_ratio"]) * s.grain.E,
        nu=float(elastic["nu"]),
        rho=float(elastic["density_ratio"]) * s.grain.rho,
        rigid=False,
    )


WALL_NOTE = (
    "this is a grain-on-wall law: where the code takes it per particle type or material it "
    "also acts on grain-grain contacts of those particles, which need the law of two grains "
    "(--against grain) instead; give them their own type pair"
)
"""The warning every wall snippet of a per-type code carries (issue 44)."""


def viscoelastic_head(s: SILaw, model, friction: float | None, where: str, mark: str) -> list:
    """The comment lines of a viscoelastic snippet: the export heading, the model and its
    constants with the part it drops (:meth:`~restitution.laws.exports.viscoelastic.
    Viscoelastic.describe`), what the particles stand for and the friction (``where``: the
    code's parameter)."""
    lines = [*_header(s), *model.describe(), _particles(s), friction_line(friction, where)]
    return [f"{mark} {line}" for line in lines]


def _particles(s: SILaw) -> str:
    """What the DEM code's particles stand for, for the snippets' comments."""
    if s.grain.kind.dimension == 3:
        return f"this law is the {s.grain.body}'s: it applies to the code's spherical particles"
    return (
        f"this law is the {s.grain.geometry}'s (a 2D disk), not a sphere's: use it for "
        "disk-shaped grains (e.g. a 2D simulation)"
    )


def time_step_lines(steps, mark: str, command) -> list[str]:
    """The time-step lines of a snippet whose code integrates Hertz's contact: the comments of
    ``steps`` (a :class:`~restitution.laws.exports.time_step.TimeSteps`) after ``mark`` and,
    when the grains' radius is known, ``command(dt)``, the code's own line setting the step
    ``dt`` (s)."""
    lines = [f"{mark} {line}" for line in steps.lines()]
    return [*lines, command(steps.time_step_s)] if steps.sized else lines


def _grain_of(s: SILaw, c: Constant | TypePairs, i: int):
    """The grain of particle type ``i``: the partner's material for type 2 of two materials."""
    return c.grains[i] if isinstance(c, TypePairs) else s.grain
