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

Usage (from book/build.sh): ``python parallel_build.py build BOOK --builder html --all -W --keep-going``.
"""

import os
import sys

import jupyter_book.sphinx
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

_build = jupyter_book.sphinx.build_sphinx
_jobs = int(os.environ.get("RINGCHAIN_BOOK_JOBS", "2"))
jupyter_book.sphinx.build_sphinx = lambda *args, **options: _build(*args, **{**options, "jobs": _jobs})

if __name__ == "__main__":
    sys.exit(main())
