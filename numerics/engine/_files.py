"""Files written whole or not at all: every output of the package goes through :func:`replacing`.

A writer that is interrupted (Ctrl-C, a full disk, an exception inside it) must not leave a truncated
file in place of the previous good one.  :func:`replacing` hands the writer a temporary name in the same
folder (so the final rename stays on one file system), flushes the finished file to the disk and renames
it over the target with :func:`os.replace`, which is atomic on POSIX and Windows: a reader sees the old
file or the new one, never a part.  On any failure, ``KeyboardInterrupt`` included, the temporary file is
removed and the exception goes on.  The temporary name keeps the target's extension last, so writers that
choose the format from the name (Matplotlib, xarray) write the format asked for.

The engine's floor owns this helper so that every floor above it (results, traces, sheets, jobs, the
command line) can write through it; ``ringchain.theory`` writes its cache of generated code the same way
(``theory/_codegen.py``), on its own floor, where a failure is silent because the cache only saves time.
"""

from __future__ import annotations

import contextlib
import os
import secrets
from pathlib import Path

__all__ = ["replacing", "write_text", "save_figure", "TEMPORARY_MARK"]

#: Part of every temporary name (``.run.nc.tmp-<pid>-<hex>.nc``): files left by a killed process can be found.
TEMPORARY_MARK = ".tmp-"


def _fsync(path, directory=False) -> None:
    """Flush ``path`` (a file, or a folder's entries) to the disk; a folder that cannot be opened is skipped."""
    flags = os.O_RDONLY | (getattr(os, "O_DIRECTORY", 0) if directory else 0)
    try:
        fd = os.open(path, flags)
    except OSError:
        if directory:  # Windows cannot open a folder; the rename is still atomic there
            return
        raise
    try:
        os.fsync(fd)
    except OSError:
        if not directory:
            raise
    finally:
        os.close(fd)


@contextlib.contextmanager
def replacing(path):
    """Context manager: a temporary path to write, renamed to ``path`` when the block ends without error.

    Parameters
    ----------
    path : str or path
        The file to write (it may exist: it is replaced only by a complete file).

    Yields
    ------
    pathlib.Path
        A new name in the same folder, with the same extension, that does not exist yet.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     target = Path(folder) / "a.txt"
    ...     with replacing(target) as tmp:
    ...         _ = tmp.write_text("whole")
    ...     target.read_text(), sorted(p.name for p in Path(folder).iterdir())
    ('whole', ['a.txt'])
    """
    path = Path(path)
    tmp = path.with_name(f".{path.name}{TEMPORARY_MARK}{os.getpid()}-{secrets.token_hex(4)}{path.suffix}")
    try:
        yield tmp
        if not tmp.exists():
            raise FileNotFoundError(f"the writer of {path} wrote nothing")
        _fsync(tmp)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    _fsync(path.parent if str(path.parent) else Path("."), directory=True)


def write_text(path, text: str) -> None:
    """Write ``text`` to ``path`` whole or not at all (UTF-8, newlines as given)."""
    with replacing(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as handle:
        handle.write(text)


def save_figure(fig, path, **options) -> None:
    """``fig.savefig(path, **options)``, whole or not at all (the format from ``path``'s extension)."""
    with replacing(path) as tmp:
        fig.savefig(tmp, **options)
