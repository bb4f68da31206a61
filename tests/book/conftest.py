"""Shared by the book's tests: the headless browser they need."""

from __future__ import annotations

import os
import shutil

import pytest


@pytest.fixture(scope="session")
def chromium() -> str:
    """Path of headless Chromium. Skipped where it is not installed, except under CI (``CI`` set), where
    ``.ci/run`` installs it: there a missing browser is a failure, so the browser checks never pass by not
    running."""
    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        message = "needs the Debian package chromium (apt-get install chromium)"
        if os.environ.get("CI"):
            pytest.fail(f"CI is set but Chromium is missing: {message}")
        pytest.skip(message)
    return path
