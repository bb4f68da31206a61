"""Lazy derivation, code generation and the on-disk cache of generated code.

Every public numeric function of :mod:`ringchain.theory` is a SymPy expression turned
into NumPy code by :func:`sympy.lambdify` (``cse=True``).  Deriving and lambdifying
costs about a second (most of it importing SymPy), so it never happens at import
time.  A :class:`Derived` object runs its derivation on first use, once per
process, and stores the generated source in a cache directory keyed by a hash of
the whole ``theory`` package source and the SymPy version.  A later process finds
the source there and runs it without importing SymPy at all; any change to any
derivation changes the key, so stale code is never used.

Cache location: ``$RINGCHAIN_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/ringchain``,
else ``~/.cache/ringchain``.  Set ``RINGCHAIN_CACHE_DIR`` to an empty string to
disable the disk cache (every process then derives).  An unwritable cache
directory is not an error: the code is then derived in every process.

Entries.  One file per derivation, ``<module>.<name>-<key>.py``: a first line with the
SHA-256 of the rest (and of the derivation's name and key), comment lines saying what
the code was generated from (derivation, key, SymPy and NumPy versions, arguments, a
SHA-256 of the expression's ``srepr``), then the generated function.  An entry that is
missing, unreadable, truncated, edited, or copied from another derivation fails the
checksum (or, written by a broken generator, does not load) and is derived again and
replaced: a damaged cache costs one derivation, never a wrong or failed call.  Entries
are written to a temporary file in the same directory and renamed into place, so a
reader never sees half an entry; the temporary file is removed if anything fails (a
full disk, say).  They are created with the permissions ``open()`` would give a new
file, 0o666 less the umask (0o644 under the usual umask 022, 0o664 under 002 for a
cache shared by a group, 0o600 under 077), and never modified in place.

:func:`cache_info` and :func:`clear_cache` (``ringchain cache info`` and
``ringchain cache clear``) report on and empty the cache.

Shipped entries.  The package carries the entries of its own source in ``theory/_shipped/``
(written by ``python -m ringchain.theory._codegen``, one per derivation, named
``<derivation>-<key of the theory sources alone>.py``, the same checksummed format).  Where the disk cache
has no valid entry, a shipped one is read if its checksum holds under this installation's full key (the
theory sources and the SymPy and NumPy versions): a fresh checkout then derives nothing that its own
version has already derived (the derivations take some 13 s of a cold ``ringchain paper``).  A shipped
entry written from other sources or versions fails the checksum and the derivation runs, as for a damaged
cache entry.  They are a cache, not a transcription: ``tests/theory/test_shipped.py`` derives every one
again and compares the generated source.  With the disk cache disabled nothing is read from them either.
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import importlib.metadata
import inspect
import os
import re
import secrets
import threading
import types
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "Derived",
    "derived",
    "cache_dir",
    "source_key",
    "sp",
    "CacheInfo",
    "cache_info",
    "clear_cache",
    "theory_key",
    "shipped_path",
    "ship",
]

_PACKAGE_DIR = Path(__file__).resolve().parent

#: Entries shipped with the package (module notes).
SHIPPED_DIR = _PACKAGE_DIR / "_shipped"

#: Every derivation made by :func:`derived` or :class:`Derived`, by name (the shipped entries are theirs).
REGISTRY: dict[str, Derived] = {}
_FUNC_NAME = "_lambdifygenerated"

#: First bytes of a cache entry; the SHA-256 checksum of the entry follows on the same line.
_MAGIC = b"# ringchain generated code v1 sha256="

#: Names of cache entries (``elliptical._stiffness_elliptical-<20 hex digits>.py``) and of the
#: temporary files they are written through: the only files :func:`clear_cache` removes.
_ENTRY_NAME = re.compile(r"[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*-[0-9a-f]{20}\.py")
_TEMP_NAME = re.compile(r"\.tmp-[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*-[0-9a-f]{20}-\d+-[0-9a-f]{8}\.py")


class _LazySympy(types.ModuleType):
    """``sympy``, imported on first attribute access (keeps ``import ringchain.theory`` light)."""

    def __getattr__(self, name):
        module = importlib.import_module("sympy")
        return getattr(module, name)


#: SymPy, imported lazily.  Derivation modules use ``sp.<name>`` only inside functions.
sp = _LazySympy("sympy")


@functools.cache
def _versions() -> tuple[tuple[str, str], ...]:
    """(distribution, version) of the libraries that generated code depends on."""
    versions = []
    for dist in ("sympy", "numpy"):
        try:
            versions.append((dist, importlib.metadata.version(dist)))
        except importlib.metadata.PackageNotFoundError:  # pragma: no cover - vendored installs
            versions.append((dist, "unknown"))
    return tuple(versions)


def _sources_digest():
    digest = hashlib.sha256()
    for path in sorted(_PACKAGE_DIR.glob("*.py")):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest


@functools.cache
def theory_key() -> str:
    """Hash of every ``.py`` file of the theory package (the names of the shipped entries)."""
    return _sources_digest().hexdigest()[:20]


@functools.cache
def source_key() -> str:
    """Hash of every ``.py`` file of the theory package plus the SymPy/NumPy versions."""
    digest = _sources_digest()
    for _, version in _versions():
        digest.update(version.encode())
    return digest.hexdigest()[:20]


def cache_dir() -> Path | None:
    """The directory of generated code, or ``None`` when the disk cache is disabled."""
    return _cache_location()[0]


def _cache_location() -> tuple[Path | None, str]:
    """The cache directory (None: disabled) and where that choice comes from."""
    env = os.environ.get("RINGCHAIN_CACHE_DIR")
    if env is not None:
        return (Path(env) if env else None), "RINGCHAIN_CACHE_DIR"
    xdg = os.environ.get("XDG_CACHE_HOME")
    if xdg:
        return Path(xdg) / "ringchain", "XDG_CACHE_HOME"
    return Path(os.path.expanduser("~")) / ".cache" / "ringchain", "default"


def _namespace(source: str) -> dict:
    """Import exactly the modules that generated ``source`` refers to."""
    namespace: dict = {}
    for module in sorted(set(re.findall(r"\b(numpy|scipy\.special)\.", source))):
        top = module.split(".")[0]
        importlib.import_module(module)
        namespace[top] = importlib.import_module(top)
    return namespace


def _compile(source: str, name: str) -> Callable:
    code = compile(source, f"<ringchain generated: {name}>", "exec")
    namespace = _namespace(source)
    exec(code, namespace)
    return namespace[_FUNC_NAME]


def generate_source(args, expr) -> str:
    """NumPy source of ``expr`` as a function of ``args``, made by :func:`sympy.lambdify`.

    The printer writes fully qualified names (``numpy.sqrt``), so the source runs in a
    namespace holding only the modules it names.  Arguments whose names are not Python names
    (``\\ell``) become SymPy dummies, numbered by a counter of the process; they are renumbered in
    order of appearance, so that one derivation always generates the same source.
    """
    from sympy.printing.numpy import NumPyPrinter

    printer = NumPyPrinter({"fully_qualified_modules": True, "allow_unknown_functions": False})
    func = sp.lambdify(args, expr, modules="numpy", printer=printer, cse=True, docstring_limit=0)
    source = inspect.getsource(func)
    dummies = dict.fromkeys(re.findall(r"\b_Dummy_\d+\b", source))
    for number, dummy in enumerate(dummies):
        source = re.sub(rf"\b{dummy}\b", f"_dummy_{number}", source)
    return source


class Derived:
    """A derivation ``build() -> (args, expr)`` and the numeric function made from it.

    ``derived.expression()`` returns ``(args, expr)`` (SymPy objects, derived once per
    process); calling the object evaluates the generated NumPy code.
    """

    def __init__(self, build: Callable, name: str | None = None):
        self.build = build
        self.name = name or f"{build.__module__.rsplit('.', 1)[-1]}.{build.__name__}"
        self.__doc__ = build.__doc__
        self._func: Callable | None = None
        self._lock = threading.Lock()
        if name is None:  # the package's own derivations (named ones are probes and tests)
            REGISTRY.setdefault(self.name, self)

    def __repr__(self) -> str:
        return f"<Derived {self.name}>"

    @functools.cached_property
    def _expression(self):
        args, expr = self.build()
        return tuple(args), expr

    def expression(self):
        """The derived ``(args, expr)``: SymPy symbols and expression."""
        return self._expression

    @property
    def cache_path(self) -> Path | None:
        directory = cache_dir()
        if directory is None:
            return None
        return directory / f"{self.name}-{source_key()}.py"

    def source(self) -> str:
        """Generated source: from the disk cache if a valid entry is there, else derived and stored."""
        path = self.cache_path
        text = None if path is None else _read_entry(path, self.name)
        return self._derive_and_store(path) if text is None else text

    def _derive_and_store(self, path: Path | None) -> str:
        args, expr = self.expression()
        text = generate_source(args, expr)
        if path is not None:
            _write_atomic(path, _entry(self.name, args, expr, text))
        return text

    def _load(self) -> Callable:
        path = self.cache_path
        text = None if path is None else _read_entry(path, self.name)
        if text is None and path is not None and REGISTRY.get(self.name) is self:
            text = _read_entry(shipped_path(self.name), self.name)
        if text is not None:
            try:
                return _compile(text, self.name)
            except Exception:  # an entry that passes its checksum yet does not load (a broken generator): rebuild
                pass
        return _compile(self._derive_and_store(path), self.name)

    @property
    def func(self) -> Callable:
        """The generated NumPy function (built on first use)."""
        if self._func is None:
            with self._lock:
                if self._func is None:
                    self._func = self._load()
        return self._func

    def __call__(self, *args):
        return self.func(*args)


def shipped_path(name: str) -> Path:
    """Where the package ships the entry of derivation ``name`` for its current theory sources."""
    return SHIPPED_DIR / f"{name}-{theory_key()}.py"


def ship() -> list[Path]:
    """Derive every derivation of the package and write its entry to :data:`SHIPPED_DIR`, removing the
    entries of other sources; returns the paths written.  Run after changing ``theory/``:
    ``python -m ringchain.theory._codegen``."""
    import ringchain.theory  # noqa: F401  (every derivation module, so that REGISTRY is complete)

    written = []
    for name in sorted(REGISTRY):
        args, expr = REGISTRY[name].expression()
        path = shipped_path(name)
        _write_atomic(path, _entry(name, args, expr, generate_source(args, expr)))
        written.append(path)
    for path, _ in _cache_files(SHIPPED_DIR):
        if path not in written:
            path.unlink()
    return written


def derived(build: Callable) -> Derived:
    """Decorator: turn a derivation ``build() -> (args, expr)`` into a :class:`Derived`."""
    return Derived(build)


# -- cache entries -----------------------------------------------------------------------------------
def _checksum(name: str, body: bytes) -> bytes:
    """SHA-256 (hex) of an entry's body, bound to the derivation's name and the source key."""
    return hashlib.sha256(f"{name}\n{source_key()}\n".encode() + body).hexdigest().encode()


def _entry(name: str, args, expr, text: str) -> bytes:
    """A cache entry: checksum line, what the code was generated from, the generated source."""
    versions = ", ".join(f"{dist} {version}" for dist, version in _versions())
    expression = hashlib.sha256(sp.srepr(expr).encode()).hexdigest()
    body = (
        f"# derivation: {name}\n"
        f"# source key: {source_key()} (theory/*.py, {versions})\n"
        f"# arguments: {', '.join(str(a) for a in args)}\n"
        f"# expression sha256: {expression} (of its srepr)\n"
        f"{text}"
    ).encode()
    return _MAGIC + _checksum(name, body) + b"\n" + body


def _read_entry(path: Path, name: str) -> str | None:
    """The generated source stored at ``path``, or None if it is missing, unreadable or fails its checksum."""
    try:
        data = path.read_bytes()
    except OSError:  # missing, unreadable, a directory...
        return None
    head, newline, body = data.partition(b"\n")
    if not newline or head != _MAGIC + _checksum(name, body):
        return None
    try:
        return body.decode()
    except UnicodeDecodeError:  # pragma: no cover - a checksummed entry is the UTF-8 that was written
        return None


def _write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file renamed into place; never raises OSError.

    The temporary file is created by ``os.open(..., 0o666)``, so the kernel applies the
    umask (and any default ACL) as for any new file, and it is removed if anything fails.
    """
    tmp = path.with_name(f".tmp-{path.stem}-{os.getpid()}-{secrets.token_hex(4)}.py")
    fd = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view) :]
        os.close(fd)
        fd = None
        os.replace(tmp, path)
    except BaseException as exc:
        if fd is not None:
            os.close(fd)
        try:
            tmp.unlink()
        except OSError:
            pass
        if not isinstance(exc, OSError):
            raise
        # A read-only or full cache directory only costs speed; the code is still correct.


# -- cache maintenance -------------------------------------------------------------------------------
@dataclass(frozen=True)
class CacheInfo:
    """What :func:`cache_info` reports about the disk cache of generated code.

    Attributes
    ----------
    path : Path or None
        The cache directory; None when the cache is disabled (``RINGCHAIN_CACHE_DIR=""``).
    origin : str
        Where the location comes from: ``"RINGCHAIN_CACHE_DIR"``, ``"XDG_CACHE_HOME"`` or ``"default"``.
    key : str
        The key of the current source (:func:`source_key`); entries under other keys are stale.
    exists, writable : bool
        Whether the directory exists, and whether this process can create entries in it
        (for a missing directory: whether it can be created).
    current, stale, temporary : int
        Entries under the current key, entries under other keys (left by other versions of
        the code), and temporary files left by interrupted writes.
    size : int
        Bytes in all of them.
    """

    path: Path | None
    origin: str
    key: str
    exists: bool = False
    writable: bool = False
    current: int = 0
    stale: int = 0
    temporary: int = 0
    size: int = 0


def _cache_files(directory: Path):
    """(path, kind) of the cache's own files in ``directory``: kind "entry" or "temporary".

    An entry is named as the cache names entries and starts with the cache's first bytes; a
    temporary file is named as :func:`_write_atomic` names them.  Other files, even named
    ``something-<key>.py``, are not the cache's: they are neither counted nor removed.
    """
    try:
        children = list(directory.iterdir())
    except OSError:
        return
    for path in sorted(children):
        if not path.is_file():
            continue
        if _ENTRY_NAME.fullmatch(path.name):
            try:
                with open(path, "rb") as handle:
                    head = handle.read(len(_MAGIC))
            except OSError:  # pragma: no cover - removed or unreadable meanwhile
                continue
            if head == _MAGIC:
                yield path, "entry"
        elif _TEMP_NAME.fullmatch(path.name):
            yield path, "temporary"


def _writable(directory: Path) -> bool:
    """Whether this process may create files in ``directory`` (or create it)."""
    probe = directory
    while not probe.exists():
        if probe.parent == probe:
            return False
        probe = probe.parent
    return probe.is_dir() and os.access(probe, os.W_OK | os.X_OK)


def cache_info() -> CacheInfo:
    """Location, key, writability and contents of the disk cache of generated code."""
    directory, origin = _cache_location()
    key = source_key()
    if directory is None:
        return CacheInfo(None, origin, key)
    counts = {"current": 0, "stale": 0, "temporary": 0}
    size = 0
    for path, kind in _cache_files(directory):
        if kind == "entry":
            kind = "current" if path.stem.endswith(f"-{key}") else "stale"
        counts[kind] += 1
        try:
            size += path.stat().st_size
        except OSError:  # pragma: no cover - removed meanwhile
            pass
    return CacheInfo(directory, origin, key, directory.is_dir(), _writable(directory), size=size, **counts)


def clear_cache() -> tuple[int, int]:
    """Remove every entry and leftover temporary file of the cache; returns (files removed, bytes).

    Only files named as the cache names them are removed, so a cache directory that also
    holds other files (``RINGCHAIN_CACHE_DIR`` pointed at a shared folder) keeps them; the
    directory itself stays.  Raises ``OSError`` if a file cannot be removed.
    """
    directory = cache_dir()
    removed = size = 0
    if directory is None:
        return removed, size
    for path, _ in _cache_files(directory):
        try:
            nbytes = path.stat().st_size
            path.unlink()
        except FileNotFoundError:  # removed meanwhile (another process clearing or replacing it)
            continue
        removed += 1
        size += nbytes
    return removed, size


if __name__ == "__main__":  # python -m ringchain.theory._codegen: refresh the shipped entries
    from ringchain.theory import _codegen as _package_module  # the package's module, not this __main__ copy

    for written in _package_module.ship():
        print(written.relative_to(_PACKAGE_DIR.parent))
