#!/usr/bin/env bash
# Screenshots of pages of the built book, taken by headless Chromium from the site served on 127.0.0.1.
#
#   bash book/screenshot.sh OUTDIR [PAGE[:HEIGHT] ...] [--dom]     default pages: contact lattice
#
# Writes OUTDIR/PAGE.png (1280 px wide, HEIGHT px tall, default 6000) and, with --dom, the page's
# DOM after its scripts ran (MathJax included) to OUTDIR/PAGE.dom.html.  Needs the Debian package
# `chromium` (apt-get install chromium) and a built site (bash book/build.sh).  Chromium runs with no
# network access beyond the local server: everything a page shows, MathJax included, comes from the site.
set -euo pipefail
book="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
site="$book/_build/html"
out="${1:?usage: screenshot.sh OUTDIR [PAGE[:HEIGHT] ...]}"
shift
pages=()
dom=0
for arg in "$@"; do
    if [[ "$arg" == --dom ]]; then dom=1; else pages+=("$arg"); fi
done
[[ ${#pages[@]} -gt 0 ]] || pages=(contact lattice)
[[ -f "$site/index.html" ]] || { echo "screenshot.sh: no built site at $site (run book/build.sh)" >&2; exit 2; }
browser="$(command -v chromium || command -v chromium-browser || true)"
[[ -n "$browser" ]] || { echo "screenshot.sh: chromium not found (apt-get install chromium)" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"

port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site" >/dev/null 2>&1 &
server=$!
profile="$(mktemp -d)"
trap 'kill "$server" 2>/dev/null || true; rm -rf "$profile"' EXIT
for _ in $(seq 50); do
    python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null && break
    sleep 0.1
done

for spec in "${pages[@]}"; do
    page="${spec%%:*}"
    height=6000
    [[ "$spec" == *:* ]] && height="${spec##*:}"
    url="http://127.0.0.1:$port/$page.html"
    # virtual-time-budget lets MathJax finish typesetting before the picture is taken.
    chrome=(timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-background-networking
        --disable-component-update --disable-sync --no-first-run --hide-scrollbars
        --user-data-dir="$profile" --window-size="1280,$height" --virtual-time-budget=15000)
    "${chrome[@]}" --screenshot="$out/$page.png" "$url" >/dev/null 2>&1
    [[ -s "$out/$page.png" ]] || { echo "screenshot.sh: no screenshot of $page" >&2; exit 1; }
    echo "$out/$page.png"
    if [[ $dom == 1 ]]; then
        "${chrome[@]}" --dump-dom "$url" >"$out/$page.dom.html" 2>/dev/null
        echo "$out/$page.dom.html"
    fi
done
