#!/usr/bin/env bash
# Build the ringchain book into book/_build/html, offline, executing every page.
#
#   bash book/build.sh            (from anywhere; needs `pip install -e ".[book]"` and npm)
#
# - MathJax 3 comes from the npm registry (mathjax@3), is copied to book/_static_mathjax/mathjax
#   (git-ignored, not committed) and served from the site itself: the built pages need no network.
# - Headless Chromium, if installed, then screenshots every page at 1280 px and 390 px into
#   book/_build/screenshots and checks the layout (book/browser_check.py).
# - Every page is executed afresh (--all: a fresh Sphinx environment, so no page is skipped as
#   unchanged); a cell error stops the build and every Sphinx warning, including anything a cell
#   writes to stderr, is fatal (-W).
# Environment: PYTHON (default: the repo's .venv/bin/python if present, else python3).
set -euo pipefail
export RINGCHAIN_NOTICES=0  # the package's notices on stderr (a compile, where a job runs) would fail a page
book="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$book")"
if [[ -z "${PYTHON:-}" ]]; then
    if [[ -x "$root/.venv/bin/python" ]]; then PYTHON="$root/.venv/bin/python"; else PYTHON=python3; fi
fi
if ! "$PYTHON" -c "import jupyter_book, ringchain.theory" 2>/dev/null; then
    echo "book/build.sh: $PYTHON lacks jupyter-book or ringchain; run: pip install -e \".[book]\"" >&2
    exit 2
fi

# --- MathJax 3, served from the site ---------------------------------------------------------
mathjax="$book/_static_mathjax/mathjax"
if [[ ! -f "$mathjax/tex-chtml.js" ]]; then
    tmp="$(mktemp -d)"
    trap 'rm -rf "$tmp"' EXIT
    echo "book/build.sh: installing mathjax@3 from npm"
    npm install --prefix "$tmp" --no-save --no-audit --no-fund --silent mathjax@3
    rm -rf "$mathjax"
    mkdir -p "$(dirname "$mathjax")"
    cp -r "$tmp/node_modules/mathjax/es5" "$mathjax"
fi

# --- build ------------------------------------------------------------------------------------
# Pages plot with the inline backend (a test session's MPLBACKEND=Agg would hide every figure).
export MPLBACKEND="module://matplotlib_inline.backend_inline"
export PYDEVD_DISABLE_FILE_VALIDATION=1   # silences a debugger note ipykernel prints to stderr
start=$SECONDS
# Two pages execute at once (Sphinx's parallel reading; book/parallel_build.py says why it is safe).
"$PYTHON" "$book/parallel_build.py" build "$book" --builder html --all -W --keep-going
echo "book/build.sh: built $book/_build/html/index.html in $((SECONDS - start)) s"

# --- what a browser shows ------------------------------------------------------------------------
# Screenshots of every page at 1280 px and 390 px into _build/screenshots, with the layout checks of
# book/browser_check.py written to _build/screenshots/report.json (tests/book reads them; the build
# itself does not fail on them). Skipped when headless Chromium is not installed.
"$PYTHON" "$book/browser_check.py" "$book/_build/html" --out "$book/_build/screenshots" --no-fail
