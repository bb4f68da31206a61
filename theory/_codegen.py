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
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import importlib.metadata
import inspect
import os
import re
import tempfile
import threading
import types
from collections.abc import Callable
from pathlib import Path

__all__ = ["Derived", "derived", "cache_dir", "source_key", "sp"]

_PACKAGE_DIR = Path(__file__).resolve().parent
_FUNC_NAME = "_lambdifygenerated"


class _LazySympy(types.ModuleType):
    """``sympy``, imported on first attribute access (keeps ``import ringchain.theory`` light)."""

    def __getattr__(self, name):
        module = importlib.import_module("sympy")
        return getattr(module, name)


#: SymPy, imported lazily.  Derivation modules use ``sp.<name>`` only inside functions.
sp = _LazySympy("sympy")


@functools.cache
def source_key() -> str:
    """Hash of every ``.py`` file of the theory package plus the SymPy/NumPy versions."""
    digest = hashlib.sha256()
    for path in sorted(_PACKAGE_DIR.glob("*.py")):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    for dist in ("sympy", "numpy"):
        try:
            digest.update(importlib.metadata.version(dist).encode())
        except importlib.metadata.PackageNotFoundError:  # pragma: no cover - vendored installs
            digest.update(b"unknown")
    return digest.hexdigest()[:20]


def cache_dir() -> Path | None:
    """The directory of generated code, or ``None`` when the disk cache is disabled."""
    env = os.environ.get("RINGCHAIN_CACHE_DIR")
    if env is not None:
        return Path(env) if env else None
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "ringchain"


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
    namespace holding only the modules it names.
    """
    from sympy.printing.numpy import NumPyPrinter

    printer = NumPyPrinter({"fully_qualified_modules": True, "allow_unknown_functions": False})
    func = sp.lambdify(args, expr, modules="numpy", printer=printer, cse=True, docstring_limit=0)
    return inspect.getsource(func)


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
        """Generated source: from the disk cache if present, else derived and stored."""
        path = self.cache_path
        if path is not None and path.is_file():
            return path.read_text()
        text = generate_source(*self.expression())
        if path is not None:
            _write_atomic(path, text)
        return text

    @property
    def func(self) -> Callable:
        """The generated NumPy function (built on first use)."""
        if self._func is None:
            with self._lock:
                if self._func is None:
                    self._func = _compile(self.source(), self.name)
        return self._func

    def __call__(self, *args):
        return self.func(*args)


def derived(build: Callable) -> Derived:
    """Decorator: turn a derivation ``build() -> (args, expr)`` into a :class:`Derived`."""
    return Derived(build)


def _write_atomic(path: Path, text: str) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-", suffix=".py")
        with os.fdopen(fd, "w") as handle:
            handle.write(text)
        os.replace(tmp, path)
    except OSError:
        # A read-only or full cache directory only costs speed; the code is still correct.
        pass
