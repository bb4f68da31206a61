"""What a reader's browser shows: every page of the built book in headless Chromium, at two widths.

    python book/browser_check.py [SITE] [--out DIR] [--pages index contact ...]

serves the built site (default ``book/_build/html``) on 127.0.0.1, opens every page in headless Chromium
at a desktop width (1280 px) and a phone width (390 px), waits for MathJax, saves a full-page screenshot of
each (``DIR/<page>-<width>.png``, default DIR ``book/_build/screenshots``; taken in a window as tall as the
page, so that it shows the page as it is) and checks what the page shows:

- **overflow**: no element of the article reaches past its column, and nothing scrolls sideways (a display
  equation, a code cell, an output or a table wider than the column), except tables and code at the phone
  width, which scroll inside their own frame (a 390 px column holds about 40 characters of code);
- **raw TeX**: no ``$...$``, ``\\frac``, ``\\(``... left in the text after MathJax, and no MathJax error;
- **broken images**: every image loads;
- **empty figures**: every figure holds an image with more than a handful of colours.

The findings go to ``DIR/report.json`` (a list of {page, width, kind, where, detail}); the script prints them
and exits with 1 if there are any (``--no-fail`` prints and exits 0, as ``book/build.sh`` runs it).
Chromium is driven over its DevTools protocol with the WebSocket client of Tornado (a dependency of Jupyter,
so installed with the book's extras); the browser gets no network access beyond the local server.
"""

from __future__ import annotations

import argparse
import asyncio
import base64
import functools
import http.server
import json
import math
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request
from pathlib import Path

BOOK = Path(__file__).resolve().parent
WIDTHS = (1280, 390)  # px: a desktop window and a phone
VIEWPORT_HEIGHT = 900  # px
#: Pages whose window (its first VIEWPORT_HEIGHT px, as a reader sees the page on opening it) every check also
#: captures, into ``out/windows``: the top of their full-page screenshots should show the same (tests/book compares
#: them; Chromium's own full-page capture once showed most pages scrolled sideways).
WINDOW_PAGES = ("index", "contact", "fitting")
MAX_SCREENSHOT_HEIGHT = 30000  # px: Chromium's limit for one capture is larger; a page is far shorter

CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
    "--mute-audio",
]

# Runs in the page once it has loaded; resolves to a JSON list of [kind, where, detail].
CHECK_SCRIPT = (BOOK / "browser_check.js").read_text()

# Resolves once the page has been laid out and painted at its current window size.
_TWO_FRAMES = "new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))"

# Resolves once the page is laid out and painted at its current window size and its finite animations have ended
# (at most 3 s): a resized window starts the theme's transitions (at 390 px its side columns slide out of view), and a
# capture in the middle of one showed the page half scrolled sideways.
_SETTLED = """new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(async () => {
  const running = document.getAnimations().filter((a) => a.effect && a.effect.getComputedTiming().endTime !== Infinity);
  await Promise.race([Promise.all(running.map((a) => a.finished.catch(() => null))),
                      new Promise((later) => setTimeout(later, 3000))]);
  requestAnimationFrame(() => requestAnimationFrame(done));
})))"""


def chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


class _DevTools:
    """The smallest client of the DevTools protocol: one page, calls answered in order, events kept."""

    def __init__(self, connection):
        self.connection = connection
        self.counter = 0
        self.events: list[dict] = []

    async def _read(self) -> dict:
        message = await self.connection.read_message()
        if message is None:
            raise RuntimeError("Chromium closed the DevTools connection")
        return json.loads(message)

    async def call(self, method: str, **params):
        self.counter += 1
        await self.connection.write_message(json.dumps({"id": self.counter, "method": method, "params": params}))
        while True:
            data = await self._read()
            if data.get("id") == self.counter:
                if "error" in data:
                    raise RuntimeError(f"{method}: {data['error']}")
                return data["result"]
            self.events.append(data)

    async def event(self, name: str):
        while True:
            for i, data in enumerate(self.events):
                if data.get("method") == name:
                    return self.events.pop(i)
            self.events.append(await self._read())


async def _full_page(tools: _DevTools, width: int) -> bytes:
    """PNG of the whole page as it is laid out at ``width``: the window made as tall as the page, one capture.

    Chromium's own full-page capture (``captureBeyondViewport``) lays some pages out anew for the capture:
    the book's chapters came out with the navigation column gone and the text cut at the left edge,
    although the page showed correctly.  A window as tall as the page (at most
    :data:`MAX_SCREENSHOT_HEIGHT`) shows it as a reader scrolling through it sees it; only what depends
    on the window's height, such as the entry the contents column highlights, may differ.
    """
    height = VIEWPORT_HEIGHT
    for _ in range(3):  # boxes sized by the window (100vh) may change the page's height once it is taller
        metrics = await tools.call("Page.getLayoutMetrics")
        wanted = min(math.ceil(metrics["cssContentSize"]["height"]), MAX_SCREENSHOT_HEIGHT)
        if wanted == height:
            break
        height = wanted
        await tools.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1,
                         mobile=False)  # fmt: skip
        await tools.call("Runtime.evaluate", expression=_TWO_FRAMES, awaitPromise=True)
    # optimizeForSpeed: a faster, larger PNG (measured: a quarter larger, the check's CPU time a tenth less).
    shot = await tools.call("Page.captureScreenshot", format="png", optimizeForSpeed=True)
    await tools.call("Emulation.setDeviceMetricsOverride", width=width, height=VIEWPORT_HEIGHT, deviceScaleFactor=1,
                     mobile=False)  # fmt: skip
    return base64.b64decode(shot["data"])


async def _inspect(port: int, pages: list[str], out: Path, timeout: float) -> list[dict]:
    """Every page of ``pages`` at every width of :data:`WIDTHS`, in a browser of its own: each page is loaded once,
    at the first width, and checked and captured at each width in turn (the window resized in between: the
    book's layout at a width is its style sheets', which follow the window as it changes).  A page's load (its
    scripts, MathJax's typesetting, its images) is most of the check's time: one load per page instead of one per
    width halved the check's CPU time."""
    from tornado.websocket import websocket_connect

    profile = tempfile.mkdtemp(prefix="ringchain-chromium-")
    process = subprocess.Popen(
        [chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--remote-debugging-port=0", "about:blank"],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    findings = []
    try:
        active = Path(profile) / "DevToolsActivePort"
        for _ in range(300):
            if active.is_file() and len(active.read_text().split()) >= 2:
                break
            if process.poll() is not None:
                raise RuntimeError(f"Chromium exited with {process.returncode}")
            await asyncio.sleep(0.05)
        debug_port = int(active.read_text().split()[0])
        with urllib.request.urlopen(f"http://127.0.0.1:{debug_port}/json/list") as response:
            targets = json.loads(response.read())
        url = next(t["webSocketDebuggerUrl"] for t in targets if t["type"] == "page")
        tools = _DevTools(await websocket_connect(url, max_message_size=1 << 30))
        await tools.call("Page.enable")
        for page in pages:
            await _window(tools, WIDTHS[0])
            tools.events.clear()
            await tools.call("Page.navigate", url=f"http://127.0.0.1:{port}/{page}.html")
            await asyncio.wait_for(tools.event("Page.loadEventFired"), timeout)
            for width in WIDTHS:
                await _window(tools, width)
                result = await asyncio.wait_for(
                    tools.call("Runtime.evaluate", expression=CHECK_SCRIPT, awaitPromise=True, returnByValue=True),
                    timeout,
                )
                if "exceptionDetails" in result:
                    raise RuntimeError(f"{page}: the check script failed: {result['exceptionDetails']}")
                for kind, where, detail in json.loads(result["result"]["value"]):
                    findings.append({"page": page, "width": width, "kind": kind, "where": where, "detail": detail})
                if page in WINDOW_PAGES:  # what the window shows, for comparison with the top of the full page
                    shot = await tools.call("Page.captureScreenshot", format="png")
                    (out / "windows" / f"{page}-{width}.png").write_bytes(base64.b64decode(shot["data"]))
                (out / f"{page}-{width}.png").write_bytes(await _full_page(tools, width))
        tools.connection.close()
        await asyncio.wait_for(tools.connection.read_message(), 10)  # None once the socket is closed
    finally:
        process.terminate()
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
        shutil.rmtree(profile, ignore_errors=True)
    return findings


async def _window(tools: _DevTools, width: int) -> None:
    """The window ``width`` px wide and :data:`VIEWPORT_HEIGHT` tall, laid out and painted, its transitions ended."""
    await tools.call("Emulation.setDeviceMetricsOverride", width=width, height=VIEWPORT_HEIGHT, deviceScaleFactor=1,
                     mobile=False)  # fmt: skip
    await tools.call("Runtime.evaluate", expression=_SETTLED, awaitPromise=True)


async def _every_page(port: int, pages: list[str], out: Path, timeout: float) -> list[dict]:
    """The pages in two halves side by side, one browser each (the check is the build's last serial step: two
    browsers halve its wall time on two cores); the findings in the order of :data:`WIDTHS`, then of ``pages``."""
    halves = [pages[0::2], pages[1::2]]
    found = await asyncio.gather(*(_inspect(port, half, out, timeout) for half in halves if half))
    order = {page: i for i, page in enumerate(pages)}
    findings = [finding for per_half in found for finding in per_half]
    return sorted(findings, key=lambda f: (WIDTHS.index(f["width"]), order[f["page"]]))


def check(site: Path, out: Path, pages: list[str] | None = None, timeout: float = 120.0) -> list[dict]:
    """Screenshots of ``pages`` (default: every page of the site) at both widths into ``out``, and the findings;
    of the pages of :data:`WINDOW_PAGES` among them, a second capture of the window alone into ``out/windows``."""
    if chromium() is None:
        raise FileNotFoundError("no chromium on PATH (apt-get install chromium)")
    site, out = Path(site).resolve(), Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if pages is None:
        pages = sorted(p.stem for p in site.glob("*.html") if p.stem not in ("search", "genindex", "py-modindex"))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=str(site)))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        (out / "windows").mkdir(exist_ok=True)
        findings = asyncio.run(_every_page(server.server_address[1], pages, out, timeout))
    finally:
        server.shutdown()
        server.server_close()
    (out / "report.json").write_text(json.dumps(findings, indent=1))
    return findings


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", nargs="?", default=str(BOOK / "_build" / "html"))
    parser.add_argument("--out", default=None, help="screenshots and report.json (default: SITE/../screenshots)")
    parser.add_argument("--pages", nargs="*", default=None, help="page names (default: every page)")
    parser.add_argument("--no-fail", action="store_true", help="exit 0 even when something is found")
    args = parser.parse_args(argv)
    site = Path(args.site)
    out = Path(args.out) if args.out else site.parent / "screenshots"
    if chromium() is None:
        print("browser_check.py: chromium not found, no screenshots (apt-get install chromium)", file=sys.stderr)
        return 0 if args.no_fail else 2
    start = time.perf_counter()
    findings = check(site, out, args.pages)
    for f in findings:
        print(f"{f['page']} at {f['width']} px: {f['kind']}: {f['where']} ({f['detail']})")
    shots = len(list(out.glob("*.png")))
    seconds = time.perf_counter() - start
    print(f"browser_check.py: {shots} screenshots in {out}, {len(findings)} findings, {seconds:.0f} s")
    return 0 if (args.no_fail or not findings) else 1


if __name__ == "__main__":
    sys.exit(main())
