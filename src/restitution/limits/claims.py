"""Claims on points of a result store: two sweeps on one store never compute a point twice.

A sweep claims the points it is about to compute (a row per point in the store's ``claims``
table, naming the sweep, its process and host, and a heartbeat); another sweep that meets a
claimed point leaves it to its owner and waits for it to be stored, unless the owner is gone:
its process no longer exists (same host), or its heartbeat is older than :data:`LEASE_S`
(another host sharing the file). A sweep killed with ``kill -9`` so leaves claims that the next
sweep takes over at once; a sweep that ends releases its own.

The table lives in the store's SQLite file beside the results and is made on first use; stores
written before it exist work unchanged.
"""

from __future__ import annotations

import os
import socket
import sqlite3
import time
import uuid
from collections.abc import Iterable
from pathlib import Path

__all__ = ["LEASE_S", "POLL_S", "Claims"]

LEASE_S = 3600.0
"""Seconds without a heartbeat after which a claim of another host is taken over (one batch of
the production sweeps takes minutes; the heartbeat follows every finished batch)."""

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
    if host != socket.gethostname():
        return now - heartbeat < LEASE_S
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
    """

    def __init__(self, path: str | Path) -> None:
        self.owner = uuid.uuid4().hex
        self._host = socket.gethostname()
        self._pid = os.getpid()
        self._conn = sqlite3.connect(
            Path(path), timeout=_BUSY_TIMEOUT_S, isolation_level=None, check_same_thread=False
        )
        self._conn.execute(_SCHEMA)

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
        """Renew the heartbeat of this sweep's claims."""
        self._conn.execute(
            "UPDATE claims SET heartbeat = ? WHERE owner = ?", (time.time(), self.owner)
        )

    def release(self) -> None:
        """Drop this sweep's claims (its points are stored, failed or left for a rerun)."""
        self._conn.execute("DELETE FROM claims WHERE owner = ?", (self.owner,))

    def close(self) -> None:
        """Release the claims and close the connection. A release that fails (a full disk, a
        locked store) is let go: the claims' heartbeat stops, so other sweeps take them over,
        and the error that ended the sweep is the one reported (issue 47: a full disk's clear
        error was masked by a traceback from here)."""
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
