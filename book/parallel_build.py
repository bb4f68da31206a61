"""Run Jupyter Book 1.x's ``build`` command with Sphinx reading two pages at once.

A page executes its cells one after the other, so a serial build leaves a core idle for the whole of it (ten
minutes on a two-core machine).  Sphinx reads pages in parallel processes (``-j``) when every extension declares
itself safe for it; the command line of Jupyter Book 1.x takes no ``-j``, and two of the extensions it loads
declare nothing, so Sphinx assumes they are unsafe and reads serially.  Both were read for this:

- ``sphinx_multitoc_numbering`` replaces ``TocTreeCollector.assign_section_numbers``, which Sphinx runs in the
  main process once every page is read and merged: nothing of it runs in the readers.
- ``sphinx_jupyterbook_latex`` adds nodes, doctree transforms and post-transforms for the LaTeX builder, each
  working on one document, with no state shared between documents.

So both are declared safe here, and the build's ``jobs`` is set to ``RINGCHAIN_BOOK_JOBS`` (default 2).

Sphinx splits the pages into chunks of ten in alphabetical order, one process each: in the clean-clone test run
one chunk held the rings chapter (188 s), the linear waves (79 s) and eight more, and ran some 100 s after the
other had ended.  Here each page is a chunk of its own and the longest are read first (:data:`LONGEST_FIRST`,
measured), so the two processes end together; the order of reading changes nothing in the site.

Usage (from book/build.sh): ``python parallel_build.py build BOOK --builder html --all -W --keep-going``.
"""

import os
import sys

import jupyter_book.sphinx
import sphinx.builders
import sphinx_jupyterbook_latex
import sphinx_multitoc_numbering
from jupyter_book.cli.main import main

#: The extensions read above, declared safe for parallel reading and writing.
AUDITED = (sphinx_multitoc_numbering, sphinx_jupyterbook_latex)


def _declared(module):
    setup = module.setup

    def declared_setup(app):
        metadata = setup(app) or {}
        return {**metadata, "parallel_read_safe": True, "parallel_write_safe": True}

    module.setup = declared_setup


for module in AUDITED:
    _declared(module)

#: Pages by the time they took to execute in a clean-clone test run (s): rings_in_space 188, disorder 102,
#: linear_waves 79, fitting 72, contact 55, rings_that_bend 40, sheets 35; the others under 35 s follow in
#: alphabetical order.
LONGEST_FIRST = ("rings_in_space", "disorder", "linear_waves", "fitting", "contact", "rings_that_bend", "sheets")


def _one_page_each(docnames, nproc, maxbatch=10):
    rank = {name: k for k, name in enumerate(LONGEST_FIRST)}
    return [[name] for name in sorted(docnames, key=lambda name: rank.get(name, len(rank)))]


_read_parallel = sphinx.builders.Builder._read_parallel


def _read_longest_first(self, docnames, nproc):
    chunks = sphinx.builders.make_chunks
    sphinx.builders.make_chunks = _one_page_each
    try:
        return _read_parallel(self, docnames, nproc)
    finally:
        sphinx.builders.make_chunks = chunks


sphinx.builders.Builder._read_parallel = _read_longest_first

_build = jupyter_book.sphinx.build_sphinx
_jobs = int(os.environ.get("RINGCHAIN_BOOK_JOBS", "2"))
jupyter_book.sphinx.build_sphinx = lambda *args, **options: _build(*args, **{**options, "jobs": _jobs})

if __name__ == "__main__":
    sys.exit(main())
