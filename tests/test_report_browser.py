"""The HTML report of `restitution paper --quick` renders in headless Chromium with every figure.

The report is one self-contained file: it is rendered from a folder that holds nothing else.
Slow (a quick paper run, about two minutes, plus two browser starts). Needs Debian's `chromium`
package (`make test-slow` installs it); fails with that instruction when it is missing.
"""

import re
import shutil
import subprocess

import numpy as np
import pytest

pytestmark = pytest.mark.slow

BROWSER = shutil.which("chromium") or shutil.which("chromium-browser")
FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    if BROWSER is None:
        pytest.fail(
            "headless Chromium not installed: run `make test-slow` (it installs Debian's chromium)"
        )
    from restitution.reproduction.paper import QUICK, build_paper

    root = tmp_path_factory.mktemp("paper")
    return build_paper(root / "out", QUICK, store=root / "results.sqlite", progress=False)


def _chromium(tmp_path, *args: str) -> subprocess.CompletedProcess:
    profile = tmp_path / "profile"
    profile.mkdir(exist_ok=True)
    return subprocess.run(
        [BROWSER, *FLAGS, f"--user-data-dir={profile}", *args],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


def _alone(run, tmp_path):
    """A copy of report.html in a folder of its own: no figure or other file beside it."""
    import shutil as sh

    folder = tmp_path / "alone"
    folder.mkdir()
    return sh.copy(run.report_html, folder / "report.html")


def test_report_renders_every_figure(run, tmp_path):
    url = _alone(run, tmp_path).resolve().as_uri()
    done = _chromium(tmp_path, "--virtual-time-budget=10000", "--dump-dom", url)
    assert done.returncode == 0, done.stderr[-2000:]
    dom = done.stdout
    # The page's own script marks each image once the page has loaded
    # (restitution.reproduction.report).
    body = re.search(r"<body([^>]*)>", dom)
    assert body is not None, dom[:2000]
    n = len(run.figures) + (run.spheres is not None)  # and the shipped sphere laws' figure
    assert f'data-images="{n}/{n}"' in body.group(1), body.group(1)
    assert 'data-errors="0"' in body.group(1), body.group(1)
    images = re.findall(r"<img\b[^>]*>", dom)
    assert len(images) == n
    assert all('data-loaded="yes"' in img for img in images), [i[:200] for i in images]
    assert all('src="data:image/png;base64,' in img for img in images)
    assert "Summary: the paper beside this reproduction" in dom
    assert "QUICK RUN" in dom


def test_report_screenshot_is_not_blank(run, tmp_path):
    import matplotlib.image

    shot = tmp_path / "report.png"
    url = _alone(run, tmp_path).resolve().as_uri()
    done = _chromium(
        tmp_path, "--window-size=1200,3000", "--virtual-time-budget=10000",
        f"--screenshot={shot}", url,
    )  # fmt: skip
    assert done.returncode == 0 and shot.is_file(), done.stderr[-2000:]
    image = matplotlib.image.imread(shot)
    assert image.shape[0] >= 1000 and image.shape[1] >= 1000
    ink = np.mean(image[..., :3] < 0.5)  # dark pixels: text, lines, table borders
    assert 0.005 < ink < 0.5
