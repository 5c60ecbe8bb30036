"""A folder or file made read-only for a test, also for root (``chattr +i``)."""

from __future__ import annotations

import contextlib
import os
import shutil
import subprocess

import pytest


@contextlib.contextmanager
def read_only(path):
    """``path`` (file or directory) read-only for the duration; skips when impossible."""
    path = str(path)
    if os.geteuid() != 0:
        mode = os.stat(path).st_mode
        os.chmod(path, 0o555 if os.path.isdir(path) else 0o444)
        try:
            yield
        finally:
            os.chmod(path, mode)
        return
    chattr = shutil.which("chattr")
    if chattr is None or subprocess.run([chattr, "+i", path], capture_output=True).returncode:
        pytest.skip("running as root without chattr +i: cannot make a read-only file")
    try:
        yield
    finally:
        subprocess.run([chattr, "-i", path], check=True)
