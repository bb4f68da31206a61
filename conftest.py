"""Test session setup shared by tests/ and the doctests of the package.

The generated-code cache (and Numba's compiled kernels) is pointed at a fresh directory, so every test
session compiles the kernels and reads the generated code from the current source instead of trusting a cache
from earlier: a derivation's code comes from the package's shipped entries (theory/_shipped), which
tests/theory/test_shipped.py derives again and compares byte for byte, or is derived afresh.
"""

import os
import tempfile

import pytest

# One fresh directory per session: made by the pytest process, inherited by its xdist workers (they share
# the compiled kernels), never by a later session.
if "PYTEST_XDIST_WORKER" not in os.environ:
    os.environ["RINGCHAIN_CACHE_DIR"] = tempfile.mkdtemp(prefix="ringchain-test-cache-")
os.environ.setdefault("MPLBACKEND", "Agg")


# Property tests are derandomized (STYLE.md: seeded randomness only): every run, here and in CI,
# draws the same examples, so a failure reproduces and a green run stays green.  Tests that set
# their own hypothesis settings inherit this profile for what they leave out.
from hypothesis import settings

settings.register_profile("ringchain", derandomize=True, database=None)
settings.load_profile("ringchain")


def _alias_package_folders() -> None:
    """Let the doctests of theory/ and numerics/ run on the package's own modules.

    pytest (--import-mode=importlib) imports a folder's files under the folder's name (``numerics.kernels``),
    a second copy of the package beside ``ringchain.numerics``: Numba then caches kernels whose types pickle
    as ``numerics.kernels.Packed``, which any other process (the book's pages, the other test worker) cannot
    unpickle, and it fails instead of compiling (ModuleNotFoundError: numerics).  pytest returns a module
    already in sys.modules under that name: the package's.
    """
    import importlib
    import pkgutil
    import sys

    for package, folder in (("ringchain.theory", "theory"), ("ringchain.numerics", "numerics")):
        module = importlib.import_module(package)
        sys.modules.setdefault(folder, module)
        for info in pkgutil.walk_packages(module.__path__, prefix=f"{package}."):
            if info.name.rsplit(".", 1)[-1] == "__main__":
                continue  # running it would run the command
            name = folder + info.name[len(package) :]
            sys.modules.setdefault(name, importlib.import_module(info.name))


_alias_package_folders()


@pytest.fixture(autouse=True)
def notices(monkeypatch):
    """The package's notices (a kernel's compile, where a job runs: engine/_kernel_calls.notify) go to this list,
    not to stderr: whether a test compiles a kernel depends on which tests its worker ran before, and tests read
    stderr for their own output.  The compile notice on stderr is tested in a fresh process
    (tests/numerics/engine/test_kernels.py)."""
    from ringchain.numerics.engine import _kernel_calls

    notices: list[str] = []
    monkeypatch.setattr(_kernel_calls, "notify", notices.append)
    return notices


#: The background build of the book (tests/book/building.py) and its process, kept for pytest_unconfigure.
_BOOK_BUILD = pytest.StashKey[tuple]()


def pytest_configure(config):
    """Start the book's build in the background when this session will test the book (tests/book/building.py):
    the longest job of the suite then runs beside the other tests instead of after them.  Only in the
    process that runs the session (not in its xdist workers, which inherit the build's folder)."""
    import importlib.util
    from pathlib import Path

    if "PYTEST_XDIST_WORKER" in os.environ or config.option.collectonly:
        return
    here = Path(__file__).resolve().parent
    book_tests = here / "tests" / "book" / "test_book.py"
    chosen = [(config.invocation_params.dir / arg.split("::")[0]).resolve() for arg in config.args]
    if not any(path == book_tests or path in book_tests.parents for path in chosen):
        return
    spec = importlib.util.spec_from_file_location("book_building", book_tests.with_name("building.py"))
    building = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(building)
    if importlib.util.find_spec("jupyter_book") is not None and building.stale():
        config.stash[_BOOK_BUILD] = (building, building.start())


def pytest_unconfigure(config):
    if _BOOK_BUILD in config.stash:
        building, process = config.stash[_BOOK_BUILD]
        building.stop(process)


def pytest_xdist_make_scheduler(config, log):
    """xdist's files-as-units scheduling (``--dist loadfile``), but with every file of tests/theory in one unit.

    The theory's tests derive in SymPy, and each derivation is cached in its process (``functools.cache``,
    :class:`ringchain.theory._codegen.Derived`): run by one worker, a derivation that several files need -- the
    comparison of every shipped entry with its derivation (tests/theory/test_shipped.py) and the symbolic tests of
    the same module -- is made once instead of once per worker (measured on attenuation: its tests 40.2 s of CPU,
    its two shipped entries 26.3 s, both in one process 39.8 s).  The unit holds the most tests, so xdist hands it
    out first, and that worker takes more files only once it is nearly done.
    """
    if config.getoption("dist") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class TheoryInOneUnit(LoadFileScheduling):
        def _split_scope(self, nodeid):
            scope = super()._split_scope(nodeid)
            return "tests/theory" if scope.startswith("tests/theory/") else scope

    return TheoryInOneUnit(config, log)
