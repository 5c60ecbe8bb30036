"""SQLite store of collision results, keyed by every input and the code version.

One row per collision: the inputs (a :class:`PointSpec`), the status (``"ok"`` or ``"failed"``
with the error message), the scalar results and the JSON of
:meth:`restitution.dynamics.results.CollisionResult.to_dict`. The key is a SHA-256 of the
canonical JSON of the inputs and the code version (:func:`restitution.provenance.code_version`:
``restitution.__version__`` plus a digest of the solver's source files), so changed code never
reuses old numbers, even between releases.

The default file is ``restitution.bodies.cache.cache_dir() / "results.sqlite"``. The database
runs in WAL mode with a busy timeout; every write is its own short transaction and inserts on
the key (``ON CONFLICT``), so several processes may write to one store at once and a killed
writer loses at most its uncommitted row. A successful row is never replaced; a failed row is
replaced when the point is retried and succeeds. A damaged ``ok`` row (values no collision can
have, or an unreadable result) reads as failed everywhere (:meth:`Store.get`,
:meth:`Store.status`, :meth:`Store.errors`), so a retry computes it again and replaces it.

A file that is not SQLite, or SQLite without this store's schema marker, is refused with a
:class:`StoreError` naming the file; it is never overwritten.
"""

from __future__ import annotations

import hashlib
import json
import math
import sqlite3
import time
from collections.abc import Iterable, Iterator
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from restitution._version import __version__
from restitution.bodies.kinds import DEFAULT_GEOMETRY, body_kind
from restitution.bodies.pair.partner import Partner
from restitution.dynamics.contact import EXPONENTIAL_WALL, ContactLaw, law_from_key
from restitution.errors import InputError, RestitutionError
from restitution.jsonable import finite_or_none, json_default
from restitution.provenance import SOLVER_PACKAGES, code_version, source_digest
from restitution.status import Status

__all__ = [
    "PointSpec",
    "Store",
    "StoreError",
    "StoredPoint",
    "damaged_message",
    "default_store_path",
]

_MARKER = "restitution-results"
_SCHEMA_VERSION = "1"
_SQLITE_MAGIC = b"SQLite format 3\x00"
_BUSY_TIMEOUT_S = 120.0

_SCALARS = (
    "epsilon",
    "energy_loss",
    "energy_drift",
    "contact_time",
    "max_compression",
    "max_force",
    "n_steps",
    "dt",
    "wall_time_s",
)

_SCHEMA = f"""
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS collisions (
    key TEXT PRIMARY KEY,
    code_version TEXT NOT NULL,
    inputs TEXT NOT NULL,
    nu REAL NOT NULL,
    v REAL NOT NULL,
    alpha REAL NOT NULL,
    n_modes INTEGER NOT NULL,
    selection TEXT NOT NULL,
    integrator TEXT NOT NULL,
    status TEXT NOT NULL CHECK (status IN ('{Status.OK}', '{Status.FAILED}')),
    error TEXT,
    {", ".join(f"{name} REAL" for name in _SCALARS)},
    result TEXT,
    created_at TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS collisions_lookup
    ON collisions (nu, n_modes, alpha, v, code_version);
"""


class StoreError(RestitutionError):
    """The result store cannot be used; the message names the file and what to do."""


def default_store_path() -> Path:
    """``cache_dir() / "results.sqlite"`` (see :func:`restitution.bodies.cache.cache_dir`)."""
    from restitution.bodies.cache import cache_dir

    return cache_dir() / "results.sqlite"


def _canonical(value: Any) -> Any:
    """Exact, JSON-ready form of an input: floats as ``float.hex``, sequences as lists."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, int | np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        return float(value).hex()
    if isinstance(value, tuple | list):
        return [_canonical(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _canonical(v) for k, v in sorted(value.items())}
    raise InputError(f"option value {value!r} cannot be part of a store key")


@dataclass(frozen=True)
class PointSpec:
    """Every input of one collision; the store's key.

    Build points with :func:`restitution.limits.sweep.grid`, which fills in every numerical setting
    of the solver; the defaults here only make small keys convenient.

    Attributes
    ----------
    nu : float
        Poisson number of the body's own elasticity (two-dimensional for the disk).
    v : float
        Speed of the body towards the wall before the collision, units of ``c``.
    alpha : float
        Wall hardness, ``1/R``.
    n_modes : int
        Number of modes.
    select : str
        How the modes are chosen (``"lowest"``: the ``n_modes`` lowest frequencies).
    integrator : str
        Time integrator name.
    options : tuple of (str, value) pairs
        Further solver keywords (tolerances, ...), sorted by name; hashable.
    geometry : str
        The body (:data:`restitution.bodies.kinds.GEOMETRIES`); its code version
        (:func:`restitution.provenance.code_version`) is part of the key.
    partner : Partner or None
        ``None``: the body against the rigid wall. Else the second body of a head-on pair
        (:class:`restitution.bodies.pair.partner.Partner`, in units of the first): ``nu`` is then
        the first body's, ``v`` the relative speed of the centres, ``n_modes`` the lowest modes
        of both together; the key holds the partner and the pair's code version. Keys of points
        without a partner do not name it (they are those of the stores written before pairs).
    relaxation_time : float
        ``tau`` of a viscoelastic body (:class:`restitution.bodies.viscoelastic.Viscoelastic`),
        ``R / c``; ``0``: elastic, and then the key does not name it (as for ``partner``).
    contact_law : ContactLaw
        The law that pushes the body off the wall (:mod:`restitution.dynamics.contact`), whose
        hardness is ``alpha``; a key (``ContactLaw.key()``) is read as its law. The exponential
        wall (default) is not named in the key (as for ``partner``); another law is, by
        :meth:`~restitution.dynamics.contact.base.ContactLaw.key` and, for a law defined
        outside the solver's packages, a digest of its module.
    """

    nu: float
    v: float
    alpha: float
    n_modes: int
    select: str = "lowest"
    integrator: str = "split4"
    options: tuple[tuple[str, Any], ...] = ()
    geometry: str = DEFAULT_GEOMETRY
    partner: Partner | None = None
    relaxation_time: float = 0.0
    contact_law: ContactLaw = EXPONENTIAL_WALL

    def __post_init__(self) -> None:
        object.__setattr__(self, "contact_law", _as_law(self.contact_law))
        object.__setattr__(self, "relaxation_time", float(self.relaxation_time))
        object.__setattr__(self, "nu", float(self.nu))
        object.__setattr__(self, "v", float(self.v))
        object.__setattr__(self, "alpha", float(self.alpha))
        object.__setattr__(self, "n_modes", int(self.n_modes))
        opts = self.options.items() if isinstance(self.options, dict) else self.options
        object.__setattr__(self, "options", tuple(sorted((str(k), v) for k, v in opts)))
        body_kind(self.geometry)  # an unknown body is refused before it becomes a key
        if self.partner is not None and not isinstance(self.partner, Partner):
            object.__setattr__(self, "partner", Partner.from_key(self.partner))

    @property
    def group(self) -> tuple:
        """Everything but ``(v, alpha)``: points of one group share a mode set."""
        return (
            self.geometry,
            self.nu,
            self.n_modes,
            self.select,
            self.integrator,
            self.options,
            self.partner,
            self.relaxation_time,
            self.contact_law,
        )

    @property
    def code_version(self) -> str:
        """The solver's version for this point: the body's, or its pair's with a partner."""
        return code_version(self.geometry, pair=self.partner is not None)

    def inputs(self) -> dict:
        """Canonical JSON-ready inputs including the code version (exact floats as hex)."""
        d = asdict(self)
        d["options"] = {k: v for k, v in self.options}
        if self.partner is None:
            del d["partner"]
        else:
            d["partner"] = self.partner.to_dict()
        if self.relaxation_time == 0.0:
            del d["relaxation_time"]
        del d["contact_law"]
        if self.contact_law != EXPONENTIAL_WALL:
            d["contact_law"] = _law_inputs(self.contact_law)
        d["code_version"] = self.code_version
        return _canonical(d)

    def key(self) -> str:
        """SHA-256 of the canonical inputs."""
        text = json.dumps(self.inputs(), sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()


def _as_law(value) -> ContactLaw:
    """A point's contact law: a :class:`ContactLaw`, or its key as a store holds it."""
    if isinstance(value, ContactLaw):
        return value
    if isinstance(value, dict | str):
        return law_from_key(value)
    raise InputError(
        f"contact_law must be a ContactLaw (restitution.dynamics.contact) or its key, got "
        f"{type(value).__name__}; omit it for the exponential wall"
    )


def _law_inputs(law: ContactLaw) -> dict:
    """A law's part of a key: :meth:`ContactLaw.key`, and the digest of the module defining
    it when that module is not one of the solver's (whose digest the code version holds)."""
    d = dict(law.key())
    module = type(law).__module__
    if not module.startswith(tuple(f"{p}." for p in SOLVER_PACKAGES)):
        try:
            d["code"] = source_digest((module,), "law.")
        except ValueError:  # a module without a spec (a script run as __main__)
            d["code"] = source_digest((), "law.")
    return d


def _law_of(stored: dict | None) -> ContactLaw:
    """The :class:`ContactLaw` of a row's canonical inputs (exponential when not named)."""
    if stored is None:
        return EXPONENTIAL_WALL
    return law_from_key(
        {
            k: float.fromhex(v) if isinstance(v, str) and v.startswith(("0x", "-0x")) else v
            for k, v in stored.items()
            if k != "code"
        }
    )


@dataclass(frozen=True)
class StoredPoint:
    """One row of the store.

    Attributes
    ----------
    spec : PointSpec
        Inputs.
    status : str
        ``"ok"`` or ``"failed"`` (:class:`restitution.status.Status`).
    error : str or None
        Error message of a failed point.
    epsilon, energy_loss, energy_drift, contact_time, max_compression, max_force, dt,
    wall_time_s : float
        Scalar results (``nan`` for a failed point); units as in
        :class:`restitution.dynamics.results.CollisionResult`.
    n_steps : int
        Time steps (0 for a failed point).
    result : dict or None
        ``CollisionResult.to_dict()``.
    code_version : str
        Package version that computed the row.
    created_at : str
        UTC time of writing, ISO 8601.
    """

    spec: PointSpec
    status: str
    error: str | None
    epsilon: float
    energy_loss: float
    energy_drift: float
    contact_time: float
    max_compression: float
    max_force: float
    n_steps: int
    dt: float
    wall_time_s: float
    result: dict | None
    code_version: str
    created_at: str

    @property
    def ok(self) -> bool:
        return self.status == Status.OK


def _now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


class Store:
    """A result store in one SQLite file.

    Parameters
    ----------
    path : str or pathlib.Path, optional
        Database file; created with its directory if missing. Default
        :func:`default_store_path`.

    Raises
    ------
    StoreError
        If the file is not a SQLite database or lacks this store's schema marker.

    Notes
    -----
    Open one ``Store`` per process (SQLite connections must not cross processes); use it as a
    context manager or call :meth:`close`.
    """

    def __init__(self, path: str | Path | None = None) -> None:
        if path is None:  # the cache must take the store's writes before any work starts
            from restitution.bodies.cache import CacheError, writable_folder

            try:
                writable_folder(default_store_path().parent)
            except CacheError as exc:
                raise CacheError(f"{exc} (or give --store PATH)") from None
        self.path = Path(path) if path is not None else default_store_path()
        self._check_file()
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise StoreError(
                f"cannot create the directory of result store {self.path} "
                f"({exc.strerror or exc}); pass --store PATH in a writable directory"
            ) from None
        try:
            self._conn = sqlite3.connect(
                self.path, timeout=_BUSY_TIMEOUT_S, isolation_level=None, check_same_thread=False
            )
        except sqlite3.Error as exc:
            raise StoreError(f"cannot open result store {self.path}: {exc}") from exc
        try:
            self._conn.execute(f"PRAGMA busy_timeout = {int(_BUSY_TIMEOUT_S * 1000)}")
            self._init_schema()
        except sqlite3.DatabaseError as exc:
            self._conn.close()
            raise self._error(exc, opening=True) from None
        except StoreError:
            self._conn.close()
            raise

    # -- opening -----------------------------------------------------------------------------

    def _foreign(self, what: str) -> StoreError:
        return StoreError(
            f"result store {self.path} is not a restitution store: {what}. Pass another path "
            "(--store PATH), or move the file away if it is not needed"
        )

    def _error(self, exc: sqlite3.Error, *, opening: bool = False) -> StoreError:
        """A :class:`StoreError` for an SQLite error, with advice that fits its cause.

        Only a file that SQLite cannot recognise is called foreign; a valid store that cannot
        be written, is locked or is damaged is never called foreign, and deleting a store is
        never advised.
        """
        name = getattr(exc, "sqlite_errorname", "")
        text = str(exc)
        if "locked" in text or name in ("SQLITE_BUSY", "SQLITE_LOCKED"):
            return StoreError(
                f"result store {self.path} stayed locked by another process for "
                f"{_BUSY_TIMEOUT_S:g} s; try again, or pass another path (--store PATH)"
            )
        if name == "SQLITE_NOTADB" or "not a database" in text:
            return self._foreign(f"SQLite cannot read it ({text})")
        if name == "SQLITE_CORRUPT" or "malformed" in text:
            return StoreError(
                f"result store {self.path} is damaged ({text}); its readable rows may be "
                f"saved with `sqlite3 {self.path} .recover`; pass another path (--store PATH) "
                "to compute afresh"
            )
        if name == "SQLITE_FULL" or "full" in text:
            return StoreError(
                f"result store {self.path}: the disk is full ({text}); free space and rerun "
                "(stored points are kept), or pass --store PATH on another disk"
            )
        action = "opened" if opening else "written"
        return StoreError(
            f"result store {self.path} cannot be {action} ({text}): make the file and its "
            "directory writable, or pass --store PATH to a writable location (a copy of this "
            "file keeps its results)"
        )

    def check_writable(self) -> None:
        """Write one row of metadata now, so that a sweep fails before computing, not after.

        Raises
        ------
        StoreError
            If the store cannot be written; the message says what to do.
        """
        try:
            with self._write():
                self._conn.execute(
                    "INSERT INTO meta VALUES ('last_write_check', ?) "
                    "ON CONFLICT(key) DO UPDATE SET value = excluded.value",
                    (_now(),),
                )
        except sqlite3.Error as exc:
            raise self._error(exc) from None

    def _check_file(self) -> None:
        if not self.path.exists():
            return
        if self.path.is_dir():
            raise self._foreign("it is a directory")
        try:
            with open(self.path, "rb") as fh:
                head = fh.read(len(_SQLITE_MAGIC))
        except OSError as exc:
            raise StoreError(
                f"cannot read result store {self.path} ({exc.strerror or exc}); make it "
                "readable or pass another path (--store PATH)"
            ) from None
        if head and head != _SQLITE_MAGIC:
            raise self._foreign("not a SQLite database")

    def _init_schema(self) -> None:
        # Check and create in one write transaction, so that two processes opening a new file
        # at once never see each other's half-made schema. The journal mode is switched to WAL
        # only once the file is known to be ours: a foreign file is left untouched.
        conn = self._conn
        with self._write():
            tables = {
                r[0] for r in conn.execute("SELECT name FROM sqlite_master WHERE type = 'table'")
            }
            if tables:
                self._check_marker(tables)
            else:
                for statement in _SCHEMA.split(";"):
                    if statement.strip():
                        conn.execute(statement)
                conn.executemany(
                    "INSERT INTO meta VALUES (?, ?)",
                    [
                        ("schema", _MARKER),
                        ("schema_version", _SCHEMA_VERSION),
                        ("created_by", __version__),
                        ("created_at", _now()),
                    ],
                )
        conn.execute("PRAGMA journal_mode = WAL")

    def _check_marker(self, tables: set[str]) -> None:
        if "meta" not in tables or "collisions" not in tables:
            raise self._foreign(f"a SQLite database with other tables {sorted(tables)}")
        meta = dict(self._conn.execute("SELECT key, value FROM meta"))
        if meta.get("schema") != _MARKER:
            raise self._foreign("a SQLite database without this store's schema marker")
        if meta.get("schema_version") != _SCHEMA_VERSION:
            raise StoreError(
                f"result store {self.path} has schema version {meta.get('schema_version')}, "
                f"this code reads version {_SCHEMA_VERSION}; pass another path (--store PATH) "
                "and keep this file for the code version that wrote it"
            )

    def _write(self):
        return _Transaction(self._conn)

    def close(self) -> None:
        """Close the connection."""
        self._conn.close()

    def __enter__(self) -> Store:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __repr__(self) -> str:
        return f"Store({str(self.path)!r})"

    # -- writing -----------------------------------------------------------------------------

    def put(self, spec: PointSpec, result: Any) -> None:
        """Store a successful collision.

        Parameters
        ----------
        spec : PointSpec
            Inputs.
        result : CollisionResult or dict
            The result, or its ``to_dict()``.
        """
        d = result if isinstance(result, dict) else result.to_dict()
        scalars = [finite_or_none(d.get(name)) for name in _SCALARS]
        if scalars[1] is None and scalars[0] is not None:
            scalars[1] = 1.0 - scalars[0] ** 2
        blob = json.dumps(d, default=json_default, allow_nan=True)
        why = _damaged(dict(zip(_SCALARS, scalars, strict=True)), blob)
        if why is not None:  # never written as a success that reads back as a damaged row
            self.put_failure(
                spec, f"the collision's result is not one: {why}; lower dt or energy_tol"
            )
            return
        self._upsert(spec, Status.OK, None, scalars, blob)

    def put_failure(self, spec: PointSpec, message: str) -> None:
        """Record a failed collision with its error message (never replaces a success)."""
        self._upsert(spec, Status.FAILED, str(message), [None] * len(_SCALARS), None)

    def _upsert(self, spec, status, error, scalars, blob) -> None:
        # A new row is inserted; an existing failed row is replaced (a retry); an existing
        # successful row is kept, so a repeated or concurrent write never duplicates a point.
        cols = (
            "key, code_version, inputs, nu, v, alpha, n_modes, selection, integrator, status, "
            f"error, {', '.join(_SCALARS)}, result, created_at"
        )
        values = [
            spec.key(),
            spec.code_version,
            json.dumps(spec.inputs(), sort_keys=True),
            spec.nu,
            spec.v,
            spec.alpha,
            spec.n_modes,
            spec.select,
            spec.integrator,
            status,
            error,
            *scalars,
            blob,
            _now(),
        ]
        update = ", ".join(
            f"{c} = excluded.{c}" for c in ["status", "error", *_SCALARS, "result", "created_at"]
        )
        sql = (
            f"INSERT INTO collisions ({cols}) VALUES ({', '.join('?' * len(values))}) "
            f"ON CONFLICT(key) DO UPDATE SET {update} WHERE collisions.status = '{Status.FAILED}'"
        )
        try:
            with self._write():
                # A damaged ``ok`` row reads as failed, so it is replaced as a failed one is.
                row = self._conn.execute(
                    f"SELECT {_STATE} FROM collisions WHERE key = ?", (values[0],)
                ).fetchone()
                if row is not None and row[0] == Status.OK and _state(*row)[0] != Status.OK:
                    self._conn.execute("DELETE FROM collisions WHERE key = ?", (values[0],))
                self._conn.execute(sql, values)
        except sqlite3.Error as exc:
            raise self._error(exc) from None

    # -- reading -----------------------------------------------------------------------------

    def get(self, spec: PointSpec) -> StoredPoint | None:
        """The stored row of ``spec`` (this code version), or None."""
        row = self._read(f"SELECT {_ROW} FROM collisions WHERE key = ?", (spec.key(),))
        row = row[0] if row else None
        return None if row is None else _row_to_point(row, spec)

    def status(self, specs: Iterable[PointSpec]) -> dict[str, str]:
        """Map key -> status for those of ``specs`` that are stored (a damaged row: failed)."""
        return {key: status for key, (status, _) in self._states(specs).items()}

    def errors(self, specs: Iterable[PointSpec]) -> dict[str, str]:
        """Map key -> error message for those of ``specs`` that are stored as failed or whose
        row is damaged."""
        return {
            key: error
            for key, (status, error) in self._states(specs).items()
            if status == Status.FAILED
        }

    def _states(self, specs: Iterable[PointSpec]) -> dict[str, tuple[str, str | None]]:
        """Map key -> (status, error) of the stored ``specs``, a damaged row read as failed."""
        keys = [s.key() for s in specs]
        out: dict[str, tuple[str, str | None]] = {}
        for start in range(0, len(keys), 500):
            chunk = keys[start : start + 500]
            marks = ",".join("?" * len(chunk))
            rows = self._read(f"SELECT key, {_STATE} FROM collisions WHERE key IN ({marks})", chunk)
            out.update((key, _state(*row)) for key, *row in rows)
        return out

    def points(
        self, *, all_versions: bool = False, geometry: str = DEFAULT_GEOMETRY, **filters: Any
    ) -> list[StoredPoint]:
        """Stored rows, optionally filtered by exact ``nu``, ``v``, ``alpha``, ``n_modes``,
        ``selection``, ``integrator`` or ``status``; by default only this code version of the
        body ``geometry`` (:func:`restitution.provenance.code_version`, which differs between
        bodies)."""
        allowed = {"nu", "v", "alpha", "n_modes", "selection", "integrator", "status"}
        unknown = set(filters) - allowed
        if unknown:
            raise InputError(f"unknown store filter(s) {sorted(unknown)}; use {sorted(allowed)}")
        where = [f"{k} = ?" for k in filters]
        args = list(filters.values())
        if not all_versions:
            where.append("code_version = ?")
            args.append(code_version(geometry))
        clause = f" WHERE {' AND '.join(where)}" if where else ""
        rows = self._read(
            f"SELECT {_ROW} FROM collisions{clause} ORDER BY nu, v, alpha, n_modes", args
        )
        return [_row_to_point(r) for r in rows]

    def _read(self, sql: str, args: Any = ()) -> list[tuple]:
        try:
            return self._conn.execute(sql, args).fetchall()
        except sqlite3.Error as exc:
            raise self._error(exc) from None

    def __iter__(self) -> Iterator[StoredPoint]:
        return iter(self.points(all_versions=True))

    def __len__(self) -> int:
        return int(self._read("SELECT COUNT(*) FROM collisions")[0][0])


_ROW = f"inputs, status, error, {', '.join(_SCALARS)}, result, code_version, created_at"


def _partner(stored: dict | None, num) -> Partner | None:
    """The :class:`Partner` of a row's canonical inputs (``None`` for a body on the wall)."""
    if stored is None:
        return None
    return Partner.from_key({k: None if v is None else num(v) for k, v in stored.items()})


_DAMAGED = (
    "it is not used, and the next sweep over it computes it again (rerun the same command); or "
    "compute into a fresh store (--store another file, or store= another path)"
)
_DAMAGED_HEAD = "damaged stored row: "


def damaged_message(message: str | None) -> bool:
    """Whether a failure message (:meth:`Store.errors`) is a damaged row's: a sweep computes
    such a point again without being asked to retry failures, as it does a lost one."""
    return (message or "").startswith(_DAMAGED_HEAD)


_STATE = "status, error, epsilon, energy_loss, energy_drift, result"
"""The columns :func:`_state` reads."""


def _state(status, error, epsilon, energy_loss, energy_drift, blob) -> tuple[str, str | None]:
    """A row's ``(status, error)``: a damaged ``ok`` row (:func:`_damaged`) is failed."""
    if status == Status.OK:
        values = {"epsilon": epsilon, "energy_loss": energy_loss, "energy_drift": energy_drift}
        why = _damaged(values, blob)
        if why is not None:
            return Status.FAILED, f"{_DAMAGED_HEAD}{why}; {_DAMAGED}"
    return status, error


def _damaged(values: dict, blob) -> str | None:
    """Why an ``ok`` row's values cannot be a collision's (unreadable result, epsilon or loss
    outside [0, 1], a non-finite drift), or ``None`` (issue 47: rows were not range-checked the
    way law files are)."""
    eps, loss, drift = values["epsilon"], values["energy_loss"], values["energy_drift"]
    if not all(isinstance(x, int | float) and math.isfinite(x) for x in (eps, loss, drift)):
        return "its epsilon, energy loss or drift is not a finite number"
    if not (0.0 <= eps <= 1.0 + 1e-9 and -1e-9 <= loss <= 1.0):
        return f"its epsilon {eps:.6g} or energy loss {loss:.6g} lies outside [0, 1]"
    if blob is not None:
        try:
            json.loads(blob)
        except (ValueError, TypeError, RecursionError):
            return "its stored result is not JSON"
    return None


def _row_to_point(row: tuple, spec: PointSpec | None = None) -> StoredPoint:
    inputs, status, error, *rest = row
    scalars, (blob, version, created) = rest[: len(_SCALARS)], rest[len(_SCALARS) :]
    values = dict(zip(_SCALARS, scalars, strict=True))
    if status == Status.OK:
        status, error = _state(status, error, *(values[k] for k in _SCALARS[:3]), blob)
        if status != Status.OK:
            blob, values = None, dict.fromkeys(values)
    try:
        d = json.loads(inputs)
    except (ValueError, TypeError, RecursionError):
        if spec is None:
            raise StoreError(
                f"a row of the result store is damaged (its inputs are not JSON); {_DAMAGED}"
            ) from None
        return _failed(spec, f"{_DAMAGED_HEAD}its inputs are not JSON; {_DAMAGED}")

    def num(v):
        return float.fromhex(v) if isinstance(v, str) else v

    options = tuple(
        (k, num(v) if isinstance(v, str) and v.startswith(("0x", "-0x")) else v)
        for k, v in sorted(d["options"].items())
    )
    spec = PointSpec(
        nu=num(d["nu"]),
        v=num(d["v"]),
        alpha=num(d["alpha"]),
        n_modes=d["n_modes"],
        select=d["select"],
        integrator=d["integrator"],
        options=options,
        geometry=d.get(
            "geometry", DEFAULT_GEOMETRY
        ),  # rows of 0.1.0 before the sphere name no body
        partner=_partner(d.get("partner"), num),
        relaxation_time=num(d.get("relaxation_time", 0.0)),
        contact_law=_law_of(d.get("contact_law")),
    )
    nan = float("nan")
    return StoredPoint(
        spec=spec,
        status=status,
        error=error,
        epsilon=nan if values["epsilon"] is None else values["epsilon"],
        energy_loss=nan if values["energy_loss"] is None else values["energy_loss"],
        energy_drift=nan if values["energy_drift"] is None else values["energy_drift"],
        contact_time=nan if values["contact_time"] is None else values["contact_time"],
        max_compression=nan if values["max_compression"] is None else values["max_compression"],
        max_force=nan if values["max_force"] is None else values["max_force"],
        n_steps=0 if values["n_steps"] is None else int(values["n_steps"]),
        dt=nan if values["dt"] is None else values["dt"],
        wall_time_s=nan if values["wall_time_s"] is None else values["wall_time_s"],
        result=None if blob is None else json.loads(blob),
        code_version=version,
        created_at=created,
    )


def _failed(spec: PointSpec, message: str) -> StoredPoint:
    """A failed point of ``spec`` with ``message`` (no values)."""
    nan = float("nan")
    return StoredPoint(spec=spec, status=Status.FAILED, error=message, epsilon=nan,
                       energy_loss=nan, energy_drift=nan, contact_time=nan, max_compression=nan,
                       max_force=nan, n_steps=0, dt=nan, wall_time_s=nan, result=None,
                       code_version="", created_at="")  # fmt: skip


class _Transaction:
    """``BEGIN IMMEDIATE`` ... ``COMMIT`` (rollback on error): one short write transaction."""

    def __init__(self, conn: sqlite3.Connection) -> None:
        self._conn = conn

    def __enter__(self) -> None:
        self._conn.execute("BEGIN IMMEDIATE")

    def __exit__(self, exc_type, exc, tb) -> None:
        if exc_type is None:
            self._conn.execute("COMMIT")
        else:
            self._conn.execute("ROLLBACK")
