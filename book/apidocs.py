"""Docstrings as reStructuredText for the API page (a local Sphinx extension, see _config.yml).

The package's docstrings are written for ``help()``: they use ``|x|`` for an absolute value, which
reStructuredText reads as a substitution.  This hook escapes the bars before Sphinx parses them, so the
API page builds with warnings fatal and the docstrings stay as they read in a terminal.
"""

from __future__ import annotations

import re

_BAR = re.compile(r"(?<![\\`])\|")


def _escape_bars(app, what, name, obj, options, lines):
    for i, line in enumerate(lines):
        if "|" in line and not line.lstrip().startswith(("+-", "+=", "| ")):  # not a table or line block
            lines[i] = _BAR.sub(r"\\|", line)


def setup(app):
    app.connect("autodoc-process-docstring", _escape_bars)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
