"""Building the book for the tests: when the built site is stale, and a build started in the background.

The build (``book/build.sh``, minutes) is the suite's longest job.  The root conftest starts it in the
background as the session starts (:func:`start`), so that it runs beside the other tests on their
xdist workers; the ``site`` fixture of test_book.py then waits for it (:func:`wait`), or builds the book
itself when no build was started (a run of tests/book alone, say).
"""

from __future__ import annotations

import os
import signal
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BOOK = ROOT / "book"
SITE = BOOK / "_build" / "html"

#: Environment variable naming the folder of a background build's log and exit code (set by :func:`start`).
STARTED = "RINGCHAIN_BOOK_BUILD"


def newest_source_mtime() -> float:
    """Modification time of the newest source of the book or of the package."""
    paths = [*BOOK.glob("*.md"), *BOOK.glob("*.yml"), *BOOK.glob("*.py")]
    paths += [BOOK / "references.bib", BOOK / "matplotlibrc"]
    paths += [BOOK / "browser_check.js", *(BOOK / "_css").glob("*.css")]
    paths += [*(ROOT / "theory").glob("*.py"), *(ROOT / "numerics").rglob("*.py")]
    return max(p.stat().st_mtime for p in paths)


def stale() -> bool:
    """Whether the built site is missing or older than a source."""
    index = SITE / "index.html"
    return not index.is_file() or index.stat().st_mtime < newest_source_mtime()


def _environment() -> dict:
    return {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}  # the pages plot inline


def start() -> subprocess.Popen:
    """Start ``book/build.sh`` in the background and name its folder in :data:`STARTED` (inherited by workers);
    returns the process (its own process group), which the caller keeps and ends (:func:`stop`)."""
    folder = Path(tempfile.mkdtemp(prefix="ringchain-book-build-"))
    script = f'bash "{BOOK / "build.sh"}" > "{folder / "log"}" 2>&1; echo $? > "{folder / "status.tmp"}"; ' \
             f'mv "{folder / "status.tmp"}" "{folder / "status"}"'  # fmt: skip
    process = subprocess.Popen(["bash", "-c", script], env=_environment(), start_new_session=True)
    os.environ[STARTED] = str(folder)
    return process


def stop(process: subprocess.Popen) -> None:
    """End a background build the session did not wait for (its tests deselected, or the session stopped)."""
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGTERM)
    process.wait()


def wait() -> tuple[int, str] | None:
    """(exit code, log) of the build :func:`start` began, once it ends; None if none was started."""
    folder = os.environ.get(STARTED)
    if not folder:
        return None
    status = Path(folder) / "status"
    while not status.is_file():
        time.sleep(1.0)
    return int(status.read_text()), (Path(folder) / "log").read_text()


def build() -> tuple[int, str]:
    """Build the book in this process: (exit code, output)."""
    result = subprocess.run(["bash", str(BOOK / "build.sh")], env=_environment(), capture_output=True, text=True)
    return result.returncode, result.stdout + result.stderr
