"""What a request gets: :class:`LawAnswer` (the law, its points at the asked speeds, what was made
of it), and the writers every answer shares: the constants for one-number DEM codes and the
export folder.

Units: SI (m/s; the answer carries its units, :data:`restitution.laws.si_point.SI_UNITS`).

An answer is made by :func:`restitution.laws.serve.serve`: the elastic law of the first route
that serves (:mod:`restitution.laws.routes`), then the mechanism that answers
(:mod:`restitution.laws.mechanisms`) or the elastic law alone (:func:`elastic_answer`); each
ends in :func:`finish`, which writes the constants and the exports of the one law that served,
so that the same request gives the same numbers in every output.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from restitution.atomic import writing
from restitution.errors import InputError
from restitution.laws import exports
from restitution.laws.mechanisms.bounds import flag_points
from restitution.laws.partners.grain import KIND as GRAIN
from restitution.laws.si_law import SILaw, si_law
from restitution.laws.si_point import SI_UNITS, overall_status

__all__ = ["LawAnswer", "constants_of", "elastic_answer", "finish", "write_exports"]


@dataclass(frozen=True, eq=False)
class LawAnswer:
    """What :func:`~restitution.laws.serve.serve` gives: the law, its points at the asked speeds
    and what was made of it.

    Attributes
    ----------
    request : LawRequest
    law : SILaw
        The elastic law that served (the one a mechanism's losses were added to).
    points : tuple
        One point per asked speed, each a :class:`~restitution.laws.si_point.SIPoint` (the
        answering mechanism's parts in its ``parts``).
    status, advice : str, str or None
        The answer's status (the worst of its points') and what to do about it.
    constant : Constant or None
        The constant for one-number codes (for two grains: the 1-2 pair's).
    pairs : TypePairs or None
        The constants per pair of particle types (two grain sizes or materials).
    exports : tuple of Path
        The files written (``export_dir``).
    units : dict
        The units of every number.
    by : object or None
        The law of the mechanism that answered (:mod:`restitution.laws.mechanisms`: a
        :class:`~restitution.laws.damped.DampedLaw`, a
        :class:`~restitution.laws.plastic.PlasticLaw`, ...), ``None`` for the elastic law.
    """

    request: object
    law: SILaw
    points: tuple
    status: str
    advice: str | None
    constant: object | None = None
    pairs: object | None = None
    exports: tuple = ()
    units: dict = field(default_factory=lambda: dict(SI_UNITS))
    by: object | None = None

    @property
    def damped(self):
        """The damping grain's law (elastic and viscous parts) when viscosity alone answered."""
        return self.by if getattr(self.by, "mechanism", None) == "viscous" else None

    @property
    def plastic(self):
        """The plastic law when plastic flow answered."""
        return self.by if getattr(self.by, "mechanism", None) == "plastic" else None

    def to_dict(self) -> dict:
        """The answer as the ``law`` command's JSON gives it (without the envelope): the law's
        own (the mechanisms it contains among them), with the answer's points."""
        speeds = list(self.request.speeds)
        if self.by is not None:
            out = self.by.to_dict(speeds, self.points)
        else:
            out = self.law.to_dict(speeds, points=self.points)
        if self.constant is not None:
            out["constant"] = self.constant.to_dict()
        if self.pairs is not None:
            out["type_pairs"] = self.pairs.to_dict()
        if self.request.export_dir is not None:
            out["exports"] = [str(p) for p in self.exports]
        return out


def elastic_answer(r, s: SILaw, note) -> LawAnswer:
    """The answer of the elastic law ``s`` alone (no mechanism asked)."""
    points, _ = flag_points(s, s.points(list(r.speeds), note=note))
    status, advice = overall_status(points)
    return finish(r, s, points, status, advice, note=note)


def finish(r, s: SILaw, points, status, advice, *, note, by=None, table: SILaw | None = None,
           model=None, walls=None) -> LawAnswer:  # fmt: skip
    """The answer of ``points``, with the constants and the exports the request asks for,
    written from ``table`` (the answering law at every speed, default ``s``) and, for the
    exports, the DEM codes' viscoelastic ``model`` and each grain type's law on the wall
    (``walls``, :func:`~restitution.laws.exports.plugin_files.plugin_files`)."""
    table = s if table is None else table
    constant, pairs = constants_of(r, table)
    written = write_exports(r, table, pairs or constant, model, note, walls)
    return LawAnswer(r, s, tuple(points), status, advice, constant, pairs, written, by=by)


def write_exports(r, s: SILaw, constant, model, note, walls=None) -> tuple:
    """The export folder of ``s`` when ``--export`` is asked (its paths), else ``()``."""
    if r.export_dir is None:
        return ()
    with writing(r.export_dir, "--export"):  # a full disk names the option and the folder
        # The law per contact is the package's own route: not a law given as a file.
        no_contact = None if r.law_file is None else (
            "the law is the file given with --law-file, and the law per contact is the "
            "package's own (its shipped curves), not that file's"
        )  # fmt: skip
        folder = exports.write_folder(s, constant, r.export_dir, model, r.friction, walls,
                                      r.radius, no_contact)  # fmt: skip
    if folder.no_closed_form is not None:
        note(f"note: no closed form written: {folder.no_closed_form}")
    if folder.no_plugin is not None:
        note(f"note: no LAMMPS plugin tables written: {folder.no_plugin}")
    return tuple(folder.paths)


def constants_of(r, s: SILaw):
    """``(constant, pairs)``: the constant for one-number codes and, for two grains, the
    constants per pair of particle types (the pair's own is the 1-2 one)."""
    if not r.constants:
        return None, None
    if s.law.partner is not None:
        identical = _identical(r.E, r.nu, r.rho, r.shape, r.identical_law_file,
                               "--identical-law-file")  # fmt: skip
        other = r.partner_grain
        identical2 = None
        if other is not None:
            identical2 = _identical(other.E, other.nu, other.rho, r.shape,
                                    r.partner_identical_law_file,
                                    "--partner-identical-law-file")  # fmt: skip
        pairs = exports.type_pair_constants(
            s,
            identical,
            speed_m_s=r.reference_speed,
            temperature_m2_s2=r.maxwell_temperature,
            identical2=identical2,
        )
        return pairs.mixed, pairs
    if r.reference_speed is not None:
        return exports.constant_at(s, r.reference_speed), None
    return exports.maxwell_constant(s, r.maxwell_temperature), None


def _identical(E, nu, rho, geometry, path, option) -> SILaw:
    """The law of two identical grains of a material, for a type pair i-i."""
    try:
        return si_law(E, nu, rho, geometry, GRAIN.against, path=path)
    except InputError as exc:
        raise InputError(
            f"the constants per type pair need the law of identical grains of each material: "
            f"{exc}; give that file with {option}"
        ) from None
