"""Claims on points of a result store: two sweeps on one store never compute a point twice.

A sweep claims the points it is about to compute (a row per point in the store's ``claims``
table, naming the sweep, its process and host, and a heartbeat); another sweep that meets a
claimed point leaves it to its owner and waits for it to be stored, unless the owner is gone:
its process no longer exists (same host), or its heartbeat is older than :data:`LEASE_S` (any
host). The heartbeat is renewed every :data:`BEAT_S` by a thread of the owning sweep, and after
every batch it finishes. A sweep killed with ``kill -9`` so leaves claims that the next sweep on
its host takes over at once; one that hangs, or whose process number was taken by another
program (a container restarted under the same host name), stops beating and its claims are
taken over after the lease (issue 47: judged by the process alone, such claims held a sweep
waiting forever). A sweep that ends releases its own.

The table lives in the store's SQLite file beside the results and is made on first use; stores
written before it exist work unchanged.
"""

from __future__ import annotations

import os
import socket
import sqlite3
import threading
import time
import uuid
from collections.abc import Iterable
from pathlib import Path

__all__ = ["BEAT_S", "LEASE_S", "POLL_S", "Claims"]

BEAT_S = 30.0
"""Seconds between two heartbeats of a sweep's claims (its heartbeat thread)."""

LEASE_S = 600.0
"""Seconds without a heartbeat after which a claim is taken over: twenty missed beats, so a
store that is busy for a while (SQLite waits up to a minute for a lock) loses no live claim."""

POLL_S = 2.0
"""Seconds between two looks at the points another sweep is computing."""

_BUSY_TIMEOUT_S = 60.0

_SCHEMA = """
CREATE TABLE IF NOT EXISTS claims (
    key TEXT PRIMARY KEY,
    owner TEXT NOT NULL,
    host TEXT NOT NULL,
    pid INTEGER NOT NULL,
    heartbeat REAL NOT NULL
)
"""


def _alive(host: str, pid: int, heartbeat: float, now: float) -> bool:
    """Whether the sweep that made a claim may still be computing it."""
    if now - heartbeat >= LEASE_S:
        return False
    if host != socket.gethostname():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's live process
        return True
    return True


class Claims:
    """The claims of one sweep (its ``owner``) on the store at ``path``.

    Parameters
    ----------
    path : path
        The result store's file (:attr:`restitution.limits.store.Store.path`).
    beat_s : float
        Seconds between two heartbeats of the heartbeat thread (:data:`BEAT_S`).
    """

    def __init__(self, path: str | Path, beat_s: float = BEAT_S) -> None:
        self.owner = uuid.uuid4().hex
        self._host = socket.gethostname()
        self._pid = os.getpid()
        self._path = Path(path)
        self._conn = sqlite3.connect(
            self._path, timeout=_BUSY_TIMEOUT_S, isolation_level=None, check_same_thread=False
        )
        self._conn.execute(_SCHEMA)
        self._stop = threading.Event()
        self._beating = threading.Thread(
            target=self._beat_until_stopped, args=(float(beat_s),), daemon=True,
            name="restitution claims heartbeat",
        )  # fmt: skip
        self._beating.start()

    def _beat_until_stopped(self, beat_s: float) -> None:
        """The heartbeat thread: renew this sweep's claims every ``beat_s`` on its own
        connection. A beat that fails (a locked or full store) is skipped; the next one may
        succeed, and a sweep that cannot beat for :data:`LEASE_S` loses its claims, which is
        what a sweep that cannot write should do."""
        conn = sqlite3.connect(self._path, timeout=_BUSY_TIMEOUT_S, isolation_level=None)
        try:
            while not self._stop.wait(beat_s):
                try:
                    self._renew(conn)
                except sqlite3.Error:
                    pass
        finally:
            conn.close()

    def _renew(self, conn: sqlite3.Connection) -> None:
        conn.execute("UPDATE claims SET heartbeat = ? WHERE owner = ?", (time.time(), self.owner))

    def claim(self, keys: Iterable[str]) -> tuple[set[str], set[str]]:
        """Claim ``keys``: ``(mine, theirs)``. A key is mine when it was free, already mine, or
        claimed by a sweep that is gone; theirs when a live sweep holds it."""
        keys = list(dict.fromkeys(keys))
        now = time.time()
        mine: set[str] = set()
        conn = self._conn
        conn.execute("BEGIN IMMEDIATE")
        try:
            held = {}
            for start in range(0, len(keys), 500):
                chunk = keys[start : start + 500]
                marks = ",".join("?" * len(chunk))
                held.update(
                    (k, (o, h, p, b))
                    for k, o, h, p, b in conn.execute(
                        f"SELECT key, owner, host, pid, heartbeat FROM claims WHERE key IN "
                        f"({marks})",
                        chunk,
                    )
                )
            for key in keys:
                other = held.get(key)
                if other is None or other[0] == self.owner or not _alive(*other[1:], now):
                    mine.add(key)
            conn.executemany(
                "INSERT OR REPLACE INTO claims VALUES (?, ?, ?, ?, ?)",
                [(k, self.owner, self._host, self._pid, now) for k in mine],
            )
            conn.execute("COMMIT")
        except BaseException:
            conn.execute("ROLLBACK")
            raise
        return mine, set(keys) - mine

    def beat(self) -> None:
        """Renew the heartbeat of this sweep's claims now (after a batch)."""
        self._renew(self._conn)

    def release(self) -> None:
        """Drop this sweep's claims (its points are stored, failed or left for a rerun)."""
        self._conn.execute("DELETE FROM claims WHERE owner = ?", (self.owner,))

    def close(self) -> None:
        """Release the claims and close the connection. A release that fails (a full disk, a
        locked store) is let go: the claims' heartbeat stops, so other sweeps take them over,
        and the error that ended the sweep is the one reported (issue 47: a full disk's clear
        error was masked by a traceback from here)."""
        self._stop.set()
        self._beating.join()
        try:
            self.release()
        except sqlite3.Error:
            pass
        finally:
            self._conn.close()

    def __enter__(self) -> Claims:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
