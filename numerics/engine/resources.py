"""The machine's resources as the engine's run estimates read them: memory available, sizes and durations
written for people (:func:`~ringchain.numerics.estimate_run`, the refusals of runs too large), and the cost of
what follows a sheet's run (:func:`fields_cost`)."""

from __future__ import annotations

import os

__all__ = ["format_bytes", "format_duration", "available_memory", "fields_cost"]

#: Processor seconds per link and sample of a run's link forces and energies, compiled in one pass
#: (:mod:`.fields`): 55-66 ns measured on square sheets of 40x40 to 140x140 (benchmarks/bench_sheet_post.py).
FIELDS_SECONDS_PER_LINK_SAMPLE = 7e-8

#: Processor seconds to write a sheet's NetCDF file: a fixed part (its 32 variables and their dimension scales,
#: 0.26-0.28 s measured) and one per byte of its fields (2.5 ns: 0.5 s for 96 MB; bench_sheet_post.py).
FILE_SECONDS, FILE_SECONDS_PER_BYTE = 0.3, 3e-9


def format_bytes(n) -> str:
    """``n`` bytes in kB, MB or GB, three significant digits."""
    for unit, size in (("GB", 2**30), ("MB", 2**20), ("kB", 2**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


def format_duration(seconds) -> str:
    """A duration in s, min, h or days, three significant digits."""
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s"


def available_memory() -> int | None:
    """Bytes of memory this process can still take: MemAvailable, capped by ulimit -v and a cgroup limit.

    None if none of them can be read.
    """
    available = None
    try:
        with open("/proc/meminfo") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    available = int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        try:
            available = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (OSError, ValueError, AttributeError):
            pass
    try:  # an address-space limit (ulimit -v) less what the process already maps
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            with open("/proc/self/statm") as handle:
                mapped = int(handle.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
            available = soft - mapped if available is None else min(available, soft - mapped)
    except (ImportError, OSError, ValueError):
        pass
    try:
        with open("/sys/fs/cgroup/memory.max") as handle:
            limit = handle.read().strip()
        with open("/sys/fs/cgroup/memory.current") as handle:
            used = int(handle.read().strip())
        if limit != "max":
            free = int(limit) - used
            available = free if available is None else min(available, free)
    except (OSError, ValueError):
        pass
    return available


def fields_cost(links: int, coordinates: int, samples: int, runs: int = 1) -> tuple[float, int]:
    """Processor seconds and bytes of what follows a sheet's run: its link forces and energies (:mod:`.fields`) and
    its NetCDF file.

    Parameters
    ----------
    links : int
        Links whose forces are read (every link, or those between the recorded sites).
    coordinates : int
        Recorded coordinates of one run (two per ring of a sheet).
    samples, runs : int
        Samples of the record and runs of the batch.

    Returns
    -------
    (float, int)
        Seconds, s: the compiled pass and the file (:data:`FIELDS_SECONDS_PER_LINK_SAMPLE`, :data:`FILE_SECONDS`,
        :data:`FILE_SECONDS_PER_BYTE`); bytes: the forces, kept with the run (the energies, one number per sample,
        and the file's buffers are small beside them).

    Examples
    --------
    >>> seconds, size = fields_cost(20200, 20000, 201)  # a 100x100 sheet, every site recorded
    >>> round(seconds, 2), format_bytes(size)
    (0.87, '31 MB')
    """
    values = int(samples) * int(runs)
    file_bytes = 8 * values * (2 * int(coordinates) + int(links))
    seconds = FIELDS_SECONDS_PER_LINK_SAMPLE * links * values + FILE_SECONDS + FILE_SECONDS_PER_BYTE * file_bytes
    return seconds, 8 * int(links) * values
