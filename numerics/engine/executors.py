"""Where the tasks of a sweep run: in this process, in local worker processes, or on a Dask cluster.

- :class:`InlineExecutor` runs every task at once in the calling process;
- :func:`default_executor` is the pool :func:`~ringchain.numerics.jobs.sweep.sweep` uses when
  it is given no executor: local processes started with the "spawn" method;
- :func:`dask_client` connects to a Dask scheduler after checking, with a short timeout,
  that one answers at the address (``ringchain sweep --dask ADDRESS``);
- :func:`run_tasks` submits the tasks of a job (a sweep, an ensemble) to any executor and
  gives their results back in task order, with a progress bar.

Worker processes and ``if __name__ == "__main__":``.  A "spawn" worker is a fresh
interpreter: it imports the module that started the pool, and for a script run as
``python script.py`` that is the script itself.  A script that calls ``sweep()`` at its
top level, without the guard, would start a new sweep in every worker, and Python then
kills the workers (``BrokenProcessPool``).  "spawn" is kept because it behaves the same
on Linux, macOS and Windows and is safe with threads ("fork" copies the parent's threads'
locks in whatever state they are, and is not available on Windows); instead
:func:`default_executor` reads the script before it starts any process and, when the call
is not under the guard, raises a ``RuntimeError`` that says where the call is and how to
fix it.  Code run with ``python -c``, in a notebook or in an interactive session, and
modules run as ``python -m package``, need no guard: spawn does not re-import them.
"""

from __future__ import annotations

import ast
import concurrent.futures as cf
import math
import multiprocessing
import numbers
import os
import socket
import sys
from pathlib import Path

from . import _kernel_calls
from ._kernel_calls import load_factor

__all__ = [
    "InlineExecutor",
    "default_executor",
    "check_main_guard",
    "run_tasks",
    "dask_client",
    "check_dask_scheduler",
    "DASK_TIMEOUT",
    "DASK_PORT",
    "POOL_START_SECONDS",
]

#: Seconds a pool of local worker processes costs on a quiet machine before its first task ends: each "spawn"
#: worker imports NumPy, SciPy, Numba and ringchain and loads the compiled kernels, about what a warm
#: ``ringchain simulate`` takes in a fresh process (1.3-1.7 s on a quiet two-core machine), plus starting the
#: processes.  benchmarks/bench_pool_start.py measures it (53.7 s for two workers with the load average at 17.6
#: on two cores); :func:`run_tasks` scales it by the load per core (``_kernel_calls.load_factor``) and, given no
#: executor, runs the job in the calling process when a pool would save less.
POOL_START_SECONDS = 2.5

#: Seconds :func:`dask_client` waits for a Dask scheduler to accept the connection and greet.
DASK_TIMEOUT = 5.0

#: Port of a Dask scheduler when the address gives none (Dask's default; 8787 is its dashboard).
DASK_PORT = 8786


class InlineExecutor(cf.Executor):
    """An Executor that runs each task at once, in the calling process (no pool, plain tracebacks)."""

    def submit(self, fn, /, *args, **kwargs):
        future = cf.Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except Exception as exc:  # handed to the caller through the future, as any Executor does
            future.set_exception(exc)
        return future


def default_executor(n_tasks: int, max_workers: int | None, what: str = "sweep()") -> cf.Executor:
    """The executor of a sweep given none: ``max_workers`` local "spawn" processes, or inline for 0.

    Parameters
    ----------
    n_tasks : int
        Tasks to run (no more processes than tasks are started).
    max_workers : int or None
        Worker processes; None: the number of CPUs; 0: :class:`InlineExecutor`.
    what : str, optional
        The call that starts the workers, as the guard's message names it.

    Raises
    ------
    ValueError
        If ``max_workers`` is not None or an integer >= 0.
    RuntimeError
        If the script that calls the sweep would be re-run by every worker (no
        ``if __name__ == "__main__":`` guard, see :func:`check_main_guard`).
    """
    if max_workers is not None and (
        isinstance(max_workers, bool) or not isinstance(max_workers, numbers.Integral) or max_workers < 0
    ):
        raise ValueError(f"max_workers must be None (all CPUs), 0 (this process) or a positive integer, "
                         f"got {max_workers!r}")  # fmt: skip
    if max_workers == 0:
        return InlineExecutor()
    check_main_guard(what)
    cpus = os.cpu_count() or 1
    workers = max(1, min(int(max_workers) if max_workers else cpus, n_tasks))
    # "spawn": a fresh interpreter per worker, the same on every platform and safe with threads.  Each
    # worker's compiled kernels get their share of the cores: Numba would start one thread per core in
    # every worker, workers x cores threads on the machine.
    return cf.ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn"),
                                  initializer=_share_threads, initargs=(max(1, cpus // workers),))  # fmt: skip


def _share_threads(threads: int) -> None:
    """Worker initializer: Numba's thread count in this process (read when Numba is first imported here)."""
    os.environ.setdefault("NUMBA_NUM_THREADS", str(threads))  # a count the user set is kept


def check_main_guard(what: str = "this call") -> None:
    """Raise ``RuntimeError`` if starting "spawn" workers now would re-run the calling script.

    A "spawn" worker re-imports the main module when it is a script (``python script.py``)
    or a module run by name (``python -m module``).  If the call that starts the workers
    sits in that module's top-level code outside ``if __name__ == "__main__":``, every
    worker would run it again.  The script is read with :mod:`ast` to find the statement
    being executed; if it cannot be read (no source, say), nothing is raised.
    """
    main = sys.modules.get("__main__")
    if main is None or not _spawn_reimports(main):
        return
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_code.co_name == "<module>" and frame.f_globals is vars(main)):
        frame = frame.f_back
    if frame is None:  # not called from the main module's top-level code (a thread, an atexit hook...)
        return
    path = getattr(main, "__file__", None)
    try:
        tree = ast.parse(Path(path).read_text(), str(path))
    except (OSError, SyntaxError, TypeError, ValueError):
        return
    line = frame.f_lineno
    if _guarded(tree.body, line):
        return
    raise RuntimeError(
        f"{what} starts worker processes with the 'spawn' method, which imports {Path(path).name} again in "
        f'each worker; line {line} runs at its top level, outside `if __name__ == "__main__":`, so every '
        "worker would start the same work again. Put the code that runs the sweep under "
        "`if __name__ == \"__main__\":` (see the README, 'Sweeps'), or run it in this process with max_workers=0."
    )


def _spawn_reimports(main) -> bool:
    """Whether a "spawn" child imports ``main`` again (as multiprocessing.spawn.get_preparation_data decides)."""
    name = getattr(getattr(main, "__spec__", None), "name", None)
    if name is not None:
        return not (name == "__main__" or name.endswith(".__main__"))
    return getattr(main, "__file__", None) is not None


def _guarded(body, line: int) -> bool:
    """Whether ``line`` lies, within the statements ``body``, under an ``if`` that tests ``__name__``."""
    for node in body:
        if not node.lineno <= line <= (node.end_lineno or node.lineno):
            continue
        if isinstance(node, ast.If) and any(isinstance(n, ast.Name) and n.id == "__name__"
                                            for n in ast.walk(node.test)):  # fmt: skip
            return True
        children = [getattr(node, field, None) for field in ("body", "orelse", "finalbody", "handlers", "cases")]
        return any(isinstance(child, list) and _guarded(child, line) for child in children)
    return False


def run_tasks(
    function,
    tasks,
    executor: cf.Executor | None = None,
    *,
    options=None,
    max_workers: int | None = None,
    progress: bool = False,
    sizes=None,
    name: str = "sweep",
    unit: str = "task",
    seconds: float | None = None,
    serial: float | None = None,
) -> list:
    """``function(*task, **options)`` for each task, run through ``executor``; the results in task order.

    Parameters
    ----------
    function : callable
        A module-level function (worker processes and Dask pickle it by name).
    tasks : sequence of tuple
        The positional arguments of each call.
    executor : concurrent.futures.Executor, optional
        Where the calls run (any Executor: a Dask ``Client(...).get_executor()``, say); default
        :func:`default_executor` with ``max_workers``, shut down at the end.
    options : dict, optional
        Keyword arguments of every call.
    max_workers : int, optional
        Processes of the default executor (None: the CPUs; 0: this process).
    progress : bool, optional
        Show a tqdm progress bar on stderr, advanced by ``sizes[k]`` when task k ends.
    sizes : sequence of int, optional
        What each task counts for on the bar (default 1 each).
    name, unit : str, optional
        The job's name (the bar's label, messages) and the bar's unit.
    seconds : float, optional
        The job's work in this process, s (an estimate).  Given no executor and no ``max_workers``, the job
        runs in the calling process when a pool of the CPUs would save less than :data:`POOL_START_SECONDS`
        (scaled by the load); one line on stderr says which.
    serial : float, optional
        The part of ``seconds`` that runs on one core (Python: making the tasks' models, reading their results),
        s: all a pool can save, spread over its workers.  The rest, the compiled kernels', already uses every core
        from one process (a batch's runs on a pool of threads), and a pool's workers only share the cores out
        again.  Default: all of ``seconds``.

    Returns
    -------
    list
        The result of each task, in the order of ``tasks`` whatever order they finish in.

    Raises
    ------
    RuntimeError
        If a worker died (a :class:`concurrent.futures.BrokenExecutor`), saying how to see why; an
        exception raised by a task is raised here as it was.
    """
    from tqdm import tqdm

    tasks = list(tasks)
    sizes = [1] * len(tasks) if sizes is None else list(sizes)
    own = executor is None
    if own and max_workers is None and seconds is not None and len(tasks) > 0:
        workers = max(1, min(os.cpu_count() or 1, len(tasks)))
        single = seconds if serial is None else min(float(serial), seconds)
        saved, cost = single * (1.0 - 1.0 / workers), POOL_START_SECONDS * load_factor()
        max_workers = 0 if saved < cost else workers
        where = "in this process" if max_workers == 0 else f"on {workers} worker processes"
        share = "" if serial is None else f", {single:.1f} s of it on one core"
        _kernel_calls.notify(
            f"{name}: {sum(sizes)} {unit}s {where} (about {seconds:.1f} s of work{share}; a pool of "
            f"{workers} would save about {saved:.1f} s and costs about {cost:.1f} s to start)"
        )
    if own:
        executor = default_executor(len(tasks), max_workers, f"{name}()")
    results: list = [None] * len(tasks)
    try:
        futures = {executor.submit(function, *task, **(options or {})): k for k, task in enumerate(tasks)}
        with tqdm(total=sum(sizes), disable=not progress, unit=unit, desc=name) as bar:
            for future in cf.as_completed(futures):
                k = futures[future]
                results[k] = future.result()
                bar.update(sizes[k])
    except cf.BrokenExecutor as exc:
        raise RuntimeError(
            f"a worker of the {name} died ({exc}); a process may have run out of memory. "
            "Run with max_workers=0 to see the error in this process."
        ) from exc
    finally:
        if own:
            executor.shutdown(cancel_futures=True)
    return results


# -- Dask -------------------------------------------------------------------------------------------
def dask_client(address: str, timeout: float = DASK_TIMEOUT):
    """A ``distributed.Client`` of the Dask scheduler at ``address``, checked to answer first.

    Parameters
    ----------
    address : str
        ``tcp://host:port``, ``host:port`` or ``host`` (port 8786); other schemes (``tls://``...)
        are passed to Dask unchecked.
    timeout : float, optional
        Seconds to wait for the connection and for the scheduler's greeting (default 5).

    Raises
    ------
    ImportError
        If Dask's ``distributed`` is not installed.
    ConnectionError
        If nothing listens at the address, or what listens is not a Dask scheduler
        (:func:`check_dask_scheduler`), or the client cannot connect within ``timeout``.
    ValueError
        For a malformed address or timeout.

    Examples
    --------
    >>> from ringchain.numerics.jobs.sweep import sweep
    >>> with dask_client("tcp://scheduler:8786") as client:  # doctest: +SKIP
    ...     rows = sweep(grid, client.get_executor())
    """
    try:
        from distributed import Client
    except ImportError:
        raise ImportError("a Dask cluster needs the dask extra: pip install 'ringchain[dask]'") from None
    check_dask_scheduler(address, timeout)
    try:
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError) as exc:
        raise ConnectionError(f"cannot connect a Dask client to {address}: {_reason(exc)}") from None


def check_dask_scheduler(address: str, timeout: float = DASK_TIMEOUT) -> None:
    """Raise ``ConnectionError`` unless a Dask scheduler answers at the TCP ``address`` within ``timeout`` s.

    A Dask scheduler greets every new connection first, with its handshake.  This opens one
    connection with ``distributed``'s own TCP comm (no retries), sends nothing, and reads the
    first message through that comm: a closed port, a silent listener (an HTTP server waits for
    a request), or one that speaks first in another protocol (an SSH banner) is reported in one
    line instead of the Dask client's 30-second wait.  The message must be a handshake as
    ``distributed`` writes it: a map holding at least the fields of this side's own handshake.
    Addresses of other schemes (``tls://``, ``ucx://``, ``inproc://``) are not checked.
    """
    timeout = float(timeout)
    if not (math.isfinite(timeout) and timeout > 0):
        raise ValueError(f"the Dask timeout must be a positive number of seconds, got {timeout!r}")
    host, port = _tcp_host_port(address)
    if host is None:
        return
    try:
        import distributed.comm  # noqa: F401 - the comm layer the check reads through
    except ImportError:
        raise ImportError("a Dask cluster needs the dask extra: pip install 'ringchain[dask]'") from None
    where = f"[{host}]:{port}" if ":" in host else f"{host}:{port}"
    problem = _in_a_loop_of_its_own(lambda: _greeting(address, where, timeout))
    if problem is None:
        return
    hint = f"; a scheduler listens on port {DASK_PORT} unless told otherwise" if port != DASK_PORT else ""
    raise ConnectionError(f"no Dask scheduler at {address}: {where} accepts connections, but {problem}{hint}")


async def _greeting(address: str, where: str, timeout: float) -> str | None:
    """None if a Dask handshake arrives at ``where`` within ``timeout`` s, else what came instead.

    Raises ConnectionError when no connection opens.  A listener that answers in another protocol
    makes the comm read a length it cannot allocate (an ASCII banner's first 8 bytes say 2e18
    bytes), or a message it cannot decode; both say "another protocol".
    """
    import asyncio

    from distributed.comm.core import CommClosedError
    from distributed.comm.registry import get_backend
    from tornado.iostream import StreamClosedError

    loop = asyncio.get_running_loop()
    deadline = loop.time() + timeout
    try:
        comm = await asyncio.wait_for(get_backend("tcp").get_connector().connect(where), timeout)
    except (asyncio.TimeoutError, TimeoutError):
        raise ConnectionError(f"no Dask scheduler at {address}: no answer from {where} within {timeout:g} s") from None
    except socket.gaierror:
        host = where.rpartition(":")[0].strip("[]")
        raise ConnectionError(f"no Dask scheduler at {address}: cannot resolve the host name {host!r}") from None
    except OSError as exc:
        cause = exc.__cause__ or exc  # the comm layer's CommClosedError carries the socket's error
        if isinstance(cause, ConnectionRefusedError):
            raise ConnectionError(f"no Dask scheduler at {address}: connection refused (nothing listens on {where})"
                                  ) from None  # fmt: skip
        if isinstance(cause, (StreamClosedError, CommClosedError, ConnectionResetError)):  # accepted, then closed
            return "it closed the connection without a Dask handshake"
        raise ConnectionError(f"no Dask scheduler at {address}: {_reason(cause)}") from None
    try:
        message = await asyncio.wait_for(comm.read(), max(deadline - loop.time(), 0.0))
    except (asyncio.TimeoutError, TimeoutError):
        return f"it sent nothing within {timeout:g} s, while a Dask scheduler greets at once"
    except CommClosedError:
        return "it closed the connection without a Dask handshake"
    except (MemoryError, OverflowError, ValueError, TypeError, EOFError):  # an impossible length, or not msgpack
        return "it speaks another protocol (its first message is not one distributed can read)"
    finally:
        comm.abort()
    if isinstance(message, dict) and set(comm.handshake_info()) <= set(message):
        return None
    return "its first message is not a Dask handshake"


def _in_a_loop_of_its_own(coroutine):
    """Run ``coroutine()`` to its end on a new event loop in a thread of its own (callers may have a loop running)."""
    import asyncio
    import threading

    outcome = {}

    def run():
        try:
            outcome["value"] = asyncio.run(coroutine())
        except BaseException as exc:  # handed to the caller's thread
            outcome["error"] = exc

    thread = threading.Thread(target=run, name="ringchain-dask-check", daemon=True)
    thread.start()
    thread.join()
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]


def _tcp_host_port(address: str) -> tuple[str | None, int]:
    """(host, port) of a TCP address (default port :data:`DASK_PORT`); (None, 0) for another scheme."""
    text = str(address).strip()
    scheme, sep, rest = text.partition("://")
    if not sep:
        scheme, rest = "tcp", text
    if scheme != "tcp":
        return None, 0
    if rest.startswith("["):  # [IPv6 address]:port
        host, bracket, tail = rest[1:].partition("]")
        if not bracket or (tail and not tail.startswith(":")):
            raise ValueError(f"malformed Dask address {address!r}")
        port_text = tail[1:] if tail else None
    elif rest.count(":") == 1:
        host, port_text = rest.split(":")
    else:  # no port, or a bare IPv6 address
        host, port_text = rest, None
    port = DASK_PORT
    if port_text is not None:
        port = int(port_text) if port_text.isdigit() else -1
        if not 0 < port < 65536:
            raise ValueError(f"malformed Dask address {address!r}: the port must be an integer in 1-65535")
    if not host:
        raise ValueError(f"malformed Dask address {address!r}: no host (e.g. tcp://scheduler:{DASK_PORT})")
    return host, port


def _reason(exc: BaseException) -> str:
    return " ".join(str(getattr(exc, "strerror", None) or exc).split()) or type(exc).__name__
