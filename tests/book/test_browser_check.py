"""book/browser_check.py finds what it is meant to find: a tiny site with one fault of each kind.

No MathJax and no book build are needed; only headless Chromium (skipped without it, a failure under CI).
"""

from __future__ import annotations

import base64
import sys
from pathlib import Path

import pytest

BOOK = Path(__file__).resolve().parents[2] / "book"

pytestmark = pytest.mark.usefixtures("chromium")  # tests/book/conftest.py: skipped without it, failed under CI

# A 1x1 white PNG: loads fine but shows nothing.
BLANK_PNG = base64.b64decode(
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8/5+hHgAHggJ/PchI7wAAAABJRU5ErkJggg=="
)

PAGE = """<!doctype html><html><head><meta name="viewport" content="width=device-width">
<style>body {{ margin: 0 }} article {{ width: 50%; padding: 0 10px }}</style></head>
<body><main><article class="bd-article"><section id="s">{body}</section></article></main></body></html>"""


def _site(tmp_path: Path, pages: dict[str, str]) -> Path:
    site = tmp_path / "site"
    site.mkdir()
    (site / "blank.png").write_bytes(BLANK_PNG)
    for name, body in pages.items():
        (site / f"{name}.html").write_text(PAGE.format(body=body))
    return site


@pytest.fixture(scope="module")
def browser_check():
    sys.path.insert(0, str(BOOK))
    try:
        import browser_check
    finally:
        sys.path.remove(str(BOOK))
    return browser_check


def test_a_clean_page_passes_and_is_photographed_at_both_widths(browser_check, tmp_path):
    site = _site(tmp_path, {"clean": "<p>Plain text that wraps as it should, and a short line.</p>"})
    assert browser_check.check(site, tmp_path / "shots") == []
    for width in browser_check.WIDTHS:
        assert (tmp_path / "shots" / f"clean-{width}.png").stat().st_size > 100


def test_each_fault_is_found(browser_check, tmp_path):
    site = _site(
        tmp_path,
        {
            "wide": '<div style="width: 2000px">a block wider than any column</div>',
            "scrolls": '<div style="overflow-x: auto"><div style="width: 3000px">wide content</div></div>',
            "tex": "<p>The law $F = K\\delta^n$ left untypeset.</p>",
            "broken": '<img src="missing.png" alt="missing">',
            "empty": '<figure id="fig-x"><img src="blank.png" width="100" height="50"></figure><figure></figure>',
        },
    )
    findings = browser_check.check(site, tmp_path / "shots")
    kinds = {(f["page"], f["kind"]) for f in findings}
    assert kinds == {
        ("wide", "overflow"),
        ("scrolls", "overflow"),
        ("tex", "raw TeX"),
        ("broken", "broken image"),
        ("empty", "empty figure"),
    }
    # every fault at both widths
    assert {f["width"] for f in findings if f["page"] == "tex"} == set(browser_check.WIDTHS)
