"""Executors of sweeps: the spawn pool and user scripts without a main guard, worker counts."""

import ast
import subprocess
import sys
import textwrap

import pytest
from ringchain.numerics import sweep
from ringchain.numerics.engine import executors
from ringchain.numerics.engine.executors import InlineExecutor, default_executor

GRID = '{"R_over_r": [6.0, 9.0]}'  # static theory only: quick in any worker


def run_script(tmp_path, source, name="user_script.py"):
    script = tmp_path / name
    script.write_text(textwrap.dedent(source))
    return subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=300, cwd=tmp_path)


def test_a_script_without_the_main_guard_is_told_so_before_any_worker_starts(tmp_path):
    result = run_script(
        tmp_path,
        f"""
        from ringchain.numerics import sweep
        print("top level ran")

        def main():
            return sweep({GRID}, max_workers=2)

        rows = main()
    """,
    )
    assert result.returncode == 1
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith("RuntimeError: sweep() starts worker processes with the 'spawn' method")
    assert "user_script.py again in each worker; line 8 runs at its top level" in last
    assert 'if __name__ == "__main__":' in last and "max_workers=0" in last
    assert "BrokenProcessPool" not in result.stderr
    assert result.stdout.count("top level ran") == 1  # no worker re-ran the script


@pytest.mark.slow
def test_a_guarded_script_and_code_without_a_file_run_on_the_pool(tmp_path):
    guarded = run_script(
        tmp_path,
        f"""
        from ringchain.numerics import sweep

        def main():
            print(len(sweep({GRID}, max_workers=2)), "rows")

        try:
            if __name__ == "__main__":
                main()
        finally:
            pass
    """,
    )
    assert guarded.returncode == 0, guarded.stderr
    assert guarded.stdout.split() == ["2", "rows"]
    # python -c: the main module has no file, so spawn imports nothing again and no guard is needed.
    code = f"from ringchain.numerics import sweep; print(len(sweep({GRID}, max_workers=2)))"
    inline = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert inline.returncode == 0, inline.stderr
    assert inline.stdout.strip() == "2"


@pytest.mark.parametrize(
    ("source", "line", "guarded"),
    [
        ("x = 1\nrun()\n", 2, False),
        ("if __name__ == '__main__':\n    run()\n", 2, True),
        ("if True:\n    run()\n", 2, False),
        ("try:\n    if __name__ == '__main__':\n        run()\nexcept Exception:\n    pass\n", 3, True),
        ("if __name__ != '__main__':\n    pass\nelse:\n    run()\n", 4, True),
        ("with open('f') as f:\n    run()\n", 2, False),
    ],
)
def test_the_guard_is_found_around_the_line_being_run(source, line, guarded):
    assert executors._guarded(ast.parse(source).body, line) is guarded


@pytest.mark.parametrize("workers", [-1, 1.5, True, "2"])
def test_a_worker_count_other_than_none_zero_or_a_positive_integer_is_refused(workers):
    with pytest.raises(ValueError, match=r"max_workers must be None \(all CPUs\), 0 \(this process\) or a positive"):
        default_executor(4, workers)
    with pytest.raises(ValueError, match="max_workers must be"):
        sweep({"R_over_r": 6.0}, max_workers=workers)


def test_zero_workers_run_in_this_process():
    assert isinstance(default_executor(4, 0), InlineExecutor)


def test_a_job_smaller_than_a_pools_start_runs_in_this_process_and_says_so(notices):
    # A job of 0.1 s of work on a pool of at most two workers saves at most 0.1 s, less than the pool's
    # start (POOL_START_SECONDS, 2.5 s, or more on a busy machine): no process is started.
    assert executors.run_tasks(abs, [(-1,), (2,)], seconds=0.1, name="sweep", unit="point") == [1, 2]
    assert len(notices) == 1 and notices[0].startswith("sweep: 2 points in this process")


def test_a_job_whose_one_core_share_is_small_runs_in_this_process_however_long(notices):
    # 1000 s of work of which 0.1 s on one core (the rest a compiled kernel's, on every core from one process
    # anyway): a pool of two would save at most 0.05 s, less than its start (POOL_START_SECONDS, 2.5 s or more).
    assert executors.run_tasks(abs, [(-1,), (2,)], seconds=1000.0, serial=0.1, name="sweep", unit="point") == [1, 2]
    assert len(notices) == 1 and notices[0].startswith("sweep: 2 points in this process (about 1000.0 s of work, "
                                                       "0.1 s of it on one core")  # fmt: skip


def test_notices_go_to_stderr_unless_silenced(capsys, monkeypatch):
    monkeypatch.undo()  # the suite's notices fixture: back to the package's own notify
    from ringchain.numerics.engine import _kernel_calls

    monkeypatch.delenv("RINGCHAIN_NOTICES", raising=False)
    _kernel_calls.notify("ringchain: a notice")
    assert capsys.readouterr().err == "ringchain: a notice\n"
    monkeypatch.setenv("RINGCHAIN_NOTICES", "0")  # as the book's build sets it
    _kernel_calls.notify("ringchain: a notice")
    assert capsys.readouterr().err == ""


def test_a_dead_worker_is_reported_with_what_to_do():
    from concurrent.futures import Executor, Future
    from concurrent.futures.process import BrokenProcessPool

    class DeadWorkers(Executor):
        def submit(self, fn, /, *args, **kwargs):
            future = Future()
            future.set_exception(BrokenProcessPool("A process in the process pool was terminated abruptly"))
            return future

    with pytest.raises(RuntimeError, match=r"a worker of the sweep died \(A process in the process pool was "
                                           r"terminated abruptly\); .* Run with max_workers=0"):  # fmt: skip
        sweep({"R_over_r": [6.0, 9.0]}, DeadWorkers())


@pytest.mark.parametrize(
    ("address", "host_port"),
    [
        ("scheduler", ("scheduler", 8786)),  # Dask's default port
        ("scheduler:9000", ("scheduler", 9000)),
        ("tcp://10.0.0.1:8786", ("10.0.0.1", 8786)),
        ("tcp://[::1]:9000", ("::1", 9000)),
        ("::1", ("::1", 8786)),
        ("tls://scheduler:8786", (None, 0)),  # other schemes are left to Dask
    ],
)
def test_dask_addresses_are_read_as_dask_reads_them(address, host_port):
    assert executors._tcp_host_port(address) == host_port


def test_the_scheduler_check_reads_the_greeting_through_distributeds_comm_layer(monkeypatch):
    # Issue 24, item 19: the greeting was decoded by hand (frame lengths with struct, msgpack type bytes),
    # a copy of distributed's wire format; it is now read by distributed's own TCP comm.
    import asyncio

    from distributed import LocalCluster
    from distributed.comm.tcp import TCP

    read = TCP.read
    reads = []

    async def spy(self, *args, **kwargs):
        reads.append((self.peer_address, asyncio.get_running_loop()))
        return await read(self, *args, **kwargs)

    monkeypatch.setattr(TCP, "read", spy)
    with LocalCluster(
        n_workers=0, processes=False, protocol="tcp", host="127.0.0.1", dashboard_address=":0"
    ) as cluster:
        executors.check_dask_scheduler(cluster.scheduler_address, timeout=5.0)  # a scheduler: no error
        ours = [peer for peer, loop in reads if loop is not cluster.loop.asyncio_loop]  # not the cluster's own comms
    assert ours == [cluster.scheduler_address]  # one read, of the scheduler's greeting, through TCP.read


def test_pool_workers_share_the_cores_between_their_numba_threads(monkeypatch):
    # Numba starts one thread per core in each process: two workers on 2 cores ran 4 threads.
    import os

    monkeypatch.delenv("NUMBA_NUM_THREADS", raising=False)
    cpus = os.cpu_count() or 1
    with default_executor(2, 2) as pool:
        counts = [pool.submit(os.getenv, "NUMBA_NUM_THREADS").result() for _ in range(2)]
    assert counts == [str(max(1, cpus // 2))] * 2
    monkeypatch.setenv("NUMBA_NUM_THREADS", "3")  # a count the user set is kept
    with default_executor(1, 1) as pool:
        assert pool.submit(os.getenv, "NUMBA_NUM_THREADS").result() == "3"
